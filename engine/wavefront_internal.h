/*
** wavefront_internal.h: the wavefront's own state, shared by wavefront.c
** (model, candidates, simulation, the finder interface) and
** wavefront_group.c (resolution of a group of simultaneous events).  Not
** for variants: they see the wavefront through wavefront.h only.
**
** Invariants between events: every alive vertex is in one cycle (prev/next
** agree); the piece a -> a.next of alive a lies on the offset line of
** v[a].eout; a vertex never changes after creation (events kill vertices and
** create new ones), so "piece (a, b) still exists" is "a alive and
** a.next == b"; every alive vertex with a finite candidate is queued under
** its id with that candidate's time.
*/
#ifndef WK_WAVEFRONT_INTERNAL_H
#define WK_WAVEFRONT_INTERNAL_H
#include "wavefront.h"
#include "point_grid.h"

#define TWO_PI 6.283185307179586476925286766559

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
    uint8_t gap_made;  /* made at a node that resolved a gap between rings on
                          the input's side (wavefront_group.c, bystander);
                          here, in ev_kind's padding: a byte more elsewhere
                          grew the vertex by 8 bytes (make regress: peak
                          tracked bytes +3.7%) */
    uint8_t forced;    /* group scratch: in W->forced (wf_force; cleared by
                          plan_rounds), so that plan_arrivals asks in O(1),
                          not by a scan of the list per vertex; in the same
                          padding (the vertex stays 120 bytes) */
    double ev_t;
    wk_point ev_p;
    uint32_t ev_a, ev_b; /* edge event: ev_b = next; split: target piece a->b */
    uint32_t at;       /* group scratch: node index or WK_NONE */
    uint32_t seen;     /* group scratch: stamp of the last cycle walk */
    uint32_t cyc;      /* group scratch: index of its cycle among the touched ones */
} wk_wf_vertex;
/* gap_made and forced sit in padding: the vertex is 120 bytes on LP64 */
_Static_assert(sizeof(void *) != 8 || sizeof(wk_wf_vertex) == 120, "wk_wf_vertex grew");

/* A node of the group being resolved (event points within eps_d). */
typedef struct wk_wf_cluster {
    wk_point p;
    uint32_t sk;       /* skeleton node id, WK_NONE until committed */
    uint32_t first, count; /* its sub-pieces' slots in the pairing arrays */
    uint32_t arrive, reflex, pinches, pairs; /* for the counters */
    uint32_t own;      /* WK_NONE, or the one seed whose node this is: a split
                          kept apart from a node within eps_d
                          (wavefront_group.c, plan_shields) */
    double r;          /* its node radius: eps_g, or a wide spot's
                          (wavefront_group.c, node_radius_at) */
} wk_wf_cluster;

/* A place where a plan failed at its node radius: nodes within r of p get
** radius r on the next try (wavefront_group.c, wf_resolve_group). */
typedef struct wk_wf_wide { wk_point p; double r; } wk_wf_wide;

/* A node cutting piece `piece` at distance s from its start. */
typedef struct wk_wf_pinch { uint32_t piece; double s; uint32_t node; } wk_wf_pinch;

/* A directed piece of the wavefront between two points of the group. */
typedef struct wk_wf_sub {
    uint32_t from, to;   /* point: node index | NODE_BIT, or a vertex id */
    uint32_t edge;       /* input edge whose offset line carries it */
    uint32_t pair_in;    /* index of the pair using it as incoming */
    uint32_t pair_out;   /* ... as outgoing */
    uint8_t dead;        /* 1: gone (collapsed or folded), 2: cancelled, leaves an arc */
} wk_wf_sub;

/* An incoming and an outgoing sub-piece joined at a node: a new vertex. */
typedef struct wk_wf_pair { uint32_t in, out, node, vertex; } wk_wf_pair;

/* A piece end that a split of this group passes by (wavefront_group.c,
** plan_shields): vertex `vertex` does not arrive at node `node`, which cuts
** the piece starting at `piece` instead. */
typedef struct wk_wf_shield { uint32_t vertex, node, piece; } wk_wf_shield;

#define NODE_BIT 0x80000000u
#define IS_NODE(p) (((p) & NODE_BIT) != 0)
#define NODE_OF(p) ((p) & ~NODE_BIT)

