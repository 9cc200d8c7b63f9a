/* bending.c — hinge dashpots: damping of the cloth's bending rate (the dihedral angle between neighbouring triangles). */
#include "model_internal.h"

#include <math.h>
#include <stdlib.h>

/* A hinge is an edge shared by two triangles: opposite nodes o1, o2 and edge
 * nodes p, q, stored as (o1, o2, p, q). With x1 = o1, x2 = o2, x3 = p,
 * x4 = q, n1 = (x1 - x3) x (x1 - x4), n2 = (x2 - x4) x (x2 - x3) and
 * e = x4 - x3, the gradient of the dihedral angle theta is -u_i with
 *   u1 = |e| n1 / |n1|^2,   u2 = |e| n2 / |n2|^2,
 *   u3 = ((x1 - x4).e / |e|) n1 / |n1|^2 + ((x2 - x4).e / |e|) n2 / |n2|^2,
 *   u4 = -(u1 + u2 + u3)
 * (the bending modes of Bridson, Marino & Fedkiw 2003). The hinge dashpot
 *   f_i = -c (dtheta/dt) dtheta/dx_i = -c (sum_j u_j.v_j) u_i
 * only dissipates: translation and rotation leave theta unchanged, so rigid
 * motion and momentum are untouched, and a flat sheet's in-plane motion
 * too. It damps the out-of-plane flapping of single cloth triangles, which
 * the edge dashpots (along the springs) do not. The hinge's own bending
 * mode has the inertia m_h = 1 / sum_a (|u_a|^2 / m_a) (the least kinetic
 * energy for a given dtheta/dt), so
 *   c = gamma m_h
 * makes it decay at the rate gamma [1/s] on any mesh: small triangles (a
 * vent's) get as much damping per unit time as large ones, not the
 * (size)^-4 more of a bending viscosity. Fixed nodes do not move (1/m = 0).
 * For smooth motion of curvature rate dkappa/dt the hinges dissipate
 * ~ gamma rho_s h^2 |dkappa/dt|^2 per area (h the edge length), which
 * vanishes as the mesh is refined. */

typedef struct hinge_edge {
    int a, b;       /* edge nodes, a < b */
    int opposite;   /* the triangle's third node */
} hinge_edge;

static int compare_edges(const void *pa, const void *pb)
{
    const hinge_edge *x = pa, *y = pb;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return 0;
}

canopy_status canopy_hinges_build(canopy_model *m)
{
    canopy_hinges *h = &m->hinges;
    free(h->nodes);
    free(h->modes);
    h->nodes = NULL;
    h->modes = NULL;
    h->count = 0;
    canopy_hinge_filter_free(&h->filter);
    const canopy_triangles *t = &m->tris;
    if (m->bending_damping == 0.0 || t->count == 0) return CANOPY_OK;
    if (m->bending_filter && !m->bending_implicit)
        return canopy_fail(m, CANOPY_ERR_STATE,
                           "the bending damping filter "
                           "(set_bending_damping_filter) needs the implicit "
                           "hinge dashpots (set_bending_damping_implicit)");

    const size_t n_edges = 3 * (size_t)t->count;
    hinge_edge *edges = malloc(n_edges * sizeof *edges);
    if (edges == NULL)
        return canopy_fail(m, CANOPY_ERR_MEMORY,
                           "cannot allocate the hinges of %d triangles",
                           t->count);
    for (int k = 0; k < t->count; ++k) {
        const int *tri = t->nodes + 3 * k;
        for (int c = 0; c < 3; ++c) {
            const int p = tri[c], q = tri[(c + 1) % 3];
            hinge_edge *e = edges + 3 * k + c;
            e->a = p < q ? p : q;
            e->b = p < q ? q : p;
            e->opposite = tri[(c + 2) % 3];
        }
    }
    qsort(edges, n_edges, sizeof *edges, compare_edges);

    /* Edges met twice (a non-manifold edge pairs its triangles in turn) */
    int count = 0;
    for (size_t k = 0; k + 1 < n_edges; ++k)
        if (compare_edges(edges + k, edges + k + 1) == 0) ++count;
    if (count > 0) {
        h->nodes = malloc(4 * sizeof(int) * (size_t)count);
        h->modes = malloc(13 * sizeof(double) * (size_t)count);
        if (h->nodes == NULL || h->modes == NULL) {
            free(h->nodes);
            free(h->modes);
            h->nodes = NULL;
            h->modes = NULL;
            free(edges);
            return canopy_fail(m, CANOPY_ERR_MEMORY,
                               "cannot allocate %d hinges", count);
        }
    }
    for (size_t k = 0; k + 1 < n_edges; ++k) {
        if (compare_edges(edges + k, edges + k + 1) != 0) continue;
        int *hn = h->nodes + 4 * h->count++;
        hn[0] = edges[k].opposite;
        hn[1] = edges[k + 1].opposite;
        hn[2] = edges[k].a;
        hn[3] = edges[k].b;
    }
    canopy_status st = CANOPY_OK;
    if (m->bending_filter) {
        /* the cloth edges, each once, as node pairs */
        int *pairs = malloc(2 * sizeof(int) * n_edges), n_pairs = 0;
        if (pairs == NULL) {
            free(edges);
            return canopy_fail(m, CANOPY_ERR_MEMORY,
                               "cannot allocate the %zu cloth edges", n_edges);
        }
        for (size_t k = 0; k < n_edges; ++k) {
            if (k > 0 && compare_edges(edges + k, edges + k - 1) == 0)
                continue;
            pairs[2 * n_pairs] = edges[k].a;
            pairs[2 * n_pairs + 1] = edges[k].b;
            ++n_pairs;
        }
        st = canopy_hinge_filter_build(m, pairs, n_pairs);
        free(pairs);
    }
    free(edges);
    return st;
}

