/* bending_implicit.c — the hinge dashpots as a backward-Euler velocity update after each step, so that they do not limit the stable step. */
#include "model_internal.h"

#include <math.h>

/* Lie splitting: the integrator advances everything but the hinge dashpots
 * over h; then, at the new positions,
 *   (M + h C) v' = M v,   C = sum over hinges of c u u^T (bending.c),
 * backward Euler on M dv/dt = -C v. C is symmetric positive semi-definite
 * with rigid motion in its null space, so the update only dissipates
 * (v'.M v' <= v.M v), keeps linear and angular momentum (1^T C = 0) and is
 * stable for any h. Fixed nodes keep their velocity; it enters the free
 * nodes' right-hand side. Solved for the increment d = v' - v:
 *   (M_ff + h C_ff) d = -h (C v)_f
 * by conjugate gradients with the diagonal as preconditioner. M is the
 * nodes' own mass m I, without the added mass of set_(directional_)added_
 * mass: that inertia belongs to the integrator's equation, where a coupled
 * solver balances it with the step's end acceleration (the integrator's
 * carried acceleration, which this update leaves as it is), so that a
 * balanced added mass changes neither part of the step. With the high-pass
 * filter on, C is
 * P^T F C F P (bending_filter.c): still symmetric positive semi-definite,
 * with 1^T P^T = 0. */

/* Cache each hinge's modes u (12 doubles, u[4][3]) and dashpot c at x
 * (c = 0: a degenerate hinge), and the filter's weights at x. */
static void cache_modes(canopy_model *m, const double *x)
{
    for (int k = 0; k < m->hinges.count; ++k) {
        double *cache = m->hinges.modes + 13 * k;
        if (!canopy_hinge_modes(m, x, k, (double (*)[3])cache, cache + 12))
            cache[12] = 0.0;
    }
    if (m->bending_filter) canopy_hinge_filter_weights(m, x);
}

/* y += scale C w with the cached modes (canopy_hinge_apply) */
static void add_unfiltered_damping(const canopy_model *m, const double *w,
                                   double *y, double scale, int free_only)
{
    for (int k = 0; k < m->hinges.count; ++k) {
        const double *cache = m->hinges.modes + 13 * k;
        if (cache[12] != 0.0)
            canopy_hinge_apply(m, k, (const double (*)[3])cache, cache[12], w,
                               y, scale, free_only);
    }
}

/* y += scale P^T F C F P w with the filter on (bending_filter.c; F zeroes
 * the fixed nodes), else scale C w; free_only: w counts as zero at fixed
 * nodes, whose rows of y are left untouched. */
static void add_cached_damping(const canopy_model *m, const double *w,
                               double *y, double scale, int free_only)
{
    if (!m->bending_filter) {
        add_unfiltered_damping(m, w, y, scale, free_only);
        return;
    }
    const canopy_hinge_filter *f = &m->hinges.filter;
    const int n = m->nodes.count;
    double *pw = f->filtered, *cpw = f->spread;
    if (free_only) {
        for (int i = 0; i < n; ++i)
            for (int d = 0; d < 3; ++d)
                cpw[3 * i + d] = m->nodes.fixed[i] ? 0.0 : w[3 * i + d];
        canopy_hinge_filter_apply(m, cpw, pw);
    } else {
        canopy_hinge_filter_apply(m, w, pw);
    }
    /* F P w, F C F P w, P^T F C F P w: F zeroes the fixed nodes, which do
     * not move (a hinge's c counts only its free nodes' inertia) */
    for (int i = 0; i < n; ++i)
        if (m->nodes.fixed[i]) pw[3 * i] = pw[3 * i + 1] = pw[3 * i + 2] = 0.0;
    for (int k = 0; k < 3 * n; ++k) cpw[k] = 0.0;
    add_unfiltered_damping(m, pw, cpw, 1.0, 1);
    canopy_hinge_filter_apply_transpose(m, cpw, pw);
    for (int i = 0; i < n; ++i) {
        if (free_only && m->nodes.fixed[i]) continue;
        for (int d = 0; d < 3; ++d) y[3 * i + d] += scale * pw[3 * i + d];
    }
}

/* y = M w on free nodes (0 on fixed nodes). */
static void apply_mass(const canopy_model *m, const double *w, double *y)
{
    const canopy_nodes *n = &m->nodes;
    for (int i = 0; i < n->count; ++i) {
        const double mi = n->fixed[i] ? 0.0 : n->mass[i];
        for (int d = 0; d < 3; ++d) y[3 * i + d] = mi * w[3 * i + d];
    }
}

/* The diagonal of M_ff + h C_ff (1 on fixed nodes' rows). */
static void diagonal(canopy_model *m, double h, double *diag)
{
    const canopy_nodes *n = &m->nodes;
    for (int i = 0; i < n->count; ++i) {
        const double mi = n->fixed[i] ? 1.0 : n->mass[i];
        diag[3 * i] = diag[3 * i + 1] = diag[3 * i + 2] = mi;
    }
    for (int k = 0; k < m->hinges.count; ++k) {
        const double *u = m->hinges.modes + 13 * k;
        if (u[12] == 0.0) continue; /* degenerate: u not set */
        if (m->bending_filter) {
            canopy_hinge_filter_add_diagonal(m, k, (const double (*)[3])u,
                                             h * u[12], diag);
            continue;
        }
        const int *hn = m->hinges.nodes + 4 * k;
        for (int a = 0; a < 4; ++a) {
            if (n->fixed[hn[a]]) continue;
            for (int d = 0; d < 3; ++d)
                diag[3 * hn[a] + d] += h * u[12] * u[3 * a + d] * u[3 * a + d];
        }
    }
}

