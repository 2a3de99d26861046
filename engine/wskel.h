/*
** wskel.h: the public interface of the wskel library (build/libwskel.a).
**
** wskel computes positively weighted straight skeletons of simple polygons.
** Everything a computation needs hangs off one run context (wk_run): the
** counting allocator, the event counters, the observer, the options and the
** first error.  There are no mutable globals, so independent runs may go in
** parallel (one wk_run per thread or per forked child).
**
** Conventions used throughout:
**   - polygons are stored counter-clockwise; edge i runs from vertex i to
**     vertex i+1 (mod n) and carries weight w[i] > 0 (its offset line moves
**     inward at speed w[i]);
**   - a skeleton's first n nodes are the input vertices in input order, t = 0;
**   - an arc [a, b, left, right] runs from node a to node b; `left` is the
**     input edge whose face lies to the left of a->b, `right` the one to the
**     right (WK_NONE never appears in a finished skeleton);
**   - every function that allocates, counts or can fail takes wk_run *R first
**     and returns a wk_status; on failure R->err holds the first failure and
**     outputs are left untouched (NULL).
*/
#ifndef WSKEL_H
#define WSKEL_H

#include <float.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "tolerance.h"

#define WK_NONE UINT32_MAX
#define WK_K_MAX (UINT32_MAX - 1) /* --k max: a variant's cache holds everything */

typedef enum wk_status {
    WK_OK = 0,
    WK_EINPUT,   /* invalid input: CLI exit code 1 */
    WK_ENOMEM,   /* allocation failed or over the memory limit: exit 2 */
    WK_EALGO,    /* the algorithm could not handle the input: exit 2 */
    WK_EUNSUPPORTED, /* the variant does not apply to this kind of polygon
                        (e.g. a polygon outside its class): exit 2 */
    WK_EINVALID, /* the validator rejected an output: exit 3 */
    WK_EUSAGE    /* bad options: exit 64 */
} wk_status;

/* Exit code of the command-line tools for a status. */
int wk_status_exit_code(wk_status s);
const char *wk_status_name(wk_status s);

typedef struct wk_point { double x, y; } wk_point;

/* ---------------------------------------------------------------- errors */

typedef struct wk_error {
    wk_status code;      /* WK_OK while no failure happened */
    char input[256];     /* input file name, "" if none */
    long input_line;     /* 1-based line in that file, 0 if none */
    const char *src_file;/* where in wskel the failure was raised */
    int src_line;
    char msg[512];       /* what went wrong, naming the culprit */
} wk_error;

/* ------------------------------------------------------------- allocator */

/* An allocator backend.  realloc has Lua's lua_Alloc shape: old_size is the
** size the caller allocated (0 when p is NULL), so the statistics need no
** block headers; new_size == 0 frees p and returns NULL; on failure it
** returns NULL and leaves p intact.  The run (wk_realloc) keeps the
** statistics and the limits; a backend only provides memory. */
typedef struct wk_alloc_backend {
    const char *name;
    void *(*realloc)(void *ud, void *p, size_t old_size, size_t new_size);
} wk_alloc_backend;

/* libc malloc/realloc/free; ud unused.  The default. */
extern const wk_alloc_backend wk_alloc_libc;

/* The checking backend for tests.  Each block carries a header (its size)
** and guard bytes before and after it; every resize and free checks them
** and checks old_size against the recorded size, and aborts with a message
** naming the block's size on a mismatch (an overrun, an underrun, a wrong
** count in WK_FREE_ARRAY, a double free).  New bytes are filled with 0xA5
** (wk_calloc still zeroes), freed blocks with 0xDD, and a resize always
** moves the block.  ud is NULL or a wk_alloc_debug_state for fault
** injection.  Stateless with ud NULL; with a state, one run (thread) at a
** time. */
extern const wk_alloc_backend wk_alloc_debug;

typedef struct wk_alloc_debug_state {
    uint64_t fail_at;   /* refuse the request with this number (1-based,
                           counting every request that allocates, resizes
                           included, frees not); 0: never */
    bool keep_failing;  /* also refuse every request after fail_at */
    uint64_t requests;  /* requests seen so far (refused ones included) */
    uint64_t refused;   /* requests refused by the injection */
} wk_alloc_debug_state;

typedef struct wk_alloc {
    const wk_alloc_backend *backend; /* wk_alloc_libc by default; change it
                             only while no block is live */
    void *ud;             /* the backend's */
    size_t live;          /* bytes allocated now */
    size_t peak;          /* high-water mark of live since the last reset */
    size_t blocks;        /* live blocks */
    uint64_t calls;       /* allocation calls (not frees) since init */
    size_t limit;         /* refuse to go beyond this many live bytes; 0: none */
    int64_t fail_after;   /* fault injection: fail the call after this many
                             successful allocations; -1: never */
    bool strict;          /* wk_run_close aborts unless live == blocks == 0;
                             also (as with the debug backend) a nonzero old
                             size for an empty block aborts (see wk_realloc) */
} wk_alloc;

/* ------------------------------------------------------------- counters */

/* A counter: its name (JSON stats key, CSV column) and what one count is. */
typedef struct wk_counter_def {
    const char *name;
    const char *meaning;
} wk_counter_def;

/* The counters of what every variant shares: the kinetic wavefront, the
** event queue and the predicates.  A variant declares its own counters in
** its wk_variant (engine/variant.h); counter ids run over both: engine
** counter i has id i, the variant's counter j has id WK_ENGINE_COUNTERS + j.
** Counters hold counts only (no times, no addresses), so they are
** deterministic. */
#define WK_ENGINE_COUNTER_LIST(X)                                                            \
    X(edge_events, "a wavefront edge shrank to zero length")                                 \
    X(split_events, "a reflex wavefront vertex hit the interior of an edge")                 \
    X(multi_split_events, "several reflex vertices met at one point")                        \
    X(reflex_preserving_edge_events, "an edge event whose new vertex is reflex")             \
    X(vanishing_components, "a wavefront cycle vanished")                                    \
    X(simultaneous_event_groups, "a group of simultaneous events was resolved")              \
    X(collinear_resolutions, "parallel edges of different weight met (the collinear rule)") \
    X(queue_pushes, "event queue insertions")                                                \
    X(queue_pops, "event queue extractions of the minimum")                                  \
    X(queue_updates, "event queue key changes")                                              \
    X(queue_removes, "event queue removals of a non-minimum")                                \
    X(exact_fallbacks, "orientation tests the float filter could not decide (exact stage)")   \
    X(tolerance_escalations, "inputs solved again with coarser tolerances (wk_solve_checked)")

