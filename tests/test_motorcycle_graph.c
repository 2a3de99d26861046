/*
** test_motorcycle_graph.c: M(P) of variants/motorcycle/motorcycle_graph.c.
**
** Oracles: hand cases with closed-form crash points (rectilinear notches
** with unit or chosen weights, where a reflex vertex between a horizontal
** and a vertical edge of weights a, b moves with components a, b; a
** regular star, whose reflex vertices meet at its centre at one time;
** head-on vertices on one line), wk_motorcycle_graph_check on every graph,
** a quadratic "no two final traces cross" check, and the brute-force twin,
** which must give the identical graph on generated polygons.
*/
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generators.h"
#include "helpers.h"
#include "motorcycle/motorcycle_graph.h"

#define NEAR 1e-9

static wk_motorcycle_graph *build_checked(wk_run *R, const wk_polygon *P) {
    wk_motorcycle_graph *G = NULL, *B = NULL;
    char why[512];
    wk_status st = wk_motorcycle_graph_build(R, P, &G);
    cr_assert_eq(st, WK_OK, "build: %s", R->err.msg);
    cr_assert(wk_motorcycle_graph_check(G, P, why, sizeof why), "%s: check: %s", P->name, why);
    st = wk_motorcycle_graph_build_brute(R, P, &B);
    cr_assert_eq(st, WK_OK, "brute: %s", R->err.msg);
    cr_assert(wk_motorcycle_graph_same(G, B, why, sizeof why), "%s: grid vs brute: %s", P->name,
              why);
    wk_motorcycle_graph_free(R, B);
    return G;
}

/* The motorcycle starting at input point (x, y) (absolute coordinates). */
static const wk_motorcycle *at(const wk_motorcycle_graph *G, double x, double y) {
    for (uint32_t i = 0; i < G->n; i++) {
        const wk_motorcycle *m = &G->m[i];
        if (fabs(m->o.x + G->centre.x - x) <= NEAR && fabs(m->o.y + G->centre.y - y) <= NEAR)
            return m;
    }
    cr_assert_fail("no motorcycle at (%g, %g)", x, y);
    return NULL;
}

static void assert_crash_at(const wk_motorcycle_graph *G, const wk_motorcycle *m, double x,
                            double y) {
    wk_point p = wk_motorcycle_crash_point(m);
    cr_assert(fabs(p.x + G->centre.x - x) <= NEAR && fabs(p.y + G->centre.y - y) <= NEAR,
              "motorcycle of vertex %u crashes at (%.17g, %.17g), want (%g, %g)", m->vertex,
              p.x + G->centre.x, p.y + G->centre.y, x, y);
}

static uint32_t stored_vertex(const wk_polygon *P, double x, double y) {
    for (uint32_t i = 0; i < P->n; i++)
        if (P->p[i].x == x && P->p[i].y == y) return i;
    cr_assert_fail("no vertex (%g, %g)", x, y);
    return WK_NONE;
}

/* ------------------------------------------------------------ hand cases */

/* An L with arms of different lengths: the reflex vertex (2, 1) runs along
** (-1, -1) into the bottom edge at (1, 0). */
Test(motorcycle_graph, one_reflex_vertex_into_a_wall) {
    wk_run R;
    wk_run_init(&R);
    static const double X[6] = {0, 3, 3, 2, 2, 0}, Y[6] = {0, 0, 1, 1, 3, 3};
    wk_polygon *P = polygon(&R, 6, X, Y, NULL);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 1);
    const wk_motorcycle *m = at(G, 2, 1);
    cr_assert_eq(m->kind, WK_MCG_WALL);
    cr_assert_eq(m->wall_edge, stored_vertex(P, 0, 0), "edge 0 -> (3, 0)");
    cr_assert_eq(m->wall_vertex, WK_NONE);
    cr_assert(fabs(m->len - sqrt(2.0)) <= NEAR && fabs(m->speed - sqrt(2.0)) <= NEAR);
    assert_crash_at(G, m, 1, 0);
    cr_assert_eq(G->stats.wall_crashes, 1);
    cr_assert_eq(G->n_steiner, 0);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* The same L with weight 1.5 on the vertical edge (2,1)->(2,3): velocity
