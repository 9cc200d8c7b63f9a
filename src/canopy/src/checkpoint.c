/* checkpoint.c — saving and restoring the dynamic state (time, positions, velocities). */
#include "model_internal.h"

#include <stdlib.h>
#include <string.h>

canopy_status canopy_state_save(canopy_model *m, canopy_state_copy *c)
{
    const int n = m->nodes.count;
    if (c->count != n || c->x == NULL) {
        size_t bytes = 3 * sizeof(double) * (size_t)(n > 0 ? n : 1);
        double *x = malloc(bytes), *v = malloc(bytes), *a = malloc(bytes);
        if (x == NULL || v == NULL || a == NULL) {
            free(x);
            free(v);
            free(a);
            return canopy_fail(m, CANOPY_ERR_MEMORY,
                               "cannot allocate a state copy of %d nodes", n);
        }
        free(c->x);
        free(c->v);
        free(c->acc);
        c->x = x;
        c->v = v;
        c->acc = a;
        c->count = n;
    }
    /* A model without nodes has no arrays (NULL): nothing to copy. */
    if (n > 0) {
        memcpy(c->x, m->nodes.x, 3 * sizeof(double) * (size_t)n);
        memcpy(c->v, m->nodes.v, 3 * sizeof(double) * (size_t)n);
        memcpy(c->acc, m->nodes.acc, 3 * sizeof(double) * (size_t)n);
    }
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
    }
    m->acc_valid = c->acc_valid;
    m->t = c->t;
}

void canopy_state_free(canopy_state_copy *c)
{
    free(c->x);
    free(c->v);
    free(c->acc);
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
