/* integrator.h — the time-integrator interface: one small constant vtable per method. */
#ifndef CANOPY_INTEGRATOR_H
#define CANOPY_INTEGRATOR_H

#include "model_internal.h"

/* One step of size dt from (model->t, x, v) in place. The caller saves the
 * state first and restores it if the step fails or diverges, so a step may
 * leave x and v half-updated on failure. Work arrays: model->work[0..15],
 * each 3*n doubles. */
typedef canopy_status (*canopy_step_fn)(canopy_model *model, double dt);

struct canopy_integrator {
    const char *name;
    int order;          /* formal order of accuracy */
    int implicit;       /* 1: needs no stability bound */
    int carries_acceleration; /* 1: keeps nodes.acc valid between steps */
    canopy_step_fn step;
};

extern const canopy_integrator canopy_integrator_euler;
extern const canopy_integrator canopy_integrator_euler_cromer;
extern const canopy_integrator canopy_integrator_euler_richardson;
extern const canopy_integrator canopy_integrator_heun;
extern const canopy_integrator canopy_integrator_verlet;
extern const canopy_integrator canopy_integrator_rk4;
extern const canopy_integrator canopy_integrator_newmark;
extern const canopy_integrator canopy_integrator_hht;
extern const canopy_integrator canopy_integrator_kang;

/* Look up by name; NULL if unknown. */
const canopy_integrator *canopy_integrator_find(const char *name);

/* z = x + s * y over 3*n entries (z may alias x). */
void canopy_axpy(int n, const double *x, double s, const double *y, double *z);

#endif /* CANOPY_INTEGRATOR_H */
