/* mcs_arena: one block allocated at create time, aligned bump allocation, mark/reset.
 * A state owns one arena for per-step temporaries (STYLE.md §3). Running out is a reported
 * error (MCS_ERR_ARENA), never a silent realloc; the high-water mark goes into the run summary. */
#ifndef MCS_ARENA_H
#define MCS_ARENA_H

#include <stddef.h>

#include "core/mcs_error.h"

typedef struct mcs_arena mcs_arena;

/* create an arena of `bytes` capacity (> 0); *out is NULL on error */
mcs_status mcs_arena_create(size_t bytes, mcs_arena **out, mcs_error *err);
/* free the block and null the pointer; NULL and *p == NULL are fine */
void mcs_arena_destroy(mcs_arena **p);

/* `bytes` aligned to `align` (a power of two; 0 means alignof(max_align_t)).
 * Returns NULL and records MCS_ERR_ARENA in err (may be NULL) when it does not fit.
 * A zero-byte request returns a valid, aligned, non-NULL pointer. */
void *mcs_arena_alloc(mcs_arena *a, size_t bytes, size_t align, mcs_error *err);
/* n elements of `size` bytes each, zero-filled; n * size overflow is MCS_ERR_ARENA */
void *mcs_arena_calloc(mcs_arena *a, size_t n, size_t size, size_t align, mcs_error *err);
/* typed helper: MCS_ARENA_NEW(a, double, 3 * nnode, err) */
#define MCS_ARENA_NEW(a, T, n, err) ((T *)mcs_arena_calloc((a), (n), sizeof(T), _Alignof(T), (err)))

/* a mark is the number of bytes in use; reset returns to it (later allocations are freed) */
size_t mcs_arena_mark(const mcs_arena *a);
void mcs_arena_reset(mcs_arena *a, size_t mark);

size_t mcs_arena_used(const mcs_arena *a);       /* bytes in use now [B]              */
size_t mcs_arena_capacity(const mcs_arena *a);   /* bytes of the block [B]            */
size_t mcs_arena_high_water(const mcs_arena *a); /* most bytes ever in use [B]        */

#endif
