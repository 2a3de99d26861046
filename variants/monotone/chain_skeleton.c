/*
** chain_skeleton.c: the weighted skeleton of one monotone chain extended by
** rays (001 section 2).
**
** Model.  The wavefront of a chain is a path of vertices (prev/next ids,
** WK_NONE beyond the two rays); vertex v sits between chain edges ein and
** eout and moves linearly from its start node, exactly as in the naive
** variant (same offset lines, same velocities, same snapping of new
** vertices onto both offset lines).  001 Lemma 1: the wavefront of a
** monotone chain stays monotone, so every change is an edge collapse: the
** only candidate event of v is the collapse of its outgoing piece v -> next,
** kept in an indexed heap (engine/event_queue.h) under v's id; an event
** touches two neighbours only, so the simulation is O(m log m).
**
** Resolution of one collapse at node N (time t), in this order, until a
** vertex with a proper velocity is born:
**   1. absorb: a neighbour within tolerance of N arrives there too (several
**      pieces vanishing at one point, 001's "vertex events");
**   2. regular or straight (parallel, equal weights): the new vertex;
**   3. collinear (parallel, different weights): the engine's rule
**      (R->opt.collinear): the losing edge's piece is swept at once, leaving
**      a flat trace along it; its far vertex arrives at its far end, which
**      becomes the new N;
**   4. antiparallel (only in a non-strictly monotone chain: two walls
**      perpendicular to the sweep facing each other): the two pieces lie on
**      one line and cancel where they overlap, leaving a flat trace from N to
**      the nearer far end, where that far vertex (both, if equally far)
**      arrives; that point becomes the new N.
** A losing piece or an antiparallel pair that is a ray has no far end: the
** flat trace is infinite and the winner becomes the chain's end ray.
**
** Tolerances as in wskel.h: a vertex arrives at N when it is within eps_d
** plus its speed times eps_t.
*/
#include "monotone.h"

#include <math.h>
#include <string.h>

typedef struct sim {
    mono *M;
    mono_chain *C;
    wk_event_queue Q;
    double t_now;
    /* scratch of collinear_rule: the run's vertices, pieces, nodes and the
    ** vertices to schedule afterwards */
    uint32_t *run_v, *run_e, *run_nd, *run_sched;
    uint32_t cap_run_v, cap_run_e, cap_run_nd, cap_run_sched;
} sim;

uint32_t wk_mono_chain_local(const mono *M, const mono_chain *C, uint32_t e) {
    uint32_t n = M->P->n, k = (e + n - C->first) % n;
    return k < C->m ? k : WK_NONE;
}

wk_point wk_mono_trace_at(const mono_trace *v, double t) {
    if (v->flat) return v->p0;
    if (t > v->t1) t = v->t1;
    double dt = t - v->t0;
    return (wk_point){v->p0.x + v->vel.x * dt, v->p0.y + v->vel.y * dt};
}