typedef enum wk_engine_counter {
#define WK_COUNTER_ENUM(name, meaning) WK_COUNTER_##name,
    WK_ENGINE_COUNTER_LIST(WK_COUNTER_ENUM)
#undef WK_COUNTER_ENUM
    WK_ENGINE_COUNTERS /* how many; the first variant counter's id */
} wk_engine_counter;

/* Most counters one variant may declare. */
#define WK_VARIANT_COUNTERS_MAX 24
#define WK_COUNTERS_MAX (WK_ENGINE_COUNTERS + WK_VARIANT_COUNTERS_MAX)

typedef struct wk_counters {
    uint64_t c[WK_COUNTERS_MAX]; /* by counter id */
} wk_counters;

typedef struct wk_variant wk_variant;
struct wk_run;

/* The counters a run of V reports, in output order: the engine's, then V's
** (V may be NULL: the engine's only).  wk_counter_def_at is NULL for
** id >= wk_counter_count(V). */
uint32_t wk_counter_count(const wk_variant *V);
const wk_counter_def *wk_counter_def_at(const wk_variant *V, uint32_t id);
/* The id of V's counter called name; false if V has none of that name. */
bool wk_counter_find(const wk_variant *V, const char *name, uint32_t *id);
/* The value of the counter called name of the run's variant (R->variant,
** set by wk_solve; the engine's counters only while it is NULL); false if
** that variant does not have it. */
bool wk_counter_lookup(const struct wk_run *R, const char *name, uint64_t *value);
/* The union of the counter names over the registry, in CSV column order:
** the engine's, then each registered variant's new names in registry order.
** Writes at most cap names; returns how many there are. */
uint32_t wk_counter_union(const char **names, uint32_t cap);

/* ------------------------------------------------------------- observer */

/* Where an event happened; a, b, c are ids involved (meaning set by whoever
** raises the event), WK_NONE if unused. */
typedef struct wk_event {
    double t, x, y;
    uint32_t a, b, c;
} wk_event;

/* Hooks may be NULL.  Observers see const data and cannot steer a run.
** event: an event was processed; `counter` is the counter it counts on
**   (engine ids such as WK_COUNTER_edge_events, or a variant's own), which
**   is also its kind.
** count: n more units of work that are not events (queue operations,
**   segments scanned, exact stages) on counter `counter`.
** finished: wk_solve's variant returned (ok: a skeleton). */
typedef struct wk_observer {
    void (*event)(void *ud, uint32_t counter, const wk_event *e);
    void (*count)(void *ud, uint32_t counter, uint64_t n);
    void (*finished)(void *ud, bool ok);
} wk_observer;

/* The default observer: the only code that writes R->counters.  Its ud is
** the wk_counters to fill. */
extern const wk_observer wk_observer_counting;

/* -------------------------------------------------------------- options */

typedef enum wk_collinear_rule {
    WK_COLLINEAR_LOWER = 0,  /* 000: the lower weight edge survives (default) */
    WK_COLLINEAR_HIGHER      /* surfer2's default: the higher weight survives */
} wk_collinear_rule;

typedef struct wk_options {
    uint32_t k;              /* cache size of variants with WK_VARIANT_USES_K; WK_K_MAX for max */
    wk_collinear_rule collinear;
    int threads;             /* OpenMP threads for variants that use them */
    bool check_invariants;   /* after every group of events, check the
                                wavefront's and the finder's invariants
                                (O(n) each: for tests, --check-invariants) */
    double tol_scale;        /* the simulation's tolerances times this (1;
                                wk_solve_checked raises it on a retry) */
    uint32_t part;           /* the readers: which polygon (0-based) of an input
                                holding several (GeoJSON MultiPolygon or
                                features, WKT MULTIPOLYGON); WK_NONE (the
                                default): refuse such an input, naming the count */
    bool nonpositive_weights; /* the readers and wk_polygon_from_* accept
                                weights <= 0 (set it only for a variant with
                                WK_VARIANT_NONPOSITIVE_WEIGHTS) */
    double height;           /* > 0: stop at t = height and close the roof
                                with a cap (--height; required with weights
                                <= 0, where the wavefront need not vanish);
                                0: run until the wavefront vanishes */
    bool angles;             /* the readers take the third column (GraphML:
                                edge-weight) as the roof's pitch in degrees,
                                w = 1 / tan(pitch): 90 a wall (0), above 90
                                an overhang (< 0); --angles */
    double until;            /* PSLGs: the time horizon (--until T > 0): the
                                wavefront is followed up to t = T and the
                                arcs still alive end at nodes at t = T; 0:
                                the default horizon (engine/pslg.c) */
    bool pslg;               /* the GraphML reader makes a PSLG even of
                                disjoint simple cycles (--pslg) */
    double step_scale;       /* variants that advance in time steps (004's
                                predictor-corrector): the first increment
                                times this (1; --step); the skeleton must
                                not depend on it */
} wk_options;

/* ------------------------------------------------------------------ run */

typedef struct wk_run {
    wk_alloc alloc;
    wk_counters counters;    /* written only through the observer */
    const wk_observer *obs;  /* never NULL */
    void *obs_ud;            /* &counters for the counting observer */
    wk_options opt;
    const wk_variant *variant; /* whose counters these are: set by wk_solve */
    wk_error err;            /* the first failure wins */
    double phase_s;          /* wall seconds of the variant's timed phase
                                (wk_variant.phase) in the last wk_solve (the
                                attempts' sum for wk_solve_checked); 0 when
                                it has none.  A time, so not a counter:
                                counters are deterministic */
    char fallback_reason[640]; /* why the variant's own run gave up in the
                                  last wk_solve and the reference answered
                                  (its failure message, prefixed by where it
                                  was raised); "" when it did not.  Kept
                                  because the failure itself is cleared: the
                                  run succeeds, and a user who sees
                                  reference_fallbacks must learn why */
} wk_run;

