/*
** test_variant_naive.c: the reference variant (variants/naive/naive.c).
**
** Oracles:
**   - property sweep: every generator family, n in {8, 12, 20, 50, 100, 200,
**     500}, ten seeds, unit and uniform weights (two-valued and integer
**     weights too for n <= 100): naive succeeds and wk_validate accepts the
**     skeleton; a summary line per family and weight mode goes to stderr.
**     The sweep goes on after a failure (cr_expect) so that the counts are
**     complete; the first few failures of each family and mode are printed
**     with a command that reproduces them.  WSKEL_TEST_QUICK (set by the
**     ASan run if it needs to) drops n = 500; WSKEL_NAIVE_FAILURE_DIR=DIR
**     writes every failing polygon to DIR as .wpoly;
**   - convex closed form: for a convex polygon the roof is the lower envelope
**     of the edges' roof planes, so every node satisfies
**     t = min_e d_e(p) / w(e) (d_e: signed distance from edge e's line,
**     positive inside) and lies inside; checked on the convex family and on
**     regular polygons built here, unit and random weights;
**   - hand-made cases in tests/data/hand (see its README.md): interior nodes
**     computed by hand (matched as a set), arc counts, chosen arcs, both
**     collinear rules (also a heavier edge catching up with a lighter
**     parallel one), weighted triangles solved from their three offset
**     lines, translation by (1e6, 1e6), clockwise input;
**   - extra cases: generated polygons outside the property grid on which a
**     wider exploratory sweep found naive failing (naive/extra_sweep_cases);
**     with unit weights the reflex-preserving edge event counter stays 0;
**   - determinism: two runs give bit-identical nodes, arcs and counters;
**   - fault injection: every allocation of a run fails in turn; each such
**     run returns WK_ENOMEM, no output, and leaves zero live bytes.
** Every case owns a fresh wk_run and ends with wk_run_close(&R) == 0.
**
** Tolerances follow wskel.h: lengths WK_TOL_REL * wk_polygon_scale(P),
** times that divided by the largest weight.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "generators.h"
#include "wskel.h"
#include "helpers.h"

/* ------------------------------------------------------------- helpers */

static double tol_d(const wk_polygon *P) { return WK_TOL_REL * wk_polygon_scale(P); }
static double tol_t(const wk_polygon *P) { return tol_d(P) / max_weight(P); }

/* Run naive and the validator; assert both succeed.  what names the case. */
static wk_skeleton *solve_valid(wk_run *R, const wk_polygon *P, const char *what) {
    wk_skeleton *S = NULL;
    char msg[1024];
    wk_status st = wk_solve(R, variant("naive"), P, &S, NULL, NULL);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "%s: naive failed (%s): %s", what, wk_status_name(st), msg);
    cr_assert_not_null(S);
    wk_validate_report rep;
    st = wk_validate(R, P, S, 0, &rep);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "%s: invalid skeleton: %s", what, msg);
    return S;
}

/* Signed distance of q from the supporting line of stored edge e, positive
** inside (left of a counter-clockwise edge). */
static double edge_dist(const wk_polygon *P, uint32_t e, double qx, double qy) {
    wk_point a = P->p[e], b = P->p[e + 1 == P->n ? 0 : e + 1];
    double dx = b.x - a.x, dy = b.y - a.y;
    return (dx * (qy - a.y) - dy * (qx - a.x)) / hypot(dx, dy);
}

static void print_skeleton(const wk_polygon *P, const wk_skeleton *S) {
    fprintf(stderr, "  skeleton: %u nodes (%u input), %u arcs\n", S->n_nodes, P->n, S->n_arcs);
    for (uint32_t i = P->n; i < S->n_nodes; i++)
        fprintf(stderr, "  node %u: (%.17g, %.17g) t %.17g\n", i, S->nodes[i].x, S->nodes[i].y,
                S->nodes[i].t);
    for (uint32_t i = 0; i < S->n_arcs; i++)
        fprintf(stderr, "  arc %u: %u -> %u  left %u right %u\n", i, S->arcs[i].a, S->arcs[i].b,
                S->arcs[i].left, S->arcs[i].right);
}

/* S has exactly n + k nodes, k arcs... and its interior nodes match the
** expected ones one to one (xy within tol_d, t within tol_t). */
static void expect_nodes(const char *what, const wk_polygon *P, const wk_skeleton *S,
                         const wk_node *want, uint32_t k, uint32_t arcs) {
    double td = tol_d(P), tt = tol_t(P);
    if (S->n_nodes != P->n + k || S->n_arcs != arcs) print_skeleton(P, S);
    cr_assert_eq(S->n_nodes, P->n + k, "%s: %u interior nodes, want %u", what,
                 S->n_nodes - P->n, k);
    cr_assert_eq(S->n_arcs, arcs, "%s: %u arcs, want %u", what, S->n_arcs, arcs);
    bool used[4096] = {false};
    cr_assert_leq(k, 4096);
    for (uint32_t i = 0; i < k; i++) {
        uint32_t hit = WK_NONE;
        for (uint32_t j = 0; j < k && hit == WK_NONE; j++) {
            const wk_node *s = &S->nodes[P->n + j];
            if (!used[j] && fabs(s->x - want[i].x) <= td && fabs(s->y - want[i].y) <= td &&
                fabs(s->t - want[i].t) <= tt)
                hit = j;
        }
        if (hit == WK_NONE) print_skeleton(P, S);
        cr_assert_neq(hit, WK_NONE, "%s: no node at (%.17g, %.17g) t %.17g (tol %g / %g)", what,
                      want[i].x, want[i].y, want[i].t, td, tt);
        used[hit] = true;
    }
}

