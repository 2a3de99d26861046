/*
** pslg.c: planar straight-line graphs (PSLGs) as input: their checks and
** their initial wavefront (paper 002, section 1: the wavefront runs on
** both sides of every edge; a terminal, a vertex of degree 1, gets a
** wavefront edge perpendicular to its segment; a vertex of degree d >= 2
** one wavefront vertex per angular gap).
**
** The PSLG is stored as a wk_polygon whose rings are the face cycles of its
** half-edges, so that the kinetic wavefront, the writers and the validator
** keep working with one face per stored edge:
**   - half-edge 2i runs src[i] -> dst[i], 2i + 1 back; the face of a
**     half-edge is on its left, so a face cycle is: at the head v of
**     half-edge u -> v, continue with the half-edge out of v that follows
**     v -> u clockwise around v (for a terminal that is v -> u itself);
**   - ring k is the k-th face cycle found, walking from the half-edges in
**     order 0, 1, 2, ...; its stored vertices ("corners") are the tails of
**     its half-edges, and after a half-edge u -> v into a terminal v one
**     more corner at v and a cap: an edge of length 0 from that corner to
**     the next one (both at v), direction (dy, -dx) for u -> v's (dx, dy)
**     (the incoming direction turned clockwise, so the cap moves on along
**     the segment, away from it), weight the segment's weight;
**   - so a vertex of degree d >= 2 is d corners, one per angular gap, and a
**     terminal 2; bounded faces give counter-clockwise rings, the outer
**     face and the faces around a connected component inside another face
**     clockwise ones, exactly as holes are stored: the region to the left
**     of every stored edge is the one its offset line sweeps.
** Input numbering: the stored order is the output order (input_index is
** the identity); corner_vertex and edge_of map corners and stored edges
** back to the GraphML's nodes and edges (document order).
**
** Checks (WK_EINPUT, naming node or edges and their lines): every node on
** an edge (an isolated vertex has no wavefront edge to move: refused), no
** two nodes at one point, no two edges between the same nodes, no two
** edges that cross, touch (a node inside another edge) or overlap, no two
** edges at a node that leave it in directions within WK_ANTIPARALLEL_SIN
** (a needle: the vertex between them would be too fast, as in polygons),
** no two edges without a common node closer than WK_PSLG_MIN_CLEARANCE_REL
** of the diagonal (below the simulation's tolerance they would touch; nodes
** joined by a shorter edge count as one node for this),
** weights > 0 within WK_POLYGON_MAX_WEIGHT_RATIO, coordinates within the
** polygon input domain (README).  Edge pairs are tested exactly
** (wk_segments_meet) over the pairs whose x ranges overlap: O(m log m +
** such pairs), quadratic only for inputs of many long overlapping x
** ranges.
*/
#include "wskel.h"

#include <math.h>
#include <string.h>

typedef struct pslg_ctx {
    wk_run *R;
    const char *name;
    uint32_t nv, ne;
    const double *x, *y;
    const uint32_t *src, *dst;
    const long *node_line, *edge_line;
    uint32_t *deg;      /* degree of each node */
    uint32_t *first;    /* CSR: node v's half-edges out are rot[first[v] .. first[v + 1]) */
    uint32_t *rot;      /* ... sorted counter-clockwise by direction */
    uint32_t *pos;      /* pos[h]: h's index in rot */
    uint32_t *tmp;      /* sort scratch */
} pslg_ctx;

static long nline(const pslg_ctx *C, uint32_t v) { return C->node_line ? C->node_line[v] : 0; }
static long eline(const pslg_ctx *C, uint32_t e) { return C->edge_line ? C->edge_line[e] : 0; }
static uint32_t h_from(const pslg_ctx *C, uint32_t h) { return h & 1 ? C->dst[h >> 1] : C->src[h >> 1]; }
static uint32_t h_to(const pslg_ctx *C, uint32_t h) { return h & 1 ? C->src[h >> 1] : C->dst[h >> 1]; }
static wk_point pt(const pslg_ctx *C, uint32_t v) { return (wk_point){C->x[v], C->y[v]}; }

