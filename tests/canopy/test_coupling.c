/* test_coupling.c — coupling quantities: pressure loads, porous seepage, normal velocities, momentum balance, damping of internal motion only. */
#include "test.h"
#include "test_membrane_fixture.h"

#include <string.h>

/* Seepage w solves dp = alpha w + beta w|w| (seed 002 eqs. 6-10) to
 * round-off for Darcy, Forchheimer and mixed laws, both signs of dp. */
CANOPY_TEST(porous_seepage_law)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_TRUE(canopy_model_seepage_velocity(m, 100.0) == 0.0); /* impermeable */
    const double laws[3][2] = {{250.0, 0.0}, {0.0, 3.0}, {250.0, 3.0}};
    const double dps[5] = {-500.0, -1.0, 1e-6, 124.5, 2000.0};
    for (int l = 0; l < 3; ++l) {
        ASSERT_OK(m, canopy_model_set_porosity(m, laws[l][0], laws[l][1]));
        for (int d = 0; d < 5; ++d) {
            const double w = canopy_model_seepage_velocity(m, dps[d]);
            const double back = laws[l][0] * w + laws[l][1] * w * fabs(w);
            ASSERT_REL(back, dps[d], 1e-13);
        }
    }
    /* NOTES §3: nylon cloth passing ~100 ft^3/ft^2/min at 124.5 Pa has
     * alpha ~ 245 Pa s/m: the seepage is 0.508 m/s. */
    ASSERT_OK(m, canopy_model_set_porosity(m, 124.5 / 0.508, 0.0));
    ASSERT_REL(canopy_model_seepage_velocity(m, 124.5), 0.508, 1e-12);
    canopy_model_destroy(&m);
}

/* Pressure load: the total force of a uniform dp on a flat membrane is
 * dp * A * n, and Newton's third law holds for the internal forces: with
 * gravity and pressure off, the spring and dashpot forces sum to zero. */
CANOPY_TEST(loads_and_momentum_balance)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    const int N = 6;
    ASSERT_OK(m, membrane_fixture(m, N, 0.2, 300.0, 0.4, 0.02));
    const int n = canopy_model_node_count(m), nt = canopy_model_triangle_count(m);
    const double zero_g[3] = {0.0, 0.0, 0.0};
    ASSERT_OK(m, canopy_model_set_gravity(m, zero_g));
    /* Random-ish state so springs are stretched and moving. */
    double x[3 * 36], x_flat[3 * 36], v[3 * 36], f[3 * 36];
    ASSERT_OK(m, canopy_model_get_positions(m, x, n));
    memcpy(x_flat, x, sizeof x);
    for (int i = 0; i < 3 * n; ++i) {
        x[i] += 0.01 * sin(1.7 * i);
        v[i] = 0.3 * cos(2.3 * i);
    }
    ASSERT_OK(m, canopy_model_set_positions(m, x, n));
    ASSERT_OK(m, canopy_model_set_velocities(m, v, n));
    ASSERT_OK(m, canopy_model_get_forces(m, f, n));
    double sum[3] = {0, 0, 0}, mag = 0.0;
    for (int i = 0; i < n; ++i)
        for (int d = 0; d < 3; ++d) {
            sum[d] += f[3 * i + d];
            mag += fabs(f[3 * i + d]);
        }
    ASSERT_TRUE(mag > 1.0);
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(sum[d], 0.0, 1e-13 * mag);
    /* Flat membrane again, uniform dp: total = dp * A * n. */
    memcpy(x, x_flat, sizeof x);
    ASSERT_OK(m, canopy_model_set_positions(m, x, n));
    memset(v, 0, sizeof v);
    ASSERT_OK(m, canopy_model_set_velocities(m, v, n));
    double dp[2 * 25], area[2 * 25], normal[3 * 2 * 25];
    for (int t = 0; t < nt; ++t) dp[t] = 40.0;
    ASSERT_OK(m, canopy_model_set_pressure_jump(m, dp, nt));
    ASSERT_OK(m, canopy_model_get_triangle_geometry(m, NULL, normal, area, nt));
    double A = 0.0;
    for (int t = 0; t < nt; ++t) {
        A += area[t];
        ASSERT_NEAR(normal[3 * t + 2], 1.0, 1e-15);
    }
    ASSERT_OK(m, canopy_model_get_forces(m, f, n));
    double fz = 0.0;
    for (int i = 0; i < n; ++i) fz += f[3 * i + 2];
    double x0[3], x1[3];
    memcpy(x0, x, sizeof x0);
    memcpy(x1, x + 3 * (n - 1), sizeof x1);
    const double A_exact = (x1[0] - x0[0]) * (x1[1] - x0[1]);
    ASSERT_REL(A, A_exact, 1e-12);
    ASSERT_REL(fz, 40.0 * A_exact, 1e-12);
    canopy_model_destroy(&m);
}