/* Index of the interior node within tol of (x, y), WK_NONE if none. */
static uint32_t node_at(const wk_polygon *P, const wk_skeleton *S, double x, double y) {
    double td = tol_d(P);
    for (uint32_t j = 0; j < S->n_nodes; j++)
        if (fabs(S->nodes[j].x - x) <= td && fabs(S->nodes[j].y - y) <= td) return j;
    return WK_NONE;
}

/* Lower envelope of the roof planes: max over nodes of |t - min_e d_e/w_e|
** (in time units) and the most negative min_e d_e (inside test). */
static void envelope_errors(const wk_polygon *P, const wk_skeleton *S, double *t_err,
                            double *outside, uint32_t *worst) {
    *t_err = 0;
    *outside = 0;
    *worst = WK_NONE;
    for (uint32_t j = 0; j < S->n_nodes; j++) {
        const wk_node *v = &S->nodes[j];
        double env = INFINITY, dmin = INFINITY;
        for (uint32_t e = 0; e < P->n; e++) {
            double d = edge_dist(P, e, v->x, v->y);
            env = fmin(env, d / P->w[e]);
            dmin = fmin(dmin, d);
        }
        double err = fabs(v->t - env);
        if (!(err <= *t_err)) {
            *t_err = err;
            *worst = j;
        }
        if (dmin < *outside) *outside = dmin;
    }
}

/* ------------------------------------------------- 1. property sweep */

static const uint32_t PROP_N[] = {8, 12, 20, 50, 100, 200, 500};
#define PROP_N_COUNT (sizeof PROP_N / sizeof PROP_N[0])
static const char *const PROP_W[] = {"unit", "uniform", "two", "int"};
#define PROP_SEEDS 10
#define PROP_PRINT_MAX 5 /* detailed failures printed per family and mode */

static void dump_failure(const wk_polygon *P, const char *family, uint32_t n, uint64_t seed,
                         const char *wmode) {
    const char *dir = getenv("WSKEL_NAIVE_FAILURE_DIR");
    if (!dir || !*dir) return;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s_n%u_s%llu_%s.wpoly", dir, family, n,
             (unsigned long long)seed, wmode);
    FILE *f = fopen(path, "w");
    if (!f) return;
    wk_run R;
    wk_run_init(&R);
    (void)wk_polygon_write_wpoly(&R, f, P);
    fclose(f);
}

static void property_family(const char *family) {
    const wk_variant *V = variant("naive");
    bool small = quick();
    double t0 = now_s();
    unsigned fam_total = 0, fam_valid = 0;
    for (size_t wi = 0; wi < sizeof PROP_W / sizeof PROP_W[0]; wi++) {
        unsigned total = 0, valid = 0, refused = 0, printed = 0;
        char wfmt[64] = "";
        for (size_t ni = 0; ni < PROP_N_COUNT; ni++) {
            uint32_t n = PROP_N[ni];
            if (wi >= 2 && n > 100) continue;
            if (small && n > 200) continue;
            for (uint64_t seed = 1; seed <= PROP_SEEDS; seed++) {
                wk_run R;
                wk_run_init(&R);
                wk_gen_params g;
                wk_gen_params_init(&g);
                g.family = family;
                g.n = n;
                g.seed = seed;
                cr_assert_eq(wk_gen_parse_weights(&R, PROP_W[wi], &g), WK_OK);
                wk_gen_weights_format(&g, wfmt, sizeof wfmt);
                wk_polygon *P = NULL;
                char msg[1024];
                wk_status st = wk_generate(&R, &g, &P);
                if (st == WK_EINPUT) { /* the family refuses this n */
                    refused++;
                    ASSERT_CLEAN_CLOSE(R);
                    continue;
                }
                err_text(&R, msg, sizeof msg);
                cr_assert_eq(st, WK_OK, "%s n=%u seed=%llu: generator failed: %s", family, n,
                             (unsigned long long)seed, msg);
                total++;
                wk_skeleton *S = NULL;
                wk_validate_report rep;
                const char *stage = "naive";
                st = wk_solve(&R, V, P, &S, NULL, NULL);
                if (st == WK_OK) {
                    stage = "validate";
                    st = wk_validate(&R, P, S, 0, &rep);
                }
                if (st == WK_OK) {
                    valid++;
                } else {
                    err_text(&R, msg, sizeof msg);
                    dump_failure(P, family, n, seed, PROP_W[wi]);
                    if (printed++ < PROP_PRINT_MAX) {
                        fprintf(stderr,
                                "naive property: FAIL %s n=%u seed=%llu weights=%s: %s %s: %s\n"
                                "  reproduce: bin/wskel-gen %s --n %u --seed %llu --weights %s"
                                " | bin/wskel --check -\n",
                                family, n, (unsigned long long)seed, wfmt, stage,
                                wk_status_name(st), msg, family, n, (unsigned long long)seed,
                                wfmt);
                        cr_expect_fail("%s n=%u seed=%llu weights=%s: %s %s: %s", family, n,
                                       (unsigned long long)seed, wfmt, stage, wk_status_name(st),
                                       msg);
                    }
                }
                if (S) wk_skeleton_free(&R, S);
                wk_polygon_free(&R, P);
                size_t live = wk_run_close(&R);
                cr_expect_eq(live, 0, "%s n=%u seed=%llu weights=%s: %zu bytes leaked (%s)",
                             family, n, (unsigned long long)seed, wfmt, live,
                             st == WK_OK ? "clean run" : "failed run");
            }
        }
        fprintf(stderr, "naive property: %s %s %u/%u valid%s", family, PROP_W[wi], valid, total,
                refused ? "" : "\n");
        if (refused) fprintf(stderr, " (%u cases refused by the generator)\n", refused);
        cr_expect_eq(valid, total, "%s %s: only %u of %u skeletons valid", family, wfmt, valid,
                     total);
        cr_expect_gt(total, 0, "%s %s: the generator refused every case", family,
                     PROP_W[wi]);
        fam_total += total;
        fam_valid += valid;
    }
    fprintf(stderr, "naive property: %s total %u/%u valid in %.2f s%s\n", family, fam_valid,
            fam_total, now_s() - t0, small ? " (quick: n <= 200)" : "");
    cr_assert_gt(fam_total, 0, "%s: the generator refused every case", family);
}