** (-1.5, -1), into the bottom edge at (0.5, 0). */
Test(motorcycle_graph, weighted_vertex_into_a_wall) {
    wk_run R;
    wk_run_init(&R);
    static const double X[6] = {0, 3, 3, 2, 2, 0}, Y[6] = {0, 0, 1, 1, 3, 3};
    static const double W[6] = {1, 1, 1, 1.5, 1, 1};
    wk_polygon *P = polygon(&R, 6, X, Y, W);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 1);
    const wk_motorcycle *m = at(G, 2, 1);
    cr_assert_eq(m->kind, WK_MCG_WALL);
    cr_assert(fabs(m->speed - sqrt(3.25)) <= NEAR, "speed %.17g", m->speed);
    cr_assert(fabs(m->len - sqrt(3.25)) <= NEAR);
    assert_crash_at(G, m, 0.5, 0);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* The symmetric L: the ray of (1, 1) runs through the vertex (0, 0). */
Test(motorcycle_graph, ray_through_a_polygon_vertex) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 1);
    const wk_motorcycle *m = &G->m[0];
    cr_assert_eq(m->kind, WK_MCG_WALL);
    cr_assert_eq(m->wall_vertex, stored_vertex(P, 0, 0));
    cr_assert_eq(m->wall_edge, WK_NONE);
    cr_assert(fabs(m->len - sqrt(2.0)) <= NEAR);
    assert_crash_at(G, m, 0, 0);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Two notches: B = (10, 3) runs along (-1, -1) into the bottom edge at
** (7, 0), passing (9.5, 2.5) at time 0.5; A = (4, 8) runs along (1, -1)
** and reaches (9.5, 2.5) at time 5.5: A crashes into B's trace there. */
Test(motorcycle_graph, one_crashes_into_the_others_trace) {
    wk_run R;
    wk_run_init(&R);
    static const double X[8] = {0, 14, 14, 10, 10, 4, 4, 0}, Y[8] = {0, 0, 3, 3, 12, 12, 8, 8};
    wk_polygon *P = polygon(&R, 8, X, Y, NULL);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 2);
    const wk_motorcycle *A = at(G, 4, 8), *B = at(G, 10, 3);
    uint32_t ia = (uint32_t)(A - G->m), ib = (uint32_t)(B - G->m);
    cr_assert_eq(B->kind, WK_MCG_WALL);
    assert_crash_at(G, B, 7, 0);
    cr_assert_eq(A->kind, WK_MCG_TRACE);
    cr_assert_eq(A->other, ib);
    assert_crash_at(G, A, 9.5, 2.5);
    cr_assert(fabs(A->len - 5.5 * sqrt(2.0)) <= NEAR);
    cr_assert(fabs(A->other_len - 0.5 * sqrt(2.0)) <= NEAR);
    cr_assert(fabs(A->wall_len - 8 * sqrt(2.0)) <= NEAR, "A's wall (12, 0)");
    /* B's trace carries one resting Steiner vertex: A's end. */
    cr_assert_eq(G->steiner_start[ib + 1] - G->steiner_start[ib], 1);
    cr_assert_eq(G->steiner[G->steiner_start[ib]].other, ia);
    cr_assert(fabs(G->steiner[G->steiner_start[ib]].d - 0.5 * sqrt(2.0)) <= NEAR);
    cr_assert_eq(G->steiner_start[ia + 1] - G->steiner_start[ia], 0);
    cr_assert_eq(G->stats.trace_crashes, 1);
    cr_assert_eq(G->stats.wall_crashes, 1);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Two notches on the line x + y = 10: A = (4, 6) along (1, -1), B = (8, 2)
