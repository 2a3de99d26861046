/*
** test_wavefront.c: the kinetic wavefront (engine/wavefront.c,
** wavefront_group.c) through the interface a finder sees (wavefront.h):
** hooks are called as documented, the accessors describe consistent cycles,
** the split search finds what the reference finds, --check-invariants runs
** the finder's check and a failing check fails the run.
*/
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "helpers.h"
#include "wavefront.h"

/* A finder that is the brute force (every piece of the cycle, through the
** split search) and records what the wavefront showed it. */
typedef struct probe {
    int starts, groups;
    uint64_t fresh_seen, ended_seen;
    bool consistent;      /* every look at the cycles was consistent */
    bool fail_check;      /* the check hook fails */
    int checks;
    double last_t;        /* times of after_group never decrease */
    bool monotone_time;
} probe;

/* Every alive vertex: next/prev inverse, both alive, the piece on the
** offset line of edge_out at the present (within a generous tolerance). */
static bool cycles_consistent(const wk_wavefront *W) {
    double t = wk_wf_now(W), tol = 1e6 * wk_wf_eps_d(W);
    for (uint32_t v = 0; v < wk_wf_vertex_count(W); v++) {
        if (!wk_wf_alive(W, v)) continue;
        uint32_t n = wk_wf_next(W, v);
        if (!wk_wf_alive(W, n) || wk_wf_prev(W, n) != v) return false;
        const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, v));
        if (fabs(wk_offset_distance(L, wk_wf_position(W, v, t), t)) > tol) return false;
        if (fabs(wk_offset_distance(L, wk_wf_position(W, n, t), t)) > tol) return false;
        if (wk_wf_start_time(W, v) > t) return false;
    }
    return true;
}

static void probe_full(void *ud, wk_wavefront *W, uint32_t v) {
    (void)ud;
    cr_assert(wk_wf_reflex(W, v), "full() is asked for reflex vertices only");
    wk_wf_split_search s;
    wk_wf_split_begin(W, v, &s);
    for (uint32_t a = wk_wf_next(W, v); a != v; a = wk_wf_next(W, a)) wk_wf_split_test(W, &s, a);
    wk_wf_split_offer(W, &s);
}

static wk_status probe_start(void *ud, wk_wavefront *W) {
    probe *p = ud;
    p->starts++;
    p->consistent &= cycles_consistent(W);
    /* the initial wavefront: vertex i leaves along edge i */
    for (uint32_t i = 0; i < wk_wf_polygon(W)->n; i++)
        if (wk_wf_alive(W, i) && wk_wf_edge_out(W, i) != i) p->consistent = false;
    return WK_OK;
}

static wk_status probe_after_group(void *ud, wk_wavefront *W, double t) {
    probe *p = ud;
    p->groups++;
    if (t < p->last_t) p->monotone_time = false;
    p->last_t = t;
    const uint32_t *fresh, *ended;
    uint32_t nf, ne;
    wk_wf_last_group(W, &fresh, &nf, &ended, &ne);
    p->fresh_seen += nf;
    p->ended_seen += ne;
    for (uint32_t i = 0; i < ne; i++)
        if (wk_wf_alive(W, ended[i])) p->consistent = false;
    p->consistent &= cycles_consistent(W);
    return WK_OK;
}

static wk_status probe_check(void *ud, const wk_wavefront *W) {
    probe *p = ud;
    p->checks++;
    if (p->fail_check)
        return WK_FAIL(wk_wf_run(W), WK_EALGO, NULL, 0, "probe: the finder's check failed on purpose");
    return WK_OK;
}

static const wk_split_finder probe_finder = {
    .full = probe_full,
    .incremental = probe_full,
    .start = probe_start,
    .after_group = probe_after_group,
    .check = probe_check,
};

static void probe_init(probe *p) {
    memset(p, 0, sizeof *p);
    p->consistent = p->monotone_time = true;
}

