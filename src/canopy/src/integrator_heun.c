/* integrator_heun.c — improved Euler (Heun's predictor–corrector), order 2 (seed 002 eqs. 23–24, seed 000 eq. 4.6). */
#include "integrator.h"

static canopy_status step(canopy_model *m, double dt)
{
    const int n = m->nodes.count;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *a1 = m->work[0], *xp = m->work[1], *vp = m->work[2],
           *a2 = m->work[3];
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

const canopy_integrator canopy_integrator_heun = {"heun", 2, 0, 0, step};
