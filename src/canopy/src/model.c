/* model.c — creating, building, validating and querying a canopy_model. */
#include "integrator.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Most Newton iterations a step may be given (set_implicit_controls): a
 * bound on the time one step can take. */
#define CANOPY_MAX_NEWTON_ITERATIONS 1000

#define NULL_MODEL_CHECK(model) \
    do { if ((model) == NULL) return CANOPY_ERR_ARGUMENT; } while (0)

/* memcpy that accepts empty arrays (whose pointers may be NULL). */
static void copy_array(void *dst, const void *src, size_t bytes)
{
    if (bytes > 0) memcpy(dst, src, bytes);
}

static int finite3(const double x[3])
{
    return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

/* Grow `*p` (elements of `size` bytes) from old_cap to new_cap, zero-filled. */
static int grow(void **p, size_t size, int old_cap, int new_cap)
{
    void *q = realloc(*p, size * (size_t)new_cap);
    if (q == NULL) return 0;
    memset((char *)q + size * (size_t)old_cap, 0,
           size * (size_t)(new_cap - old_cap));
    *p = q;
    return 1;
}

/* Doubling from cap until need fits; saturates at INT_MAX (need is at most
 * INT_MAX: the reserve_* functions refuse a count that cannot grow). */
static int next_capacity(int cap, int need)
{
    int c = cap > 0 ? cap : 64;
    while (c < need) c = c > INT_MAX / 2 ? INT_MAX : 2 * c;
    return c;
}

/* The count after adding one, if an int holds it. */
static int count_can_grow(int count)
{
    return count < INT_MAX;
}

/* Room for one more entry. */
static canopy_status reserve_nodes(canopy_model *m)
{
    canopy_nodes *n = &m->nodes;
    if (n->count < n->capacity) return CANOPY_OK;
    if (!count_can_grow(n->count))
        return canopy_fail(m, CANOPY_ERR_RANGE, "the model holds %d nodes, "
                           "the most an int can count", n->count);
    int cap = next_capacity(n->capacity, n->count + 1), old = n->capacity;
    if (!grow((void **)&n->x, 3 * sizeof(double), old, cap) ||
        !grow((void **)&n->v, 3 * sizeof(double), old, cap) ||
        !grow((void **)&n->mass, sizeof(double), old, cap) ||
        !grow((void **)&n->added_mass, sizeof(double), old, cap) ||
        !grow((void **)&n->added_dir, 3 * sizeof(double), old, cap) ||
        !grow((void **)&n->force_ext, 3 * sizeof(double), old, cap) ||
        !grow((void **)&n->acc, 3 * sizeof(double), old, cap) ||
        !grow((void **)&n->guide, 3 * sizeof(double), old, cap) ||
        !grow((void **)&n->fixed, 1, old, cap) ||
        !grow((void **)&n->group, 1, old, cap)) {
        /* Arrays that grew keep the larger block; capacity stays the old one,
         * which is safe (the next attempt reallocates again). */
        return canopy_fail(m, CANOPY_ERR_MEMORY, "cannot grow node arrays to %d",
                           cap);
    }
    n->capacity = cap;
    return CANOPY_OK;
}

/* Room for one more entry. */
static canopy_status reserve_springs(canopy_model *m)
{
    canopy_springs *s = &m->springs;
    if (s->count < s->capacity) return CANOPY_OK;
    if (!count_can_grow(s->count))
        return canopy_fail(m, CANOPY_ERR_RANGE, "the model holds %d springs, "
                           "the most an int can count", s->count);
    int cap = next_capacity(s->capacity, s->count + 1), old = s->capacity;
    if (!grow((void **)&s->ends, 2 * sizeof(int), old, cap) ||
        !grow((void **)&s->rest, sizeof(double), old, cap) ||
        !grow((void **)&s->rest_vec, 3 * sizeof(double), old, cap) ||
        !grow((void **)&s->k, sizeof(double), old, cap) ||
        !grow((void **)&s->c, sizeof(double), old, cap) ||
        !grow((void **)&s->law, 1, old, cap) ||
        !grow((void **)&s->group, 1, old, cap)) {
        return canopy_fail(m, CANOPY_ERR_MEMORY,
                           "cannot grow spring arrays to %d", cap);
    }
    s->capacity = cap;
    return CANOPY_OK;
}

/* Room for one more entry. */
static canopy_status reserve_triangles(canopy_model *m)
{
    canopy_triangles *t = &m->tris;
    if (t->count < t->capacity) return CANOPY_OK;
    if (!count_can_grow(t->count))
        return canopy_fail(m, CANOPY_ERR_RANGE, "the model holds %d "
                           "triangles, the most an int can count", t->count);
    int cap = next_capacity(t->capacity, t->count + 1), old = t->capacity;
    if (!grow((void **)&t->nodes, 3 * sizeof(int), old, cap) ||
        !grow((void **)&t->dp, sizeof(double), old, cap) ||
        !grow((void **)&t->added_mass, sizeof(double), old, cap)) {
        return canopy_fail(m, CANOPY_ERR_MEMORY,
                           "cannot grow triangle arrays to %d", cap);
    }
    t->capacity = cap;
    return CANOPY_OK;
}

canopy_status canopy_model_create(canopy_model **out)
{
    if (out == NULL) return CANOPY_ERR_ARGUMENT;
    *out = NULL;
    canopy_model *m = calloc(1, sizeof *m);
    if (m == NULL) return CANOPY_ERR_MEMORY;
    m->gravity[2] = -9.81;
    m->payload_node = -1;
    m->integrator = &canopy_integrator_rk4;
    m->max_omega_dt = 0.1;
    m->hht_alpha = -0.1;
    m->implicit_tol = 1e-10;
    m->implicit_max_iter = 25;
    m->speed_limit = 1e4;
    m->fabric_compression = 1.0;
    *out = m;
    return CANOPY_OK;
}

void canopy_model_destroy(canopy_model **model)
{
    if (model == NULL || *model == NULL) return;
    canopy_model *m = *model;
    free(m->nodes.x); free(m->nodes.v); free(m->nodes.mass);
    free(m->nodes.added_mass); free(m->nodes.added_dir);
    free(m->nodes.force_ext); free(m->nodes.acc); free(m->nodes.guide);
    free(m->nodes.fixed); free(m->nodes.group);
    free(m->springs.ends); free(m->springs.rest); free(m->springs.rest_vec);
    free(m->springs.k); free(m->springs.c); free(m->springs.law);
    free(m->springs.group);
    free(m->tris.nodes); free(m->tris.dp); free(m->tris.added_mass);
    free(m->hinges.nodes); free(m->hinges.modes);
    canopy_hinge_filter_free(&m->hinges.filter);
    canopy_state_free(&m->checkpoint);
    canopy_state_free(&m->rollback);
    canopy_stepper_free(&m->stepper);
    canopy_hinge_solver_destroy(&m->hinge_solver);
    canopy_vectors_free(&m->bound_sums);
    canopy_vectors_free(&m->pressure_step);
    free(m);
    *model = NULL;
}

canopy_status canopy_check_node(canopy_model *model, int node, const char *what)
{
    if (node < 0 || node >= model->nodes.count)
        return canopy_fail(model, CANOPY_ERR_RANGE,
                           "%s: node index %d outside [0, %d)", what, node,
                           model->nodes.count);
    return CANOPY_OK;
}

/* Any change of topology, mass or fixing invalidates the prepared state and
 * the user checkpoint (whose arrays are sized by the node count). */
static void topology_changed(canopy_model *m)
{
    m->prepared = 0;
    m->checkpoint.valid = 0;
    m->acc_valid = 0;
}

canopy_status canopy_model_add_node(canopy_model *model, const double x[3],
                                    double mass, canopy_group group,
                                    int *index_out)
{
    NULL_MODEL_CHECK(model);
    if (x == NULL || !finite3(x))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_node: position is NULL or not finite");
    if (!(mass >= 0.0) || !isfinite(mass))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_node: mass %g must be finite and >= 0", mass);
    if ((int)group < 0 || group > CANOPY_GROUP_OTHER)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_node: unknown group %d", (int)group);
    canopy_status st = reserve_nodes(model);
    if (st != CANOPY_OK) return st;
    canopy_nodes *n = &model->nodes;
    int i = n->count++;
    memcpy(n->x + 3 * i, x, 3 * sizeof(double));
    memset(n->v + 3 * i, 0, 3 * sizeof(double));
    memset(n->force_ext + 3 * i, 0, 3 * sizeof(double));
    n->mass[i] = mass;
    n->added_mass[i] = 0.0;
    memset(n->added_dir + 3 * i, 0, 3 * sizeof(double));
    memset(n->guide + 3 * i, 0, 3 * sizeof(double));
    n->fixed[i] = 0;
    n->group[i] = (unsigned char)group;
    topology_changed(model);
    if (index_out) *index_out = i;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_add_node_mass(canopy_model *model, int node,
                                         double mass)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = canopy_check_node(model, node, "add_node_mass");
    if (st != CANOPY_OK) return st;
    if (!(mass >= 0.0) || !isfinite(mass))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_node_mass: mass %g for node %d must be finite "
                           "and >= 0", mass, node);
    if (!isfinite(model->nodes.mass[node] + mass))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_node_mass: mass %g added to node %d's %g is "
                           "not finite", mass, node, model->nodes.mass[node]);
    model->nodes.mass[node] += mass;
    topology_changed(model);
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_fixed(canopy_model *model, int node, int fixed)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = canopy_check_node(model, node, "set_fixed");
    if (st != CANOPY_OK) return st;
    model->nodes.fixed[node] = fixed ? 1 : 0;
    topology_changed(model);
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_guide(canopy_model *model, int node,
                                     const double axis[3])
{
    NULL_MODEL_CHECK(model);
    canopy_status st = canopy_check_node(model, node, "set_guide");
    if (st != CANOPY_OK) return st;
    double e[3] = {0.0, 0.0, 0.0};
    if (axis != NULL) {
        if (!isfinite(axis[0]) || !isfinite(axis[1]) || !isfinite(axis[2]))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "set_guide: axis of node %d is not finite",
                               node);
        /* scaled first, so that 1e-300 or 1e300 components normalise */
        const double big = fmax(fabs(axis[0]), fmax(fabs(axis[1]),
                                                     fabs(axis[2])));
        if (big > 0.0) {
            const double u[3] = {axis[0] / big, axis[1] / big, axis[2] / big};
            const double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            for (int d = 0; d < 3; ++d) e[d] = u[d] / len;
        }
    }
    canopy_nodes *n = &model->nodes;
    memcpy(n->guide + 3 * node, e, 3 * sizeof(double));
    /* on the wire from now on: no velocity or acceleration across it */
    canopy_guide_project(model, node, n->v + 3 * node);
    canopy_guide_project(model, node, n->acc + 3 * node);
    topology_changed(model);
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_get_guide(const canopy_model *model, int node,
                                     double axis[3])
{
    NULL_MODEL_CHECK(model);
    if (axis == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT,
                             "get_guide: axis is NULL");
    if (node < 0 || node >= model->nodes.count)
        return canopy_reject(model, CANOPY_ERR_RANGE,
                             "get_guide: node %d is not in 0..%d", node,
                             model->nodes.count - 1);
    memcpy(axis, model->nodes.guide + 3 * node, 3 * sizeof(double));
    return CANOPY_OK;
}

