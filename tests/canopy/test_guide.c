/* test_guide.c — a node on a guide (canopy_model_set_guide) moves along its wire alone, with the axial dynamics of a one-dimensional reference, in every integrator that supports guides. */
#include "test.h"
#include "test_flapping_sheet_fixture.h"

/* A bead of mass 1 on a vertical wire through the origin, tied by a
 * spring (k = 100 N/m, rest length 1) to a fixed node at (1, 0, 0), under
 * gravity -9.81 z. Released at rest at the origin (the spring at its rest
 * length), it oscillates along z with
 *     z'' = -g - k (L - 1) z / L,   L = sqrt(1 + z^2),
 * while the wire takes the spring's pull towards x. The reference is that
 * equation integrated by classical RK4 at a step 1000 times finer than the
 * library's; its own error (order 4) is far below the tolerances below. */
static double axial_accel(double z)
{
    const double L = sqrt(1.0 + z * z);
    return -9.81 - 100.0 * (L - 1.0) * z / L;
}

static void reference(double t_end, int steps, double *z_out, double *w_out)
{
    const double h = t_end / steps;
    double z = 0.0, w = 0.0;
    for (int s = 0; s < steps; ++s) {
        const double k1z = w, k1w = axial_accel(z);
        const double k2z = w + 0.5 * h * k1w, k2w = axial_accel(z + 0.5 * h * k1z);
        const double k3z = w + 0.5 * h * k2w, k3w = axial_accel(z + 0.5 * h * k2z);
        const double k4z = w + h * k3w, k4w = axial_accel(z + h * k3z);
        z += h / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
        w += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
    }
    *z_out = z;
    *w_out = w;
}

/* Build the bead and its anchor; bead index in *bead. */
static canopy_model *bead_on_wire(const char *integrator, int *bead)
{
    canopy_model *m = NULL;
    if (canopy_model_create(&m) != CANOPY_OK) return NULL;
    const double anchor[3] = {1.0, 0.0, 0.0}, origin[3] = {0.0, 0.0, 0.0};
    const double g[3] = {0.0, 0.0, -9.81}, axis[3] = {0.0, 0.0, 2.5};
    int a;
    if (canopy_model_add_node(m, anchor, 0.0, CANOPY_GROUP_LINE, &a) ||
        canopy_model_set_fixed(m, a, 1) ||
        canopy_model_add_node(m, origin, 1.0, CANOPY_GROUP_PAYLOAD, bead) ||
        canopy_model_add_spring(m, a, *bead, 100.0, 0.0,
                                CANOPY_SPRING_MODEL_II, CANOPY_GROUP_LINE,
                                NULL) ||
        canopy_model_set_gravity(m, g) ||
        canopy_model_set_guide(m, *bead, axis) ||
        canopy_model_set_integrator(m, integrator)) {
        canopy_model_destroy(&m);
        return NULL;
    }
    return m;
}

/* Run to t_end in steps of dt; the bead's final z and velocity, and the
 * largest |x|, |y| and across-wire speed it ever had. */
static int run_bead(const char *integrator, double dt, double t_end,
                    double *z, double *w, double *across)
{
    int bead;
    canopy_model *m = bead_on_wire(integrator, &bead);
    if (m == NULL) return 0;
    const int steps = (int)(t_end / dt + 0.5);
    double x[6], v[6];
    *across = 0.0;
    for (int s = 0; s < steps; ++s) {
        if (canopy_model_step(m, dt) != CANOPY_OK) {
            printf("%s: step %d failed: %s\n", integrator, s,
                   canopy_model_message(m));
            canopy_model_destroy(&m);
            return 0;
        }
        canopy_model_get_positions(m, x, 2);
        canopy_model_get_velocities(m, v, 2);
        const double *xb = x + 3 * bead, *vb = v + 3 * bead;
        *across = fmax(*across, fmax(fmax(fabs(xb[0]), fabs(xb[1])),
                                     fmax(fabs(vb[0]), fabs(vb[1]))));
    }
    *z = x[3 * bead + 2];
    *w = v[3 * bead + 2];
    canopy_model_destroy(&m);
    return 1;
}

