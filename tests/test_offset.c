/*
** test_offset.c: wk_offset (engine/offset.c).
**
** Oracles: for a convex polygon the roof is min_e d(x, e) / w(e), so the
** offset at t is the intersection of the half-planes d(x, e) >= w(e) t
** (computed here by clipping, independently of the skeleton); for any
** polygon, the offset's rings are simple and pairwise disjoint (exact
** wk_segments_meet over every pair of sides), lie strictly inside P for
** t > 0, outer rings turn counter-clockwise and holes clockwise, and the area
** decreases with t.  t = 0 gives P itself; at and after the last node's time
** the set is empty.  Allocation failures at every step leave no leak.
*/
#include <criterion/criterion.h>

#include "helpers.h"

static wk_skeleton *solve(wk_run *R, const wk_polygon *P) {
    wk_skeleton *S = NULL;
    char msg[1024];
    wk_status st = wk_solve_checked(R, variant("naive"), P, 0, &S, NULL, NULL, NULL);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "solve: %s", msg);
    return S;
}

static wk_offset_set *offset(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double t) {
    wk_offset_set *O = NULL;
    char msg[1024];
    wk_status st = wk_offset(R, P, S, t, &O);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "offset t=%g: %s", t, msg);
    cr_assert_not_null(O);
    cr_assert_eq(O->polygon_start[0], 0);
    cr_assert_eq(O->polygon_start[O->n_polygons], O->n_rings);
    cr_assert_eq(O->ring_start[0], 0);
    return O;
}

static double set_area(const wk_offset_set *O) {
    double a = 0;
    for (uint32_t k = 0; k < O->n_rings; k++) a += wk_offset_ring_area(O, k);
    return a;
}

static double max_time(const wk_skeleton *S) {
    double m = 0;
    for (uint32_t i = 0; i < S->n_nodes; i++) m = fmax(m, S->nodes[i].t);
    return m;
}

/* The convex offset by clipping P's vertices with every half-plane
** d(x, e) >= w(e) t; writes the vertices to q (room 2 n + 8), returns the count. */
static uint32_t convex_offset(const wk_polygon *P, double t, wk_point *q, wk_point *tmp) {
    uint32_t m = P->n;
    memcpy(q, P->p, P->n * sizeof *q);
    for (uint32_t e = 0; e < P->n && m; e++) {
        wk_point a = P->p[e], b = P->p[wk_polygon_next(P, e)];
        double dx = b.x - a.x, dy = b.y - a.y, l = hypot(dx, dy);
        double nx = -dy / l, ny = dx / l, c = nx * a.x + ny * a.y + P->w[e] * t;
        uint32_t k = 0;
        for (uint32_t i = 0; i < m; i++) {
            wk_point u = q[i], v = q[(i + 1) % m];
            double su = nx * u.x + ny * u.y - c, sv = nx * v.x + ny * v.y - c;
            if (su >= 0) tmp[k++] = u;
            if ((su >= 0) != (sv >= 0)) {
                double s = su / (su - sv);
                tmp[k++] = (wk_point){u.x + s * (v.x - u.x), u.y + s * (v.y - u.y)};
            }
        }
        m = k;
        memcpy(q, tmp, m * sizeof *q);
    }
    return m;
}

static double shoelace(const wk_point *p, uint32_t n) {
    double a = 0;
    for (uint32_t i = 0; i < n; i++) {
        wk_point u = p[i], v = p[(i + 1) % n];
        a += u.x * v.y - v.x * u.y;
    }
    return 0.5 * a;
}

