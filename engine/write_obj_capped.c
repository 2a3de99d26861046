/*
** write_obj_capped.c: the faces of a roof cut at a height, and its OBJ.
** The faces: of a skeleton cut at a height (arcs with
** the cap, WK_NONE, on one side; wk_options.height): one face per input
** edge (walls of weight 0 are vertical faces), in input edge order, then
** one face per counter-clockwise closed cycle of the cap, the clockwise
** cycles inside it (holes still open at the height) bridged in
** (cap_bridge_holes), all counter-clockwise seen from above.  A face is
** walked from its edge (e, next(e)) along its arcs; this
** path handles faces whose every node has two of the face's arcs (no
** islands, no node visited twice) and says so otherwise (WK_EUNSUPPORTED).
** A PSLG's skeleton is cut at its horizon T the same way (its cap is the
** wavefront at T); there a clockwise cap cycle inside no face is the rim,
** no face (cap_bridge_holes), and the edges' faces come from wk_faces_build, which
** bridges a face's islands in (faces.h) as the uncapped roof does.
*/
#include "write.h"

#include <math.h>
#include <string.h>

/* The next node of face f after cur, arriving from prev: the other arc of
** f at cur (its arcs listed in arcs[0..k)); WK_NONE if there are not
** exactly two. */
static uint32_t step(const wk_skeleton *S, const uint32_t *arcs, uint32_t k, uint32_t cur,
                     uint32_t *used_arc, uint32_t prev_arc) {
    uint32_t found = WK_NONE, count = 0;
    for (uint32_t i = 0; i < k; i++) {
        const wk_arc *c = &S->arcs[arcs[i]];
        if (c->a != cur && c->b != cur) continue;
        count++;
        if (arcs[i] != prev_arc) found = arcs[i];
    }
    if (count != 2 && !(count == 1 && prev_arc == WK_NONE)) return WK_NONE;
    if (found == WK_NONE) return WK_NONE;
    *used_arc = found;
    const wk_arc *c = &S->arcs[found];
    return c->a == cur ? c->b : c->a;
}

/* Is (x, y) inside the node cycle c[0 .. len) (even-odd, doubles: cap
** cycles are disjoint wavefront components, so any vertex decides)? */
static bool inside_cycle(const wk_skeleton *S, const uint32_t *c, uint32_t len, double x, double y) {
    bool in = false;
    for (uint32_t i = 0, j = len - 1; i < len; j = i++) {
        const wk_node *a = &S->nodes[c[j]], *b = &S->nodes[c[i]];
        if ((a->y > y) != (b->y > y) && x < a->x + (y - a->y) * (b->x - a->x) / (b->y - a->y))
            in = !in;
    }
    return in;
}

/* Does cycle h lie inside cycle c?  The cap's cycles are disjoint
** wavefront components, so any vertex of h decides; a majority of them
** does, so that a vertex of h on c (a height at a collision) cannot. */
static bool cycle_inside(const wk_skeleton *S, const uint32_t *h, uint32_t hl, const uint32_t *c,
                         uint32_t cl) {
    uint32_t in = 0;
    for (uint32_t i = 0; i < hl; i++)
        in += inside_cycle(S, c, cl, S->nodes[h[i]].x, S->nodes[h[i]].y);
    return 2 * in > hl;
}

