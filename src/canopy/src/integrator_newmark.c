/* integrator_newmark.c — implicit Newmark-beta (average acceleration) and HHT-alpha, Newton with matrix-free CG. */
#include "integrator.h"

#include <float.h>
#include <math.h>

/* HHT-alpha (Hilber, Hughes & Taylor 1977; seed 002 eq. 41) with
 * alpha in [-1/3, 0], gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4:
 *   M a_{n+1} = (1 + alpha) F(x_{n+1}, v_{n+1}) - alpha F(x_n, v_n),
 *   x_{n+1} = x_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_{n+1}),
 *   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})   (seed 002 eqs. 25-26).
 * alpha = 0 is Newmark's average-acceleration rule (beta 1/4, gamma 1/2).
 * M is the nodes' inertia, including a directional added mass
 * m_i I + m_a d d^T and the triangles' consistent added mass (inertia.c).
 * The unknown dx = x_{n+1} - x_n is found by Newton's method on the
 * residual above; each Newton correction solves
 *   [M / (beta dt^2) + (1 + alpha)(K + gamma / (beta dt) C)] delta = -R
 * with Jacobi-preconditioned conjugate gradients, K the tangent stiffness
 * (compressive geometric terms dropped, so the matrix stays SPD: a
 * quasi-Newton method whose fixed point is still the exact residual's). */

typedef struct hht_coeffs {
    double alpha, beta, gamma, dt;
} hht_coeffs;

/* The conjugate-gradient solver's vectors: residual, direction, J p, the
 * preconditioned residual, the tangent's scratch and M p. */
typedef struct cg_vectors {
    double *r, *p, *Ap, *z, *tmp, *Mp;
} cg_vectors;

/* Newmark's and HHT's own state, 17 node vectors of scratch (the carried
 * acceleration is model state, nodes.acc): the step's known a_n and F_n;
 * the trial x1, v1, a1, their forces F1 and residual R; the displacement dx,
 * the Newton correction delta and the Jacobi diagonal; M a1 (and M's
 * diagonal before the Newton iterations); the CG vectors. */
typedef struct hht_workspace {
    canopy_vectors store;
    double *an, *Fn, *x1, *v1, *a1, *F1, *R, *dx, *delta, *diag, *Ma;
    cg_vectors cg;
} hht_workspace;

static void *hht_alloc(int nodes, size_t *bytes)
{
    hht_workspace *w = canopy_vectors_state_alloc(sizeof *w, 17, nodes, bytes);
    if (w == NULL) return NULL;
    double **slot[17] = {&w->an, &w->Fn,    &w->x1,   &w->v1,   &w->a1,
                         &w->F1, &w->R,     &w->dx,   &w->delta, &w->diag,
                         &w->Ma, &w->cg.r, &w->cg.p, &w->cg.Ap, &w->cg.z,
                         &w->cg.tmp, &w->cg.Mp};
    for (int k = 0; k < 17; ++k) *slot[k] = canopy_vectors_at(&w->store, k);
    return w;
}

static double dot_free(const canopy_model *m, const double *a, const double *b)
{
    double s = 0.0;
    for (int i = 0; i < m->nodes.count; ++i) {
        if (m->nodes.fixed[i]) continue;
        s += a[3 * i] * b[3 * i] + a[3 * i + 1] * b[3 * i + 1] +
             a[3 * i + 2] * b[3 * i + 2];
    }
    return s;
}

/* y = J u at positions x, velocities v. tmp, mu: scratch. */
static void jacobian_apply(const canopy_model *m, const hht_coeffs *c,
                           const double *x, const double *v, const double *u,
                           double *y, double *tmp, double *mu)
{
    const int n = m->nodes.count;
    canopy_tangent_stiffness(m, x, v, u, y, 1);
    canopy_tangent_damping(m, x, v, u, tmp);
    canopy_inertia_apply_all(m, u, mu);
    const double cd = c->gamma / (c->beta * c->dt);
    const double cm = 1.0 / (c->beta * c->dt * c->dt);
    for (int i = 0; i < n; ++i) {
        if (m->nodes.fixed[i]) {
            y[3 * i] = y[3 * i + 1] = y[3 * i + 2] = 0.0;
            continue;
        }
        for (int d = 0; d < 3; ++d) {
            const int k = 3 * i + d;
            y[k] = cm * mu[k] + (1.0 + c->alpha) * (y[k] + cd * tmp[k]);
        }
        canopy_guide_project(m, i, y + 3 * i);
    }
}

