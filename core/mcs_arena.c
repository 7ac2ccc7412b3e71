#include "core/mcs_arena.h"

#include <assert.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct mcs_arena {
    unsigned char *base; /* the one block (capacity bytes)          */
    size_t capacity;     /* size of the block [B]                   */
    size_t used;         /* bytes in use, offset of the next free [B] */
    size_t high_water;   /* maximum of used over the arena's life [B] */
};

mcs_status mcs_arena_create(size_t bytes, mcs_arena **out, mcs_error *err)
{
    *out = NULL;
    if (bytes == 0) return MCS_ERR(err, MCS_ERR_USAGE, "arena: capacity must be > 0 bytes");
    mcs_arena *a = calloc(1, sizeof *a);
    if (a) a->base = malloc(bytes);
    if (!a || !a->base) {
        free(a);
        return MCS_ERR(err, MCS_ERR_NOMEM, "arena: cannot allocate %zu bytes", bytes);
    }
    a->capacity = bytes;
    *out = a;
    return MCS_OK;
}

void mcs_arena_destroy(mcs_arena **p)
{
    if (!p || !*p) return;
    free((*p)->base);
    free(*p);
    *p = NULL;
}

void *mcs_arena_alloc(mcs_arena *a, size_t bytes, size_t align, mcs_error *err)
{
    if (align == 0) align = _Alignof(max_align_t);
    assert((align & (align - 1)) == 0 && "arena alignment must be a power of two");
    /* pad so the absolute address is aligned (the block is only max_align_t aligned) */
    uintptr_t next = (uintptr_t)(a->base + a->used);
    size_t pad = (size_t)((align - (next & (align - 1))) & (align - 1));
    size_t room = a->capacity - a->used;
    if (pad > room || bytes > room - pad) {
        MCS_ERR(err, MCS_ERR_ARENA,
                "scratch arena exhausted: %zu bytes requested (align %zu), %zu of %zu in use",
                bytes, align, a->used, a->capacity);
        return NULL;
    }
    void *p = a->base + a->used + pad;
    a->used += pad + bytes;
    if (a->used > a->high_water) a->high_water = a->used;
    return p;
}

void *mcs_arena_calloc(mcs_arena *a, size_t n, size_t size, size_t align, mcs_error *err)
{
    if (size != 0 && n > SIZE_MAX / size) {
        MCS_ERR(err, MCS_ERR_ARENA, "scratch arena: %zu x %zu bytes overflows", n, size);
        return NULL;
    }
    void *p = mcs_arena_alloc(a, n * size, align, err);
    if (p && n * size != 0) memset(p, 0, n * size);
    return p;
}

size_t mcs_arena_mark(const mcs_arena *a)
{
    return a->used;
}

void mcs_arena_reset(mcs_arena *a, size_t mark)
{
    assert(mark <= a->used && "arena reset to a mark beyond the bytes in use");
    if (mark <= a->used) a->used = mark;
}

size_t mcs_arena_used(const mcs_arena *a)
{
    return a->used;
}
size_t mcs_arena_capacity(const mcs_arena *a)
{
    return a->capacity;
}
size_t mcs_arena_high_water(const mcs_arena *a)
{
    return a->high_water;
}
