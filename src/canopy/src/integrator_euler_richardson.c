/* integrator_euler_richardson.c — Euler–Richardson (explicit midpoint), order 2 (seed 002 eqs. 17–22). */
#include "integrator.h"

/* The step's own state: the acceleration and the midpoint state. */
typedef struct euler_richardson_state {
    canopy_vectors store;
    double *a, *xm, *vm;
} euler_richardson_state;

static void *alloc(int nodes, size_t *bytes)
{
    euler_richardson_state *s =
        canopy_vectors_state_alloc(sizeof *s, 3, nodes, bytes);
    if (s != NULL) {
        s->a = canopy_vectors_at(&s->store, 0);
        s->xm = canopy_vectors_at(&s->store, 1);
        s->vm = canopy_vectors_at(&s->store, 2);
    }
    return s;
}

static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    euler_richardson_state *s = state;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *a = s->a, *xm = s->xm, *vm = s->vm;
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, v, 0.5 * dt, a, vm);   /* eq. 18 */
    canopy_axpy(n, x, 0.5 * dt, v, xm);   /* eq. 19 */
    canopy_accelerations(m, xm, vm, a);   /* eq. 20 */
    canopy_axpy(n, v, dt, a, v);          /* eq. 21 */
    canopy_axpy(n, x, dt, vm, x);         /* eq. 22 */
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_euler_richardson = {
    "euler-richardson", 2, 0, 0, alloc, step, canopy_vectors_state_free, 0};