/* The bending modes u (4 x 3) and the dashpot c of hinge k at x; 0 for a
 * degenerate hinge (a triangle of zero area). c gives the hinge's bending
 * the decay rate m->bending_damping with the nodes' own masses: an added
 * mass (set_added_mass) changes neither c nor the update of
 * bending_implicit.c. */
int canopy_hinge_modes(const canopy_model *m, const double *x, int k,
                       double u[4][3], double *c)
{
    const int *hn = m->hinges.nodes + 4 * k;
    const double *x1 = x + 3 * hn[0], *x2 = x + 3 * hn[1];
    const double *x3 = x + 3 * hn[2], *x4 = x + 3 * hn[3];
    double d14[3], d24[3], e[3], n1[3], n2[3];
    for (int d = 0; d < 3; ++d) {
        d14[d] = x1[d] - x4[d];
        d24[d] = x2[d] - x4[d];
        e[d] = x4[d] - x3[d];
    }
    /* n1, n2: twice the area normals of (x1, x3, x4) and (x2, x4, x3) */
    const int t1[3] = {hn[0], hn[2], hn[3]}, t2[3] = {hn[1], hn[3], hn[2]};
    canopy_triangle_area_normal(x, t1, n1);
    canopy_triangle_area_normal(x, t2, n2);
    for (int d = 0; d < 3; ++d) {
        n1[d] *= 2.0;
        n2[d] *= 2.0;
    }
    const double N1 = n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2];
    const double N2 = n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2];
    const double le2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    if (!(N1 > 0.0) || !(N2 > 0.0) || !(le2 > 0.0)) return 0;
    const double le = sqrt(le2);
    const double s1 = (d14[0] * e[0] + d14[1] * e[1] + d14[2] * e[2]) / le;
    const double s2 = (d24[0] * e[0] + d24[1] * e[1] + d24[2] * e[2]) / le;
    for (int d = 0; d < 3; ++d) {
        const double a1 = n1[d] / N1, a2 = n2[d] / N2;
        u[0][d] = le * a1;
        u[1][d] = le * a2;
        u[2][d] = s1 * a1 + s2 * a2;
        u[3][d] = -(u[0][d] + u[1][d] + u[2][d]);
    }
    double inv_inertia = 0.0, all = 0.0, free = 0.0;
    for (int a = 0; a < 4; ++a) {
        const int i = hn[a];
        const double u2 = u[a][0] * u[a][0] + u[a][1] * u[a][1] +
                          u[a][2] * u[a][2];
        all += u2;
        if (m->nodes.fixed[i]) continue;
        free += u2;
        inv_inertia += u2 / m->nodes.mass[i];
    }
    /* Free nodes on the hinge's axis only, beside fixed wings (a pinned
     * edge): their modes are round-off, c u u^T would damp them along a
     * direction of noise. The hinge cannot bend; leave it out. */
    if (!(inv_inertia > 0.0) || !(free > 1e-16 * all)) return 0;
    *c = m->bending_damping / inv_inertia;
    return 1;
}

void canopy_hinge_apply(const canopy_model *m, int k, const double u[4][3],
                        double c, const double *w, double *y, double scale,
                        int free_only)
{
    const unsigned char *fixed = m->nodes.fixed;
    const int *hn = m->hinges.nodes + 4 * k;
    double rate = 0.0;
    for (int a = 0; a < 4; ++a) {
        if (free_only && fixed[hn[a]]) continue;
        const double *wa = w + 3 * hn[a];
        rate += u[a][0] * wa[0] + u[a][1] * wa[1] + u[a][2] * wa[2];
    }
    const double s = scale * c * rate;
    for (int a = 0; a < 4; ++a) {
        if (free_only && fixed[hn[a]]) continue;
        double *ya = y + 3 * hn[a];
        ya[0] += s * u[a][0]; ya[1] += s * u[a][1]; ya[2] += s * u[a][2];
    }
}

/* y += sign C w over every hinge, its modes at x */
static void apply_hinge_damping(const canopy_model *m, const double *x,
                                const double *w, double *y, double sign,
                                int free_only)
{
    for (int k = 0; k < m->hinges.count; ++k) {
        double u[4][3], c;
        if (canopy_hinge_modes(m, x, k, u, &c))
            canopy_hinge_apply(m, k, u, c, w, y, sign, free_only);
    }
}

void canopy_hinge_forces(const canopy_model *m, const double *x,
                         const double *v, double *f)
{
    apply_hinge_damping(m, x, v, f, -1.0, 0);
}

void canopy_hinge_tangent_damping(const canopy_model *m, const double *x,
                                  const double *w, double *y)
{
    apply_hinge_damping(m, x, w, y, 1.0, 1);
}

void canopy_hinge_damping_sums(const canopy_model *m, const double *x,
                               double *sum, int stride)
{
    /* Block Gershgorin on C = c u u^T: row block i sums c |u_i| |u_j| over
     * the free nodes j (fixed nodes do not move: no row, no column) */
    for (int k = 0; k < m->hinges.count; ++k) {
        double u[4][3], c;
        if (!canopy_hinge_modes(m, x, k, u, &c)) continue;
        const int *hn = m->hinges.nodes + 4 * k;
        double norm[4], total = 0.0;
        for (int a = 0; a < 4; ++a) {
            norm[a] = m->nodes.fixed[hn[a]]
                    ? 0.0
                    : sqrt(u[a][0] * u[a][0] + u[a][1] * u[a][1] +
                           u[a][2] * u[a][2]);
            total += norm[a];
        }
        for (int a = 0; a < 4; ++a) sum[stride * hn[a]] += c * norm[a] * total;
    }
}