struct wk_wavefront {
    wk_run *R;
    const wk_polygon *P;
    wk_skeleton *S;
    wk_offset_line *L;
    wk_wf_vertex *v;
    uint32_t nv, cap_v;
    wk_event_queue Q;
    double eps_d, eps_t, t_now;
    double t_group;    /* the last group's time (0 before the first); t_now
                          may pass it through a finder's own events, which
                          are no events of the skeleton: a PSLG's default
                          horizon counts from t_group */
    double eps_g;      /* node radius of the group being planned away from
                          its wide spots: eps_d, or wider on the last-resort
                          retry of the whole group (wf_resolve_group) */
    wk_wf_wide *wide; uint32_t n_wide, cap_wide; /* this group's wide spots */
    double eps_gmax;   /* the largest node radius of the plan (eps_g, spots) */
    uint32_t fail_node[2]; /* the nodes a failed plan names (WK_NONE: none) */
    wk_point origin;   /* all positions are relative to it (bounding-box centre) */
    uint32_t stamp;
    /* group scratch, kept between groups */
    uint32_t *seeds; uint32_t n_seeds, cap_seeds;
    uint32_t *deferred; uint32_t n_deferred, cap_deferred; /* events within eps_t left for a later group */
    double t_last;     /* the latest seed time of the group (t <= t_last <= t + eps_t) */
    uint32_t *forced; uint32_t n_forced, cap_forced;
    uint32_t *swept; uint32_t n_swept, cap_swept; /* forced crack tips that left their
                          node within eps_t (wavefront_group.c, plan_force_touching) */
    uint32_t *comp; uint32_t n_comp, cap_comp;
    wk_wf_cluster *cl; uint32_t n_cl, cap_cl;
    wk_wf_pinch *pin; uint32_t n_pin, cap_pin;
    wk_wf_sub *sub; uint32_t n_sub, cap_sub;
    wk_wf_pair *pair; uint32_t n_pair, cap_pair;
    uint32_t *slot; uint32_t n_slot, cap_slot;
    uint32_t *fresh; uint32_t n_fresh, cap_fresh;
    uint32_t *dead; uint32_t n_dead, cap_dead; /* vertices ended in this group */
    bool local_walk;   /* this group's vertices come from local walks (collect_local) */
    uint8_t *cycflag; uint32_t n_cyc, cap_cycflag;
    uint32_t *run, *run_node; uint32_t n_run, cap_run, cap_run_node; /* collinear runs */
    wk_wf_shield *shield; uint32_t n_shield, cap_shield; /* this group's shielded piece ends */
    uint32_t n_gap_shield; /* shield[0 .. n_gap_shield): plan_shields' (gaps between rings) */
    /* the shields by vertex once there are WF_INDEX_MIN (wavefront_group.c,
    ** shield_of): a hash table of shield ids (WK_NONE: empty) keyed by the
    ** shield's vertex, each the newest of its vertex, and per shield the
    ** next older one of the same vertex (shield_older); 0 slots: off */
    uint32_t *shield_ix; uint32_t n_shield_ix, cap_shield_ix;
    uint32_t *shield_older; uint32_t cap_shield_older;
    /* plan_seed_cuts' pinches by (piece, node): a hash table of pinch ids */
    uint32_t *pin_ix; uint32_t cap_pin_ix;
    uint32_t n_own;    /* this plan's nodes of one seed (wk_wf_cluster.own) */
    /* a large group's nodes and untouched vertices by place
    ** (wavefront_group.c, WF_GRID_MIN); off: the plan scans */
    wk_point_grid cg; bool cg_on;
    wk_point_grid vg; bool vg_on;
    uint32_t *by_from; uint32_t cap_by_from; /* plan_force_touching's sub-pieces by start */
    bool input_sides;  /* sub-tolerance gaps between input vertices are
                          resolved on the input's side (wf_input_cut_side,
                          plan_shields): at the nominal tolerance and
                          finer only, so the coarser retries of
                          wk_solve_checked fall back on the tolerance picture where the cascade of
                          sub-tolerance events that follows cannot be
                          resolved consistently */
    const wk_split_finder *finder; /* how split events are found */
    void *finder_ud;
};

/* The likely final size of the arrays that grow by one per wavefront
** vertex or skeleton node (WK_GROW_HINT): 2n + 16. */
static inline uint32_t wf_size_hint(const wk_wavefront *W) {
    return W->P->n < UINT32_MAX / 4 ? 2 * W->P->n + 16 : 0;
}

/* Position of vertex V at time t (relative to W->origin). */
static inline wk_point wk_wf_pos(const wk_wf_vertex *V, double t) {
    double dt = t - V->t0;
    return (wk_point){V->p0.x + V->vel.x * dt, V->p0.y + V->vel.y * dt};
}

