/*
** offset.c: the wavefront at time t as polygons with holes (wk_offset,
** contract in wskel.h).
**
** The roof T of a skeleton is linear on each face (T = d(x, e) / w(e) in
** edge e's face) and linear along each arc between its nodes' times.  The
** offset at t is the boundary of {T > t}:
**   1. An arc is crossed when exactly one of its nodes is above t (node
**      time > t; a node at exactly t counts as below, so the result is the
**      limit from above and t = 0 crosses each input vertex's arc at the
**      vertex itself).  Its offset vertex is interpolated by time from the
**      lower node, the same computation for both faces of the arc, so the
**      two faces see one point.
**   2. Walking face f with the face on the left (arc a -> b has face `left`
**      on its left), an arc crossed upwards (a below, b above) is where the
**      walk enters {T > t}; the offset segment in f, directed along f's edge
**      (region above on its left), ends there (U).  Crossed downwards it
**      starts there (D).  So the left face of an up-crossed arc sees U, the
**      right face D, and the reverse for a down-crossed arc: every crossed
**      arc starts one segment and ends one.
**   3. In each face the crossings sorted along the edge's direction
**      alternate D, U, D, U (the offset line enters and leaves the face;
**      islands' loops are arcs labelled f too, so they take part); pairing
**      them gives the segments, next[D arc] = U arc.  Near-ties that the sort
**      got out of order are repaired within WK_OFFSET_TIE_REL * scale
**      (tolerance.h); beyond that the face fails with WK_EALGO.
**   4. next[] is a permutation of the crossed arcs; its cycles are the
**      rings, counter-clockwise around components and clockwise around
**      holes (the region above is always on the left).
**   5. A hole ring belongs to the outer ring of least area that contains it
**      (components can nest: an offset part inside another part's hole),
**      decided by exact point-in-ring tests on a hole vertex.
** A PSLG's offset is the region swept, {T < t} (wskel.h): a node at t
** counts as not yet passed (above()), and each ring is reversed after
** step 4 so that the swept region lies on its left; steps 5 and 6 then
** nest the rings as for a polygon.  Stored edges are read through their
** directions (wk_polygon_edge_dir), since a PSLG's caps have length 0.
** Tolerance: crossing points are interpolated in double from nodes that the
** skeleton placed within its own error (a few eps_d), so offset vertices
** carry that error and no more; every topological decision (which arc is
** crossed) compares stored node times with t exactly, so the rings are
** always closed and consistent whatever the rounding.
*/
#include "faces.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct crossing_ref {
    double u;      /* position along the face's edge direction */
    uint32_t arc;  /* the crossed arc's crossing index */
    uint32_t up;   /* 1: U (segment ends here), 0: D (segment starts here) */
} crossing_ref;

/* Total order: u, then U before D (two crossings at one point where the
** line touches the boundary from outside: a segment ends before the next
** begins), then index. */
static int ref_cmp(const void *pa, const void *pb) {
    const crossing_ref *a = pa, *b = pb;
    if (a->u != b->u) return a->u < b->u ? -1 : 1;
    if (a->up != b->up) return a->up ? -1 : 1;
    return (a->arc > b->arc) - (a->arc < b->arc);
}

double wk_offset_ring_area(const wk_offset_set *O, uint32_t k) {
    return 0.5 * wk_shoelace_exact(O->p + O->ring_start[k], O->ring_start[k + 1] - O->ring_start[k]);
}

void wk_offset_set_free(wk_run *R, wk_offset_set *O) {
    if (!O) return;
    WK_FREE_ARRAY(R, O->p, O->ring_start ? O->ring_start[O->n_rings] : 0);
    WK_FREE_ARRAY(R, O->ring_start, (size_t)O->n_rings + 1);
    WK_FREE_ARRAY(R, O->polygon_start, (size_t)O->n_polygons + 1);
    WK_FREE_ARRAY(R, O, 1);
}

/* Pair face f's crossings refs[0..m) (sorted) into segments: next[D] = U. */
static wk_status pair_face(wk_run *R, const wk_polygon *P, uint32_t f, crossing_ref *refs,
                           uint32_t m, double tie, uint32_t *next) {
    for (uint32_t i = 0; i < m; i++) {
        uint32_t want = i & 1; /* D at even positions, U at odd */
        if (refs[i].up != want) {
            uint32_t j = i + 1;
            while (j < m && refs[j].up != want && refs[j].u - refs[i].u <= tie) j++;
            if (j == m || refs[j].up != want || refs[j].u - refs[i].u > tie)
                return WK_FAIL(R, WK_EALGO, P->name, 0,
                               "offset: the crossings of face %u's offset line with its boundary "
                               "do not alternate (at %.17g along the edge)",
                               wk_polygon_input_edge(P, f), refs[i].u);
            crossing_ref r = refs[j];
            memmove(refs + i + 1, refs + i, (size_t)(j - i) * sizeof *refs);
            refs[i] = r;
        }
        if (want) next[refs[i - 1].arc] = refs[i].arc;
    }
    return WK_OK;
}

