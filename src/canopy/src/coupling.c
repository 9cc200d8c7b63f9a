/* coupling.c — what a fluid solver reads from the canopy each step: triangle markers, velocities, porous slip. */
#include "model_internal.h"

#include <math.h>

static canopy_status tri_count_check(const canopy_model *model, int nt,
                                     const char *what)
{
    if (nt != model->tris.count)
        return canopy_reject(model, CANOPY_ERR_RANGE,
                           "%s: count %d does not match the model's %d "
                           "triangles", what, nt, model->tris.count);
    return CANOPY_OK;
}

canopy_status canopy_model_get_triangle_geometry(const canopy_model *model,
                                                 double *centroid,
                                                 double *normal, double *area,
                                                 int nt)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    canopy_status st = tri_count_check(model, nt, "get_triangle_geometry");
    if (st != CANOPY_OK) return st;
    const double *x = model->nodes.x;
    for (int t = 0; t < nt; ++t) {
        const int *tri = model->tris.nodes + 3 * t;
        double an[3];
        canopy_triangle_area_normal(x, tri, an);
        const double A = sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        if (area) area[t] = A;
        if (normal)
            for (int d = 0; d < 3; ++d)
                normal[3 * t + d] = A > 0.0 ? an[d] / A : 0.0;
        if (centroid)
            for (int d = 0; d < 3; ++d)
                centroid[3 * t + d] = (x[3 * tri[0] + d] + x[3 * tri[1] + d] +
                                       x[3 * tri[2] + d]) / 3.0;
    }
    return CANOPY_OK;
}

canopy_status canopy_model_get_triangle_velocities(const canopy_model *model,
                                                   double *velocity, int nt)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (velocity == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT,
                             "get_triangle_velocities: velocity is NULL");
    canopy_status st = tri_count_check(model, nt, "get_triangle_velocities");
    if (st != CANOPY_OK) return st;
    const double *v = model->nodes.v;
    for (int t = 0; t < nt; ++t) {
        const int *tri = model->tris.nodes + 3 * t;
        for (int d = 0; d < 3; ++d)
            velocity[3 * t + d] = (v[3 * tri[0] + d] + v[3 * tri[1] + d] +
                                   v[3 * tri[2] + d]) / 3.0;
    }
    return CANOPY_OK;
}

/* Seepage velocity w from dp = alpha w + beta w |w| (seed 002 eqs. 6-10 in
 * Forchheimer form): w = sign(dp) 2|dp| / (alpha + sqrt(alpha^2 + 4 beta |dp|)),
 * the root written without cancellation. Impermeable (alpha = beta = 0): 0. */
double canopy_model_seepage_velocity(const canopy_model *model, double dp)
{
    if (model == NULL) return NAN;
    const double a = model->porosity_alpha, b = model->porosity_beta;
    if (a == 0.0 && b == 0.0) return 0.0;
    const double mag = fabs(dp);
    const double w = 2.0 * mag / (a + sqrt(a * a + 4.0 * b * mag));
    return dp < 0.0 ? -w : w;
}

canopy_status canopy_model_get_normal_velocities(const canopy_model *model,
                                                 double *vn, int nt)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (vn == NULL)
        return canopy_reject(model, CANOPY_ERR_ARGUMENT,
                             "get_normal_velocities: vn is NULL");
    canopy_status st = tri_count_check(model, nt, "get_normal_velocities");
    if (st != CANOPY_OK) return st;
    const double *x = model->nodes.x, *v = model->nodes.v;
    for (int t = 0; t < nt; ++t) {
        const int *tri = model->tris.nodes + 3 * t;
        double an[3];
        canopy_triangle_area_normal(x, tri, an);
        const double A = sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
        double un = 0.0;
        if (A > 0.0)
            for (int d = 0; d < 3; ++d)
                un += an[d] / A *
                      (v[3 * tri[0] + d] + v[3 * tri[1] + d] +
                       v[3 * tri[2] + d]) / 3.0;
        vn[t] = un + canopy_model_seepage_velocity(model, model->tris.dp[t]);
    }
    return CANOPY_OK;
}