static double dot(int N, const double *a, const double *b)
{
    double s = 0.0;
    for (int k = 0; k < N; ++k) s += a[k] * b[k];
    return s;
}

/* The update's own workspace: six node vectors of scratch (the increment
 * d, CG's residual, preconditioned residual, direction and (M + h C) p,
 * and the diagonal). */
struct canopy_hinge_solver {
    canopy_vectors store;
    double *inc, *r, *z, *p, *Ap, *diag;
};

static canopy_hinge_solver *solver_create(int nodes)
{
    canopy_hinge_solver *s =
        canopy_vectors_state_alloc(sizeof *s, 6, nodes, NULL);
    if (s == NULL) return NULL;
    s->inc = canopy_vectors_at(&s->store, 0);
    s->r = canopy_vectors_at(&s->store, 1);
    s->z = canopy_vectors_at(&s->store, 2);
    s->p = canopy_vectors_at(&s->store, 3);
    s->Ap = canopy_vectors_at(&s->store, 4);
    s->diag = canopy_vectors_at(&s->store, 5);
    return s;
}

canopy_status canopy_hinge_solver_prepare(canopy_model *m)
{
    if (!m->bending_implicit || m->hinges.count == 0) {
        canopy_hinge_solver_destroy(&m->hinge_solver);
        return CANOPY_OK;
    }
    const int nodes = m->nodes.count;
    if (m->hinge_solver != NULL && m->hinge_solver->store.nodes == nodes)
        return CANOPY_OK;
    canopy_hinge_solver *s = solver_create(nodes);
    if (s == NULL)
        return canopy_fail(m, CANOPY_ERR_MEMORY,
                           "cannot allocate the implicit hinge dashpots' "
                           "workspace for %d nodes", nodes);
    canopy_hinge_solver_destroy(&m->hinge_solver);
    m->hinge_solver = s;
    return CANOPY_OK;
}

void canopy_hinge_solver_destroy(canopy_hinge_solver **solver)
{
    if (solver == NULL) return;
    canopy_vectors_state_free(*solver);
    *solver = NULL;
}

size_t canopy_hinge_solver_bytes(const canopy_hinge_solver *solver)
{
    return solver ? sizeof *solver + canopy_vectors_bytes(&solver->store) : 0;
}

void canopy_hinge_damping_implicit_forces(canopy_model *m, double *f)
{
    cache_modes(m, m->nodes.x);
    add_cached_damping(m, m->nodes.v, f, -1.0, 0);
}

canopy_status canopy_hinge_damping_implicit_update(canopy_model *m, double h)
{
    const int N = 3 * m->nodes.count;
    double *v = m->nodes.v;
    const canopy_hinge_solver *s = m->hinge_solver;
    double *inc = s->inc, *r = s->r, *z = s->z, *p = s->p, *Ap = s->Ap,
           *diag = s->diag;
    cache_modes(m, m->nodes.x);

    /* r = b = -h (C v) on free rows; fixed rows stay 0 throughout */
    for (int k = 0; k < N; ++k) r[k] = 0.0;
    add_cached_damping(m, v, r, -h, 0);
    for (int i = 0; i < m->nodes.count; ++i) {
        if (m->nodes.fixed[i]) r[3 * i] = r[3 * i + 1] = r[3 * i + 2] = 0.0;
        canopy_guide_project(m, i, r + 3 * i);   /* guided: along the guide */
    }
    const double b_norm = sqrt(dot(N, r, r));
    if (b_norm == 0.0) return CANOPY_OK;

    diagonal(m, h, diag);
    for (int k = 0; k < N; ++k) {
        inc[k] = 0.0;
        z[k] = r[k] / diag[k];
    }
    for (int i = 0; i < m->nodes.count; ++i) canopy_guide_project(m, i, z + 3 * i);
    for (int k = 0; k < N; ++k) p[k] = z[k];
    double rz = dot(N, r, z);
    const double tol = 1e-10 * b_norm;
    const int max_it = N < 2000 ? N + 20 : 2000 + N / 10;
    double r_norm = b_norm;
    for (int it = 1; it <= max_it; ++it) {
        apply_mass(m, p, Ap);
        add_cached_damping(m, p, Ap, h, 1);
        for (int i = 0; i < m->nodes.count; ++i)
            canopy_guide_project(m, i, Ap + 3 * i);
        const double pAp = dot(N, p, Ap);
        if (!(pAp > 0.0)) break;
        const double alpha = rz / pAp;
        for (int k = 0; k < N; ++k) {
            inc[k] += alpha * p[k];
            r[k] -= alpha * Ap[k];
        }
        r_norm = sqrt(dot(N, r, r));
        if (r_norm <= tol) {
            for (int k = 0; k < N; ++k) v[k] += inc[k];
            return CANOPY_OK;
        }
        for (int k = 0; k < N; ++k) z[k] = r[k] / diag[k];
        for (int i = 0; i < m->nodes.count; ++i)
            canopy_guide_project(m, i, z + 3 * i);
        const double rz_new = dot(N, r, z);
        const double beta = rz_new / rz;
        rz = rz_new;
        for (int k = 0; k < N; ++k) p[k] = z[k] + beta * p[k];
    }
    return canopy_fail(m, CANOPY_ERR_DIVERGED,
                       "implicit bending damping (step %g): conjugate "
                       "gradients stopped at a residual of %g of the "
                       "right-hand side", h, r_norm / b_norm);
}