** along (-1, 1), each ray hitting the other's vertex; they meet head-on at
** (6, 4) at time 2.  With weight 3 on B's edges B is 3 times faster: they
** meet at (5, 5), at time 1. */
Test(motorcycle_graph, head_on_meet_midway) {
    static const double X[8] = {0, 8, 8, 12, 12, 4, 4, 0}, Y[8] = {0, 0, 2, 2, 10, 10, 6, 6};
    static const double W[8] = {1, 3, 3, 1, 1, 1, 1, 1};
    for (int weighted = 0; weighted < 2; weighted++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, 8, X, Y, weighted ? W : NULL);
        wk_motorcycle_graph *G = build_checked(&R, P);
        cr_assert_eq(G->n, 2);
        const wk_motorcycle *A = at(G, 4, 6), *B = at(G, 8, 2);
        cr_assert_eq(A->wall_vertex, stored_vertex(P, 8, 2));
        cr_assert_eq(B->wall_vertex, stored_vertex(P, 4, 6));
        cr_assert_eq(A->kind, WK_MCG_SIMULTANEOUS);
        cr_assert_eq(B->kind, WK_MCG_SIMULTANEOUS);
        cr_assert_eq(G->n_groups, 1);
        cr_assert_eq(G->groups[0].count, 2);
        double mx = weighted ? 5 : 6, my = weighted ? 5 : 4, t = weighted ? 1 : 2;
        assert_crash_at(G, A, mx, my);
        assert_crash_at(G, B, mx, my);
        cr_assert(fabs(G->groups[0].t - t) <= NEAR, "t %.17g", G->groups[0].t);
        cr_assert_eq(G->stats.simultaneous_groups, 1);
        cr_assert_eq(G->stats.simultaneous_motorcycles, 2);
        cr_assert_eq(G->n_steiner, 2, "each ends at the other's end");
        wk_motorcycle_graph_free(&R, G);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

/* A regular star with k spikes: its k reflex vertices all reach the centre
** at the same time, one group of k (for even k opposite ones are head-on
** on one line too). */
Test(motorcycle_graph, regular_star_meets_at_the_centre) {
    static const uint32_t ks[] = {3, 4, 5, 6, 7, 8, 12, 13, 64, 101};
    for (size_t c = 0; c < sizeof ks / sizeof ks[0]; c++) {
        uint32_t k = ks[c], n = 2 * k;
        double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
        double rho = 0.4 * cos(PI / k), ox = 3.25, oy = -1.5;
        for (uint32_t i = 0; i < n; i++) {
            double a = PI * i / k, q = i % 2 ? rho : 1.0;
            x[i] = ox + q * cos(a);
            y[i] = oy + q * sin(a);
        }
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, n, x, y, NULL);
        wk_motorcycle_graph *G = build_checked(&R, P);
        cr_assert_eq(G->n, k);
        cr_assert_eq(G->n_groups, 1, "k=%u: %u groups", k, G->n_groups);
        cr_assert_eq(G->groups[0].count, k, "k=%u: group of %u", k, G->groups[0].count);
        for (uint32_t i = 0; i < k; i++) {
            cr_assert_eq(G->m[i].kind, WK_MCG_SIMULTANEOUS, "k=%u", k);
            assert_crash_at(G, &G->m[i], ox, oy);
            cr_assert_eq(G->steiner_start[i + 1] - G->steiner_start[i], k - 1);
        }
        double t = wk_motorcycle_time_at(&G->m[0], G->m[0].len);
        cr_assert(fabs(G->groups[0].t - t) <= NEAR);
        cr_assert(fabs(G->groups[0].p.x + G->centre.x - ox) <= NEAR &&
                  fabs(G->groups[0].p.y + G->centre.y - oy) <= NEAR);
        cr_assert_eq(G->stats.simultaneous_motorcycles, k);
        wk_motorcycle_graph_free(&R, G);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
        free(x);
        free(y);
    }
}

/* A square hole in a rectangle: its four corners are reflex and run
** diagonally outwards into the outer edges. */
Test(motorcycle_graph, polygon_with_a_hole) {
    wk_run R;
    wk_run_init(&R);
    static const uint32_t sizes[2] = {4, 4};
    static const double X[8] = {0, 12, 12, 0, 3, 3, 5, 5}, Y[8] = {0, 0, 10, 10, 4, 6, 6, 4};
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_from_rings(&R, 2, sizes, X, Y, NULL, "hole", NULL, &P), WK_OK, "%s",
                 R.err.msg);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 4);
    static const double want[4][4] = {{5, 6, 9, 10}, {3, 6, 0, 9}, {3, 4, 0, 1}, {5, 4, 9, 0}};
    for (int c = 0; c < 4; c++) {
        const wk_motorcycle *m = at(G, want[c][0], want[c][1]);
        cr_assert_eq(m->kind, WK_MCG_WALL);
        cr_assert_neq(m->wall_edge, WK_NONE);
        assert_crash_at(G, m, want[c][2], want[c][3]);
    }
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(motorcycle_graph, convex_polygon_has_none) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 0);
    cr_assert_eq(G->n_steiner, 0);
    cr_assert_eq(G->steiner_start[0], 0);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ----------------------------------------------------- generated inputs */

