/* integrator_verlet.c — velocity Verlet, order 2 (seed 002 eqs. 37–40). */
#include "integrator.h"

typedef struct verlet_state {
    canopy_vectors store;
    double *a, *vp;     /* acceleration; velocity estimate at t_{n+1} */
} verlet_state;

static void *alloc(int nodes, size_t *bytes)
{
    verlet_state *s = canopy_vectors_state_alloc(sizeof *s, 2, nodes, bytes);
    if (s != NULL) {
        s->a = canopy_vectors_at(&s->store, 0);
        s->vp = canopy_vectors_at(&s->store, 1);
    }
    return s;
}

/* a_n is evaluated afresh from (x_n, v_n) at the start of each step rather
 * than carried over: loads change between fluid steps, and a step then
 * depends on the state (t, x, v) alone, which makes checkpoints and restarts
 * exact. Dashpots make the force depend on velocity; evaluating eq. 39 with
 * the half-step velocity would cut the method to first order, so it uses the
 * second-order estimate v_n + dt a_n of v_{n+1} instead. */
static canopy_status step(void *state, canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    verlet_state *s = state;
    double *x = m->nodes.x, *v = m->nodes.v, *a = s->a, *vp = s->vp;
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, v, dt, a, vp);        /* velocity estimate at t_{n+1} */
    canopy_axpy(n, v, 0.5 * dt, a, v);   /* eq. 37: v_{n+1/2} */
    canopy_axpy(n, x, dt, v, x);         /* eq. 38 */
    canopy_accelerations(m, x, vp, a);   /* eq. 39 */
    canopy_axpy(n, v, 0.5 * dt, a, v);   /* eq. 40 */
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_verlet = {
    "verlet", 2, 0, 0, alloc, step, canopy_vectors_state_free, 0};
