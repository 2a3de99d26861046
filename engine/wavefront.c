/*
** wavefront.c: the kinetic wavefront shared by the variants.  Event-driven
** simulation of the weighted wavefront of a simple polygon; how split events
** are found is the finder's business (wavefront.h), the resolution of a
** group of simultaneous events is wavefront_group.c, everything else is
** here.
**
** Model.  The wavefront is a set of disjoint cycles of wavefront vertices
** (prev/next ids).  Vertex v sits between input edges ein (before it,
** counter-clockwise) and eout (after it) and moves linearly:
** pos(v, t) = p0 + vel (t - t0) for t >= t0.  The wavefront piece v -> v.next
** lies on the offset line of v.eout.  A vertex never changes after creation:
** an event kills vertices and creates new ones, so "piece (a, b) still
** exists" is simply "a alive and a.next == b".
**
** Events.  Each alive vertex carries its earliest candidate event in the
** queue: the collapse of its outgoing piece (edge event) or, if reflex, its
** first hit of a piece of its own cycle (split event, reported by the
** finder).  Candidates stay exact under changes: a changed piece is a new
** piece, so after each step the finder is asked again for every reflex
** vertex of the touched cycles: in full when its target piece disappeared
** (or the vertex is new), incrementally (new pieces only) otherwise.
**
** PSLGs (wk_polygon.pslg, engine/pslg.c): the rings are the face cycles of
** the graph's half-edges, so the same model runs; the initial wavefront
** touches itself (both sides of a segment, the corners at a node), which
** wk_wf_split_test does not take for splits, and the run ends at a time
** horizon (wavefront_horizon.c) instead of when the wavefront has vanished.
**
** Tolerances: WK_TOL_REL times the polygon's scale for distances, divided by
** the largest weight for times (wskel.h).
*/
#include "wavefront_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ vertices */

/* The vertex array grows by doubling but stops at 2n + 16 first
** (WK_GROW_HINT): n input vertices in general position make 2n - 3
** wavefront vertices, one per arc (simultaneous events make fewer, holes
** may make more).  Doubling alone left up to half of it empty: star
** 3*10^5 (599,997 vertices of 120 bytes in a capacity of 2^20) held 1,113
** tracked bytes per input vertex at its peak.  The skeleton's nodes and
** arcs likewise (wk_skeleton.cap_hint). */
uint32_t wf_new_vertex(wk_wavefront *W, uint32_t ein, uint32_t eout, wk_point p, double t,
                       uint32_t node) {
    if (WK_GROW_HINT(W->R, W->v, W->cap_v, W->nv + 1, wf_size_hint(W)) != WK_OK) return WK_NONE;
    uint32_t id = W->nv++;
    wk_wf_vertex *x = &W->v[id];
    memset(x, 0, sizeof *x);
    x->ein = ein;
    x->eout = eout;
    x->t0 = t;
    x->node = node;
    x->alive = 1;
    x->fresh = 1;
    x->prev = x->next = WK_NONE;
    x->at = WK_NONE;
    x->ev_kind = WK_WF_NONE;
    x->ev_t = INFINITY;
    bool reflex;
    x->vkind = (uint8_t)wk_vertex_start(W->L, ein, eout, p, t, W->eps_d, &x->p0, &x->vel, &reflex);
    x->reflex = reflex;
    /* A non-finite vertex would poison every later comparison (a NaN is
    ** never within tolerance of anything: groups would grow without end). */
    if (!isfinite(x->p0.x) || !isfinite(x->p0.y) || !isfinite(x->vel.x) || !isfinite(x->vel.y)) {
        WK_FAIL(W->R, WK_EALGO, W->P->name, 0,
                "wavefront: vertex between edges %u and %u at t = %.17g is not finite", ein, eout, t);
        return WK_NONE;
    }
    return id;
}

wk_status wf_add_arc(wk_wavefront *W, uint32_t a, uint32_t b, uint32_t left, uint32_t right) {
    if (a == b) return WK_OK; /* zero-length: nothing traced */
    if (left == right)
        return WK_FAIL(W->R, WK_EALGO, W->P->name, 0,
                       "wavefront: arc between nodes %u and %u would have face %u on both sides", a, b,
                       left);
    return wk_skeleton_add_arc(W->R, W->S, a, b, left, right);
}

wk_status wf_terminate(wk_wavefront *W, uint32_t v, uint32_t sk) {
    wk_wf_vertex *x = &W->v[v];
    x->alive = 0;
    wk_event_queue_remove(W->R, &W->Q, v);
    if (WK_GROW(W->R, W->dead, W->cap_dead, W->n_dead + 1) != WK_OK)
        return W->R->err.code;
    W->dead[W->n_dead++] = v;
    return wf_add_arc(W, x->node, sk, x->ein, x->eout);
}

/* True if input vertex u lies behind the offset line of edge e of another
** ring now (W->t_now) by more than rounding, computed from the input
** coordinates: u's distance from e's input line, measured from e's input
** end nearer to u (a difference of input points: exact when they are
** close, Sterbenz), plus the relative motion, so a gap of 1e-11 between
** two rings keeps its sign and size, which positions relative to W->origin
** (rounded to the coordinates' ulps, then compared with eps_d) would not.
** Rounding: WK_SPLIT_SIDE_ULPS ulps (as wf_input_cut_side) of the gap and
** of the motion, u's speed s counted as s + s^2 / w (its velocity is
** solved from its edges' normals, with condition about s / w).  At the
** nominal and finer tolerances only (W->input_sides), as every input-side
** rule. */
/* The rate term of a moving vertex's rounding: a vertex of speed s between
** edges of least weight wu is placed with an error growing like s + s^2 / wu
** per unit of time (its velocity is built from the two offset lines). */
double wk_speed_rounding(wk_point vel, double wu) {
    double s = fabs(vel.x) + fabs(vel.y);
    return s + s * s / wu;
}

static double speed_rounding(const wk_wavefront *W, const wk_wf_vertex *U) {
    return wk_speed_rounding(U->vel, fmin(W->L[U->ein].w, W->L[U->eout].w));
}

static bool behind_offset_line(const wk_wavefront *W, uint32_t u, uint32_t e) {
    const wk_polygon *P = W->P;
    if (!W->input_sides || !wf_other_ring(W, u, e)) return false;
    const wk_offset_line *L = &W->L[e];
    const wk_wf_vertex *U = &W->v[u];
    uint32_t x = e, y = wk_polygon_next(P, e);
    double t = W->t_now;
    wk_point dx = {P->p[u].x - P->p[x].x, P->p[u].y - P->p[x].y};
    wk_point dy = {P->p[u].x - P->p[y].x, P->p[u].y - P->p[y].y};
    wk_point r = fabs(dy.x) + fabs(dy.y) < fabs(dx.x) + fabs(dx.y) ? dy : dx;
    double rate = L->nx * U->vel.x + L->ny * U->vel.y - L->w;
    double d = L->nx * r.x + L->ny * r.y + rate * t;
    double bar = WK_SPLIT_SIDE_ULPS * DBL_EPSILON * (fabs(r.x) + fabs(r.y) + (speed_rounding(W, U) + L->w) * t);
    return d < -bar;
}