static double dist2(wk_point a, wk_point b) {
    double dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

void wk_mono_chain_clear(wk_run *R, mono_chain *C) {
    WK_FREE_ARRAY(R, C->v, C->cap_v);
    WK_FREE_ARRAY(R, C->node, C->cap_n);
    WK_FREE_ARRAY(R, C->lw_start, C->m + 1);
    WK_FREE_ARRAY(R, C->rw_start, C->m + 1);
    WK_FREE_ARRAY(R, C->lw, C->n_lw);
    WK_FREE_ARRAY(R, C->rw, C->n_rw);
    C->nv = C->cap_v = C->nn = C->cap_n = C->n_lw = C->n_rw = 0;
}

static uint32_t new_node(sim *S, wk_point p, double t, uint32_t input) {
    mono_chain *C = S->C;
    if (WK_GROW(S->M->R, C->node, C->cap_n, C->nn + 1) != WK_OK) return WK_NONE;
    C->node[C->nn] = (mono_node){p, t, input};
    return C->nn++;
}

/* A new trace starting at node `node` (point p, time t).  Snaps the start
** onto both offset lines when that is well conditioned (as naive does), so
** later events depend on the input lines rather than on this one's
** rounding. */
static uint32_t new_trace(sim *S, uint32_t ein, uint32_t eout, wk_point p, double t,
                          uint32_t node) {
    mono_chain *C = S->C;
    const wk_offset_line *L = S->M->L;
    if (WK_GROW(S->M->R, C->v, C->cap_v, C->nv + 1) != WK_OK) return WK_NONE;
    if (C->nv + 1 > S->Q.cap &&
        wk_event_queue_reserve(S->M->R, &S->Q, 2 * S->Q.cap + 16) != WK_OK)
        return WK_NONE;
    uint32_t id = C->nv++;
    mono_trace *x = &C->v[id];
    memset(x, 0, sizeof *x);
    x->ein = ein;
    x->eout = eout;
    x->t0 = t;
    x->t1 = INFINITY;
    x->start = node;
    x->end = WK_NONE;
    x->prev = x->next = WK_NONE;
    x->alive = 1;
    x->ev_t = INFINITY;
    bool reflex;
    /* snapped within WK_MONO_EXACT_SLACK eps_d: see refine */
    x->kind = (uint8_t)wk_vertex_start(L, ein, eout, p, t, WK_MONO_EXACT_SLACK * S->M->eps_d,
                                       &x->p0, &x->vel, &reflex);
    x->reflex = reflex;
    return id;
}

/* A flat trace (an arc swept at one instant) from node a along unit vector
** u to node b (WK_NONE: infinite). */
static uint32_t new_flat(sim *S, uint32_t ein, uint32_t eout, uint32_t a, uint32_t b, wk_point u,
                         double t) {
    uint32_t id = new_trace(S, ein, eout, S->C->node[a].p, t, a);
    if (id == WK_NONE) return WK_NONE;
    mono_trace *x = &S->C->v[id];
    x->flat = 1;
    x->vel = u;
    x->alive = 0;
    x->t1 = t;
    x->end = b;
    return id;
}

static void terminate(sim *S, uint32_t x, uint32_t node) {
    mono_trace *v = &S->C->v[x];
    v->alive = 0;
    v->end = node;
    v->t1 = S->C->node[node].t;
    if (v->t1 < v->t0) v->t1 = v->t0;
    wk_event_queue_remove(S->M->R, &S->Q, x);
}

/* Replace a kinematic estimate by the meeting point of three offset lines
** when that system is well conditioned and agrees (as naive's refine). */
static void refine(const sim *S, const mono_trace *V, uint32_t e1, uint32_t e2, uint32_t e3,
                   double *t, wk_point *p) {
    const mono *M = S->M;
    if (e1 == e2 || e2 == e3 || e1 == e3 || V->kind != WK_VEL_REGULAR) return;
    wk_point q;
    double tq;
    if (!wk_three_lines_meet(&M->L[e1], &M->L[e2], &M->L[e3], &q, &tq)) return;
    /* The kinematic estimate extrapolates positions since the vertex was
    ** born, so its error grows with the vertex's speed and age (vertices
    ** between nearly parallel edges are fast); the window grows alike
    ** (tolerance.h, "chain skeletons and their merge"). */
    double speed = fabs(V->vel.x) + fabs(V->vel.y);
    double age = *t - V->t0 > 0 ? *t - V->t0 : 0;
    double wt = WK_REFINE_TIME_SLACK * M->eps_t + WK_MONO_REFINE_AGE_REL * age;
    double wd = WK_REFINE_DIST_SLACK * M->eps_d * (1 + speed) +
                WK_MONO_REFINE_AGE_REL * age * (1 + speed);
    if (fabs(tq - *t) > wt || dist2(q, *p) > wd * wd) return;
    if (tq < S->t_now) tq = S->t_now;
    *t = tq;
    *p = q;
}

/* Candidate collapse of the piece a -> a.next and its queue entry. */
static wk_status schedule(sim *S, uint32_t a) {
    mono_trace *A = &S->C->v[a];
    A->ev_t = INFINITY;
    if (!A->alive || A->next == WK_NONE) {
        wk_event_queue_remove(S->M->R, &S->Q, a);
        return WK_OK;
    }
    const mono_trace *B = &S->C->v[A->next];
    const wk_offset_line *L = &S->M->L[A->eout];
    double t0 = S->t_now;
    wk_point pa = wk_mono_trace_at(A, t0), pb = wk_mono_trace_at(B, t0);
    double d = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
    double rate = (B->vel.x - A->vel.x) * L->ux + (B->vel.y - A->vel.y) * L->uy;
    double t;
    /* as the reference's edge events: a piece below eps_d collapses now
    ** unless it shrinks so slowly that now would be more than eps_t early */
    if (d <= S->M->eps_d && rate <= 0 && (d <= 0 || -rate * S->M->eps_t >= d || rate == 0)) t = t0;
    else if (rate < 0) t = t0 + (d > 0 ? d : 0) / -rate;
    else {
        wk_event_queue_remove(S->M->R, &S->Q, a);
        return WK_OK;
    }
    if (!isfinite(t)) {
        wk_event_queue_remove(S->M->R, &S->Q, a);
        return WK_OK;
    }
    wk_point qa = wk_mono_trace_at(A, t), qb = wk_mono_trace_at(B, t);
    wk_point p = {0.5 * (qa.x + qb.x), 0.5 * (qa.y + qb.y)};
    if (B->kind == WK_VEL_REGULAR) refine(S, A, A->ein, A->eout, B->eout, &t, &p);
    A->ev_t = t;
    A->ev_p = p;
    return wk_event_queue_set(S->M->R, &S->Q, a, (wk_event_key){t, 0});
}

/* Does vertex x take part in the event at `at`, time t?  Within eps_d, plus
** what x moves within the time tolerance (the event's time is constructed).
** At t = 0 (the collinear rule on input vertices) the time is exact and x
** is at its input vertex: no time slack.  With it, the input vertex next to
** a collinear pair, between edges at sine 4e-8 with weights 1 and 3 (speed
** 5e7, so 416 units within eps_t, 99 away), was taken as arriving: the
** pair's swept piece went to the wrong face, unlike the reference's rule
** (tests/data/fuzz/mismatch_monotone_collinear_sliver.wpoly). */
static bool arrives(const sim *S, uint32_t x, wk_point at, double t) {
    const mono_trace *v = &S->C->v[x];
    double speed = fabs(v->vel.x) + fabs(v->vel.y);
    double r = S->M->eps_d + (t > 0 ? speed * S->M->eps_t : 0);
    return dist2(wk_mono_trace_at(v, t), at) <= r * r;
}

/* ... unless the stretch of line e (ein for x = P before the vertex being
** born at `at` between ein and eout, eout for x = Q after it) collapses
** later (wk_stretch_collapses_later; the reference's group resolution,
** plan_slow_stretches in engine/wavefront_group.c, decides alike). */
static bool arrives_now(const sim *S, uint32_t x, wk_point at, double t, uint32_t ein,
                        uint32_t eout, bool x_after) {
    if (!arrives(S, x, at, t)) return false;
    const mono_trace *v = &S->C->v[x];
    wk_point vq;
    /* at the nominal tolerance and finer only, as the reference (its
    ** coarser retries keep the tolerance picture) */
    if (t <= 0 || v->flat || S->M->R->opt.tol_scale > 1 ||
        wk_vertex_velocity(&S->M->L[ein], &S->M->L[eout], &vq) != WK_VEL_REGULAR)
        return true;
    return !wk_stretch_collapses_later(&S->M->L[x_after ? eout : ein], at, vq,
                                       wk_mono_trace_at(v, t), v->vel, x_after, S->M->eps_t);
}

static void link(sim *S, uint32_t a, uint32_t b) {
    if (a != WK_NONE) S->C->v[a].next = b;
    if (b != WK_NONE) S->C->v[b].prev = a;
}

/* A live vertex between two parallel pieces of the same sense (collinear or
** straight): it lies inside a run of pieces on one line. */
static bool on_one_line(const mono_trace *v) {
    return v->alive && (v->kind == WK_VEL_COLLINEAR || v->kind == WK_VEL_STRAIGHT);
}

/* The node where run vertex i is at time t, made once (as naive's run_node):
** its own start node if it was born now, else a new node at its place. */
static uint32_t run_node(sim *S, uint32_t i, double t) {
    if (S->run_nd[i] == WK_NONE) {
        const mono_trace *U = &S->C->v[S->run_v[i]];
        S->run_nd[i] = U->t0 == t ? U->start : new_node(S, wk_mono_trace_at(U, t), t, WK_NONE);
    }
    return S->run_nd[i];
}

/* The collinear rule at node `node` (time t), where a vertex between
** parallel edges ein and eout of different weight would be born (P before
** it, Q after it).  As the reference's wf_collinear_rule, so that the
** skeletons agree: take the maximal run of pieces on that line (through live
** straight or collinear vertices on both sides, not just the pair: three or
** more weights can meet at once); the winning weight (lowest by default,
** highest with --collinear higher) survives, every other piece is swept at
** once, leaving a flat trace along it between its face and the winning
** piece that extends over it (the last winner before it, else the first
** winner).  Flats towards a winner after them run backwards along their
** edge (the winner's face on their right: its left wall), the others
** forwards (its right wall), each wall in order away from the winner.  The
** run's vertices next to a swept piece end; new vertices join the winners
** to their neighbours.  A run that reaches a chain end is a ray there: its
** swept end pieces leave infinite flats, and a winner becomes the ray. */
static wk_status collinear_rule(sim *S, uint32_t node, uint32_t P, uint32_t Q, uint32_t ein,
                                uint32_t eout, double t) {
    mono *M = S->M;
    wk_run *R = M->R;
    mono_chain *C = S->C;
    const wk_offset_line *L = M->L;
    /* run vertices 0..k (0 and k: the vertices before and after the run,
    ** WK_NONE at a ray; vc: the vertex being born at `node`), pieces
    ** 0..k-1, piece j between vertices j and j + 1 */
    uint32_t nb = 0, na = 0, x;
    for (x = P; x != WK_NONE && on_one_line(&C->v[x]); x = C->v[x].prev)
        if (++nb > C->nv) goto cyclic;
    uint32_t first = x;
    for (x = Q; x != WK_NONE && on_one_line(&C->v[x]); x = C->v[x].next)
        if (++na > C->nv) goto cyclic;
    uint32_t last = x, k = nb + na + 2, vc = nb + 1;
    if (WK_GROW(R, S->run_v, S->cap_run_v, k + 1) != WK_OK ||
        WK_GROW(R, S->run_e, S->cap_run_e, k) != WK_OK ||
        WK_GROW(R, S->run_nd, S->cap_run_nd, k + 1) != WK_OK ||
        WK_GROW(R, S->run_sched, S->cap_run_sched, k + 3) != WK_OK)
        return R->err.code;
    uint32_t *V = S->run_v, *E = S->run_e, *ND = S->run_nd, *SCH = S->run_sched, n_sch = 0;
    V[0] = first;
    V[k] = last;
    V[vc] = WK_NONE;
    E[nb] = ein;
    E[vc] = eout;
    x = P;
    for (uint32_t j = nb; j >= 1; j--, x = C->v[x].prev) {
        V[j] = x;
        E[j - 1] = C->v[x].ein;
    }
    x = Q;
    for (uint32_t j = vc + 1; j < k; j++, x = C->v[x].next) {
        V[j] = x;
        E[j] = C->v[x].eout;
    }
    for (uint32_t j = 0; j <= k; j++) ND[j] = WK_NONE;
    ND[vc] = node;
    bool lower = R->opt.collinear == WK_COLLINEAR_LOWER;
    double best = L[E[0]].w;
    for (uint32_t j = 1; j < k; j++)
        if (lower ? L[E[j]].w < best : L[E[j]].w > best) best = L[E[j]].w;
    uint32_t fw = 0;
    while (L[E[fw]].w != best) fw++;
    wk_point at = C->node[node].p;
    /* flats along the losing pieces: before the first winner backwards,
    ** then the others forwards */
    for (uint32_t j = fw; j-- > 0;) {
        uint32_t a = run_node(S, j + 1, t), b = WK_NONE;
        if (a == WK_NONE) return R->err.code;
        if (!(j == 0 && first == WK_NONE) && (b = run_node(S, j, t)) == WK_NONE) return R->err.code;
        wk_point u = {-L[E[j]].ux, -L[E[j]].uy};
        if (new_flat(S, E[j], E[fw], a, b, u, t) == WK_NONE) return R->err.code;
        wk_event e = {t, at.x, at.y, E[j], E[fw], WK_NONE};
        wk_notify_event(R, WK_COUNTER_collinear_resolutions, &e);
    }
    uint32_t ext = E[fw];
    for (uint32_t j = fw + 1; j < k; j++) {
        if (L[E[j]].w == best) {
            ext = E[j];
            continue;
        }
        uint32_t a = run_node(S, j, t), b = WK_NONE;
        if (a == WK_NONE) return R->err.code;
        if (!(j + 1 == k && last == WK_NONE) && (b = run_node(S, j + 1, t)) == WK_NONE)
            return R->err.code;
        wk_point u = {L[E[j]].ux, L[E[j]].uy};
        if (new_flat(S, ext, E[j], a, b, u, t) == WK_NONE) return R->err.code;
        wk_event e = {t, at.x, at.y, E[j], ext, WK_NONE};
        wk_notify_event(R, WK_COUNTER_collinear_resolutions, &e);
    }
    /* the new wavefront along the run (naive's rebuild): cur is its last
    ** vertex so far (WK_NONE: none yet, the chain starts with a ray), cur_out
    ** the edge leaving it */
    uint32_t cur = WK_NONE, cur_out = E[fw];
    if (first != WK_NONE) {
        cur = C->v[first].prev;
        cur_out = C->v[first].ein;
    }
    if (cur != WK_NONE) SCH[n_sch++] = cur;
    for (uint32_t i = first == WK_NONE ? 1 : 0; i <= k; i++) {
        if (i == k && last == WK_NONE) {
            link(S, cur, WK_NONE);
            break;
        }
        uint32_t u = V[i];
        uint32_t e_in = i == 0 ? C->v[u].ein : E[i - 1];
        uint32_t e_out = i == k ? C->v[u].eout : E[i];
        bool lost_before = i > 0 && L[E[i - 1]].w != best;
        bool lost_after = i < k && L[E[i]].w != best;
        if (!lost_before && !lost_after) { /* untouched (never the new vertex) */
            link(S, cur, u);
            cur = u;
            cur_out = C->v[u].eout;
            SCH[n_sch++] = u;
            continue;
        }
        uint32_t nd = i == vc ? node : run_node(S, i, t);
        if (nd == WK_NONE) return R->err.code;
        uint32_t u_next = u != WK_NONE ? C->v[u].next : WK_NONE;
        if (u != WK_NONE) terminate(S, u, nd);
        uint32_t leave = i == k ? e_out : (lost_after ? cur_out : e_out);
        if (i == 0) leave = E[fw];
        if (lost_after && i > 0 && i < k && L[e_in].w == best) leave = e_in;
        if (i < k && !lost_after) leave = e_out;
        if (leave != cur_out) {
            uint32_t g = new_trace(S, cur_out, leave, C->node[nd].p, t, nd);
            if (g == WK_NONE) return R->err.code;
            if (C->v[g].kind != WK_VEL_REGULAR && C->v[g].kind != WK_VEL_STRAIGHT)
                return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                               "monotone: the collinear rule at t = %.17g leaves edges %u and %u "
                               "meeting in parallel",
                               t, cur_out, leave);
            link(S, cur, g);
            cur = g;
            cur_out = leave;
            SCH[n_sch++] = g;
        }
        if (i == k) link(S, cur, u_next);
    }
    for (uint32_t j = 0; j < n_sch; j++)
        if (C->v[SCH[j]].alive && schedule(S, SCH[j]) != WK_OK) return R->err.code;
    return WK_OK;
cyclic:
    return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                   "monotone: a chain's whole wavefront lies on one line at t = %.17g", t);
}

