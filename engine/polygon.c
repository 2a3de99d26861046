/*
** polygon.c: the input polygon (with holes): construction from arrays,
** validation, orientation, and the small queries on it.
**
** Invariants of a wk_polygon handed out by wk_polygon_from_rings (and
** wk_polygon_from_arrays, its one-ring case):
**   - 3 <= n <= WK_POLYGON_MAX_N over 1 <= n_rings <= WK_POLYGON_MAX_RINGS
**     rings of >= 3 vertices each; coordinates finite with magnitude at most
**     WK_POLYGON_MAX_COORD, nonzero ones at least WK_POLYGON_MIN_COORD;
**     weights finite and > 0;
**   - each ring is simple: consecutive vertices differ, no other two
**     vertices coincide, no edge meets a non-adjacent edge, adjacent edges
**     meet only at their shared vertex (straight-on 180-degree vertices are
**     allowed, 0-degree spikes are not), and its vertices are not all on one
**     line; no two rings share a point; every hole lies inside ring 0 and in
**     no other hole; so the area (outer minus holes) is positive;
**   - ring 0 is stored counter-clockwise, holes clockwise.  A ring given the
**     other way is reversed in place (its index range stays): stored local
**     vertex j is input local m-1-j, stored local edge j is input local edge
**     (m-2-j) mod m, and w[] moves with it, so every weight stays on its
**     geometric edge; reversed says whether ring 0 was;
**   - input_index[j] is the input number of stored vertex j;
**   - r is the number of reflex vertices (strict right turns, exactly).
**
** Validation runs on the input order, so every message uses input numbering
** (vertex i, edge i = input vertex i -> the next of its ring, counted from 0
** over all rings in file order) and the input line of the culprit when the
** caller passed lines[].
**
** The simplicity test is a Shamos-Hoey sweep over all edges of all rings at
** once, O(n log n), deciding every comparison with the exact predicates (see
** sweep_* below for why it is complete on degenerate inputs).  It is not
** Bentley-Ottmann: it stops at the first intersection it finds, which need
** not be the leftmost.  The same sweep finds which ring encloses which
** (sweep_nest), so the nesting costs one treap search per ring.
*/
#include "kinetics.h"
#include "wskel.h"

#include <errno.h>
#include <math.h>
#include <string.h>

/* ---- messages ---- */

static long line_of(const long *lines, uint32_t i) { return lines ? lines[i] : 0; }

/* "edge 3 (line 5)" or "edge 3" when there are no lines. */
static const char *describe(char *buf, size_t size, const char *what, const long *lines,
                            uint32_t i) {
    if (lines)
        snprintf(buf, size, "%s %u (line %ld)", what, i, lines[i]);
    else
        snprintf(buf, size, "%s %u", what, i);
    return buf;
}

/* ---- exact point helpers ---- */


static bool same_point(wk_point p, wk_point q) { return p.x == q.x && p.y == q.y; }

static uint32_t ring_end(const wk_polygon *P, uint32_t k) { return P->ring_start[k + 1]; }
static uint32_t ring_size(const wk_polygon *P, uint32_t k) {
    return P->ring_start[k + 1] - P->ring_start[k];
}

/* ---- sorting: bottom-up merge sort of vertex ids by (x, y, id) ----
** Our own because qsort has no context argument in C11 and sorting
** (x, y, id) records would triple the memory at 5e7 vertices.  Stable,
** O(n log n) worst case, deterministic. */

static bool vertex_less(const wk_point *p, uint32_t a, uint32_t b) {
    int c = wk_point_lex_cmp(p[a], p[b]);
    return c != 0 ? c < 0 : a < b;
}

/* Sorts a[0..n) using tmp (same size); returns whichever buffer holds the
** result. */
static uint32_t *sort_vertices(const wk_point *p, uint32_t *a, uint32_t *tmp, uint32_t n) {
    for (size_t width = 1; width < n; width *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * width) {
            size_t mid = lo + width < n ? lo + width : n;
            size_t hi = lo + 2 * width < n ? lo + 2 * width : n;
            size_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi) tmp[k++] = vertex_less(p, a[j], a[i]) ? a[j++] : a[i++];
            while (i < mid) tmp[k++] = a[i++];
            while (j < hi) tmp[k++] = a[j++];
        }
        uint32_t *t = a;
        a = tmp;
        tmp = t;
    }
    return a;
}

/* ---- the sweep ----
**
** Events are the vertices in lexicographic (x, y) order; as all vertices are
** distinct by then, this is a sweep by a line rotated infinitesimally
** counter-clockwise from vertical, so no edge is vertical and no two events
** share a sweep position.  Each edge is oriented from its lexicographically
** smaller endpoint L to the larger R, and "above" means "left of L -> R".
**
** The status is a treap of the edges crossing the sweep line, ordered from
** below to above.  At vertex v, the incident edges that end at v are removed
** first (their former neighbours are tested against each other), then the
** ones that start at v are inserted (each is tested against its new
** neighbours).  Every pair of edges that is ever consecutive in the status
** is thus tested, except pairs of adjacent polygon edges, which meet only at
** their shared vertex once spikes are excluded.
**
** Completeness: let p be the lexicographically smallest point where two
** non-adjacent edges meet.  Up to p no two status edges change order, so the
** status is the true order.  If p is not a vertex, the edges through p are
** consecutive in the status just before p and some consecutive pair was
** tested when it became consecutive.  If p is a vertex v with an edge s
** starting there, the insertion search for s either compares s with an edge
** through v (comparison 0: reported) or ends between two edges that are
** strictly below and above v, which cannot be, as the edges through v lie
** between them.  If both edges at v end there, an edge through v is
** consecutive with one of them in the status and that pair was tested.
**
** Priorities are a bijective hash of the edge id, so the tree shape, and the
** intersection reported, depend on the input only. */

