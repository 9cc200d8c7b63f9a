/* build_lines.c — canopy_build_chord and canopy_build_suspension_lines: straight strings of equal segments with linear-density masses, and the payload confluence. */
#include "build_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Springs and interior nodes of a straight string from node a (existing) to
 * node *b in n_seg equal segments; if *b < 0 the end node is created (last,
 * at end_pos, so a new string's nodes are numbered in order) and *b set.
 * Interior nodes (group `group`) get the linear density x segment length
 * (half from each adjacent segment); the two end nodes get nothing here:
 * *end_mass_a / *end_mass_b receive what each is owed (half a segment), for
 * the caller to add once nothing can fail any more. */
static canopy_status string_between(canopy_model *model, int a, int *b_io,
                                    const double *end_pos, int n_seg,
                                    const canopy_material *mat,
                                    canopy_group group, double *end_mass_a,
                                    double *end_mass_b)
{
    int b = *b_io;
    double xa[3], xb[3];
    for (int d = 0; d < 3; ++d) {
        xa[d] = model->nodes.x[3 * a + d];
        xb[d] = b >= 0 ? model->nodes.x[3 * b + d] : end_pos[d];
    }
    int prev = a;
    double prev_half = 0.0;
    canopy_status st;
    for (int s = 1; s <= n_seg; ++s) {
        int node = b;
        if (s < n_seg || b < 0) {
            const double t = (double)s / n_seg;
            const double x[3] = {s < n_seg ? xa[0] + (xb[0] - xa[0]) * t : xb[0],
                                 s < n_seg ? xa[1] + (xb[1] - xa[1]) * t : xb[1],
                                 s < n_seg ? xa[2] + (xb[2] - xa[2]) * t : xb[2]};
            if ((st = canopy_model_add_node(model, x, 0.0, group, &node)) !=
                CANOPY_OK)
                return st;
            if (s == n_seg) *b_io = node;
        }
        double l0;
        st = canopy_build_string_spring(model, prev, node, mat, group, &l0);
        if (st != CANOPY_OK) return st;
        /* Lumped mass: half of each adjacent segment's rho l0 (NOTES §3). */
        const double half = 0.5 * mat->density * l0;
        if (prev == a)
            *end_mass_a = half;
        else if ((st = canopy_model_add_node_mass(model, prev,
                                                  prev_half + half)) !=
                 CANOPY_OK)
            return st;
        prev_half = half;
        prev = node;
    }
    *end_mass_b = prev_half;
    return CANOPY_OK;
}

static canopy_status check_group(canopy_model *model, const char *who,
                                 canopy_group group)
{
    if ((int)group < 0 || (int)group > (int)CANOPY_GROUP_OTHER)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: group %d is not a canopy_group", who,
                           (int)group);
    return CANOPY_OK;
}

