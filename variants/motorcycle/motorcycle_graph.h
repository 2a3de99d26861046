/*
** motorcycle_graph.h: the motorcycle graph M(P) of a polygon with holes
** (002, section 2), the input of the motorcycle variant's wavefront: every
** reflex edge of the straight skeleton lies on a motorcycle trace (002,
** Theorem 1), and the points where traces end on other traces are the
** resting Steiner vertices of 002, section 3.
**
** Model
** -----
** Coordinates are relative to c = wk_polygon_centre(P) (stored in the
** graph).  One motorcycle per reflex vertex v of P (wk_polygon_is_reflex,
** exact), in increasing vertex order: it starts at o = P->p[v] - c and moves
** with the velocity of the wavefront vertex at v, i.e. wk_vertex_velocity of
** the offset lines (wk_offset_line_of_edge_at, relative to c) of the edges
** prev(v) -> v and v -> next(v); weighted when P is.  u is its unit
** direction, speed = |velocity|, and it reaches distance d along u at time
** tau(d) = d / speed.  Degenerate vertices: a zero-width spike
** (WK_VEL_ANTIPARALLEL) runs along the spike, and a reflex vertex between
** edges parallel below WK_PARALLEL_SIN runs along the mean normal; both
** have speed INFINITY, so tau = 0 on all of their trace.
**
** PSLGs (P->pslg, engine/pslg.c: rings are the face cycles of the
** half-edges): a motorcycle per reflex corner, and a corner next to a cap
** is reflex (so two per terminal, 002); motorcycles with one origin (a
** terminal's two) never meet there; a segment is two walls at one place and
** a ray's wall is the half-edge it reaches from its left; a ray that meets
** no wall escapes (wk_motorcycle_escapes): wall_len is the distance it
** covers until the wavefront takes no more events, with a margin.
**
** Walls are all edges of all rings.  Each motorcycle's ray is first shot
** against them (engine/ray_shoot.h, first boundary point, its own two edges
** ignored; a vertex within the shooter's tol of the ray is hit as that
** vertex): wall_len, wall_edge / wall_vertex.  Its trace is then the
** segment o .. o + len u, len <= wall_len, where it crashes.
**
** Tolerances: eps_d = WK_TOL_REL * wk_polygon_scale(P) and
** eps_t = WK_TOL_TIME * eps_d / wmax (tolerance.h; both times
** R->opt.tol_scale when that is > 0).  The wall tolerance is the shooter's
** (WK_TOL_REL * the same diagonal).
**
** Crash rules
** -----------
** Candidates: two motorcycles i < j meet at x where their bounding segments
** (o .. o + wall_len u) cross, with distances d_i, d_j along them, accepted
** up to eps_d beyond a segment's ends and then clamped to [0, wall_len];
** non-parallel lines meet at their crossing; parallel ones (|u_i x u_j| <=
** WK_MCG_PARALLEL_SIN) only when collinear within eps_d: head-on at the
** point they reach at the same time (d_i / s_i = d_j / s_j, i.e. midway
** for equal speeds), one behind the other at the front one's origin.  x is
** a function of (i, j) alone (always computed with the smaller id first).
**
** Arrival times t_i = tau_i(d_i), t_j = tau_j(d_j).  Events are processed
** in the order of T = max(t_i, t_j), ties broken by (i, j); a motorcycle is
** "alive" until a crash is recorded for it.  At an event:
**   - sequential (|t_i - t_j| > eps_t): the earlier one w is the winner, the
**     later one l the loser.  l crashes into w's trace at x (TRACE, other w,
**     other_len d_w) if l is alive, w reached x (alive, or crashed at
**     len_w >= d_w - eps_d), and x is not l's wall point (d_l <
**     wall_len_l - eps_d: there the WALL crash wins, so a trace ending on the
**     boundary is never a resting Steiner vertex).  Otherwise nothing.
**   - simultaneous (|t_i - t_j| <= eps_t): for each of the two, "at x"
**     means crashed with |len - d| <= eps_d, "before" crashed with
**     len < d - eps_d, "beyond" crashed with len > d + eps_d.
**       either before: nothing (they never met there);
**       both alive: both crash at x, a new SIMULTANEOUS group at x;
**       each alive or at x: the alive ones crash at x and both end in one
**         group (a crash at x of another kind becomes SIMULTANEOUS, its
**         wall or trace kept as the group's `on`; two groups merge, the
**         older surviving);
**       one beyond (it crashed later, past x, the event that stopped it
**         came first within the time window): an alive other crashes into
**         its trace (TRACE), as in the sequential case; else nothing.
**   A motorcycle reaching a point where traces end (a crash point of
**   others) after them crashes there into one of those traces; at the same
**   time (within eps_t) it joins their group.  A regular star's k reflex
**   vertices all meet at the centre: one group of k.
**   - a motorcycle still alive at the end crashes into its wall (WALL, at
**     wall_len).
** Ids break every tie and each pair gives at most one event, so the result
** is deterministic, and the grid build and the brute-force twin process
** the same state-changing events in the same order: identical graphs
** (field by field, bit for bit; only candidate_pairs differs).
**
** Algorithm (wk_motorcycle_graph_build)
** --------------------------------------
** Bounding segments from the ray shooter (expected O(1 + cells) per ray),
** then a time-ordered simulation over a uniform grid of about one cell per
** ten motorcycles (up to 16 times more when the origins are clustered, see
** MCG_CELLS_PER_MOTORCYCLE and MCG_REFINE_OCCUPANCY in the .c; 0.03 per
** motorcycle when they are spread, MCG_CELLS_PER_MOTORCYCLE_SPREAD; a
** refined grid that makes more than 40 listings per motorcycle (long
** traces across the box) is dropped and the simulation starts again unrefined,
** MCG_REFINED_LISTINGS_MAX): each motorcycle lists itself in the cells within
** WK_MCG_GRID_DELTA * eps_d of its bounding segment, slab by slab along the
** segment's major axis, each slab at the time it comes within that distance
** (a registration event in the same heap); a motorcycle that has crashed
** lists itself no further.  On listing itself in a cell it tests the
** motorcycles already there (candidate_pairs counts the crossings
** computed), and pushes the pair's event when the crossing x lies in that
** cell (so each pair once), unless the listed one has already crashed
** before x (len < d - eps_d: the event would be a no-op whenever it came,
** as a crash length is final), or x lies more than 2 eps_d beyond the
** crash bound of either: the distance of a "sure" crash of that
** motorcycle found by any earlier pair test (into a crashed trace that
** reached the crossing more than eps_t earlier, not at its wall point: the
** sequential rule crashes it there if nothing did before), so its trace
** ends no later.  A cell's listing keeps the trace's line rounded to floats
** in the cell's frame (20 bytes), and a scan passes a pair to that test
** (candidate_pairs counts these) only when the rounded crossing, widened by
** a bound on the rounding, could lie in the cell while the listed one is
** alive, or could lie before the listed one's crash point and the new
** one's bound (short_skip in the .c; the other pairs are no-ops: star
** 10^5 16.6M -> 1.0M pairs on the same grid, the same events).  A pair that meets at x is
** listed in x's
** cell by both before the event's time (the listing runs at least 3 eps_d
** ahead of any crash that could matter there), so no valid event is
** missed.  A cell keeps its motorcycles' ids in one array (the data a
** crossing needs in one compact array by id); once it lists 64 or more
** (and again each time that count doubles; not in the outer cells, where
** grid_index clamps) it also indexes their lines by canonical angle th in [0, pi) and
** signed offset h of the cell's centre C (about sqrt(k) angle bins by
** 4 sqrt(k) offset bins; each angle bin keeps the range of its occupied
** offset bins, so a scan never reads the empty buckets: in a hub, whose
** lines all pass near one point, those were most of the 4k buckets read per
** listing), and a new motorcycle tests only the lines that
** can cross its own in the cell's disk (C, rho): two lines meet at
** distance r from C only if |h_i - h_j cos D| <= r |sin D| (D = th_j -
** th_i), so an angle bin whose D range misses +-pi/2 is searched only over
** the offset bins that the four bounds of h_j allow, widened by sigma =
** 1e-9 of the box + 4 eps_d (far above the rounding of a computed crossing
** times |sin D|, ~1e-16 of the box).  That skips the near-parallel spokes
** that share the cells of a hub without crossing there, and only those:
** every pair whose computed crossing lies in the cell is still tested.
** Cost O((n + M + K) log n) for M cells crossed by the final traces (plus
** one slab each) and K pairs tested: near n log n when traces are short
** against the cell size (comb, rectilinear, spiral: 0.1 s at n = 10^5, 1 s
** at 10^6).  The star and random families' needle notches send ~r/2 fast
** motorcycles radially into a hub at the centre; without the index K ~
** r^2 / 8 (star n = 10^5: 194M pairs, 20 s), with it K ~ r^1.5 (43M, 4.6 s
** of which 1.3 s is the ray shooting).  A crowded cell's scan also visits
** its angle bins outwards from the new line's and skips a bin when every
** crossing with its lines lies beyond the new motorcycle's crash bound
** (two lines at distances h_i, h_j from a point P cross within
** 2 max(h_i, h_j) / |sin D| of it; P the least-squares point of the cell's
** lines, the hub): star 10^5 43M -> 21M pairs, the centre cell's 19.0M ->
** 0.8M, the same graph (the hub's pairs were tested against the line
** extensions of traces that crashed inside the cell: of its 19.6M
** line-in-disk pairs only 0.8M met a trace before its crash point).  What
** remains is the annulus: long near-radial traces listed in about sqrt(r)
** cells each (r^1.5 listings), see the variant's README, Cost.
** wk_motorcycle_graph_build_brute tests all pairs up front.
*/
#ifndef WK_MOTORCYCLE_GRAPH_H
#define WK_MOTORCYCLE_GRAPH_H
#include <math.h>