/* Offsets of convex P at several times agree with the clipped half-planes:
** area, and every vertex of either within tol of a vertex of the other
** (clipping leaves near-duplicates where an edge has nearly vanished). */
static void check_convex(const wk_polygon *P, const char *what) {
    wk_run R;
    wk_run_init(&R);
    wk_skeleton *S = solve(&R, P);
    double T = max_time(S), scale = wk_polygon_scale(P), tol = 1e-7 * scale;
    wk_point *q = calloc(2 * (size_t)P->n + 8, sizeof *q), *tmp = calloc(2 * (size_t)P->n + 8, sizeof *q);
    uint32_t checked = 0;
    for (int k = 0; k <= 20; k++) {
        double t = T * k / 20.3;
        wk_offset_set *O = offset(&R, P, S, t);
        uint32_t m = convex_offset(P, t, q, tmp);
        double want = m >= 3 ? shoelace(q, m) : 0;
        cr_assert(fabs(set_area(O) - want) <= 1e-7 * scale * scale, "%s t=%g: area %.17g, want %.17g",
                  what, t, set_area(O), want);
        cr_assert_leq(O->n_polygons, 1, "%s t=%g: %u components of a convex offset", what, t,
                      O->n_polygons);
        cr_assert_eq(O->n_rings, O->n_polygons, "%s t=%g: a hole in a convex offset", what, t);
        for (uint32_t i = 0; i < O->ring_start[O->n_rings]; i++) {
            double best = INFINITY;
            for (uint32_t j = 0; j < m; j++)
                best = fmin(best, hypot(O->p[i].x - q[j].x, O->p[i].y - q[j].y));
            cr_assert(best <= tol, "%s t=%g: offset vertex %u (%.17g, %.17g) is %g from the closed form",
                      what, t, i, O->p[i].x, O->p[i].y, best);
        }
        for (uint32_t j = 0; j < m; j++) {
            double best = INFINITY;
            for (uint32_t i = 0; i < O->ring_start[O->n_rings]; i++)
                best = fmin(best, hypot(O->p[i].x - q[j].x, O->p[i].y - q[j].y));
            cr_assert(best <= tol, "%s t=%g: closed-form vertex %u missing (%g away)", what, t, j, best);
        }
        checked += O->n_polygons;
        wk_offset_set_free(&R, O);
    }
    cr_assert_gt(checked, 10, "%s: too few nonempty offsets checked", what);
    free(q);
    free(tmp);
    wk_skeleton_free(&R, S);
    ASSERT_CLEAN_CLOSE(R);
}

Test(offset, rectangle_closed_form) {
    wk_run R;
    wk_run_init(&R);
    const double x[4] = {0, 4, 4, 0}, y[4] = {0, 0, 2, 2}, w[4] = {1, 2, 0.5, 1.5};
    wk_polygon *P = polygon(&R, 4, x, y, NULL);
    check_convex(P, "rectangle unit");
    wk_polygon *Q = polygon(&R, 4, x, y, w);
    check_convex(Q, "rectangle weighted");
    /* one time by hand: unit weights at t = 0.5, [0.5, 3.5] x [0.5, 1.5] */
    wk_skeleton *S = solve(&R, P);
    wk_offset_set *O = offset(&R, P, S, 0.5);
    cr_assert_eq(O->n_rings, 1);
    cr_assert_eq(O->ring_start[1], 4);
    cr_assert_float_eq(set_area(O), 3.0, 1e-12);
    wk_offset_set_free(&R, O);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    wk_polygon_free(&R, Q);
    ASSERT_CLEAN_CLOSE(R);
}

