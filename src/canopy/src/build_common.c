/* build_common.c — shared builder machinery (materials, fabric triangles with lumped mass and deduplicated edge springs, zipping, rollback) and the *_default() specs. */
#include "build_internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* --- defaults -------------------------------------------------------------
 *
 * Damping of the defaults. A dashpot c in parallel with every spring k makes
 * the damping matrix C = (c/k) K, i.e. stiffness-proportional: a mode of
 * frequency omega gets the damping ratio zeta = (c/k) omega / 2. Rigid motion
 * and slow, large-scale modes (breathing, swinging) are left essentially
 * undamped, while the mesh-scale noise at the top of the spectrum, which an
 * explicit integrator resolves but which carries no physics, is damped.
 *
 * Fabric, k = 5000 N/m, c = 0.05 N s/m, edge e = 0.1 m: a node of the regular
 * lattice carries (sqrt(3)/2) e^2 = 8.66e-3 m^2 of cloth, m = 3.23e-4 kg.
 * One spring on that mass: zeta = c / (2 sqrt(k m)) = 0.05 / 2.54 = 0.020.
 * Top of the lattice spectrum, omega_max ~ sqrt(7 k / m) = 1.04e4 rad/s
 * (seed 000 §5.2, M ~ 7): zeta = 1e-5 s x 1.04e4 / 2 = 0.052. A canopy mode
 * at 10 Hz gets zeta = 3e-4. (zeta_max scales as 1/e: 0.10 at e = 0.05.) The
 * dashpots raise the eigen-frequency bound Lambda of advance.c by ~7 %.
 *
 * Line, E A = 5000 N, 0.01 kg/m, c = 0.35 N s/m: for segments of length l0,
 * k = E A / l0, m = rho l0 and the chain's top frequency 2 sqrt(k/m) give
 * zeta_max = c / sqrt(E A rho) = 0.35 / 7.07 = 0.05 whatever l0 is. */

canopy_material canopy_material_fabric_default(void)
{
    canopy_material m;
    m.stiffness = 5000.0;                   /* seed 000 §5.1: k = 5000 */
    m.modulus = 2.0 * 5000.0 / sqrt(3.0);   /* the E t that k implies (unused
                                               while stiffness > 0) */
    m.density = 0.0373;                     /* MIL-C-7020 Type I, 1.1 oz/yd^2 */
    m.damping = 0.05;
    m.law = CANOPY_SPRING_MODEL_II;
    return m;
}

canopy_material canopy_material_line_default(void)
{
    canopy_material m;
    m.stiffness = 0.0;                      /* from E A / l0 per segment */
    m.modulus = 5000.0;                     /* E A [N] */
    m.density = 0.01;                       /* kg/m */
    m.damping = 0.35;
    m.law = CANOPY_SPRING_TENSION_ONLY;
    return m;
}

/* The 7 ft flat circular canopy (NOTES §4: 2.134 m, 16 lines). Tapes, when
 * switched on, use the line material. */
canopy_circular_spec canopy_circular_spec_default(void)
{
    canopy_circular_spec s;
    s.diameter = 2.134;
    s.vent_diameter = 0.0;
    s.height = 0.0;
    s.skirt_length = 0.0;
    s.skirt_diameter = 0.0;
    s.edge_length = 0.1;
    s.center[0] = s.center[1] = s.center[2] = 0.0;
    s.n_attachments = 16;
    s.radial_tapes = 0;
    s.fabric = canopy_material_fabric_default();
    s.tape = canopy_material_line_default();
    return s;
}

/* The cross canopy of seed 000 Table 5.2 (1.27 m, 20 lines); arm width 0.264
 * of the span, a usual cross-parachute proportion. */
canopy_cross_spec canopy_cross_spec_default(void)
{
    canopy_cross_spec s;
    s.span = 1.27;
    s.arm_width = 0.264 * 1.27;
    s.edge_length = 0.05;
    s.center[0] = s.center[1] = s.center[2] = 0.0;
    s.n_attachments = 20;
    s.fabric = canopy_material_fabric_default();
    return s;
}

canopy_rectangle_spec canopy_rectangle_spec_default(void)
{
    canopy_rectangle_spec s;
    s.width = 1.0;
    s.length = 1.0;
    s.edge_length = 0.1;
    s.origin[0] = s.origin[1] = s.origin[2] = 0.0;
    s.fabric = canopy_material_fabric_default();
    return s;
}

