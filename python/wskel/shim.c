/*
** shim.c: the flat C interface the Python binding (python/wskel/__init__.py)
** calls through ctypes, compiled with the library into
** python/wskel/_libwskel.so by `make python`.
**
** Why a shim: ctypes would otherwise have to mirror wk_run, wk_polygon and
** wk_skeleton field by field and follow every change to them.  Here Python
** sees one opaque handle and passes and receives plain arrays only:
**
**   h = wks_new()                         one handle = one wk_run
**   wks_solve(h, rings, x, y, w, ...)     polygon + skeleton, kept in h
**   wks_solve_pslg(h, nv, x, y, ne, ...)  the same for a PSLG (nodes and
**                                         edges), up to a time horizon;
**   wks_pslg_sizes / wks_pslg_copy        its horizon, rings, corners' nodes
**                                         and stored edges' input edges
**   wks_nodes / wks_arcs / wks_counter_*  copy results into caller arrays
**   wks_offset(h, t) + wks_offset_copy    the wavefront at time t
**   wks_roof(h) + wks_roof_copy           one face cycle per input edge (a
**                                         PSLG: per stored edge, then the
**                                         cap's faces at the horizon)
**   wks_error_*                           h's first failure (R->err)
**   wks_close(h)                          frees everything; returns the
**                                         run's live bytes (0 = no leak)
**
** Numbering: everything handed out uses input numbering (as the writers
** do): node i < n is input vertex i (the i-th point of the concatenated
** rings), arcs name nodes by wk_polygon_output_node and faces by
** wk_polygon_input_edge, face cycles list output node ids.  A PSLG's output
** numbering is its stored numbering (engine/pslg.c): nodes i < n are the
** corners of its initial wavefront, edges its half-edges and caps; an arc
** of the cap (the wavefront at the horizon) has WK_NONE on its left.
**
** Memory: every object of the computation goes through the run's counting
** allocator; the handle itself (which holds the run) is the one block from
** libc calloc, freed by wks_close.  A handle is used by one thread at a time.
*/
#include <stdlib.h>
#include <string.h>

#include "wskel.h"
/* engine-private, for wk_capped_faces_build: a PSLG's roof is the same list
** of faces that the OBJ writer writes (its edges' faces, then the cap's). */
#include "write.h"

typedef struct wks_handle {
    wk_run R;
    wk_alloc_debug_state dbg; /* the debug backend's, for wks_new_checked */
    const wk_variant *V;  /* set by wks_solve */
    wk_polygon *P;
    wk_skeleton *S;
    wk_offset_set *O;     /* the last wks_offset's, freed by the next or by close */
    uint32_t *face_start; /* roof: n_faces + 1 offsets into face_node */
    uint32_t *face_node;
    uint32_t n_face_node;
    uint32_t n_faces;     /* roof faces: P->n, a PSLG's P->n + its cap faces */
    double time_s;
    size_t peak_bytes;
} wks_handle;

wks_handle *wks_new(void) {
    wks_handle *h = calloc(1, sizeof *h);
    if (h) wk_run_init(&h->R);
    return h;
}

/* For tests: a handle whose run uses the debug allocator backend (sizes
** checked on every free, guard bytes; see engine/wskel.h), refusing its
** fail_at-th allocation request (0: none), so that every failure path of
** the shim can be driven.  Not strict: a leak is reported by wks_close's
** return value, not by an abort that would take the interpreter down. */
wks_handle *wks_new_checked(uint64_t fail_at) {
    wks_handle *h = wks_new();
    if (!h) return NULL;
    h->dbg.fail_at = fail_at;
    h->R.alloc.backend = &wk_alloc_debug; /* no block is live yet */
    h->R.alloc.ud = &h->dbg;
    return h;
}
/* Allocation requests the debug backend has seen (wks_new_checked). */
uint64_t wks_alloc_requests(const wks_handle *h) { return h->dbg.requests; }

static void free_roof(wks_handle *h) {
    if (h->face_node) WK_FREE_ARRAY(&h->R, h->face_node, h->n_face_node);
    if (h->face_start) WK_FREE_ARRAY(&h->R, h->face_start, h->n_faces + 1);
    h->face_node = h->face_start = NULL;
    h->n_face_node = h->n_faces = 0;
}

