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
#include "fixtures.h"

#define AR wk_variant_find("arrangement")

typedef struct sk_copy {
    uint32_t n_nodes, n_arcs;
    wk_node *nodes;
    wk_arc *arcs;
} sk_copy;

static sk_copy copy_of(const wk_skeleton *S) {
    sk_copy c = {S->n_nodes, S->n_arcs, malloc(S->n_nodes * sizeof(wk_node)),
                 malloc(S->n_arcs * sizeof(wk_arc))};
    for (uint32_t i = 0; i < S->n_nodes; i++) c.nodes[i] = S->nodes[i];
    for (uint32_t i = 0; i < S->n_arcs; i++) c.arcs[i] = S->arcs[i];
    return c;
}

static void copy_free(sk_copy *c) {
    free(c->nodes);
    free(c->arcs);
}

/* Skeletons a and b of the same polygon are equal: a bijection of nodes
** within tol (x, y and t) under which the arcs and their faces agree.
** Quadratic matching: fine for the sizes tested here. */
static bool same_skeleton(const sk_copy *a, const sk_copy *b, double tol, char *why, size_t wlen) {
    if (a->n_nodes != b->n_nodes || a->n_arcs != b->n_arcs) {
        snprintf(why, wlen, "%u/%u nodes, %u/%u arcs", a->n_nodes, b->n_nodes, a->n_arcs, b->n_arcs);
        return false;
    }
    uint32_t *map = malloc(a->n_nodes * sizeof *map);
    bool *used = calloc(b->n_nodes, 1);
    bool ok = true;
    for (uint32_t i = 0; i < a->n_nodes && ok; i++) {
        map[i] = UINT32_MAX;
        for (uint32_t j = 0; j < b->n_nodes; j++) {
            if (used[j]) continue;
            if (fabs(a->nodes[i].x - b->nodes[j].x) <= tol && fabs(a->nodes[i].y - b->nodes[j].y) <= tol &&
                fabs(a->nodes[i].t - b->nodes[j].t) <= tol) {
                map[i] = j;
                used[j] = true;
                break;
            }
        }
        if (map[i] == UINT32_MAX) {
            snprintf(why, wlen, "node %u (%.9g, %.9g, t %.9g) has no match", i, a->nodes[i].x,
                     a->nodes[i].y, a->nodes[i].t);
            ok = false;
        }
    }
    for (uint32_t i = 0; i < a->n_arcs && ok; i++) {
        wk_arc x = a->arcs[i];
        uint32_t xa = map[x.a], xb = map[x.b];
        bool found = false;
        for (uint32_t j = 0; j < b->n_arcs && !found; j++) {
            wk_arc y = b->arcs[j];
            found = (y.a == xa && y.b == xb && y.left == x.left && y.right == x.right) ||
                    (y.a == xb && y.b == xa && y.left == x.right && y.right == x.left);
        }
        if (!found) {
            snprintf(why, wlen, "arc %u [%u, %u, %u, %u] has no match", i, x.a, x.b, x.left, x.right);
            ok = false;
        }
    }
    free(map);
    free(used);
    return ok;
}

static wk_status solve(const wk_polygon *P, const char *variant, uint32_t k, int threads,
                       sk_copy *out, wk_counters *counters, char *err, size_t elen) {
    wk_run R;
    wk_run_init(&R);
    R.opt.k = k;
    R.opt.threads = threads;
    wk_skeleton *S = NULL;
    wk_status st = wk_solve(&R, wk_variant_find(variant), P, &S, NULL, NULL);
    if (st == WK_OK) st = wk_validate(&R, P, S, 0, NULL);
    if (st != WK_OK) wk_error_format(&R, err, elen);
    if (S) {
        *out = copy_of(S);
        wk_skeleton_free(&R, S);
    }
    if (counters) *counters = R.counters;
    cr_assert_eq(wk_run_close(&R), 0, "%s leaked", variant);
    return st;
}

