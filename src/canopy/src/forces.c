/* forces.c — the one force evaluation every integrator shares: springs, dashpots, hinge dashpots, gravity, pressure, loads. */
#include "model_internal.h"

#include <math.h>
#include <string.h>

/* Spring and dashpot forces. For spring s between i and j with d = x_j - x_i,
 * l = |d|, e = d / l:
 *   Model-II      f_i = +k (l - l0) e           (seed 000 eq. 2.18), with
 *                 k times the cloth's compression ratio r while l < l0
 *   Model-I       f_i = +k (d - d0)             (seed 000 eq. 2.17)
 *   tension-only  f_i = +max(0, k (l - l0) + c dl/dt) e (canopy_line_tension)
 * plus, for the others, the dashpot f_i = +c ((v_j - v_i).e) e; f_j = -f_i. */
static void spring_forces(const canopy_model *m, const double *x,
                          const double *v, double *f)
{
    const canopy_springs *s = &m->springs;
    const int *ends = s->ends;
    for (int k = 0; k < s->count; ++k) {
        const int i = ends[2 * k], j = ends[2 * k + 1];
        const double *xi = x + 3 * i, *xj = x + 3 * j;
        const double d0 = xj[0] - xi[0], d1 = xj[1] - xi[1], d2 = xj[2] - xi[2];
        const double l = sqrt(d0 * d0 + d1 * d1 + d2 * d2);
        const double inv = l > 0.0 ? 1.0 / l : 0.0;
        const double e0 = d0 * inv, e1 = d1 * inv, e2 = d2 * inv;
        const double *vi = v + 3 * i, *vj = v + 3 * j;
        const double rate = (vj[0] - vi[0]) * e0 + (vj[1] - vi[1]) * e1 +
                            (vj[2] - vi[2]) * e2;
        double fx, fy, fz;
        switch (s->law[k]) {
        case CANOPY_SPRING_MODEL_I: {
            const double *r = s->rest_vec + 3 * k;
            const double damp = s->c[k] * rate;
            fx = s->k[k] * (d0 - r[0]) + damp * e0;
            fy = s->k[k] * (d1 - r[1]) + damp * e1;
            fz = s->k[k] * (d2 - r[2]) + damp * e2;
            break;
        }
        case CANOPY_SPRING_TENSION_ONLY: {
            const double T = canopy_line_tension(s->k[k], s->c[k],
                                                 l - s->rest[k], rate);
            fx = T * e0; fy = T * e1; fz = T * e2;
            break;
        }
        default: {
            const double stretch = l - s->rest[k];
            const double T = canopy_spring_stiffness(m, k, stretch) * stretch
                           + s->c[k] * rate;
            fx = T * e0; fy = T * e1; fz = T * e2;
            break;
        }
        }
        f[3 * i] += fx; f[3 * i + 1] += fy; f[3 * i + 2] += fz;
        f[3 * j] -= fx; f[3 * j + 1] -= fy; f[3 * j + 2] -= fz;
    }
}

/* Pressure load dp * A * n per triangle, 1/3 to each vertex (NOTES §3). */
void canopy_pressure_forces(const canopy_model *m, const double *x, double *f)
{
    const canopy_triangles *t = &m->tris;
    for (int k = 0; k < t->count; ++k) {
        const double dp = t->dp[k];
        if (dp == 0.0) continue;
        const int *tri = t->nodes + 3 * k;
        double an[3];
        canopy_triangle_area_normal(x, tri, an);
        const double s = dp / 3.0;
        for (int c = 0; c < 3; ++c) {
            double *fi = f + 3 * tri[c];
            fi[0] += s * an[0]; fi[1] += s * an[1]; fi[2] += s * an[2];
        }
    }
}

void canopy_forces(const canopy_model *m, const double *x, const double *v,
                   double *f)
{
    const canopy_nodes *n = &m->nodes;
    const double *g = m->gravity, *fe = n->force_ext;
    for (int i = 0; i < n->count; ++i) {
        const double mi = n->mass[i];
        f[3 * i]     = mi * g[0] + fe[3 * i];
        f[3 * i + 1] = mi * g[1] + fe[3 * i + 1];
        f[3 * i + 2] = mi * g[2] + fe[3 * i + 2];
    }
    spring_forces(m, x, v, f);
    if (m->hinges.count && !m->bending_implicit)
        canopy_hinge_forces(m, x, v, f);
    if (m->pressure_held) {
        const double *held = canopy_vectors_at(&m->pressure_step, 0);
        for (int i = 0; i < 3 * n->count; ++i) f[i] += held[i];
    } else {
        canopy_pressure_forces(m, x, f);
    }
}

void canopy_accelerations(const canopy_model *m, const double *x,
                          const double *v, double *a)
{
    canopy_forces(m, x, v, a);
    const canopy_nodes *n = &m->nodes;
    for (int i = 0; i < n->count; ++i) {
        if (n->fixed[i]) {
            a[3 * i] = a[3 * i + 1] = a[3 * i + 2] = 0.0;
            continue;
        }
        canopy_node_acceleration(m, i, a + 3 * i);
    }
}
