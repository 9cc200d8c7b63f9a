/* test_builders.c — geometry builders: masses, areas, triangle quality, orientation, attachments, lines and bad specs. */
#include "test.h"

#include <string.h>

static const double PI = 3.14159265358979323846;

/* Everything a test needs to look at, copied out of the model. */
typedef struct snapshot {
    int n, ns, nt;
    double *x, *mass, *rest, *k;
    int *group, *tri, *ends, *sgroup;
} snapshot;

static int snapshot_take(canopy_model *m, snapshot *s)
{
    s->n = canopy_model_node_count(m);
    s->ns = canopy_model_spring_count(m);
    s->nt = canopy_model_triangle_count(m);
    const size_t n = (size_t)s->n, ns = (size_t)s->ns, nt = (size_t)s->nt;
    s->x = malloc(3 * n * sizeof(double) + 1);
    s->mass = malloc(n * sizeof(double) + 1);
    s->group = malloc(n * sizeof(int) + 1);
    s->tri = malloc(3 * nt * sizeof(int) + 1);
    s->ends = malloc(2 * ns * sizeof(int) + 1);
    s->sgroup = malloc(ns * sizeof(int) + 1);
    s->rest = malloc(ns * sizeof(double) + 1);
    s->k = malloc(ns * sizeof(double) + 1);
    if (!s->x || !s->mass || !s->group || !s->tri || !s->ends || !s->sgroup ||
        !s->rest || !s->k)
        return 0;
    /* (Empty arrays are not fetched: model.c memcpy's from a NULL array
     * when a count is 0.) */
    return canopy_model_get_positions(m, s->x, s->n) == CANOPY_OK &&
           canopy_model_get_masses(m, s->mass, s->n) == CANOPY_OK &&
           canopy_model_get_node_groups(m, s->group, s->n) == CANOPY_OK &&
           (s->nt == 0 ||
            canopy_model_get_triangles(m, s->tri, s->nt) == CANOPY_OK) &&
           (s->ns == 0 ||
            (canopy_model_get_springs(m, s->ends, s->rest, s->k, s->ns) ==
                 CANOPY_OK &&
             canopy_model_get_spring_groups(m, s->sgroup, s->ns) ==
                 CANOPY_OK));
}

static void snapshot_free(snapshot *s)
{
    free(s->x); free(s->mass); free(s->group); free(s->tri);
    free(s->ends); free(s->sgroup); free(s->rest); free(s->k);
}

static void tri_area_normal(const snapshot *s, int t, double an[3])
{
    const double *a = s->x + 3 * s->tri[3 * t], *b = s->x + 3 * s->tri[3 * t + 1],
                 *c = s->x + 3 * s->tri[3 * t + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    an[0] = 0.5 * (u[1] * w[2] - u[2] * w[1]);
    an[1] = 0.5 * (u[2] * w[0] - u[0] * w[2]);
    an[2] = 0.5 * (u[0] * w[1] - u[1] * w[0]);
}

/* Triangle quality over all triangles. */
typedef struct quality {
    double area;            /* sum of triangle areas */
    double min_angle, max_angle;   /* degrees */
    double min_edge, max_edge, mean_edge;  /* fabric springs' rest lengths */
    double min_nz;          /* smallest unit-normal z component */
    double max_nxy;         /* largest |n_x|, |n_y| of unit normals */
} quality;

static quality measure(const snapshot *s)
{
    quality q = {0.0, 180.0, 0.0, INFINITY, 0.0, 0.0, INFINITY, 0.0};
    for (int t = 0; t < s->nt; ++t) {
        double an[3];
        tri_area_normal(s, t, an);
        const double a = sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        q.area += a;
        if (an[2] / a < q.min_nz) q.min_nz = an[2] / a;
        if (fabs(an[0]) / a > q.max_nxy) q.max_nxy = fabs(an[0]) / a;
        if (fabs(an[1]) / a > q.max_nxy) q.max_nxy = fabs(an[1]) / a;
        for (int c = 0; c < 3; ++c) {
            const double *p = s->x + 3 * s->tri[3 * t + c];
            const double *u = s->x + 3 * s->tri[3 * t + (c + 1) % 3];
            const double *w = s->x + 3 * s->tri[3 * t + (c + 2) % 3];
            const double d1[3] = {u[0] - p[0], u[1] - p[1], u[2] - p[2]};
            const double d2[3] = {w[0] - p[0], w[1] - p[1], w[2] - p[2]};
            const double cs = (d1[0] * d2[0] + d1[1] * d2[1] + d1[2] * d2[2]) /
                              sqrt((d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]) *
                                   (d2[0] * d2[0] + d2[1] * d2[1] + d2[2] * d2[2]));
            const double ang = acos(cs) * 180.0 / PI;
            if (ang < q.min_angle) q.min_angle = ang;
            if (ang > q.max_angle) q.max_angle = ang;
        }
    }
    int nf = 0;
    for (int k = 0; k < s->ns; ++k) {
        if (s->sgroup[k] != CANOPY_GROUP_FABRIC) continue;
        if (s->rest[k] < q.min_edge) q.min_edge = s->rest[k];
        if (s->rest[k] > q.max_edge) q.max_edge = s->rest[k];
        q.mean_edge += s->rest[k];
        ++nf;
    }
    if (nf) q.mean_edge /= nf;
    return q;
}

static void print_quality(const char *name, const snapshot *s,
                          const quality *q)
{
    printf("  %-34s nodes %5d springs %5d triangles %5d  angles %.1f..%.1f "
           "deg  edges %.4f..%.4f (ratio %.3f, mean %.4f)\n",
           name, s->n, s->ns, s->nt, q->min_angle, q->max_angle, q->min_edge,
           q->max_edge, q->min_edge / q->max_edge, q->mean_edge);
}

static int cmp_pair(const void *a, const void *b)
{
    const long long x = *(const long long *)a, y = *(const long long *)b;
    return x < y ? -1 : x > y;
}

/* The fabric springs are exactly the distinct triangle edges (no edge twice,
 * none missing). Returns the number of distinct edges, or -1. */
static int check_edges(const snapshot *s)
{
    const int nt = s->nt;
    long long *te = malloc(3 * (size_t)nt * sizeof *te + 1);
    long long *se = malloc((size_t)s->ns * sizeof *se + 1);
    if (!te || !se) { free(te); free(se); return -1; }
    for (int t = 0; t < nt; ++t)
        for (int c = 0; c < 3; ++c) {
            long long a = s->tri[3 * t + c], b = s->tri[3 * t + (c + 1) % 3];
            te[3 * t + c] = a < b ? a * 4000000000LL + b : b * 4000000000LL + a;
        }
    qsort(te, 3 * (size_t)nt, sizeof *te, cmp_pair);
    int ne = 0;
    for (int i = 0; i < 3 * nt; ++i)
        if (i == 0 || te[i] != te[i - 1]) te[ne++] = te[i];
    int nf = 0;
    for (int k = 0; k < s->ns; ++k) {
        if (s->sgroup[k] != CANOPY_GROUP_FABRIC) continue;
        long long a = s->ends[2 * k], b = s->ends[2 * k + 1];
        se[nf++] = a < b ? a * 4000000000LL + b : b * 4000000000LL + a;
    }
    qsort(se, (size_t)nf, sizeof *se, cmp_pair);
    int ok = nf == ne;
    for (int i = 0; ok && i < nf; ++i) ok = se[i] == te[i];
    free(te);
    free(se);
    return ok ? ne : -1;
}

