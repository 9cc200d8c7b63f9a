/* vectors.c — allocation of node-vector blocks and of the workspaces built on them. */
#include "vectors.h"

#include <stdint.h>
#include <stdlib.h>

int canopy_vectors_alloc(canopy_vectors *v, int count, int nodes)
{
    v->data = NULL;
    v->count = v->nodes = 0;
    if (count < 0 || nodes < 0) return -1;
    const size_t per = 3 * (size_t)nodes;
    if (count > 0 && per > SIZE_MAX / sizeof(double) / (size_t)count)
        return -1;
    const size_t total = per * (size_t)count;
    double *data = calloc(total > 0 ? total : 1, sizeof(double));
    if (data == NULL) return -1;
    v->data = data;
    v->count = count;
    v->nodes = nodes;
    return 0;
}

void canopy_vectors_free(canopy_vectors *v)
{
    free(v->data);
    v->data = NULL;
    v->count = v->nodes = 0;
}

size_t canopy_vectors_bytes(const canopy_vectors *v)
{
    return sizeof(double) * 3 * (size_t)v->nodes * (size_t)v->count;
}

void *canopy_vectors_state_alloc(size_t size, int count, int nodes,
                                 size_t *bytes)
{
    if (size < sizeof(canopy_vectors)) return NULL;
    canopy_vectors *state = calloc(1, size);
    if (state == NULL) return NULL;
    if (canopy_vectors_alloc(state, count, nodes) != 0) {
        free(state);
        return NULL;
    }
    if (bytes) *bytes = size + canopy_vectors_bytes(state);
    return state;
}

void canopy_vectors_state_free(void *state)
{
    if (state == NULL) return;
    canopy_vectors_free(state);
    free(state);
}
