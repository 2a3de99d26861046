/*
** write_obj_capped.c: the OBJ roof of a skeleton cut at a height (arcs with
** the cap, WK_NONE, on one side; wk_options.height): one face per input
** edge (walls of weight 0 are vertical faces), in input edge order, then
** one face per closed cycle of the cap, all counter-clockwise seen from
** above.  A face is walked from its edge (e, next(e)) along its arcs; this
** path handles faces whose every node has two of the face's arcs (no
** islands, no node visited twice) and says so otherwise (WK_EUNSUPPORTED).
*/
#include "write.h"

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

wk_status wk_write_obj_capped(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    uint32_t *vertex_of = NULL, *edge_of = NULL;
    if (wk_write_begin_capped(R, P, S, "write obj: ") != WK_OK ||
        wk_input_order(R, P, &vertex_of, &edge_of) != WK_OK)
        return R->err.code;
    uint32_t A = S->n_arcs;
    uint32_t *arcs = WK_NEW_ARRAY(R, uint32_t, A + 1);
    uint8_t *done = WK_NEW_ARRAY(R, uint8_t, A + 1);
    wk_status st = R->err.code;
    if (!arcs || !done) goto out;
    fputs("# wskel roof of ", f);
    wk_write_name(f, P);
    fprintf(f, ": %u vertices (x y t), one face per input edge, then the cap at the height\n",
            S->n_nodes);
    for (uint32_t i = 0; i < S->n_nodes; i++) {
        const wk_node *v = &S->nodes[wk_stored_node(P, vertex_of, i)];
        fprintf(f, "v %.17g %.17g %.17g\n", v->x, v->y, v->t);
    }
    /* faces f = 0 .. n-1 are the edges' (stored), f = n the cap */
    for (uint32_t fi = 0; fi <= P->n; fi++) {
        uint32_t e = fi < P->n ? edge_of[fi] : WK_NONE, k = 0;
        for (uint32_t i = 0; i < A; i++)
            if (S->arcs[i].left == e || S->arcs[i].right == e) arcs[k++] = i;
        if (e != WK_NONE) {
            /* from next(e) around to e: the input edge closes the face */
            uint32_t start = wk_polygon_next(P, e), cur = start, prev_arc = WK_NONE, guard = 0;
            fprintf(f, "f %u %u", wk_polygon_output_node(P, e) + 1,
                    wk_polygon_output_node(P, start) + 1);
            while (cur != e) {
                uint32_t used;
                uint32_t nx = step(S, arcs, k, cur, &used, prev_arc);
                if (nx == WK_NONE || ++guard > k) {
                    st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                                 "write obj: the face of edge %u of this capped roof is not one "
                                 "simple cycle (not written yet)",
                                 wk_polygon_input_edge(P, e));
                    goto out;
                }
                prev_arc = used;
                cur = nx;
                if (cur != e) fprintf(f, " %u", wk_polygon_output_node(P, cur) + 1);
            }
            fputc('\n', f);
            continue;
        }
        /* the cap: each arc a -> b has the cap on its left, so following
        ** a -> b -> ... goes counter-clockwise around it */
        for (uint32_t i = 0; i < k; i++) {
            if (done[i]) continue;
            fputc('f', f);
            uint32_t j = i, guard = 0;
            while (!done[j]) {
                done[j] = 1;
                const wk_arc *c = &S->arcs[arcs[j]];
                uint32_t from = c->left == WK_NONE ? c->a : c->b, to = c->left == WK_NONE ? c->b : c->a;
                fprintf(f, " %u", wk_polygon_output_node(P, from) + 1);
                uint32_t nj = WK_NONE;
                for (uint32_t q = 0; q < k && nj == WK_NONE; q++) {
                    const wk_arc *d = &S->arcs[arcs[q]];
                    uint32_t dfrom = d->left == WK_NONE ? d->a : d->b;
                    if (!done[q] && dfrom == to) nj = q;
                }
                if (nj == WK_NONE || ++guard > k) break;
                j = nj;
            }
            fputc('\n', f);
        }
    }
    st = wk_write_end(R, f, "obj");
out:
    if (arcs) WK_FREE_ARRAY(R, arcs, A + 1);
    if (done) WK_FREE_ARRAY(R, done, A + 1);
    WK_FREE_ARRAY(R, vertex_of, P->n);
    WK_FREE_ARRAY(R, edge_of, P->n);
    return st;
}
