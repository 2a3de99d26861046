/*
** test_variant_arrangement.c: the arrangement variant against the reference.
** For every generator family, sizes up to 500, unit and random weights and
** k in {1, 2, 7, max}: the skeleton passes the validator and equals naive's
** (same nodes within tolerance, same arcs between them with the same faces).
** The skeleton must not depend on k or on the thread count; only counters
** and memory may.  WSKEL_TEST_QUICK=1 (the ASan run) drops the largest size.
*/
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "generators.h"
#include "wskel.h"
#include "helpers.h"

#define AR variant("arrangement")

/* A copy of S's nodes and arcs that outlives its run (free with copy_free). */
static wk_skeleton copy_of(const wk_skeleton *S) {
    wk_skeleton c = {.n_input = S->n_input, .n_nodes = S->n_nodes, .n_arcs = S->n_arcs,
                     .nodes = malloc((S->n_nodes + 1) * sizeof(wk_node)),
                     .arcs = malloc((S->n_arcs + 1) * sizeof(wk_arc))};
    cr_assert(c.nodes && c.arcs);
    memcpy(c.nodes, S->nodes, S->n_nodes * sizeof(wk_node));
    memcpy(c.arcs, S->arcs, S->n_arcs * sizeof(wk_arc));
    return c;
}

static void copy_free(wk_skeleton *c) {
    free(c->nodes);
    free(c->arcs);
}

/* Skeletons of the same polygon equal: one to one within tol, in x, y and t. */
static bool same(const wk_skeleton *a, const wk_skeleton *b, double tol, char *why, size_t wlen) {
    return same_skeleton(a, b, (sk_match){.tol = tol, .tol_t = tol}, why, wlen);
}

static wk_status solve(const wk_polygon *P, const char *name, uint32_t k, int threads,
                       wk_skeleton *out, wk_counters *counters, char *err, size_t elen) {
    wk_run R;
    wk_run_init(&R);
    R.opt.k = k;
    R.opt.threads = threads;
    wk_skeleton *S = NULL;
    wk_status st = wk_solve(&R, variant(name), P, &S, NULL, NULL);
    if (st == WK_OK) st = wk_validate(&R, P, S, 0, NULL);
    if (st != WK_OK) wk_error_format(&R, err, elen);
    if (S) {
        *out = copy_of(S);
        wk_skeleton_free(&R, S);
    }
    if (counters) *counters = R.counters;
    cr_assert_eq(wk_run_close(&R), 0, "%s leaked", name);
    return st;
}

static void sweep(const char *family, const char *weights) {
    static const uint32_t ns[] = {10, 20, 50, 100, 200, 500};
    static const uint32_t ks[] = {1, 2, 7, WK_K_MAX};
    uint32_t total = 0, good = 0;
    for (size_t ni = 0; ni < sizeof ns / sizeof ns[0]; ni++) {
        if (quick() && ns[ni] > 200) continue;
        for (uint64_t seed = 1; seed <= 5; seed++) {
            wk_run G;
            wk_run_init(&G);
            wk_polygon *P = NULL;
            if (gen(&G, family, ns[ni], -1, seed, weights, &P) != WK_OK) {
                ASSERT_CLEAN_CLOSE(G);
                continue; /* the family refuses this n */
            }
            char err[600] = "";
            wk_skeleton ref = {0};
            cr_assert_eq(solve(P, "naive", 1, 1, &ref, NULL, err, sizeof err), WK_OK, "naive: %s", err);
            double tol = 1e-7 * wk_polygon_scale(P);
            for (size_t ki = 0; ki < sizeof ks / sizeof ks[0]; ki++) {
                total++;
                wk_skeleton got = {0};
                char why[512] = "";
                wk_status st = solve(P, "arrangement", ks[ki], 1, &got, NULL, err, sizeof err);
                if (st != WK_OK) {
                    cr_expect_eq(st, WK_OK, "%s n=%u seed=%llu weights=%s k=%u: %s", family,
                                 ns[ni], (unsigned long long)seed, weights, ks[ki], err);
                } else if (!same(&got, &ref, tol, why, sizeof why)) {
                    cr_expect(false, "%s n=%u seed=%llu weights=%s k=%u differs from naive: %s",
                              family, ns[ni], (unsigned long long)seed, weights, ks[ki], why);
                } else {
                    good++;
                }
                copy_free(&got);
            }
            copy_free(&ref);
            wk_polygon_free(&G, P);
            ASSERT_CLEAN_CLOSE(G);
        }
    }
    fprintf(stderr, "arrangement vs naive: %s weights=%s %u/%u identical\n", family, weights,
            good, total);
    cr_assert_gt(total, 0, "%s weights=%s: the generator refused every case", family, weights);
}