canopy_status canopy_model_add_spring(canopy_model *model, int i, int j,
                                      double stiffness, double damping,
                                      canopy_spring_law law, canopy_group group,
                                      int *index_out)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = canopy_check_node(model, i, "add_spring (end i)");
    if (st != CANOPY_OK) return st;
    st = canopy_check_node(model, j, "add_spring (end j)");
    if (st != CANOPY_OK) return st;
    if (i == j)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring: both ends are node %d", i);
    if (!(stiffness > 0.0) || !isfinite(stiffness))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring %d-%d: stiffness %g must be > 0", i, j,
                           stiffness);
    if (!(damping >= 0.0) || !isfinite(damping))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring %d-%d: damping %g must be >= 0", i, j,
                           damping);
    if ((int)law < 0 || law > CANOPY_SPRING_TENSION_ONLY)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring %d-%d: unknown spring law %d", i, j,
                           (int)law);
    if ((int)group < 0 || group > CANOPY_GROUP_OTHER)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring %d-%d: unknown group %d", i, j,
                           (int)group);
    const double *xi = model->nodes.x + 3 * i, *xj = model->nodes.x + 3 * j;
    double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
    double l0 = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(l0 > 0.0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring %d-%d: zero rest length (nodes "
                           "coincide)", i, j);
    if (!isfinite(l0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_spring %d-%d: rest length %g is not finite "
                           "(nodes too far apart)", i, j, l0);
    st = reserve_springs(model);
    if (st != CANOPY_OK) return st;
    canopy_springs *s = &model->springs;
    int k = s->count++;
    s->ends[2 * k] = i;
    s->ends[2 * k + 1] = j;
    s->rest[k] = l0;
    memcpy(s->rest_vec + 3 * k, d, sizeof d);
    s->k[k] = stiffness;
    s->c[k] = damping;
    s->law[k] = (unsigned char)law;
    s->group[k] = (unsigned char)group;
    topology_changed(model);
    if (index_out) *index_out = k;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_rest_length(canopy_model *model, int spring,
                                           double rest_length)
{
    NULL_MODEL_CHECK(model);
    if (spring < 0 || spring >= model->springs.count)
        return canopy_fail(model, CANOPY_ERR_RANGE,
                           "set_rest_length: spring index %d outside [0, %d)",
                           spring, model->springs.count);
    if (!(rest_length > 0.0) || !isfinite(rest_length))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_rest_length: spring %d rest length %g must be "
                           "> 0", spring, rest_length);
    double scale = rest_length / model->springs.rest[spring];
    model->springs.rest[spring] = rest_length;
    for (int d = 0; d < 3; ++d) model->springs.rest_vec[3 * spring + d] *= scale;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_add_triangle(canopy_model *model, int a, int b,
                                        int c, int *index_out)
{
    NULL_MODEL_CHECK(model);
    canopy_status st;
    if ((st = canopy_check_node(model, a, "add_triangle (a)")) != CANOPY_OK ||
        (st = canopy_check_node(model, b, "add_triangle (b)")) != CANOPY_OK ||
        (st = canopy_check_node(model, c, "add_triangle (c)")) != CANOPY_OK)
        return st;
    if (a == b || b == c || a == c)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "add_triangle: nodes %d %d %d are not distinct", a,
                           b, c);
    st = reserve_triangles(model);
    if (st != CANOPY_OK) return st;
    int t = model->tris.count++;
    model->tris.nodes[3 * t] = a;
    model->tris.nodes[3 * t + 1] = b;
    model->tris.nodes[3 * t + 2] = c;
    model->tris.dp[t] = 0.0;
    model->tris.added_mass[t] = 0.0;
    topology_changed(model);
    if (index_out) *index_out = t;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_gravity(canopy_model *model, const double g[3])
{
    NULL_MODEL_CHECK(model);
    if (g == NULL || !finite3(g))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_gravity: vector is NULL or not finite");
    memcpy(model->gravity, g, 3 * sizeof(double));
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_get_gravity(const canopy_model *model, double g[3])
{
    NULL_MODEL_CHECK(model);
    if (g == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT,
                             "get_gravity: g is NULL");
    memcpy(g, model->gravity, 3 * sizeof(double));
    return CANOPY_OK;
}

canopy_status canopy_model_set_porosity(canopy_model *model, double alpha,
                                        double beta)
{
    NULL_MODEL_CHECK(model);
    if (!(alpha >= 0.0) || !isfinite(alpha) || !(beta >= 0.0) ||
        !isfinite(beta))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_porosity: alpha %g and beta %g must be finite "
                           "and >= 0", alpha, beta);
    model->porosity_alpha = alpha;
    model->porosity_beta = beta;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_payload_node(canopy_model *model, int node)
{
    NULL_MODEL_CHECK(model);
    if (node != -1) {
        canopy_status st = canopy_check_node(model, node, "set_payload_node");
        if (st != CANOPY_OK) return st;
    }
    model->payload_node = node;
    canopy_clear_message(model);
    return CANOPY_OK;
}

/* --- validation and workspaces ------------------------------------------ */

canopy_status canopy_model_prepare(canopy_model *model)
{
    if (model->prepared) return CANOPY_OK;
    const canopy_nodes *n = &model->nodes;
    if (n->count == 0)
        return canopy_fail(model, CANOPY_ERR_STATE, "the model has no nodes");
    /* The hinge dashpots are sized by, and the implicit ones act on, the
     * nodes' own masses (bending.c): an added mass cannot stand in there. */
    const int own_mass = model->bending_damping > 0.0;
    for (int i = 0; i < n->count; ++i) {
        if (n->fixed[i]) continue;
        if (!(canopy_effective_mass(model, i) > 0.0) ||
            (own_mass && !(n->mass[i] > 0.0)))
            return canopy_fail(model, CANOPY_ERR_STATE,
                               "node %d is free but has zero mass", i);
    }
    for (int i = 0; i < n->count; ++i) {
        if (!canopy_guided(model, i)) continue;
        if (n->fixed[i])
            return canopy_fail(model, CANOPY_ERR_STATE,
                               "node %d is both fixed and on a guide "
                               "(set_guide)", i);
        if (model->integrator == &canopy_integrator_kang)
            return canopy_fail(model, CANOPY_ERR_STATE,
                               "node %d is on a guide (set_guide), which "
                               "needs an explicit integrator, newmark or "
                               "hht, not 'kang'", i);
    }
    if (model->directional_added_mass &&
        model->integrator == &canopy_integrator_kang)
        return canopy_fail(model, CANOPY_ERR_STATE,
                           "a directional added mass (set_directional_added_"
                           "mass) needs an explicit integrator, newmark or "
                           "hht, not '%s'",
                           model->integrator->name);
    if (model->triangle_added_mass &&
        model->integrator != &canopy_integrator_hht &&
        model->integrator != &canopy_integrator_newmark)
        return canopy_fail(model, CANOPY_ERR_STATE,
                           "a triangles' added mass (set_triangle_added_"
                           "mass) needs integrator newmark or hht, not '%s'",
                           model->integrator->name);
    /* Each workspace is replaced only once its successor is allocated. */
    canopy_status st = canopy_stepper_prepare(model);
    if (st != CANOPY_OK) return st;
    if (model->bound_sums.nodes != n->count || model->bound_sums.data == NULL) {
        canopy_vectors sums;
        if (canopy_vectors_alloc(&sums, 1, n->count) != 0)
            return canopy_fail(model, CANOPY_ERR_MEMORY,
                               "cannot allocate the frequency bound's sums "
                               "for %d nodes", n->count);
        canopy_vectors_free(&model->bound_sums);
        model->bound_sums = sums;
    }
    if (model->pressure_step.nodes != n->count ||
        model->pressure_step.data == NULL) {
        canopy_vectors held;
        if (canopy_vectors_alloc(&held, 1, n->count) != 0)
            return canopy_fail(model, CANOPY_ERR_MEMORY,
                               "cannot allocate the held pressure load for "
                               "%d nodes", n->count);
        canopy_vectors_free(&model->pressure_step);
        model->pressure_step = held;
    }
    if ((st = canopy_hinges_build(model)) != CANOPY_OK) return st;
    if ((st = canopy_hinge_solver_prepare(model)) != CANOPY_OK) return st;
    model->prepared = 1;
    return CANOPY_OK;
}

/* --- sizes and state ----------------------------------------------------- */

int canopy_model_node_count(const canopy_model *model)
{
    return model ? model->nodes.count : 0;
}
int canopy_model_spring_count(const canopy_model *model)
{
    return model ? model->springs.count : 0;
}
int canopy_model_triangle_count(const canopy_model *model)
{
    return model ? model->tris.count : 0;
}
double canopy_model_time(const canopy_model *model)
{
    return model ? model->t : NAN;
}

canopy_status canopy_model_set_time(canopy_model *model, double t)
{
    NULL_MODEL_CHECK(model);
    if (!isfinite(t))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_time: time is not finite");
    model->t = t;
    canopy_clear_message(model);
    return CANOPY_OK;
}

/* Count check shared by the array getters/setters (const-safe: the message
 * is only written when the model is mutable). */
static canopy_status count_check(const canopy_model *model, const void *ptr,
                                 int given, int expected, const char *what)
{
    if (ptr == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT, "%s: array is NULL",
                             what);
    if (given != expected)
        return canopy_reject(model, CANOPY_ERR_RANGE,
                           "%s: count %d does not match the model's %d", what,
                           given, expected);
    return CANOPY_OK;
}

canopy_status canopy_model_get_positions(const canopy_model *model, double *x,
                                         int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, x, n, model->nodes.count,
                                   "get_positions");
    if (st != CANOPY_OK) return st;
    copy_array(x, model->nodes.x, 3 * sizeof(double) * (size_t)n);
    return CANOPY_OK;
}

canopy_status canopy_model_get_velocities(const canopy_model *model, double *v,
                                          int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, v, n, model->nodes.count,
                                   "get_velocities");
    if (st != CANOPY_OK) return st;
    copy_array(v, model->nodes.v, 3 * sizeof(double) * (size_t)n);
    return CANOPY_OK;
}

static canopy_status set_vectors(canopy_model *model, double *dst,
                                 const double *src, int n, const char *what)
{
    canopy_status st = count_check(model, src, n, model->nodes.count, what);
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < 3 * n; ++i)
        if (!isfinite(src[i]))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "%s: component %d of node %d is not finite",
                               what, i % 3, i / 3);
    copy_array(dst, src, 3 * sizeof(double) * (size_t)n);
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_positions(canopy_model *model, const double *x,
                                         int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = set_vectors(model, model->nodes.x, x, n, "set_positions");
    if (st == CANOPY_OK) model->acc_valid = 0;
    return st;
}

