/* build_circular.c — canopy_build_circular: flat or parabolic circular canopy (optional vent, extended skirt, radial tapes) as rings of nodes zipped into near-equilateral triangles. */
#include "build_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define WHO "build_circular"

static const double TWO_PI = 6.283185307179586476925286766559;

/* Geometry of the surface of revolution, seed 000 eq. 5.4 written with the
 * apex on the axis: z(r) = z_apex - a r^2, a = height / R^2, R the rim
 * radius. `diameter` is the horizontal rim diameter 2R (for a flat canopy
 * its constructed diameter); the vent is the horizontal circle r = r_v and
 * `center` is the centre of the vent opening (the apex without vent), so
 * z_apex = center_z + a r_v^2. An extended skirt continues the meridian
 * beyond the rim (arc length s_rim) in a straight line of length L, each
 * unit of arc moving the radius by dr < 0 and the height by dz < 0, to the
 * hem r = R + L dr. */
typedef struct surface {
    double R, rv, a;
    double cx, cy, z_apex;
    double s_rim;       /* meridian arc length from the axis to the rim */
    double L, dr, dz;   /* extended skirt: slant length (0: none), direction */
    int gores_to_vent;  /* a vent with radial tapes: gore rings reach it */
} surface;

/* Meridian arc length from the axis to radius r:
 * s(r) = int_0^r sqrt(1 + (2 a rho)^2) d rho
 *      = (r sqrt(1 + b^2 r^2) + asinh(b r) / b) / 2, b = 2a. */
static double arc_length(const surface *sf, double r)
{
    const double b = 2.0 * sf->a;
    if (b * r < 1e-6) return r * (1.0 + b * b * r * r / 6.0);
    return 0.5 * (r * sqrt(1.0 + b * b * r * r) + asinh(b * r) / b);
}

/* Radius at arc length s in [0, s_rim + L]: on the extended skirt the
 * straight line; inside the rim Newton from r = R (s(r) is increasing and
 * convex, so the iterates decrease monotonically onto the root). */
static double radius_at(const surface *sf, double s)
{
    if (s > sf->s_rim) return sf->R + (s - sf->s_rim) * sf->dr;
    if (sf->a == 0.0) return s;
    const double b = 2.0 * sf->a;
    double r = sf->R;
    for (int it = 0; it < 200; ++it) {
        const double step = (arc_length(sf, r) - s) / sqrt(1.0 + b * b * r * r);
        r -= step;
        if (r < 0.0) r = 0.0;
        if (fabs(step) <= 1e-15 * sf->R) break;
    }
    return r;
}

/* Height at arc length s whose radius is r. */
static double height_at(const surface *sf, double s, double r)
{
    const double z_rim = sf->z_apex - sf->a * sf->R * sf->R;
    if (s > sf->s_rim) return z_rim + (s - sf->s_rim) * sf->dz;
    return sf->z_apex - sf->a * r * r;
}

/* One ring of nodes. A gore ring has `per_gore` nodes in each of the
 * n_attachments gores (node count a multiple of n_attachments) and a node on
 * every gore seam, angle 2 pi g / n_attachments. Its nodes split the gore
 * evenly, or, for an offset ring, sit half-way between the even positions
 * of a p-segment ring: gore fractions 0, 0.5/p, 1.5/p, ..., (p - 0.5)/p with
 * p = per_gore - 1 (straight seams, like the rectangle's sides). A free ring
 * (where a ring holds fewer nodes than attachments, near the apex or a vent
 * that no radial tapes reach) has `count` evenly spaced nodes. Every ring
 * starts at angle 0. */
typedef struct ring {
    double s, r, z;  /* meridian arc length, radius, height */
    int count;       /* nodes in the ring */
    int per_gore;    /* nodes per gore (seam node counted once); 0: free ring */
    int offset;
    int first;       /* model index of the ring's node at angle 0 */
} ring;