/* Monotonic wall clock in seconds (for phase timing). */
double wk_clock_s(void);
/* The variant's timed phase: t0 = wk_phase_begin(); ...; wk_phase_end(R, t0)
** adds the elapsed wall time to R->phase_s. */
static inline double wk_phase_begin(void) { return wk_clock_s(); }
static inline void wk_phase_end(wk_run *R, double t0) { R->phase_s += wk_clock_s() - t0; }

/* Cannot fail; leaves R closable.  Default options, libc allocator,
** counting observer. */
void wk_run_init(wk_run *R);
/* wk_run_init, then the debug backend (no fault injection, ud NULL) and
** alloc.strict: a run whose every allocation is checked. */
void wk_run_init_checked(wk_run *R);
/* Test builds compile their own sources with -DWK_CHECKED_RUNS (see the
** Makefile), so that every run a test opens is checked without each test
** saying so; the library itself is built without it. */
#if defined(WK_CHECKED_RUNS)
#define wk_run_init(R) wk_run_init_checked(R)
#endif
/* Releases nothing itself (objects are freed by their owners); returns the
** number of live bytes left, which must be 0 after a clean run.  With
** alloc.strict, a leak aborts instead, naming the live bytes and blocks. */
size_t wk_run_close(wk_run *R);
/* Start a new phase for the peak statistic: peak := live. */
void wk_run_reset_peak(wk_run *R);

/* Forget the recorded failure (a variant that recovers from one, e.g. by
** handing the input to the reference variant). */
void wk_run_clear_error(wk_run *R);
/* Record a failure (the first one wins) and return its code.  Use WK_FAIL. */
wk_status wk_fail(wk_run *R, wk_status code, const char *input, long input_line,
                  const char *src_file, int src_line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 7, 8)))
#endif
    ;
#define WK_FAIL(R, code, input, line, ...) \
    wk_fail((R), (code), (input), (line), __FILE__, __LINE__, __VA_ARGS__)
/* Format R->err as "file:line: message" into buf. */
void wk_error_format(const wk_run *R, char *buf, size_t size);

/* Raw allocation through the run (counts bytes, honours limit/fault
** injection).  Returns NULL on failure after recording WK_ENOMEM.
** wk_realloc(R, p, old, 0) frees and returns NULL without failing.
**
** Empty blocks: a request for 0 bytes (wk_calloc with count or size 0, e.g.
** WK_NEW_ARRAY(R, T, 0)) succeeds with a non-NULL pointer to no storage,
** shared by all empty blocks, that must not be dereferenced.  It is counted
** as an allocation call (fail_after may refuse it, as before) but adds no
** live bytes and no block, and the backend never sees it.  Freeing
** it (old size 0, as WK_FREE_ARRAY(R, p, 0) passes) does nothing; growing it
** is a fresh allocation.  So allocation and free agree for every count,
** with no size rounding for callers to repeat. */
void *wk_realloc(wk_run *R, void *p, size_t old_size, size_t new_size);
void *wk_calloc(wk_run *R, size_t count, size_t size);
#define WK_NEW_ARRAY(R, T, n) ((T *)wk_calloc((R), (n), sizeof(T)))
#define WK_FREE_ARRAY(R, p, n) \
    ((void)wk_realloc((R), (p), (size_t)(n) * sizeof(*(p)), 0), (p) = NULL)

/* Growing arrays.  wk_grow_ptr returns p grown to hold at least need
** elements of elem_size bytes (capacity *cap, doubling from 8) and updates
** *cap; on failure it records WK_ENOMEM and returns p itself with *cap
** unchanged, so the array is never lost.  Nothing happens when need <= *cap
** and p is not NULL.
**
** WK_GROW(R, p, cap, need) applies it to an array p of any object type T
** and yields a wk_status.  It assigns the result to p in p's own type: a
** T * object is only ever accessed as a T *, where storing through a
** (void **) cast of &p would access it as a void * (undefined behaviour by
** the aliasing rules, and wrong wherever T * and void * differ in
** representation).  C11 has no typed temporaries in an expression, so the
** status comes from the postcondition, which holds exactly on success:
** p != NULL and cap >= need.  p, cap and need are evaluated more than once,
** so they must be free of side effects (they are plain lvalues and sums in
** practice). */
void *wk_grow_ptr(wk_run *R, void *p, uint32_t *cap, uint32_t need, size_t elem_size);
#define WK_GROW(R, p, cap, need)                                                   \
    ((p) = wk_grow_ptr((R), (p), &(cap), (need), sizeof *(p)),                     \
     (wk_status)((p) != NULL && (cap) >= (uint32_t)(need) ? WK_OK : WK_ENOMEM))
/* WK_GROW for an array whose final size is probably at most `hint` (0: no
** hint): it grows to the power of two WK_GROW would give (at least need),
** but to hint instead while need <= hint < that.  So its capacity is never
** above WK_GROW's, and an array that ends within the hint holds no doubling
** slack (the wavefront's vertices: 2n - 3 for n input vertices in general
** position; wavefront.c). */
void *wk_grow_ptr_hint(wk_run *R, void *p, uint32_t *cap, uint32_t need, size_t elem_size,
                       uint32_t hint);
/* The capacity wk_grow_ptr_hint picks for an array of cap elements that must
** hold need (cap < need), doubling from `first`: for arrays grown in
** lockstep by hand (a variant's per-vertex arrays). */
uint64_t wk_grow_capacity(uint32_t cap, uint32_t need, uint32_t hint, uint32_t first);
#define WK_GROW_HINT(R, p, cap, need, hint)                                        \
    ((p) = wk_grow_ptr_hint((R), (p), &(cap), (need), sizeof *(p), (hint)),        \
     (wk_status)((p) != NULL && (cap) >= (uint32_t)(need) ? WK_OK : WK_ENOMEM))