/* Lines for the 7 ft canopy: 2 m lines, its 5.398 kg payload (NOTES §4). */
canopy_lines_spec canopy_lines_spec_default(void)
{
    canopy_lines_spec s;
    s.line_length = 2.0;
    s.edge_length = 0.1;
    s.payload_mass = 5.398;
    s.line = canopy_material_line_default();
    return s;
}

/* --- validation and stiffness ------------------------------------------- */

int canopy_build_finite3(const double x[3])
{
    return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

canopy_status canopy_build_check_material(canopy_model *model, const char *who,
                                          const char *field,
                                          const canopy_material *mat)
{
    if (!isfinite(mat->stiffness) || mat->stiffness < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s.stiffness %g must be finite and >= 0", who,
                           field, mat->stiffness);
    if (!isfinite(mat->modulus) || mat->modulus < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s.modulus %g must be finite and >= 0", who,
                           field, mat->modulus);
    if (!(mat->stiffness > 0.0) && !(mat->modulus > 0.0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s.stiffness and %s.modulus are both 0; one "
                           "must be > 0", who, field, field);
    /* Density 0 is allowed: the nodes then get no mass from the builder
     * and the caller adds it (e.g. equal node masses, seed 000 §5.2); a free
     * node without mass is reported when the model is first stepped. */
    if (!isfinite(mat->density) || mat->density < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s.density %g must be finite and >= 0", who,
                           field, mat->density);
    if (!isfinite(mat->damping) || mat->damping < 0.0)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s.damping %g must be finite and >= 0", who,
                           field, mat->damping);
    if ((int)mat->law < 0 || (int)mat->law > (int)CANOPY_SPRING_TENSION_ONLY)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s.law %d is not a canopy_spring_law", who,
                           field, (int)mat->law);
    return CANOPY_OK;
}

double canopy_build_sheet_stiffness(const canopy_material *mat)
{
    /* k = (sqrt(3)/2) E t: inverse of E t = (2/sqrt(3)) k (NOTES §3; the
     * seed measured E_s ~ 1.1 k, seed 000 §5.1 eq. 5.2). */
    return mat->stiffness > 0.0 ? mat->stiffness
                                : 0.5 * sqrt(3.0) * mat->modulus;
}

double canopy_build_string_stiffness(const canopy_material *mat, double l0)
{
    /* E = (F/A)(l/dl) (seed 000 eq. 5.1) gives k = F/dl = E A / l. */
    return mat->stiffness > 0.0 ? mat->stiffness : mat->modulus / l0;
}

/* --- rollback ------------------------------------------------------------ */

void canopy_build_mark_take(const canopy_model *model, canopy_build_mark *mark)
{
    mark->nodes = model->nodes.count;
    mark->springs = model->springs.count;
    mark->triangles = model->tris.count;
    mark->checkpoint_valid = model->checkpoint.valid;
    mark->acc_valid = model->acc_valid;
    mark->payload_node = model->payload_node;
}

void canopy_build_rollback(canopy_model *model, const canopy_build_mark *mark)
{
    /* Entries past the counts are dead storage: every add_* call rewrites
     * all fields of the entry it appends. */
    model->nodes.count = mark->nodes;
    model->springs.count = mark->springs;
    model->tris.count = mark->triangles;
    /* The checkpoint's arrays still hold mark->nodes nodes: adding only
     * marked it invalid. The carried acceleration of the old nodes was not
     * touched either. */
    model->checkpoint.valid = mark->checkpoint_valid;
    model->acc_valid = mark->acc_valid;
    model->payload_node = mark->payload_node;
    model->prepared = 0;
}

canopy_status canopy_build_abort(canopy_model *model,
                                 const canopy_build_mark *mark,
                                 canopy_status st, const char *who,
                                 const char *args)
{
    canopy_build_rollback(model, mark);
    if (st != CANOPY_ERR_ARGUMENT && st != CANOPY_ERR_RANGE) return st;
    /* The internal message without its "CANOPY_ERR_X: " prefix. */
    char inner[CANOPY_MESSAGE_SIZE];
    const char *text = strstr(model->message, ": ");
    snprintf(inner, sizeof inner, "%s", text ? text + 2 : model->message);
    return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                       "%s: %s make a degenerate model (%s)", who, args,
                       inner);
}

