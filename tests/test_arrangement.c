/*
** test_arrangement.c: A(P), its crossing count, and the dynamic arrangement
** with next-crossing queries and the k cache (engine/arrangement.h).
**
** Oracles: hand-made polygons whose segments are known in closed form (a
** notched square, unit and weighted; a plus-shaped cross whose four
** segments meet in the centre); an O(n) brute force per ray written here
** independently (hit points within 1e-9 of the scale) plus the library's
** own O(n) twin (bit-identical); an O(r^2) count with the exact segment
** predicate, and the crossing family's r(r-1)/2; runs with
** 1, 2 and 3 threads compared bit for bit; next_crossings against sorting
** every crossing; the cache against a model of what it must answer, on
** scripted and random operation sequences; fault injection on every
** allocation.  Every test owns its wk_run and ends with zero live bytes.
** WSKEL_TEST_QUICK (set by the ASan run) shrinks the generated sizes.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "arrangement/bisector_arrangement.h"
#include "generators.h"
#include "helpers.h"

static wk_polygon *poly(wk_run *R, uint32_t n, const double *xy, const double *w) {
    double x[64], y[64];
    for (uint32_t i = 0; i < n; i++) {
        x[i] = xy[2 * i];
        y[i] = xy[2 * i + 1];
    }
    return polygon_named(R, n, x, y, w, "hand");
}

static uint64_t rng(uint64_t *s) {
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 11;
}
static double unif(uint64_t *s) { return (double)rng(s) / 9007199254740992.0; }

/* ------------------------------------------------------------ hand-made */

/* Square [0,10]^2 with a V notch in the top side, tip (5, 8). */
static const double NOTCH[] = {0, 0, 10, 0, 10, 10, 6, 10, 5, 8, 4, 10, 0, 10};

Test(arrangement, notched_square_unit) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    wk_polygon *P = poly(&R, 7, NOTCH, NULL);
    wk_aseg *S;
    uint32_t r;
    cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK);
    cr_assert_eq(r, 1);
    cr_assert_eq(S[0].vertex, 4);
    cr_assert_eq(S[0].vkind, WK_VEL_REGULAR);
    cr_assert_float_eq(S[0].u.x, 0.0, 1e-15);
    cr_assert_float_eq(S[0].u.y, -1.0, 1e-15);
    cr_assert_float_eq(S[0].speed, sqrt(5.0), 1e-12); /* sin of the half angle: 1/sqrt5 */
    cr_assert_eq(S[0].hit.edge, 0);
    cr_assert_eq(S[0].hit.vertex, WK_NONE);
    cr_assert_float_eq(S[0].b.x, 5.0, 1e-12);
    cr_assert_float_eq(S[0].b.y, 0.0, 1e-12);
    cr_assert_float_eq(S[0].len, 8.0, 1e-12);
    uint64_t K;
    cr_assert_eq(wk_arrangement_count_crossings(&R, S, r, &K), WK_OK);
    cr_assert_eq(K, 0);
    WK_FREE_ARRAY(&R, S, r);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(arrangement, notched_square_weighted) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    /* Edge 3 runs (6,10) -> (5,8), the notch's right flank, weight 2. */
    double w[7] = {1, 1, 1, 2, 1, 1, 1};
    wk_polygon *P = poly(&R, 7, NOTCH, w);
    wk_aseg *S;
    uint32_t r;
    cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK);
    cr_assert_eq(r, 1);
    /* n_a = (2,-1)/sqrt5, n_b = (-2,-1)/sqrt5; n_a.v = 2, n_b.v = 1 gives
    ** v = sqrt5 (1/4, -3/2): 8 down means 4/3 right. */
    double s5 = sqrt(5.0);
    cr_assert_float_eq(S[0].speed, s5 * hypot(0.25, 1.5), 1e-12);
    cr_assert_float_eq(S[0].u.x, 0.25 / hypot(0.25, 1.5), 1e-14);
    cr_assert_eq(S[0].hit.edge, 0);
    cr_assert_float_eq(S[0].b.x, 5.0 + 4.0 / 3.0, 1e-12);
    cr_assert_float_eq(S[0].b.y, 0.0, 1e-12);
    cr_assert_float_eq(S[0].len, hypot(4.0 / 3.0, 8.0), 1e-12);
    WK_FREE_ARRAY(&R, S, r);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Plus-shaped cross, arms of width 2 reaching 3 from the centre.  The four
** reflex corners (+-1, +-1) move diagonally inwards; each ray passes the
** centre and ends exactly on the opposite reflex corner (a vertex hit). */
static const double CROSS[] = {-1, -3, 1,  -3, 1,  -1, 3,  -1, 3,  1,  1,  1,
                               1,  3,  -1, 3,  -1, 1,  -3, 1,  -3, -1, -1, -1};

