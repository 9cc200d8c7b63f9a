/* integrator_verlet.c — velocity Verlet, order 2 (seed 002 eqs. 37–40). */
#include "integrator.h"

/* a_n is evaluated afresh from (x_n, v_n) at the start of each step rather
 * than carried over: loads change between fluid steps, and a step then
 * depends on the state (t, x, v) alone, which makes checkpoints and restarts
 * exact. Dashpots make the force depend on velocity; evaluating eq. 39 with
 * the half-step velocity would cut the method to first order, so it uses the
 * second-order estimate v_n + dt a_n of v_{n+1} instead. */
static canopy_status step(canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    double *x = m->nodes.x, *v = m->nodes.v, *a = m->work[0],
           *vp = m->work[1];
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, v, dt, a, vp);        /* velocity estimate at t_{n+1} */
    canopy_axpy(n, v, 0.5 * dt, a, v);   /* eq. 37: v_{n+1/2} */
    canopy_axpy(n, x, dt, v, x);         /* eq. 38 */
    canopy_accelerations(m, x, vp, a);   /* eq. 39 */
    canopy_axpy(n, v, 0.5 * dt, a, v);   /* eq. 40 */
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_verlet = {"verlet", 2, 0, 0, step};