canopy_status canopy_build_check_segment(canopy_model *model, const char *who,
                                         const char *what, double length,
                                         int n_segments,
                                         const canopy_material *material)
{
    const double seg = length / n_segments;
    const double k = canopy_build_string_stiffness(material, seg);
    const double half_mass = 0.5 * material->density * seg;
    if (!(seg * seg >= DBL_MIN) || !isfinite(seg * seg))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s gives segments of length %g (%d of %g), "
                           "too short or too long for double precision", who,
                           what, seg, n_segments, length);
    if (!(k > 0.0) || !isfinite(k) || !isfinite(half_mass))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: %s gives segments of length %g, whose "
                           "stiffness %g or mass %g from the material is not "
                           "finite and > 0", who, what, seg, k, 2 * half_mass);
    return CANOPY_OK;
}

canopy_status canopy_build_string_spring(canopy_model *model, int i, int j,
                                         const canopy_material *material,
                                         canopy_group group, double *l0_out)
{
    const double *xi = model->nodes.x + 3 * i, *xj = model->nodes.x + 3 * j;
    const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
    const double l0 = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (l0_out) *l0_out = l0;
    return canopy_model_add_spring(model, i, j,
                                   canopy_build_string_stiffness(material, l0),
                                   material->damping, material->law, group,
                                   NULL);
}

/* --- fabric: triangles, masses, one spring per edge ---------------------- */

static size_t hash_slot(unsigned long long key, size_t capacity)
{
    /* Fibonacci hashing; capacity is a power of two. */
    return (size_t)((key * 0x9E3779B97F4A7C15ULL) >> 20) & (capacity - 1);
}

static int edge_table_alloc(canopy_fabric_builder *fb, size_t capacity)
{
    unsigned long long *keys = calloc(capacity, sizeof *keys);
    if (keys == NULL) return 0;
    unsigned long long *old = fb->keys;
    const size_t old_cap = fb->capacity;
    fb->keys = keys;
    fb->capacity = capacity;
    for (size_t s = 0; s < old_cap; ++s) {
        if (old[s] == 0) continue;
        size_t h = hash_slot(old[s], capacity);
        while (keys[h] != 0) h = (h + 1) & (capacity - 1);
        keys[h] = old[s];
    }
    free(old);
    return 1;
}

canopy_status canopy_fabric_begin(canopy_fabric_builder *fb,
                                  canopy_model *model,
                                  const canopy_material *material,
                                  canopy_group group, const double up[3],
                                  size_t expected_edges)
{
    fb->model = model;
    fb->stiffness = canopy_build_sheet_stiffness(material);
    fb->damping = material->damping;
    fb->density = material->density;
    fb->law = material->law;
    fb->group = group;
    fb->up[0] = up[0]; fb->up[1] = up[1]; fb->up[2] = up[2];
    fb->keys = NULL;
    fb->capacity = 0;
    fb->used = 0;
    size_t cap = 64;
    while (cap < 2 * expected_edges) cap *= 2;   /* load factor <= 1/2 */
    if (!edge_table_alloc(fb, cap))
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           "cannot allocate an edge table of %zu entries", cap);
    return CANOPY_OK;
}

void canopy_fabric_end(canopy_fabric_builder *fb)
{
    free(fb->keys);
    fb->keys = NULL;
    fb->capacity = fb->used = 0;
}

/* Spring for edge a–b unless the fabric already has one. */
static canopy_status fabric_edge(canopy_fabric_builder *fb, int a, int b)
{
    const unsigned lo = (unsigned)(a < b ? a : b), hi = (unsigned)(a < b ? b : a);
    const unsigned long long key =
        ((unsigned long long)(lo + 1u) << 32) | (unsigned long long)(hi + 1u);
    size_t h = hash_slot(key, fb->capacity);
    while (fb->keys[h] != 0) {
        if (fb->keys[h] == key) return CANOPY_OK;
        h = (h + 1) & (fb->capacity - 1);
    }
    canopy_status st = canopy_model_add_spring(fb->model, a, b, fb->stiffness,
                                               fb->damping, fb->law, fb->group,
                                               NULL);
    if (st != CANOPY_OK) return st;
    fb->keys[h] = key;
    if (2 * ++fb->used > fb->capacity &&
        !edge_table_alloc(fb, 2 * fb->capacity))
        return canopy_fail(fb->model, CANOPY_ERR_MEMORY,
                           "cannot grow the edge table to %zu entries",
                           2 * fb->capacity);
    return CANOPY_OK;
}