canopy_status canopy_model_set_velocities(canopy_model *model, const double *v,
                                          int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = set_vectors(model, model->nodes.v, v, n,
                                   "set_velocities");
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < n; ++i) canopy_guide_project(model, i, model->nodes.v + 3 * i);
    model->acc_valid = 0;
    return st;
}

canopy_status canopy_model_get_acceleration_state(const canopy_model *model,
                                                  double *a, int n, int *valid)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, a, n, model->nodes.count,
                                   "get_acceleration_state");
    if (st != CANOPY_OK) return st;
    copy_array(a, model->nodes.acc, 3 * sizeof(double) * (size_t)n);
    if (valid) *valid = model->acc_valid;
    return CANOPY_OK;
}

canopy_status canopy_model_set_acceleration_state(canopy_model *model,
                                                  const double *a, int n,
                                                  int valid)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = set_vectors(model, model->nodes.acc, a, n,
                                   "set_acceleration_state");
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < n; ++i) canopy_guide_project(model, i, model->nodes.acc + 3 * i);
    model->acc_valid = valid ? 1 : 0;
    return st;
}

canopy_status canopy_model_set_state(canopy_model *model, double t,
                                     const double *x, const double *v,
                                     const double *acc, int acc_valid, int n)
{
    NULL_MODEL_CHECK(model);
    if (!isfinite(t))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_state: time is not finite");
    canopy_status st = count_check(model, x, n, model->nodes.count,
                                   "set_state (positions)");
    if (st == CANOPY_OK)
        st = count_check(model, v, n, model->nodes.count,
                         "set_state (velocities)");
    if (st == CANOPY_OK && acc_valid)
        st = count_check(model, acc, n, model->nodes.count,
                         "set_state (acceleration)");
    if (st != CANOPY_OK) return st;
    const double *arrays[3] = {x, v, acc_valid ? acc : NULL};
    const char *names[3] = {"position", "velocity", "acceleration"};
    for (int a = 0; a < 3; ++a)
        for (int i = 0; arrays[a] != NULL && i < 3 * n; ++i)
            if (!isfinite(arrays[a][i]))
                return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                                   "set_state: component %d of node %d's "
                                   "%s is not finite", i % 3, i / 3,
                                   names[a]);
    copy_array(model->nodes.x, x, 3 * sizeof(double) * (size_t)n);
    copy_array(model->nodes.v, v, 3 * sizeof(double) * (size_t)n);
    if (acc_valid)
        copy_array(model->nodes.acc, acc, 3 * sizeof(double) * (size_t)n);
    model->acc_valid = acc_valid ? 1 : 0;
    model->t = t;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_nodal_forces(canopy_model *model,
                                            const double *f, int n)
{
    NULL_MODEL_CHECK(model);
    return set_vectors(model, model->nodes.force_ext, f, n, "set_nodal_forces");
}

