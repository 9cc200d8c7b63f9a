/* integrator_euler.c — explicit (forward) Euler, order 1 (seed 002 eq. 12, seed 000 eq. 4.5). */
#include "integrator.h"

/* The step's own state: the acceleration a_n. */
typedef struct euler_state {
    canopy_vectors store;
    double *a;
} euler_state;

static void *alloc(int nodes, size_t *bytes)
{
    euler_state *s = canopy_vectors_state_alloc(sizeof *s, 1, nodes, bytes);
    if (s != NULL) s->a = canopy_vectors_at(&s->store, 0);
    return s;
}

static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    euler_state *s = state;
    double *x = m->nodes.x, *v = m->nodes.v, *a = s->a;
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, x, dt, v, x);
    canopy_axpy(n, v, dt, a, v);
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_euler = {
    "euler", 1, 0, 0, alloc, step, canopy_vectors_state_free, 0};