typedef struct sweep {
    wk_run *R; /* counts the exact stages of the comparisons */
    const wk_polygon *P; /* for the rings (next/prev) */
    const wk_point *p;
    uint32_t n;
    uint32_t root;
    uint32_t *lft, *rgt, *par; /* treap links by edge id, WK_NONE if none */
    /* first intersection found: edges a and b, how they meet, and for a
    ** touch the vertex lying on the other edge (WK_NONE if not known) */
    uint32_t bad_a, bad_b, bad_vertex;
    wk_seg_meet bad_kind;
    /* nesting (polygons with holes): ccw[k] is ring k's orientation (+1 or
    ** -1, as given); parent[k] the ring whose inside immediately encloses
    ** ring k, WK_NONE if none; seen[k] set once ring k's first (leftmost)
    ** vertex was swept.  NULL for a single ring. */
    const int8_t *ccw;
    uint32_t *parent;
    uint8_t *seen;
} sweep;

static uint64_t edge_priority(uint32_t e) {
    uint64_t z = (uint64_t)e + 0x9E3779B97F4A7C15u; /* splitmix64 finaliser */
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* Vertex id of the left (lexicographically smaller) endpoint of edge e. */
static uint32_t left_vertex(const sweep *S, uint32_t e) {
    uint32_t f = wk_polygon_next(S->P, e);
    return wk_point_lex_cmp(S->p[e], S->p[f]) < 0 ? e : f;
}
static uint32_t right_vertex(const sweep *S, uint32_t e) {
    uint32_t f = wk_polygon_next(S->P, e);
    return wk_point_lex_cmp(S->p[e], S->p[f]) < 0 ? f : e;
}

static bool adjacent_edges(const wk_polygon *P, uint32_t a, uint32_t b) {
    return wk_polygon_next(P, a) == b || wk_polygon_next(P, b) == a;
}

static void rotate_up(sweep *S, uint32_t x) {
    uint32_t p = S->par[x], g = S->par[p];
    if (S->lft[p] == x) {
        S->lft[p] = S->rgt[x];
        if (S->rgt[x] != WK_NONE) S->par[S->rgt[x]] = p;
        S->rgt[x] = p;
    } else {
        S->rgt[p] = S->lft[x];
        if (S->lft[x] != WK_NONE) S->par[S->lft[x]] = p;
        S->lft[x] = p;
    }
    S->par[p] = x;
    S->par[x] = g;
    if (g == WK_NONE)
        S->root = x;
    else if (S->lft[g] == p)
        S->lft[g] = x;
    else
        S->rgt[g] = x;
}

static uint32_t tree_prev(const sweep *S, uint32_t x) {
    if (S->lft[x] != WK_NONE) {
        x = S->lft[x];
        while (S->rgt[x] != WK_NONE) x = S->rgt[x];
        return x;
    }
    while (S->par[x] != WK_NONE && S->lft[S->par[x]] == x) x = S->par[x];
    return S->par[x];
}

static uint32_t tree_next(const sweep *S, uint32_t x) {
    if (S->rgt[x] != WK_NONE) {
        x = S->rgt[x];
        while (S->lft[x] != WK_NONE) x = S->lft[x];
        return x;
    }
    while (S->par[x] != WK_NONE && S->rgt[S->par[x]] == x) x = S->par[x];
    return S->par[x];
}

static void record(sweep *S, uint32_t a, uint32_t b, wk_seg_meet kind, uint32_t vertex) {
    S->bad_a = a;
    S->bad_b = b;
    S->bad_kind = kind;
    S->bad_vertex = vertex;
}

/* Test edges a and b (either may be WK_NONE); returns false after recording
** an intersection. */
static bool test_pair(sweep *S, uint32_t a, uint32_t b) {
    if (a == WK_NONE || b == WK_NONE || adjacent_edges(S->P, a, b)) return true;
    const wk_point *p = S->p;
    wk_seg_meet m = wk_segments_meet_counted(S->R, p[a], p[wk_polygon_next(S->P, a)], p[b],
                                             p[wk_polygon_next(S->P, b)]);
    if (m == WK_SEG_DISJOINT) return true;
    record(S, a, b, m, WK_NONE);
    return false;
}

/* Where edge s, starting at vertex v, goes relative to status edge t at the
** current event: +1 above, -1 below, 0 when they meet beyond v's being a
** shared endpoint (then recorded). */
static int compare_at(sweep *S, uint32_t s, uint32_t t, uint32_t v) {
    const wk_point *p = S->p;
    if (left_vertex(S, t) == v) {
        /* t is s's sibling, also starting at v: order by direction. */
        int o = wk_orient2d_counted(S->R, p[v], p[right_vertex(S, t)], p[right_vertex(S, s)]);
        if (o == 0) record(S, s, t, WK_SEG_OVERLAP, WK_NONE); /* defensive: spikes are
                                                                 rejected before */
        return o;
    }
    /* t started left of v and ends right of it (edges ending at v are
    ** removed already and only s and its sibling have v as an endpoint). */
    int o = wk_orient2d_counted(S->R, p[left_vertex(S, t)], p[right_vertex(S, t)], p[v]);
    if (o == 0) record(S, s, t, WK_SEG_TOUCH, v); /* v lies on t */
    return o;
}

static bool sweep_insert(sweep *S, uint32_t s, uint32_t v) {
    uint32_t cur = S->root, parent = WK_NONE;
    int side = 0;
    while (cur != WK_NONE) {
        side = compare_at(S, s, cur, v);
        if (side == 0) return false;
        parent = cur;
        cur = side > 0 ? S->rgt[cur] : S->lft[cur];
    }
    S->lft[s] = S->rgt[s] = WK_NONE;
    S->par[s] = parent;
    if (parent == WK_NONE)
        S->root = s;
    else if (side > 0)
        S->rgt[parent] = s;
    else
        S->lft[parent] = s;
    uint64_t ps = edge_priority(s);
    while (S->par[s] != WK_NONE && ps > edge_priority(S->par[s])) rotate_up(S, s);
    return test_pair(S, s, tree_prev(S, s)) && test_pair(S, s, tree_next(S, s));
}

static bool sweep_remove(sweep *S, uint32_t x) {
    uint32_t below = tree_prev(S, x), above = tree_next(S, x);
    /* Rotate x down to a leaf, keeping heap order, then unlink it. */
    for (;;) {
        uint32_t l = S->lft[x], r = S->rgt[x];
        if (l == WK_NONE && r == WK_NONE) break;
        uint32_t c;
        if (l == WK_NONE)
            c = r;
        else if (r == WK_NONE)
            c = l;
        else
            c = edge_priority(l) > edge_priority(r) ? l : r;
        rotate_up(S, c);
    }
    uint32_t p = S->par[x];
    if (p == WK_NONE)
        S->root = WK_NONE;
    else if (S->lft[p] == x)
        S->lft[p] = WK_NONE;
    else
        S->rgt[p] = WK_NONE;
    S->par[x] = WK_NONE;
    return test_pair(S, below, above);
}

/* Nesting.  At the first (lexicographically smallest) vertex v of ring k,
** no edge of ring k is in the status yet, and the status edge e directly
** below v (if any) has nothing between it and v: v lies in the region just
** above e.  If that region is inside e's ring j (j's interior is left of
** its edges when j runs counter-clockwise, and "above" is left of e's
** left-to-right direction), j encloses ring k; otherwise the region is the
** one just outside j, which parent(j) encloses (j started before v, so
** parent(j) is known).  No edge below: nothing encloses ring k.  Only
** meaningful if the sweep finds no intersection (a touch at v is recorded
** here). */
static bool sweep_nest(sweep *S, uint32_t v) {
    uint32_t k = wk_polygon_ring(S->P, v), cur = S->root, below = WK_NONE;
    S->seen[k] = 1;
    while (cur != WK_NONE) {
        int o = wk_orient2d_counted(S->R, S->p[left_vertex(S, cur)], S->p[right_vertex(S, cur)],
                                    S->p[v]);
        if (o == 0) {
            record(S, v, cur, WK_SEG_TOUCH, v); /* v lies on edge cur */
            return false;
        }
        if (o > 0) below = cur;
        cur = o > 0 ? S->rgt[cur] : S->lft[cur];
    }
    if (below == WK_NONE) {
        S->parent[k] = WK_NONE;
        return true;
    }
    uint32_t j = wk_polygon_ring(S->P, below);
    bool left_to_right = left_vertex(S, below) == below;
    bool above_inside = left_to_right == (S->ccw[j] > 0);
    S->parent[k] = above_inside ? j : S->parent[j];
    return true;
}

/* Runs the sweep over the vertices in lexicographic order; false after
** recording an intersection. */
static bool sweep_run(sweep *S, const uint32_t *order) {
    uint32_t n = S->n;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t v = order[k];
        if (S->seen && !S->seen[wk_polygon_ring(S->P, v)] && !sweep_nest(S, v)) return false;
        uint32_t in = wk_polygon_prev(S->P, v), out = v; /* the edges at v */
        bool in_ends = right_vertex(S, in) == v, out_ends = right_vertex(S, out) == v;
        if (in_ends && !sweep_remove(S, in)) return false;
        if (out_ends && !sweep_remove(S, out)) return false;
        if (!in_ends && !sweep_insert(S, in, v)) return false;
        if (!out_ends && !sweep_insert(S, out, v)) return false;
    }
    return true;
}

