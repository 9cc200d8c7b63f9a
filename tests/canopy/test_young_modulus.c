/* test_young_modulus.c — acceptance test 4: the 2-D Young's modulus of the builders' fabric lattice, E t = (2/sqrt(3)) k (seed 000 §5.1 measured ~1.1 k). */
#include "test.h"

#include <string.h>

/* A rectangular Model-II sheet (canopy_build_rectangle, spring constant k,
 * equilateral rows) clamped along y = 0 and pulled along +y by a uniform edge
 * load F on y = L, sides free, no net body force: seed 000 §5.1, eq. 5.2,
 *     E_s = (F / D) (l / dl),
 * with D the width and the strain measured between the rows at L/3 and 2L/3
 * (away from the clamp, which prevents lateral contraction, and from the
 * loaded row). A regular triangular lattice of springs k has
 * E t = (2/sqrt(3)) k = 1.1547 k and Poisson's ratio 1/3 (NOTES §3); the
 * seed measured E_s ~ 1.1 k.
 *
 * The straight free sides are a chain of extra springs (the short edges of
 * the half-cells, length h = (sqrt(3)/2) e, along the sides) that the
 * infinite lattice does not have: they carry about k h strain each, so
 * (F/D)(l/dl) exceeds the lattice value by ~ 2 h / D (D = 1 m here: ~8 %,
 * inside the 10 % the acceptance test allows). Subtracting what those side
 * springs carry across the middle of the sheet gives the bulk lattice
 * modulus, which must match 2/sqrt(3) k to 2 %.
 *
 * Static equilibrium by damped dynamics: HHT-alpha with maximal numerical
 * dissipation (alpha = -1/3) and dashpots on the springs' relative velocity
 * that damp the first stretching mode critically. */