#define FAMILY_TESTS(fam)                                                  \
    Test(arrangement, fam##_unit, .timeout = 300) { sweep(#fam, "unit"); } \
    Test(arrangement, fam##_uniform, .timeout = 300) { sweep(#fam, "uniform"); }

FAMILY_TESTS(star)
FAMILY_TESTS(comb)
FAMILY_TESTS(spiral)
FAMILY_TESTS(notched)
FAMILY_TESTS(crossing)
FAMILY_TESTS(random)
FAMILY_TESTS(monotone)
FAMILY_TESTS(rectilinear)
FAMILY_TESTS(convex)

/* Same skeleton for every k and thread count; counters of the cache differ
** with k but never the events of the wavefront. */
Test(arrangement, independent_of_k_and_threads) {
    wk_run G;
    wk_run_init(&G);
    wk_polygon *P = gen_polygon(&G, "crossing", 160, 3, NULL);
    char err[600] = "", why[512] = "";
    wk_skeleton base = {0};
    wk_counters c1, c;
    cr_assert_eq(solve(P, "arrangement", 1, 1, &base, &c1, err, sizeof err), WK_OK, "%s", err);
    cr_assert_gt(counter_in(&c1, AR, "arrangement_crossings_initial"), 0);
    cr_assert_gt(counter_in(&c1, AR, "start_events"), 0);
    uint32_t ks[] = {2, 4, 16, WK_K_MAX};
    for (int th = 1; th <= 2; th++) {
        for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
            wk_skeleton got = {0};
            cr_assert_eq(solve(P, "arrangement", ks[i], th, &got, &c, err, sizeof err), WK_OK, "%s", err);
            cr_assert(same(&got, &base, 0.0, why, sizeof why), "k=%u threads=%d: %s", ks[i],
                      th, why);
            cr_assert_eq(counter_in(&c, AR, "edge_events"), counter_in(&c1, AR, "edge_events"));
            cr_assert_eq(counter_in(&c, AR, "split_events"), counter_in(&c1, AR, "split_events"));
            cr_assert_eq(counter_in(&c, AR, "start_events"), counter_in(&c1, AR, "start_events"));
            cr_assert_eq(counter_in(&c, AR, "switch_events"), counter_in(&c1, AR, "switch_events"));
            cr_assert_eq(counter_in(&c, AR, "arrangement_crossings_initial"), counter_in(&c1, AR, "arrangement_crossings_initial"));
            /* a bigger cache means fewer queries */
            cr_assert_leq(counter_in(&c, AR, "intersection_queries"), counter_in(&c1, AR, "intersection_queries"));
            copy_free(&got);
        }
    }
    copy_free(&base);
    wk_polygon_free(&G, P);
    ASSERT_CLEAN_CLOSE(G);
}

/* Every allocation failing in turn: WK_ENOMEM, no skeleton, no leak. */
Test(arrangement, fault_injection) {
    wk_run G;
    wk_run_init(&G);
    wk_polygon *P = gen_polygon(&G, "crossing", 40, 1, NULL);
    for (int64_t fail = 0;; fail++) {
        wk_run R;
        wk_run_init(&R);
        R.opt.k = 2;
        R.alloc.fail_after = fail;
        wk_skeleton *S = NULL;
        wk_status st = wk_solve(&R, variant("arrangement"), P, &S, NULL, NULL);
        if (st == WK_OK) {
            wk_skeleton_free(&R, S);
            ASSERT_CLEAN_CLOSE(R);
            break;
        }
        cr_assert_eq(st, WK_ENOMEM, "fail_after=%lld gave %d", (long long)fail, (int)st);
        cr_assert_null(S);
        cr_assert_eq(wk_run_close(&R), 0, "fail_after=%lld leaked", (long long)fail);
        cr_assert_lt(fail, 100000);
    }
    wk_polygon_free(&G, P);
    ASSERT_CLEAN_CLOSE(G);
}