/* Normal velocities: canopy normal velocity + seepage for the current dp. */
CANOPY_TEST(normal_velocity_with_porous_slip)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, membrane_fixture(m, 3, 0.5, 100.0, 0.0, 0.01));
    const int n = canopy_model_node_count(m), nt = canopy_model_triangle_count(m);
    double v[27], dp[8], vn[8], tv[24];
    for (int i = 0; i < n; ++i) {
        v[3 * i] = 0.7;           /* tangential: must not show */
        v[3 * i + 1] = -0.2;
        v[3 * i + 2] = 1.5;       /* normal */
    }
    ASSERT_OK(m, canopy_model_set_velocities(m, v, n));
    for (int t = 0; t < nt; ++t) dp[t] = 10.0 * (t + 1);
    ASSERT_OK(m, canopy_model_set_pressure_jump(m, dp, nt));
    ASSERT_OK(m, canopy_model_set_porosity(m, 200.0, 1.5));
    ASSERT_OK(m, canopy_model_get_normal_velocities(m, vn, nt));
    ASSERT_OK(m, canopy_model_get_triangle_velocities(m, tv, nt));
    for (int t = 0; t < nt; ++t) {
        const double w = canopy_model_seepage_velocity(m, dp[t]);
        ASSERT_NEAR(vn[t], 1.5 + w, 1e-14);
        ASSERT_NEAR(tv[3 * t], 0.7, 1e-15);
        ASSERT_TRUE(w > 0.0);
    }
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_get_normal_velocities(m, vn, nt + 1));
    canopy_model_destroy(&m);
}

/* The impulse method (seed 000 §2.9): dashpots damp the internal motion
 * only. A membrane with strong dashpots moving rigidly keeps its velocity
 * exactly; its internal vibration decays. */
CANOPY_TEST(damping_acts_on_internal_motion_only)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, membrane_fixture(m, 5, 0.1, 400.0, 0.5, 0.01));
    const int n = canopy_model_node_count(m);
    for (int i = 0; i < n; ++i) ASSERT_OK(m, canopy_model_set_fixed(m, i, 0));
    const double zero_g[3] = {0.0, 0.0, 0.0};
    ASSERT_OK(m, canopy_model_set_gravity(m, zero_g));
    double v[75], x[75];
    for (int i = 0; i < n; ++i) {
        v[3 * i] = 2.0; v[3 * i + 1] = -1.0; v[3 * i + 2] = 3.0;
    }
    ASSERT_OK(m, canopy_model_set_velocities(m, v, n));
    for (int s = 0; s < 200; ++s) ASSERT_OK(m, canopy_model_advance(m, 1e-3, NULL));
    ASSERT_OK(m, canopy_model_get_velocities(m, v, n));
    for (int i = 0; i < n; ++i) {
        ASSERT_NEAR(v[3 * i], 2.0, 1e-12);
        ASSERT_NEAR(v[3 * i + 1], -1.0, 1e-12);
        ASSERT_NEAR(v[3 * i + 2], 3.0, 1e-12);
    }
    /* Now stretch it in-plane and let it ring: internal energy decays. */
    ASSERT_OK(m, canopy_model_get_positions(m, x, n));
    for (int i = 0; i < n; ++i) x[3 * i] *= 1.02;
    ASSERT_OK(m, canopy_model_set_positions(m, x, n));
    canopy_energies e0, e1;
    ASSERT_OK(m, canopy_model_energies(m, &e0));
    for (int s = 0; s < 1000; ++s) ASSERT_OK(m, canopy_model_advance(m, 1e-3, NULL));
    ASSERT_OK(m, canopy_model_energies(m, &e1));
    /* Kinetic energy of the rigid drift (2,-1,3) is conserved; the rest
     * (spring + vibration) has decayed. */
    const double drift = 0.5 * 0.01 * n * (4.0 + 1.0 + 9.0);
    const double internal0 = e0.kinetic + e0.spring - drift;
    const double internal1 = e1.kinetic + e1.spring - drift;
    printf("internal energy %.4g J -> %.4g J after 1 s\n", internal0, internal1);
    ASSERT_TRUE(internal1 < 0.01 * internal0);
    canopy_model_destroy(&m);
}