#include "kinetics.h"
#include "wskel.h"

typedef enum wk_motorcycle_crash {
    WK_MCG_WALL = 0,     /* into wall_edge / wall_vertex at len = wall_len */
    WK_MCG_TRACE,        /* into the trace of `other`, at other_len along it */
    WK_MCG_SIMULTANEOUS  /* with the others of `group`, at the group's point */
} wk_motorcycle_crash;

/* One motorcycle (88 bytes on 64-bit). */
typedef struct wk_motorcycle {
    wk_point o;           /* start: the reflex vertex, relative to the centre */
    wk_point u;           /* unit direction */
    double speed;         /* distance per unit time, > 0; INFINITY for the
                             degenerate vertices (see Model) */
    double len;           /* crash distance along u: crash point o + len u,
                             crash time len / speed (0 when INFINITY) */
    double wall_len;      /* distance to the first wall along the ray
                             (>= len); 0 for a ray that starts within tol of
                             another edge (a tiny edge next to the vertex) */
    double other_len;     /* TRACE: distance along other's u of the crash
                             point; else 0 */
    uint32_t vertex;      /* the reflex vertex of P (stored numbering) */
    uint32_t wall_edge;   /* the edge the ray hits in its interior, or WK_NONE */
    uint32_t wall_vertex; /* the vertex the ray hits, or WK_NONE (one of the
                             two is set) */
    wk_motorcycle_crash kind;
    uint32_t other;       /* TRACE: the motorcycle crashed into; else WK_NONE */
    uint32_t group;       /* SIMULTANEOUS: index into groups; else WK_NONE */
} wk_motorcycle;

