/* test_inflation.c — acceptance test 6: a 7 ft canopy with lines, payload held, inflated by a uniform pressure jump to a steady shape; the payload's reaction equals the pressure force plus the weight of canopy and lines. */
#include "test.h"

#include <string.h>
#include <time.h>

/* Setup (NOTES §4, 7 ft flat circular canopy): diameter 2.134 m, edge
 * 0.15 m, 16 lines of 2 m, nylon cloth 0.0373 kg/m^2 (k = 5000 N/m) and
 * lines 0.01 kg/m (E A = 5000 N) with their default dashpots, gravity
 * -9.81 m/s^2, payload node fixed, dp = 50 Pa on every triangle (along the
 * +z normals: inflating).
 *
 * The cloth is tension-only (the header's compression-free cloth). A flat
 * canopy can only inflate by pulling its skirt in, which puts the skirt
 * region into hoop compression; Model-II springs carry that compression
 * without any bending stiffness, so the compressed band buckles and keeps
 * fluttering (measured: no static state, kinetic energy growing after a
 * first settling). Tension-only cloth goes slack instead and the gores
 * bulge, as real canopies do.
 *
 * Settling. Dashpots on the springs' relative velocity alone do not settle
 * this problem (measured with rk4: kinetic energy stays at ~2-30 J of the
 * ~90 J of pressure work for 2.5-3 s of simulated time with fabric dashpots
 * of 0.5-2 N s/m): slack cloth has no stiffness and, by the header's law,
 * no damping, the follower pressure keeps feeding the flapping, and the
 * rigid swing of the whole structure about the payload is undamped by
 * construction (relative velocity only). The implicit integrators fail to
 * converge on the first violent steps (Newton stalls at 1e-1..1e-3
 * relative with dt 5e-4..1e-2). So the static state is found by dynamic
 * relaxation: the model is advanced with rk4 (and its dashpots), and the
 * velocities are set to zero whenever the kinetic energy has passed a peak
 * (kinetic damping). That is a solver for the static problem, not a
 * damping model: with the payload held there is no rigid descent to
 * preserve.
 *
 * Check: at the static state the springs' pull on the payload node (its
 * total force from canopy_model_get_forces minus its own weight) must equal
 * sum dp A n over the triangles (canopy_model_get_triangle_geometry) plus
 * the weight of all free nodes (canopy and lines), within 1 %. */
