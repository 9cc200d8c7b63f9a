/* build_cross.c — canopy_build_cross: a flat cross canopy triangulated with the cross's own four-fold symmetry (a square centre, four arms whose node rows run across them). */
#include "build_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Why not one lattice for the whole cross: a lattice of equilateral
 * triangles has straight lines of edges in three directions only, so with
 * rows along x the arms along y can fold down about a straight crease across
 * them while the arms along x can only fold about a zigzag, which costs
 * in-plane strain. A falling cross then closes like a taco: two opposite arms
 * fold, the other two stay out. Here every arm is built the same way in its
 * own frame, so a quarter turn about the centre maps the mesh onto itself:
 *
 *  - centre: the square w x w as an nc x nc grid of squares, each cut by the
 *    diagonal that points away from the centre (right isosceles triangles;
 *    a quarter turn maps the pattern onto itself);
 *  - arm: rows of nodes across the arm (parallel to its tip), nr row
 *    spacings from the centre's side to the tip; even rows have the nc + 1
 *    nodes of the centre's side, odd rows sit half a spacing off with the
 *    two side nodes added, so that the sides are straight; row 0 is the
 *    centre's side, row nr (nr even) the tip; consecutive rows are zipped.
 *
 * Each arm has axis a (outwards) and across direction c = z x a; u runs
 * along c from -w/2 to w/2. */

/* Node index of the centre grid point (i, j), i along x, j along y. */
static int grid_node(int first, int nc, int i, int j)
{
    return first + j * (nc + 1) + i;
}

/* The centre's side facing arm k, as grid nodes in increasing u (t = 0..nc). */
static int side_node(int first, int nc, int arm, int t)
{
    switch (arm) {
    case 0: return grid_node(first, nc, nc, t);          /* +x: u along +y */
    case 1: return grid_node(first, nc, nc - t, nc);     /* +y: u along -x */
    case 2: return grid_node(first, nc, 0, nc - t);      /* -x: u along -y */
    default: return grid_node(first, nc, t, 0);          /* -y: u along +x */
    }
}

/* First node of row r (1..nr) of arm k: the arms' rows follow the centre
 * grid, arm after arm, row after row (even rows nc + 1 nodes, odd rows
 * nc + 2; nr is even, so an arm has nr (nc + 1) + nr / 2 nodes). */
static int row_node(int first, int nc, int nr, int k, int r)
{
    return first + (nc + 1) * (nc + 1) + k * (nr * (nc + 1) + nr / 2) +
           (r - 1) * (nc + 1) + r / 2;
}

/* u of node t of a row: even rows at the nc + 1 grid points, odd rows at the
 * two sides and the nc midpoints between (nc + 2 nodes). */
static double row_u(int odd, int nc, double w, int t)
{
    if (!odd) return -0.5 * w + w * t / nc;
    if (t == 0) return -0.5 * w;
    if (t == nc + 1) return 0.5 * w;
    return -0.5 * w + w * (t - 0.5) / nc;
}