/* Motorcycles that crashed together (>= 2 members). */
typedef struct wk_motorcycle_group {
    wk_point p;           /* the shared crash point (of the event that made
                             the group) */
    double t;             /* its time: the max arrival time of that event */
    uint32_t first;       /* members: group_members[first .. first + count), */
    uint32_t count;       /* increasing ids */
    uint32_t on_other;    /* the trace the point lies on, when a member had
                             crashed into it before joining; else WK_NONE */
    double on_len;        /* distance along on_other's u; else 0 */
    uint32_t on_edge;     /* the wall the point lies on (a member's wall hit */
    uint32_t on_vertex;   /* within eps_d), else both WK_NONE */
} wk_motorcycle_group;

/* A point on a motorcycle's trace where another's trace ends. */
typedef struct wk_motorcycle_steiner {
    double d;             /* distance along the trace's u */
    uint32_t other;       /* the motorcycle whose trace ends there */
} wk_motorcycle_steiner;

/* Counts of one build (for the caller's counters). */
typedef struct wk_motorcycle_stats {
    uint64_t motorcycles;
    uint64_t wall_crashes;
    uint64_t trace_crashes;
    uint64_t simultaneous_groups;
    uint64_t simultaneous_motorcycles; /* members over all groups */
    uint64_t candidate_pairs;          /* pairs whose crossing was computed
                                          (over both runs after a restart) */
} wk_motorcycle_stats;

