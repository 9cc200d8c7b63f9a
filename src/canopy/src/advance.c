/* advance.c — single steps and sub-cycled advance with stability bound, divergence check and rollback. */
#include "integrator.h"

#include <math.h>

canopy_status canopy_model_frequency_bound(canopy_model *model, double *omega)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (omega == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "frequency_bound: omega is NULL");
    canopy_status st = canopy_model_prepare(model);
    if (st != CANOPY_OK) return st;
    const canopy_nodes *n = &model->nodes;
    const canopy_springs *s = &model->springs;
    /* Per-node sums of stiffness and dashpot (x: K, y: C; z: the hinge
     * dashpots' row sums of C, bending.c). Dashpots that the integrator
     * solves implicitly (Newmark, HHT) or the split update applies
     * (implicit hinges) stay out: they bound no oscillation (a damped
     * mode's frequency is below its undamped one) and threaten no
     * stability there. */
    const int damping_bounds = !model->integrator->implicit_damping;
    double *sum = canopy_vectors_at(&model->bound_sums, 0);
    for (int i = 0; i < 3 * n->count; ++i) sum[i] = 0.0;
    for (int k = 0; k < s->count; ++k) {
        const int i = s->ends[2 * k], j = s->ends[2 * k + 1];
        sum[3 * i] += s->k[k];     sum[3 * j] += s->k[k];
        if (damping_bounds) {
            sum[3 * i + 1] += s->c[k]; sum[3 * j + 1] += s->c[k];
        }
    }
    if (!model->bending_implicit)
        canopy_hinge_damping_sums(model, n->x, sum + 2, 3);
    double lambda = 0.0;
    for (int i = 0; i < n->count; ++i) {
        if (n->fixed[i]) continue;
        const double m = canopy_effective_mass(model, i);
        const double w2 = 2.0 * sum[3 * i] / m;     /* seed 000 eq. 3.5 */
        const double rho = (2.0 * sum[3 * i + 1] + sum[3 * i + 2]) / m;
        const double L = 0.5 * rho + sqrt(0.25 * rho * rho + w2);
        if (L > lambda) lambda = L;
    }
    *omega = lambda;
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_stable_step(canopy_model *model, double *dt)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (dt == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "stable_step: dt is NULL");
    double omega;
    canopy_status st = canopy_model_frequency_bound(model, &omega);
    if (st != CANOPY_OK) return st;
    *dt = omega > 0.0 ? model->max_omega_dt / omega : INFINITY;
    return CANOPY_OK;
}

/* NaN/Inf or a node faster than the speed limit: returns the offending node,
 * or -1 when the state is sound. */
static int find_runaway(const canopy_model *m, double *speed)
{
    const canopy_nodes *n = &m->nodes;
    const double lim2 = m->speed_limit * m->speed_limit;
    for (int i = 0; i < n->count; ++i) {
        const double *x = n->x + 3 * i, *v = n->v + 3 * i;
        const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (!isfinite(x[0] + x[1] + x[2]) || !isfinite(v2) || v2 > lim2) {
            *speed = sqrt(v2);
            return i;
        }
    }
    return -1;
}

/* One step without rollback (the caller saved the state). */
static canopy_status raw_step(canopy_model *model, double dt, int substep)
{
    canopy_status st = model->integrator->step(model->stepper.state, model, dt);
    if (st != CANOPY_OK) return st;
    if (!model->integrator->carries_acceleration) model->acc_valid = 0;
    /* The hinge dashpots' split update changes v only; the integrator's
     * carried acceleration stays its own step's (bending_implicit.c). */
    if (model->bending_implicit && model->hinges.count) {
        st = canopy_hinge_damping_implicit_update(model, dt);
        if (st != CANOPY_OK) return st;
    }
    model->t += dt;
    double speed = 0.0;
    int bad = find_runaway(model, &speed);
    if (bad >= 0) {
        if (isfinite(speed))
            return canopy_fail(model, CANOPY_ERR_DIVERGED,
                               "%s sub-step %d (dt %g): node %d speed %g m/s "
                               "exceeds the limit %g m/s",
                               model->integrator->name, substep, dt, bad, speed,
                               model->speed_limit);
        return canopy_fail(model, CANOPY_ERR_DIVERGED,
                           "%s sub-step %d (dt %g): node %d position or "
                           "velocity is not finite", model->integrator->name,
                           substep, dt, bad);
    }
    return CANOPY_OK;
}