canopy_status canopy_fabric_triangle(canopy_fabric_builder *fb, int a, int b,
                                     int c)
{
    canopy_model *m = fb->model;
    int tri[3] = {a, b, c};
    double an[3];
    canopy_triangle_area_normal(m->nodes.x, tri, an);
    if (an[0] * fb->up[0] + an[1] * fb->up[1] + an[2] * fb->up[2] < 0.0) {
        tri[1] = c;
        tri[2] = b;
    }
    canopy_status st = canopy_model_add_triangle(m, tri[0], tri[1], tri[2],
                                                 NULL);
    if (st != CANOPY_OK) return st;
    /* Lumped mass: areal density x 1/3 of the triangle's area to each vertex
     * (NOTES §3, one mass model). */
    const double area = sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
    const double share = fb->density * area / 3.0;
    for (int v = 0; v < 3; ++v)
        if ((st = canopy_model_add_node_mass(m, tri[v], share)) != CANOPY_OK)
            return st;
    if ((st = fabric_edge(fb, tri[0], tri[1])) != CANOPY_OK) return st;
    if ((st = fabric_edge(fb, tri[1], tri[2])) != CANOPY_OK) return st;
    return fabric_edge(fb, tri[2], tri[0]);
}

static double point_distance(const double *xyz, int i, int j)
{
    const double *a = xyz + 3 * i, *b = xyz + 3 * j;
    const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

int canopy_zip_step(const double *xyz, const int *lower, int nl,
                    const int *upper, int nu, int i, int j)
{
    if (i == nl) return 0;
    if (j == nu) return 1;
    /* Candidate diagonals: lower[i+1]-upper[j] (advance lower) or
     * lower[i]-upper[j+1] (advance upper); the shorter one wins. */
    const double dl = point_distance(xyz, lower[i + 1], upper[j]);
    const double du = point_distance(xyz, lower[i], upper[j + 1]);
    if (fabs(dl - du) <= 1e-9 * (dl + du))
        return (double)(i + 1) * nu <= (double)(j + 1) * nl;
    return dl < du;
}

canopy_status canopy_fabric_zip(canopy_fabric_builder *fb, const int *lower,
                                int nl, const int *upper, int nu)
{
    int i = 0, j = 0;
    while (i < nl || j < nu) {
        canopy_status st;
        if (canopy_zip_step(fb->model->nodes.x, lower, nl, upper, nu, i, j)) {
            st = canopy_fabric_triangle(fb, lower[i], lower[i + 1], upper[j]);
            ++i;
        } else {
            st = canopy_fabric_triangle(fb, lower[i], upper[j + 1], upper[j]);
            ++j;
        }
        if (st != CANOPY_OK) return st;
    }
    return CANOPY_OK;
}


/* Spacing count of a length at the target edge: round(len / e) >= 1. */
int canopy_build_spacings(double len, double e)
{
    const double q = floor(len / e + 0.5);
    if (!(q <= CANOPY_BUILD_SPACINGS_MAX)) return CANOPY_BUILD_SPACINGS_MAX;
    return q < 1.0 ? 1 : (int)q;
}

/* Row spacings of a band of thickness T for node spacing s: the fewest rows
 * with spacing <= (sqrt(3)/2) s (the relative slack keeps an exact fit). */
int canopy_build_row_spacings(double T, double s)
{
    const double q = ceil(T / (0.5 * sqrt(3.0) * s) * (1.0 - 1e-12));
    if (!(q <= CANOPY_BUILD_SPACINGS_MAX)) return CANOPY_BUILD_SPACINGS_MAX;
    return q < 1.0 ? 1 : (int)q;
}

/* Checks shared by the flat builders: edge length finite and > 0, the
 * placement point finite, the fabric material valid. */
canopy_status canopy_build_check_positive(canopy_model *model, const char *who,
                                          const char *name, double value)
{
    if (isfinite(value) && value > 0.0) return CANOPY_OK;
    return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                       "%s: spec.%s %g must be finite and > 0", who, name,
                       value);
}

canopy_status canopy_build_check_flat(canopy_model *model, const char *who,
                                      double edge, const double point[3],
                                      const char *point_name,
                                      const canopy_material *fabric)
{
    canopy_status st = canopy_build_check_positive(model, who, "edge_length",
                                                   edge);
    if (st) return st;
    if (!canopy_build_finite3(point))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "%s: spec.%s (%g, %g, %g) is not finite", who,
                           point_name, point[0], point[1], point[2]);
    return canopy_build_check_material(model, who, "spec.fabric", fabric);
}

