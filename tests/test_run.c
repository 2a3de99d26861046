/*
** test_run.c: the run context: byte counting, peak high-water mark and its
** reset, the memory limit, fault injection, overflow checks, the first error
** winning, error formatting and the counting observer.
*/
#include <criterion/criterion.h>

#include <string.h>

#include "wskel.h"
#include "helpers.h"

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
    wk_notify_event(&R, WK_COUNTER_edge_events, &e);
    wk_notify_event(&R, WK_COUNTER_edge_events, &e);
    wk_notify_event(&R, WK_COUNTER_split_events, &e);
    wk_count(&R, WK_COUNTER_queue_pushes, 7);
    wk_count(&R, WK_ENGINE_COUNTERS + 2, 3); /* a variant's third counter */
    cr_assert_eq(counter(&R, "edge_events"), 2);
    cr_assert_eq(counter(&R, "split_events"), 1);
    cr_assert_eq(counter(&R, "queue_pushes"), 7);
    uint64_t v = 0;
    cr_assert(!wk_counter_lookup(&R, "cache_hits", &v), "no variant yet: engine counters only");
    R.variant = wk_variant_find("arrangement");
    cr_assert(wk_counter_lookup(&R, wk_counter_def_at(R.variant, WK_ENGINE_COUNTERS + 2)->name, &v));
    cr_assert_eq(v, 3);
    cr_assert(!wk_counter_lookup(&R, "chain_edge_events_lower", &v), "not an arrangement counter");
    cr_assert_eq(wk_run_close(&R), 0);
}

Test(run, registry_lists_naive) {
    const wk_variant *V = wk_variant_find("naive");
    cr_assert_not_null(V);
    cr_assert(wk_variant_flags(V) & WK_VARIANT_WEIGHTS);
    cr_assert_eq(wk_variant_reference(), V);
    cr_assert_null(wk_variant_find("no-such-variant"));
    cr_assert_eq(wk_variant_at(0), V);
}

Test(run, counter_union_lists_every_name_once) {
    const char *names[256];
    uint32_t n = wk_counter_union(names, 256);
    cr_assert_leq(n, 256);
    cr_assert_geq(n, WK_ENGINE_COUNTERS);
    for (uint32_t i = 0; i < WK_ENGINE_COUNTERS; i++)
        cr_assert_str_eq(names[i], wk_counter_def_at(NULL, i)->name, "engine counters come first");
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) cr_assert_str_neq(names[i], names[j]);
    /* every counter of every variant is a column */
    for (size_t v = 0; wk_variant_at(v); v++) {
        const wk_variant *V = wk_variant_at(v);
        for (uint32_t id = 0; id < wk_counter_count(V); id++) {
            bool found = false;
            for (uint32_t i = 0; i < n && !found; i++)
                found = !strcmp(names[i], wk_counter_def_at(V, id)->name);
            cr_assert(found, "%s of %s missing", wk_counter_def_at(V, id)->name, wk_variant_name(V));
            cr_assert(wk_counter_def_at(V, id)->meaning[0], "a counter without a meaning");
        }
        cr_assert_null(wk_counter_def_at(V, wk_counter_count(V)));
    }
}
