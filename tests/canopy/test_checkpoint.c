/* test_checkpoint.c — checkpoint/restore/commit and failed-step rollback reproduce an uninterrupted run exactly. */
#include "test.h"
#include "test_membrane_fixture.h"

#include <string.h>

enum { N = 8, STEPS = 40, SPLIT = 17 };

static canopy_status make_model(canopy_model **m, const char *integrator)
{
    canopy_status st = canopy_model_create(m);
    if (st) return st;
    if ((st = membrane_fixture(*m, N, 0.1, 500.0, 0.05, 0.01))) return st;
    const int nt = canopy_model_triangle_count(*m);
    double dp[2 * (N - 1) * (N - 1)];
    for (int t = 0; t < nt; ++t) dp[t] = 20.0 + 0.1 * t;
    if ((st = canopy_model_set_pressure_jump(*m, dp, nt))) return st;
    return canopy_model_set_integrator(*m, integrator);
}

static void check_integrator(const char *integrator)
{
    canopy_model *a = NULL, *b = NULL;
    ASSERT_OK(a, make_model(&a, integrator));
    ASSERT_OK(b, make_model(&b, integrator));
    const int n = canopy_model_node_count(a), nt = canopy_model_triangle_count(a);
    const double dt = 2e-3;
    for (int s = 0; s < STEPS; ++s) ASSERT_OK(a, canopy_model_advance(a, dt, NULL));

    /* b: the same run, but from step SPLIT on, each step is first tried with
     * other loads and restored (twice), as a coupling iteration would. */
    double dp_true[2 * (N - 1) * (N - 1)], dp_trial[2 * (N - 1) * (N - 1)];
    ASSERT_OK(b, canopy_model_get_pressure_jump(b, dp_true, nt));
    for (int t = 0; t < nt; ++t) dp_trial[t] = -3.0 * dp_true[t];
    for (int s = 0; s < STEPS; ++s) {
        if (s >= SPLIT) {
            ASSERT_OK(b, canopy_model_checkpoint(b));
            for (int trial = 0; trial < 2; ++trial) {
                ASSERT_OK(b, canopy_model_set_pressure_jump(b, dp_trial, nt));
                ASSERT_OK(b, canopy_model_advance(b, dt, NULL));
                ASSERT_OK(b, canopy_model_restore(b));
            }
            ASSERT_OK(b, canopy_model_set_pressure_jump(b, dp_true, nt));
        }
        ASSERT_OK(b, canopy_model_advance(b, dt, NULL));
        if (s >= SPLIT) ASSERT_OK(b, canopy_model_commit(b));
    }
    double xa[3 * N * N], xb[3 * N * N], va[3 * N * N], vb[3 * N * N];
    ASSERT_OK(a, canopy_model_get_positions(a, xa, n));
    ASSERT_OK(b, canopy_model_get_positions(b, xb, n));
    ASSERT_OK(a, canopy_model_get_velocities(a, va, n));
    ASSERT_OK(b, canopy_model_get_velocities(b, vb, n));
    const double dx = rel_diff(xa, xb, 3 * n), dv = rel_diff(va, vb, 3 * n);
    printf("%-8s checkpoint/restore vs uninterrupted: positions %.2e, "
           "velocities %.2e (relative)\n", integrator, dx, dv);
    ASSERT_TRUE(dx <= 1e-12);
    ASSERT_TRUE(dv <= 1e-12);
    ASSERT_NEAR(canopy_model_time(b), canopy_model_time(a), 1e-12);
    /* The motion is real: the membrane moved. */
    ASSERT_TRUE(rel_diff(xa, (double[3 * N * N]){0}, 3 * n) > 0.0);
    canopy_model_destroy(&a);
    canopy_model_destroy(&b);
}

CANOPY_TEST(checkpoint_restore_exact)
{
    check_integrator("rk4");
    check_integrator("hht");     /* carries its acceleration between steps */
    check_integrator("newmark");
}

/* A diverging step returns CANOPY_ERR_DIVERGED and leaves the state exactly
 * as it was, for advance (several sub-steps) and for a single step. */