/* For a TOUCH between non-adjacent edges a and b: a vertex of one lying on
** the other (there is one, as vertices are distinct). */
static void touch_vertex(wk_run *R, const wk_polygon *P, uint32_t a, uint32_t b,
                         uint32_t *vertex, uint32_t *on_edge) {
    const wk_point *p = P->p;
    uint32_t ends[2][2] = {{a, wk_polygon_next(P, a)}, {b, wk_polygon_next(P, b)}};
    uint32_t edges[2] = {a, b};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            uint32_t v = ends[i][j], e = edges[1 - i];
            if (wk_segments_meet_counted(R, p[v], p[v], p[e], p[wk_polygon_next(P, e)]) !=
                WK_SEG_DISJOINT) {
                *vertex = v;
                *on_edge = e;
                return;
            }
        }
    *vertex = WK_NONE; /* defensive: cannot happen for a real touch */
    *on_edge = b;
}

static wk_status report_intersection(wk_run *R, const sweep *S, const char *name,
                                     const long *lines) {
    char da[96], db[96], dv[96];
    uint32_t a = S->bad_a, b = S->bad_b;
    if (S->bad_kind == WK_SEG_TOUCH) {
        uint32_t v = S->bad_vertex, e = b;
        const wk_polygon *P = S->P;
        if (v == WK_NONE) touch_vertex(R, P, a, b, &v, &e);
        if (v != WK_NONE) {
            /* If an edge at v runs along e, say so: "overlaps" tells more
            ** than "touches". */
            uint32_t at_v[2] = {wk_polygon_prev(P, v), v};
            for (int i = 0; i < 2; i++) {
                uint32_t f = at_v[i];
                if (!adjacent_edges(P, f, e) &&
                    wk_segments_meet_counted(R, S->p[f], S->p[wk_polygon_next(P, f)], S->p[e],
                                             S->p[wk_polygon_next(P, e)]) == WK_SEG_OVERLAP) {
                    a = f < e ? f : e;
                    b = f < e ? e : f;
                    return WK_FAIL(R, WK_EINPUT, name, line_of(lines, a),
                                   "%s overlaps %s (collinear)",
                                   describe(da, sizeof da, "edge", lines, a),
                                   describe(db, sizeof db, "edge", lines, b));
                }
            }
            /* Else name the edge at v that is not adjacent to e (at least
            ** one is not, once spikes are excluded). */
            uint32_t f = adjacent_edges(P, v, e) ? wk_polygon_prev(P, v) : v;
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, v), "%s touches %s: %s lies on it",
                           describe(da, sizeof da, "edge", lines, f),
                           describe(db, sizeof db, "edge", lines, e),
                           describe(dv, sizeof dv, "vertex", lines, v));
        }
    }
    if (a > b) {
        uint32_t t = a;
        a = b;
        b = t;
    }
    const char *verb = S->bad_kind == WK_SEG_CROSS     ? "crosses"
                       : S->bad_kind == WK_SEG_OVERLAP ? "overlaps"
                                                       : "touches";
    return WK_FAIL(R, WK_EINPUT, name, line_of(lines, a), "%s %s %s%s",
                   describe(da, sizeof da, "edge", lines, a), verb,
                   describe(db, sizeof db, "edge", lines, b),
                   S->bad_kind == WK_SEG_OVERLAP ? " (collinear)" : "");
}

/* ---- validation ---- */

