/* integrator_euler_richardson.c — Euler–Richardson (explicit midpoint), order 2 (seed 002 eqs. 17–22). */
#include "integrator.h"

static canopy_status step(canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *a = m->work[0], *xm = m->work[1], *vm = m->work[2];
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, v, 0.5 * dt, a, vm);   /* eq. 18 */
    canopy_axpy(n, x, 0.5 * dt, v, xm);   /* eq. 19 */
    canopy_accelerations(m, xm, vm, a);   /* eq. 20 */
    canopy_axpy(n, v, dt, a, v);          /* eq. 21 */
    canopy_axpy(n, x, dt, vm, x);         /* eq. 22 */
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_euler_richardson = {
    "euler-richardson", 2, 0, 0, step};
