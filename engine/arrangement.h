/*
** arrangement.h: the reflex-vertex arrangement A(P) of 000, section 3.1, and
** the next-crossing queries with the per-segment k cache of 000, section 3.2.
** The first building block of the arrangement variant (issue 4); the
** extended wavefront and its events live elsewhere.
**
** Design note
** -----------
** 1. A(P) (ray_shoot.c, arrangement.c).  For every reflex vertex v of P, the
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
** 2. Initial crossings (arrangement.c).  A second bucket grid, about 4 r
**    cells over the r segments; pairs sharing a cell are tested with the
**    exact segment predicate (Shewchuk's stage-A float filter inline,
**    wk_segments_meet for the undecided) and a proper crossing is counted
**    only in its canonical cell: the cell of the computed crossing point
**    when both segments are listed there (they are, up to rounding; a
**    distance check proves it without table lookups), else the first cell in
**    row-major order that both are listed in.  The canonical cell depends
**    only on the pair, so each crossing is counted exactly once, and the
**    count is exact (rounding only moves work between cells).  Grid entries
**    are counted in parallel (a crowded cell is shared by all threads) with
**    an integer reduction: deterministic.  Cost O(r^1.5 + pairs sharing a
**    cell); when all segments pass one small region (star polygons) that is
**    about 5 K tests: K = 12.4 million counts in ~0.6 s on one core.
** 3. The dynamic arrangement (wk_arrangement, arrangement.c).  Current
**    segments sit in a dense array of slots (start point, unit direction,
**    length, active part [lo, hi]) scanned linearly by next-crossing queries
**    (000, 3.2: O(r) per query, linear space); ids are handed out in
**    increasing order and never reused, so a stale id is always detectable.
**    A query keeps the k smallest crossings beyond a position with a bounded
**    max-heap (selection; k = 1 keeps a running minimum), then heap-sorts the
**    k survivors.  Each segment may own a cache: the sorted crossings found
**    by its last refill and the range (from, to] of positions in which that
**    list is complete.  Positions are pairs (s, id) ordered
**    lexicographically, so crossings at the same parameter (several segments
**    through one point) have a well-defined order and none is skipped.  A
**    refill asks for k = R->opt.k (WK_K_MAX: all); its entries (16 bytes)
**    come from R, so peak tracked bytes grow with k up to O(r + K).
** 4. Invalidation, exactly where needed.  Insert: a cache loses its tail
**    from the new segment's crossing onwards when that crossing falls inside
**    its complete range (WK_C_INVALIDATE; dropped when nothing is left).
**    Remove: O(1); entries of other caches that name the removed segment
**    stay and are skipped when read (ids are never reused, so a removed id
**    is always recognised).  Shrinking an active part only removes crossings, so
**    caches are filtered when read (every returned entry is re-checked
**    against both active parts); widening one is treated like an insert.
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
**   - queries: two unit directions with |cross| <= WK_ARR_PARALLEL (1e-12,
**     the sine kinetics.c uses) are parallel and never cross (collinear
**     overlaps are not crossings).  Crossing parameters are computed in
**     double, always by one function with the arguments in the same order,
**     so the same pair yields the same bits in the scan, the cache and the
**     invalidation.
**   - coordinates: the rounding arguments above need a coordinate's rounding
**     (2^-53 |x|) far below WK_TOL_REL times the diagonal, i.e. coordinates
**     within ~10^6 diagonals of the origin; beyond that the grid may miss
**     what the brute force finds.  Translate to wk_polygon_centre first.
**
** Not here: moving Steiner vertices, events and the wavefront (the variant).
*/
#ifndef WK_ARRANGEMENT_H
#define WK_ARRANGEMENT_H
#include "kinetics.h"
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

/* =================================================================== A(P) */

/* One segment of the initial arrangement A(P). */
typedef struct wk_aseg {
    uint32_t vertex;        /* the reflex vertex of P it starts at */
    wk_velocity_kind vkind; /* REGULAR; ANTIPARALLEL for a needle notch (u
                               follows the notch, speed = INFINITY); STRAIGHT
                               or COLLINEAR when the reflex turn is below
                               kinetics.c's parallel sine (u = mean normal;
                               speed w, or INFINITY for COLLINEAR) */
    wk_point a;             /* start: P->p[vertex] */
    wk_point b;             /* end: the first boundary point hit */
    wk_point u;             /* unit direction of the vertex's velocity */
    double speed;           /* |velocity| (distance per unit time) */
    double len;             /* distance from a to the hit along u */
    wk_ray_hit hit;         /* what was hit */
} wk_aseg;

