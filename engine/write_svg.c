/*
** write_svg.c: a picture of the skeleton, for people (not a data format:
** coordinates are written with 10 significant digits).
**
** Layers, bottom to top: the polygon (filled light), offset curves at the
** requested times (thin grey), convex arcs (blue), reflex arcs (orange, see
** wk_arc_is_reflex), nodes (small dots).  SVG's y axis points down, so every
** y is negated and the picture is not mirrored; the viewBox is the polygon's
** bounding box plus a 4% margin, and stroke widths and dot radii are
** fractions of the polygon's scale (bounding box diagonal), so any input
** size draws the same.
**
** Offset curve of face e at time t: the part of the line at signed distance
** w(e) t from edge e's supporting line that lies inside the face's cycle,
** i.e. the wavefront of e at time t.  The line is cut with every side of the
** cycle (a side crosses it when its ends' signs of d - w t differ, zero
** counting as negative, so a cycle always yields an even number of cuts); the
** cuts sorted along the edge's direction pair up into inside segments.
** Offsets need the faces, so they are built (first, before anything is
** written) only when times are given: an invalid skeleton whose faces do not
** close still draws without them.
**
** A roof cut at a height (--height; arcs with the cap, WK_NONE, on one side)
** draws its cap arcs (green) over the skeleton, and its offsets from the
** faces of wk_capped_faces_build.  A wall (weight 0) does not move, so the
** line test above cannot find its wavefront: a wall's face is cut with the
** plane at height t instead (its sides' node times against t), which is the
** same cut for any face.  With negative weights the roof reaches outside the
** polygon, so the viewBox covers every node, not only the polygon.
**
** A PSLG (P->pslg) has no region to fill: its segments are drawn instead
** (each once), its cap (the wavefront at the horizon) in green, and its
** offsets are the rings of wk_offset at each time (the boundary of the
** region swept by then; faces with islands included, which the line cut
** above would need bridged cycles for).
*/
#include "write.h"

#include <math.h>
#include <stdlib.h>

typedef struct cut { double u, x, y; } cut; /* position along the edge, point */

static int cut_cmp(const void *pa, const void *pb) {
    const cut *a = pa, *b = pb;
    return (a->u > b->u) - (a->u < b->u);
}

/* 0.0 - y, not -y: no "-0" in the output. */
static void put_xy(FILE *f, double x, double y) { fprintf(f, "%.10g,%.10g", x, 0.0 - y); }

static void put_xml_text(FILE *f, const char *s) {
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '&') fputs("&amp;", f);
        else if (*c == '<') fputs("&lt;", f);
        else if (*c == '>') fputs("&gt;", f);
        else fputc(*c < 0x20 ? '?' : *c, f);
    }
}

/* Segments of face e's wavefront at time t, as path commands. */
static void put_offset(FILE *f, const wk_polygon *P, const wk_skeleton *S, uint32_t e,
                       const uint32_t *cyc, uint32_t len, double t, cut *cuts) {
    wk_point p = P->p[e], d = wk_polygon_edge_dir(P, e); /* a PSLG's cap: length 0, a direction */
    double dx = d.x, dy = d.y, l = hypot(dx, dy);
    if (!(l > 0)) return;
    dx /= l;
    dy /= l;
    double want = P->w[e] * t;
    bool wall = P->w[e] == 0;
    uint32_t m = 0;
    for (uint32_t i = 0; i < len; i++) {
        const wk_node *a = &S->nodes[cyc[i]], *b = &S->nodes[cyc[i + 1 == len ? 0 : i + 1]];
        double sa = wall ? a->t - t : dx * (a->y - p.y) - dy * (a->x - p.x) - want;
        double sb = wall ? b->t - t : dx * (b->y - p.y) - dy * (b->x - p.x) - want;
        if ((sa > 0) == (sb > 0)) continue;
        double k = sa / (sa - sb), x = a->x + k * (b->x - a->x), y = a->y + k * (b->y - a->y);
        cuts[m++] = (cut){(x - p.x) * dx + (y - p.y) * dy, x, y};
    }
    qsort(cuts, m, sizeof *cuts, cut_cmp);
    for (uint32_t i = 0; i + 1 < m; i += 2) {
        fputs("M", f);
        put_xy(f, cuts[i].x, cuts[i].y);
        fputs("L", f);
        put_xy(f, cuts[i + 1].x, cuts[i + 1].y);
    }
}

/* The faces whose cycles the offsets cut: face e's cycle (stored nodes) is
** node[start[e] .. start[e + 1]) for stored edge edge[e] (edge NULL: e). */
typedef struct svg_faces {
    uint32_t n, *start, *node;
    const uint32_t *edge;
} svg_faces;