/* Mass of the nodes of one group. */
static double group_mass(const snapshot *s, int group)
{
    double m = 0.0;
    for (int i = 0; i < s->n; ++i)
        if (s->group[i] == group) m += s->mass[i];
    return m;
}

static double total_mass(const snapshot *s)
{
    double m = 0.0;
    for (int i = 0; i < s->n; ++i) m += s->mass[i];
    return m;
}

/* --- circular ------------------------------------------------------------ */

static void check_flat_circle(double diameter, double edge, int n_att,
                              const double center[3], double min_angle)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = diameter;
    c.edge_length = edge;
    c.n_attachments = n_att;
    for (int d = 0; d < 3; ++d) c.center[d] = center[d];
    int *att = malloc(sizeof(int) * (size_t)n_att);
    ASSERT_TRUE(att != NULL);
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    ASSERT_TRUE(strcmp(canopy_model_message(m), "") == 0);
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    quality q = measure(&s);
    char name[96];
    snprintf(name, sizeof name, "circular D %.3g e %.3g n %d:", diameter, edge,
             n_att);
    print_quality(name, &s, &q);

    /* Topology: a disk (V - E + F = 1), springs = distinct triangle edges. */
    const int ne = check_edges(&s);
    ASSERT_TRUE(ne == s.ns);
    ASSERT_TRUE(s.n - ne + s.nt == 1);

    /* Skirt nodes: on the circle, count a multiple of n_att. */
    const double R = 0.5 * diameter;
    int n_skirt = 0;
    for (int i = 0; i < s.n; ++i) {
        const double r = hypot(s.x[3 * i] - center[0], s.x[3 * i + 1] - center[1]);
        ASSERT_TRUE(r <= R * (1.0 + 1e-12));
        ASSERT_TRUE(s.x[3 * i + 2] == center[2]);
        ASSERT_TRUE(s.group[i] == CANOPY_GROUP_FABRIC);
        ASSERT_TRUE(s.mass[i] > 0.0);
        if (fabs(r - R) <= 1e-12 * R) ++n_skirt;
    }
    ASSERT_TRUE(n_skirt % n_att == 0);
    /* Area of the triangulation = area of the inscribed regular n_skirt-gon
     * (up to round-off), whose deficit from pi R^2 is
     * 1 - sin(x)/x <= x^2/6 with x = 2 pi / n_skirt. */
    const double x = 2.0 * PI / n_skirt;
    const double polygon = 0.5 * n_skirt * R * R * sin(x);
    ASSERT_REL(q.area, polygon, 1e-12);
    ASSERT_TRUE(fabs(q.area - PI * R * R) <= PI * R * R * x * x / 6.0);
    /* One mass model: total mass = areal density x area, exactly. */
    ASSERT_REL(total_mass(&s), c.fabric.density * q.area, 1e-12);
    /* Orientation: all normals +z. */
    ASSERT_TRUE(q.min_nz > 1.0 - 1e-12);
    /* Near-equilateral: bounds measured over many sizes (see report). */
    ASSERT_TRUE(q.min_angle > min_angle);
    ASSERT_TRUE(q.max_angle < 112.0);
    ASSERT_TRUE(q.min_edge / q.max_edge > 0.3);
    ASSERT_TRUE(fabs(q.mean_edge / edge - 1.0) < 0.1);
    /* Attachments: skirt nodes at angles 2 pi k / n. */
    for (int k = 0; k < n_att; ++k) {
        const double *p = s.x + 3 * att[k];
        ASSERT_NEAR(p[0], center[0] + R * cos(2.0 * PI * k / n_att), 1e-12 * R);
        ASSERT_NEAR(p[1], center[1] + R * sin(2.0 * PI * k / n_att), 1e-12 * R);
        ASSERT_TRUE(p[2] == center[2]);
    }
    /* Frequency bound is computable: every node has mass. */
    double omega = 0.0;
    ASSERT_OK(m, canopy_model_frequency_bound(m, &omega));
    ASSERT_TRUE(omega > 0.0 && isfinite(omega));
    snapshot_free(&s);
    free(att);
    canopy_model_destroy(&m);
}

CANOPY_TEST(builders_circular_flat)
{
    const double origin[3] = {0.0, 0.0, 0.0}, shifted[3] = {1.5, -2.0, 30.0};
    check_flat_circle(2.134, 0.1, 16, origin, 27.0);   /* the 7 ft canopy */
    check_flat_circle(2.134, 0.15, 8, shifted, 27.0);
    check_flat_circle(1.0, 0.05, 12, shifted, 27.0);
    check_flat_circle(10.1, 0.3, 30, origin, 27.0);    /* 1/3-scale G-11 */
    check_flat_circle(1.0, 0.2, 3, origin, 27.0);
}

/* Parabolic canopy with a vent (T-10-like, seed 000 Table 5.2 and eq. 5.4)
 * and radial tapes. */