Test(arrangement, cross_segments_meet_in_the_centre) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    wk_polygon *P = poly(&R, 12, CROSS, NULL);
    wk_aseg *S;
    uint32_t r;
    cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK);
    cr_assert_eq(r, 4);
    for (uint32_t j = 0; j < 4; j++) {
        wk_point a = S[j].a;
        cr_assert_eq(S[j].hit.vertex != WK_NONE, true, "segment %u hit an edge", j);
        cr_assert_eq(S[j].hit.edge, WK_NONE);
        /* the opposite corner, exactly */
        cr_assert(S[j].b.x == -a.x && S[j].b.y == -a.y, "segment %u ends at (%g, %g)", j, S[j].b.x,
                  S[j].b.y);
        cr_assert_float_eq(S[j].len, 2 * sqrt(2.0), 1e-12);
        cr_assert_float_eq(S[j].speed, sqrt(2.0), 1e-12);
    }
    /* Each diagonal carries two overlapping segments (collinear: no
    ** crossing); each segment crosses both of the other diagonal. */
    uint64_t K;
    cr_assert_eq(wk_arrangement_count_crossings(&R, S, r, &K), WK_OK);
    cr_assert_eq(K, 4);
    cr_assert_eq(counter(&R, "arrangement_crossings_initial"), 4);

    /* In the dynamic structure: the two crossings of a segment are at the
    ** same parameter (the centre); both are reported, in id order, and the
    ** cache steps through them with the (s, after) position. */
    wk_arrangement A;
    wk_arrangement_init(&A);
    cr_assert_eq(wk_arrangement_insert_aseg(&R, &A, S, r), WK_OK);
    wk_crossing out[4];
    uint32_t cnt;
    cr_assert_eq(wk_arrangement_next_crossings(&R, &A, 0, 0.0, 7, out, &cnt), WK_OK);
    cr_assert_eq(cnt, 2);
    cr_assert(out[0].s == out[1].s && out[0].other < out[1].other);
    cr_assert_float_eq(out[0].s, sqrt(2.0), 1e-12);
    R.opt.k = 1;
    wk_crossing c;
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 0.0, &c), WK_OK);
    cr_assert_eq(c.other, out[0].other);
    cr_assert_eq(wk_arrangement_cache_next_after(&R, &A, 0, c.s, c.other, &c), WK_OK);
    cr_assert_eq(c.other, out[1].other);
    cr_assert_eq(wk_arrangement_cache_next_after(&R, &A, 0, c.s, c.other, &c), WK_OK);
    cr_assert_eq(c.other, WK_NONE);
    cr_assert(wk_arrangement_check(&A));
    wk_arrangement_clear(&R, &A);
    WK_FREE_ARRAY(&R, S, r);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------------------ ray shooting */

/* Independent brute force: first point of the ray on any edge not
** incident to `from`, by the plain parametric intersection. */
static bool plain_shot(const wk_polygon *P, uint32_t from, wk_point o, wk_point u, wk_point *hit) {
    uint32_t n = P->n;
    double best = INFINITY;
    for (uint32_t e = 0; e < n; e++) {
        uint32_t f = (e + 1) % n;
        if (from != WK_NONE && (e == from || f == from)) continue;
        wk_point a = P->p[e], b = P->p[f];
        double sx = b.x - a.x, sy = b.y - a.y;
        double den = u.x * sy - u.y * sx;
        if (den == 0) continue;
        double qx = a.x - o.x, qy = a.y - o.y;
        double t = (qx * sy - qy * sx) / den;
        double s = (qx * u.y - qy * u.x) / den;
        if (t > 0 && s >= -1e-12 && s <= 1 + 1e-12 && t < best) best = t;
    }
    if (best == INFINITY) return false;
    *hit = (wk_point){o.x + best * u.x, o.y + best * u.y};
    return true;
}

static bool same_hit(const wk_ray_hit *a, const wk_ray_hit *b) {
    return memcmp(&a->t, &b->t, sizeof a->t) == 0 && memcmp(&a->p, &b->p, sizeof a->p) == 0 &&
           a->edge == b->edge && a->vertex == b->vertex;
}

Test(arrangement, ray_shooting_matches_brute_force) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    static const char *const fams[] = {"star", "crossing", "random", "comb", "spiral", "notched"};
    uint32_t ns[] = {50, 200, 2000};
    uint32_t nn = quick() ? 2 : 3;
    uint64_t checked = 0, vertex_hits = 0;
    for (size_t f = 0; f < sizeof fams / sizeof fams[0]; f++)
        for (uint32_t k = 0; k < nn; k++)
            for (uint64_t seed = 1; seed <= 3; seed++) {
                wk_polygon *P = NULL;
                cr_assert_eq(gen(&R, fams[f], ns[k], -1, seed, seed == 3 ? "uniform" : NULL, &P),
                             WK_OK, "%s", R.err.msg);
                double scale = wk_polygon_scale(P);
                wk_aseg *S;
                uint32_t r;
                cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK, "%s", R.err.msg);
                cr_assert_eq(r, P->r);
                double tol = WK_TOL_REL * scale;
                for (uint32_t j = 0; j < r; j++) {
                    wk_ray_hit h;
                    cr_assert(wk_ray_shoot_brute(P, tol, S[j].a, S[j].u, S[j].vertex, &h));
                    cr_assert(same_hit(&h, &S[j].hit),
                              "%s n=%u seed=%llu vertex %u: grid and "
                              "brute force differ",
                              fams[f], ns[k], (unsigned long long)seed, S[j].vertex);
                    wk_point q;
                    cr_assert(plain_shot(P, S[j].vertex, S[j].a, S[j].u, &q));
                    cr_assert_leq(hypot(q.x - S[j].b.x, q.y - S[j].b.y), 1e-9 * scale,
                                  "%s n=%u seed=%llu vertex %u: (%.17g, %.17g) vs (%.17g, %.17g)",
                                  fams[f], ns[k], (unsigned long long)seed, S[j].vertex, S[j].b.x,
                                  S[j].b.y, q.x, q.y);
                    vertex_hits += S[j].hit.vertex != WK_NONE;
                    checked++;
                }
                /* Random rays from random points of the bounding box (inside
                ** or outside P): the grid walk and the twin agree. */
                wk_ray_shooter sh;
                cr_assert_eq(wk_ray_shooter_init(&R, &sh, P), WK_OK);
                double x0 = P->p[0].x, x1 = x0, y0 = P->p[0].y, y1 = y0;
                for (uint32_t i = 0; i < P->n; i++) {
                    x0 = fmin(x0, P->p[i].x);
                    x1 = fmax(x1, P->p[i].x);
                    y0 = fmin(y0, P->p[i].y);
                    y1 = fmax(y1, P->p[i].y);
                }
                uint64_t s = seed * 977 + k;
                for (int q = 0; q < 200; q++) {
                    wk_point o = {x0 + unif(&s) * (x1 - x0), y0 + unif(&s) * (y1 - y0)};
                    double ang = 2 * PI * unif(&s);
                    wk_point u = {cos(ang), sin(ang)};
                    /* sometimes from a vertex, sometimes axis-parallel */
                    uint32_t from = WK_NONE;
                    if (q % 4 == 1) {
                        from = (uint32_t)(rng(&s) % P->n);
                        o = P->p[from];
                    }
                    if (q % 8 == 3)
                        u = (wk_point){q % 16 == 3 ? 1.0 : 0.0, q % 16 == 3 ? 0.0 : -1.0};
                    wk_ray_hit a, b;
                    bool fa = wk_ray_shoot(&sh, o, u, from, &a);
                    bool fb = wk_ray_shoot_brute(P, sh.tol, o, u, from, &b);
                    cr_assert_eq(fa, fb);
                    if (fa) cr_assert(same_hit(&a, &b), "%s n=%u random ray %d", fams[f], ns[k], q);
                }
                wk_ray_shooter_clear(&R, &sh);
                WK_FREE_ARRAY(&R, S, r);
                wk_polygon_free(&R, P);
            }
    cr_assert_gt(checked, 1000);
    (void)vertex_hits;
    ASSERT_CLEAN_CLOSE(R);
}