/* No two final traces cross where both go on beyond the crossing by more
** than the tolerance: the later one would have crashed there.  O(r^2). */
static void assert_no_crossing_traces(const wk_motorcycle_graph *G, const char *what) {
    double tol = WK_MCG_CHECK_SLACK * G->eps_d;
    for (uint32_t i = 0; i < G->n; i++)
        for (uint32_t j = i + 1; j < G->n; j++) {
            const wk_motorcycle *a = &G->m[i], *b = &G->m[j];
            double cr = a->u.x * b->u.y - a->u.y * b->u.x;
            if (fabs(cr) <= 1e-6) continue; /* near-parallel: ill-conditioned */
            double dx = b->o.x - a->o.x, dy = b->o.y - a->o.y;
            double s = (dx * b->u.y - dy * b->u.x) / cr, t = (dx * a->u.y - dy * a->u.x) / cr;
            cr_assert(!(s > tol && s < a->len - tol && t > tol && t < b->len - tol),
                      "%s: traces %u and %u cross at %g, %g of %g, %g", what, i, j, s, t, a->len,
                      b->len);
        }
}

typedef struct gcase {
    const char *family;
    uint32_t n;
    uint32_t holes;
    const char *weights;
} gcase;

Test(motorcycle_graph, grid_matches_brute_force_on_generated_polygons, .timeout = 600) {
    static const gcase cases[] = {
        {"star", 60, 0, NULL},         {"star", 500, 0, "uniform"},  {"star", 5000, 0, NULL},
        {"random", 60, 0, NULL},       {"random", 1000, 0, "two"},   {"random", 5000, 0, NULL},
        {"comb", 100, 0, NULL},        {"comb", 2000, 0, "uniform"}, {"spiral", 400, 0, NULL},
        {"notched", 300, 0, NULL},     {"notched", 3000, 0, "int"},  {"crossing", 400, 0, NULL},
        {"rectilinear", 500, 0, NULL}, {"rectilinear", 4000, 0, NULL},
        {"monotone", 1000, 0, NULL},   {"holes", 400, 6, NULL},      {"holes", 3000, 40, "uniform"},
        /* clustered origins: the refined grid (MCG_REFINE_OCCUPANCY) */
        {"coastline", 2000, 0, NULL},  {"coastline", 8000, 0, NULL},
    };
    uint32_t seeds = quick() ? 1 : 3;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (uint64_t seed = 1; seed <= seeds; seed++) {
            const gcase *g = &cases[c];
            if (quick() && g->n > 1000) continue;
            wk_run R;
            wk_run_init(&R);
            wk_polygon *P = NULL;
            char what[128];
            snprintf(what, sizeof what, "%s n=%u holes=%u seed=%llu w=%s", g->family, g->n,
                     g->holes, (unsigned long long)seed, g->weights ? g->weights : "unit");
            wk_status st = gen_holes(&R, g->family, g->n, -1, g->holes, seed, g->weights, &P);
            cr_assert_eq(st, WK_OK, "%s: %s", what, R.err.msg);
            snprintf(P->name, sizeof P->name, "%s", what);
            wk_motorcycle_graph *G = build_checked(&R, P);
            cr_assert_eq(G->n, P->r, "%s", what);
            if (G->n <= 2500) assert_no_crossing_traces(G, what);
            /* Deterministic: a second build is the same graph. */
            wk_motorcycle_graph *H = NULL;
            char why[512];
            cr_assert_eq(wk_motorcycle_graph_build(&R, P, &H), WK_OK);
            cr_assert(wk_motorcycle_graph_same(G, H, why, sizeof why), "%s: rebuild: %s", what,
                      why);
            cr_assert_eq(G->stats.candidate_pairs, H->stats.candidate_pairs);
            wk_motorcycle_graph_free(&R, H);
            wk_motorcycle_graph_free(&R, G);
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
        }
}