/* A polygon with holes cut below a hole's closing (concentric squares at
** --height 1, issue 14): the cap at H is the region inside
** its outer cycle minus the hole cycles nested in it.  Walked with the cap
** on the left an outer cycle runs counter-clockwise and a hole's cycle
** clockwise; written as its own face, a clockwise cycle was a lid over the
** courtyard and the outer face covered the hole too.  So every clockwise
** cycle is bridged into the innermost counter-clockwise cycle around it
** (wk_bridge_loop, as faces.c bridges a face's islands in): one weakly
** simple face per outer cycle, holes by decreasing max x (faces.c says
** why).  Cycles of zero area stay faces as before.
** A PSLG's cap (the wavefront at its horizon T) bounds the unswept region
** the same way: a counter-clockwise cycle is the wavefront of a bounded
** face still alive at T, closed by its cap face; a clockwise one runs
** around a component with the unswept region outside it.  Inside no
** counter-clockwise cycle it is the rim of the unbounded outer face, which
** no face closes: it is dropped (pslg).  Inside one it is a hole of that
** face (a 10x10 square with a segment of length 2 in its middle at
** --until 0.5, issues 13/14: the face was refused, and written whole it
** would be a lid over the segment's swept stadium), bridged in as for
** polygons; the innermost cycle around it is its parent when components
** nest (a segment inside a square inside a square).  A PSLG cycle of zero
** area (a bounded face collapsing exactly at T) closes nothing and is
** dropped: bridged in, it would cross the rim around it. */
static wk_status cap_bridge_holes(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                  wk_capped_faces *CF, const char *what) {
    uint32_t f0 = CF->n_edge_faces, m = CF->n_faces - f0, base = f0 ? CF->end[f0 - 1] : 0;
    uint32_t n_cw = 0;
    bool pslg = P->pslg;
    for (uint32_t f = f0; f < CF->n_faces; f++) {
        uint32_t from = f ? CF->end[f - 1] : 0;
        double a = wk_cycle_area(S, CF->node + from, CF->end[f] - from);
        n_cw += a < 0 || (pslg && a == 0);
    }
    if (n_cw == 0) return WK_OK;
    uint32_t room = CF->n_node - base + 2 * m;
    double *area = WK_NEW_ARRAY(R, double, m);
    uint32_t *owner = WK_NEW_ARRAY(R, uint32_t, m), *out = WK_NEW_ARRAY(R, uint32_t, room);
    uint32_t *ends = WK_NEW_ARRAY(R, uint32_t, m); /* the written faces' ends in out */
    uint8_t *flag = WK_NEW_ARRAY(R, uint8_t, room), *done = WK_NEW_ARRAY(R, uint8_t, m);
    wk_status st = R->err.code;
    if (!area || !owner || !out || !flag || !done || !ends) goto out;
#define CYC(j) (CF->node + (f0 + (j) ? CF->end[f0 + (j) - 1] : 0))
#define LEN(j) (CF->end[f0 + (j)] - (f0 + (j) ? CF->end[f0 + (j) - 1] : 0))
    for (uint32_t j = 0; j < m; j++) area[j] = wk_cycle_area(S, CYC(j), LEN(j));
    for (uint32_t h = 0; h < m; h++) {
        owner[h] = WK_NONE;
        if (area[h] >= 0) continue;
        for (uint32_t o = 0; o < m; o++)
            if (area[o] > 0 && (owner[h] == WK_NONE || area[o] < area[owner[h]]) &&
                cycle_inside(S, CYC(h), LEN(h), CYC(o), LEN(o)))
                owner[h] = o;
        if (owner[h] == WK_NONE && !pslg) {
            st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                         "%sthe cap at the height t = %g has a clockwise cycle (through node "
                         "%u) inside no counter-clockwise one: no cap face to cut it from",
                         what, S->nodes[CYC(h)[0]].t, CYC(h)[0]);
            goto out;
        }
    }
    uint32_t pos = 0, k = 0;
    for (uint32_t o = 0; o < m; o++) {
        if (area[o] < 0 || (pslg && area[o] == 0)) continue; /* a hole, a rim or nothing */
        uint32_t len = LEN(o);
        memcpy(out + pos, CYC(o), (size_t)len * sizeof *out);
        memset(flag + pos, 0, len);
        for (;;) {
            uint32_t pick = WK_NONE;
            double px = -INFINITY;
            for (uint32_t h = 0; h < m; h++) {
                if (owner[h] != o || done[h]) continue;
                double mx = -INFINITY;
                for (uint32_t i = 0; i < LEN(h); i++) mx = fmax(mx, S->nodes[CYC(h)[i]].x);
                if (pick == WK_NONE || mx > px) {
                    px = mx;
                    pick = h;
                }
            }
            if (pick == WK_NONE) break;
            done[pick] = 1;
            if ((st = wk_bridge_loop(R, P, S, WK_NONE, out + pos, flag + pos, &len, CYC(pick),
                                     LEN(pick), what)) != WK_OK)
                goto out;
        }
        pos += len;
        ends[k++] = pos;
    }
