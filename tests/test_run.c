/*
** test_run.c: the run context: byte counting, peak high-water mark and its
** reset, the memory limit, fault injection, overflow checks, the first error
** winning, error formatting and the counting observer.
*/
#include <criterion/criterion.h>

#include <string.h>

#include "wskel.h"

Test(run, counts_live_and_peak_bytes) {
    wk_run R;
    wk_run_init(&R);
    double *a = WK_NEW_ARRAY(&R, double, 100);
    cr_assert_not_null(a);
    cr_assert_eq(R.alloc.live, 800);
    char *b = WK_NEW_ARRAY(&R, char, 200);
    cr_assert_eq(R.alloc.live, 1000);
    cr_assert_eq(R.alloc.peak, 1000);
    WK_FREE_ARRAY(&R, a, 100);
    cr_assert_null(a);
    cr_assert_eq(R.alloc.live, 200);
    cr_assert_eq(R.alloc.peak, 1000);
    wk_run_reset_peak(&R);
    cr_assert_eq(R.alloc.peak, 200);
    WK_FREE_ARRAY(&R, b, 200);
    cr_assert_eq(R.alloc.blocks, 0);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, grow_doubles_and_keeps_contents) {
    wk_run R;
    wk_run_init(&R);
    uint32_t *v = NULL, cap = 0;
    for (uint32_t i = 0; i < 1000; i++) {
        cr_assert_eq(WK_GROW(&R, v, cap, i + 1), WK_OK);
        v[i] = i * 3;
    }
    cr_assert_geq(cap, 1000);
    for (uint32_t i = 0; i < 1000; i++) cr_assert_eq(v[i], i * 3);
    cr_assert_eq(R.alloc.live, cap * sizeof *v);
    WK_FREE_ARRAY(&R, v, cap);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, memory_limit_and_fault_injection) {
    wk_run R;
    wk_run_init(&R);
    R.alloc.limit = 1000;
    char *a = WK_NEW_ARRAY(&R, char, 600);
    cr_assert_not_null(a);
    char *b = WK_NEW_ARRAY(&R, char, 600);
    cr_assert_null(b);
    cr_assert_eq(R.err.code, WK_ENOMEM);
    WK_FREE_ARRAY(&R, a, 600);
    cr_assert_eq(wk_run_close(&R), 0);

    wk_run_init(&R);
    R.alloc.fail_after = 2;
    void *p1 = wk_calloc(&R, 1, 8), *p2 = wk_calloc(&R, 1, 8), *p3 = wk_calloc(&R, 1, 8);
    cr_assert(p1 && p2 && !p3);
    wk_realloc(&R, p1, 8, 0);
    wk_realloc(&R, p2, 8, 0);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, overflowing_sizes_are_refused) {
    wk_run R;
    wk_run_init(&R);
    void *p = wk_calloc(&R, SIZE_MAX / 2, 4);
    cr_assert_null(p);
    cr_assert_eq(R.err.code, WK_ENOMEM);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, first_error_wins_and_formats_like_lua) {
    wk_run R;
    wk_run_init(&R);
    cr_assert_eq(WK_FAIL(&R, WK_EINPUT, "star.wpoly", 17, "weight of edge %d must be > 0 (got %g)",
                         15, -1.0),
                 WK_EINPUT);
    cr_assert_eq(WK_FAIL(&R, WK_EALGO, "x", 1, "later"), WK_EALGO);
    char buf[256];
    wk_error_format(&R, buf, sizeof buf);
    cr_assert_str_eq(buf, "star.wpoly:17: weight of edge 15 must be > 0 (got -1)");
    cr_assert_eq(R.err.code, WK_EINPUT);
    cr_assert_eq(wk_status_exit_code(WK_EINPUT), 1);
    cr_assert_eq(wk_status_exit_code(WK_EALGO), 2);
    cr_assert_eq(wk_status_exit_code(WK_ENOMEM), 2);
    cr_assert_eq(wk_status_exit_code(WK_EINVALID), 3);
    cr_assert_eq(wk_status_exit_code(WK_EUSAGE), 64);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, counting_observer_counts_by_kind) {
    wk_run R;
    wk_run_init(&R);
    wk_event e = {0, 0, 0, 0, 0, 0};
    wk_notify_event(&R, WK_EV_EDGE, &e);
    wk_notify_event(&R, WK_EV_EDGE, &e);
    wk_notify_event(&R, WK_EV_SPLIT, &e);
    wk_notify_arrangement(&R, WK_A_SCANNED, 7);
    wk_notify_cache(&R, WK_C_HIT);
    cr_assert_eq(R.counters.edge_events, 2);
    cr_assert_eq(R.counters.split_events, 1);
    cr_assert_eq(R.counters.segments_scanned, 7);
    cr_assert_eq(R.counters.cache_hits, 1);
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, registry_lists_naive) {
    const wk_variant *V = wk_variant_find("naive");
    cr_assert_not_null(V);
    cr_assert(V->flags & WK_VARIANT_WEIGHTS);
    cr_assert_null(wk_variant_find("no-such-variant"));
    cr_assert_eq(wk_variant_at(0), V);
}
