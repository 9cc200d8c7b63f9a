/* inertia.c — the nodes' inertia as a whole: the per-node masses and the triangles' consistent added mass. */
#include "model_internal.h"

/* A triangle t of added mass m_t moving with its nodes' mean acceleration
 * abar_t = (a_a + a_b + a_c)/3 has the kinetic-energy rate m_t abar_t.v;
 * its inertia force on each node is a third of m_t abar_t, so
 *   M_t = (m_t / 9) 1_t 1_t^T   (in every direction),
 * symmetric and positive semi-definite. For a uniform acceleration it gives
 * each node a third of the adjacent triangles' m_t, as a lumped mass
 * would; a motion whose mean over every triangle is zero has none. */
static void triangle_inertia_add(const canopy_model *m, const double *u,
                                 double *y)
{
    const canopy_triangles *tr = &m->tris;
    for (int t = 0; t < tr->count; ++t) {
        const double w = tr->added_mass[t] / 9.0;
        if (!(w > 0.0)) continue;
        const int *nd = tr->nodes + 3 * t;
        for (int d = 0; d < 3; ++d) {
            const double s =
                w * (u[3 * nd[0] + d] + u[3 * nd[1] + d] + u[3 * nd[2] + d]);
            y[3 * nd[0] + d] += s;
            y[3 * nd[1] + d] += s;
            y[3 * nd[2] + d] += s;
        }
    }
}

void canopy_inertia_apply_all(const canopy_model *m, const double *u,
                              double *y)
{
    for (int i = 0; i < m->nodes.count; ++i)
        canopy_inertia_apply(m, i, u + 3 * i, y + 3 * i);
    if (m->triangle_added_mass) triangle_inertia_add(m, u, y);
}

void canopy_inertia_diagonal_all(const canopy_model *m, double *diag)
{
    for (int i = 0; i < m->nodes.count; ++i)
        canopy_inertia_diagonal(m, i, diag + 3 * i);
    if (!m->triangle_added_mass) return;
    const canopy_triangles *tr = &m->tris;
    for (int t = 0; t < tr->count; ++t) {
        const double w = tr->added_mass[t] / 9.0;
        for (int k = 0; k < 3; ++k) {
            const int i = tr->nodes[3 * t + k];
            diag[3 * i] += w;
            diag[3 * i + 1] += w;
            diag[3 * i + 2] += w;
        }
    }
}