/* The same for an array held in an object of type void * (*pp must be one:
** for a T * use WK_GROW, or copy it to a void * and back). */
wk_status wk_grow(wk_run *R, void **pp, uint32_t *cap, uint32_t need, size_t elem_size);

/* Observer notifications (thin inline wrappers). */
static inline void wk_notify_event(wk_run *R, uint32_t counter, const wk_event *e) {
    if (R->obs->event) R->obs->event(R->obs_ud, counter, e);
}
static inline void wk_count(wk_run *R, uint32_t counter, uint64_t n) {
    if (R->obs->count) R->obs->count(R->obs_ud, counter, n);
}

/* -------------------------------------------------------------- polygon */

/* Largest vertex count wk_polygon_from_arrays accepts (and the readers). */
#define WK_POLYGON_MAX_N 50000000u
/* Largest coordinate magnitude accepted: keeps every product the exact
** predicates form far from overflow. */
#define WK_POLYGON_MAX_COORD 1e150
/* Smallest nonzero coordinate magnitude accepted: the exact predicates
** (Shewchuk's) assume that no product underflows; a subnormal coordinate
** such as 1.5e-323 next to coordinates of size 1 made them decide wrongly
** (tests/data/bad/subnormal_vertex.wpoly, a fuzz finding: every variant's
** skeleton failed validation).  1e-150 keeps products of two coordinates
** above DBL_MIN. */
#define WK_POLYGON_MIN_COORD 1e-150
/* Largest ratio of two weights accepted: make stress sweeps ratios up to it
** (tests/stress/makers.py, class weight_ratio: every variant passes); far
** beyond it the vertex speeds overflow (a fuzz finding with weights 1 and
** 5e307: "vertex ... is not finite"). */
#define WK_POLYGON_MAX_WEIGHT_RATIO 1e6
/* Smallest hole accepted, as a fraction of the polygon's bounding-box
** diagonal (its own diagonal): a hole below the simulation's tolerances
** cannot leave the cycle of arcs around it that the skeleton of a polygon
** with holes has (a fuzz finding: holes of size 10 next to a vertex 5e12
** away, every variant's skeleton a tree).  1e-6 is the validator's default
** tolerance, 1000 times eps_d (tolerance.h). */
#define WK_POLYGON_MIN_HOLE_REL 1e-6
/* Largest distance of the polygon from the coordinate origin, in polygon
** diagonals (the largest |coordinate| over the bounding-box diagonal).  The
** simulation works relative to the polygon's centre, but the skeleton's
** nodes are written (and validated) in the input's coordinates, which carry
** a rounding of 2^-53 |coordinate|.  At 9e8 diagonals that rounding is
** 1e-7 diagonals, a tenth of the validator's default tolerance
** (WK_VALIDATE_TOL_REL); beyond it thin faces of a correct skeleton collapse
** onto each other in the written coordinates (a stress finding: a comb
** 1.4e-3 across at 2.2e6 from the origin, faces 1.3e-10 wide written with an
** ulp of 4.7e-10, failed the planarity check in every variant; the same
** comb at the origin passes).  Translate such input nearer the origin. */
#define WK_POLYGON_MAX_OFFSET_REL 9.0e8

/* A polygon, possibly with holes: ring 0 is the outer boundary, rings 1..
** are holes.  Stored vertex ids run over the rings in order: ring k is
** p[ring_start[k] .. ring_start[k+1]), and stored edge j runs from vertex j
** to wk_polygon_next(P, j) (the ring closes implicitly).  The outer ring is
** stored counter-clockwise, holes clockwise, so the interior is on the left
** of every edge and everything local (offset lines, reflex tests, bisectors)
** reads the same for holes. */
typedef struct wk_polygon {
    uint32_t n;          /* vertices (= edges) over all rings, >= 3 */
    uint32_t r;          /* reflex vertices (interior angle > pi) */
    wk_point *p;         /* outer ring counter-clockwise, holes clockwise */
    double *w;           /* w[i]: weight of edge i (p[i] -> next), > 0 */
    uint32_t n_rings;    /* 1 + the number of holes */
    uint32_t *ring_start; /* n_rings + 1 offsets; ring_start[n_rings] == n */
    uint32_t *ring_of;   /* ring of each stored vertex; NULL when n_rings == 1 */
    bool reversed;       /* the outer ring's input was clockwise and was reversed */
    uint32_t *input_index; /* input_index[i]: the input number of stored vertex i */
    char name[256];      /* file name for messages */
    /* A planar straight-line graph (engine/pslg.c) is stored as the cycles
    ** of its initial wavefront: one ring per face cycle of half-edges (the
    ** face on the left), a vertex of degree d once per angular gap (a
    ** "corner"), a terminal (degree 1) twice with a cap edge of length 0
    ** between, perpendicular to its segment.  Rings may then share points
    ** and run along each other (both sides of a segment), and the outer
    ** face's cycle has no enclosing ring; P->p and the skeleton's first n
    ** nodes are the corners.  NULL / 0 for polygons. */
    bool pslg;
    wk_point *dir;       /* PSLG: direction of stored edge e (b - a for a
                            half-edge, the incoming half-edge's direction
                            turned clockwise for a cap); NULL for polygons */
    uint32_t *corner_vertex; /* PSLG: the input node (document order) of each corner */
    uint32_t *edge_of;   /* PSLG: the input edge (document order) of each
                            stored edge; WK_NONE for a cap */
    uint32_t n_graph_vertices, n_graph_edges; /* PSLG: the input graph's size */
} wk_polygon;

/* The direction of stored edge e (not normalised): its end minus its start,
** or for a PSLG the stored direction (a cap has length 0). */
static inline wk_point wk_polygon_edge_dir(const wk_polygon *P, uint32_t e);

/* Largest number of rings (1 + holes) accepted. */
#define WK_POLYGON_MAX_RINGS 10000000u

