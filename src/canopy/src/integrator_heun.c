/* integrator_heun.c — improved Euler (Heun's predictor–corrector), order 2 (seed 002 eqs. 23–24, seed 000 eq. 4.6). */
#include "integrator.h"

/* The step's own state: the accelerations at both ends and the predictor. */
typedef struct heun_state {
    canopy_vectors store;
    double *a1, *xp, *vp, *a2;
} heun_state;

static void *alloc(int nodes, size_t *bytes)
{
    heun_state *s = canopy_vectors_state_alloc(sizeof *s, 4, nodes, bytes);
    if (s != NULL) {
        s->a1 = canopy_vectors_at(&s->store, 0);
        s->xp = canopy_vectors_at(&s->store, 1);
        s->vp = canopy_vectors_at(&s->store, 2);
        s->a2 = canopy_vectors_at(&s->store, 3);
    }
    return s;
}

static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    heun_state *s = state;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *a1 = s->a1, *xp = s->xp, *vp = s->vp, *a2 = s->a2;
    canopy_accelerations(m, x, v, a1);
    canopy_axpy(n, x, dt, v, xp);          /* Euler predictor (eq. 23) */
    canopy_axpy(n, v, dt, a1, vp);
    canopy_accelerations(m, xp, vp, a2);
    for (int i = 0; i < 3 * n; ++i) {      /* trapezoidal corrector (eq. 24) */
        x[i] += 0.5 * dt * (v[i] + vp[i]);
        v[i] += 0.5 * dt * (a1[i] + a2[i]);
    }
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_heun = {
    "heun", 2, 0, 0, alloc, step, canopy_vectors_state_free, 0};