static double ring_angle(const ring *rg, int j, int n_att)
{
    if (rg->per_gore == 0) return TWO_PI * j / rg->count;
    const int g = j / rg->per_gore, t = j % rg->per_gore;
    double frac;
    if (!rg->offset)
        frac = (double)t / rg->per_gore;
    else
        frac = t == 0 ? 0.0 : (t - 0.5) / (rg->per_gore - 1);
    return TWO_PI * (g + frac) / n_att;
}

static void ring_point(const surface *sf, const ring *rg, int j, int n_att,
                       double x[3])
{
    const double th = ring_angle(rg, j, n_att);
    x[0] = sf->cx + rg->r * cos(th);
    x[1] = sf->cy + rg->r * sin(th);
    x[2] = rg->z;
}

static canopy_status validate(canopy_model *model,
                              const canopy_circular_spec *spec)
{
    canopy_status st;
    if (spec == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT, WHO ": spec is NULL");
    if ((st = canopy_build_check_positive(model, WHO, "diameter",
                                          spec->diameter)))
        return st;
    if (!isfinite(spec->vent_diameter) || spec->vent_diameter < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.vent_diameter %g must be finite and "
                           ">= 0", spec->vent_diameter);
    if (!(spec->vent_diameter < spec->diameter))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.vent_diameter %g must be smaller than "
                           "spec.diameter %g", spec->vent_diameter,
                           spec->diameter);
    if (!isfinite(spec->height) || spec->height < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.height %g must be finite and >= 0",
                           spec->height);
    if (!isfinite(spec->skirt_length) || spec->skirt_length < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.skirt_length %g must be finite and "
                           ">= 0", spec->skirt_length);
    if (spec->skirt_length > 0.0) {
        /* The band must turn down from the rim (dz < 0, or it would lie in
         * the rim's plane) and inwards (dr < 0, which orients it). */
        if (!isfinite(spec->skirt_diameter) || !(spec->skirt_diameter > 0.0) ||
            !(spec->skirt_diameter < spec->diameter))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               WHO ": spec.skirt_diameter %g must be in (0, "
                               "spec.diameter %g) for an extended skirt",
                               spec->skirt_diameter, spec->diameter);
        if (!(0.5 * (spec->diameter - spec->skirt_diameter) <
              spec->skirt_length))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               WHO ": spec.skirt_length %g must exceed the "
                               "radial step from the rim to the hem, (spec."
                               "diameter %g - spec.skirt_diameter %g) / 2",
                               spec->skirt_length, spec->diameter,
                               spec->skirt_diameter);
    }
    if ((st = canopy_build_check_positive(model, WHO, "edge_length",
                                          spec->edge_length)))
        return st;
    if (!canopy_build_finite3(spec->center))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.center (%g, %g, %g) is not finite",
                           spec->center[0], spec->center[1], spec->center[2]);
    if (spec->n_attachments < 3 ||
        spec->n_attachments > (int)(CANOPY_BUILD_MAX_ITEMS / 4))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.n_attachments %d must be in [3, %d]",
                           spec->n_attachments,
                           (int)(CANOPY_BUILD_MAX_ITEMS / 4));
    if (spec->radial_tapes != 0 && spec->radial_tapes != 1)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.radial_tapes %d must be 0 or 1",
                           spec->radial_tapes);
    st = canopy_build_check_material(model, WHO, "spec.fabric", &spec->fabric);
    if (st != CANOPY_OK) return st;
    if (spec->radial_tapes)
        st = canopy_build_check_material(model, WHO, "spec.tape", &spec->tape);
    return st;
}

/* --- ring positions -------------------------------------------------------
 * Rings lie along the meridian arc at the height of an equilateral triangle,
 * g = (sqrt(3)/2) e, so a parabola gets even spacing. When the radial
 * tapes run to a vent, the gore rings reach it; where its gores are
 * narrower than e (each gore then holds one segment of width 2 pi r / n),
 * the spacing follows the gore width, g = (sqrt(3)/2) min(e, 2 pi r / n),
 * so those triangles stay near-equilateral too. The
 * gaps are g(s_k) lambda, lambda chosen so that an integer number of rings
 * lands exactly on the skirt. */