static inline uint32_t wk_polygon_ring(const wk_polygon *P, uint32_t i) {
    return P->ring_of ? P->ring_of[i] : 0;
}
/* The next and previous stored vertex on i's ring. */
static inline uint32_t wk_polygon_next(const wk_polygon *P, uint32_t i) {
    uint32_t k = wk_polygon_ring(P, i);
    return i + 1 == P->ring_start[k + 1] ? P->ring_start[k] : i + 1;
}
static inline uint32_t wk_polygon_prev(const wk_polygon *P, uint32_t i) {
    uint32_t k = wk_polygon_ring(P, i);
    return i == P->ring_start[k] ? P->ring_start[k + 1] - 1 : i - 1;
}
static inline wk_point wk_polygon_edge_dir(const wk_polygon *P, uint32_t e) {
    if (P->dir) return P->dir[e];
    wk_point a = P->p[e], b = P->p[wk_polygon_next(P, e)];
    return (wk_point){b.x - a.x, b.y - a.y};
}

/* Build a polygon from arrays (copied), validate it (see wk_polygon_validate)
** and orient it counter-clockwise.  w may be NULL (unit weights).  name is
** used in messages.  lines may be NULL, else lines[i] is the input line of
** vertex i (for messages). */
wk_status wk_polygon_from_arrays(wk_run *R, uint32_t n, const double *x, const double *y,
                                 const double *w, const char *name, const long *lines,
                                 wk_polygon **out);
/* The same for a polygon with holes: n_rings rings of ring_size[k] >= 3
** vertices each, concatenated in x, y (and w, lines); ring 0 is the outer
** boundary.  Each ring may come in either orientation; it is stored as the
** struct says, weights staying on their edges, input numbering kept (input
** vertex i is the i-th of the arrays, input edge i runs from it to the next
** vertex of its ring).  Checks, besides each ring's own: rings pairwise
** disjoint (not even touching), every hole strictly inside the outer ring,
** no hole inside another. */
wk_status wk_polygon_from_rings(wk_run *R, uint32_t n_rings, const uint32_t *ring_size,
                                const double *x, const double *y, const double *w,
                                const char *name, const long *lines, wk_polygon **out);
/* Read a .wpoly, GraphML, GeoJSON or WKT file (chosen by content: '<'
** GraphML, '{' GeoJSON, a letter WKT, else .wpoly; "-" reads stdin).
** GeoJSON and WKT may hold several polygons: R->opt.part chooses one. */
wk_status wk_polygon_read_file(wk_run *R, const char *path, wk_polygon **out);
wk_status wk_polygon_read_wpoly(wk_run *R, FILE *f, const char *name, wk_polygon **out);
wk_status wk_polygon_read_graphml(wk_run *R, const char *buf, size_t len, const char *name,
                                  wk_polygon **out);
/* Smallest distance accepted between a PSLG node and an edge not at it,
** as a fraction of the bounding-box diagonal: above the simulation's
** coarsest eps_d (WK_TOL_REL times WK_TOL_ESCALATE_MAX, tolerance.h), so
** that no contact the input does not have happens at t = 0 (a "Y" whose
** arm ended 2e-15 from a segment, below eps_d but not touching it, left
** the wavefront without a cap).  Nodes joined by edges shorter than it
** count as one node (an edge below the tolerance collapses at once, as in
** polygons).  Input domain; an input that means the node to lie on the
** edge must say so with a node there. */
#define WK_PSLG_MIN_CLEARANCE_REL 1e-7
/* A PSLG's default time horizon: the last event's time plus this many
** bounding-box diagonals over the largest weight.  After the last event the
** wavefront only grows, every bounded component has vanished and the
** skeleton has all its nodes; the margin shows the unbounded arcs' directions
** (an input with no event, a single segment, still gets a positive horizon). */
#define WK_PSLG_HORIZON_MARGIN 0.25
/* The default run follows a PSLG's events up to this many diagonals over
** the smallest weight: every bounded wavefront component has vanished by
** then (a point of a bounded face is less than a diagonal from its
** boundary, which reaches it by that distance over the smallest weight).
** Later events of the unbounded wavefront (nearly parallel pieces that
** shrink very slowly: a "+" whose arms are 1e-16 off perpendicular has one
** at t = 4.5e16) are left to an explicit --until. */
#define WK_PSLG_DEFAULT_EVENTS_REL 1.0
/* Largest --until accepted, in diagonals over the smallest weight: beyond
** it the nodes at the horizon are so far out that their rounding exceeds
** the validator's tolerance (input domain). */
#define WK_PSLG_MAX_HORIZON_REL 1e6
/* A PSLG from arrays (engine/pslg.c): nv nodes (x, y; node_line may be
** NULL), ne edges src[i] - dst[i] of weight w[i] (w may be NULL: 1;
** edge_line may be NULL).  Validated (no isolated node, no duplicate
** point or edge, no crossing, touching or overlapping edges, the input
** domain's bounds) and stored as its initial wavefront's face cycles (see
** wk_polygon.pslg).  WK_EINPUT naming the culprit and its line. */
wk_status wk_pslg_from_arrays(wk_run *R, uint32_t nv, const double *x, const double *y,
                              uint32_t ne, const uint32_t *src, const uint32_t *dst,
                              const double *w, const char *name, const long *node_line,
                              const long *edge_line, wk_polygon **out);
/* GeoJSON and WKT from memory (engine/polygon_read_gis.c: the accepted
** forms, the weights property, --part).  buf[len] need not be NUL. */
wk_status wk_polygon_read_geojson(wk_run *R, const char *buf, size_t len, const char *name,
                                  wk_polygon **out);
wk_status wk_polygon_read_wkt(wk_run *R, const char *buf, size_t len, const char *name,
                              wk_polygon **out);
