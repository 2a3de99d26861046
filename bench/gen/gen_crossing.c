/*
** gen_crossing.c: the crossing family: Theta(r^2) crossings in the bisector
** arrangement with only r reflex vertices, the case that separates the
** arrangement-based variants (their cost grows with the crossings) from the
** others.
**
** Shape: the disc of radius R = S/2 around c = (S/2, S/2), S = 1000, with r
** thin spikes (wedges of the outside) reaching in from the circle.  Spike j
** (j = 0..r-1) has axis angle alpha_j = pi (j + U[-0.2, 0.2]) / M, M the
** smallest odd number >= r, turned by pi for odd j (phi_j = alpha_j +
** pi (j mod 2)): the even spikes fill the upper half of the circle, the odd
** ones the lower half, consecutive tip angles at least 1.6 pi/M apart, while
** the axis directions mod pi stay at least 0.6 pi/M apart.  The tip T_j lies
** at depth rho_j = R U[0.1, 0.9] along the axis, shifted sideways by
** d_j = U[-D, D], D = 0.05 rho0 sin(0.6 pi/M), rho0 = 0.1 R; its two sides
** leave T_j at angles +-beta_j from the outward axis and end on the circle
** (the base vertices), beta_j chosen so that the base spans the angle
** phi_j +- w, w = min(0.4 pi/M, 0.1).  Between consecutive spikes lie
** p = n - 3r >= 4 padding vertices on the circle, shared out in proportion
** to the gaps' angles (floor, the remainder one each to the first gaps),
** jittered by at most 0.2 of their step.  r = 0 is the jittered n-gon.
** The tips sit at strongly staggered depths, so their rays are crossed at
** different times; the arrangement variant meets a large share of the
** crossings as start events (bench/README.md, measured).
**
** Why simple and r exact: every circle vertex is listed by increasing angle
** (total below 2 pi); spike j lies in the sector phi_j +- 1.05 w (its base
** angles move off phi_j +- w by about d_j/R, its tip by d_j/rho_j), the
** sectors are disjoint (2.1 w < 1.6 pi/M) and each chord between circle
** vertices stays in its gap's sector.  A base vertex is convex: the tip is
** inside the disc and outside the cap cut off by the chord from the previous
** circle vertex.  A tip is reflex: it lies at radius <= 0.9 R, nearer the
** centre than the base chord (distance >= R cos(1.05 w) > 0.99 R).  The
** padding makes every gap step below 1.4 (pi/2), so chords stay more than
** R cos(0.7 pi/2) > 0.45 R from c.
**
** Why exactly r(r-1)/2 crossings (unit weights): the sides of a spike make
** equal angles with its axis, so T_j's bisector runs straight along the axis
** towards c, on the line at distance |d_j| <= D from c.  Until it enters the
** disc of radius rho0 (free of boundary: tips at >= rho0, chords at > 0.45 R)
** it stays within its own sector (angle off by < 2 D/rho0, far below w), so
** it crosses that disc entirely.  Two such lines meet at distance at most
** (|d_i| + |d_j|) / sin(0.6 pi/M) <= 0.1 rho0 from c, inside the disc and
** hence on both rays; lines meet only once.  So every pair of rays crosses,
** once, within 0.01 R of the centre.  All margins are fixed fractions of the
** local geometry (D of the angular step, w of the spike spacing), far above
** double rounding for n <= WK_GEN_N_MAX.
*/
#include "gen_internal.h"

#include <math.h>

#define SIDE WK_GEN_BOX

/* Angle of (px, py) around the centre, unwrapped to near ref. */
static double angle_near(double px, double py, double ref) {
    double a = atan2(py - 0.5 * SIDE, px - 0.5 * SIDE);
    while (a < ref - WK_GEN_PI) a += 2.0 * WK_GEN_PI;
    while (a > ref + WK_GEN_PI) a -= 2.0 * WK_GEN_PI;
    return a;
}

/* The point where the ray from (tx, ty) in direction (ux, uy) (unit) leaves
** the circle. */
static void to_circle(double tx, double ty, double ux, double uy, double rad, double *px,
                      double *py) {
    double qx = tx - 0.5 * SIDE, qy = ty - 0.5 * SIDE;
    double b = qx * ux + qy * uy, cc = qx * qx + qy * qy - rad * rad;
    double t = -b + sqrt(b * b - cc);
    *px = tx + t * ux, *py = ty + t * uy;
}

