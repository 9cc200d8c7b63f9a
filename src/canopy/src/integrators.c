/* integrators.c — the table of built-in integrators, lookup by name, and a shared vector helper. */
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

void canopy_axpy(int n, const double *x, double s, const double *y, double *z)
{
    for (int i = 0; i < 3 * n; ++i) z[i] = x[i] + s * y[i];
}