/* The weight of a roof pitch of `degrees` (0 < degrees < 180; 90 gives
** exactly 0): 1 / tan.  WK_EINPUT naming name and line otherwise. */
wk_status wk_weight_of_angle(wk_run *R, double degrees, const char *name, long line, double *w);
/* Write .wpoly (counter-clockwise, as stored). */
wk_status wk_polygon_write_wpoly(wk_run *R, FILE *f, const wk_polygon *P);
void wk_polygon_free(wk_run *R, wk_polygon *P);
/* Check an existing polygon (e.g. one built by hand or modified) with the
** checks of wk_polygon_from_arrays, on the stored order (so messages use
** stored numbering, without lines), plus: stored counter-clockwise, r up to
** date.  WK_OK or WK_EINPUT; uses O(n) scratch memory (may fail WK_ENOMEM). */
wk_status wk_polygon_validate(wk_run *R, const wk_polygon *P);
/* Input numbering.  Stored vertex j is input vertex P->input_index[j]; stored
** edge j (p[j] -> next) is input edge wk_polygon_input_edge(P, j), where
** input edge i runs from input vertex i to the next input vertex of its ring.  Writers emit
** input numbering; algorithms and the validator use stored numbering. */
uint32_t wk_polygon_input_edge(const wk_polygon *P, uint32_t e);
/* Output id of skeleton node j: input_index[j] for j < n, j otherwise. */
uint32_t wk_polygon_output_node(const wk_polygon *P, uint32_t j);
/* Signed area: the outer ring's minus the holes' (positive once stored). */
double wk_polygon_area(const wk_polygon *P);
/* True if vertex i is reflex (robust orientation test). */
bool wk_polygon_is_reflex(const wk_polygon *P, uint32_t i);
/* The same, counting an exact stage on R's exact_fallbacks. */
bool wk_polygon_is_reflex_counted(wk_run *R, const wk_polygon *P, uint32_t i);

/* ----------------------------------------------------------- predicates */

/* Sign of the orientation of (a, b, c): +1 left turn (counter-clockwise),
** -1 right turn, 0 collinear.  Exact (float filter, expansion fallback).
** *exact_used (may be NULL) is set to true when the exact stage ran. */
int wk_orient2d(wk_point a, wk_point b, wk_point c, bool *exact_used);
/* Lexicographic order on (x, y): -1, 0, +1; exact (no arithmetic). */
int wk_point_lex_cmp(wk_point p, wk_point q);
/* Unfiltered double evaluation, for benchmarks and tests only. */
int wk_orient2d_fast(wk_point a, wk_point b, wk_point c);

/* Twice the signed area of the closed polygon p[0..n) (the shoelace sum),
** evaluated exactly with expansion arithmetic and rounded once at the end:
** the sign is always right (assuming no overflow or underflow in the
** products) and the value is within a few ulps. */
double wk_shoelace_exact(const wk_point *p, uint32_t n);

/* How two closed segments [a, b] and [c, d] meet, decided exactly (built on
** wk_orient2d).  TOUCH: they share exactly one point, which is an endpoint of
** at least one of them (or a segment is a single point); CROSS: they share
** one point interior to both; OVERLAP: collinear, sharing a segment of
** positive length. */
typedef enum wk_seg_meet {
    WK_SEG_DISJOINT = 0,
    WK_SEG_CROSS,
    WK_SEG_TOUCH,
    WK_SEG_OVERLAP
} wk_seg_meet;
wk_seg_meet wk_segments_meet(wk_point a, wk_point b, wk_point c, wk_point d);
/* wk_segments_meet, also setting *exact_stages (may be NULL) to how many of
** its four orientation tests ran the exact stage, for callers that count
** exact_fallbacks (the predicates know no run). */
wk_seg_meet wk_segments_meet_ex(wk_point a, wk_point b, wk_point c, wk_point d,
                                uint32_t *exact_stages);
/* True if the closed segments [a, b] and [c, d] share a point (exact). */
bool wk_segments_intersect(wk_point a, wk_point b, wk_point c, wk_point d);

/* wk_orient2d and wk_segments_meet for callers that have a run: each
** orientation test that needed the exact stage counts 1 on
** WK_COUNTER_exact_fallbacks. */
/* wk_orient2d's float filter (its first stage, the same bound and the same
** decisions), inline: the counted callers are the validator's and the
** variants' inner loops (point-in-polygon crossing counts), where the call
** cost more than the filter.  The exact stage is wk_orient2d's. */
#define WK_ORIENT2D_ERRBOUND_A ((3.0 + 8.0 * DBL_EPSILON) * (0.5 * DBL_EPSILON))
static inline int wk_orient2d_counted(wk_run *R, wk_point a, wk_point b, wk_point c) {
    double detleft = (a.x - c.x) * (b.y - c.y);
    double detright = (a.y - c.y) * (b.x - c.x);
    double det = detleft - detright;
    double detsum = (detleft < 0 ? -detleft : detleft) + (detright < 0 ? -detright : detright);
    if (det >= WK_ORIENT2D_ERRBOUND_A * detsum || -det >= WK_ORIENT2D_ERRBOUND_A * detsum)
        return (det > 0) - (det < 0);
    bool exact;
    int o = wk_orient2d(a, b, c, &exact);
    if (exact) wk_count(R, WK_COUNTER_exact_fallbacks, 1);
    return o;
}
static inline wk_seg_meet wk_segments_meet_counted(wk_run *R, wk_point a, wk_point b, wk_point c,
                                                   wk_point d) {
    uint32_t exact;
    wk_seg_meet m = wk_segments_meet_ex(a, b, c, d, &exact);
    if (exact) wk_count(R, WK_COUNTER_exact_fallbacks, exact);
    return m;
}

/* ------------------------------------------------------------- skeleton */

typedef struct wk_node { double x, y, t; } wk_node;
/* left/right: input edges (stored numbering).  Only a skeleton cut at a
** height (wk_options.height) has arcs with WK_NONE on one side: the cap,
** the wavefront at t = height, whose face is no edge's. */
typedef struct wk_arc { uint32_t a, b, left, right; } wk_arc;

typedef struct wk_skeleton {
    uint32_t n_input;        /* the first n_input nodes are the input vertices */
    uint32_t n_nodes, cap_nodes;
    uint32_t n_arcs, cap_arcs;
    wk_node *nodes;
    wk_arc *arcs;
    double horizon;          /* a PSLG's skeleton: the time horizon T (its cap,
                                the wavefront at T, has arcs with WK_NONE on
                                the left); 0 otherwise */
    uint32_t cap_hint;       /* nodes and arcs grow with this hint
                                (WK_GROW_HINT; 0: none) */
} wk_skeleton;

