/*
** gen_random.c: the random family: a random simple polygon with no planted
** structure, r whatever comes out (about half the vertices).
**
** n <= RANDOM_2OPT_MAX: n uniform points of [-1000, 1000]^2, visited in
** Hilbert-curve order (a closed tour with few, local crossings), then
** untangled by 2-opt moves: while two non-adjacent edges ab and cd meet
** (exactly, wk_segments_meet), replace them by ac and bd, reversing the
** stretch b..c.  For a proper crossing this shortens the tour strictly, so
** the loop ends; MOVES_PER_VERTEX caps it anyway (a touching configuration
** could in principle repeat), failing with WK_EALGO instead of spinning.
** Each pass tests all O(n^2) pairs behind a bounding-box filter.
**
** Larger n: a star-shaped polygon with random radii in [0.2, 1] R and random
** angles: gaps uniform in [0.05, 1], normalised to 2 pi, so that no two
** angles come closer than about 0.05 / n of a turn (plain sorted uniform
** angles would, at n in the millions, put two within rounding of each
** other).
*/
#include "gen_internal.h"

#include <math.h>
#include <stdlib.h>

/* Above this, 2-opt's O(n^2) passes cost more than a second. */
#define RANDOM_2OPT_MAX 5000u
#define MOVES_PER_VERTEX 200u

/* Position of (x, y) on the Hilbert curve of a 2^16 x 2^16 grid (the
** classic xy2d: per level, the quadrant's offset, then rotate/flip the
** coordinates into that quadrant's frame). */
static uint64_t hilbert_index(uint32_t x, uint32_t y) {
    const uint32_t N = 1u << 16;
    uint64_t d = 0;
    for (uint32_t s = N / 2; s > 0; s /= 2) {
        uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += (uint64_t)s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = N - 1 - x;
                y = N - 1 - y;
            }
            uint32_t t = x;
            x = y;
            y = t;
        }
    }
    return d;
}

static int cmp_u64(const void *a, const void *b) {
    uint64_t p = *(const uint64_t *)a, q = *(const uint64_t *)b;
    return (p > q) - (p < q);
}

static void reverse(uint32_t *t, uint32_t i, uint32_t j) {
    for (; i < j; i++, j--) {
        uint32_t s = t[i];
        t[i] = t[j];
        t[j] = s;
    }
}

static bool boxes_apart(wk_point a, wk_point b, wk_point c, wk_point d) {
    return fmax(a.x, b.x) < fmin(c.x, d.x) || fmax(c.x, d.x) < fmin(a.x, b.x) ||
           fmax(a.y, b.y) < fmin(c.y, d.y) || fmax(c.y, d.y) < fmin(a.y, b.y);
}

/* Untangle the closed tour t over pts; WK_EALGO if the move cap is hit. */
static wk_status two_opt(wk_run *R, const wk_point *pts, uint32_t *t, uint32_t n) {
    uint64_t moves = 0, cap = (uint64_t)MOVES_PER_VERTEX * n;
    bool changed = true;
    while (changed) {
        changed = false;
        for (uint32_t i = 0; i + 2 < n; i++) {
            for (uint32_t j = i + 2; j < n; j++) {
                if (i == 0 && j == n - 1) continue; /* edges n-1 and 0 are adjacent */
                wk_point a = pts[t[i]], b = pts[t[i + 1]];
                wk_point c = pts[t[j]], d = pts[t[j + 1 == n ? 0 : j + 1]];
                if (boxes_apart(a, b, c, d)) continue;
                if (wk_segments_meet(a, b, c, d) == WK_SEG_DISJOINT) continue;
                if (++moves > cap)
                    return WK_FAIL(R, WK_EALGO, NULL, 0,
                                   "random: 2-opt did not converge after %llu moves (n=%u)",
                                   (unsigned long long)cap, n);
                reverse(t, i + 1, j);
                changed = true;
            }
        }
    }
    return WK_OK;
}

static wk_status random_2opt(wk_run *R, uint32_t n, wk_rng *rng, double *x, double *y) {
    wk_status st = WK_OK;
    wk_point *pts = WK_NEW_ARRAY(R, wk_point, n);
    uint64_t *key = WK_NEW_ARRAY(R, uint64_t, n);
    uint32_t *t = WK_NEW_ARRAY(R, uint32_t, n);
    if (!pts || !key || !t) {
        st = WK_ENOMEM;
        goto done;
    }
    for (uint32_t i = 0; i < n; i++) {
        double ux = wk_rng_unit(rng), uy = wk_rng_unit(rng);
        pts[i] = (wk_point){WK_GEN_BOX * (2.0 * ux - 1.0), WK_GEN_BOX * (2.0 * uy - 1.0)};
        /* Hilbert key in the high 32 bits, the point id below: unique keys,
        ** so the sort order is total. */
        uint64_t h = hilbert_index((uint32_t)(ux * 65536.0), (uint32_t)(uy * 65536.0));
        key[i] = (h << 32) | i;
    }
    qsort(key, n, sizeof *key, cmp_u64);
    for (uint32_t i = 0; i < n; i++) t[i] = (uint32_t)(key[i] & 0xFFFFFFFFu);
    if ((st = two_opt(R, pts, t, n)) != WK_OK) goto done;
    /* Counter-clockwise: the shoelace sum of a simple polygon is far from 0. */
    double area = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        wk_point p = pts[t[i]], q = pts[t[i + 1 == n ? 0 : i + 1]];
        area += p.x * q.y - p.y * q.x;
    }
    for (uint32_t i = 0; i < n; i++) {
        wk_point p = pts[t[area > 0 ? i : n - 1 - i]];
        x[i] = p.x;
        y[i] = p.y;
    }
done:
    WK_FREE_ARRAY(R, pts, n);
    WK_FREE_ARRAY(R, key, n);
    WK_FREE_ARRAY(R, t, n);
    return st;
}

static void random_star(uint32_t n, wk_rng *rng, double *x, double *y) {
    double total = 0.0, theta0 = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
    for (uint32_t i = 0; i < n; i++) {
        x[i] = wk_rng_range(rng, 0.05, 1.0); /* gap before vertex i */
        total += x[i];
    }
    /* Vertex i sits after gaps 1..i; gap 0 closes the turn back to vertex 0.
    ** x[] is overwritten as we go, behind the reads. */
    double acc = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        if (i > 0) acc += x[i];
        double t = theta0 + 2.0 * WK_GEN_PI * acc / total;
        double q = WK_GEN_BOX * wk_rng_range(rng, 0.2, 1.0);
        x[i] = q * cos(t);
        y[i] = q * sin(t);
    }
}

wk_status wk_gen_random(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                        int64_t *r_out) {
    if (g->r >= 0)
        return WK_FAIL(R, WK_EINPUT, NULL, 0,
                       "random: r cannot be chosen (use star, notched or monotone for a given r)");
    *r_out = -1;
    if (g->n <= RANDOM_2OPT_MAX) return random_2opt(R, g->n, rng, x, y);
    random_star(g->n, rng, x, y);
    return WK_OK;
}
