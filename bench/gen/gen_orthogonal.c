/*
** gen_orthogonal.c: the families on integer coordinates, comb and
** rectilinear, whose point is many simultaneous events: equal lengths make
** many wavefront collisions happen at exactly the same time and place,
** exactly representable in doubles.
**
** Both are x-monotone: a bottom chain below y = 0 (or the comb's base line)
** and a top chain above it, over the same x range, so they are simple as
** soon as consecutive vertices differ.  Edges alternate horizontal and
** vertical, so no three consecutive vertices are collinear, and an
** orthogonal polygon has 4 more convex than reflex vertices: r = n/2 - 2.
** The comb's padding (n mod 4 extra vertices, a shallow convex arc under the
** base) is the only non-axis-parallel part and adds convex vertices only.
**
** Coordinates stay below 2^53, so every one is an exact double.
*/
#include "gen_internal.h"

#include <math.h>

/* ---- comb ----
**
** t = floor(n/4) teeth of width a*u on a bar, gaps b*u (a, b in 1..3 from
** the seed, u the largest integer unit that keeps the width near 1000, at
** least 1); tooth height and bar height integers from the seed.  Vertices:
** (0,0), padding, (L,0), then along the top from right to left two per
** tooth top and two per gap bottom: 2 + 2t + 2(t-1) + e = 4t + e = n.
** Reflex: the two bottom corners of each of the t-1 gaps. */

wk_status wk_gen_comb(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                      int64_t *r_out) {
    uint32_t n = g->n;
    if (n < 4) return WK_FAIL(R, WK_EINPUT, NULL, 0, "comb: n=%u < 4", n);
    uint32_t t = n / 4, e = n % 4;
    int64_t r = 2 * ((int64_t)t - 1);
    wk_status st = wk_gen_fixed_r(R, g, r, "2*(floor(n/4)-1)");
    if (st != WK_OK) return st;
    double a = (double)(1 + wk_rng_below(rng, 3)), b = (double)(1 + wk_rng_below(rng, 3));
    double units = a * t + b * (t - 1);
    double u = floor(WK_GEN_BOX / units);
    if (u < 1.0) u = 1.0;
    double tw = a * u, gw = b * u, L = units * u;
    double hb = (double)(100 + wk_rng_below(rng, 201)); /* bar: 100..300 */
    double H = hb + (double)(200 + wk_rng_below(rng, 401)); /* top: bar + 200..600 */

    uint32_t v = 0;
    x[v] = 0.0, y[v] = 0.0, v++;
    /* Padding: e points of the convex arc y = -40 sin(pi s), s = j/(e+1),
    ** rounded; for e <= 3 the rounded values stay strictly convex. */
    for (uint32_t j = 1; j <= e; j++) {
        double s = (double)j / (e + 1);
        x[v] = floor(L * s + 0.5);
        y[v] = -floor(40.0 * sin(WK_GEN_PI * s) + 0.5);
        v++;
    }
    x[v] = L, y[v] = 0.0, v++;
    for (uint32_t k = t; k-- > 0;) {
        double left = k * (tw + gw);
        x[v] = left + tw, y[v] = H, v++;
        x[v] = left, y[v] = H, v++;
        if (k > 0) {
            x[v] = left, y[v] = hb, v++;
            x[v] = left - gw, y[v] = hb, v++;
        }
    }
    *r_out = r;
    return WK_OK;
}

/* ---- rectilinear ----
**
** Two staircases over [0, W]: the top chain has mt columns with heights in
** {1..4} * 100, the bottom chain mb columns with depths in {1..4} * 100,
** neighbouring columns always differing; mt + mb = n/2.  Column widths are a
** random composition of K = 2 mt grid units (unit: the largest integer
** keeping W near 1000), so widths repeat a lot and many events coincide.
** Vertices: 2 per column, n = 2 (mt + mb). */

/* Split K units into m >= 1 positive parts: the m-1 cut points are a
** selection sample of 1..K-1; writes the m+1 boundaries (0..K) to cut. */
static void composition(wk_rng *rng, uint32_t K, uint32_t m, uint32_t *cut) {
    uint32_t need = m - 1, c = 0;
    cut[c++] = 0;
    for (uint32_t i = 1; i < K && need > 0; i++)
        if (wk_rng_below(rng, K - i) < need) cut[c++] = i, need--;
    cut[c] = K;
}

/* Heights in {1..4} * 100, each different from the previous. */
static double next_level(wk_rng *rng, double prev) {
    double h;
    do h = 100.0 * (double)(1 + wk_rng_below(rng, 4));
    while (h == prev);
    return h;
}

wk_status wk_gen_rectilinear(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                             double *y, int64_t *r_out) {
    uint32_t n = g->n;
    if (n % 2 != 0) return WK_FAIL(R, WK_EINPUT, NULL, 0, "rectilinear: n=%u is odd", n);
    if (n < 4) return WK_FAIL(R, WK_EINPUT, NULL, 0, "rectilinear: n=%u < 4", n);
    int64_t r = (int64_t)(n / 2) - 2;
    wk_status st = wk_gen_fixed_r(R, g, r, "n/2-2");
    if (st != WK_OK) return st;
    uint32_t m = n / 2, mt = (m + 1) / 2, mb = m - mt, K = 2 * mt;
    double u = floor(WK_GEN_BOX / K);
    if (u < 1.0) u = 1.0;
    uint32_t *cut = WK_NEW_ARRAY(R, uint32_t, mt + 1);
    if (!cut) return WK_ENOMEM;

    /* Bottom chain, left to right: (X_j, -d_j) (X_{j+1}, -d_j) per column,
    ** sharing nothing; the top chain right to left the same way. */
    uint32_t v = 0;
    double level = 0.0;
    composition(rng, K, mb, cut);
    for (uint32_t j = 0; j < mb; j++) {
        level = next_level(rng, level);
        x[v] = u * cut[j], y[v] = -level, v++;
        x[v] = u * cut[j + 1], y[v] = -level, v++;
    }
    /* Top columns are drawn left to right but listed right to left. */
    composition(rng, K, mt, cut);
    level = 0.0;
    for (uint32_t j = 0; j < mt; j++) {
        level = next_level(rng, level);
        uint32_t a = n - 1 - 2 * j; /* column j's two vertices, from the end */
        x[a] = u * cut[j], y[a] = level;
        x[a - 1] = u * cut[j + 1], y[a - 1] = level;
    }
    WK_FREE_ARRAY(R, cut, mt + 1);
    *r_out = r;
    return WK_OK;
}
