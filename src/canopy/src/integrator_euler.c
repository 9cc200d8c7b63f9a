/* integrator_euler.c — explicit (forward) Euler, order 1 (seed 002 eq. 12, seed 000 eq. 4.5). */
#include "integrator.h"

static canopy_status step(canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    double *x = m->nodes.x, *v = m->nodes.v, *a = m->work[0];
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, x, dt, v, x);
    canopy_axpy(n, v, dt, a, v);
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_euler = {"euler", 1, 0, 0, step};