static double ring_gap(const surface *sf, double s, double e, int n_att)
{
    const double h = 0.5 * sqrt(3.0) * e;
    if (!sf->gores_to_vent) return h;
    double w = TWO_PI * radius_at(sf, s) / n_att;
    if (w < 1e-6 * e) w = 1e-6 * e;   /* a vent of (almost) zero size */
    return w < e ? 0.5 * sqrt(3.0) * w : h;
}

/* Where n_steps gaps of lambda g(s) from s0 end. */
static double march(const surface *sf, double s0, int n_steps, double lambda,
                    double e, int n_att)
{
    double s = s0;
    for (int k = 0; k < n_steps; ++k) s += lambda * ring_gap(sf, s, e, n_att);
    return s;
}

/* Ring arc positions s[0..nr] (s[0] = vent or apex, s[nr] = skirt). */
static void place_rings(const surface *sf, double s0, double s1, double e,
                        int n_att, ring *rg, int nr)
{
    rg[0].s = s0;
    rg[nr].s = s1;
    if (!sf->gores_to_vent) {
        for (int k = 1; k < nr; ++k) rg[k].s = s0 + (s1 - s0) * k / nr;
        return;
    }
    double lo = 0.25, hi = 4.0;   /* march(lo) < s1 < march(hi) */
    while (march(sf, s0, nr, lo, e, n_att) > s1) lo *= 0.5;
    while (march(sf, s0, nr, hi, e, n_att) < s1) hi *= 2.0;
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (march(sf, s0, nr, mid, e, n_att) < s1) lo = mid; else hi = mid;
    }
    double s = s0;
    for (int k = 1; k < nr; ++k) {
        s += lo * ring_gap(sf, s, e, n_att);
        rg[k].s = s < s1 ? s : s1;
    }
}

/* Number of rings: the (fractional) number of gaps g(s) that fit, rounded. */
static int ring_intervals(const surface *sf, double s0, double s1, double e,
                          int n_att)
{
    double s = s0, n = 0.0;
    for (;;) {
        const double g = ring_gap(sf, s, e, n_att);
        if (s + g >= s1) { n += (s1 - s) / g; break; }
        s += g;
        n += 1.0;
    }
    const double q = floor(n + 0.5);
    return q < 1.0 ? 1 : (int)q;
}

/* --- ring counts ----------------------------------------------------------
 * From the skirt inwards each ring takes, among a few candidates near the
 * natural count 2 pi r / e_loc (e_loc = (2/sqrt(3)) x the gap to the outer
 * ring), the one whose strip of triangles to the outer ring scores best:
 * mean shape quality (1 = equilateral), less 0.3 |ln(spacing / e_loc)|,
 * less (30 - smallest angle) / 30 degrees when that angle is below 30.
 * Staggered rows (offset rings) thus win over right-angled "unstaggered"
 * strips whenever a gore holds two or more segments. Candidates: a
 * gore ring with p - 1, p or p + 1 even segments per gore (p = round of the
 * natural count per gore), an offset ring on those p (p >= 2), and, without
 * tapes running to a vent and once a ring holds fewer nodes than
 * attachments, a free ring (all rings inside a free ring are free) of a
 * count that keeps the mesh symmetric; a vent's edge ring has at least 6.
 * The strip is evaluated exactly as it will be built (same points, same
 * zipping rule). */

typedef struct planner {
    const surface *sf;
    int n_att;
    double *pts;     /* points of the two rings (and the apex) */
    int *ca, *cb;    /* chains */
    size_t cap;      /* capacity in points */
} planner;

