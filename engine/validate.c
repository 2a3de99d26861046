/*
** validate.c: the validator, the oracle that tests and `wskel --check` trust.
**
** Contract.  wk_validate(R, P, S, tol, rep) checks the properties below in
** this order and reports the first violation as WK_EINVALID, with a message
** "validate (x): ..." naming the property, the culprit (node, arc, edge: all
** stored ids) and the numbers.  tol is an absolute distance; tol <= 0 selects
** 1e-6 * wk_polygon_scale(P) (callers may pass a multiple of that).
**
**   (a) input nodes: S->n_input == P->n, S->n_nodes >= n, and node i < n is
**       input vertex i exactly (same doubles) with t == 0.
**   (b) other nodes: x, y, t finite, the point inside P or within tol of its
**       boundary, and t > 0, or |t| <= tol_t = tol / wmax with the point
**       within tol of the boundary: the trace of a feature below the
**       tolerance (an edge of 1e-16, a vertex off a line by 1e-12), resolved
**       at t = 0 within the time tolerance (tolerance.h).
**   (c) arcs: node ids < n_nodes, a != b; face ids < n, left != right; at
**       both ends v and for both faces e, |d_e(v) - w(e) t_v| <= tol, where
**       d_e is the signed distance from the supporting line of edge e,
**       positive inside (the wavefront of e reaches v at time t_v).  An arc
**       between two input vertices joins adjacent ones and has the edge
**       between them as a face: it traces that edge, swept at t = 0 by the
**       collinear rule.  An arc leaving input vertex v between v's two
**       edges, of equal weight and facing the same way, runs along the sum
**       of their normals within 4 tol (wk_validate_arc_bisector: for nearly
**       parallel edges the distances above leave its direction free).
**   (d) tree: every node is on an arc, all nodes are connected, and with h
**       holes exactly h arcs close a cycle (hence arcs == nodes - 1 + h; a
**       tree without holes).  Why h: P with h holes has Euler
**       characteristic 1 - h, and the faces (disks, one per edge) cut it
**       along the skeleton and the boundary, so the skeleton together with
**       the boundary rings has n faces and cyclomatic number n + h; the
**       boundary's n edges take n of those, leaving h to the arcs, one
**       around each hole.  With holes and unequal weights the skeleton may
**       be disconnected (islands, faces.h): then components may be > 1 and
**       arcs == nodes - components + h; (e) then checks that each island
**       is a closed loop inside one face, and (f) the face's sides, loops
**       included, pairwise (the bridges that faces.c adds are skipped).  At most one arc at an input
**       vertex leaves the boundary (its other end has t > tol_t): one
**       wavefront vertex starts there.  The others (any number) run at
**       t ~ 0: an edge swept at t = 0 by the collinear rule is traced by an
**       arc along it, and a corner between two swept edges has one arc along
**       each besides its bisector; a sub-tolerance feature leaves arcs at
**       t ~ 0 too.  Why no bound on their number: going round an input
**       vertex v inside P, the faces met are face(e_out) first and face(e_in)
**       last; by (c) every face met in between belongs to an edge whose line
**       passes through v, and an arc to another input vertex traces the one
**       edge between them, so each t ~ 0 arc at v is the trace of one swept
**       edge (or edge piece) ending at v: their number is the number of
**       swept pieces there.
**   (e) faces: for every edge e the arcs labelled e form the path of
**       wk_face_cycle (no branch, no dead end, no stray arc; closed loops
**       only around islands, with holes and unequal weights); the
**       face's signed area (xy projection) is >= -tol * scale; the face
**       areas sum to the polygon's area (outer ring minus holes) within
**       1e-6 relative plus eps_d times the faces' perimeters (see
**       check_face_areas).
**   (f) planarity: every face cycle is a simple polygon: no two of its sides
**       cross at a point interior to both, and no two overlap along a length
**       > tol.  A crossing is ignored when an endpoint of one side lies
**       within tol of the other side (nodes that nearly touch by rounding);
**       an overlap of two adjacent sides whose far ends lie within tol of
**       each other is a sliver on a sub-tolerance base (the face of an edge
**       shorter than tol), not a fold.
**
** Why (f) is checked per face and still proves that no two arcs anywhere
** cross and no arc leaves P: every arc lies on exactly two face cycles, once
** in each direction, and edge e on face e only, so the cycles sum (as 1-chains)
** to the boundary of P, and winding numbers add: for any point x off the
** skeleton, sum over faces of wind(face, x) = wind(P, x), which is 0 or 1.  A
** simple, positively oriented face has winding number 0 or 1 everywhere, so
** (e) and (f) together mean that each point of P lies in exactly one face and
** no point outside P lies in any.  If two arcs crossed, the points just left
** of both would lie in both their left faces (or one face would not be
** simple); if an arc crossed the boundary, points outside P would lie in a
** face.  This is exact up to the tolerances above, and its cost is about
** linear in the total number of face sides (2 arcs + n), where a global
** search over all arcs with a uniform grid stops being near-linear as soon
** as many long arcs run close together (a star with 10^5 thin spikes).
**
** What this does not prove, and checks left out on purpose.  (c), (e) and
** (f) make S a roof of P within tol: faces tiling P, each on its edge's
** plane z = d_e / w(e), continuous across every arc.  The straight skeleton
** is one such roof, the one the wavefront defines; nothing checked at the
** tolerance tells it from another roof within tol of it, and the straight
** skeleton is discontinuous in P where two events coincide (two reflex
** wavefront vertices meeting): polygons 1e-5 apart can have skeletons units
** apart, each passing for the other polygon (README, "The validator";
** tests/data/skeletons).  Implied, so not checked separately: (i) the roof
** never above the weighted distance, t_v <= dist(v, boundary) / w_min: a
** roof as above has gradient 1 / w(e) on face e, so along the segment from
** v to its nearest boundary point (inside P, height 0 there) it rises at
** most 1 / w_min per unit.  With each edge's own weight, t_v <=
** dist(v, e) / w(e), it is false for unequal weights: beyond the end of a
** heavy edge e at a reflex vertex, points are swept by the light edge f
** there, at dist / w(f) > dist / w(e).  (ii) Face completeness: (c), (e),
** (f).
**
** (b) uses a uniform grid over the polygon's edges (about two edges per
** cell).  Each cell gets a reference point that is not on the boundary and
** whose inside/outside status is propagated along its row from a point
** right of the polygon; a query counts the edges of its own cell that cross
** the segment from the cell's reference point to it.  Crossings are decided
** with wk_orient2d, vertices on the segment's line counting as right of it
** (a symbolic shift of the segment), so parities are exact.  Cost
** O(n + cells) to build, O(edges in the cell) per query.
**
** Faces with more than FACE_PAIRS_MAX sides use the same grid over their own
** sides to find candidate pairs; smaller ones test all pairs.
*/
#include "faces.h"
#include "validate_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* Up to this many sides a face tests all pairs of sides (at most 252
** non-adjacent ones), which is cheaper than building a grid. */
#define FACE_PAIRS_MAX 24
/* Reference point candidates per grid cell before giving up (each is
** rejected only if it lies exactly on an edge, which essentially never
** happens twice). */
#define REF_TRIES 32
/* The point-in-polygon grid: PIP_DENSITY cells per vertex, made finer (up
** to PIP_DENSITY_MAX) when the edges crowd into few cells, so that an
** occupied cell lists about PIP_EDGES_PER_CELL edges.  Not tolerances: cost
** trade-offs.  A fractal coastline's edges occupy about 1% of the cells of
** its box at n = 10^6, and each node's crossing count read all the edges
** of its cell (11% of a self-validating variant's run there, perf); its
** edges are short, each in about one cell. */
#define PIP_DENSITY 0.5
#define PIP_DENSITY_MAX 8.0
#define PIP_EDGES_PER_CELL 4.0
#define PIP_ITEMS_PER_EDGE 2.0