canopy_status canopy_model_get_masses(const canopy_model *model, double *mass,
                                      int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, mass, n, model->nodes.count,
                                   "get_masses");
    if (st != CANOPY_OK) return st;
    copy_array(mass, model->nodes.mass, sizeof(double) * (size_t)n);
    return CANOPY_OK;
}

canopy_status canopy_model_get_fixed(const canopy_model *model, int *fixed,
                                     int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, fixed, n, model->nodes.count,
                                   "get_fixed");
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < n; ++i) fixed[i] = model->nodes.fixed[i];
    return CANOPY_OK;
}

canopy_status canopy_model_get_node_groups(const canopy_model *model,
                                           int *group, int n)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, group, n, model->nodes.count,
                                   "get_node_groups");
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < n; ++i) group[i] = model->nodes.group[i];
    return CANOPY_OK;
}

canopy_status canopy_model_get_springs(const canopy_model *model, int *ends,
                                       double *rest_length, double *stiffness,
                                       int ns)
{
    NULL_MODEL_CHECK(model);
    const canopy_springs *s = &model->springs;
    if (ns != s->count)
        return count_check(model, &ns, ns, s->count, "get_springs");
    if (ends) copy_array(ends, s->ends, 2 * sizeof(int) * (size_t)ns);
    if (rest_length) copy_array(rest_length, s->rest, sizeof(double) * (size_t)ns);
    if (stiffness) copy_array(stiffness, s->k, sizeof(double) * (size_t)ns);
    return CANOPY_OK;
}