/* z = P (r / diag): the Jacobi step, kept on the guided nodes' guides. */
static void precondition(const canopy_model *m, const double *r,
                         const double *diag, double *z)
{
    for (int k = 0; k < 3 * m->nodes.count; ++k) z[k] = r[k] / diag[k];
    for (int i = 0; i < m->nodes.count; ++i) canopy_guide_project(m, i, z + 3 * i);
}

/* y = A u for the operator conjugate gradients solve with; ctx: what A
 * needs. */
typedef void (*cg_operator)(const canopy_model *m, const void *ctx,
                            const double *u, double *y);

/* Solve A x = rhs by Jacobi-preconditioned CG (diag: A's diagonal) to
 * relative tolerance rtol, over the free nodes and along the guided ones'
 * guides; rhs must not be one of cg's r, p, Ap or z. Returns the
 * iterations used, or -1 if not converged. */
static int pcg(const canopy_model *m, cg_operator apply, const void *ctx,
               const cg_vectors *cg, const double *rhs, double *x,
               const double *diag, double rtol)
{
    const int N = 3 * m->nodes.count;
    double *r = cg->r, *p = cg->p, *Ap = cg->Ap, *z = cg->z;
    precondition(m, rhs, diag, z);
    for (int k = 0; k < N; ++k) {
        x[k] = 0.0;
        r[k] = rhs[k];
        p[k] = z[k];
    }
    const double r0 = sqrt(dot_free(m, r, r));
    if (r0 == 0.0) return 0;
    double rz = dot_free(m, r, z);
    const int max_it = N < 2000 ? N + 20 : 2000 + N / 10;
    for (int it = 1; it <= max_it; ++it) {
        apply(m, ctx, p, Ap);
        const double pAp = dot_free(m, p, Ap);
        if (!(pAp > 0.0)) return -1;
        const double a = rz / pAp;
        for (int k = 0; k < N; ++k) {
            x[k] += a * p[k];
            r[k] -= a * Ap[k];
        }
        if (sqrt(dot_free(m, r, r)) <= rtol * r0) return it;
        precondition(m, r, diag, z);
        const double rz_new = dot_free(m, r, z);
        const double b = rz_new / rz;
        rz = rz_new;
        for (int k = 0; k < N; ++k) p[k] = z[k] + b * p[k];
    }
    return -1;
}

/* The Newton correction's operator J at positions x, velocities v. */
typedef struct jacobian_context {
    const hht_coeffs *c;
    const double *x, *v;
    double *tmp, *Mp; /* scratch */
} jacobian_context;

static void jacobian_operator(const canopy_model *m, const void *ctx,
                              const double *u, double *y)
{
    const jacobian_context *j = ctx;
    jacobian_apply(m, j->c, j->x, j->v, u, y, j->tmp, j->Mp);
}

/* Solve J delta = rhs to relative tolerance rtol. Returns the iterations
 * used, or -1 if not converged. */
static int cg_solve(canopy_model *m, const hht_coeffs *c, const cg_vectors *cg,
                    const double *x, const double *v, const double *rhs,
                    double *delta, const double *diag, double rtol)
{
    const jacobian_context j = {c, x, v, cg->tmp, cg->Mp};
    return pcg(m, jacobian_operator, &j, cg, rhs, delta, diag, rtol);
}

/* y = M u, the fixed nodes' rows zero, the guided ones' along the guide. */
static void mass_operator(const canopy_model *m, const void *ctx,
                          const double *u, double *y)
{
    (void)ctx;
    canopy_inertia_apply_all(m, u, y);
    for (int i = 0; i < m->nodes.count; ++i) {
        if (m->nodes.fixed[i]) {
            y[3 * i] = y[3 * i + 1] = y[3 * i + 2] = 0.0;
            continue;
        }
        canopy_guide_project(m, i, y + 3 * i);
    }
}

/* a <- M^-1 a on the free nodes (the guided ones along their guide), for
 * the triangles' consistent added mass, which couples the nodes: to 1e-12
 * of the right-hand side. a holds F on entry. d: scratch for the diagonal.
 * Returns the iterations used, or -1 if not converged. */
static int mass_solve(const canopy_model *m, const cg_vectors *cg, double *d,
                      double *a)
{
    const int n = m->nodes.count;
    double *rhs = cg->tmp;
    canopy_inertia_diagonal_all(m, d);
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            const int j = 3 * i + k;
            rhs[j] = m->nodes.fixed[i] ? 0.0 : a[j];
            if (m->nodes.fixed[i]) d[j] = 1.0;
        }
        canopy_guide_project(m, i, rhs + 3 * i);
    }
    return pcg(m, mass_operator, NULL, cg, rhs, a, d, 1e-12);
}