/* The variant to suggest for weights <= 0 (the registry says which). */
static const char *nonpositive_variant(void) {
    const char *v = wk_variant_with_flags(WK_VARIANT_NONPOSITIVE_WEIGHTS);
    return v ? v : "(none registered)";
}

/* The checks that need no memory: finite and bounded coordinates, weights. */
static wk_status check_values(wk_run *R, const wk_point *p, const double *w, uint32_t n,
                              const char *name, const long *lines) {
    for (uint32_t i = 0; i < n; i++) {
        if (!isfinite(p[i].x) || !isfinite(p[i].y))
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                           "vertex %u has a coordinate that is not a finite number (%g, %g)", i,
                           p[i].x, p[i].y);
        if (fabs(p[i].x) > WK_POLYGON_MAX_COORD || fabs(p[i].y) > WK_POLYGON_MAX_COORD)
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                           "vertex %u: coordinate too large (%g, %g; the limit is %g)", i,
                           p[i].x, p[i].y, WK_POLYGON_MAX_COORD);
        if ((p[i].x != 0 && fabs(p[i].x) < WK_POLYGON_MIN_COORD) ||
            (p[i].y != 0 && fabs(p[i].y) < WK_POLYGON_MIN_COORD))
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                           "vertex %u: coordinate too small (%g, %g): nonzero coordinates must "
                           "have magnitude at least %g (input domain: the exact predicates' "
                           "products must not underflow; round it to 0 or scale the polygon)",
                           i, p[i].x, p[i].y, WK_POLYGON_MIN_COORD);
    }
    if (w)
        for (uint32_t i = 0; i < n; i++) {
            if (!isfinite(w[i]))
                return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                               "weight of edge %u is not a finite number (got %g)", i, w[i]);
            if (!(w[i] > 0) && !R->opt.nonpositive_weights)
                return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                               "weight of edge %u must be > 0 (got %g); zero and negative "
                               "weights need --variant %s (with --height H)",
                               i, w[i], nonpositive_variant());
        }
    if (w) {
        /* the ratio of the positive weights (zero and negative ones, where
        ** a variant takes them, are bounded by the same ratio in size) */
        uint32_t lo = WK_NONE, hi = WK_NONE;
        for (uint32_t i = 0; i < n; i++) {
            if (w[i] == 0) continue;
            if (lo == WK_NONE || fabs(w[i]) < fabs(w[lo])) lo = i;
            if (hi == WK_NONE || fabs(w[i]) > fabs(w[hi])) hi = i;
        }
        if (lo != WK_NONE && fabs(w[hi]) > WK_POLYGON_MAX_WEIGHT_RATIO * fabs(w[lo]))
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, hi),
                           "weights of edge %u (%g) and edge %u (%g) differ by a factor of %.3g, "
                           "above the %g the wavefront resolves (input domain, see README)",
                           hi, w[hi], lo, w[lo], fabs(w[hi] / w[lo]), WK_POLYGON_MAX_WEIGHT_RATIO);
    }
    return WK_OK;
}

/* " of ring k" for polygons with holes, "" otherwise (messages). */
static const char *ring_note(char *buf, size_t size, const wk_polygon *P, uint32_t k) {
    if (P->n_rings == 1) buf[0] = 0;
    else snprintf(buf, size, " of ring %u%s", k, k == 0 ? " (the outer boundary)" : " (a hole)");
    return buf;
}

/* The local checks of one ring, O(ring), no memory: repeated vertices, all
** on one line, 0-degree spikes. */
static wk_status check_local(wk_run *R, const wk_polygon *P, uint32_t ring, const long *lines) {
    char da[96], db[96], dr[64];
    const wk_point *p = P->p;
    const char *name = P->name;
    uint32_t s = P->ring_start[ring], m = ring_size(P, ring);
    for (uint32_t i = s; i < s + m; i++) {
        uint32_t j = wk_polygon_next(P, i);
        if (!same_point(p[i], p[j])) continue;
        if (j == s && P->n_rings == 1)
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                           "the last vertex (%u) repeats the first: the polygon closes "
                           "implicitly, do not repeat vertex 0 (zero-length edge %u)",
                           i, i);
        if (j == s)
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                           "the last vertex (%u)%s repeats its first (%u): a ring closes "
                           "implicitly, do not repeat its first vertex (zero-length edge %u)",
                           i, ring_note(dr, sizeof dr, P, ring), s, i);
        return WK_FAIL(R, WK_EINPUT, name, line_of(lines, j),
                       "vertex %u repeats vertex %u (zero-length edge %u)", j, i, i);
    }
    uint32_t k = s + 2;
    while (k < s + m && wk_orient2d_counted(R, p[s], p[s + 1], p[k]) == 0) k++;
    if (k == s + m)
        return WK_FAIL(R, WK_EINPUT, name, line_of(lines, s),
                       "%s has zero area (all %u vertices are collinear)",
                       P->n_rings == 1 ? "polygon" : ring == 0 ? "the outer ring" : "a hole",
                       m);
    for (uint32_t v = s; v < s + m; v++) {
        uint32_t u = wk_polygon_prev(P, v), w = wk_polygon_next(P, v);
        if (wk_orient2d_counted(R, p[u], p[v], p[w]) != 0) continue;
        /* Collinear: straight on (valid) if u and w lie on opposite sides of
        ** v, a spike if on the same side.  Exact: only comparisons. */
        if ((wk_point_lex_cmp(p[u], p[v]) < 0) != (wk_point_lex_cmp(p[w], p[v]) < 0)) continue;
        return WK_FAIL(R, WK_EINPUT, name, line_of(lines, v),
                       "%s and %s fold back on each other at vertex %u (0-degree spike)",
                       describe(da, sizeof da, "edge", lines, u),
                       describe(db, sizeof db, "edge", lines, v), v);
    }
    return WK_OK;
}

/* Orientation of a simple ring, exactly: +1 counter-clockwise, -1
** clockwise.  The lexicographically smallest vertex is convex (both
** neighbours lie on one side of it; collinear would be a spike), so the turn
** there is the ring's. */
static int ring_orientation(wk_run *R, const wk_polygon *P, uint32_t ring) {
    uint32_t s = P->ring_start[ring], m = s;
    for (uint32_t i = s + 1; i < ring_end(P, ring); i++)
        if (wk_point_lex_cmp(P->p[i], P->p[m]) < 0) m = i;
    return wk_orient2d_counted(R, P->p[wk_polygon_prev(P, m)], P->p[m], P->p[wk_polygon_next(P, m)]);
}

