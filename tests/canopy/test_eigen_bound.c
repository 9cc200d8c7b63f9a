/* test_eigen_bound.c — seed 000 ch. 3 and §5.2: eigen-frequency bounds and the drum test spectrum. */
#include "test.h"

#include <stdlib.h>

/* A flat circular membrane, Ø 1 m, edge 0.1 m, rim nodes fixed, every node
 * of equal mass m (fabric density 0, then m added per node), stiffness k. */
static canopy_status drum(canopy_model **out, canopy_spring_law law, double k,
                          double m, int *max_neighbours)
{
    canopy_status st = canopy_model_create(out);
    if (st) return st;
    canopy_model *model = *out;
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = 1.0;
    c.edge_length = 0.1;
    c.n_attachments = 6;
    c.radial_tapes = 0;
    c.fabric.density = 0.0;
    c.fabric.stiffness = k;
    c.fabric.damping = 0.0;
    c.fabric.law = law;
    const double zero_g[3] = {0.0, 0.0, 0.0};
    if ((st = canopy_build_circular(model, &c, NULL)) ||
        (st = canopy_model_set_gravity(model, zero_g)))
        return st;
    const int n = canopy_model_node_count(model), ns = canopy_model_spring_count(model);
    double *x = malloc(sizeof(double) * 3 * (size_t)n);
    int *ends = malloc(sizeof(int) * 2 * (size_t)ns), *deg = calloc((size_t)n, sizeof(int));
    canopy_model_get_positions(model, x, n);
    canopy_model_get_springs(model, ends, NULL, NULL, ns);
    for (int s = 0; s < 2 * ns; ++s) ++deg[ends[s]];
    *max_neighbours = 0;
    for (int i = 0; i < n && st == CANOPY_OK; ++i) {
        if (deg[i] > *max_neighbours) *max_neighbours = deg[i];
        const double r = hypot(x[3 * i], x[3 * i + 1]);
        st = canopy_model_add_node_mass(model, i, m);
        if (st == CANOPY_OK && r > 0.5 - 1e-9) st = canopy_model_set_fixed(model, i, 1);
    }
    free(x); free(ends); free(deg);
    return st;
}

/* Largest linearised frequency vs the Gershgorin bound sqrt(2Mk/m) (seed
 * eq. 3.6) for Model-I and the seed's empirical sqrt(Mk/m), M = 7 (eq. 3.7,
 * §5.2) for Model-II fabric. The Lanczos estimate plus its residual bound
 * must stay below the bound. */
CANOPY_TEST(eigen_frequency_bounds)
{
    const double k = 1000.0, m = 2.5;
    for (int pass = 0; pass < 2; ++pass) {
        const canopy_spring_law law = pass ? CANOPY_SPRING_MODEL_II : CANOPY_SPRING_MODEL_I;
        canopy_model *model = NULL;
        int M;
        ASSERT_OK(model, drum(&model, law, k, m, &M));
        double omega, res, gersh;
        ASSERT_OK(model, canopy_model_max_frequency(model, &omega, &res));
        ASSERT_OK(model, canopy_model_frequency_bound(model, &gersh));
        /* omega^2 is known to within res: omega <= sqrt(omega^2 + res). */
        const double upper = sqrt(omega * omega + res);
        const double bound = pass ? sqrt(7.0 * k / m) : sqrt(2.0 * M * k / m);
        printf("%s: %d nodes, max neighbours M = %d; largest omega %.4f rad/s "
               "(omega^2 residual %.1e), bound %s = %.4f (ratio %.3f); "
               "library's per-node Gershgorin bound %.4f\n",
               pass ? "Model-II" : "Model-I ", canopy_model_node_count(model), M,
               omega, res, pass ? "sqrt(7k/m)" : "sqrt(2Mk/m)", bound,
               omega / bound, gersh);
        ASSERT_TRUE(upper < bound);
        ASSERT_TRUE(upper <= gersh * (1.0 + 1e-12));
        /* Model-I's spectrum is the graph Laplacian's: its top is near the
         * Gershgorin bound, so the estimate is not trivially small. */
        if (!pass) ASSERT_TRUE(omega > 0.5 * bound);
        canopy_model_destroy(&model);
    }
}