canopy_status canopy_model_get_spring_groups(const canopy_model *model,
                                             int *group, int ns)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, group, ns, model->springs.count,
                                   "get_spring_groups");
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < ns; ++i) group[i] = model->springs.group[i];
    return CANOPY_OK;
}

canopy_status canopy_model_get_triangles(const canopy_model *model, int *tri,
                                         int nt)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, tri, nt, model->tris.count,
                                   "get_triangles");
    if (st != CANOPY_OK) return st;
    copy_array(tri, model->tris.nodes, 3 * sizeof(int) * (size_t)nt);
    return CANOPY_OK;
}

canopy_status canopy_model_set_pressure_jump(canopy_model *model,
                                             const double *dp, int nt)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, dp, nt, model->tris.count,
                                   "set_pressure_jump");
    if (st != CANOPY_OK) return st;
    for (int t = 0; t < nt; ++t)
        if (!isfinite(dp[t]))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "set_pressure_jump: triangle %d value is not "
                               "finite", t);
    copy_array(model->tris.dp, dp, sizeof(double) * (size_t)nt);
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_get_pressure_jump(const canopy_model *model,
                                             double *dp, int nt)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, dp, nt, model->tris.count,
                                   "get_pressure_jump");
    if (st != CANOPY_OK) return st;
    copy_array(dp, model->tris.dp, sizeof(double) * (size_t)nt);
    return CANOPY_OK;
}