/* New skeleton whose first P->n nodes are P's vertices at t = 0. */
wk_status wk_skeleton_new(wk_run *R, const wk_polygon *P, wk_skeleton **out);
/* Append a node; *id receives its index. */
wk_status wk_skeleton_add_node(wk_run *R, wk_skeleton *S, double x, double y, double t,
                               uint32_t *id);
wk_status wk_skeleton_add_arc(wk_run *R, wk_skeleton *S, uint32_t a, uint32_t b,
                              uint32_t left, uint32_t right);
void wk_skeleton_free(wk_run *R, wk_skeleton *S);
/* Remove interior nodes of degree 2 whose two arcs separate the same two
** faces the same way (one wavefront vertex that was replaced by an identical
** one during a group of simultaneous events): the two arcs become one.
** Keeps node and arc order otherwise (deterministic). */
wk_status wk_skeleton_merge_pass_through(wk_run *R, wk_skeleton *S);

/* ------------------------------------------------------------ tolerance */

/* The one tolerance policy is tolerance.h (WK_TOL_REL and the others);
** scale is the diagonal of the polygon's bounding box. */
double wk_polygon_scale(const wk_polygon *P);
/* The polygon's bounding box. */
void wk_polygon_bbox(const wk_polygon *P, wk_point *lo, wk_point *hi);
/* Euclidean distance from point a to input edge e (the closed segment). */
double wk_polygon_edge_distance(const wk_polygon *P, uint32_t e, wk_point a);

/* ------------------------------------------------------------ validator */

/* Read a wskel-1 JSON skeleton (write_json.c's format, input numbering) of
** polygon P from the file at path, into stored numbering, for wk_validate
** (engine/skeleton_read.c).  Only decodes: the properties are the
** validator's.  WK_EINPUT naming the file for what is no such skeleton of P
** (see the file); *out NULL on failure, else freed with wk_skeleton_free. */
wk_status wk_skeleton_read_json(wk_run *R, const wk_polygon *P, const char *path,
                                wk_skeleton **out);

typedef struct wk_validate_report {
    uint32_t nodes, arcs, faces;
    double max_distance_error; /* worst |dist(node, line e) - w(e) t| */
    double area_error;         /* |sum of face areas - polygon area| */
} wk_validate_report;

/* Check S against P (see engine/validate.c for the list of properties).
** tol: absolute distance tolerance; <= 0 selects the default
** (1e-6 * scale).  Returns WK_OK or WK_EINVALID with the first violated
** property in R->err.  rep may be NULL. */
wk_status wk_validate(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                      wk_validate_report *rep);
/* The checks for weights of any sign and for a skeleton cut at a height
** (engine/validate_general.c says what they prove and what they cannot with
** overhangs); wk_validate takes this path by itself when R->opt.height > 0
** or a weight is <= 0.  area_error is not computed (0). */
wk_status wk_validate_general(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                              wk_validate_report *rep);
/* The checks for a PSLG's skeleton up to its horizon (engine/validate_pslg.c
** says what they prove); wk_validate takes this path by itself when P->pslg.
** area_error: |sum of face areas - area swept by the horizon|. */
wk_status wk_validate_pslg(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                           wk_validate_report *rep);

/* -------------------------------------------------------------- writers */

typedef struct wk_run_info {
    const char *variant;
    uint32_t k;              /* WK_NONE: not applicable ("k":null) */
    double time_s;           /* construction time */
    size_t peak_bytes;       /* peak tracked bytes of the construction */
    const wk_counters *counters; /* NULL: no counters in the stats */
    const wk_variant *counters_of; /* whose counters (NULL: the engine's only) */
} wk_run_info;

wk_status wk_write_json(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S,
                        const wk_run_info *info);
wk_status wk_write_text(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S);
/* offsets: times at which to draw offset curves (may be NULL / 0). */
wk_status wk_write_svg(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S,
                       const double *offsets, uint32_t n_offsets);
wk_status wk_write_obj(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S);
wk_status wk_write_vtp(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S);
/* GIS formats (engine/write_gis.c): GeoJSON, one LineString Feature per arc
** with XYZ positions (t as Z) and properties a, b, left, right; WKT, one
** MULTILINESTRING Z line. */
wk_status wk_write_geojson(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S);
wk_status wk_write_wkt(wk_run *R, FILE *f, const wk_polygon *P, const wk_skeleton *S);

/* An output file that appears whole or not at all (see engine/output.c):
** open with a path (NULL: stdout), write to o.f, then close with the status
** of the writing; on failure the partial file is removed.  close returns
** the final status (a flush, close or rename failure is WK_EALGO). */
typedef struct wk_output {
    FILE *f;
    const char *path;
    bool atomic;        /* written to tmp and renamed */
    char tmp[4096];
} wk_output;
wk_status wk_output_open(wk_run *R, wk_output *o, const char *path);
wk_status wk_output_close(wk_run *R, wk_output *o, wk_status st);

/* Faces: the boundary of edge e's face as a node cycle starting with the
** edge's two vertices (e, next(e), ..., back), islands bridged in (see
** engine/faces.h).  Used by the validator and the
** roof writers.  *cycle is allocated through R (free with WK_FREE_ARRAY
** using *len). */
wk_status wk_face_cycle(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t e,
                        uint32_t **cycle, uint32_t *len);

/* -------------------------------------------------------------- offsets */