static int planner_reserve(planner *pl, size_t points)
{
    if (points <= pl->cap) return 1;
    size_t cap = pl->cap ? pl->cap : 256;
    while (cap < points) cap *= 2;
    double *p = realloc(pl->pts, 3 * cap * sizeof *p);
    if (p == NULL) return 0;
    pl->pts = p;
    int *a = realloc(pl->ca, cap * sizeof *a);
    if (a == NULL) return 0;
    pl->ca = a;
    int *b = realloc(pl->cb, cap * sizeof *b);
    if (b == NULL) return 0;
    pl->cb = b;
    pl->cap = cap;
    return 1;
}

static double triangle_min_angle(const double *a, const double *b,
                                 const double *c)
{
    const double *v[3] = {a, b, c};
    double amin = 180.0;
    for (int k = 0; k < 3; ++k) {
        const double *p = v[k], *q = v[(k + 1) % 3], *r = v[(k + 2) % 3];
        const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        const double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
        const double nu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        const double nw = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        if (!(nu > 0.0 && nw > 0.0)) return 0.0;
        double cs = (u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / (nu * nw);
        cs = cs > 1.0 ? 1.0 : (cs < -1.0 ? -1.0 : cs);
        const double ang = acos(cs) * (180.0 / 3.14159265358979323846);
        if (ang < amin) amin = ang;
    }
    return amin;
}

/* Shape quality 4 sqrt(3) area / (sum of squared edges): 1 for an
 * equilateral triangle, 0.857 for the right triangle of an unstaggered
 * lattice (legs 1 and sqrt(3)/2), 0.75 for a half-cell (30-60-90). */
static double triangle_quality(const double *a, const double *b,
                               const double *c)
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double v[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]};
    const double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double l2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + w[0] * w[0] +
                      w[1] * w[1] + w[2] * w[2] + v[0] * v[0] + v[1] * v[1] +
                      v[2] * v[2];
    return l2 > 0.0 ? 2.0 * sqrt(3.0) * area2 / l2 : 0.0;
}

/* Statistics of a set of triangles: smallest angle, summed quality. */
typedef struct strip_stats {
    double min_angle, quality_sum;
    int count;
} strip_stats;

static void stats_add(strip_stats *st, const double *a, const double *b,
                      const double *c)
{
    const double ang = triangle_min_angle(a, b, c);
    if (ang < st->min_angle) st->min_angle = ang;
    st->quality_sum += triangle_quality(a, b, c);
    ++st->count;
}

static void zip_stats(const double *xyz, const int *lower, int nl,
                      const int *upper, int nu, strip_stats *st)
{
    int i = 0, j = 0;
    while (i < nl || j < nu) {
        if (canopy_zip_step(xyz, lower, nl, upper, nu, i, j)) {
            stats_add(st, xyz + 3 * lower[i], xyz + 3 * lower[i + 1],
                      xyz + 3 * upper[j]);
            ++i;
        } else {
            stats_add(st, xyz + 3 * lower[i], xyz + 3 * upper[j + 1],
                      xyz + 3 * upper[j]);
            ++j;
        }
    }
}

/* Statistics of the strip between rings `in` and `out` (and of the apex
 * fan if `apex` is not NULL); 0 if out of memory. */
