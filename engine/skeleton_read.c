/*
** skeleton_read.c: a wskel-1 JSON skeleton (write_json.c) read back against
** its polygon, so that a skeleton written by any program (a variant, an
** older build, CGAL's driver) can be validated on its own:
** `wskel --validate SKEL.json POLY`.
**
** The file is in input numbering (nodes[0..n) the input vertices in input
** order, faces the input edges, -1 none); the skeleton returned is in stored
** numbering, as the validator expects.  The reader only decodes: every
** property (input nodes equal to the vertices, ids in range, ...) is left
** to wk_validate, so a wrong file is reported as the validator's finding.
** What it refuses (WK_EINPUT, naming the file): JSON it cannot parse, a
** missing or mistyped "nodes" or "arcs", an "n" that is not the polygon's
** vertex count, fewer nodes than vertices, a negative node id, a PSLG's
** skeleton (its corner numbering is not read back).
*/
#include "faces.h"

#include <jansson.h>
#include <math.h>

/* A JSON number as a double; null (how write_json.c writes a non-finite
** value) as NaN, so that the validator names the node. */
static bool get_num(json_t *v, double *out) {
    if (json_is_null(v)) {
        *out = NAN;
        return true;
    }
    if (!json_is_number(v)) return false;
    *out = json_number_value(v);
    return true;
}

/* A face in input numbering: -1 (none) or an input edge; ids beyond n are
** kept (the validator rejects them). */
static bool get_face(json_t *v, const uint32_t *edge_of, uint32_t n, uint32_t *out) {
    if (!json_is_integer(v)) return false;
    json_int_t f = json_integer_value(v);
    if (f < -1 || f > (json_int_t)UINT32_MAX - 1) return false;
    *out = f == -1 ? WK_NONE : (uint32_t)f < n ? edge_of[f] : (uint32_t)f;
    return true;
}

static bool get_node_id(json_t *v, const uint32_t *vertex_of, uint32_t n, uint32_t *out) {
    if (!json_is_integer(v)) return false;
    json_int_t a = json_integer_value(v);
    if (a < 0 || a > (json_int_t)UINT32_MAX - 1) return false;
    *out = (uint32_t)a < n ? vertex_of[a] : (uint32_t)a;
    return true;
}

wk_status wk_skeleton_read_json(wk_run *R, const wk_polygon *P, const char *path,
                                wk_skeleton **out) {
    *out = NULL;
    if (P->pslg)
        return WK_FAIL(R, WK_EINPUT, path, 0,
                       "reading a PSLG's skeleton back is not supported (polygons only)");
    json_error_t jerr;
    json_t *root = json_load_file(path, JSON_REJECT_DUPLICATES, &jerr);
    if (!root) return WK_FAIL(R, WK_EINPUT, path, jerr.line, "JSON: %s", jerr.text);
    uint32_t *vertex_of = NULL, *edge_of = NULL;
    wk_skeleton *S = NULL;
    wk_status st = WK_OK;
    json_t *nodes = json_object_get(root, "nodes"), *arcs = json_object_get(root, "arcs");
    json_t *n = json_object_get(root, "n");
    if (!json_is_object(root) || !json_is_array(nodes) || !json_is_array(arcs)) {
        st = WK_FAIL(R, WK_EINPUT, path, 0, "not a wskel-1 skeleton (no \"nodes\" and \"arcs\" arrays)");
        goto done;
    }
    if (n && (!json_is_integer(n) || json_integer_value(n) != (json_int_t)P->n)) {
        st = WK_FAIL(R, WK_EINPUT, path, 0,
                     "the skeleton is of a polygon with n = %lld vertices, this polygon has %u",
                     json_is_integer(n) ? (long long)json_integer_value(n) : -1LL, P->n);
        goto done;
    }
    size_t nn = json_array_size(nodes), na = json_array_size(arcs);
    if (nn < P->n || nn > UINT32_MAX - 1 || na > UINT32_MAX - 1) {
        st = WK_FAIL(R, WK_EINPUT, path, 0,
                     "%zu nodes and %zu arcs: the first %u nodes must be the input vertices", nn,
                     na, P->n);
        goto done;
    }
    if (wk_input_order(R, P, &vertex_of, &edge_of) != WK_OK ||
        wk_skeleton_new(R, P, &S) != WK_OK) {
        st = R->err.code;
        goto done;
    }
    for (size_t i = 0; i < nn && st == WK_OK; i++) {
        json_t *v = json_array_get(nodes, i);
        double x, y, t;
        if (!json_is_array(v) || json_array_size(v) != 3 || !get_num(json_array_get(v, 0), &x) ||
            !get_num(json_array_get(v, 1), &y) || !get_num(json_array_get(v, 2), &t)) {
            st = WK_FAIL(R, WK_EINPUT, path, 0, "nodes[%zu] is not [x, y, t]", i);
            break;
        }
        if (i < P->n) S->nodes[vertex_of[i]] = (wk_node){x, y, t};
        else {
            uint32_t id;
            st = wk_skeleton_add_node(R, S, x, y, t, &id);
        }
    }
    for (size_t i = 0; i < na && st == WK_OK; i++) {
        json_t *c = json_array_get(arcs, i);
        uint32_t a, b, l, r;
        if (!json_is_array(c) || json_array_size(c) != 4 ||
            !get_node_id(json_array_get(c, 0), vertex_of, P->n, &a) ||
            !get_node_id(json_array_get(c, 1), vertex_of, P->n, &b) ||
            !get_face(json_array_get(c, 2), edge_of, P->n, &l) ||
            !get_face(json_array_get(c, 3), edge_of, P->n, &r)) {
            st = WK_FAIL(R, WK_EINPUT, path, 0,
                         "arcs[%zu] is not [a, b, left, right] (node ids >= 0, faces >= -1)", i);
            break;
        }
        st = wk_skeleton_add_arc(R, S, a, b, l, r);
    }
done:
    json_decref(root);
    if (vertex_of) WK_FREE_ARRAY(R, vertex_of, P->n);
    if (edge_of) WK_FREE_ARRAY(R, edge_of, P->n);
    if (st != WK_OK) {
        if (S) wk_skeleton_free(R, S);
        return st;
    }
    *out = S;
    return WK_OK;
}
