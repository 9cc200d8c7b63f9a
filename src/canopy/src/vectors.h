/* vectors.h — a block of node vectors (arrays of 3*nodes doubles), the storage behind the integrators' and solvers' own workspaces. */
#ifndef CANOPY_VECTORS_H
#define CANOPY_VECTORS_H

#include <stddef.h>

/* `count` arrays of 3*nodes doubles, one after another in `data`. An
 * all-zero struct holds nothing. */
typedef struct canopy_vectors {
    double *data;
    int count, nodes;
} canopy_vectors;

/* Fill *v with `count` zeroed arrays of 3*nodes doubles (count, nodes >= 0).
 * *v must hold nothing. Returns 0, or -1 (out of memory, or a size beyond
 * size_t) with *v left holding nothing. */
int canopy_vectors_alloc(canopy_vectors *v, int count, int nodes);
/* Release the arrays; *v then holds nothing. */
void canopy_vectors_free(canopy_vectors *v);
/* Bytes of the arrays. */
size_t canopy_vectors_bytes(const canopy_vectors *v);

/* Array k of the block (0 <= k < count). */
static inline double *canopy_vectors_at(const canopy_vectors *v, int k)
{
    return v->data + (size_t)k * 3 * (size_t)v->nodes;
}

/* A workspace struct of `size` bytes whose first member is a canopy_vectors
 * holding `count` arrays of 3*nodes doubles, all zero; NULL when out of
 * memory. *bytes (may be NULL) receives the bytes allocated. Freed by
 * canopy_vectors_state_free (NULL: no-op). */
void *canopy_vectors_state_alloc(size_t size, int count, int nodes,
                                 size_t *bytes);
void canopy_vectors_state_free(void *state);

#endif /* CANOPY_VECTORS_H */