/* An input vertex u within eps_d of a line of edge e is near its piece
** only because the input puts it there: a vertex 6e-6 beyond a
** non-adjacent edge of a needle 1e6 long, the gap between them outside the
** polygon (forcing it onto the piece made the gap interior and left a cycle
** in the skeleton, tests/data/fuzz/needle_vertex_beyond_edge.wpoly), or
** the vertex of a hole 1e-10 from another hole's vertex (taken as a split
** at t = 0 it joined the holes as if they touched, and the wavefront went
** round in circles: tests/data/fuzz/ealgo_holes_vertices_1e-10_apart.wpoly).
** A vertex that meets a piece comes from its front.  It never reaches the
** line when it lies strictly behind e's input line (exact test) and moves
** away from it (relative to the line, which moves forward at its weight).
** Likewise, for e on another ring, when it lies behind e's offset line now
** by more than rounding (behind_offset_line): it crossed that line before
** now, outside every piece, and a piece the last group made on the line is
** not near it (a hole's apex 7e-11 above a notch's tip passes the tip,
** crosses the line of the tip's edge 4.5e-11 beyond it, and lies 5e-11
** behind it when the tip splits the hole's edge: taken as a split now, of
** the piece that split left on the tip's edge, the group rebuilt the same
** vertices again and again, "no progress",
** tests/data/holes/near_touch_apex_passes_notch_tip.wpoly).
** Only input vertices: a constructed vertex's place is a node eps_d wide,
** and one eps_d behind the line is not near the piece anyway.  The split
** test asks it too (wk_wf_split_test). */
/* A vertex exactly on an input line (not its own), receding from it at
** rate by more than its rounding (speed_round, the line's weight w): behind
** the line at every t > 0 (wf_never_reaches_line). */
static bool on_line_receding(double rate, double speed_round, double w) {
    return rate < -WK_SPLIT_SIDE_ULPS * DBL_EPSILON * (speed_round + w);
}

bool wf_never_reaches_line(const wk_wavefront *W, uint32_t u, uint32_t e) {
    const wk_polygon *P = W->P;
    if (u >= P->n || W->v[u].t0 != 0) return false;
    const wk_offset_line *L = &W->L[e];
    /* exactly behind the input line (as wk_input_vertex_never_reaches_line), or behind another ring's edge line by
    ** more than rounding (behind_offset_line); either way not approaching it */
    int o = wk_orient2d_counted(W->R, P->p[e], P->p[wk_polygon_next(P, e)], P->p[u]);
    double rate = L->nx * W->v[u].vel.x + L->ny * W->v[u].vel.y - L->w;
    if (o < 0 || behind_offset_line(W, u, e)) return rate <= 0;
    /* exactly on the input line (not one of u's own edges) and receding from
    ** it by more than its rounding (WK_SPLIT_SIDE_ULPS ulps of u's speed s,
    ** speed_rounding, as in behind_offset_line): behind it at every
    ** t > 0.  An H with needles whose edges 3 and 7 are collinear and
    ** antiparallel, 4 apart: reflex vertex 3 (speed 5e5) split edge 6
    ** 1.6e-5 behind edge 7's line, node_behind_piece took it for a vertex
    ** from the line's front, the node pinched edge 7 and the skeleton
    ** closed a cycle (exit 3; tests/data/fuzz/invalid_naive_h_needles_pass_by.wpoly) */
    if (o != 0 || e == W->v[u].ein || e == W->v[u].eout) return false;
    /* A PSLG's cap has length 0 (engine/pslg.c): orient2d of its two equal
    ** points is 0 for every point, so "exactly on the line" says nothing
    ** there.  Taken as on it, the corners of a terminal facing another
    ** terminal 1 away on the same line (tests/data/pslg/mc_node_contact.graphml,
    ** (7,10) and (7,11)) counted as behind each other's caps: their meeting
    ** at t = 0.5 was not planned, the traces ran on to the horizon and the
    ** PSLG validator refused the skeleton (cap cycles meet). */
    if (P->p[e].x == P->p[wk_polygon_next(P, e)].x && P->p[e].y == P->p[wk_polygon_next(P, e)].y)
        return false;
    return on_line_receding(rate, speed_rounding(W, &W->v[u]), L->w);
}

bool wk_input_vertex_never_reaches_line(wk_run *R, const wk_polygon *P, uint32_t u, wk_point vel,
                                        const wk_offset_line *L, uint32_t e) {
    int o = wk_orient2d_counted(R, P->p[e], P->p[wk_polygon_next(P, e)], P->p[u]);
    double rate = L->nx * vel.x + L->ny * vel.y - L->w;
    if (o < 0) return rate <= 0;
    /* exactly on the line and receding, as wf_never_reaches_line (positive
    ** weights: the rounding bound needs them) */
    uint32_t ein = wk_polygon_prev(P, u);
    double wu = fmin(P->w[ein], P->w[u]);
    if (o != 0 || e == ein || e == u || !(wu > 0) || !(L->w > 0)) return false;
    return on_line_receding(rate, wk_speed_rounding(vel, wu), L->w);
}

int wf_input_cut_side(const wk_wavefront *W, uint32_t v, uint32_t x, const wk_offset_line *L, int end,
                      double t) {
    if (!W->input_sides || !wf_is_input_vertex(W, v) || !wf_is_input_vertex(W, x)) return 0;
    return wk_input_cut_side(W->P, v, W->v[v].vel, x, W->v[x].vel, L, end, t);
}

int wk_input_cut_side(const wk_polygon *P, uint32_t v, wk_point vv, uint32_t x, wk_point vx,
                      const wk_offset_line *L, int end, double t) {
    double rate = L->nx * vv.x + L->ny * vv.y - L->w;
    if (!(rate < 0)) return 0;
    /* v relative to x now: the input coordinates' difference (exact for
    ** points closer than either's magnitude, Sterbenz) plus the relative
    ** motion, so a gap far below eps_d keeps its sign and size, which
    ** positions relative to an origin (rounded to the coordinates' ulps)
    ** would not; then where v meets the line (x is on it) */
    wk_point r0 = {(P->p[v].x - P->p[x].x) + (vv.x - vx.x) * t, (P->p[v].y - P->p[x].y) + (vv.y - vx.y) * t};
    double dt = (L->nx * r0.x + L->ny * r0.y) / -rate;
    wk_point r = {r0.x + (vv.x - vx.x) * dt, r0.y + (vv.y - vx.y) * dt};
    double s = L->ux * r.x + L->uy * r.y;
    if (end) s = -s; /* measured from the piece's end backwards */
    double bar = WK_SPLIT_SIDE_ULPS * DBL_EPSILON *
                 (fabs(r0.x) + fabs(r0.y) + (fabs(vv.x) + fabs(vv.y) + fabs(vx.x) + fabs(vx.y)) * fabs(dt));
    return s > bar ? 1 : s < -bar ? -1 : 0;
}