/* Are the edges of offset lines a and b antiparallel within
** WK_MONO_ANTIPARALLEL_SIN (normals opposite, |sine| at most the bar)? */
static bool antiparallel_walls(const wk_offset_line *a, const wk_offset_line *b) {
    double det = a->nx * b->ny - a->ny * b->nx, dot = a->nx * b->nx + a->ny * b->ny;
    return dot < 0 && fabs(det) <= WK_MONO_ANTIPARALLEL_SIN;
}

/* Resolve the wavefront at node `node` (time t) where the vertices between P
** and Q have arrived: the new vertex would sit between edges ein (P's
** outgoing edge) and eout (Q's incoming edge).  See the top comment. */
static wk_status resolve(sim *S, uint32_t node, uint32_t P, uint32_t Q, uint32_t ein,
                         uint32_t eout, double t) {
    mono *M = S->M;
    wk_run *R = M->R;
    mono_chain *C = S->C;
    for (uint32_t guard = 0; guard <= 2 * C->m + 8; guard++) {
        wk_point at = C->node[node].p;
        while (P != WK_NONE && arrives_now(S, P, at, t, ein, eout, false)) {
            terminate(S, P, node);
            ein = C->v[P].ein;
            P = C->v[P].prev;
        }
        while (Q != WK_NONE && arrives_now(S, Q, at, t, ein, eout, true)) {
            terminate(S, Q, node);
            eout = C->v[Q].eout;
            Q = C->v[Q].next;
        }
        wk_point vel;
        wk_velocity_kind kind = wk_vertex_velocity(&M->L[ein], &M->L[eout], &vel);
        /* Two facing walls meeting here, antiparallel up to the rounding of
        ** turned coordinates (WK_MONO_ANTIPARALLEL_SIN), collide as the
        ** exactly antiparallel ones do: the regular vertex between them
        ** would run off along them at ~1/sine and never end (random
        ** x-monotone polygons with vertical pairs turned by 0.3 rad: a
        ** 17-long wall at 3e5 facing one 207 away, sine 1.09e-12). */
        if (kind == WK_VEL_REGULAR && antiparallel_walls(&M->L[ein], &M->L[eout]))
            kind = WK_VEL_ANTIPARALLEL;
        if (kind == WK_VEL_REGULAR || kind == WK_VEL_STRAIGHT) {
            uint32_t V = new_trace(S, ein, eout, at, t, node);
            if (V == WK_NONE) return R->err.code;
            link(S, P, V);
            link(S, V, Q);
            if (schedule(S, V) != WK_OK) return R->err.code;
            if (P != WK_NONE && schedule(S, P) != WK_OK) return R->err.code;
            return WK_OK;
        }
        if (kind == WK_VEL_COLLINEAR) return collinear_rule(S, node, P, Q, ein, eout, t);
        /* antiparallel: a flat trace from `node` towards the nearer far end f
        ** (side: +1 the outgoing piece's, towards Q; -1 the incoming one's,
        ** towards P) */
        int side;
        wk_point u;
        {
            double dP = P != WK_NONE ? dist2(wk_mono_trace_at(&C->v[P], t), at) : INFINITY;
            double dQ = Q != WK_NONE ? dist2(wk_mono_trace_at(&C->v[Q], t), at) : INFINITY;
            if (!isfinite(dP) && !isfinite(dQ)) {
                /* the two end rays lie on each other and cancel entirely
                ** (beyond the polygon: walls perpendicular to the sweep at
                ** both ends); the chain's wavefront is gone */
                wk_point u = {M->L[eout].ux, M->L[eout].uy};
                if (new_flat(S, ein, eout, node, WK_NONE, u, t) == WK_NONE) return R->err.code;
                return WK_OK;
            }
            side = dQ <= dP ? +1 : -1;
        }
        u = side > 0 ? (wk_point){M->L[eout].ux, M->L[eout].uy}
                     : (wk_point){-M->L[ein].ux, -M->L[ein].uy};
        uint32_t f = side > 0 ? Q : P;
        if (f == WK_NONE) {
            /* the piece is a ray: swept entirely; the winner becomes the ray */
            if (new_flat(S, ein, eout, node, WK_NONE, u, t) == WK_NONE) return R->err.code;
            if (side > 0) {
                link(S, P, WK_NONE);
                if (P != WK_NONE && schedule(S, P) != WK_OK) return R->err.code;
            } else {
                link(S, WK_NONE, Q);
                /* Q's piece is unchanged */
            }
            return WK_OK;
        }
        wk_point pf = wk_mono_trace_at(&C->v[f], t);
        /* a far vertex born at this instant is its own start node (an input
        ** vertex at t = 0): reuse it, as naive does */
        uint32_t nf = C->v[f].t0 == t ? C->v[f].start : new_node(S, pf, t, WK_NONE);
        if (nf == WK_NONE || new_flat(S, ein, eout, node, nf, u, t) == WK_NONE)
            return R->err.code;
        node = nf; /* the absorb step at the top lets f (and, if as far, the
                      other side's far vertex) arrive there */
    }
    return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                   "monotone: no end to the resolution of a chain event at t = %.17g", t);
}

