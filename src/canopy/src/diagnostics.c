/* diagnostics.c — energies, canopy area, projected diameter, payload state, nodal forces and spring tensions. */
#include "model_internal.h"

#include <math.h>
#include <string.h>

static double spring_energy(const canopy_model *m, int k)
{
    const canopy_springs *s = &m->springs;
    const int i = s->ends[2 * k], j = s->ends[2 * k + 1];
    const double *x = m->nodes.x;
    double d[3];
    for (int c = 0; c < 3; ++c) d[c] = x[3 * j + c] - x[3 * i + c];
    if (s->law[k] == CANOPY_SPRING_MODEL_I) {     /* seed 000 eq. 2.13 */
        const double *r = s->rest_vec + 3 * k;
        double e2 = 0.0;
        for (int c = 0; c < 3; ++c) e2 += (d[c] - r[c]) * (d[c] - r[c]);
        return 0.5 * s->k[k] * e2;
    }
    const double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double stretch = l - s->rest[k];                /* seed 000 eq. 2.14 */
    if (s->law[k] == CANOPY_SPRING_TENSION_ONLY && stretch < 0.0) stretch = 0.0;
    return 0.5 * canopy_spring_stiffness(m, k, stretch) * stretch * stretch;
}

canopy_status canopy_model_energies(const canopy_model *model,
                                    canopy_energies *e)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (e == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT, "energies: e is NULL");
    const canopy_nodes *n = &model->nodes;
    const double *g = model->gravity;
    double kin = 0.0, grav = 0.0, spr = 0.0;
    for (int i = 0; i < n->count; ++i) {
        const double *v = n->v + 3 * i, *x = n->x + 3 * i;
        kin += 0.5 * n->mass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        grav -= n->mass[i] * (g[0] * x[0] + g[1] * x[1] + g[2] * x[2]);
    }
    for (int k = 0; k < model->springs.count; ++k) spr += spring_energy(model, k);
    e->kinetic = kin;
    e->spring = spr;
    e->gravity = grav;
    e->total = kin + spr + grav;
    return CANOPY_OK;
}

canopy_status canopy_model_canopy_area(const canopy_model *model, double *area)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (area == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT, "canopy_area: area is NULL");
    double A = 0.0;
    for (int t = 0; t < model->tris.count; ++t) {
        double an[3];
        canopy_triangle_area_normal(model->nodes.x, model->tris.nodes + 3 * t,
                                    an);
        A += sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
    }
    *area = A;
    return CANOPY_OK;
}

canopy_status canopy_model_projected_diameter(const canopy_model *model,
                                              double *diameter)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (diameter == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT, "projected_diameter: diameter is NULL");
    const canopy_triangles *t = &model->tris;
    if (t->count == 0)
        return canopy_reject(model, CANOPY_ERR_STATE,
                           "projected_diameter: the model has no canopy "
                           "triangles");
    /* Axis: along gravity through the area-weighted canopy centroid. */
    const double *g = model->gravity, *x = model->nodes.x;
    double axis[3] = {0.0, 0.0, 1.0};
    const double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (gl > 0.0)
        for (int d = 0; d < 3; ++d) axis[d] = g[d] / gl;
    double c[3] = {0.0, 0.0, 0.0}, A = 0.0;
    for (int k = 0; k < t->count; ++k) {
        const int *tri = t->nodes + 3 * k;
        double an[3];
        canopy_triangle_area_normal(x, tri, an);
        const double a = sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        for (int d = 0; d < 3; ++d)
            c[d] += a * (x[3 * tri[0] + d] + x[3 * tri[1] + d] +
                         x[3 * tri[2] + d]) / 3.0;
        A += a;
    }
    if (A > 0.0)
        for (int d = 0; d < 3; ++d) c[d] /= A;
    double rmax2 = 0.0;
    for (int k = 0; k < 3 * t->count; ++k) {
        const double *p = x + 3 * t->nodes[k];
        double r[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
        const double along = r[0] * axis[0] + r[1] * axis[1] + r[2] * axis[2];
        double r2 = 0.0;
        for (int d = 0; d < 3; ++d) {
            const double q = r[d] - along * axis[d];
            r2 += q * q;
        }
        if (r2 > rmax2) rmax2 = r2;
    }
    *diameter = 2.0 * sqrt(rmax2);
    return CANOPY_OK;
}

canopy_status canopy_model_payload_state(const canopy_model *model,
                                         double x[3], double v[3])
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    const int p = model->payload_node;
    if (p < 0 || p >= model->nodes.count)
        return canopy_reject(model, CANOPY_ERR_STATE,
                           "payload_state: the model has no payload node");
    if (x) memcpy(x, model->nodes.x + 3 * p, 3 * sizeof(double));
    if (v) memcpy(v, model->nodes.v + 3 * p, 3 * sizeof(double));
    return CANOPY_OK;
}

canopy_status canopy_model_get_forces(canopy_model *model, double *f, int n)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (f == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT, "get_forces: f is NULL");
    if (n != model->nodes.count)
        return canopy_fail(model, CANOPY_ERR_RANGE,
                           "get_forces: count %d does not match the model's %d "
                           "nodes", n, model->nodes.count);
    const canopy_status st = canopy_model_prepare(model); /* the hinges */
    if (st != CANOPY_OK) return st;
    canopy_forces(model, model->nodes.x, model->nodes.v, f);
    if (model->bending_implicit && model->hinges.count)
        canopy_hinge_damping_implicit_forces(model, f);
    return CANOPY_OK;
}

canopy_status canopy_model_get_tensions(const canopy_model *model, double *T,
                                        int ns)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (T == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT, "get_tensions: T is NULL");
    const canopy_springs *s = &model->springs;
    if (ns != s->count)
        return canopy_reject(model, CANOPY_ERR_RANGE,
                           "get_tensions: count %d does not match the model's "
                           "%d springs", ns, s->count);
    const double *x = model->nodes.x, *v = model->nodes.v;
    for (int k = 0; k < ns; ++k) {
        const int i = s->ends[2 * k], j = s->ends[2 * k + 1];
        double d[3], dv[3];
        for (int c = 0; c < 3; ++c) {
            d[c] = x[3 * j + c] - x[3 * i + c];
            dv[c] = v[3 * j + c] - v[3 * i + c];
        }
        const double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double rate = l > 0.0 ? (d[0] * dv[0] + d[1] * dv[1] +
                                       d[2] * dv[2]) / l : 0.0;
        double stretch = l - s->rest[k];
        if (s->law[k] == CANOPY_SPRING_MODEL_I) {
            /* Axial component of k (d - d0). */
            const double *r = s->rest_vec + 3 * k;
            stretch = l > 0.0 ? ((d[0] - r[0]) * d[0] + (d[1] - r[1]) * d[1] +
                                 (d[2] - r[2]) * d[2]) / l : 0.0;
        }
        if (s->law[k] == CANOPY_SPRING_TENSION_ONLY)
            T[k] = canopy_line_tension(s->k[k], s->c[k], stretch, rate);
        else
            T[k] = canopy_spring_stiffness(model, k, stretch) * stretch
                 + s->c[k] * rate;
    }
    return CANOPY_OK;
}
