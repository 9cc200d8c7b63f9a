/* test_implicit_dashpots.c — spring dashpots leave the frequency bound of the integrators that solve them implicitly, which stay accurate at the undamped bound's step. */
#include "test.h"

/* An overdamped oscillator: mass m = 2 on a spring k = 3 with a dashpot
 * c = 100 (Model-II, along x, tied to a fixed anchor 10 m away so that the
 * motion is linear), x0 = 2, v0 = 0. Closed form with g = c/2m = 25,
 * w0^2 = k/m: x = A e^{r1 t} + B e^{r2 t}, r = -g +- sqrt(g^2 - w0^2)
 * (r1 = -0.0300, r2 = -49.97), A = x0 r2/(r2 - r1), B = -x0 r1/(r2 - r1).
 * The Gershgorin bound (canopy.h): omega^2 = 2k/m = 3, rho = 2c/m = 100. */

static const double K = 3.0, M = 2.0, C = 100.0, X0 = 2.0;

static double exact(double t)
{
    const double g = C / (2.0 * M), d = sqrt(g * g - K / M);
    const double r1 = -g + d, r2 = -g - d;
    return X0 * (r2 * exp(r1 * t) - r1 * exp(r2 * t)) / (r2 - r1);
}

static canopy_status oscillator(canopy_model **out, const char *integrator,
                                double c)
{
    canopy_model *m = NULL;
    canopy_status st = canopy_model_create(&m);
    if (st != CANOPY_OK) return st;
    const double anchor[3] = {-10.0, 0.0, 0.0}, rest[3] = {0.0, 0.0, 0.0};
    const double zero_g[3] = {0.0, 0.0, 0.0};
    const double x0[6] = {-10.0, 0.0, 0.0, X0, 0.0, 0.0};
    int a, b;
    if ((st = canopy_model_add_node(m, anchor, 0.0, CANOPY_GROUP_OTHER, &a)) ||
        (st = canopy_model_add_node(m, rest, M, CANOPY_GROUP_OTHER, &b)) ||
        (st = canopy_model_set_fixed(m, a, 1)) ||
        (st = canopy_model_add_spring(m, a, b, K, c, CANOPY_SPRING_MODEL_II,
                                      CANOPY_GROUP_OTHER, NULL)) ||
        (st = canopy_model_set_gravity(m, zero_g)) ||
        (st = canopy_model_set_integrator(m, integrator)) ||
        (st = canopy_model_set_implicit_controls(m, 1e-12, 50)) ||
        (st = canopy_model_set_positions(m, x0, 2))) {
        canopy_model_destroy(&m);
        return st;
    }
    *out = m;
    return CANOPY_OK;
}

/* The bound: HHT and Newmark leave the dashpot out (sqrt 3 whatever c);
 * RK4, which takes it explicitly, keeps rho/2 + sqrt(rho^2/4 + omega^2). */
CANOPY_TEST(implicit_dashpots_leave_the_frequency_bound)
{
    const char *names[3] = {"hht", "newmark", "rk4"};
    for (int k = 0; k < 3; ++k) {
        canopy_model *m = NULL;
        double omega = 0.0;
        ASSERT_OK(m, oscillator(&m, names[k], C));
        ASSERT_OK(m, canopy_model_frequency_bound(m, &omega));
        const double rho = 2.0 * C / M, w2 = 2.0 * K / M;
        const double expected =
            k < 2 ? sqrt(w2) : 0.5 * rho + sqrt(0.25 * rho * rho + w2);
        printf("  %s: bound %.6g rad/s (expected %.6g)\n", names[k], omega,
               expected);
        ASSERT_NEAR(omega, expected, 1e-12 * expected);
        canopy_model_destroy(&m);
    }
}

/* HHT at the undamped bound's step with max_omega_dt 1 (h = 1/sqrt 3, so
 * 20 advances of 0.5 s take one sub-step each) and 0.5 (two each) follows
 * the closed form at t = 10 s at its formal order: log2 of the two errors'
 * ratio within 2 +- 0.3, as in test_oscillator_order.c. So the dashpot's
 * stiff mode (r2 h = -25 at h = 0.5) does not spoil the step that the
 * slow mode (r1 h = 0.015) sets. RK4 at the coarser step is far outside its
 * stability limit (Lambda h = 58 against 2.8) and does not follow. */
static double hht_error(double max_omega_dt, int *substeps)
{
    canopy_model *m = NULL;
    double err = NAN;
    if (oscillator(&m, "hht", C) != CANOPY_OK) return NAN;
    if (canopy_model_set_max_omega_dt(m, max_omega_dt) != CANOPY_OK)
        goto done;
    *substeps = 0;
    for (int s = 0; s < 20; ++s) {
        int n = 0;
        if (canopy_model_advance(m, 0.5, &n) != CANOPY_OK) goto done;
        *substeps += n;
    }
    double x[6];
    if (canopy_model_get_positions(m, x, 2) != CANOPY_OK) goto done;
    err = fabs(x[3] - exact(10.0));
done:
    canopy_model_destroy(&m);
    return err;
}

CANOPY_TEST(implicit_dashpots_hht_follows_the_overdamped_oscillator)
{
    int n1 = 0, n2 = 0;
    const double e1 = hht_error(1.0, &n1), e2 = hht_error(0.5, &n2);
    const double order = log2(e1 / e2);
    printf("  hht: %d sub-steps over 10 s, error %.3g x0; %d sub-steps, "
           "%.3g x0; order %.3f\n", n1, e1 / X0, n2, e2 / X0, order);
    ASSERT_TRUE(n1 == 20 && n2 == 40);
    ASSERT_NEAR(order, 2.0, 0.3);

    canopy_model *m = NULL;
    ASSERT_OK(m, oscillator(&m, "rk4", C));
    int failed = 0;
    for (int s = 0; s < 20 && !failed; ++s)
        failed = canopy_model_step(m, 1.0 / sqrt(3.0)) != CANOPY_OK;
    double xr[6];
    ASSERT_OK(m, canopy_model_get_positions(m, xr, 2));
    const double err_rk4 = fabs(xr[3] - exact(20.0 / sqrt(3.0)));
    printf("  rk4 at h = 1/sqrt 3: %s, error %.3g x0\n",
           failed ? "diverged" : "ran", err_rk4 / X0);
    ASSERT_TRUE(failed || !(err_rk4 < e1));
    canopy_model_destroy(&m);
}