static wk_status build_walls(mono *M, mono_chain *C) {
    wk_run *R = M->R;
    C->lw_start = WK_NEW_ARRAY(R, uint32_t, C->m + 1);
    C->rw_start = WK_NEW_ARRAY(R, uint32_t, C->m + 1);
    C->n_lw = C->n_rw = C->nv ? C->nv : 1;
    C->lw = WK_NEW_ARRAY(R, uint32_t, C->n_lw);
    C->rw = WK_NEW_ARRAY(R, uint32_t, C->n_rw);
    if (!C->lw_start || !C->rw_start || !C->lw || !C->rw) return R->err.code;
    for (uint32_t i = 0; i < C->nv; i++) {
        uint32_t ko = wk_mono_chain_local(M, C, C->v[i].eout);
        uint32_t ki = wk_mono_chain_local(M, C, C->v[i].ein);
        if (ko == WK_NONE || ki == WK_NONE)
            return WK_FAIL(R, WK_EALGO, M->P->name, 0, "monotone: trace with a foreign edge");
        C->lw_start[ko + 1]++;
        C->rw_start[ki + 1]++;
    }
    for (uint32_t k = 0; k < C->m; k++) {
        C->lw_start[k + 1] += C->lw_start[k];
        C->rw_start[k + 1] += C->rw_start[k];
    }
    /* fill in creation order: use the start arrays as cursors, then shift */
    for (uint32_t i = 0; i < C->nv; i++) {
        uint32_t ko = wk_mono_chain_local(M, C, C->v[i].eout);
        uint32_t ki = wk_mono_chain_local(M, C, C->v[i].ein);
        C->lw[C->lw_start[ko]++] = i;
        C->rw[C->rw_start[ki]++] = i;
    }
    for (uint32_t k = C->m; k > 0; k--) {
        C->lw_start[k] = C->lw_start[k - 1];
        C->rw_start[k] = C->rw_start[k - 1];
    }
    C->lw_start[0] = C->rw_start[0] = 0;
    return WK_OK;
}

