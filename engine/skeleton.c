/*
** skeleton.c: the skeleton result: nodes (x, y, t) and arcs (a, b, left, right).
** Invariant: nodes[0..n_input) are the input vertices at t = 0 in input order
** (as stored, i.e. counter-clockwise); arcs only refer to existing nodes.
*/
#include "wskel.h"

wk_status wk_skeleton_new(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    *out = NULL;
    wk_skeleton *S = WK_NEW_ARRAY(R, wk_skeleton, 1);
    if (!S) return R->err.code;
    S->n_input = P->n;
    for (uint32_t i = 0; i < P->n; i++) {
        uint32_t id;
        if (wk_skeleton_add_node(R, S, P->p[i].x, P->p[i].y, 0.0, &id) != WK_OK) {
            wk_skeleton_free(R, S);
            return R->err.code;
        }
    }
    *out = S;
    return WK_OK;
}

wk_status wk_skeleton_add_node(wk_run *R, wk_skeleton *S, double x, double y, double t,
                               uint32_t *id) {
    if (WK_GROW(R, S->nodes, S->cap_nodes, S->n_nodes + 1) != WK_OK) return R->err.code;
    S->nodes[S->n_nodes] = (wk_node){x, y, t};
    *id = S->n_nodes++;
    return WK_OK;
}

wk_status wk_skeleton_add_arc(wk_run *R, wk_skeleton *S, uint32_t a, uint32_t b, uint32_t left,
                              uint32_t right) {
    if (WK_GROW(R, S->arcs, S->cap_arcs, S->n_arcs + 1) != WK_OK) return R->err.code;
    S->arcs[S->n_arcs++] = (wk_arc){a, b, left, right};
    return WK_OK;
}

void wk_skeleton_free(wk_run *R, wk_skeleton *S) {
    if (!S) return;
    WK_FREE_ARRAY(R, S->nodes, S->cap_nodes);
    WK_FREE_ARRAY(R, S->arcs, S->cap_arcs);
    WK_FREE_ARRAY(R, S, 1);
}