/* The bead stays on its wire exactly (the guide removes every across-wire
 * increment: |x|, |y| and their speeds are exactly 0) and follows the
 * axial reference: rk4 to 1e-9 m at dt = 1e-3 (order 4: its error there
 * is ~2e-11 m); hht (alpha -0.3) and newmark at dt = 2e-3 and 1e-3, with
 * the error falling by the factor 4 of a second-order method (between 3
 * and 5). */
CANOPY_TEST(guide_bead_on_wire)
{
    const double t_end = 1.0;
    double z_ref, w_ref;
    reference(t_end, 1000000, &z_ref, &w_ref);
    printf("reference at t = 1: z = %.9f m, w = %.9f m/s\n", z_ref, w_ref);

    double z, w, across;
    ASSERT_TRUE(run_bead("rk4", 1e-3, t_end, &z, &w, &across));
    printf("rk4 dt 1e-3: z error %.3g m, w error %.3g m/s, across %.3g\n",
           z - z_ref, w - w_ref, across);
    ASSERT_TRUE(fabs(z - z_ref) < 1e-9 && fabs(w - w_ref) < 1e-8);
    ASSERT_TRUE(across == 0.0);

    const char *implicit[] = {"hht", "newmark"};
    for (int k = 0; k < 2; ++k) {
        double z1, w1, z2, w2, a1, a2;
        ASSERT_TRUE(run_bead(implicit[k], 2e-3, t_end, &z1, &w1, &a1));
        ASSERT_TRUE(run_bead(implicit[k], 1e-3, t_end, &z2, &w2, &a2));
        const double e1 = fabs(z1 - z_ref), e2 = fabs(z2 - z_ref);
        printf("%s: z error %.3g m (dt 2e-3), %.3g m (dt 1e-3): ratio %.2f; "
               "across %.3g\n", implicit[k], e1, e2, e1 / e2, fmax(a1, a2));
        ASSERT_TRUE(e2 < 1e-3);
        ASSERT_TRUE(e1 / e2 > 3.0 && e1 / e2 < 5.0);
        ASSERT_TRUE(a1 == 0.0 && a2 == 0.0);
    }
}

/* Rejections leave the model as it was: a bad node, a non-finite axis;
 * a guided node that is also fixed, or the kang integrator, fail at the
 * first step with a message; a NULL axis takes the node off its guide. */
CANOPY_TEST(guide_rejections)
{
    int bead;
    canopy_model *m = bead_on_wire("rk4", &bead);
    ASSERT_TRUE(m != NULL);
    if (m == NULL) return;
    const double nan_axis[3] = {NAN, 0.0, 1.0};
    double e[3];
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_set_guide(m, 7, nan_axis));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_guide(m, bead, nan_axis));
    ASSERT_TRUE(strstr(canopy_model_message(m), "not finite") != NULL);
    ASSERT_OK(m, canopy_model_get_guide(m, bead, e));
    ASSERT_TRUE(e[0] == 0.0 && e[1] == 0.0 && e[2] == 1.0);

    ASSERT_OK(m, canopy_model_set_integrator(m, "kang"));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_step(m, 1e-3));
    printf("kang: %s\n", canopy_model_message(m));
    ASSERT_TRUE(strstr(canopy_model_message(m), "guide") != NULL);
    ASSERT_OK(m, canopy_model_set_integrator(m, "rk4"));
    ASSERT_OK(m, canopy_model_set_fixed(m, bead, 1));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_step(m, 1e-3));
    ASSERT_TRUE(strstr(canopy_model_message(m), "fixed and on a guide") != NULL);
    ASSERT_OK(m, canopy_model_set_fixed(m, bead, 0));

    /* off the guide: the spring pulls it towards the anchor */
    ASSERT_OK(m, canopy_model_set_guide(m, bead, NULL));
    ASSERT_OK(m, canopy_model_get_guide(m, bead, e));
    ASSERT_TRUE(e[0] == 0.0 && e[1] == 0.0 && e[2] == 0.0);
    for (int s = 0; s < 200; ++s) ASSERT_OK(m, canopy_model_step(m, 1e-3));
    double x[6];
    ASSERT_OK(m, canopy_model_get_positions(m, x, 2));
    printf("off the guide after 0.2 s: x = %.4f m\n", x[3 * bead]);
    ASSERT_TRUE(x[3 * bead] > 1e-3);
    canopy_model_destroy(&m);
}

