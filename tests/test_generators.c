/*
** test_generators.c: the polygon families of bench/generators.h.
**
** For every family over n in 8..2000 and ten seeds: generation succeeds,
** exactly n vertices, counter-clockwise, exactly the promised reflex count,
** simple (wk_polygon_from_arrays's sweep, and for small n an independent
** O(n^2) check with wk_segments_meet), deterministic per seed, different
** across seeds; the weight modes stay in range and never move a vertex; the
** crossing family's r bisector rays cross pairwise, r(r-1)/2 times (counted
** by brute force); impossible parameters fail with WK_EINPUT and a message
** naming the limit; allocation failures are clean.  The families with holes
** (holes, convex --holes H): every polygon validates, has 1 + H rings split
** as documented, no ring reversed, rings pairwise disjoint and holes inside
** (O(n^2) oracle), deterministic, H = 0 one simple ring.  Each test has its own
** run and ends with zero live bytes.
*/
#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

#include "generators.h"
#include "helpers.h"
#include "rng.h"

static const uint32_t sizes[] = {8, 9, 10, 11, 13, 16, 31, 64, 100, 257, 500, 1000, 2000};
#define N_SIZES (sizeof sizes / sizeof sizes[0])
#define N_SEEDS 10

/* The reflex count a family promises for (n, r as asked), -1 if none. */
static int64_t expected_r(const char *f, uint32_t n, int64_t r) {
    if (!strcmp(f, "comb")) return 2 * ((int64_t)(n / 4) - 1);
    if (!strcmp(f, "spiral") || !strcmp(f, "rectilinear")) return (int64_t)(n / 2) - 2;
    if (!strcmp(f, "convex")) return 0;
    if (!strcmp(f, "notched")) return r >= 0 ? r : n / 4;
    if (!strcmp(f, "crossing")) return r >= 0 ? r : 2 * (((int64_t)n - 4) / 6);
    if (!strcmp(f, "monotone")) return r >= 0 ? r : ((int64_t)n - 2) / 2;
    if (!strcmp(f, "star")) return r;
    return -1; /* random, coastline */
}

static bool family_takes(const char *f, uint32_t n) {
    return strcmp(f, "rectilinear") != 0 || n % 2 == 0;
}

/* Independent simplicity oracle, O(n^2): adjacent edges share only their
** vertex, other edges nothing. */
static bool brute_simple(const wk_polygon *P) {
    uint32_t n = P->n;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) {
            wk_seg_meet m = wk_segments_meet(P->p[i], P->p[(i + 1) % n], P->p[j],
                                             P->p[(j + 1) % n]);
            bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if (adjacent ? m != WK_SEG_TOUCH : m != WK_SEG_DISJOINT) return false;
        }
    return true;
}

static uint32_t count_reflex(const wk_polygon *P) {
    uint32_t r = 0;
    for (uint32_t i = 0; i < P->n; i++) r += wk_polygon_is_reflex(P, i);
    return r;
}

/* Check one generated polygon against the family's promises. */
static void check_polygon(const char *f, uint32_t n, int64_t r_asked, uint64_t seed,
                          const wk_polygon *P) {
    cr_assert_eq(P->n, n, "%s n=%u seed=%llu: %u vertices", f, n, (unsigned long long)seed, P->n);
    cr_assert(!P->reversed, "%s n=%u: generated clockwise", f, n);
    cr_assert(wk_polygon_area(P) > 0, "%s n=%u: area", f, n);
    cr_assert_eq(count_reflex(P), P->r, "%s n=%u: P->r", f, n);
    int64_t want = expected_r(f, n, r_asked);
    if (want >= 0)
        cr_assert_eq((int64_t)P->r, want, "%s n=%u r=%lld seed=%llu: %u reflex, want %lld", f,
                     n, (long long)r_asked, (unsigned long long)seed, P->r, (long long)want);
    for (uint32_t i = 0; i < n; i++) cr_assert(isfinite(P->p[i].x) && isfinite(P->p[i].y));
    if (n <= 300) cr_assert(brute_simple(P), "%s n=%u seed=%llu: not simple", f, n,
                            (unsigned long long)seed);
}