/* A ray through a vertex (exactly, and within the tolerance) hits the vertex,
** from the grid and the brute force alike. */
Test(arrangement, ray_through_a_vertex_hits_the_vertex) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    /* A square with a convex bump: vertex 3 at (5, 12) sticks out of the
    ** top side; a vertical ray x = 5 passes exactly through it. */
    static const double B[] = {0, 0, 10, 0, 10, 10, 5, 12, 0, 10};
    wk_polygon *P = poly(&R, 5, B, NULL);
    wk_ray_shooter sh;
    cr_assert_eq(wk_ray_shooter_init(&R, &sh, P), WK_OK);
    double dx[] = {0.0, 0.5e-9, -0.5e-9};
    for (int k = 0; k < 3; k++) {
        wk_ray_hit h, g;
        cr_assert(wk_ray_shoot(&sh, (wk_point){5.0 + dx[k], 1.0}, (wk_point){0, 1}, WK_NONE, &h));
        cr_assert(wk_ray_shoot_brute(P, sh.tol, (wk_point){5.0 + dx[k], 1.0}, (wk_point){0, 1},
                                     WK_NONE, &g));
        cr_assert(same_hit(&h, &g));
        cr_assert_eq(h.vertex, 3, "offset %g: hit edge %u vertex %u", dx[k], h.edge, h.vertex);
        cr_assert(h.p.x == 5.0 && h.p.y == 12.0);
    }
    /* Farther than the tolerance: the edge. */
    wk_ray_hit h;
    cr_assert(wk_ray_shoot(&sh, (wk_point){5.001, 1.0}, (wk_point){0, 1}, WK_NONE, &h));
    cr_assert_eq(h.vertex, WK_NONE);
    cr_assert_eq(h.edge, 2);
    wk_ray_shooter_clear(&R, &sh);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------------------ crossings */

static uint64_t brute_crossings(const wk_aseg *S, uint32_t r) {
    uint64_t k = 0;
    for (uint32_t i = 0; i < r; i++)
        for (uint32_t j = i + 1; j < r; j++)
            k += wk_segments_meet(S[i].a, S[i].b, S[j].a, S[j].b) == WK_SEG_CROSS;
    return k;
}

Test(arrangement, crossing_count_matches_brute_force) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    static const char *const fams[] = {"star",   "notched",  "random",   "comb",
                                       "spiral", "crossing", "monotone", "rectilinear"};
    uint32_t ns[] = {40, 300, 1500};
    uint32_t nn = quick() ? 2 : 3;
    static const char *const weights[] = {NULL, "uniform", "two"};
    uint64_t total = 0; /* crossings checked: 0 == 0 everywhere would prove nothing */
    for (size_t f = 0; f < sizeof fams / sizeof fams[0]; f++)
        for (uint32_t k = 0; k < nn; k++)
            for (uint64_t seed = 1; seed <= 2; seed++)
                for (int w = 0; w < 3; w++) {
                    wk_polygon *P = NULL;
                    cr_assert_eq(gen(&R, fams[f], ns[k], -1, seed, weights[w], &P), WK_OK, "%s",
                                 R.err.msg);
                    wk_aseg *S;
                    uint32_t r;
                    cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK, "%s", R.err.msg);
                    uint64_t before = counter(&R, "arrangement_crossings_initial"), K;
                    cr_assert_eq(wk_arrangement_count_crossings(&R, S, r, &K), WK_OK);
                    uint64_t want = brute_crossings(S, r);
                    cr_assert_eq(K, want,
                                 "%s n=%u seed=%llu weights=%s: %llu crossings, brute "
                                 "force %llu",
                                 fams[f], ns[k], (unsigned long long)seed,
                                 weights[w] ? weights[w] : "unit", (unsigned long long)K,
                                 (unsigned long long)want);
                    cr_assert_eq(counter(&R, "arrangement_crossings_initial") - before, K);
                    total += K;
                    WK_FREE_ARRAY(&R, S, r);
                    wk_polygon_free(&R, P);
                }
    cr_assert_gt(total, 0, "no crossing in any case");
    ASSERT_CLEAN_CLOSE(R);
}

Test(arrangement, crossing_family_count) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    static const int64_t rs[] = {0, 1, 2, 3, 9, 40, 101, 400};
    for (size_t j = 0; j < sizeof rs / sizeof rs[0]; j++)
        for (uint64_t seed = 1; seed <= 2; seed++) {
            int64_t r = rs[j];
            wk_polygon *P = NULL;
            cr_assert_eq(gen(&R, "crossing", (uint32_t)(3 * r + 4 + 7 * seed), r, seed, NULL, &P),
                         WK_OK, "%s", R.err.msg);
            wk_aseg *S;
            uint32_t rr;
            cr_assert_eq(wk_arrangement_segments(&R, P, &S, &rr), WK_OK);
            cr_assert_eq(rr, (uint32_t)r);
            uint64_t K;
            cr_assert_eq(wk_arrangement_count_crossings(&R, S, rr, &K), WK_OK);
            cr_assert_eq(K, (uint64_t)r * (uint64_t)(r > 0 ? r - 1 : 0) / 2, "r=%lld: %llu",
                         (long long)r, (unsigned long long)K);
            WK_FREE_ARRAY(&R, S, rr);
            wk_polygon_free(&R, P);
        }
    ASSERT_CLEAN_CLOSE(R);
}

