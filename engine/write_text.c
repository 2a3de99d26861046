/*
** write_text.c: the skeleton as plain text for people, awk and sed.
**
**   # comment lines (any number, first)
**   nodes N
**   x y t            N lines, input numbering: the first n are the input
**                    vertices in input order (t = 0); %.17g, round-trips
**   arcs M
**   a b left right   M lines: node ids, and the input edges whose faces lie
**                    left and right of a -> b (-1: the cap, --height)
**
** Reading it back: skip lines starting with '#', then read "nodes", N, the
** N triples, "arcs", M and the M quadruples, all whitespace-separated.
*/
#include "write.h"

wk_status wk_write_text(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    uint32_t *vertex_of;
    if (wk_write_begin_capped(R, P, S, "write text: ") != WK_OK ||
        wk_input_order(R, P, &vertex_of, NULL) != WK_OK)
        return R->err.code;
    fputs("# wskel skeleton (wskel-1 text), polygon ", f);
    wk_write_name(f, P);
    fprintf(f, ": n = %u vertices, r = %u reflex; input numbering\n", P->n, P->r);
    fputs("# nodes: x y t (the first n are the input vertices, t = 0)\n"
          "# arcs: a b left right (left/right: input edges whose faces lie left/right of a->b)\n",
          f);
    fprintf(f, "nodes %u\n", S->n_nodes);
    for (uint32_t i = 0; i < S->n_nodes; i++) {
        const wk_node *v = &S->nodes[wk_stored_node(P, vertex_of, i)];
        fprintf(f, "%.17g %.17g %.17g\n", v->x, v->y, v->t);
    }
    fprintf(f, "arcs %u\n", S->n_arcs);
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        fprintf(f, "%u %u %lld %lld\n", wk_polygon_output_node(P, c->a),
                wk_polygon_output_node(P, c->b), wk_write_face(P, c->left),
                wk_write_face(P, c->right));
    }
    WK_FREE_ARRAY(R, vertex_of, P->n);
    return wk_write_end(R, f, "text");
}