/* Exact point in ring: +1 inside, -1 outside, 0 on the boundary. */
static int ring_side(wk_point q, const wk_point *p, uint32_t n) {
    int inside = 0;
    for (uint32_t i = 0, j = n - 1; i < n; j = i++) {
        wk_point a = p[j], b = p[i];
        if (wk_segments_meet(a, b, q, q) != WK_SEG_DISJOINT) return 0;
        if ((a.y > q.y) != (b.y > q.y)) {
            /* the edge crosses q's horizontal: is the crossing right of q? */
            int o = wk_orient2d(a, b, q, NULL);
            if ((b.y > a.y) ? o > 0 : o < 0) inside = !inside;
        }
    }
    return inside ? 1 : -1;
}

typedef struct ring_info {
    uint32_t start, len;  /* in the ring vertex scratch */
    double area;          /* signed */
    wk_point lo, hi;      /* bounding box */
    uint32_t parent;      /* holes: the outer ring's index; outer: WK_NONE */
    uint32_t comp;        /* the component's index */
    uint32_t slot;        /* position in the output */
} ring_info;

/* Has the wavefront not yet passed node v at time t?  A polygon's offset is
** the region ahead of the wavefront, {T > t}: a node at exactly t is
** passed (the limit from above).  A PSLG's is the region swept, {T < t}
** within the horizon: a node at exactly t is not passed yet (the limit from
** below), so t = 0 gives nothing and t = T the wavefront at T, its cap. */
static bool above(const wk_polygon *P, const wk_node *v, double t) {
    return P->pslg ? v->t >= t : v->t > t;
}

