/*
** write.h: what the writers (write_*.c) share; engine-private.
**
** Every writer emits input numbering (wk_polygon_output_node,
** wk_polygon_input_edge), refuses a skeleton whose ids are out of range (a
** finished skeleton never has any), and ends by flushing and checking the
** stream, so a full disk or a closed pipe is a failure (WK_EALGO "write
** failed") rather than a silently truncated file.  Writers never close f.
*/
#ifndef WK_WRITE_H
#define WK_WRITE_H
#include "faces.h"

#include <errno.h>
#include <string.h>

/* s as a JSON string (quotes, backslashes and control characters escaped;
** the JSON and GeoJSON writers). */
static inline void wk_write_json_string(FILE *f, const char *s) {
    fputc('"', f);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\') fprintf(f, "\\%c", *c);
        else if (*c < 0x20) fprintf(f, "\\u%04x", *c);
        else fputc(*c, f);
    }
    fputc('"', f);
}

/* The checks every writer runs before writing anything. */
static inline wk_status wk_write_begin(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                       const char *what) {
    errno = 0; /* so that wk_write_end reports this stream's error */
    for (uint32_t i = 0; i < S->n_arcs; i++)
        if (S->arcs[i].left == WK_NONE || S->arcs[i].right == WK_NONE)
            return WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                           "%sa roof cut at a height (its cap, --height) is not written in this "
                           "format yet; use --format json, text, obj or vtp",
                           what);
    return wk_faces_check_ids(R, P, S, what);
}

/* The faces of a roof cut at a height (write_obj_capped.c): faces
** 0 .. n_edge_faces-1 are the input edges' in input edge order, the rest
** the cap's faces (a counter-clockwise cycle, its holes bridged in); face
** f is node[end[f-1] .. end[f]) (stored node ids), counter-clockwise seen
** from above.  WK_EUNSUPPORTED for a face that is
** not one simple cycle. */
typedef struct wk_capped_faces {
    uint32_t *node, *end;
    uint32_t n_node, cap_node, n_faces, cap_end, n_edge_faces;
} wk_capped_faces;
wk_status wk_capped_faces_build(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                const uint32_t *edge_of, wk_capped_faces *CF, const char *what);
void wk_capped_faces_clear(wk_run *R, wk_capped_faces *CF);
/* The OBJ roof of a skeleton with a cap (write_obj_capped.c). */
wk_status wk_write_obj_capped(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S);

/* For the writers that can show a cap (json, text): the checks of
** wk_write_begin, except that one side of an arc may be WK_NONE (the cap of
** a skeleton cut at a height, wk_options.height). */
static inline wk_status wk_write_begin_capped(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                              const char *what) {
    errno = 0;
    if (S->n_input != P->n || S->n_nodes < P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0, "%sthe skeleton is not of this polygon", what);
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        bool faces_ok = (c->left < P->n || c->left == WK_NONE) &&
                        (c->right < P->n || c->right == WK_NONE) && c->left != c->right;
        if (c->a >= S->n_nodes || c->b >= S->n_nodes || c->a == c->b || !faces_ok)
            return WK_FAIL(R, WK_EINVALID, P->name, 0, "%sarc %u [%u, %u, %u, %u] is malformed",
                           what, i, c->a, c->b, c->left, c->right);
    }
    return WK_OK;
}

/* A face in output numbering: the input edge, or -1 for the cap. */
static inline long long wk_write_face(const wk_polygon *P, uint32_t e) {
    return e == WK_NONE ? -1 : (long long)wk_polygon_input_edge(P, e);
}

/* Flush f and report any error the stream has seen since it was opened. */
static inline wk_status wk_write_end(wk_run *R, FILE *f, const char *format) {
    if (fflush(f) != 0 || ferror(f))
        return WK_FAIL(R, WK_EALGO, NULL, 0, "write failed (%s output): %s", format,
                       errno ? strerror(errno) : "stream error");
    return WK_OK;
}

/* The polygon's name on a comment line: control characters become '?'. */
static inline void wk_write_name(FILE *f, const wk_polygon *P) {
    for (const unsigned char *c = (const unsigned char *)(P->name[0] ? P->name : "polygon"); *c;
         c++)
        fputc(*c < 0x20 ? '?' : *c, f);
}

/* The stored node whose output id is i, given vertex_of from wk_input_order
** (the inverse of wk_polygon_output_node). */
static inline uint32_t wk_stored_node(const wk_polygon *P, const uint32_t *vertex_of, uint32_t i) {
    return i < P->n ? vertex_of[i] : i;
}

#endif