static uint32_t next_of(uint32_t i, uint32_t n) { return i + 1 == n ? 0 : i + 1; }

/* ------------------------------------------------------------------ grid */

/* A uniform grid over the sides of a closed polyline pts[0..k) (side i runs
** pts[i] -> pts[i+1 mod k]).  Cell (cx, cy) covers [x0 + cx s, x0 + (cx+1) s]
** x [y0 + cy s, ...]; a side is listed in every cell it passes through,
** widened by `margin` so that rounding never drops a cell it touches. */
typedef struct grid {
    double x0, y0, s, inv, margin;
    uint32_t nx, ny;
    size_t n_cells;
    uint32_t n_items;
    uint32_t *start; /* n_cells + 1 offsets into item */
    uint32_t *item;  /* side ids, cell by cell */
} grid;

static uint32_t grid_index(double v, uint32_t n) {
    if (!(v > 0)) return 0; /* also NaN */
    if (v >= (double)n) return n - 1;
    return (uint32_t)v;
}
static uint32_t grid_col(const grid *G, double x) { return grid_index((x - G->x0) * G->inv, G->nx); }
static uint32_t grid_row(const grid *G, double y) { return grid_index((y - G->y0) * G->inv, G->ny); }

/* Visit the cells of side p -> q: per column, the rows its y-range spans.
** Counting pass (fill false): start[c + 1]++; filling pass: item[start[c]++].
** Returns the number of cells visited. */
static size_t grid_side(grid *G, wk_point p, wk_point q, uint32_t id, bool fill) {
    double m = G->margin;
    double xlo = fmin(p.x, q.x), xhi = fmax(p.x, q.x);
    uint32_t c0 = grid_col(G, xlo - m), c1 = grid_col(G, xhi + m);
    double slope = p.x != q.x ? (q.y - p.y) / (q.x - p.x) : 0.0;
    size_t visited = 0;
    for (uint32_t c = c0; c <= c1; c++) {
        double ya, yb;
        if (p.x == q.x) {
            ya = p.y;
            yb = q.y;
        } else {
            double xa = fmax(xlo, G->x0 + c * G->s), xb = fmin(xhi, G->x0 + (c + 1) * G->s);
            if (xa > xb) xa = xb = c == c0 ? xlo : xhi; /* the margin reached this column */
            ya = p.y + (xa - p.x) * slope;
            yb = p.y + (xb - p.x) * slope;
        }
        uint32_t r0 = grid_row(G, fmin(ya, yb) - m), r1 = grid_row(G, fmax(ya, yb) + m);
        for (uint32_t r = r0; r <= r1; r++) {
            size_t cell = (size_t)r * G->nx + c;
            if (fill) G->item[G->start[cell]++] = id;
            else G->start[cell + 1]++;
            visited++;
        }
    }
    return visited;
}

static void grid_clear(wk_run *R, grid *G) {
    if (G->start) WK_FREE_ARRAY(R, G->start, G->n_cells + 1);
    if (G->item) WK_FREE_ARRAY(R, G->item, G->n_items);
}

/* About `density` cells per side, square cells.  s >= max(W, H) / m bounds
** each of nx, ny by m + 1 and s >= sqrt(W H / m) their product by about 3 m. */
/* Side i of the polyline: pts[i] -> pts[i+1 mod k], or, with rings (P not
** NULL, pts == P->p), to the next vertex of i's ring. */
static wk_point side_end(const wk_point *pts, uint32_t k, const wk_polygon *P, uint32_t i) {
    return P ? pts[wk_polygon_next(P, i)] : pts[next_of(i, k)];
}