/* With the pressure frozen (set_pressure_frozen): its load on the shape at
 * the start of a step or advance, held until release_pressure. */
static void hold_pressure(canopy_model *model)
{
    if (!model->pressure_frozen) return;
    double *held = canopy_vectors_at(&model->pressure_step, 0);
    for (int i = 0; i < 3 * model->nodes.count; ++i) held[i] = 0.0;
    canopy_pressure_forces(model, model->nodes.x, held);
    model->pressure_held = 1;
}

static void release_pressure(canopy_model *model)
{
    model->pressure_held = 0;
}

canopy_status canopy_model_step(canopy_model *model, double dt)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (!(dt > 0.0) || !isfinite(dt))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "step: dt %g must be finite and > 0", dt);
    canopy_status st = canopy_model_prepare(model);
    if (st != CANOPY_OK) return st;
    if ((st = canopy_state_save(model, &model->rollback)) != CANOPY_OK)
        return st;
    hold_pressure(model);
    st = raw_step(model, dt, 0);
    release_pressure(model);
    if (st != CANOPY_OK) {
        canopy_state_load(model, &model->rollback);
        return st;
    }
    canopy_clear_message(model);
    return CANOPY_OK;
}

/* How many times an implicit sub-step whose Newton solve failed is halved
 * before canopy_model_advance gives up (down to 1/16 of it). */
enum { CANOPY_MAX_HALVINGS = 4 };

/* One sub-step of h; for an implicit integrator whose Newton solve does not
 * converge, the sub-step again as two halves, recursively. The integrator
 * leaves the state untouched when its solve fails, so the halves start from
 * where the sub-step did. *count: sub-steps taken so far. */
static canopy_status step_or_halve(canopy_model *model, double h, int depth,
                                   int *count)
{
    canopy_status st = raw_step(model, h, *count);
    if (st == CANOPY_OK) {
        ++*count;
        return st;
    }
    if (st != CANOPY_ERR_NOT_CONVERGED || !model->integrator->implicit ||
        depth >= CANOPY_MAX_HALVINGS)
        return st;
    st = step_or_halve(model, 0.5 * h, depth + 1, count);
    if (st != CANOPY_OK) return st;
    return step_or_halve(model, 0.5 * h, depth + 1, count);
}

canopy_status canopy_model_advance(canopy_model *model, double dt,
                                   int *substeps_out)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (!(dt > 0.0) || !isfinite(dt))
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "advance: dt %g must be finite and > 0", dt);
    double h;
    canopy_status st = canopy_model_stable_step(model, &h);
    if (st != CANOPY_OK) return st;
    /* Sub-steps rounded up; the relative slack keeps an exact multiple from
     * gaining a spurious extra step through round-off. */
    double ratio = dt / h;
    if (ratio > 1e9)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "advance: dt %g needs %g sub-steps of %g (limit 1e9)",
                           dt, ratio, h);
    int n = (int)ceil(ratio * (1.0 - 1e-12));
    if (n < 1) n = 1;
    const double sub = dt / n;
    if ((st = canopy_state_save(model, &model->rollback)) != CANOPY_OK)
        return st;
    const double t_end = model->t + dt;
    int taken = 0;
    hold_pressure(model);
    for (int k = 0; k < n; ++k) {
        st = step_or_halve(model, sub, 0, &taken);
        if (st != CANOPY_OK) {
            release_pressure(model);
            canopy_state_load(model, &model->rollback);
            return st;
        }
    }
    release_pressure(model);
    model->t = t_end;
    if (substeps_out) *substeps_out = taken;
    canopy_clear_message(model);
    return CANOPY_OK;
}