/* The rings' nesting as the sweep found it (sweep_nest): ring 0 must be
** enclosed by nothing, every hole by ring 0 exactly. */
static wk_status check_nesting(wk_run *R, const wk_polygon *P, const uint32_t *parent,
                               const long *lines) {
    if (parent[0] != WK_NONE)
        return WK_FAIL(R, WK_EINPUT, P->name, line_of(lines, 0),
                       "the outer ring (ring 0, the first) lies inside ring %u: the outer "
                       "boundary must come first and contain every hole", parent[0]);
    for (uint32_t k = 1; k < P->n_rings; k++) {
        long line = line_of(lines, P->ring_start[k]);
        if (parent[k] == WK_NONE)
            return WK_FAIL(R, WK_EINPUT, P->name, line,
                           "hole %u (ring %u, vertices %u..%u) is not inside the outer ring", k, k,
                           P->ring_start[k], ring_end(P, k) - 1);
        if (parent[k] != 0)
            return WK_FAIL(R, WK_EINPUT, P->name, line,
                           "hole %u (ring %u) lies inside hole %u: a hole inside a hole is a "
                           "separate polygon (compute it on its own)", k, k, parent[k]);
    }
    return WK_OK;
}

/* Coinciding vertices, then the sweep (intersections, and the nesting of
** the rings when there are holes).  ccw[k]: ring k's orientation as it
** stands (NULL for one ring).  Needs 5n words of scratch. */
static wk_status check_simple(wk_run *R, const wk_polygon *P, const int8_t *ccw,
                              const long *lines) {
    wk_status st = WK_OK;
    char da[96], db[96];
    const wk_point *p = P->p;
    uint32_t n = P->n, h = P->n_rings;
    const char *name = P->name;
    uint32_t *buf = WK_NEW_ARRAY(R, uint32_t, n);
    uint32_t *tmp = WK_NEW_ARRAY(R, uint32_t, n);
    sweep S = {R, P, p, n, WK_NONE, NULL, NULL, NULL, WK_NONE, WK_NONE, WK_NONE,
               WK_SEG_DISJOINT, NULL, NULL, NULL};
    if (!buf || !tmp) goto oom;
    for (uint32_t i = 0; i < n; i++) buf[i] = i;
    const uint32_t *order = sort_vertices(p, buf, tmp, n);
    for (uint32_t k = 1; k < n; k++) {
        uint32_t a = order[k - 1], b = order[k];
        if (!same_point(p[a], p[b])) continue;
        if (a > b) {
            uint32_t t = a;
            a = b;
            b = t;
        }
        st = WK_FAIL(R, WK_EINPUT, name, line_of(lines, a), "%s coincides with %s",
                     describe(da, sizeof da, "vertex", lines, a),
                     describe(db, sizeof db, "vertex", lines, b));
        goto done;
    }
    S.lft = WK_NEW_ARRAY(R, uint32_t, n);
    S.rgt = WK_NEW_ARRAY(R, uint32_t, n);
    S.par = WK_NEW_ARRAY(R, uint32_t, n);
    if (!S.lft || !S.rgt || !S.par) goto oom;
    if (h > 1) {
        S.ccw = ccw;
        S.parent = WK_NEW_ARRAY(R, uint32_t, h);
        S.seen = WK_NEW_ARRAY(R, uint8_t, h);
        if (!S.parent || !S.seen) goto oom;
    }
    if (!sweep_run(&S, order)) st = report_intersection(R, &S, name, lines);
    else if (h > 1) st = check_nesting(R, P, S.parent, lines);
    goto done;
oom:
    st = WK_ENOMEM;
done:
    if (S.parent) WK_FREE_ARRAY(R, S.parent, h);
    if (S.seen) WK_FREE_ARRAY(R, S.seen, h);
    WK_FREE_ARRAY(R, S.lft, n);
    WK_FREE_ARRAY(R, S.rgt, n);
    WK_FREE_ARRAY(R, S.par, n);
    WK_FREE_ARRAY(R, buf, n);
    WK_FREE_ARRAY(R, tmp, n);
    return st;
}

bool wk_polygon_is_reflex_counted(wk_run *R, const wk_polygon *P, uint32_t i) {
    return wk_orient2d_counted(R, P->p[wk_polygon_prev(P, i)], P->p[i],
                               P->p[wk_polygon_next(P, i)]) < 0;
}

/* The input domain's angle bound: a vertex whose two edges are antiparallel
** to WK_ANTIPARALLEL_SIN (tolerance.h) is a needle (a spike, or a crack of
** interior angle near 2 pi) that the wavefront cannot resolve in doubles: its
** vertex would move at 1 / sin times the edges' speed.  Decided exactly as
** the wavefront will (the same offset lines, relative to the same origin),
** so a polygon accepted here never fails with "input vertex is a spike".
** i is a stored vertex; messages name the input vertex. */
static wk_status check_needles(wk_run *R, const wk_polygon *P, const long *lines) {
    uint32_t n = P->n;
    wk_point o = wk_polygon_centre(P);
    for (uint32_t i = 0; i < n; i++) {
        uint32_t h = wk_polygon_prev(P, i);
        wk_offset_line a, b;
        wk_offset_line_of_edge_at(P, h, o, &a);
        wk_offset_line_of_edge_at(P, i, o, &b);
        wk_point v;
        if (wk_vertex_velocity(&a, &b, &v) != WK_VEL_ANTIPARALLEL) continue;
        uint32_t in = P->input_index[i];
        double sine = fabs(a.ux * b.uy - a.uy * b.ux);
        return WK_FAIL(R, WK_EINPUT, P->name, line_of(lines, in),
                       "vertex %u is a needle: its edges are antiparallel to a sine of %.3g, below "
                       "the %g the wavefront resolves (input domain, see README)",
                       in, sine, WK_ANTIPARALLEL_SIN);
    }
    return WK_OK;
}