void wf_link(wk_wavefront *W, uint32_t a, uint32_t b) {
    W->v[a].next = b;
    W->v[b].prev = a;
}

wk_status wf_mark_fresh(wk_wavefront *W, uint32_t v) {
    return wf_push_u32(W->R, &W->fresh, &W->n_fresh, &W->cap_fresh, v);
}

wk_status wf_push_u32(wk_run *R, uint32_t **a, uint32_t *n, uint32_t *cap, uint32_t x) {
    if (WK_GROW(R, *a, *cap, *n + 1) != WK_OK) return R->err.code;
    (*a)[(*n)++] = x;
    return WK_OK;
}

/* ---------------------------------------------------------- candidates */

/* Replace a kinematic estimate (t, p) of the event where offset lines e1,
** e2, e3 meet by their exact meeting point when that system is well
** conditioned and agrees with the estimate: the event then depends on input
** edges only, as in CGAL's trisegments. */
static void refine(const wk_wavefront *W, const wk_wf_vertex *V, uint32_t e1, uint32_t e2, uint32_t e3,
                   double *t, wk_point *p) {
    if (e1 == e2 || e2 == e3 || e1 == e3 || V->vkind != WK_VEL_REGULAR) return;
    /* the lines from the input points in long double (kinetics.h): the
    ** double lines W->L can be off by far more than eps_t there */
    wk_point q;
    double tq;
    if (!wk_three_edges_meet(W->P, e1, e2, e3, W->origin, &q, &tq)) return;
    double speed = fabs(V->vel.x) + fabs(V->vel.y);
    double dslack = WK_REFINE_DIST_SLACK * W->eps_d;
    if (fabs(tq - *t) > WK_REFINE_TIME_SLACK * W->eps_t ||
        wf_dist2(q, *p) > dslack * dslack * (1 + speed * speed))
        return;
    if (tq < W->t_now) tq = W->t_now;
    *t = tq;
    *p = q;
}

/* Collapse time of the piece a -> a.next, relative motion along the edge. */
static void edge_event(wk_wavefront *W, uint32_t a, double *t, wk_point *p) {
    const wk_wf_vertex *A = &W->v[a], *B = &W->v[A->next];
    const wk_offset_line *L = &W->L[A->eout];
    double t0 = W->t_now;
    wk_point pa = wk_wf_pos(A, t0), pb = wk_wf_pos(B, t0);
    double d = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
    double rate = (B->vel.x - A->vel.x) * L->ux + (B->vel.y - A->vel.y) * L->uy;
    *t = INFINITY;
    /* A piece below eps_d that shrinks collapses now, unless it shrinks so
    ** slowly that "now" would be more than eps_t early: its ends may be fast
    ** and move far together meanwhile (a weighted comb with edges collinear
    ** to 2e-6: collapsing a 1.1e-6 piece at once put a node 48 units off;
    ** computed earlier, when the piece was 2e-6 long, the time was exact). */
    /* (rate == 0: a sub-tolerance piece that never shrinks is gone now) */
    if (d <= W->eps_d && rate <= 0 && (d <= 0 || -rate * W->eps_t >= d || rate == 0)) {
        *t = t0;
    } else if (rate < 0) {
        *t = t0 + (d > 0 ? d : 0) / -rate;
    } else {
        return;
    }
    /* Where the ends meet, each end's place weighted by the other's speed: a
    ** vertex of speed s is off by s times the rounding of t, so a slow end
    ** is the better witness.  A vertex born between edges antiparallel to
    ** 1.7e-11 moves at 5e10: the midpoint put the node 3e-6 off, the slow
    ** end's place is right (stress s6-c04959-nearly_straight).  Equal
    ** speeds give the midpoint. */
    wk_point qa = wk_wf_pos(A, *t), qb = wk_wf_pos(B, *t);
    double sa = fabs(A->vel.x) + fabs(A->vel.y), sb = fabs(B->vel.x) + fabs(B->vel.y);
    double fa = sa + sb > 0 ? sb / (sa + sb) : 0.5;
    *p = (wk_point){fa * qa.x + (1 - fa) * qb.x, fa * qa.y + (1 - fa) * qb.y};
    if (B->vkind == WK_VEL_REGULAR) refine(W, A, A->ein, A->eout, B->eout, t, p);
}

/* True if input vertex V, meeting the line of a piece at p at time t, s
** (< 0: outside) from the piece's end X, passes X by more than rounding,
** X a vertex an earlier group made (an input end: wf_input_cut_side).
** Rounding: WK_SPLIT_SIDE_ULPS ulps of the points and of both vertices'
** motions (speed s counted as s + s^2 / w, as behind_offset_line).  Three
** holes whose apexes lie 4e-9 apart: the third apex meets the line of a
** piece the first split made 3.7e-8 past its end (eps_d 2.8e-7); taken for
** a split, 6e-10 before the apex's true split of the neighbouring hole's
** edge, it joined the rings where CGAL's skeleton (and that of a finder
** that does not offer that piece) keeps them apart
** (tests/data/holes/near_touch_three_holes_passes_made_end.wpoly).  A hit
** before X starts (t < X's t0: X was made at a node of one seed, at that
** seed's later time, wavefront_group.c node_time) is none: the piece
** reaches X only then; the front apex of three holes 6e-10 apart met such
** a vertex at t = 3e-11, 1.2e-10 before it started, where CGAL's apex goes
** on (near_touch_three_holes_early_split*.wpoly). */
bool wf_made_end_passed(const wk_wavefront *W, const wk_wf_vertex *V, const wk_wf_vertex *X, wk_point p,
                        double s, double t) {
    if (!W->input_sides || X->t0 <= 0) return false;
    /* X starts later than t (a split's vertex at its node of one seed,
    ** node_time in wavefront_group.c): the piece reaches there only then */
    if (t < X->t0) return true;
    if (!(s < 0)) return false;
    wk_point px = wk_wf_pos(X, t);
    double sv = fabs(V->vel.x) + fabs(V->vel.y), sx = fabs(X->vel.x) + fabs(X->vel.y);
    double wv = fmin(W->L[V->ein].w, W->L[V->eout].w), wx = fmin(W->L[X->ein].w, W->L[X->eout].w);
    double bar = WK_SPLIT_SIDE_ULPS * DBL_EPSILON *
                 (fabs(p.x) + fabs(p.y) + fabs(px.x) + fabs(px.y) + fabs(X->p0.x) + fabs(X->p0.y) +
                  (sv + sv * sv / wv) * t + (sx + sx * sx / wx) * (t - X->t0));
    return -s > bar;
}