size_t wks_close(wks_handle *h) {
    if (!h) return 0;
    free_roof(h);
    wk_offset_set_free(&h->R, h->O);
    wk_skeleton_free(&h->R, h->S);
    wk_polygon_free(&h->R, h->P);
    size_t live = wk_run_close(&h->R);
    free(h);
    return live;
}

/* ------------------------------------------------------------------ solve */

/* Build the polygon (n_rings rings of ring_size[k] points, ring 0 outer; w
** NULL for unit weights) and solve it with the named variant.  k: 0 leaves
** the default, WK_K_MAX is "max".  check: wk_solve_checked with the CLI's
** default tolerance, else plain wk_solve.  Returns the status; on failure
** the error accessors describe it. */
int wks_solve(wks_handle *h, uint32_t n_rings, const uint32_t *ring_size, const double *x,
              const double *y, const double *w, const char *name, const char *variant,
              uint32_t k, int threads, int check) {
    wk_run *R = &h->R;
    if (h->P) return WK_FAIL(R, WK_EUSAGE, "", 0, "wks_solve called twice on one handle");
    h->V = wk_variant_find(variant);
    if (!h->V) return WK_FAIL(R, WK_EUSAGE, "", 0, "unknown variant '%s'", variant);
    if (k) R->opt.k = k;
    if (threads > 0) R->opt.threads = threads;
    if (n_rings == 0) return WK_FAIL(R, WK_EINPUT, name, 0, "no outer ring given");
    wk_status st = wk_polygon_from_rings(R, n_rings, ring_size, x, y, w, name, NULL, &h->P);
    if (st != WK_OK) return st;
    if (!(wk_variant_flags(h->V) & WK_VARIANT_WEIGHTS))
        for (uint32_t i = 0; i < h->P->n; i++)
            if (h->P->w[i] != 1.0)
                return WK_FAIL(R, WK_EALGO, h->P->name, 0,
                               "variant %s supports unit weights only (edge %u has weight %g)",
                               wk_variant_name(h->V), wk_polygon_input_edge(h->P, i), h->P->w[i]);
    if (check)
        return wk_solve_checked(R, h->V, h->P, WK_VALIDATE_TOL_REL * wk_polygon_scale(h->P), &h->S,
                                &h->time_s, &h->peak_bytes, NULL);
    return wk_solve(R, h->V, h->P, &h->S, &h->time_s, &h->peak_bytes);
}

/* A PSLG: nv nodes (x, y), ne edges src[i] - dst[i] of weight w[i] (w NULL:
** unit weights), built by wk_pslg_from_arrays (the GraphML reader's path:
** nodes and edges in document order give the CLI's skeleton), solved up
** to the horizon until (0: the default horizon, engine/pslg.c) with the
** named variant; a variant without WK_VARIANT_PSLG is refused by wk_solve
** (WK_EUNSUPPORTED).  check as for wks_solve (the PSLG validator). */
int wks_solve_pslg(wks_handle *h, uint32_t nv, const double *x, const double *y, uint32_t ne,
                   const uint32_t *src, const uint32_t *dst, const double *w, const char *name,
                   const char *variant, double until, int threads, int check) {
    wk_run *R = &h->R;
    if (h->P) return WK_FAIL(R, WK_EUSAGE, "", 0, "wks_solve_pslg called twice on one handle");
    h->V = wk_variant_find(variant);
    if (!h->V) return WK_FAIL(R, WK_EUSAGE, "", 0, "unknown variant '%s'", variant);
    if (!(until >= 0)) /* NaN too */
        return WK_FAIL(R, WK_EUSAGE, "", 0, "until must be a positive number (got %g)", until);
    R->opt.until = until;
    if (threads > 0) R->opt.threads = threads;
    wk_status st = wk_pslg_from_arrays(R, nv, x, y, ne, src, dst, w, name, NULL, NULL, &h->P);
    if (st != WK_OK) return st;
    if (!(wk_variant_flags(h->V) & WK_VARIANT_WEIGHTS))
        for (uint32_t i = 0; i < h->P->n; i++) /* a cap has its segment's weight */
            if (h->P->w[i] != 1.0 && h->P->edge_of[i] != WK_NONE)
                return WK_FAIL(R, WK_EUNSUPPORTED, h->P->name, 0,
                               "variant %s supports unit weights only (edge %u has weight %g)",
                               wk_variant_name(h->V), h->P->edge_of[i], h->P->w[i]);
    if (check)
        return wk_solve_checked(R, h->V, h->P, WK_VALIDATE_TOL_REL * wk_polygon_scale(h->P), &h->S,
                                &h->time_s, &h->peak_bytes, NULL);
    return wk_solve(R, h->V, h->P, &h->S, &h->time_s, &h->peak_bytes);
}