static void put_offsets(FILE *f, const wk_polygon *P, const wk_skeleton *S, const svg_faces *F,
                        const double *offsets, uint32_t n_offsets, double sw, cut *cuts) {
    for (uint32_t k = 0; k < n_offsets; k++) {
        if (!(offsets[k] > 0) || !isfinite(offsets[k])) continue; /* t = 0: the boundary */
        fprintf(f, "<path class=\"offset\" data-t=\"%.10g\" fill=\"none\" stroke=\"#8a8a8a\" "
                   "stroke-width=\"%.4g\" d=\"",
                offsets[k], sw * 0.5);
        for (uint32_t e = 0; e < F->n; e++)
            put_offset(f, P, S, F->edge ? F->edge[e] : e, F->node + F->start[e],
                       F->start[e + 1] - F->start[e], offsets[k], cuts);
        fputs("\"/>\n", f);
    }
}

/* A PSLG's offsets: the rings of wk_offset at each time (the boundary of
** the region swept by then), closed subpaths; at the horizon they run
** along the cap. */
static void put_offset_rings(FILE *f, wk_offset_set *const *sets, const double *offsets,
                             uint32_t n_offsets, double sw) {
    for (uint32_t k = 0; k < n_offsets; k++) {
        if (!sets[k]) continue; /* t = 0: the segments themselves */
        const wk_offset_set *O = sets[k];
        fprintf(f, "<path class=\"offset\" data-t=\"%.10g\" fill=\"none\" stroke=\"#8a8a8a\" "
                   "stroke-width=\"%.4g\" d=\"",
                offsets[k], sw * 0.5);
        for (uint32_t r = 0; r < O->n_rings; r++) {
            for (uint32_t i = O->ring_start[r]; i < O->ring_start[r + 1]; i++) {
                fputs(i == O->ring_start[r] ? "M" : "L", f);
                put_xy(f, O->p[i].x, O->p[i].y);
            }
            fputs("Z", f);
        }
        fputs("\"/>\n", f);
    }
}

static bool is_cap_arc(const wk_arc *c) { return c->left == WK_NONE || c->right == WK_NONE; }

/* kind: 0 convex, 1 reflex, 2 the cap */
static void put_arcs(FILE *f, const wk_polygon *P, const wk_skeleton *S, int kind,
                     const char *colour, double sw) {
    static const char *const CLASS[3] = {"convex", "reflex", "cap"};
    fprintf(f, "<path class=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"%.4g\" d=\"",
            CLASS[kind], colour, sw);
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        bool cap = is_cap_arc(&S->arcs[i]);
        if (kind == 2 ? !cap : cap || wk_arc_is_reflex(P, S, i) != (kind == 1)) continue;
        const wk_node *a = &S->nodes[S->arcs[i].a], *b = &S->nodes[S->arcs[i].b];
        fputs("M", f);
        put_xy(f, a->x, a->y);
        fputs("L", f);
        put_xy(f, b->x, b->y);
    }
    fputs("\"/>\n", f);
}

/* The polygon, filled: one path, a subpath per ring; evenodd leaves the
** holes unfilled. */
static void put_polygon(FILE *f, const wk_polygon *P, double sw) {
    fprintf(f, "<path class=\"polygon\" fill=\"#f4f1e4\" fill-rule=\"evenodd\" "
               "stroke=\"#333333\" stroke-width=\"%.4g\" d=\"",
            sw);
    for (uint32_t k = 0; k < P->n_rings; k++) {
        for (uint32_t i = P->ring_start[k]; i < P->ring_start[k + 1]; i++) {
            fputs(i == P->ring_start[k] ? (k ? " M" : "M") : " L", f);
            put_xy(f, P->p[i].x, P->p[i].y);
        }
        fputs(" Z", f);
    }
    fputs("\"/>\n", f);
}

/* A PSLG has no region to fill: its segments, each once.  The two
** half-edges of a segment run between its two nodes in opposite
** directions; the one leaving the node of lower GraphML index is drawn. */
static void put_segments(FILE *f, const wk_polygon *P, double sw) {
    fprintf(f, "<path class=\"segments\" fill=\"none\" stroke=\"#333333\" stroke-width=\"%.4g\" d=\"",
            2 * sw);
    for (uint32_t e = 0; e < P->n; e++) {
        if (P->edge_of[e] == WK_NONE) continue; /* a cap */
        if (P->corner_vertex[e] > P->corner_vertex[wk_polygon_next(P, e)]) continue;
        fputs(" M", f);
        put_xy(f, P->p[e].x, P->p[e].y);
        fputs(" L", f);
        wk_point q = P->p[wk_polygon_next(P, e)];
        put_xy(f, q.x, q.y);
    }
    fputs("\"/>\n", f);
}

