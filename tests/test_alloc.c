/*
** test_alloc.c: the allocator backends and the run's allocation rules.
**
** The debug backend must catch what it promises to catch: overwritten guard
** bytes on either side, a wrong old size (WK_FREE_ARRAY with the wrong
** count), a leak at a strict wk_run_close; those abort, so each runs in a
** forked child whose stderr is captured and whose death by SIGABRT and
** message (naming the block size, or the live bytes and blocks) are checked.
** Also: the scrub patterns, fault injection (once at N, from N on), empty
** blocks (count 0) leaving no live bytes, WK_GROW growing and, on failure,
** leaving array and capacity unchanged, and the exact_fallbacks counter of
** the polygon checks and the validator.
**
** This file, like every test, is built with WK_CHECKED_RUNS, so wk_run_init
** gives a checked run; (wk_run_init)(&R) is the plain one.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "wskel.h"

/* ---- running a body that should abort ---- */

typedef void (*body_fn)(void);

/* Runs body in a child with stderr captured into msg; true if the child
** died of SIGABRT. */
static bool aborts(body_fn body, char *msg, size_t size) {
    int fd[2];
    cr_assert_eq(pipe(fd), 0);
    fflush(NULL);
    pid_t pid = fork();
    cr_assert_neq(pid, -1);
    if (pid == 0) {
        close(fd[0]);
        dup2(fd[1], 2);
        body();
        _exit(0); /* no abort: the parent sees a normal exit */
    }
    close(fd[1]);
    size_t len = 0;
    ssize_t got;
    while ((got = read(fd[0], msg + len, size - 1 - len)) > 0) len += (size_t)got;
    msg[len] = '\0';
    close(fd[0]);
    int status = 0;
    cr_assert_eq(waitpid(pid, &status, 0), pid);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
}

static void expect_abort(body_fn body, const char *want) {
    char msg[2048];
    cr_assert(aborts(body, msg, sizeof msg), "no abort; stderr: '%s'", msg);
    cr_assert(strstr(msg, want), "message '%s' lacks '%s'", msg, want);
}

static uint64_t exact_fallbacks(const wk_run *R) {
    return R->counters.c[WK_COUNTER_exact_fallbacks];
}

/* ---- backends ---- */