/* The input domain's bound on holes: each hole's bounding-box diagonal at
** least WK_POLYGON_MIN_HOLE_REL of the polygon's (wskel.h says why). */
static wk_status check_hole_sizes(wk_run *R, const wk_polygon *P, const long *lines) {
    if (P->n_rings == 1) return WK_OK;
    double scale = wk_polygon_scale(P);
    for (uint32_t k = 1; k < P->n_rings; k++) {
        uint32_t s = P->ring_start[k];
        double x0 = P->p[s].x, x1 = x0, y0 = P->p[s].y, y1 = y0;
        for (uint32_t i = s + 1; i < ring_end(P, k); i++) {
            x0 = fmin(x0, P->p[i].x);
            x1 = fmax(x1, P->p[i].x);
            y0 = fmin(y0, P->p[i].y);
            y1 = fmax(y1, P->p[i].y);
        }
        double d = hypot(x1 - x0, y1 - y0);
        if (!(d >= WK_POLYGON_MIN_HOLE_REL * scale))
            return WK_FAIL(R, WK_EINPUT, P->name, line_of(lines, s),
                           "hole %u is %.3g across, below %g of the polygon's %.3g (input "
                           "domain, see README: a hole below the tolerance cannot be resolved)",
                           k, d, WK_POLYGON_MIN_HOLE_REL, scale);
    }
    return WK_OK;
}

/* The input domain's bound on the distance from the origin: the largest
** |coordinate| at most WK_POLYGON_MAX_OFFSET_REL diagonals (wskel.h says
** why).  Names the farthest vertex. */
static wk_status check_offset(wk_run *R, const wk_polygon *P, const long *lines) {
    double scale = wk_polygon_scale(P), far = 0;
    uint32_t at = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        double m = fmax(fabs(P->p[i].x), fabs(P->p[i].y));
        if (m > far) far = m, at = i;
    }
    if (!(far <= WK_POLYGON_MAX_OFFSET_REL * scale))
        return WK_FAIL(R, WK_EINPUT, P->name, line_of(lines, at),
                       "vertex %u (%.17g, %.17g) is %.3g polygon diagonals (%.3g) from the "
                       "origin, above the %.3g whose output coordinates keep the tolerance's "
                       "precision (input domain, see README): translate the polygon nearer "
                       "the origin",
                       P->input_index ? P->input_index[at] : at, P->p[at].x, P->p[at].y,
                       far / scale, scale, WK_POLYGON_MAX_OFFSET_REL);
    return WK_OK;
}

/* The input domain's bound on thinness: refuse a polygon that may lie
** wholly within c = WK_POLYGON_MIN_WIDTH_REL diagonals of its boundary,
** i.e. A < c P + pi/2 r c^2 (tolerance.h says why, and why this is necessary
** for an inscribed radius <= c).  A is exact then rounded (wk_polygon_area),
** P sums the edges' lengths from coordinate differences (one rounding each,
** no origin enters), r is the reflex count (exact): deterministic, and the
** same for the stored polygon (wk_polygon_validate, the writer's round
** trip).  Names the vertex farthest from the bounding-box centre, which
** usually stretches the diagonal. */
static wk_status check_width(wk_run *R, const wk_polygon *P, uint32_t r, const long *lines) {
    double scale = wk_polygon_scale(P), c = WK_POLYGON_MIN_WIDTH_REL * scale;
    double area = wk_polygon_area(P), perimeter = 0, far = -1;
    wk_point o = wk_polygon_centre(P);
    uint32_t at = 0;
    for (uint32_t i = 0; i < P->n; i++) {
        wk_point a = P->p[i], b = P->p[wk_polygon_next(P, i)];
        perimeter += hypot(b.x - a.x, b.y - a.y);
        double m = hypot(a.x - o.x, a.y - o.y);
        if (m > far) far = m, at = i;
    }
    const double half_pi = 1.5707963267948966;
    if (!(area < c * perimeter + half_pi * r * c * c)) return WK_OK;
    uint32_t in = P->input_index ? P->input_index[at] : at;
    return WK_FAIL(R, WK_EINPUT, P->name, line_of(lines, in),
                   "polygon thinner than the tolerance: area %.6g, perimeter %.6g, diagonal %.6g: "
                   "mean width 2A/P = %.3g diagonals, below 2c for c = %g diagonals "
                   "(WK_POLYGON_MIN_WIDTH_REL; the bound: A < c P + pi/2 r c^2, %u reflex "
                   "vertices), so all of it may lie within the tolerance of its boundary (input "
                   "domain, see README); its vertex farthest from the centre: vertex %u "
                   "(%.17g, %.17g)",
                   area, perimeter, scale, 2 * area / perimeter / scale, WK_POLYGON_MIN_WIDTH_REL,
                   r, in, P->p[at].x, P->p[at].y);
}

/* ---- construction ---- */

/* Reverse ring k in place: stored local vertex j := input local m-1-j.
** Stored local edge j then runs input local m-1-j -> m-2-j, i.e. it is
** input local edge m-2-j (j < m-1) or m-1 (input local 0 -> m-1): weights
** w[0..m-2] reverse among themselves, w[m-1] stays. */
static void reverse_ring(wk_polygon *P, uint32_t k) {
    uint32_t s = P->ring_start[k], m = ring_size(P, k);
    for (uint32_t i = s, j = s + m - 1; i < j; i++, j--) {
        wk_point tp = P->p[i];
        P->p[i] = P->p[j];
        P->p[j] = tp;
        uint32_t ti = P->input_index[i];
        P->input_index[i] = P->input_index[j];
        P->input_index[j] = ti;
    }
    for (uint32_t i = s, j = s + m - 2; i < j; i++, j--) {
        double tw = P->w[i];
        P->w[i] = P->w[j];
        P->w[j] = tw;
    }
}

static wk_status check_rings(wk_run *R, const wk_polygon *P, int8_t *ccw, const long *lines) {
    wk_status st;
    for (uint32_t k = 0; k < P->n_rings; k++)
        if ((st = check_local(R, P, k, lines)) != WK_OK) return st;
    for (uint32_t k = 0; k < P->n_rings; k++) ccw[k] = (int8_t)ring_orientation(R, P, k);
    return check_simple(R, P, P->n_rings > 1 ? ccw : NULL, lines);
}