Test(wavefront, hooks_see_consistent_cycles_and_match_the_reference) {
    const char *families[] = {"star", "comb", "spiral", "random", "rectilinear"};
    for (size_t f = 0; f < sizeof families / sizeof families[0]; f++) {
        for (uint64_t seed = 1; seed <= 3; seed++) {
            wk_run R;
            wk_run_init(&R);
            wk_polygon *P = gen_polygon(&R, families[f], 120, seed, seed == 3 ? "uniform" : NULL);
            probe p;
            probe_init(&p);
            wk_skeleton *S = NULL;
            cr_assert_eq(wk_wavefront_run(&R, P, &probe_finder, &p, &S), WK_OK, "%s: %s",
                         families[f], R.err.msg);
            cr_assert_eq(p.starts, 1);
            cr_assert_gt(p.groups, 0);
            cr_assert_eq((uint64_t)p.groups, counter(&R, "simultaneous_event_groups"),
                         "after_group once per group");
            cr_assert(p.consistent, "%s seed %llu: the finder saw an inconsistent wavefront",
                      families[f], (unsigned long long)seed);
            cr_assert(p.monotone_time);
            cr_assert_geq(p.ended_seen, P->n, "every input vertex ends in some group");
            cr_assert_eq(p.checks, 0, "no checks without check_invariants");
            cr_assert_eq(wk_validate(&R, P, S, 0, NULL), WK_OK, "%s", R.err.msg);
            /* the same skeleton as the reference variant */
            wk_skeleton *T = NULL;
            cr_assert_eq(wk_solve(&R, wk_variant_reference(), P, &T, NULL, NULL), WK_OK);
            cr_assert_eq(S->n_nodes, T->n_nodes);
            cr_assert_eq(S->n_arcs, T->n_arcs);
            cr_assert(!memcmp(S->nodes, T->nodes, S->n_nodes * sizeof *S->nodes), "%s: nodes differ",
                      families[f]);
            cr_assert(!memcmp(S->arcs, T->arcs, S->n_arcs * sizeof *S->arcs));
            wk_skeleton_free(&R, S);
            wk_skeleton_free(&R, T);
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
        }
    }
}

