/*
** write_vtp.c: the skeleton and its roof as VTK XML PolyData (ASCII), for
** ParaView and VTK's vtkXMLPolyDataReader.
**
** Points: the nodes in output numbering, lifted to (x, y, t); point data
** "t" (Float64) repeats the time for colouring.
** Cells, in VTK's cell order (verts, lines, strips, polys; this file has no
** verts or strips), so cell data arrays run in the same order:
**   cells [0, n):          lines, the polygon boundary, input edge i from
**                           input vertex i to i+1 (mod n);
**   cells [n, n + M):      lines, the M arcs in skeleton order;
**   cells [n + M, 2n + M): polygons, the roof face of input edge i (its face
**                           cycle, counter-clockwise seen from above).
** Cell data: "edge_id" (Int32): the input edge for boundary lines and roof
** faces, -1 for arcs (an arc has two); "kind" (Int32): 0 boundary, 1 convex
** arc, 2 reflex arc (see wk_arc_is_reflex), 3 roof face, 4 the cap (an arc
** or a face of the cap of a roof cut at a height, --height: then the cells
** after the n roof faces are the cap's faces, edge_id -1; a PSLG's skeleton
** is cut at its horizon the same way, boundary lines and roof faces then
** per stored half-edge or cap, see wk_capped_faces_build).
** Connectivity and offsets are Int64, the VTK 9 default.
*/
#include "write.h"

enum { KIND_BOUNDARY = 0, KIND_CONVEX = 1, KIND_REFLEX = 2, KIND_ROOF = 3, KIND_CAP = 4 };

static void open_array(FILE *f, const char *type, const char *name) {
    fprintf(f, "<DataArray type=\"%s\" Name=\"%s\" format=\"ascii\">\n", type, name);
}

static bool is_cap(const wk_arc *c) { return c->left == WK_NONE || c->right == WK_NONE; }

/* Points (the nodes in output numbering at (x, y, t)) and the line cells
** (boundary, then arcs), the same with and without a cap. */
static void put_points_and_lines(FILE *f, const wk_polygon *P, const wk_skeleton *S,
                                 const uint32_t *vertex_of) {
    uint32_t n = P->n, N = S->n_nodes, M = S->n_arcs;
    fputs("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", f);
    for (uint32_t i = 0; i < N; i++) {
        const wk_node *v = &S->nodes[wk_stored_node(P, vertex_of, i)];
        fprintf(f, "%.17g %.17g %.17g\n", v->x, v->y, v->t);
    }
    fputs("</DataArray>\n</Points>\n", f);
    fputs("<Lines>\n", f);
    open_array(f, "Int64", "connectivity");
    /* input vertex i to the next of its ring: input numbering keeps each
    ** ring's index range, so wk_polygon_next's arithmetic holds for it */
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%u %u\n", i, wk_polygon_next(P, i));
    for (uint32_t i = 0; i < M; i++)
        fprintf(f, "%u %u\n", wk_polygon_output_node(P, S->arcs[i].a),
                wk_polygon_output_node(P, S->arcs[i].b));
    fputs("</DataArray>\n", f);
    open_array(f, "Int64", "offsets");
    for (uint64_t i = 1; i <= (uint64_t)n + M; i++) fprintf(f, "%llu\n", (unsigned long long)(2 * i));
    fputs("</DataArray>\n</Lines>\n", f);
}

