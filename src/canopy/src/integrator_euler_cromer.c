/* integrator_euler_cromer.c — Euler–Cromer (symplectic Euler), order 1 (seed 002 eqs. 15–16). */
#include "integrator.h"

/* The step's own state: the acceleration a_n. */
typedef struct euler_cromer_state {
    canopy_vectors store;
    double *a;
} euler_cromer_state;

static void *alloc(int nodes, size_t *bytes)
{
    euler_cromer_state *s =
        canopy_vectors_state_alloc(sizeof *s, 1, nodes, bytes);
    if (s != NULL) s->a = canopy_vectors_at(&s->store, 0);
    return s;
}

static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    euler_cromer_state *s = state;
    double *x = m->nodes.x, *v = m->nodes.v, *a = s->a;
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, v, dt, a, v);    /* v_{n+1} = v_n + dt a_n   */
    canopy_axpy(n, x, dt, v, x);    /* x_{n+1} = x_n + dt v_{n+1} */
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_euler_cromer = {
    "euler-cromer", 1, 0, 0, alloc, step, canopy_vectors_state_free, 0};