CANOPY_TEST(failed_step_restores_state)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, make_model(&m, "euler"));
    const int n = canopy_model_node_count(m);
    for (int s = 0; s < 5; ++s) ASSERT_OK(m, canopy_model_advance(m, 1e-3, NULL));
    double x0[3 * N * N], v0[3 * N * N], x1[3 * N * N], v1[3 * N * N];
    ASSERT_OK(m, canopy_model_get_positions(m, x0, n));
    ASSERT_OK(m, canopy_model_get_velocities(m, v0, n));
    const double t0 = canopy_model_time(m);
    /* Way past the stable step with explicit Euler: grows without bound. */
    ASSERT_OK(m, canopy_model_set_max_omega_dt(m, 50.0));
    ASSERT_OK(m, canopy_model_set_speed_limit(m, 100.0));
    ASSERT_STATUS(CANOPY_ERR_DIVERGED, canopy_model_advance(m, 10.0, NULL));
    printf("message: %s\n", canopy_model_message(m));
    ASSERT_TRUE(strstr(canopy_model_message(m), "node") != NULL);
    ASSERT_OK(m, canopy_model_get_positions(m, x1, n));
    ASSERT_OK(m, canopy_model_get_velocities(m, v1, n));
    ASSERT_TRUE(memcmp(x0, x1, sizeof(double) * 3 * (size_t)n) == 0);
    ASSERT_TRUE(memcmp(v0, v1, sizeof(double) * 3 * (size_t)n) == 0);
    ASSERT_TRUE(canopy_model_time(m) == t0);
    /* NaN/Inf path: speed limit off, a single huge step overflows. */
    ASSERT_OK(m, canopy_model_set_speed_limit(m, INFINITY));
    canopy_status st = CANOPY_OK;
    for (int s = 0; s < 200 && st == CANOPY_OK; ++s)
        st = canopy_model_step(m, 1e3);
    ASSERT_TRUE(st == CANOPY_ERR_DIVERGED);
    printf("message: %s\n", canopy_model_message(m));
    double x2[3 * N * N];
    ASSERT_OK(m, canopy_model_get_positions(m, x2, n));
    for (int i = 0; i < 3 * n; ++i) ASSERT_TRUE(isfinite(x2[i]));
    /* Implicit solver failure also restores: one Newton iteration only. */
    canopy_model_destroy(&m);
    ASSERT_OK(m, make_model(&m, "newmark"));
    ASSERT_OK(m, canopy_model_set_implicit_controls(m, 1e-14, 1));
    ASSERT_OK(m, canopy_model_get_positions(m, x0, n));
    ASSERT_STATUS(CANOPY_ERR_NOT_CONVERGED, canopy_model_step(m, 0.05));
    printf("message: %s\n", canopy_model_message(m));
    ASSERT_OK(m, canopy_model_get_positions(m, x1, n));
    ASSERT_TRUE(memcmp(x0, x1, sizeof(double) * 3 * (size_t)n) == 0);
    ASSERT_TRUE(canopy_model_time(m) == 0.0);
    canopy_model_destroy(&m);
}

/* Restore returns the loads set on the model too (pressure jump and nodal
 * forces), so that a failed coupling step's state, written after restore,
 * is the one the step started from: advancing from it without setting the
 * loads again repeats the step as first taken. */
CANOPY_TEST(restore_returns_loads)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, make_model(&m, "hht"));
    const int n = canopy_model_node_count(m), nt = canopy_model_triangle_count(m);
    const double dt = 2e-3;
    double f[3 * N * N], other[3 * N * N];
    for (int i = 0; i < 3 * n; ++i) {
        f[i] = 0.01 * ((i % 7) - 3);
        other[i] = -5.0 * f[i] + 0.3;
    }
    ASSERT_OK(m, canopy_model_set_nodal_forces(m, f, n));
    for (int s = 0; s < 5; ++s) ASSERT_OK(m, canopy_model_advance(m, dt, NULL));

    double dp0[2 * (N - 1) * (N - 1)], dp_trial[2 * (N - 1) * (N - 1)],
        dp1[2 * (N - 1) * (N - 1)];
    ASSERT_OK(m, canopy_model_get_pressure_jump(m, dp0, nt));
    ASSERT_OK(m, canopy_model_checkpoint(m));
    /* The step as first taken, with the loads it started with */
    double xa[3 * N * N], xb[3 * N * N];
    ASSERT_OK(m, canopy_model_advance(m, dt, NULL));
    ASSERT_OK(m, canopy_model_get_positions(m, xa, n));
    ASSERT_OK(m, canopy_model_restore(m));
    /* A coupling iteration with other loads, then restore */
    for (int t = 0; t < nt; ++t) dp_trial[t] = 40.0 - 2.0 * dp0[t];
    ASSERT_OK(m, canopy_model_set_pressure_jump(m, dp_trial, nt));
    ASSERT_OK(m, canopy_model_set_nodal_forces(m, other, n));
    ASSERT_OK(m, canopy_model_advance(m, dt, NULL));
    ASSERT_OK(m, canopy_model_restore(m));
    ASSERT_OK(m, canopy_model_get_pressure_jump(m, dp1, nt));
    ASSERT_TRUE(memcmp(dp0, dp1, sizeof(double) * (size_t)nt) == 0);
    /* The same step again without setting the loads: the nodal forces
     * and the pressure jump are the checkpoint's, so it repeats exactly */
    ASSERT_OK(m, canopy_model_advance(m, dt, NULL));
    ASSERT_OK(m, canopy_model_get_positions(m, xb, n));
    printf("restore returns the loads: the step repeated to %.2e "
           "(relative)\n", rel_diff(xa, xb, 3 * n));
    ASSERT_TRUE(memcmp(xa, xb, sizeof(double) * 3 * (size_t)n) == 0);
    canopy_model_destroy(&m);
}