static wk_status grid_build(wk_run *R, grid *G, const wk_point *pts, uint32_t k,
                            const wk_polygon *rings, double density, const char *name) {
    memset(G, 0, sizeof *G);
    double xmin = pts[0].x, xmax = xmin, ymin = pts[0].y, ymax = ymin;
    for (uint32_t i = 1; i < k; i++) {
        xmin = fmin(xmin, pts[i].x);
        xmax = fmax(xmax, pts[i].x);
        ymin = fmin(ymin, pts[i].y);
        ymax = fmax(ymax, pts[i].y);
    }
    double W = xmax - xmin, H = ymax - ymin, m = fmax(1.0, k * density);
    if (!isfinite(W) || !isfinite(H)) /* defensive: (b) and the polygon checks come first */
        return WK_FAIL(R, WK_EINVALID, name, 0, "validate: non-finite coordinates");
    double s = fmax(sqrt(W * H / m), fmax(W, H) / m);
    if (!(s > 0)) s = 1.0; /* all points equal */
    G->x0 = xmin;
    G->y0 = ymin;
    G->s = s;
    G->inv = 1.0 / s;
    G->nx = (uint32_t)(W / s) + 1;
    G->ny = (uint32_t)(H / s) + 1;
    G->n_cells = (size_t)G->nx * G->ny;
    /* Rounding in grid_side is relative to the coordinates' magnitude. */
    G->margin = WK_PIP_MARGIN_REL * s + 8 * DBL_EPSILON * (fabs(xmin) + fabs(ymin) + W + H);
    G->start = WK_NEW_ARRAY(R, uint32_t, G->n_cells + 1);
    if (!G->start) return R->err.code;
    size_t total = 0;
    for (uint32_t i = 0; i < k; i++)
        total += grid_side(G, pts[i], side_end(pts, k, rings, i), i, false);
    if (total > UINT32_MAX - 1) {
        grid_clear(R, G);
        return WK_FAIL(R, WK_ENOMEM, name, 0, "validator grid too large (%zu entries)", total);
    }
    G->n_items = (uint32_t)total;
    G->item = WK_NEW_ARRAY(R, uint32_t, G->n_items);
    if (!G->item) {
        grid_clear(R, G);
        return R->err.code;
    }
    for (size_t c = 0; c < G->n_cells; c++) G->start[c + 1] += G->start[c];
    for (uint32_t i = 0; i < k; i++) grid_side(G, pts[i], side_end(pts, k, rings, i), i, true);
    memmove(G->start + 1, G->start, G->n_cells * sizeof *G->start);
    G->start[0] = 0;
    return WK_OK;
}

/* --------------------------------------------------------- point in polygon */

typedef struct pip {
    wk_run *R; /* counts the exact stages of the crossing tests */
    grid G;
    const wk_polygon *P;
    uint8_t *cell;   /* per cell: bit 7 set if its reference point is inside P;
                        low bits: which candidate is the reference point */
    uint32_t *stamp; /* per edge: the scan that last counted it */
    uint32_t clock;
} pip;

static wk_point ref_candidate(const grid *G, size_t c, unsigned j) {
    double fx = 0.5, fy = 0.5;
    if (j) { /* additive recurrences: distinct, not collinear, inside the cell */
        fx = 0.05 + 0.9 * fmod(0.5 + j * 0.6180339887498949, 1.0);
        fy = 0.05 + 0.9 * fmod(0.5 + j * 0.4142135623730950, 1.0);
    }
    return (wk_point){G->x0 + ((double)(c % G->nx) + fx) * G->s,
                      G->y0 + ((double)(c / G->nx) + fy) * G->s};
}

static wk_point edge_p(const wk_polygon *P, uint32_t e) { return P->p[e]; }
static wk_point edge_q(const wk_polygon *P, uint32_t e) { return P->p[wk_polygon_next(P, e)]; }

/* Does edge p -> q cross segment c -> z?  c and z must not be on the
** boundary; a vertex on line cz counts as right of it (see the top). */
static bool edge_crosses(wk_run *R, wk_point p, wk_point q, wk_point c, wk_point z) {
    bool sp = wk_orient2d_counted(R, c, z, p) > 0, sq = wk_orient2d_counted(R, c, z, q) > 0;
    if (sp == sq) return false;
    return wk_orient2d_counted(R, p, q, c) * wk_orient2d_counted(R, p, q, z) < 0;
}

static void pip_tick(pip *Q) {
    if (++Q->clock == 0) { /* wrapped: forget every stamp */
        memset(Q->stamp, 0, (size_t)Q->P->n * sizeof *Q->stamp);
        Q->clock = 1;
    }
}

/* Parity of the edges in cells c0 and c1 (c1 may equal c0) crossing c -> z. */
static unsigned pip_crossings(pip *Q, size_t c0, size_t c1, wk_point c, wk_point z) {
    unsigned odd = 0;
    pip_tick(Q);
    for (int pass = 0; pass < (c1 != c0 ? 2 : 1); pass++) {
        size_t cell = pass ? c1 : c0;
        for (uint32_t k = Q->G.start[cell]; k < Q->G.start[cell + 1]; k++) {
            uint32_t e = Q->G.item[k];
            if (Q->stamp[e] == Q->clock) continue;
            Q->stamp[e] = Q->clock;
            odd ^= edge_crosses(Q->R, edge_p(Q->P, e), edge_q(Q->P, e), c, z);
        }
    }
    return odd;
}

/* z on the closed segment ab: what wk_segments_meet(a, b, z, z) !=
** WK_SEG_DISJOINT decides, with one orientation instead of four (the two
** of the degenerate segment zz are exactly 0, which the float filter can
** never certify, so each cost an exact stage: 7.8M of the 7.8M exact
** stages of a star of n = 10^5 solved and validated by a variant that checks
** its own output). */
static bool on_segment(wk_run *R, wk_point a, wk_point b, wk_point z) {
    if (wk_orient2d_counted(R, a, b, z) != 0) return false;
    if (wk_point_lex_cmp(a, b) > 0) {
        wk_point t = a;
        a = b;
        b = t;
    }
    return wk_point_lex_cmp(z, a) >= 0 && wk_point_lex_cmp(z, b) <= 0;
}