/* Segments crossing at exact, repeated points and along the grid's walls:
** many segments through one point, axis-parallel ones on a lattice. */
Test(arrangement, crossing_count_degenerate_layouts) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    enum { M = 120 };
    wk_aseg S[M];
    memset(S, 0, sizeof S);
    uint64_t s = 5;
    for (int layout = 0; layout < 3; layout++) {
        for (int i = 0; i < M; i++) {
            if (layout == 0) { /* a lattice of horizontal and vertical segments */
                double c = (double)(i / 2 % 30) * 10;
                S[i].a = i % 2 ? (wk_point){c, -5} : (wk_point){-5, c};
                S[i].b = i % 2 ? (wk_point){c, 300} : (wk_point){300, c};
            } else if (layout == 1) { /* a pencil through (1, 1) plus chords */
                double ang = PI * (double)i / M;
                S[i].a = (wk_point){1 - 50 * cos(ang), 1 - 50 * sin(ang)};
                S[i].b = (wk_point){1 + 50 * cos(ang) * (i % 3 ? 1 : 0.01),
                                    1 + 50 * sin(ang) * (i % 3 ? 1 : 0.01)};
            } else { /* random short and long, some nearly parallel */
                double x = 100 * unif(&s), y = 100 * unif(&s),
                       ang = i % 5 ? 2 * PI * unif(&s) : 1e-13 * unif(&s);
                double len = i % 2 ? 5 + 10 * unif(&s) : 150;
                S[i].a = (wk_point){x, y};
                S[i].b = (wk_point){x + len * cos(ang), y + len * sin(ang)};
            }
        }
        uint64_t K;
        cr_assert_eq(wk_arrangement_count_crossings(&R, S, M, &K), WK_OK);
        cr_assert_eq(K, brute_crossings(S, M), "layout %d", layout);
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(arrangement, thread_count_does_not_change_anything) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    static const char *const fams[] = {"star", "random", "crossing", "spiral"};
    uint32_t n = quick() ? 400 : 3000;
    for (size_t f = 0; f < sizeof fams / sizeof fams[0]; f++) {
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, fams[f], n, -1, 7, "uniform", &P), WK_OK, "%s", R.err.msg);
        wk_aseg *ref = NULL;
        uint32_t rref = 0;
        uint64_t kref = 0;
        for (int t = 1; t <= 3; t++) {
            R.opt.threads = t;
            wk_aseg *S;
            uint32_t r;
            uint64_t K;
            cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK);
            cr_assert_eq(wk_arrangement_count_crossings(&R, S, r, &K), WK_OK);
            if (t == 1) {
                cr_assert_gt(r, 0, "%s: no segments to compare", fams[f]);
                ref = S;
                rref = r;
                kref = K;
                continue;
            }
            cr_assert_eq(r, rref);
            cr_assert_eq(K, kref);
            for (uint32_t j = 0; j < r; j++) {
                cr_assert_eq(S[j].vertex, ref[j].vertex);
                cr_assert_eq(S[j].vkind, ref[j].vkind);
                cr_assert(memcmp(&S[j].a, &ref[j].a, sizeof(wk_point)) == 0);
                cr_assert(memcmp(&S[j].b, &ref[j].b, sizeof(wk_point)) == 0);
                cr_assert(memcmp(&S[j].u, &ref[j].u, sizeof(wk_point)) == 0);
                cr_assert(memcmp(&S[j].speed, &ref[j].speed, sizeof(double)) == 0);
                cr_assert(memcmp(&S[j].len, &ref[j].len, sizeof(double)) == 0);
                cr_assert(same_hit(&S[j].hit, &ref[j].hit));
            }
            WK_FREE_ARRAY(&R, S, r);
        }
        WK_FREE_ARRAY(&R, ref, rref);
        wk_polygon_free(&R, P);
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------------------ queries */

static int cmp_crossing(const void *x, const void *y) {
    const wk_crossing *a = x, *b = y;
    if (a->s != b->s) return a->s < b->s ? -1 : 1;
    return (a->other > b->other) - (a->other < b->other);
}

/* Every crossing of seg beyond (s_from, after), sorted: the oracle. */
static uint32_t all_crossings(const wk_arrangement *A, uint32_t seg, double s_from, uint32_t after,
                              wk_crossing *out) {
    const wk_arr_seg *Q = wk_arrangement_get(A, seg);
    uint32_t n = 0;
    for (uint32_t id = 0; id < A->n_ids; id++) {
        const wk_arr_seg *O = wk_arrangement_get(A, id);
        if (!O || id == seg) continue;
        double s, t;
        if (!wk_arrangement_crossing(Q, O, &s, &t)) continue;
        if (s < Q->lo || s > Q->hi || t < O->lo || t > O->hi) continue;
        if (s < s_from || (s == s_from && id <= after)) continue;
        out[n++] = (wk_crossing){s, t, id};
    }
    qsort(out, n, sizeof *out, cmp_crossing);
    return n;
}

static bool same_crossing(const wk_crossing *a, const wk_crossing *b) {
    return a->other == b->other && memcmp(&a->s, &b->s, sizeof a->s) == 0 &&
           (a->other == WK_NONE || memcmp(&a->t, &b->t, sizeof a->t) == 0);
}

