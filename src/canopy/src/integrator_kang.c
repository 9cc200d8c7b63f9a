/* integrator_kang.c — Kang et al.'s fast approximate implicit update, order 1 (seed 002 eqs. 52–57). */
#include "integrator.h"

/* With S_i = sum_j k_ij over the springs at node i and F the total force at
 * (x_n, v_n) (springs, the model's own dashpots in place of seed eq. 53,
 * gravity, pressure, loads):
 *   dv0_j = F_j dt / (m_j + dt^2 S_j)                       (a Jacobi guess)
 *   dv_i  = (F_i dt + dt^2 sum_j k_ij dv0_j) / (m_i + dt^2 S_i)   (eq. 55)
 *   v_{n+1} = v_n + dv,  x_{n+1} = x_n + dt v_{n+1}               (eqs. 56-57)
 * i.e. one Jacobi sweep of backward Euler's linear system. */
typedef struct kang_state {
    canopy_vectors store;
    double *F;          /* forces at (x_n, v_n) */
    double *S;          /* per-node stiffness sums (n of its 3n doubles) */
    double *dv0, *sum;  /* the Jacobi guess; sum_j k_ij dv0_j */
} kang_state;

static void *alloc(int nodes, size_t *bytes)
{
    kang_state *s = canopy_vectors_state_alloc(sizeof *s, 4, nodes, bytes);
    if (s != NULL) {
        s->F = canopy_vectors_at(&s->store, 0);
        s->S = canopy_vectors_at(&s->store, 1);
        s->dv0 = canopy_vectors_at(&s->store, 2);
        s->sum = canopy_vectors_at(&s->store, 3);
    }
    return s;
}

static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    const kang_state *st = state;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *F = st->F, *S = st->S, *dv0 = st->dv0, *sum = st->sum;
    canopy_forces(m, x, v, F);
    for (int i = 0; i < n; ++i) S[i] = 0.0;
    for (int s = 0; s < m->springs.count; ++s) {
        S[m->springs.ends[2 * s]] += m->springs.k[s];
        S[m->springs.ends[2 * s + 1]] += m->springs.k[s];
    }
    const double dt2 = dt * dt;
    for (int i = 0; i < n; ++i) {
        const double inv = m->nodes.fixed[i]
                               ? 0.0
                               : dt / (canopy_effective_mass(m, i) + dt2 * S[i]);
        for (int d = 0; d < 3; ++d) {
            dv0[3 * i + d] = F[3 * i + d] * inv;
            sum[3 * i + d] = 0.0;
        }
    }
    for (int s = 0; s < m->springs.count; ++s) {
        const int i = m->springs.ends[2 * s], j = m->springs.ends[2 * s + 1];
        const double k = m->springs.k[s];
        for (int d = 0; d < 3; ++d) {
            sum[3 * i + d] += k * dv0[3 * j + d];
            sum[3 * j + d] += k * dv0[3 * i + d];
        }
    }
    for (int i = 0; i < n; ++i) {
        if (!m->nodes.fixed[i]) {
            const double den = canopy_effective_mass(m, i) + dt2 * S[i];
            for (int d = 0; d < 3; ++d)
                v[3 * i + d] += (F[3 * i + d] * dt + dt2 * sum[3 * i + d]) / den;
        }
        for (int d = 0; d < 3; ++d) x[3 * i + d] += dt * v[3 * i + d];
    }
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_kang = {
    "kang", 1, 1, 0, alloc, step, canopy_vectors_state_free, 0};