CANOPY_TEST(inflation_payload_reaction)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.edge_length = 0.15;
    c.n_attachments = 16;
    c.fabric.law = CANOPY_SPRING_TENSION_ONLY;
    int att[16], payload = -1;
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = 2.0;
    l.edge_length = 0.15;
    l.payload_mass = 5.398;
    ASSERT_OK(m, canopy_build_suspension_lines(m, att, 16, &l, &payload));
    ASSERT_OK(m, canopy_model_set_fixed(m, payload, 1));

    const int n = canopy_model_node_count(m), nt = canopy_model_triangle_count(m);
    const double dp0 = 50.0;
    double *dp = malloc(sizeof(double) * (size_t)nt);
    double *f = malloc(3 * sizeof(double) * (size_t)n);
    double *v0 = calloc(3 * (size_t)n, sizeof(double));
    double *mass = malloc(sizeof(double) * (size_t)n);
    double *area = malloc(sizeof(double) * (size_t)nt);
    double *normal = malloc(3 * sizeof(double) * (size_t)nt);
    ASSERT_TRUE(dp && f && v0 && mass && area && normal);
    for (int t = 0; t < nt; ++t) dp[t] = dp0;
    ASSERT_OK(m, canopy_model_set_pressure_jump(m, dp, nt));
    ASSERT_OK(m, canopy_model_get_masses(m, mass, n));
    double m_free = 0.0;
    for (int i = 0; i < n; ++i)
        if (i != payload) m_free += mass[i];

    /* rk4 at omega dt <= 1 of the Gershgorin bound: stable (rk4's limit is
     * ~2.8 and the bound exceeds the true top frequency); accuracy of the
     * path is irrelevant for a static solution. */
    ASSERT_OK(m, canopy_model_set_integrator(m, "rk4"));
    ASSERT_OK(m, canopy_model_set_max_omega_dt(m, 1.0));
    const double dt = 5e-4, R = 0.5 * c.diameter;
    double kin_prev = 0.0, res = INFINITY, kin = INFINITY, Pz = 0.0;
    int step = 0, resets = 0, converged = 0;
    const clock_t c0 = clock();
    while (step < 12000 && !converged) {
        ASSERT_OK(m, canopy_model_advance(m, dt, NULL));
        ++step;
        canopy_energies en;
        ASSERT_OK(m, canopy_model_energies(m, &en));
        if (en.kinetic < kin_prev) {        /* past a peak: kinetic damping */
            ASSERT_OK(m, canopy_model_set_velocities(m, v0, n));
            kin_prev = 0.0;
            ++resets;
        } else {
            kin_prev = en.kinetic;
        }
        if (step % 50) continue;
        /* Residual: total force on the free nodes; kinetic energy against
         * the pressure force times the canopy radius (~ the work done). */
        ASSERT_OK(m, canopy_model_get_forces(m, f, n));
        double r2 = 0.0;
        for (int i = 0; i < n; ++i)
            if (i != payload)
                r2 += f[3 * i] * f[3 * i] + f[3 * i + 1] * f[3 * i + 1] +
                      f[3 * i + 2] * f[3 * i + 2];
        res = sqrt(r2);
        ASSERT_OK(m, canopy_model_get_triangle_geometry(m, NULL, normal, area, nt));
        Pz = 0.0;
        for (int t = 0; t < nt; ++t) Pz += dp[t] * area[t] * normal[3 * t + 2];
        ASSERT_OK(m, canopy_model_energies(m, &en));
        kin = en.kinetic;
        converged = res < 1e-6 * Pz && kin < 1e-10 * Pz * R;
    }
    const double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    printf("  %d nodes, %d triangles: %s after %.3f s simulated (%d "
           "kinetic-damping resets, %.1f s cpu): residual %.2e N, kinetic "
           "%.2e J\n", n, nt, converged ? "settled" : "NOT settled",
           step * dt, resets, cpu, res, kin);
    ASSERT_TRUE(converged);

    /* Reaction at the payload vs pressure + weight, at the final shape. */
    const double *g = (const double[3]){0.0, 0.0, -9.81};
    ASSERT_OK(m, canopy_model_get_forces(m, f, n));
    ASSERT_OK(m, canopy_model_get_triangle_geometry(m, NULL, normal, area, nt));
    double P[3] = {0.0, 0.0, 0.0}, A = 0.0;
    for (int t = 0; t < nt; ++t) {
        for (int d = 0; d < 3; ++d) P[d] += dp[t] * area[t] * normal[3 * t + d];
        A += area[t];
    }
    double reaction[3], expected[3], diff2 = 0.0, exp2 = 0.0;
    for (int d = 0; d < 3; ++d) {
        reaction[d] = f[3 * payload + d] - mass[payload] * g[d];
        expected[d] = P[d] + m_free * g[d];
        diff2 += (reaction[d] - expected[d]) * (reaction[d] - expected[d]);
        exp2 += expected[d] * expected[d];
    }
    const double rel = sqrt(diff2 / exp2);
    double diameter = 0.0, xp[3];
    ASSERT_OK(m, canopy_model_projected_diameter(m, &diameter));
    ASSERT_OK(m, canopy_model_payload_state(m, xp, NULL));
    printf("  pressure force sum dp A n = (%.3e, %.3e, %.4f) N over %.4f m^2 "
           "of cloth; weight of canopy + lines %.4f N\n", P[0], P[1], P[2], A,
           m_free * 9.81);
    printf("  reaction at payload (%.3e, %.3e, %.4f) N, expected (%.3e, "
           "%.3e, %.4f) N: relative difference %.2e; projected diameter "
           "%.3f m (constructed %.3f m)\n", reaction[0], reaction[1],
           reaction[2], expected[0], expected[1], expected[2], rel, diameter,
           c.diameter);
    ASSERT_TRUE(rel < 0.01);
    ASSERT_TRUE(P[2] > 0.0 && reaction[2] > 0.0);   /* lines in tension */
    ASSERT_TRUE(diameter < c.diameter);              /* skirt pulled in */
    ASSERT_TRUE(cpu < 60.0);
    free(dp); free(f); free(v0); free(mass); free(area); free(normal);
    canopy_model_destroy(&m);
}
