/*
** polygon.c: the input polygon: construction from arrays, validation,
** counter-clockwise orientation, and the small queries on it.
**
** Invariants of a wk_polygon handed out by wk_polygon_from_arrays:
**   - 3 <= n <= WK_POLYGON_MAX_N; coordinates finite with magnitude at most
**     WK_POLYGON_MAX_COORD; weights finite and > 0;
**   - the boundary is simple: consecutive vertices differ, no other two
**     vertices coincide, no edge meets a non-adjacent edge, adjacent edges
**     meet only at their shared vertex (straight-on 180-degree vertices are
**     allowed, 0-degree spikes are not), and the vertices are not all on one
**     line; so the area is positive;
**   - p[] is counter-clockwise.  If the input was clockwise, reversed is true
**     and stored vertex j is input vertex n-1-j; stored edge j
**     (p[j] -> p[j+1]) is then input edge (n-2-j) mod n, and w[j] is that
**     input edge's weight, so every weight stays on its geometric edge;
**   - input_index[j] is the input number of stored vertex j;
**   - r is the number of reflex vertices (strict right turns, exactly).
**
** Validation runs on the input order, so every message uses input numbering
** (vertex i, edge i = input vertex i -> i+1, counted from 0) and the input
** line of the culprit when the caller passed lines[].
**
** The simplicity test is a Shamos-Hoey sweep, O(n log n), deciding every
** comparison with the exact predicates (see sweep_* below for why it is
** complete on degenerate inputs).  It is not Bentley-Ottmann: it stops at
** the first intersection it finds, which need not be the leftmost.
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

static uint32_t next_of(uint32_t i, uint32_t n) { return i + 1 == n ? 0 : i + 1; }
static uint32_t prev_of(uint32_t i, uint32_t n) { return i == 0 ? n - 1 : i - 1; }

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
    const wk_point *p;
    uint32_t n;
    uint32_t root;
    uint32_t *lft, *rgt, *par; /* treap links by edge id, WK_NONE if none */
    /* first intersection found: edges a and b, how they meet, and for a
    ** touch the vertex lying on the other edge (WK_NONE if not known) */
    uint32_t bad_a, bad_b, bad_vertex;
    wk_seg_meet bad_kind;
} sweep;

