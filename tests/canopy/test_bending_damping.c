/* test_bending_damping.c — the hinge dashpots: the dihedral-angle force against finite differences, no force on rigid motion, dissipation, the stable step. */
#include "test.h"
#include "test_flapping_sheet_fixture.h"

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Dihedral angle of the hinge (o1, o2, p, q): the signed angle between the
 * normals of (o1, p, q) and (o2, q, p) about the edge q - p. */
static double dihedral(const double *x)
{
    const double *o1 = x, *o2 = x + 3, *p = x + 6, *q = x + 9;
    double a[3], b[3], c[3], d[3], e[3], n1[3], n2[3], s[3];
    for (int k = 0; k < 3; ++k) {
        a[k] = o1[k] - p[k]; b[k] = o1[k] - q[k];
        c[k] = o2[k] - q[k]; d[k] = o2[k] - p[k];
        e[k] = q[k] - p[k];
    }
    cross3(a, b, n1);
    cross3(c, d, n2);
    cross3(n1, n2, s);
    return atan2(dot3(s, e) / sqrt(dot3(e, e)), dot3(n1, n2));
}

/* Two triangles (o1, p, q) and (o2, q, p) folded about their edge, zero
 * gravity, no springs: the only force is the hinge dashpot. */
static canopy_status hinge_pair(canopy_model **out, const double x[12],
                                double rate)
{
    canopy_status st = canopy_model_create(out);
    if (st) return st;
    canopy_model *m = *out;
    const double g[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 4 && st == CANOPY_OK; ++i)
        st = canopy_model_add_node(m, x + 3 * i, 0.1, CANOPY_GROUP_FABRIC, NULL);
    if (st == CANOPY_OK) st = canopy_model_add_triangle(m, 0, 2, 3, NULL);
    if (st == CANOPY_OK) st = canopy_model_add_triangle(m, 1, 3, 2, NULL);
    if (st == CANOPY_OK) st = canopy_model_set_gravity(m, g);
    if (st == CANOPY_OK) st = canopy_model_set_bending_damping(m, rate);
    return st;
}

/* f_i = -c (dtheta/dt) dtheta/dx_i, c = rate / sum_a |dtheta/dx_a|^2 / m_a,
 * with dtheta/dx from central differences of the dihedral angle.
 * Differences of step 1e-6 on O(1) coordinates are good to ~1e-9
 * relative. */
CANOPY_TEST(bending_damping_matches_dihedral_angle_rate)
{
    const double x[12] = {0.1, 1.0, 0.3,   -0.2, -0.9, -0.4,
                          -0.5, 0.05, 0.0,  0.6, -0.1, 0.1};
    const double v[12] = {0.3, -0.2, 1.0,  0.1, 0.4, -0.7,
                          -0.5, 0.2, 0.3,  0.2, 0.1, -0.4};
    const double decay = 250.0;
    canopy_model *m = NULL;
    ASSERT_OK(m, hinge_pair(&m, x, decay));
    ASSERT_OK(m, canopy_model_set_velocities(m, v, 4));
    double f[12];
    ASSERT_OK(m, canopy_model_get_forces(m, f, 4));

    double grad[12], rate = 0.0;
    for (int k = 0; k < 12; ++k) {
        double xp[12], xm[12];
        memcpy(xp, x, sizeof xp);
        memcpy(xm, x, sizeof xm);
        xp[k] += 1e-6;
        xm[k] -= 1e-6;
        grad[k] = (dihedral(xp) - dihedral(xm)) / 2e-6;
        rate += grad[k] * v[k];
    }
    double inv_inertia = 0.0;     /* every node of the pair has m = 0.1 */
    for (int k = 0; k < 12; ++k) inv_inertia += grad[k] * grad[k] / 0.1;
    const double c = decay / inv_inertia;
    double err = 0.0, scale = 0.0;
    for (int k = 0; k < 12; ++k) {
        const double expected = -c * rate * grad[k];
        err = fmax(err, fabs(f[k] - expected));
        scale = fmax(scale, fabs(expected));
    }
    printf("  largest force %.3g N, deviation %.2g N\n", scale, err);
    ASSERT_TRUE(scale > 0.1);
    ASSERT_TRUE(err < 1e-7 * scale);
    canopy_model_destroy(&m);
}