/* ---- sorting (a bottom-up merge sort with context: stable, O(m log m)) */

typedef bool (*less_fn)(const pslg_ctx *C, uint32_t a, uint32_t b);

static void merge_sort(const pslg_ctx *C, uint32_t *a, uint32_t *tmp, uint32_t n, less_fn less) {
    uint32_t *src = a, *dst = tmp;
    for (uint32_t w = 1; w < n; w *= 2) {
        for (uint32_t lo = 0; lo < n; lo += 2 * w) {
            uint32_t mid = lo + w < n ? lo + w : n, hi = lo + 2 * w < n ? lo + 2 * w : n;
            uint32_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi) dst[k++] = less(C, src[j], src[i]) ? src[j++] : src[i++];
            while (i < mid) dst[k++] = src[i++];
            while (j < hi) dst[k++] = src[j++];
        }
        uint32_t *t = src;
        src = dst;
        dst = t;
    }
    if (src != a) memcpy(a, src, (size_t)n * sizeof *a);
}

static bool node_less(const pslg_ctx *C, uint32_t a, uint32_t b) {
    return C->x[a] < C->x[b] || (C->x[a] == C->x[b] && C->y[a] < C->y[b]);
}

static double edge_xmin(const pslg_ctx *C, uint32_t e) {
    return fmin(C->x[C->src[e]], C->x[C->dst[e]]);
}
static bool edge_less(const pslg_ctx *C, uint32_t a, uint32_t b) {
    return edge_xmin(C, a) < edge_xmin(C, b);
}

/* Counter-clockwise order of the half-edges out of one node, starting at
** direction (1, 0): the upper half-plane (y > 0, or y == 0 and x > 0)
** first, then by exact orientation. */
static int upper(const pslg_ctx *C, uint32_t h) {
    wk_point a = pt(C, h_from(C, h)), b = pt(C, h_to(C, h));
    return b.y > a.y || (b.y == a.y && b.x > a.x);
}
static bool angle_less(const pslg_ctx *C, uint32_t h1, uint32_t h2) {
    int u1 = upper(C, h1), u2 = upper(C, h2);
    if (u1 != u2) return u1 > u2;
    return wk_orient2d(pt(C, h_from(C, h1)), pt(C, h_to(C, h1)), pt(C, h_to(C, h2)), NULL) > 0;
}

/* ---- checks */

static wk_status check_values(pslg_ctx *C, const double *w, double *diag_out) {
    wk_run *R = C->R;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, big = 0;
    uint32_t far = 0;
    for (uint32_t v = 0; v < C->nv; v++) {
        double c[2] = {C->x[v], C->y[v]};
        for (int k = 0; k < 2; k++) {
            if (!isfinite(c[k]))
                return WK_FAIL(R, WK_EINPUT, C->name, nline(C, v),
                               "node %u has a coordinate that is not a finite number", v);
            if (fabs(c[k]) > WK_POLYGON_MAX_COORD)
                return WK_FAIL(R, WK_EINPUT, C->name, nline(C, v),
                               "node %u: coordinate too large (%g; the limit is %g)", v, c[k],
                               WK_POLYGON_MAX_COORD);
            if (c[k] != 0 && fabs(c[k]) < WK_POLYGON_MIN_COORD)
                return WK_FAIL(R, WK_EINPUT, C->name, nline(C, v),
                               "node %u: coordinate too small (%g): nonzero coordinates must have "
                               "magnitude at least %g (input domain)",
                               v, c[k], WK_POLYGON_MIN_COORD);
            lo[k] = fmin(lo[k], c[k]);
            hi[k] = fmax(hi[k], c[k]);
            if (fabs(c[k]) > big) {
                big = fabs(c[k]);
                far = v;
            }
        }
    }
    double diag = hypot(hi[0] - lo[0], hi[1] - lo[1]);
    *diag_out = diag;
    /* (diag 0: every node at one point, which check_nodes refuses) */
    if (diag > 0 && big > WK_POLYGON_MAX_OFFSET_REL * diag)
        return WK_FAIL(R, WK_EINPUT, C->name, nline(C, far),
                       "node %u lies %.3g diagonals from the origin, beyond the %g the output "
                       "resolves (input domain): translate the graph nearer the origin",
                       far, big / diag, WK_POLYGON_MAX_OFFSET_REL);
    uint32_t wlo = 0, whi = 0;
    for (uint32_t e = 0; e < C->ne; e++) {
        double we = w ? w[e] : 1.0;
        if (!isfinite(we) || !(we > 0))
            return WK_FAIL(R, WK_EINPUT, C->name, eline(C, e),
                           "weight of edge %u must be a finite number > 0 in a PSLG (got %g)", e, we);
        if (w && w[e] < w[wlo]) wlo = e;
        if (w && w[e] > w[whi]) whi = e;
    }
    if (w && C->ne && w[whi] > WK_POLYGON_MAX_WEIGHT_RATIO * w[wlo])
        return WK_FAIL(R, WK_EINPUT, C->name, eline(C, whi),
                       "weights of edge %u (%g) and edge %u (%g) differ by a factor above the %g "
                       "the wavefront resolves (input domain)",
                       whi, w[whi], wlo, w[wlo], WK_POLYGON_MAX_WEIGHT_RATIO);
    return WK_OK;
}

