/*
** write_gis.c: skeletons and offsets in the formats GIS tools read
** (GeoJSON, RFC 7946, and WKT, OGC Simple Features), %.17g so they
** round-trip.
**
** Skeleton, GeoJSON: a FeatureCollection with one Feature per arc, in arc
** order; geometry a LineString of two XYZ positions [x, y, t] (t, the
** node's time, as the third coordinate: what PostGIS/SFCGAL's
** ST_StraightSkeleton does with Z for the height of the roof), properties
** {"a": node, "b": node, "left": edge, "right": edge} in input numbering
** (as the json and text formats).  A "wskel" member at the top names the
** polygon and the counts.  A PSLG's skeleton (wk_polygon.pslg) has its cap,
** the wavefront at the horizon: those arcs have "left": -1.
** Skeleton, WKT: one line, MULTILINESTRING Z with one two-point line per arc
** in arc order (x y t).
** Offsets, GeoJSON: a FeatureCollection with one Feature per time, in the
** order given; geometry a MultiPolygon (one polygon per component: outer
** ring counter-clockwise, then its holes clockwise, every ring closed by
** repeating its first position, as RFC 7946 requires), properties {"t": t}.
** An empty offset is a MultiPolygon with no polygons.
** Offsets, WKT: one MULTIPOLYGON line per time, in the order given
** (MULTIPOLYGON EMPTY when empty), rings closed.
*/
#include "write.h"

wk_status wk_write_geojson(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    /* a PSLG's skeleton has its cap (the wavefront at the horizon): left -1 */
    if ((P->pslg ? wk_write_begin_capped(R, P, S, "write geojson: ")
                 : wk_write_begin(R, P, S, "write geojson: ")) != WK_OK)
        return R->err.code;
    fputs("{\"type\": \"FeatureCollection\",\n \"wskel\": {\"polygon\": ", f);
    wk_write_json_string(f, P->name[0] ? P->name : "polygon");
    fprintf(f, ", \"n\": %u, \"nodes\": %u, \"arcs\": %u, \"z\": \"t\"},\n \"features\": [", P->n,
            S->n_nodes, S->n_arcs);
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        const wk_node *a = &S->nodes[c->a], *b = &S->nodes[c->b];
        fprintf(f,
                "%s\n  {\"type\": \"Feature\", \"properties\": {\"a\": %u, \"b\": %u, \"left\": %lld, "
                "\"right\": %lld}, \"geometry\": {\"type\": \"LineString\", \"coordinates\": "
                "[[%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g]]}}",
                i ? "," : "", wk_polygon_output_node(P, c->a), wk_polygon_output_node(P, c->b),
                wk_write_face(P, c->left), wk_write_face(P, c->right), a->x, a->y, a->t, b->x, b->y,
                b->t);
    }
    fputs("\n ]}\n", f);
    return wk_write_end(R, f, "geojson");
}

wk_status wk_write_wkt(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    if ((P->pslg ? wk_write_begin_capped(R, P, S, "write wkt: ")
                 : wk_write_begin(R, P, S, "write wkt: ")) != WK_OK)
        return R->err.code;
    if (!S->n_arcs) {
        fputs("MULTILINESTRING Z EMPTY\n", f);
    } else {
        fputs("MULTILINESTRING Z (", f);
        for (uint32_t i = 0; i < S->n_arcs; i++) {
            const wk_node *a = &S->nodes[S->arcs[i].a], *b = &S->nodes[S->arcs[i].b];
            fprintf(f, "%s(%.17g %.17g %.17g, %.17g %.17g %.17g)", i ? ", " : "", a->x, a->y, a->t,
                    b->x, b->y, b->t);
        }
        fputs(")\n", f);
    }
    return wk_write_end(R, f, "wkt");
}

/* Ring k of O, closed: GeoJSON positions or WKT points. */
static void put_ring(FILE *f, const wk_offset_set *O, uint32_t k, bool json) {
    uint32_t s = O->ring_start[k], e = O->ring_start[k + 1];
    fputs(json ? "[" : "(", f);
    for (uint32_t j = s; j <= e; j++) {
        wk_point q = O->p[j == e ? s : j];
        if (json) fprintf(f, "%s[%.17g, %.17g]", j > s ? ", " : "", q.x, q.y);
        else fprintf(f, "%s%.17g %.17g", j > s ? ", " : "", q.x, q.y);
    }
    fputs(json ? "]" : ")", f);
}

static void put_polygons(FILE *f, const wk_offset_set *O, bool json) {
    for (uint32_t c = 0; c < O->n_polygons; c++) {
        fputs(c ? (json ? ",\n    [" : ", (") : (json ? "\n    [" : "("), f);
        for (uint32_t k = O->polygon_start[c]; k < O->polygon_start[c + 1]; k++) {
            if (k > O->polygon_start[c]) fputs(", ", f);
            put_ring(f, O, k, json);
        }
        fputs(json ? "]" : ")", f);
    }
}

wk_status wk_write_offsets_geojson(wk_run *R, FILE *f, const wk_polygon *P,
                                   wk_offset_set *const *O, uint32_t n_sets) {
    errno = 0;
    fputs("{\"type\": \"FeatureCollection\",\n \"wskel\": {\"polygon\": ", f);
    wk_write_json_string(f, P->name[0] ? P->name : "polygon");
    fputs(", \"offsets\": true},\n \"features\": [", f);
    for (uint32_t i = 0; i < n_sets; i++) {
        fprintf(f,
                "%s\n  {\"type\": \"Feature\", \"properties\": {\"t\": %.17g}, \"geometry\": "
                "{\"type\": \"MultiPolygon\", \"coordinates\": [",
                i ? "," : "", O[i]->t);
        put_polygons(f, O[i], true);
        fputs("]}}", f);
    }
    fputs("\n ]}\n", f);
    return wk_write_end(R, f, "geojson");
}

wk_status wk_write_offsets_wkt(wk_run *R, FILE *f, wk_offset_set *const *O, uint32_t n_sets) {
    errno = 0;
    for (uint32_t i = 0; i < n_sets; i++) {
        if (!O[i]->n_polygons) {
            fputs("MULTIPOLYGON EMPTY\n", f);
            continue;
        }
        fputs("MULTIPOLYGON (", f);
        put_polygons(f, O[i], false);
        fputs(")\n", f);
    }
    return wk_write_end(R, f, "wkt");
}
