/*
** run.c: the run context: counting allocator, first-error record, the
** counting observer and wk_solve.
**
** Invariants: alloc.live is the sum of the sizes of the blocks handed out and
** not yet freed (callers pass the old size, as in Lua, so no headers);
** alloc.peak >= alloc.live; err.code != WK_OK once any failure was recorded,
** and later failures never overwrite the first.
*/
#define _POSIX_C_SOURCE 200809L
#include "wskel.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void *libc_realloc(void *ud, void *p, size_t old_size, size_t new_size) {
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        free(p);
        return NULL;
    }
    return realloc(p, new_size);
}

/* ---- counting observer: the only writer of wk_counters ---- */

static void count_event(void *ud, wk_event_kind kind, const wk_event *e) {
    wk_counters *c = ud;
    switch (kind) {
    case WK_EV_EDGE: c->edge_events++; break;
    case WK_EV_SPLIT: c->split_events++; break;
    case WK_EV_MULTI_SPLIT: c->multi_split_events++; break;
    case WK_EV_SWITCH: c->switch_events++; break;
    case WK_EV_START: c->start_events++; break;
    case WK_EV_REFLEX_EDGE: c->reflex_preserving_edge_events++; break;
    case WK_EV_VANISH: c->vanishing_components++; break;
    case WK_EV_GROUP: c->simultaneous_event_groups++; break;
    case WK_EV_COLLINEAR: c->collinear_resolutions++; break;
    case WK_EV_CHAIN_EDGE:
        c->edge_events++;
        if (e->c == 0) c->chain_edge_events_lower++;
        else c->chain_edge_events_upper++;
        break;
    case WK_EV_MERGE_VERTEX: c->merge_chain_vertices++; break;
    case WK_EV_MERGE_CELL: c->merge_cells_visited++; break;
    case WK_EV_FALLBACK: c->reference_fallbacks++; break;
    case WK_EV_BRUTE_SPLIT: c->brute_force_split_scans++; break;
    case WK_EV_KIND_COUNT: break;
    }
}
static void count_queue(void *ud, wk_queue_op op) {
    wk_counters *c = ud;
    switch (op) {
    case WK_Q_PUSH: c->queue_pushes++; break;
    case WK_Q_POP: c->queue_pops++; break;
    case WK_Q_UPDATE: c->queue_updates++; break;
    case WK_Q_REMOVE: c->queue_removes++; break;
    }
}
static void count_cache(void *ud, wk_cache_op op) {
    wk_counters *c = ud;
    switch (op) {
    case WK_C_HIT: c->cache_hits++; break;
    case WK_C_MISS: c->cache_misses++; break;
    case WK_C_REFILL: c->cache_refills++; break;
    case WK_C_INVALIDATE: c->cache_invalidations++; break;
    }
}
static void count_arrangement(void *ud, wk_arr_op op, uint64_t n) {
    wk_counters *c = ud;
    switch (op) {
    case WK_A_INSERT: c->arrangement_inserts += n; break;
    case WK_A_REMOVE: c->arrangement_removes += n; break;
    case WK_A_QUERY: c->intersection_queries += n; break;
    case WK_A_SCANNED: c->segments_scanned += n; break;
    case WK_A_INITIAL_CROSSING: c->arrangement_crossings_initial += n; break;
    }
}
static void count_exact(void *ud) { ((wk_counters *)ud)->exact_fallbacks++; }
static void count_stale(void *ud) { ((wk_counters *)ud)->stale_events++; }

const wk_observer wk_observer_counting = {
    count_event, count_queue, count_cache, count_arrangement, count_exact, count_stale, NULL,
};

/* ---- run ---- */

void wk_run_init(wk_run *R) {
    memset(R, 0, sizeof *R);
    R->alloc.fn = libc_realloc;
    R->alloc.fail_after = -1;
    R->obs = &wk_observer_counting;
    R->obs_ud = &R->counters;
    R->opt.variant = "naive";
    R->opt.k = 1;
    R->opt.collinear = WK_COLLINEAR_LOWER;
    R->opt.threads = 1;
    R->err.code = WK_OK;
}

size_t wk_run_close(wk_run *R) { return R->alloc.live; }

void wk_run_reset_peak(wk_run *R) { R->alloc.peak = R->alloc.live; }

wk_status wk_fail(wk_run *R, wk_status code, const char *input, long input_line,
                  const char *src_file, int src_line, const char *fmt, ...) {
    if (R->err.code != WK_OK) return code; /* the first failure wins */
    R->err.code = code;
    snprintf(R->err.input, sizeof R->err.input, "%s", input ? input : "");
    R->err.input_line = input_line;
    R->err.src_file = src_file;
    R->err.src_line = src_line;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(R->err.msg, sizeof R->err.msg, fmt, ap);
    va_end(ap);
    return code;
}

void wk_error_format(const wk_run *R, char *buf, size_t size) {
    const wk_error *e = &R->err;
    if (e->input[0] && e->input_line > 0)
        snprintf(buf, size, "%s:%ld: %s", e->input, e->input_line, e->msg);
    else if (e->input[0])
        snprintf(buf, size, "%s: %s", e->input, e->msg);
    else
        snprintf(buf, size, "%s", e->msg);
}

int wk_status_exit_code(wk_status s) {
    switch (s) {
    case WK_OK: return 0;
    case WK_EINPUT: return 1;
    case WK_ENOMEM: return 2;
    case WK_EALGO: return 2;
    case WK_EUNSUPPORTED: return 2;
    case WK_EINVALID: return 3;
    case WK_EUSAGE: return 64;
    }
    return 2;
}

const char *wk_status_name(wk_status s) {
    switch (s) {
    case WK_OK: return "ok";
    case WK_EINPUT: return "input rejected";
    case WK_ENOMEM: return "out of memory";
    case WK_EALGO: return "algorithm failed";
    case WK_EUNSUPPORTED: return "unsupported by this variant";
    case WK_EINVALID: return "invalid output";
    case WK_EUSAGE: return "usage";
    }
    return "unknown";
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

/* ---- solve ---- */

wk_status wk_solve(wk_run *R, const wk_variant *V, const wk_polygon *P, wk_skeleton **out,
                   double *time_s, size_t *peak_bytes) {
    *out = NULL;
    size_t live0 = R->alloc.live;
    wk_run_reset_peak(R);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    wk_status st = V->run(R, P, out);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if (time_s) *time_s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    if (peak_bytes) *peak_bytes = R->alloc.peak - live0;
    if (st != WK_OK) {
        /* Never half-return (CGAL): no skeleton on failure. */
        if (*out) wk_skeleton_free(R, *out);
        *out = NULL;
        if (R->err.code == WK_OK) WK_FAIL(R, st, NULL, 0, "variant %s failed", V->name);
    }
    if (R->obs->finished) R->obs->finished(R->obs_ud, st == WK_OK);
    return st;
}
