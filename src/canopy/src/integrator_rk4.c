/* integrator_rk4.c — classic fourth-order Runge–Kutta (seed 000 ch. 4, seed 002 eqs. 42–51). */
#include "integrator.h"

typedef struct rk4_state {
    canopy_vectors store;
    double *xs, *vs, *a;   /* the stage's state and acceleration */
    double *sx, *sv;       /* weighted slope sums */
} rk4_state;

static void *alloc(int nodes, size_t *bytes)
{
    rk4_state *s = canopy_vectors_state_alloc(sizeof *s, 5, nodes, bytes);
    if (s != NULL) {
        s->xs = canopy_vectors_at(&s->store, 0);
        s->vs = canopy_vectors_at(&s->store, 1);
        s->a = canopy_vectors_at(&s->store, 2);
        s->sx = canopy_vectors_at(&s->store, 3);
        s->sv = canopy_vectors_at(&s->store, 4);
    }
    return s;
}

static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count, N = 3 * n;
    const rk4_state *s = state;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *xs = s->xs, *vs = s->vs, *a = s->a, *sx = s->sx, *sv = s->sv;

    canopy_accelerations(m, x, v, a);            /* K1 = (v, a) */
    for (int i = 0; i < N; ++i) {
        sx[i] = v[i];
        sv[i] = a[i];
        xs[i] = x[i] + 0.5 * dt * v[i];
        vs[i] = v[i] + 0.5 * dt * a[i];
    }
    canopy_accelerations(m, xs, vs, a);          /* K2 = (vs, a) */
    for (int i = 0; i < N; ++i) {
        const double vk = vs[i];
        sx[i] += 2.0 * vk;
        sv[i] += 2.0 * a[i];
        xs[i] = x[i] + 0.5 * dt * vk;
        vs[i] = v[i] + 0.5 * dt * a[i];
    }
    canopy_accelerations(m, xs, vs, a);          /* K3 */
    for (int i = 0; i < N; ++i) {
        const double vk = vs[i];
        sx[i] += 2.0 * vk;
        sv[i] += 2.0 * a[i];
        xs[i] = x[i] + dt * vk;
        vs[i] = v[i] + dt * a[i];
    }
    canopy_accelerations(m, xs, vs, a);          /* K4 */
    for (int i = 0; i < N; ++i) {
        x[i] += dt / 6.0 * (sx[i] + vs[i]);
        v[i] += dt / 6.0 * (sv[i] + a[i]);
    }
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_rk4 = {
    "rk4", 4, 0, 0, alloc, step, canopy_vectors_state_free, 0};