/* The crash bound (motorcycle_graph.c, geo.bound and cell_scan) skips the
** hub's pairs that can only be no-ops: star 5000 seed 1 tested 538,149
** pairs before it and 324,422 with it (the graph is the brute force's, see
** above).  Since the scans' shortlist (short_skip) and the coarser grid of
** spread origins (MCG_CELLS_PER_MOTORCYCLE_SPREAD, 9 x 9 cells here) the
** full tests are 111,521, and 274,436 with the bound never set (a
** temporary build).  Fails if the bound or the shortlist stops working. */
Test(motorcycle_graph, crash_bound_prunes_the_hub) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(gen(&R, "star", 5000, -1, 1, NULL, &P), WK_OK);
    wk_motorcycle_graph *G = NULL;
    cr_assert_eq(wk_motorcycle_graph_build(&R, P, &G), WK_OK);
    cr_assert_eq(G->n, 2214);
    cr_assert_lt(G->stats.candidate_pairs, 180000, "pairs %llu",
                 (unsigned long long)G->stats.candidate_pairs);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Long traces on a refined grid (motorcycle_graph.c,
** MCG_REFINED_LISTINGS_MAX): monotone 3*10^4 seed 1 has its origins on the
** boundary, so the occupancy rule refines the grid, and traces about a
** quarter of the box long, listed in ever more cells (r^1.5).  Past 40
** listings per motorcycle the grid is dropped and the simulation starts
** again unrefined: the same graph (a second build, the consistency check;
** JSON identical to the refined grid's at 10^5, session mcmp) with a peak
** of 32.5 MB of tracked bytes instead of 43.7 MB (10^5: 160 MB instead of
** 400 MB).  Fails if the budget stops firing there. */
Test(motorcycle_graph, long_traces_drop_the_refined_grid, .timeout = 300) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(gen(&R, "monotone", 30000, -1, 1, NULL, &P), WK_OK);
    size_t base = R.alloc.live;
    wk_run_reset_peak(&R);
    wk_motorcycle_graph *G = NULL, *H = NULL;
    cr_assert_eq(wk_motorcycle_graph_build(&R, P, &G), WK_OK);
    size_t peak = R.alloc.peak - base;
    cr_assert_eq(G->n, 14999);
    cr_assert_lt(peak, (size_t)38000000, "peak %zu bytes", peak);
    char why[512];
    cr_assert(wk_motorcycle_graph_check(G, P, why, sizeof why), "%s", why);
    cr_assert_eq(wk_motorcycle_graph_build(&R, P, &H), WK_OK);
    cr_assert(wk_motorcycle_graph_same(G, H, why, sizeof why), "rebuild: %s", why);
    wk_motorcycle_graph_free(&R, H);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* --------------------------------------------------------------- memory */

Test(motorcycle_graph, every_allocation_failure_is_clean) {
    for (int which = 0; which < 2; which++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, "star", 80, -1, 2, NULL, &P), WK_OK);
        size_t base = R.alloc.live;
        int failures = 0;
        for (int64_t N = 0;; N++) {
            R.err.code = WK_OK;
            R.alloc.fail_after = (int64_t)R.alloc.calls + N;
            wk_motorcycle_graph *G = NULL;
            wk_status st = which ? wk_motorcycle_graph_build_brute(&R, P, &G)
                                 : wk_motorcycle_graph_build(&R, P, &G);
            R.alloc.fail_after = -1;
            if (st == WK_OK) {
                cr_assert_not_null(G);
                wk_motorcycle_graph_free(&R, G);
                cr_assert_eq(R.alloc.live, base);
                break;
            }
            cr_assert_null(G);
            cr_assert_eq(st, WK_ENOMEM, "N=%lld: status %d (%s)", (long long)N, st, R.err.msg);
            cr_assert_eq(R.alloc.live, base, "N=%lld: %zu bytes leaked", (long long)N,
                         R.alloc.live - base);
            failures++;
            cr_assert_lt(N, 100000);
        }
        cr_assert_gt(failures, 5);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

/* The same for a star whose hub cells get the line index (64 or more
** motorcycles in a cell): every 1/400th allocation call fails in turn. */
Test(motorcycle_graph, allocation_failures_with_cell_index_are_clean, .timeout = 300) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(gen(&R, "star", 3000, -1, 1, NULL, &P), WK_OK);
    size_t base = R.alloc.live;
    uint64_t c0 = R.alloc.calls;
    wk_motorcycle_graph *G = NULL;
    cr_assert_eq(wk_motorcycle_graph_build(&R, P, &G), WK_OK);
    int64_t calls = (int64_t)(R.alloc.calls - c0);
    wk_motorcycle_graph_free(&R, G);
    cr_assert_eq(R.alloc.live, base);
    int64_t step = calls / 400 > 1 ? calls / 400 : 1;
    int failures = 0;
    for (int64_t N = 0; N < calls; N += step) {
        R.err.code = WK_OK;
        R.alloc.fail_after = (int64_t)R.alloc.calls + N;
        G = NULL;
        wk_status st = wk_motorcycle_graph_build(&R, P, &G);
        R.alloc.fail_after = -1;
        if (st == WK_OK) {
            wk_motorcycle_graph_free(&R, G);
        } else {
            cr_assert_null(G);
            cr_assert_eq(st, WK_ENOMEM, "N=%lld: status %d (%s)", (long long)N, st, R.err.msg);
            failures++;
        }
        cr_assert_eq(R.alloc.live, base, "N=%lld: %zu bytes leaked", (long long)N,
                     R.alloc.live - base);
    }
    cr_assert_gt(failures, 100);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------------------ PSLGs */

static wk_polygon *pslg(wk_run *R, uint32_t nv, const double *x, const double *y, uint32_t ne,
                        const uint32_t *s, const uint32_t *d) {
    wk_polygon *P = NULL;
    cr_assert_eq(wk_pslg_from_arrays(R, nv, x, y, ne, s, d, NULL, "pslg", NULL, NULL, &P), WK_OK,
                 "%s", R->err.msg);
    return P;
}

/* A segment (0,0)-(2,0): its two terminals are four reflex corners (002:
** two motorcycles per terminal), leaving at 45 degrees to the segment with
** speed sqrt 2; the two at one terminal do not crash at their common
** origin, and all four escape into the outer face: no wall, a trace as long
** as escape_len (speed * one diagonal over the weight, times 1.25, plus
** 1.25 diagonals). */
Test(motorcycle_graph, pslg_segment_has_four_escaping_motorcycles) {
    static const double X[2] = {0, 2}, Y[2] = {0, 0};
    static const uint32_t S[1] = {0}, D[1] = {1};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = pslg(&R, 2, X, Y, 1, S, D);
    wk_motorcycle_graph *G = build_checked(&R, P);
    cr_assert_eq(G->n, 4, "%u motorcycles", G->n);
    double want = 1.25 * (sqrt(2.0) * 2 + 2);
    for (uint32_t i = 0; i < 4; i++) {
        const wk_motorcycle *m = &G->m[i];
        cr_assert(wk_motorcycle_escapes(m), "motorcycle %u hits a wall", i);
        cr_assert_eq(m->kind, WK_MCG_WALL);
        cr_assert(fabs(m->speed - sqrt(2.0)) <= NEAR, "speed %.17g", m->speed);
        cr_assert(fabs(fabs(m->u.x) - sqrt(0.5)) <= NEAR && fabs(fabs(m->u.y) - sqrt(0.5)) <= NEAR);
        cr_assert(fabs(m->len - want) <= NEAR * want, "len %.17g, want %.17g", m->len, want);
    }
    cr_assert_eq(G->n_groups, 0);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* A "T": the segment (0,0)-(0,2) ends 1 below the middle of (-4,3)-(4,3).
** Its top terminal's motorcycles leave at 45 degrees up and hit the bar at
** (-1, 3) and (1, 3), each on the half-edge facing it (the bar's lower side:
** the one whose left is below, i.e. running right to left), never the one
** on the far side. */
Test(motorcycle_graph, pslg_terminal_hits_the_facing_half_edge) {
    static const double X[4] = {0, 0, -4, 4}, Y[4] = {0, 2, 3, 3};
    static const uint32_t S[2] = {0, 2}, D[2] = {1, 3};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = pslg(&R, 4, X, Y, 2, S, D);
    wk_motorcycle_graph *G = build_checked(&R, P);
    uint32_t hits = 0;
    for (uint32_t i = 0; i < G->n; i++) {
        const wk_motorcycle *m = &G->m[i];
        if (!(fabs(m->o.x + G->centre.x) <= NEAR && fabs(m->o.y + G->centre.y - 2) <= NEAR)) continue;
        cr_assert_eq(m->kind, WK_MCG_WALL, "top terminal's motorcycle %u crashes into a trace", i);
        cr_assert_neq(m->wall_edge, WK_NONE);
        wk_point d = wk_polygon_edge_dir(P, m->wall_edge);
        cr_assert(d.x < 0 && d.y == 0, "wall half-edge runs (%g, %g), want right to left", d.x, d.y);
        wk_point c = wk_motorcycle_crash_point(m);
        cr_assert(fabs(fabs(c.x + G->centre.x) - 1) <= NEAR && fabs(c.y + G->centre.y - 3) <= NEAR,
                  "crash at (%g, %g)", c.x + G->centre.x, c.y + G->centre.y);
        hits++;
    }
    cr_assert_eq(hits, 2, "%u motorcycles from the top terminal", hits);
    wk_motorcycle_graph_free(&R, G);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}
