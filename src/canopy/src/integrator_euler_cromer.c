/* integrator_euler_cromer.c — Euler–Cromer (symplectic Euler), order 1 (seed 002 eqs. 15–16). */
#include "integrator.h"

static canopy_status step(canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    double *x = m->nodes.x, *v = m->nodes.v, *a = m->work[0];
    canopy_accelerations(m, x, v, a);
    canopy_axpy(n, v, dt, a, v);    /* v_{n+1} = v_n + dt a_n   */
    canopy_axpy(n, x, dt, v, x);    /* x_{n+1} = x_n + dt v_{n+1} */
    return CANOPY_OK;
}

const canopy_integrator canopy_integrator_euler_cromer = {"euler-cromer", 1, 0,
                                                          0, step};