Test(generators, every_family_spread) {
    wk_run R;
    wk_run_init(&R);
    for (size_t k = 0; wk_gen_families[k]; k++) {
        const char *f = wk_gen_families[k];
        for (size_t s = 0; s < N_SIZES; s++) {
            uint32_t n = sizes[s];
            if (!family_takes(f, n)) continue;
            wk_polygon *prev = NULL;
            for (uint64_t seed = 1; seed <= N_SEEDS; seed++) {
                wk_polygon *P = NULL, *Q = NULL;
                wk_status st = gen(&R, f, n, -1, seed, NULL, &P);
                cr_assert_eq(st, WK_OK, "%s n=%u seed=%llu: %s", f, n, (unsigned long long)seed,
                             R.err.msg);
                check_polygon(f, n, -1, seed, P);
                /* deterministic per seed, different across seeds */
                cr_assert_eq(gen(&R, f, n, -1, seed, NULL, &Q), WK_OK);
                cr_assert(!memcmp(P->p, Q->p, n * sizeof *P->p), "%s n=%u seed=%llu: rerun differs",
                          f, n, (unsigned long long)seed);
                if (prev)
                    cr_assert(memcmp(P->p, prev->p, n * sizeof *P->p) != 0,
                              "%s n=%u: seeds %llu and %llu agree", f, n,
                              (unsigned long long)seed - 1, (unsigned long long)seed);
                wk_polygon_free(&R, Q);
                wk_polygon_free(&R, prev);
                prev = P;
            }
            wk_polygon_free(&R, prev);
        }
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* The families that take --r, at the edges of their ranges. */
Test(generators, chosen_r) {
    wk_run R;
    wk_run_init(&R);
    static const char *const fams[] = {"star", "notched", "crossing", "monotone"};
    for (size_t k = 0; k < 4; k++) {
        const char *f = fams[k];
        for (size_t s = 0; s < N_SIZES; s++) {
            uint32_t n = sizes[s];
            int64_t top = !strcmp(f, "monotone")   ? (int64_t)n - 3
                          : !strcmp(f, "crossing") ? ((int64_t)n - 4) / 3
                                                   : n / 2;
            int64_t rs[] = {0, 1, 2, top / 3, top / 2 + 1, top - 1, top};
            for (size_t j = 0; j < sizeof rs / sizeof rs[0]; j++) {
                int64_t r = rs[j];
                if (r < 0 || r > top) continue;
                for (uint64_t seed = 1; seed <= N_SEEDS; seed++) {
                    wk_polygon *P = NULL;
                    wk_status st = gen(&R, f, n, r, seed, NULL, &P);
                    cr_assert_eq(st, WK_OK, "%s n=%u r=%lld seed=%llu: %s", f, n, (long long)r,
                                 (unsigned long long)seed, R.err.msg);
                    check_polygon(f, n, r, seed, P);
                    wk_polygon_free(&R, P);
                }
            }
        }
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, deterministic_per_seed) {
    wk_run R;
    wk_run_init(&R);
    for (size_t k = 0; wk_gen_families[k]; k++) {
        const char *f = wk_gen_families[k];
        for (uint32_t n = 8; n <= 2000; n *= 5) {
            wk_polygon *A = NULL, *B = NULL, *C = NULL;
            cr_assert_eq(gen(&R, f, n, -1, 42, "uniform", &A), WK_OK, "%s", R.err.msg);
            cr_assert_eq(gen(&R, f, n, -1, 42, "uniform", &B), WK_OK, "%s", R.err.msg);
            cr_assert_eq(gen(&R, f, n, -1, 43, "uniform", &C), WK_OK, "%s", R.err.msg);
            cr_assert(!memcmp(A->p, B->p, n * sizeof *A->p), "%s n=%u: same seed differs", f, n);
            cr_assert(!memcmp(A->w, B->w, n * sizeof *A->w), "%s n=%u: weights differ", f, n);
            cr_assert(memcmp(A->p, C->p, n * sizeof *A->p) != 0, "%s n=%u: seeds 42, 43 agree",
                      f, n);
            wk_polygon_free(&R, A);
            wk_polygon_free(&R, B);
            wk_polygon_free(&R, C);
        }
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, weights_in_range_and_geometry_unmoved) {
    wk_run R;
    wk_run_init(&R);
    static const struct {
        const char *mode;
        wk_weight_mode m;
        double a, b;
    } cases[] = {
        {"unit", WK_W_UNIT, 1, 1},          {"uniform", WK_W_UNIFORM, 0.5, 2},
        {"uniform:1:5", WK_W_UNIFORM, 1, 5}, {"two", WK_W_TWO, 1, 3},
        {"two:2.5:0.25", WK_W_TWO, 2.5, 0.25}, {"int", WK_W_INT, 1, 4},
        {"int:3:9", WK_W_INT, 3, 9},
    };
    for (size_t k = 0; wk_gen_families[k]; k++) {
        const char *f = wk_gen_families[k];
        wk_polygon *U = NULL;
        cr_assert_eq(gen(&R, f, 500, -1, 7, NULL, &U), WK_OK);
        for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
            wk_polygon *P = NULL;
            cr_assert_eq(gen(&R, f, 500, -1, 7, cases[c].mode, &P), WK_OK, "%s %s: %s", f,
                         cases[c].mode, R.err.msg);
            cr_assert(!memcmp(U->p, P->p, P->n * sizeof *P->p), "%s: weights %s moved vertices",
                      f, cases[c].mode);
            double a = cases[c].a, b = cases[c].b;
            bool seen_a = false, seen_b = false;
            for (uint32_t i = 0; i < P->n; i++) {
                double w = P->w[i];
                switch (cases[c].m) {
                case WK_W_UNIT: cr_assert_eq(w, 1.0); break;
                case WK_W_UNIFORM: cr_assert(w >= a && w <= b, "%s: %g", cases[c].mode, w); break;
                case WK_W_TWO: cr_assert(w == a || w == b, "%s: %g", cases[c].mode, w); break;
                case WK_W_INT:
                    cr_assert(w >= a && w <= b && w == floor(w), "%s: %g", cases[c].mode, w);
                    break;
                }
                seen_a |= w == a;
                seen_b |= w == b;
            }
            if (cases[c].m == WK_W_TWO || cases[c].m == WK_W_INT)
                cr_assert(seen_a && seen_b, "%s: both ends should occur in 500 draws",
                          cases[c].mode);
            wk_polygon_free(&R, P);
        }
        wk_polygon_free(&R, U);
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, weight_mode_parsing) {
    wk_run R;
    wk_run_init(&R);
    static const char *const bad[] = {"", "foo", "unit:1:2", "uniform:3:1", "uniform:1",
                                      "uniform:1:x", "two:0:1", "two:-1:2", "int:1.5:3",
                                      "int:1:inf", "uniform:nan:2", "int:0:3"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        wk_run Q;
        wk_run_init(&Q);
        wk_gen_params g;
        wk_gen_params_init(&g);
        cr_assert_eq(wk_gen_parse_weights(&Q, bad[i], &g), WK_EUSAGE, "'%s' accepted", bad[i]);
        cr_assert_eq(g.weights, WK_W_UNIT, "'%s' changed g", bad[i]);
        ASSERT_CLEAN_CLOSE(Q);
    }
    static const char *const good[] = {"unit", "uniform", "uniform:0.1:0.1", "two:1:3",
                                       "int:1:4", "uniform:0.3:1e3"};
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
        wk_gen_params g, h;
        wk_gen_params_init(&g);
        wk_gen_params_init(&h);
        cr_assert_eq(wk_gen_parse_weights(&R, good[i], &g), WK_OK, "'%s': %s", good[i],
                     R.err.msg);
        char buf[128];
        wk_gen_weights_format(&g, buf, sizeof buf);
        cr_assert_eq(wk_gen_parse_weights(&R, buf, &h), WK_OK, "'%s'", buf);
        cr_assert(g.weights == h.weights && g.wa == h.wa && g.wb == h.wb, "'%s' -> '%s'",
                  good[i], buf);
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, impossible_parameters) {
    static const struct {
        const char *family;
        uint32_t n;
        int64_t r;
        wk_status st;
        const char *msg;
    } cases[] = {
        {"notched", 100, 60, WK_EINPUT, "notched: r=60 > n/2=50"},
        {"star", 100, 51, WK_EINPUT, "star: r=51 > n/2=50"},
        {"star", 4, 1, WK_EINPUT, "star: r=1 > 0 needs n >= 5"},
        {"notched", 4, 2, WK_EINPUT, "notched: r=2 > n-3=1"},
        {"monotone", 10, 8, WK_EINPUT, "monotone: r=8 > n-3=7"},
        {"crossing", 30, 9, WK_EINPUT, "crossing: n=30 < 3r+4=31 (r=9)"},
        {"rectilinear", 11, -1, WK_EINPUT, "rectilinear: n=11 is odd"},
        {"comb", 3, -1, WK_EINPUT, "n=3"},
        {"comb", 16, 5, WK_EINPUT, "comb: r=5 cannot be chosen: r = 2*(floor(n/4)-1) = 6"},
        {"spiral", 20, 3, WK_EINPUT, "spiral: r=3 cannot be chosen: r = floor(n/2)-2 = 8"},
        {"convex", 20, 1, WK_EINPUT, "convex: r=1 cannot be chosen"},
        {"spiral", 5, -1, WK_EINPUT, "spiral: n=5 < 6"},
        {"random", 20, 3, WK_EINPUT, "random: r cannot be chosen"},
        {"coastline", 100, 50, WK_EINPUT, "coastline: r cannot be chosen"},
        {"star", 2, -1, WK_EINPUT, "star: n=2 is outside [3, "},
        {"convex", WK_GEN_N_MAX + 1, -1, WK_EINPUT, "is outside"},
        {"hexagon", 20, -1, WK_EUSAGE, "unknown family 'hexagon'"},
        {NULL, 20, -1, WK_EUSAGE, "unknown family"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = (wk_polygon *)&R; /* must come back NULL */
        wk_status st = gen(&R, cases[i].family, cases[i].n, cases[i].r, 1, NULL, &P);
        cr_assert_eq(st, cases[i].st, "case %zu: status %d", i, st);
        cr_assert_null(P);
        cr_assert(strstr(R.err.msg, cases[i].msg), "case %zu: message '%s' lacks '%s'", i,
                  R.err.msg, cases[i].msg);
        ASSERT_CLEAN_CLOSE(R);
    }
}

/* ---- the crossing family's promise, by brute force ---- */

typedef struct ray {
    wk_point a, b; /* from the reflex vertex to the first boundary point hit */
} ray;

/* The unit-weight bisector of reflex vertex i, cut at the first boundary
** point it reaches. */
static ray bisector_ray(const wk_polygon *P, uint32_t i) {
    uint32_t n = P->n;
    wk_point p = P->p[i], u = P->p[(i + n - 1) % n], v = P->p[(i + 1) % n];
    double ex = p.x - u.x, ey = p.y - u.y, fx = v.x - p.x, fy = v.y - p.y;
    double le = hypot(ex, ey), lf = hypot(fx, fy);
    /* inward (left) normals of the two edges; their sum is the bisector */
    double dx = -ey / le - fy / lf, dy = ex / le + fx / lf;
    double best = INFINITY;
    for (uint32_t e = 0; e < n; e++) {
        uint32_t f = (e + 1) % n;
        if (e == i || f == i) continue;
        wk_point a = P->p[e], b = P->p[f];
        double sx = b.x - a.x, sy = b.y - a.y;
        double den = dx * sy - dy * sx;
        if (den == 0) continue;
        double qx = a.x - p.x, qy = a.y - p.y;
        double t = (qx * sy - qy * sx) / den;  /* along the ray */
        double s = (qx * dy - qy * dx) / den;  /* along the edge */
        if (t > 0 && s >= 0 && s <= 1 && t < best) best = t;
    }
    return (ray){p, {p.x + best * dx, p.y + best * dy}};
}

static uint64_t count_ray_crossings(const wk_polygon *P) {
    ray rays[128];
    uint32_t k = 0;
    for (uint32_t i = 0; i < P->n; i++)
        if (wk_polygon_is_reflex(P, i)) {
            cr_assert(k < 128);
            rays[k++] = bisector_ray(P, i);
        }
    uint64_t crossings = 0;
    for (uint32_t i = 0; i < k; i++)
        for (uint32_t j = i + 1; j < k; j++)
            crossings += wk_segments_meet(rays[i].a, rays[i].b, rays[j].a, rays[j].b) ==
                         WK_SEG_CROSS;
    return crossings;
}

Test(generators, crossing_family_ray_crossings) {
    wk_run R;
    wk_run_init(&R);
    static const int64_t rs[] = {0, 1, 2, 3, 4, 5, 6, 9, 10, 16, 21, 32, 40, 101, 128};
    for (size_t j = 0; j < sizeof rs / sizeof rs[0]; j++) {
        int64_t r = rs[j];
        uint64_t want = (uint64_t)r * (uint64_t)(r > 0 ? r - 1 : 0) / 2;
        for (uint32_t pad = 4; pad <= 54; pad += 25)
            for (uint64_t seed = 1; seed <= 3; seed++) {
                uint32_t n = (uint32_t)(3 * r) + pad;
                wk_polygon *P = NULL;
                cr_assert_eq(gen(&R, "crossing", n, r, seed, NULL, &P), WK_OK, "%s", R.err.msg);
                uint64_t got = count_ray_crossings(P);
                cr_assert_eq(got, want, "crossing r=%lld n=%u seed=%llu: %llu crossings, want %llu",
                             (long long)r, n, (unsigned long long)seed, (unsigned long long)got,
                             (unsigned long long)want);
                wk_polygon_free(&R, P);
            }
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- shape promises of the structured families ---- */

Test(generators, orthogonal_families_on_integers) {
    wk_run R;
    wk_run_init(&R);
    for (uint32_t n = 4; n <= 403; n++) {
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, "comb", n, -1, n, NULL, &P), WK_OK, "comb n=%u: %s", n, R.err.msg);
        check_polygon("comb", n, -1, n, P);
        for (uint32_t i = 0; i < n; i++)
            cr_assert(P->p[i].x == floor(P->p[i].x) && P->p[i].y == floor(P->p[i].y));
        wk_polygon_free(&R, P);
        if (n % 2) continue;
        cr_assert_eq(gen(&R, "rectilinear", n, -1, n, NULL, &P), WK_OK, "%s", R.err.msg);
        check_polygon("rectilinear", n, -1, n, P);
        for (uint32_t i = 0; i < n; i++) {
            wk_point a = P->p[i], b = P->p[(i + 1) % n];
            cr_assert(a.x == floor(a.x) && a.y == floor(a.y));
            cr_assert((a.x == b.x) != (a.y == b.y), "rectilinear n=%u: edge %u not axis-parallel",
                      n, i);
        }
        wk_polygon_free(&R, P);
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, monotone_is_x_monotone) {
    wk_run R;
    wk_run_init(&R);
    for (uint32_t n = 3; n <= 300; n += 7)
        for (int64_t r = 0; r <= (int64_t)n - 3; r += 1 + (int64_t)n / 5) {
            wk_polygon *P = NULL;
            cr_assert_eq(gen(&R, "monotone", n, r, n + 1000 * (uint64_t)r, NULL, &P), WK_OK,
                         "%s", R.err.msg);
            check_polygon("monotone", n, r, 0, P);
            /* x strictly increases from the leftmost vertex to the rightmost,
            ** then strictly decreases: exactly two direction changes. */
            uint32_t changes = 0;
            for (uint32_t i = 0; i < n; i++) {
                double d0 = P->p[(i + 1) % n].x - P->p[i].x;
                double d1 = P->p[(i + 2) % n].x - P->p[(i + 1) % n].x;
                cr_assert(d0 != 0, "monotone n=%u: vertical edge", n);
                changes += (d0 > 0) != (d1 > 0);
            }
            cr_assert_eq(changes, 2, "monotone n=%u r=%lld: not x-monotone", n, (long long)r);
            wk_polygon_free(&R, P);
        }
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- failure paths and size ---- */

/* Fail the k-th allocation for k = 0, 1, ...: every failure is WK_ENOMEM
** with nothing left allocated, until generation succeeds. */
Test(generators, allocation_failures_are_clean) {
    static const struct {
        const char *family;
        uint32_t n;
        int64_t r;
    } cases[] = {{"star", 50, 10}, {"notched", 50, -1}, {"monotone", 50, 20}, {"random", 50, -1},
                 {"rectilinear", 50, -1}, {"spiral", 50, -1}, {"crossing", 50, 6},
                 {"coastline", 50, -1}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        for (int64_t k = 0;; k++) {
            cr_assert(k < 1000, "%s: never succeeds", cases[c].family);
            wk_run R;
            wk_run_init(&R);
            R.alloc.fail_after = k;
            wk_polygon *P = NULL;
            wk_status st = gen(&R, cases[c].family, cases[c].n, cases[c].r, 3, "uniform", &P);
            if (st == WK_OK) {
                check_polygon(cases[c].family, cases[c].n, cases[c].r, 3, P);
                wk_polygon_free(&R, P);
                ASSERT_CLEAN_CLOSE(R);
                break;
            }
            cr_assert_eq(st, WK_ENOMEM, "%s k=%lld: %s", cases[c].family, (long long)k,
                         R.err.msg);
            cr_assert_null(P);
            cr_assert_eq(wk_run_close(&R), 0, "%s k=%lld: leak", cases[c].family, (long long)k);
        }
    }
}

Test(generators, large_n_smoke) {
    wk_run R;
    wk_run_init(&R);
    static const char *const fams[] = {"star", "spiral"};
    for (size_t k = 0; k < 2; k++) {
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, fams[k], 100000, -1, 1, NULL, &P), WK_OK, "%s", R.err.msg);
        cr_assert_eq(P->n, 100000);
        if (!strcmp(fams[k], "spiral")) cr_assert_eq(P->r, 100000 / 2 - 2);
        wk_polygon_free(&R, P);
    }
    wk_polygon *P = NULL;
    cr_assert_eq(gen(&R, "star", 100000, 50000, 1, NULL, &P), WK_OK, "%s", R.err.msg);
    cr_assert_eq(P->r, 50000);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- the families with holes (holes, convex --holes) ---- */

static wk_status gen_h(wk_run *R, const char *family, uint32_t n, uint32_t holes, uint64_t seed,
                       const char *weights, wk_polygon **P) {
    return gen_holes(R, family, n, -1, holes, seed, weights, P);
}

/* Independent oracle for a polygon with holes, O(n^2): edges of one ring
** meet only when adjacent (at their shared vertex), edges of different
** rings never; each hole's first vertex is inside the outer ring (crossing
** number with exact orientation tests; the rings are disjoint, so one
** vertex decides). */
static bool brute_rings_ok(const wk_polygon *P) {
    uint32_t n = P->n;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) {
            uint32_t ni = wk_polygon_next(P, i), nj = wk_polygon_next(P, j);
            wk_seg_meet m = wk_segments_meet(P->p[i], P->p[ni], P->p[j], P->p[nj]);
            bool adjacent = ni == j || nj == i;
            if (adjacent ? m != WK_SEG_TOUCH : m != WK_SEG_DISJOINT) return false;
        }
    for (uint32_t k = 1; k < P->n_rings; k++) {
        wk_point q = P->p[P->ring_start[k]];
        bool inside = false;
        for (uint32_t i = 0; i < P->ring_start[1]; i++) {
            wk_point a = P->p[i], b = P->p[wk_polygon_next(P, i)];
            if ((a.y > q.y) != (b.y > q.y)) {
                int o = wk_orient2d(a, b, q, NULL);
                if ((b.y > a.y) ? o > 0 : o < 0) inside = !inside;
            }
        }
        if (!inside) return false;
    }
    return true;
}

/* The documented split: holes get max(3H, floor(n/2)) (at most n-3) in
** all, evenly, the first ones one more; the outer ring the rest. */
static void check_split(const wk_polygon *P, uint32_t n, uint32_t H) {
    cr_assert_eq(P->n_rings, H + 1, "n=%u H=%u: %u rings", n, H, P->n_rings);
    uint32_t nh = H == 0 ? 0 : n / 2;
    if (nh < 3 * H) nh = 3 * H;
    if (H > 0 && nh > n - 3) nh = n - 3;
    cr_assert_eq(P->ring_start[1], n - nh, "n=%u H=%u: outer ring %u", n, H, P->ring_start[1]);
    for (uint32_t j = 0; j < H; j++) {
        uint32_t m = P->ring_start[j + 2] - P->ring_start[j + 1];
        cr_assert_eq(m, nh / H + (j < nh % H), "n=%u H=%u: hole %u has %u vertices", n, H, j, m);
        cr_assert(m >= 3);
    }
}

static void check_holes_polygon(wk_run *R, const char *f, uint32_t n, uint32_t H, uint64_t seed,
                                const wk_polygon *P) {
    cr_assert_eq(P->n, n, "%s n=%u H=%u seed=%llu: %u vertices", f, n, H,
                 (unsigned long long)seed, P->n);
    check_split(P, n, H);
    cr_assert(!P->reversed, "%s n=%u H=%u: outer ring generated clockwise", f, n, H);
    for (uint32_t i = 0; i < n; i++) {
        cr_assert_eq(P->input_index[i], i, "%s n=%u H=%u: ring reversed on input", f, n, H);
        cr_assert(isfinite(P->p[i].x) && isfinite(P->p[i].y));
    }
    cr_assert_eq(wk_polygon_validate(R, P), WK_OK, "%s n=%u H=%u seed=%llu: %s", f, n, H,
                 (unsigned long long)seed, R->err.msg);
    cr_assert(wk_polygon_area(P) > 0);
    cr_assert_eq(count_reflex(P), P->r);
    if (!strcmp(f, "convex"))
        cr_assert_eq(P->r, n - P->ring_start[1], "convex n=%u H=%u: r=%u, want the hole vertices",
                     n, H, P->r);
    if (n <= 400)
        cr_assert(brute_rings_ok(P), "%s n=%u H=%u seed=%llu: rings meet or a hole is outside",
                  f, n, H, (unsigned long long)seed);
}

Test(generators, holes_valid_split_and_counts) {
    wk_run R;
    wk_run_init(&R);
    static const char *const fams[] = {"holes", "convex"};
    static const uint32_t Hs[] = {0, 1, 2, 3, 4, 5, 8, 17, 50};
    static const uint32_t extra[] = {0, 1, 7, 40, 300};
    for (size_t k = 0; k < 2; k++)
        for (size_t h = 0; h < sizeof Hs / sizeof Hs[0]; h++)
            for (size_t e = 0; e < sizeof extra / sizeof extra[0]; e++) {
                uint32_t H = Hs[h], n = 3 * H + 3 + extra[e];
                for (uint64_t seed = 1; seed <= 6; seed++) {
                    wk_polygon *P = NULL;
                    wk_status st = gen_h(&R, fams[k], n, H, seed, "uniform", &P);
                    cr_assert_eq(st, WK_OK, "%s n=%u H=%u seed=%llu: %s", fams[k], n, H,
                                 (unsigned long long)seed, R.err.msg);
                    check_holes_polygon(&R, fams[k], n, H, seed, P);
                    wk_polygon_free(&R, P);
                }
            }
    ASSERT_CLEAN_CLOSE(R);
}

/* H = 0: one simple counter-clockwise ring; convex --holes 0 is exactly
** the convex family of before (same draws). */
Test(generators, holes_zero_is_simple) {
    wk_run R;
    wk_run_init(&R);
    for (uint32_t n = 3; n <= 300; n += 13)
        for (uint64_t seed = 1; seed <= 4; seed++) {
            wk_polygon *P = NULL, *Q = NULL;
            cr_assert_eq(gen_h(&R, "holes", n, 0, seed, NULL, &P), WK_OK, "%s", R.err.msg);
            cr_assert_eq(P->n_rings, 1);
            cr_assert_null(P->ring_of);
            check_polygon("holes", n, -1, seed, P);
            cr_assert_eq(gen_h(&R, "convex", n, 0, seed, NULL, &Q), WK_OK, "%s", R.err.msg);
            wk_polygon *C = NULL;
            cr_assert_eq(gen(&R, "convex", n, -1, seed, NULL, &C), WK_OK);
            cr_assert_eq(Q->n_rings, 1);
            cr_assert(!memcmp(Q->p, C->p, n * sizeof *Q->p), "convex --holes 0 moved");
            wk_polygon_free(&R, P);
            wk_polygon_free(&R, Q);
            wk_polygon_free(&R, C);
        }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, holes_deterministic_and_weights_unmoved) {
    wk_run R;
    wk_run_init(&R);
    static const char *const fams[] = {"holes", "convex"};
    for (size_t k = 0; k < 2; k++)
        for (uint32_t H = 1; H <= 30; H += 7) {
            uint32_t n = 12 * H + 20;
            wk_polygon *A = NULL, *B = NULL, *C = NULL, *U = NULL;
            cr_assert_eq(gen_h(&R, fams[k], n, H, 42, "int", &A), WK_OK, "%s", R.err.msg);
            cr_assert_eq(gen_h(&R, fams[k], n, H, 42, "int", &B), WK_OK, "%s", R.err.msg);
            cr_assert_eq(gen_h(&R, fams[k], n, H, 43, "int", &C), WK_OK, "%s", R.err.msg);
            cr_assert_eq(gen_h(&R, fams[k], n, H, 42, NULL, &U), WK_OK, "%s", R.err.msg);
            cr_assert(!memcmp(A->p, B->p, n * sizeof *A->p), "%s H=%u: rerun differs", fams[k], H);
            cr_assert(!memcmp(A->w, B->w, n * sizeof *A->w), "%s H=%u: weights differ", fams[k], H);
            cr_assert(!memcmp(A->ring_start, B->ring_start, (H + 2) * sizeof *A->ring_start));
            cr_assert(memcmp(A->p, C->p, n * sizeof *A->p) != 0, "%s H=%u: seeds agree", fams[k],
                      H);
            cr_assert(!memcmp(A->p, U->p, n * sizeof *A->p), "%s H=%u: weights moved vertices",
                      fams[k], H);
            bool varied = false;
            for (uint32_t i = 0; i < n; i++) {
                cr_assert(A->w[i] >= 1 && A->w[i] <= 4 && A->w[i] == floor(A->w[i]));
                varied |= A->w[i] != A->w[0];
            }
            cr_assert(varied, "%s H=%u: one weight everywhere", fams[k], H);
            wk_polygon_free(&R, A);
            wk_polygon_free(&R, B);
            wk_polygon_free(&R, C);
            wk_polygon_free(&R, U);
        }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, holes_impossible_parameters) {
    static const struct {
        const char *family;
        uint32_t n, holes;
        int64_t r;
        wk_status st;
        const char *msg;
    } cases[] = {
        {"holes", 11, 3, -1, WK_EINPUT, "holes: n=11 < 3*holes+3=12"},
        {"convex", 5, 1, -1, WK_EINPUT, "convex: n=5 < 3*holes+3=6"},
        {"holes", 20, 2, 4, WK_EINPUT, "holes: r=4 cannot be chosen"},
        {"convex", 20, 2, 4, WK_EINPUT, "convex: r=4 cannot be chosen: r = the hole vertices = 10"},
        {"star", 20, 1, -1, WK_EINPUT, "star: holes=1: this family has no holes"},
        {"comb", 40, 2, -1, WK_EINPUT, "comb: holes=2: this family has no holes"},
        {"holes", 100, WK_POLYGON_MAX_RINGS, -1, WK_EINPUT, "holes: holes="},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        wk_run R;
        wk_run_init(&R);
        wk_gen_params g;
        wk_gen_params_init(&g);
        g.family = cases[i].family;
        g.n = cases[i].n;
        g.holes = cases[i].holes;
        g.r = cases[i].r;
        wk_polygon *P = (wk_polygon *)&R;
        wk_status st = wk_generate(&R, &g, &P);
        cr_assert_eq(st, cases[i].st, "case %zu: status %d (%s)", i, st, R.err.msg);
        cr_assert_null(P);
        cr_assert(strstr(R.err.msg, cases[i].msg), "case %zu: message '%s' lacks '%s'", i,
                  R.err.msg, cases[i].msg);
        ASSERT_CLEAN_CLOSE(R);
    }
    cr_assert(wk_gen_family_takes_holes("holes") && wk_gen_family_takes_holes("convex"));
    cr_assert(!wk_gen_family_takes_holes("star") && !wk_gen_family_takes_holes("nope"));
}

Test(generators, holes_allocation_failures_are_clean) {
    static const char *const fams[] = {"holes", "convex"};
    for (size_t c = 0; c < 2; c++)
        for (int64_t k = 0;; k++) {
            cr_assert(k < 1000, "%s: never succeeds", fams[c]);
            wk_run R;
            wk_run_init(&R);
            R.alloc.fail_after = k;
            wk_polygon *P = NULL;
            wk_status st = gen_h(&R, fams[c], 60, 4, 3, "uniform", &P);
            if (st == WK_OK) {
                R.alloc.fail_after = -1; /* the check's own validation allocates */
                check_holes_polygon(&R, fams[c], 60, 4, 3, P);
                wk_polygon_free(&R, P);
                ASSERT_CLEAN_CLOSE(R);
                break;
            }
            cr_assert_eq(st, WK_ENOMEM, "%s k=%lld: %s", fams[c], (long long)k, R.err.msg);
            cr_assert_null(P);
            cr_assert_eq(wk_run_close(&R), 0, "%s k=%lld: leak", fams[c], (long long)k);
        }
}

Test(generators, holes_large_smoke) {
    wk_run R;
    wk_run_init(&R);
    static const uint32_t Hs[] = {1, 100, 10000};
    for (size_t h = 0; h < 3; h++) {
        wk_polygon *P = NULL;
        cr_assert_eq(gen_h(&R, "holes", 100000, Hs[h], 1, NULL, &P), WK_OK, "H=%u: %s", Hs[h],
                     R.err.msg);
        check_split(P, 100000, Hs[h]);
        wk_polygon_free(&R, P);
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- the coastline family ---- */

/* The stated range of the coastline's reflex count: within 1.5 sqrt(n) + 4
** of n/2 (about five standard deviations of the fair coins of the motifs;
** the k0 <= 7 convex corners of the coarse polygon are inside the 4). */
static void check_coastline_r(const wk_polygon *P, uint64_t seed) {
    double n = P->n, dev = fabs((double)P->r - n / 2);
    cr_assert(dev <= 1.5 * sqrt(n) + 4, "coastline n=%u seed=%llu: r=%u, |r - n/2| = %g > %g",
              P->n, (unsigned long long)seed, P->r, dev, 1.5 * sqrt(n) + 4);
}

Test(generators, coastline_every_small_n) {
    wk_run R;
    wk_run_init(&R);
    for (uint32_t n = 3; n <= 600; n++)
        for (uint64_t seed = 1; seed <= 3; seed++) {
            wk_polygon *P = NULL;
            cr_assert_eq(gen(&R, "coastline", n, -1, seed, NULL, &P), WK_OK,
                         "coastline n=%u seed=%llu: %s", n, (unsigned long long)seed, R.err.msg);
            check_polygon("coastline", n, -1, seed, P);
            if (n >= 16) check_coastline_r(P, seed);
            wk_polygon_free(&R, P);
        }
    ASSERT_CLEAN_CLOSE(R);
}

/* A seed whose coarse polygon has k0 vertices: the family's first draw
** is k0 = 4 + below(4) from the geometry stream (stream 1). */
static uint64_t coastline_seed_for(uint32_t k0) {
    for (uint64_t seed = 1;; seed++) {
        wk_rng g;
        wk_rng_seed(&g, seed, 1);
        if (4 + wk_rng_below(&g, 4) == k0) return seed;
    }
}

/* Around the sizes where a full Koch level begins (n = k0 4^L, k0 = 4..7:
** the partial level is empty, or one edge gets a 2-child motif, or all but
** one get 4), up to 114688 (bench/README.md reports the same up to 2 * 10^6),
** and the large sizes the benchmarks use. */
Test(generators, coastline_level_boundaries_and_large_n) {
    wk_run R;
    wk_run_init(&R);
    uint32_t top = quick() ? 20000 : 120000;
    for (uint32_t k0 = 4; k0 <= 7; k0++) {
        uint64_t seed = coastline_seed_for(k0);
        for (uint32_t b = k0 * 4; b <= top; b *= 4)
            for (uint32_t n = b - 1; n <= b + 1; n++) {
                wk_polygon *P = NULL;
                cr_assert_eq(gen(&R, "coastline", n, -1, seed, NULL, &P), WK_OK,
                             "coastline n=%u seed=%llu: %s", n, (unsigned long long)seed,
                             R.err.msg);
                cr_assert_eq(P->n, n);
                cr_assert(!P->reversed);
                check_coastline_r(P, seed);
                wk_polygon_free(&R, P);
            }
    }
    static const uint32_t big[] = {100000, 1000000, 2000000};
    for (size_t i = 0; i < (quick() ? 1 : 3); i++) {
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, "coastline", big[i], -1, 1, NULL, &P), WK_OK, "n=%u: %s", big[i],
                     R.err.msg);
        cr_assert_eq(P->n, big[i]);
        check_coastline_r(P, 1);
        wk_polygon_free(&R, P);
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(generators, coastline_deterministic) {
    wk_run R;
    wk_run_init(&R);
    static const uint32_t ns[] = {16, 257, 5000, 100000};
    for (size_t i = 0; i < 4; i++) {
        uint32_t n = ns[i];
        wk_polygon *A = NULL, *B = NULL, *C = NULL, *W = NULL;
        cr_assert_eq(gen(&R, "coastline", n, -1, 9, NULL, &A), WK_OK, "%s", R.err.msg);
        cr_assert_eq(gen(&R, "coastline", n, -1, 9, NULL, &B), WK_OK, "%s", R.err.msg);
        cr_assert_eq(gen(&R, "coastline", n, -1, 10, NULL, &C), WK_OK, "%s", R.err.msg);
        cr_assert_eq(gen(&R, "coastline", n, -1, 9, "two", &W), WK_OK, "%s", R.err.msg);
        cr_assert(!memcmp(A->p, B->p, n * sizeof *A->p), "coastline n=%u: rerun differs", n);
        cr_assert_eq(A->r, B->r);
        cr_assert(memcmp(A->p, C->p, n * sizeof *A->p) != 0, "coastline n=%u: seeds agree", n);
        cr_assert(!memcmp(A->p, W->p, n * sizeof *A->p), "coastline n=%u: weights moved it", n);
        wk_polygon_free(&R, A);
        wk_polygon_free(&R, B);
        wk_polygon_free(&R, C);
        wk_polygon_free(&R, W);
    }
    ASSERT_CLEAN_CLOSE(R);
}