static int strip_stats_of(planner *pl, const ring *in, const ring *out,
                          const double *apex, strip_stats *st)
{
    const int no = out->count, ni = in->count, base = no + 1;
    if (!planner_reserve(pl, (size_t)no + (size_t)ni + 3)) return 0;
    double *pts = pl->pts;
    for (int j = 0; j < no; ++j) ring_point(pl->sf, out, j, pl->n_att, pts + 3 * j);
    for (int j = 0; j < ni; ++j)
        ring_point(pl->sf, in, j, pl->n_att, pts + 3 * (base + j));
    for (int d = 0; d < 3; ++d) {
        pts[3 * no + d] = pts[d];
        pts[3 * (base + ni) + d] = pts[3 * base + d];
    }
    st->min_angle = 180.0;
    st->quality_sum = 0.0;
    st->count = 0;
    if (in->per_gore > 0 && out->per_gore > 0) {
        for (int g = 0; g < pl->n_att; ++g) {
            for (int t = 0; t <= out->per_gore; ++t)
                pl->ca[t] = g * out->per_gore + t;
            for (int t = 0; t <= in->per_gore; ++t)
                pl->cb[t] = base + g * in->per_gore + t;
            zip_stats(pts, pl->ca, out->per_gore, pl->cb, in->per_gore, st);
        }
    } else {
        for (int t = 0; t <= no; ++t) pl->ca[t] = t;
        for (int t = 0; t <= ni; ++t) pl->cb[t] = base + t;
        zip_stats(pts, pl->ca, no, pl->cb, ni, st);
    }
    if (apex != NULL)
        for (int j = 0; j < ni; ++j)
            stats_add(st, apex, pts + 3 * (base + j), pts + 3 * (base + j + 1));
    return 1;
}

/* Choose ring i's layout given ring i + 1. */
static int choose_ring(planner *pl, ring *rg, int i, int vent, double e_loc)
{
    ring *c = &rg[i];
    const ring *out = &rg[i + 1];
    const int n_att = pl->n_att;
    const double natural = TWO_PI * c->r / e_loc;
    const double pq = floor(natural / n_att + 0.5);
    const int p0 = pq < 1.0 ? 1 : (int)pq;
    /* Free rings keep a rotational symmetry with the gores: their counts
     * are multiples of the smallest prime factor f of n_attachments (if
     * f <= 5), so the whole mesh is at least f-fold symmetric and a uniform
     * pressure has no sideways resultant (2-fold symmetry suffices). */
    int f = 1;
    for (int d = 2; d <= 5; ++d)
        if (n_att % d == 0) { f = d; break; }
    const double nq = f * floor(natural / f + 0.5);
    int n0 = (int)nq;
    /* the vent's edge: at least a hexagon (83 % of the circle's area) */
    const int n_min = (vent && i == 0) ? 6 : 3;
    while (n0 < n_min) n0 += f;
    const int free_ok = !pl->sf->gores_to_vent &&
                        (out->per_gore == 0 || n0 < n_att);
    double apex[3] = {pl->sf->cx, pl->sf->cy, pl->sf->z_apex};
    const double *ap = (!vent && i == 1) ? apex : NULL;

    ring cand[9];
    int nc = 0;
    if (out->per_gore > 0) {
        const int ps[3] = {p0, p0 - 1, p0 + 1};
        for (int k = 0; k < 3; ++k) {
            if (ps[k] < 1) continue;
            cand[nc] = *c;
            cand[nc].per_gore = ps[k];
            cand[nc].offset = 0;
            cand[nc].count = ps[k] * n_att;
            ++nc;
        }
        for (int k = 0; k < 3; ++k) {
            if (ps[k] < 2) continue;
            cand[nc] = *c;
            cand[nc].per_gore = ps[k] + 1;
            cand[nc].offset = 1;
            cand[nc].count = (ps[k] + 1) * n_att;
            ++nc;
        }
    }
    if (free_ok) {
        const int ns[3] = {n0, n0 - f, n0 + f};
        for (int k = 0; k < 3; ++k) {
            if (ns[k] < n_min) continue;
            cand[nc] = *c;
            cand[nc].per_gore = 0;
            cand[nc].offset = 0;
            cand[nc].count = ns[k];
            ++nc;
        }
    }
    double best = -INFINITY;
    int ib = 0;
    for (int k = 0; k < nc; ++k) {
        strip_stats st;
        if (!strip_stats_of(pl, &cand[k], out, ap, &st)) return 0;
        /* An offset ring's spacing is that of the p-segment ring it is
         * staggered against (its seam segments are half-segments). */
        const int segs = cand[k].offset ? cand[k].count - n_att
                                        : cand[k].count;
        const double spacing = TWO_PI * c->r / segs;
        const double score = st.quality_sum / st.count -
                             0.3 * fabs(log(spacing / e_loc)) -
                             (st.min_angle < 30.0 ? (30.0 - st.min_angle) / 30.0
                                                  : 0.0);
        if (score > best + 1e-9) {
            best = score;
            ib = k;
        }
    }
    *c = cand[ib];
    return 1;
}