typedef struct wk_motorcycle_graph {
    wk_point centre;       /* wk_polygon_centre(P): the frame of all points */
    double eps_d, eps_t;   /* the tolerances used (distance, time) */
    uint32_t n;            /* motorcycles = reflex vertices of P */
    wk_motorcycle *m;      /* n, by increasing vertex */
    uint32_t n_groups;
    wk_motorcycle_group *groups;  /* n_groups, in order of creation */
    uint32_t n_group_members;
    uint32_t *group_members;      /* n_group_members */
    /* Resting Steiner vertices, CSR: steiner[steiner_start[i] ..
    ** steiner_start[i + 1]) are the points of motorcycle i's trace where
    ** others' traces end, sorted by (d, other): every k with TRACE into i
    ** (d = k.other_len), every member k of a group lying on i's trace
    ** (d = on_len), and, when i is in a group, its other members
    ** (d = i.len). */
    uint32_t *steiner_start;      /* n + 1 */
    uint32_t n_steiner;
    wk_motorcycle_steiner *steiner; /* n_steiner */
    wk_motorcycle_stats stats;
} wk_motorcycle_graph;

/* A PSLG's motorcycle whose ray meets no wall (the outer face): its
** trace ends where the wavefront takes no more events (motorcycle_graph.c,
** escape_len), a WALL crash with neither wall edge nor wall vertex. */
static inline bool wk_motorcycle_escapes(const wk_motorcycle *m) {
    return m->wall_edge == WK_NONE && m->wall_vertex == WK_NONE;
}

/* Crash point and time of m. */
static inline wk_point wk_motorcycle_crash_point(const wk_motorcycle *m) {
    return (wk_point){m->o.x + m->len * m->u.x, m->o.y + m->len * m->u.y};
}
static inline double wk_motorcycle_time_at(const wk_motorcycle *m, double d) {
    return m->speed == INFINITY ? 0.0 : d / m->speed;
}

/* M(P) by the grid simulation (see the design above).  On success *out is
** the caller's (wk_motorcycle_graph_free); on failure (WK_ENOMEM, WK_EALGO
** for a ray that meets no wall) *out is NULL and nothing is left allocated.
** P is only read. */
wk_status wk_motorcycle_graph_build(wk_run *R, const wk_polygon *P, wk_motorcycle_graph **out);
/* The same graph from all O(r^2) candidate pairs (tests): identical to
** wk_motorcycle_graph_build except stats.candidate_pairs. */
wk_status wk_motorcycle_graph_build_brute(wk_run *R, const wk_polygon *P,
                                          wk_motorcycle_graph **out);
/* Accepts NULL. */
void wk_motorcycle_graph_free(wk_run *R, wk_motorcycle_graph *G);

/* Consistency of G against P (tests and debug builds; O(n + r + groups),
** no allocation): every motorcycle starts at its reflex vertex, len <=
** wall_len; a WALL crash point lies on its wall, a TRACE crash point on the
** other's trace (which reached it no later, within eps_t), a SIMULTANEOUS
** one at its group's point at the group's time (WK_MCG_CHECK_SLACK), the
** groups and Steiner lists match the crash records.  False with the first
** failure in why. */
bool wk_motorcycle_graph_check(const wk_motorcycle_graph *G, const wk_polygon *P, char *why,
                               size_t size);
/* True if A and B are the same graph field by field (bit for bit),
** stats.candidate_pairs excepted; else false with the first difference. */
bool wk_motorcycle_graph_same(const wk_motorcycle_graph *A, const wk_motorcycle_graph *B,
                              char *why, size_t size);

#endif
