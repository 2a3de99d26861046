/*
** gen_crossing.c: the crossing family: Theta(r^2) crossings in the bisector
** arrangement with only r reflex vertices, the case that separates the
** arrangement-based variants (their cost grows with the crossings) from the
** others.
**
** Shape, in the box [0, S]^2 with S = 1000: the bottom wall carries qb =
** ceil(r/2) thin symmetric spikes pointing straight up, the left wall ql =
** floor(r/2) spikes pointing right; the top and right sides are replaced by
** a convex arc from (S, 0) to (0, S) through p >= 1 padding vertices on the
** circle through the square's four corners (p = 1 gives the square itself).
** Vertices: 3 per spike (two base corners, convex; the tip, reflex) plus
** (0,0), (S,0), (0,S) and the arc: n = 3r + 3 + p, so n >= 3r + 4.
**
** Why the crossings are exact: a spike's tip is symmetric, so its unit-weight
** bisector is vertical (horizontal on the left wall).  Tips sit at x (or y)
** in [0.1 S, 0.9 S] and spikes are at most 0.03 S tall, so a vertical ray
** from a bottom tip passes right of every left spike and reaches the arc
** above y = S; likewise for the horizontal rays.  Each vertical ray thus
** crosses each horizontal one at (x_i, y_j) inside the square: qb * ql
** crossings, and parallel rays never cross.
*/
#include "gen_internal.h"

#include <math.h>

#define SIDE WK_GEN_BOX

/* Spikes on one wall: tip positions along the wall, half-widths and heights,
** one cell of the band [0.1 S, 0.9 S] each.  Tips are jittered within their
** cells by at most 0.3 cell and bases are 0.15 cell wide on each side, so
** neighbouring spikes keep at least 0.1 cell apart. */
typedef struct spike {
    double pos, half, height;
} spike;

static spike draw_spike(wk_rng *rng, uint32_t i, uint32_t q) {
    double cell = 0.8 * SIDE / q;
    spike s;
    s.pos = 0.1 * SIDE + cell * ((double)i + 0.5 + wk_rng_range(rng, -0.3, 0.3));
    s.half = 0.15 * cell;
    s.height = cell * wk_rng_range(rng, 0.5, 1.0);
    if (s.height > 0.03 * SIDE) s.height = 0.03 * SIDE;
    return s;
}

wk_status wk_gen_crossing(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                          int64_t *r_out) {
    uint32_t n = g->n;
    int64_t r = g->r >= 0 ? g->r : 2 * (((int64_t)n - 4) / 6);
    if (r < 0) r = 0;
    if (3 * r + 4 > (int64_t)n)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "crossing: n=%u < 3r+4=%lld (r=%lld)", n,
                       (long long)(3 * r + 4), (long long)r);
    uint32_t qb = (uint32_t)((r + 1) / 2), ql = (uint32_t)(r / 2);
    uint32_t p = n - 3 * (uint32_t)r - 3;

    uint32_t v = 0;
    x[v] = 0.0, y[v] = 0.0, v++;
    for (uint32_t i = 0; i < qb; i++) { /* bottom wall, left to right */
        spike s = draw_spike(rng, i, qb);
        x[v] = s.pos - s.half, y[v] = 0.0, v++;
        x[v] = s.pos, y[v] = s.height, v++;
        x[v] = s.pos + s.half, y[v] = 0.0, v++;
    }
    x[v] = SIDE, y[v] = 0.0, v++;
    /* The arc: angles strictly inside (-pi/4, 3pi/4) on the circle of radius
    ** S/sqrt(2) around (S/2, S/2), jittered by at most 0.2 of a step. */
    double half = 0.5 * SIDE, rad = SIDE / sqrt(2.0), step = WK_GEN_PI / (p + 1);
    for (uint32_t k = 0; k < p; k++) {
        double jit = p == 1 ? 0.0 : wk_rng_range(rng, -0.2, 0.2);
        double a = -0.25 * WK_GEN_PI + step * ((double)k + 1.0 + jit);
        x[v] = half + rad * cos(a), y[v] = half + rad * sin(a), v++;
    }
    if (p == 1) x[v - 1] = SIDE, y[v - 1] = SIDE; /* exactly the square */
    x[v] = 0.0, y[v] = SIDE, v++;
    for (uint32_t j = ql; j-- > 0;) { /* left wall, top to bottom */
        spike s = draw_spike(rng, j, ql);
        x[v] = 0.0, y[v] = s.pos + s.half, v++;
        x[v] = s.height, y[v] = s.pos, v++;
        x[v] = 0.0, y[v] = s.pos - s.half, v++;
    }
    *r_out = r;
    return WK_OK;
}