/* The step's known and trial arrays (3n doubles each). */
typedef struct hht_state {
    const double *x0, *v0, *an, *Fn;
    double *x1, *v1, *a1, *F1, *R, *Ma;
} hht_state;

/* For the displacement dx = x_{n+1} - x_n (fixed nodes: dt v_n): x1, v1,
 * a1, the forces F1 and the residual R = M a1 - (1 + alpha) F1 + alpha Fn
 * (zero at fixed nodes). Returns |R| over the free nodes; *ma_norm = |M a1|. */
static double hht_residual(const canopy_model *m, const hht_coeffs *c,
                           const hht_state *s, const double *dx,
                           double *ma_norm)
{
    const int n = m->nodes.count;
    const double dt = c->dt;
    for (int k = 0; k < 3 * n; ++k) {
        s->x1[k] = s->x0[k] + dx[k];
        s->a1[k] = (dx[k] - dt * s->v0[k] - dt * dt * (0.5 - c->beta) * s->an[k]) /
                   (c->beta * dt * dt);
        s->v1[k] = s->v0[k] + dt * ((1.0 - c->gamma) * s->an[k] + c->gamma * s->a1[k]);
    }
    for (int i = 0; i < n; ++i)
        if (m->nodes.fixed[i])
            for (int d = 0; d < 3; ++d) {
                s->a1[3 * i + d] = 0.0;
                s->v1[3 * i + d] = s->v0[3 * i + d];
            }
    canopy_forces(m, s->x1, s->v1, s->F1);
    canopy_inertia_apply_all(m, s->a1, s->Ma);
    double ma2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double *inertia = s->Ma + 3 * i;
        for (int d = 0; d < 3; ++d) {
            const int k = 3 * i + d;
            s->R[k] = m->nodes.fixed[i]
                          ? 0.0
                          : inertia[d] - (1.0 + c->alpha) * s->F1[k] + c->alpha * s->Fn[k];
            if (!m->nodes.fixed[i]) ma2 += inertia[d] * inertia[d];
        }
        /* a guided node: the guide takes the residual across it */
        canopy_guide_project(m, i, s->R + 3 * i);
    }
    *ma_norm = sqrt(ma2);
    return sqrt(dot_free(m, s->R, s->R));
}

