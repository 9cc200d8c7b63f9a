/* test_pressure_frozen.c — the pressure jump's load held over a step on the shape at its start (canopy_model_set_pressure_frozen) against the follower load. */
#include "test.h"

#include <math.h>

/* One triangle: nodes 0 (0,0,0) and 1 (1,0,0) fixed, node 2 (0,1,0) free
 * with mass m, no springs, gravity off, RK4, pressure jump dp. Its normal
 * is +z, its area 1/2, so node 2 starts with the force dp / 6 along z. */
static canopy_status hinged_triangle(canopy_model **out, double m, double dp)
{
    canopy_status st = canopy_model_create(out);
    if (st) return st;
    canopy_model *model = *out;
    const double zero_g[3] = {0.0, 0.0, 0.0};
    const double a[3] = {0.0, 0.0, 0.0}, b[3] = {1.0, 0.0, 0.0},
                 c[3] = {0.0, 1.0, 0.0};
    if ((st = canopy_model_set_gravity(model, zero_g)) ||
        (st = canopy_model_add_node(model, a, m, CANOPY_GROUP_FABRIC, NULL)) ||
        (st = canopy_model_add_node(model, b, m, CANOPY_GROUP_FABRIC, NULL)) ||
        (st = canopy_model_add_node(model, c, m, CANOPY_GROUP_FABRIC, NULL)) ||
        (st = canopy_model_add_triangle(model, 0, 1, 2, NULL)) ||
        (st = canopy_model_set_fixed(model, 0, 1)) ||
        (st = canopy_model_set_fixed(model, 1, 1)) ||
        (st = canopy_model_set_integrator(model, "rk4")) ||
        (st = canopy_model_set_pressure_jump(model, &dp, 1)))
        return st;
    return CANOPY_OK;
}

/* Held: node 2 feels the constant force dp/6 along z for the whole step,
 * so one RK4 step (exact for a constant acceleration) takes it to
 * z = (dp / 6) t^2 / (2 m) with y = 1 (to rounding). Following the
 * triangle instead, the force tilts towards -y as node 2 rises and y
 * drops: with z ~ 0.5 m by the step's end the normal turns by ~25 deg, and
 * y falls by more than 1 %. After the step, get_forces gives the load on
 * the current shape either way (the tilted normal). */
CANOPY_TEST(pressure_frozen_holds_the_step_start_load)
{
    const double m = 1.0, dp = 6.0, dt = 1.0;   /* force 1 N, z = 0.5 m */
    double x_held[9], x_follow[9], f[9];
    canopy_model *model = NULL;

    ASSERT_OK(model, hinged_triangle(&model, m, dp));
    ASSERT_TRUE(canopy_model_pressure_frozen(model) == 0);
    ASSERT_OK(model, canopy_model_set_pressure_frozen(model, 1));
    ASSERT_TRUE(canopy_model_pressure_frozen(model) == 1);
    ASSERT_OK(model, canopy_model_step(model, dt));
    ASSERT_OK(model, canopy_model_get_positions(model, x_held, 3));
    ASSERT_OK(model, canopy_model_get_forces(model, f, 3));
    canopy_model_destroy(&model);

    ASSERT_OK(model, hinged_triangle(&model, m, dp));
    ASSERT_OK(model, canopy_model_step(model, dt));
    ASSERT_OK(model, canopy_model_get_positions(model, x_follow, 3));
    canopy_model_destroy(&model);

    const double z = (dp / 6.0) * dt * dt / (2.0 * m);
    printf("  held: node 2 at (%.12g, %.12g, %.12g), exact (0, 1, %g); "
           "following: (%.6g, %.6g, %.6g); force after the held step "
           "(%.6g, %.6g, %.6g) N\n", x_held[6], x_held[7], x_held[8], z,
           x_follow[6], x_follow[7], x_follow[8], f[6], f[7], f[8]);
    ASSERT_TRUE(fabs(x_held[6]) < 1e-14);
    ASSERT_TRUE(fabs(x_held[7] - 1.0) < 1e-14);
    ASSERT_TRUE(fabs(x_held[8] - z) < 1e-14);
    ASSERT_TRUE(x_follow[7] < 0.99);
    /* the load on the shape after the step: normal (0, -z, 1) / |.|,
     * area |(1,0,0) x (0,1,z)| / 2 = sqrt(1 + z^2) / 2 */
    ASSERT_TRUE(fabs(f[7] - dp / 6.0 * -z) < 1e-12);
    ASSERT_TRUE(fabs(f[8] - dp / 6.0) < 1e-12);
}

/* A NULL model is refused; the getter of a NULL model says 0. */
CANOPY_TEST(pressure_frozen_refuses_a_null_model)
{
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_pressure_frozen(NULL, 1));
    ASSERT_TRUE(canopy_model_pressure_frozen(NULL) == 0);
}