/* A(P): one segment per reflex vertex, in vertex order, shot in parallel
** with R->opt.threads OpenMP threads (identical result for any count).  On
** success *out (NULL when r = 0) is owned by the caller: free with
** WK_FREE_ARRAY(R, *out, *r).  Fails with WK_ENOMEM, or WK_EALGO if a ray
** meets no edge (never for a valid polygon); then *out = NULL, *r = 0. */
wk_status wk_arrangement_segments(wk_run *R, const wk_polygon *P, wk_aseg **out, uint32_t *r);

/* Number of pairs of the r segments that cross properly (one common point,
** interior to both; touching and collinear overlaps do not count), exact.
** Reports the count once via wk_notify_arrangement(R,
** WK_A_INITIAL_CROSSING, count).  Uses R->opt.threads; O(r + cells entries +
** pairs sharing a cell) time, O(r sqrt(r)) grid memory, freed before it
** returns.  On failure *count = 0 and nothing is reported. */
wk_status wk_arrangement_count_crossings(wk_run *R, const wk_aseg *segs, uint32_t r,
                                         uint64_t *count);

/* ====================================================== dynamic arrangement */

/* Two unit directions are parallel below this |cross| (see the note). */
#define WK_ARR_PARALLEL 1e-12

/* A crossing of the queried segment with another current segment. */
typedef struct wk_crossing {
    double s;       /* parameter on the queried segment (distance from its start) */
    double t;       /* parameter on the other segment */
    uint32_t other; /* the other segment's id; WK_NONE for "no crossing" */
} wk_crossing;

/* One current segment (a slot of the dense array).  64 bytes. */
typedef struct wk_arr_seg {
    double ax, ay; /* start point */
    double ux, uy; /* unit direction */
    double len;    /* length: the segment is a + s u, s in [0, len] */
    double lo, hi; /* active part, 0 <= lo <= hi <= len (distance units) */
    uint32_t id;
} wk_arr_seg;

/* A cached crossing, 16 bytes.  A tombstone (dead = 1: the other segment
** was removed) keeps its s and other, so the order stays intact. */
typedef struct wk_arr_centry {
    double s;       /* parameter on the cache's segment */
    uint32_t other; /* the other segment's id */
    uint32_t dead;  /* 1: tombstone */
} wk_arr_centry;

/* The cache of one segment: e[0..n) sorted by (s, other); complete for all
** positions in the half-open range (from, to] (pairs (s, id),
** lexicographic); to_s = INFINITY when the refill found fewer than k. */
typedef struct wk_arr_cache {
    wk_arr_centry *e; /* cap entries allocated, the first n in use */
    uint32_t n, cap;
    bool valid;
    double from_s, to_s;
    uint32_t from_id, to_id;
} wk_arr_cache;

/* Per id (ids are never reused): where the segment lives and its cache. */
typedef struct wk_arr_id {
    uint32_t slot; /* index into seg[], WK_NONE once removed */
    wk_arr_cache cache;
} wk_arr_id;

/* Invariants between calls (wk_arrangement_check):
**   seg[0..n_live) are the current segments, ids[seg[i].id].slot == i;
**   ids[i].slot == WK_NONE for removed ids, and their caches are empty;
**   n_cached == number of valid caches; every valid cache is sorted by
**   (s, other), its live entries lie in (from, to], and it belongs to a
**   current segment. */
typedef struct wk_arrangement {
    wk_arr_seg *seg; /* dense, unordered (swap-remove) */
    uint32_t n_live, cap_seg;
    wk_arr_id *ids;
    uint32_t n_ids, cap_ids;
    uint32_t n_cached;
    wk_crossing *scratch; /* refill buffer, min(k, n_live) entries */
    uint32_t cap_scratch;
} wk_arrangement;