/* True if X, the end of a piece that vertex V would meet at time t within
** eps_d of X, was made at V's own node in the same group (same skeleton
** node, same start time) and t lies within eps_t of that: the pairing at the
** node put X's piece outside V's sector (it pairs pieces by their
** directions), so the hit is the tolerance's picture of the node itself,
** not an event.  Taken for a split, it rebuilt the same two vertices again
** and again: two reflex vertices of two rings meeting head-on 1e-12 .. 1e-11
** apart (weighted: a hole's apex above a notch's tip, or two holes' apexes)
** are one group of their two splits (and the edge event that follows
** within eps_t), which makes a reflex and a convex vertex at one node; the
** reflex one, started at the group's first time, lies on the convex one's
** line a few 1e-12 in front of it and "split" that piece eps_t later, at
** the same node (exit 2, "no progress", test_near_touch.py --sweep 3000 cases 1080,
** 1502, 1567, 1680, 2242, 2977; tests/data/holes/near_touch_sibling_*.wpoly).
** In the exact order the reflex vertex comes into being only at the edge
** event, already behind that line and moving away from it. */
static bool wf_sibling_end(const wk_wavefront *W, const wk_wf_vertex *V, const wk_wf_vertex *X, double t) {
    return V->t0 > 0 && X->t0 == V->t0 && X->node == V->node && t <= V->t0 + W->eps_t;
}

/* V (vi), behind the line of piece a by d0 < 0 at t_now and receding
** (rate < 0), crossed that line at t_c = t_now - d0 / rate.  If it then
** already existed, is behind by more than rounding, and an end of the
** piece was made after t_c (so the piece did not reach there at t_c; a
** split there would have been an event at t_c, not a late one), V
** passed the line beyond the piece's end of that time: the split the
** finders' clamp ("up to eps_d behind: a split now") would make is none.
** A 12-gon H with needles near (1e6, 1e6): reflex vertex 7 passed 1e-5
** beside the line of edge 3 beyond the crack's tip (vertex 3, speed
** 6.7e5) at t = 5e-6; the tip split edge 6 at t = 1.5e-5 on or next to
** vertex 7's track, and the new end of edge 3's piece put vertex 7 2e-5
** behind a piece it never met: split there, it closed a cycle (exit 3 in
** 4 variants with vertex 7 of speed 4.2e4, 0.41 past the split; in one
** with vertex 6 moved to x = 1e7, vertex 7 of speed 1.4 1e-5 beside it
** and shielded from its node, plan_slow_stretches).  CGAL's vertex 7
** runs on (tests/data/fuzz/invalid_naive_h_needles_fold*.wpoly). */
static bool wf_passed_before_piece(const wk_wavefront *W, uint32_t vi, uint32_t a, double d0,
                                   double rate) {
    const wk_wf_vertex *V = &W->v[vi];
    if (!(d0 < 0) || !(rate < 0)) return false;
    return wk_passed_line_before_piece(wk_wf_pos(V, W->t_now), W->t_now, d0, rate,
                                       speed_rounding(W, V), W->L[W->v[a].eout].w, V->t0,
                                       W->v[a].t0, W->v[W->v[a].next].t0);
}

bool wk_passed_line_before_piece(wk_point pv, double t_now, double d0, double rate,
                                 double speed_round, double w, double v_t0, double a_t0,
                                 double b_t0) {
    if (!(d0 < 0) || !(rate < 0)) return false;
    double tc = t_now - d0 / rate;
    /* behind by more than rounding (as behind_offset_line): t_c is real */
    double bar = WK_SPLIT_SIDE_ULPS * DBL_EPSILON *
                 (fabs(pv.x) + fabs(pv.y) + (speed_round + w) * t_now);
    if (!(v_t0 < tc) || !(-d0 > bar)) return false;
    return a_t0 > tc || b_t0 > tc;
}

void wk_wf_split_begin(const wk_wavefront *W, uint32_t v, wk_wf_split_search *s) {
    s->v = v;
    s->t = W->v[v].ev_t;
    s->p = W->v[v].ev_p;
    s->a = s->b = WK_NONE;
}

void wk_wf_split_test(const wk_wavefront *W, wk_wf_split_search *s, uint32_t a) {
    uint32_t vi = s->v;
    const wk_wf_vertex *V = &W->v[vi], *A = &W->v[a];
    uint32_t b = A->next;
    if (a == vi || b == vi) return; /* its own pieces */
    const wk_wf_vertex *B = &W->v[b];
    const wk_offset_line *L = &W->L[A->eout];
    double rate = L->nx * V->vel.x + L->ny * V->vel.y - L->w;
    if (rate >= -WK_APPROACH_REL * (L->w + fabs(V->vel.x) + fabs(V->vel.y))) return;
    /* A PSLG's initial wavefront touches itself: the two sides of a segment
    ** and the corners around a node start on each other's lines (and on
    ** the pieces the collinear rule extends at t = 0).  A vertex born at
    ** t = 0 on (or behind) the piece's line and moving behind it can meet
    ** that line only at t = 0 (its distance is linear in t), where a valid
    ** PSLG has no contact but these: its nodes keep WK_PSLG_MIN_CLEARANCE_REL
    ** (above eps_d) from the edges not at them.  No split. */
    if (W->P->pslg && V->t0 == 0 && wk_offset_distance(L, V->p0, 0) <= W->eps_d) return;
    /* An input vertex strictly behind the piece's input line, moving away
    ** from it, is within eps_d of it only because the input puts it there
    ** (a crack outside the polygon between them): no split, however close.
    ** A vertex 1.2 units beyond a needle's edge (at a scale of 1e13, eps_d
    ** 1e4) split it at t = 0 and closed a cycle, where the edge across the
    ** crack on its front side is the one it meets
    ** (tests/data/fuzz/invalid_weighted_needles_hexfloat.wpoly). */
    wk_point pv = wk_wf_pos(V, W->t_now);
    double d0 = wk_offset_distance(L, pv, W->t_now);
    if (d0 < -W->eps_d) return; /* already beyond the line: moving away */
    /* Asked only within eps_d of the line (the exact test costs an
    ** orientation per candidate, a quarter of a star's run when asked for
    ** all): a vertex more than eps_d in front of the offset line is not
    ** behind the input line, as the distance's rounding is far below eps_d. */
    if (d0 <= W->eps_d && wf_never_reaches_line(W, vi, A->eout)) return;
    if (wf_passed_before_piece(W, vi, a, d0, rate)) return;
    double t = W->t_now + (d0 > 0 ? d0 : 0) / -rate;
    if (t > s->t) return;
    wk_point p = wk_wf_pos(V, t), pa = wk_wf_pos(A, t), pb = wk_wf_pos(B, t);
    double sa = (p.x - pa.x) * L->ux + (p.y - pa.y) * L->uy;
    double sb = (pb.x - p.x) * L->ux + (pb.y - p.y) * L->uy;
    if (sa < -W->eps_d || sb < -W->eps_d) return;
    /* Rings that nearly touch: where an input vertex meets the line of a
    ** piece of another ring, within eps_d of an end that is an input
    ** vertex, follows from the input coordinates (wf_input_cut_side, as in
    ** plan_shields for a cut inside the piece).  Outside the piece by more
    ** than rounding, it passes that end: no split of this piece (of the
    ** neighbouring piece, if any, that piece's test says).  A hole's apex
    ** 7e-11 above a notch's tip meets the line of the tip's edge 4.5e-11
    ** beyond the tip, first; the event is the tip's split of the hole's
    ** edge (CGAL's).  Taken for a split, the apex's hit made the tolerance
    ** picture join the rings at a node whose new reflex vertex, between two
    ** edges 0.02 rad from parallel, starts within eps_d of the piece it was
    ** made next to, and split it at once, again and again ("no progress",
    ** tests/data/holes/near_touch_apex_passes_notch_tip.wpoly). */
    if (wf_other_ring(W, vi, A->eout) &&
        ((sa <= W->eps_d && wf_input_cut_side(W, vi, a, L, 0, t) < 0) ||
         (sb <= W->eps_d && wf_input_cut_side(W, vi, b, L, 1, t) < 0)))
        return;
    if (wf_other_ring(W, vi, A->eout) && wf_is_input_vertex(W, vi) &&
        ((sa <= W->eps_d && wf_made_end_passed(W, V, A, p, sa, t)) ||
         (sb <= W->eps_d && wf_made_end_passed(W, V, B, p, sb, t))))
        return;
    if ((sa <= W->eps_d && wf_sibling_end(W, V, A, t)) || (sb <= W->eps_d && wf_sibling_end(W, V, B, t)))
        return;
    /* Not in front of the line (a hit now only by the tolerance): a split
    ** that the group may resolve by pairing V's edges with each other, the
    ** piece passing through, is none: V's sector does not hold the piece's
    ** direction, it is behind the line.  Taken for a split, the group made
    ** V again, the same candidate with it, for ever: three holes whose
    ** apexes lie 1e-8 apart, weighted, turned (test_near_touch.py --sweep
    ** 3000 case 1941): the reflex vertex an edge event made 7e-8 from a
    ** vertex kept apart at an input-side node (gap_made) lay within eps_d
    ** behind the line of that vertex's piece; exit 2 (no progress) at the
    ** nominal tolerance, and the coarser retry's skeleton was not the one
    ** of the gaps magnified 10 and 100 times (nor a finder's that never
    ** offered the split; tests/data/holes/near_touch_split_pairs_through.wpoly). */
    if (d0 <= 0 && wf_split_changes_nothing(W, V->ein, V->eout, A->eout)) return;
    if (t == s->t && s->a != WK_NONE && a > s->a) return; /* deterministic tie */
    refine(W, V, V->ein, V->eout, A->eout, &t, &p);
    s->t = t;
    s->p = p;
    s->a = a;
    s->b = b;
}

