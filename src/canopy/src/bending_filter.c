/* bending_filter.c — the hinge dashpots' high-pass filter: they act on the cloth velocity's deviation from its local linear fit, so smooth shape changes are left alone. */
#include "model_internal.h"

#include <math.h>
#include <stdlib.h>

/* With the filter on, the hinge dashpots' damping matrix C (bending.c)
 * becomes P^T F C F P with P = I - A and F zeroing the fixed nodes (they
 * do not move, and a hinge's c counts only its free nodes' inertia).
 * (A w)_i is the value at node i of the least-squares linear fit
 * a + g.xi of w over node i and its cloth neighbours (the nodes it shares
 * a triangle edge with), xi their positions in node i's tangent plane. A reproduces any field linear over
 * the stencil, so P w is the second-difference part of w, ~ (k h)^2 w for
 * a smooth field of wavenumber k on edges h, but of the order of w for
 * flapping at the mesh scale. A smooth bending then decays at
 * ~ rate (k h)^8 instead of ~ rate (k h)^4 (test_bending_damping_scale.c),
 * while single triangles' flapping still decays at about the rate.
 * P^T F C F P is symmetric positive semi-definite, so the dashpots still
 * only dissipate. A's rows sum to 1 (a constant is fitted exactly), so
 * 1^T P^T = 0 and linear momentum is kept; a rigid rotation is linear in
 * space, so P leaves only its O(h^2 curvature) part off the tangent plane.
 * Where the fit is ill-posed (neighbours nearly on a line in the tangent
 * plane, as in a tightly folded cloth) A falls back to the stencil's mean.
 * Nodes on no triangle have the stencil {i}: P's row is 0. */

void canopy_hinge_filter_free(canopy_hinge_filter *f)
{
    free(f->start);
    free(f->nodes);
    free(f->weights);
    free(f->normals);
    free(f->filtered);
    free(f->spread);
    free(f->slot);
    free(f->touched);
    free(f->row);
    f->start = f->nodes = f->slot = f->touched = NULL;
    f->weights = f->normals = f->filtered = f->spread = f->row = NULL;
}

canopy_status canopy_hinge_filter_build(canopy_model *m, const int *edges,
                                        int n_edges)
{
    canopy_hinge_filter *f = &m->hinges.filter;
    canopy_hinge_filter_free(f);
    const int n = m->nodes.count;
    const size_t entries = (size_t)n + 2 * (size_t)n_edges;
    f->start = calloc((size_t)n + 1, sizeof(int));
    f->nodes = malloc(entries * sizeof(int));
    f->weights = malloc(entries * sizeof(double));
    f->normals = malloc(3 * (size_t)n * sizeof(double));
    f->filtered = malloc(3 * (size_t)n * sizeof(double));
    f->spread = malloc(3 * (size_t)n * sizeof(double));
    f->slot = malloc((size_t)n * sizeof(int));
    if (!f->start || !f->nodes || !f->weights || !f->normals ||
        !f->filtered || !f->spread || !f->slot) {
        canopy_hinge_filter_free(f);
        return canopy_fail(m, CANOPY_ERR_MEMORY,
                           "cannot allocate the bending damping filter of %d "
                           "nodes", n);
    }
    /* stencil sizes: the node itself and its neighbours */
    for (int i = 0; i < n; ++i) f->start[i + 1] = 1;
    for (int e = 0; e < n_edges; ++e) {
        ++f->start[edges[2 * e] + 1];
        ++f->start[edges[2 * e + 1] + 1];
    }
    for (int i = 0; i < n; ++i) f->start[i + 1] += f->start[i];
    int *fill = f->slot;
    for (int i = 0; i < n; ++i) {
        f->nodes[f->start[i]] = i;
        fill[i] = f->start[i] + 1;
    }
    for (int e = 0; e < n_edges; ++e) {
        const int a = edges[2 * e], b = edges[2 * e + 1];
        f->nodes[fill[a]++] = b;
        f->nodes[fill[b]++] = a;
    }
    /* a hinge's row of U F P touches at most its four stencils */
    f->largest = 0;
    for (int i = 0; i < n; ++i) {
        f->slot[i] = -1;
        if (f->start[i + 1] - f->start[i] > f->largest)
            f->largest = f->start[i + 1] - f->start[i];
    }
    f->touched = malloc(4 * (size_t)f->largest * sizeof(int));
    f->row = malloc(12 * (size_t)f->largest * sizeof(double));
    if (!f->touched || !f->row) {
        canopy_hinge_filter_free(f);
        return canopy_fail(m, CANOPY_ERR_MEMORY,
                           "cannot allocate the bending damping filter of %d "
                           "nodes", n);
    }
    return CANOPY_OK;
}