static bool on_cell_edge(const pip *Q, size_t cell, wk_point z) {
    for (uint32_t k = Q->G.start[cell]; k < Q->G.start[cell + 1]; k++) {
        uint32_t e = Q->G.item[k];
        if (on_segment(Q->R, edge_p(Q->P, e), edge_q(Q->P, e), z)) return true;
    }
    return false;
}

static wk_point pip_ref(const pip *Q, size_t cell) {
    return ref_candidate(&Q->G, cell, Q->cell[cell] & 0x7f);
}

static void pip_clear(wk_run *R, pip *Q) {
    grid_clear(R, &Q->G);
    if (Q->cell) WK_FREE_ARRAY(R, Q->cell, Q->G.n_cells);
    if (Q->stamp) WK_FREE_ARRAY(R, Q->stamp, Q->P->n);
}

/* The density for the point-in-polygon grid given its first build G (at
** PIP_DENSITY) of k edges: short edges along a curve (about one cell each:
** at most PIP_ITEMS_PER_EDGE entries per edge) fall by the factor f per
** occupied cell when the cell side does, at f^2 the cells.  Long edges (a
** star's spikes: 39 entries per edge at n = 10^5, 75% of the cells
** occupied) would only be listed in more cells. */
static double pip_density(const grid *G, uint32_t k) {
    if ((double)G->n_items > PIP_ITEMS_PER_EDGE * k) return PIP_DENSITY;
    size_t occupied = 0;
    for (size_t c = 0; c < G->n_cells; c++) occupied += G->start[c + 1] > G->start[c];
    if (occupied == 0) return PIP_DENSITY;
    double f = (double)G->n_items / (double)occupied / PIP_EDGES_PER_CELL;
    if (!(f > 1.0)) return PIP_DENSITY;
    return fmin(PIP_DENSITY * f * f, PIP_DENSITY_MAX);
}

static wk_status pip_build(wk_run *R, pip *Q, const wk_polygon *P) {
    memset(Q, 0, sizeof *Q);
    Q->R = R;
    Q->P = P;
    if (grid_build(R, &Q->G, P->p, P->n, P, PIP_DENSITY, P->name) != WK_OK) return R->err.code;
    double density = pip_density(&Q->G, P->n);
    if (density > PIP_DENSITY) {
        grid_clear(R, &Q->G);
        if (grid_build(R, &Q->G, P->p, P->n, P, density, P->name) != WK_OK) return R->err.code;
    }
    const grid *G = &Q->G;
    Q->cell = WK_NEW_ARRAY(R, uint8_t, G->n_cells);
    Q->stamp = Q->cell ? WK_NEW_ARRAY(R, uint32_t, P->n) : NULL;
    if (!Q->stamp) {
        pip_clear(R, Q);
        return R->err.code;
    }
    for (uint32_t r = 0; r < G->ny; r++) {
        for (uint32_t cx = G->nx; cx-- > 0;) {
            size_t cell = (size_t)r * G->nx + cx;
            unsigned j = 0;
            while (j < REF_TRIES && on_cell_edge(Q, cell, ref_candidate(G, cell, j))) j++;
            if (j == REF_TRIES) {
                pip_clear(R, Q);
                return WK_FAIL(R, WK_EALGO, P->name, 0,
                               "validate (b): no reference point off the boundary in grid "
                               "cell %zu",
                               cell);
            }
            Q->cell[cell] = (uint8_t)j;
            wk_point c = ref_candidate(G, cell, j);
            unsigned in;
            if (cx + 1 == G->nx) { /* ray to a point right of the polygon */
                wk_point far = {G->x0 + (G->nx + 1.0) * G->s, c.y};
                in = pip_crossings(Q, cell, cell, c, far);
            } else {
                in = (Q->cell[cell + 1] >> 7) ^
                     pip_crossings(Q, cell, cell + 1, c, pip_ref(Q, cell + 1));
            }
            Q->cell[cell] |= (uint8_t)(in << 7);
        }
    }
    return WK_OK;
}

/* Exact for points off the boundary; a point on it may go either way. */
static bool pip_inside(pip *Q, wk_point z) {
    const grid *G = &Q->G;
    if (!(z.x >= G->x0 && z.x <= G->x0 + G->nx * G->s && z.y >= G->y0 &&
          z.y <= G->y0 + G->ny * G->s))
        return false;
    size_t cell = (size_t)grid_row(G, z.y) * G->nx + grid_col(G, z.x);
    return ((Q->cell[cell] >> 7) ^ pip_crossings(Q, cell, cell, pip_ref(Q, cell), z)) != 0;
}

static bool pip_near(const pip *Q, wk_point z, double tol) {
    const grid *G = &Q->G;
    uint32_t c0 = grid_col(G, z.x - tol), c1 = grid_col(G, z.x + tol);
    uint32_t r0 = grid_row(G, z.y - tol), r1 = grid_row(G, z.y + tol);
    for (uint32_t r = r0; r <= r1; r++)
        for (uint32_t c = c0; c <= c1; c++) {
            size_t cell = (size_t)r * G->nx + c;
            for (uint32_t k = G->start[cell]; k < G->start[cell + 1]; k++) {
                uint32_t e = G->item[k];
                if (wk_segment_point_distance(edge_p(Q->P, e), edge_q(Q->P, e), z) <= tol) return true;
            }
        }
    return false;
}

/* ------------------------------------------------------------ properties */