/* Plan the rings (arc positions, radii, heights, counts) without touching
 * the model. rings[0] is the vent ring, or the apex node (r = 0, count 1)
 * without a vent; rings[nr] is the skirt (the hem); with an extended skirt
 * rings[*n_rim_out] is the rim, and the band's rings are evenly spaced. */
static canopy_status plan_rings(canopy_model *model,
                                const canopy_circular_spec *spec,
                                const surface *sf, ring **rings_out,
                                int *nr_out, int *n_rim_out)
{
    const double e = spec->edge_length;
    const int n_att = spec->n_attachments;
    const int vent = sf->rv > 0.0;
    const double s0 = arc_length(sf, sf->rv), s1 = sf->s_rim + sf->L;
    /* Size check before any allocation or marching: nodes ~ area /
     * (sqrt(3)/2 e^2), plus per ring up to two gores' worth, plus the rings
     * a vent's narrow gores add (their spacing grows geometrically). */
    const double h = 0.5 * sqrt(3.0) * e;
    double rings_est = (s1 - s0) / h + 2.0;
    if (sf->gores_to_vent) rings_est += n_att * log(1.0 + n_att * e / sf->rv);
    const double nodes_est =
        (s1 * s1 - s0 * s0) * 3.2 / (h * e) + rings_est * 2.0 * n_att;
    if (!isfinite(nodes_est))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.diameter %g, spec.vent_diameter %g, "
                           "spec.height %g and spec.edge_length %g are out "
                           "of the range the builder can mesh in double "
                           "precision", spec->diameter, spec->vent_diameter,
                           spec->height, e);
    if (!(nodes_est <= CANOPY_BUILD_MAX_ITEMS))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           WHO ": spec.edge_length %g (with spec.diameter %g, "
                           "spec.vent_diameter %g, spec.n_attachments %d) "
                           "needs ~%.3g nodes, more than the builder's limit "
                           "%.3g", e, spec->diameter, spec->vent_diameter,
                           n_att, nodes_est, CANOPY_BUILD_MAX_ITEMS);
    const int n_rim = ring_intervals(sf, s0, sf->s_rim, e, n_att);
    const int nr = n_rim + (sf->L > 0.0 ? canopy_build_spacings(sf->L, h) : 0);
    ring *rg = calloc((size_t)nr + 1, sizeof *rg);
    if (rg == NULL)
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           WHO ": cannot allocate %d rings", nr + 1);
    place_rings(sf, s0, sf->s_rim, e, n_att, rg, n_rim);
    for (int i = n_rim + 1; i <= nr; ++i)
        rg[i].s = i == nr ? s1 : sf->s_rim + sf->L * (i - n_rim) / (nr - n_rim);
    for (int i = 0; i <= nr; ++i) {
        const double r = i == n_rim ? sf->R
                         : (i == 0 ? sf->rv : radius_at(sf, rg[i].s));
        rg[i].r = r;
        rg[i].z = height_at(sf, rg[i].s, r);
    }
    /* The skirt: p = round(2 pi r_hem / (e n)) >= 1 even segments per gore. */
    const double pq = floor(TWO_PI * rg[nr].r / (e * n_att) + 0.5);
    rg[nr].per_gore = pq < 1.0 ? 1 : (int)pq;
    rg[nr].count = rg[nr].per_gore * n_att;
    planner pl = {sf, n_att, NULL, NULL, NULL, 0};
    int ok = 1;
    for (int i = nr - 1; i >= 0 && ok; --i) {
        if (i == 0 && !vent) {
            rg[0].count = 1;
            continue;
        }
        const double e_loc = (rg[i + 1].s - rg[i].s) * 2.0 / sqrt(3.0);
        ok = choose_ring(&pl, rg, i, vent, e_loc);
    }
    free(pl.pts);
    free(pl.ca);
    free(pl.cb);
    if (!ok) {
        free(rg);
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           WHO ": cannot allocate ring planning space");
    }
    *rings_out = rg;
    *nr_out = nr;
    *n_rim_out = n_rim;
    return CANOPY_OK;
}

