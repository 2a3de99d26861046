/*
** offset_standin.c: TEMPORARY stand-in for the engine's wk_offset, compiled
** into the Python module only while engine/offset.c does not exist (see the
** Makefile's python target and offset_standin.h).  Not shipped once the
** engine's own implementation is merged.
**
** Domain: convex polygons without holes (P->r == 0, one ring); anything
** else is WK_EUNSUPPORTED, never a wrong answer.  There the wavefront at
** time t is the intersection of the half-planes {q : dist(q, line e) >=
** w[e] t} on the inner side of every edge e, computed by clipping the
** polygon with each half-plane in turn (Sutherland-Hodgman: a convex
** polygon stays convex and gains at most one vertex per clip).  The
** skeleton is not needed for that; the argument is kept for the API.
** Result: one component with one counter-clockwise ring, or no component
** once the clipped area is no longer positive (t at or past the collapse).
*/
#include <math.h>

#include "offset_standin.h"

/* Clip the convex ring in[0..n) by {q : (q - a) . nrm >= d}; returns the
** vertex count written to out (capacity n + 1 suffices). */
static uint32_t clip(const wk_point *in, uint32_t n, wk_point a, wk_point nrm, double d,
                     wk_point *out) {
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++) {
        wk_point p = in[i], q = in[(i + 1) % n];
        double sp = (p.x - a.x) * nrm.x + (p.y - a.y) * nrm.y - d;
        double sq = (q.x - a.x) * nrm.x + (q.y - a.y) * nrm.y - d;
        if (sp >= 0) out[m++] = p;
        if ((sp >= 0) != (sq >= 0)) {
            double u = sp / (sp - sq);
            out[m++] = (wk_point){p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)};
        }
    }
    return m;
}

wk_status wk_offset(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double t,
                    wk_offset_set **out) {
    (void)S; /* the half-plane intersection needs no skeleton */
    *out = NULL;
    if (!(t >= 0) || !isfinite(t))
        return WK_FAIL(R, WK_EUSAGE, P->name, 0, "offset time must be finite and >= 0 (got %g)", t);
    if (P->n_rings != 1 || P->r != 0)
        return WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                       "the offset stand-in (python/wskel/offset_standin.c) handles convex "
                       "polygons without holes only (this one has %u reflex vertices, %u holes)",
                       P->r, P->n_rings - 1);
    uint32_t cap = 2 * P->n + 2;
    wk_point *a = WK_NEW_ARRAY(R, wk_point, cap), *b = WK_NEW_ARRAY(R, wk_point, cap);
    wk_offset_set *O = WK_NEW_ARRAY(R, wk_offset_set, 1);
    wk_status st = WK_OK;
    uint32_t m = P->n;
    bool alive = false;
    if (!a || !b || !O) {
        st = WK_ENOMEM;
        goto done;
    }
    for (uint32_t i = 0; i < m; i++) a[i] = P->p[i];
    for (uint32_t e = 0; e < P->n && m >= 3; e++) {
        wk_point p = P->p[e], q = P->p[wk_polygon_next(P, e)];
        double len = hypot(q.x - p.x, q.y - p.y);
        wk_point nrm = {-(q.y - p.y) / len, (q.x - p.x) / len}; /* inward: P is CCW */
        m = clip(a, m, p, nrm, P->w[e] * t, b);
        wk_point *tmp = a;
        a = b;
        b = tmp;
    }
    double area2 = m >= 3 ? wk_shoelace_exact(a, m) : 0;
    alive = area2 > 0;
    O->t = t;
    O->n_polygons = alive ? 1 : 0;
    O->n_rings = alive ? 1 : 0;
    O->polygon_start = WK_NEW_ARRAY(R, uint32_t, O->n_polygons + 1);
    O->ring_start = WK_NEW_ARRAY(R, uint32_t, O->n_rings + 1);
    O->p = WK_NEW_ARRAY(R, wk_point, alive ? m : 0);
    if (!O->polygon_start || !O->ring_start || !O->p) {
        st = WK_ENOMEM;
        goto done;
    }
    if (alive) {
        O->polygon_start[1] = 1;
        O->ring_start[1] = m;
        for (uint32_t i = 0; i < m; i++) O->p[i] = a[i];
    }
done:
    WK_FREE_ARRAY(R, a, cap);
    WK_FREE_ARRAY(R, b, cap);
    if (st != WK_OK) {
        /* Freed with the sizes they were allocated with (ring_start is not
        ** filled in yet, so wk_offset_set_free could not tell p's). */
        if (O) {
            uint32_t np = O->n_polygons, nr = O->n_rings, npts = alive ? m : 0;
            if (O->p) WK_FREE_ARRAY(R, O->p, npts);
            if (O->ring_start) WK_FREE_ARRAY(R, O->ring_start, nr + 1);
            if (O->polygon_start) WK_FREE_ARRAY(R, O->polygon_start, np + 1);
            WK_FREE_ARRAY(R, O, 1);
        }
        return st;
    }
    *out = O;
    return WK_OK;
}

void wk_offset_set_free(wk_run *R, wk_offset_set *O) {
    if (!O) return;
    /* Sizes are read before the arrays they live in go. */
    uint32_t n_points = O->ring_start ? O->ring_start[O->n_rings] : 0;
    if (O->p) WK_FREE_ARRAY(R, O->p, n_points);
    if (O->ring_start) WK_FREE_ARRAY(R, O->ring_start, O->n_rings + 1);
    if (O->polygon_start) WK_FREE_ARRAY(R, O->polygon_start, O->n_polygons + 1);
    WK_FREE_ARRAY(R, O, 1);
}