wk_status wk_write_svg(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S,
                       const double *offsets, uint32_t n_offsets) {
    if (!offsets) n_offsets = 0;
    bool capped = false;
    for (uint32_t i = 0; i < S->n_arcs && !capped; i++) capped = is_cap_arc(&S->arcs[i]);
    wk_faces F;
    memset(&F, 0, sizeof F);
    wk_capped_faces CF;
    memset(&CF, 0, sizeof CF);
    uint32_t *edge_of = NULL, *cf_start = NULL;
    svg_faces SF = {0, NULL, NULL, NULL};
    cut *cuts = NULL;
    uint32_t maxlen = 0;
    wk_offset_set **pslg_sets = NULL;
    wk_status st = capped ? wk_write_begin_capped(R, P, S, "write svg: ")
                          : wk_write_begin(R, P, S, "write svg: ");
    if (st != WK_OK) return st;
    if (n_offsets && !capped) {
        if (wk_faces_build(R, P, S, &F, "write svg (offset curves): ") != WK_OK) return R->err.code;
        SF = (svg_faces){F.n, F.start, F.node, NULL};
    } else if (n_offsets && P->pslg) {
        /* the swept region's rings from wk_offset (faces with islands
        ** included), computed before anything is written */
        if (!(pslg_sets = WK_NEW_ARRAY(R, wk_offset_set *, n_offsets))) {
            st = R->err.code;
            goto out;
        }
        for (uint32_t k = 0; k < n_offsets; k++)
            if (offsets[k] > 0 && (st = wk_offset(R, P, S, offsets[k], &pslg_sets[k])) != WK_OK)
                goto out;
    } else if (n_offsets) {
        /* the edges' faces of the capped roof, as start offsets */
        if (wk_input_order(R, P, NULL, &edge_of) != WK_OK ||
            wk_capped_faces_build(R, P, S, edge_of, &CF, "write svg (offset curves): ") != WK_OK ||
            !(cf_start = WK_NEW_ARRAY(R, uint32_t, CF.n_edge_faces + 1))) {
            st = R->err.code;
            goto out;
        }
        cf_start[0] = 0;
        for (uint32_t e = 0; e < CF.n_edge_faces; e++) cf_start[e + 1] = CF.end[e];
        SF = (svg_faces){CF.n_edge_faces, cf_start, CF.node, edge_of};
    }
    for (uint32_t e = 0; e < SF.n; e++)
        if (SF.start[e + 1] - SF.start[e] > maxlen) maxlen = SF.start[e + 1] - SF.start[e];
    if (n_offsets && !pslg_sets && !(cuts = WK_NEW_ARRAY(R, cut, maxlen))) {
        st = R->err.code;
        goto out;
    }

    wk_point lo, hi;
    wk_polygon_bbox(P, &lo, &hi);
    double x0 = lo.x, x1 = hi.x, y0 = lo.y, y1 = hi.y;
    for (uint32_t j = 0; j < S->n_nodes; j++) {
        const wk_node *v = &S->nodes[j];
        if (!isfinite(v->x) || !isfinite(v->y)) continue;
        x0 = fmin(x0, v->x), x1 = fmax(x1, v->x), y0 = fmin(y0, v->y), y1 = fmax(y1, v->y);
    }
    double scale = hypot(x1 - x0, y1 - y0), pad = 0.04 * scale, sw = 0.002 * scale;
    double W = x1 - x0 + 2 * pad, H = y1 - y0 + 2 * pad;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%.10g %.10g %.10g %.10g\" "
               "width=\"800\" height=\"%.0f\">\n<title>",
            x0 - pad, -(y1 + pad), W, H, W > 0 ? 800.0 * H / W : 800.0);
    put_xml_text(f, P->name[0] ? P->name : "polygon");
    fprintf(f, ": weighted straight skeleton, %u nodes, %u arcs (blue convex, orange reflex%s)"
               "</title>\n<g stroke-linecap=\"round\" stroke-linejoin=\"round\">\n",
            S->n_nodes, S->n_arcs, capped ? ", green the cap" : "");
    if (P->pslg) put_segments(f, P, sw);
    else put_polygon(f, P, sw);
    if (pslg_sets) put_offset_rings(f, pslg_sets, offsets, n_offsets, sw);
    else if (n_offsets) put_offsets(f, P, S, &SF, offsets, n_offsets, sw, cuts);
    put_arcs(f, P, S, 0, "#1f5fbf", sw);
    put_arcs(f, P, S, 1, "#e07b00", sw);
    if (capped) put_arcs(f, P, S, 2, "#2e9e44", sw);
    fprintf(f, "<g class=\"nodes\" fill=\"#222222\">\n");
    for (uint32_t j = 0; j < S->n_nodes; j++)
        fprintf(f, "<circle cx=\"%.10g\" cy=\"%.10g\" r=\"%.4g\"/>\n", S->nodes[j].x,
                0.0 - S->nodes[j].y, 2 * sw);
    fputs("</g>\n</g>\n</svg>\n", f);
    st = wk_write_end(R, f, "svg");
out:
    if (pslg_sets) {
        for (uint32_t k = 0; k < n_offsets; k++) wk_offset_set_free(R, pslg_sets[k]);
        WK_FREE_ARRAY(R, pslg_sets, n_offsets);
    }
    if (cuts) WK_FREE_ARRAY(R, cuts, maxlen);
    if (cf_start) WK_FREE_ARRAY(R, cf_start, CF.n_edge_faces + 1);
    if (edge_of) WK_FREE_ARRAY(R, edge_of, P->n);
    wk_capped_faces_clear(R, &CF);
    wk_faces_clear(R, &F);
    return st;
}