void wk_wf_split_offer(wk_wavefront *W, const wk_wf_split_search *s) {
    wk_wf_offer_split(W, s->v, s->t, s->p, s->a, s->b);
}

wk_status wk_wf_reschedule_after_pieces_at(wk_wavefront *W, const uint32_t *vs, uint32_t n) {
    const uint32_t *fresh, *ended;
    uint32_t n_fresh, n_ended;
    wk_wf_last_group(W, &fresh, &n_fresh, &ended, &n_ended);
    bool changed = false;
    for (uint32_t i = 0; i < n && !changed; i++) {
        uint32_t c = vs[i];
        if (!wk_wf_alive(W, c)) continue;
        for (uint32_t j = 0; j < n_fresh && !changed; j++)
            changed = fresh[j] == c || fresh[j] == wk_wf_prev(W, c);
    }
    for (uint32_t v = 0; changed && v < wk_wf_vertex_count(W); v++)
        if (wk_wf_alive(W, v) && wk_wf_reflex(W, v) && wk_wf_reschedule(W, v) != WK_OK)
            return W->R->err.code;
    return WK_OK;
}

void wk_wf_split_at_vertices(wk_wavefront *W, uint32_t v, const uint32_t *vs, uint32_t n) {
    wk_wf_split_search s;
    bool any = false;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t c = vs[i];
        if (c == v || !wk_wf_alive(W, c)) continue;
        if (!any) wk_wf_split_begin(W, v, &s);
        any = true;
        wk_wf_split_test(W, &s, wk_wf_prev(W, c));
        wk_wf_split_test(W, &s, c);
    }
    if (any) wk_wf_split_offer(W, &s);
}

static wk_status schedule(wk_wavefront *W, uint32_t vi) {
    wk_wf_vertex *V = &W->v[vi];
    double t = V->ev_t;
    if (V->ev_kind == WK_WF_NONE || !isfinite(t)) {
        wk_event_queue_remove(W->R, &W->Q, vi);
        return WK_OK;
    }
    if (t < W->t_now) t = W->t_now;
    return wk_event_queue_set(W->R, &W->Q, vi, (wk_event_key){t, V->ev_kind});
}

/* The speed that matters for vi's candidate: its own, and for an edge
** event the faster of the piece's two ends. */
static double event_speed(const wk_wavefront *W, uint32_t vi) {
    const wk_wf_vertex *V = &W->v[vi];
    double s = fabs(V->vel.x) + fabs(V->vel.y);
    if (V->ev_kind == WK_WF_EDGE) {
        const wk_wf_vertex *B = &W->v[V->next];
        double sb = fabs(B->vel.x) + fabs(B->vel.y);
        if (sb > s) s = sb;
    }
    return s;
}

/* Full recomputation of vi's candidate: its edge event and, if reflex, the
** split event the finder reports. */
static void full_candidate(wk_wavefront *W, uint32_t vi) {
    wk_wf_vertex *V = &W->v[vi];
    double t;
    wk_point p = {0, 0};
    edge_event(W, vi, &t, &p);
    V->ev_kind = isfinite(t) ? WK_WF_EDGE : WK_WF_NONE;
    V->ev_t = t;
    V->ev_p = p;
    V->ev_a = vi;
    V->ev_b = V->next;
    V->cand_next = V->next;
    V->fresh = 0;
    if (V->reflex) W->finder->full(W->finder_ud, W, vi);
}

void wk_wf_split_scan(wk_wavefront *W, uint32_t vi) {
    wk_wf_split_search s;
    wk_wf_split_begin(W, vi, &s);
    if (W->P->n_rings == 1) {
        /* one ring: a split cuts a cycle in two, so only vi's own cycle can
        ** be hit */
        for (uint32_t a = W->v[vi].next; a != vi; a = W->v[a].next) wk_wf_split_test(W, &s, a);
    } else {
        /* holes: vi may hit a piece of another cycle (a split then joins
        ** the two cycles), so every alive piece is a candidate.  A cycle
        ** already cut off from vi's region is harmless: vi would have to
        ** cross its own cycle first, an earlier event. */
        for (uint32_t a = 0; a < W->nv; a++)
            if (a != vi && W->v[a].alive) wk_wf_split_test(W, &s, a);
    }
    wk_wf_split_offer(W, &s);
}