CANOPY_TEST(builders_circular_parabolic_vent_tapes)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = 10.7;
    c.vent_diameter = 0.6;
    c.height = 2.5;
    c.edge_length = 0.3;
    c.n_attachments = 30;
    c.center[2] = 10.0;
    c.radial_tapes = 1;
    c.tape.density = 0.02;
    int att[30];
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    quality q = measure(&s);
    print_quality("parabolic T-10 vent, tapes:", &s, &q);

    const double R = 5.35, rv = 0.3, a = c.height / (R * R);
    const double z_apex = c.center[2] + a * rv * rv;
    /* Every node on the paraboloid z = z_apex - a r^2 (eq. 5.4), between the
     * vent and the skirt. */
    double max_dev = 0.0;
    int n_vent = 0, n_skirt = 0;
    for (int i = 0; i < s.n; ++i) {
        const double r = hypot(s.x[3 * i], s.x[3 * i + 1]);
        const double dev = fabs(s.x[3 * i + 2] - (z_apex - a * r * r));
        if (dev > max_dev) max_dev = dev;
        ASSERT_TRUE(r >= rv * (1.0 - 1e-12) && r <= R * (1.0 + 1e-12));
        if (fabs(r - rv) <= 1e-12) {
            ++n_vent;
            ASSERT_NEAR(s.x[3 * i + 2], c.center[2], 1e-12);
        }
        if (fabs(r - R) <= 1e-12 * R) ++n_skirt;
    }
    ASSERT_TRUE(max_dev < 1e-12);
    ASSERT_TRUE(n_vent % 30 == 0 && n_skirt % 30 == 0 && n_vent > 0);
    /* An annulus: V - E + F = 0 over the fabric edges. */
    const int ne = check_edges(&s);
    ASSERT_TRUE(ne > 0);
    ASSERT_TRUE(s.n - ne + s.nt == 0);
    /* Normals consistently on the +z (outer) side of the dome. */
    ASSERT_TRUE(q.min_nz > 0.0);
    /* Area: the inscribed polyhedron is a little smaller than the smooth
     * paraboloid band, pi/(6 a^2) [(1 + 4a^2 R^2)^1.5 - (1 + 4a^2 rv^2)^1.5]. */
    const double smooth = PI / (6.0 * a * a) *
                          (pow(1.0 + 4.0 * a * a * R * R, 1.5) -
                           pow(1.0 + 4.0 * a * a * rv * rv, 1.5));
    printf("  area %.6f m^2, smooth paraboloid %.6f m^2 (%.3f %%)\n", q.area,
           smooth, 100.0 * (q.area / smooth - 1.0));
    ASSERT_TRUE(q.area < smooth && q.area > smooth * (1.0 - 2e-3));
    ASSERT_TRUE(q.min_angle > 27.0);
    ASSERT_TRUE(q.max_angle < 112.0);
    /* Tapes: every spring of group TAPE joins two nodes on one seam angle;
     * per seam the tapes run from the skirt to the vent ring: their total
     * length is at least the meridian chord sum. Mass = fabric + tapes. */
    double tape_length = 0.0;
    int n_tape = 0;
    for (int k = 0; k < s.ns; ++k) {
        if (s.sgroup[k] != CANOPY_GROUP_TAPE) continue;
        ++n_tape;
        tape_length += s.rest[k];
        const double *p = s.x + 3 * s.ends[2 * k], *r = s.x + 3 * s.ends[2 * k + 1];
        const double t1 = atan2(p[1], p[0]), t2 = atan2(r[1], r[0]);
        const double g1 = t1 / (2.0 * PI / 30.0);
        ASSERT_NEAR(g1, floor(g1 + 0.5), 1e-9);
        ASSERT_NEAR(t1, t2, 1e-12);
        /* line material: k = E A / l0 */
        ASSERT_REL(s.k[k] * s.rest[k], c.tape.modulus, 1e-12);
    }
    ASSERT_TRUE(n_tape > 0 && n_tape % 30 == 0);
    ASSERT_TRUE(s.ns == ne + n_tape);
    /* Meridian arc length from vent to skirt, per seam. */
    const double b = 2.0 * a;
    const double arc = 0.5 * (R * sqrt(1 + b * b * R * R) + asinh(b * R) / b) -
                       0.5 * (rv * sqrt(1 + b * b * rv * rv) + asinh(b * rv) / b);
    ASSERT_TRUE(tape_length <= 30.0 * arc && tape_length > 30.0 * arc * 0.999);
    ASSERT_REL(total_mass(&s), c.fabric.density * q.area +
                                   c.tape.density * tape_length, 1e-12);
    for (int k = 0; k < 30; ++k) {
        const double *p = s.x + 3 * att[k];
        ASSERT_NEAR(atan2(p[1], p[0]), atan2(sin(2 * PI * k / 30), cos(2 * PI * k / 30)),
                    1e-12);
        ASSERT_NEAR(hypot(p[0], p[1]), R, 1e-12 * R);
    }
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* A vent without radial tapes (the T-10 tutorial's canopy): the rings
 * inside the skirt are free rings, so the cloth keeps the target edge
 * length up to the vent instead of narrowing with 30 gores of 0.11 m there
 * (whose stiffness and flapping set the structure's time step). */
CANOPY_TEST(builders_circular_parabolic_vent_free_rings)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = 10.7;
    c.vent_diameter = 1.07;
    c.height = 1.6;
    c.edge_length = 1.25;
    c.n_attachments = 30;
    c.center[2] = 1.584;
    int att[30];
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    quality q = measure(&s);
    print_quality("parabolic T-10 vent, no tapes:", &s, &q);

    const double R = 5.35, rv = 0.535, a = c.height / (R * R);
    const double z_apex = c.center[2] + a * rv * rv;
    int n_vent = 0, n_skirt = 0;
    double vent_polygon = 0.0;  /* area of the hole: a regular polygon */
    for (int i = 0; i < s.n; ++i) {
        const double r = hypot(s.x[3 * i], s.x[3 * i + 1]);
        ASSERT_NEAR(s.x[3 * i + 2], z_apex - a * r * r, 1e-12);
        if (fabs(r - rv) <= 1e-12) ++n_vent;
        if (fabs(r - R) <= 1e-12 * R) ++n_skirt;
    }
    /* the vent's edge: a 2-fold symmetric free ring of at least 6 nodes
     * (30 = 2 x 15: multiples of 2), the skirt a gore ring */
    printf("  vent ring %d nodes, skirt ring %d nodes\n", n_vent, n_skirt);
    ASSERT_TRUE(n_vent >= 6 && n_vent < 30 && n_vent % 2 == 0);
    ASSERT_TRUE(n_skirt % 30 == 0);
    vent_polygon = 0.5 * n_vent * rv * rv * sin(2.0 * PI / n_vent);
    ASSERT_TRUE(vent_polygon > 0.82 * PI * rv * rv);
    const int ne = check_edges(&s);
    ASSERT_TRUE(s.n - ne + s.nt == 0);       /* an annulus */
    ASSERT_TRUE(q.min_nz > 0.0);
    /* near-equilateral to the vent: no edge below 40 % of the target (the
     * gore rings' vent edges are 2 pi rv / 30 = 0.09 e) */
    ASSERT_TRUE(q.min_edge > 0.4 * c.edge_length);
    ASSERT_TRUE(q.min_angle > 25.0);
    /* the attachments still sit on the skirt at the seam angles */
    for (int k = 0; k < 30; ++k) {
        const double *p = s.x + 3 * att[k];
        ASSERT_NEAR(atan2(p[1], p[0]),
                    atan2(sin(2 * PI * k / 30), cos(2 * PI * k / 30)), 1e-12);
    }
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* Each directed triangle edge (a -> b in the triangle's vertex order) at
 * most once: neighbouring triangles are oriented alike. */
static int orientation_consistent(const snapshot *s)
{
    const size_t m = 3 * (size_t)s->nt;
    long long *key = malloc(m * sizeof *key + 1);
    if (key == NULL) return 0;
    for (int t = 0; t < s->nt; ++t)
        for (int e = 0; e < 3; ++e)
            key[3 * t + e] = (long long)s->tri[3 * t + e] * s->n +
                             s->tri[3 * t + (e + 1) % 3];
    int ok = 1;
    for (size_t i = 0; i < m && ok; ++i)
        for (size_t j = i + 1; j < m; ++j)
            if (key[i] == key[j]) { ok = 0; break; }
    free(key);
    return ok;
}

/* An extended skirt (T-10-like: a 9.16 m dome 1.6 m high with a 0.508 m
 * vent, a 0.914 m band to a 7.47 m hem, 30 gores): every node on the
 * meridian (the paraboloid inside the rim, the straight band beyond it),
 * a ring on the rim's crease, the attachments on the hem at the seam
 * angles, the area of the dome and the frustum, and one orientation
 * across the fold (the band's outer side facing down). */
CANOPY_TEST(builders_circular_extended_skirt)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = 9.16;
    c.vent_diameter = 0.508;
    c.height = 1.6;
    c.skirt_length = 0.914;
    c.skirt_diameter = 7.47;
    c.edge_length = 0.5;
    c.n_attachments = 30;
    c.center[2] = 2.0;
    int att[30];
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    ASSERT_TRUE(strcmp(canopy_model_message(m), "") == 0);
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    quality q = measure(&s);
    print_quality("extended skirt (T-10-like):", &s, &q);

    const double R = 0.5 * c.diameter, rv = 0.5 * c.vent_diameter;
    const double Rh = 0.5 * c.skirt_diameter, L = c.skirt_length;
    const double a = c.height / (R * R), z_apex = c.center[2] + a * rv * rv;
    const double z_rim = z_apex - a * R * R;
    const double dr = -(R - Rh) / L, dz = -sqrt(1.0 - dr * dr);
    const double z_hem = z_rim + L * dz;
    int n_rim = 0, n_hem = 0, n_band = 0;
    for (int i = 0; i < s.n; ++i) {
        const double r = hypot(s.x[3 * i], s.x[3 * i + 1]), z = s.x[3 * i + 2];
        if (z >= z_rim - 1e-12) {           /* the dome */
            ASSERT_TRUE(r <= R * (1.0 + 1e-12));
            ASSERT_NEAR(z, z_apex - a * r * r, 1e-12);
            if (fabs(r - R) <= 1e-12 * R) ++n_rim;
        } else {                            /* the band: r = R + t dr */
            const double t = (r - R) / dr;
            ASSERT_TRUE(t > 0.0 && t <= L * (1.0 + 1e-12));
            ASSERT_NEAR(z, z_rim + t * dz, 1e-12);
            ++n_band;
            if (fabs(r - Rh) <= 1e-12 * R) {
                ASSERT_NEAR(z, z_hem, 1e-12);
                ++n_hem;
            }
        }
    }
    printf("  rim ring %d nodes, hem ring %d nodes, %d band nodes\n", n_rim,
           n_hem, n_band);
    ASSERT_TRUE(n_rim >= 30 && n_rim % 30 == 0);
    ASSERT_TRUE(n_hem >= 30 && n_hem % 30 == 0);
    ASSERT_TRUE(n_band > n_hem);            /* rings between rim and hem */
    for (int k = 0; k < 30; ++k) {
        const double *p = s.x + 3 * att[k];
        ASSERT_NEAR(hypot(p[0], p[1]), Rh, 1e-12 * R);
        ASSERT_NEAR(p[2], z_hem, 1e-12);
        ASSERT_NEAR(atan2(p[1], p[0]),
                    atan2(sin(2 * PI * k / 30), cos(2 * PI * k / 30)), 1e-12);
    }
    /* an annulus of springs along the triangles' edges */
    const int ne = check_edges(&s);
    ASSERT_TRUE(ne == s.ns);
    ASSERT_TRUE(s.n - ne + s.nt == 0);
    /* one orientation: the dome's triangles face up, the band's down */
    ASSERT_TRUE(orientation_consistent(&s));
    double dome = 0.0, band = 0.0;
    for (int t = 0; t < s.nt; ++t) {
        double an[3], zc = 0.0;
        tri_area_normal(&s, t, an);
        for (int v = 0; v < 3; ++v) zc += s.x[3 * s.tri[3 * t + v] + 2] / 3.0;
        const double area = sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        if (zc < z_rim - 1e-12) {
            ASSERT_TRUE(an[2] < 0.0);
            band += area;
        } else {
            ASSERT_TRUE(an[2] > 0.0);
            dome += area;
        }
    }
    /* the paraboloid's area between vent and rim, pi/(6 a^2) [(1 + 4 a^2
     * R^2)^(3/2) - (1 + 4 a^2 rv^2)^(3/2)], and the frustum's, pi (R + Rh) L,
     * against the inscribed polygons' (deficit ~ (2 pi / ring nodes)^2 / 6
     * < 0.2 % with >= 60 nodes a ring) */
    const double dome_exact = PI / (6.0 * a * a) *
                              (pow(1.0 + 4.0 * a * a * R * R, 1.5) -
                               pow(1.0 + 4.0 * a * a * rv * rv, 1.5));
    const double band_exact = PI * (R + Rh) * L;
    printf("  dome %.4f m^2 (exact %.4f), band %.4f m^2 (exact %.4f)\n", dome,
           dome_exact, band, band_exact);
    ASSERT_TRUE(fabs(dome / dome_exact - 1.0) < 0.01);
    ASSERT_TRUE(fabs(band / band_exact - 1.0) < 0.005);
    ASSERT_TRUE(q.min_angle > 25.0);
    ASSERT_REL(total_mass(&s), c.fabric.density * q.area, 1e-12);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* Tapes of a canopy without vent end at the apex node: on a flat canopy
 * each seam's tapes add up to the radius exactly. */
CANOPY_TEST(builders_circular_tapes_to_apex)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.radial_tapes = 1;
    int att[16];
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    const double R = 0.5 * c.diameter;
    double length[16] = {0};
    int apex = -1;
    for (int i = 0; i < s.n; ++i)
        if (hypot(s.x[3 * i], s.x[3 * i + 1]) == 0.0) apex = i;
    ASSERT_TRUE(apex >= 0);
    int at_apex = 0;
    for (int k = 0; k < s.ns; ++k) {
        if (s.sgroup[k] != CANOPY_GROUP_TAPE) continue;
        const int i = s.ends[2 * k], j = s.ends[2 * k + 1];
        const int other = i == apex ? j : i;
        if (i == apex || j == apex) ++at_apex;
        const double th = atan2(s.x[3 * other + 1], s.x[3 * other]);
        long g = lround(th / (2.0 * PI / 16.0));
        if (g < 0) g += 16;
        length[g] += s.rest[k];
    }
    ASSERT_TRUE(at_apex == 16);
    for (int g = 0; g < 16; ++g) ASSERT_REL(length[g], R, 1e-12);
    quality q = measure(&s);
    ASSERT_REL(total_mass(&s),
               c.fabric.density * q.area + c.tape.density * 16.0 * R, 1e-12);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* --- rectangle and cross ------------------------------------------------- */

CANOPY_TEST(builders_rectangle)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    const double e = 0.1;
    r.width = 1.0;
    r.length = 12 * 0.5 * sqrt(3.0) * e;  /* rows fit exactly: equilateral */
    r.edge_length = e;
    r.origin[0] = 0.5; r.origin[1] = -1.0; r.origin[2] = 2.0;
    ASSERT_OK(m, canopy_build_rectangle(m, &r));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    quality q = measure(&s);
    print_quality("rectangle 1 x 1.04 (exact rows):", &s, &q);
    ASSERT_REL(q.area, r.width * r.length, 1e-12);
    ASSERT_REL(total_mass(&s), r.fabric.density * q.area, 1e-12);
    ASSERT_TRUE(q.min_nz > 1.0 - 1e-12);
    ASSERT_TRUE(check_edges(&s) == s.ns);
    ASSERT_TRUE(s.n - s.ns + s.nt == 1);
    /* Equilateral interior, half-cells on the sides: edges e and e/2,
     * angles 30..90 degrees. */
    ASSERT_REL(q.min_edge, 0.5 * e, 1e-9);
    ASSERT_REL(q.max_edge, e, 1e-9);
    ASSERT_TRUE(q.min_angle > 30.0 - 1e-6 && q.max_angle < 90.0 + 1e-6);
    /* Straight sides: every node inside the box; corners are nodes. */
    int corners = 0;
    for (int i = 0; i < s.n; ++i) {
        const double *p = s.x + 3 * i;
        ASSERT_TRUE(p[0] >= 0.5 && p[0] <= 1.5 && p[1] >= -1.0 &&
                    p[1] <= -1.0 + r.length * (1 + 1e-15) && p[2] == 2.0);
        if ((p[0] == 0.5 || p[0] == 1.5) &&
            (p[1] == -1.0 || fabs(p[1] - (-1.0 + r.length)) < 1e-12))
            ++corners;
    }
    ASSERT_TRUE(corners == 4);
    snapshot_free(&s);

    /* Sizes that do not fit: rows are never more than (sqrt(3)/2) x spacing
     * apart, so angles stay >= 30 degrees. */
    const double sizes[4][2] = {{1.0, 1.3}, {0.33, 2.0}, {2.0, 0.17}, {0.05, 0.05}};
    for (int k = 0; k < 4; ++k) {
        canopy_model *m2 = NULL;
        ASSERT_OK(m2, canopy_model_create(&m2));
        r = canopy_rectangle_spec_default();
        r.width = sizes[k][0];
        r.length = sizes[k][1];
        ASSERT_OK(m2, canopy_build_rectangle(m2, &r));
        ASSERT_TRUE(snapshot_take(m2, &s));
        q = measure(&s);
        char name[64];
        snprintf(name, sizeof name, "rectangle %g x %g:", r.width, r.length);
        print_quality(name, &s, &q);
        ASSERT_REL(q.area, r.width * r.length, 1e-12);
        ASSERT_REL(total_mass(&s), r.fabric.density * q.area, 1e-12);
        ASSERT_TRUE(q.min_nz > 1.0 - 1e-12);
        ASSERT_TRUE(q.min_angle > 30.0 - 1e-9);
        ASSERT_TRUE(check_edges(&s) == s.ns);
        snapshot_free(&s);
        canopy_model_destroy(&m2);
    }
    canopy_model_destroy(&m);
}

static void check_cross(int n_att)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_cross_spec c = canopy_cross_spec_default();
    c.n_attachments = n_att;
    c.center[0] = 0.25; c.center[1] = 0.5; c.center[2] = -1.0;
    int att[64];
    ASSERT_OK(m, canopy_build_cross(m, &c, att));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    quality q = measure(&s);
    char name[64];
    snprintf(name, sizeof name, "cross (Table 5.2), %d attachments:", n_att);
    print_quality(name, &s, &q);
    const double S = c.span, w = c.arm_width;
    ASSERT_REL(q.area, 2.0 * S * w - w * w, 1e-12);
    ASSERT_REL(total_mass(&s), c.fabric.density * q.area, 1e-12);
    ASSERT_TRUE(q.min_nz > 1.0 - 1e-12);
    ASSERT_TRUE(check_edges(&s) == s.ns);
    ASSERT_TRUE(s.n - s.ns + s.nt == 1);
    ASSERT_TRUE(q.min_angle > 30.0 - 1e-9 && q.max_angle < 100.0);
    /* Attachments: n/4 per arm tip, evenly spaced, corners included,
     * counter-clockwise from the +x tip. */
    const int per = n_att / 4;
    for (int tip = 0; tip < 4; ++tip)
        for (int t = 0; t < per; ++t) {
            const int node = att[tip * per + t];
            ASSERT_TRUE(node >= 0 && node < s.n);
            if (node < 0 || node >= s.n) continue;
            const double u = -0.5 * w + w * (per > 1 ? (double)t / (per - 1) : 0.5);
            double ex, ey;
            switch (tip) {
            case 0: ex = 0.5 * S; ey = u; break;
            case 1: ex = -u; ey = 0.5 * S; break;
            case 2: ex = -0.5 * S; ey = -u; break;
            default: ex = u; ey = -0.5 * S; break;
            }
            ASSERT_NEAR(s.x[3 * node], c.center[0] + ex, 1e-12);
            ASSERT_NEAR(s.x[3 * node + 1], c.center[1] + ey, 1e-12);
        }
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* Node at (x, y) within tol, or -1. */
static int node_at(const snapshot *s, double x, double y, double tol)
{
    for (int i = 0; i < s->n; ++i)
        if (fabs(s->x[3 * i] - x) <= tol && fabs(s->x[3 * i + 1] - y) <= tol)
            return i;
    return -1;
}

/* A quarter turn about the centre maps the cross's nodes onto nodes and its
 * springs onto springs (every arm meshed alike, so no pair of opposite arms
 * folds more easily than the other), and the attachments of one tip onto
 * those of the next. */
static void check_cross_symmetry(int n_att, double edge)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_cross_spec c = canopy_cross_spec_default();
    c.n_attachments = n_att;
    c.edge_length = edge;
    c.center[0] = 0.25; c.center[1] = 0.5;
    int att[64];
    ASSERT_OK(m, canopy_build_cross(m, &c, att));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    const double tol = 1e-9 * c.span;
    int *turned = malloc((size_t)s.n * sizeof *turned + 1);
    ASSERT_TRUE(turned != NULL);
    int unmatched = 0;
    for (int i = 0; i < s.n; ++i) {
        const double dx = s.x[3 * i] - c.center[0];
        const double dy = s.x[3 * i + 1] - c.center[1];
        turned[i] = node_at(&s, c.center[0] - dy, c.center[1] + dx, tol);
        if (turned[i] < 0) ++unmatched;
    }
    ASSERT_TRUE(unmatched == 0);
    if (unmatched == 0) {
        int missing = 0;
        for (int k = 0; k < s.ns; ++k) {
            const int a = turned[s.ends[2 * k]], b = turned[s.ends[2 * k + 1]];
            int found = 0;
            for (int l = 0; l < s.ns && !found; ++l)
                found = (s.ends[2 * l] == a && s.ends[2 * l + 1] == b) ||
                        (s.ends[2 * l] == b && s.ends[2 * l + 1] == a);
            if (!found) ++missing;
        }
        ASSERT_TRUE(missing == 0);
        const int per = n_att / 4;
        for (int k = 0; k < n_att; ++k)
            ASSERT_TRUE(turned[att[k]] == att[(k + per) % n_att]);
    }
    free(turned);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

CANOPY_TEST(builders_cross_quarter_turn)
{
    check_cross_symmetry(20, 0.05);
    check_cross_symmetry(20, 0.15);   /* the cross tutorial's resolution */
    check_cross_symmetry(16, 0.05);   /* 4 per tip: 3 intervals, doubled */
    check_cross_symmetry(4, 0.1);
}

CANOPY_TEST(builders_cross)
{
    check_cross(20);   /* seed 000 Table 5.2: 20 lines */
    check_cross(4);    /* tip centres */
    check_cross(8);    /* tip corners */
    check_cross(16);
}

/* --- lines ---------------------------------------------------------------- */

CANOPY_TEST(builders_suspension_lines)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c = canopy_circular_spec_default();
    c.center[0] = 3.0; c.center[1] = 4.0; c.center[2] = 100.0;
    int att[16], payload = -1;
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    snapshot s0;
    ASSERT_TRUE(snapshot_take(m, &s0));
    const double fabric_mass = total_mass(&s0);
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = 2.0;
    l.edge_length = 0.1;
    l.payload_mass = 5.398;    /* NOTES §4: the 7 ft case */
    ASSERT_OK(m, canopy_build_suspension_lines(m, att, 16, &l, &payload));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    ASSERT_TRUE(payload == s0.n);
    ASSERT_TRUE(s.group[payload] == CANOPY_GROUP_PAYLOAD);
    double xp[3];
    ASSERT_OK(m, canopy_model_payload_state(m, xp, NULL));
    const double R = 0.5 * c.diameter;
    ASSERT_NEAR(xp[0], 3.0, 1e-12);
    ASSERT_NEAR(xp[1], 4.0, 1e-12);
    ASSERT_NEAR(xp[2], 100.0 - sqrt(4.0 - R * R), 1e-12);
    /* Each line: distance from attachment to confluence = line_length, and
     * the segments of that line add up to it. */
    double line_rest[16] = {0};
    int segments[16] = {0};
    for (int k = 0; k < 16; ++k) {
        const double *a = s.x + 3 * att[k];
        const double d = sqrt((a[0] - xp[0]) * (a[0] - xp[0]) +
                              (a[1] - xp[1]) * (a[1] - xp[1]) +
                              (a[2] - xp[2]) * (a[2] - xp[2]));
        ASSERT_REL(d, l.line_length, 1e-12);
    }
    /* Walk each line from its attachment through the LINE springs. */
    int n_line_springs = 0;
    for (int k = 0; k < s.ns; ++k) {
        if (s.sgroup[k] != CANOPY_GROUP_LINE) continue;
        ++n_line_springs;
        ASSERT_REL(s.k[k] * s.rest[k], l.line.modulus, 1e-12);
    }
    for (int k = 0; k < 16; ++k) {
        int node = att[k], prev = -1;
        while (node != payload && segments[k] < 1000) {
            int next = -1;
            for (int q = 0; q < s.ns && next < 0; ++q) {
                if (s.sgroup[q] != CANOPY_GROUP_LINE) continue;
                const int i = s.ends[2 * q], j = s.ends[2 * q + 1];
                if (i == node && j != prev) next = j;
                else if (j == node && i != prev) next = i;
                if (next >= 0) line_rest[k] += s.rest[q];
            }
            if (next < 0) break;
            prev = node;
            node = next;
            ++segments[k];
        }
        ASSERT_TRUE(node == payload);
        ASSERT_TRUE(segments[k] == 20);     /* round(2.0 / 0.1) */
        ASSERT_REL(line_rest[k], l.line_length, 1e-12);
    }
    ASSERT_TRUE(n_line_springs == 16 * 20);
    int n_line_nodes = 0;
    for (int i = s0.n; i < s.n; ++i)
        if (s.group[i] == CANOPY_GROUP_LINE) ++n_line_nodes;
    ASSERT_TRUE(n_line_nodes == 16 * 19 && s.n == s0.n + 1 + 16 * 19);
    /* Masses: lines carry density x length (half a segment on each
     * attachment, half on the confluence), payload its mass. */
    const double line_mass = l.line.density * 16.0 * l.line_length;
    ASSERT_REL(total_mass(&s), fabric_mass + line_mass + l.payload_mass, 1e-12);
    ASSERT_REL(group_mass(&s, CANOPY_GROUP_LINE),
               line_mass * 19.0 / 20.0, 1e-12);
    ASSERT_REL(s.mass[payload],
               l.payload_mass + 16.0 * 0.5 * l.line.density * 0.1, 1e-12);
    printf("  7 ft canopy + 16 lines: fabric %.6f kg, lines %.6f kg, payload "
           "%.3f kg, confluence %.6f m below the skirt\n", fabric_mass,
           line_mass, l.payload_mass, sqrt(4.0 - R * R));
    snapshot_free(&s0);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* Attachments at different radii (the cross: corners farther out than the
 * tip middles): the confluence uses their mean radius; each line is
 * straight, its rest length its own length. */
CANOPY_TEST(builders_lines_mixed_radii)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_cross_spec c = canopy_cross_spec_default();
    int att[20], payload;
    ASSERT_OK(m, canopy_build_cross(m, &c, att));
    snapshot s0;
    ASSERT_TRUE(snapshot_take(m, &s0));
    double rho = 0.0;
    for (int k = 0; k < 20; ++k)
        rho += hypot(s0.x[3 * att[k]], s0.x[3 * att[k] + 1]) / 20.0;
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = 1.27;     /* Table 5.2 */
    l.payload_mass = 0.1;
    ASSERT_OK(m, canopy_build_suspension_lines(m, att, 20, &l, &payload));
    double xp[3];
    ASSERT_OK(m, canopy_model_payload_state(m, xp, NULL));
    ASSERT_NEAR(xp[0], 0.0, 1e-12);
    ASSERT_NEAR(xp[1], 0.0, 1e-12);
    ASSERT_NEAR(xp[2], -sqrt(l.line_length * l.line_length - rho * rho), 1e-12);
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    double len = 0.0, rest = 0.0;
    for (int k = 0; k < 20; ++k) {
        const double *a = s.x + 3 * att[k];
        len += sqrt(a[0] * a[0] + a[1] * a[1] + (a[2] - xp[2]) * (a[2] - xp[2]));
    }
    for (int k = 0; k < s.ns; ++k)
        if (s.sgroup[k] == CANOPY_GROUP_LINE) rest += s.rest[k];
    ASSERT_REL(rest, len, 1e-12);
    ASSERT_REL(total_mass(&s), total_mass(&s0) + l.line.density * len + 0.1,
               1e-12);
    snapshot_free(&s0);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

CANOPY_TEST(builders_chord)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_material mat = canopy_material_line_default();
    mat.stiffness = 5000.0;               /* NOTES §4 string chord */
    mat.density = 0.01 / 0.02;            /* 0.01 kg per 0.02 m segment */
    const double a[3] = {0.0, 0.0, 0.0}, b[3] = {0.0, 0.0, -1.0};
    int last = -1;
    ASSERT_OK(m, canopy_build_chord(m, a, b, 50, &mat, CANOPY_GROUP_LINE, -1,
                                    &last));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    ASSERT_TRUE(s.n == 51 && s.ns == 50 && last == 50);
    ASSERT_NEAR(s.x[3 * last + 2], -1.0, 0.0);
    for (int i = 1; i < 50; ++i) ASSERT_REL(s.mass[i], 0.01, 1e-12);
    ASSERT_REL(s.mass[0], 0.005, 1e-12);
    ASSERT_REL(s.mass[50], 0.005, 1e-12);
    for (int k = 0; k < 50; ++k) {
        ASSERT_REL(s.k[k], 5000.0, 0.0);
        ASSERT_REL(s.rest[k], 0.02, 1e-12);
    }
    snapshot_free(&s);
    /* Continue from the existing end with modulus-derived stiffness. */
    mat.stiffness = 0.0;
    mat.modulus = 300.0;
    const double c2[3] = {0.3, 0.4, -1.0};
    int last2 = -1;
    ASSERT_OK(m, canopy_build_chord(m, NULL, c2, 5, &mat, CANOPY_GROUP_OTHER,
                                    last, &last2));
    ASSERT_TRUE(snapshot_take(m, &s));
    ASSERT_TRUE(s.n == 56 && s.ns == 55 && last2 == 55);
    ASSERT_REL(s.mass[last], 0.005 + 0.5 * mat.density * 0.1, 1e-12);
    for (int k = 50; k < 55; ++k) ASSERT_REL(s.k[k], 300.0 / 0.1, 1e-12);
    ASSERT_REL(total_mass(&s), mat.density * 1.5, 1e-12);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* Fabric stiffness from the 2-D modulus: k = (sqrt(3)/2) E t (NOTES §3). */
CANOPY_TEST(builders_fabric_modulus)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    r.fabric.stiffness = 0.0;
    r.fabric.modulus = 2918.7;     /* seed 000 §5.1: E_s of the canopy */
    ASSERT_OK(m, canopy_build_rectangle(m, &r));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    for (int k = 0; k < s.ns; ++k)
        ASSERT_REL(s.k[k], 0.5 * sqrt(3.0) * 2918.7, 1e-15);
    snapshot_free(&s);
    /* Density 0: no mass from the builder (the caller adds it, as the drum
     * test of seed 000 §5.2 does with equal node masses). */
    r.fabric.density = 0.0;
    r.origin[2] = 1.0;
    const int n0 = canopy_model_node_count(m);
    ASSERT_OK(m, canopy_build_rectangle(m, &r));
    ASSERT_TRUE(snapshot_take(m, &s));
    for (int i = n0; i < s.n; ++i) ASSERT_TRUE(s.mass[i] == 0.0);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

/* Builders append to a model that already holds parts. */
CANOPY_TEST(builders_append)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    ASSERT_OK(m, canopy_build_rectangle(m, &r));
    const int n1 = canopy_model_node_count(m), s1 = canopy_model_spring_count(m),
              t1 = canopy_model_triangle_count(m);
    canopy_circular_spec c = canopy_circular_spec_default();
    c.center[2] = 5.0;
    int att[16];
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    snapshot s;
    ASSERT_TRUE(snapshot_take(m, &s));
    for (int t = t1; t < s.nt; ++t)
        for (int q = 0; q < 3; ++q) ASSERT_TRUE(s.tri[3 * t + q] >= n1);
    for (int t = 0; t < t1; ++t)
        for (int q = 0; q < 3; ++q) ASSERT_TRUE(s.tri[3 * t + q] < n1);
    for (int k = s1; k < s.ns; ++k)
        ASSERT_TRUE(s.ends[2 * k] >= n1 && s.ends[2 * k + 1] >= n1);
    for (int k = 0; k < 16; ++k) ASSERT_TRUE(att[k] >= n1);
    ASSERT_TRUE(check_edges(&s) == s.ns);
    snapshot_free(&s);
    canopy_model_destroy(&m);
}

CANOPY_TEST(builders_defaults)
{
    canopy_material f = canopy_material_fabric_default();
    ASSERT_TRUE(f.density == 0.0373 && f.stiffness == 5000.0 &&
                f.law == CANOPY_SPRING_MODEL_II && f.damping > 0.0);
    canopy_material l = canopy_material_line_default();
    ASSERT_TRUE(l.density == 0.01 && l.modulus == 5000.0 && l.stiffness == 0.0 &&
                l.law == CANOPY_SPRING_TENSION_ONLY && l.damping > 0.0);
    canopy_circular_spec c = canopy_circular_spec_default();
    ASSERT_TRUE(c.diameter == 2.134 && c.n_attachments == 16 &&
                c.vent_diameter == 0.0 && c.height == 0.0);
    canopy_lines_spec ls = canopy_lines_spec_default();
    ASSERT_TRUE(ls.payload_mass == 5.398 && ls.line_length > 0.5 * c.diameter);
    /* Every default builds. */
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    int att[64], payload;
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    ASSERT_OK(m, canopy_build_suspension_lines(m, att, c.n_attachments, &ls,
                                               &payload));
    canopy_cross_spec x = canopy_cross_spec_default();
    ASSERT_OK(m, canopy_build_cross(m, &x, att));
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    ASSERT_OK(m, canopy_build_rectangle(m, &r));
    canopy_model_destroy(&m);
}

/* --- bad specs ------------------------------------------------------------ */

typedef struct counts {
    int n, ns, nt;
} counts;

static counts counts_of(const canopy_model *m)
{
    counts c = {canopy_model_node_count(m), canopy_model_spring_count(m),
                canopy_model_triangle_count(m)};
    return c;
}

#define ASSERT_REJECTED(model, expected, call, text)                          \
    do {                                                                      \
        const counts before_ = counts_of(model);                              \
        ASSERT_STATUS(expected, call);                                        \
        ASSERT_MESSAGE_HAS(model, text);                                      \
        const counts after_ = counts_of(model);                               \
        ASSERT_TRUE(before_.n == after_.n && before_.ns == after_.ns &&       \
                    before_.nt == after_.nt);                                 \
    } while (0)

CANOPY_TEST(builders_bad_specs)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    canopy_circular_spec c0 = canopy_circular_spec_default();
    int att[64];
    ASSERT_OK(m, canopy_build_circular(m, &c0, att));   /* a non-empty model */
    canopy_circular_spec c;

#define CIRC_BAD(field, value, text)                                          \
    do {                                                                      \
        c = c0;                                                               \
        c.field = value;                                                      \
        ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,                               \
                        canopy_build_circular(m, &c, att), text);             \
    } while (0)
    CIRC_BAD(diameter, 0.0, "spec.diameter 0");
    CIRC_BAD(diameter, -2.0, "spec.diameter");
    CIRC_BAD(diameter, NAN, "spec.diameter");
    CIRC_BAD(diameter, INFINITY, "spec.diameter");
    CIRC_BAD(edge_length, 0.0, "spec.edge_length 0 must be");
    CIRC_BAD(edge_length, NAN, "spec.edge_length");
    CIRC_BAD(edge_length, 1e-9, "spec.edge_length");     /* absurd size */
    CIRC_BAD(vent_diameter, 2.134, "spec.vent_diameter");
    CIRC_BAD(vent_diameter, -0.1, "spec.vent_diameter");
    CIRC_BAD(height, -1.0, "spec.height");
    CIRC_BAD(height, NAN, "spec.height");
    CIRC_BAD(skirt_length, -0.1, "spec.skirt_length");
    CIRC_BAD(skirt_length, NAN, "spec.skirt_length");
    CIRC_BAD(skirt_length, 0.3, "spec.skirt_diameter 0");   /* no hem given */
    c = c0;
    c.skirt_length = 0.3;
    c.skirt_diameter = 2.134;            /* a band must turn inwards */
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_circular(m, &c, att),
                    "spec.skirt_diameter 2.134 must be in (0");
    c.skirt_diameter = 1.5;              /* (2.134 - 1.5) / 2 > 0.3 */
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_circular(m, &c, att),
                    "spec.skirt_length 0.3 must exceed");
    CIRC_BAD(center[1], NAN, "spec.center");
    CIRC_BAD(n_attachments, 2, "spec.n_attachments 2");
    CIRC_BAD(n_attachments, -5, "spec.n_attachments");
    CIRC_BAD(radial_tapes, 2, "spec.radial_tapes");
    CIRC_BAD(fabric.density, -1e-3, "spec.fabric.density");
    CIRC_BAD(fabric.density, NAN, "spec.fabric.density");
    CIRC_BAD(fabric.stiffness, -1.0, "spec.fabric.stiffness");
    CIRC_BAD(fabric.damping, -0.1, "spec.fabric.damping");
    CIRC_BAD(fabric.law, (canopy_spring_law)7, "spec.fabric.law");
    c = c0;
    c.fabric.stiffness = 0.0;
    c.fabric.modulus = 0.0;
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_circular(m, &c, att),
                    "spec.fabric.stiffness and spec.fabric.modulus");
    c = c0;
    c.radial_tapes = 1;
    c.tape.density = -1.0;
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_circular(m, &c, att),
                    "spec.tape.density");
    c.radial_tapes = 0;      /* an unused tape material is not checked */
    ASSERT_OK(m, canopy_build_circular(m, &c, att));
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_circular(m, NULL, att),
                    "spec is NULL");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_build_circular(NULL, &c0, att));

    canopy_rectangle_spec r0 = canopy_rectangle_spec_default(), r;