/* The families with their own test; any other family of wk_gen_families is
** swept by property_other_families, so a new family is never skipped. */
static const char *const KNOWN_FAMILIES[] = {"star",   "comb",     "spiral",   "notched",
                                             "crossing", "random", "monotone", "rectilinear",
                                             "convex", NULL};

#define PROPERTY_TEST(fam) \
    Test(naive, property_##fam, .timeout = 300) { property_family(#fam); }

PROPERTY_TEST(star)
PROPERTY_TEST(comb)
PROPERTY_TEST(spiral)
PROPERTY_TEST(notched)
PROPERTY_TEST(crossing)
PROPERTY_TEST(random)
PROPERTY_TEST(monotone)
PROPERTY_TEST(rectilinear)
PROPERTY_TEST(convex)

Test(naive, property_other_families, .timeout = 300) {
    for (size_t i = 0; wk_gen_families[i]; i++) {
        bool known = false;
        for (size_t j = 0; KNOWN_FAMILIES[j]; j++)
            if (!strcmp(wk_gen_families[i], KNOWN_FAMILIES[j])) known = true;
        if (!known) property_family(wk_gen_families[i]);
    }
    for (size_t j = 0; KNOWN_FAMILIES[j]; j++) {
        bool listed = false;
        for (size_t i = 0; wk_gen_families[i]; i++)
            if (!strcmp(wk_gen_families[i], KNOWN_FAMILIES[j])) listed = true;
        cr_expect(listed, "family %s has a property test but is no longer generated",
                  KNOWN_FAMILIES[j]);
    }
}

/* ------------------------------------------------ 2. convex closed form */

/* naive on a convex P: valid, and every node on the lower envelope of the
** roof planes and inside.  Returns false (after cr_expect) on a failure. */
static bool convex_case(wk_run *R, const wk_polygon *P, const char *what, double *worst_rel) {
    wk_skeleton *S = NULL;
    char msg[1024];
    wk_status st = wk_solve(R, variant("naive"), P, &S, NULL, NULL);
    if (st == WK_OK) st = wk_validate(R, P, S, 0, NULL);
    if (st != WK_OK) {
        err_text(R, msg, sizeof msg);
        fprintf(stderr, "naive convex: FAIL %s: %s: %s\n", what, wk_status_name(st), msg);
        cr_expect_fail("%s: %s: %s", what, wk_status_name(st), msg);
        if (S) wk_skeleton_free(R, S);
        return false;
    }
    double t_err, outside;
    uint32_t worst;
    envelope_errors(P, S, &t_err, &outside, &worst);
    double tt = tol_t(P), td = tol_d(P);
    *worst_rel = fmax(*worst_rel, t_err / tt);
    bool ok = t_err <= tt && outside >= -td;
    if (!ok) {
        const wk_node *v = &S->nodes[worst];
        fprintf(stderr,
                "naive convex: FAIL %s: node %u (%.17g, %.17g) t %.17g is %.3g off the roof "
                "envelope (tol %.3g); most negative edge distance %.3g (tol %.3g)\n",
                what, worst, v->x, v->y, v->t, t_err, tt, outside, td);
        cr_expect_fail("%s: node %u off the roof envelope by %.3g (tol %.3g), outside by %.3g",
                       what, worst, t_err, tt, -outside);
    }
    wk_skeleton_free(R, S);
    return ok;
}

Test(naive, convex_family_closed_form, .timeout = 300) {
    static const uint32_t sizes[] = {3, 4, 5, 6, 8, 12, 20, 50, 100, 200, 500};
    static const char *const modes[] = {"unit", "uniform", "two", "int"};
    unsigned total = 0, good = 0;
    double worst_rel = 0;
    for (size_t mi = 0; mi < 4; mi++)
        for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
            if (quick() && sizes[si] > 200) continue;
            for (uint64_t seed = 1; seed <= 10; seed++) {
                wk_run R;
                wk_run_init(&R);
                wk_polygon *P = gen_polygon(&R, "convex", sizes[si], seed, modes[mi]);
                cr_assert_eq(P->r, 0);
                char what[128];
                snprintf(what, sizeof what, "convex n=%u seed=%llu weights=%s", sizes[si],
                         (unsigned long long)seed, modes[mi]);
                total++;
                good += convex_case(&R, P, what, &worst_rel);
                wk_polygon_free(&R, P);
                ASSERT_CLEAN_CLOSE(R);
            }
        }
    fprintf(stderr,
            "naive convex closed form: generator %u/%u on the envelope (worst error %.3g of the "
            "time tolerance)\n",
            good, total, worst_rel);
    cr_assert_gt(total, 0);
    cr_expect_eq(good, total);
}

/* xorshift64*, for the weights of the hand-built polygons. */
static double rnd(uint64_t *s) {
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ull) >> 11) * 0x1.0p-53;
}