/* A solved PSLG's horizon and sizes: rings (face cycles of the initial
** wavefront), graph nodes and edges.  Zeros for a polygon. */
void wks_pslg_sizes(const wks_handle *h, double *horizon, uint32_t *n_rings, uint32_t *n_graph_nodes,
                    uint32_t *n_graph_edges) {
    bool pslg = h->P && h->P->pslg;
    *horizon = pslg && h->S ? h->S->horizon : 0;
    *n_rings = pslg ? h->P->n_rings : 0;
    *n_graph_nodes = pslg ? h->P->n_graph_vertices : 0;
    *n_graph_edges = pslg ? h->P->n_graph_edges : 0;
}

/* ring_size: n_rings; corner_node, edge_of: wks_n_input each (the input
** node of each corner; the input edge of each stored edge, WK_NONE for a
** cap), as the JSON's "rings" and "pslg" members. */
void wks_pslg_copy(const wks_handle *h, uint32_t *ring_size, uint32_t *corner_node,
                   uint32_t *edge_of) {
    const wk_polygon *P = h->P;
    if (!P || !P->pslg) return;
    for (uint32_t k = 0; k < P->n_rings; k++) ring_size[k] = P->ring_start[k + 1] - P->ring_start[k];
    memcpy(corner_node, P->corner_vertex, P->n * sizeof *corner_node);
    memcpy(edge_of, P->edge_of, P->n * sizeof *edge_of);
}

uint32_t wks_n_input(const wks_handle *h) { return h->P ? h->P->n : 0; }
uint32_t wks_n_nodes(const wks_handle *h) { return h->S ? h->S->n_nodes : 0; }
uint32_t wks_n_arcs(const wks_handle *h) { return h->S ? h->S->n_arcs : 0; }
double wks_time_s(const wks_handle *h) { return h->time_s; }
size_t wks_peak_bytes(const wks_handle *h) { return h->peak_bytes; }
size_t wks_live_bytes(const wks_handle *h) { return h->R.alloc.live; }

/* xyt: 3 * wks_n_nodes doubles (x, y, t per node, output numbering). */
void wks_nodes(const wks_handle *h, double *xyt) {
    const wk_skeleton *S = h->S;
    for (uint32_t j = 0; j < S->n_nodes; j++) {
        uint32_t o = wk_polygon_output_node(h->P, j);
        xyt[3 * o] = S->nodes[j].x;
        xyt[3 * o + 1] = S->nodes[j].y;
        xyt[3 * o + 2] = S->nodes[j].t;
    }
}

/* An arc's face in output numbering; the cap (WK_NONE) stays WK_NONE. */
static uint32_t out_face(const wk_polygon *P, uint32_t e) {
    return e == WK_NONE ? WK_NONE : wk_polygon_input_edge(P, e);
}

/* ablr: 4 * wks_n_arcs ids (a, b, left, right per arc, in arc order). */
void wks_arcs(const wks_handle *h, uint32_t *ablr) {
    const wk_skeleton *S = h->S;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        ablr[4 * i] = wk_polygon_output_node(h->P, c->a);
        ablr[4 * i + 1] = wk_polygon_output_node(h->P, c->b);
        ablr[4 * i + 2] = out_face(h->P, c->left);
        ablr[4 * i + 3] = out_face(h->P, c->right);
    }
}