#undef CYC
#undef LEN
    if ((st = WK_GROW(R, CF->node, CF->cap_node, base + pos)) != WK_OK) {
        st = R->err.code;
        goto out;
    }
    memcpy(CF->node + base, out, (size_t)pos * sizeof *out);
    for (uint32_t j = 0; j < k; j++) CF->end[f0 + j] = base + ends[j];
    CF->n_faces = f0 + k;
    CF->n_node = base + pos;
    st = WK_OK;
out:
    if (area) WK_FREE_ARRAY(R, area, m);
    if (owner) WK_FREE_ARRAY(R, owner, m);
    if (out) WK_FREE_ARRAY(R, out, room);
    if (flag) WK_FREE_ARRAY(R, flag, room);
    if (done) WK_FREE_ARRAY(R, done, m);
    if (ends) WK_FREE_ARRAY(R, ends, m);
    return st;
}

wk_status wk_capped_faces_build(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                const uint32_t *edge_of, wk_capped_faces *CF, const char *what) {
    memset(CF, 0, sizeof *CF);
    uint32_t A = S->n_arcs;
    uint32_t *arcs = WK_NEW_ARRAY(R, uint32_t, A + 1);
    uint8_t *done = WK_NEW_ARRAY(R, uint8_t, A + 1);
    wk_status st = R->err.code;
    wk_faces PF; /* a PSLG's edge faces, islands bridged */
    memset(&PF, 0, sizeof PF);
    if (!arcs || !done) goto out;
    if (P->pslg && (st = wk_faces_build(R, P, S, &PF, what)) != WK_OK) goto out;
#define PUSH_NODE(v)                                                                   \
    do {                                                                               \
        if (WK_GROW(R, CF->node, CF->cap_node, CF->n_node + 1) != WK_OK) {             \
            st = R->err.code; /* WK_ENOMEM, never WK_OK */                             \
            goto out;                                                                  \
        }                                                                              \
        CF->node[CF->n_node++] = (v);                                                  \
    } while (0)
#define END_FACE()                                                                       \
    do {                                                                                 \
        if (WK_GROW(R, CF->end, CF->cap_end, CF->n_faces + 1) != WK_OK) {                \
            st = R->err.code;                                                            \
            goto out;                                                                    \
        }                                                                                \
        CF->end[CF->n_faces++] = CF->n_node;                                             \
    } while (0)
    /* faces fi = 0 .. n-1 are the edges' (input order), fi = n the cap */
    for (uint32_t fi = 0; fi <= P->n; fi++) {
        uint32_t e = fi < P->n ? edge_of[fi] : WK_NONE, k = 0;
        if (P->pslg && e != WK_NONE) { /* its cycle from faces.c, islands bridged in (a
                                       ** bridge may leave node e before the edge does) */
            for (uint32_t q = PF.start[e]; q < PF.start[e + 1]; q++) PUSH_NODE(PF.node[q]);
            END_FACE();
            continue;
        }
        for (uint32_t i = 0; i < A; i++)
            if (S->arcs[i].left == e || S->arcs[i].right == e) arcs[k++] = i;
        if (e != WK_NONE) {
            /* from next(e) around to e: the input edge closes the face */
            uint32_t start = wk_polygon_next(P, e), cur = start, prev_arc = WK_NONE, guard = 0;
            PUSH_NODE(e);
            PUSH_NODE(start);
            while (cur != e) {
                uint32_t used;
                uint32_t nx = step(S, arcs, k, cur, &used, prev_arc);
                if (nx == WK_NONE || ++guard > k) {
                    st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                                 "%sthe face of edge %u of this capped roof is not one simple "
                                 "cycle (not written yet)",
                                 what, wk_polygon_input_edge(P, e));
                    goto out;
                }
                prev_arc = used;
                cur = nx;
                if (cur != e) PUSH_NODE(cur);
            }
            END_FACE();
            continue;
        }
        /* the cap: each arc a -> b has the cap on its left, so following
        ** a -> b -> ... goes counter-clockwise around it */
        CF->n_edge_faces = CF->n_faces;
        for (uint32_t i = 0; i < k; i++) {
            if (done[i]) continue;
            uint32_t j = i, guard = 0;
            while (!done[j]) {
                done[j] = 1;
                const wk_arc *c = &S->arcs[arcs[j]];
                uint32_t from = c->left == WK_NONE ? c->a : c->b, to = c->left == WK_NONE ? c->b : c->a;
                PUSH_NODE(from);
                uint32_t nj = WK_NONE;
                for (uint32_t q = 0; q < k && nj == WK_NONE; q++) {
                    const wk_arc *d = &S->arcs[arcs[q]];
                    uint32_t dfrom = d->left == WK_NONE ? d->a : d->b;
                    if (!done[q] && dfrom == to) nj = q;
                }
                if (nj == WK_NONE || ++guard > k) break;
                j = nj;
            }
            END_FACE();
        }
    }
    if ((st = cap_bridge_holes(R, P, S, CF, what)) != WK_OK) goto out;