/* Nodes: no isolated one, no two at one point. */
static wk_status check_nodes(pslg_ctx *C, uint32_t *order) {
    wk_run *R = C->R;
    for (uint32_t v = 0; v < C->nv; v++)
        if (C->deg[v] == 0)
            return WK_FAIL(R, WK_EINPUT, C->name, nline(C, v),
                           "node %u (document order) is isolated (on no edge): a PSLG vertex "
                           "needs an edge, an isolated point has no wavefront edge to move "
                           "(remove it)",
                           v);
    for (uint32_t v = 0; v < C->nv; v++) order[v] = v;
    merge_sort(C, order, C->tmp, C->nv, node_less);
    for (uint32_t k = 1; k < C->nv; k++) {
        uint32_t a = order[k - 1], b = order[k];
        if (C->x[a] == C->x[b] && C->y[a] == C->y[b]) {
            if (a > b) {
                uint32_t t = a;
                a = b;
                b = t;
            }
            return WK_FAIL(R, WK_EINPUT, C->name, nline(C, b),
                           "nodes %u and %u are at the same point (%g, %g) (node %u on line %ld)", a,
                           b, C->x[a], C->y[a], a, nline(C, a));
        }
    }
    return WK_OK;
}

static double point_segment_distance(wk_point p, wk_point a, wk_point b) {
    double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double s = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return hypot(p.x - a.x - s * dx, p.y - a.y - s * dy);
}