static wk_status check_input_nodes(wk_run *R, const wk_polygon *P, const wk_skeleton *S) {
    if (S->n_input != P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "validate (a): the skeleton has %u input nodes, the polygon %u vertices",
                       S->n_input, P->n);
    if (S->n_nodes < P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "validate (a): the skeleton has %u nodes, fewer than the %u input "
                       "vertices",
                       S->n_nodes, P->n);
    for (uint32_t i = 0; i < P->n; i++) {
        const wk_node *v = &S->nodes[i];
        if (v->x != P->p[i].x || v->y != P->p[i].y || v->t != 0)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (a): node %u is (%.17g, %.17g) at t = %.17g, not input "
                           "vertex %u (%.17g, %.17g) at t = 0",
                           i, v->x, v->y, v->t, i, P->p[i].x, P->p[i].y);
    }
    return WK_OK;
}

/* The validator's time tolerance: tol / wmax. */
static double time_tol(const wk_polygon *P, double tol) {
    double wmax = 0;
    for (uint32_t i = 0; i < P->n; i++) wmax = fmax(wmax, P->w[i]);
    return wmax > 0 ? tol / wmax : tol;
}

static wk_status check_nodes(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol) {
    double tol_t = time_tol(P, tol);
    for (uint32_t j = P->n; j < S->n_nodes; j++) {
        const wk_node *v = &S->nodes[j];
        if (!isfinite(v->x) || !isfinite(v->y) || !isfinite(v->t))
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (b): node %u is (%g, %g) at t = %g: not finite", j, v->x,
                           v->y, v->t);
        if (!(v->t > 0) && !(fabs(v->t) <= tol_t))
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (b): node %u at (%.17g, %.17g) has t = %.17g; only input "
                           "vertices may have t <= 0 (or traces of sub-tolerance features, "
                           "|t| <= %.3g)",
                           j, v->x, v->y, v->t, tol_t);
    }
    if (S->n_nodes == P->n) return WK_OK;
    pip Q;
    if (pip_build(R, &Q, P) != WK_OK) return R->err.code;
    wk_status st = WK_OK;
    for (uint32_t j = P->n; j < S->n_nodes && st == WK_OK; j++) {
        wk_point z = {S->nodes[j].x, S->nodes[j].y};
        /* the distance to the boundary only matters for a node outside or
        ** at t <= 0: most nodes are neither, and pip_near cost twice what
        ** pip_inside did (coastline 10^6: 13% of a self-validating
        ** variant's run) */
        bool inside = pip_inside(&Q, z), after_start = S->nodes[j].t > 0;
        bool near = (!inside || !after_start) && pip_near(&Q, z, tol);
        if (!inside && !near)
            st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                         "validate (b): node %u at (%.17g, %.17g), t = %.17g, lies outside the "
                         "polygon (farther than tol = %.3g from its boundary)",
                         j, z.x, z.y, S->nodes[j].t, tol);
        else if (!after_start && !near)
            st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                         "validate (b): node %u at (%.17g, %.17g) has t = %.17g but lies farther "
                         "than tol = %.3g from the boundary",
                         j, z.x, z.y, S->nodes[j].t, tol);
    }
    pip_clear(R, &Q);
    return st;
}

/* Signed distance of (x, y) from the supporting line of edge e, positive on
** the inner (left) side. */
static double line_dist(const wk_polygon *P, uint32_t e, double x, double y) {
    wk_point p = edge_p(P, e), q = edge_q(P, e);
    double dx = q.x - p.x, dy = q.y - p.y;
    return (dx * (y - p.y) - dy * (x - p.x)) / hypot(dx, dy);
}

static wk_status check_arcs(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                            double *max_err) {
    if (wk_faces_check_ids(R, P, S, "validate (c): ") != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        uint32_t ends[2] = {c->a, c->b}, faces[2] = {c->left, c->right};
        for (int k = 0; k < 4; k++) {
            uint32_t v = ends[k >> 1], e = faces[k & 1];
            const wk_node *nd = &S->nodes[v];
            double d = line_dist(P, e, nd->x, nd->y), want = P->w[e] * nd->t;
            double err = fabs(d - want);
            if (!(err <= tol))
                return WK_FAIL(R, WK_EINVALID, P->name, 0,
                               "validate (c): arc %u [%u, %u, %u, %u]: node %u (t = %.17g) is at "
                               "distance %.17g from the line of edge %u, expected w t = %.17g "
                               "(error %.3g > tol %.3g)",
                               i, c->a, c->b, c->left, c->right, v, nd->t, d, e, want, err, tol);
            if (err > *max_err) *max_err = err;
        }
        if (wk_validate_arc_bisector(R, P, S, i, tol, P->name, "c") != WK_OK) return R->err.code;
        /* An arc between two input vertices traces an edge swept at t = 0:
        ** the vertices are adjacent and the edge between them is one of its
        ** faces.  Without this an arc spanning two swept edges of a
        ** collinear run (overlapping the arc along the second) would pass:
        ** (f) does not look at sides that lie on their face's own edge. */
        uint32_t n = P->n;
        if (c->a < n && c->b < n) {
            uint32_t e = wk_polygon_next(P, c->a) == c->b   ? c->a
                         : wk_polygon_next(P, c->b) == c->a ? c->b
                                                            : WK_NONE;
            if (e == WK_NONE || (c->left != e && c->right != e))
                return WK_FAIL(R, WK_EINVALID, P->name, 0,
                               "validate (c): arc %u [%u, %u, %u, %u] joins two input vertices but "
                               "does not trace the edge between them (one swept edge per arc)",
                               i, c->a, c->b, c->left, c->right);
        }
    }
    return WK_OK;
}

static uint32_t uf_find(uint32_t *parent, uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]]; /* path halving */
        v = parent[v];
    }
    return v;
}

