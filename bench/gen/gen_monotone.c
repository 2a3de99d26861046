/*
** gen_monotone.c: the monotone family: an x-monotone polygon with exactly r
** reflex vertices, 0 <= r <= n-3, for the monotone variant and as a
** controlled-r input in general.
**
** Construction.  n distinct x from jittered cells of [-1000, 1000]; the
** leftmost (L) and rightmost (Rt) vertices are shared by the two chains, and
** every other vertex goes to the lower or the upper chain by a coin flip; r
** of these n-2 interior vertices, chosen at random, are to be reflex.  Each
** chain is a piecewise-linear function over [xL, xR] that vanishes at both
** ends, described by its slope change (kink) at each vertex:
**   lower chain: convex = slope increases (+K), reflex = decreases (-lambda e);
**   upper chain: convex = slope decreases (-K), reflex = increases (+lambda e);
** K, e uniform in [1, 2].  A chain's turn at a vertex has the sign of its own
** kink only, so the reflex count is exact whatever the magnitudes.
**
** Simplicity needs upper > lower inside (L, Rt).  A function vanishing at
** both ends with kinks k_v is -sum_v k_v hat(x, x_v), with the tent
** hat(x, s) = min((x-xL)(xR-s), (s-xL)(xR-x)) / (xR-xL) >= 0, so
**   upper - lower = C(x) - lambda E(x),
** C = sum over convex vertices of K hat, E = sum over reflex ones of e hat,
** whichever chain they are on.  C > 0 inside as at least one interior vertex
** is convex (r <= n-3).  Both are piecewise linear with breakpoints at the
** vertices, so lambda = min(1, 0.5 min_v C(x_v) / E(x_v)) keeps the
** difference above C/2 everywhere.
**
** Precision: chains are integrated edge by edge from their slopes, so a
** vertex's turn depends on the roundings next to it only (one rounding of
** y, about 1e-16 of the chain's height), while its kink moves it by lambda e
** times the local edge length; the closing correction (a linear function,
** which changes no turn) and the final scaling add one rounding each.
*/
#include "gen_internal.h"

#include <math.h>

/* Per vertex: which chain, whether reflex, and the magnitude drawn. */
typedef struct mvert {
    uint8_t upper, reflex;
    double mag;
} mvert;

/* Sums over the tents of one kind (convex or reflex) at x[k], for all k, by
** prefix sums: hat(x, s) (xR-xL) is (x-xL)(xR-s) for s >= x, (s-xL)(xR-x)
** for s <= x.  out[k] = sum mag_v hat(x_k, x_v) over the vertices v of
** the kind.  All terms are >= 0, so the sums are accurate. */
static void tent_sums(const double *x, const mvert *m, uint32_t n, uint8_t reflex, double *out) {
    double xl = x[0], W = x[n - 1] - x[0];
    /* left[k] = sum_{v <= k} mag (x_v - xL); then right sums backwards */
    double acc = 0.0;
    for (uint32_t k = 1; k + 1 < n; k++) {
        if (m[k].reflex == reflex) acc += m[k].mag * (x[k] - xl);
        out[k] = acc * (x[n - 1] - x[k]);
    }
    acc = 0.0;
    for (uint32_t k = n - 1; k-- > 1;) {
        out[k] += acc * (x[k] - xl);
        if (m[k].reflex == reflex) acc += m[k].mag * (x[n - 1] - x[k]);
        out[k] /= W;
    }
}

/* Integrate one chain (vertices 0, the chain's interior ones, n-1 in x
** order) from its kinks, close it to 0 at both ends and store y. */
static void integrate_chain(const double *x, const mvert *m, uint32_t n, uint8_t upper,
                            double lambda, double *y) {
    double slope = 0.0, yy = 0.0;
    uint32_t prev = 0;
    y[0] = 0.0;
    for (uint32_t k = 1; k < n; k++) {
        if (k + 1 < n && m[k].upper != upper) continue;
        yy += slope * (x[k] - x[prev]);
        y[k] = yy;
        if (k + 1 < n) {
            double kink = m[k].reflex ? lambda * m[k].mag : -m[k].mag; /* upper's signs */
            slope += upper ? kink : -kink;
        }
        prev = k;
    }
    /* Closing: subtract the line through (xL, 0) and (xR, y[n-1]). */
    double end = y[n - 1], W = x[n - 1] - x[0];
    for (uint32_t k = 1; k + 1 < n; k++)
        if (m[k].upper == upper) y[k] -= end * ((x[k] - x[0]) / W);
}

wk_status wk_gen_monotone(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                          int64_t *r_out) {
    uint32_t n = g->n;
    int64_t r = g->r >= 0 ? g->r : ((int64_t)n - 2) / 2;
    if (r > (int64_t)n - 3)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "monotone: r=%lld > n-3=%u", (long long)r, n - 3);
    mvert *m = WK_NEW_ARRAY(R, mvert, n);
    double *c = WK_NEW_ARRAY(R, double, n), *e = WK_NEW_ARRAY(R, double, n);
    double *xs = WK_NEW_ARRAY(R, double, n);
    wk_status st = WK_OK;
    if (!m || !c || !e || !xs) {
        st = WK_ENOMEM;
        goto done;
    }
    for (uint32_t k = 0; k < n; k++)
        xs[k] = -WK_GEN_BOX + 2.0 * WK_GEN_BOX * ((double)k + wk_rng_range(rng, 0.1, 0.9)) / n;
    uint32_t need = (uint32_t)r;
    for (uint32_t k = 1; k + 1 < n; k++) {
        m[k].upper = (uint8_t)wk_rng_below(rng, 2);
        /* selection sampling: r of the n-2 interior vertices */
        m[k].reflex = wk_rng_below(rng, n - 1 - k) < need;
        if (m[k].reflex) need--;
        m[k].mag = wk_rng_range(rng, 1.0, 2.0);
    }
    tent_sums(xs, m, n, 0, c);
    tent_sums(xs, m, n, 1, e);
    double lambda = 1.0;
    for (uint32_t k = 1; k + 1 < n; k++)
        if (e[k] > 0 && 0.5 * c[k] < lambda * e[k]) lambda = 0.5 * c[k] / e[k];

    /* Heights into c (lower chain) and e (upper chain), then scale into
    ** [-1000, 1000] and lay out counter-clockwise: L, lower chain left to
    ** right, Rt, upper chain right to left. */
    integrate_chain(xs, m, n, 0, lambda, c);
    integrate_chain(xs, m, n, 1, lambda, e);
    double top = 0.0;
    for (uint32_t k = 1; k + 1 < n; k++) {
        double h = fabs(m[k].upper ? e[k] : c[k]);
        if (h > top) top = h;
    }
    double scale = top > 0 ? WK_GEN_BOX / top : 1.0;
    uint32_t v = 0;
    x[v] = xs[0], y[v] = 0.0, v++;
    for (uint32_t k = 1; k + 1 < n; k++)
        if (!m[k].upper) x[v] = xs[k], y[v] = c[k] * scale, v++;
    x[v] = xs[n - 1], y[v] = 0.0, v++;
    for (uint32_t k = n - 1; k-- > 1;)
        if (m[k].upper) x[v] = xs[k], y[v] = e[k] * scale, v++;
    *r_out = r;
done:
    WK_FREE_ARRAY(R, m, n);
    WK_FREE_ARRAY(R, c, n);
    WK_FREE_ARRAY(R, e, n);
    WK_FREE_ARRAY(R, xs, n);
    return st;
}