/* Added mass per node, acting along direction[3i..3i+2] (normalised) or,
 * where that is zero or direction is NULL, in every direction. */
static canopy_status store_added_mass(canopy_model *model,
                                      const double *added_mass,
                                      const double *direction, int n,
                                      const char *who)
{
    canopy_status st = count_check(model, added_mass, n, model->nodes.count,
                                   who);
    if (st != CANOPY_OK) return st;
    for (int i = 0; i < n; ++i) {
        if (!(added_mass[i] >= 0.0) || !isfinite(added_mass[i]))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "%s: node %d value %g must be finite and >= 0",
                               who, i, added_mass[i]);
        if (direction && !isfinite(direction[3 * i] + direction[3 * i + 1] +
                                   direction[3 * i + 2]))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "%s: node %d direction is not finite", who, i);
    }
    int directional = 0;
    for (int i = 0; i < n; ++i) {
        double *u = model->nodes.added_dir + 3 * i;
        u[0] = u[1] = u[2] = 0.0;
        model->nodes.added_mass[i] = added_mass[i];
        if (direction == NULL || !(added_mass[i] > 0.0)) continue;
        const double *d = direction + 3 * i;
        /* hypot: neither overflows nor underflows for finite d */
        const double len = hypot(hypot(d[0], d[1]), d[2]);
        if (len > 0.0) {
            u[0] = d[0] / len; u[1] = d[1] / len; u[2] = d[2] / len;
            directional = 1;
        }
    }
    model->directional_added_mass = directional;
    model->prepared = 0; /* masses changed: re-validate */
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_added_mass(canopy_model *model,
                                          const double *added_mass, int n)
{
    NULL_MODEL_CHECK(model);
    return store_added_mass(model, added_mass, NULL, n, "set_added_mass");
}