/* The arrangement of a generated polygon's A(P), plus random extra
** segments, with some active parts shrunk and some segments removed. */
static void build_random(wk_run *R, wk_arrangement *A, const char *fam, uint32_t n, uint64_t seed,
                         uint32_t extra) {
    wk_polygon *P = NULL;
    cr_assert_eq(gen(R, fam, n, -1, seed, NULL, &P), WK_OK, "%s", R->err.msg);
    wk_aseg *S;
    uint32_t r;
    cr_assert_eq(wk_arrangement_segments(R, P, &S, &r), WK_OK);
    wk_arrangement_init(A);
    cr_assert_eq(wk_arrangement_insert_aseg(R, A, S, r), WK_OK);
    uint64_t s = seed;
    for (uint32_t i = 0; i < extra; i++) {
        wk_point a = {-1000 + 2000 * unif(&s), -1000 + 2000 * unif(&s)};
        double ang = 2 * PI * unif(&s);
        cr_assert_eq(wk_arrangement_insert(R, A, a, (wk_point){cos(ang), sin(ang)},
                                           100 + 1500 * unif(&s), NULL),
                     WK_OK);
    }
    for (uint32_t id = 0; id < A->n_ids; id++) {
        const wk_arr_seg *g = wk_arrangement_get(A, id);
        if (rng(&s) % 4 == 0) {
            double lo = g->len * 0.3 * unif(&s), hi = g->len * (1 - 0.3 * unif(&s));
            cr_assert_eq(wk_arrangement_set_active(R, A, id, lo, hi), WK_OK);
        }
        if (rng(&s) % 7 == 0) cr_assert_eq(wk_arrangement_remove(R, A, id), WK_OK);
    }
    cr_assert(wk_arrangement_check(A));
    WK_FREE_ARRAY(R, S, r);
    wk_polygon_free(R, P);
}

Test(arrangement, next_crossings_match_brute_force) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    wk_arrangement A;
    build_random(&R, &A, "star", quick() ? 120 : 400, 3, 40);
    wk_crossing *all = WK_NEW_ARRAY(&R, wk_crossing, A.n_live);
    wk_crossing *out = WK_NEW_ARRAY(&R, wk_crossing, A.n_live);
    uint32_t ks[] = {1, 2, 7, WK_K_MAX};
    uint64_t s = 11, queries = 0, nonempty = 0;
    for (uint32_t id = 0; id < A.n_ids; id++) {
        const wk_arr_seg *g = wk_arrangement_get(&A, id);
        if (!g) continue;
        /* from the start, from a random point, and from a crossing (ties) */
        uint32_t nall = all_crossings(&A, id, -1.0, WK_NONE, all);
        double froms[3] = {-1.0, g->len * unif(&s), nall ? all[nall / 2].s : 0.0};
        uint32_t afters[3] = {WK_NONE, WK_NONE, nall ? all[nall / 2].other : WK_NONE};
        for (int f = 0; f < 3; f++)
            for (int kk = 0; kk < 4; kk++) {
                uint32_t want = all_crossings(&A, id, froms[f], afters[f], all);
                uint64_t q0 = counter(&R, "intersection_queries"), sc0 = counter(&R, "segments_scanned");
                uint32_t got;
                cr_assert_eq(wk_arrangement_next_crossings_after(&R, &A, id, froms[f], afters[f],
                                                                 ks[kk], out, &got),
                             WK_OK);
                cr_assert_eq(counter(&R, "intersection_queries") - q0, 1);
                cr_assert_eq(counter(&R, "segments_scanned") - sc0, A.n_live - 1);
                uint32_t exp = want < ks[kk] ? want : ks[kk];
                cr_assert_eq(got, exp, "seg %u k=%u: %u crossings, want %u", id, ks[kk], got, exp);
                for (uint32_t i = 0; i < got; i++)
                    cr_assert(same_crossing(&out[i], &all[i]), "seg %u k=%u: crossing %u differs",
                              id, ks[kk], i);
                if (afters[f] == WK_NONE) { /* the plain form agrees */
                    uint32_t got2;
                    cr_assert_eq(
                        wk_arrangement_next_crossings(&R, &A, id, froms[f], ks[kk], out, &got2),
                        WK_OK);
                    cr_assert_eq(got2, got);
                }
                queries++;
                nonempty += got > 0;
            }
    }
    cr_assert_gt(nonempty, queries / 2);
    uint32_t cnt;
    cr_assert_eq(wk_arrangement_next_crossings(&R, &A, A.n_ids + 5, 0, 1, out, &cnt), WK_EALGO);
    WK_FREE_ARRAY(&R, all, A.n_live);
    WK_FREE_ARRAY(&R, out, A.n_live);
    wk_arrangement_clear(&R, &A);
    ASSERT_CLEAN_CLOSE(R);
}

/* A horizontal segment H = id 0 from (0,0) to (10,0) and five verticals
** (ids 1..5) crossing it at s = 0.5, 1.5, ..., 4.5. */
static void comb_setup(wk_run *R, wk_arrangement *A) {
    wk_arrangement_init(A);
    cr_assert_eq(wk_arrangement_insert(R, A, (wk_point){0, 0}, (wk_point){2, 0}, 10, NULL), WK_OK);
    for (int i = 0; i < 5; i++)
        cr_assert_eq(
            wk_arrangement_insert(R, A, (wk_point){0.5 + i, -1}, (wk_point){0, 1}, 2, NULL), WK_OK);
}

typedef struct cache_counts {
    uint64_t hit, miss, refill, inval;
} cache_counts;

static cache_counts counts(const wk_run *R) {
    return (cache_counts){counter(R, "cache_hits"), counter(R, "cache_misses"),
                          counter(R, "cache_refills"), counter(R, "cache_invalidations")};
}

