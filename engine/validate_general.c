/*
** validate_general.c: the validator for skeletons with weights of any sign
** or cut at a height (wk_options.height: the roof's cap), the path
** wk_validate takes when R->opt.height > 0 or a weight is <= 0; the checks
** of validate.c for positive weights are untouched.
**
** Checks, in this order (the first violation is WK_EINVALID, "validate
** (general x): ..."):
**   (a) input nodes: the first n nodes are the input vertices, t = 0;
**   (b) nodes: finite, 0 <= t <= H (within tol_t = tol / max |w|; H the
**       height, unbounded without one);
**   (c) arcs: node ids valid, a != b; each side an edge (< n) or WK_NONE
**       (the cap), not both the cap, left != right; at both ends v and for
**       each side e that is an edge, |d_e(v) - w(e) t_v| <= tol with d_e
**       the signed distance from e's supporting line, positive inside (so
**       the nodes of an outward edge, w < 0, lie outside P, and those of a
**       wall, w = 0, on its line); an arc with a cap side has both ends at
**       t = H, and there is no cap without a height;
**   (d) closure: for each edge e, the arcs with e on a side plus the input
**       edge e form closed walks (every node has even degree in them), and
**       so do the cap's arcs;
**   (e) no self-crossing: within each face (its arcs and its edge, in the
**       face's own plane: (x, y) for w(e) != 0, where the plane is a graph
**       over the xy plane; (position along e, |w|max t) for a wall) and
**       within the cap (xy at t = H), no two sides that share no node
**       cross or overlap by more than tol (a crossing within tol of an end
**       is rounding; a face that has moved at most tol, an edge swept at
**       once by the collinear rule at t = 0, may fold back along its edge).
** What this proves: every node of face e lies on e's plane (the plane
** through e rising with slope 1/w(e), vertical for w = 0), so each face is
** planar and the roof's faces meet along arcs that both of their planes
** contain; each face's boundary is the input edge plus closed walks (it
** contains its edge, and a face's arcs are shared with the neighbour named
** on their other side, because every arc names both) that do not cross one
** another or themselves, so each face is a polygon in 3D (x, y, t) whose
** boundary does not cross itself (with islands where a walk lies inside
** another); the cap is closed and does not cross itself.  What it cannot
** prove: that two faces do not overlap in space (with negative weights the
** roof overhangs, so its projection is not a planar subdivision and
** validate.c's area and planarity checks do not apply), that a face's
** walks do not touch at a node (a pinch, allowed), or that the skeleton is
** the one the wavefront defines rather than another roof with the same
** planes (an arc could be missing where two closed walks join).
*/
#include "validate_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct incidence { uint32_t face, node; } incidence;

static int incidence_cmp(const void *x, const void *y) {
    const incidence *a = x, *b = y;
    if (a->face != b->face) return a->face < b->face ? -1 : 1;
    return a->node < b->node ? -1 : a->node > b->node;
}

/* ---- (e): the sides of one face (or the cap) do not cross */

typedef struct side2 {
    wk_point a, b;    /* the side's ends in the face's plane */
    uint32_t na, nb;  /* their nodes */
    uint32_t what;    /* arc id, or n_arcs + e for the input edge e */
} side2;

static int side2_cmp(const void *x, const void *y) {
    const side2 *a = x, *b = y;
    double ax = fmin(a->a.x, a->b.x), bx = fmin(b->a.x, b->b.x);
    if (ax != bx) return ax < bx ? -1 : 1;
    return a->what < b->what ? -1 : a->what > b->what;
}

static const char *side2_name(const wk_skeleton *S, const side2 *x, char *buf, size_t size) {
    if (x->what >= S->n_arcs) snprintf(buf, size, "edge %u", x->what - S->n_arcs);
    else snprintf(buf, size, "arc %u [%u, %u]", x->what, x->na, x->nb);
    return buf;
}

/* The point of node v in face f's plane (f == WK_NONE: the cap, xy). */
static wk_point in_plane(const wk_polygon *P, const wk_skeleton *S, uint32_t f, uint32_t v,
                         double wabs) {
    const wk_node *z = &S->nodes[v];
    if (f == WK_NONE || P->w[f] != 0) return (wk_point){z->x, z->y};
    wk_point a = P->p[f], d = wk_polygon_edge_dir(P, f);
    double len = hypot(d.x, d.y);
    return (wk_point){((z->x - a.x) * d.x + (z->y - a.y) * d.y) / len, z->t * wabs};
}

