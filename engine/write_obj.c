/*
** write_obj.c: the roof as a Wavefront OBJ mesh, as surfer2 and monos write
** it: every node lifted to z = t ("v x y t", in output numbering, so OBJ
** vertex k is node k-1), then one face per input edge in input edge order
** ("f" with 1-based vertex ids), the edge's face cycle counter-clockwise seen
** from above (normals point up).  A face of an edge removed at t = 0 by the
** collinear rule has two vertices; it is written as is (zero area).
*/
#include "write.h"

wk_status wk_write_obj(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    uint32_t *vertex_of = NULL, *edge_of = NULL;
    for (uint32_t i = 0; i < S->n_arcs; i++)
        if (S->arcs[i].left == WK_NONE || S->arcs[i].right == WK_NONE)
            return wk_write_obj_capped(R, f, P, S); /* a roof cut at a height */
    wk_faces F;
    if (wk_write_begin(R, P, S, "write obj: ") != WK_OK ||
        wk_faces_build(R, P, S, &F, "write obj: ") != WK_OK)
        return R->err.code;
    if (wk_input_order(R, P, &vertex_of, &edge_of) != WK_OK) {
        wk_faces_clear(R, &F);
        return R->err.code;
    }
    fputs("# wskel roof of ", f);
    wk_write_name(f, P);
    fprintf(f, ": %u vertices (x y t), %u faces (one per input edge, in input edge order)\n",
            S->n_nodes, P->n);
    for (uint32_t i = 0; i < S->n_nodes; i++) {
        const wk_node *v = &S->nodes[wk_stored_node(P, vertex_of, i)];
        fprintf(f, "v %.17g %.17g %.17g\n", v->x, v->y, v->t);
    }
    for (uint32_t i = 0; i < P->n; i++) {
        uint32_t e = edge_of[i];
        fputc('f', f);
        for (uint32_t k = F.start[e]; k < F.start[e + 1]; k++)
            fprintf(f, " %u", wk_polygon_output_node(P, F.node[k]) + 1);
        fputc('\n', f);
    }
    WK_FREE_ARRAY(R, vertex_of, P->n);
    WK_FREE_ARRAY(R, edge_of, P->n);
    wk_faces_clear(R, &F);
    return wk_write_end(R, f, "obj");
}