/* Walk H's crossings one by one through the cache and return the counts. */
static cache_counts walk(wk_run *R, wk_arrangement *A, uint32_t k) {
    R->opt.k = k;
    cache_counts c0 = counts(R);
    double s = -1;
    for (int i = 0; i <= 5; i++) {
        wk_crossing c;
        cr_assert_eq(wk_arrangement_cache_next(R, A, 0, s, &c), WK_OK);
        if (i < 5) {
            cr_assert_eq(c.other, (uint32_t)i + 1, "k=%u step %d: other %u", k, i, c.other);
            cr_assert_float_eq(c.s, 0.5 + i, 1e-12);
            cr_assert_float_eq(c.t, 1.0, 1e-12);
            s = c.s;
        } else {
            cr_assert_eq(c.other, WK_NONE);
        }
        cr_assert(wk_arrangement_check(A));
    }
    cache_counts c1 = counts(R);
    return (cache_counts){c1.hit - c0.hit, c1.miss - c0.miss, c1.refill - c0.refill,
                          c1.inval - c0.inval};
}

Test(arrangement, cache_hits_misses_refills_scripted) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    struct {
        uint32_t k;
        cache_counts want;
    } cases[] = {
        /* k=1: every step refills; the last refill finds nothing (0 < k), so
        ** "none" is certain only after it. */
        {1, {0, 6, 6, 0}},
        /* k=2: refills at 0.5 (0.5, 1.5), 2.5 (2.5, 3.5), 4.5 (4.5 alone: then
        ** complete to the end, so the final "none" is a hit). */
        {2, {3, 3, 3, 0}},
        {4, {4, 2, 2, 0}},
        {5, {4, 2, 2, 0}}, /* five found = k: the end is not known yet */
        {6, {5, 1, 1, 0}},
        {WK_K_MAX, {5, 1, 1, 0}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        wk_arrangement A;
        comb_setup(&R, &A);
        cache_counts got = walk(&R, &A, cases[i].k);
        cr_assert(got.hit == cases[i].want.hit && got.miss == cases[i].want.miss &&
                      got.refill == cases[i].want.refill && got.inval == cases[i].want.inval,
                  "k=%u: hit %llu miss %llu refill %llu inval %llu", cases[i].k,
                  (unsigned long long)got.hit, (unsigned long long)got.miss,
                  (unsigned long long)got.refill, (unsigned long long)got.inval);
        wk_arrangement_clear(&R, &A);
    }
    ASSERT_CLEAN_CLOSE(R);
}

Test(arrangement, cache_memory_grows_with_k) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    size_t peak[3];
    uint32_t ks[3] = {1, 8, WK_K_MAX};
    for (int i = 0; i < 3; i++) {
        wk_arrangement A;
        build_random(&R, &A, "star", 200, 2, 0);
        R.opt.k = ks[i];
        size_t live0 = R.alloc.live;
        wk_run_reset_peak(&R);
        for (uint32_t id = 0; id < A.n_ids; id++) {
            wk_crossing c;
            if (wk_arrangement_get(&A, id))
                cr_assert_eq(wk_arrangement_cache_next(&R, &A, id, -1.0, &c), WK_OK);
        }
        peak[i] = R.alloc.peak - live0;
        wk_arrangement_clear(&R, &A);
    }
    cr_assert_lt(peak[0], peak[1]);
    cr_assert_lt(peak[1], peak[2]);
    ASSERT_CLEAN_CLOSE(R);
}

Test(arrangement, invalidation_on_insert_remove_and_active_parts) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    wk_arrangement A;
    comb_setup(&R, &A);
    R.opt.k = WK_K_MAX;
    wk_crossing c;
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, -1, &c), WK_OK); /* fill: all 5 */
    cr_assert_eq(c.other, 1);
    cache_counts c0 = counts(&R);

    /* A segment that misses H, and one crossing H at s = 7 (beyond every
    ** entry but inside the complete range, which reaches to infinity). */
    uint32_t miss_id, far_id, mid_id;
    cr_assert_eq(wk_arrangement_insert(&R, &A, (wk_point){0, 5}, (wk_point){1, 0}, 9, &miss_id),
                 WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval);
    cr_assert_eq(wk_arrangement_insert(&R, &A, (wk_point){7, -1}, (wk_point){0, 1}, 2, &far_id),
                 WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval + 1);
    cr_assert_eq(A.ids[0].cache.n, 5); /* kept all five, range now ends before 7 */
    cr_assert(wk_arrangement_check(&A));
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 4.5, &c), WK_OK); /* past the range: miss */
    cr_assert_eq(c.other, far_id);
    cr_assert_eq(counts(&R).miss, c0.miss + 1);

    /* Refill from the start, then cut the middle: a crossing at s = 2.2. */
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, -1, &c), WK_OK);
    c0 = counts(&R);
    cr_assert_eq(wk_arrangement_insert(&R, &A, (wk_point){2.2, 1}, (wk_point){0, -1}, 3, &mid_id),
                 WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval + 1);
    cr_assert_eq(A.ids[0].cache.n, 2); /* 0.5 and 1.5 kept */
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 0.5, &c), WK_OK);
    cr_assert_eq(c.other, 2);
    cr_assert_eq(counts(&R).hit, c0.hit + 1);
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 1.5, &c), WK_OK);
    cr_assert_eq(c.other, mid_id);
    cr_assert_float_eq(c.s, 2.2, 1e-12);
    cr_assert_eq(counts(&R).miss, c0.miss + 1);

    /* The cache now starts at 1.5.  A new crossing before its range (s = 1)
    ** affects nothing. */
    c0 = counts(&R);
    cr_assert_eq(wk_arrangement_insert(&R, &A, (wk_point){1, -3}, (wk_point){0, 1}, 6, NULL),
                 WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval);

    /* Remove vertical 4 (s = 3.5): its entry stays and is skipped when read
    ** (ids are never reused), so nothing is invalidated. */
    cr_assert_eq(wk_arrangement_remove(&R, &A, 4), WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval);
    cr_assert_eq(wk_arrangement_remove(&R, &A, 4), WK_EALGO); /* not current any more */
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 2.2, &c), WK_OK);
    cr_assert_eq(c.other, 3); /* 2.5 */
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 2.5, &c), WK_OK);
    cr_assert_eq(c.other, 5); /* 4.5: 3.5 was removed */
    cr_assert_eq(counts(&R).hit, c0.hit + 2);
    cr_assert_eq(counts(&R).miss, c0.miss);

    /* Shrink vertical 5 so that it no longer reaches H: the cache filters it
    ** (no invalidation needed).  Widen it again: H's cache still holds the
    ** entry, so nothing is invalidated and the crossing is back. */
    cr_assert_eq(wk_arrangement_set_active(&R, &A, 5, 1.5, 2), WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval);
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 2.5, &c), WK_OK);
    cr_assert_eq(c.other, far_id); /* 7: the cache (to infinity) no longer holds 4.5 */
    cr_assert_eq(wk_arrangement_set_active(&R, &A, 5, 0, 2), WK_OK);
    cr_assert_eq(counts(&R).inval, c0.inval);
    cr_assert(wk_arrangement_check(&A));
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 2.5, &c), WK_OK);
    cr_assert_eq(c.other, 5);
    cr_assert_eq(wk_arrangement_set_active(&R, &A, 5, 0, 3), WK_EINPUT); /* beyond len */
    cr_assert_eq(wk_arrangement_insert(&R, &A, (wk_point){0, 0}, (wk_point){0, 0}, 1, NULL),
                 WK_EINPUT);

    /* Removing the cached segment itself frees its cache. */
    cr_assert_eq(wk_arrangement_remove(&R, &A, 0), WK_OK);
    cr_assert_eq(A.n_cached, 0);
    cr_assert(wk_arrangement_check(&A));
    cr_assert_eq(wk_arrangement_cache_next(&R, &A, 0, 0, &c), WK_EALGO);
    wk_arrangement_clear(&R, &A);
    ASSERT_CLEAN_CLOSE(R);
}

