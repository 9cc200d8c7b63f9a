/* test_line_tension.c — a damped line never pushes, its tension is continuous where it goes taut, and HHT converges through a line snapping taut. */
#include "test.h"

/* A line of rest length 1 from a fixed anchor at the origin to a free node
 * on the -z axis: tension-only spring k, dashpot c. */
static canopy_model *hanging_line(double k, double c, double mass)
{
    canopy_model *m = NULL;
    if (canopy_model_create(&m) != CANOPY_OK) return NULL;
    const double top[3] = {0.0, 0.0, 0.0}, end[3] = {0.0, 0.0, -1.0};
    int a, b;
    if (canopy_model_add_node(m, top, 0.0, CANOPY_GROUP_LINE, &a) != CANOPY_OK ||
        canopy_model_set_fixed(m, a, 1) != CANOPY_OK ||
        canopy_model_add_node(m, end, mass, CANOPY_GROUP_PAYLOAD, &b) != CANOPY_OK ||
        canopy_model_add_spring(m, a, b, k, c, CANOPY_SPRING_TENSION_ONLY,
                                CANOPY_GROUP_LINE, NULL) != CANOPY_OK ||
        canopy_model_set_payload_node(m, b) != CANOPY_OK) {
        canopy_model_destroy(&m);
        return NULL;
    }
    return m;
}

/* The line's tension with the free end at depth 1 + stretch moving down at
 * speed rate (the stretch rate). */
static double tension_at(canopy_model *m, double stretch, double rate)
{
    const double x[6] = {0.0, 0.0, 0.0, 0.0, 0.0, -(1.0 + stretch)};
    const double v[6] = {0.0, 0.0, 0.0, 0.0, 0.0, -rate};
    double T = NAN;
    if (canopy_model_set_positions(m, x, 2) != CANOPY_OK ||
        canopy_model_set_velocities(m, v, 2) != CANOPY_OK ||
        canopy_model_get_tensions(m, &T, 1) != CANOPY_OK)
        return NAN;
    return T;
}

/* k = 5000 N/m, c = 0.1 N s/m (damping time c/k = 2e-5 s).
 * - Taut by 1 mm (k s = 5 N) but shortening at 100 m/s (c rate = -10 N):
 *   the spring-dashpot force would push with 5 N; a line carries 0.
 * - Going taut at 1 m/s: across s = -1e-6 .. +1e-6 m the tension may change
 *   by k 2e-6 = 0.01 N at most (it is Lipschitz in the stretch), not jump by
 *   the dashpot's c rate = 0.1 N.
 * - Slack by 1 mm and separating at 1 m/s (k s + c rate = -4.9 N): 0.
 * - The node force is the tension along the line: f_z = +T at the free end. */
CANOPY_TEST(line_tension_law)
{
    canopy_model *m = hanging_line(5000.0, 0.1, 1.0);
    ASSERT_TRUE(m != NULL);
    if (m == NULL) return;
    const double no_gravity[3] = {0.0, 0.0, 0.0};
    ASSERT_OK(m, canopy_model_set_gravity(m, no_gravity));
    const double pushing = tension_at(m, 1e-3, -100.0);
    const double below = tension_at(m, -1e-6, 1.0);
    const double above = tension_at(m, 1e-6, 1.0);
    const double slack = tension_at(m, -1e-3, 1.0);
    const double taut = tension_at(m, 1e-3, 1.0);
    double f[6];
    ASSERT_OK(m, canopy_model_get_forces(m, f, 2));
    printf("T: shortening taut line %.4g N, going taut %.6g -> %.6g N, "
           "slack %.4g N, taut %.6g N (node force %.6g N)\n",
           pushing, below, above, slack, taut, f[5]);
    ASSERT_TRUE(pushing == 0.0);
    ASSERT_TRUE(fabs(above - below) <= 0.01 * (1.0 + 1e-9));
    ASSERT_TRUE(fabs(above - (5000.0 * 1e-6 + 0.1)) <= 1e-12);
    ASSERT_TRUE(slack == 0.0);
    ASSERT_TRUE(fabs(taut - 5.1) <= 1e-12);
    ASSERT_TRUE(fabs(f[5] - taut) <= 1e-12);
    canopy_model_destroy(&m);
}

/* A 1 kg payload 5 cm above the end of its slack line, falling at 3 m/s,
 * is caught by the line (k = 5000 N/m, c = 30 N s/m, damping ratio
 * c / (2 sqrt(k m)) = 0.21) under gravity 9.81; HHT alpha = -0.3 with
 * dt = 0.03 s (omega dt = 2.1). Every step's Newton solve converges to
 * 1e-10: with the dashpot switched on at l = l0 (the law before
 * canopy_line_tension) the residual jumps there and Newton stalls at
 * relative residual 0.35 in step 16, where the bouncing payload's line goes
 * taut again. The line never pushes, and after 3 s (45
 * of the line's damping times 1 / (zeta omega) = 0.067 s) the payload hangs
 * still at the static stretch m g / k = 1.962 mm, to 1 % of it. */
CANOPY_TEST(hht_line_snaps_taut)
{
    const double k = 5000.0, c = 30.0, mass = 1.0, g = 9.81, dt = 0.03;
    canopy_model *m = hanging_line(k, c, mass);
    ASSERT_TRUE(m != NULL);
    if (m == NULL) return;
    const double gravity[3] = {0.0, 0.0, -g};
    const double x[6] = {0.0, 0.0, 0.0, 0.0, 0.0, -0.95};
    const double v[6] = {0.0, 0.0, 0.0, 0.0, 0.0, -3.0};
    ASSERT_OK(m, canopy_model_set_positions(m, x, 2));
    ASSERT_OK(m, canopy_model_set_velocities(m, v, 2));
    ASSERT_OK(m, canopy_model_set_gravity(m, gravity));
    ASSERT_OK(m, canopy_model_set_integrator(m, "hht"));
    ASSERT_OK(m, canopy_model_set_hht_alpha(m, -0.3));
    ASSERT_OK(m, canopy_model_set_implicit_controls(m, 1e-10, 50));
    double min_T = 0.0, max_T = 0.0;
    const int steps = 100;
    for (int s = 0; s < steps; ++s) {
        ASSERT_OK(m, canopy_model_step(m, dt));
        double T;
        ASSERT_OK(m, canopy_model_get_tensions(m, &T, 1));
        if (T < min_T) min_T = T;
        if (T > max_T) max_T = T;
    }
    double xp[3], vp[3];
    ASSERT_OK(m, canopy_model_payload_state(m, xp, vp));
    const double stretch = -xp[2] - 1.0, expected = mass * g / k;
    printf("largest tension %.4g N; after %.3g s the stretch is %.5g mm "
           "(m g / k = %.5g mm), speed %.3g m/s\n",
           max_T, steps * dt, 1e3 * stretch, 1e3 * expected, fabs(vp[2]));
    ASSERT_TRUE(min_T >= 0.0);
    ASSERT_TRUE(max_T > 2.0 * mass * g); /* the catch really jerked the line */
    ASSERT_TRUE(fabs(stretch - expected) <= 0.01 * expected);
    canopy_model_destroy(&m);
}
