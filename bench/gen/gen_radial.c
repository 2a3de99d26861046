/*
** gen_radial.c: the families built in polar coordinates around the origin:
** convex, star, notched and spiral.
**
** Why they are simple: convex, star and notched list their vertices by
** strictly increasing angle (total < 2 pi) at positive radii, so each is
** star-shaped from the origin.  The spiral is a band between two offset
** curves of an Archimedean spiral; its step sizes are chosen so that every
** chord stays inside the band's clearance (see spiral_turns).
**
** Why the reflex count is exact where promised: a vertex on the circle of
** radius R whose neighbours lie on the segments from the origin to the
** circle is a left turn, since the origin is strictly left of the chord
** through it and its predecessor (the angular gaps are below pi).  A vertex
** pushed strictly behind the chord of its two neighbours (towards the
** origin) is a right turn.  Every margin is a fixed fraction of the local
** geometry, far above double rounding for n <= WK_GEN_N_MAX.
*/
#include "gen_internal.h"

#include <math.h>

/* Angular jitter, as a fraction of the step 2 pi / n: consecutive angles
** stay between 0.6 and 1.4 steps apart, so the order never changes. */
#define JITTER 0.2

static double jittered_angle(wk_rng *rng, uint32_t i, uint32_t n, double theta0) {
    return theta0 + 2.0 * WK_GEN_PI * ((double)i + wk_rng_range(rng, -JITTER, JITTER)) / n;
}

/* mark[i] = 1 for exactly r positions of the cycle 0..n-1, no two adjacent
** (cyclically), chosen from rng; needs 2r <= n.  Picks the order of r
** blocks "pushed, plain" and n-2r single "plain" items by selection
** sampling, lays them out and rotates by a random offset: each pushed
** position is followed by a plain one, also across the wrap. */
static void choose_nonadjacent(wk_rng *rng, uint32_t n, uint32_t r, uint8_t *mark) {
    uint32_t items = n - r, need = r, pos = 0, offset = (uint32_t)wk_rng_below(rng, n);
    for (uint32_t i = 0; i < n; i++) mark[i] = 0;
    for (uint32_t i = 0; i < items; i++) {
        if (wk_rng_below(rng, items - i) < need) {
            need--;
            mark[(pos + offset) % n] = 1;
            pos += 2;
        } else {
            pos += 1;
        }
    }
}

/* The checks star and notched share. */
static wk_status check_pushed(wk_run *R, const wk_gen_params *g, int64_t r) {
    uint32_t n = g->n;
    if (r > n / 2)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: r=%lld > n/2=%u", g->family, (long long)r,
                       n / 2);
    if (r > (int64_t)n - 3)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: r=%lld > n-3=%u", g->family, (long long)r,
                       n - 3);
    if (r > 0 && n < 5) /* with 4 vertices the chord of a vertex's neighbours
                           passes through the centre: nothing to push past */
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: r=%lld > 0 needs n >= 5 (got n=%u)",
                       g->family, (long long)r, n);
    return WK_OK;
}

/* ---- convex ---- */

wk_status wk_gen_convex(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                        int64_t *r_out) {
    wk_status st = wk_gen_fixed_r(R, g, 0, NULL);
    if (st != WK_OK) return st;
    /* Points of an ellipse in angular order are in convex position; the
    ** rotation keeps the axes from lining up with the coordinate axes. */
    double a = WK_GEN_BOX * wk_rng_range(rng, 0.6, 1.0);
    double b = WK_GEN_BOX * wk_rng_range(rng, 0.6, 1.0);
    double rot = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI), c = cos(rot), s = sin(rot);
    for (uint32_t i = 0; i < g->n; i++) {
        double t = jittered_angle(rng, i, g->n, 0.0);
        double ex = a * cos(t), ey = b * sin(t);
        x[i] = c * ex - s * ey;
        y[i] = s * ex + c * ey;
    }
    *r_out = 0;
    return WK_OK;
}

/* ---- star ---- */

/* Angles ang[0..n) increasing by 0.6 to 1.4 steps; the gap of vertex i's
** two neighbours, with the wrap. */
static double neighbour_gap(const double *ang, uint32_t i, uint32_t n) {
    double lo = ang[i == 0 ? n - 1 : i - 1], hi = ang[i + 1 == n ? 0 : i + 1];
    if (i == 0) lo -= 2.0 * WK_GEN_PI;
    if (i + 1 == n) hi += 2.0 * WK_GEN_PI;
    return hi - lo;
}

/* Radii for exactly r reflex vertices: plain vertices on the circle of
** radius R, pushed ones (non-adjacent) at u * R cos(gap/2), u in [0.2, 0.8],
** i.e. strictly between the origin and the chord of their neighbours. */
static wk_status star_pushed(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *ang,
                             double *rad, uint32_t r) {
    uint32_t n = g->n;
    uint8_t *mark = WK_NEW_ARRAY(R, uint8_t, n);
    if (!mark) return WK_ENOMEM;
    choose_nonadjacent(rng, n, r, mark);
    for (uint32_t i = 0; i < n; i++) {
        double u = wk_rng_range(rng, 0.2, 0.8);
        rad[i] = mark[i] ? u * WK_GEN_BOX * cos(0.5 * neighbour_gap(ang, i, n)) : WK_GEN_BOX;
    }
    WK_FREE_ARRAY(R, mark, n);
    return WK_OK;
}

