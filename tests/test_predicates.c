/*
** test_predicates.c: wk_orient2d and the segment predicates against an
** independent exact reference (GMP rationals: every double converts exactly
** to an mpq, and the determinant is then computed without rounding).
**
** The near-degenerate families are the ones where double evaluation is known
** to fail (Shewchuk's 2^-53 grid against the line y = x, products whose
** difference is below their rounding error), so each test also checks that
** the fast version really does disagree somewhere: otherwise the test would
** not exercise the exact stage at all.
*/
#include <criterion/criterion.h>
#include <gmp.h>
#include <math.h>
#include <stdint.h>

#include "wskel.h"
#include "helpers.h"

/* ---- reference ---- */

static int ref_orient(wk_point a, wk_point b, wk_point c) {
    mpq_t ax, ay, bx, by, cx, cy, l, r;
    mpq_inits(ax, ay, bx, by, cx, cy, l, r, NULL);
    mpq_set_d(ax, a.x);
    mpq_set_d(ay, a.y);
    mpq_set_d(bx, b.x);
    mpq_set_d(by, b.y);
    mpq_set_d(cx, c.x);
    mpq_set_d(cy, c.y);
    mpq_sub(ax, ax, cx); /* a - c */
    mpq_sub(ay, ay, cy);
    mpq_sub(bx, bx, cx); /* b - c */
    mpq_sub(by, by, cy);
    mpq_mul(l, ax, by);
    mpq_mul(r, ay, bx);
    mpq_sub(l, l, r);
    int s = mpq_sgn(l);
    mpq_clears(ax, ay, bx, by, cx, cy, l, r, NULL);
    return s;
}

/* Exact closed-segment intersection from the reference orientation. */
static bool ref_between(wk_point a, wk_point b, wk_point p) {
    return fmin(a.x, b.x) <= p.x && p.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= p.y &&
           p.y <= fmax(a.y, b.y);
}
static bool ref_intersect(wk_point a, wk_point b, wk_point c, wk_point d) {
    int o1 = ref_orient(a, b, c), o2 = ref_orient(a, b, d);
    int o3 = ref_orient(c, d, a), o4 = ref_orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && ref_between(a, b, c)) || (o2 == 0 && ref_between(a, b, d)) ||
           (o3 == 0 && ref_between(c, d, a)) || (o4 == 0 && ref_between(c, d, b));
}

