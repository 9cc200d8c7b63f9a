/* integrators.c — the table of built-in integrators, lookup by name, the model's stepper (its integrator's own state) and a shared vector helper. */
#include "integrator.h"

#include <string.h>

static const canopy_integrator *const table[] = {
    &canopy_integrator_euler,   &canopy_integrator_euler_cromer,
    &canopy_integrator_euler_richardson, &canopy_integrator_heun,
    &canopy_integrator_verlet,  &canopy_integrator_rk4,
    &canopy_integrator_newmark, &canopy_integrator_hht,
    &canopy_integrator_kang,
};
enum { TABLE_SIZE = (int)(sizeof table / sizeof table[0]) };

int canopy_integrator_count(void) { return TABLE_SIZE; }

const char *canopy_integrator_name(int i)
{
    return (i >= 0 && i < TABLE_SIZE) ? table[i]->name : NULL;
}

int canopy_integrator_order(int i)
{
    return (i >= 0 && i < TABLE_SIZE) ? table[i]->order : 0;
}

const canopy_integrator *canopy_integrator_find(const char *name)
{
    for (int i = 0; i < TABLE_SIZE; ++i)
        if (strcmp(table[i]->name, name) == 0) return table[i];
    return NULL;
}

canopy_status canopy_stepper_prepare(canopy_model *model)
{
    canopy_stepper *s = &model->stepper;
    const canopy_integrator *type = model->integrator;
    const int nodes = model->nodes.count;
    if (s->type == type && s->nodes == nodes && s->state != NULL)
        return CANOPY_OK;
    size_t bytes = 0;
    void *state = type->alloc(nodes, &bytes);
    if (state == NULL)
        return canopy_fail(model, CANOPY_ERR_MEMORY,
                           "cannot allocate the workspace of integrator '%s' "
                           "for %d nodes", type->name, nodes);
    canopy_stepper_free(s);
    s->type = type;
    s->state = state;
    s->nodes = nodes;
    s->bytes = bytes;
    return CANOPY_OK;
}

void canopy_stepper_free(canopy_stepper *s)
{
    if (s->type != NULL) s->type->free(s->state);
    s->type = NULL;
    s->state = NULL;
    s->nodes = 0;
    s->bytes = 0;
}

void canopy_axpy(int n, const double *x, double s, const double *y, double *z)
{
    for (int i = 0; i < 3 * n; ++i) z[i] = x[i] + s * y[i];
}
