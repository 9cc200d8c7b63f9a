/* test_triangle_added_mass.c — the triangles' consistent added mass (set_triangle_added_mass): none on a motion whose triangle mean is zero, a lumped mass's on a uniform one, and the input it refuses. */
#include "test.h"

#include <math.h>

/* One free triangle in the plane z = 0: three nodes of mass 0.1 kg joined
 * by springs of 100 N/m, no gravity, integrator hht (alpha -0.1) with
 * Newton converged to 1e-13. */
static canopy_model *triangle(void)
{
    canopy_model *m = NULL;
    if (canopy_model_create(&m) != CANOPY_OK) return NULL;
    const double x[3][3] = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8, 0}};
    for (int i = 0; i < 3; ++i)
        if (canopy_model_add_node(m, x[i], 0.1, CANOPY_GROUP_FABRIC, NULL) !=
            CANOPY_OK) {
            canopy_model_destroy(&m);
            return NULL;
        }
    const int ends[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (int s = 0; s < 3; ++s)
        if (canopy_model_add_spring(m, ends[s][0], ends[s][1], 100.0, 0.0,
                                    CANOPY_SPRING_MODEL_II, CANOPY_GROUP_FABRIC,
                                    NULL) != CANOPY_OK) {
            canopy_model_destroy(&m);
            return NULL;
        }
    const double no_gravity[3] = {0.0, 0.0, 0.0};
    if (canopy_model_add_triangle(m, 0, 1, 2, NULL) != CANOPY_OK ||
        canopy_model_set_gravity(m, no_gravity) != CANOPY_OK ||
        canopy_model_set_integrator(m, "hht") != CANOPY_OK ||
        canopy_model_set_implicit_controls(m, 1e-13, 100) != CANOPY_OK ||
        canopy_model_set_max_omega_dt(m, 1e9) != CANOPY_OK) {
        canopy_model_destroy(&m);
        return NULL;
    }
    return m;
}

/* Push the nodes along z with forces F w_i and advance 20 steps of 1 ms;
 * positions to x (9 doubles). */
static canopy_status push(canopy_model *m, const double w[3], double *x)
{
    double f[9] = {0};
    for (int i = 0; i < 3; ++i) f[3 * i + 2] = 0.5 * w[i];
    canopy_status st = canopy_model_set_nodal_forces(m, f, 3);
    for (int s = 0; s < 20 && st == CANOPY_OK; ++s)
        st = canopy_model_advance(m, 1e-3, NULL);
    if (st == CANOPY_OK) st = canopy_model_get_positions(m, x, 3);
    return st;
}

static double max_z_difference(const double *a, const double *b)
{
    double d = 0.0;
    for (int i = 0; i < 3; ++i) d = fmax(d, fabs(a[3 * i + 2] - b[3 * i + 2]));
    return d;
}

/* Forces 2, -1, -1 (sum zero, equal masses): the springs are internal to
 * the triangle, so the nodes' mean acceleration stays zero and the
 * consistent added mass (here 15 times the cloth's) exerts nothing: the
 * motion is the one without added mass, to the Newton tolerance. The same
 * mass lumped on the nodes slows it several times. */
CANOPY_TEST(triangle_added_mass_leaves_a_zero_mean_motion)
{
    const double w[3] = {2.0, -1.0, -1.0};
    const double tri_mass[1] = {4.5}, lumped[3] = {1.5, 1.5, 1.5};
    double x_none[9], x_cons[9], x_lump[9];
    canopy_model *none = triangle(), *cons = triangle(), *lump = triangle();
    ASSERT_TRUE(none && cons && lump);
    ASSERT_OK(cons, canopy_model_set_triangle_added_mass(cons, tri_mass, 1));
    ASSERT_OK(lump, canopy_model_set_added_mass(lump, lumped, 3));
    ASSERT_OK(none, push(none, w, x_none));
    ASSERT_OK(cons, push(cons, w, x_cons));
    ASSERT_OK(lump, push(lump, w, x_lump));
    /* node 0's displacement: 10 N/kg for 20 ms gives 2 mm */
    const double moved = fabs(x_none[2]);
    ASSERT_TRUE(moved > 1e-3);
    ASSERT_NEAR(max_z_difference(x_cons, x_none), 0.0, 1e-9 * moved);
    ASSERT_TRUE(max_z_difference(x_lump, x_none) > 0.5 * moved);
    canopy_model_destroy(&none);
    canopy_model_destroy(&cons);
    canopy_model_destroy(&lump);
}