/* An orthonormal basis t1, t2 of the plane normal to `normal`; 0 when the
 * normal is zero (a node on no triangle of nonzero area). */
static int tangent_basis(const double *normal, double t1[3], double t2[3])
{
    const double len = sqrt(normal[0] * normal[0] + normal[1] * normal[1] +
                            normal[2] * normal[2]);
    if (!(len > 0.0)) return 0;
    const double nz[3] = {normal[0] / len, normal[1] / len, normal[2] / len};
    /* the axis least aligned with n */
    int axis = 0;
    for (int d = 1; d < 3; ++d)
        if (fabs(nz[d]) < fabs(nz[axis])) axis = d;
    double e[3] = {0.0, 0.0, 0.0};
    e[axis] = 1.0;
    /* t1 = n x e normalised, t2 = n x t1 */
    t1[0] = nz[1] * e[2] - nz[2] * e[1];
    t1[1] = nz[2] * e[0] - nz[0] * e[2];
    t1[2] = nz[0] * e[1] - nz[1] * e[0];
    const double l1 = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (int d = 0; d < 3; ++d) t1[d] /= l1;
    t2[0] = nz[1] * t1[2] - nz[2] * t1[1];
    t2[1] = nz[2] * t1[0] - nz[0] * t1[2];
    t2[2] = nz[0] * t1[1] - nz[1] * t1[0];
    return 1;
}

/* phi = (1, xi1, xi2): node j's coordinates in node i's tangent plane
 * (basis t1, t2), over scale */
static void fit_basis(const double *x, int i, int j, const double t1[3],
                      const double t2[3], double scale, double phi[3])
{
    const double *xi = x + 3 * i, *xj = x + 3 * j;
    const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
    phi[0] = 1.0;
    phi[1] = (d[0] * t1[0] + d[1] * t1[1] + d[2] * t1[2]) / scale;
    phi[2] = (d[0] * t2[0] + d[1] * t2[1] + d[2] * t2[2]) / scale;
}

/* Weights of node i's stencil: the linear fit's value at node i, or the
 * stencil's mean where the fit is ill-posed. */
static void stencil_weights(const canopy_hinge_filter *f, const double *x,
                            int i)
{
    const int s0 = f->start[i], s1 = f->start[i + 1], count = s1 - s0;
    double *w = f->weights + s0;
    double t1[3], t2[3];
    int fitted = 0;
    if (count >= 3 && tangent_basis(f->normals + 3 * i, t1, t2)) {
        /* tangent coordinates, scaled by the mean neighbour distance */
        const double *xi = x + 3 * i;
        double scale = 0.0;
        for (int s = s0 + 1; s < s1; ++s) {
            const double *xj = x + 3 * f->nodes[s];
            const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
            scale += sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        }
        scale /= count - 1;
        if (scale > 0.0) {
            /* normal matrix M = sum phi phi^T */
            double M[3][3] = {{0.0}}, phi[3];
            for (int s = s0; s < s1; ++s) {
                fit_basis(x, i, f->nodes[s], t1, t2, scale, phi);
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) M[a][b] += phi[a] * phi[b];
            }
            /* y = M^-1 e1 (the first column of the adjugate over det) */
            const double c0 = M[1][1] * M[2][2] - M[1][2] * M[2][1];
            const double c1 = M[1][2] * M[2][0] - M[1][0] * M[2][2];
            const double c2 = M[1][0] * M[2][1] - M[1][1] * M[2][0];
            const double det = M[0][0] * c0 + M[0][1] * c1 + M[0][2] * c2;
            /* a well-spread stencil of p points has det ~ p^3 / 10 */
            if (det > 1e-3 * count * count * count) {
                for (int s = s0; s < s1; ++s) {
                    fit_basis(x, i, f->nodes[s], t1, t2, scale, phi);
                    w[s - s0] = (c0 * phi[0] + c1 * phi[1] + c2 * phi[2]) / det;
                }
                fitted = 1;
            }
        }
    }
    if (!fitted)
        for (int s = 0; s < count; ++s) w[s] = 1.0 / count;
}

