/* tangent.c — matrix-free tangent stiffness K = -df/dx and dashpot tangent C = -df/dv. */
#include "model_internal.h"

#include <math.h>
#include <string.h>

/* The tension of tension-only spring k of length l along e at velocities v
 * (canopy_line_tension); v NULL: the spring alone, dashpot idle. */
static double line_tension(const canopy_model *m, int k, const double *v,
                           const double e[3], double l)
{
    const canopy_springs *s = &m->springs;
    const int i = s->ends[2 * k], j = s->ends[2 * k + 1];
    double rate = 0.0;
    if (v != NULL)
        for (int d = 0; d < 3; ++d) rate += e[d] * (v[3 * j + d] - v[3 * i + d]);
    return canopy_line_tension(s->k[k], v != NULL ? s->c[k] : 0.0,
                               l - s->rest[k], rate);
}

/* For a Model-II spring (seed 000 eq. 3.12) the tangent block is
 *   K_s = k [ e e^T + (1 - l0/l) (I - e e^T) ]
 * (k times the compression factor while l < l0),
 * for Model-I K_s = k I; for a tension-only spring carrying tension T,
 * k e e^T + (T / l) (I - e e^T), and 0 while it carries none. The global K
 * couples i and j as [K_s, -K_s; -K_s, K_s]. With `clamp`, a negative
 * geometric factor (1 - l0/l) of a compressed spring is replaced by 0. */
void canopy_tangent_stiffness(const canopy_model *m, const double *x,
                              const double *v, const double *u, double *y,
                              int clamp)
{
    const canopy_springs *s = &m->springs;
    const unsigned char *fixed = m->nodes.fixed;
    memset(y, 0, 3 * sizeof(double) * (size_t)m->nodes.count);
    for (int k = 0; k < s->count; ++k) {
        const int i = s->ends[2 * k], j = s->ends[2 * k + 1];
        const double ui[3] = {fixed[i] ? 0.0 : u[3 * i],
                              fixed[i] ? 0.0 : u[3 * i + 1],
                              fixed[i] ? 0.0 : u[3 * i + 2]};
        const double uj[3] = {fixed[j] ? 0.0 : u[3 * j],
                              fixed[j] ? 0.0 : u[3 * j + 1],
                              fixed[j] ? 0.0 : u[3 * j + 2]};
        const double du[3] = {ui[0] - uj[0], ui[1] - uj[1], ui[2] - uj[2]};
        double w[3];
        if (s->law[k] == CANOPY_SPRING_MODEL_I) {
            for (int d = 0; d < 3; ++d) w[d] = s->k[k] * du[d];
        } else {
            const double *xi = x + 3 * i, *xj = x + 3 * j;
            double e[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
            const double l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            if (!(l > 0.0)) continue;
            for (int d = 0; d < 3; ++d) e[d] /= l;
            double geo = 1.0 - s->rest[k] / l;
            double axial = 1.0;
            if (s->law[k] == CANOPY_SPRING_TENSION_ONLY) {
                const double T = line_tension(m, k, v, e, l);
                axial = T > 0.0 ? 1.0 : 0.0;
                geo = s->k[k] > 0.0 ? T / (s->k[k] * l) : 0.0;
            }
            if (s->law[k] == CANOPY_SPRING_MODEL_II && l < s->rest[k]) {
                axial = canopy_compression_factor(m, k);
                geo *= axial;
            }
            if (clamp && geo < 0.0) geo = 0.0;
            const double ed = e[0] * du[0] + e[1] * du[1] + e[2] * du[2];
            for (int d = 0; d < 3; ++d)
                w[d] = s->k[k] * (axial * ed * e[d] + geo * (du[d] - ed * e[d]));
        }
        if (!fixed[i]) { y[3 * i] += w[0]; y[3 * i + 1] += w[1]; y[3 * i + 2] += w[2]; }
        if (!fixed[j]) { y[3 * j] -= w[0]; y[3 * j + 1] -= w[1]; y[3 * j + 2] -= w[2]; }
    }
}

/* Dashpot tangent: C_s = c e e^T (zero for a tension-only spring carrying
 * no tension). */
void canopy_tangent_damping(const canopy_model *m, const double *x,
                            const double *v, const double *u, double *y)
{
    const canopy_springs *s = &m->springs;
    const unsigned char *fixed = m->nodes.fixed;
    memset(y, 0, 3 * sizeof(double) * (size_t)m->nodes.count);
    for (int k = 0; k < s->count; ++k) {
        if (s->c[k] == 0.0) continue;
        const int i = s->ends[2 * k], j = s->ends[2 * k + 1];
        const double *xi = x + 3 * i, *xj = x + 3 * j;
        double e[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
        const double l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if (!(l > 0.0)) continue;
        for (int d = 0; d < 3; ++d) e[d] /= l;
        if (s->law[k] == CANOPY_SPRING_TENSION_ONLY &&
            !(line_tension(m, k, v, e, l) > 0.0))
            continue;
        double ed = 0.0;
        for (int d = 0; d < 3; ++d) {
            const double ui = fixed[i] ? 0.0 : u[3 * i + d];
            const double uj = fixed[j] ? 0.0 : u[3 * j + d];
            ed += e[d] * (ui - uj);
        }
        for (int d = 0; d < 3; ++d) {
            const double w = s->c[k] * ed * e[d];
            if (!fixed[i]) y[3 * i + d] += w;
            if (!fixed[j]) y[3 * j + d] -= w;
        }
    }
    if (!m->bending_implicit) canopy_hinge_tangent_damping(m, x, u, y);
}