/* Random operation sequences: every cache answer equals the next crossing
** found by a fresh scan, whatever happened to the caches before. */
Test(arrangement, cache_agrees_with_scans_under_random_updates) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    uint32_t ks[] = {1, 2, 7, WK_K_MAX};
    uint32_t steps = quick() ? 1500 : 6000;
    for (int kk = 0; kk < 4; kk++) {
        wk_arrangement A;
        build_random(&R, &A, "star", 80, 10 + (uint64_t)kk, 20);
        R.opt.k = ks[kk];
        uint64_t s = 99 + (uint64_t)kk;
        /* a cursor per segment id: where its walk stands */
        enum { CAP = 4096 };
        static double cur_s[CAP];
        static uint32_t cur_id[CAP];
        for (uint32_t i = 0; i < CAP; i++) {
            cur_s[i] = -1;
            cur_id[i] = WK_NONE;
        }
        for (uint32_t step = 0; step < steps; step++) {
            uint32_t op = (uint32_t)(rng(&s) % 20);
            uint32_t id = (uint32_t)(rng(&s) % A.n_ids);
            const wk_arr_seg *g = wk_arrangement_get(&A, id);
            if (op == 0 && A.n_ids + 1 < CAP) {
                wk_point a = {-1000 + 2000 * unif(&s), -1000 + 2000 * unif(&s)};
                double ang = 2 * PI * unif(&s);
                cr_assert_eq(wk_arrangement_insert(&R, &A, a, (wk_point){cos(ang), sin(ang)},
                                                   200 + 1500 * unif(&s), NULL),
                             WK_OK);
            } else if (op == 1 && g && A.n_live > 5) {
                cr_assert_eq(wk_arrangement_remove(&R, &A, id), WK_OK);
            } else if (op == 2 && g) {
                double lo = g->len * 0.4 * unif(&s), hi = g->len * (1 - 0.4 * unif(&s));
                cr_assert_eq(wk_arrangement_set_active(&R, &A, id, lo, hi), WK_OK);
            } else if (g) {
                if (op == 3) { /* restart the walk somewhere */
                    cur_s[id] = g->len * unif(&s) - 1;
                    cur_id[id] = WK_NONE;
                }
                wk_crossing c, want[1];
                uint32_t n;
                cr_assert_eq(wk_arrangement_cache_next_after(&R, &A, id, cur_s[id], cur_id[id], &c),
                             WK_OK);
                cr_assert_eq(wk_arrangement_next_crossings_after(&R, &A, id, cur_s[id], cur_id[id],
                                                                 1, want, &n),
                             WK_OK);
                if (n == 0)
                    cr_assert_eq(c.other, WK_NONE, "k=%u step %u: cache says %u, scan none", ks[kk],
                                 step, c.other);
                else
                    cr_assert(same_crossing(&c, &want[0]),
                              "k=%u step %u seg %u: cache (%.17g, %u), "
                              "scan (%.17g, %u)",
                              ks[kk], step, id, c.s, c.other, want[0].s, want[0].other);
                if (c.other != WK_NONE) {
                    cur_s[id] = c.s;
                    cur_id[id] = c.other;
                } else {
                    cur_s[id] = -1;
                    cur_id[id] = WK_NONE;
                }
            }
            if (step % 64 == 0) cr_assert(wk_arrangement_check(&A), "step %u", step);
        }
        cr_assert(wk_arrangement_check(&A));
        if (ks[kk] > 1) cr_assert_gt(counter(&R, "cache_hits"), 0);
        cr_assert_gt(counter(&R, "cache_invalidations"), 0);
        wk_arrangement_clear(&R, &A);
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------------------ faults */

/* One scripted run of everything that allocates: A(P), the count, an
** arrangement with inserts, cache refills, removals, then clear.  Frees all
** it allocated on every path. */
static wk_status script(wk_run *R, const wk_polygon *P) {
    wk_aseg *S = NULL;
    uint32_t r = 0;
    uint64_t K;
    wk_arrangement A;
    wk_arrangement_init(&A);
    wk_ray_shooter sh;
    wk_status st = wk_ray_shooter_init(R, &sh, P);
    wk_ray_shooter_clear(R, &sh);
    if (st != WK_OK) goto done;
    if ((st = wk_arrangement_segments(R, P, &S, &r)) != WK_OK) goto done;
    if ((st = wk_arrangement_count_crossings(R, S, r, &K)) != WK_OK) goto done;
    if ((st = wk_arrangement_insert_aseg(R, &A, S, r)) != WK_OK) goto done;
    for (uint32_t id = 0; id < r; id += 3) {
        wk_crossing c;
        if ((st = wk_arrangement_cache_next(R, &A, id, -1, &c)) != WK_OK) goto done;
        if (c.other != WK_NONE && (st = wk_arrangement_cache_next(R, &A, id, c.s, &c)) != WK_OK)
            goto done;
    }
    for (uint32_t id = 1; id < r; id += 5)
        if ((st = wk_arrangement_remove(R, &A, id)) != WK_OK) goto done;
    if ((st = wk_arrangement_insert(R, &A, P->p[0], (wk_point){1, 1}, 10, NULL)) != WK_OK)
        goto done;
done:
    wk_arrangement_clear(R, &A);
    if (S) WK_FREE_ARRAY(R, S, r);
    return st;
}

Test(arrangement, every_allocation_failure_is_clean) {
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    R.opt.k = 3;
    wk_polygon *P = NULL;
    cr_assert_eq(gen(&R, "star", 60, -1, 4, NULL, &P), WK_OK);
    size_t base = R.alloc.live;
    int failures = 0;
    for (int64_t N = 0;; N++) {
        R.err.code = WK_OK;
        R.alloc.fail_after = (int64_t)R.alloc.calls + N;
        wk_status st = script(&R, P);
        R.alloc.fail_after = -1;
        cr_assert_eq(R.alloc.live, base, "N=%lld: %zu bytes leaked", (long long)N,
                     R.alloc.live - base);
        if (st == WK_OK) break;
        cr_assert_eq(st, WK_ENOMEM, "N=%lld: status %d (%s)", (long long)N, st, R.err.msg);
        failures++;
        cr_assert_lt(N, 100000);
    }
    cr_assert_gt(failures, 10);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------------------ timings */

/* Not a timed test: skipped (cr_skip_test) unless WSKEL_ARR_TIMING is set;
** then it prints figures only, e.g.
**   make build/tests/run_tests &&
**   WSKEL_ARR_TIMING=1 build/tests/run_tests --filter 'arrangement/timings' --jobs 1
** Shooting and counting on star (seed 1) and crossing polygons with 1 and 2
** threads (best of 3), then the cost of next-crossing scans. */
Test(arrangement, timings, .timeout = 600) {
    if (!getenv("WSKEL_ARR_TIMING"))
        cr_skip_test("timings only with WSKEL_ARR_TIMING=1 (they print figures, assert nothing "
                     "about time)");
    wk_run R;
    wk_run_init(&R);
    R.variant = wk_variant_find("arrangement"); /* its counters */
    struct {
        const char *fam;
        uint32_t n;
        int64_t r;
    } cases[] = {{"star", 1000, -1},    {"star", 5000, -1},     {"star", 10000, -1},
                 {"star", 10000, 5000}, {"crossing", 2000, -1}, {"spiral", 100000, -1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, cases[i].fam, cases[i].n, cases[i].r, 1, NULL, &P), WK_OK);
        for (int t = 1; t <= 2; t++) {
            R.opt.threads = t;
            double best_shoot = INFINITY, best_count = INFINITY;
            uint64_t K = 0;
            uint32_t r = 0;
            size_t peak = 0;
            for (int rep = 0; rep < 3; rep++) {
                wk_aseg *S;
                double t0 = now_s();
                cr_assert_eq(wk_arrangement_segments(&R, P, &S, &r), WK_OK);
                double t1 = now_s();
                size_t live0 = R.alloc.live;
                wk_run_reset_peak(&R);
                cr_assert_eq(wk_arrangement_count_crossings(&R, S, r, &K), WK_OK);
                double t2 = now_s();
                peak = R.alloc.peak - live0;
                best_shoot = fmin(best_shoot, t1 - t0);
                best_count = fmin(best_count, t2 - t1);
                WK_FREE_ARRAY(&R, S, r);
            }
            fprintf(stderr,
                    "%-8s n=%-6u r=%-5u threads=%d  shoot %8.4f s  count %8.4f s  "
                    "crossings %llu  (count peak %zu bytes)\n",
                    cases[i].fam, cases[i].n, r, t, best_shoot, best_count, (unsigned long long)K,
                    peak);
        }
        wk_polygon_free(&R, P);
    }
    /* Scans: every segment of star n = 10,000 queried from its start. */
    R.opt.threads = 1;
    wk_arrangement A;
    build_random(&R, &A, "star", 10000, 1, 0);
    wk_crossing *out = WK_NEW_ARRAY(&R, wk_crossing, A.n_live);
    uint32_t ks[] = {1, 7, WK_K_MAX};
    for (int kk = 0; kk < 3; kk++) {
        uint64_t sc0 = counter(&R, "segments_scanned");
        double t0 = now_s();
        for (uint32_t id = 0; id < A.n_ids; id++) {
            uint32_t cnt;
            if (wk_arrangement_get(&A, id))
                cr_assert_eq(wk_arrangement_next_crossings(&R, &A, id, -1, ks[kk], out, &cnt),
                             WK_OK);
        }
        double dt = now_s() - t0;
        uint64_t sc = counter(&R, "segments_scanned") - sc0;
        fprintf(stderr,
                "scan star n=10000 (%u segments) k=%u: %.3f s, %.2f ns per scanned segment\n",
                A.n_live, ks[kk], dt, 1e9 * dt / (double)sc);
    }
    WK_FREE_ARRAY(&R, out, A.n_live);
    wk_arrangement_clear(&R, &A);
    ASSERT_CLEAN_CLOSE(R);
}
