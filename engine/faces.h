/*
** faces.h: derived views of a finished skeleton that the validator and the
** writers share (engine-private; not part of the public API in wskel.h).
**
** A face is the region swept by one input edge's wavefront.  Its boundary,
** as a node cycle, is the edge itself (node e -> node next(e)) followed by the
** path of arcs labelled e from node next(e) back to node e, each arc oriented so
** that the face lies on its left: an arc with left == e is walked a -> b,
** one with right == e is walked b -> a.  Every arc lies on exactly two face
** cycles, once in each direction, so the cycles sum (as chains) to the
** polygon boundary; the validator relies on this.
**
** wk_faces holds all n cycles in one compressed array, built in
** O(arcs log(largest face)) by bucketing the arcs by edge.  wk_face_cycle
** (wskel.h) builds a single face in O(arcs); calling it for every edge is
** quadratic, so code that needs all faces uses wk_faces_build.
*/
#ifndef WK_FACES_H
#define WK_FACES_H
#include "wskel.h"

/* A face with islands (a weighted skeleton of a polygon with holes can be
** disconnected: a hole's faces inside a faster edge's face) has, besides the
** path from its edge, closed loops of arcs around each island; its cycle is
** then one weakly simple cycle with each loop joined to the outer path by a
** bridge, two opposite sides u -> q -> ... -> q -> u along one segment that
** no arc crosses, and bridge[] flags those sides (the validator's
** planarity test skips them; areas are unchanged, as the two cancel). */
typedef struct wk_faces {
    uint32_t n;        /* faces = polygon edges */
    uint32_t *start;   /* n + 1 offsets: face e is node[start[e] .. start[e+1]) */
    uint32_t *node;    /* every cycle, face e's beginning with nodes e, next(e) */
    uint8_t *bridge;   /* bridge[i]: side node[i] -> its successor is a bridge;
                          NULL when no face has an island */
    uint32_t cap_node, cap_bridge; /* allocated entries */
} wk_faces;

/* Check that S fits P (n_input == n <= n_nodes) and that every arc has node
** ids < S->n_nodes, a != b, face ids < P->n and left != right: what any code
** indexing arrays by these ids needs.  A PSLG's cap arcs (the wavefront at
** its horizon) have WK_NONE on their left: accepted, and wk_faces_build
** puts them on their right face's cycle only.  what prefixes the message (e.g.
** "validate (c): ").  Fails with WK_EINVALID naming the first bad arc. */
wk_status wk_faces_check_ids(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                             const char *what);

/* Build every face cycle of S (stored numbering), after checking the ids as
** wk_faces_check_ids does.  On failure F is left empty (zeroed) and R->err
** says which face is broken and why (WK_EINVALID, message prefixed by what),
** or WK_ENOMEM.  Free with wk_faces_clear. */
wk_status wk_faces_build(wk_run *R, const wk_polygon *P, const wk_skeleton *S, wk_faces *F,
                         const char *what);
/* Free F's arrays; accepts a zeroed or cleared F. */
void wk_faces_clear(wk_run *R, wk_faces *F);

/* Bridge the closed node cycle lp[0 .. L) (clockwise: an island of face e,
** or with e == WK_NONE a hole of a cap face) into the counter-clockwise
** cycle cyc[0 .. *len) (room *len + L + 2; flag[] the same room, set for
** the two bridge sides), the hole-to-outer bridge of ear clipping.  Bridge
** several loops by decreasing max x (faces.c says why). */
wk_status wk_bridge_loop(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t e,
                         uint32_t *cyc, uint8_t *flag, uint32_t *len, const uint32_t *lp,
                         uint32_t L, const char *what);

/* Signed area of a node cycle in the xy projection (positive when
** counter-clockwise), computed relative to its first node. */
double wk_cycle_area(const wk_skeleton *S, const uint32_t *cycle, uint32_t len);

/* True if arc i is traced by a reflex wavefront vertex.  Oriented so that
** time grows from a to b, the arc has the edge before its wavefront vertex
** (counter-clockwise order) on its left and the edge after it on its right;
** the vertex is reflex iff those edges turn right: cross(dir left, dir
** right) < 0.  Arcs at constant time (ridges between parallel edges) and arcs
** with invalid labels count as convex.  A drawing aid: plain doubles. */
bool wk_arc_is_reflex(const wk_polygon *P, const wk_skeleton *S, uint32_t i);

/* Inverse of the input numbering: vertex_of[i] is the stored vertex that is
** input vertex i, edge_of[i] the stored edge that is input edge i (both
** n-element arrays allocated through R; free with WK_FREE_ARRAY(R, x, P->n)).
** Either pointer may be NULL when not wanted.  WK_EALGO if the polygon's
** numbering is not a permutation (defensive: the polygon module's bug). */
wk_status wk_input_order(wk_run *R, const wk_polygon *P, uint32_t **vertex_of,
                         uint32_t **edge_of);

#endif
