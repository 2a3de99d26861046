/*
** alloc.c: the counting allocator every run allocates through (Lua's
** lua_Alloc shape: callers pass the old size, so the statistics need no
** block headers).
**
** Invariants: alloc.live is the sum of the sizes of the blocks handed out and
** not yet freed; alloc.peak >= alloc.live; a refused request records
** WK_ENOMEM as the run's error and changes no statistic.
*/
#include "wskel.h"

#include <stdlib.h>
#include <string.h>

void *wk_libc_realloc(void *ud, void *p, size_t old_size, size_t new_size) {
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        free(p);
        return NULL;
    }
    return realloc(p, new_size);
}

/* ---- allocation ---- */

void *wk_realloc(wk_run *R, void *p, size_t old_size, size_t new_size) {
    wk_alloc *A = &R->alloc;
    if (new_size == 0) {
        if (p) {
            A->fn(A->ud, p, old_size, 0);
            A->live -= old_size;
            A->blocks--;
        }
        return NULL;
    }
    size_t base = p ? old_size : 0;
    /* Refuse absurd sizes before asking the backend (Redis zmalloc). */
    if (new_size > ((size_t)1 << 46) ||
        (A->limit && A->live - base + new_size > A->limit) ||
        (A->fail_after >= 0 && A->calls >= (uint64_t)A->fail_after)) {
        WK_FAIL(R, WK_ENOMEM, NULL, 0, "out of memory (asked for %zu bytes, %zu live)", new_size,
                A->live);
        return NULL;
    }
    void *q = A->fn(A->ud, p, base, new_size);
    if (!q) {
        WK_FAIL(R, WK_ENOMEM, NULL, 0, "out of memory (asked for %zu bytes, %zu live)", new_size,
                A->live);
        return NULL;
    }
    A->calls++;
    if (!p) A->blocks++;
    A->live = A->live - base + new_size;
    if (A->live > A->peak) A->peak = A->live;
    return q;
}

void *wk_calloc(wk_run *R, size_t count, size_t size) {
    if (count == 0) count = 1; /* a valid, freeable block even for empty arrays */
    if (size && count > SIZE_MAX / size) {
        WK_FAIL(R, WK_ENOMEM, NULL, 0, "allocation of %zu x %zu bytes overflows", count, size);
        return NULL;
    }
    void *p = wk_realloc(R, NULL, 0, count * size);
    if (p) memset(p, 0, count * size);
    return p;
}

wk_status wk_grow(wk_run *R, void **pp, uint32_t *cap, uint32_t need, size_t elem_size) {
    if (need <= *cap && *pp) return WK_OK;
    uint64_t ncap = *cap ? *cap : 8;
    while (ncap < need) ncap *= 2;
    if (ncap > UINT32_MAX - 1) ncap = UINT32_MAX - 1;
    if (ncap < need) return WK_FAIL(R, WK_ENOMEM, NULL, 0, "array of %u elements too large", need);
    void *q = wk_realloc(R, *pp, (size_t)*cap * elem_size, (size_t)ncap * elem_size);
    if (!q) return R->err.code;
    *pp = q;
    *cap = (uint32_t)ncap;
    return WK_OK;
}

