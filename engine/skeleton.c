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
    if (WK_GROW_HINT(R, S->nodes, S->cap_nodes, S->n_nodes + 1, S->cap_hint) != WK_OK) return R->err.code;
    S->nodes[S->n_nodes] = (wk_node){x, y, t};
    *id = S->n_nodes++;
    return WK_OK;
}

wk_status wk_skeleton_add_arc(wk_run *R, wk_skeleton *S, uint32_t a, uint32_t b, uint32_t left,
                              uint32_t right) {
    if (WK_GROW_HINT(R, S->arcs, S->cap_arcs, S->n_arcs + 1, S->cap_hint) != WK_OK) return R->err.code;
    S->arcs[S->n_arcs++] = (wk_arc){a, b, left, right};
    return WK_OK;
}

void wk_skeleton_free(wk_run *R, wk_skeleton *S) {
    if (!S) return;
    WK_FREE_ARRAY(R, S->nodes, S->cap_nodes);
    WK_FREE_ARRAY(R, S->arcs, S->cap_arcs);
    WK_FREE_ARRAY(R, S, 1);
}

wk_status wk_skeleton_merge_pass_through(wk_run *R, wk_skeleton *S) {
    uint32_t nn = S->n_nodes, na = S->n_arcs;
    /* inc[2 m], inc[2 m + 1]: the first two arcs at node m; deg[m] its degree */
    uint32_t *deg = WK_NEW_ARRAY(R, uint32_t, nn);
    uint32_t *inc = WK_NEW_ARRAY(R, uint32_t, 2 * (size_t)nn);
    uint32_t *remap = WK_NEW_ARRAY(R, uint32_t, nn);
    uint8_t *gone = WK_NEW_ARRAY(R, uint8_t, na);
    wk_status st = R->err.code;
    if (!deg || !inc || !remap || !gone) goto done;
    for (uint32_t i = 0; i < na; i++) {
        uint32_t e[2] = {S->arcs[i].a, S->arcs[i].b};
        for (int j = 0; j < 2; j++) {
            if (deg[e[j]] < 2) inc[2 * e[j] + deg[e[j]]] = i;
            deg[e[j]]++;
        }
    }
    for (uint32_t m = S->n_input; m < nn; m++) {
        if (deg[m] != 2) continue;
        wk_arc *x = &S->arcs[inc[2 * m]], *y = &S->arcs[inc[2 * m + 1]];
        /* orient x to end at m and y to start at m */
        wk_arc X = *x, Y = *y;
        if (X.a == m) X = (wk_arc){X.b, X.a, X.right, X.left};
        if (Y.b == m) Y = (wk_arc){Y.b, Y.a, Y.right, Y.left};
        if (X.b != m || Y.a != m || X.left != Y.left || X.right != Y.right || X.a == Y.b) continue;
        *x = (wk_arc){X.a, Y.b, X.left, X.right};
        gone[inc[2 * m + 1]] = 1;
        deg[m] = 0;
        /* the far end of y now holds x instead of y */
        uint32_t far = Y.b;
        for (int j = 0; j < 2; j++)
            if (deg[far] <= 2 && inc[2 * far + j] == inc[2 * m + 1]) inc[2 * far + j] = inc[2 * m];
    }
    uint32_t k = 0;
    for (uint32_t m = 0; m < nn; m++) {
        bool keep = m < S->n_input || deg[m] != 0;
        remap[m] = keep ? k : WK_NONE;
        if (keep) S->nodes[k++] = S->nodes[m];
    }
    S->n_nodes = k;
    k = 0;
    for (uint32_t i = 0; i < na; i++) {
        if (gone[i]) continue;
        wk_arc a = S->arcs[i];
        a.a = remap[a.a];
        a.b = remap[a.b];
        S->arcs[k++] = a;
    }
    S->n_arcs = k;
    st = WK_OK;
done:
    if (deg) WK_FREE_ARRAY(R, deg, nn);
    if (inc) WK_FREE_ARRAY(R, inc, 2 * (size_t)nn);
    if (remap) WK_FREE_ARRAY(R, remap, nn);
    if (gone) WK_FREE_ARRAY(R, gone, na);
    return st;
}