canopy_status canopy_model_set_directional_added_mass(canopy_model *model,
                                                      const double *added_mass,
                                                      const double *direction,
                                                      int n)
{
    NULL_MODEL_CHECK(model);
    if (n > 0 && direction == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_directional_added_mass: direction is NULL");
    return store_added_mass(model, added_mass, direction, n,
                            "set_directional_added_mass");
}

canopy_status canopy_model_set_triangle_added_mass(canopy_model *model,
                                                  const double *added_mass,
                                                  int nt)
{
    NULL_MODEL_CHECK(model);
    canopy_status st = count_check(model, added_mass, nt, model->tris.count,
                                   "set_triangle_added_mass");
    if (st != CANOPY_OK) return st;
    for (int t = 0; t < nt; ++t)
        if (!(added_mass[t] >= 0.0) || !isfinite(added_mass[t]))
            return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                               "set_triangle_added_mass: triangle %d value "
                               "%g must be finite and >= 0", t,
                               added_mass[t]);
    int any = 0;
    for (int t = 0; t < nt; ++t) {
        model->tris.added_mass[t] = added_mass[t];
        if (added_mass[t] > 0.0) any = 1;
    }
    model->triangle_added_mass = any;
    model->prepared = 0; /* masses changed: re-validate */
    canopy_clear_message(model);
    return CANOPY_OK;
}

/* --- integration controls ------------------------------------------------ */

canopy_status canopy_model_set_integrator(canopy_model *model, const char *name)
{
    NULL_MODEL_CHECK(model);
    const canopy_integrator *it = name ? canopy_integrator_find(name) : NULL;
    if (it == NULL) {
        char list[256] = "";
        size_t used = 0;
        for (int i = 0; i < canopy_integrator_count(); ++i) {
            const char *nm = canopy_integrator_name(i);
            size_t len = strlen(nm);
            if (used + len + 3 >= sizeof list) break;
            if (i) { memcpy(list + used, ", ", 2); used += 2; }
            memcpy(list + used, nm, len);
            used += len;
            list[used] = '\0';
        }
        return canopy_fail(model, CANOPY_ERR_UNKNOWN_NAME,
                           "integrator '%s' is not known; valid names: %s",
                           name ? name : "(null)", list);
    }
    model->integrator = it;
    model->prepared = 0; /* re-validate (directional added mass) */
    canopy_clear_message(model);
    return CANOPY_OK;
}

const char *canopy_model_integrator(const canopy_model *model)
{
    return model ? model->integrator->name : "";
}

