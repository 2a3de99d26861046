/*
** alloc.c: the counting allocator every run allocates through, and its
** backends: libc (the default) and the checking backend for tests.
**
** Invariants:
**   - alloc.live is the sum of the sizes of the blocks handed out and not
**     yet freed, as their callers state them (Lua's lua_Alloc shape: callers
**     pass the old size, so the run keeps no block headers); alloc.blocks is
**     their number; alloc.peak >= alloc.live.
**   - A refused request records WK_ENOMEM as the run's error, changes no
**     statistic and leaves the old block (if any) intact.
**   - A request for 0 bytes yields EMPTY, which is not a block: it adds
**     nothing to live or blocks, no backend ever sees it, freeing it does
**     nothing and growing it allocates afresh.  So allocation and free agree
**     for every count, 0 included, with no rounding at the call sites.
**   - wk_grow_ptr (and WK_GROW) never lose the array: on failure the array
**     and its capacity are unchanged.
**   - Debug backend: a live block is DBG_HEAD bytes of header (its size, that
**     size xor DBG_MAGIC, then guard bytes), the caller's bytes, then
**     DBG_TAIL guard bytes; all of it is verified before the block is
**     resized or freed.
*/
#include "wskel.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* Requests above 64 TiB are refused before any backend sees them (Redis
** zmalloc): such a size is a bug or an overflow, not a real need. */
#define MAX_REQUEST ((size_t)1 << 46)

/* ---- backends ---- */

static void *libc_realloc(void *ud, void *p, size_t old_size, size_t new_size) {
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        free(p);
        return NULL;
    }
    return realloc(p, new_size);
}

const wk_alloc_backend wk_alloc_libc = {"libc", libc_realloc};

/* The header is a multiple of max_align_t's alignment, so the caller's bytes
** keep malloc's alignment. */
#define DBG_HEAD 32
#define DBG_TAIL 16
#define DBG_WORDS (2 * sizeof(size_t)) /* size and check word */
_Static_assert(DBG_HEAD % _Alignof(max_align_t) == 0, "header breaks alignment");
_Static_assert(DBG_HEAD >= DBG_WORDS + 8, "header too small for its guard bytes");
#define DBG_MAGIC ((size_t)0x5eadb10c5eadb10cULL)
/* Byte patterns: distinct from each other and from zero, so a dump shows
** which region a stray value came from. */
#define DBG_GUARD 0xFD
#define DBG_FRESH 0xA5
#define DBG_FREED 0xDD