void wk_arrangement_init(wk_arrangement *A);
/* Free everything (segments and caches); A is empty and reusable. */
void wk_arrangement_clear(wk_run *R, wk_arrangement *A);
/* Insert the segment a + s dir, s in [0, len] (dir need not be unit: it is
** normalised, and s is a distance), active part [0, len].  *id receives its
** id (the number of inserts before it).  Invalidates the caches it crosses
** inside their complete range.  Counts WK_A_INSERT.  WK_ENOMEM leaves A
** unchanged; WK_EINPUT for a zero or non-finite direction or a bad len. */
wk_status wk_arrangement_insert(wk_run *R, wk_arrangement *A, wk_point a, wk_point dir, double len,
                                uint32_t *id);
/* Insert the r segments of A(P) in order: ids first_id .. first_id + r - 1
** where first_id is the id count before the call. */
wk_status wk_arrangement_insert_aseg(wk_run *R, wk_arrangement *A, const wk_aseg *segs, uint32_t r);
/* Remove a current segment: frees its cache; entries of other caches that
** name it are skipped when read.  Counts WK_A_REMOVE.  WK_EALGO if id is not
** current (A unchanged).  Never allocates. */
wk_status wk_arrangement_remove(wk_run *R, wk_arrangement *A, uint32_t id);
/* Set the active part of a current segment (0 <= lo <= hi <= len, else
** WK_EINPUT).  Shrinking invalidates nothing (cached entries are re-checked
** when read); widening drops the segment's own cache and invalidates the
** others like an insert. */
wk_status wk_arrangement_set_active(wk_run *R, wk_arrangement *A, uint32_t id, double lo,
                                    double hi);
/* The current segment with this id, or NULL.  Valid until the next insert
** or remove. */
const wk_arr_seg *wk_arrangement_get(const wk_arrangement *A, uint32_t id);

/* The next k crossings of segment seg with the other current segments
** beyond parameter s_from: crossings (s, other) with s > s_from, s in seg's
** active part and t in the other's active part, sorted by (s, other).  One
** scan over the current segments (counted: one WK_A_QUERY, WK_A_SCANNED with
** the number of other segments examined); k = 1 keeps the minimum, k > 1
** keeps the k smallest in a bounded max-heap.  out must have room for
** min(k, wk_arrangement live count) entries; *count receives how many were
** found (< k: there are no more).  k = 0 is treated as 1.  WK_EALGO if seg
** is not current.  Never allocates. */
wk_status wk_arrangement_next_crossings(wk_run *R, wk_arrangement *A, uint32_t seg, double s_from,
                                        uint32_t k, wk_crossing *out, uint32_t *count);
/* The same beyond the position (s_from, after): crossings at s == s_from
** with other > after are included, so a caller can step through several
** crossings at one point.  after = WK_NONE gives the plain form. */
wk_status wk_arrangement_next_crossings_after(wk_run *R, wk_arrangement *A, uint32_t seg,
                                              double s_from, uint32_t after, uint32_t k,
                                              wk_crossing *out, uint32_t *count);

/* The first crossing of seg beyond s_from, from seg's cache when it still
** covers s_from (WK_C_HIT), else after refilling it with the next
** k = R->opt.k crossings (WK_K_MAX: all of them) (WK_C_MISS, WK_C_REFILL,
** and the query's counters).  *c receives the crossing, or other = WK_NONE
** and s = t = INFINITY when there is none.  Cache memory comes from R (at
** most k entries of 16 bytes per segment, plus one scratch buffer of
** min(k, live) crossings).  WK_ENOMEM leaves the old cache dropped and *c
** untouched; WK_EALGO if seg is not current. */
wk_status wk_arrangement_cache_next(wk_run *R, wk_arrangement *A, uint32_t seg, double s_from,
                                    wk_crossing *c);
/* The same beyond the position (s_from, after) (see _next_crossings_after). */
wk_status wk_arrangement_cache_next_after(wk_run *R, wk_arrangement *A, uint32_t seg, double s_from,
                                          uint32_t after, wk_crossing *c);

/* The crossing of current segments a and b (a's parameter in s, b's in t),
** ignoring active parts; false if parallel.  The one formula every part of
** this module uses. */
bool wk_arrangement_crossing(const wk_arr_seg *a, const wk_arr_seg *b, double *s, double *t);
/* Check the invariants above (tests and debug builds). */
bool wk_arrangement_check(const wk_arrangement *A);

#endif
