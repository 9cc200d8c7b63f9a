/* test_fabric_compression.c — the cloth's Model-II springs softened in compression (canopy_model_set_fabric_compression): force, tension, energy, tangent and which springs it touches. */
#include "test.h"

#include <stdlib.h>

/* Two springs of stiffness k, rest length 1 m along x, each from a fixed
 * node to a free one of mass m: spring 0 is cloth, spring 1 a Model-II
 * suspension line. Gravity off. */
static canopy_status two_springs(canopy_model **out, double k, double m)
{
    canopy_status st = canopy_model_create(out);
    if (st) return st;
    canopy_model *model = *out;
    const double zero_g[3] = {0.0, 0.0, 0.0};
    const double a0[3] = {0.0, 0.0, 0.0}, a1[3] = {1.0, 0.0, 0.0};
    const double b0[3] = {0.0, 2.0, 0.0}, b1[3] = {1.0, 2.0, 0.0};
    if ((st = canopy_model_set_gravity(model, zero_g)) ||
        (st = canopy_model_add_node(model, a0, m, CANOPY_GROUP_FABRIC, NULL)) ||
        (st = canopy_model_add_node(model, a1, m, CANOPY_GROUP_FABRIC, NULL)) ||
        (st = canopy_model_add_node(model, b0, m, CANOPY_GROUP_LINE, NULL)) ||
        (st = canopy_model_add_node(model, b1, m, CANOPY_GROUP_LINE, NULL)) ||
        (st = canopy_model_add_spring(model, 0, 1, k, 0.0, CANOPY_SPRING_MODEL_II,
                                      CANOPY_GROUP_FABRIC, NULL)) ||
        (st = canopy_model_add_spring(model, 2, 3, k, 0.0, CANOPY_SPRING_MODEL_II,
                                      CANOPY_GROUP_LINE, NULL)) ||
        (st = canopy_model_set_fixed(model, 0, 1)) ||
        (st = canopy_model_set_fixed(model, 2, 1)))
        return st;
    return CANOPY_OK;
}

/* Free nodes 1 and 3 moved to x = 1 + stretch: both springs stretched
 * (stretch > 0) or compressed (stretch < 0) by the same length. */
static canopy_status stretch_both(canopy_model *model, double stretch)
{
    double x[12] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 1.0, 2.0, 0.0};
    x[3] += stretch;
    x[9] += stretch;
    return canopy_model_set_positions(model, x, 4);
}

/* With ratio r the compressed cloth spring pushes with r k |dl| and stores
 * r k dl^2 / 2, the line spring beside it k |dl| and k dl^2 / 2; stretched,
 * both pull with k dl. Tensions, forces, energy and the linearised
 * frequency (the tangent: sqrt(r k / m) against sqrt(k / m)) must all say
 * the same. The values are exact up to rounding (1e-12 relative). */
CANOPY_TEST(fabric_compression_softens_compressed_cloth_springs_only)
{
    const double k = 2000.0, m = 0.5, r = 0.1, dl = 0.05;
    canopy_model *model = NULL;
    ASSERT_OK(model, two_springs(&model, k, m));
    ASSERT_OK(model, canopy_model_set_fabric_compression(model, r));

    double f[12], T[2], omega, residual;
    canopy_energies e;
    /* Compressed. The line alone: its frequency is the largest. */
    ASSERT_OK(model, stretch_both(model, -dl));
    ASSERT_OK(model, canopy_model_get_forces(model, f, 4));
    ASSERT_OK(model, canopy_model_get_tensions(model, T, 2));
    ASSERT_OK(model, canopy_model_energies(model, &e));
    printf("  compressed by %g m: cloth force %.6g N (r k dl = %.6g), line "
           "force %.6g N; tensions %.6g / %.6g N; spring energy %.6g J\n",
           dl, f[3], r * k * dl, f[9], T[0], T[1], e.spring);
    ASSERT_TRUE(fabs(f[3] - r * k * dl) < 1e-12 * k * dl);
    ASSERT_TRUE(fabs(f[9] - k * dl) < 1e-12 * k * dl);
    ASSERT_TRUE(fabs(T[0] + r * k * dl) < 1e-12 * k * dl);
    ASSERT_TRUE(fabs(T[1] + k * dl) < 1e-12 * k * dl);
    ASSERT_TRUE(fabs(e.spring - 0.5 * (1.0 + r) * k * dl * dl) <
                1e-12 * k * dl * dl);
    ASSERT_OK(model, canopy_model_max_frequency(model, &omega, &residual));
    ASSERT_TRUE(fabs(omega - sqrt(k / m)) < 1e-6 * sqrt(k / m));

    /* Stretched: both springs alike. */
    ASSERT_OK(model, stretch_both(model, dl));
    ASSERT_OK(model, canopy_model_get_forces(model, f, 4));
    ASSERT_OK(model, canopy_model_energies(model, &e));
    ASSERT_TRUE(fabs(f[3] + k * dl) < 1e-12 * k * dl);
    ASSERT_TRUE(fabs(f[9] + k * dl) < 1e-12 * k * dl);
    ASSERT_TRUE(fabs(e.spring - k * dl * dl) < 1e-12 * k * dl * dl);
    canopy_model_destroy(&model);

    /* The cloth spring alone, compressed: its axial frequency is the
     * tangent's r k. */
    ASSERT_OK(model, canopy_model_create(&model));
    const double zero_g[3] = {0.0, 0.0, 0.0};
    const double a0[3] = {0.0, 0.0, 0.0}, a1[3] = {1.0, 0.0, 0.0};
    const double compressed[6] = {0.0, 0.0, 0.0, 1.0 - dl, 0.0, 0.0};
    ASSERT_OK(model, canopy_model_set_gravity(model, zero_g));
    ASSERT_OK(model, canopy_model_add_node(model, a0, m, CANOPY_GROUP_FABRIC, NULL));
    ASSERT_OK(model, canopy_model_add_node(model, a1, m, CANOPY_GROUP_FABRIC, NULL));
    ASSERT_OK(model, canopy_model_add_spring(model, 0, 1, k, 0.0,
                                             CANOPY_SPRING_MODEL_II,
                                             CANOPY_GROUP_FABRIC, NULL));
    ASSERT_OK(model, canopy_model_set_positions(model, compressed, 2));
    ASSERT_OK(model, canopy_model_set_fixed(model, 0, 1));
    ASSERT_OK(model, canopy_model_set_fabric_compression(model, r));
    ASSERT_OK(model, canopy_model_max_frequency(model, &omega, &residual));
    printf("  cloth spring compressed: linearised frequency %.6g rad/s "
           "(sqrt(r k / m) = %.6g)\n", omega, sqrt(r * k / m));
    ASSERT_TRUE(fabs(omega - sqrt(r * k / m)) < 1e-6 * sqrt(r * k / m));
    canopy_model_destroy(&model);
}

