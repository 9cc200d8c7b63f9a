/* test_bad_input.c — acceptance test 8: bad input gives a clear status and message and corrupts nothing. */
#include "test.h"
#include "test_membrane_fixture.h"

#include <string.h>

CANOPY_TEST(bad_input_building)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, membrane_fixture(m, 4, 0.1, 100.0, 0.0, 0.01));
    const int n = canopy_model_node_count(m), ns = canopy_model_spring_count(m),
              nt = canopy_model_triangle_count(m);
    double x_before[48], x_after[48 + 6]; /* n + 2 nodes at the end */
    ASSERT_OK(m, canopy_model_get_positions(m, x_before, n));

    /* Negative mass. */
    const double p[3] = {5.0, 5.0, 5.0};
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_add_node(m, p, -1.0, CANOPY_GROUP_FABRIC, NULL));
    ASSERT_MESSAGE_HAS(m, "mass -1");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_add_node_mass(m, 3, -0.5));
    ASSERT_MESSAGE_HAS(m, "node 3");
    /* NaN position. */
    const double bad[3] = {0.0, NAN, 0.0};
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_add_node(m, bad, 1.0, CANOPY_GROUP_FABRIC, NULL));
    ASSERT_MESSAGE_HAS(m, "not finite");
    double x_nan[48];
    memcpy(x_nan, x_before, sizeof x_nan);
    x_nan[3 * 5 + 2] = NAN;
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_positions(m, x_nan, n));
    ASSERT_MESSAGE_HAS(m, "node 5");
    /* Zero rest length: a spring between coincident nodes. */
    int c1, c2;
    const double q[3] = {1.0, 1.0, 1.0};
    ASSERT_OK(m, canopy_model_add_node(m, q, 0.1, CANOPY_GROUP_OTHER, &c1));
    ASSERT_OK(m, canopy_model_add_node(m, q, 0.1, CANOPY_GROUP_OTHER, &c2));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_add_spring(m, c1, c2, 10.0, 0.0,
                                          CANOPY_SPRING_MODEL_II,
                                          CANOPY_GROUP_OTHER, NULL));
    ASSERT_MESSAGE_HAS(m, "zero rest length");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_rest_length(m, 0, 0.0));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_model_add_spring(m, 0, 1, -5.0, 0.0,
                                          CANOPY_SPRING_MODEL_II,
                                          CANOPY_GROUP_OTHER, NULL));
    ASSERT_MESSAGE_HAS(m, "stiffness -5");
    /* Out-of-range indices. */
    ASSERT_STATUS(CANOPY_ERR_RANGE,
                  canopy_model_add_spring(m, 0, 999, 10.0, 0.0,
                                          CANOPY_SPRING_MODEL_II,
                                          CANOPY_GROUP_OTHER, NULL));
    ASSERT_MESSAGE_HAS(m, "999");
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_add_triangle(m, 0, 1, -1, NULL));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_set_fixed(m, n + 50, 1));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_set_payload_node(m, -7));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_set_rest_length(m, ns + 3, 1.0));
    /* Count mismatches are errors, not truncations. */
    double dp[64] = {0};
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_set_pressure_jump(m, dp, nt - 1));
    ASSERT_MESSAGE_HAS(m, "does not match");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_pressure_jump(m, NULL, nt));

    /* Nothing was corrupted: counts grew only by the two good nodes. */
    ASSERT_TRUE(canopy_model_node_count(m) == n + 2);
    ASSERT_TRUE(canopy_model_spring_count(m) == ns);
    ASSERT_TRUE(canopy_model_triangle_count(m) == nt);
    ASSERT_OK(m, canopy_model_get_positions(m, x_after, n + 2));
    ASSERT_TRUE(memcmp(x_before, x_after, sizeof(double) * 3 * (size_t)n) == 0);
    canopy_model_destroy(&m);
    ASSERT_TRUE(m == NULL);
    canopy_model_destroy(&m);           /* destroying NULL is a no-op */
    canopy_model_destroy(NULL);
}

CANOPY_TEST(bad_input_integration)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    /* Stepping an empty model. */
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_step(m, 1e-3));
    ASSERT_MESSAGE_HAS(m, "no nodes");
    /* A free node without mass. */
    const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0};
    int i, j;
    ASSERT_OK(m, canopy_model_add_node(m, a, 0.0, CANOPY_GROUP_OTHER, &i));
    ASSERT_OK(m, canopy_model_add_node(m, b, 1.0, CANOPY_GROUP_OTHER, &j));
    ASSERT_OK(m, canopy_model_add_spring(m, i, j, 10.0, 0.0,
                                         CANOPY_SPRING_MODEL_II,
                                         CANOPY_GROUP_OTHER, NULL));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_advance(m, 1e-3, NULL));
    ASSERT_MESSAGE_HAS(m, "node 0 is free but has zero mass");
    ASSERT_OK(m, canopy_model_set_fixed(m, i, 1));
    /* Unknown integrator: the message lists the valid names, the old one stays. */
    ASSERT_STATUS(CANOPY_ERR_UNKNOWN_NAME, canopy_model_set_integrator(m, "rk5"));
    ASSERT_MESSAGE_HAS(m, "'rk5'");
    ASSERT_MESSAGE_HAS(m, "euler-cromer");
    ASSERT_MESSAGE_HAS(m, "kang");
    printf("message: %s\n", canopy_model_message(m));
    ASSERT_TRUE(strcmp(canopy_model_integrator(m), "rk4") == 0);
    ASSERT_STATUS(CANOPY_ERR_UNKNOWN_NAME, canopy_model_set_integrator(m, NULL));
    /* Bad controls. */
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_step(m, -1.0));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_step(m, NAN));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_advance(m, 0.0, NULL));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_max_omega_dt(m, 0.0));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_hht_alpha(m, 0.2));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_implicit_controls(m, 0.0, 5));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_porosity(m, -1.0, 0.0));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_model_set_added_mass(m, (double[2]){0.0, -1.0}, 2));
    /* Restore without a checkpoint; commit without one. */
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_restore(m));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_model_commit(m));
    /* After all that the model still runs, and a success clears the message. */
    ASSERT_OK(m, canopy_model_advance(m, 1e-2, NULL));
    ASSERT_TRUE(canopy_model_message(m)[0] == '\0');
    ASSERT_TRUE(strcmp(canopy_status_name(CANOPY_ERR_RANGE), "CANOPY_ERR_RANGE") == 0);
    ASSERT_TRUE(strcmp(canopy_status_name((canopy_status)99), "CANOPY_UNKNOWN_STATUS") == 0);
    ASSERT_TRUE(canopy_model_create(NULL) == CANOPY_ERR_ARGUMENT);
    canopy_model_destroy(&m);
}