Test(wavefront, check_invariants_runs_the_finders_check_and_a_failure_stops_the_run) {
    wk_run R;
    wk_run_init(&R);
    R.opt.check_invariants = true;
    wk_polygon *P = gen_polygon(&R, "star", 60, 1, NULL);
    probe p;
    probe_init(&p);
    wk_skeleton *S = NULL;
    cr_assert_eq(wk_wavefront_run(&R, P, &probe_finder, &p, &S), WK_OK, "%s", R.err.msg);
    cr_assert_eq(p.checks, p.groups, "one check after every group");
    wk_skeleton_free(&R, S);
    probe_init(&p);
    p.fail_check = true;
    S = NULL;
    cr_assert_eq(wk_wavefront_run(&R, P, &probe_finder, &p, &S), WK_EALGO);
    cr_assert_null(S, "no skeleton on failure");
    cr_assert(strstr(R.err.msg, "on purpose"), "%s", R.err.msg);
    cr_assert_eq(p.checks, 1, "the run stops at the first failed check");
    wk_run_clear_error(&R);
    cr_assert_eq(R.err.code, WK_OK);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* A square: all four edge events meet at the centre in one group, at
** t = 1/2 for side 1; a weighted rectangle's nodes at the closed form. */
Test(wavefront, square_is_one_group_at_the_centre) {
    static const double x[] = {0, 1, 1, 0}, y[] = {0, 0, 1, 1};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, x, y, NULL);
    probe p;
    probe_init(&p);
    wk_skeleton *S = NULL;
    cr_assert_eq(wk_wavefront_run(&R, P, &probe_finder, &p, &S), WK_OK, "%s", R.err.msg);
    cr_assert_eq(p.groups, 1);
    cr_assert_eq(p.ended_seen, 4);
    cr_assert_eq(p.fresh_seen, 0, "a vanishing square creates no vertex");
    cr_assert_eq(S->n_nodes, 5);
    cr_assert_float_eq(S->nodes[4].x, 0.5, 1e-12);
    cr_assert_float_eq(S->nodes[4].y, 0.5, 1e-12);
    cr_assert_float_eq(S->nodes[4].t, 0.5, 1e-12);
    cr_assert_eq(counter(&R, "vanishing_components"), 1);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* The split search: a notch's reflex vertex hits the opposite edge.  The
** vertex at (2, 1) between two 45-degree edges moves straight down at
** speed sqrt(2) and meets the bottom edge's offset line y = t at
** t = 1 / (1 + sqrt(2)) = sqrt(2) - 1, at x = 2, before any edge event (the
** shortest piece, 1 long, shrinks at rate 1 + tan(22.5 deg)). */
Test(wavefront, split_search_finds_the_notch_split) {
    static const double x[] = {0, 4, 4, 3, 2, 1, 0}, y[] = {0, 0, 2, 2, 1, 2, 2};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 7, x, y, NULL);
    cr_assert_eq(P->r, 1);
    probe p;
    probe_init(&p);
    wk_skeleton *S = NULL;
    cr_assert_eq(wk_wavefront_run(&R, P, &probe_finder, &p, &S), WK_OK, "%s", R.err.msg);
    cr_assert_eq(wk_validate(&R, P, S, 0, NULL), WK_OK, "%s", R.err.msg);
    cr_assert_eq(counter(&R, "split_events"), 1);
    double ts = sqrt(2.0) - 1;
    bool found = false;
    for (uint32_t i = P->n; i < S->n_nodes; i++)
        found |= fabs(S->nodes[i].x - 2) < 1e-12 && fabs(S->nodes[i].y - ts) < 1e-12 &&
                 fabs(S->nodes[i].t - ts) < 1e-12;
    cr_assert(found, "no node at (2, sqrt 2 - 1), t = sqrt 2 - 1");
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* A stretch that shrinks slowly is no arrival (plan_slow_stretches).  The
** weighted comb with a spike of tests/data/fuzz/
** mismatch_deforming_weighted_comb_spike.wpoly: at t = 110/7 a reflex
** vertex splits a tooth's wall 5.14e-3 (0.6 eps_d) above the wall's lower
** end, and the stretch left between them shrinks at 8.9e-5 (their other
** edges, 3 and 8, both weight 3, meet at a sine of 3e-5).  Merged at once,
** edges 3 and 8 were made neighbours 173 units from their crossing, and
** the spike (edges 2 and 3, moving at 1.3e5) ended there, 141 units from
** the exact end of the skeleton: where faces 2, 7, 8 and 2, 3, 7 meet, by
** the offset lines in 80-digit arithmetic (tests/exact_nodes.py). */
Test(wavefront, slow_stretch_is_no_arrival) {
    static const double x[] = {0,   990, 907049, 8075800, 880, 770, 770, 660, 660, 550,
                               550, 440, 440,    330,     330, 220, 220, 111, 110, 0};
    static const double y[] = {3,   0,   9,   19,  259, 259, 709, 709, 259, 259,
                               709, 709, 259, 259, 719, 709, 259, 259, 709, 709};
    static const double w[] = {1, 2, 1, 3, 1, 4, 1, 3, 3, 2, 3, 4, 3, 2, 3, 3, 4, 1, 3, 3};
    static const double exact[2][3] = {
        {848.448073679657568, 70.551926320342446, 62.816024559885854}, /* faces 2, 7, 8 */
        {848.448776932460078, 70.552160738924286, 62.816258977486697}, /* faces 2, 3, 7 */
    };
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 20, x, y, w);
    probe p;
    probe_init(&p);
    wk_skeleton *S = NULL;
    cr_assert_eq(wk_wavefront_run(&R, P, &probe_finder, &p, &S), WK_OK, "%s", R.err.msg);
    cr_assert_eq(wk_validate(&R, P, S, 0, NULL), WK_OK, "%s", R.err.msg);
    cr_assert(p.consistent);
    for (int k = 0; k < 2; k++) {
        double best = INFINITY;
        for (uint32_t i = P->n; i < S->n_nodes; i++)
            best = fmin(best, fmax(fmax(fabs(S->nodes[i].x - exact[k][0]), fabs(S->nodes[i].y - exact[k][1])),
                                   fabs(S->nodes[i].t - exact[k][2])));
        cr_assert(best < 1e-6, "no node within 1e-6 of (%.15g, %.15g), t = %.15g: nearest %g",
                  exact[k][0], exact[k][1], exact[k][2], best);
    }
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}
