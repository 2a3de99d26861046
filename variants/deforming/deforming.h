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
#include "event_queue.h"
#include "kinetics.h"
#include "variant.h"

#define DF_COUNTER_LIST(X)                                                                        \
    X(steps, "predictor windows opened (every alive vertex predicted)")                           \
    X(event_free_steps, "windows that held no event (no swap, no penetration)")                   \
    X(corrections, "corrections to the time of an earliest event (groups resolved)")               \
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

/* Per-vertex state of the kinetic search (predict.c). */
typedef struct df_kin {
    uint32_t pver;  /* version of the piece this -> next (bumped when it changes) */
    uint32_t stamp; /* generation of the last query that saw it */
    uint32_t tnext; /* touched list (DF_TOUCH_END ends it; WK_NONE: not on it) */
    uint32_t inpath; /* generation of the window whose path grid holds it */
} df_kin;

/* An entry of a cell list: a piece (item = its start vertex, ver = its
** version then) or a vertex path (ver unused). */
typedef struct df_entry {
    uint32_t item, ver, next;
} df_entry;

/* The first window's length in grid cells (times --step): about the
** cells a path may cross before the queries' pair tests grow with it
** (star n = 3200: 2 cells 1.0 s, see README "Cost"). */
#define DF_WINDOW_CELLS 2.0

#define DF_TOUCH_END (WK_NONE - 1u)

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
    double dt;            /* the next window's length, in grid cells a vertex
                             of the mean speed crosses (the step-size policy) */
    double scale;         /* the input's size (wk_polygon_scale) */
    double dt_near;       /* 004's increment: the first, doubled after a
                             window without events, twice the time between
                             the last two groups after a group (near_root) */
    double best;          /* the earliest event time found so far (a query) */
    bool collect;         /* push_event keeps events (else only best) */
    df_vertex *v;
    uint32_t nv, cap_v, n_alive;
    df_event *ev;
    uint32_t n_ev, cap_ev;
    /* per-vertex scratch (grown with v, entries reset after each use):
    ** the event point a vertex belongs to, marks on pieces */
    uint32_t *member, *mark;
    uint32_t cap_member, cap_mark;
    struct df_resolve_scratch *rs; /* resolve.c's growable arrays */
    /* The kinetic search (predict.c): a window [t, T1] with a grid of the
    ** pieces' swept areas and the vertices' paths over it, and a queue of
    ** vertices keyed by a lower bound of their earliest event. */
    df_kin *k;
    uint32_t cap_k;
    wk_event_queue Q;
    bool window;          /* a window is open */
    double T1, t1;        /* its end; the search's end (eps_t past it) */
    uint32_t wgen;        /* generation of the window */
    uint32_t win_groups, win_alive; /* groups resolved in it; alive at its start */
    uint32_t touch_head;  /* vertices whose links or life changed (resolve.c) */
    uint32_t gen;         /* query generation (stamps, cell marks) */
    uint64_t tests;       /* pair tests not yet counted */
    uint32_t g;           /* cells a side */
    double gx0, gy0, gcw, gch, gcell;
    uint32_t *head_piece, *head_path, *cell_mark, *cl;
    uint32_t cap_head_piece, cap_head_path, cap_cell_mark, cap_cl, n_cl;
    df_entry *ent, *big_piece;
    uint32_t n_ent, cap_ent, n_big_piece, cap_big_piece;
    uint32_t *big_path, *popped, *tl, *near;
    uint32_t n_big_path, cap_big_path, n_popped, cap_popped, n_tl, cap_tl, n_near, cap_near;
} df_state;

/* x's links or life changed (resolve.c, df_add_vertex): the kinetic search
** re-predicts it and its piece after the resolution. */
static inline void df_touch(df_state *D, uint32_t x) {
    if (D->k[x].tnext != WK_NONE) return;
    D->k[x].tnext = D->touch_head;
    D->touch_head = x;
}

static inline wk_point df_pos(const df_vertex *V, double t) {
    double d = t - V->t0;
    return (wk_point){V->p0.x + d * V->v.x, V->p0.y + d * V->v.y};
}

/* predict.c: open a window at D->t of length D->dt: the grids, every alive
** vertex predicted and queued. */
wk_status df_window(df_state *D);
/* predict.c: the earliest group of events in the window into D->ev (the
** events up to the earliest one plus D->eps_t that have met then), *t_event
** its time; none (D->n_ev == 0): the window holds no more events. */
wk_status df_next_group(df_state *D, double *t_event);
/* predict.c: after df_resolve: re-predict what it touched and what the
** group's search took off the queue, enter the new pieces and paths. */
wk_status df_update(df_state *D);
/* predict.c: the alive vertices whose paths in the open window pass
** within r of X (into D->near, D->n_near; each once): the candidates of
** resolve.c's arrivals. */
wk_status df_vertices_near(df_state *D, wk_point X, double r);
/* predict.c: free the search's arrays. */
void df_predict_free(df_state *D);
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
