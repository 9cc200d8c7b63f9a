/* test_oscillator_order.c — every integrator converges to the seed 002 appendix A oscillator at its formal order. */
#include "test.h"

#include <string.h>

/* Mass m = 2 on a spring k = 3 (Model-II, along x, tied to a fixed anchor
 * 10 m away so the motion is exactly linear), x0 = 2, v0 = 0 (seed 002
 * appendix A, eqs. 73-81). Damped case: dashpot c = 1 on the spring
 * (damping ratio 0.204). Closed form with g = c/2m, wd = sqrt(k/m - g^2):
 *   x = e^{-g t} (x0 cos wd t + (g x0 / wd) sin wd t).
 * Error at T = 10 s: |x - x_exact| + |v - v_exact| / omega0. The measured
 * order log2(e(h) / e(h/2)) must be within +-0.3 of the formal order p. The
 * step h is chosen per order so that the error is in its asymptotic range
 * and far above round-off: h = 0.005 (p = 1), 0.01 (p = 2), 0.05 (p = 4),
 * i.e. omega0 h = 0.006 ... 0.06. */

static const double K = 3.0, M = 2.0, X0 = 2.0, T_END = 10.0;

static void exact(double c, double t, double *x, double *v)
{
    const double g = c / (2.0 * M), wd = sqrt(K / M - g * g);
    const double A = X0, B = g * X0 / wd, e = exp(-g * t);
    const double cs = cos(wd * t), sn = sin(wd * t);
    *x = e * (A * cs + B * sn);
    *v = e * ((-g * A + wd * B) * cs + (-g * B - wd * A) * sn);
}

static double error_at(const char *integrator, double c, double dt)
{
    canopy_model *m = NULL;
    double err = NAN;
    if (canopy_model_create(&m)) return NAN;
    const double anchor[3] = {-10.0, 0.0, 0.0}, rest[3] = {0.0, 0.0, 0.0};
    const double zero_g[3] = {0.0, 0.0, 0.0};
    int a, b;
    if (canopy_model_add_node(m, anchor, 0.0, CANOPY_GROUP_OTHER, &a) ||
        canopy_model_add_node(m, rest, M, CANOPY_GROUP_OTHER, &b) ||
        canopy_model_set_fixed(m, a, 1) ||
        canopy_model_add_spring(m, a, b, K, c, CANOPY_SPRING_MODEL_II,
                                CANOPY_GROUP_OTHER, NULL) ||
        canopy_model_set_gravity(m, zero_g) ||
        canopy_model_set_integrator(m, integrator) ||
        canopy_model_set_implicit_controls(m, 1e-12, 50))
        goto done;
    const double x0[6] = {-10.0, 0.0, 0.0, X0, 0.0, 0.0};
    if (canopy_model_set_positions(m, x0, 2)) goto done;
    const int n = (int)lround(T_END / dt);
    for (int s = 0; s < n; ++s)
        if (canopy_model_step(m, dt) != CANOPY_OK) {
            fprintf(stderr, "%s: %s\n", integrator, canopy_model_message(m));
            goto done;
        }
    double x[6], v[6], xe, ve;
    canopy_model_get_positions(m, x, 2);
    canopy_model_get_velocities(m, v, 2);
    exact(c, n * dt, &xe, &ve);
    err = fabs(x[3] - xe) + fabs(v[3] - ve) / sqrt(K / M);
done:
    canopy_model_destroy(&m);
    return err;
}

static void check_orders(double c)
{
    printf("%s oscillator (k=3, m=2, x0=2, c=%g), error at t=%g s:\n",
           c > 0 ? "damped" : "undamped", c, T_END);
    printf("  %-17s %5s %8s %11s %11s %9s\n", "integrator", "order", "h",
           "e(h)", "e(h/2)", "measured");
    for (int i = 0; i < canopy_integrator_count(); ++i) {
        const char *name = canopy_integrator_name(i);
        const int order = canopy_integrator_order(i);
        const double h = order == 1 ? 0.005 : order == 2 ? 0.01 : 0.05;
        const double e1 = error_at(name, c, h), e2 = error_at(name, c, h / 2);
        const double p = log2(e1 / e2);
        printf("  %-17s %5d %8.4f %11.3e %11.3e %9.3f\n", name, order, h, e1,
               e2, p);
        if (!(fabs(p - order) <= 0.3))
            CANOPY_TEST_FAIL_("%s (c=%g): measured order %.3f, formal %d",
                              name, c, p, order);
    }
}

CANOPY_TEST(oscillator_order_undamped) { check_orders(0.0); }
CANOPY_TEST(oscillator_order_damped) { check_orders(1.0); }
