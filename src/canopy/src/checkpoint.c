/* checkpoint.c — saving and restoring the dynamic state (time, positions, velocities, carried acceleration) and the loads set on the model. */
#include "model_internal.h"

#include <stdlib.h>
#include <string.h>

/* Arrays of at least one element, so that a model without nodes or
 * triangles still has a valid copy. */
static double *alloc_doubles(int count)
{
    return malloc(sizeof(double) * (size_t)(count > 0 ? count : 1));
}

canopy_status canopy_state_save(canopy_model *m, canopy_state_copy *c)
{
    const int n = m->nodes.count, nt = m->tris.count;
    if (c->count != n || c->triangles != nt || c->x == NULL) {
        double *x = alloc_doubles(3 * n), *v = alloc_doubles(3 * n),
               *a = alloc_doubles(3 * n), *f = alloc_doubles(3 * n),
               *dp = alloc_doubles(nt);
        if (x == NULL || v == NULL || a == NULL || f == NULL || dp == NULL) {
            free(x);
            free(v);
            free(a);
            free(f);
            free(dp);
            return canopy_fail(m, CANOPY_ERR_MEMORY,
                               "cannot allocate a state copy of %d nodes "
                               "and %d triangles", n, nt);
        }
        canopy_state_free(c);
        c->x = x;
        c->v = v;
        c->acc = a;
        c->force_ext = f;
        c->dp = dp;
        c->count = n;
        c->triangles = nt;
    }
    /* A model without nodes (triangles) has no arrays (NULL): nothing to
     * copy. */
    if (n > 0) {
        memcpy(c->x, m->nodes.x, 3 * sizeof(double) * (size_t)n);
        memcpy(c->v, m->nodes.v, 3 * sizeof(double) * (size_t)n);
        memcpy(c->acc, m->nodes.acc, 3 * sizeof(double) * (size_t)n);
        memcpy(c->force_ext, m->nodes.force_ext,
               3 * sizeof(double) * (size_t)n);
    }
    if (nt > 0) memcpy(c->dp, m->tris.dp, sizeof(double) * (size_t)nt);
    c->acc_valid = m->acc_valid;
    c->t = m->t;
    c->valid = 1;
    return CANOPY_OK;
}

void canopy_state_load(canopy_model *m, const canopy_state_copy *c)
{
    if (c->count > 0) {
        memcpy(m->nodes.x, c->x, 3 * sizeof(double) * (size_t)c->count);
        memcpy(m->nodes.v, c->v, 3 * sizeof(double) * (size_t)c->count);
        memcpy(m->nodes.acc, c->acc, 3 * sizeof(double) * (size_t)c->count);
        memcpy(m->nodes.force_ext, c->force_ext,
               3 * sizeof(double) * (size_t)c->count);
    }
    if (c->triangles > 0)
        memcpy(m->tris.dp, c->dp, sizeof(double) * (size_t)c->triangles);
    m->acc_valid = c->acc_valid;
    m->t = c->t;
}

void canopy_state_free(canopy_state_copy *c)
{
    free(c->x);
    free(c->v);
    free(c->acc);
    free(c->force_ext);
    free(c->dp);
    memset(c, 0, sizeof *c);
}

canopy_status canopy_model_checkpoint(canopy_model *model)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    canopy_status st = canopy_state_save(model, &model->checkpoint);
    if (st == CANOPY_OK) canopy_clear_message(model);
    return st;
}

canopy_status canopy_model_restore(canopy_model *model)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (!model->checkpoint.valid || model->checkpoint.count != model->nodes.count)
        return canopy_fail(model, CANOPY_ERR_STATE,
                           "restore: no checkpoint of the current model "
                           "(call canopy_model_checkpoint first)");
    canopy_state_load(model, &model->checkpoint);
    canopy_clear_message(model);
    return CANOPY_OK;
}

canopy_status canopy_model_commit(canopy_model *model)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (!model->checkpoint.valid)
        return canopy_fail(model, CANOPY_ERR_STATE,
                           "commit: no checkpoint to commit");
    model->checkpoint.valid = 0;
    canopy_clear_message(model);
    return CANOPY_OK;
}