#define RECT_BAD(field, value, text)                                          \
    do {                                                                      \
        r = r0;                                                               \
        r.field = value;                                                      \
        ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_rectangle(m, &r), \
                        text);                                                \
    } while (0)
    RECT_BAD(width, 0.0, "spec.width 0");
    RECT_BAD(length, INFINITY, "spec.length");
    RECT_BAD(length, -1.0, "spec.length");
    RECT_BAD(edge_length, -0.1, "spec.edge_length");
    RECT_BAD(edge_length, 1e-8, "spec.edge_length");
    RECT_BAD(origin[2], NAN, "spec.origin");
    RECT_BAD(fabric.density, -0.1, "spec.fabric.density");

    canopy_cross_spec x0 = canopy_cross_spec_default(), x;
#define CROSS_BAD(field, value, text)                                         \
    do {                                                                      \
        x = x0;                                                               \
        x.field = value;                                                      \
        ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT, canopy_build_cross(m, &x, att), \
                        text);                                                \
    } while (0)
    CROSS_BAD(span, 0.0, "spec.span");
    CROSS_BAD(arm_width, NAN, "spec.arm_width");
    CROSS_BAD(arm_width, 1.27, "spec.arm_width 1.27 must be smaller");
    CROSS_BAD(n_attachments, 6, "spec.n_attachments 6");
    CROSS_BAD(n_attachments, 0, "spec.n_attachments");
    CROSS_BAD(edge_length, 0.0, "spec.edge_length");
    CROSS_BAD(center[0], INFINITY, "spec.center");
    CROSS_BAD(fabric.law, (canopy_spring_law)-1, "spec.fabric.law");

    canopy_lines_spec l0 = canopy_lines_spec_default(), l;
    int payload = -1;
