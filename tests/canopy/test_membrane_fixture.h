/* test_membrane_fixture.h — a small hand-built membrane with pressure triangles, shared by tests that need a 2-D model. */
#ifndef CANOPY_TEST_MEMBRANE_FIXTURE_H
#define CANOPY_TEST_MEMBRANE_FIXTURE_H

#include "canopy.h"

/* An n x n grid of nodes (spacing h) in the plane z = 0, split into right
 * triangles, Model-II springs on every edge (k, c), node mass m, the four
 * corners fixed. Returns CANOPY_OK or the failing call's status. */
static inline canopy_status membrane_fixture(canopy_model *model, int n,
                                             double h, double k, double c,
                                             double m)
{
    canopy_status st;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x[3] = {i * h, j * h, 0.0};
            if ((st = canopy_model_add_node(model, x, m, CANOPY_GROUP_FABRIC,
                                            NULL)))
                return st;
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * n + i;
            if (i + 1 < n &&
                (st = canopy_model_add_spring(model, a, a + 1, k, c,
                                              CANOPY_SPRING_MODEL_II,
                                              CANOPY_GROUP_FABRIC, NULL)))
                return st;
            if (j + 1 < n &&
                (st = canopy_model_add_spring(model, a, a + n, k, c,
                                              CANOPY_SPRING_MODEL_II,
                                              CANOPY_GROUP_FABRIC, NULL)))
                return st;
            if (i + 1 < n && j + 1 < n) {
                if ((st = canopy_model_add_spring(model, a, a + n + 1, k, c,
                                                  CANOPY_SPRING_MODEL_II,
                                                  CANOPY_GROUP_FABRIC, NULL)) ||
                    (st = canopy_model_add_triangle(model, a, a + 1, a + n + 1,
                                                    NULL)) ||
                    (st = canopy_model_add_triangle(model, a, a + n + 1, a + n,
                                                    NULL)))
                    return st;
            }
        }
    const int corners[4] = {0, n - 1, n * (n - 1), n * n - 1};
    for (int q = 0; q < 4; ++q)
        if ((st = canopy_model_set_fixed(model, corners[q], 1))) return st;
    return CANOPY_OK;
}

#endif /* CANOPY_TEST_MEMBRANE_FIXTURE_H */