/* The same file for a roof cut at a height: faces from
** wk_capped_faces_build, the cap's arcs and faces of kind KIND_CAP. */
static wk_status write_vtp_capped(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    uint32_t *vertex_of = NULL, *edge_of = NULL, n = P->n, N = S->n_nodes, M = S->n_arcs;
    wk_capped_faces CF;
    if (wk_write_begin_capped(R, P, S, "write vtp: ") != WK_OK ||
        wk_input_order(R, P, &vertex_of, &edge_of) != WK_OK)
        return R->err.code;
    wk_status st = wk_capped_faces_build(R, P, S, edge_of, &CF, "write vtp: ");
    if (st != WK_OK) goto out;
    fputs("<?xml version=\"1.0\"?>\n"
          "<!-- wskel: weighted straight skeleton and roof cut at a height; cells: n boundary "
          "lines, the arcs, n roof faces, the cap's faces -->\n"
          "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "<PolyData>\n",
          f);
    fprintf(f,
            "<Piece NumberOfPoints=\"%u\" NumberOfVerts=\"0\" NumberOfLines=\"%llu\" "
            "NumberOfStrips=\"0\" NumberOfPolys=\"%u\">\n",
            N, (unsigned long long)n + M, CF.n_faces);
    fputs("<PointData Scalars=\"t\">\n", f);
    open_array(f, "Float64", "t");
    for (uint32_t i = 0; i < N; i++)
        fprintf(f, "%.17g\n", S->nodes[wk_stored_node(P, vertex_of, i)].t);
    fputs("</DataArray>\n</PointData>\n", f);
    fputs("<CellData Scalars=\"kind\">\n", f);
    open_array(f, "Int32", "edge_id");
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%u\n", i);
    for (uint32_t i = 0; i < M; i++) fputs("-1\n", f);
    for (uint32_t i = 0; i < CF.n_faces; i++) fprintf(f, "%lld\n", i < n ? (long long)i : -1LL);
    fputs("</DataArray>\n", f);
    open_array(f, "Int32", "kind");
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%d\n", KIND_BOUNDARY);
    for (uint32_t i = 0; i < M; i++)
        fprintf(f, "%d\n", is_cap(&S->arcs[i])          ? KIND_CAP
                           : wk_arc_is_reflex(P, S, i) ? KIND_REFLEX
                                                       : KIND_CONVEX);
    for (uint32_t i = 0; i < CF.n_faces; i++) fprintf(f, "%d\n", i < n ? KIND_ROOF : KIND_CAP);
    fputs("</DataArray>\n</CellData>\n", f);
    put_points_and_lines(f, P, S, vertex_of);
    fputs("<Polys>\n", f);
    open_array(f, "Int64", "connectivity");
    for (uint32_t fi = 0; fi < CF.n_faces; fi++)
        for (uint32_t k = fi ? CF.end[fi - 1] : 0; k < CF.end[fi]; k++)
            fprintf(f, "%u%c", wk_polygon_output_node(P, CF.node[k]), k + 1 < CF.end[fi] ? ' ' : '\n');
    fputs("</DataArray>\n", f);
    open_array(f, "Int64", "offsets");
    for (uint32_t fi = 0; fi < CF.n_faces; fi++) fprintf(f, "%u\n", CF.end[fi]);
    fputs("</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n", f);
    st = wk_write_end(R, f, "vtp");
    wk_capped_faces_clear(R, &CF);
out:
    WK_FREE_ARRAY(R, vertex_of, n);
    WK_FREE_ARRAY(R, edge_of, n);
    return st;
}

wk_status wk_write_vtp(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S) {
    uint32_t *vertex_of = NULL, *edge_of = NULL, n = P->n, N = S->n_nodes, M = S->n_arcs;
    for (uint32_t i = 0; i < M; i++)
        if (is_cap(&S->arcs[i])) return write_vtp_capped(R, f, P, S);
    wk_faces F;
    if (wk_write_begin(R, P, S, "write vtp: ") != WK_OK ||
        wk_faces_build(R, P, S, &F, "write vtp: ") != WK_OK)
        return R->err.code;
    if (wk_input_order(R, P, &vertex_of, &edge_of) != WK_OK) {
        wk_faces_clear(R, &F);
        return R->err.code;
    }

    fputs("<?xml version=\"1.0\"?>\n"
          "<!-- wskel: weighted straight skeleton and roof; cells: n boundary lines, the arcs, "
          "n roof faces -->\n"
          "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "<PolyData>\n",
          f);
    fprintf(f,
            "<Piece NumberOfPoints=\"%u\" NumberOfVerts=\"0\" NumberOfLines=\"%llu\" "
            "NumberOfStrips=\"0\" NumberOfPolys=\"%u\">\n",
            N, (unsigned long long)n + M, n);

    fputs("<PointData Scalars=\"t\">\n", f);
    open_array(f, "Float64", "t");
    for (uint32_t i = 0; i < N; i++)
        fprintf(f, "%.17g\n", S->nodes[wk_stored_node(P, vertex_of, i)].t);
    fputs("</DataArray>\n</PointData>\n", f);

    fputs("<CellData Scalars=\"kind\">\n", f);
    open_array(f, "Int32", "edge_id");
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%u\n", i);
    for (uint32_t i = 0; i < M; i++) fputs("-1\n", f);
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%u\n", i);
    fputs("</DataArray>\n", f);
    open_array(f, "Int32", "kind");
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%d\n", KIND_BOUNDARY);
    for (uint32_t i = 0; i < M; i++)
        fprintf(f, "%d\n", wk_arc_is_reflex(P, S, i) ? KIND_REFLEX : KIND_CONVEX);
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%d\n", KIND_ROOF);
    fputs("</DataArray>\n</CellData>\n", f);

    put_points_and_lines(f, P, S, vertex_of);

    fputs("<Polys>\n", f);
    open_array(f, "Int64", "connectivity");
    for (uint32_t i = 0; i < n; i++) {
        uint32_t e = edge_of[i];
        for (uint32_t k = F.start[e]; k < F.start[e + 1]; k++)
            fprintf(f, "%u%c", wk_polygon_output_node(P, F.node[k]), k + 1 < F.start[e + 1] ? ' ' : '\n');
    }
    fputs("</DataArray>\n", f);
    open_array(f, "Int64", "offsets");
    uint64_t off = 0;
    for (uint32_t i = 0; i < n; i++) {
        off += F.start[edge_of[i] + 1] - F.start[edge_of[i]];
        fprintf(f, "%llu\n", (unsigned long long)off);
    }
    fputs("</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n", f);

    WK_FREE_ARRAY(R, vertex_of, n);
    WK_FREE_ARRAY(R, edge_of, n);
    wk_faces_clear(R, &F);
    return wk_write_end(R, f, "vtp");
}
