/*
** gen_coastline.c: the coastline family: a random Koch-like fractal curve
** closed into a simple polygon, about half of its vertices reflex, in O(n)
** time and n + O(1) bytes beyond the coordinates, simple by construction.
**
** Construction.  Start from a regular k0-gon (k0 = 4..7 from the seed,
** k0 = n below 4) of radius R0 with a seeded rotation; then, as long as
** 4 E <= n (E the current edge count), replace every edge a -> b by the
** Koch motif a -> p -> q -> r -> b; a last, partial level gives each edge
** 1, 2, 3 or 4 children (the extra n - E vertices shared out evenly, the
** remainder one each to a seeded subset of the edges), so the polygon has
** exactly n vertices.
**
** Local coordinates of an edge: a = (0, 0), b = (1, 0), the point (X, Y)
** is a + X (b - a) + Y (b - a) turned left by 90 degrees (the left side is
** the inside: the polygon is counter-clockwise).  With s = +-1 from the
** seed (the side of the bump) and alpha1, alpha2 uniform in [0.25, 0.33]:
**
**     p = (alpha1, 0),  q = (1/2, s h),  r = (1 - alpha2, 0),
**     h = u hmax,  u uniform in [0.3, 1],
**     hmax = 0.95 min over alpha in {alpha1, alpha2} of
**            min(alpha sin 2 theta, (1/2 - alpha) / tan theta, tan theta / 2).
**
** The partial level's motifs: 1 child, the edge itself; 2 children,
** a -> m -> b with m = (U[0.4, 0.6], s U[0.1, 0.3]); 3 children,
** a -> p -> q -> b with p = (1/3, s U[0.08, 0.25]), q = (2/3, -s U[0.08,
** 0.25]); 4 children, the Koch motif.
**
** Why simple.  Give every edge ab the region D(ab), the rhombus with
** diagonal ab and half-angle theta = 40 degrees at a and b (in local
** coordinates |Y| <= t min(X, 1 - X), t = tan theta).  Invariant at every
** full level: the regions of the current edges have pairwise disjoint
** interiors, and two of them meet only in a common endpoint of their edges
** or along boundary pieces that the later curve never reaches.
**   Start: the region of each edge of the regular k0-gon lies in the
** sector (the cone from the centre through its two vertices): at a vertex
** the edge makes the angle pi/2 - pi/k0 >= 45 degrees > theta with the ray
** to the centre.  The sectors are disjoint.
**   Koch step (in local coordinates of the parent):
**   - D(ap) is D(ab) scaled by alpha1 from a (p lies on ab), so inside
**     D(ab); D(rb) likewise;
**   - D(pq) lies in D(ab) and in X <= 1/2: its vertices are p, q and the
**     two apexes mid(pq) +- (t/2) (-h, 1/2 - alpha1); X <= 1/2 for both
**     is t h <= 1/2 - alpha1, and |Y| <= t X for the upper apex is
**     h <= alpha1 sin 2 theta (the lower one holds for any h <= 2.8, q for
**     h < t/2): the three terms of hmax, with 5% to spare.  D(qr) is the
**     mirror image in X >= 1/2;
**   - so D(pq) and D(qr) meet only in q, D(ap) (in X <= alpha1 < 1/2) and
**     D(rb) miss D(qr) and D(pq) respectively, D(ap) and D(rb) are apart;
**     D(ap) and D(pq) share the vertex p, where their cones (directions
**     pi +- theta and phi +- theta, phi = atan(h/(1/2 - alpha1)) in
**     (0, pi/2)) are disjoint because phi + theta < pi - theta; two
**     convex sets in disjoint convex cones at a common apex are separated
**     by a line through it.
**   The step keeps the direction of the curve at a and b (the first and
** last children lie along ab), so a vertex's turn is fixed when it is made,
** and the cones at every vertex stay as they were.
**   Partial level: each child lies inside its parent's region and leaves
** its boundary only at a and b (the new vertices are interior points of
** the convex region); the 2- and 3-child motifs are simple (for 3, ap in
** X <= 1/3 and qb in X >= 2/3), the 4-child motif is the Koch step.
**   So every edge of the final polygon lies in the interior of one region
** but for its endpoints, and two edges meet only at a shared vertex.  The
** margins are fixed fractions of the local edge length (a child is at
** least 0.17 of its parent, so the shortest edges are about 10^-8 R0 at
** n = 10^7 and the margins 10^6 times the rounding of coordinates of
** magnitude 1000); wk_generate's exact check stays the authority.  The turns
** the Koch motif makes are 13 to 49 degrees at p and r, 31 to 97 at q; the
** partial level turns the curve at a and b by at most 37 degrees, inside
** the 40-degree cones, so no vertex comes near a needle.
**
** Reflex vertices: a Koch motif with s = +1 bumps inward (q reflex, p and r
** convex), with s = -1 outward (p and r reflex, q convex); the 2-child
** motif's m is reflex for s = +1, the 3-child motif makes one reflex and one
** convex vertex.  With s a fair coin, r is about (n - k0)/2 (measured:
** bench/README.md); the family reports r = -1 (whatever comes out).
**
** Box: R0 = 1000 / (cos(pi/k0) + t sin(pi/k0)), so every region, hence the
** polygon, lies in the disc of radius 1000.  The coarse polygon goes
** through sin/cos (last-bit platform differences, as for star).
*/
#include "gen_internal.h"

#include <math.h>