/* Seed Fig. 5.4: k = 1000, m = 10, 2.5, 0.625; the spectrum of a sample
 * point's tangential (x) motion after a small random perturbation has no
 * peak above nu_c = sqrt(7k/m) / 2 pi = 4.21, 8.42, 16.84 Hz. Spectrum: DFT
 * of the Hann-windowed record; "no peak" means every magnitude beyond
 * nu_c + 2/T (past the window's main lobe) is below 5 % of the largest (the
 * Hann window's highest side lobe is 2.8 %). */
CANOPY_TEST(drum_spectrum_cutoff)
{
    const double k = 1000.0, masses[3] = {10.0, 2.5, 0.625};
    const double nu_seed[3] = {4.21, 8.42, 16.84};
    for (int c = 0; c < 3; ++c) {
        const double m = masses[c], nu_c = sqrt(7.0 * k / m) / (2.0 * M_PI);
        ASSERT_NEAR(nu_c, nu_seed[c], 0.01);
        canopy_model *model = NULL;
        int M;
        ASSERT_OK(model, drum(&model, CANOPY_SPRING_MODEL_II, k, m, &M));
        const int n = canopy_model_node_count(model);
        double *x = malloc(sizeof(double) * 3 * (size_t)n);
        int *fixed = malloc(sizeof(int) * (size_t)n);
        canopy_model_get_positions(model, x, n);
        canopy_model_get_fixed(model, fixed, n);
        /* Sample: the free node nearest (0.25, 0.05, 0). Perturb every free
         * node by up to 1e-3 of the edge length in x, y and z. */
        int sample = -1;
        double best = 1e9;
        unsigned long long seed = 12345u;
        for (int i = 0; i < n; ++i) {
            if (fixed[i]) continue;
            const double d = hypot(x[3 * i] - 0.25, x[3 * i + 1] - 0.05);
            if (d < best) { best = d; sample = i; }
            for (int q = 0; q < 3; ++q) {
                seed = seed * 6364136223846793005ull + 1442695040888963407ull;
                x[3 * i + q] += 1e-4 * ((double)(seed >> 11) / 9007199254740992.0 - 0.5);
            }
        }
        const double x_rest = x[3 * sample];
        ASSERT_OK(model, canopy_model_set_positions(model, x, n));
        double dt;
        ASSERT_OK(model, canopy_model_stable_step(model, &dt));
        const double T = 40.0 / nu_c;
        const int steps = (int)ceil(T / dt);
        double *rec = malloc(sizeof(double) * (size_t)steps);
        for (int s = 0; s < steps; ++s) {
            if (canopy_model_step(model, dt) != CANOPY_OK) {
                CANOPY_TEST_FAIL_("%s", canopy_model_message(model));
                break;
            }
            canopy_model_get_positions(model, x, n);
            rec[s] = x[3 * sample] - x_rest;
        }
        double mean = 0.0;
        for (int s = 0; s < steps; ++s) mean += rec[s] / steps;
        const double Tr = steps * dt, df = 0.25 / Tr, f_max = 3.0 * nu_c;
        double peak = 0.0, peak_f = 0.0, above = 0.0, above_f = 0.0;
        for (double f = df; f <= f_max; f += df) {
            double re = 0.0, im = 0.0;
            for (int s = 0; s < steps; ++s) {
                const double w = 0.5 - 0.5 * cos(2.0 * M_PI * s / (steps - 1));
                const double ph = 2.0 * M_PI * f * s * dt;
                re += w * (rec[s] - mean) * cos(ph);
                im -= w * (rec[s] - mean) * sin(ph);
            }
            const double mag = hypot(re, im);
            if (mag > peak) { peak = mag; peak_f = f; }
            if (f > nu_c + 2.0 / Tr && mag > above) { above = mag; above_f = f; }
        }
        printf("m = %5.3f: cut-off %.2f Hz (seed %.2f); %d steps of %.3g s; "
               "strongest peak %.2f Hz; largest magnitude above cut-off %.3f "
               "of the peak (at %.2f Hz)\n", m, nu_c, nu_seed[c], steps, dt,
               peak_f, above / peak, above_f);
        ASSERT_TRUE(peak > 0.0);
        ASSERT_TRUE(peak_f < nu_c);
        ASSERT_TRUE(above < 0.05 * peak);
        free(x); free(fixed); free(rec);
        canopy_model_destroy(&model);
    }
}