void wk_wf_offer_split(wk_wavefront *W, uint32_t vi, double t, wk_point p, uint32_t a, uint32_t b) {
    wk_wf_vertex *V = &W->v[vi];
    if (a == WK_NONE || !(t < V->ev_t)) return;
    /* The finders clamp a vertex up to eps_d behind the line to a split
    ** now; an input vertex exactly behind the line never meets it (as in
    ** wk_wf_split_test). */
    const wk_offset_line *L = &W->L[W->v[a].eout];
    double d0 = wk_offset_distance(L, wk_wf_pos(V, W->t_now), W->t_now);
    double rate = L->nx * V->vel.x + L->ny * V->vel.y - L->w;
    /* A vertex that does not approach the piece's offset line (moving along
    ** it or away from it, WK_APPROACH_REL as in wk_wf_split_test) never
    ** meets the piece by its own motion: only an end of the piece can run
    ** into it, and that is the end's event.  A finder that measures the
    ** meeting along v's track offered it anyway: in a cross with vertices
    ** pulled out to 5e11 and 3.4e10, a reflex vertex whose outgoing edge is
    ** collinear with a far edge (both on y = 1) moves along that edge's
    ** offset line and was offered a split of it at t = 0, 4.3e10 short of
    ** the piece; the group's progress guarantee (wavefront_group.c,
    ** plan_seed_cuts) pulled the piece's end to the node, and the skeleton
    ** had a node at t = 0 5e8 from its edge's line (exit 3; issue 11,
    ** tests/data/fuzz/invalid_arrangement_cross_far_collinear.wpoly). */
    if (rate >= -WK_APPROACH_REL * (L->w + fabs(V->vel.x) + fabs(V->vel.y))) return;
    if (vi < W->P->n && V->t0 == 0 && d0 < 0 && wf_never_reaches_line(W, vi, W->v[a].eout)) return;
    if (wf_passed_before_piece(W, vi, a, d0, rate)) return;
    V->ev_kind = WK_WF_SPLIT;
    V->ev_t = t;
    V->ev_p = p;
    V->ev_a = a;
    V->ev_b = b;
}

wk_status wk_wf_reschedule(wk_wavefront *W, uint32_t vi) {
    full_candidate(W, vi);
    return schedule(W, vi);
}

/* True if the piece V's candidate refers to still exists. */
static bool target_alive(const wk_wavefront *W, const wk_wf_vertex *V) {
    if (V->ev_kind == WK_WF_NONE) return true; /* nothing to lose */
    const wk_wf_vertex *A = &W->v[V->ev_a];
    return A->alive && A->next == V->ev_b;
}

/* ------------------------------------------------- the finder's view */

wk_run *wk_wf_run(const wk_wavefront *W) { return W->R; }
const wk_polygon *wk_wf_polygon(const wk_wavefront *W) { return W->P; }
double wk_wf_now(const wk_wavefront *W) { return W->t_now; }
double wk_wf_eps_d(const wk_wavefront *W) { return W->eps_d; }
double wk_wf_eps_t(const wk_wavefront *W) { return W->eps_t; }
const wk_offset_line *wk_wf_line(const wk_wavefront *W, uint32_t e) { return &W->L[e]; }
uint32_t wk_wf_vertex_count(const wk_wavefront *W) { return W->nv; }
bool wk_wf_alive(const wk_wavefront *W, uint32_t v) { return W->v[v].alive; }
bool wk_wf_reflex(const wk_wavefront *W, uint32_t v) { return W->v[v].reflex; }
uint32_t wk_wf_next(const wk_wavefront *W, uint32_t v) { return W->v[v].next; }
uint32_t wk_wf_prev(const wk_wavefront *W, uint32_t v) { return W->v[v].prev; }
uint32_t wk_wf_edge_out(const wk_wavefront *W, uint32_t v) { return W->v[v].eout; }
double wk_wf_start_time(const wk_wavefront *W, uint32_t v) { return W->v[v].t0; }
wk_point wk_wf_position(const wk_wavefront *W, uint32_t v, double t) { return wk_wf_pos(&W->v[v], t); }
wk_point wk_wf_velocity(const wk_wavefront *W, uint32_t v) { return W->v[v].vel; }

void wk_wf_last_group(const wk_wavefront *W, const uint32_t **fresh, uint32_t *n_fresh,
                      const uint32_t **ended, uint32_t *n_ended) {
    *fresh = W->fresh;
    *n_fresh = W->n_fresh;
    *ended = W->dead;
    *n_ended = W->n_dead;
}

/* ---------------------------------------------------------- simulation */

/* After a group: new candidates for fresh vertices, their predecessors and
** every reflex vertex of the touched cycles (with holes: of every cycle). */
static wk_status refresh(wk_wavefront *W) {
    wk_run *R = W->R;
    W->stamp++;
    /* A seed the group passed by (a split that met its piece's end only at
    ** the tolerance, shielded from the node: wavefront_group.c,
    ** plan_slow_stretches) is still alive, its candidate popped and its
    ** target piece possibly gone: a new candidate. */
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        uint32_t u = W->seeds[i];
        if (!W->v[u].alive || W->v[u].seen == W->stamp) continue;
        W->v[u].seen = W->stamp;
        full_candidate(W, u);
        if (schedule(W, u) != WK_OK) return R->err.code;
    }
    if (W->finder->local_refresh) {
        /* The finder keeps its split candidates current itself: only the
        ** fresh vertices and the ones whose next changed need new
        ** candidates, and a predecessor's edge event depends on its next. */
        for (uint32_t i = 0; i < W->n_fresh; i++) {
            uint32_t f = W->fresh[i];
            if (!W->v[f].alive) continue;
            uint32_t two[2] = {f, W->v[f].prev};
            for (int j = 0; j < 2; j++) {
                wk_wf_vertex *U = &W->v[two[j]];
                if (U->seen == W->stamp) continue;
                U->seen = W->stamp;
                full_candidate(W, two[j]);
                if (schedule(W, two[j]) != WK_OK) return R->err.code;
            }
        }
        /* With holes a candidate may target a piece of another cycle that
        ** the finder does not follow (one found by the split test's scan
        ** rather than by the finder's own structure): when this group ended
        ** that piece, the candidate is recomputed.  A stale one was resolved
        ** as a split of a piece that no longer existed (a local-refresh finder, a hole
        ** whose vertex targeted a piece of another hole that a third hole's
        ** split had just ended: tests/test_near_touch.py --sweep 1000, case
        ** 696).  O(vertices) per group with holes only, as the walk below. */
        if (W->P->n_rings > 1 && W->n_fresh > 0)
            for (uint32_t u = 0; u < W->nv; u++) {
                wk_wf_vertex *U = &W->v[u];
                if (!U->alive || U->seen == W->stamp || target_alive(W, U)) continue;
                U->seen = W->stamp;
                full_candidate(W, u);
                if (schedule(W, u) != WK_OK) return R->err.code;
            }
        return WK_OK;
    }
    for (uint32_t i = 0; i < W->n_fresh; i++) {
        uint32_t f = W->fresh[i];
        if (!W->v[f].alive || W->v[f].seen == W->stamp) continue;
        uint32_t u = f;
        do {
            wk_wf_vertex *U = &W->v[u];
            U->seen = W->stamp;
            if (U->fresh || U->next != U->cand_next || !target_alive(W, U)) {
                full_candidate(W, u);
            } else if (U->reflex) {
                W->finder->incremental(W->finder_ud, W, u);
            }
            if (schedule(W, u) != WK_OK) return R->err.code;
            u = U->next;
        } while (u != f);
    }
    /* With holes a reflex vertex may hit a piece of another cycle (a split
    ** joins them), and the fresh pieces can be anywhere: the reflex
    ** vertices of the cycles the group did not touch are tested against
    ** them too (O(vertices) per group; with one ring a split only ever
    ** hits the vertex's own cycle, walked above).  Missing this left a
    ** hole's reflex vertex blind to a piece that another join had just made
    ** (weights 0.25..10: 11 of 987 generated polygons with holes ended in
    ** "no progress"). */
    if (W->P->n_rings > 1 && W->n_fresh > 0)
        for (uint32_t u = 0; u < W->nv; u++) {
            wk_wf_vertex *U = &W->v[u];
            if (!U->alive || U->seen == W->stamp || !U->reflex) continue;
            U->seen = W->stamp;
            if (!target_alive(W, U)) full_candidate(W, u);
            else W->finder->incremental(W->finder_ud, W, u);
            if (schedule(W, u) != WK_OK) return R->err.code;
        }
    return WK_OK;
}

