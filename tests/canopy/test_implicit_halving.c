/* test_implicit_halving.c — canopy_model_advance takes an implicit step whose Newton solve fails again as two halves. */
#include "test.h"
#include "test_membrane_fixture.h"

/* A flat 6 x 6 membrane (spacing 0.1 m, k = 1000 N/m, node mass 1 g, no
 * gravity) under 100 Pa, HHT alpha = -0.3 with Newton limited to 12
 * iterations at tolerance 1e-10. Out of its plane the flat membrane has no
 * stiffness at first, so the load's response is strongly nonlinear: one
 * 0.01 s step does not converge in 12 iterations, while a 0.005 s step
 * does. */
static canopy_model *pressed_membrane(void)
{
    canopy_model *m = NULL;
    if (canopy_model_create(&m) != CANOPY_OK) return NULL;
    const double no_gravity[3] = {0.0, 0.0, 0.0};
    double dp[50];
    int ok = membrane_fixture(m, 6, 0.1, 1000.0, 0.0, 0.001) == CANOPY_OK &&
             canopy_model_triangle_count(m) == 50 &&
             canopy_model_set_gravity(m, no_gravity) == CANOPY_OK;
    for (int t = 0; t < 50; ++t) dp[t] = 100.0;
    ok = ok && canopy_model_set_pressure_jump(m, dp, 50) == CANOPY_OK &&
         canopy_model_set_integrator(m, "hht") == CANOPY_OK &&
         canopy_model_set_hht_alpha(m, -0.3) == CANOPY_OK &&
         canopy_model_set_implicit_controls(m, 1e-10, 12) == CANOPY_OK &&
         canopy_model_set_max_omega_dt(m, 1e9) == CANOPY_OK;
    if (!ok) canopy_model_destroy(&m);
    return m;
}

/* canopy_model_step(0.01) fails with CANOPY_ERR_NOT_CONVERGED and leaves
 * the state as it was; canopy_model_advance(0.01) (one sub-step: the bound
 * is off) succeeds in 2 sub-steps and ends exactly (bit for bit) where two
 * canopy_model_step(0.005) do. */
CANOPY_TEST(implicit_step_halved_when_newton_fails)
{
    canopy_model *whole = pressed_membrane(), *advanced = pressed_membrane(),
                 *halves = pressed_membrane();
    ASSERT_TRUE(whole != NULL && advanced != NULL && halves != NULL);
    if (whole == NULL || advanced == NULL || halves == NULL) return;
    enum { N = 36 };
    double x0[3 * N], x[3 * N], v[3 * N], xh[3 * N], vh[3 * N];
    ASSERT_OK(whole, canopy_model_get_positions(whole, x0, N));

    ASSERT_STATUS(CANOPY_ERR_NOT_CONVERGED, canopy_model_step(whole, 0.01));
    printf("one step of 0.01 s: %s\n", canopy_model_message(whole));
    ASSERT_OK(whole, canopy_model_get_positions(whole, x, N));
    ASSERT_TRUE(memcmp(x, x0, sizeof x) == 0);
    ASSERT_TRUE(canopy_model_time(whole) == 0.0);

    int substeps = 0;
    ASSERT_OK(advanced, canopy_model_advance(advanced, 0.01, &substeps));
    ASSERT_OK(halves, canopy_model_step(halves, 0.005));
    ASSERT_OK(halves, canopy_model_step(halves, 0.005));
    ASSERT_OK(advanced, canopy_model_get_positions(advanced, x, N));
    ASSERT_OK(advanced, canopy_model_get_velocities(advanced, v, N));
    ASSERT_OK(halves, canopy_model_get_positions(halves, xh, N));
    ASSERT_OK(halves, canopy_model_get_velocities(halves, vh, N));
    double lift = 0.0;
    for (int i = 0; i < N; ++i)
        if (x[3 * i + 2] > lift) lift = x[3 * i + 2];
    printf("advance(0.01): %d sub-steps, t = %g s, largest lift %.4g mm\n",
           substeps, canopy_model_time(advanced), 1e3 * lift);
    ASSERT_TRUE(substeps == 2);
    ASSERT_TRUE(fabs(canopy_model_time(advanced) - 0.01) <= 1e-15);
    ASSERT_TRUE(lift > 0.0);
    ASSERT_TRUE(memcmp(x, xh, sizeof x) == 0);
    ASSERT_TRUE(memcmp(v, vh, sizeof v) == 0);
    canopy_model_destroy(&whole);
    canopy_model_destroy(&advanced);
    canopy_model_destroy(&halves);
}