static inline double wf_dist2(wk_point a, wk_point b) {
    double dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

/* wavefront.c: vertices, arcs and the lists a group fills. */
uint32_t wf_new_vertex(wk_wavefront *W, uint32_t ein, uint32_t eout, wk_point p, double t,
                       uint32_t node); /* WK_NONE on failure */
wk_status wf_add_arc(wk_wavefront *W, uint32_t a, uint32_t b, uint32_t left, uint32_t right);
/* Kill v at skeleton node sk: its arc runs from where it started to sk. */
wk_status wf_terminate(wk_wavefront *W, uint32_t v, uint32_t sk);
void wf_link(wk_wavefront *W, uint32_t a, uint32_t b);
/* True if input vertex u (alive since t = 0) never reaches the offset line
** of edge e: it does not approach it and lies strictly behind e's input
** line (exact test) or, for e on another ring, behind e's offset line now
** by more than rounding (from the input coordinates; W->input_sides). */
bool wf_never_reaches_line(const wk_wavefront *W, uint32_t u, uint32_t e);
/* True if input vertex V meets a piece's line at p at time t, s (< 0:
** outside the piece) from its end X, past X by more than rounding, X a
** vertex an earlier group made (nominal tolerance and finer only); or
** before X starts (a vertex of a node of one seed starts at its seed's
** time, after the group's). */
bool wf_made_end_passed(const wk_wavefront *W, const wk_wf_vertex *V, const wk_wf_vertex *X, wk_point p,
                        double s, double t);
/* True if input vertex u and input edge e lie on different rings. */
static inline bool wf_other_ring(const wk_wavefront *W, uint32_t u, uint32_t e) {
    return u < W->P->n && wk_polygon_ring(W->P, u) != wk_polygon_ring(W->P, e);
}
/* True if u is an input vertex alive since t = 0 (it moves from its input
** coordinates P->p[u]). */
static inline bool wf_is_input_vertex(const wk_wavefront *W, uint32_t u) {
    return u < W->P->n && W->v[u].t0 == 0;
}
/* Where input vertex v, approaching the offset line L, meets it relative
** to input vertex x on L, an end of a piece of L (end 0: its start, 1: its
** end), computed at time t from the input coordinates: +1 inside the piece
** (beyond x towards its other end) by more than rounding
** (WK_SPLIT_SIDE_ULPS), -1 outside it past x by more than rounding, 0
** within rounding of x or when v or x is no input vertex, v does not
** approach L or W->input_sides is off. */
int wf_input_cut_side(const wk_wavefront *W, uint32_t v, uint32_t x, const wk_offset_line *L, int end,
                      double t);
/* wavefront_group.c: true if a vertex between edges ein and eout, cutting
** a piece of edge e at a node where nothing else arrives, may be paired
** back to itself by plan_pairs (each incoming piece continues with the
** first outgoing one clockwise): ein's first is eout, or e's first is e
** (it passes through), so in one order or the other the split changes
** nothing. */
bool wf_split_changes_nothing(const wk_wavefront *W, uint32_t ein, uint32_t eout, uint32_t e);
wk_status wf_mark_fresh(wk_wavefront *W, uint32_t v);
wk_status wf_push_u32(wk_run *R, uint32_t **a, uint32_t *n, uint32_t *cap, uint32_t x);

/* wavefront_horizon.c: a PSLG's wavefront at its horizon T (R->opt.until,
** or wf_default_horizon after the last event): every alive vertex ends at a node
** at t = T and the pieces between them become the cap's arcs; sets
** W->S->horizon. */
wk_status wf_close_at_horizon(wk_wavefront *W, double T);
/* The default horizon: the last group's time (t_group) plus
** WK_PSLG_HORIZON_MARGIN diagonals over the largest weight. */
double wf_default_horizon(const wk_wavefront *W);
/* The last event time a PSLG's run follows: --until, or by default
** WK_PSLG_DEFAULT_EVENTS_REL diagonals over the smallest weight. */
double wf_event_limit(const wk_wavefront *W);
/* --until within the input domain (WK_PSLG_MAX_HORIZON_REL); WK_EINPUT. */
wk_status wf_check_horizon(const wk_wavefront *W);

/* wavefront_group.c: resolve the group of events seeded by W->seeds at
** time t (W->fresh and W->dead list what it created and ended). */
wk_status wf_resolve_group(wk_wavefront *W, double t);
/* The collinear rule for vertex v at time t (no-op unless v sits between
** parallel edges). */
wk_status wf_collinear_rule(wk_wavefront *W, uint32_t v, double t);

#endif