static wk_status check_tree(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol) {
    uint32_t N = S->n_nodes, n = P->n;
    double tol_t = time_tol(P, tol);
    uint32_t *deg = WK_NEW_ARRAY(R, uint32_t, N);
    uint32_t *leaving = deg ? WK_NEW_ARRAY(R, uint32_t, n) : NULL; /* arcs leaving the boundary */
    uint32_t *parent = leaving ? WK_NEW_ARRAY(R, uint32_t, N) : NULL;
    uint32_t *size = parent ? WK_NEW_ARRAY(R, uint32_t, N) : NULL;
    wk_status st = size ? WK_OK : R->err.code;
    if (st != WK_OK) goto done;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        deg[c->a]++;
        deg[c->b]++;
        /* an arc at input vertex a whose other end b is later than t ~ 0 */
        if (c->a < n && !(fabs(S->nodes[c->b].t) <= tol_t)) leaving[c->a]++;
        if (c->b < n && !(fabs(S->nodes[c->a].t) <= tol_t)) leaving[c->b]++;
    }
    for (uint32_t v = 0; v < N && st == WK_OK; v++) {
        if (deg[v] == 0)
            st = WK_FAIL(R, WK_EINVALID, P->name, 0, "validate (d): node %u is on no arc", v);
        else if (v < n && leaving[v] > 1)
            st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                         "validate (d): input vertex %u has %u arcs that leave the boundary (to "
                         "nodes later than t = %.3g); one wavefront vertex starts there",
                         v, leaving[v], tol_t);
    }
    if (st != WK_OK) goto done;
    for (uint32_t v = 0; v < N; v++) {
        parent[v] = v;
        size[v] = 1;
    }
    /* With h holes the skeleton has exactly h independent cycles (one
    ** around each hole): h arcs may close a cycle, the (h+1)-th may not. */
    uint32_t holes = P->n_rings - 1, closing = 0;
    for (uint32_t i = 0; i < S->n_arcs && st == WK_OK; i++) {
        const wk_arc *c = &S->arcs[i];
        uint32_t ra = uf_find(parent, c->a), rb = uf_find(parent, c->b);
        if (ra == rb) {
            if (++closing <= holes) continue;
            st = holes == 0 ? WK_FAIL(R, WK_EINVALID, P->name, 0,
                                      "validate (d): arc %u [%u, %u, %u, %u] closes a cycle (its "
                                      "nodes are already connected)",
                                      i, c->a, c->b, c->left, c->right)
                            : WK_FAIL(R, WK_EINVALID, P->name, 0,
                                      "validate (d): arc %u [%u, %u, %u, %u] closes cycle %u; "
                                      "with %u holes the skeleton has exactly %u",
                                      i, c->a, c->b, c->left, c->right, closing, holes, holes);
            break;
        }
        if (size[ra] < size[rb]) {
            uint32_t t = ra;
            ra = rb;
            rb = t;
        }
        parent[rb] = ra;
        size[ra] += size[rb];
    }
    /* Connected, except that a weighted skeleton of a polygon with holes
    ** may have islands (faces.h): then each further component closes as many
    ** cycles as it holds holes and the count above still holds per
    ** component, but (e) must find each island as a loop inside one face.
    ** With equal weights no wavefront overtakes a hole's, so no islands. */
    bool equal_weights = true;
    for (uint32_t i = 1; i < n && equal_weights; i++) equal_weights = P->w[i] == P->w[0];
    if (st == WK_OK && (holes == 0 || equal_weights)) {
        uint32_t r0 = uf_find(parent, 0);
        for (uint32_t v = 1; v < N; v++)
            if (uf_find(parent, v) != r0) {
                st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                             "validate (d): the arcs do not connect node %u to node 0 (%u arcs "
                             "for %u nodes; a connected skeleton with %u holes has %u)",
                             v, S->n_arcs, N, holes, N - 1 + holes);
                break;
            }
    }
    /* the arcs that closed a cycle are the independent cycles (arcs - nodes
    ** + components): with islands there must be h of them as well */
    if (st == WK_OK && holes > 0 && !equal_weights && closing != holes)
        st = WK_FAIL(R, WK_EINVALID, P->name, 0,
                     "validate (d): %u arcs, %u nodes, %u components: %u independent cycles, "
                     "the polygon has %u holes",
                     S->n_arcs, N, N - (S->n_arcs - closing), closing, holes);
done:
    if (size) WK_FREE_ARRAY(R, size, N);
    if (parent) WK_FREE_ARRAY(R, parent, N);
    if (leaving) WK_FREE_ARRAY(R, leaving, n);
    if (deg) WK_FREE_ARRAY(R, deg, N);
    return st;
}

static double cycle_perimeter(const wk_skeleton *S, const uint32_t *cycle, uint32_t len) {
    double l = 0.0;
    for (uint32_t i = 0; i < len; i++) {
        const wk_node *a = &S->nodes[cycle[i]], *b = &S->nodes[cycle[next_of(i, len)]];
        l += hypot(b->x - a->x, b->y - a->y);
    }
    return l;
}

/* The areas' sum is compared with the polygon's within
** WK_VALIDATE_AREA_REL of the area plus the area that nodes misplaced by
** the simulation's eps_d can account for: moving a face's nodes by d
** changes its area by at most d times its perimeter.  The second term
** matters only for thin polygons whose area is small against perimeter
** times scale (a regular polygon with one vertex pulled 4e9 away: the
** relative error of its face areas' sum reached 1.8e-6 from rounding alone;
** tests/data/degenerate). */
static wk_status check_face_areas(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                  const wk_faces *F, double tol, double *area_err) {
    double scale = wk_polygon_scale(P), sum = 0.0, total = wk_polygon_area(P), perimeter = 0.0;
    for (uint32_t e = 0; e < F->n; e++) {
        const uint32_t *cyc = F->node + F->start[e];
        uint32_t len = F->start[e + 1] - F->start[e];
        double a = wk_cycle_area(S, cyc, len);
        if (!(a >= -tol * scale))
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "validate (e): the face of edge %u has signed area %.17g < 0 (its "
                           "cycle of %u nodes runs clockwise)",
                           e, a, len);
        sum += a;
        perimeter += cycle_perimeter(S, cyc, len);
    }
    *area_err = fabs(sum - total);
    double allowed = WK_VALIDATE_AREA_REL * fabs(total) + WK_TOL_REL * scale * perimeter;
    if (!(*area_err <= allowed))
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "validate (e): the face areas sum to %.17g, the polygon's area is %.17g "
                       "(error %.3g > %.3g: %g of the area plus eps_d times the faces' "
                       "perimeters)",
                       sum, total, *area_err, allowed, WK_VALIDATE_AREA_REL);
    return WK_OK;
}

