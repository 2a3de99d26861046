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
**       so do the cap's arcs.
** What this proves: every node of face e lies on e's plane (the plane
** through e rising with slope 1/w(e), vertical for w = 0), so each face is
** planar and the roof's faces meet along arcs that both of their planes
** contain; each face's boundary is the input edge plus closed walks (it
** contains its edge, and a face's arcs are shared with the neighbour named
** on their other side, because every arc names both); the cap is closed.
** What it cannot prove: that the faces do not overlap in space or are
** simple polygons (with negative weights the roof overhangs, so its
** projection is not a planar subdivision and validate.c's area and
** planarity checks do not apply), or that the skeleton is the one the
** wavefront defines rather than another roof with the same planes (an
** arc could be missing where two closed walks join).
*/
#include "validate_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct incidence { uint32_t face, node; } incidence;

static int incidence_cmp(const void *x, const void *y) {
    const incidence *a = x, *b = y;
    if (a->face != b->face) return a->face < b->face ? -1 : 1;
    return a->node < b->node ? -1 : a->node > b->node;
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
    return st;
}
