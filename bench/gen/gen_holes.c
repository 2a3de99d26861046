/*
** gen_holes.c: the families with holes: `holes` (star or convex holes in a
** star or convex outer polygon) and `convex --holes H` (convex windows in
** the convex family's ellipse).
**
** Vertex split (both families): with H holes, the holes get
** n_h = max(3H, floor(n/2)) vertices in all (at most n - 3), shared out
** evenly: hole j gets floor(n_h/H), plus one for j < n_h mod H; the outer
** ring gets the rest, n - n_h >= 3.  So n >= 3H + 3.  H = 0: the outer ring
** alone, n vertices.
**
** Why simple, with every ring disjoint from the others and the holes inside
** the outer ring: the outer ring lists its vertices by strictly increasing
** angle around the origin at positive radii (gaps below pi), so it is
** star-shaped from the origin and contains the open disc D(0, d), d its
** smallest distance from the origin to an edge.  The holes live in a square
** inscribed in D(0, rho), rho = 0.9 d (the 10% absorb the rounding of d):
** the square is cut into g x g cells (g = ceil(sqrt(H))), H of the cells
** are chosen from the seed, and each chosen cell holds one disc of a seeded
** radius 0.3..0.9 of half the cell, placed at a seeded offset so that it
** keeps 5% of half a cell away from the cell's border.  A hole is listed
** clockwise by strictly decreasing angle around its disc's centre at radii
** within the disc: star-shaped (radii 0.35..1 of the disc's) or convex
** (points of an inscribed ellipse).  Discs in different cells are disjoint
** with a margin far above the coordinates' rounding, so no two rings meet.
** wk_generate still has wk_polygon_from_rings check all of it.
**
** Reflex count: convex --holes H promises r = n_h, every hole vertex (a
** convex hole stored clockwise is reflex at each of its vertices, the
** ellipse's points are convex); holes promises nothing (-1).
*/
#include "gen_internal.h"

#include <math.h>

#define JITTER 0.2

wk_status wk_gen_ring_split(wk_run *R, const wk_gen_params *g, uint32_t *ring_size) {
    uint32_t n = g->n, H = g->holes;
    if (H >= WK_POLYGON_MAX_RINGS)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: holes=%u > %u", g->family, H,
                       WK_POLYGON_MAX_RINGS - 1);
    if ((uint64_t)n < 3 * (uint64_t)H + 3)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: n=%u < 3*holes+3=%llu", g->family, n,
                       3 * (unsigned long long)H + 3);
    if (H == 0) {
        ring_size[0] = n;
        return WK_OK;
    }
    uint32_t nh = n / 2;
    if (nh < 3 * H) nh = 3 * H;
    if (nh > n - 3) nh = n - 3;
    ring_size[0] = n - nh;
    for (uint32_t j = 0; j < H; j++) ring_size[1 + j] = nh / H + (j < nh % H ? 1 : 0);
    return WK_OK;
}

/* The smallest distance from the origin to an edge of the ring x, y [0..m). */
static double origin_clearance(const double *x, const double *y, uint32_t m) {
    double best = INFINITY;
    for (uint32_t i = 0; i < m; i++) {
        uint32_t j = i + 1 == m ? 0 : i + 1;
        double ax = x[i], ay = y[i], dx = x[j] - ax, dy = y[j] - ay;
        double len2 = dx * dx + dy * dy;
        double t = len2 > 0 ? -(ax * dx + ay * dy) / len2 : 0.0;
        if (t < 0) t = 0;
        if (t > 1) t = 1;
        double px = ax + t * dx, py = ay + t * dy, d = sqrt(px * px + py * py);
        if (d < best) best = d;
    }
    return best;
}

/* Outer ring, star-shaped: jittered angles, radii in [0.5, 1] R. */
static void outer_star(wk_rng *rng, uint32_t m, double *x, double *y) {
    double theta0 = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
    for (uint32_t i = 0; i < m; i++) {
        double t = theta0 + 2.0 * WK_GEN_PI * ((double)i + wk_rng_range(rng, -JITTER, JITTER)) / m;
        double q = WK_GEN_BOX * wk_rng_range(rng, 0.5, 1.0);
        x[i] = q * cos(t);
        y[i] = q * sin(t);
    }
}