Test(alloc, checked_runs_use_the_debug_backend) {
    wk_run R;
    wk_run_init(&R); /* checked: this file is built with WK_CHECKED_RUNS */
    cr_assert_eq(R.alloc.backend, &wk_alloc_debug);
    cr_assert_str_eq(R.alloc.backend->name, "debug");
    cr_assert(R.alloc.strict);
    (wk_run_init)(&R);
    cr_assert_eq(R.alloc.backend, &wk_alloc_libc, "libc is the default");
    cr_assert_str_eq(R.alloc.backend->name, "libc");
    cr_assert_not(R.alloc.strict);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(alloc, debug_backend_scrubs_and_keeps_contents) {
    wk_run R;
    wk_run_init(&R);
    unsigned char *p = wk_realloc(&R, NULL, 0, 16);
    cr_assert_not_null(p);
    for (int i = 0; i < 16; i++) cr_assert_eq(p[i], 0xA5, "new byte %d", i);
    for (int i = 0; i < 16; i++) p[i] = (unsigned char)i;
    unsigned char *q = wk_realloc(&R, p, 16, 40);
    cr_assert_not_null(q);
    cr_assert_neq(q, p, "a resize moves the block");
    for (int i = 0; i < 16; i++) cr_assert_eq(q[i], i, "kept byte %d", i);
    for (int i = 16; i < 40; i++) cr_assert_eq(q[i], 0xA5, "grown byte %d", i);
    q = wk_realloc(&R, q, 40, 8);
    for (int i = 0; i < 8; i++) cr_assert_eq(q[i], i, "kept after shrinking, byte %d", i);
    cr_assert_eq(R.alloc.live, 8, "the header and guards are not counted");
    wk_realloc(&R, q, 8, 0);
    double *z = WK_NEW_ARRAY(&R, double, 5);
    for (int i = 0; i < 5; i++) cr_assert_eq(z[i], 0.0, "wk_calloc still zeroes");
    WK_FREE_ARRAY(&R, z, 5);
    cr_assert_eq(wk_run_close(&R), 0);
}

static void overrun(void) {
    wk_run R;
    wk_run_init(&R);
    char *p = WK_NEW_ARRAY(&R, char, 24);
    p[24] = 'x'; /* one past the end: inside the tail guard */
    WK_FREE_ARRAY(&R, p, 24);
}

static void underrun(void) {
    wk_run R;
    wk_run_init(&R);
    char *p = WK_NEW_ARRAY(&R, char, 24);
    p[-1] = 'x';
    WK_FREE_ARRAY(&R, p, 24);
}

static void overrun_then_grow(void) {
    wk_run R;
    wk_run_init(&R);
    uint32_t *v = NULL, cap = 0;
    (void)WK_GROW(&R, v, cap, 8);
    v[cap + 1] = 7;
    (void)WK_GROW(&R, v, cap, cap + 1); /* the resize checks the old block */
}

Test(alloc, guard_bytes_catch_overruns_and_underruns) {
    expect_abort(overrun, "block of 24 bytes: guard byte 0 after it overwritten");
    expect_abort(underrun, "block of 24 bytes: guard byte 1 before it overwritten");
    expect_abort(overrun_then_grow, "block of 32 bytes: guard byte 4 after it overwritten");
}

static void wrong_count(void) {
    wk_run R;
    wk_run_init(&R);
    double *p = WK_NEW_ARRAY(&R, double, 10);
    WK_FREE_ARRAY(&R, p, 9);
}

static void wrong_resize(void) {
    wk_run R;
    wk_run_init(&R);
    void *p = wk_realloc(&R, NULL, 0, 100);
    (void)wk_realloc(&R, p, 64, 200);
}

static void wrong_count_of_empty(void) {
    wk_run R;
    wk_run_init(&R);
    uint32_t *p = WK_NEW_ARRAY(&R, uint32_t, 0);
    WK_FREE_ARRAY(&R, p, 3);
}

Test(alloc, wrong_old_size_aborts) {
    expect_abort(wrong_count, "block of 80 bytes released or resized as 72 bytes");
    expect_abort(wrong_resize, "block of 100 bytes released or resized as 64 bytes");
    expect_abort(wrong_count_of_empty, "empty block (0 bytes) released or resized as 12 bytes");
}

static void leak(void) {
    wk_run R;
    wk_run_init(&R);
    (void)WK_NEW_ARRAY(&R, double, 3);
    (void)WK_NEW_ARRAY(&R, char, 5);
    wk_run_close(&R);
}

static void clean(void) {
    wk_run R;
    wk_run_init(&R);
    double *p = WK_NEW_ARRAY(&R, double, 3);
    WK_FREE_ARRAY(&R, p, 3);
    wk_run_close(&R);
}

Test(alloc, strict_close_aborts_on_a_leak) {
    expect_abort(leak, "29 bytes in 2 blocks still live");
    char msg[256];
    cr_assert_not(aborts(clean, msg, sizeof msg), "a clean run closes: %s", msg);
    /* Not strict: the live bytes are returned, as before. */
    wk_run R;
    (wk_run_init)(&R);
    double *p = WK_NEW_ARRAY(&R, double, 3);
    cr_assert_eq(wk_run_close(&R), 24);
    WK_FREE_ARRAY(&R, p, 3);
    cr_assert_eq(wk_run_close(&R), 0);
}

/* ---- fault injection ---- */

Test(alloc, debug_fault_injection_fails_once_at_n) {
    wk_run R;
    wk_run_init(&R);
    wk_alloc_debug_state D = {.fail_at = 3};
    R.alloc.ud = &D;
    char *p[5];
    for (int i = 0; i < 5; i++) p[i] = WK_NEW_ARRAY(&R, char, 10);
    for (int i = 0; i < 5; i++) cr_assert_eq(p[i] == NULL, i == 2, "allocation %d", i + 1);
    cr_assert_eq(R.err.code, WK_ENOMEM);
    cr_assert_eq(D.requests, 5);
    cr_assert_eq(D.refused, 1);
    cr_assert_eq(R.alloc.live, 40, "the refused request changed no statistic");
    cr_assert_eq(R.alloc.blocks, 4);
    for (int i = 0; i < 5; i++)
        if (p[i]) WK_FREE_ARRAY(&R, p[i], 10);
    cr_assert_eq(D.requests, 5, "frees are not requests");
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(alloc, debug_fault_injection_fails_from_n_on) {
    wk_run R;
    wk_run_init(&R);
    wk_alloc_debug_state D = {.fail_at = 3, .keep_failing = true};
    R.alloc.ud = &D;
    char *p[5];
    for (int i = 0; i < 5; i++) p[i] = WK_NEW_ARRAY(&R, char, 10);
    for (int i = 0; i < 5; i++) cr_assert_eq(p[i] == NULL, i >= 2, "allocation %d", i + 1);
    cr_assert_eq(D.refused, 3);
    /* A refused resize keeps the block: contents and size. */
    memset(p[0], 'a', 10);
    cr_assert_null(wk_realloc(&R, p[0], 10, 20));
    for (int i = 0; i < 10; i++) cr_assert_eq(p[0][i], 'a');
    WK_FREE_ARRAY(&R, p[0], 10); /* still 10 bytes: the old-size check agrees */
    WK_FREE_ARRAY(&R, p[1], 10);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(alloc, run_level_fail_after_still_counts_calls) {
    wk_run R;
    wk_run_init(&R);
    R.alloc.fail_after = 1;
    uint32_t *e = WK_NEW_ARRAY(&R, uint32_t, 0); /* an empty array is still a call */
    cr_assert_not_null(e);
    cr_assert_null(WK_NEW_ARRAY(&R, uint32_t, 0), "the second call fails");
    cr_assert_eq(R.err.code, WK_ENOMEM);
    WK_FREE_ARRAY(&R, e, 0);
    cr_assert_eq(wk_run_close(&R), 0);
}

/* ---- empty blocks ---- */

Test(alloc, empty_blocks_leave_no_live_bytes) {
    wk_run R;
    wk_run_init(&R);
    double *a = WK_NEW_ARRAY(&R, double, 0);
    char *b = wk_calloc(&R, 7, 0);
    cr_assert(a && b, "empty arrays are not NULL (NULL means failure)");
    cr_assert_eq(R.alloc.live, 0);
    cr_assert_eq(R.alloc.blocks, 0);
    cr_assert_eq(R.alloc.calls, 2);
    cr_assert_eq(R.err.code, WK_OK);
    WK_FREE_ARRAY(&R, a, 0);
    wk_realloc(&R, b, 0, 0);
    cr_assert_null(a);
    cr_assert_eq(R.alloc.live, 0);

    /* Growing an empty array is a fresh allocation. */
    uint32_t *v = WK_NEW_ARRAY(&R, uint32_t, 0), cap = 0;
    cr_assert_eq(WK_GROW(&R, v, cap, 1), WK_OK);
    cr_assert_eq(cap, 8);
    cr_assert_eq(R.alloc.live, 8 * sizeof *v);
    cr_assert_eq(R.alloc.blocks, 1);
    v[7] = 1;
    WK_FREE_ARRAY(&R, v, cap);
    cr_assert_eq(wk_run_close(&R), 0);
}

/* ---- WK_GROW ---- */

typedef struct triple { double a, b, c; } triple;

Test(alloc, grow_doubles_keeps_contents_and_is_typed) {
    wk_run R;
    wk_run_init(&R);
    triple *t = NULL;
    uint32_t cap = 0, seen_caps = 0, last = 0;
    for (uint32_t i = 0; i < 100; i++) {
        cr_assert_eq(WK_GROW(&R, t, cap, i + 1), WK_OK);
        if (cap != last) {
            seen_caps++;
            last = cap;
        }
        t[i] = (triple){i, 2.0 * i, 3.0 * i};
    }
    cr_assert_eq(cap, 128);
    cr_assert_eq(seen_caps, 5, "8, 16, 32, 64, 128");
    for (uint32_t i = 0; i < 100; i++) cr_assert_eq(t[i].c, 3.0 * i);
    triple *same = t;
    cr_assert_eq(WK_GROW(&R, t, cap, 128), WK_OK);
    cr_assert_eq(t, same, "no resize when it fits");
    cr_assert_eq(WK_GROW(&R, t, cap, 1000), WK_OK);
    cr_assert_eq(cap, 1024, "doubles until it fits");
    cr_assert_eq(R.alloc.live, 1024 * sizeof *t);
    WK_FREE_ARRAY(&R, t, cap);

    /* wk_grow on a genuine void * object. */
    void *raw = NULL;
    uint32_t rcap = 0;
    cr_assert_eq(wk_grow(&R, &raw, &rcap, 20, 4), WK_OK);
    cr_assert_eq(rcap, 32);
    wk_realloc(&R, raw, (size_t)rcap * 4, 0);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(alloc, failed_grow_leaves_array_and_cap_unchanged) {
    wk_run R;
    wk_run_init(&R);
    wk_alloc_debug_state D = {0};
    R.alloc.ud = &D;
    uint32_t *v = NULL, cap = 0;
    cr_assert_eq(WK_GROW(&R, v, cap, 8), WK_OK);
    for (uint32_t i = 0; i < 8; i++) v[i] = 100 + i;
    uint32_t *before = v;
    size_t live = R.alloc.live;

    D.fail_at = D.requests + 1; /* the backend refuses the resize */
    cr_assert_eq(WK_GROW(&R, v, cap, 9), WK_ENOMEM);
    cr_assert_eq(v, before);
    cr_assert_eq(cap, 8);
    cr_assert_eq(R.alloc.live, live);
    for (uint32_t i = 0; i < 8; i++) cr_assert_eq(v[i], 100 + i);
    cr_assert_eq(R.err.code, WK_ENOMEM);

    wk_run_clear_error(&R);
    R.alloc.limit = live + 4; /* the run refuses it */
    cr_assert_eq(WK_GROW(&R, v, cap, 9), WK_ENOMEM);
    cr_assert_eq(v, before);
    cr_assert_eq(cap, 8);

    wk_run_clear_error(&R);
    uint32_t huge = UINT32_MAX; /* beyond any capacity */
    cr_assert_eq(WK_GROW(&R, v, cap, huge), WK_ENOMEM);
    cr_assert_eq(v, before);
    cr_assert_eq(cap, 8);

    R.alloc.limit = 0;
    cr_assert_eq(WK_GROW(&R, v, cap, 9), WK_OK, "works again once memory is there");
    cr_assert_eq(cap, 16);
    for (uint32_t i = 0; i < 8; i++) cr_assert_eq(v[i], 100 + i);
    WK_FREE_ARRAY(&R, v, cap);

    /* A first allocation that fails leaves NULL and 0. */
    D.fail_at = D.requests + 1;
    uint32_t *w = NULL, wcap = 0;
    cr_assert_eq(WK_GROW(&R, w, wcap, 1), WK_ENOMEM);
    cr_assert_null(w);
    cr_assert_eq(wcap, 0);
    cr_assert_eq(wk_run_close(&R), 0);
}

/* ---- exact_fallbacks ---- */

Test(alloc, segments_meet_ex_reports_exact_stages) {
    uint32_t k = 99;
    wk_point a = {0, 0}, b = {2, 2}, c = {1, 1}, d = {3, 3};
    cr_assert_eq(wk_segments_meet_ex(a, b, c, d, &k), WK_SEG_OVERLAP);
    cr_assert_eq(k, 4, "four collinear tests, none decided by the filter");
    wk_point e = {0, 2}, f = {2, 0};
    cr_assert_eq(wk_segments_meet_ex(a, b, e, f, &k), WK_SEG_CROSS);
    cr_assert_eq(k, 0);
    cr_assert_eq(wk_segments_meet_ex(a, b, e, f, NULL), WK_SEG_CROSS);
}

Test(alloc, polygon_checks_count_exact_fallbacks) {
    /* Vertex 3 is straight on a diagonal, (2,2) (1,1) (0,0): exactly
    ** collinear with nonzero products, which the filter cannot decide. */
    static const double cx[] = {0, 2, 2, 1}, cy[] = {0, 0, 2, 1};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_from_arrays(&R, 4, cx, cy, NULL, "c.wpoly", NULL, &P), WK_OK);
    uint64_t built = exact_fallbacks(&R);
    cr_assert_gt(built, 0, "collinear vertex: exact stages counted");
    cr_assert_eq(wk_polygon_validate(&R, P), WK_OK);
    cr_assert_gt(exact_fallbacks(&R), built, "wk_polygon_validate counts too");
    wk_polygon_free(&R, P);
    cr_assert_eq(wk_run_close(&R), 0);

    /* A generic polygon: every test is decided by the filter. */
    static const double gx[] = {0, 3, 2.5, 0.3, 1.1}, gy[] = {0, 0.5, 2.7, 1.9, 0.9};
    wk_run_init(&R);
    cr_assert_eq(wk_polygon_from_arrays(&R, 5, gx, gy, NULL, "g.wpoly", NULL, &P), WK_OK);
    cr_assert_eq(wk_polygon_validate(&R, P), WK_OK);
    cr_assert_eq(exact_fallbacks(&R), 0);
    wk_polygon_free(&R, P);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(alloc, validator_counts_exact_fallbacks) {
    /* The skeleton of the unit square, checked as given: the node (0.5, 0.5)
    ** lies exactly on both diagonals, so face sides meet collinearly. */
    static const double sx[] = {0, 1, 1, 0}, sy[] = {0, 0, 1, 1};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_from_arrays(&R, 4, sx, sy, NULL, "s.wpoly", NULL, &P), WK_OK);
    uint64_t before = exact_fallbacks(&R);
    wk_skeleton *S = NULL;
    cr_assert_eq(wk_solve(&R, wk_variant_reference(), P, &S, NULL, NULL), WK_OK);
    cr_assert_eq(wk_validate(&R, P, S, 0, NULL), WK_OK);
    cr_assert_gt(exact_fallbacks(&R), before, "validator: exact stages counted");
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    cr_assert_eq(wk_run_close(&R), 0);
}