wk_status wk_polygon_from_rings(wk_run *R, uint32_t n_rings, const uint32_t *ring_size_in,
                                const double *x, const double *y, const double *w,
                                const char *name, const long *lines, wk_polygon **out) {
    *out = NULL;
    if (!name) name = "";
    if (n_rings < 1)
        return WK_FAIL(R, WK_EINPUT, name, 0, "a polygon needs at least one ring");
    if (n_rings > WK_POLYGON_MAX_RINGS)
        return WK_FAIL(R, WK_EINPUT, name, 0, "too many rings (%u; the limit is %u)", n_rings,
                       WK_POLYGON_MAX_RINGS);
    uint64_t total = 0;
    for (uint32_t k = 0; k < n_rings; k++) {
        if (ring_size_in[k] < 3) {
            long line = lines && total < WK_POLYGON_MAX_N ? lines[total] : 0;
            if (n_rings == 1)
                return WK_FAIL(R, WK_EINPUT, name, line,
                               "polygon needs at least 3 vertices (got %u)", ring_size_in[k]);
            return WK_FAIL(R, WK_EINPUT, name, line,
                           "ring %u needs at least 3 vertices (got %u)", k, ring_size_in[k]);
        }
        total += ring_size_in[k];
    }
    if (total > WK_POLYGON_MAX_N)
        return WK_FAIL(R, WK_EINPUT, name, 0, "too many vertices (%llu; the limit is %u)",
                       (unsigned long long)total, WK_POLYGON_MAX_N);
    uint32_t n = (uint32_t)total;
    wk_status st;
    int8_t *ccw = NULL;
    wk_polygon *P = WK_NEW_ARRAY(R, wk_polygon, 1);
    if (!P) return WK_ENOMEM;
    P->n = n;
    P->n_rings = n_rings;
    snprintf(P->name, sizeof P->name, "%s", name);
    P->p = WK_NEW_ARRAY(R, wk_point, n);
    P->w = WK_NEW_ARRAY(R, double, n);
    P->input_index = WK_NEW_ARRAY(R, uint32_t, n);
    P->ring_start = WK_NEW_ARRAY(R, uint32_t, (size_t)n_rings + 1);
    if (n_rings > 1) P->ring_of = WK_NEW_ARRAY(R, uint32_t, n);
    ccw = WK_NEW_ARRAY(R, int8_t, n_rings);
    if (!P->p || !P->w || !P->input_index || !P->ring_start || (n_rings > 1 && !P->ring_of) ||
        !ccw) {
        st = WK_ENOMEM;
        goto fail;
    }
    P->ring_start[0] = 0;
    for (uint32_t k = 0; k < n_rings; k++) P->ring_start[k + 1] = P->ring_start[k] + ring_size_in[k];
    for (uint32_t k = 0; n_rings > 1 && k < n_rings; k++)
        for (uint32_t i = P->ring_start[k]; i < P->ring_start[k + 1]; i++) P->ring_of[i] = k;
    for (uint32_t i = 0; i < n; i++) {
        P->p[i] = (wk_point){x[i], y[i]};
        P->w[i] = w ? w[i] : 1.0;
        P->input_index[i] = i;
    }
    if ((st = check_values(R, P->p, P->w, n, name, lines)) != WK_OK ||
        (st = check_rings(R, P, ccw, lines)) != WK_OK)
        goto fail;
    /* Stored orientation: the outer ring counter-clockwise, holes clockwise. */
    for (uint32_t k = 0; k < n_rings; k++)
        if (ccw[k] != (k == 0 ? 1 : -1)) {
            reverse_ring(P, k);
            if (k == 0) P->reversed = true;
        }
    /* Defensive: a valid polygon has positive exact area, so the rounded
    ** area is positive too unless the products underflow (coordinates
    ** around 1e-160 and below), which the predicates do not support. */
    double area = wk_polygon_area(P);
    if (!(area > 0)) {
        st = WK_FAIL(R, WK_EINPUT, name, line_of(lines, 0),
                     "polygon area underflows (computed %g): coordinates too small", area);
        goto fail;
    }
    if ((st = check_needles(R, P, lines)) != WK_OK) goto fail;
    if ((st = check_hole_sizes(R, P, lines)) != WK_OK) goto fail;
    if ((st = check_offset(R, P, lines)) != WK_OK) goto fail;
    P->r = 0;
    for (uint32_t i = 0; i < n; i++) P->r += wk_polygon_is_reflex_counted(R, P, i);
    if ((st = check_width(R, P, P->r, lines)) != WK_OK) goto fail;
    WK_FREE_ARRAY(R, ccw, n_rings);
    *out = P;
    return WK_OK;
fail:
    if (ccw) WK_FREE_ARRAY(R, ccw, n_rings);
    wk_polygon_free(R, P);
    return st;
}

wk_status wk_polygon_from_arrays(wk_run *R, uint32_t n, const double *x, const double *y,
                                 const double *w, const char *name, const long *lines,
                                 wk_polygon **out) {
    return wk_polygon_from_rings(R, 1, &n, x, y, w, name, lines, out);
}

