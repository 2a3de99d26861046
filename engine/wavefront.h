/*
** wavefront.h: the kinetic wavefront that the variants share, and the
** narrow interface between it and whoever finds its split events (CGAL's
** builder / traits / visitor split: the wavefront does the topology, a
** finder supplies events).  wavefront.c holds the model and the simulation,
** wavefront_group.c the resolution of a group of simultaneous events.
**
** A variant supplies a wk_split_finder: how a reflex vertex's split event is
** found (every piece of its cycle, 000's bisector segments, 002's
** traces).  Everything else (edge events, resolution of event groups, the
** collinear rule, the skeleton) is the wavefront's, so variants differ only
** in what the papers make them differ in.  The wavefront itself is opaque:
** a finder sees it through the functions below and never writes it except
** by offering split candidates and asking for rescheduling.
**
** What a finder may rely on between events: every alive vertex is in one
** cycle (prev/next agree); the piece a -> next(a) of an alive vertex a lies
** on the offset line of edge_out(a); a vertex never changes after creation
** (events kill vertices and create new ones), so "piece (a, b) still
** exists" is "a alive and next(a) == b".  Vertex ids are dense and stable
** (0 .. vertex_count - 1, dead ones included); coordinates are relative to
** an origin inside the polygon (wk_wf_origin), times absolute.
*/
#ifndef WK_WAVEFRONT_H
#define WK_WAVEFRONT_H
#include "event_queue.h"
#include "kinetics.h"

typedef struct wk_wavefront wk_wavefront;

/* How split events are found.  Hooks receive the finder's ud first.
** full: a fresh reflex vertex v, or one whose target piece disappeared;
**   offer its earliest split (wk_wf_offer_split, or a wk_wf_split_search)
**   (its edge event is already its candidate).
** incremental: v's target piece still exists; only pieces next to the
**   vertices of wk_wf_last_group's `fresh` list are new.
** start (may be NULL): after the initial wavefront exists, before the first
**   candidates are computed.
** after_group (may be NULL): after a group of simultaneous events was
**   resolved (wk_wf_last_group lists the new and relinked vertices and the
**   ended ones), before candidates are refreshed.
** next_time / process_next (may be NULL): the finder's own events (e.g.
**   000's start and switch events), processed before any wavefront event
**   that is not earlier; process_next may call wk_wf_reschedule for
**   vertices whose split candidate moved.
** check (may be NULL): with R->opt.check_invariants, after every group and
**   the finder's after_group: the finder's own invariants; WK_EALGO with a
**   message if one is broken. */
typedef struct wk_split_finder {
    void (*full)(void *ud, wk_wavefront *W, uint32_t v);
    void (*incremental)(void *ud, wk_wavefront *W, uint32_t v);
    wk_status (*start)(void *ud, wk_wavefront *W);
    wk_status (*after_group)(void *ud, wk_wavefront *W, double t);
    double (*next_time)(void *ud);
    wk_status (*process_next)(void *ud, wk_wavefront *W);
    wk_status (*check)(void *ud, const wk_wavefront *W);
    bool local_refresh; /* candidates need no walk over the touched cycles:
                           the finder reschedules what it changes */
} wk_split_finder;

/* Run the simulation on P with the given finder; on success *out is the
** skeleton (caller frees).  No skeleton on failure. */
wk_status wk_wavefront_run(wk_run *R, const wk_polygon *P, const wk_split_finder *finder,
                           void *finder_ud, wk_skeleton **out);

/* ------------------------------------------------- what a finder may read */