/* The solved variant's counters (the engine's, then its own). */
uint32_t wks_n_counters(const wks_handle *h) { return wk_counter_count(h->V); }
const char *wks_counter_name(const wks_handle *h, uint32_t i) {
    const wk_counter_def *d = wk_counter_def_at(h->V, i);
    return d ? d->name : NULL;
}
uint64_t wks_counter_value(const wks_handle *h, uint32_t i) {
    return i < WK_COUNTERS_MAX ? h->R.counters.c[i] : 0;
}

/* ---------------------------------------------------------------- offsets */

int wks_offset(wks_handle *h, double t) {
    wk_offset_set_free(&h->R, h->O);
    h->O = NULL;
    if (!h->S) return WK_FAIL(&h->R, WK_EUSAGE, "", 0, "wks_offset before a successful wks_solve");
    return wk_offset(&h->R, h->P, h->S, t, &h->O);
}

/* Sizes of the last offset: components, rings, points. */
void wks_offset_sizes(const wks_handle *h, uint32_t *n_polygons, uint32_t *n_rings,
                      uint32_t *n_points) {
    const wk_offset_set *O = h->O;
    *n_polygons = O ? O->n_polygons : 0;
    *n_rings = O ? O->n_rings : 0;
    *n_points = O ? O->ring_start[O->n_rings] : 0;
}

/* polygon_start: n_polygons + 1, ring_start: n_rings + 1, xy: 2 * n_points. */
void wks_offset_copy(const wks_handle *h, uint32_t *polygon_start, uint32_t *ring_start,
                     double *xy) {
    const wk_offset_set *O = h->O;
    if (!O) return;
    memcpy(polygon_start, O->polygon_start, (O->n_polygons + 1) * sizeof *polygon_start);
    memcpy(ring_start, O->ring_start, (O->n_rings + 1) * sizeof *ring_start);
    for (uint32_t i = 0; i < O->ring_start[O->n_rings]; i++) {
        xy[2 * i] = O->p[i].x;
        xy[2 * i + 1] = O->p[i].y;
    }
}

/* ------------------------------------------------------------------- roof */

/* A PSLG's roof: the faces of wk_capped_faces_build, as the OBJ writer
** writes them (stored edge order = output order, then the cap's faces). */
static int pslg_roof(wks_handle *h) {
    wk_run *R = &h->R;
    const wk_polygon *P = h->P;
    uint32_t *edge_of = NULL;
    wk_capped_faces CF;
    memset(&CF, 0, sizeof CF);
    wk_status st = wk_input_order(R, P, NULL, &edge_of);
    if (st == WK_OK) st = wk_capped_faces_build(R, P, h->S, edge_of, &CF, "roof: ");
    if (st == WK_OK) {
        h->face_start = WK_NEW_ARRAY(R, uint32_t, CF.n_faces + 1);
        if (h->face_start) h->n_faces = CF.n_faces; /* free_roof frees by it */
        h->face_node = CF.n_node ? WK_NEW_ARRAY(R, uint32_t, CF.n_node) : NULL;
        if (h->face_node) h->n_face_node = CF.n_node;
        if (!h->face_start || (CF.n_node && !h->face_node)) {
            st = WK_ENOMEM;
        } else {
            h->face_start[0] = 0;
            for (uint32_t f = 0; f < CF.n_faces; f++) h->face_start[f + 1] = CF.end[f];
            for (uint32_t i = 0; i < CF.n_node; i++)
                h->face_node[i] = wk_polygon_output_node(P, CF.node[i]);
        }
    }
    wk_capped_faces_clear(R, &CF);
    if (edge_of) WK_FREE_ARRAY(R, edge_of, P->n);
    if (st != WK_OK) free_roof(h);
    return st;
}