canopy_status canopy_build_chord(canopy_model *model, const double start[3],
                                 const double end[3], int n_segments,
                                 const canopy_material *material,
                                 canopy_group group, int first_node,
                                 int *last_node_out)
{
    static const char who[] = "build_chord";
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (first_node >= 0 && first_node >= model->nodes.count)
        return canopy_fail(model, CANOPY_ERR_RANGE,
                           "%s: first_node %d outside [0, %d)", who,
                           first_node, model->nodes.count);
    if (first_node < 0 && (start == NULL || !canopy_build_finite3(start)))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: start is NULL or not finite (and first_node "
                           "%d < 0)", who, first_node);
    if (end == NULL || !canopy_build_finite3(end))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: end is NULL or not finite", who);
    if (n_segments < 1 || n_segments > (int)CANOPY_BUILD_MAX_ITEMS)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: n_segments %d must be in [1, %.0f]", who,
                           n_segments, CANOPY_BUILD_MAX_ITEMS);
    if (material == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT, "%s: material is NULL",
                           who);
    canopy_status st = canopy_build_check_material(model, who, "material",
                                                   material);
    if (st != CANOPY_OK) return st;
    if ((st = check_group(model, who, group)) != CANOPY_OK) return st;
    const double *x0 = first_node >= 0 ? model->nodes.x + 3 * first_node
                                       : start;
    const double d[3] = {end[0] - x0[0], end[1] - x0[1], end[2] - x0[2]};
    const double len = hypot(hypot(d[0], d[1]), d[2]); /* no underflow */
    if (!(len > 0.0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: end coincides with the start%s", who,
                           first_node >= 0 ? " (first_node)" : "");
    char args[200];
    snprintf(args, sizeof args, "the distance %g from %s (%g, %g, %g) to "
             "end (%g, %g, %g) over n_segments %d", len,
             first_node >= 0 ? "first_node" : "start", x0[0], x0[1], x0[2],
             end[0], end[1], end[2], n_segments);
    st = canopy_build_check_segment(model, who, args, len, n_segments,
                                    material);
    if (st != CANOPY_OK) return st;
    if (first_node >= 0 &&
        !isfinite(model->nodes.mass[first_node] +
                  0.5 * material->density * len / n_segments))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: first_node %d's mass %g cannot take the "
                           "chord's share", who, first_node,
                           model->nodes.mass[first_node]);

    canopy_build_mark mark;
    canopy_build_mark_take(model, &mark);
    int a = first_node, b = -1;
    double ma = 0.0, mb = 0.0;
    if (a < 0) st = canopy_model_add_node(model, start, 0.0, group, &a);
    if (st == CANOPY_OK)
        st = string_between(model, a, &b, end, n_segments, material, group,
                            &ma, &mb);
    if (st != CANOPY_OK) return canopy_build_abort(model, &mark, st, who, args);
    /* Nothing can fail from here: indices valid, masses finite, >= 0. */
    canopy_model_add_node_mass(model, a, ma);
    canopy_model_add_node_mass(model, b, mb);
    if (last_node_out) *last_node_out = b;
    canopy_clear_message(model);
    return CANOPY_OK;
}

/* Confluence point of the suspension lines: on the vertical axis through
 * the attachments' centroid c, below them, at distance line_length from an
 * attachment at the mean horizontal radius rho_m and the mean height:
 *     p = (c_x, c_y, c_z - sqrt(L^2 - rho_m^2)).
 * For attachments on one horizontal circle (every builder's skirt) that is
 * distance L from each of them exactly; otherwise each line is the straight
 * segment to p, of its own length, with rest length = that length. */
