/* build_rectangle.c — canopy_build_rectangle: near-equilateral triangulation of a flat rectilinear union of rectangles by staggered rows. */
#include "build_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The shape is a grid of x-segments [X_a, X_a+1] (nx[a] node spacings each)
 * and y-bands [Y_b, Y_b+1] (ny[b] row spacings each); cell (a, b) belongs to
 * the shape if cov[b * nxs + a]. Rows of nodes run along x, ny[b] + 1 per
 * band (a band's first and last rows are shared with its neighbours, so a
 * row lies exactly on every rectangle boundary). Rows alternate: an even row
 * splits each segment evenly, an odd row sits half a spacing off, with
 * extra nodes on the segment ends that bound the row's coverage (and, on
 * rows lying on a band boundary, on every segment end) so that the sides are
 * straight and the corners are nodes. Consecutive rows are zipped into
 * triangles over each covered x-interval of the band between them. With
 * row spacing (sqrt(3)/2) x spacing the interior is equilateral; the rows
 * are spaced at most that, so the half-cells along the sides keep angles
 * >= 30 degrees. */
typedef struct lattice {
    int nxs, nb;
    const double *X, *Y;      /* nxs + 1 and nb + 1 breakpoints */
    const int *nx, *ny;
    const unsigned char *cov; /* nb x nxs */
    double z;
} lattice;

/* Band of each row: the band below (-1 for the first row) and above (-1 for
 * the last), and the row's y. */
typedef struct row_info {
    int lo, hi;
    double y;
    int first, count;          /* node index of its first node, node count */
    size_t xs;                 /* offset of its x values in the x array */
} row_info;

static int covered(const lattice *L, const row_info *r, int a)
{
    return (r->lo >= 0 && L->cov[r->lo * L->nxs + a]) ||
           (r->hi >= 0 && L->cov[r->hi * L->nxs + a]);
}

/* x of the row's nodes, in increasing order, into xs (if not NULL); returns
 * their number. Breakpoints are copied exactly, so chains can be cut at
 * them by comparison. */
static int row_nodes(const lattice *L, const row_info *r, int offset,
                     double *xs)
{
    const int boundary = r->lo != r->hi;
    int n = 0;
    for (int a = 0; a < L->nxs; ++a) {
        if (!covered(L, r, a)) continue;
        const int prev = a > 0 && covered(L, r, a - 1);
        const int next = a + 1 < L->nxs && covered(L, r, a + 1);
        const double x0 = L->X[a], x1 = L->X[a + 1];
        const int k = L->nx[a];
        if (!prev) { if (xs) xs[n] = x0; ++n; }
        if (!offset) {
            for (int j = 1; j < k; ++j) {
                if (xs) xs[n] = x0 + (x1 - x0) * j / k;
                ++n;
            }
            if (xs) xs[n] = x1;
            ++n;
        } else {
            for (int j = 0; j < k; ++j) {
                if (xs) xs[n] = x0 + (x1 - x0) * (j + 0.5) / k;
                ++n;
            }
            if (!next || boundary) { if (xs) xs[n] = x1; ++n; }
        }
    }
    return n;
}

/* Nodes of row r with x in [x0, x1] as a chain; returns segments (count - 1). */
static int chain_in(const row_info *r, const double *xall, double x0,
                    double x1, int *chain)
{
    int n = 0;
    const double *xs = xall + r->xs;
    for (int j = 0; j < r->count; ++j)
        if (xs[j] >= x0 && xs[j] <= x1) chain[n++] = r->first + j;
    return n - 1;
}

static canopy_status lattice_fill(canopy_model *model, const lattice *L,
                                  const canopy_material *fabric,
                                  row_info *rows, int nrows, double *xall,
                                  int *chain_a, int *chain_b)
{
    canopy_status st;
    for (int r = 0; r < nrows; ++r) {
        const double *xs = xall + rows[r].xs;
        for (int j = 0; j < rows[r].count; ++j) {
            const double x[3] = {xs[j], rows[r].y, L->z};
            int idx;
            st = canopy_model_add_node(model, x, 0.0, CANOPY_GROUP_FABRIC,
                                       &idx);
            if (st != CANOPY_OK) return st;
            if (j == 0) rows[r].first = idx;
        }
    }
    canopy_fabric_builder fb;
    const double up[3] = {0.0, 0.0, 1.0};
    st = canopy_fabric_begin(&fb, model, fabric, CANOPY_GROUP_FABRIC, up,
                             3 * (size_t)model->nodes.count);
    if (st != CANOPY_OK) return st;
    for (int r = 0; r + 1 < nrows && st == CANOPY_OK; ++r) {
        const int b = rows[r].hi;
        for (int a = 0; a < L->nxs && st == CANOPY_OK; ++a) {
            if (!L->cov[b * L->nxs + a] ||
                (a > 0 && L->cov[b * L->nxs + a - 1]))
                continue;
            int a1 = a;
            while (a1 + 1 < L->nxs && L->cov[b * L->nxs + a1 + 1]) ++a1;
            const double x0 = L->X[a], x1 = L->X[a1 + 1];
            const int nl = chain_in(&rows[r], xall, x0, x1, chain_a);
            const int nu = chain_in(&rows[r + 1], xall, x0, x1, chain_b);
            st = canopy_fabric_zip(&fb, chain_a, nl, chain_b, nu);
        }
    }
    canopy_fabric_end(&fb);
    return st;
}