/* The roof: the face of every input edge as a cycle of output node ids
** (wk_face_cycle), face i of input edge i; the nodes' t is the height.  A
** PSLG: pslg_roof. */
int wks_roof(wks_handle *h) {
    wk_run *R = &h->R;
    if (!h->S) return WK_FAIL(R, WK_EUSAGE, "", 0, "wks_roof before a successful wks_solve");
    free_roof(h);
    if (h->P->pslg) return pslg_roof(h);
    const wk_polygon *P = h->P;
    uint32_t cap = 0;
    h->face_start = WK_NEW_ARRAY(R, uint32_t, P->n + 1);
    if (!h->face_start) return WK_ENOMEM;
    h->n_faces = P->n;
    /* Two passes would solve every face twice; instead collect stored faces
    ** in stored order, then place them by input edge through a permutation. */
    uint32_t *len = WK_NEW_ARRAY(R, uint32_t, P->n), *stored_of = WK_NEW_ARRAY(R, uint32_t, P->n);
    uint32_t *all = NULL, n_all = 0;
    wk_status st = (len && stored_of) ? WK_OK : WK_ENOMEM;
    for (uint32_t e = 0; st == WK_OK && e < P->n; e++) {
        uint32_t *cyc = NULL, m = 0;
        st = wk_face_cycle(R, P, h->S, e, &cyc, &m);
        if (st != WK_OK) break;
        st = WK_GROW(R, all, cap, n_all + m);
        if (st == WK_OK) {
            for (uint32_t i = 0; i < m; i++) all[n_all + i] = wk_polygon_output_node(P, cyc[i]);
            n_all += m;
            len[e] = m;
            stored_of[wk_polygon_input_edge(P, e)] = e;
        }
        WK_FREE_ARRAY(R, cyc, m);
    }
    if (st == WK_OK) {
        /* stored face e starts at sum of len[< e] in all */
        uint32_t *at = WK_NEW_ARRAY(R, uint32_t, P->n);
        h->face_node = WK_NEW_ARRAY(R, uint32_t, n_all);
        /* Its size is recorded as soon as it exists: free_roof frees by it. */
        if (h->face_node) h->n_face_node = n_all;
        if (!at || !h->face_node) {
            st = WK_ENOMEM;
        } else {
            for (uint32_t e = 1; e < P->n; e++) at[e] = at[e - 1] + len[e - 1];
            for (uint32_t i = 0; i < P->n; i++) {
                uint32_t e = stored_of[i];
                h->face_start[i + 1] = h->face_start[i] + len[e];
                memcpy(h->face_node + h->face_start[i], all + at[e], len[e] * sizeof *all);
            }
        }
        if (at) WK_FREE_ARRAY(R, at, P->n);
    }
    if (all) WK_FREE_ARRAY(R, all, cap);
    if (len) WK_FREE_ARRAY(R, len, P->n);
    if (stored_of) WK_FREE_ARRAY(R, stored_of, P->n);
    if (st != WK_OK) free_roof(h);
    return st;
}

uint32_t wks_roof_size(const wks_handle *h) { return h->n_face_node; }
uint32_t wks_roof_faces(const wks_handle *h) { return h->n_faces; }
/* face_start: wks_roof_faces + 1 offsets, node: wks_roof_size ids. */
void wks_roof_copy(const wks_handle *h, uint32_t *face_start, uint32_t *node) {
    memcpy(face_start, h->face_start, (h->n_faces + 1) * sizeof *face_start);
    if (h->n_face_node) memcpy(node, h->face_node, h->n_face_node * sizeof *node);
}

/* ----------------------------------------------------------------- errors */

int wks_error_status(const wks_handle *h) { return h->R.err.code; }
int wks_error_exit_code(const wks_handle *h) { return wk_status_exit_code(h->R.err.code); }
const char *wks_error_status_name(const wks_handle *h) { return wk_status_name(h->R.err.code); }
const char *wks_error_message(const wks_handle *h) { return h->R.err.msg; }
const char *wks_error_input(const wks_handle *h) { return h->R.err.input; }
long wks_error_input_line(const wks_handle *h) { return h->R.err.input_line; }
const char *wks_error_src_file(const wks_handle *h) {
    return h->R.err.src_file ? h->R.err.src_file : "";
}
int wks_error_src_line(const wks_handle *h) { return h->R.err.src_line; }
/* "file:line: message", as the CLI prints it. */
void wks_error_format(const wks_handle *h, char *buf, size_t size) {
    wk_error_format(&h->R, buf, size);
}