/* The invariants of wavefront_internal.h over the whole wavefront, O(nv +
** queue): every alive vertex's neighbours are alive and point back, every
** cycle has at least 3 vertices, each vertex lies on the offset lines of
** both its edges (within the tolerance its own speed allows), and every
** alive vertex with a finite candidate is queued.  The queue's heap order
** is checked by the queue. */
static wk_status check_invariants(wk_wavefront *W) {
    wk_run *R = W->R;
    const char *name = W->P->name;
    double t = W->t_now;
    W->stamp++;
    for (uint32_t v = 0; v < W->nv; v++) {
        const wk_wf_vertex *V = &W->v[v];
        if (!V->alive) continue;
        if (!W->v[V->next].alive || !W->v[V->prev].alive || W->v[V->next].prev != v)
            return WK_FAIL(R, WK_EALGO, name, 0, "invariant: vertex %u's cycle is broken at t = %.17g", v, t);
        wk_point p = wk_wf_pos(V, t);
        double speed = fabs(V->vel.x) + fabs(V->vel.y);
        double tol = WK_INVARIANT_SLACK * (W->eps_d + speed * W->eps_t) * (1 + t);
        double din = fabs(wk_offset_distance(&W->L[V->ein], p, t));
        double dout = fabs(wk_offset_distance(&W->L[V->eout], p, t));
        if (V->vkind != WK_VEL_ANTIPARALLEL && (din > tol || dout > tol))
            return WK_FAIL(R, WK_EALGO, name, 0,
                           "invariant: vertex %u is %.3g / %.3g off its edges' offset lines at t = %.17g",
                           v, din, dout, t);
        if (V->ev_kind != WK_WF_NONE && isfinite(V->ev_t) && !wk_event_queue_contains(&W->Q, v))
            return WK_FAIL(R, WK_EALGO, name, 0, "invariant: vertex %u's candidate is not queued", v);
        if (V->seen == W->stamp) continue;
        uint32_t len = 0, u = v;
        do {
            W->v[u].seen = W->stamp;
            u = W->v[u].next;
        } while (u != v && ++len <= W->nv);
        if (len + 1 < 3 || len > W->nv)
            return WK_FAIL(R, WK_EALGO, name, 0, "invariant: a cycle of %u vertices at t = %.17g", len + 1, t);
    }
    if (!wk_event_queue_check(&W->Q))
        return WK_FAIL(R, WK_EALGO, name, 0, "invariant: the event queue is out of order");
    if (W->finder->check && W->finder->check(W->finder_ud, W) != WK_OK) return R->err.code;
    return WK_OK;
}

/* Resolve the group at time t, let the finder see what changed, then give
** the touched vertices new candidates. */
static wk_status process_group(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    if (wf_resolve_group(W, t) != WK_OK) return R->err.code;
    if (W->finder->after_group && W->finder->after_group(W->finder_ud, W, t) != WK_OK)
        return R->err.code;
    if (refresh(W) != WK_OK) return R->err.code;
    return R->opt.check_invariants ? check_invariants(W) : WK_OK;
}

