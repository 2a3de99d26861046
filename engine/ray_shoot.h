/*
** ray_shoot.h: a uniform bucket grid over segments and ray shooting against
** a polygon's boundary: geometric search structures for any variant whose
** rays end where they first meet the boundary (000's A(P) segments; 002's
** traces crash into walls the same way).
**
** Design note
** -----------
** 1. A ray (e.g. 000 A(P): for every reflex vertex v of P, the
**    segment from v along its velocity (wk_vertex_velocity of its two
**    edges' offset lines, so weighted when P is) to the first point where the
**    ray meets the boundary of P: a vertex, or an edge other than v's two.
**    Shots use a uniform bucket grid over P's edges (about n cells; a cell
**    lists every edge that comes within `delta` of it) walked along the ray
**    cell by cell (Amanatides-Woo DDA), stopping at the first cell whose exit
**    distance is at least the best hit so far.  Expected O(1 + cells
**    crossed) per shot instead of O(n).  Shots are independent: one OpenMP
**    loop (R->opt.threads) in which each shot writes only its own slot, the
**    output is allocated before the loop, the grid is read-only and R is
**    only read; failures are collected per slot and reported after the loop
**    in vertex order, so the result is bit-identical for any thread count.
**
** Tolerances (the policy of wskel.h, WK_TOL_REL):
**   - ray shooting: tol = WK_TOL_REL * wk_polygon_scale(P).  A vertex whose
**     distance from the ray's line is at most tol, ahead of the origin, is a
**     hit on that vertex (so a ray through a vertex, exactly or up to
**     rounding, hits the vertex, never one of its edges); an edge is hit in
**     its interior only when its endpoints lie more than tol on opposite
**     sides of the line.  Hits are ordered by distance, then vertex before
**     edge, then id: the grid and the brute-force twin agree bit for bit.
**     Grid buckets are inflated by delta = 2 tol, which covers the tol band
**     and the rounding of the cell boundaries.
**   - coordinates: the rounding arguments above need a coordinate's rounding
**     (2^-53 |x|) far below WK_TOL_REL times the diagonal, i.e. coordinates
**     within ~10^6 diagonals of the origin; beyond that the grid may miss
**     what the brute force finds.  Translate to wk_polygon_centre first.
*/
#ifndef WK_RAY_SHOOT_H
#define WK_RAY_SHOOT_H
#include "kinetics.h"

#include <math.h>
#include "wskel.h"

/* ============================================================ bucket grid */

/* A uniform grid over a box whose cells list the segments that come within
** delta of them (conservatively: rounding in the cell arithmetic is far
** below delta).  Membership is defined by one function,
** wk_seg_grid_row_span, used both to fill the cells and to test a cell
** afterwards, so "segment i is listed in cell c" can be re-decided exactly.
** Layout: CSR, items[start[c] .. start[c+1]) are the ids listed in cell
** c = row * nx + col, increasing.  Read-only after build (shared by
** threads). */
typedef struct wk_seg_grid {
    double x0, y0;    /* lower-left corner of cell (0, 0) */
    double cw, ch;    /* cell width and height (> 0, distance units) */
    uint32_t nx, ny;  /* columns and rows, >= 1 */
    double delta;     /* inflation distance (> 0) */
    uint32_t n_cells; /* nx * ny */
    uint32_t n_items; /* total cell entries */
    uint32_t *start;  /* n_cells + 1 offsets */
    uint32_t *items;  /* n_items segment ids */
    /* Optional span table (build with keep_spans): membership by lookup.
    ** Segment i spans rows row0[i] .. row0[i] + soff[i+1] - soff[i] - 1;
    ** its columns in the k-th of them are span[2 (soff[i] + k)] ..
    ** span[2 (soff[i] + k) + 1] (empty when the first exceeds the second). */
    uint32_t nseg;   /* segments (valid with or without spans) */
    uint32_t n_rows; /* total rows over all segments; 0 without spans */
    uint32_t *row0;  /* nseg, or NULL */
    uint32_t *soff;  /* nseg + 1, or NULL */
    uint32_t *span;  /* 2 n_rows, or NULL */
} wk_seg_grid;

/* Endpoints of segment i of some collection. */
typedef void (*wk_seg_get_fn)(const void *ud, uint32_t i, wk_point *a, wk_point *b);

/* Empty, closable grid (no allocation). */
void wk_seg_grid_init(wk_seg_grid *G);
/* Build a grid of about target_cells cells over the box [lo, hi] (which
** must contain every segment) for segments 0..nseg-1 given by get(ud, i).
** delta > 0.  keep_spans: also keep the span table (8 bytes per row a
** segment spans) for wk_seg_grid_touches_id.  On failure (WK_ENOMEM, also
** when the entries would exceed 2^32 - 1) G is left empty.  G must be
** empty (fresh or cleared). */
wk_status wk_seg_grid_build(wk_run *R, wk_seg_grid *G, uint32_t nseg, wk_seg_get_fn get,
                            const void *ud, wk_point lo, wk_point hi, uint32_t target_cells,
                            double delta, bool keep_spans);