wk_run *wk_wf_run(const wk_wavefront *W);
const wk_polygon *wk_wf_polygon(const wk_wavefront *W);
/* The time of the event being processed (the wavefront's present). */
double wk_wf_now(const wk_wavefront *W);
/* Tolerances (wskel.h's policy): distances eps_d, times eps_t. */
double wk_wf_eps_d(const wk_wavefront *W);
double wk_wf_eps_t(const wk_wavefront *W);
/* Offset line of input edge e (stored numbering), in relative coordinates. */
const wk_offset_line *wk_wf_line(const wk_wavefront *W, uint32_t e);
/* Vertices created so far (ids 0 .. count-1; the first n are the input
** vertices, where vertex i leaves along edge i). */
uint32_t wk_wf_vertex_count(const wk_wavefront *W);
bool wk_wf_alive(const wk_wavefront *W, uint32_t v);
bool wk_wf_reflex(const wk_wavefront *W, uint32_t v);
uint32_t wk_wf_next(const wk_wavefront *W, uint32_t v);
uint32_t wk_wf_prev(const wk_wavefront *W, uint32_t v);
/* Input edge of the piece v -> next(v). */
uint32_t wk_wf_edge_out(const wk_wavefront *W, uint32_t v);
/* When v was created. */
double wk_wf_start_time(const wk_wavefront *W, uint32_t v);
/* Where v is at time t (relative coordinates; v moves linearly). */
wk_point wk_wf_position(const wk_wavefront *W, uint32_t v, double t);
wk_point wk_wf_velocity(const wk_wavefront *W, uint32_t v);
/* What the last group changed: the vertices it created or relinked (their
** next changed) and the vertices it ended.  Valid until the next group. */
void wk_wf_last_group(const wk_wavefront *W, const uint32_t **fresh, uint32_t *n_fresh,
                      const uint32_t **ended, uint32_t *n_ended);

/* ------------------------------------------------ what a finder may write */

/* Offer v a split with piece a -> b at time t and point p: kept if earlier
** than v's current candidate. */
void wk_wf_offer_split(wk_wavefront *W, uint32_t v, double t, wk_point p, uint32_t a, uint32_t b);
/* Recompute v's candidate (edge event plus the finder's split) and queue it. */
wk_status wk_wf_reschedule(wk_wavefront *W, uint32_t v);

/* A split search over chosen pieces: begin (the best so far is v's current
** candidate), test pieces, offer the best.  The test is the reference's:
** v reaches the offset line of a's piece within its extent, before the best
** so far; equal times keep the lower piece id (deterministic). */
typedef struct wk_wf_split_search {
    uint32_t v;
    double t;
    wk_point p;
    uint32_t a, b; /* best piece so far, WK_NONE if none beat the candidate */
} wk_wf_split_search;
void wk_wf_split_begin(const wk_wavefront *W, uint32_t v, wk_wf_split_search *s);
void wk_wf_split_test(const wk_wavefront *W, wk_wf_split_search *s, uint32_t a);
void wk_wf_split_offer(wk_wavefront *W, const wk_wf_split_search *s);
/* The search over both pieces at each alive vertex of vs[0..n) but v
** itself, O(n): for finders whose own structure cannot see splits at
** those vertices (contacts: vertices within eps_d of another ring at
** t = 0, whose pieces sweep across other vertices' paths unseen). */
void wk_wf_split_at_vertices(wk_wavefront *W, uint32_t v, const uint32_t *vs, uint32_t n);
/* After a group (in the finder's after-group hook): when the group made or
** relinked a piece at one of vs[0..n) (the vertex or its predecessor is
** among the group's fresh vertices), reschedule every alive reflex vertex,
** whose wk_wf_split_at_vertices answer may have changed; the engine
** refreshes only the vertices the group touched.  O(n * fresh), and
** O(vertices) when it fires: for rare vs (contacts). */
wk_status wk_wf_reschedule_after_pieces_at(wk_wavefront *W, const uint32_t *vs, uint32_t n);
/* The search over every piece of v's cycle, O(cycle): begin, test all, offer. */
void wk_wf_split_scan(wk_wavefront *W, uint32_t v);
/* The search over the pieces just beyond v's own two, walking on past each
** neighbour within WK_ARR_NEAR_SLACK * eps_d of v: across a sub-tolerance
** edge v is that close to its neighbour's other piece, a contact the
** reference takes as a split at once and that no ray along v's motion sees.
** O(1) unless v sits in a chain of such edges. */
void wk_wf_near_split(wk_wavefront *W, uint32_t v);

/* The rule of the split test for input vertices (wavefront.c): input
** vertex u of P, moving at vel since t = 0 (the caller knows it is alive
** since then), never reaches the offset line L of input edge e when it lies
** strictly behind e's input line (an exact orientation) and does not
** approach the line (n . vel - w <= 0): it is within eps_d of the piece only
** because the input puts it there (a crack outside the polygon between
** them, the chamfer of a reflex corner shorter than eps_d); or when it lies
** exactly on that line (e not one of its own edges, weights positive) and
** recedes from it by more than its rounding (wf_never_reaches_line's rule:
** the H with needles whose edges 3 and 7 are collinear and face each
** other).  For a variant with its own wavefront, so that its contacts
** follow the engine's. */
bool wk_input_vertex_never_reaches_line(wk_run *R, const wk_polygon *P, uint32_t u, wk_point vel,
                                        const wk_offset_line *L, uint32_t e);