/* --- building ------------------------------------------------------------ */

/* Node of ring rg at index j (wrapping). */
static int ring_node(const ring *rg, int j)
{
    return rg->first + j % rg->count;
}

/* Zip ring `in` with ring `out`: gore by gore when both are gore rings (the
 * seams become mesh edges), else around the whole circle from angle 0. The
 * planner evaluated exactly these strips. */
static canopy_status zip_rings(canopy_fabric_builder *fb, const ring *in,
                               const ring *out, int n_att, int *chain_a,
                               int *chain_b)
{
    if (in->per_gore > 0 && out->per_gore > 0) {
        for (int g = 0; g < n_att; ++g) {
            for (int t = 0; t <= out->per_gore; ++t)
                chain_a[t] = ring_node(out, g * out->per_gore + t);
            for (int t = 0; t <= in->per_gore; ++t)
                chain_b[t] = ring_node(in, g * in->per_gore + t);
            canopy_status st = canopy_fabric_zip(fb, chain_a, out->per_gore,
                                                 chain_b, in->per_gore);
            if (st != CANOPY_OK) return st;
        }
        return CANOPY_OK;
    }
    for (int t = 0; t <= out->count; ++t) chain_a[t] = ring_node(out, t);
    for (int t = 0; t <= in->count; ++t) chain_b[t] = ring_node(in, t);
    return canopy_fabric_zip(fb, chain_a, out->count, chain_b, in->count);
}

/* Tape springs along each attachment angle, skirt to vent (or to the apex
 * node, skipping the free rings, which have no node at that angle), each
 * with the tape's linear mass shared half to each end. */
static canopy_status add_tapes(canopy_model *model,
                               const canopy_circular_spec *spec,
                               const ring *rg, int nr, int vent)
{
    const int n_att = spec->n_attachments;
    for (int k = 0; k < n_att; ++k) {
        int prev = rg[nr].first + k * rg[nr].per_gore;
        for (int i = nr - 1; i >= 0; --i) {
            int node;
            if (rg[i].per_gore > 0)
                node = rg[i].first + k * rg[i].per_gore;
            else if (i == 0 && !vent)
                node = rg[0].first;           /* the apex node */
            else
                continue;                     /* free ring: no node here */
            double l0;
            canopy_status st = canopy_build_string_spring(
                model, prev, node, &spec->tape, CANOPY_GROUP_TAPE, &l0);
            if (st != CANOPY_OK) return st;
            const double half = 0.5 * spec->tape.density * l0;
            if ((st = canopy_model_add_node_mass(model, prev, half)) !=
                    CANOPY_OK ||
                (st = canopy_model_add_node_mass(model, node, half)) !=
                    CANOPY_OK)
                return st;
            prev = node;
        }
    }
    return CANOPY_OK;
}