Test(offset, regular_and_random_convex_closed_form) {
    wk_run R;
    wk_run_init(&R);
    double x[9], y[9], w[9];
    for (int i = 0; i < 9; i++) {
        x[i] = 3 * cos(2 * PI * i / 9);
        y[i] = 3 * sin(2 * PI * i / 9);
        w[i] = 0.5 + 0.37 * (i % 4);
    }
    wk_polygon *P = polygon(&R, 9, x, y, NULL), *Q = polygon(&R, 9, x, y, w);
    check_convex(P, "9-gon unit");
    check_convex(Q, "9-gon weighted");
    wk_polygon_free(&R, P);
    wk_polygon_free(&R, Q);
    for (uint64_t seed = 1; seed <= 6; seed++) {
        wk_polygon *C = gen_polygon(&R, "convex", 40, seed, seed % 2 ? "uniform" : NULL);
        check_convex(C, "generated convex");
        wk_polygon_free(&R, C);
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* Exact point in polygon with holes: +1 inside, 0 on the boundary, -1 outside. */
static int inside_polygon(const wk_polygon *P, wk_point q) {
    int in = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        wk_point a = P->p[i], b = P->p[wk_polygon_next(P, i)];
        if (wk_segments_meet(a, b, q, q) != WK_SEG_DISJOINT) return 0;
        if ((a.y > q.y) != (b.y > q.y)) {
            int o = wk_orient2d(a, b, q, NULL);
            if ((b.y > a.y) ? o > 0 : o < 0) in = !in;
        }
    }
    return in ? 1 : -1;
}

/* Every ring simple, rings pairwise disjoint, orientation by role, inside P. */
static void check_rings(const wk_polygon *P, const wk_offset_set *O, const char *what) {
    uint32_t ns = O->ring_start[O->n_rings];
    for (uint32_t c = 0; c < O->n_polygons; c++)
        for (uint32_t k = O->polygon_start[c]; k < O->polygon_start[c + 1]; k++) {
            cr_assert_geq(O->ring_start[k + 1] - O->ring_start[k], 3);
            double a = wk_offset_ring_area(O, k);
            cr_assert(k == O->polygon_start[c] ? a > 0 : a < 0,
                      "%s t=%g: ring %u of component %u has area %g", what, O->t, k, c, a);
        }
    /* side s: from p[s] to the next vertex of its ring */
    uint32_t *ring = calloc(ns ? ns : 1, sizeof *ring);
    for (uint32_t k = 0; k < O->n_rings; k++)
        for (uint32_t j = O->ring_start[k]; j < O->ring_start[k + 1]; j++) ring[j] = k;
#define NEXT(s) ((s) + 1 == O->ring_start[ring[s] + 1] ? O->ring_start[ring[s]] : (s) + 1)
    for (uint32_t s = 0; s < ns; s++) {
        if (O->t > 0)
            cr_assert_eq(inside_polygon(P, O->p[s]), 1, "%s t=%g: offset vertex %u not inside P", what,
                         O->t, s);
        for (uint32_t u = s + 1; u < ns; u++) {
            wk_seg_meet m = wk_segments_meet(O->p[s], O->p[NEXT(s)], O->p[u], O->p[NEXT(u)]);
            bool adjacent = NEXT(s) == u || NEXT(u) == s;
            if (adjacent)
                cr_assert_eq(m, WK_SEG_TOUCH, "%s t=%g: adjacent sides %u, %u meet as %d", what, O->t,
                             s, u, (int)m);
            else
                cr_assert_eq(m, WK_SEG_DISJOINT, "%s t=%g: sides %u and %u (rings %u, %u) meet as %d",
                             what, O->t, s, u, ring[s], ring[u], (int)m);
        }
    }
#undef NEXT
    free(ring);
}

/* Rings simple and inside, area decreasing, t = 0 is P, the end is empty. */
static void check_general(const wk_polygon *P, const char *what, uint32_t steps) {
    wk_run R;
    wk_run_init(&R);
    wk_skeleton *S = solve(&R, P);
    double T = max_time(S), prev = INFINITY;
    wk_offset_set *O = offset(&R, P, S, 0);
    /* P's region with P's vertices; a vertex between collinear edges whose
    ** face is empty (removed at t = 0 by the collinear rule) may be left out */
    uint32_t nv = O->ring_start[O->n_rings];
    cr_assert_leq(nv, P->n, "%s: t = 0 has %u vertices, P %u", what, nv, P->n);
    cr_assert_float_eq(set_area(O), wk_polygon_area(P), 1e-12 * fabs(wk_polygon_area(P)));
    cr_assert_eq(O->n_rings, P->n_rings);
    for (uint32_t j = 0; j < nv; j++) { /* each a vertex of P, exactly */
        bool found = false;
        for (uint32_t i = 0; i < P->n && !found; i++)
            found = O->p[j].x == P->p[i].x && O->p[j].y == P->p[i].y;
        cr_assert(found, "%s: t = 0 vertex %u is no vertex of P", what, j);
    }
    for (uint32_t i = 0; i < P->n; i++) { /* a vertex left out is a straight one */
        wk_point a = P->p[wk_polygon_prev(P, i)], b = P->p[i], c = P->p[wk_polygon_next(P, i)];
        bool found = false;
        for (uint32_t j = 0; j < nv && !found; j++) found = O->p[j].x == b.x && O->p[j].y == b.y;
        cr_assert(found || wk_orient2d(a, b, c, NULL) == 0,
                  "%s: vertex %u of P (not straight) is missing at t = 0", what, i);
    }
    check_rings(P, O, what);
    wk_offset_set_free(&R, O);
    for (uint32_t k = 1; k <= steps; k++) {
        double t = T * k / (steps + 0.5);
        O = offset(&R, P, S, t);
        check_rings(P, O, what);
        double a = set_area(O);
        cr_assert_lt(a, prev, "%s: area at t=%g is %g, not below %g", what, t, a, prev);
        prev = a;
        wk_offset_set_free(&R, O);
    }
    O = offset(&R, P, S, T);
    cr_assert_eq(O->n_polygons, 0, "%s: offset at the last node's time is not empty", what);
    wk_offset_set_free(&R, O);
    O = offset(&R, P, S, 2 * T + 1);
    cr_assert_eq(O->n_polygons, 0);
    cr_assert_eq(O->n_rings, 0);
    wk_offset_set_free(&R, O);
    wk_skeleton_free(&R, S);
    ASSERT_CLEAN_CLOSE(R);
}

Test(offset, generated_polygons_simple_inside_decreasing) {
    wk_run R;
    wk_run_init(&R);
    static const char *const fam[] = {"star", "comb", "spiral", "random", "rectilinear", "coastline"};
    uint32_t cases = 0;
    for (size_t f = 0; f < sizeof fam / sizeof *fam; f++)
        for (uint64_t seed = 1; seed <= 3; seed++) {
            wk_polygon *P = NULL;
            if (gen(&R, fam[f], 40, -1, seed, seed == 3 ? "uniform" : NULL, &P) != WK_OK) {
                wk_run_clear_error(&R);
                continue;
            }
            char what[64];
            snprintf(what, sizeof what, "%s seed %llu", fam[f], (unsigned long long)seed);
            check_general(P, what, 12);
            wk_polygon_free(&R, P);
            cases++;
        }
    cr_assert_geq(cases, 15);
    ASSERT_CLEAN_CLOSE(R);
}

Test(offset, holes_simple_inside_decreasing) {
    wk_run R;
    wk_run_init(&R);
    uint32_t cases = 0;
    for (uint64_t seed = 1; seed <= 6; seed++) {
        wk_polygon *P = NULL;
        char msg[1024];
        wk_status st = gen_holes(&R, seed <= 3 ? "holes" : "convex", 36, -1, 1 + seed % 3, seed,
                                 seed % 2 ? "uniform" : NULL, &P);
        err_text(&R, msg, sizeof msg);
        cr_assert_eq(st, WK_OK, "%s", msg);
        char what[64];
        snprintf(what, sizeof what, "holes seed %llu", (unsigned long long)seed);
        check_general(P, what, 12);
        wk_polygon_free(&R, P);
        cases++;
    }
    cr_assert_eq(cases, 6);
    ASSERT_CLEAN_CLOSE(R);
}

/* A square with a square hole: at t = 1 the ring [1, 9]^2 around the hole
** [3, 7]^2, one component with one hole. */
Test(offset, square_with_hole_closed_form) {
    wk_run R;
    wk_run_init(&R);
    const uint32_t size[2] = {4, 4};
    const double x[8] = {0, 10, 10, 0, 4, 6, 6, 4}, y[8] = {0, 0, 10, 10, 4, 4, 6, 6};
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_from_rings(&R, 2, size, x, y, NULL, "hole.wpoly", NULL, &P), WK_OK);
    wk_skeleton *S = solve(&R, P);
    wk_offset_set *O = offset(&R, P, S, 1);
    cr_assert_eq(O->n_polygons, 1);
    cr_assert_eq(O->n_rings, 2);
    cr_assert_float_eq(wk_offset_ring_area(O, 0), 64.0, 1e-9);
    cr_assert_float_eq(wk_offset_ring_area(O, 1), -16.0, 1e-9);
    for (uint32_t i = 0; i < O->ring_start[2]; i++) {
        double ax = fabs(O->p[i].x - 5), ay = fabs(O->p[i].y - 5);
        bool outer = i < O->ring_start[1];
        cr_assert_float_eq(ax, outer ? 4.0 : 2.0, 1e-9);
        cr_assert_float_eq(ay, outer ? 4.0 : 2.0, 1e-9);
    }
    wk_offset_set_free(&R, O);
    /* the hole grows and the outer ring shrinks until they meet at t = 2 */
    O = offset(&R, P, S, 2.5);
    cr_assert_eq(O->n_polygons, 0);
    wk_offset_set_free(&R, O);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* A split: the dumbbell (two squares joined by a thin bar) parts into two
** components; at the split's own time both touch at one point. */
Test(offset, split_into_components) {
    wk_run R;
    wk_run_init(&R);
    const double x[12] = {0, 4, 4, 6, 6, 10, 10, 6, 6, 4, 4, 0};
    const double y[12] = {0, 0, 1.5, 1.5, 0, 0, 4, 4, 2.5, 2.5, 4, 4};
    wk_polygon *P = polygon(&R, 12, x, y, NULL);
    wk_skeleton *S = solve(&R, P);
    wk_offset_set *O = offset(&R, P, S, 0.25);
    cr_assert_eq(O->n_polygons, 1);
    wk_offset_set_free(&R, O);
    O = offset(&R, P, S, 1.0);
    cr_assert_eq(O->n_polygons, 2);
    cr_assert_eq(O->n_rings, 2);
    check_rings(P, O, "dumbbell");
    wk_offset_set_free(&R, O);
    O = offset(&R, P, S, 0.5); /* the bar vanishes at exactly t = 0.5: limit from above */
    cr_assert_eq(O->n_polygons, 2);
    wk_offset_set_free(&R, O);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(offset, bad_time) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = solve(&R, P);
    wk_offset_set *O = (wk_offset_set *)&R;
    cr_assert_eq(wk_offset(&R, P, S, -1, &O), WK_EINPUT);
    cr_assert_null(O);
    wk_run_clear_error(&R);
    cr_assert_eq(wk_offset(&R, P, S, NAN, &O), WK_EINPUT);
    wk_run_clear_error(&R);
    cr_assert_eq(wk_offset(&R, P, S, INFINITY, &O), WK_EINPUT);
    wk_run_clear_error(&R);
    wk_offset_set_free(&R, NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Fail the k-th allocation of wk_offset for k = 0, 1, ... until it succeeds:
** every failure is WK_ENOMEM with nothing left behind. */
Test(offset, allocation_failures) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(gen_holes(&R, "holes", 30, -1, 2, 5, "uniform", &P), WK_OK);
    wk_skeleton *S = solve(&R, P);
    double T = max_time(S);
    int ok = 0;
    for (int64_t k = 0; k < 200 && !ok; k++) {
        size_t live = R.alloc.live;
        wk_offset_set *O = NULL;
        R.alloc.fail_after = (int64_t)R.alloc.calls + k;
        wk_status st = wk_offset(&R, P, S, 0.3 * T, &O);
        R.alloc.fail_after = -1;
        if (st == WK_OK) {
            ok = 1;
            cr_assert_gt(O->n_rings, 0);
            wk_offset_set_free(&R, O);
        } else {
            cr_assert_eq(st, WK_ENOMEM, "fail after %lld: status %d", (long long)k, (int)st);
            cr_assert_null(O);
            wk_run_clear_error(&R);
        }
        cr_assert_eq(R.alloc.live, live, "fail after %lld: %zu bytes left", (long long)k,
                     R.alloc.live - live);
    }
    cr_assert(ok, "wk_offset never succeeded");
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Times exactly at node times (the degenerate case): the offset is computed
** (no WK_EALGO), its vertices are inside P, its area lies between the areas
** just before and just after, and rings keep their orientation. */
Test(offset, at_node_times) {
    wk_run R;
    wk_run_init(&R);
    static const char *const fam[] = {"star", "comb", "rectilinear", "spiral", "holes", "convex"};
    uint32_t cases = 0;
    for (size_t f = 0; f < sizeof fam / sizeof *fam; f++)
        for (uint64_t seed = 1; seed <= 2; seed++) {
            wk_polygon *P = NULL;
            uint32_t holes = !strcmp(fam[f], "holes") || !strcmp(fam[f], "convex") ? 2 : 0;
            if (gen_holes(&R, fam[f], 24, -1, holes, seed, seed == 2 ? "int" : NULL, &P) != WK_OK) {
                wk_run_clear_error(&R);
                continue;
            }
            wk_skeleton *S = solve(&R, P);
            double T = max_time(S);
            for (uint32_t i = P->n; i < S->n_nodes; i++) {
                double t = S->nodes[i].t;
                wk_offset_set *O = offset(&R, P, S, t);
                wk_offset_set *lo = offset(&R, P, S, fmax(0, t - 1e-7 * T));
                wk_offset_set *hi = offset(&R, P, S, t + 1e-7 * T);
                double a = set_area(O), al = set_area(lo), ah = set_area(hi);
                double slack = 1e-9 * wk_polygon_area(P);
                cr_assert(a <= al + slack && a >= ah - slack,
                          "%s seed %llu node %u t=%.17g: area %g not within [%g, %g]", fam[f],
                          (unsigned long long)seed, i, t, a, ah, al);
                for (uint32_t s = 0; s < O->ring_start[O->n_rings]; s++)
                    cr_assert_geq(inside_polygon(P, O->p[s]), t > 0 ? 1 : 0);
                for (uint32_t c = 0; c < O->n_polygons; c++)
                    for (uint32_t k = O->polygon_start[c]; k < O->polygon_start[c + 1]; k++)
                        cr_assert((wk_offset_ring_area(O, k) > 0) == (k == O->polygon_start[c]));
                wk_offset_set_free(&R, O);
                wk_offset_set_free(&R, lo);
                wk_offset_set_free(&R, hi);
                cases++;
            }
            wk_skeleton_free(&R, S);
            wk_polygon_free(&R, P);
        }
    cr_assert_gt(cases, 100);
    ASSERT_CLEAN_CLOSE(R);
}

/* The files with holes (tests/data/holes: islands, concentric squares,
** collinear and vertex events with holes) and hand-made polygons
** (degenerate ties: regular polygons, combs, a spiral). */
Test(offset, data_files_holes_islands_hand) {
    static const char *const files[] = {
        "holes/weighted_islands.wpoly",   "holes/concentric_squares.wpoly",
        "holes/hole_collinear_outer.wpoly", "holes/hole_vertex_event.wpoly",
        "holes/holes_collinear_pair.wpoly", "holes/square_hole_off_centre.wpoly",
        "holes/triangle_hole.wpoly",      "hand/regular_64.wpoly",
        "hand/comb_equal.wpoly",          "hand/collinear_catch_up.wpoly",
        "hand/collinear_weights.wpoly",   "hand/cross_uneven.wpoly",
        "hand/h_shape_offset.wpoly",      "hand/reflex_preserving.wpoly",
        "hand/sliver.wpoly",              "hand/weighted_square.wpoly",
    };
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        wk_run R;
        wk_run_init(&R);
        char path[512];
        data_path(path, sizeof path, files[i]);
        wk_polygon *P = NULL;
        cr_assert_eq(wk_polygon_read_file(&R, path, &P), WK_OK, "%s: %s", files[i], R.err.msg);
        check_general(P, files[i], 16);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}