#define THETA_TAN 0.83909963117728 /* tan 40 degrees */
#define THETA_SIN2 0.98480775301221 /* sin 80 degrees */
#define ALPHA_LO 0.25
#define ALPHA_HI 0.33

/* The point (X, Y) in the local coordinates of a -> b. */
static void local_point(double ax, double ay, double bx, double by, double X, double Y,
                        double *px, double *py) {
    double ux = bx - ax, uy = by - ay;
    *px = ax + X * ux - Y * uy;
    *py = ay + X * uy + Y * ux;
}

static double h_bound(double alpha) {
    double h = alpha * THETA_SIN2, h2 = (0.5 - alpha) / THETA_TAN, h3 = 0.5 * THETA_TAN;
    if (h2 < h) h = h2;
    if (h3 < h) h = h3;
    return h;
}

/* The new vertices (c - 1 of them, c in 2..4) of edge a -> b into
** px[0..c-1), py[0..c-1). */
static void motif(wk_rng *rng, uint32_t c, double ax, double ay, double bx, double by,
                  double *px, double *py) {
    double s = wk_rng_below(rng, 2) ? 1.0 : -1.0;
    if (c == 2) {
        double X = wk_rng_range(rng, 0.4, 0.6), Y = s * wk_rng_range(rng, 0.1, 0.3);
        local_point(ax, ay, bx, by, X, Y, &px[0], &py[0]);
    } else if (c == 3) {
        double y1 = s * wk_rng_range(rng, 0.08, 0.25), y2 = -s * wk_rng_range(rng, 0.08, 0.25);
        local_point(ax, ay, bx, by, 1.0 / 3.0, y1, &px[0], &py[0]);
        local_point(ax, ay, bx, by, 2.0 / 3.0, y2, &px[1], &py[1]);
    } else {
        double a1 = wk_rng_range(rng, ALPHA_LO, ALPHA_HI), a2 = wk_rng_range(rng, ALPHA_LO, ALPHA_HI);
        double hmax = h_bound(a1), hb = h_bound(a2);
        if (hb < hmax) hmax = hb;
        double h = 0.95 * hmax * wk_rng_range(rng, 0.3, 1.0);
        local_point(ax, ay, bx, by, a1, 0.0, &px[0], &py[0]);
        local_point(ax, ay, bx, by, 0.5, s * h, &px[1], &py[1]);
        local_point(ax, ay, bx, by, 1.0 - a2, 0.0, &px[2], &py[2]);
    }
}

/* Replace each of the E edges of x, y (a closed ring) by count(i) children,
** in place: edge i's vertices go to x[off_i ..), off_i the sum of the
** earlier counts; cnt NULL means 4 each.  Edges are done from the last to
** the first, so edge i reads x[i] and x[i + 1] before anything is written
** there (every write lands at or beyond off_j >= j, and off_{i+1} = i + 1
** rewrites x[i+1] with itself). */
static void expand(wk_rng *rng, double *x, double *y, uint32_t E, const uint8_t *cnt,
                   uint32_t total) {
    uint32_t off = total;
    for (uint32_t k = E; k-- > 0;) {
        uint32_t c = cnt ? cnt[k] : 4;
        double ax = x[k], ay = y[k];
        double bx = x[k + 1 == E ? 0 : k + 1], by = y[k + 1 == E ? 0 : k + 1];
        off -= c;
        double px[3], py[3];
        if (c > 1) motif(rng, c, ax, ay, bx, by, px, py);
        x[off] = ax;
        y[off] = ay;
        for (uint32_t j = 1; j < c; j++) {
            x[off + j] = px[j - 1];
            y[off + j] = py[j - 1];
        }
    }
}

wk_status wk_gen_coastline(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                           int64_t *r_out) {
    if (g->r >= 0)
        return WK_FAIL(R, WK_EINPUT, NULL, 0,
                       "coastline: r cannot be chosen (about n/2 come out; use star, notched or "
                       "monotone for a given r)");
    uint32_t n = g->n;
    uint32_t k0 = 4 + (uint32_t)wk_rng_below(rng, 4);
    if (k0 > n) k0 = n < 4 ? n : 4;
    double step = 2.0 * WK_GEN_PI / k0, theta0 = wk_rng_range(rng, 0.0, 2.0 * WK_GEN_PI);
    double R0 = WK_GEN_BOX / (cos(0.5 * step) + THETA_TAN * sin(0.5 * step));
    for (uint32_t i = 0; i < k0; i++) {
        x[i] = R0 * cos(theta0 + step * i);
        y[i] = R0 * sin(theta0 + step * i);
    }
    uint32_t E = k0;
    while ((uint64_t)E * 4 <= n) {
        expand(rng, x, y, E, NULL, 4 * E);
        E *= 4;
    }
    if (E < n) {
        uint8_t *cnt = WK_NEW_ARRAY(R, uint8_t, E);
        if (!cnt) return WK_ENOMEM;
        uint32_t extra = n - E, q = extra / E, need = extra % E;
        for (uint32_t i = 0; i < E; i++) {
            uint32_t more = 0;
            if (need > 0 && wk_rng_below(rng, E - i) < need) {
                need--;
                more = 1;
            }
            cnt[i] = (uint8_t)(1 + q + more);
        }
        expand(rng, x, y, E, cnt, n);
        WK_FREE_ARRAY(R, cnt, E);
    }
    *r_out = -1;
    return WK_OK;
}