Test(naive, convex_regular_closed_form) {
    static const uint32_t sizes[] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 16, 31, 64, 100};
    unsigned total = 0, good = 0;
    double worst_rel = 0;
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        uint32_t n = sizes[si];
        for (int variant = 0; variant < 4; variant++) { /* 0: unit, 1-3: random weights */
            double x[100], y[100], w[100];
            uint64_t s = 0x9e3779b97f4a7c15ull * (n + 1) + (uint64_t)variant;
            double cx = 100 * rnd(&s) - 50, cy = 100 * rnd(&s) - 50, rad = 1 + 999 * rnd(&s);
            double rot = variant ? 2 * PI * rnd(&s) : 0;
            for (uint32_t i = 0; i < n; i++) {
                x[i] = cx + rad * cos(rot + 2 * PI * i / n);
                y[i] = cy + rad * sin(rot + 2 * PI * i / n);
                w[i] = variant ? 0.25 + 3.75 * rnd(&s) : 1.0;
            }
            wk_run R;
            wk_run_init(&R);
            char what[128];
            snprintf(what, sizeof what, "regular %u-gon (%s weights)", n,
                     variant ? "random" : "unit");
            wk_polygon *P = polygon_named(&R, n, x, y, w, what);
            total++;
            good += convex_case(&R, P, what, &worst_rel);
            if (!variant) { /* unit: everything meets at the centre */
                wk_skeleton *S = solve_valid(&R, P, what);
                wk_node c = {cx, cy, rad * cos(PI / n)};
                expect_nodes(what, P, S, &c, 1, n);
                wk_skeleton_free(&R, S);
            }
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
        }
    }
    fprintf(stderr,
            "naive convex closed form: regular %u/%u on the envelope (worst error %.3g of the "
            "time tolerance)\n",
            good, total, worst_rel);
    cr_expect_eq(good, total);
}

/* ---------------------------------------------------- 3. hand-made */

/* Read NAME, solve, validate, expect the interior nodes and arc count. */
static void hand_case(const char *name, const wk_node *want, uint32_t k, uint32_t arcs) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = read_hand(&R, name);
    wk_skeleton *S = solve_valid(&R, P, name);
    expect_nodes(name, P, S, want, k, arcs);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(naive, hand_square) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = read_hand(&R, "square");
    wk_skeleton *S = solve_valid(&R, P, "square");
    const wk_node c = {0.5, 0.5, 0.5};
    expect_nodes("square", P, S, &c, 1, 4);
    for (uint32_t i = 0; i < 4; i++) /* vertex i between edges i-1 and i */
        cr_expect(has_arc(S, i, 4, (i + 3) % 4, i), "square: arc %u-4 missing", i);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(naive, hand_rectangle_ridge) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = read_hand(&R, "rect2x1");
    wk_skeleton *S = solve_valid(&R, P, "rect2x1");
    const wk_node want[2] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}};
    expect_nodes("rect2x1", P, S, want, 2, 5);
    uint32_t a = node_at(P, S, 0.5, 0.5), b = node_at(P, S, 1.5, 0.5);
    /* the ridge a -> b has the bottom (edge 0) on its right, the top on its left */
    cr_expect(has_arc(S, a, b, 2, 0), "rect2x1: ridge arc missing");
    cr_expect(has_arc(S, 0, a, 3, 0) && has_arc(S, 3, a, 2, 3), "rect2x1: left arcs missing");
    cr_expect(has_arc(S, 1, b, 0, 1) && has_arc(S, 2, b, 1, 2), "rect2x1: right arcs missing");
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(naive, hand_regular_polygons) {
    static const uint32_t sizes[] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 64};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        uint32_t n = sizes[i];
        char name[32];
        snprintf(name, sizeof name, "regular_%02u", n);
        const wk_node c = {0, 0, cos(PI / n)};
        hand_case(name, &c, 1, n);
    }
}

Test(naive, hand_equal_teeth_comb) {
    const wk_node want[15] = {
        {0.5, 4.5, 0.5}, {2.5, 4.5, 0.5}, {4.5, 4.5, 0.5}, {6.5, 4.5, 0.5}, {8.5, 4.5, 0.5},
        {0.5, 1.5, 0.5}, {2.5, 1.5, 0.5}, {4.5, 1.5, 0.5}, {6.5, 1.5, 0.5}, {8.5, 1.5, 0.5},
        {1, 1, 1},       {2.5, 1, 1},     {4.5, 1, 1},     {6.5, 1, 1},     {8, 1, 1}};
    hand_case("comb_equal", want, 15, 34);
}