canopy_status canopy_build_suspension_lines(canopy_model *model,
                                            const int *attach, int n_attach,
                                            const canopy_lines_spec *spec,
                                            int *payload_node_out)
{
    static const char who[] = "build_suspension_lines";
    canopy_status st;
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (attach == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT, "%s: attach is NULL",
                           who);
    if (n_attach < 3)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: n_attach %d must be >= 3", who, n_attach);
    if (spec == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT, "%s: spec is NULL", who);
    const int n = model->nodes.count;
    for (int k = 0; k < n_attach; ++k)
        if (attach[k] < 0 || attach[k] >= n)
            return canopy_fail(model, CANOPY_ERR_RANGE,
                               "%s: attach[%d] = %d is not a node index in "
                               "[0, %d)", who, k, attach[k], n);
    {
        /* Duplicates: first occurrence of each node, in one pass. */
        int *first = malloc((size_t)n * sizeof *first);
        if (first == NULL)
            return canopy_fail(model, CANOPY_ERR_MEMORY,
                               "%s: cannot allocate %d ints", who, n);
        for (int k = 0; k < n_attach; ++k) first[attach[k]] = -1;
        int dup = -1;
        for (int k = 0; k < n_attach && dup < 0; ++k) {
            if (first[attach[k]] >= 0) dup = k;
            else first[attach[k]] = k;
        }
        const int other = dup >= 0 ? first[attach[dup]] : -1;
        free(first);
        if (dup >= 0)
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "%s: attach[%d] and attach[%d] are both "
                               "node %d", who, other, dup, attach[dup]);
    }
    if ((st = canopy_build_check_positive(model, who, "line_length",
                                          spec->line_length)))
        return st;
    if ((st = canopy_build_check_positive(model, who, "edge_length",
                                          spec->edge_length)))
        return st;
    if (!isfinite(spec->payload_mass) || spec->payload_mass < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.payload_mass %g must be finite and >= 0",
                           who, spec->payload_mass);
    st = canopy_build_check_material(model, who, "spec.line", &spec->line);
    if (st != CANOPY_OK) return st;

    const double *X = model->nodes.x;
    double c[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < n_attach; ++k)
        for (int d = 0; d < 3; ++d) c[d] += X[3 * attach[k] + d] / n_attach;
    double rho = 0.0;
    for (int k = 0; k < n_attach; ++k) {
        const double dx = X[3 * attach[k]] - c[0];
        const double dy = X[3 * attach[k] + 1] - c[1];
        rho += sqrt(dx * dx + dy * dy) / n_attach;
    }
    const double L = spec->line_length;
    if (!(L > rho))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.line_length %g must exceed the "
                           "attachments' (mean) radius %g about their "
                           "centroid", who, L, rho);
    const double p[3] = {c[0], c[1], c[2] - sqrt((L - rho) * (L + rho))};
    /* Segments per line and a size check before adding anything. */
    double total_segments = 0.0;
    for (int k = 0; k < n_attach; ++k) {
        const double *xa = X + 3 * attach[k];
        const double dd[3] = {p[0] - xa[0], p[1] - xa[1], p[2] - xa[2]};
        const double len = hypot(hypot(dd[0], dd[1]), dd[2]);
        total_segments += floor(len / spec->edge_length + 0.5) + 1.0;
        const double q = floor(len / spec->edge_length + 0.5);
        if (!(q <= CANOPY_BUILD_MAX_ITEMS)) continue; /* reported below */
        char what[160];
        snprintf(what, sizeof what, "the line from attach[%d] = node %d, of "
                 "length %g (spec.line_length %g, spec.edge_length %g)", k,
                 attach[k], len, L, spec->edge_length);
        st = canopy_build_check_segment(model, who, what, len,
                                        q < 1.0 ? 1 : (int)q, &spec->line);
        if (st != CANOPY_OK) return st;
        if (!isfinite(model->nodes.mass[attach[k]] +
                      0.5 * spec->line.density * len / (q < 1.0 ? 1 : q)))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "%s: attach[%d] = node %d's mass %g cannot "
                               "take its line's share", who, k, attach[k],
                               model->nodes.mass[attach[k]]);
    }
    if (!(total_segments <= CANOPY_BUILD_MAX_ITEMS))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.edge_length %g needs ~%.3g line "
                           "segments, more than the builder's limit %.3g",
                           who, spec->edge_length, total_segments,
                           CANOPY_BUILD_MAX_ITEMS);
    double *owed = malloc((size_t)n_attach * sizeof *owed);
    if (owed == NULL)
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           "%s: cannot allocate %d doubles", who, n_attach);

    canopy_build_mark mark;
    canopy_build_mark_take(model, &mark);
    int conf = -1;
    st = canopy_model_add_node(model, p, spec->payload_mass,
                               CANOPY_GROUP_PAYLOAD, &conf);
    for (int k = 0; k < n_attach && st == CANOPY_OK; ++k) {
        const double *xa = model->nodes.x + 3 * attach[k];
        const double dd[3] = {p[0] - xa[0], p[1] - xa[1], p[2] - xa[2]};
        const double len = hypot(hypot(dd[0], dd[1]), dd[2]);
        const double q = floor(len / spec->edge_length + 0.5);
        const int n_seg = q < 1.0 ? 1 : (int)q;
        double mc = 0.0;
        int b = conf;
        st = string_between(model, attach[k], &b, NULL, n_seg, &spec->line,
                            CANOPY_GROUP_LINE, &owed[k], &mc);
        if (st == CANOPY_OK) st = canopy_model_add_node_mass(model, conf, mc);
    }
    if (st != CANOPY_OK) {
        free(owed);
        char args[160];
        snprintf(args, sizeof args, "spec.line_length %g, spec.edge_length "
                 "%g and spec.payload_mass %g on %d attachments",
                 spec->line_length, spec->edge_length, spec->payload_mass,
                 n_attach);
        return canopy_build_abort(model, &mark, st, who, args);
    }
    /* Nothing can fail from here (valid indices, finite masses >= 0): the
     * attachments, which existed before, get their half segments now. */
    for (int k = 0; k < n_attach; ++k)
        canopy_model_add_node_mass(model, attach[k], owed[k]);
    free(owed);
    canopy_model_set_payload_node(model, conf);
    if (payload_node_out) *payload_node_out = conf;
    canopy_clear_message(model);
    return CANOPY_OK;
}