/* A guided node inside cloth with implicit hinge dashpots (1e4 /s) under
 * hht: the dashpots' velocity update and the Newton steps both keep it on
 * its guide, a wire tilted off the sheet's normal. The flapping sheet
 * (test_flapping_sheet_fixture.h), the node nearest its centre guided
 * along (0.3, 0, 1), a 2 Pa pressure jump on the sheet; after 20 steps
 * of 2 ms it has moved along the wire and across it by no more than the
 * round-off of its coordinates (1e-14 m: ~100 ulp of 0.5 m). */
CANOPY_TEST(guide_in_cloth_with_implicit_hinge_dashpots)
{
    enum { N_MAX = 200 };
    canopy_model *m = NULL;
    ASSERT_OK(m, flapping_sheet(&m, 1e4, 1));
    const int n = canopy_model_node_count(m);
    ASSERT_TRUE(n <= N_MAX);
    double x0[3 * N_MAX], x[3 * N_MAX];
    ASSERT_OK(m, canopy_model_get_positions(m, x0, n));
    int centre = 0;
    double best = 1e300;
    for (int i = 0; i < n; ++i) {
        const double d = hypot(x0[3 * i] - 0.5, x0[3 * i + 1] - 0.5);
        if (d < best) { best = d; centre = i; }
    }
    const double axis[3] = {0.3, 0.0, 1.0};
    ASSERT_OK(m, canopy_model_set_guide(m, centre, axis));
    ASSERT_OK(m, canopy_model_set_integrator(m, "hht"));
    const int nt = canopy_model_triangle_count(m);
    double dp[2 * N_MAX];
    ASSERT_TRUE(nt <= 2 * N_MAX);
    for (int t = 0; t < nt; ++t) dp[t] = 2.0;
    ASSERT_OK(m, canopy_model_set_pressure_jump(m, dp, nt));
    for (int s = 0; s < 20; ++s) ASSERT_OK(m, canopy_model_step(m, 2e-3));
    ASSERT_OK(m, canopy_model_get_positions(m, x, n));
    double e[3], d[3];
    ASSERT_OK(m, canopy_model_get_guide(m, centre, e));
    for (int k = 0; k < 3; ++k) d[k] = x[3 * centre + k] - x0[3 * centre + k];
    const double along = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    const double across = sqrt(pow(d[0] - along * e[0], 2) +
                               pow(d[1] - along * e[1], 2) +
                               pow(d[2] - along * e[2], 2));
    double moved = 0.0;
    for (int k = 0; k < 3 * n; ++k) moved = fmax(moved, fabs(x[k] - x0[k]));
    printf("guided node %d: %.4g m along its wire, %.3g m across; the "
           "sheet moved up to %.4g m\n", centre, along, across, moved);
    ASSERT_TRUE(fabs(along) > 1e-4);
    ASSERT_TRUE(across <= 1e-14);
    canopy_model_destroy(&m);
}

/* A model's state copied into another with canopy_model_set_state (as a
 * parallel restart copies the master's to the other ranks) is the same
 * state, bit for bit, and so is the next step of both; the setters one by
 * one project a guided node's vectors onto its guide again, which changes
 * the carried acceleration's last bits on a tilted wire and can turn a +0
 * component into -0 on the vertical one (printed, not asserted). The bead on a
 * wire tilted along (0.3, 0, 1) and on the vertical wire, after 30 hht
 * steps of 2 ms. Bad input (a NaN, a NULL acceleration that is said to be
 * valid, a wrong count, a NaN time) is refused and changes nothing. */
static int same_bits(const double *a, const double *b, int count)
{
    return memcmp(a, b, sizeof(double) * (size_t)count) == 0;
}