Test(naive, hand_cross_multi_split) {
    const wk_node want[5] = {{0, 0, 1}, {2, 0, 1}, {0, 2, 1}, {-2, 0, 1}, {0, -2, 1}};
    hand_case("cross", want, 5, 16);
    const wk_node want2[5] = {{0, 0, 1}, {2, 0, 1}, {0, 3, 1}, {-1, 0, 1}, {0, -4, 1}};
    hand_case("cross_uneven", want2, 5, 16);
    /* the four reflex corners (stored 0, 3, 6, 9) run straight to the centre */
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = read_hand(&R, "cross");
    wk_skeleton *S = solve_valid(&R, P, "cross");
    uint32_t c = node_at(P, S, 0, 0);
    cr_assert_neq(c, WK_NONE);
    for (uint32_t v = 0; v < 12; v += 3)
        cr_expect(has_arc(S, v, c, (v + 11) % 12, v), "cross: reflex corner %u not joined to the centre", v);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

static const wk_node H_NODES[10] = {{0.5, 0.5, 0.5}, {0.5, 2.5, 0.5}, {0.5, 3.5, 0.5},
                                    {0.5, 5.5, 0.5}, {3.5, 0.5, 0.5}, {3.5, 2.5, 0.5},
                                    {3.5, 3.5, 0.5}, {3.5, 5.5, 0.5}, {1, 3, 1},
                                    {3, 3, 1}};

Test(naive, hand_h_shape) { hand_case("h_shape", H_NODES, 10, 21); }

Test(naive, hand_collinear_equal_weights) {
    const wk_node c = {1, 1, 1};
    hand_case("collinear_equal", &c, 1, 5);
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = read_hand(&R, "collinear_equal");
    wk_skeleton *S = solve_valid(&R, P, "collinear_equal");
    cr_expect(has_arc(S, 1, 5, 0, 1), "collinear_equal: the 180-degree vertex does not run straight to the centre");
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(naive, hand_collinear_different_weights_both_rules) {
    wk_node got[2][2];
    for (int rule = 0; rule < 2; rule++) {
        wk_run R;
        wk_run_init(&R);
        R.opt.collinear = rule ? WK_COLLINEAR_HIGHER : WK_COLLINEAR_LOWER;
        const char *what = rule ? "collinear_weights (HIGHER)" : "collinear_weights (LOWER)";
        wk_polygon *P = read_hand(&R, "collinear_weights");
        wk_skeleton *S = solve_valid(&R, P, what);
        if (rule == 0) {
            const wk_node want[2] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}};
            expect_nodes(what, P, S, want, 2, 6);
            /* edge 1 (weight 2) removed at t = 0: arc 1-2 along it */
            cr_expect(has_arc(S, 1, 2, 0, 1) || has_arc(S, 1, 2, 1, 0),
                      "%s: no arc along the removed edge 1", what);
        } else {
            const wk_node want[2] = {{1.0 / 3, 2.0 / 3, 1.0 / 3}, {5.0 / 3, 2.0 / 3, 1.0 / 3}};
            expect_nodes(what, P, S, want, 2, 6);
            /* edge 0 (weight 1) removed at t = 0: arc 0-1 along it */
            cr_expect(has_arc(S, 0, 1, 1, 0) || has_arc(S, 0, 1, 0, 1),
                      "%s: no arc along the removed edge 0", what);
        }
        cr_expect_geq(counter(&R, "collinear_resolutions"), 1, "%s: collinear_resolutions = %llu",
                      what, (unsigned long long)counter(&R, "collinear_resolutions"));
        for (int j = 0; j < 2; j++) got[rule][j] = S->nodes[P->n + j];
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
    cr_expect(memcmp(got[0], got[1], sizeof got[0]) != 0, "the two collinear rules agree");
}

/* A heavier parallel edge catches up with a lighter one after an event. */
Test(naive, hand_collinear_catch_up_both_rules) {
    for (int rule = 0; rule < 2; rule++) {
        wk_run R;
        wk_run_init(&R);
        R.opt.collinear = rule ? WK_COLLINEAR_HIGHER : WK_COLLINEAR_LOWER;
        const char *what = rule ? "collinear_catch_up (HIGHER)" : "collinear_catch_up (LOWER)";
        wk_polygon *P = read_hand(&R, "collinear_catch_up");
        wk_skeleton *S = solve_valid(&R, P, what);
        if (rule == 0) {
            const wk_node want[4] = {{30, 10, 10},
                                     {30, 90, 10},
                                     {410.0 / 3, 40.0 / 3, 190.0 / 3},
                                     {410.0 / 3, 110.0 / 3, 190.0 / 3}};
            expect_nodes(what, P, S, want, 4, 9);
            uint32_t a = node_at(P, S, 30, 10), b = node_at(P, S, 30, 90);
            cr_expect(has_arc(S, a, b, 0, 2), "%s: no arc along the removed edge 0", what);
        } else {
            const wk_node want[4] = {{30, 10, 10}, {30, -40, 10}, {150, 0, 50}, {150, 50, 50}};
            expect_nodes(what, P, S, want, 4, 9);
            uint32_t a = node_at(P, S, 30, 10), b = node_at(P, S, 30, -40);
            cr_expect(has_arc(S, a, b, 0, 2), "%s: no arc along the removed edge 2", what);
        }
        cr_expect_geq(counter(&R, "collinear_resolutions"), 1, "%s: collinear_resolutions = %llu",
                      what, (unsigned long long)counter(&R, "collinear_resolutions"));
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

Test(naive, hand_weighted_square) {
    const wk_node want[2] = {{0.25, 0.75, 0.25}, {0.75, 0.75, 0.25}};
    hand_case("weighted_square", want, 2, 5);
}

/* The weighted triangle's only node: d_e(p) = w_e t for its three edges. */
static wk_node triangle_node(const double *x, const double *y, const double *w) {
    double A[3][4];
    for (int e = 0; e < 3; e++) {
        int f = (e + 1) % 3;
        double dx = x[f] - x[e], dy = y[f] - y[e], len = hypot(dx, dy);
        double nx = -dy / len, ny = dx / len; /* left normal: inside for CCW */
        A[e][0] = nx;
        A[e][1] = ny;
        A[e][2] = -w[e];
        A[e][3] = nx * x[e] + ny * y[e];
    }
#define DET3(c0, c1, c2)                                                    \
    (A[0][c0] * (A[1][c1] * A[2][c2] - A[1][c2] * A[2][c1]) -               \
     A[0][c1] * (A[1][c0] * A[2][c2] - A[1][c2] * A[2][c0]) +               \
     A[0][c2] * (A[1][c0] * A[2][c1] - A[1][c1] * A[2][c0]))
    double D = DET3(0, 1, 2);
    wk_node r = {DET3(3, 1, 2) / D, DET3(0, 3, 2) / D, DET3(0, 1, 3) / D};
#undef DET3
    return r;
}

Test(naive, hand_weighted_triangles) {
    static const char *const files[2] = {"triangle_acute", "triangle_obtuse"};
    for (int f = 0; f < 2; f++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = read_hand(&R, files[f]);
        double x[3], y[3], w[3];
        for (int i = 0; i < 3; i++) x[i] = P->p[i].x, y[i] = P->p[i].y, w[i] = P->w[i];
        wk_node c = triangle_node(x, y, w);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
        hand_case(files[f], &c, 1, 3);
    }
    /* More weight triples on three triangles, built here. */
    static const double tri[3][6] = {
        {0, 4, 1, 0, 0, 3}, {0, 10, 1, 0, 0, 1}, {0, 1000, 500, 0, 0, 0.5}};
    static const double triples[][3] = {
        {1, 1, 1},   {1, 2, 3},     {3, 2, 1},      {1, 1, 10},     {10, 10, 1},
        {0.1, 1, 1}, {1, 100, 1},   {1, 1e3, 1e-3}, {2, 2, 1},      {1, 2, 2},
        {7, 1, 5},   {0.5, 0.5, 2}, {1e-4, 1, 1},   {1, 1.5, 2.25}, {4, 1, 1}};
    unsigned cases = 0;
    for (int t = 0; t < 3; t++)
        for (size_t k = 0; k < sizeof triples / sizeof triples[0]; k++) {
            wk_run R;
            wk_run_init(&R);
            const double *x = tri[t], *y = tri[t] + 3, *w = triples[k];
            char what[128];
            snprintf(what, sizeof what, "triangle %d weights %g %g %g", t, w[0], w[1], w[2]);
            wk_polygon *P = polygon_named(&R, 3, x, y, w, what);
            wk_skeleton *S = solve_valid(&R, P, what);
            wk_node c = triangle_node(x, y, w);
            expect_nodes(what, P, S, &c, 1, 3);
            for (uint32_t v = 0; v < 3; v++)
                cr_expect(has_arc(S, v, 3, (v + 2) % 3, v), "%s: arc %u-3 missing", what, v);
            wk_skeleton_free(&R, S);
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
            cases++;
        }
    fprintf(stderr, "naive hand: %u weighted triangles\n", cases + 2);
}

Test(naive, hand_reflex_preserving_edge_event) {
    double ts = 0.1 / (3 * sqrt(2.0) - 2);
    const wk_node want[4] = {{ts, ts, ts}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}};
    hand_case("reflex_preserving", want, 4, 10);
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = read_hand(&R, "reflex_preserving");
    cr_assert(wk_polygon_is_reflex(P, 0) && wk_polygon_is_reflex(P, 6),
              "both chamfer ends must be reflex");
    wk_skeleton *S = solve_valid(&R, P, "reflex_preserving");
    uint32_t x = node_at(P, S, ts, ts), c = node_at(P, S, 1, 1);
    cr_assert(x != WK_NONE && c != WK_NONE);
    /* the chamfer ends run into x; the reflex vertex of edges 5 and 0 goes on to (1,1) */
    cr_expect(has_arc(S, 6, x, 5, 6) && has_arc(S, 0, x, 6, 0), "chamfer arcs missing");
    cr_expect(has_arc(S, x, c, 5, 0), "no arc from the event point to (1,1) between edges 5 and 0");
    /* exactly one edge event leaves a reflex vertex: the chamfer's */
    cr_expect_eq(counter(&R, "reflex_preserving_edge_events"), 1,
                 "reflex_preserving: reflex_preserving_edge_events = %llu, want 1",
                 (unsigned long long)counter(&R, "reflex_preserving_edge_events"));
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(naive, hand_sliver) {
    const wk_node want[2] = {{0.0005, 0.0005, 0.0005}, {999.9995, 0.0005, 0.0005}};
    hand_case("sliver", want, 2, 5);
}

Test(naive, hand_offset_1e6_file) {
    wk_node want[10];
    for (int i = 0; i < 10; i++)
        want[i] = (wk_node){H_NODES[i].x + 1e6, H_NODES[i].y + 1e6, H_NODES[i].t};
    hand_case("h_shape_offset", want, 10, 21);
}

/* The polygons the translation, orientation and determinism tests use:
** hand files and a few generated ones. */
typedef struct poly_src { const char *hand, *family; uint32_t n; uint64_t seed; const char *w; } poly_src;
static const poly_src SOURCES[] = {
    {"square", 0, 0, 0, 0},          {"h_shape", 0, 0, 0, 0},
    {"cross", 0, 0, 0, 0},           {"comb_equal", 0, 0, 0, 0},
    {"collinear_weights", 0, 0, 0, 0}, {"reflex_preserving", 0, 0, 0, 0},
    {"triangle_obtuse", 0, 0, 0, 0}, {"regular_12", 0, 0, 0, 0},
    {"sliver", 0, 0, 0, 0},
    {0, "random", 50, 1, "uniform"}, {0, "star", 100, 2, "two"},
    {0, "rectilinear", 50, 3, "unit"}, {0, "notched", 100, 4, "int"},
    {0, "spiral", 100, 5, "uniform"}, {0, "monotone", 50, 6, "unit"},
};
#define N_SOURCES (sizeof SOURCES / sizeof SOURCES[0])

static wk_polygon *source_polygon(wk_run *R, const poly_src *s, char *what, size_t size) {
    if (s->hand) {
        snprintf(what, size, "%s", s->hand);
        return read_hand(R, s->hand);
    }
    snprintf(what, size, "%s n=%u seed=%llu weights=%s", s->family, s->n,
             (unsigned long long)s->seed, s->w);
    return gen_polygon(R, s->family, s->n, s->seed, s->w);
}

/* P and Q store the same weights in the same order (same_skeleton checks
** that they store the same vertices). */
static bool same_weights(const wk_polygon *P, const wk_polygon *Q) {
    if (P->n != Q->n) return false;
    for (uint32_t i = 0; i < P->n; i++)
        if (P->w[i] != Q->w[i]) return false;
    return true;
}

Test(naive, translation_by_1e6) {
    for (size_t k = 0; k < N_SOURCES; k++) {
        wk_run R;
        wk_run_init(&R);
        char what[128], why[512];
        wk_polygon *P = source_polygon(&R, &SOURCES[k], what, sizeof what);
        uint32_t n = P->n;
        double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
        cr_assert(x && y);
        const double D = 1e6;
        for (uint32_t i = 0; i < n; i++) x[i] = P->p[i].x + D, y[i] = P->p[i].y + D;
        wk_polygon *Q = polygon_named(&R, n, x, y, P->w, "shifted");
        free(x);
        free(y);
        cr_assert(!Q->reversed);
        wk_skeleton *S = solve_valid(&R, P, what);
        char qwhat[160];
        snprintf(qwhat, sizeof qwhat, "%s + (1e6, 1e6)", what);
        wk_skeleton *T = solve_valid(&R, Q, qwhat);
        /* rounding the shifted coordinates moves them by up to 2^-33 ~ 1.2e-10;
        ** compare within the validator's default distance tolerance */
        double tol = 1e-6 * wk_polygon_scale(P);
        cr_expect(same_weights(P, Q), "%s: stored weights differ", qwhat);
        sk_match m = {.tol = tol, .tol_t = tol / max_weight(P), .dx = D, .dy = D};
        cr_expect(same_skeleton(S, T, m, why, sizeof why), "%s: translated skeleton differs: %s",
                  qwhat, why);
        wk_skeleton_free(&R, T);
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, Q);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

Test(naive, clockwise_input_same_skeleton) {
    for (size_t k = 0; k < N_SOURCES; k++) {
        wk_run R;
        wk_run_init(&R);
        char what[128], why[512];
        wk_polygon *P = source_polygon(&R, &SOURCES[k], what, sizeof what);
        uint32_t n = P->n;
        double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), *w = malloc(n * sizeof *w);
        cr_assert(x && y && w);
        /* clockwise: input vertex k = stored n-1-k; input edge k runs stored
        ** n-1-k -> n-2-k, i.e. it is stored edge (n-2-k) mod n */
        for (uint32_t i = 0; i < n; i++) {
            x[i] = P->p[n - 1 - i].x;
            y[i] = P->p[n - 1 - i].y;
            w[i] = P->w[(2 * n - 2 - i) % n];
        }
        wk_polygon *Q = polygon_named(&R, n, x, y, w, "clockwise");
        free(x);
        free(y);
        free(w);
        cr_assert(Q->reversed, "%s: reversed input not detected as clockwise", what);
        wk_skeleton *S = solve_valid(&R, P, what);
        wk_skeleton *T = solve_valid(&R, Q, "clockwise copy");
        cr_expect(same_weights(P, Q), "%s: the clockwise copy stores other weights", what);
        sk_match m = {.tol = tol_d(P), .tol_t = tol_t(P)};
        cr_expect(same_skeleton(S, T, m, why, sizeof why),
                  "%s: clockwise copy gives another skeleton: %s", what, why);
        wk_skeleton_free(&R, T);
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, Q);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

/* With unit weights an edge event never leaves a reflex vertex: an edge
** between vertices of interior angles a and b shrinks only if
** cot(a/2) + cot(b/2) > 0, i.e. a + b < 2 pi, and the new vertex has angle
** a + b - pi < pi.  So the counter must stay 0 (000, section 1). */
Test(naive, unit_weights_no_reflex_preserving_edge_events) {
    static const uint32_t sizes[] = {8, 20, 50, 200};
    unsigned cases = 0;
    for (size_t fi = 0; wk_gen_families[fi]; fi++)
        for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
            for (uint64_t seed = 1; seed <= 3; seed++) {
                wk_run R;
                wk_run_init(&R);
                const char *family = wk_gen_families[fi];
                wk_polygon *P = NULL;
                if (gen(&R, family, sizes[si], -1, seed, NULL, &P) != WK_OK) {
                    ASSERT_CLEAN_CLOSE(R);
                    continue;
                }
                wk_skeleton *S = NULL;
                if (wk_solve(&R, variant("naive"), P, &S, NULL, NULL) == WK_OK) { /* failures: property tests */
                    cases++;
                    cr_expect_eq(counter(&R, "reflex_preserving_edge_events"), 0,
                                 "%s n=%u seed=%llu (unit weights): "
                                 "reflex_preserving_edge_events = %llu",
                                 family, sizes[si], (unsigned long long)seed,
                                 (unsigned long long)counter(&R, "reflex_preserving_edge_events"));
                    wk_skeleton_free(&R, S);
                }
                wk_polygon_free(&R, P);
                ASSERT_CLEAN_CLOSE(R);
            }
    cr_assert_gt(cases, 0);
}

/* -------------------------------------------- beyond the sweep's grid */

/* Generated polygons outside the property grid (other n and seeds, both
** collinear rules, weights that differ in the 7th digit) on which naive
** failed in a wider exploratory sweep; each must now validate. */
typedef struct extra_case {
    const char *family;
    uint32_t n;
    uint64_t seed;
    const char *weights;
    wk_collinear_rule rule;
} extra_case;

static const extra_case EXTRA_CASES[] = {
    /* a heavier vertical wall catches up with a lighter parallel one (the
    ** collinear rule after an event) while other events happen at once */
    {"rectilinear", 34, 59, "int", WK_COLLINEAR_LOWER},
    {"rectilinear", 38, 131, "int", WK_COLLINEAR_LOWER},
    {"rectilinear", 150, 3, "int", WK_COLLINEAR_HIGHER},
    {"rectilinear", 150, 13, "int", WK_COLLINEAR_HIGHER},
    /* nearly equal weights: events that nearly coincide */
    {"rectilinear", 18, 26, "uniform:1:1.000001", WK_COLLINEAR_LOWER},
    {"rectilinear", 18, 41, "uniform:1:1.000001", WK_COLLINEAR_HIGHER},
    {"rectilinear", 30, 120, "two:1:1.0000001", WK_COLLINEAR_LOWER},
    {"comb", 30, 51, "two:1:1.0000001", WK_COLLINEAR_LOWER},
    {"comb", 32, 10, "two:1:1.0000001", WK_COLLINEAR_LOWER},
    {"comb", 32, 11, "two:1:1.0000001", WK_COLLINEAR_LOWER},
};

Test(naive, extra_sweep_cases) {
    unsigned good = 0, total = 0;
    for (size_t k = 0; k < sizeof EXTRA_CASES / sizeof EXTRA_CASES[0]; k++) {
        const extra_case *c = &EXTRA_CASES[k];
        wk_run R;
        wk_run_init(&R);
        R.opt.collinear = c->rule;
        wk_polygon *P = gen_polygon(&R, c->family, c->n, c->seed, c->weights);
        const char *rule = c->rule == WK_COLLINEAR_HIGHER ? "higher" : "lower";
        wk_skeleton *S = NULL;
        const char *stage = "naive";
        wk_status st = wk_solve(&R, variant("naive"), P, &S, NULL, NULL);
        if (st == WK_OK) {
            stage = "validate";
            st = wk_validate(&R, P, S, 0, NULL);
        }
        total++;
        if (st == WK_OK) {
            good++;
        } else {
            char msg[1024];
            err_text(&R, msg, sizeof msg);
            fprintf(stderr,
                    "naive extra: FAIL %s n=%u seed=%llu weights=%s collinear=%s: %s %s: %s\n"
                    "  reproduce: bin/wskel-gen %s --n %u --seed %llu --weights %s"
                    " | bin/wskel --check --collinear %s -\n",
                    c->family, c->n, (unsigned long long)c->seed, c->weights, rule, stage,
                    wk_status_name(st), msg, c->family, c->n, (unsigned long long)c->seed,
                    c->weights, rule);
            cr_expect_fail("%s n=%u seed=%llu weights=%s collinear=%s: %s %s: %s", c->family,
                           c->n, (unsigned long long)c->seed, c->weights, rule, stage,
                           wk_status_name(st), msg);
        }
        if (S) wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
    fprintf(stderr, "naive extra: %u/%u valid\n", good, total);
}

/* ---------------------------------------------------- 4. determinism */

Test(naive, deterministic_bit_identical) {
    for (size_t k = 0; k < N_SOURCES; k++) {
        wk_run R[2];
        wk_polygon *P[2];
        wk_skeleton *S[2];
        char what[128];
        for (int j = 0; j < 2; j++) {
            wk_run_init(&R[j]);
            P[j] = source_polygon(&R[j], &SOURCES[k], what, sizeof what);
            S[j] = solve_valid(&R[j], P[j], what);
        }
        cr_assert_eq(S[0]->n_nodes, S[1]->n_nodes, "%s: node counts differ", what);
        cr_assert_eq(S[0]->n_arcs, S[1]->n_arcs, "%s: arc counts differ", what);
        cr_expect(!memcmp(S[0]->nodes, S[1]->nodes, S[0]->n_nodes * sizeof(wk_node)),
                  "%s: nodes differ between two runs", what);
        cr_expect(!memcmp(S[0]->arcs, S[1]->arcs, S[0]->n_arcs * sizeof(wk_arc)),
                  "%s: arcs differ between two runs", what);
for (uint32_t id = 0; id < wk_counter_count(R[0].variant); id++)
            cr_expect_eq(R[0].counters.c[id], R[1].counters.c[id], "%s: counter %s %llu vs %llu",
                         what, wk_counter_def_at(R[0].variant, id)->name,
                         (unsigned long long)R[0].counters.c[id],
                         (unsigned long long)R[1].counters.c[id]);
        for (int j = 0; j < 2; j++) {
            wk_skeleton_free(&R[j], S[j]);
            wk_polygon_free(&R[j], P[j]);
            ASSERT_CLEAN_CLOSE(R[j]);
        }
    }
}

/* ------------------------------------------------- 5. fault injection */

static void fault_injection(const char *name) {
    uint64_t k;
    unsigned failed = 0;
    for (k = 0; k < 1000000; k++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = read_hand(&R, name);
        R.alloc.fail_after = (int64_t)(R.alloc.calls + k);
        wk_skeleton *S = NULL;
        wk_status st = wk_solve(&R, variant("naive"), P, &S, NULL, NULL);
        R.alloc.fail_after = -1;
        bool done = st == WK_OK;
        if (done) {
            char msg[1024];
            wk_status vs = wk_validate(&R, P, S, 0, NULL);
            err_text(&R, msg, sizeof msg);
            cr_expect_eq(vs, WK_OK, "%s: fail_after +%llu: run succeeded but invalid: %s", name,
                         (unsigned long long)k, msg);
            wk_skeleton_free(&R, S);
        } else {
            char msg[1024];
            err_text(&R, msg, sizeof msg);
            cr_expect_eq(st, WK_ENOMEM, "%s: fail_after +%llu: status %s, want WK_ENOMEM: %s", name,
                         (unsigned long long)k, wk_status_name(st), msg);
            cr_expect_eq(R.err.code, WK_ENOMEM, "%s: fail_after +%llu: R.err.code %d", name,
                         (unsigned long long)k, (int)R.err.code);
            cr_expect_null(S, "%s: fail_after +%llu: output set on failure", name,
                           (unsigned long long)k);
            failed++;
        }
        wk_polygon_free(&R, P);
        size_t live = wk_run_close(&R);
        cr_assert_eq(live, 0, "%s: fail_after +%llu (%s): %zu bytes leaked", name,
                     (unsigned long long)k, done ? "success" : "failure", live);
        if (done) break;
    }
    cr_assert_lt(k, 1000000, "%s: never succeeded", name);
    cr_expect_gt(failed, 0, "%s: no allocation to fail", name);
    fprintf(stderr, "naive fault injection: %s: %u failing runs, success at fail_after +%llu\n",
            name, failed, (unsigned long long)k);
}

Test(naive, fault_injection_cross) { fault_injection("cross"); }
Test(naive, fault_injection_collinear_weights) { fault_injection("collinear_weights"); }
Test(naive, fault_injection_reflex_preserving) { fault_injection("reflex_preserving"); }
Test(naive, fault_injection_comb) { fault_injection("comb_equal"); }
