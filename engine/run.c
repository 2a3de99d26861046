/*
** run.c: the run context: first-error record, status names and
** wk_solve (the allocator is alloc.c, the counting observer counters.c).
**
** Invariants: alloc.live is the sum of the sizes of the blocks handed out and
** not yet freed (callers pass the old size, as in Lua, so no headers);
** alloc.peak >= alloc.live; err.code != WK_OK once any failure was recorded,
** and later failures never overwrite the first; a strict run closes with
** live == blocks == 0 or not at all (it aborts).
*/
#define _POSIX_C_SOURCE 200809L
#include "variant.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- run ---- */

/* Parenthesised name: a file built with WK_CHECKED_RUNS (where wk_run_init is
** a macro) can still define the function. */
void (wk_run_init)(wk_run *R) {
    memset(R, 0, sizeof *R);
    R->alloc.backend = &wk_alloc_libc;
    R->alloc.fail_after = -1;
    R->obs = &wk_observer_counting;
    R->obs_ud = &R->counters;
    R->opt.k = 1;
    R->opt.collinear = WK_COLLINEAR_LOWER;
    R->opt.threads = 1;
    R->opt.tol_scale = 1;
    R->opt.part = WK_NONE;
    R->opt.step_scale = 1;
    R->err.code = WK_OK;
}

void wk_run_init_checked(wk_run *R) {
    (wk_run_init)(R);
    R->alloc.backend = &wk_alloc_debug;
    R->alloc.strict = true;
}

size_t wk_run_close(wk_run *R) {
    const wk_alloc *A = &R->alloc;
    if (A->strict && (A->live || A->blocks)) {
        /* A leak (or a free with the wrong size) caught where the run ends,
        ** not at the test's assertion, which a leaking error path may skip. */
        fprintf(stderr,
                "wskel: wk_run_close: %zu bytes in %zu blocks still live (a leak, or a free "
                "with the wrong size)\n",
                A->live, A->blocks);
        abort();
    }
    return A->live;
}

void wk_run_reset_peak(wk_run *R) { R->alloc.peak = R->alloc.live; }

void wk_run_clear_error(wk_run *R) {
    memset(&R->err, 0, sizeof R->err);
    R->err.code = WK_OK;
}

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

/* ---- solve ---- */

double wk_clock_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

wk_status wk_solve(wk_run *R, const wk_variant *V, const wk_polygon *P, wk_skeleton **out,
                   double *time_s, size_t *peak_bytes) {
    *out = NULL;
    size_t live0 = R->alloc.live;
    wk_run_reset_peak(R);
    R->variant = V;
    R->phase_s = 0;
    R->fallback_reason[0] = '\0';
    if (P->pslg && !(V->flags & WK_VARIANT_PSLG)) {
        const char *able = wk_variant_with_flags(WK_VARIANT_PSLG);
        wk_status st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                               "variant %s does not take PSLG input (a graph that is not disjoint "
                               "simple cycles); %s does",
                               V->name, able ? able : "(none registered)");
        if (R->obs->finished) R->obs->finished(R->obs_ud, false);
        return st;
    }
    /* A variant without WK_VARIANT_WEIGHTS takes equal weights: one weight w
    ** for every edge is the unit-weight skeleton with its times divided by
    ** w, so it needs nothing of the variant.  Unequal weights are refused
    ** here, for library callers as for the CLI (the CLI refused every
    ** weight other than 1, equal ones too, which such a variant solves). */
    if (!(V->flags & WK_VARIANT_WEIGHTS))
        for (uint32_t i = 1; i < P->n; i++)
            if (P->w[i] != P->w[0]) {
                const char *able = wk_variant_with_flags(WK_VARIANT_WEIGHTS);
                wk_status st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                                       "variant %s supports equal weights only (edge %u has weight "
                                       "%g, edge %u %g); %s takes unequal weights",
                                       V->name, wk_polygon_input_edge(P, i), P->w[i],
                                       wk_polygon_input_edge(P, 0), P->w[0],
                                       able ? able : "(none registered)");
                if (R->obs->finished) R->obs->finished(R->obs_ud, false);
                return st;
            }
    double t0 = wk_clock_s();
    wk_status st = V->run(R, P, out);
    if (time_s) *time_s = wk_clock_s() - t0;
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