static wk_status check_sides(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t f,
                             side2 *sd, size_t k, double tol, double wabs) {
    qsort(sd, k, sizeof *sd, side2_cmp);
    /* a face that has moved at most tol (an edge the collinear rule swept
    ** at t = 0) is traced by arcs back and forth along its edge */
    double tmax = 0;
    for (size_t i = 0; i < k; i++) tmax = fmax(tmax, fmax(S->nodes[sd[i].na].t, S->nodes[sd[i].nb].t));
    bool still = f != WK_NONE && tmax * (P->w[f] != 0 ? fabs(P->w[f]) : wabs) <= tol;
    char s1[64], s2[64];
    for (size_t i = 0; i < k; i++) {
        double xmax = fmax(sd[i].a.x, sd[i].b.x);
        for (size_t j = i + 1; j < k && fmin(sd[j].a.x, sd[j].b.x) <= xmax; j++) {
            const side2 *x = &sd[i], *y = &sd[j];
            if (x->na == y->na || x->na == y->nb || x->nb == y->na || x->nb == y->nb) continue;
            wk_seg_meet m = wk_segments_meet_counted(R, x->a, x->b, y->a, y->b);
            double near = 0;
            if (m == WK_SEG_CROSS)
                near = fmin(fmin(wk_segment_point_distance(y->a, y->b, x->a), wk_segment_point_distance(y->a, y->b, x->b)),
                            fmin(wk_segment_point_distance(x->a, x->b, y->a), wk_segment_point_distance(x->a, x->b, y->b)));
            else if (m == WK_SEG_OVERLAP && !still)
                near = wk_collinear_overlap(x->a, x->b, y->a, y->b);
            if (near > tol) {
                char what[32];
                if (f == WK_NONE) snprintf(what, sizeof what, "the cap");
                else snprintf(what, sizeof what, "the face of edge %u", f);
                return WK_FAIL(R, WK_EINVALID, P->name, 0,
                               "validate (general e): %s crosses itself: %s and %s %s", what,
                               side2_name(S, x, s1, sizeof s1), side2_name(S, y, s2, sizeof s2),
                               m == WK_SEG_CROSS ? "cross" : "overlap");
            }
        }
    }
    return WK_OK;
}

static wk_status check_no_self_crossing(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                        double tol, double wabs) {
    /* the sides of each face: its arcs (both sides of every arc) and its edge */
    uint32_t nf = P->n + 1; /* face P->n: the cap */
    uint32_t *start = WK_NEW_ARRAY(R, uint32_t, nf + 1);
    if (!start) return R->err.code;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        start[c->left == WK_NONE ? P->n : c->left]++;
        start[c->right == WK_NONE ? P->n : c->right]++;
    }
    for (uint32_t e = 0; e < P->n; e++) start[e]++;
    uint32_t maxk = 0;
    for (uint32_t f = 0, acc = 0; f <= nf; f++) {
        uint32_t c = f < nf ? start[f] : 0;
        if (c > maxk) maxk = c;
        start[f] = acc;
        acc += c;
    }
    uint32_t *ids = WK_NEW_ARRAY(R, uint32_t, start[nf] + 1);
    uint32_t *fill = WK_NEW_ARRAY(R, uint32_t, nf + 1);
    side2 *sd = WK_NEW_ARRAY(R, side2, maxk + 1);
    wk_status st = WK_OK;
    if (!ids || !fill || !sd) {
        st = R->err.code;
        goto done;
    }
    memcpy(fill, start, (nf + 1) * sizeof *fill);
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        ids[fill[c->left == WK_NONE ? P->n : c->left]++] = i;
        ids[fill[c->right == WK_NONE ? P->n : c->right]++] = i;
    }
    for (uint32_t e = 0; e < P->n; e++) ids[fill[e]++] = S->n_arcs + e;
    for (uint32_t f = 0; f < nf && st == WK_OK; f++) {
        uint32_t face = f == P->n ? WK_NONE : f;
        size_t k = 0;
        for (uint32_t i = start[f]; i < start[f + 1]; i++) {
            uint32_t a, b;
            if (ids[i] >= S->n_arcs) {
                a = ids[i] - S->n_arcs;
                b = wk_polygon_next(P, a);
            } else {
                a = S->arcs[ids[i]].a;
                b = S->arcs[ids[i]].b;
            }
            sd[k++] = (side2){in_plane(P, S, face, a, wabs), in_plane(P, S, face, b, wabs), a, b,
                              ids[i]};
        }
        st = check_sides(R, P, S, face, sd, k, tol, wabs);
    }