#undef PUSH_NODE
#undef END_FACE
    st = WK_OK;
out:
    wk_faces_clear(R, &PF);
    if (arcs) WK_FREE_ARRAY(R, arcs, A + 1);
    if (done) WK_FREE_ARRAY(R, done, A + 1);
    if (st != WK_OK) wk_capped_faces_clear(R, CF);
    return st;
}

void wk_capped_faces_clear(wk_run *R, wk_capped_faces *CF) {
    WK_FREE_ARRAY(R, CF->node, CF->cap_node);
    WK_FREE_ARRAY(R, CF->end, CF->cap_end);
    memset(CF, 0, sizeof *CF);
}

wk_status wk_write_obj_capped(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    uint32_t *vertex_of = NULL, *edge_of = NULL;
    wk_capped_faces CF;
    if (wk_write_begin_capped(R, P, S, "write obj: ") != WK_OK ||
        wk_input_order(R, P, &vertex_of, &edge_of) != WK_OK)
        return R->err.code;
    wk_status st = wk_capped_faces_build(R, P, S, edge_of, &CF, "write obj: ");
    if (st == WK_OK) {
        fputs("# wskel roof of ", f);
        wk_write_name(f, P);
        fprintf(f, ": %u vertices (x y t), one face per input edge, then the cap at the height\n",
                S->n_nodes);
        for (uint32_t i = 0; i < S->n_nodes; i++) {
            const wk_node *v = &S->nodes[wk_stored_node(P, vertex_of, i)];
            fprintf(f, "v %.17g %.17g %.17g\n", v->x, v->y, v->t);
        }
        for (uint32_t fi = 0; fi < CF.n_faces; fi++) {
            fputc('f', f);
            for (uint32_t k = fi ? CF.end[fi - 1] : 0; k < CF.end[fi]; k++)
                fprintf(f, " %u", wk_polygon_output_node(P, CF.node[k]) + 1);
            fputc('\n', f);
        }
        st = wk_write_end(R, f, "obj");
        wk_capped_faces_clear(R, &CF);
    }
    WK_FREE_ARRAY(R, vertex_of, P->n);
    WK_FREE_ARRAY(R, edge_of, P->n);
    return st;
}