CANOPY_TEST(guide_state_copied_bit_for_bit)
{
    const double tilted[3] = {0.3, 0.0, 1.0};
    for (int wire = 0; wire < 2; ++wire) {
        int bead, bead2;
        canopy_model *a = bead_on_wire("hht", &bead);
        canopy_model *b = bead_on_wire("hht", &bead2);
        ASSERT_TRUE(a != NULL && b != NULL);
        if (a == NULL || b == NULL) {
            canopy_model_destroy(&a);
            canopy_model_destroy(&b);
            return;
        }
        if (wire == 0) {
            ASSERT_OK(a, canopy_model_set_guide(a, bead, tilted));
            ASSERT_OK(b, canopy_model_set_guide(b, bead2, tilted));
        }
        for (int s = 0; s < 30; ++s) ASSERT_OK(a, canopy_model_step(a, 2e-3));
        double x[6], v[6], acc[6], xb[6], vb[6], accb[6];
        int valid = 0, validb = 0;
        ASSERT_OK(a, canopy_model_get_positions(a, x, 2));
        ASSERT_OK(a, canopy_model_get_velocities(a, v, 2));
        ASSERT_OK(a, canopy_model_get_acceleration_state(a, acc, 2, &valid));
        ASSERT_TRUE(valid);
        const double t = canopy_model_time(a);

        /* one by one: the acceleration projected again */
        ASSERT_OK(b, canopy_model_set_positions(b, x, 2));
        ASSERT_OK(b, canopy_model_set_velocities(b, v, 2));
        ASSERT_OK(b, canopy_model_set_acceleration_state(b, acc, 2, valid));
        ASSERT_OK(b, canopy_model_get_acceleration_state(b, accb, 2, &validb));
        printf("%s wire: the setters one by one keep the acceleration bit "
               "for bit: %s\n", wire == 0 ? "tilted" : "vertical",
               same_bits(acc, accb, 6) ? "yes" : "no");

        /* bad input: refused, nothing changed */
        const double before = canopy_model_time(b);
        double bad[6];
        memcpy(bad, acc, sizeof bad);
        bad[5] = NAN;
        ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                      canopy_model_set_state(b, t, x, v, bad, 1, 2));
        ASSERT_TRUE(strstr(canopy_model_message(b), "acceleration") != NULL);
        ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                      canopy_model_set_state(b, t, x, v, NULL, 1, 2));
        ASSERT_STATUS(CANOPY_ERR_RANGE,
                      canopy_model_set_state(b, t, x, v, acc, 1, 3));
        ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                      canopy_model_set_state(b, NAN, x, v, acc, 1, 2));
        ASSERT_OK(b, canopy_model_get_acceleration_state(b, bad, 2, &validb));
        ASSERT_TRUE(same_bits(bad, accb, 6) && validb == valid);
        ASSERT_TRUE(canopy_model_time(b) == before);

        /* the whole state at once */
        ASSERT_OK(b, canopy_model_set_state(b, t, x, v, acc, valid, 2));
        ASSERT_OK(b, canopy_model_get_positions(b, xb, 2));
        ASSERT_OK(b, canopy_model_get_velocities(b, vb, 2));
        ASSERT_OK(b, canopy_model_get_acceleration_state(b, accb, 2, &validb));
        ASSERT_TRUE(same_bits(x, xb, 6) && same_bits(v, vb, 6) &&
                    same_bits(acc, accb, 6) && validb == valid &&
                    canopy_model_time(b) == t);
        ASSERT_OK(a, canopy_model_step(a, 2e-3));
        ASSERT_OK(b, canopy_model_step(b, 2e-3));
        ASSERT_OK(a, canopy_model_get_velocities(a, v, 2));
        ASSERT_OK(b, canopy_model_get_velocities(b, vb, 2));
        ASSERT_OK(a, canopy_model_get_positions(a, x, 2));
        ASSERT_OK(b, canopy_model_get_positions(b, xb, 2));
        printf("%s wire: set_state's copy and its next step bit for bit: "
               "%s\n", wire == 0 ? "tilted" : "vertical",
               same_bits(v, vb, 6) && same_bits(x, xb, 6) ? "yes" : "no");
        ASSERT_TRUE(same_bits(v, vb, 6) && same_bits(x, xb, 6));

        /* without an acceleration: NULL is fine, and none is carried */
        ASSERT_OK(b, canopy_model_set_state(b, t, x, v, NULL, 0, 2));
        ASSERT_OK(b, canopy_model_get_acceleration_state(b, accb, 2, &validb));
        ASSERT_TRUE(validb == 0);
        canopy_model_destroy(&a);
        canopy_model_destroy(&b);
    }
}