static canopy_status cross_fill(canopy_model *model,
                                const canopy_cross_spec *spec, int nc, int nr,
                                int *lower, int *upper, int *attach_out)
{
    const double S = spec->span, w = spec->arm_width;
    const double *o = spec->center;
    const double arm_length = 0.5 * (S - w);
    const double axis[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    canopy_status st;

    /* Centre grid */
    const int first = model->nodes.count;
    for (int j = 0; j <= nc; ++j)
        for (int i = 0; i <= nc; ++i) {
            const double x[3] = {o[0] - 0.5 * w + w * i / nc,
                                 o[1] - 0.5 * w + w * j / nc, o[2]};
            st = canopy_model_add_node(model, x, 0.0, CANOPY_GROUP_FABRIC,
                                       NULL);
            if (st != CANOPY_OK) return st;
        }
    /* Arm rows 1..nr, arm after arm (the order row_node counts) */
    for (int k = 0; k < 4; ++k) {
        const double ax = axis[k][0], ay = axis[k][1];
        const double cx = -ay, cy = ax;                  /* c = z x a */
        for (int r = 1; r <= nr; ++r) {
            const double d = 0.5 * w + arm_length * r / nr;
            const int odd = r % 2, count = odd ? nc + 2 : nc + 1;
            for (int t = 0; t < count; ++t) {
                const double u = row_u(odd, nc, w, t);
                const double x[3] = {o[0] + d * ax + u * cx,
                                     o[1] + d * ay + u * cy, o[2]};
                st = canopy_model_add_node(model, x, 0.0, CANOPY_GROUP_FABRIC,
                                           NULL);
                if (st != CANOPY_OK) return st;
            }
        }
    }

    canopy_fabric_builder fb;
    const double up[3] = {0.0, 0.0, 1.0};
    st = canopy_fabric_begin(&fb, model, &spec->fabric, CANOPY_GROUP_FABRIC,
                             up, 3 * (size_t)model->nodes.count);
    if (st != CANOPY_OK) return st;
    /* Centre: the diagonal of each square points away from the centre */
    for (int j = 0; j < nc && st == CANOPY_OK; ++j)
        for (int i = 0; i < nc && st == CANOPY_OK; ++i) {
            const int p00 = grid_node(first, nc, i, j);
            const int p10 = grid_node(first, nc, i + 1, j);
            const int p01 = grid_node(first, nc, i, j + 1);
            const int p11 = grid_node(first, nc, i + 1, j + 1);
            const int outward_rising = (2 * i + 1 - nc) * (2 * j + 1 - nc) > 0;
            if (outward_rising) {
                st = canopy_fabric_triangle(&fb, p00, p10, p11);
                if (st == CANOPY_OK)
                    st = canopy_fabric_triangle(&fb, p00, p11, p01);
            } else {
                st = canopy_fabric_triangle(&fb, p00, p10, p01);
                if (st == CANOPY_OK)
                    st = canopy_fabric_triangle(&fb, p10, p11, p01);
            }
        }
    /* Arms: zip each row to the next */
    for (int k = 0; k < 4 && st == CANOPY_OK; ++k) {
        for (int t = 0; t <= nc; ++t) lower[t] = side_node(first, nc, k, t);
        int nl = nc;
        for (int r = 1; r <= nr && st == CANOPY_OK; ++r) {
            const int nu = r % 2 ? nc + 1 : nc;
            const int f = row_node(first, nc, nr, k, r);
            for (int t = 0; t <= nu; ++t) upper[t] = f + t;
            st = canopy_fabric_zip(&fb, lower, nl, upper, nu);
            for (int t = 0; t <= nu; ++t) lower[t] = upper[t];
            nl = nu;
        }
    }
    canopy_fabric_end(&fb);

    /* Attachments: m per tip (row nr, even), corners included, counter-
     * clockwise from the +x tip; u rises along c, which is that order. */
    if (st == CANOPY_OK && attach_out) {
        const int m = spec->n_attachments / 4;
        for (int k = 0; k < 4; ++k) {
            const int tip = row_node(first, nc, nr, k, nr);
            for (int t = 0; t < m; ++t)
                attach_out[k * m + t] =
                    tip + (m >= 2 ? t * nc / (m - 1) : nc / 2);
        }
    }
    return st;
}

canopy_status canopy_build_cross(canopy_model *model,
                                 const canopy_cross_spec *spec,
                                 int *attach_out)
{
    static const char who[] = "build_cross";
    canopy_status st;
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (spec == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT, "%s: spec is NULL", who);
    if ((st = canopy_build_check_positive(model, who, "span",
                                          spec->span)))
        return st;
    if ((st = canopy_build_check_positive(model, who, "arm_width",
                                          spec->arm_width)))
        return st;
    if (!(spec->arm_width < spec->span))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.arm_width %g must be smaller than "
                           "spec.span %g", who, spec->arm_width, spec->span);
    if (spec->n_attachments < 4 || spec->n_attachments % 4 != 0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.n_attachments %d must be a positive "
                           "multiple of 4", who, spec->n_attachments);
    st = canopy_build_check_flat(model, who, spec->edge_length, spec->center,
                                 "center", &spec->fabric);
    if (st != CANOPY_OK) return st;
    const double e = spec->edge_length, S = spec->span, w = spec->arm_width;
    const int m = spec->n_attachments / 4;   /* per arm tip */
    if (!(S / e <= CANOPY_BUILD_MAX_ITEMS && m <= CANOPY_BUILD_MAX_ITEMS / 4))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.edge_length %g (or spec.n_attachments %d) "
                           "is out of proportion to spec.span %g", who, e,
                           spec->n_attachments, S);
    /* Spacings across an arm: a multiple of the m - 1 attachment intervals
     * (so that the attachments are tip nodes) and even (so that the centre's
     * diagonals have a quarter turn's symmetry and m = 1 has a middle node) */
    const int q0 = m >= 2 ? m - 1 : 2;
    const int q = q0 % 2 == 0 ? q0 : 2 * q0;
    const int nc = q * canopy_build_spacings(w / q, e);
    /* Rows along an arm: spaced at most (sqrt(3)/2) w / nc, an even count
     * so that the tip row is an even (unshifted) row */
    int nr = canopy_build_row_spacings(0.5 * (S - w), w / nc);
    if (nr % 2) ++nr;
    char args[200];
    snprintf(args, sizeof args, "spec.span %g, spec.arm_width %g, "
             "spec.edge_length %g and spec.n_attachments %d at spec.center "
             "(%g, %g, %g)", S, w, e, spec->n_attachments, spec->center[0],
             spec->center[1], spec->center[2]);
    const double nodes = (nc + 1.0) * (nc + 1.0) + 4.0 * nr * (nc + 2.0);
    if (!(nodes <= CANOPY_BUILD_MAX_ITEMS))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s need ~%.3g nodes (the arms' rows are "
                           "spaced like the nodes across them), more than "
                           "the builder's limit %.3g", who, args, nodes,
                           CANOPY_BUILD_MAX_ITEMS);
    int *chains = malloc(2 * (size_t)(nc + 2) * sizeof *chains);
    if (chains == NULL)
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           "%s: cannot allocate %d chain nodes", who,
                           2 * (nc + 2));
    canopy_build_mark mark;
    canopy_build_mark_take(model, &mark);
    st = cross_fill(model, spec, nc, nr, chains, chains + nc + 2, attach_out);
    free(chains);
    if (st != CANOPY_OK) return canopy_build_abort(model, &mark, st, who, args);
    canopy_clear_message(model);
    return CANOPY_OK;
}