/* A free square sheet of cloth, every node kicked by a random velocity so
 * that its springs pass in and out of compression, undamped, no gravity,
 * RK4 at omega dt = 0.1. The force must be the gradient of the energy
 * r k dl^2 / 2 (compressed) and k dl^2 / 2 (stretched): then the total
 * energy drifts only by RK4's error, O(1e-5) relative over 2000 steps
 * (NOTES §4: -5.6e-5 after 4000 steps at omega dt 0.1 on the worst mode;
 * the kink of the force at l = l0 costs a little more), whereas an energy
 * that kept k in compression would differ by ~ (1 - r) times the
 * compressed springs' share, tens of per cent here. */
CANOPY_TEST(fabric_compression_conserves_energy)
{
    const double r = 0.1;
    canopy_model *model = NULL;
    ASSERT_OK(model, canopy_model_create(&model));
    canopy_rectangle_spec s = canopy_rectangle_spec_default();
    s.width = 0.5;
    s.length = 0.5;
    s.edge_length = 0.1;
    s.fabric.damping = 0.0;
    s.fabric.law = CANOPY_SPRING_MODEL_II;
    ASSERT_OK(model, canopy_build_rectangle(model, &s));
    const double zero_g[3] = {0.0, 0.0, 0.0};
    ASSERT_OK(model, canopy_model_set_gravity(model, zero_g));
    ASSERT_OK(model, canopy_model_set_integrator(model, "rk4"));
    ASSERT_OK(model, canopy_model_set_max_omega_dt(model, 0.1));
    ASSERT_OK(model, canopy_model_set_fabric_compression(model, r));

    const int n = canopy_model_node_count(model);
    double *v = malloc(3 * sizeof(double) * (size_t)n);
    ASSERT_TRUE(v != NULL);
    if (v == NULL) return;
    unsigned seed = 12345u;
    for (int i = 0; i < 3 * n; ++i) {
        seed = seed * 1103515245u + 12345u;
        v[i] = ((double)(seed >> 8 & 0xffff) / 65535.0 - 0.5) * 0.4;
    }
    ASSERT_OK(model, canopy_model_set_velocities(model, v, n));
    free(v);

    double dt;
    ASSERT_OK(model, canopy_model_stable_step(model, &dt));
    canopy_energies e0, e;
    ASSERT_OK(model, canopy_model_energies(model, &e0));
    const double total0 = e0.kinetic + e0.spring;
    double worst = 0.0, compressed_share = 0.0;
    int ns = canopy_model_spring_count(model);
    double *T = malloc(sizeof(double) * (size_t)ns);
    ASSERT_TRUE(T != NULL);
    if (T == NULL) return;
    for (int step = 1; step <= 2000; ++step) {
        ASSERT_OK(model, canopy_model_step(model, dt));
        ASSERT_OK(model, canopy_model_energies(model, &e));
        const double drift = fabs(e.kinetic + e.spring - total0) / total0;
        if (drift > worst) worst = drift;
        if (step % 100 == 0) {
            ASSERT_OK(model, canopy_model_get_tensions(model, T, ns));
            int compressed = 0;
            for (int q = 0; q < ns; ++q) compressed += T[q] < 0.0;
            compressed_share += (double)compressed / ns / 20.0;
        }
    }
    free(T);
    printf("  %d nodes, dt %.3g s: energy %.6g J, largest relative drift "
           "%.3g over 2000 RK4 steps; on average %.0f %% of the springs "
           "compressed\n", n, dt, total0, worst, 100.0 * compressed_share);
    ASSERT_TRUE(compressed_share > 0.2);
    ASSERT_TRUE(worst < 1e-4);
    canopy_model_destroy(&model);
}

CANOPY_TEST(fabric_compression_rejects_a_ratio_outside_0_1)
{
    canopy_model *model = NULL;
    ASSERT_OK(model, canopy_model_create(&model));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_fabric_compression(model, -0.1));
    ASSERT_TRUE(strstr(canopy_model_message(model), "ratio") != NULL);
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_fabric_compression(model, 1.5));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_fabric_compression(model, NAN));
    ASSERT_OK(model, canopy_model_set_fabric_compression(model, 0.0));
    ASSERT_OK(model, canopy_model_set_fabric_compression(model, 1.0));
    canopy_model_destroy(&model);
}