/* Rigid translation plus rotation of a folded pair: no force (to round-off
 * of the O(1) terms); a bending velocity of the same size gets one. The
 * power of the dashpot -c (dtheta/dt)^2 is never positive. */
CANOPY_TEST(bending_damping_leaves_rigid_motion_alone)
{
    const double x[12] = {0.1, 1.0, 0.3,   -0.2, -0.9, -0.4,
                          -0.5, 0.05, 0.0,  0.6, -0.1, 0.1};
    canopy_model *m = NULL;
    ASSERT_OK(m, hinge_pair(&m, x, 30.0));
    const double V[3] = {0.7, -1.1, 0.4}, W[3] = {-0.8, 0.5, 1.3};
    double v[12], f[12];
    for (int i = 0; i < 4; ++i) {
        double w[3];
        cross3(W, x + 3 * i, w);
        for (int k = 0; k < 3; ++k) v[3 * i + k] = V[k] + w[k];
    }
    ASSERT_OK(m, canopy_model_set_velocities(m, v, 4));
    ASSERT_OK(m, canopy_model_get_forces(m, f, 4));
    double rigid = 0.0;
    for (int k = 0; k < 12; ++k) rigid = fmax(rigid, fabs(f[k]));

    /* Fold faster: o1 and o2 move along their triangles' normals */
    memset(v, 0, sizeof v);
    v[2] = 1.0; v[5] = 1.0;
    ASSERT_OK(m, canopy_model_set_velocities(m, v, 4));
    ASSERT_OK(m, canopy_model_get_forces(m, f, 4));
    double bending = 0.0, power = 0.0, total[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < 12; ++k) {
        bending = fmax(bending, fabs(f[k]));
        power += f[k] * v[k];
        total[k % 3] += f[k];
    }
    ASSERT_TRUE(bending > 0.1);
    ASSERT_TRUE(rigid < 1e-12 * bending);
    ASSERT_TRUE(power < 0.0);
    /* Internal: no net force */
    ASSERT_TRUE(fabs(total[0]) + fabs(total[1]) + fabs(total[2]) < 1e-12 * bending);
    canopy_model_destroy(&m);
}

/* A pinned 1 m x 1 m sheet (edge 0.1 m, the default fabric with its edge
 * dashpots) whose nodes flap out of plane, alternately up and down. The
 * edge dashpots act along the flat sheet's springs, which this motion
 * stretches only to second order: without hinge dashpots the energy
 * (kinetic + elastic) after 0.01 s is still above 90 % of the start. Hinge
 * dashpots of rate 1e4 /s dominate the frequency bound (they shorten the
 * stable step); RK4 at that step stays stable and the energy falls below
 * 1e-3 of the start (e^-100 for one hinge alone; the hinges' modes
 * overlap, so the decay is not one exponential). */
CANOPY_TEST(bending_damping_damps_flapping_within_the_stable_step)
{
    double energy_left[2], step[2];
    for (int pass = 0; pass < 2; ++pass) {
        canopy_model *m = NULL;
        ASSERT_OK(m, flapping_sheet(&m, pass ? 1e4 : 0.0, 0));
        canopy_energies e0, e1;
        ASSERT_OK(m, canopy_model_energies(m, &e0));
        ASSERT_OK(m, canopy_model_stable_step(m, &step[pass]));
        ASSERT_OK(m, canopy_model_advance(m, 0.01, NULL));
        ASSERT_OK(m, canopy_model_energies(m, &e1));
        energy_left[pass] = (e1.kinetic + e1.spring) / (e0.kinetic + e0.spring);
        printf("  rate %g /s: stable step %.3g s, energy after 0.01 s %.3g of the start\n",
               pass ? 1e4 : 0.0, step[pass], energy_left[pass]);
        canopy_model_destroy(&m);
    }
    ASSERT_TRUE(energy_left[0] > 0.9);
    ASSERT_TRUE(energy_left[1] < 1e-3);
    ASSERT_TRUE(step[1] < 0.5 * step[0]);
}

CANOPY_TEST(bending_damping_rejects_a_bad_rate)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_bending_damping(m, -1.0));
    ASSERT_TRUE(strstr(canopy_model_message(m), "rate") != NULL);
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_bending_damping(m, NAN));
    canopy_model_destroy(&m);
}