#define LINES_BAD(field, value, text)                                         \
    do {                                                                      \
        l = l0;                                                               \
        l.field = value;                                                      \
        ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,                               \
                        canopy_build_suspension_lines(m, att, 16, &l, &payload), \
                        text);                                                \
    } while (0)
    LINES_BAD(line_length, 1.0, "spec.line_length 1 must exceed");  /* < R */
    LINES_BAD(line_length, NAN, "spec.line_length");
    LINES_BAD(line_length, 0.0, "spec.line_length");
    LINES_BAD(edge_length, 0.0, "spec.edge_length");
    LINES_BAD(edge_length, 1e-9, "spec.edge_length");
    LINES_BAD(payload_mass, -1.0, "spec.payload_mass");
    LINES_BAD(payload_mass, NAN, "spec.payload_mass");
    LINES_BAD(line.density, -0.01, "spec.line.density");
    LINES_BAD(line.modulus, -1.0, "spec.line.modulus");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_suspension_lines(m, att, 2, &l0, &payload),
                    "n_attach 2");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_suspension_lines(m, NULL, 16, &l0, &payload),
                    "attach is NULL");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_suspension_lines(m, att, 16, NULL, &payload),
                    "spec is NULL");
    int dup[16];
    memcpy(dup, att, sizeof dup);
    dup[7] = dup[3];
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_suspension_lines(m, dup, 16, &l0, &payload),
                    "attach[3] and attach[7]");
    dup[7] = 1 << 20;
    ASSERT_REJECTED(m, CANOPY_ERR_RANGE,
                    canopy_build_suspension_lines(m, dup, 16, &l0, &payload),
                    "attach[7]");
    ASSERT_TRUE(payload == -1);

    canopy_material mat = canopy_material_line_default();
    const double p0[3] = {0.0, 0.0, 0.0}, p1[3] = {1.0, 0.0, 0.0};
    const double pn[3] = {0.0, NAN, 0.0};
    int last = -1;
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, p0, p1, 0, &mat, CANOPY_GROUP_LINE,
                                       -1, &last), "n_segments 0");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, p0, p0, 4, &mat, CANOPY_GROUP_LINE,
                                       -1, &last), "coincides");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, pn, p1, 4, &mat, CANOPY_GROUP_LINE,
                                       -1, &last), "start");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, p0, NULL, 4, &mat, CANOPY_GROUP_LINE,
                                       -1, &last), "end");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, p0, p1, 4, NULL, CANOPY_GROUP_LINE,
                                       -1, &last), "material is NULL");
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, p0, p1, 4, &mat, (canopy_group)9, -1,
                                       &last), "group 9");
    ASSERT_REJECTED(m, CANOPY_ERR_RANGE,
                    canopy_build_chord(m, NULL, p1, 4, &mat, CANOPY_GROUP_LINE,
                                       1 << 22, &last), "first_node");
    mat.damping = INFINITY;
    ASSERT_REJECTED(m, CANOPY_ERR_ARGUMENT,
                    canopy_build_chord(m, p0, p1, 4, &mat, CANOPY_GROUP_LINE,
                                       -1, &last), "material.damping");
    ASSERT_TRUE(last == -1);
    canopy_model_destroy(&m);
}