wk_status wk_gen_crossing(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                          int64_t *r_out) {
    uint32_t n = g->n;
    int64_t r = g->r >= 0 ? g->r : 2 * (((int64_t)n - 4) / 6);
    if (r < 0) r = 0;
    if (3 * r + 4 > (int64_t)n)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "crossing: n=%u < 3r+4=%lld (r=%lld)", n,
                       (long long)(3 * r + 4), (long long)r);
    double half = 0.5 * SIDE, rad = 0.5 * SIDE;
    *r_out = r;
    if (r == 0) {
        for (uint32_t i = 0; i < n; i++) {
            double a = 2.0 * WK_GEN_PI * ((double)i + wk_rng_range(rng, -0.2, 0.2)) / n;
            x[i] = half + rad * cos(a), y[i] = half + rad * sin(a);
        }
        return WK_OK;
    }
    uint32_t q = (uint32_t)r, M = q % 2 ? q : q + 1, p = n - 3 * q;
    double w = 0.4 * WK_GEN_PI / M, rho0 = 0.1 * rad;
    if (w > 0.1) w = 0.1;
    double D = 0.05 * rho0 * sin(0.6 * WK_GEN_PI / M);

    /* Pass 1: the spikes, in angular order (even j, then odd j), each as its
    ** three vertices at x[3s..3s+2], y[...]. */
    uint32_t s = 0;
    for (uint32_t par = 0; par < 2; par++)
        for (uint32_t j = par; j < q; j += 2, s++) {
            double phi = WK_GEN_PI * ((double)j + wk_rng_range(rng, -0.2, 0.2)) / M +
                         WK_GEN_PI * par;
            double d = wk_rng_range(rng, -D, D), rho = rad * wk_rng_range(rng, 0.1, 0.9);
            double ox = cos(phi), oy = sin(phi), nx = -oy, ny = ox;
            double tx = half + rho * ox + d * nx, ty = half + rho * oy + d * ny;
            /* beta: the sides of a centred tip would end at phi +- w */
            double beta = atan2(rad * sin(w), rad * cos(w) - rho);
            double cb = cos(beta), sb = sin(beta);
            to_circle(tx, ty, cb * ox - sb * nx, cb * oy - sb * ny, rad, &x[3 * s], &y[3 * s]);
            x[3 * s + 1] = tx, y[3 * s + 1] = ty;
            to_circle(tx, ty, cb * ox + sb * nx, cb * oy + sb * ny, rad, &x[3 * s + 2],
                      &y[3 * s + 2]);
        }

    /* Pass 2, from the back so nothing is overwritten before it is read:
    ** spike s moves to its final place, followed by its gap's padding. */
    double gsum = 0.0;
    for (uint32_t k = 0; k < q; k++) {
        uint32_t k1 = (k + 1) % q;
        double b = angle_near(x[3 * k + 2], y[3 * k + 2], 0.0);
        double a = angle_near(x[3 * k1], y[3 * k1], b + WK_GEN_PI);
        if (a <= b) a += 2.0 * WK_GEN_PI;
        gsum += a - b;
    }
    uint32_t given = 0;
    for (uint32_t k = 0; k < q; k++) {
        uint32_t k1 = (k + 1) % q;
        double b = angle_near(x[3 * k + 2], y[3 * k + 2], 0.0);
        double a = angle_near(x[3 * k1], y[3 * k1], b + WK_GEN_PI);
        if (a <= b) a += 2.0 * WK_GEN_PI;
        given += (uint32_t)floor(p * ((a - b) / gsum));
    }
    uint32_t extra = p - given; /* < q: each floor lost less than one */
    uint32_t end = n;
    for (uint32_t k = q; k-- > 0;) {
        uint32_t k1 = (k + 1) % q;
        /* k1's vertices may already have moved (k1 = 0 has not: it is last) */
        double ax = k1 == 0 ? x[0] : x[end], ay = k1 == 0 ? y[0] : y[end];
        double b = angle_near(x[3 * k + 2], y[3 * k + 2], 0.0);
        double a = angle_near(ax, ay, b + WK_GEN_PI);
        if (a <= b) a += 2.0 * WK_GEN_PI;
        uint32_t c = (uint32_t)floor(p * ((a - b) / gsum)) + (k < extra ? 1u : 0u);
        double step = (a - b) / (c + 1);
        double sx[3] = {x[3 * k], x[3 * k + 1], x[3 * k + 2]};
        double sy[3] = {y[3 * k], y[3 * k + 1], y[3 * k + 2]};
        for (uint32_t i = c; i-- > 0;) { /* padding, last first */
            double t = b + step * ((double)i + 1.0 + wk_rng_range(rng, -0.2, 0.2));
            end--;
            x[end] = half + rad * cos(t), y[end] = half + rad * sin(t);
        }
        for (uint32_t i = 3; i-- > 0;) end--, x[end] = sx[i], y[end] = sy[i];
    }
    (void)end; /* 0 now */
    return WK_OK;
}
