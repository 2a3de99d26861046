/*
** deforming.h: what the files of the deforming-polygon variant (paper 004)
** share: the deforming polygon (vertices on doubly linked cycles, each
** moving linearly from its birth), the events a step finds, and the
** counters.  See README.md for the algorithm, its invariants and its
** deviations from the paper.
**
** Invariants between steps (at the current time D->t):
**   - every alive vertex is on one cycle (prev/next agree, both alive);
**   - the piece a -> next(a) lies on the offset line of edge eout(a), and
**     eout(a) == ein(next(a));
**   - a vertex's position at time t is p0 + (t - t0) v (relative
**     coordinates, origin D->o); its motion never changes after its birth
**     (events end vertices and create new ones; only prev/next are
**     relinked, when a piece is cut);
**   - no event is earlier than D->t: every edge collapse and penetration up
**     to D->t has been resolved.
*/
#ifndef WK_DEFORMING_H
#define WK_DEFORMING_H
#include "kinetics.h"
#include "variant.h"

#define DF_COUNTER_LIST(X)                                                                        \
    X(steps, "predictor steps (time increments tried)")                                           \
    X(event_free_steps, "steps whose predicted polygon was admissible (no swap, no penetration)")  \
    X(corrections, "steps corrected back to the time of their earliest event")                    \
    X(edge_swaps, "edge collapses found by an edge swap")                                         \
    X(penetrations, "edge splits found by a vertex penetrating a piece")                          \
    X(merges, "parts of the wavefront joined by a vertex reaching a piece from the swept side")    \
    X(pair_tests, "vertex-piece pairs tested for penetration (after the grid)")                   \
    X(event_points, "points where events were resolved")                                          \
    X(reference_fallbacks, "inputs handed to the reference variant (own result not certified)")

WK_VARIANT_COUNTER_ENUM(DF_COUNTER_LIST)

typedef struct df_vertex {
    wk_point p0;      /* position at t0 (relative coordinates) */
    wk_point v;       /* velocity (distance per time) */
    double t0;        /* birth time */
    uint32_t ein;     /* input edge of the piece prev -> this */
    uint32_t eout;    /* input edge of the piece this -> next */
    uint32_t prev, next;
    uint32_t node;    /* skeleton node where it was born */
    uint8_t alive;
} df_vertex;

/* An event a step found: a collapse of the piece a -> next(a) (b unused),
** the penetration of vertex a through the piece b -> next(b) from the
** unswept side (the region between them closes: it splits), or a merge:
** vertex a reaching the piece b -> next(b) from the swept side (only with
** weights <= 0: the swept region between them closes, the unswept region
** joins; 004 Fig. 11b). */
typedef enum df_event_kind { DF_COLLAPSE = 0, DF_PENETRATION = 1, DF_MERGE = 2 } df_event_kind;
/* x: where the event happens (relative coordinates) when its time came
** from the input lines (wk_three_lines_meet; at_x set), else the resolution
** takes the vertices' places at the group's time. */
typedef struct df_event {
    double t;
    uint32_t kind, a, b;
    wk_point x;
    bool at_x;
} df_event;

typedef struct df_state {
    wk_run *R;
    const wk_polygon *P;
    wk_skeleton *S;
    wk_point o;           /* origin of the relative coordinates */
    wk_offset_line *L;    /* offset line of each input edge, relative */
    double eps_d;         /* distance tolerance (tolerance.h policy) */
    double eps_t;         /* events within this of the earliest are one group */
    double wmax;          /* largest |weight| (1 if every edge is a wall) */
    double t_vanish;      /* positive weights, no height: every vertex has
                             ended by then (0: no such bound) */
    bool nonpositive;     /* some weight is <= 0 */
    double t;             /* present */
    double dt;            /* the next step's increment (the step-size policy) */
    uint64_t last_tests;  /* penetration tests of the last step */
    double best;          /* the earliest event time found so far in a step */
    df_vertex *v;
    uint32_t nv, cap_v, n_alive;
    df_event *ev;
    uint32_t n_ev, cap_ev;
    /* per-vertex scratch (grown with v, entries reset after each use):
    ** the event point a vertex belongs to, marks on pieces */
    uint32_t *member, *mark;
    uint32_t cap_member, cap_mark;
    struct df_resolve_scratch *rs; /* resolve.c's growable arrays */
    /* step scratch: alive ids, grid */
    uint32_t *ids;
    uint32_t cap_ids;
    uint32_t *cell_start, *cell_items, *big, *stamp, *cell_mark;
    uint32_t cap_cell_start, cap_cell_items, cap_big, cap_stamp, cap_cell_mark;
} df_state;

static inline wk_point df_pos(const df_vertex *V, double t) {
    double d = t - V->t0;
    return (wk_point){V->p0.x + d * V->v.x, V->p0.y + d * V->v.y};
}

/* predict.c: one predictor step from D->t over D->dt.  Fills D->ev with the
** events up to the earliest one plus D->eps_t (none: the predicted polygon
** is admissible).  *t_event receives the earliest event's time. */
wk_status df_predict(df_state *D, double *t_event);
/* resolve.c: resolve every event of D->ev at time te (the corrector has
** moved the present there): cut, end and create vertices, write nodes and
** arcs.  WK_EALGO when the events do not form a configuration it can
** resolve (the caller then hands the input to the reference). */
wk_status df_resolve(df_state *D, double te);
/* resolve.c: the collinear rule at vertex x at time te (see there). */
wk_status df_collinear_rule(df_state *D, uint32_t x, double te, bool fresh);
/* resolve.c: free what df_resolve keeps between calls. */
void df_resolve_free(df_state *D);
/* deforming.c: a new alive vertex; *id receives it. */
wk_status df_add_vertex(df_state *D, const df_vertex *V, uint32_t *id);

#endif