/* Union-find over the nodes (C->first as parents: it is filled only later,
** by build_rotation). */
static uint32_t uf_find(uint32_t *parent, uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

/* Edges: pairs whose x ranges come within the clearance, tested exactly
** for contact, then (disjoint pairs without a shared node) for the
** clearance (in doubles: a bound, not a decision the skeleton hinges on).
** Nodes joined by edges shorter than the clearance count as one node there
** (an edge below the tolerance collapses at t ~ 0, as in polygons, and the
** edges on either side of it become neighbours). */
static wk_status check_edges(pslg_ctx *C, uint32_t *order, double clearance) {
    wk_run *R = C->R;
    uint32_t *parent = C->first;
    for (uint32_t v = 0; v < C->nv; v++) parent[v] = v;
    for (uint32_t e = 0; e < C->ne; e++) {
        wk_point a = pt(C, C->src[e]), b = pt(C, C->dst[e]);
        if (hypot(b.x - a.x, b.y - a.y) < clearance)
            parent[uf_find(parent, C->src[e])] = uf_find(parent, C->dst[e]);
    }
    for (uint32_t e = 0; e < C->ne; e++) order[e] = e;
    merge_sort(C, order, C->tmp, C->ne, edge_less);
    for (uint32_t i = 0; i < C->ne; i++) {
        uint32_t a = order[i];
        wk_point a0 = pt(C, C->src[a]), a1 = pt(C, C->dst[a]);
        double axmax = fmax(a0.x, a1.x) + clearance, aylo = fmin(a0.y, a1.y) - clearance,
               ayhi = fmax(a0.y, a1.y) + clearance;
        for (uint32_t j = i + 1; j < C->ne; j++) {
            uint32_t b = order[j];
            if (edge_xmin(C, b) > axmax) break;
            wk_point b0 = pt(C, C->src[b]), b1 = pt(C, C->dst[b]);
            if (fmin(b0.y, b1.y) > ayhi || fmax(b0.y, b1.y) < aylo) continue;
            uint32_t shared = (C->src[a] == C->src[b] || C->src[a] == C->dst[b]) +
                              (C->dst[a] == C->src[b] || C->dst[a] == C->dst[b]);
            uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
            if (shared == 2)
                return WK_FAIL(R, WK_EINPUT, C->name, eline(C, hi),
                               "edges %u and %u join the same two nodes (edge %u on line %ld)", lo,
                               hi, lo, eline(C, lo));
            uint32_t exact = 0;
            wk_seg_meet m = wk_segments_meet_ex(a0, a1, b0, b1, &exact);
            if (exact) wk_count(R, WK_COUNTER_exact_fallbacks, exact);
            uint32_t ra0 = uf_find(parent, C->src[a]), ra1 = uf_find(parent, C->dst[a]),
                     rb0 = uf_find(parent, C->src[b]), rb1 = uf_find(parent, C->dst[b]);
            bool near_shared = ra0 == rb0 || ra0 == rb1 || ra1 == rb0 || ra1 == rb1;
            if (m == WK_SEG_DISJOINT && shared == 0 && !near_shared) {
                double dist = fmin(fmin(point_segment_distance(a0, b0, b1), point_segment_distance(a1, b0, b1)),
                                   fmin(point_segment_distance(b0, a0, a1), point_segment_distance(b1, a0, a1)));
                if (dist < clearance)
                    return WK_FAIL(R, WK_EINPUT, C->name, eline(C, hi),
                                   "edge %u passes %.3g from edge %u (edge %u on line %ld), closer "
                                   "than %g of the diagonal (input domain: a node meant to lie on "
                                   "an edge must split it)",
                                   hi, dist, lo, lo, eline(C, lo), WK_PSLG_MIN_CLEARANCE_REL);
                continue;
            }
            if (m == WK_SEG_DISJOINT || (shared == 1 && m == WK_SEG_TOUCH)) continue;
            const char *how = m == WK_SEG_CROSS     ? "crosses"
                              : m == WK_SEG_OVERLAP ? "overlaps"
                                                    : "touches";
            return WK_FAIL(R, WK_EINPUT, C->name, eline(C, hi),
                           "edge %u %s edge %u (edge %u on line %ld): a PSLG's edges meet only at "
                           "shared nodes%s",
                           hi, how, lo, lo, eline(C, lo),
                           m == WK_SEG_TOUCH ? " (here a node lies inside the other edge)" : "");
        }
    }
    return WK_OK;
}

/* Rotation system: each node's half-edges out, counter-clockwise; and no
** needle between consecutive ones. */
static wk_status build_rotation(pslg_ctx *C) {
    wk_run *R = C->R;
    C->first[0] = 0;
    for (uint32_t v = 0; v < C->nv; v++) C->first[v + 1] = C->first[v] + C->deg[v];
    for (uint32_t v = 0; v < C->nv; v++) C->deg[v] = 0; /* refilled below */
    for (uint32_t h = 0; h < 2 * C->ne; h++) {
        uint32_t v = h_from(C, h);
        C->rot[C->first[v] + C->deg[v]++] = h;
    }
    for (uint32_t v = 0; v < C->nv; v++) {
        uint32_t f = C->first[v], d = C->deg[v];
        merge_sort(C, C->rot + f, C->tmp, d, angle_less);
        for (uint32_t k = 0; k < d; k++) C->pos[C->rot[f + k]] = k;
        for (uint32_t k = 0; d >= 2 && k < d; k++) {
            uint32_t h1 = C->rot[f + k], h2 = C->rot[f + (k + 1) % d];
            wk_point o = pt(C, v), p1 = pt(C, h_to(C, h1)), p2 = pt(C, h_to(C, h2));
            double ax = p1.x - o.x, ay = p1.y - o.y, bx = p2.x - o.x, by = p2.y - o.y;
            double cr = ax * by - ay * bx, dot = ax * bx + ay * by;
            if (dot > 0 && fabs(cr) <= WK_ANTIPARALLEL_SIN * hypot(ax, ay) * hypot(bx, by))
                return WK_FAIL(R, WK_EINPUT, C->name, nline(C, v),
                               "node %u is a needle: edges %u and %u leave it in directions closer "
                               "than a sine of %g (input domain, see README)",
                               v, h1 >> 1, h2 >> 1, WK_ANTIPARALLEL_SIN);
        }
    }
    return WK_OK;
}

/* The half-edge after h on h's face cycle (h itself's twin at a terminal). */
static uint32_t face_next(const pslg_ctx *C, uint32_t h) {
    uint32_t t = h ^ 1u, v = h_from(C, t), d = C->deg[v];
    return C->rot[C->first[v] + (C->pos[t] + d - 1) % d];
}

static wk_status build_polygon(pslg_ctx *C, const double *w, wk_polygon **out) {
    wk_run *R = C->R;
    uint32_t n = 2 * C->ne;
    for (uint32_t v = 0; v < C->nv; v++) n += C->deg[v] == 1;
    wk_polygon *P = WK_NEW_ARRAY(R, wk_polygon, 1);
    if (!P) return R->err.code;
    P->n = n;
    P->pslg = true;
    P->n_graph_vertices = C->nv;
    P->n_graph_edges = C->ne;
    snprintf(P->name, sizeof P->name, "%s", C->name ? C->name : "");
    P->p = WK_NEW_ARRAY(R, wk_point, n);
    P->w = WK_NEW_ARRAY(R, double, n);
    P->input_index = WK_NEW_ARRAY(R, uint32_t, n);
    P->dir = WK_NEW_ARRAY(R, wk_point, n);
    P->corner_vertex = WK_NEW_ARRAY(R, uint32_t, n);
    P->edge_of = WK_NEW_ARRAY(R, uint32_t, n);
    P->ring_of = WK_NEW_ARRAY(R, uint32_t, n);
    uint8_t *seen = WK_NEW_ARRAY(R, uint8_t, 2 * (size_t)C->ne);
    uint32_t *starts = NULL, n_rings = 0, cap_starts = 0;
    if (!P->p || !P->w || !P->input_index || !P->dir || !P->corner_vertex || !P->edge_of ||
        !P->ring_of || !seen)
        goto fail;
    uint32_t k = 0;
    for (uint32_t h0 = 0; h0 < 2 * C->ne; h0++) {
        if (seen[h0]) continue;
        if (WK_GROW(R, starts, cap_starts, n_rings + 2) != WK_OK) goto fail;
        starts[n_rings++] = k;
        uint32_t h = h0;
        do {
            seen[h] = 1;
            uint32_t a = h_from(C, h), b = h_to(C, h), e = h >> 1;
            double we = w ? w[e] : 1.0;
            wk_point d = {C->x[b] - C->x[a], C->y[b] - C->y[a]};
            P->p[k] = pt(C, a);
            P->w[k] = we;
            P->dir[k] = d;
            P->corner_vertex[k] = a;
            P->edge_of[k] = e;
            k++;
            if (C->deg[b] == 1) { /* the cap at terminal b */
                P->p[k] = pt(C, b);
                P->w[k] = we;
                P->dir[k] = (wk_point){d.y, -d.x};
                P->corner_vertex[k] = b;
                P->edge_of[k] = WK_NONE;
                k++;
            }
            h = face_next(C, h);
        } while (h != h0);
    }
    starts[n_rings] = k;
    P->n_rings = n_rings;
    P->ring_start = WK_NEW_ARRAY(R, uint32_t, (size_t)n_rings + 1);
    if (!P->ring_start) goto fail;
    memcpy(P->ring_start, starts, ((size_t)n_rings + 1) * sizeof *starts);
    for (uint32_t r = 0; r < n_rings; r++)
        for (uint32_t i = starts[r]; i < starts[r + 1]; i++) P->ring_of[i] = r;
    if (n_rings == 1) WK_FREE_ARRAY(R, P->ring_of, n); /* wk_polygon: NULL with one ring */
    for (uint32_t i = 0; i < n; i++) {
        P->input_index[i] = i;
        /* reflex: a right turn from the incoming edge's direction */
        if (wk_orient2d((wk_point){0, 0}, P->dir[wk_polygon_prev(P, i)], P->dir[i], NULL) < 0) P->r++;
    }
    WK_FREE_ARRAY(R, starts, cap_starts);
    WK_FREE_ARRAY(R, seen, 2 * (size_t)C->ne);
    *out = P;
    return WK_OK;
fail:
    WK_FREE_ARRAY(R, starts, cap_starts);
    WK_FREE_ARRAY(R, seen, 2 * (size_t)C->ne);
    wk_polygon_free(R, P);
    return R->err.code ? R->err.code : WK_ENOMEM;
}

wk_status wk_pslg_from_arrays(wk_run *R, uint32_t nv, const double *x, const double *y,
                              uint32_t ne, const uint32_t *src, const uint32_t *dst,
                              const double *w, const char *name, const long *node_line,
                              const long *edge_line, wk_polygon **out) {
    *out = NULL;
    if (nv == 0) return WK_FAIL(R, WK_EINPUT, name, 0, "the graph has no nodes");
    /* no edges: every node is isolated, which check_nodes reports with its line */
    if (ne > WK_POLYGON_MAX_N / 3)
        return WK_FAIL(R, WK_EINPUT, name, 0, "too many edges (%u; the limit is %u)", ne,
                       WK_POLYGON_MAX_N / 3);
    pslg_ctx C = {R, name, nv, ne, x, y, src, dst, node_line, edge_line, NULL, NULL, NULL, NULL, NULL};
    uint32_t big = nv > 2 * ne ? nv : 2 * ne;
    C.deg = WK_NEW_ARRAY(R, uint32_t, nv);
    C.first = WK_NEW_ARRAY(R, uint32_t, (size_t)nv + 1);
    C.rot = WK_NEW_ARRAY(R, uint32_t, 2 * (size_t)ne);
    C.pos = WK_NEW_ARRAY(R, uint32_t, 2 * (size_t)ne);
    C.tmp = WK_NEW_ARRAY(R, uint32_t, big);
    uint32_t *order = WK_NEW_ARRAY(R, uint32_t, big);
    wk_status st = WK_OK;
    if (!C.deg || !C.first || !C.rot || !C.pos || !C.tmp || !order) {
        st = R->err.code;
        goto done;
    }
    for (uint32_t e = 0; e < ne; e++) {
        if (src[e] >= nv || dst[e] >= nv || src[e] == dst[e]) {
            st = WK_FAIL(R, WK_EINPUT, name, edge_line ? edge_line[e] : 0,
                         "edge %u: bad or equal end nodes (%u, %u)", e, src[e], dst[e]);
            goto done;
        }
        C.deg[src[e]]++;
        C.deg[dst[e]]++;
    }
    double diag = 0;
    if ((st = check_values(&C, w, &diag)) != WK_OK || (st = check_nodes(&C, order)) != WK_OK ||
        (st = check_edges(&C, order, WK_PSLG_MIN_CLEARANCE_REL * diag)) != WK_OK ||
        (st = build_rotation(&C)) != WK_OK)
        goto done;
    st = build_polygon(&C, w, out);
done:
    WK_FREE_ARRAY(R, C.deg, nv);
    WK_FREE_ARRAY(R, C.first, (size_t)nv + 1);
    WK_FREE_ARRAY(R, C.rot, 2 * (size_t)ne);
    WK_FREE_ARRAY(R, C.pos, 2 * (size_t)ne);
    WK_FREE_ARRAY(R, C.tmp, big);
    WK_FREE_ARRAY(R, order, big);
    return st;
}
