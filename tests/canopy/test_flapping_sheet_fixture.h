/* test_flapping_sheet_fixture.h — a pinned 1 m square sheet whose nodes flap out of plane, shared by the hinge-dashpot tests. */
#ifndef CANOPY_TEST_FLAPPING_SHEET_FIXTURE_H
#define CANOPY_TEST_FLAPPING_SHEET_FIXTURE_H

#include "canopy.h"

#include <stdlib.h>

/* A 1 m x 1 m rectangle (edge 0.1 m, the default fabric with its edge
 * dashpots), zero gravity, its boundary pinned, the inner nodes moving out
 * of plane at 0.1 m/s, alternately up and down; hinge dashpots of `rate`
 * [1/s], implicit or explicit. */
static inline canopy_status flapping_sheet(canopy_model **out,
                                           double rate, int implicit)
{
    canopy_status st = canopy_model_create(out);
    if (st) return st;
    canopy_model *m = *out;
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    r.width = 1.0;
    r.length = 1.0;
    r.edge_length = 0.1;
    const double g[3] = {0.0, 0.0, 0.0};
    if ((st = canopy_build_rectangle(m, &r))) return st;
    if ((st = canopy_model_set_gravity(m, g))) return st;
    if ((st = canopy_model_set_bending_damping(m, rate))) return st;
    if ((st = canopy_model_set_bending_damping_implicit(m, implicit))) return st;
    const int n = canopy_model_node_count(m);
    double *x = malloc(sizeof(double) * 3 * (size_t)n);
    double *v = calloc(3 * (size_t)n, sizeof(double));
    if (x == NULL || v == NULL) st = CANOPY_ERR_MEMORY;
    if (st == CANOPY_OK) st = canopy_model_get_positions(m, x, n);
    for (int i = 0; i < n && st == CANOPY_OK; ++i) {
        const double px = x[3 * i], py = x[3 * i + 1];
        if (px < 1e-9 || py < 1e-9 || px > r.width - 1e-9 ||
            py > r.length - 1e-9) {
            st = canopy_model_set_fixed(m, i, 1);
            continue;
        }
        v[3 * i + 2] = (i % 2) ? 0.1 : -0.1;
    }
    if (st == CANOPY_OK) st = canopy_model_set_velocities(m, v, n);
    free(x);
    free(v);
    return st;
}

#endif