done:
    WK_FREE_ARRAY(R, ids, start[nf] + 1);
    WK_FREE_ARRAY(R, fill, nf + 1);
    WK_FREE_ARRAY(R, sd, maxk + 1);
    WK_FREE_ARRAY(R, start, nf + 1);
    return st;
}

wk_status wk_validate_general(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                              wk_validate_report *rep) {
    wk_validate_report local;
    if (!rep) rep = &local;
    memset(rep, 0, sizeof *rep);
    rep->nodes = S->n_nodes;
    rep->arcs = S->n_arcs;
    rep->faces = P->n;
    if (!(tol > 0)) tol = WK_VALIDATE_TOL_REL * wk_polygon_scale(P);
    double H = R->opt.height, wabs = 0;
    for (uint32_t e = 0; e < P->n; e++)
        if (fabs(P->w[e]) > wabs) wabs = fabs(P->w[e]);
    double tol_t = wabs > 0 ? tol / wabs : tol;
    /* (a) */
    if (S->n_input != P->n || S->n_nodes < P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0, "validate (general a): %u input nodes for %u vertices",
                       S->n_input, P->n);
    for (uint32_t i = 0; i < P->n; i++)
        if (S->nodes[i].x != P->p[i].x || S->nodes[i].y != P->p[i].y || S->nodes[i].t != 0)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (general a): node %u is not input vertex %u at t = 0", i, i);
    /* (b) */
    for (uint32_t i = P->n; i < S->n_nodes; i++) {
        const wk_node *v = &S->nodes[i];
        if (!isfinite(v->x) || !isfinite(v->y) || !isfinite(v->t) || v->t < -tol_t ||
            (H > 0 && v->t > H + tol_t))
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (general b): node %u (%g, %g, t %g) is not finite or not in "
                           "0 <= t <= %g",
                           i, v->x, v->y, v->t, H > 0 ? H : INFINITY);
    }
    /* (c) */
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        if (c->a >= S->n_nodes || c->b >= S->n_nodes || c->a == c->b)
            return WK_FAIL(R, WK_EINVALID, P->name, 0, "validate (general c): arc %u [%u, %u] has bad ends",
                           i, c->a, c->b);
        if ((c->left >= P->n && c->left != WK_NONE) || (c->right >= P->n && c->right != WK_NONE) ||
            c->left == c->right)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (general c): arc %u has faces %u, %u", i, c->left, c->right);
        if (wk_validate_arc_ends(R, P, S, i, H, tol, tol_t, P->name, "general c", "the height",
                                 "plane", rep) != WK_OK ||
            wk_validate_arc_bisector(R, P, S, i, tol, P->name, "general c") != WK_OK)
            return R->err.code;
    }
    /* (d): incidences (face, node): both sides of every arc, the input edges */
    size_t m = 4 * (size_t)S->n_arcs + 2 * (size_t)P->n;
    incidence *in = WK_NEW_ARRAY(R, incidence, m);
    if (!in) return R->err.code;
    size_t k = 0;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        in[k++] = (incidence){c->left, c->a};
        in[k++] = (incidence){c->left, c->b};
        in[k++] = (incidence){c->right, c->a};
        in[k++] = (incidence){c->right, c->b};
    }
    for (uint32_t e = 0; e < P->n; e++) {
        in[k++] = (incidence){e, e};
        in[k++] = (incidence){e, wk_polygon_next(P, e)};
    }
    qsort(in, m, sizeof *in, incidence_cmp);
    wk_status st = WK_OK;
    for (size_t i = 0, j; i < m; i = j) {
        for (j = i; j < m && in[j].face == in[i].face && in[j].node == in[i].node; j++) {
        }
        if ((j - i) % 2) {
            if (in[i].face == WK_NONE)
                st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                             "validate (general d): the cap is not closed at node %u", in[i].node);
            else
                st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                             "validate (general d): the face of edge %u is not closed at node %u "
                             "(%zu of its arcs meet there)",
                             in[i].face, in[i].node, j - i);
            break;
        }
    }
    WK_FREE_ARRAY(R, in, m);
    if (st == WK_OK) st = check_no_self_crossing(R, P, S, tol, wabs);
    return st;
}