wk_status wk_mono_chain_build(mono *M, uint32_t c) {
    wk_run *R = M->R;
    const wk_polygon *P = M->P;
    uint32_t n = P->n;
    mono_chain *C = &M->ch[c];
    sim S;
    memset(&S, 0, sizeof S);
    S.M = M;
    S.C = C;
    wk_event_queue_init(&S.Q);
    wk_status st = WK_OK;
    if (wk_event_queue_reserve(R, &S.Q, 2 * C->m + 16) != WK_OK) {
        st = R->err.code;
        goto done;
    }
    /* the initial wavefront: one vertex per interior chain vertex */
    for (uint32_t j = 1; j < C->m; j++) {
        uint32_t i = (C->first + j) % n;
        wk_point p = wk_mono_vertex(M, i);
        uint32_t node = new_node(&S, p, 0.0, i);
        uint32_t id = node == WK_NONE ? WK_NONE : new_trace(&S, (i + n - 1) % n, i, p, 0.0, node);
        if (id == WK_NONE) {
            st = R->err.code;
            goto done;
        }
        if (j > 1) link(&S, id - 1, id);
    }
    /* input vertices between parallel edges of different weight: the rule
    ** applies at t = 0 (an antiparallel input vertex would be a spike, which
    ** the polygon checks refuse) */
    uint32_t n0 = C->nv;
    for (uint32_t i = 0; i < n0; i++) {
        mono_trace *v = &C->v[i];
        if (!v->alive || v->kind != WK_VEL_COLLINEAR) continue;
        uint32_t prev = v->prev, next = v->next, ein = v->ein, eout = v->eout, node = v->start;
        terminate(&S, i, node);
        link(&S, prev, WK_NONE);
        link(&S, WK_NONE, next);
        if ((st = resolve(&S, node, prev, next, ein, eout, 0.0)) != WK_OK) goto done;
    }
    for (uint32_t i = 0; i < C->nv; i++) {
        if (C->v[i].alive && (st = schedule(&S, i)) != WK_OK) goto done;
    }
    while (S.Q.size) {
        uint32_t a = wk_event_queue_pop(R, &S.Q);
        mono_trace *A = &C->v[a];
        if (!A->alive || A->next == WK_NONE) continue; /* defensive: never queued so */
        double t = A->ev_t < S.t_now ? S.t_now : A->ev_t;
        S.t_now = t;
        uint32_t b = A->next;
        uint32_t node = new_node(&S, A->ev_p, t, WK_NONE);
        if (node == WK_NONE) {
            st = R->err.code;
            goto done;
        }
        A = &C->v[a];
        wk_event e = {t, A->ev_p.x, A->ev_p.y, a, b, c};
        wk_notify_event(R, WK_COUNTER_edge_events, &e); /* e.c: the chain */
        wk_count(R, c == 0 ? WK_VC_chain_edge_events_lower : WK_VC_chain_edge_events_upper, 1);
        uint32_t Pv = A->prev, Qv = C->v[b].next, ein = A->ein, eout = C->v[b].eout;
        terminate(&S, a, node);
        terminate(&S, b, node);
        link(&S, Pv, WK_NONE);
        link(&S, WK_NONE, Qv);
        if ((st = resolve(&S, node, Pv, Qv, ein, eout, t)) != WK_OK) goto done;
    }
    st = build_walls(M, C);
done:
    wk_event_queue_clear(R, &S.Q);
    WK_FREE_ARRAY(R, S.run_v, S.cap_run_v);
    WK_FREE_ARRAY(R, S.run_e, S.cap_run_e);
    WK_FREE_ARRAY(R, S.run_nd, S.cap_run_nd);
    WK_FREE_ARRAY(R, S.run_sched, S.cap_run_sched);
    return st;
}