/* Directional added mass (the air resists a membrane's normal motion only):
 * inertia m I + m_a d d^T. A free node under gravity alone (a constant
 * force) gains velocity a dt in one RK4 step, with a = g m / (m + m_a)
 * along d and a = g across it; a zero direction is isotropic; newmark and
 * hht solve with it, kang refuses it. */
CANOPY_TEST(directional_added_mass)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    const double x0[3] = {0.0, 0.0, 0.0};
    const double g[3] = {3.0, 1.0, -9.0};
    const double mass = 2.0, ma = 6.0, dt = 0.1;
    int a = -1, b = -1;
    ASSERT_OK(m, canopy_model_add_node(m, x0, mass, CANOPY_GROUP_OTHER, &a));
    ASSERT_OK(m, canopy_model_add_node(m, x0, mass, CANOPY_GROUP_OTHER, &b));
    ASSERT_OK(m, canopy_model_set_gravity(m, g));
    ASSERT_OK(m, canopy_model_set_integrator(m, "rk4"));
    /* node a: added mass along z (given unnormalised); node b: isotropic */
    const double added[2] = {ma, ma};
    const double dir[6] = {0.0, 0.0, 2.0, 0.0, 0.0, 0.0};
    ASSERT_OK(m, canopy_model_set_directional_added_mass(m, added, dir, 2));
    ASSERT_OK(m, canopy_model_step(m, dt));
    double v[6];
    ASSERT_OK(m, canopy_model_get_velocities(m, v, 2));
    const double r = mass / (mass + ma);
    ASSERT_NEAR(v[0], g[0] * dt, 1e-14);
    ASSERT_NEAR(v[1], g[1] * dt, 1e-14);
    ASSERT_NEAR(v[2], g[2] * r * dt, 1e-14);
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(v[3 + d], g[d] * r * dt, 1e-14);
    /* Newmark and HHT solve with the same 3x3 inertia: under a constant
     * force both are exact, so each step adds the same increments; kang,
     * whose update assumes a scalar mass, refuses the direction. */
    const char *implicit[2] = {"newmark", "hht"};
    for (int k = 0; k < 2; ++k) {
        double before[6], after[6];
        ASSERT_OK(m, canopy_model_set_integrator(m, implicit[k]));
        ASSERT_OK(m, canopy_model_get_velocities(m, before, 2));
        ASSERT_OK(m, canopy_model_step(m, dt));
        ASSERT_OK(m, canopy_model_get_velocities(m, after, 2));
        ASSERT_NEAR(after[0] - before[0], g[0] * dt, 1e-12);
        ASSERT_NEAR(after[1] - before[1], g[1] * dt, 1e-12);
        ASSERT_NEAR(after[2] - before[2], g[2] * r * dt, 1e-12);
        for (int d = 0; d < 3; ++d)
            ASSERT_NEAR(after[3 + d] - before[3 + d], g[d] * r * dt, 1e-12);
    }
    ASSERT_OK(m, canopy_model_set_integrator(m, "kang"));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_step(m, dt));
    ASSERT_MESSAGE_HAS(m, "not 'kang'");
    /* set_added_mass clears the directions: kang then runs */
    ASSERT_OK(m, canopy_model_set_added_mass(m, added, 2));
    ASSERT_OK(m, canopy_model_step(m, dt));
    /* Bad input */
    const double bad[2] = {ma, -1.0};
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_set_directional_added_mass(m, bad, dir, 2));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_set_directional_added_mass(m, added, NULL, 2));
    canopy_model_destroy(&m);
}