wk_status wk_polygon_validate(wk_run *R, const wk_polygon *P) {
    const char *name = P->name;
    uint32_t n = P->n, h = P->n_rings;
    if (n < 3 || n > WK_POLYGON_MAX_N)
        return WK_FAIL(R, WK_EINPUT, name, 0, "vertex count %u out of range [3, %u]", n,
                       WK_POLYGON_MAX_N);
    if (h < 1 || h > WK_POLYGON_MAX_RINGS || !P->ring_start || P->ring_start[0] != 0 ||
        P->ring_start[h] != n || (h > 1) != (P->ring_of != NULL))
        return WK_FAIL(R, WK_EINPUT, name, 0, "ring table out of range (%u rings)", h);
    for (uint32_t k = 0; k < h; k++) {
        if (ring_size(P, k) < 3 || ring_size(P, k) > n)
            return WK_FAIL(R, WK_EINPUT, name, 0, "ring %u has %u vertices", k, ring_size(P, k));
        for (uint32_t i = P->ring_start[k]; h > 1 && i < ring_end(P, k); i++)
            if (P->ring_of[i] != k)
                return WK_FAIL(R, WK_EINPUT, name, 0, "vertex %u's ring is %u, not %u", i,
                               P->ring_of[i], k);
    }
    wk_status st;
    int8_t *ccw = WK_NEW_ARRAY(R, int8_t, h);
    if (!ccw) return WK_ENOMEM;
    if ((st = check_values(R, P->p, P->w, n, name, NULL)) != WK_OK ||
        (st = check_rings(R, P, ccw, NULL)) != WK_OK)
        goto done;
    for (uint32_t k = 0; k < h; k++)
        if (ccw[k] != (k == 0 ? 1 : -1)) {
            st = WK_FAIL(R, WK_EINPUT, name, 0,
                         k == 0 ? "polygon is stored clockwise"
                                : "hole %u is stored counter-clockwise (holes are stored clockwise)",
                         k);
            goto done;
        }
    if ((st = check_needles(R, P, NULL)) != WK_OK || (st = check_hole_sizes(R, P, NULL)) != WK_OK ||
        (st = check_offset(R, P, NULL)) != WK_OK)
        goto done;
    uint32_t r = 0;
    for (uint32_t i = 0; i < n; i++) r += wk_polygon_is_reflex_counted(R, P, i);
    if (r != P->r) st = WK_FAIL(R, WK_EINPUT, name, 0, "reflex count is %u, stored %u", r, P->r);
    else st = check_width(R, P, r, NULL);
done:
    WK_FREE_ARRAY(R, ccw, h);
    return st;
}

void wk_polygon_free(wk_run *R, wk_polygon *P) {
    if (!P) return;
    WK_FREE_ARRAY(R, P->p, P->n);
    WK_FREE_ARRAY(R, P->w, P->n);
    WK_FREE_ARRAY(R, P->input_index, P->n);
    if (P->ring_start) WK_FREE_ARRAY(R, P->ring_start, (size_t)P->n_rings + 1);
    if (P->ring_of) WK_FREE_ARRAY(R, P->ring_of, P->n);
    if (P->dir) WK_FREE_ARRAY(R, P->dir, P->n);
    if (P->corner_vertex) WK_FREE_ARRAY(R, P->corner_vertex, P->n);
    if (P->edge_of) WK_FREE_ARRAY(R, P->edge_of, P->n);
    WK_FREE_ARRAY(R, P, 1);
}

/* ---- queries ---- */

double wk_polygon_area(const wk_polygon *P) {
    /* Exact per ring, then rounded: a plain shoelace sum can come out zero
    ** or even negative for a valid but thin polygon, breaking "positive for
    ** counter-clockwise".  Holes are stored clockwise: they subtract. */
    double a = 0.0;
    for (uint32_t k = 0; k < P->n_rings; k++)
        a += wk_shoelace_exact(P->p + P->ring_start[k], ring_size(P, k));
    return 0.5 * a;
}

bool wk_polygon_is_reflex(const wk_polygon *P, uint32_t i) {
    /* Strict right turn (the interior is on the left of every stored edge);
    ** straight on (180 degrees) is not reflex. */
    return wk_orient2d(P->p[wk_polygon_prev(P, i)], P->p[i], P->p[wk_polygon_next(P, i)], NULL) < 0;
}

void wk_polygon_bbox(const wk_polygon *P, wk_point *lo, wk_point *hi) {
    *lo = *hi = P->p[0];
    for (uint32_t i = 1; i < P->n; i++) {
        if (P->p[i].x < lo->x) lo->x = P->p[i].x;
        if (P->p[i].x > hi->x) hi->x = P->p[i].x;
        if (P->p[i].y < lo->y) lo->y = P->p[i].y;
        if (P->p[i].y > hi->y) hi->y = P->p[i].y;
    }
}

double wk_polygon_edge_distance(const wk_polygon *P, uint32_t e, wk_point a) {
    wk_point p = P->p[e], q = P->p[wk_polygon_next(P, e)];
    double dx = q.x - p.x, dy = q.y - p.y, l2 = dx * dx + dy * dy;
    double m = l2 > 0 ? ((a.x - p.x) * dx + (a.y - p.y) * dy) / l2 : 0;
    m = m < 0 ? 0 : m > 1 ? 1 : m;
    return hypot(p.x + m * dx - a.x, p.y + m * dy - a.y);
}

double wk_polygon_scale(const wk_polygon *P) {
    wk_point lo, hi;
    wk_polygon_bbox(P, &lo, &hi);
    return hypot(hi.x - lo.x, hi.y - lo.y);
}

uint32_t wk_polygon_input_edge(const wk_polygon *P, uint32_t e) {
    /* A ring kept as given: stored edge e is input edge input_index[e].  A
    ** reversed ring (its first stored vertex is its last input one): stored
    ** edge e runs backwards along the input edge that starts at the input
    ** vertex stored at next(e). */
    uint32_t k = wk_polygon_ring(P, e), s = P->ring_start[k];
    bool reversed = P->input_index[s] != s;
    return P->input_index[reversed ? wk_polygon_next(P, e) : e];
}

uint32_t wk_polygon_output_node(const wk_polygon *P, uint32_t j) {
    return j < P->n ? P->input_index[j] : j;
}

wk_status wk_polygon_write_wpoly(wk_run *R, FILE *f, const wk_polygon *P) {
    errno = 0;
    if (P->n_rings == 1)
        fprintf(f, "# wskel polygon: %u vertices, counter-clockwise; x y weight\n", P->n);
    else
        fprintf(f, "# wskel polygon: %u vertices in %u rings (the outer one counter-clockwise, "
                "%u hole%s clockwise); x y weight\n", P->n, P->n_rings, P->n_rings - 1,
                P->n_rings == 2 ? "" : "s");
    /* %.17g round-trips every double. */
    for (uint32_t k = 0; k < P->n_rings; k++) {
        fprintf(f, "%u\n", ring_size(P, k));
        for (uint32_t i = P->ring_start[k]; i < ring_end(P, k); i++)
            fprintf(f, "%.17g %.17g %.17g\n", P->p[i].x, P->p[i].y, P->w[i]);
    }
    if (fflush(f) != 0 || ferror(f))
        return WK_FAIL(R, WK_EINPUT, P->name, 0, "cannot write the polygon: %s",
                       errno ? strerror(errno) : "write error");
    return WK_OK;
}
