/*
** monotone.h: the data shared by the files of the monotone variant (001:
** Biedl, Held, Huber, Kaaser, Palfrader, weighted straight skeletons of
** monotone polygons), and its counters.  Only variants/monotone/ includes it.
**
** Pipeline (one file per step):
**   direction.c       find a direction d in which P is monotone, or refuse;
**   chain_skeleton.c  the skeleton of each chain extended by rays (edge
**                     collapses only, 001 Lemma 1), kept as traces;
**   merge.c           the merge chain M' (intersection of the two roofs,
**                     001 section 3) walked from v_w to v_e over the faces'
**                     walls;
**   assemble.c        the final skeleton: each chain's traces clipped to its
**                     side of M', plus M';
**   monotone.c        the variant entry.
**
** Frame.  Input coordinates are never changed.  Every point of the variant
** (nodes, traces, M', the offset lines) is relative to the origin o, the
** centre of P's bounding box (wk_polygon_centre, as the reference's
** wavefront has it): far from the origin the rounding of the absolute
** coordinates is far above eps_d (a polygon of size 1e-3 at 2.2e6: ulp
** 4.7e-10 against eps_d = 1.3e-12), near it p - o is exact for the
** polygon's vertices; the skeleton's nodes get o back (assemble.c).
** "East" is the sweep
** direction d (a unit vector), "north" is d rotated by +90 degrees; the
** lower chain runs counter-clockwise from the westmost vertex v_w to the
** eastmost v_e, the upper chain from v_e back to v_w.  Only d is rotated
** (001 section 6 asks for rotations; rotating the directions instead of the
** points keeps every construction on the input lines).
**
** Traces.  A chain's wavefront vertex between edges ein (before it,
** counter-clockwise) and eout moves from its start node to its end node;
** its trace is an arc with ein's face on the left and eout's on the right
** (the engine's convention).  A "flat" trace is an arc swept at one instant:
** the piece of an edge removed by the collinear rule, or two antiparallel
** pieces cancelling (vertical walls meeting in a non-strictly monotone
** chain); it runs from start along vel (a unit vector) and has t0 == t1.
** An infinite trace (end == WK_NONE) belongs to a vertex still alive when
** the chain's events ran out (the chain is extended by rays, so its
** skeleton is unbounded).
**
** Walls.  The face of chain edge e is swept by e's single wavefront piece
** (no splits in a monotone chain), so its slice at time t is one segment
** whose ends trace the face's left wall (traces with eout == e, face on
** their right) and right wall (traces with ein == e, face on their left).
** In creation order the traces of a wall form a polyline whose times never
** decrease: merge.c finds a level by binary search and walks from there.
*/
#ifndef WK_MONOTONE_H
#define WK_MONOTONE_H
#include "event_queue.h"
#include "kinetics.h"
#include "variant.h"

#define MONO_COUNTER_LIST(X)                                                                 \
    X(chain_edge_events_lower, "edge events in the lower chain's skeleton (also edge_events)") \
    X(chain_edge_events_upper, "edge events in the upper chain's skeleton (also edge_events)") \
    X(merge_chain_vertices, "vertices of the merge chain M'")                                 \
    X(merge_cells_visited, "wall traces the merge walk looked at (001's cells)")              \
    X(reference_fallbacks, "inputs handed to the reference variant (merge not certified)")

WK_VARIANT_COUNTER_ENUM(MONO_COUNTER_LIST)

/* The direction's tolerance is WK_MONO_DIR_TOL (tolerance.h, with its
** reason).  MONO_DIR_RUNS_MAX: at most this many separate ranges of good
** directions (widest first) are tried as sweep directions (direction.c);
** each try costs O(n).  One or two occur in practice (a range can be split
** only where it wraps around angle 0, or at single directions perpendicular
** to edges); the bound keeps a pathological input at O(n) tries. */
#define MONO_DIR_RUNS_MAX 16

/* Trace of one wavefront vertex of a chain (see the top). */
typedef struct mono_trace {
    wk_point p0;      /* position at t0 (its start node) */
    wk_point vel;     /* velocity (distance per time); flat: unit direction */
    double t0, t1;    /* start and end time; t1 = INFINITY if it never ends */
    uint32_t ein, eout; /* input edges (stored numbering) */
    uint32_t start, end; /* chain node ids; end == WK_NONE if infinite */
    uint32_t prev, next; /* wavefront neighbours while alive, WK_NONE at a ray */
    uint8_t alive, kind, flat, reflex;
    double ev_t;      /* candidate collapse time of the piece to next */
    wk_point ev_p;    /* and its place */
} mono_trace;