wk_status wk_solve_checked(wk_run *R, const wk_variant *V, const wk_polygon *P, double tol,
                           wk_skeleton **out, double *time_s, size_t *peak_bytes,
                           wk_validate_report *rep) {
    *out = NULL;
    double total_s = 0, phase_s = 0, scale0 = R->opt.tol_scale;
    size_t peak = 0;
    wk_error first;
    wk_status st = WK_OK;
    /* reference_fallbacks adds up over the rungs, so the reason of the first
    ** hand-over is kept over them too (each wk_solve starts afresh): a run
    ** answered on a later rung still says why an earlier rung's own run gave
    ** up (a moved glyph printed the counter without a reason). */
    char reason[sizeof R->fallback_reason] = "";
    /* The ladder: the given tolerances, then coarser ones up to
    ** WK_TOL_ESCALATE_MAX, then finer ones down to WK_TOL_REFINE_MIN
    ** (tolerance.h says when each helps).  A first attempt that succeeds
    ** costs nothing extra, and the order keeps every earlier answer. */
    double ladder[16];
    int rungs = 0;
    for (double s = 1; s <= WK_TOL_ESCALATE_MAX && rungs < 8; s *= WK_TOL_ESCALATE_STEP)
        ladder[rungs++] = s;
    for (double s = 1 / WK_TOL_ESCALATE_STEP; s >= WK_TOL_REFINE_MIN && rungs < 16;
         s /= WK_TOL_ESCALATE_STEP)
        ladder[rungs++] = s;
    for (int i = 0; i < rungs; i++) {
        double t_s = 0;
        size_t pk = 0;
        R->opt.tol_scale = scale0 * ladder[i];
        st = wk_solve(R, V, P, out, &t_s, &pk);
        total_s += t_s;
        phase_s += R->phase_s;
        if (!reason[0] && R->fallback_reason[0]) {
            if (ladder[i] == 1) memcpy(reason, R->fallback_reason, sizeof reason);
            else
                snprintf(reason, sizeof reason, "(tolerance x %g) %.600s", ladder[i],
                         R->fallback_reason);
        }
        if (pk > peak) peak = pk;
        if (st == WK_OK && (st = wk_validate(R, P, *out, tol, rep)) != WK_OK) {
            wk_skeleton_free(R, *out);
            *out = NULL;
        }
        if (i == 0) first = R->err;
        if (st == WK_OK || (st != WK_EALGO && st != WK_EINVALID) || i + 1 == rungs) break;
        wk_run_clear_error(R);
        wk_count(R, WK_COUNTER_tolerance_escalations, 1);
    }
    R->opt.tol_scale = scale0;
    R->phase_s = phase_s;
    memcpy(R->fallback_reason, reason, sizeof reason);
    if (st != WK_OK) R->err = first; /* the first attempt says what went wrong */
    if (time_s) *time_s = total_s;
    if (peak_bytes) *peak_bytes = peak;
    return st == WK_OK ? WK_OK : R->err.code;
}

wk_status wk_solve_by_reference(wk_run *R, const wk_polygon *P, uint32_t counter,
                                wk_skeleton **out) {
    *out = NULL;
    if (R->err.code != WK_OK && !R->fallback_reason[0]) {
        const char *src = R->err.src_file ? strrchr(R->err.src_file, '/') : NULL;
        snprintf(R->fallback_reason, sizeof R->fallback_reason, "%s:%d: %s",
                 src ? src + 1 : R->err.src_file ? R->err.src_file : "?", R->err.src_line,
                 R->err.msg);
    }
    wk_run_clear_error(R);
    wk_event ev = {0, 0, 0, WK_NONE, WK_NONE, WK_NONE};
    wk_notify_event(R, counter, &ev);
    wk_status st = wk_variant_reference()->run(R, P, out);
    if (st == WK_OK && (st = wk_validate(R, P, *out, 0, NULL)) != WK_OK) {
        wk_skeleton_free(R, *out);
        *out = NULL;
    }
    return st;
}