static uint64_t edge_priority(uint32_t e) {
    uint64_t z = (uint64_t)e + 0x9E3779B97F4A7C15u; /* splitmix64 finaliser */
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* Vertex id of the left (lexicographically smaller) endpoint of edge e. */
static uint32_t left_vertex(const sweep *S, uint32_t e) {
    uint32_t f = next_of(e, S->n);
    return wk_point_lex_cmp(S->p[e], S->p[f]) < 0 ? e : f;
}
static uint32_t right_vertex(const sweep *S, uint32_t e) {
    uint32_t f = next_of(e, S->n);
    return wk_point_lex_cmp(S->p[e], S->p[f]) < 0 ? f : e;
}

static bool adjacent_edges(uint32_t a, uint32_t b, uint32_t n) {
    return next_of(a, n) == b || next_of(b, n) == a;
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
    if (a == WK_NONE || b == WK_NONE || adjacent_edges(a, b, S->n)) return true;
    const wk_point *p = S->p;
    uint32_t n = S->n;
    wk_seg_meet m =
        wk_segments_meet_counted(S->R, p[a], p[next_of(a, n)], p[b], p[next_of(b, n)]);
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

/* Runs the sweep over the vertices in lexicographic order; false after
** recording an intersection. */
static bool sweep_run(sweep *S, const uint32_t *order) {
    uint32_t n = S->n;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t v = order[k];
        uint32_t in = prev_of(v, n), out = v; /* the edges at v */
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
static void touch_vertex(wk_run *R, const wk_point *p, uint32_t n, uint32_t a, uint32_t b,
                         uint32_t *vertex, uint32_t *on_edge) {
    uint32_t ends[2][2] = {{a, next_of(a, n)}, {b, next_of(b, n)}};
    uint32_t edges[2] = {a, b};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            uint32_t v = ends[i][j], e = edges[1 - i];
            if (wk_segments_meet_counted(R, p[v], p[v], p[e], p[next_of(e, n)]) !=
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
        if (v == WK_NONE) touch_vertex(R, S->p, S->n, a, b, &v, &e);
        if (v != WK_NONE) {
            /* If an edge at v runs along e, say so: "overlaps" tells more
            ** than "touches". */
            uint32_t n = S->n, at_v[2] = {prev_of(v, n), v};
            for (int i = 0; i < 2; i++) {
                uint32_t f = at_v[i];
                if (!adjacent_edges(f, e, n) &&
                    wk_segments_meet_counted(R, S->p[f], S->p[next_of(f, n)], S->p[e],
                                             S->p[next_of(e, n)]) == WK_SEG_OVERLAP) {
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
            uint32_t f = adjacent_edges(v, e, n) ? prev_of(v, n) : v;
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
    }
    if (w)
        for (uint32_t i = 0; i < n; i++) {
            if (!isfinite(w[i]))
                return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                               "weight of edge %u is not a finite number (got %g)", i, w[i]);
            if (!(w[i] > 0))
                return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                               "weight of edge %u must be > 0 (got %g)", i, w[i]);
        }
    return WK_OK;
}

/* The local checks, O(n), no memory: repeated vertices, all on one line,
** 0-degree spikes. */
static wk_status check_local(wk_run *R, const wk_point *p, uint32_t n, const char *name,
                             const long *lines) {
    char da[96], db[96];
    for (uint32_t i = 0; i < n; i++) {
        uint32_t j = next_of(i, n);
        if (!same_point(p[i], p[j])) continue;
        if (j == 0)
            return WK_FAIL(R, WK_EINPUT, name, line_of(lines, i),
                           "the last vertex (%u) repeats the first: the polygon closes "
                           "implicitly, do not repeat vertex 0 (zero-length edge %u)",
                           i, i);
        return WK_FAIL(R, WK_EINPUT, name, line_of(lines, j),
                       "vertex %u repeats vertex %u (zero-length edge %u)", j, i, i);
    }
    uint32_t k = 2;
    while (k < n && wk_orient2d_counted(R, p[0], p[1], p[k]) == 0) k++;
    if (k == n)
        return WK_FAIL(R, WK_EINPUT, name, line_of(lines, 0),
                       "polygon has zero area (all %u vertices are collinear)", n);
    for (uint32_t v = 0; v < n; v++) {
        uint32_t u = prev_of(v, n), w = next_of(v, n);
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

/* Coinciding vertices, then the sweep.  Needs 5n words of scratch. */
static wk_status check_simple(wk_run *R, const wk_point *p, uint32_t n, const char *name,
                              const long *lines) {
    wk_status st = WK_OK;
    char da[96], db[96];
    uint32_t *buf = WK_NEW_ARRAY(R, uint32_t, n);
    uint32_t *tmp = WK_NEW_ARRAY(R, uint32_t, n);
    sweep S = {R, p, n, WK_NONE, NULL, NULL, NULL, WK_NONE, WK_NONE, WK_NONE, WK_SEG_DISJOINT};
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
    if (!sweep_run(&S, order)) st = report_intersection(R, &S, name, lines);
    goto done;
oom:
    st = WK_ENOMEM;
done:
    WK_FREE_ARRAY(R, S.lft, n);
    WK_FREE_ARRAY(R, S.rgt, n);
    WK_FREE_ARRAY(R, S.par, n);
    WK_FREE_ARRAY(R, buf, n);
    WK_FREE_ARRAY(R, tmp, n);
    return st;
}

/* Orientation of a simple polygon, exactly: +1 counter-clockwise, -1
** clockwise.  The lexicographically smallest vertex is convex (both
** neighbours lie on one side of it; collinear would be a spike), so the turn
** there is the polygon's. */
static int orientation(wk_run *R, const wk_point *p, uint32_t n) {
    uint32_t m = 0;
    for (uint32_t i = 1; i < n; i++)
        if (wk_point_lex_cmp(p[i], p[m]) < 0) m = i;
    return wk_orient2d_counted(R, p[prev_of(m, n)], p[m], p[next_of(m, n)]);
}

bool wk_polygon_is_reflex_counted(wk_run *R, const wk_polygon *P, uint32_t i) {
    uint32_t n = P->n;
    return wk_orient2d_counted(R, P->p[prev_of(i, n)], P->p[i], P->p[next_of(i, n)]) < 0;
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
        uint32_t h = prev_of(i, n);
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

/* ---- construction ---- */

wk_status wk_polygon_from_arrays(wk_run *R, uint32_t n, const double *x, const double *y,
                                 const double *w, const char *name, const long *lines,
                                 wk_polygon **out) {
    *out = NULL;
    if (!name) name = "";
    if (n < 3)
        return WK_FAIL(R, WK_EINPUT, name, 0, "polygon needs at least 3 vertices (got %u)", n);
    if (n > WK_POLYGON_MAX_N)
        return WK_FAIL(R, WK_EINPUT, name, 0, "too many vertices (%u; the limit is %u)", n,
                       WK_POLYGON_MAX_N);
    wk_status st;
    wk_polygon *P = WK_NEW_ARRAY(R, wk_polygon, 1);
    if (!P) return WK_ENOMEM;
    P->n = n;
    snprintf(P->name, sizeof P->name, "%s", name);
    P->p = WK_NEW_ARRAY(R, wk_point, n);
    P->w = WK_NEW_ARRAY(R, double, n);
    P->input_index = WK_NEW_ARRAY(R, uint32_t, n);
    if (!P->p || !P->w || !P->input_index) {
        st = WK_ENOMEM;
        goto fail;
    }
    for (uint32_t i = 0; i < n; i++) {
        P->p[i] = (wk_point){x[i], y[i]};
        P->w[i] = w ? w[i] : 1.0;
        P->input_index[i] = i;
    }
    if ((st = check_values(R, P->p, P->w, n, name, lines)) != WK_OK ||
        (st = check_local(R, P->p, n, name, lines)) != WK_OK ||
        (st = check_simple(R, P->p, n, name, lines)) != WK_OK)
        goto fail;

    if (orientation(R, P->p, n) < 0) {
        /* Reverse: stored vertex j := input vertex n-1-j.  Stored edge j then
        ** runs input n-1-j -> n-2-j, i.e. it is input edge (n-2-j) mod n:
        ** weights w[0..n-2] reverse among themselves, w[n-1] stays. */
        for (uint32_t i = 0, j = n - 1; i < j; i++, j--) {
            wk_point tp = P->p[i];
            P->p[i] = P->p[j];
            P->p[j] = tp;
        }
        for (uint32_t i = 0, j = n - 2; i < j; i++, j--) {
            double tw = P->w[i];
            P->w[i] = P->w[j];
            P->w[j] = tw;
        }
        for (uint32_t i = 0; i < n; i++) P->input_index[i] = n - 1 - i;
        P->reversed = true;
    }
    /* Defensive: a simple polygon has positive exact area, so the rounded
    ** area is positive too unless the products underflow (coordinates
    ** around 1e-160 and below), which the predicates do not support. */
    double area = wk_polygon_area(P);
    if (!(area > 0)) {
        st = WK_FAIL(R, WK_EINPUT, name, line_of(lines, 0),
                     "polygon area underflows (computed %g): coordinates too small", area);
        goto fail;
    }
    if ((st = check_needles(R, P, lines)) != WK_OK) goto fail;
    P->r = 0;
    for (uint32_t i = 0; i < n; i++) P->r += wk_polygon_is_reflex_counted(R, P, i);
    *out = P;
    return WK_OK;
fail:
    wk_polygon_free(R, P);
    return st;
}

wk_status wk_polygon_validate(wk_run *R, const wk_polygon *P) {
    const char *name = P->name;
    uint32_t n = P->n;
    if (n < 3 || n > WK_POLYGON_MAX_N)
        return WK_FAIL(R, WK_EINPUT, name, 0, "vertex count %u out of range [3, %u]", n,
                       WK_POLYGON_MAX_N);
    wk_status st;
    if ((st = check_values(R, P->p, P->w, n, name, NULL)) != WK_OK ||
        (st = check_local(R, P->p, n, name, NULL)) != WK_OK ||
        (st = check_simple(R, P->p, n, name, NULL)) != WK_OK)
        return st;
    if (orientation(R, P->p, n) < 0)
        return WK_FAIL(R, WK_EINPUT, name, 0, "polygon is stored clockwise");
    if ((st = check_needles(R, P, NULL)) != WK_OK) return st;
    uint32_t r = 0;
    for (uint32_t i = 0; i < n; i++) r += wk_polygon_is_reflex_counted(R, P, i);
    if (r != P->r)
        return WK_FAIL(R, WK_EINPUT, name, 0, "reflex count is %u, stored %u", r, P->r);
    return WK_OK;
}

void wk_polygon_free(wk_run *R, wk_polygon *P) {
    if (!P) return;
    WK_FREE_ARRAY(R, P->p, P->n);
    WK_FREE_ARRAY(R, P->w, P->n);
    WK_FREE_ARRAY(R, P->input_index, P->n);
    WK_FREE_ARRAY(R, P, 1);
}

/* ---- queries ---- */

double wk_polygon_area(const wk_polygon *P) {
    /* Exact, then rounded: a plain shoelace sum can come out zero or even
    ** negative for a valid but thin polygon, breaking "positive for
    ** counter-clockwise". */
    return 0.5 * wk_shoelace_exact(P->p, P->n);
}

bool wk_polygon_is_reflex(const wk_polygon *P, uint32_t i) {
    uint32_t n = P->n;
    /* Strict right turn at a counter-clockwise vertex; straight on (180
    ** degrees) is not reflex. */
    return wk_orient2d(P->p[prev_of(i, n)], P->p[i], P->p[next_of(i, n)], NULL) < 0;
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

double wk_polygon_scale(const wk_polygon *P) {
    wk_point lo, hi;
    wk_polygon_bbox(P, &lo, &hi);
    return hypot(hi.x - lo.x, hi.y - lo.y);
}

uint32_t wk_polygon_input_edge(const wk_polygon *P, uint32_t e) {
    if (!P->reversed) return e;
    /* Stored edge e runs input vertex n-1-e -> n-2-e: input edge n-2-e, or
    ** n-1 (input vertex n-1 -> 0) for e = n-1. */
    return e + 1 < P->n ? P->n - 2 - e : P->n - 1;
}

uint32_t wk_polygon_output_node(const wk_polygon *P, uint32_t j) {
    return j < P->n ? P->input_index[j] : j;
}

wk_status wk_polygon_write_wpoly(wk_run *R, FILE *f, const wk_polygon *P) {
    errno = 0;
    fprintf(f, "# wskel polygon: %u vertices, counter-clockwise; x y weight\n%u\n", P->n, P->n);
    /* %.17g round-trips every double. */
    for (uint32_t i = 0; i < P->n; i++)
        fprintf(f, "%.17g %.17g %.17g\n", P->p[i].x, P->p[i].y, P->w[i]);
    if (fflush(f) != 0 || ferror(f))
        return WK_FAIL(R, WK_EINPUT, P->name, 0, "cannot write the polygon: %s",
                       errno ? strerror(errno) : "write error");
    return WK_OK;
}