static wk_status simulate(wk_wavefront *W) {
    wk_run *R = W->R;
    const wk_polygon *P = W->P;
    uint32_t n = P->n;
    /* the initial wavefront: one vertex per input vertex, one cycle per
    ** ring (holes are stored clockwise, so the interior is left of every
    ** piece and every cycle moves the same way) */
    for (uint32_t i = 0; i < n; i++) {
        wk_point q = {P->p[i].x - W->origin.x, P->p[i].y - W->origin.y};
        uint32_t id = wf_new_vertex(W, wk_polygon_prev(P, i), i, q, 0.0, i);
        if (id == WK_NONE) return R->err.code;
    }
    for (uint32_t i = 0; i < n; i++) wf_link(W, i, wk_polygon_next(P, i));
    W->t_now = W->t_group = 0;
    W->n_fresh = 0;
    W->n_dead = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (W->v[i].vkind == WK_VEL_COLLINEAR && wf_collinear_rule(W, i, 0.0) != WK_OK) return R->err.code;
        if (W->v[i].alive && W->v[i].vkind == WK_VEL_ANTIPARALLEL)
            return WK_FAIL(R, WK_EALGO, P->name, 0, "wavefront: input vertex %u is a spike", i);
    }
    if (wk_event_queue_reserve(R, &W->Q, 2 * n + 16) != WK_OK) return R->err.code;
    if (W->finder->start && W->finder->start(W->finder_ud, W) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < W->nv; i++) {
        if (!W->v[i].alive) continue;
        full_candidate(W, i);
        if (schedule(W, i) != WK_OK) return R->err.code;
    }
    uint64_t same_time = 0;
    double stop = P->pslg ? wf_event_limit(W) : INFINITY;
    bool pslg_default = P->pslg && !(R->opt.until > 0), stop_final = false;
    for (;;) {
        double tq = W->Q.size ? wk_event_queue_time(&W->Q, wk_event_queue_peek(&W->Q)) : INFINITY;
        double tf = W->finder->next_time ? W->finder->next_time(W->finder_ud) : INFINITY;
        if (!isfinite(tf)) tf = INFINITY;
        double tn = tf <= tq ? tf : tq;
        if (tn == INFINITY) break;
        /* a PSLG's horizon: events after it are not part of the skeleton;
        ** the default one is set after the last group before the limit, and
        ** the events up to it still count.  A finder's own events count as
        ** the wavefront's here (they may reveal one at their time or later)
        ** but set no horizon (t_group) */
        if (tn > stop) {
            if (!pslg_default || stop_final) break;
            stop = wf_default_horizon(W);
            stop_final = true;
            if (tn > stop) break;
        }
        /* the finder's own events (e.g. 000's start and switch events) go first when
        ** they are not later than the next wavefront event */
        if (tf <= tq) {
            if (tf > W->t_now) W->t_now = tf;
            if (W->finder->process_next(W->finder_ud, W) != WK_OK) return R->err.code;
            continue;
        }
        uint32_t first = wk_event_queue_pop(R, &W->Q);
        double t = W->v[first].ev_t;
        if (t < W->t_now) t = W->t_now;
        same_time = (t <= W->t_now + W->eps_t) ? same_time + 1 : 0;
        if (same_time > 4 * (uint64_t)P->n + 64)
            return WK_FAIL(R, WK_EALGO, P->name, 0, "wavefront: no progress at t = %.17g", t);
        W->t_now = W->t_group = t;
        W->n_seeds = 0;
        if (wf_push_u32(R, &W->seeds, &W->n_seeds, &W->cap_seeds, first) != WK_OK) return R->err.code;
        W->t_last = t;
        W->n_deferred = 0;
        while (W->Q.size) {
            uint32_t id = wk_event_queue_peek(&W->Q);
            double te = wk_event_queue_time(&W->Q, id);
            if (te > t + W->eps_t) break;
            wk_event_queue_pop(R, &W->Q);
            /* Simultaneous means within eps_t, as long as the vertices of
            ** the event move less than eps_d in between: a vertex of speed
            ** s covers s (te - t), and one faster than WK_TOL_TIME^-1 wmax
            ** would be resolved where it is not yet.  Such an event waits
            ** for its own group (the tip of a needle 1e6 long, speed 1e12,
            ** reaching the slow end of its needle 4e-11 after the other
            ** tip event and 39 units away; a reflex vertex of speed 4e5
            ** resolved 9e-6 early, 3.6 units short of the piece it splits:
            ** the fuzz finding of an H at 1e6 with needles 1e5..8e6 long, issue 11). */
            if ((te - t) * event_speed(W, id) > W->eps_d) {
                if (wf_push_u32(R, &W->deferred, &W->n_deferred, &W->cap_deferred, id) != WK_OK)
                    return R->err.code;
                continue;
            }
            if (te > W->t_last) W->t_last = te;
            if (wf_push_u32(R, &W->seeds, &W->n_seeds, &W->cap_seeds, id) != WK_OK)
                return R->err.code;
        }
        for (uint32_t i = 0; i < W->n_deferred; i++)
            if (schedule(W, W->deferred[i]) != WK_OK) return R->err.code;
        if (process_group(W, t) != WK_OK) return R->err.code;
    }
    /* A PSLG's outer wavefront never vanishes: what is alive at the
    ** horizon ends there (wavefront_horizon.c). */
    if (P->pslg)
        return wf_close_at_horizon(W, R->opt.until > 0 ? R->opt.until
                                      : stop_final     ? stop
                                                       : wf_default_horizon(W));
    for (uint32_t i = 0; i < W->nv; i++)
        if (W->v[i].alive) {
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "wavefront: wavefront vertex %u still alive when the queue ran empty", i);
        }
    return WK_OK;
}

wk_status wk_wavefront_run(wk_run *R, const wk_polygon *P, const wk_split_finder *finder,
                           void *finder_ud, wk_skeleton **out) {
    wk_wavefront W;
    memset(&W, 0, sizeof W);
    W.finder = finder;
    W.finder_ud = finder_ud;
    W.R = R;
    W.P = P;
    wk_event_queue_init(&W.Q);
    double wmax = 0;
    for (uint32_t i = 0; i < P->n; i++) wmax = P->w[i] > wmax ? P->w[i] : wmax;
    W.eps_d = R->opt.tol_scale * WK_TOL_REL * wk_polygon_scale(P);
    /* tolerance.h: eps_d and eps_t */
    W.eps_t = WK_TOL_TIME * W.eps_d / wmax;
    W.eps_g = W.eps_gmax = W.eps_d;
    /* A polygon with two rings whose vertices lie 3e-10 apart (a hole at a
    ** notch's tip, weighted: tests/test_near_touch.py case 32) has a cascade of sub-tolerance events after
    ** the first split resolved on the input's side, which the tolerance
    ** picture then closes into a cycle; at 4 eps_d, with the gap closed as
    ** the tolerance sees it, the skeleton is valid. */
    W.input_sides = R->opt.tol_scale <= 1;
    wk_status st = WK_OK;
    W.L = WK_NEW_ARRAY(R, wk_offset_line, P->n);
    if (!W.L) {
        st = R->err.code;
        goto done;
    }
    W.origin = wk_polygon_centre(P);
    for (uint32_t i = 0; i < P->n; i++) wk_offset_line_of_edge_at(P, i, W.origin, &W.L[i]);
    if ((st = wk_skeleton_new(R, P, &W.S)) != WK_OK) goto done;
    W.S->cap_hint = wf_size_hint(&W);
    if (P->pslg && (st = wf_check_horizon(&W)) != WK_OK) goto done;
    st = simulate(&W);
    if (st == WK_OK) st = wk_skeleton_merge_pass_through(R, W.S);
done:
    wk_event_queue_clear(R, &W.Q);
    WK_FREE_ARRAY(R, W.L, P->n);
    WK_FREE_ARRAY(R, W.v, W.cap_v);
    WK_FREE_ARRAY(R, W.seeds, W.cap_seeds);
    WK_FREE_ARRAY(R, W.forced, W.cap_forced);
    WK_FREE_ARRAY(R, W.swept, W.cap_swept);
    WK_FREE_ARRAY(R, W.comp, W.cap_comp);
    WK_FREE_ARRAY(R, W.cl, W.cap_cl);
    WK_FREE_ARRAY(R, W.wide, W.cap_wide);
    WK_FREE_ARRAY(R, W.pin, W.cap_pin);
    WK_FREE_ARRAY(R, W.sub, W.cap_sub);
    WK_FREE_ARRAY(R, W.pair, W.cap_pair);
    WK_FREE_ARRAY(R, W.slot, W.cap_slot);
    WK_FREE_ARRAY(R, W.fresh, W.cap_fresh);
    WK_FREE_ARRAY(R, W.cycflag, W.cap_cycflag);
    WK_FREE_ARRAY(R, W.run, W.cap_run);
    WK_FREE_ARRAY(R, W.run_node, W.cap_run_node);
    WK_FREE_ARRAY(R, W.dead, W.cap_dead);
    WK_FREE_ARRAY(R, W.shield, W.cap_shield);
    WK_FREE_ARRAY(R, W.shield_ix, W.cap_shield_ix);
    WK_FREE_ARRAY(R, W.shield_older, W.cap_shield_older);
    WK_FREE_ARRAY(R, W.pin_ix, W.cap_pin_ix);
    WK_FREE_ARRAY(R, W.deferred, W.cap_deferred);
    wk_point_grid_free(R, &W.cg);
    wk_point_grid_free(R, &W.vg);
    WK_FREE_ARRAY(R, W.by_from, W.cap_by_from);
    if (st != WK_OK) {
        wk_skeleton_free(R, W.S);
        return st;
    }
    *out = W.S;
    return WK_OK;
}
