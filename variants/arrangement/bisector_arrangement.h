/*
** bisector_arrangement.h: the reflex-vertex arrangement A(P) of 000, section
** 3.1, and the next-crossing queries with the per-segment k cache of 000,
** section 3.2: the arrangement variant's search structure (the extended
** wavefront and its events are finder.c).  Rays are shot with the engine's
** ray_shoot.h.
**
** Design note
** -----------
** 1. Initial crossings .  A second bucket grid, about 4 r
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
** 2. The dynamic arrangement (wk_arrangement).  Current
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
** 3. Invalidation, exactly where needed.  Insert: a cache loses its tail
**    from the new segment's crossing onwards when that crossing falls inside
**    its complete range (cache_invalidations; dropped when nothing is left).
**    Remove: O(1); entries of other caches that name the removed segment
**    stay and are skipped when read (ids are never reused, so a removed id
**    is always recognised).  Shrinking an active part only removes crossings, so
**    caches are filtered when read (every returned entry is re-checked
**    against both active parts); widening one is treated like an insert.
**
** Tolerances (the policy of wskel.h, WK_TOL_REL):
**   - queries: two unit directions with |cross| <= WK_ARR_PARALLEL (1e-12,
**     the sine kinetics.c uses) are parallel and never cross (collinear
**     overlaps are not crossings).  Crossing parameters are computed in
**     double, always by one function with the arguments in the same order,
**     so the same pair yields the same bits in the scan, the cache and the
**     invalidation.
*/
#ifndef WK_BISECTOR_ARRANGEMENT_H
#define WK_BISECTOR_ARRANGEMENT_H
#include "arrangement.h"
#include "ray_shoot.h"

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
    bool contact;           /* the vertex lies within the shooter's tol of
                               an edge other than its own two and its
                               neighbours' (a contact at t = 0 with another
                               part of the boundary, which the ray may pass) */
} wk_aseg;

/* A(P): one segment per reflex vertex, in vertex order, shot in parallel
** with R->opt.threads OpenMP threads (identical result for any count).  On
** success *out (NULL when r = 0) is owned by the caller: free with
** WK_FREE_ARRAY(R, *out, *r).  A ray that meets nothing because its vertex
** lies within the shooter's tolerance of another edge (a tiny edge next to
** it) gets a vertex hit at (about) its origin.  Fails with WK_ENOMEM, or
** WK_EALGO if a ray meets no edge otherwise (never for a valid polygon);
** then *out = NULL, *r = 0. */
wk_status wk_arrangement_segments(wk_run *R, const wk_polygon *P, wk_aseg **out, uint32_t *r);

/* Number of pairs of the r segments that cross properly (one common point,
** interior to both; touching and collinear overlaps do not count), exact.
** Reports the count once on the arrangement_crossings_initial
** counter.  Uses R->opt.threads; O(r + cells entries +
** pairs sharing a cell) time, O(r sqrt(r)) grid memory, freed before it
** returns.  On failure *count = 0 and nothing is reported. */
wk_status wk_arrangement_count_crossings(wk_run *R, const wk_aseg *segs, uint32_t r,
                                         uint64_t *count);

/* ====================================================== dynamic arrangement */

/* WK_ARR_PARALLEL (tolerance.h): two unit directions are parallel below
** this |cross| (see the note). */

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
** inside their complete range.  Counts arrangement_inserts.  WK_ENOMEM leaves A
** unchanged; WK_EINPUT for a zero or non-finite direction or a bad len. */
wk_status wk_arrangement_insert(wk_run *R, wk_arrangement *A, wk_point a, wk_point dir, double len,
                                uint32_t *id);
/* Insert the r segments of A(P) in order: ids first_id .. first_id + r - 1
** where first_id is the id count before the call. */
wk_status wk_arrangement_insert_aseg(wk_run *R, wk_arrangement *A, const wk_aseg *segs, uint32_t r);
/* Remove a current segment: frees its cache; entries of other caches that
** name it are skipped when read.  Counts arrangement_removes.  WK_EALGO if id is not
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
** scan over the current segments (counted: one intersection_query, segments_scanned with
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
** covers s_from (cache_hits), else after refilling it with the next
** k = R->opt.k crossings (WK_K_MAX: all of them) (cache_misses, cache_refills,
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
