/*
** wavefront.h: the kinetic wavefront that the variants share (see
** wavefront.c for the model, the events and the resolution of simultaneous
** events).  A variant supplies a wk_split_finder: how a reflex vertex's
** split event is found (brute force, the bisector arrangement, a motorcycle
** graph).  Everything else (edge events, resolution of event groups, the
** collinear rule, the skeleton) is here, so variants differ only in what
** the papers make them differ in.
**
** Invariants between events: every alive vertex is in one cycle (prev/next
** agree); the piece a -> a.next of alive a lies on the offset line of
** v[a].eout; a vertex never changes after creation (events kill vertices and
** create new ones), so "piece (a, b) still exists" is "a alive and
** a.next == b".
*/
#ifndef WK_WAVEFRONT_H
#define WK_WAVEFRONT_H
#include "event_queue.h"
#include "kinetics.h"

/* candidate event kinds; the order breaks ties between simultaneous ones */
enum { WK_WF_NONE = 0, WK_WF_EDGE = 1, WK_WF_SPLIT = 2 };

typedef struct wk_wf_vertex {
    wk_point p0, vel;  /* position at t0 and velocity (distance per time) */
    double t0;         /* creation time */
    uint32_t prev, next;
    uint32_t ein, eout;/* input edges before / after (stored numbering) */
    uint32_t node;     /* skeleton node where it started */
    uint8_t alive, reflex, vkind;
    uint8_t fresh;     /* created in the current group, candidate not yet computed */
    uint32_t cand_next;/* next when the candidate was computed */
    uint8_t ev_kind;   /* candidate event */
    double ev_t;
    wk_point ev_p;
    uint32_t ev_a, ev_b; /* edge event: ev_b = next; split: target piece a->b */
    uint32_t at;       /* group scratch: node index or WK_NONE */
    uint32_t seen;     /* group scratch: stamp of the last cycle walk */
    uint32_t cyc;      /* group scratch: index of its cycle among the touched ones */
} wk_wf_vertex;

typedef struct wk_wf_cluster {
    wk_point p;
    uint32_t sk;       /* skeleton node id, WK_NONE until committed */
    uint32_t first, count; /* its sub-pieces' slots in the pairing arrays */
    uint32_t arrive, reflex, pinches, pairs; /* for the counters */
} wk_wf_cluster;

typedef struct wk_wf_pinch { uint32_t piece; double s; uint32_t node; } wk_wf_pinch;

typedef struct wk_wf_sub {
    uint32_t from, to;   /* point: node index | NODE_BIT, or a vertex id */
    uint32_t edge;       /* input edge whose offset line carries it */
    uint32_t pair_in;    /* index of the pair using it as incoming */
    uint32_t pair_out;   /* ... as outgoing */
    uint8_t dead;        /* 1: gone (collapsed or folded), 2: cancelled, leaves an arc */
} wk_wf_sub;

typedef struct wk_wf_pair { uint32_t in, out, node, vertex; } wk_wf_pair;

#define NODE_BIT 0x80000000u
#define IS_NODE(p) (((p) & NODE_BIT) != 0)
#define NODE_OF(p) ((p) & ~NODE_BIT)

typedef struct wk_wavefront wk_wavefront;