/* The side rule of rings that nearly touch (wavefront.c, the split test and
** the shields of a group): where input vertex v of P (velocity vv since
** t = 0), approaching the offset line L, meets it relative to input vertex
** x on L (velocity vx), an end of a piece of L (end 0: its start, 1: its
** end), from the input coordinates at time t: +1 inside the piece by more
** than rounding (WK_SPLIT_SIDE_ULPS), -1 outside it past x by more than
** rounding, 0 within rounding of x or when v does not approach L.  For a
** variant with its own wavefront, so that its contacts between rings
** follow the engine's (at the nominal tolerance and finer only, as the
** engine's). */
int wk_input_cut_side(const wk_polygon *P, uint32_t v, wk_point vv, uint32_t x, wk_point vx,
                      const wk_offset_line *L, int end, double t);

/* The rounding rate of a vertex moving at vel between edges whose least
** weight is wu (> 0): its place is off by up to s + s^2 / wu per unit of
** time, s = |vel|_1 (its velocity is solved from its edges' normals, with
** condition about s / wu). */
double wk_speed_rounding(wk_point vel, double wu);

/* The rule of the split test for a vertex behind a piece's line
** (wavefront.c, wf_passed_before_piece): a vertex at pv (relative
** coordinates) at t_now, born at v_t0, behind the offset line of weight w
** by d0 < 0 and receding from it (rate < 0; speed_round its
** wk_speed_rounding), crossed the line at t_c = t_now - d0 / rate.  True
** (no contact with the piece) if it existed then, is behind by more than
** rounding, and an end of the piece (born at a_t0, b_t0) was made after
** t_c: the piece did not reach there when the vertex crossed.  For a
** variant with its own wavefront, so that its contacts follow the
** engine's. */
bool wk_passed_line_before_piece(wk_point pv, double t_now, double d0, double rate,
                                 double speed_round, double w, double v_t0, double a_t0,
                                 double b_t0);

/* ------------------------------------- rays along a segment (wavefront_ray.c)
** For finders that follow a moving Steiner vertex along a static segment
** o + lambda u (u a unit vector, relative coordinates): 000's segments,
** 002's traces. */

/* lambda where the segment's line meets offset line L at time t; NaN if
** they are parallel (|n . u| < WK_ARR_PARALLEL). */
double wk_wf_ray_on_line(wk_point o, wk_point u, const wk_offset_line *L, double t);
/* lambda where the ray (lambda > lambda0 - WK_RAY_BEHIND_SLACK * eps_d: a
** piece that close behind the start is a contact) meets piece a -> next(a)
** at time t, or INFINITY; *mu receives the place along the piece (0 .. 1,
** within WK_RAY_PIECE_SLACK). */
double wk_wf_ray_hit_piece(const wk_wavefront *W, wk_point o, wk_point u, uint32_t a, double t,
                           double lambda0, double *mu);
/* The first piece the ray (lambda > lambda0) meets at time t: over v's
** cycle, O(cycle), or over every alive piece with holes or v = WK_NONE (a
** hole's cycle may not have joined v's yet).  A hit at a piece's end
** (within WK_RAY_END_SNAP) is shot again WK_RAY_RESHOOT_DELAY * eps_t
** later (sooner, WK_RAY_RESHOOT_GAP_SHARE, when v would reach a piece
** there by then), when the vertex there has moved off the ray, among the
** pieces at the hit point (WK_RAY_RESHOOT_NEAR; all, if it meets none of
** them then).
** v's own two pieces are never hit.  WK_NONE if the ray meets nothing. */
uint32_t wk_wf_ray_shoot(const wk_wavefront *W, wk_point o, wk_point u, uint32_t v, double t,
                         double lambda0);
/* When the moving Steiner vertex at lambda l0 (at now) and l1 (at now + 1)
** on piece a -> next(a) leaves the piece over one of its ends: *te
** (INFINITY if never: it rides along with an end vertex, within
** WK_RIDE_ALONG_REL) and *end (0 over a, 1 over next(a)). */
void wk_wf_ray_exit(const wk_wavefront *W, wk_point o, wk_point u, uint32_t a, double now,
                    double l0, double l1, double *te, uint8_t *end);

#endif