/* Equal forces: the triangle translates, and the consistent added mass acts
 * as the same mass lumped a third to each node: the two move alike, and
 * as the exact translation z = F t^2 / (2 (m + m_t/3)) per node. */
CANOPY_TEST(triangle_added_mass_moves_a_uniform_motion_as_lumped)
{
    const double w[3] = {1.0, 1.0, 1.0};
    const double tri_mass[1] = {4.5}, lumped[3] = {1.5, 1.5, 1.5};
    double x_cons[9], x_lump[9];
    canopy_model *cons = triangle(), *lump = triangle();
    ASSERT_TRUE(cons && lump);
    ASSERT_OK(cons, canopy_model_set_triangle_added_mass(cons, tri_mass, 1));
    ASSERT_OK(lump, canopy_model_set_added_mass(lump, lumped, 3));
    ASSERT_OK(cons, push(cons, w, x_cons));
    ASSERT_OK(lump, push(lump, w, x_lump));
    const double exact = 0.5 * 0.5 / (0.1 + 1.5) * 0.02 * 0.02;
    ASSERT_NEAR(max_z_difference(x_cons, x_lump), 0.0, 1e-9 * exact);
    for (int i = 0; i < 3; ++i) ASSERT_REL(x_cons[3 * i + 2], exact, 1e-9);
    canopy_model_destroy(&cons);
    canopy_model_destroy(&lump);
}

/* Bad input leaves the model as it was; an integrator that cannot couple
 * the nodes is refused when the model advances, the state untouched. */
CANOPY_TEST(triangle_added_mass_rejections)
{
    canopy_model *m = triangle();
    ASSERT_TRUE(m != NULL);
    const double two[2] = {1.0, 1.0}, negative[1] = {-1.0},
                 not_finite[1] = {NAN}, good[1] = {4.5};
    ASSERT_STATUS(CANOPY_ERR_RANGE,
                  canopy_model_set_triangle_added_mass(m, two, 2));
    ASSERT_MESSAGE_HAS(m, "set_triangle_added_mass");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_set_triangle_added_mass(m, NULL, 1));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_set_triangle_added_mass(m, negative, 1));
    ASSERT_MESSAGE_HAS(m, "triangle 0");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_set_triangle_added_mass(m, not_finite, 1));
    /* none was stored: rk4 still advances */
    ASSERT_OK(m, canopy_model_set_integrator(m, "rk4"));
    ASSERT_OK(m, canopy_model_advance(m, 1e-3, NULL));
    ASSERT_OK(m, canopy_model_set_triangle_added_mass(m, good, 1));
    double before[9], after[9];
    ASSERT_OK(m, canopy_model_get_positions(m, before, 3));
    const double t0 = canopy_model_time(m);
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_advance(m, 1e-3, NULL));
    ASSERT_MESSAGE_HAS(m, "newmark or hht");
    ASSERT_OK(m, canopy_model_get_positions(m, after, 3));
    for (int k = 0; k < 9; ++k) ASSERT_NEAR(after[k], before[k], 0.0);
    ASSERT_NEAR(canopy_model_time(m), t0, 0.0);
    /* all zero: none again, and rk4 advances */
    const double zero[1] = {0.0};
    ASSERT_OK(m, canopy_model_set_triangle_added_mass(m, zero, 1));
    ASSERT_OK(m, canopy_model_advance(m, 1e-3, NULL));
    canopy_model_destroy(&m);
}