/* Outer ring, convex: the convex family's ellipse (same draws). */
static void outer_ellipse(wk_rng *rng, uint32_t m, double *x, double *y) {
    double a = WK_GEN_BOX * wk_rng_range(rng, 0.6, 1.0);
    double b = WK_GEN_BOX * wk_rng_range(rng, 0.6, 1.0);
    double rot = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI), c = cos(rot), s = sin(rot);
    for (uint32_t i = 0; i < m; i++) {
        double t = 2.0 * WK_GEN_PI * ((double)i + wk_rng_range(rng, -JITTER, JITTER)) / m;
        double ex = a * cos(t), ey = b * sin(t);
        x[i] = c * ex - s * ey;
        y[i] = s * ex + c * ey;
    }
}

/* One hole of m vertices, clockwise, inside the disc (cx, cy, rh): convex
** (an ellipse with semi-axes 0.5..1 rh) or star-shaped (radii 0.35..1 rh). */
static void hole_ring(wk_rng *rng, bool convex, double cx, double cy, double rh, uint32_t m,
                      double *x, double *y) {
    double theta0 = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
    double a = rh, b = rh, c = 1.0, s = 0.0;
    if (convex) {
        a = rh * wk_rng_range(rng, 0.5, 1.0);
        b = rh * wk_rng_range(rng, 0.5, 1.0);
        double rot = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
        c = cos(rot);
        s = sin(rot);
    }
    for (uint32_t i = 0; i < m; i++) {
        double t = theta0 - 2.0 * WK_GEN_PI * ((double)i + wk_rng_range(rng, -JITTER, JITTER)) / m;
        double ex, ey;
        if (convex) {
            ex = a * cos(t);
            ey = b * sin(t);
        } else {
            double q = rh * wk_rng_range(rng, 0.35, 1.0);
            ex = q * cos(t);
            ey = q * sin(t);
        }
        x[i] = cx + c * ex - s * ey;
        y[i] = cy + s * ex + c * ey;
    }
}

/* The holes of ring_size[1..H] after the outer ring (ring_size[0] vertices
** at x, y), in disjoint discs inside D(0, 0.9 clearance).  kind: 0 every
** hole star-shaped, 1 every hole convex, 2 a coin flip per hole. */
static wk_status place_holes(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                             double *y, const uint32_t *ring_size, int kind) {
    uint32_t H = g->holes, m0 = ring_size[0];
    if (H == 0) return WK_OK;
    double d = origin_clearance(x, y, m0);
    if (!(d > 0))
        return WK_FAIL(R, WK_EALGO, NULL, 0, "generator bug: %s: outer ring clearance %g",
                       g->family, d);
    double rho = 0.9 * d, side = rho * sqrt(2.0); /* the inscribed square's side */
    uint64_t gr = (uint64_t)floor(sqrt((double)H));
    while (gr * gr < H) gr++;
    uint64_t cells = gr * gr, need = H;
    double cell = side / (double)gr, half = 0.5 * cell, lo = -0.5 * side;
    uint32_t v = m0, j = 0;
    for (uint64_t k = 0; k < cells && need > 0; k++) {
        if (wk_rng_below(rng, cells - k) >= need) continue;
        need--;
        double ux = lo + ((double)(k % gr) + 0.5) * cell;
        double uy = lo + ((double)(k / gr) + 0.5) * cell;
        double rh = half * wk_rng_range(rng, 0.3, 0.9);
        double slack = 0.95 * half - rh;
        double cx = ux + wk_rng_range(rng, -slack, slack);
        double cy = uy + wk_rng_range(rng, -slack, slack);
        bool convex = kind == 1 || (kind == 2 && wk_rng_below(rng, 2));
        uint32_t m = ring_size[1 + j++];
        hole_ring(rng, convex, cx, cy, rh, m, x + v, y + v);
        v += m;
    }
    return WK_OK;
}

wk_status wk_gen_holes(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                       uint32_t *ring_size, int64_t *r_out) {
    wk_status st = wk_gen_ring_split(R, g, ring_size);
    if (st != WK_OK) return st;
    if (g->r >= 0)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "holes: r=%lld cannot be chosen (r is random)",
                       (long long)g->r);
    if (wk_rng_below(rng, 2)) outer_ellipse(rng, ring_size[0], x, y);
    else outer_star(rng, ring_size[0], x, y);
    *r_out = -1;
    return place_holes(R, g, rng, x, y, ring_size, 2);
}

wk_status wk_gen_convex_holes(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                              double *y, uint32_t *ring_size, int64_t *r_out) {
    wk_status st = wk_gen_ring_split(R, g, ring_size);
    if (st != WK_OK) return st;
    int64_t r = (int64_t)g->n - ring_size[0];
    if ((st = wk_gen_fixed_r(R, g, r, "the hole vertices")) != WK_OK) return st;
    outer_ellipse(rng, ring_size[0], x, y);
    *r_out = r;
    return place_holes(R, g, rng, x, y, ring_size, 1);
}
