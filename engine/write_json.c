/*
** write_json.c: the skeleton as JSON, the format other tools and the Python
** tests read.  The contract (format "wskel-1"):
**
**   {"format":"wskel-1", "variant":NAME, "k":K, "n":N, "r":R,
**    "nodes":[[x,y,t], ...],          input numbering: nodes[0..n) are the
**                                      input vertices in input order, t = 0
**    "arcs":[[a,b,left,right], ...],  node ids; left/right: the input edges
**                                      whose faces lie left/right of a -> b
**                                      (-1: the cap of a skeleton cut at a
**                                      height, --height)
**    "pslg":{"horizon":T, "graph_nodes":V, "graph_edges":E,
**            "corner_node":[...], "edge_of":[...]}   only for a PSLG (after
**                                      "rings"): nodes[0..n) are its corners,
**                                      edges its half-edges and caps (-1 in
**                                      edge_of), the arcs with -1 on the left
**                                      the wavefront at T
**    "stats":{COUNTER:count, ... (every name of WK_COUNTER_LIST),
**             "time_s":seconds, "peak_bytes":bytes}}
**
** K is null when the variant has no cache (info->k == WK_NONE), the number
** when finite, and "max" for WK_K_MAX.  With info == NULL: variant "unknown",
** k null, stats null; with info->counters == NULL the stats hold only time_s
** and peak_bytes.  Doubles are written with %.17g (they round-trip); a
** non-finite double, which only an invalid skeleton has, is written as null
** so that the file stays JSON.  One node or arc per line keeps diffs readable.
*/
#include "write.h"

#include <math.h>

static void put_double(FILE *f, double v) {
    if (isfinite(v)) fprintf(f, "%.17g", v);
    else fputs("null", f);
}

static void put_k(FILE *f, const wk_run_info *info) {
    if (!info || info->k == WK_NONE) fputs("null", f);
    else if (info->k == WK_K_MAX) fputs("\"max\"", f);
    else fprintf(f, "%u", info->k);
}

wk_status wk_write_json(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S,
                        const wk_run_info *info) {
    uint32_t *vertex_of;
    if (wk_write_begin_capped(R, P, S, "write json: ") != WK_OK ||
        wk_input_order(R, P, &vertex_of, NULL) != WK_OK)
        return R->err.code;

    fputs("{\"format\":\"wskel-1\",\"variant\":", f);
    wk_write_json_string(f, info && info->variant ? info->variant : "unknown");
    fputs(",\"k\":", f);
    put_k(f, info);
    fprintf(f, ",\"n\":%u,\"r\":%u,\"rings\":[", P->n, P->r);
    for (uint32_t k = 0; k < P->n_rings; k++)
        fprintf(f, "%s%u", k ? "," : "", P->ring_start[k + 1] - P->ring_start[k]);
    fputc(']', f);
    if (P->pslg) {
        /* a PSLG: the horizon, and each corner's input node and each stored
        ** edge's input edge (-1: a cap) in the GraphML's document order */
        fputs(",\n\"pslg\":{\"horizon\":", f);
        put_double(f, S->horizon);
        fprintf(f, ",\"graph_nodes\":%u,\"graph_edges\":%u,\"corner_node\":[",
                P->n_graph_vertices, P->n_graph_edges);
        for (uint32_t i = 0; i < P->n; i++) fprintf(f, "%s%u", i ? "," : "", P->corner_vertex[i]);
        fputs("],\"edge_of\":[", f);
        for (uint32_t i = 0; i < P->n; i++)
            fprintf(f, "%s%lld", i ? "," : "", P->edge_of[i] == WK_NONE ? -1LL : (long long)P->edge_of[i]);
        fputs("]}", f);
    }
    fputs(",\n\"nodes\":[\n", f);
    for (uint32_t i = 0; i < S->n_nodes; i++) {
        const wk_node *v = &S->nodes[wk_stored_node(P, vertex_of, i)];
        fputc('[', f);
        put_double(f, v->x);
        fputc(',', f);
        put_double(f, v->y);
        fputc(',', f);
        put_double(f, v->t);
        fputs(i + 1 < S->n_nodes ? "],\n" : "]\n", f);
    }
    fputs("],\n\"arcs\":[\n", f);
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        fprintf(f, "[%u,%u,%lld,%lld]%s\n", wk_polygon_output_node(P, c->a),
                wk_polygon_output_node(P, c->b), wk_write_face(P, c->left),
                wk_write_face(P, c->right), i + 1 < S->n_arcs ? "," : "");
    }
    fputs("],\n\"stats\":", f);
    if (!info) {
        fputs("null", f);
    } else {
        fputc('{', f);
        if (info->counters)
            for (uint32_t i = 0; i < wk_counter_count(info->counters_of); i++)
                fprintf(f, "\"%s\":%llu,", wk_counter_def_at(info->counters_of, i)->name,
                        (unsigned long long)info->counters->c[i]);
        fputs("\"time_s\":", f);
        put_double(f, info->time_s);
        fprintf(f, ",\"peak_bytes\":%zu}", info->peak_bytes);
    }
    fputs("}\n", f);
    WK_FREE_ARRAY(R, vertex_of, P->n);
    return wk_write_end(R, f, "json");
}
