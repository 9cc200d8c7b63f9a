/* integrator_rk4.c — classic fourth-order Runge–Kutta (seed 000 ch. 4, seed 002 eqs. 42–51). */
#include "integrator.h"

static canopy_status step(canopy_model *m, double dt)
{
    const int n = m->nodes.count, N = 3 * n;
    double *x = m->nodes.x, *v = m->nodes.v;
    double *xs = m->work[0], *vs = m->work[1], *a = m->work[2];
    double *sx = m->work[3], *sv = m->work[4];   /* weighted slope sums */

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

const canopy_integrator canopy_integrator_rk4 = {"rk4", 4, 0, 0, step};