struct wk_wavefront {
    wk_run *R;
    const wk_polygon *P;
    wk_skeleton *S;
    wk_offset_line *L;
    wk_wf_vertex *v;
    uint32_t nv, cap_v;
    wk_event_queue Q;
    double eps_d, eps_t, t_now;
    wk_point origin;   /* all positions are relative to it (bounding-box centre) */
    uint32_t stamp;
    /* group scratch, kept between groups */
    uint32_t *seeds; uint32_t n_seeds, cap_seeds;
    uint32_t *forced; uint32_t n_forced, cap_forced;
    uint32_t *comp; uint32_t n_comp, cap_comp;
    wk_wf_cluster *cl; uint32_t n_cl, cap_cl;
    wk_wf_pinch *pin; uint32_t n_pin, cap_pin;
    wk_wf_sub *sub; uint32_t n_sub, cap_sub;
    wk_wf_pair *pair; uint32_t n_pair, cap_pair;
    uint32_t *slot; uint32_t n_slot, cap_slot;
    uint32_t *fresh; uint32_t n_fresh, cap_fresh;
    uint32_t *dead; uint32_t n_dead, cap_dead; /* vertices ended in this group */
    bool local_open;   /* this group looked at part of one cycle only */
    uint8_t *cycflag; uint32_t n_cyc, cap_cycflag;
    uint32_t *run, *run_node; uint32_t n_run, cap_run, cap_run_node; /* collinear runs */
    const struct wk_split_finder *finder; /* how split events are found */
    void *finder_ud;
};


/* How split events are found.  Hooks receive the finder's ud first.
** full: a fresh reflex vertex v, or one whose target piece disappeared;
**   offer its earliest split with wk_wavefront_offer_split (edge event
**   already set in v).
** incremental: v's target piece still exists; only pieces next to the
**   vertices in W->fresh are new.
** start (may be NULL): after the initial wavefront exists, before the first
**   candidates are computed.
** after_group (may be NULL): after a group of simultaneous events was
**   resolved (W->fresh lists the new and relinked vertices), before
**   candidates are refreshed.
** next_time / process_next (may be NULL): the finder's own events (e.g.
**   arrangement start and switch events), processed before any wavefront
**   event that is not earlier; process_next may call
**   wk_wavefront_reschedule for vertices whose split candidate moved. */
typedef struct wk_split_finder {
    void (*full)(void *ud, wk_wavefront *W, uint32_t v);
    void (*incremental)(void *ud, wk_wavefront *W, uint32_t v);
    wk_status (*start)(void *ud, wk_wavefront *W);
    wk_status (*after_group)(void *ud, wk_wavefront *W, double t);
    double (*next_time)(void *ud);
    wk_status (*process_next)(void *ud, wk_wavefront *W);
    bool local_refresh; /* candidates need no walk over the touched cycles:
                           the finder reschedules what it changes */
} wk_split_finder;


/* Run the simulation on P with the given finder; on success *out is the
** skeleton (caller frees).  No skeleton on failure. */
wk_status wk_wavefront_run(wk_run *R, const wk_polygon *P, const wk_split_finder *finder,
                           void *finder_ud, wk_skeleton **out);

/* Position of vertex v at time t (relative to W->origin). */
static inline wk_point wk_wf_pos(const wk_wf_vertex *v, double t) {
    double dt = t - v->t0;
    return (wk_point){v->p0.x + v->vel.x * dt, v->p0.y + v->vel.y * dt};
}

/* Does reflex vertex vi hit piece a -> a.next (within its extent) before
** *best?  If so, *best, *bp and the target (*ta, *tb) are updated. */
void wk_wavefront_split_test(wk_wavefront *W, uint32_t vi, uint32_t a, double *best,
                             wk_point *bp, uint32_t *ta, uint32_t *tb);
/* The brute-force split search: vi against every piece of its cycle, O(cycle). */
void wk_wavefront_split_scan(wk_wavefront *W, uint32_t vi);
/* Offer vi a split with piece a -> b at time t and point p; kept if earlier
** than its current candidate. */
void wk_wavefront_offer_split(wk_wavefront *W, uint32_t vi, double t, wk_point p, uint32_t a,
                              uint32_t b);
/* Recompute vi's candidate (edge event plus the finder's split) and queue it. */
wk_status wk_wavefront_reschedule(wk_wavefront *W, uint32_t vi);
/* True if the piece vi's candidate refers to still exists. */
bool wk_wavefront_target_alive(const wk_wavefront *W, const wk_wf_vertex *V);

#endif