/* A node of a chain skeleton. */
typedef struct mono_node {
    wk_point p;
    double t;
    uint32_t input;   /* polygon vertex id if it is one, else WK_NONE */
} mono_node;

/* One chain: edges first, first+1, ..., first+m-1 (mod n), counter-clockwise;
** edge first is extended backwards and edge first+m-1 forwards to rays. */
typedef struct mono_chain {
    uint32_t first, m;
    mono_trace *v;
    uint32_t nv, cap_v;
    mono_node *node;
    uint32_t nn, cap_n;
    /* walls, CSR over local edge index k = 0..m-1: trace ids in creation
    ** order; lw: traces with eout == edge k, rw: with ein == edge k */
    uint32_t *lw_start, *lw, *rw_start, *rw;
    uint32_t n_lw, n_rw;
} mono_chain;

/* A node of the merge chain M'. */
typedef struct mono_mnode {
    wk_point p;
    double t;
    wk_point in_dir, out_dir; /* unit directions of M' arriving / leaving */
    uint8_t has_in, has_out;
    uint32_t sk;              /* skeleton node id */
} mono_mnode;

/* M' crosses trace `trace` of chain `chain` (0 lower, 1 upper) at merge node
** `mnode`, at parameter mu along the trace (0 at its start; distance along
** vel for infinite and flat traces, fraction of the segment otherwise). */
typedef struct mono_cross {
    uint32_t chain, trace, mnode;
    double mu;
} mono_cross;

/* An arc of M' between merge nodes, upper face left, lower face right. */
typedef struct mono_marc {
    uint32_t a, b, left, right;
} mono_marc;

/* Everything the variant builds; lives for one run. */
typedef struct mono {
    wk_run *R;
    const wk_polygon *P;
    wk_point o;             /* origin of the variant's frame (see the top) */
    wk_offset_line *L;      /* per edge, relative to o */
    wk_point d;             /* east (unit) */
    bool strict;            /* no edge is perpendicular to d */
    bool reversed;          /* d is the opposite of direction.c's choice */
    bool coplanar_later;    /* the merge failed entering a coplanar pair
                               from its later side (merge.c) */
    uint32_t vw, ve;        /* westmost / eastmost vertex (chain ends) */
    double eps_d, eps_t;    /* the engine's tolerance policy (tolerance.h) */
    mono_chain ch[2];       /* 0: lower, 1: upper */
    mono_mnode *mn;
    uint32_t n_mn, cap_mn;
    mono_cross *cr;
    uint32_t n_cr, cap_cr;
    mono_marc *ma;
    uint32_t n_ma, cap_ma;
} mono;

/* Input vertex i relative to the origin o. */
static inline wk_point wk_mono_vertex(const mono *M, uint32_t i) {
    return (wk_point){M->P->p[i].x - M->o.x, M->P->p[i].y - M->o.y};
}

/* direction.c: choose d (a unit vector) in which P is monotone, preferring a
** direction with no edge perpendicular to it (M->strict), and set M->d,
** M->strict, M->vw, M->ve.  WK_EUNSUPPORTED with a message naming a
** witness when P is monotone in no direction; WK_EALGO when the good
** directions are too narrow to use with doubles; WK_ENOMEM.
** O(n log n). */
wk_status wk_mono_direction(mono *M);
/* direction.c: after wk_mono_direction, sweep the other way: d = -d, with
** v_w, v_e and M->strict for it (monotone.c's second walk).  WK_EALGO if
** -d does not check out (it does whenever d does, up to rounding). */
wk_status wk_mono_direction_reverse(mono *M);

/* chain_skeleton.c: simulate chain c (0 lower, 1 upper) of M, filling
** M->ch[c] (traces, nodes, walls).  WK_EALGO if the chain's wavefront breaks
** a monotone chain's rules (which would mean a wrong direction or a
** degenerate case this variant does not handle); WK_ENOMEM. */
wk_status wk_mono_chain_build(mono *M, uint32_t c);
void wk_mono_chain_clear(wk_run *R, mono_chain *C);
/* Position of trace v at time t (clamped to its own time span). */
wk_point wk_mono_trace_at(const mono_trace *v, double t);
/* Local index of edge e in chain C, or WK_NONE if e is not in C. */
uint32_t wk_mono_chain_local(const mono *M, const mono_chain *C, uint32_t e);

/* merge.c: walk M' from v_w to v_e, filling M->mn, M->cr, M->ma.  WK_EALGO
** if the walk gets lost (no crossing found, too many steps). */
wk_status wk_mono_merge(mono *M);

/* assemble.c: build the skeleton from the clipped chain skeletons and M'
** (merge nodes get their skeleton ids here).  *out owned by the caller. */
wk_status wk_mono_assemble(mono *M, wk_skeleton **out);

#endif