/* Deterministic generator (splitmix64): tests repeat exactly. */
static uint64_t rng_next(uint64_t *s) {
    uint64_t z = (*s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}
static double rng_unit(uint64_t *s) { return (double)(rng_next(s) >> 11) * 0x1p-53; }

/* ---- orient2d ---- */

Test(predicates, obvious_cases_need_no_exact_stage) {
    wk_run R;
    wk_run_init(&R);
    bool ex = true;
    wk_point o = {0, 0}, x = {1, 0}, y = {0, 1};
    cr_assert_eq(wk_orient2d(o, x, y, &ex), 1);
    cr_assert_not(ex);
    cr_assert_eq(wk_orient2d(o, y, x, &ex), -1);
    cr_assert_not(ex);
    cr_assert_eq(wk_orient2d(o, x, (wk_point){2, 0}, &ex), 0);
    cr_assert_not(ex, "exactly zero products need no exact stage");
    cr_assert_eq(wk_orient2d(o, x, y, NULL), 1, "exact_used may be NULL");
    cr_assert_eq(wk_orient2d_fast(o, x, y), 1);
    cr_assert_eq(wk_orient2d_fast(o, y, x), -1);
    ASSERT_CLEAN_CLOSE(R);
}

/* Shewchuk's demonstration: points (0.5 + i u, 0.5 + j u), u = 2^-53, tested
** against the line through (12, 12) and (24, 24). */
Test(predicates, shewchuk_grid_matches_gmp) {
    wk_run R;
    wk_run_init(&R);
    const double u = 0x1p-53;
    wk_point q = {12, 12}, r = {24, 24};
    int wrong_fast = 0, exact_runs = 0, zero = 0, pos = 0, neg = 0;
    for (int i = 0; i < 256; i++)
        for (int j = 0; j < 256; j++) {
            wk_point p = {0.5 + i * u, 0.5 + j * u};
            bool ex;
            int s = wk_orient2d(p, q, r, &ex);
            int ref = ref_orient(p, q, r);
            cr_assert_eq(s, ref, "i=%d j=%d: got %d, exact %d", i, j, s, ref);
            exact_runs += ex;
            wrong_fast += wk_orient2d_fast(p, q, r) != ref;
            zero += ref == 0;
            pos += ref > 0;
            neg += ref < 0;
        }
    cr_assert_gt(wrong_fast, 1000, "the grid must defeat plain doubles (%d wrong)", wrong_fast);
    cr_assert_gt(exact_runs, 0);
    cr_assert(zero > 0 && pos > 0 && neg > 0, "all three answers occur (%d %d %d)", zero, pos,
              neg);
    ASSERT_CLEAN_CLOSE(R);
}

/* Exact differences, products that round to the same double:
** (2^27+1)(2^27-1) = 2^54 - 1 rounds to 2^54 = 2^27 * 2^27. */
Test(predicates, product_cancellation) {
    wk_run R;
    wk_run_init(&R);
    const double t = 0x1p27;
    wk_point a = {t + 1, t}, b = {t, t - 1}, c = {0, 0};
    bool ex;
    cr_assert_eq(wk_orient2d_fast(a, b, c), 0, "doubles see no turn");
    cr_assert_eq(wk_orient2d(a, b, c, &ex), -1, "det = -1: a right turn");
    cr_assert(ex);
    cr_assert_eq(ref_orient(a, b, c), -1);
    cr_assert_eq(wk_orient2d(b, a, c, NULL), 1);
    cr_assert_eq(wk_orient2d(a, c, b, NULL), 1);
    /* The same with inexact differences: shift everything by 0.25. */
    wk_point a2 = {a.x + 0.25, a.y}, b2 = {b.x + 0.25, b.y}, c2 = {0.25, 0};
    cr_assert_eq(wk_orient2d(a2, b2, c2, NULL), ref_orient(a2, b2, c2));
    ASSERT_CLEAN_CLOSE(R);
}

/* Random points on random lines, rounded: mostly near-collinear. */
Test(predicates, random_near_collinear_matches_gmp) {
    wk_run R;
    wk_run_init(&R);
    uint64_t s = 42;
    int wrong_fast = 0, exact_runs = 0;
    for (int k = 0; k < 100000; k++) {
        double scale = ldexp(1.0, (int)(rng_next(&s) % 40) - 20);
        wk_point a = {(rng_unit(&s) - 0.5) * scale, (rng_unit(&s) - 0.5) * scale};
        wk_point b = {(rng_unit(&s) - 0.5) * scale, (rng_unit(&s) - 0.5) * scale};
        double t = rng_unit(&s) * 3 - 1;
        wk_point c = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        if (k % 3 == 1) c.x = nextafter(c.x, INFINITY);
        if (k % 5 == 2) { /* exactly collinear: a multiple of a grid step */
            a = (wk_point){(double)(int)(rng_next(&s) % 1000), (double)(int)(rng_next(&s) % 1000)};
            b = (wk_point){a.x + 3, a.y + 7};
            c = (wk_point){a.x - 6 * 1024, a.y - 14 * 1024};
        }
        bool ex;
        int got = wk_orient2d(a, b, c, &ex);
        int ref = ref_orient(a, b, c);
        cr_assert_eq(got, ref, "case %d", k);
        /* Cyclic shifts keep the sign, swaps flip it. */
        cr_assert_eq(wk_orient2d(b, c, a, NULL), ref);
        cr_assert_eq(wk_orient2d(c, a, b, NULL), ref);
        cr_assert_eq(wk_orient2d(b, a, c, NULL), -ref);
        exact_runs += ex;
        wrong_fast += wk_orient2d_fast(a, b, c) != ref;
    }
    cr_assert_gt(exact_runs, 1000);
    cr_assert_gt(wrong_fast, 100, "only %d fast failures: the cases are not hard", wrong_fast);
    ASSERT_CLEAN_CLOSE(R);
}

Test(predicates, extreme_but_allowed_magnitudes) {
    wk_run R;
    wk_run_init(&R);
    uint64_t s = 7;
    for (int k = 0; k < 20000; k++) {
        double m = k % 2 ? 1e150 : 1e-100;
        wk_point a = {(rng_unit(&s) - 0.5) * m, (rng_unit(&s) - 0.5) * m};
        wk_point b = {(rng_unit(&s) - 0.5) * m, (rng_unit(&s) - 0.5) * m};
        double t = rng_unit(&s);
        wk_point c = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        cr_assert_eq(wk_orient2d(a, b, c, NULL), ref_orient(a, b, c), "case %d", k);
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- segments ---- */

Test(predicates, segment_cases) {
    wk_run R;
    wk_run_init(&R);
    wk_point a = {0, 0}, b = {4, 0};
#define P(x, y) ((wk_point){(x), (y)})
    cr_assert_eq(wk_segments_meet(a, b, P(2, -1), P(2, 1)), WK_SEG_CROSS);
    cr_assert_eq(wk_segments_meet(a, b, P(2, 0), P(2, 1)), WK_SEG_TOUCH, "T-junction");
    cr_assert_eq(wk_segments_meet(a, b, P(4, 0), P(5, 1)), WK_SEG_TOUCH, "shared endpoint");
    cr_assert_eq(wk_segments_meet(a, b, P(4, 0), P(6, 0)), WK_SEG_TOUCH, "end to end");
    cr_assert_eq(wk_segments_meet(a, b, P(3, 0), P(6, 0)), WK_SEG_OVERLAP);
    cr_assert_eq(wk_segments_meet(a, b, P(1, 0), P(2, 0)), WK_SEG_OVERLAP, "contained");
    cr_assert_eq(wk_segments_meet(a, b, P(5, 0), P(6, 0)), WK_SEG_DISJOINT, "collinear apart");
    cr_assert_eq(wk_segments_meet(a, b, P(0, 1), P(4, 1)), WK_SEG_DISJOINT, "parallel");
    cr_assert_eq(wk_segments_meet(a, b, P(5, -1), P(5, 1)), WK_SEG_DISJOINT, "line hits, segment not");
    cr_assert_eq(wk_segments_meet(a, b, P(2, 0), P(2, 0)), WK_SEG_TOUCH, "point on segment");
    cr_assert_eq(wk_segments_meet(a, b, P(2, 1e-300), P(2, 1e-300)), WK_SEG_DISJOINT);
    cr_assert_eq(wk_segments_meet(P(1, 1), P(1, 1), P(1, 1), P(1, 1)), WK_SEG_TOUCH);
    /* Vertical segments: lexicographic extents use y. */
    cr_assert_eq(wk_segments_meet(P(0, 0), P(0, 4), P(0, 3), P(0, 6)), WK_SEG_OVERLAP);
    cr_assert_eq(wk_segments_meet(P(0, 0), P(0, 4), P(0, 5), P(0, 6)), WK_SEG_DISJOINT);
    cr_assert(wk_segments_intersect(a, b, P(2, -1), P(2, 1)));
    cr_assert_not(wk_segments_intersect(a, b, P(5, 0), P(6, 0)));
    /* Near-degenerate: m is within rounding of the line through c and d, and
    ** a vertical segment rises from m: it crosses [c, d] iff m is below. */
    wk_point c = {0.1, 0.3}, d = {0.7, 2.1};
    for (int k = -3; k <= 3; k++) {
        wk_point m = {0.3, nextafter(0.9, k < 0 ? 0.0 : 2.0)};
        for (int i = 0; i < (k < 0 ? -k : k); i++) m.y = nextafter(m.y, k < 0 ? 0.0 : 2.0);
        if (k == 0) m.y = 0.9;
        int side = ref_orient(c, d, m);
        wk_seg_meet want = side == 0 ? WK_SEG_TOUCH : side < 0 ? WK_SEG_CROSS : WK_SEG_DISJOINT;
        cr_assert_eq(wk_segments_meet(c, d, m, P(0.3, 5)), want, "k=%d side=%d", k, side);
    }
#undef P
    ASSERT_CLEAN_CLOSE(R);
}

Test(predicates, random_segments_match_gmp) {
    wk_run R;
    wk_run_init(&R);
    uint64_t s = 99;
    int hits = 0;
    for (int k = 0; k < 50000; k++) {
        wk_point p[4];
        for (int i = 0; i < 4; i++) {
            /* A coarse grid (exact degeneracies) or near-collinear decimals. */
            if (k % 2)
                p[i] = (wk_point){(double)(rng_next(&s) % 5), (double)(rng_next(&s) % 5)};
            else {
                double t = rng_unit(&s) * 2 - 0.5;
                p[i] = (wk_point){0.1 + t * 0.7, 0.3 + t * 2.1};
                if (rng_next(&s) % 3 == 0) p[i].y = nextafter(p[i].y, 0);
            }
        }
        bool got = wk_segments_intersect(p[0], p[1], p[2], p[3]);
        bool ref = ref_intersect(p[0], p[1], p[2], p[3]);
        cr_assert_eq(got, ref, "case %d", k);
        hits += got;
        wk_seg_meet m = wk_segments_meet(p[0], p[1], p[2], p[3]);
        cr_assert_eq(m == WK_SEG_DISJOINT, !ref);
        cr_assert_eq(wk_segments_meet(p[2], p[3], p[0], p[1]), m, "symmetric");
    }
    cr_assert(hits > 1000 && hits < 49000, "a mix of answers (%d)", hits);
    ASSERT_CLEAN_CLOSE(R);
}
