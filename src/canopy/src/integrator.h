/* integrator.h — the time-integrator interface: one small constant vtable per method. */
#ifndef CANOPY_INTEGRATOR_H
#define CANOPY_INTEGRATOR_H

#include "model_internal.h"
#include "vectors.h"

/* Each method owns its state (GSL's ode-initval2 steppers): `alloc` makes
 * the workspace for a model of `nodes` nodes (NULL when out of memory;
 * *bytes receives its size), `free` releases it (NULL: no-op). The model
 * keeps one state, for its integrator and node count (canopy_stepper,
 * made by canopy_stepper_prepare). The workspaces hold scratch only: what a
 * method carries from one step to the next (HHT's acceleration) is model
 * state (nodes.acc), which checkpoints, rollback and restart files keep. */
typedef void *(*canopy_state_alloc_fn)(int nodes, size_t *bytes);
typedef void (*canopy_state_free_fn)(void *state);

/* One step of size dt from (model->t, x, v) in place, with the method's own
 * state. The caller saves the state first and restores it if the step fails
 * or diverges, so a step may leave x and v half-updated on failure. */
typedef canopy_status (*canopy_step_fn)(void *state, canopy_model *model,
                                        double dt);

struct canopy_integrator {
    const char *name;
    int order;          /* formal order of accuracy */
    int implicit;       /* 1: needs no stability bound */
    int carries_acceleration; /* 1: keeps nodes.acc valid between steps */
    canopy_state_alloc_fn alloc;
    canopy_step_fn step;
    canopy_state_free_fn free;
    int implicit_damping; /* 1: solves the spring dashpots with the stiffness,
                           * so they leave the frequency bound */
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

/* Give the model a state for its integrator at its node count, unless it
 * has one already; on failure CANOPY_ERR_MEMORY with the handle's message,
 * and the model keeps the state it had. */
canopy_status canopy_stepper_prepare(canopy_model *model);
/* Release the state (the stepper then holds none). */
void canopy_stepper_free(canopy_stepper *stepper);

/* Look up by name; NULL if unknown. */
const canopy_integrator *canopy_integrator_find(const char *name);

/* z = x + s * y over 3*n entries (z may alias x). */
void canopy_axpy(int n, const double *x, double s, const double *y, double *z);

#endif /* CANOPY_INTEGRATOR_H */
