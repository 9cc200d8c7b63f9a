/* test_string_chord.c — seed 000 Figs. 5.8–5.9: a swinging string chord with payload conserves energy under RK4. */
#include "test.h"

/* 50 point masses m = 0.01 on Model-II springs k = 5000, one end fixed, a
 * payload of 1 at the free end, gravity -9.8, no damping; released at rest,
 * horizontal, at rest length. RK4 at the library's stable step
 * (omega dt <= 0.1 with the Gershgorin bound) for 20 000 steps. The total
 * energy (kinetic + spring + gravitational) must stay within 0.001 % of the
 * energy the swing exchanges (the largest kinetic energy reached), which is
 * the seed's "conserved within 0.001 percent". */
CANOPY_TEST(string_chord_energy)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    const int n_masses = 50;
    const double length = 1.0, k = 5000.0, mass = 0.01, payload = 1.0;
    const double g[3] = {0.0, 0.0, -9.8};
    int prev;
    const double x0[3] = {0.0, 0.0, 0.0};
    ASSERT_OK(m, canopy_model_add_node(m, x0, 0.0, CANOPY_GROUP_LINE, &prev));
    ASSERT_OK(m, canopy_model_set_fixed(m, prev, 1));
    for (int i = 1; i <= n_masses; ++i) {
        const double x[3] = {length * i / n_masses, 0.0, 0.0};
        int node;
        ASSERT_OK(m, canopy_model_add_node(m, x, mass, CANOPY_GROUP_LINE, &node));
        ASSERT_OK(m, canopy_model_add_spring(m, prev, node, k, 0.0,
                                             CANOPY_SPRING_MODEL_II,
                                             CANOPY_GROUP_LINE, NULL));
        prev = node;
    }
    ASSERT_OK(m, canopy_model_add_node_mass(m, prev, payload));
    ASSERT_OK(m, canopy_model_set_payload_node(m, prev));
    ASSERT_OK(m, canopy_model_set_gravity(m, g));
    ASSERT_OK(m, canopy_model_set_integrator(m, "rk4"));
    double dt;
    ASSERT_OK(m, canopy_model_stable_step(m, &dt));
    canopy_energies e0, e;
    ASSERT_OK(m, canopy_model_energies(m, &e0));
    double max_kinetic = 0.0, max_drift = 0.0;
    for (int s = 1; s <= 20000; ++s) {
        ASSERT_OK(m, canopy_model_step(m, dt));
        ASSERT_OK(m, canopy_model_energies(m, &e));
        if (e.kinetic > max_kinetic) max_kinetic = e.kinetic;
        const double drift = fabs(e.total - e0.total);
        if (drift > max_drift) max_drift = drift;
    }
    double xp[3];
    ASSERT_OK(m, canopy_model_payload_state(m, xp, NULL));
    printf("dt = %.4g s, t = %.4f s, payload at (%.3f, %.3f, %.3f)\n", dt,
           canopy_model_time(m), xp[0], xp[1], xp[2]);
    printf("max kinetic energy %.6g J, max |E - E0| %.3g J = %.3g %% of it\n",
           max_kinetic, max_drift, 100.0 * max_drift / max_kinetic);
    ASSERT_TRUE(max_kinetic > 1.0);           /* it really swung */
    ASSERT_TRUE(max_drift <= 1e-5 * max_kinetic);
    canopy_model_destroy(&m);
}