void wk_seg_grid_clear(wk_run *R, wk_seg_grid *G);
/* Column / row of a coordinate, clamped to the grid (NaN gives 0).  For
** v >= 0 the conversion truncates, which is floor (and much cheaper than
** floor() without SSE4.1). */
static inline uint32_t wk_seg_grid_index_(double v, uint32_t n) {
    if (!(v >= 0.0)) return 0;
    if (v >= (double)n) return n - 1;
    return (uint32_t)v;
}
static inline uint32_t wk_seg_grid_col(const wk_seg_grid *G, double x) {
    return wk_seg_grid_index_((x - G->x0) / G->cw, G->nx);
}
static inline uint32_t wk_seg_grid_row(const wk_seg_grid *G, double y) {
    return wk_seg_grid_index_((y - G->y0) / G->ch, G->ny);
}
/* Rows [*r0, *r1] segment ab may be listed in. */
void wk_seg_grid_rows(const wk_seg_grid *G, wk_point a, wk_point b, uint32_t *r0, uint32_t *r1);
/* Columns [*c0, *c1] of row `row` in which segment ab is listed; false if
** none.  The definition of membership. */
bool wk_seg_grid_row_span(const wk_seg_grid *G, wk_point a, wk_point b, uint32_t row, uint32_t *c0,
                          uint32_t *c1);
/* True if segment ab is listed in cell (col, row). */
bool wk_seg_grid_touches(const wk_seg_grid *G, wk_point a, wk_point b, uint32_t col, uint32_t row);
/* The same for segment i by table lookup (grid built with keep_spans): the
** stored result of wk_seg_grid_row_span, so the same answer. */
static inline bool wk_seg_grid_touches_id(const wk_seg_grid *G, uint32_t i, uint32_t col,
                                          uint32_t row) {
    uint32_t r0 = G->row0[i];
    if (row < r0 || row - r0 >= G->soff[i + 1] - G->soff[i]) return false;
    const uint32_t *sp = G->span + 2 * ((size_t)G->soff[i] + (row - r0));
    return col >= sp[0] && col <= sp[1];
}

/* ============================================================ ray shooting */

/* Where a ray first meets the boundary of P. */
typedef struct wk_ray_hit {
    double t;        /* distance from the origin along the unit direction;
                        for a vertex hit, the vertex's projection on the ray */
    wk_point p;      /* the hit point (exactly the vertex for a vertex hit) */
    uint32_t edge;   /* edge hit in its interior, or WK_NONE */
    uint32_t vertex; /* vertex hit, or WK_NONE */
} wk_ray_hit;

/* Ray shooting against the edges of one polygon: the edge grid plus the
** tolerance.  P must outlive it; read-only after init (thread-safe). */
typedef struct wk_ray_shooter {
    const wk_polygon *P;
    double tol;    /* vertex snapping distance, WK_TOL_REL * scale */
    wk_seg_grid G; /* over P's edges, about n cells, delta = 2 tol */
} wk_ray_shooter;

/* Build the edge grid.  On failure S is left empty, and
** wk_ray_shooter_clear is safe on it either way. */
wk_status wk_ray_shooter_init(wk_run *R, wk_ray_shooter *S, const wk_polygon *P);
void wk_ray_shooter_clear(wk_run *R, wk_ray_shooter *S);
/* First boundary point of P on the ray o + t u, t > 0 (u a unit vector).
** from_vertex: a vertex of P the ray starts at (its two edges and itself are
** ignored), or WK_NONE.  o may be anywhere; outside P's bounding box the
** answer comes from the brute force.  Returns false if the ray meets
** nothing (possible only for an origin outside P); *hit is then untouched.
** Pure: safe from any number of threads. */
bool wk_ray_shoot(const wk_ray_shooter *S, wk_point o, wk_point u, uint32_t from_vertex,
                  wk_ray_hit *hit);
/* The same answer by testing every edge: O(n).  For tests, benchmarks and
** as a fallback; bit-identical to wk_ray_shoot. */
bool wk_ray_shoot_brute(const wk_polygon *P, double tol, wk_point o, wk_point u,
                        uint32_t from_vertex, wk_ray_hit *hit);

/* A walk of a ray o + lambda u through a uniform grid (origin x0, cell size
** cw along one axis): the lambda at which the ray leaves cell index c
** through its wall in direction s = sign(u) (INFINITY when s == 0),
** recomputed from the wall, not accumulated, so no error builds up along
** the walk.  Used for both axes by the engine's segment grid and the
** variants' own grids. */
static inline double wk_grid_exit(double x0, double cw, uint32_t c, int s, double o, double u) {
    return s > 0 ? (x0 + (double)(c + 1) * cw - o) / u
         : s < 0 ? (x0 + (double)c * cw - o) / u
                 : INFINITY;
}

#endif