canopy_status canopy_model_set_max_omega_dt(canopy_model *model, double value)
{
    NULL_MODEL_CHECK(model);
    if (!(value > 0.0) || !isfinite(value))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_max_omega_dt: %g must be finite and > 0",
                           value);
    model->max_omega_dt = value;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_hht_alpha(canopy_model *model, double alpha)
{
    NULL_MODEL_CHECK(model);
    if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_hht_alpha: %g outside [-1/3, 0]", alpha);
    model->hht_alpha = alpha;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_implicit_controls(canopy_model *model,
                                                 double tolerance,
                                                 int max_iterations)
{
    NULL_MODEL_CHECK(model);
    if (!(tolerance > 0.0) || !isfinite(tolerance) || max_iterations < 1 ||
        max_iterations > CANOPY_MAX_NEWTON_ITERATIONS)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_implicit_controls: tolerance %g must be "
                           "finite and > 0 and max_iterations %d in [1, %d]",
                           tolerance, max_iterations,
                           CANOPY_MAX_NEWTON_ITERATIONS);
    model->implicit_tol = tolerance;
    model->implicit_max_iter = max_iterations;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_bending_damping(canopy_model *model,
                                               double rate)
{
    NULL_MODEL_CHECK(model);
    if (!(rate >= 0.0) || !isfinite(rate))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_bending_damping: rate %g must be finite and "
                           ">= 0", rate);
    model->bending_damping = rate;
    model->prepared = 0; /* the hinges are built (or dropped) by prepare */
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_bending_damping_implicit(canopy_model *model,
                                                        int implicit)
{
    NULL_MODEL_CHECK(model);
    model->bending_implicit = implicit ? 1 : 0;
    model->prepared = 0; /* the filter needs it (bending.c) */
    canopy_clear_message(model);
    return CANOPY_OK;
}

int canopy_model_bending_damping_implicit(const canopy_model *model)
{
    return model ? model->bending_implicit : 0;
}

canopy_status canopy_model_set_bending_damping_filter(canopy_model *model,
                                                      int high_pass)
{
    NULL_MODEL_CHECK(model);
    model->bending_filter = high_pass ? 1 : 0;
    model->prepared = 0; /* the stencils are built (or dropped) by prepare */
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_fabric_compression(canopy_model *model,
                                                  double ratio)
{
    NULL_MODEL_CHECK(model);
    if (!(ratio >= 0.0 && ratio <= 1.0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_fabric_compression: ratio %g must be in "
                           "[0, 1]", ratio);
    model->fabric_compression = ratio;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_set_pressure_frozen(canopy_model *model,
                                               int frozen)
{
    NULL_MODEL_CHECK(model);
    model->pressure_frozen = frozen ? 1 : 0;
    canopy_clear_message(model);
    return CANOPY_OK;
}

int canopy_model_pressure_frozen(const canopy_model *model)
{
    return model ? model->pressure_frozen : 0;
}

canopy_status canopy_model_set_speed_limit(canopy_model *model, double vmax)
{
    NULL_MODEL_CHECK(model);
    if (!(vmax > 0.0))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "set_speed_limit: %g must be > 0", vmax);
    model->speed_limit = vmax;
    canopy_clear_message(model);
    return CANOPY_OK;
}

size_t canopy_model_memory_bytes(const canopy_model *model)
{
    if (model == NULL) return 0;
    size_t b = sizeof *model;
    b += (size_t)model->nodes.capacity *
         (3 * sizeof(double) * 4 + 2 * sizeof(double) + 2);
    b += (size_t)model->springs.capacity *
         (2 * sizeof(int) + 6 * sizeof(double) + 2);
    b += (size_t)model->tris.capacity * (3 * sizeof(int) + 2 * sizeof(double));
    b += (4 * sizeof(int) + 13 * sizeof(double)) * (size_t)model->hinges.count;
    const canopy_hinge_filter *f = &model->hinges.filter;
    if (f->start) {
        const size_t n = (size_t)model->nodes.count;
        const size_t entries = (size_t)f->start[n];
        const size_t largest = (size_t)f->largest;
        b += (2 * n + 1 + 4 * largest) * sizeof(int) +
             (9 * n + 12 * largest) * sizeof(double) +
             entries * (sizeof(int) + sizeof(double));
    }
    b += model->stepper.bytes;
    b += canopy_hinge_solver_bytes(model->hinge_solver);
    b += canopy_vectors_bytes(&model->bound_sums);
    b += canopy_vectors_bytes(&model->pressure_step);
    b += 9 * sizeof(double) * (size_t)model->checkpoint.count;
    b += 9 * sizeof(double) * (size_t)model->rollback.count;
    return b;
}