/* The wavefront at time t as polygons with holes: the closure of
** {x in P : T(x) > t}, where T is the skeleton's roof (T(x) = d(x, e) / w(e)
** in edge e's face), i.e. each face cut by its edge's offset line at
** distance w(e) t (engine/offset.c).  Layout: component c's rings are
** polygon_start[c] .. polygon_start[c+1]), its first ring the outer one
** (counter-clockwise), then its holes (clockwise); ring k's vertices are
** p[ring_start[k] .. ring_start[k+1]), not closed (the first point is not
** repeated).  Times exactly at a node's time give the limit from above
** (t + 0): a node at time t counts as already passed, so what vanishes at t
** (an edge, a component) is gone, and where a split happens at t the two
** parts are two components touching at one point; repeated consecutive
** points are merged and rings left with fewer than 3 points or zero area
** dropped.  t = 0 gives P itself: P's region, its vertices exactly P's (a
** vertex between collinear edges is left out when the collinear rule
** removed one of the edges at t = 0: its face is empty).  Deterministic.
** A PSLG (P->pslg) has no region: its offset at t is the region the
** wavefront has swept by t, {x : T(x) < t} (a buffer of the graph), one
** polygon around each connected component, holes where a bounded face's
** wavefront is still alive; the limit from below (t = 0 gives no polygon,
** t = S->horizon the wavefront at the horizon, its cap); t past the
** horizon is WK_EUNSUPPORTED (the skeleton is not known there). */
typedef struct wk_offset_set {
    double t;
    uint32_t n_polygons;     /* connected components of the wavefront at t */
    uint32_t *polygon_start; /* n_polygons + 1 offsets into the rings: a component's first ring is
                                its outer ring (counter-clockwise), then its holes (clockwise) */
    uint32_t n_rings;
    uint32_t *ring_start;    /* n_rings + 1 offsets into p */
    wk_point *p;             /* ring vertices, rings not closed (first point not repeated) */
} wk_offset_set;
/* The offset of polygon P at time t >= 0 computed from its skeleton S (each face cut by its edge's
** offset line at t; weights respected: edge e's line is at distance w(e) t). Empty set when t is
** beyond the last node's time (or at it).  S must be P's finished skeleton (ids are checked:
** WK_EINVALID; a face whose crossings cannot be paired: WK_EALGO); t must be finite and >= 0
** (WK_EINPUT).  *out is owned by the caller (wk_offset_set_free); on failure it is NULL.
** O(arcs + m log m + H V) for m crossed arcs, H hole rings and V outer ring vertices. */
wk_status wk_offset(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double t,
                    wk_offset_set **out);
/* Accepts NULL. */
void wk_offset_set_free(wk_run *R, wk_offset_set *O);
/* Signed area of ring k of O (exact shoelace, rounded once). */
double wk_offset_ring_area(const wk_offset_set *O, uint32_t k);
/* Offsets as GIS formats (engine/write_gis.c): GeoJSON, a FeatureCollection
** with one MultiPolygon Feature per set, properties {"t": t}; WKT, one
** MULTIPOLYGON line per set (MULTIPOLYGON EMPTY when empty).  Rings closed. */
wk_status wk_write_offsets_geojson(wk_run *R, FILE *f, const wk_polygon *P,
                                   wk_offset_set *const *O, uint32_t n_sets);
wk_status wk_write_offsets_wkt(wk_run *R, FILE *f, wk_offset_set *const *O, uint32_t n_sets);

/* ------------------------------------------------------------- variants */

/* A variant is one algorithm (variants/<name>/); its struct is the
** interface a variant implements (engine/variant.h).  Here: what callers
** may ask of one. */
#define WK_VARIANT_WEIGHTS 1u /* handles unequal weights (without it: equal ones only, wk_solve refuses the rest) */
#define WK_VARIANT_USES_K 2u  /* the k option matters */
/* takes weights <= 0 (zero: a stationary edge, a wall; negative: an edge
** moving outward, an overhang) and --height (wk_options.height): the
** readers accept such weights only when R->opt.nonpositive_weights says the
** chosen variant has this flag */
#define WK_VARIANT_NONPOSITIVE_WEIGHTS 4u
/* takes PSLG input (wk_polygon.pslg); wk_solve refuses a PSLG for any
** other variant with WK_EUNSUPPORTED */
#define WK_VARIANT_PSLG 8u
const char *wk_variant_name(const wk_variant *V);
const char *wk_variant_summary(const wk_variant *V);
unsigned wk_variant_flags(const wk_variant *V); /* WK_VARIANT_* */
const char *wk_variant_phase(const wk_variant *V); /* its timed phase, or NULL */

/* The name of the first registered variant with all of `flags`, or NULL
** (messages that suggest a variant without the engine naming one). */
const char *wk_variant_with_flags(unsigned flags);
/* NULL-terminated registry lookup; NULL if unknown. */
const wk_variant *wk_variant_find(const char *name);
/* i-th registered variant, NULL past the end. */
const wk_variant *wk_variant_at(size_t i);
/* The reference variant (the oracle; a variant's fallback where its own
** algorithm cannot certify a result). */
const wk_variant *wk_variant_reference(void);
/* For a variant whose own algorithm gave up on P (or whose skeleton failed
** its check): clear R's error, count the variant's counter `counter` (its
** reference_fallbacks), and answer with the reference variant, validated.
** A right skeleton at the reference's cost, never a wrong one. */
wk_status wk_solve_by_reference(wk_run *R, const wk_polygon *P, uint32_t counter,
                                wk_skeleton **out);

/* Run a variant on P: resets the peak, times the construction.  On success
** *out is the skeleton (caller frees with wk_skeleton_free); time_s and
** peak_bytes (may be NULL) receive the construction's figures. */
wk_status wk_solve(wk_run *R, const wk_variant *V, const wk_polygon *P, wk_skeleton **out,
                   double *time_s, size_t *peak_bytes);
/* wk_solve, then wk_validate (tol as there; rep may be NULL).  When the
** variant fails (WK_EALGO) or its skeleton fails validation, the input is
** solved again with the simulation's tolerances WK_TOL_ESCALATE_STEP times
** coarser, up to WK_TOL_ESCALATE_MAX, then WK_TOL_ESCALATE_STEP times finer,
** down to WK_TOL_REFINE_MIN (tolerance.h): a skeleton feature at the scale
** of the tolerance that the fine tolerance split inconsistently is resolved
** at a coarser one, still far inside the validator's; features that a very
** fast vertex (a needle-sharp spike) sweeps past within one time tolerance
** are told apart at a finer one.  Returns
** the first valid skeleton, or the first attempt's failure.  time_s and
** peak_bytes cover all attempts (time summed, peak the largest); the
** counters add up over the attempts and tolerance_escalations counts the
** retries. */
wk_status wk_solve_checked(wk_run *R, const wk_variant *V, const wk_polygon *P, double tol,
                           wk_skeleton **out, double *time_s, size_t *peak_bytes,
                           wk_validate_report *rep);

#endif