wk_status wk_gen_star(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                      int64_t *r_out) {
    uint32_t n = g->n;
    wk_status st = WK_OK;
    if (g->r >= 0 && (st = check_pushed(R, g, g->r)) != WK_OK) return st;
    /* x and y double as the angle and radius arrays until the end. */
    double *ang = x, *rad = y, theta0 = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
    for (uint32_t i = 0; i < n; i++) ang[i] = jittered_angle(rng, i, n, theta0);
    if (g->r < 0) {
        for (uint32_t i = 0; i < n; i++) rad[i] = WK_GEN_BOX * wk_rng_range(rng, 0.2, 1.0);
        *r_out = -1;
    } else {
        if ((st = star_pushed(R, g, rng, ang, rad, (uint32_t)g->r)) != WK_OK) return st;
        *r_out = g->r;
    }
    for (uint32_t i = 0; i < n; i++) {
        double t = ang[i], q = rad[i];
        x[i] = q * cos(t);
        y[i] = q * sin(t);
    }
    return WK_OK;
}

/* ---- notched ---- */

wk_status wk_gen_notched(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                         int64_t *r_out) {
    uint32_t n = g->n;
    int64_t r = g->r >= 0 ? g->r : n / 4;
    wk_status st = check_pushed(R, g, r);
    if (st != WK_OK) return st;
    uint8_t *mark = WK_NEW_ARRAY(R, uint8_t, n);
    if (!mark) return WK_ENOMEM;
    choose_nonadjacent(rng, n, (uint32_t)r, mark);
    /* The chord of a vertex's two neighbours lies at distance c from the
    ** centre and is 2s long.  A notch goes d behind it, d between a quarter
    ** and all of min(s, 0.8c): shallow next to its edges for large n, never
    ** through the centre for small n. */
    double step = 2.0 * WK_GEN_PI / n;
    double c = WK_GEN_BOX * cos(step), s = WK_GEN_BOX * sin(step);
    double dmax = s < 0.8 * c ? s : 0.8 * c;
    for (uint32_t i = 0; i < n; i++) {
        double t = step * i;
        double q = mark[i] ? c - dmax * wk_rng_range(rng, 0.25, 1.0) : WK_GEN_BOX;
        x[i] = q * cos(t);
        y[i] = q * sin(t);
    }
    WK_FREE_ARRAY(R, mark, n);
    *r_out = r;
    return WK_OK;
}

/* ---- spiral ----
**
** Centre curve rho(phi) = b (phi + pi), phi in [0, Phi = 2 pi T]; the band
** has width w = pi b, half the pitch 2 pi b, so consecutive turns leave a
** gap of pi b.  Outer chain: rho + w/2 at increasing phi (left turns);
** inner chain: rho - w/2 >= w/2 > 0 at decreasing phi (right turns), both
** with JITTER on the angles.  The four cap vertices are convex, so
** r = (inner vertices) - 2 = floor(n/2) - 2.
**
** Step conditions, with the longest gap 1.4 steps: two gaps span less than
** pi (three consecutive vertices of a curve whose tangent turns less than pi
** make a strict turn of the curve's sense); and a chord's sagitta, at most
** R (1 - cos(0.7 step)), stays below half the clearance w = gap = pi b. */

static bool spiral_ok(double turns, uint32_t k) {
    double step = 2.0 * WK_GEN_PI * turns / (k - 1);
    double b = WK_GEN_BOX / (2.0 * WK_GEN_PI * turns + 1.5 * WK_GEN_PI);
    return 2.8 * step < 0.65 * WK_GEN_PI &&
           WK_GEN_BOX * (1.0 - cos(0.7 * step)) < 0.5 * WK_GEN_PI * b;
}

/* About sqrt(k)/2 turns, fewer while a step condition fails (small k). */
static double spiral_turns(uint32_t k) {
    double t = 0.5 * sqrt((double)k);
    if (t < 1.0) t = 1.0;
    while (!spiral_ok(t, k)) t *= 0.9;
    return t;
}

wk_status wk_gen_spiral(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                        int64_t *r_out) {
    uint32_t n = g->n;
    if (n < 6) return WK_FAIL(R, WK_EINPUT, NULL, 0, "spiral: n=%u < 6", n);
    int64_t r = (int64_t)(n / 2) - 2;
    wk_status st = wk_gen_fixed_r(R, g, r, "floor(n/2)-2");
    if (st != WK_OK) return st;
    uint32_t k_in = n / 2, k_out = n - k_in;
    double turns = spiral_turns(k_in), phi_end = 2.0 * WK_GEN_PI * turns;
    double b = WK_GEN_BOX / (phi_end + 1.5 * WK_GEN_PI), half = 0.5 * WK_GEN_PI * b;
    double theta0 = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
    uint32_t v = 0;
    for (uint32_t j = 0; j < k_out; j++, v++) {
        double jit = (j == 0 || j + 1 == k_out) ? 0.0 : wk_rng_range(rng, -JITTER, JITTER);
        double phi = phi_end * ((double)j + jit) / (k_out - 1);
        double q = b * (phi + WK_GEN_PI) + half;
        x[v] = q * cos(phi + theta0);
        y[v] = q * sin(phi + theta0);
    }
    for (uint32_t j = 0; j < k_in; j++, v++) {
        double jit = (j == 0 || j + 1 == k_in) ? 0.0 : wk_rng_range(rng, -JITTER, JITTER);
        double phi = phi_end * ((double)(k_in - 1 - j) + jit) / (k_in - 1);
        double q = b * (phi + WK_GEN_PI) - half;
        x[v] = q * cos(phi + theta0);
        y[v] = q * sin(phi + theta0);
    }
    *r_out = r;
    return WK_OK;
}