CANOPY_TEST(young_modulus_fabric_lattice)
{
    const double k = 5000.0, e = 0.05, W = 1.0;
    const double h = 0.5 * sqrt(3.0) * e;
    const int rows = 60;
    const double L = rows * h;              /* rows fit exactly */
    const double strain_target = 1e-3;      /* linear regime */
    const double F = 2.0 / sqrt(3.0) * k * W * strain_target;

    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    r.width = W;
    r.length = L;
    r.edge_length = e;
    r.fabric.stiffness = k;
    r.fabric.law = CANOPY_SPRING_MODEL_II;
    /* First stretching mode of the clamped sheet, omega_1 = (pi / 2L)
     * sqrt(E t / rho_A) ~ 240 rad/s; parallel dashpots give each mode
     * zeta = (c/k) omega / 2, so c = 2 k / omega_1 damps it critically. */
    const double omega1 = 3.14159265358979 / (2.0 * L) *
                          sqrt(2.0 / sqrt(3.0) * k / r.fabric.density);
    r.fabric.damping = 2.0 * k / omega1;
    ASSERT_OK(m, canopy_build_rectangle(m, &r));

    const int n = canopy_model_node_count(m), ns = canopy_model_spring_count(m);
    double *x0 = malloc(3 * sizeof(double) * (size_t)n);
    double *x = malloc(3 * sizeof(double) * (size_t)n);
    double *f = calloc(3 * (size_t)n, sizeof(double));
    double *mass = malloc(sizeof(double) * (size_t)n);
    double *rest = malloc(sizeof(double) * (size_t)ns);
    int *ends = malloc(2 * sizeof(int) * (size_t)ns);
    int *fixed = calloc((size_t)n, sizeof(int));
    ASSERT_TRUE(x0 && x && f && mass && rest && ends && fixed);
    ASSERT_OK(m, canopy_model_get_positions(m, x0, n));
    ASSERT_OK(m, canopy_model_get_masses(m, mass, n));
    ASSERT_OK(m, canopy_model_get_springs(m, ends, rest, NULL, ns));

    /* Clamp y = 0; load y = L: each node's share is half of each adjacent
     * segment of the loaded row (a uniform traction F / W). */
    int n_top = 0, n_clamped = 0;
    double share_sum = 0.0;
    for (int i = 0; i < n; ++i) {
        if (x0[3 * i + 1] == 0.0) {
            ASSERT_OK(m, canopy_model_set_fixed(m, i, 1));
            fixed[i] = 1;
            ++n_clamped;
        }
        if (fabs(x0[3 * i + 1] - L) > 1e-12) continue;
        double left = 0.0, right = 0.0;   /* nearest row neighbours */
        for (int j = 0; j < n; ++j) {
            if (j == i || fabs(x0[3 * j + 1] - L) > 1e-12) continue;
            const double d = x0[3 * j] - x0[3 * i];
            if (d > 0.0 && (right == 0.0 || d < right)) right = d;
            if (d < 0.0 && (left == 0.0 || -d < left)) left = -d;
        }
        const double share = 0.5 * (left + right);
        f[3 * i + 1] = F * share / W;
        share_sum += share;
        ++n_top;
    }
    ASSERT_NEAR(share_sum, W, 1e-12);
    ASSERT_TRUE(n_top == 21 && n_clamped == 21);
    /* No body force: only the edge load acts. */
    const double g[3] = {0.0, 0.0, 0.0};
    ASSERT_OK(m, canopy_model_set_gravity(m, g));
    ASSERT_OK(m, canopy_model_set_nodal_forces(m, f, n));

    ASSERT_OK(m, canopy_model_set_integrator(m, "hht"));
    ASSERT_OK(m, canopy_model_set_hht_alpha(m, -1.0 / 3.0));
    /* The dashpots amplify position round-off by c / (beta dt): the
     * residual's floor is ~1e-10 relative. */
    ASSERT_OK(m, canopy_model_set_implicit_controls(m, 1e-8, 50));
    const double dt = 5e-3;
    const double work = F * strain_target * L;   /* ~ the load's work */
    double res = INFINITY, kin = INFINITY;
    int steps = 0, converged = 0;
    while (steps < 2000 && !converged) {
        for (int s = 0; s < 10; ++s, ++steps)
            ASSERT_OK(m, canopy_model_step(m, dt));
        /* Residual: total force on the free nodes (springs, dashpots,
         * load); kinetic energy. */
        ASSERT_OK(m, canopy_model_get_forces(m, x, n));
        double r2 = 0.0;
        for (int i = 0; i < n; ++i)
            if (!fixed[i])
                r2 += x[3 * i] * x[3 * i] + x[3 * i + 1] * x[3 * i + 1] +
                      x[3 * i + 2] * x[3 * i + 2];
        res = sqrt(r2);
        canopy_energies en;
        ASSERT_OK(m, canopy_model_energies(m, &en));
        kin = en.kinetic;
        converged = res < 1e-8 * F && kin < 1e-14 * work;
    }
    printf("  sheet %.2f x %.4f m, %d nodes, k = %.0f N/m, F = %.4f N: "
           "%s after %d HHT steps of %.0e s (residual %.2e N, kinetic "
           "%.2e J)\n", W, L, n, k, F,
           converged ? "static" : "NOT converged", steps, dt, res, kin);
    ASSERT_TRUE(converged);

    /* Strain between the rows at L/3 and 2L/3 (mean y-displacement of each
     * row); Poisson's ratio from the least-squares slope of the lateral
     * displacement across the middle row. */
    ASSERT_OK(m, canopy_model_get_positions(m, x, n));
    const double y1 = (rows / 3) * h, y2 = (2 * rows / 3) * h,
                 ym = (rows / 2) * h;
    double u1 = 0.0, u2 = 0.0, zmax = 0.0;
    double sx = 0.0, su = 0.0, sxx = 0.0, sxu = 0.0;
    int c1 = 0, c2 = 0, cm = 0;
    for (int i = 0; i < n; ++i) {
        const double u = x[3 * i + 1] - x0[3 * i + 1];
        if (fabs(x0[3 * i + 1] - y1) < 1e-9) { u1 += u; ++c1; }
        if (fabs(x0[3 * i + 1] - y2) < 1e-9) { u2 += u; ++c2; }
        if (fabs(x0[3 * i + 1] - ym) < 1e-9) {
            const double xi = x0[3 * i], ux = x[3 * i] - x0[3 * i];
            sx += xi; su += ux; sxx += xi * xi; sxu += xi * ux; ++cm;
        }
        if (fabs(x[3 * i + 2]) > zmax) zmax = fabs(x[3 * i + 2]);
    }
    ASSERT_TRUE(c1 > 0 && c2 > 0 && cm > 2);
    u1 /= c1;
    u2 /= c2;
    const double strain = (u2 - u1) / (y2 - y1);
    const double lateral = (cm * sxu - sx * su) / (cm * sxx - sx * sx);
    const double poisson = -lateral / strain;
    const double Et = (F / W) / strain;             /* seed 000 eq. 5.2 */
    const double ratio = Et / k;
    /* What the two side chains carry across the middle row: tension of the
     * side springs (both ends on x = 0 or both on x = W) spanning y = ym. */
    double side = 0.0;
    int n_side = 0;
    for (int s = 0; s < ns; ++s) {
        const int i = ends[2 * s], j = ends[2 * s + 1];
        const double xi = x0[3 * i], xj = x0[3 * j];
        const int on_side = (xi == 0.0 && xj == 0.0) || (xi == W && xj == W);
        const double ya = fmin(x0[3 * i + 1], x0[3 * j + 1]),
                     yb = fmax(x0[3 * i + 1], x0[3 * j + 1]);
        if (!on_side || !(ya < ym + 0.5 * h && yb > ym + 0.5 * h)) continue;
        const double d[3] = {x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1],
                             x[3 * j + 2] - x[3 * i + 2]};
        const double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        side += k * (l - rest[s]) * fabs(d[1]) / l;
        ++n_side;
    }
    ASSERT_TRUE(n_side == 2);
    const double bulk = ((F - side) / W) / strain / k;
    printf("  strain %.6e: E t = (F/D)(l/dl) = %.2f N/m, E t / k = %.4f "
           "(lattice 2/sqrt(3) = %.4f, seed 000 §5.1 measured ~1.1)\n",
           strain, Et, ratio, 2.0 / sqrt(3.0));
    printf("  side chains carry %.4f N of %.4f N; bulk lattice E t / k = "
           "%.4f; Poisson's ratio %.4f (lattice 1/3)\n", side, F, bulk,
           poisson);
    ASSERT_TRUE(zmax < 1e-12);                      /* stays in plane */
    ASSERT_REL(ratio, 2.0 / sqrt(3.0), 0.10);
    ASSERT_REL(bulk, 2.0 / sqrt(3.0), 0.02);
    ASSERT_REL(poisson, 1.0 / 3.0, 0.05);
    free(x0); free(x); free(f); free(mass); free(rest); free(ends);
    free(fixed);
    canopy_model_destroy(&m);
}