/* ------------------------------------------------------------- planarity */

typedef struct face_ctx {
    const wk_polygon *P;
    uint32_t e;           /* the face */
    const uint32_t *cyc;  /* its node cycle */
    uint32_t L;           /* sides = nodes */
    const wk_point *pts;  /* the cycle's nodes in the xy plane */
    double tol;
    const wk_skeleton *S; /* for the nodes' times */
    const uint8_t *bridge; /* bridge[i]: side i joins an island (faces.h); NULL: none */
} face_ctx;

/* "edge 3" for side 0 (the input edge), "arc 7 -> 9" for the others. */
static const char *side_name(const face_ctx *F, uint32_t s, char *buf, size_t size) {
    if (s == 0) snprintf(buf, size, "edge %u", F->e);
    else snprintf(buf, size, "arc %u -> %u", F->cyc[s], F->cyc[next_of(s, F->L)]);
    return buf;
}

/* Test sides i and j of the face; adjacent sides may only share their node. */
static wk_status test_sides(wk_run *R, const face_ctx *F, uint32_t i, uint32_t j) {
    /* a bridge is no part of the skeleton: the two sides of one overlap by
    ** construction, and the real sides are all tested among themselves */
    if (F->bridge && (F->bridge[i] || F->bridge[j])) return WK_OK;
    wk_point a = F->pts[i], b = F->pts[next_of(i, F->L)];
    wk_point c = F->pts[j], d = F->pts[next_of(j, F->L)];
    if (fmax(a.x, b.x) < fmin(c.x, d.x) || fmax(c.x, d.x) < fmin(a.x, b.x) ||
        fmax(a.y, b.y) < fmin(c.y, d.y) || fmax(c.y, d.y) < fmin(a.y, b.y))
        return WK_OK;
    char s1[64], s2[64];
    /* Sides on one line up to rounding overlap although the exact tests see
    ** them touch or miss (tests/data/degenerate/flat_triple_weighted.wpoly:
    ** an arc folding back along the next one at a node, off by 1e-16).  The
    ** bar is rounding (64 ulp of the coordinates, and at most 1e-3 tol), not
    ** tol: legitimate faces can be far thinner than tol (a triangle with
    ** weights 1, 1000, 0.001: 1e-6 wide at 1000; n = 10^6 polygons of the x-sweep family:
    ** long faces 1e-3 wide; a 2e-3 polygon at 1e6 from the origin: faces
    ** 1e-8 wide, where 64 ulp is 1.4e-8). */
    double lab = hypot(b.x - a.x, b.y - a.y), lcd = hypot(d.x - c.x, d.y - c.y);
    /* Overlaps are allowed where the sides stay within tol of the face's
    ** input edge (its wavefront has moved at most tol at their nodes, side 0
    ** included): that is how an edge swept away at once is traced, by the
    ** collinear rule or, for nearly collinear input edges of different
    ** weight, by an edge event at t = 1e-12 (the vertex between them is
    ** 10^11 times faster than the edges; rotated grids), with arcs back and
    ** forth along the edge. */
    double tmax = 0;
    uint32_t ends[4] = {F->cyc[i], F->cyc[next_of(i, F->L)], F->cyc[j], F->cyc[next_of(j, F->L)]};
    for (int k = 0; k < 4; k++) tmax = fmax(tmax, F->S->nodes[ends[k]].t);
    bool at_boundary = tmax * F->P->w[F->e] <= F->tol;
    /* Adjacent sides whose far ends lie within tol of each other bound a
    ** sliver on a base below tol, not a fold: the face of an input edge
    ** far shorter than tol is a triangle whose apex angle can be below
    ** rounding (tests/data/fuzz/invalid_every_variant_unit_edge_far_2e16.wpoly:
    ** edge 1 is 1 long, its face's apex 7.85e14 away, eps_d 2.5e7; the two
    ** legs are collinear to 64 ulp and "overlapped" along 7.85e14). */
    bool sliver = false;
    if (next_of(i, F->L) == j) sliver = hypot(d.x - a.x, d.y - a.y) <= F->tol;
    else if (next_of(j, F->L) == i) sliver = hypot(b.x - c.x, b.y - c.y) <= F->tol;
    if (!at_boundary && lab > F->tol && lcd > F->tol) {
        double mag = fmax(fmax(fmax(fabs(a.x), fabs(a.y)), fmax(fabs(b.x), fabs(b.y))),
                          fmax(fmax(fabs(c.x), fabs(c.y)), fmax(fabs(d.x), fabs(d.y))));
        double ftol = fmin(WK_FOLD_ULPS * DBL_EPSILON * mag, WK_FOLD_TOL_CAP * F->tol);
        bool ab_long = lab >= lcd;
        wk_point p = ab_long ? a : c, q = ab_long ? b : d;
        wk_point u = ab_long ? c : a, v = ab_long ? d : b;
        double len = ab_long ? lab : lcd;
        double du = fabs((q.x - p.x) * (u.y - p.y) - (q.y - p.y) * (u.x - p.x)) / len;
        double dv = fabs((q.x - p.x) * (v.y - p.y) - (q.y - p.y) * (v.x - p.x)) / len;
        if (du <= ftol && dv <= ftol && !sliver) {
            double ov = wk_collinear_overlap(a, b, c, d);
            if (ov > F->tol)
                return WK_FAIL(R, WK_EINVALID, F->P->name, 0,
                               "validate (f): the face of edge %u is not simple: %s and %s "
                               "overlap along a length of %.3g",
                               F->e, side_name(F, i, s1, sizeof s1),
                               side_name(F, j, s2, sizeof s2), ov);
        }
    }
    wk_seg_meet m = wk_segments_meet_counted(R, a, b, c, d);
    if (m == WK_SEG_CROSS) {
        double near = fmin(fmin(wk_segment_point_distance(c, d, a), wk_segment_point_distance(c, d, b)),
                           fmin(wk_segment_point_distance(a, b, c), wk_segment_point_distance(a, b, d)));
        if (near <= F->tol) return WK_OK;
        double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
        double u = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x)) / den;
        return WK_FAIL(R, WK_EINVALID, F->P->name, 0,
                       "validate (f): the face of edge %u is not simple: %s and %s cross at "
                       "(%.17g, %.17g)",
                       F->e, side_name(F, i, s1, sizeof s1), side_name(F, j, s2, sizeof s2),
                       a.x + u * (b.x - a.x), a.y + u * (b.y - a.y));
    }
    if (m == WK_SEG_OVERLAP) {
        double len = wk_collinear_overlap(a, b, c, d);
        if (len <= F->tol || at_boundary || sliver) return WK_OK;
        return WK_FAIL(R, WK_EINVALID, F->P->name, 0,
                       "validate (f): the face of edge %u is not simple: %s and %s overlap "
                       "along a length of %.3g",
                       F->e, side_name(F, i, s1, sizeof s1), side_name(F, j, s2, sizeof s2),
                       len);
    }
    return WK_OK;
}