/* Misuse found by a check: a bug in the caller, so stop where it shows. */
static _Noreturn void misuse(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static _Noreturn void misuse(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fputs("wskel allocator: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    abort();
}

/* The raw block behind p, after checking it and the caller's old size. */
static unsigned char *dbg_check(void *p, size_t old_size) {
    unsigned char *h = (unsigned char *)p - DBG_HEAD;
    size_t size, check;
    memcpy(&size, h, sizeof size);
    memcpy(&check, h + sizeof size, sizeof check);
    if ((size ^ DBG_MAGIC) != check)
        misuse("block %p (released or resized as %zu bytes): header overwritten (an underrun, "
                "a double free, or a pointer this allocator did not return)",
                p, old_size);
    for (size_t i = DBG_WORDS; i < DBG_HEAD; i++)
        if (h[i] != DBG_GUARD)
            misuse("block of %zu bytes: guard byte %zu before it overwritten (an underrun)", size,
                    (size_t)DBG_HEAD - i);
    for (size_t i = 0; i < DBG_TAIL; i++)
        if (h[DBG_HEAD + size + i] != DBG_GUARD)
            misuse("block of %zu bytes: guard byte %zu after it overwritten (an overrun)", size,
                    i);
    if (old_size != size)
        misuse("block of %zu bytes released or resized as %zu bytes (a wrong old size, e.g. "
                "WK_FREE_ARRAY with the wrong count)",
                size, old_size);
    return h;
}

static void dbg_release(unsigned char *h, size_t size) {
    /* Scrubbed first, so a use after free reads DBG_FREED, not stale data
    ** that happens to look right. */
    memset(h, DBG_FREED, DBG_HEAD + size + DBG_TAIL);
    free(h);
}

static bool dbg_refuse(wk_alloc_debug_state *D) {
    if (!D) return false;
    D->requests++;
    bool no = D->fail_at &&
              (D->requests == D->fail_at || (D->keep_failing && D->requests > D->fail_at));
    D->refused += no;
    return no;
}

static void *dbg_realloc(void *ud, void *p, size_t old_size, size_t new_size) {
    unsigned char *h = p ? dbg_check(p, old_size) : NULL;
    if (new_size == 0) {
        if (h) dbg_release(h, old_size);
        return NULL;
    }
    if (dbg_refuse(ud) || new_size > SIZE_MAX - DBG_HEAD - DBG_TAIL) return NULL;
    /* Always a new block: a caller that kept a pointer into the old one
    ** then reads DBG_FREED (or trips ASan) instead of working by luck. */
    unsigned char *q = malloc(DBG_HEAD + new_size + DBG_TAIL);
    if (!q) return NULL;
    size_t check = new_size ^ DBG_MAGIC;
    memcpy(q, &new_size, sizeof new_size);
    memcpy(q + sizeof new_size, &check, sizeof check);
    memset(q + DBG_WORDS, DBG_GUARD, DBG_HEAD - DBG_WORDS);
    size_t keep = h ? (old_size < new_size ? old_size : new_size) : 0;
    if (keep) memcpy(q + DBG_HEAD, h + DBG_HEAD, keep);
    memset(q + DBG_HEAD + keep, DBG_FRESH, new_size - keep);
    memset(q + DBG_HEAD + new_size, DBG_GUARD, DBG_TAIL);
    if (h) dbg_release(h, old_size);
    return q + DBG_HEAD;
}

const wk_alloc_backend wk_alloc_debug = {"debug", dbg_realloc};

/* ---- allocation ---- */

/* What every 0-byte request returns: never written (it is const, so a write
** faults), never passed to a backend. */
static const max_align_t empty_block;
#define EMPTY ((void *)&empty_block)

static bool refused(const wk_alloc *A, size_t base, size_t new_size) {
    return new_size > MAX_REQUEST || (A->limit && A->live - base + new_size > A->limit) ||
           (A->fail_after >= 0 && A->calls >= (uint64_t)A->fail_after);
}

static void *out_of_memory(wk_run *R, size_t new_size) {
    WK_FAIL(R, WK_ENOMEM, NULL, 0, "out of memory (asked for %zu bytes, %zu live)", new_size,
            R->alloc.live);
    return NULL;
}

void *wk_realloc(wk_run *R, void *p, size_t old_size, size_t new_size) {
    wk_alloc *A = &R->alloc;
    if (p == EMPTY) {
        /* The only size it can have is 0; anything else is a wrong count at
        ** the call site, which checking runs report like the debug
        ** backend's own old-size check. */
        if (old_size != 0 && (A->strict || A->backend == &wk_alloc_debug))
            misuse("empty block (0 bytes) released or resized as %zu bytes (a wrong old size, "
                    "e.g. WK_FREE_ARRAY with the wrong count)",
                    old_size);
        p = NULL;
        old_size = 0;
    }
    if (new_size == 0) {
        if (p) {
            A->backend->realloc(A->ud, p, old_size, 0);
            A->live -= old_size;
            A->blocks--;
        }
        return NULL;
    }
    size_t base = p ? old_size : 0;
    if (refused(A, base, new_size)) return out_of_memory(R, new_size);
    void *q = A->backend->realloc(A->ud, p, base, new_size);
    if (!q) return out_of_memory(R, new_size);
    A->calls++;
    if (!p) A->blocks++;
    A->live = A->live - base + new_size;
    if (A->live > A->peak) A->peak = A->live;
    return q;
}

void *wk_calloc(wk_run *R, size_t count, size_t size) {
    if (size && count > SIZE_MAX / size) {
        WK_FAIL(R, WK_ENOMEM, NULL, 0, "allocation of %zu x %zu bytes overflows", count, size);
        return NULL;
    }
    size_t bytes = count * size;
    if (bytes == 0) {
        /* Still an allocation call, so fault injection reaches the caller's
        ** failure path for empty arrays as it did when they took a block. */
        if (refused(&R->alloc, 0, 0)) return out_of_memory(R, 0);
        R->alloc.calls++;
        return EMPTY;
    }
    void *p = wk_realloc(R, NULL, 0, bytes);
    if (p) memset(p, 0, bytes);
    return p;
}

/* The grow functions' common end: resize p to ncap elements (clamped to
** the 32-bit ids), or fail naming the size and keep p as it was. */
static void *resize_to(wk_run *R, void *p, uint32_t *cap, uint32_t need, uint64_t ncap,
                       size_t elem_size) {
    if (ncap > UINT32_MAX - 1) ncap = UINT32_MAX - 1;
    if (ncap < need || (elem_size && ncap > SIZE_MAX / elem_size)) {
        WK_FAIL(R, WK_ENOMEM, NULL, 0, "array of %u elements of %zu bytes too large", need,
                elem_size);
        return p;
    }
    void *q = wk_realloc(R, p, p ? (size_t)*cap * elem_size : 0, (size_t)ncap * elem_size);
    if (!q) return p;
    *cap = (uint32_t)ncap;
    return q;
}

void *wk_grow_ptr(wk_run *R, void *p, uint32_t *cap, uint32_t need, size_t elem_size) {
    if (need <= *cap && p) return p;
    uint64_t ncap = *cap ? *cap : 8;
    while (ncap < need) ncap *= 2;
    return resize_to(R, p, cap, need, ncap, elem_size);
}

uint64_t wk_grow_capacity(uint32_t cap, uint32_t need, uint32_t hint, uint32_t first) {
    uint64_t ncap = first;
    while (ncap < need || ncap < cap) ncap *= 2;
    if (hint && need <= hint && hint < ncap && hint >= cap) ncap = hint;
    return ncap;
}

void *wk_grow_ptr_hint(wk_run *R, void *p, uint32_t *cap, uint32_t need, size_t elem_size,
                       uint32_t hint) {
    if (need <= *cap && p) return p;
    return resize_to(R, p, cap, need, wk_grow_capacity(*cap, need, hint, 8), elem_size);
}

wk_status wk_grow(wk_run *R, void **pp, uint32_t *cap, uint32_t need, size_t elem_size) {
    *pp = wk_grow_ptr(R, *pp, cap, need, elem_size);
    return *pp && *cap >= need ? WK_OK : WK_ENOMEM;
}