/* Plan rows, check sizes, allocate, build; on failure after the first node
 * roll back. `who` names the builder, `args` the user's arguments that set
 * the sizes (for the messages). */
static canopy_status lattice_build(canopy_model *model, const lattice *L,
                                   const canopy_material *fabric,
                                   const char *who, const char *args)
{
    int nrows = 1;
    double row_max = 0.0;
    for (int b = 0; b < L->nb; ++b) nrows += L->ny[b];
    for (int a = 0; a < L->nxs; ++a) row_max += L->nx[a] + 2;
    if (!((double)nrows * row_max <= CANOPY_BUILD_MAX_ITEMS))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s need ~%.3g nodes, more than the builder's "
                           "limit %.3g", who, args, (double)nrows * row_max,
                           CANOPY_BUILD_MAX_ITEMS);
    row_info *rows = calloc((size_t)nrows, sizeof *rows);
    if (rows == NULL)
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           "%s: cannot allocate %d rows", who, nrows);
    int r = 0;
    for (int b = 0; b < L->nb; ++b) {
        for (int k = 0; k < L->ny[b]; ++k, ++r) {
            rows[r].lo = k == 0 ? b - 1 : b;
            rows[r].hi = b;
            rows[r].y = k == 0 ? L->Y[b]
                               : L->Y[b] + (L->Y[b + 1] - L->Y[b]) * k /
                                               L->ny[b];
        }
    }
    rows[r].lo = L->nb - 1;
    rows[r].hi = -1;
    rows[r].y = L->Y[L->nb];
    size_t total = 0;
    int widest = 0;
    for (r = 0; r < nrows; ++r) {
        rows[r].xs = total;
        rows[r].count = row_nodes(L, &rows[r], r % 2, NULL);
        total += (size_t)rows[r].count;
        if (rows[r].count > widest) widest = rows[r].count;
    }
    double *xall = malloc(total * sizeof *xall);
    int *chain = malloc(2 * (size_t)widest * sizeof *chain);
    if (xall == NULL || chain == NULL) {
        free(xall);
        free(chain);
        free(rows);
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           "%s: cannot allocate %zu node positions", who,
                           total);
    }
    for (r = 0; r < nrows; ++r) row_nodes(L, &rows[r], r % 2, xall + rows[r].xs);

    canopy_build_mark mark;
    canopy_build_mark_take(model, &mark);
    canopy_status st = lattice_fill(model, L, fabric, rows, nrows, xall, chain,
                                    chain + widest);
    if (st != CANOPY_OK) st = canopy_build_abort(model, &mark, st, who, args);
    free(xall);
    free(chain);
    free(rows);
    return st;
}

canopy_status canopy_build_rectangle(canopy_model *model,
                                     const canopy_rectangle_spec *spec)
{
    static const char who[] = "build_rectangle";
    canopy_status st;
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (spec == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT, "%s: spec is NULL", who);
    if ((st = canopy_build_check_positive(model, who, "width",
                                          spec->width)))
        return st;
    if ((st = canopy_build_check_positive(model, who, "length",
                                          spec->length)))
        return st;
    st = canopy_build_check_flat(model, who, spec->edge_length, spec->origin,
                                 "origin", &spec->fabric);
    if (st != CANOPY_OK) return st;
    const double e = spec->edge_length;
    if (!(spec->width / e <= CANOPY_BUILD_MAX_ITEMS &&
          spec->length / e <= CANOPY_BUILD_MAX_ITEMS))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.edge_length %g is too small for %g x %g",
                           who, e, spec->width, spec->length);
    const double X[2] = {spec->origin[0], spec->origin[0] + spec->width};
    const double Y[2] = {spec->origin[1], spec->origin[1] + spec->length};
    const int nx = canopy_build_spacings(spec->width, e);
    const int ny = canopy_build_row_spacings(spec->length, spec->width / nx);
    const unsigned char cov = 1;
    const lattice L = {1, 1, X, Y, &nx, &ny, &cov, spec->origin[2]};
    char args[200];
    snprintf(args, sizeof args, "spec.width %g, spec.length %g and "
             "spec.edge_length %g at spec.origin (%g, %g, %g)", spec->width,
             spec->length, e, spec->origin[0], spec->origin[1],
             spec->origin[2]);
    st = lattice_build(model, &L, &spec->fabric, who, args);
    if (st == CANOPY_OK) canopy_clear_message(model);
    return st;
}