static canopy_status hht_step(hht_workspace *ws, canopy_model *m, double dt,
                              double alpha)
{
    const int n = m->nodes.count, N = 3 * n;
    const hht_coeffs c = {alpha, 0.25 * (1.0 - alpha) * (1.0 - alpha),
                          0.5 - alpha, dt};
    const double *x0 = m->nodes.x, *v0 = m->nodes.v;
    double *an = ws->an, *Fn = ws->Fn, *F1 = ws->F1, *a1 = ws->a1,
           *v1 = ws->v1, *x1 = ws->x1, *R = ws->R, *delta = ws->delta,
           *diag = ws->diag, *dx = ws->dx;

    /* a_n: HHT's own acceleration from its previous step (it satisfies the
     * HHT equation of that step, not M a = F(x_n, v_n); recomputing it would
     * make the method first order). At start-up, and for Newmark, M^-1 F. */
    canopy_forces(m, x0, v0, Fn);
    const int carried = alpha != 0.0 && m->acc_valid;
    for (int i = 0; i < n; ++i) {
        double *a = an + 3 * i;
        for (int d = 0; d < 3; ++d)
            a[d] = m->nodes.fixed[i] ? 0.0
                 : carried          ? m->nodes.acc[3 * i + d]
                                    : Fn[3 * i + d];
        if (!m->nodes.fixed[i] && !carried && !m->triangle_added_mass)
            canopy_node_acceleration(m, i, a);
    }
    if (!carried && m->triangle_added_mass &&
        mass_solve(m, &ws->cg, ws->Ma, an) < 0)
        return canopy_fail(m, CANOPY_ERR_NOT_CONVERGED,
                           "%s: conjugate gradients did not converge on "
                           "the start-up acceleration M^-1 F",
                           alpha == 0.0 ? "newmark" : "hht");
    /* Jacobi preconditioner from per-node stiffness and dashpot sums. */
    for (int k = 0; k < N; ++k) diag[k] = 0.0;
    for (int s = 0; s < m->springs.count; ++s) {
        const int i = m->springs.ends[2 * s], j = m->springs.ends[2 * s + 1];
        const double w = m->springs.k[s] + c.gamma / (c.beta * dt) * m->springs.c[s];
        diag[3 * i] += w;
        diag[3 * j] += w;
    }
    const double *md = ws->Ma;
    canopy_inertia_diagonal_all(m, ws->Ma);
    for (int i = 0; i < n; ++i) {
        const double stiff = (1.0 + alpha) * diag[3 * i];
        for (int d = 0; d < 3; ++d)
            diag[3 * i + d] = m->nodes.fixed[i]
                                  ? 1.0
                                  : md[3 * i + d] / (c.beta * dt * dt) + stiff;
    }
    /* Predictor: dx = dt v_n + dt^2/2 a_n (fixed nodes: dt v_n, exact). */
    for (int k = 0; k < N; ++k) dx[k] = dt * v0[k] + 0.5 * dt * dt * an[k];

    double gscale = 0.0;
    for (int i = 0; i < n; ++i) {
        if (m->nodes.fixed[i]) continue;
        const double *g = m->gravity;
        gscale += m->nodes.mass[i] * m->nodes.mass[i] *
                  (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    }
    gscale = sqrt(gscale);
    const double Fn_norm = sqrt(dot_free(m, Fn, Fn));

    const hht_state st = {x0, v0, an, Fn, x1, v1, a1, F1, R, ws->Ma};
    double ma_norm = 0.0;
    double res = hht_residual(m, &c, &st, dx, &ma_norm), scale = 0.0;
    int stagnated = 0;
    for (int it = 0; it <= m->implicit_max_iter; ++it) {
        scale = ma_norm + sqrt(dot_free(m, F1, F1)) + Fn_norm + gscale;
        if (!isfinite(res)) break;
        if (res <= m->implicit_tol * scale || stagnated) {
            for (int k = 0; k < N; ++k) {
                m->nodes.x[k] = x1[k];
                m->nodes.v[k] = v1[k];
                m->nodes.acc[k] = a1[k];
            }
            m->acc_valid = 1;
            return CANOPY_OK;
        }
        if (it == m->implicit_max_iter) break;
        for (int k = 0; k < N; ++k) R[k] = -R[k];
        if (cg_solve(m, &c, &ws->cg, x1, v1, R, delta, diag, 1e-6) < 0)
            return canopy_fail(m, CANOPY_ERR_NOT_CONVERGED,
                               "%s: conjugate gradients did not converge "
                               "(dt %g, Newton iteration %d)",
                               alpha == 0.0 ? "newmark" : "hht", dt, it);
        /* Backtracking: the correction scaled by s = 1, 1/2, ... 1/64, the
         * first that lowers the residual (else the smallest). The tangent
         * leaves out the compressed springs' geometric stiffness, so on
         * crumpled cloth over a long step a full correction can overshoot. */
        const double res_old = res;
        double s_used = 0.0;
        for (double s = 1.0; s >= 1.0 / 64.0; s *= 0.5) {
            for (int k = 0; k < N; ++k) dx[k] += (s - s_used) * delta[k];
            s_used = s;
            res = hht_residual(m, &c, &st, dx, &ma_norm);
            if (res < res_old) break;
        }
        /* A correction at the round-off level of the displacement or of the
         * positions themselves means the residual cannot fall further (it
         * divides dx by beta dt^2, and forces near rest are tiny): accept
         * after this last update. */
        const double dnorm = s_used * sqrt(dot_free(m, delta, delta));
        if (dnorm <= m->implicit_tol * 1e-3 * sqrt(dot_free(m, dx, dx)) ||
            dnorm <= 4.0 * DBL_EPSILON * sqrt(dot_free(m, x1, x1)))
            stagnated = 1;
    }
    return canopy_fail(m, CANOPY_ERR_NOT_CONVERGED,
                       "%s: Newton did not converge in %d iterations (dt %g, "
                       "relative residual %g, tolerance %g)",
                       alpha == 0.0 ? "newmark" : "hht", m->implicit_max_iter,
                       dt, scale > 0.0 ? res / scale : res, m->implicit_tol);
}

static canopy_status newmark_step(void *state, canopy_model *m, double dt)
{
    return hht_step(state, m, dt, 0.0);
}

static canopy_status hht_alpha_step(void *state, canopy_model *m, double dt)
{
    return hht_step(state, m, dt, m->hht_alpha);
}

const canopy_integrator canopy_integrator_newmark = {
    "newmark", 2, 1, 0, hht_alloc, newmark_step, canopy_vectors_state_free, 1};
const canopy_integrator canopy_integrator_hht = {
    "hht", 2, 1, 1, hht_alloc, hht_alpha_step, canopy_vectors_state_free, 1};