void canopy_hinge_filter_weights(canopy_model *m, const double *x)
{
    canopy_hinge_filter *f = &m->hinges.filter;
    const int n = m->nodes.count;
    for (int k = 0; k < 3 * n; ++k) f->normals[k] = 0.0;
    const canopy_triangles *t = &m->tris;
    for (int k = 0; k < t->count; ++k) {
        const int *tri = t->nodes + 3 * k;
        double an[3];
        canopy_triangle_area_normal(x, tri, an);
        for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) f->normals[3 * tri[c] + d] += an[d];
    }
    for (int i = 0; i < n; ++i) stencil_weights(f, x, i);
}

void canopy_hinge_filter_apply(const canopy_model *m, const double *w,
                               double *out)
{
    const canopy_hinge_filter *f = &m->hinges.filter;
    for (int i = 0; i < m->nodes.count; ++i) {
        double fit[3] = {0.0, 0.0, 0.0};
        for (int s = f->start[i]; s < f->start[i + 1]; ++s) {
            const double *wj = w + 3 * f->nodes[s];
            for (int d = 0; d < 3; ++d) fit[d] += f->weights[s] * wj[d];
        }
        for (int d = 0; d < 3; ++d) out[3 * i + d] = w[3 * i + d] - fit[d];
    }
}

void canopy_hinge_filter_apply_transpose(const canopy_model *m,
                                         const double *z, double *out)
{
    const canopy_hinge_filter *f = &m->hinges.filter;
    const int n = m->nodes.count;
    for (int k = 0; k < 3 * n; ++k) out[k] = z[k];
    for (int i = 0; i < n; ++i) {
        const double *zi = z + 3 * i;
        for (int s = f->start[i]; s < f->start[i + 1]; ++s) {
            double *oj = out + 3 * f->nodes[s];
            for (int d = 0; d < 3; ++d) oj[d] -= f->weights[s] * zi[d];
        }
    }
}

void canopy_hinge_filter_add_diagonal(canopy_model *m, int k,
                                      const double u[4][3], double scale,
                                      double *diag)
{
    /* row k of U F P: node j gets sum_a u_a P_{n_a j} over the free n_a,
     * P_{n_a j} = delta - A */
    canopy_hinge_filter *f = &m->hinges.filter;
    const int *hn = m->hinges.nodes + 4 * k;
    int *touched = f->touched;
    double (*row)[3] = (double (*)[3])f->row;
    int count = 0;
    for (int a = 0; a < 4; ++a) {
        const int i = hn[a];
        if (m->nodes.fixed[i]) continue; /* F: fixed nodes do not move */
        for (int s = f->start[i]; s < f->start[i + 1]; ++s) {
            const int j = f->nodes[s];
            const double p = (j == i ? 1.0 : 0.0) - f->weights[s];
            if (f->slot[j] < 0) {
                f->slot[j] = count;
                touched[count] = j;
                row[count][0] = row[count][1] = row[count][2] = 0.0;
                ++count;
            }
            double *r = row[f->slot[j]];
            for (int d = 0; d < 3; ++d) r[d] += p * u[a][d];
        }
    }
    for (int c = 0; c < count; ++c) {
        const int j = touched[c];
        f->slot[j] = -1;
        if (m->nodes.fixed[j]) continue;
        for (int d = 0; d < 3; ++d)
            diag[3 * j + d] += scale * row[c][d] * row[c][d];
    }
}