static canopy_status build(canopy_model *model,
                           const canopy_circular_spec *spec, ring *rg, int nr,
                           int n_rim, const surface *sf, int *chain_a,
                           int *chain_b)
{
    const int n_att = spec->n_attachments;
    const int vent = sf->rv > 0.0;
    canopy_status st;
    for (int i = 0; i <= nr; ++i) {
        for (int j = 0; j < rg[i].count; ++j) {
            double x[3];
            ring_point(sf, &rg[i], j, n_att, x);
            int idx;
            st = canopy_model_add_node(model, x, 0.0, CANOPY_GROUP_FABRIC,
                                       &idx);
            if (st != CANOPY_OK) return st;
            if (j == 0) rg[i].first = idx;
        }
    }
    canopy_fabric_builder fb;
    const double up[3] = {0.0, 0.0, 1.0};   /* the dome's outer side */
    st = canopy_fabric_begin(&fb, model, &spec->fabric, CANOPY_GROUP_FABRIC,
                             up, 3 * (size_t)model->nodes.count);
    if (st != CANOPY_OK) return st;
    if (!vent) { /* the apex fan */
        for (int j = 0; j < rg[1].count && st == CANOPY_OK; ++j)
            st = canopy_fabric_triangle(&fb, rg[0].first, ring_node(&rg[1], j),
                                        ring_node(&rg[1], j + 1));
    }
    for (int i = vent ? 0 : 1; i < nr && st == CANOPY_OK; ++i) {
        /* The extended skirt folds the surface down and inwards at the rim:
         * its outer side (the dome's, carried on) faces down there. */
        if (i == n_rim) fb.up[2] = -1.0;
        st = zip_rings(&fb, &rg[i], &rg[i + 1], n_att, chain_a, chain_b);
    }
    canopy_fabric_end(&fb);
    if (st == CANOPY_OK && spec->radial_tapes)
        st = add_tapes(model, spec, rg, nr, vent);
    return st;
}

canopy_status canopy_build_circular(canopy_model *model,
                                    const canopy_circular_spec *spec,
                                    int *attach_out)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    canopy_status st = validate(model, spec);
    if (st != CANOPY_OK) return st;

    surface sf;
    sf.R = 0.5 * spec->diameter;
    sf.rv = 0.5 * spec->vent_diameter;
    sf.a = spec->height / (sf.R * sf.R);
    sf.cx = spec->center[0];
    sf.cy = spec->center[1];
    sf.z_apex = spec->center[2] + sf.a * sf.rv * sf.rv;
    sf.gores_to_vent = sf.rv > 0.0 && spec->radial_tapes;
    sf.s_rim = arc_length(&sf, sf.R);
    sf.L = spec->skirt_length;
    sf.dr = sf.dz = 0.0;
    if (sf.L > 0.0) {
        sf.dr = -(sf.R - 0.5 * spec->skirt_diameter) / sf.L;
        sf.dz = -sqrt(1.0 - sf.dr * sf.dr);
    }

    ring *rg = NULL;
    int nr = 0, n_rim = 0;
    if ((st = plan_rings(model, spec, &sf, &rg, &nr, &n_rim)) != CANOPY_OK)
        return st;
    int max_count = 0;
    for (int i = 0; i <= nr; ++i)
        if (rg[i].count > max_count) max_count = rg[i].count;
    int *chain = malloc(2 * ((size_t)max_count + 1) * sizeof *chain);
    if (chain == NULL) {
        free(rg);
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           WHO ": cannot allocate %d chain entries",
                           2 * (max_count + 1));
    }

    canopy_build_mark mark;
    canopy_build_mark_take(model, &mark);
    st = build(model, spec, rg, nr, n_rim, &sf, chain, chain + max_count + 1);
    if (st == CANOPY_OK) {
        if (attach_out)
            for (int k = 0; k < spec->n_attachments; ++k)
                attach_out[k] = rg[nr].first + k * rg[nr].per_gore;
        canopy_clear_message(model);
    } else {
        char args[320];
        snprintf(args, sizeof args, "spec.diameter %g, spec.vent_diameter "
                 "%g, spec.height %g, spec.skirt_length %g, spec.edge_length "
                 "%g and spec.n_attachments %d at spec.center (%g, %g, %g)",
                 spec->diameter, spec->vent_diameter, spec->height,
                 spec->skirt_length, spec->edge_length, spec->n_attachments,
                 spec->center[0],
                 spec->center[1], spec->center[2]);
        st = canopy_build_abort(model, &mark, st, WHO, args);
    }
    free(chain);
    free(rg);
    return st;
}