static bool adjacent_sides(uint32_t i, uint32_t j, uint32_t L) {
    return next_of(i, L) == j || next_of(j, L) == i;
}

static wk_status check_face_simple(wk_run *R, const face_ctx *F) {
    uint32_t L = F->L;
    if (L < 3) return WK_OK; /* the 2-cycle of an edge removed at t = 0 */
    /* Adjacent sides: only a fold-back (overlap) is wrong. */
    for (uint32_t i = 0; i < L; i++)
        if (test_sides(R, F, i, next_of(i, L)) != WK_OK) return R->err.code;
    if (L <= 3) return WK_OK;
    if (L <= FACE_PAIRS_MAX) {
        for (uint32_t i = 0; i < L; i++)
            for (uint32_t j = i + 2; j < L; j++)
                if (!adjacent_sides(i, j, L) && test_sides(R, F, i, j) != WK_OK)
                    return R->err.code;
        return WK_OK;
    }
    grid G;
    if (grid_build(R, &G, F->pts, L, NULL, 1.0, F->P->name) != WK_OK) return R->err.code;
    wk_status st = WK_OK;
    for (size_t c = 0; c < G.n_cells && st == WK_OK; c++)
        for (uint32_t x = G.start[c]; x < G.start[c + 1] && st == WK_OK; x++)
            for (uint32_t y = x + 1; y < G.start[c + 1] && st == WK_OK; y++) {
                uint32_t i = G.item[x], j = G.item[y];
                if (!adjacent_sides(i, j, L)) st = test_sides(R, F, i, j);
            }
    grid_clear(R, &G);
    return st;
}

static wk_status check_planar(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                              const wk_faces *F, double tol) {
    uint32_t maxL = 0;
    for (uint32_t e = 0; e < F->n; e++)
        if (F->start[e + 1] - F->start[e] > maxL) maxL = F->start[e + 1] - F->start[e];
    wk_point *pts = WK_NEW_ARRAY(R, wk_point, maxL);
    if (!pts) return R->err.code;
    wk_status st = WK_OK;
    for (uint32_t e = 0; e < F->n && st == WK_OK; e++) {
        face_ctx fc = {P, e, F->node + F->start[e], F->start[e + 1] - F->start[e], pts, tol, S,
                       F->bridge ? F->bridge + F->start[e] : NULL};
        for (uint32_t i = 0; i < fc.L; i++)
            pts[i] = (wk_point){S->nodes[fc.cyc[i]].x, S->nodes[fc.cyc[i]].y};
        st = check_face_simple(R, &fc);
    }
    WK_FREE_ARRAY(R, pts, maxL);
    return st;
}

/* ------------------------------------------------------------------ entry */

wk_status wk_validate(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                      wk_validate_report *rep) {
    /* A separate path for weights <= 0 or a cut at a height: the properties
    ** below (a tree inside P, face areas, planarity) need positive weights
    ** and a vanished wavefront (validate_general.c). */
    if (P->pslg) return wk_validate_pslg(R, P, S, tol, rep);
    bool general = R->opt.height > 0;
    for (uint32_t e = 0; e < P->n && !general; e++) general = !(P->w[e] > 0);
    if (general) return wk_validate_general(R, P, S, tol, rep);
    wk_validate_report local;
    if (!rep) rep = &local;
    memset(rep, 0, sizeof *rep);
    rep->nodes = S->n_nodes;
    rep->arcs = S->n_arcs;
    if (!(tol > 0)) tol = WK_VALIDATE_TOL_REL * wk_polygon_scale(P);

    if (check_input_nodes(R, P, S) != WK_OK || check_nodes(R, P, S, tol) != WK_OK ||
        check_arcs(R, P, S, tol, &rep->max_distance_error) != WK_OK ||
        check_tree(R, P, S, tol) != WK_OK)
        return R->err.code;
    wk_faces F;
    if (wk_faces_build(R, P, S, &F, "validate (e): ") != WK_OK) return R->err.code;
    rep->faces = F.n;
    wk_status st = check_face_areas(R, P, S, &F, tol, &rep->area_error);
    if (st == WK_OK) st = check_planar(R, P, S, &F, tol);
    wk_faces_clear(R, &F);
    return st;
}