static void sweep(const char *family, wk_weight_mode weights) {
    static const uint32_t ns[] = {10, 20, 50, 100, 200, 500};
    static const uint32_t ks[] = {1, 2, 7, WK_K_MAX};
    bool quick = getenv("WSKEL_TEST_QUICK") != NULL;
    uint32_t total = 0, good = 0;
    for (size_t ni = 0; ni < sizeof ns / sizeof ns[0]; ni++) {
        if (quick && ns[ni] > 200) continue;
        for (uint64_t seed = 1; seed <= 5; seed++) {
            wk_run G;
            wk_run_init(&G);
            wk_gen_params g;
            wk_gen_params_init(&g);
            g.family = family;
            g.n = ns[ni];
            g.seed = seed;
            g.weights = weights;
            wk_polygon *P = NULL;
            if (wk_generate(&G, &g, &P) != WK_OK) {
                wk_run_close(&G);
                continue; /* the family refuses this n */
            }
            char err[600] = "";
            sk_copy ref = {0, 0, NULL, NULL};
            cr_assert_eq(solve(P, "naive", 1, 1, &ref, NULL, err, sizeof err), WK_OK, "naive: %s", err);
            double tol = 1e-7 * wk_polygon_scale(P);
            for (size_t ki = 0; ki < sizeof ks / sizeof ks[0]; ki++) {
                total++;
                sk_copy got = {0, 0, NULL, NULL};
                char why[300] = "";
                wk_status st = solve(P, "arrangement", ks[ki], 1, &got, NULL, err, sizeof err);
                if (st != WK_OK) {
                    cr_expect_eq(st, WK_OK, "%s n=%u seed=%llu weights=%d k=%u: %s", family, g.n,
                                 (unsigned long long)seed, (int)weights, ks[ki], err);
                } else if (!same_skeleton(&got, &ref, tol, why, sizeof why)) {
                    cr_expect(false, "%s n=%u seed=%llu weights=%d k=%u differs from naive: %s",
                              family, g.n, (unsigned long long)seed, (int)weights, ks[ki], why);
                } else {
                    good++;
                }
                copy_free(&got);
            }
            copy_free(&ref);
            wk_polygon_free(&G, P);
            cr_assert_eq(wk_run_close(&G), 0);
        }
    }
    fprintf(stderr, "arrangement vs naive: %s weights=%d %u/%u identical\n", family, (int)weights,
            good, total);
}

#define FAMILY_TESTS(fam)                                                  \
    Test(arrangement, fam##_unit, .timeout = 300) { sweep(#fam, WK_W_UNIT); } \
    Test(arrangement, fam##_uniform, .timeout = 300) { sweep(#fam, WK_W_UNIFORM); }

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
    wk_gen_params g;
    wk_gen_params_init(&g);
    g.family = "crossing";
    g.n = 160;
    g.seed = 3;
    wk_polygon *P = NULL;
    cr_assert_eq(wk_generate(&G, &g, &P), WK_OK);
    char err[600] = "", why[300] = "";
    sk_copy base = {0, 0, NULL, NULL};
    wk_counters c1, c;
    cr_assert_eq(solve(P, "arrangement", 1, 1, &base, &c1, err, sizeof err), WK_OK, "%s", err);
    cr_assert_gt(counter_in(&c1, AR, "arrangement_crossings_initial"), 0);
    cr_assert_gt(counter_in(&c1, AR, "start_events"), 0);
    uint32_t ks[] = {2, 4, 16, WK_K_MAX};
    for (int th = 1; th <= 2; th++) {
        for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
            sk_copy got = {0, 0, NULL, NULL};
            cr_assert_eq(solve(P, "arrangement", ks[i], th, &got, &c, err, sizeof err), WK_OK, "%s", err);
            cr_assert(same_skeleton(&got, &base, 0.0, why, sizeof why), "k=%u threads=%d: %s", ks[i],
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
    cr_assert_eq(wk_run_close(&G), 0);
}

/* Every allocation failing in turn: WK_ENOMEM, no skeleton, no leak. */
Test(arrangement, fault_injection) {
    wk_run G;
    wk_run_init(&G);
    wk_gen_params g;
    wk_gen_params_init(&g);
    g.family = "crossing";
    g.n = 40;
    g.seed = 1;
    wk_polygon *P = NULL;
    cr_assert_eq(wk_generate(&G, &g, &P), WK_OK);
    for (int64_t fail = 0;; fail++) {
        wk_run R;
        wk_run_init(&R);
        R.opt.k = 2;
        R.alloc.fail_after = fail;
        wk_skeleton *S = NULL;
        wk_status st = wk_solve(&R, wk_variant_find("arrangement"), P, &S, NULL, NULL);
        if (st == WK_OK) {
            wk_skeleton_free(&R, S);
            cr_assert_eq(wk_run_close(&R), 0);
            break;
        }
        cr_assert_eq(st, WK_ENOMEM, "fail_after=%lld gave %d", (long long)fail, (int)st);
        cr_assert_null(S);
        cr_assert_eq(wk_run_close(&R), 0, "fail_after=%lld leaked", (long long)fail);
        cr_assert_lt(fail, 100000);
    }
    wk_polygon_free(&G, P);
    cr_assert_eq(wk_run_close(&G), 0);
}