wk_status wk_offset(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double t,
                    wk_offset_set **out) {
    *out = NULL;
    if (!(t >= 0) || !isfinite(t))
        return WK_FAIL(R, WK_EINPUT, P->name, 0, "offset time must be a finite number >= 0 (got %g)",
                       t);
    if (P->pslg && t > S->horizon)
        return WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                       "offset time %g is beyond the horizon t = %.17g up to which the PSLG's "
                       "skeleton was computed (--until)",
                       t, S->horizon);
    if (wk_faces_check_ids(R, P, S, "offset: ") != WK_OK) return R->err.code;
    const uint32_t A = S->n_arcs, n = P->n;
    uint32_t *xid = NULL, *fstart = NULL, *next = NULL, *order = NULL;
    wk_point *xp = NULL, *rp = NULL;
    crossing_ref *refs = NULL;
    ring_info *rings = NULL;
    uint8_t *seen = NULL;
    wk_offset_set *O = NULL;
    uint32_t m = 0, n_rings = 0, nv = 0, cap_rings = 0, n_outer = 0;
    wk_status st = WK_OK;

    /* 1. crossed arcs and their points */
    if (!(xid = WK_NEW_ARRAY(R, uint32_t, A ? A : 1))) goto fail;
    for (uint32_t i = 0; i < A; i++) {
        const wk_arc *c = &S->arcs[i];
        bool a_up = above(P, &S->nodes[c->a], t), b_up = above(P, &S->nodes[c->b], t);
        xid[i] = a_up != b_up ? m++ : WK_NONE;
    }
    if (!(xp = WK_NEW_ARRAY(R, wk_point, m ? m : 1)) || !(next = WK_NEW_ARRAY(R, uint32_t, m ? m : 1)) ||
        !(fstart = WK_NEW_ARRAY(R, uint32_t, (size_t)n + 2)) ||
        !(refs = WK_NEW_ARRAY(R, crossing_ref, 2 * (size_t)m + 1)))
        goto fail;
    for (uint32_t i = 0; i < A; i++) {
        if (xid[i] == WK_NONE) continue;
        const wk_arc *c = &S->arcs[i];
        const wk_node *lo = &S->nodes[c->a], *hi = &S->nodes[c->b];
        if (lo->t > hi->t) {
            const wk_node *s = lo;
            lo = hi;
            hi = s;
        }
        double k = (t - lo->t) / (hi->t - lo->t); /* in [0, 1), a PSLG's (0, 1] */
        xp[xid[i]] = (wk_point){lo->x + k * (hi->x - lo->x), lo->y + k * (hi->y - lo->y)};
        if (c->left == WK_NONE || c->right == WK_NONE) { /* defensive: a cap lies at T */
            st = WK_FAIL(R, WK_EALGO, P->name, 0, "offset: cap arc %u crosses t = %g", i, t);
            goto done;
        }
        fstart[c->left + 2]++;
        fstart[c->right + 2]++;
        next[xid[i]] = WK_NONE;
    }

    /* 2. bucket by face (fstart[f + 1] is the fill cursor, then the end) */
    for (uint32_t f = 0; f < n; f++) fstart[f + 2] += fstart[f + 1];
    for (uint32_t i = 0; i < A; i++) {
        if (xid[i] == WK_NONE) continue;
        const wk_arc *c = &S->arcs[i];
        uint32_t up = above(P, &S->nodes[c->b], t); /* a -> b goes up */
        uint32_t face[2] = {c->left, c->right};
        for (int s = 0; s < 2; s++) {
            uint32_t f = face[s];
            wk_point p = P->p[f], d = wk_polygon_edge_dir(P, f);
            double dx = d.x, dy = d.y;
            double u = (xp[xid[i]].x - p.x) * dx + (xp[xid[i]].y - p.y) * dy; /* times |e| */
            refs[fstart[f + 1]++] = (crossing_ref){u, xid[i], s == 0 ? up : !up};
        }
    }

    /* 3. pair within each face */
    double scale = wk_polygon_scale(P);
    for (uint32_t f = 0; f < n; f++) {
        uint32_t k = fstart[f + 1] - fstart[f];
        if (!k) continue;
        wk_point d = wk_polygon_edge_dir(P, f);
        double len = hypot(d.x, d.y);
        qsort(refs + fstart[f], k, sizeof *refs, ref_cmp);
        if ((st = pair_face(R, P, f, refs + fstart[f], k, WK_OFFSET_TIE_REL * scale * len,
                            next)) != WK_OK)
            goto done;
    }
    for (uint32_t i = 0; i < m; i++)
        if (next[i] == WK_NONE) { /* defensive: every crossed arc starts one segment */
            st = WK_FAIL(R, WK_EALGO, P->name, 0, "offset: crossing %u starts no segment", i);
            goto done;
        }

    /* 4. rings: cycles of next[], repeated points merged */
    if (!(seen = WK_NEW_ARRAY(R, uint8_t, m ? m : 1)) || !(rp = WK_NEW_ARRAY(R, wk_point, m ? m : 1)))
        goto fail;
    for (uint32_t s = 0; s < m; s++) {
        if (seen[s]) continue;
        uint32_t start = nv;
        for (uint32_t i = s; !seen[i]; i = next[i]) {
            seen[i] = 1;
            if (nv > start && rp[nv - 1].x == xp[i].x && rp[nv - 1].y == xp[i].y) continue;
            rp[nv++] = xp[i];
        }
        while (nv - start > 1 && rp[nv - 1].x == rp[start].x && rp[nv - 1].y == rp[start].y) nv--;
        uint32_t len = nv - start;
        if (P->pslg) /* the swept region on the left, not the region ahead */
            for (uint32_t a = start, b = nv - 1; a < b; a++, b--) {
                wk_point tmp = rp[a];
                rp[a] = rp[b];
                rp[b] = tmp;
            }
        double area = len >= 3 ? 0.5 * wk_shoelace_exact(rp + start, len) : 0;
        if (area == 0) {
            nv = start;
            continue;
        }
        if (n_rings == cap_rings && WK_GROW(R, rings, cap_rings, n_rings + 1) != WK_OK) goto fail;
        ring_info *ri = &rings[n_rings++];
        *ri = (ring_info){start, len, area, rp[start], rp[start], WK_NONE, 0, 0};
        for (uint32_t j = start; j < nv; j++) {
            ri->lo.x = fmin(ri->lo.x, rp[j].x);
            ri->lo.y = fmin(ri->lo.y, rp[j].y);
            ri->hi.x = fmax(ri->hi.x, rp[j].x);
            ri->hi.y = fmax(ri->hi.y, rp[j].y);
        }
    }

    /* 5. holes to their outer rings */
    for (uint32_t k = 0; k < n_rings; k++) {
        if (rings[k].area > 0) {
            n_outer++;
            continue;
        }
        ring_info *h = &rings[k];
        uint32_t best = WK_NONE;
        for (uint32_t o = 0; o < n_rings; o++) {
            const ring_info *c = &rings[o];
            if (!(c->area > 0) || (best != WK_NONE && c->area >= rings[best].area)) continue;
            if (h->lo.x < c->lo.x || h->lo.y < c->lo.y || h->hi.x > c->hi.x || h->hi.y > c->hi.y)
                continue;
            int side = 0;
            for (uint32_t j = 0; j < h->len && side == 0; j++)
                side = ring_side(rp[h->start + j], rp + c->start, c->len);
            if (side >= 0) best = o; /* all on the boundary: touching, counted as inside */
        }
        if (best == WK_NONE) { /* defensive: a hole ring outside every component */
            st = WK_FAIL(R, WK_EALGO, P->name, 0,
                         "offset: a clockwise ring of %u points at t = %g lies in no component",
                         h->len, t);
            goto done;
        }
        h->parent = best;
    }

    /* 6. output: components in order of their outer ring, each outer ring
    ** first, then its holes in ring order. */
    if (!(order = WK_NEW_ARRAY(R, uint32_t, (size_t)n_rings + 1)) ||
        !(O = WK_NEW_ARRAY(R, wk_offset_set, 1)))
        goto fail;
    O->t = t;
    if (!(O->polygon_start = WK_NEW_ARRAY(R, uint32_t, (size_t)n_outer + 1))) goto fail;
    O->n_polygons = n_outer;
    if (!(O->ring_start = WK_NEW_ARRAY(R, uint32_t, (size_t)n_rings + 1))) goto fail;
    O->n_rings = n_rings;
    if (!(O->p = WK_NEW_ARRAY(R, wk_point, nv))) goto fail;
    O->ring_start[n_rings] = nv; /* what wk_offset_set_free needs from here on */
    for (uint32_t k = 0, c = 0; k < n_rings; k++)
        if (rings[k].parent == WK_NONE) rings[k].comp = c++;
    for (uint32_t k = 0; k < n_rings; k++)
        if (rings[k].parent != WK_NONE) rings[k].comp = rings[rings[k].parent].comp;
    for (uint32_t k = 0; k < n_rings; k++) O->polygon_start[rings[k].comp + 1]++;
    for (uint32_t c = 0; c < n_outer; c++) O->polygon_start[c + 1] += O->polygon_start[c];
    /* order[c] (c < n_outer): the next free ring slot of component c */
    for (uint32_t c = 0; c < n_outer; c++) order[c] = O->polygon_start[c];
    for (uint32_t k = 0; k < n_rings; k++)
        if (rings[k].parent == WK_NONE) rings[k].slot = order[rings[k].comp]++;
    for (uint32_t k = 0; k < n_rings; k++)
        if (rings[k].parent != WK_NONE) rings[k].slot = order[rings[k].comp]++;
    for (uint32_t k = 0; k < n_rings; k++) order[rings[k].slot] = k; /* slot -> ring */
    for (uint32_t j = 0, pos = 0; j < n_rings; j++) {
        const ring_info *ri = &rings[order[j]];
        O->ring_start[j] = pos;
        memcpy(O->p + pos, rp + ri->start, (size_t)ri->len * sizeof *rp);
        pos += ri->len;
    }
    *out = O;
    O = NULL;
    goto done;

fail:
    st = R->err.code != WK_OK ? R->err.code : WK_ENOMEM;
done:
    if (O) { /* half-built: each array is NULL or allocated with the size its count says */
        if (O->ring_start) WK_FREE_ARRAY(R, O->p, O->ring_start[n_rings]);
        if (O->ring_start) WK_FREE_ARRAY(R, O->ring_start, (size_t)n_rings + 1);
        if (O->polygon_start) WK_FREE_ARRAY(R, O->polygon_start, (size_t)n_outer + 1);
        WK_FREE_ARRAY(R, O, 1);
    }
    WK_FREE_ARRAY(R, order, (size_t)n_rings + 1);
    WK_FREE_ARRAY(R, rings, cap_rings);
    WK_FREE_ARRAY(R, rp, m ? m : 1);
    WK_FREE_ARRAY(R, seen, m ? m : 1);
    WK_FREE_ARRAY(R, refs, 2 * (size_t)m + 1);
    WK_FREE_ARRAY(R, fstart, (size_t)n + 2);
    WK_FREE_ARRAY(R, next, m ? m : 1);
    WK_FREE_ARRAY(R, xp, m ? m : 1);
    WK_FREE_ARRAY(R, xid, A ? A : 1);
    return st;
}
