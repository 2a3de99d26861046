/*
** motorcycle.c: the motorcycle variant (002, section 3): the shared kinetic
** wavefront (engine/wavefront.c) whose split events are found through the
** motorcycle graph M(P) instead of a search over all wavefront pieces.
**
** Model.  Every reflex wavefront vertex v owns a trace: the static segment
** o + lambda u, lambda in [0, len], from where v started to where its
** motorcycle crashed (a vertex of P: motorcycle_graph.c; a reflex vertex
** born later: to where its ray meets the wavefront).  002, Theorem 1: with
** unit weights every reflex arc of the skeleton lies on its motorcycle's
** trace, so v never leaves its trace alive.  Along the trace the part not
** yet swept is [lambda_v(t), lambda_F(t)]: v at one end, at the other the
** moving Steiner vertex F where the trace meets the wavefront piece in front
** of v (002's moving Steiner vertex on v's trace).  v's split event is v
** meeting F, so no search over the wavefront is needed.
**
** Where F starts.  A motorcycle that crashed into a wall has F on that
** wall's piece at t = 0.  One that crashed into another trace s' at the
** point X (a resting Steiner vertex of 002) has F "beyond": the wavefront
** first reaches its trace at X, and it reaches X through s' (X is on s', so
** it is swept when v' or F' passes it).  So F enters the trace at X by a
** cut, below, and until then v has no split.  The trace s' "guards" X.
**
** Events of a trace (this file's queue, processed before any wavefront
** event that is not earlier):
**   switch: F reaches an end vertex of its piece and moves on to the
**     neighbouring piece (002: a convex vertex jumps over a moving Steiner
**     vertex);
**   start:  F reaches a crossing X with another trace s' (the end of one
**     of them).  If X lies in the unswept part of s', the piece carrying F
**     now cuts s' at X: F' := X on that piece (002: start event);
**   front:  v itself reaches such a crossing; if X is in the unswept part
**     of s', v's piece facing v' now cuts s' there.
** Crossings of a trace are few: the ends of the traces that crashed into it
** and its own end (and, for traces shot later, the traces they cross), kept
** sorted per trace.
**
** Guards that end early.  If v' dies before reaching X (an edge event with
** a convex neighbour), the part of s' beyond v' is still unswept, but no
** event of s' will reach X any more.  Every trace that was waiting at X
** with F beyond is then extended: its ray is shot against the wavefront (F
** placed on the first piece along it) and its crossings with the live
** traces over the added part are listed (trace_extensions).  002 keeps the
** unswept remainder of s' in its extended wavefront instead; this variant
** tracks one moving Steiner vertex per trace (README).
**
** After every group of wavefront events only what the group touched is
** revisited (wk_wf_last_group), as in the arrangement variant.
*/
#include "motorcycle.h"
#include "motorcycle_graph.h"
#include "event_queue.h"
#include "ray_shoot.h"
#include "wavefront.h"

#include <math.h>
#include <string.h>
#ifdef MC_DEBUG
#include <stdio.h>
#define DBG(...) fprintf(stderr, __VA_ARGS__)
#else
#define DBG(...) ((void)0)
#endif

enum { MC_SWITCH = 0, MC_START = 1, MC_FRONT = 2 };

/* A crossing on a trace: at lam from its origin, with trace `other`. */
typedef struct mc_cross {
    double lam;
    uint32_t other;
} mc_cross;

typedef struct mc_seg {
    uint32_t v;          /* its reflex vertex; WK_NONE once removed */
    wk_point o, u;       /* the trace: o + lambda u (relative coordinates) */
    double len;
    uint32_t pa, pb;     /* F's piece pa -> pb, WK_NONE if F is unknown or beyond */
    bool beyond;         /* F has not reached the trace yet: guarded at its end */
    uint32_t next_on, prev_on; /* the list of traces whose F is on piece pa */
    mc_cross *x;         /* crossings, sorted by (lam, other) */
    uint32_t nx, capx;
    mc_cross xf;         /* next crossing F reaches (towards v) */
    mc_cross xv;         /* next crossing v reaches */
    double ev_t;
    uint8_t ev_kind;
    uint8_t ev_end;      /* switch: 0 F leaves over pa, 1 over pb */
    bool hold;           /* F has met v: no switch until the next group */
    uint32_t probe;      /* held without F: v's split is searched next to this piece */
    uint32_t mark;
} mc_seg;

typedef struct mc_state {
    wk_run *R;
    mc_seg *s;
    uint32_t n_s, cap_s;
    uint32_t *seg_of;    /* per wavefront vertex: its trace or WK_NONE */
    uint32_t *fhead;     /* per wavefront vertex a: first trace with F on a -> a.next */
    uint32_t cap_v;
    wk_event_queue Q;
    uint32_t *todo;
    uint32_t n_todo, cap_todo, stamp;
    uint32_t *ext;       /* traces whose guard ended early: extend them */
    uint32_t n_ext, cap_ext;
    uint32_t *held;      /* traces with hold set */
    uint32_t n_held, cap_held;
    uint32_t *unknown;   /* traces whose F became unknown since the last group */
    uint32_t n_unknown, cap_unknown;
    double guard_t;
    uint64_t guard_n;
} mc_state;

/* ------------------------------------------------------------ geometry */

static double lambda_on_line(const mc_seg *S, const wk_offset_line *L, double t) {
    double den = L->nx * S->u.x + L->ny * S->u.y;
    if (fabs(den) < WK_ARR_PARALLEL) return NAN;
    return (L->c + L->w * t - (L->nx * S->o.x + L->ny * S->o.y)) / den;
}

static double lambda_of(const mc_seg *S, wk_point p) {
    return (p.x - S->o.x) * S->u.x + (p.y - S->o.y) * S->u.y;
}

static double lambda_v(const wk_wavefront *W, const mc_seg *S, double t) {
    return lambda_of(S, wk_wf_position(W, S->v, t));
}

/* F's place along the trace: NaN if unknown, +inf while beyond. */
static double lambda_f(const wk_wavefront *W, const mc_seg *S, double t) {
    if (S->beyond) return INFINITY;
    if (S->pa == WK_NONE) return NAN;
    return lambda_on_line(S, wk_wf_line(W, wk_wf_edge_out(W, S->pa)), t);
}

/* ------------------------------------------------------------ crossings */

static const mc_cross NO_CROSS = {INFINITY, WK_NONE};

static bool cross_less(double l1, uint32_t o1, double l2, uint32_t o2) {
    return l1 < l2 || (l1 == l2 && o1 < o2);
}

static wk_status add_cross(mc_state *A, uint32_t si, double lam, uint32_t other) {
    mc_seg *S = &A->s[si];
    if (WK_GROW(A->R, S->x, S->capx, S->nx + 1) != WK_OK) return A->R->err.code;
    uint32_t k = S->nx;
    while (k > 0 && cross_less(lam, other, S->x[k - 1].lam, S->x[k - 1].other)) {
        S->x[k] = S->x[k - 1];
        k--;
    }
    S->x[k] = (mc_cross){lam, other};
    S->nx++;
    return WK_OK;
}

/* The first crossing beyond (lam, after) going away from v. */
static mc_cross next_up(const mc_seg *S, double lam, uint32_t after) {
    for (uint32_t k = 0; k < S->nx; k++) {
        const mc_cross *c = &S->x[k];
        if (c->lam > lam || (c->lam == lam && after != WK_NONE && c->other > after)) return *c;
    }
    return NO_CROSS;
}

/* The first crossing beyond (lam, after) going towards v (equal places in
** increasing `other`, as the arrangement's reverse order). */
static mc_cross next_down(const mc_seg *S, double lam, uint32_t after) {
    mc_cross best = NO_CROSS;
    best.lam = -INFINITY;
    for (uint32_t k = S->nx; k-- > 0;) {
        const mc_cross *c = &S->x[k];
        bool ok = c->lam < lam || (c->lam == lam && after != WK_NONE && c->other > after);
        if (!ok) continue;
        if (best.other == WK_NONE || c->lam > best.lam ||
            (c->lam == best.lam && c->other < best.other))
            best = *c;
        else if (c->lam < best.lam)
            break;
    }
    if (best.other == WK_NONE) best.lam = -INFINITY;
    return best;
}

/* ------------------------------------------------------------ bookkeeping */

static wk_status ensure_vertex_arrays(mc_state *A, uint32_t nv) {
    if (nv <= A->cap_v) return WK_OK;
    uint32_t ncap = A->cap_v ? A->cap_v : 64;
    while (ncap < nv) ncap *= 2;
    uint32_t *so = WK_NEW_ARRAY(A->R, uint32_t, ncap);
    uint32_t *fh = so ? WK_NEW_ARRAY(A->R, uint32_t, ncap) : NULL;
    if (!fh) {
        if (so) WK_FREE_ARRAY(A->R, so, ncap);
        return A->R->err.code;
    }
    for (uint32_t i = 0; i < ncap; i++) {
        so[i] = i < A->cap_v ? A->seg_of[i] : WK_NONE;
        fh[i] = i < A->cap_v ? A->fhead[i] : WK_NONE;
    }
    if (A->cap_v) {
        WK_FREE_ARRAY(A->R, A->seg_of, A->cap_v);
        WK_FREE_ARRAY(A->R, A->fhead, A->cap_v);
    }
    A->seg_of = so;
    A->fhead = fh;
    A->cap_v = ncap;
    return WK_OK;
}

static void unlink_f(mc_state *A, uint32_t si) {
    mc_seg *S = &A->s[si];
    if (S->pa == WK_NONE) return;
    if (S->prev_on != WK_NONE) A->s[S->prev_on].next_on = S->next_on;
    else A->fhead[S->pa] = S->next_on;
    if (S->next_on != WK_NONE) A->s[S->next_on].prev_on = S->prev_on;
    S->pa = S->pb = S->next_on = S->prev_on = WK_NONE;
}

static void link_f(mc_state *A, wk_wavefront *W, uint32_t si, uint32_t a) {
    mc_seg *S = &A->s[si];
    S->beyond = false;
    S->pa = a;
    S->pb = wk_wf_next(W, a);
    S->prev_on = WK_NONE;
    S->next_on = A->fhead[a];
    if (S->next_on != WK_NONE) A->s[S->next_on].prev_on = si;
    A->fhead[a] = si;
}

/* Where the ray o + lambda u (lambda > lambda0) meets piece a -> a.next at
** time t: lambda, or INFINITY; *mu: the position along the piece (0..1). */
static double hit_piece(const wk_wavefront *W, const mc_seg *S, uint32_t a, double t,
                        double lambda0, double *mu) {
    uint32_t b = wk_wf_next(W, a);
    wk_point pa = wk_wf_position(W, a, t), pb = wk_wf_position(W, b, t);
    double dx = pb.x - pa.x, dy = pb.y - pa.y;
    double den = S->u.x * dy - S->u.y * dx;
    if (fabs(den) < WK_DIV_GUARD) return INFINITY;
    double ex = pa.x - S->o.x, ey = pa.y - S->o.y;
    double lam = (ex * dy - ey * dx) / den;
    *mu = (ex * S->u.y - ey * S->u.x) / den;
    if (*mu < -WK_RAY_PIECE_SLACK || *mu > 1 + WK_RAY_PIECE_SLACK ||
        lam <= lambda0 + wk_wf_eps_d(W) * WK_RAY_AHEAD_REL)
        return INFINITY;
    return lam;
}

static void shoot_piece(const wk_wavefront *W, const mc_seg *S, uint32_t v, uint32_t a, double t,
                        double lambda0, uint32_t *best, double *bl, bool *at_end) {
    double mu;
    if (a == v || wk_wf_next(W, a) == v) return;
    double lam = hit_piece(W, S, a, t, lambda0, &mu);
    if (lam < *bl) {
        *bl = lam;
        *best = a;
        *at_end = mu < WK_RAY_END_SNAP || mu > 1 - WK_RAY_END_SNAP;
    }
}

/* The first piece the ray meets at time t, over v's cycle (every alive
** piece with holes: the first piece may be on a hole's cycle). */
static uint32_t shoot_at(mc_state *A, const wk_wavefront *W, const mc_seg *S, uint32_t v, double t,
                         double lambda0, bool *at_end) {
    uint32_t best = WK_NONE;
    double bl = INFINITY;
    wk_count(A->R, WK_VC_ray_shots, 1);
    if (wk_wf_polygon(W)->n_rings == 1) {
        for (uint32_t a = wk_wf_next(W, v); a != v; a = wk_wf_next(W, a))
            shoot_piece(W, S, v, a, t, lambda0, &best, &bl, at_end);
    } else {
        for (uint32_t a = 0; a < wk_wf_vertex_count(W); a++)
            if (wk_wf_alive(W, a)) shoot_piece(W, S, v, a, t, lambda0, &best, &bl, at_end);
    }
    return best;
}

static uint32_t shoot(mc_state *A, const wk_wavefront *W, const mc_seg *S, uint32_t v, double t,
                      double lambda0) {
    bool at_end = false;
    uint32_t a = shoot_at(A, W, S, v, t, lambda0, &at_end);
    if (a != WK_NONE && at_end) {
        double later = t + WK_RAY_RESHOOT_DELAY * wk_wf_eps_t(W);
        uint32_t b = shoot_at(A, W, S, v, later, lambda_of(S, wk_wf_position(W, v, later)), &at_end);
        if (b != WK_NONE) a = b;
    }
    return a;
}

/* --------------------------------------------------------------- events */

static void seg_event(mc_state *A, wk_wavefront *W, uint32_t si) {
    mc_seg *S = &A->s[si];
    double now = wk_wf_now(W);
    (void)A;
    S->ev_t = INFINITY;
    S->ev_kind = MC_SWITCH;
    if (S->v == WK_NONE) return;
    if (S->pa != WK_NONE && !S->hold) {
        const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, S->pa));
        double l0 = lambda_on_line(S, L, now), l1 = lambda_on_line(S, L, now + 1);
        if (isfinite(l0) && isfinite(l1)) {
            wk_point f0 = {S->o.x + l0 * S->u.x, S->o.y + l0 * S->u.y};
            wk_point f1 = {S->o.x + l1 * S->u.x, S->o.y + l1 * S->u.y};
            wk_point a0 = wk_wf_position(W, S->pa, now), a1 = wk_wf_position(W, S->pa, now + 1);
            wk_point b0 = wk_wf_position(W, S->pb, now), b1 = wk_wf_position(W, S->pb, now + 1);
            double sa0 = (f0.x - a0.x) * L->ux + (f0.y - a0.y) * L->uy;
            double sa1 = (f1.x - a1.x) * L->ux + (f1.y - a1.y) * L->uy;
            double sb0 = (b0.x - f0.x) * L->ux + (b0.y - f0.y) * L->uy;
            double sb1 = (b1.x - f1.x) * L->ux + (b1.y - f1.y) * L->uy;
            double ra = sa1 - sa0, rb = sb1 - sb0;
            double tiny = WK_RIDE_ALONG_REL * (fabs(l1 - l0) + L->w);
            if (ra < -tiny) {
                double te = now + (sa0 > 0 ? sa0 : 0) / -ra;
                if (te < S->ev_t) S->ev_t = te, S->ev_kind = MC_SWITCH, S->ev_end = 0;
            }
            if (rb < -tiny) {
                double te = now + (sb0 > 0 ? sb0 : 0) / -rb;
                if (te < S->ev_t) S->ev_t = te, S->ev_kind = MC_SWITCH, S->ev_end = 1;
            }
            if (S->xf.other != WK_NONE) {
                double target = S->xf.lam, rate = l1 - l0;
                if (rate < 0) {
                    double te = now + (l0 > target ? (l0 - target) : 0) / -rate;
                    if (te < S->ev_t) S->ev_t = te, S->ev_kind = MC_START;
                }
            }
        }
    }
    if (S->xv.other != WK_NONE) {
        wk_point vel = wk_wf_velocity(W, S->v);
        double rate = vel.x * S->u.x + vel.y * S->u.y;
        double lv = lambda_v(W, S, now);
        if (rate > 0) {
            double te = now + (S->xv.lam > lv ? S->xv.lam - lv : 0) / rate;
            if (te < S->ev_t) S->ev_t = te, S->ev_kind = MC_FRONT;
        }
    }
}

static wk_status schedule_seg(mc_state *A, wk_wavefront *W, uint32_t si) {
    seg_event(A, W, si);
    mc_seg *S = &A->s[si];
    DBG("    sched seg %u v %u at %.9g: ev %.9g kind %d pa %d xf(%.6g,%d) xv(%.6g,%d) lv %.6g\n", si, S->v, wk_wf_now(W), S->ev_t, S->ev_kind, (int)S->pa, S->xf.lam, (int)S->xf.other, S->xv.lam, (int)S->xv.other, S->v == WK_NONE ? 0 : lambda_v(W, S, wk_wf_now(W)));
    if (!isfinite(S->ev_t)) {
        wk_event_queue_remove(A->R, &A->Q, si);
        return WK_OK;
    }
    double t = S->ev_t < wk_wf_now(W) ? wk_wf_now(W) : S->ev_t;
    return wk_event_queue_set(A->R, &A->Q, si, (wk_event_key){t, S->ev_kind});
}

/* Next crossings of trace si from where v and F are now. */
static wk_status arm_segment(mc_state *A, wk_wavefront *W, uint32_t si) {
    mc_seg *S = &A->s[si];
    double t = wk_wf_now(W), lf = lambda_f(W, S, t), lv = lambda_v(W, S, t);
    S->xf = S->pa != WK_NONE && isfinite(lf) ? next_down(S, lf, WK_NONE) : NO_CROSS;
    if (S->xf.other == WK_NONE) S->xf = NO_CROSS;
    S->xv = next_up(S, lv < 0 ? 0 : lv, WK_NONE);
    return schedule_seg(A, W, si);
}

/* F of trace si is unknown: v's split is searched over its cycle until the
** next group places F again. */
static wk_status note_unknown(mc_state *A, uint32_t si) {
    if (WK_GROW(A->R, A->unknown, A->cap_unknown, A->n_unknown + 1) != WK_OK) return A->R->err.code;
    A->unknown[A->n_unknown++] = si;
    return WK_OK;
}

/* No switch events for trace si's F until the next group (F has met v). */
static wk_status hold(mc_state *A, uint32_t si) {
    if (A->s[si].hold) return WK_OK;
    if (WK_GROW(A->R, A->held, A->cap_held, A->n_held + 1) != WK_OK) return A->R->err.code;
    A->s[si].hold = true;
    A->held[A->n_held++] = si;
    return WK_OK;
}

/* Place F of trace si by a ray shot from its vertex at time t. */
static bool unswept(const wk_wavefront *W, const mc_seg *T, double lx, double t);

/* Trace si's end is still guarded at time t: a live trace through it has
** the end in its unswept part (so the end will be cut when it is swept). */
static bool guarded(const mc_state *A, const wk_wavefront *W, uint32_t si, double t) {
    const mc_seg *S = &A->s[si];
    double slack = WK_RELOCATE_SLACK * wk_wf_eps_d(W);
    wk_point X = {S->o.x + S->len * S->u.x, S->o.y + S->len * S->u.y};
    for (uint32_t k = 0; k < S->nx; k++) {
        const mc_cross *c = &S->x[k];
        if (fabs(c->lam - S->len) > slack || c->other >= A->n_s) continue;
        const mc_seg *T = &A->s[c->other];
        if (T->v != WK_NONE && unswept(W, T, lambda_of(T, X), t)) return true;
    }
    return false;
}

/* Place F of trace si by a ray shot from its vertex at time t.  A hit
** beyond the trace's end leaves F beyond when that end is still guarded
** (allow_beyond): the wavefront will reach the trace there, and following
** F along the ray past the end would only track pieces that cannot matter. */
static wk_status place_f(mc_state *A, wk_wavefront *W, uint32_t si, double t, bool allow_beyond) {
    mc_seg *S = &A->s[si];
    unlink_f(A, si);
    S->beyond = false;
    double lv = lambda_v(W, S, t);
    uint32_t a = shoot(A, W, S, S->v, t, lv);
    if (a == WK_NONE) return note_unknown(A, si);
    link_f(A, W, si, a);
    if (allow_beyond && lambda_f(W, S, t) > S->len + WK_RELOCATE_SLACK * wk_wf_eps_d(W) &&
        guarded(A, W, si, t)) {
        unlink_f(A, si);
        A->s[si].beyond = true;
    }
    return WK_OK;
}

static wk_status new_segment(mc_state *A, uint32_t v, wk_point o, wk_point u, double len,
                             uint32_t *out) {
    if (WK_GROW(A->R, A->s, A->cap_s, A->n_s + 1) != WK_OK) return A->R->err.code;
    uint32_t si = A->n_s++;
    mc_seg *S = &A->s[si];
    memset(S, 0, sizeof *S);
    S->v = v;
    S->o = o;
    S->u = u;
    S->len = len;
    S->pa = S->pb = S->next_on = S->prev_on = S->probe = WK_NONE;
    S->xf = S->xv = NO_CROSS;
    A->seg_of[v] = si;
    *out = si;
    return WK_OK;
}

/* Crossings of trace si's part lambda in [l0, l1] with the unswept parts
** of the other live traces, listed on both (and those re-armed). */
static wk_status list_crossings(mc_state *A, wk_wavefront *W, uint32_t si, double l0, double l1) {
    double t = wk_wf_now(W), eps = wk_wf_eps_d(W);
    for (uint32_t j = 0; j < A->n_s; j++) {
        if (j == si || A->s[j].v == WK_NONE) continue;
        const mc_seg *S = &A->s[si], *T = &A->s[j];
        double den = S->u.x * T->u.y - S->u.y * T->u.x;
        if (fabs(den) < WK_ARR_PARALLEL) continue;
        double ex = T->o.x - S->o.x, ey = T->o.y - S->o.y;
        double a = (ex * T->u.y - ey * T->u.x) / den; /* on S */
        double b = (ex * S->u.y - ey * S->u.x) / den; /* on T */
        if (a < l0 - eps || a > l1 + eps || b > T->len + eps) continue;
        if (b < lambda_v(W, T, t) - eps) continue;
        if (add_cross(A, si, a, j) != WK_OK || add_cross(A, j, b, si) != WK_OK) return A->R->err.code;
        /* the new crossing may come before the ones j has fetched */
        mc_seg *J = &A->s[j];
        double lv = lambda_v(W, J, t), lf = lambda_f(W, J, t);
        bool again = false;
        if (b > lv && cross_less(b, si, J->xv.lam, J->xv.other)) J->xv = (mc_cross){b, si}, again = true;
        if (J->pa != WK_NONE && isfinite(lf) && b < lf &&
            (J->xf.other == WK_NONE || cross_less(J->xf.lam, J->xf.other, b, si)))
            J->xf = (mc_cross){b, si}, again = true;
        if (again && schedule_seg(A, W, j) != WK_OK) return A->R->err.code;
    }
    return WK_OK;
}

/* A trace for a reflex vertex that is not a vertex of P (the collinear
** rule at t = 0, a multi-split, a vertex event): its ray against the
** wavefront, like 000's segments of vertices born later. */
static wk_status late_segment(mc_state *A, wk_wavefront *W, uint32_t v, double t) {
    wk_run *R = A->R;
    wk_point vel = wk_wf_velocity(W, v);
    double sp = hypot(vel.x, vel.y);
    if (!(sp > 0)) return WK_FAIL(R, WK_EALGO, wk_wf_polygon(W)->name, 0, "motorcycle: reflex vertex at rest");
    wk_count(R, WK_VC_late_traces, 1);
    uint32_t si;
    if (new_segment(A, v, wk_wf_position(W, v, t), (wk_point){vel.x / sp, vel.y / sp}, 0, &si) !=
        WK_OK)
        return R->err.code;
    if (place_f(A, W, si, t, false) != WK_OK) return R->err.code;
    mc_seg *S = &A->s[si];
    double lf = S->pa == WK_NONE ? NAN : lambda_f(W, S, t);
    S->len = isfinite(lf) && lf > 0 ? lf : 0;
    if (list_crossings(A, W, si, 0, S->len) != WK_OK) return R->err.code;
    return arm_segment(A, W, si);
}

/* The trace si waited at its end for a guard that ended early: extend it
** to where its ray meets the wavefront now. */
static wk_status extend_segment(mc_state *A, wk_wavefront *W, uint32_t si, double t) {
    mc_seg *S = &A->s[si];
    if (S->v == WK_NONE || !S->beyond) return WK_OK;
    wk_count(A->R, WK_VC_trace_extensions, 1);
    double old = S->len;
    if (place_f(A, W, si, t, false) != WK_OK) return A->R->err.code;
    S = &A->s[si];
    double lf = S->pa == WK_NONE ? NAN : lambda_f(W, S, t);
    if (isfinite(lf) && lf > S->len) S->len = lf;
    if (S->len > old && list_crossings(A, W, si, old, S->len) != WK_OK) return A->R->err.code;
    if (arm_segment(A, W, si) != WK_OK) return A->R->err.code;
    return wk_wf_reschedule(W, A->s[si].v);
}

static wk_status queue_ext(mc_state *A, uint32_t si) {
    if (WK_GROW(A->R, A->ext, A->cap_ext, A->n_ext + 1) != WK_OK) return A->R->err.code;
    A->ext[A->n_ext++] = si;
    return WK_OK;
}

/* Trace si ends at its crossing with sj (it crashed into sj, or with sj
** at one point): sj guards its end. */
static bool ends_on(const mc_state *A, uint32_t si, uint32_t sj, double slack) {
    const mc_seg *S = &A->s[si];
    for (uint32_t k = 0; k < S->nx; k++)
        if (S->x[k].other == sj && fabs(S->x[k].lam - S->len) <= slack) return true;
    return false;
}

/* Trace sj's part beyond lam will not be reached through sj any more: the
** traces waiting there with F beyond, whose end sj guards, are extended. */
static wk_status release_guards(mc_state *A, const wk_wavefront *W, uint32_t sj, double lam) {
    const mc_seg *T = &A->s[sj];
    double slack = WK_RELOCATE_SLACK * wk_wf_eps_d(W);
    for (uint32_t k = 0; k < T->nx; k++) {
        const mc_cross *c = &T->x[k];
        if (c->lam < lam || c->other >= A->n_s) continue;
        const mc_seg *S = &A->s[c->other];
        if (S->v != WK_NONE && S->beyond && ends_on(A, c->other, sj, slack) &&
            queue_ext(A, c->other) != WK_OK)
            return A->R->err.code;
        T = &A->s[sj];
    }
    return WK_OK;
}

static wk_status remove_segment(mc_state *A, wk_wavefront *W, uint32_t si, double t) {
    mc_seg *S = &A->s[si];
    DBG("t=%.9g remove seg %u v %u lv %.9g lf %.9g len %.9g\n", t, si, S->v, lambda_v(W, S, t), lambda_f(W, S, t), S->len);
    /* where v ended: beyond it the trace is unswept unless F was there */
    double lv = lambda_v(W, S, t), lf = lambda_f(W, S, t);
    if (!(isfinite(lf) && lf <= lv + WK_RELOCATE_SLACK * wk_wf_eps_d(W)) &&
        release_guards(A, W, si, lv - wk_wf_eps_d(W)) != WK_OK)
        return A->R->err.code;
    S = &A->s[si];
    unlink_f(A, si);
    A->seg_of[S->v] = WK_NONE;
    S->v = WK_NONE;
    wk_event_queue_remove(A->R, &A->Q, si);
    return WK_OK;
}

/* -------------------------------------------------------------- hooks */

static void brute_split(wk_wavefront *W, uint32_t v) {
    wk_event ev = {wk_wf_now(W), 0, 0, v, WK_NONE, WK_NONE};
    wk_notify_event(wk_wf_run(W), WK_VC_brute_force_split_scans, &ev);
    wk_wf_split_scan(W, v);
}

/* Contacts across sub-tolerance edges next to v (see the arrangement
** variant's README: the reference takes them as splits right now). */
static void near_split(wk_wavefront *W, uint32_t v) {
    double t = wk_wf_now(W), near = WK_ARR_NEAR_SLACK * wk_wf_eps_d(W);
    wk_point pv = wk_wf_position(W, v, t);
    wk_wf_split_search s;
    wk_wf_split_begin(W, v, &s);
    for (uint32_t a = wk_wf_next(W, v); a != v && wk_wf_next(W, a) != v; a = wk_wf_next(W, a)) {
        wk_wf_split_test(W, &s, a);
        wk_point pa = wk_wf_position(W, a, t);
        if (!(hypot(pa.x - pv.x, pa.y - pv.y) <= near)) break;
    }
    for (uint32_t b = wk_wf_prev(W, v); b != v && wk_wf_prev(W, b) != v; b = wk_wf_prev(W, b)) {
        wk_wf_split_test(W, &s, wk_wf_prev(W, b));
        wk_point pb = wk_wf_position(W, b, t);
        if (!(hypot(pb.x - pv.x, pb.y - pv.y) <= near)) break;
    }
    wk_wf_split_offer(W, &s);
}

static void mc_full(void *ud, wk_wavefront *W, uint32_t v) {
    mc_state *A = ud;
    near_split(W, v);
    if (v >= A->cap_v || A->seg_of[v] == WK_NONE) {
        brute_split(W, v);
        return;
    }
    const mc_seg *S = &A->s[A->seg_of[v]];
    if (S->beyond) return; /* the wavefront has not reached v's trace yet */
    if (S->probe != WK_NONE && wk_wf_alive(W, S->probe)) {
        wk_wf_split_search q;
        wk_wf_split_begin(W, v, &q);
        uint32_t a = wk_wf_prev(W, wk_wf_prev(W, S->probe));
        for (int k = 0; k < 5; k++, a = wk_wf_next(W, a))
            if (a != v && wk_wf_next(W, a) != v) wk_wf_split_test(W, &q, a);
        wk_wf_split_offer(W, &q);
        return;
    }
    if (S->pa == WK_NONE || !wk_wf_alive(W, S->pa) || wk_wf_next(W, S->pa) != S->pb) {
        brute_split(W, v);
        return;
    }
    double t0 = wk_wf_now(W);
    double lv0 = lambda_v(W, S, t0), lv1 = lambda_v(W, S, t0 + 1);
    double lf0 = lambda_f(W, S, t0), lf1 = lambda_f(W, S, t0 + 1);
    if (!isfinite(lf0) || !isfinite(lf1)) return;
    double gap = lf0 - lv0, rate = (lf1 - lf0) - (lv1 - lv0);
    if (!(rate < 0)) return;
    double t = t0 + (gap > 0 ? gap : 0) / -rate;
    wk_wf_offer_split(W, v, t, wk_wf_position(W, v, t), S->pa, S->pb);
}

static void mc_incremental(void *ud, wk_wavefront *W, uint32_t v) { mc_full(ud, W, v); }

static wk_status mc_start(void *ud, wk_wavefront *W) {
    mc_state *A = ud;
    wk_run *R = A->R;
    const wk_polygon *P = wk_wf_polygon(W);
    if (ensure_vertex_arrays(A, wk_wf_vertex_count(W)) != WK_OK) return R->err.code;
    wk_motorcycle_graph *G = NULL;
    wk_status st = wk_motorcycle_graph_build(R, P, &G);
    if (st != WK_OK) return st;
    wk_count(R, WK_VC_motorcycles, G->stats.motorcycles);
    wk_count(R, WK_VC_wall_crashes, G->stats.wall_crashes);
    wk_count(R, WK_VC_trace_crashes, G->stats.trace_crashes);
    wk_count(R, WK_VC_simultaneous_crashes, G->stats.simultaneous_motorcycles);
    wk_count(R, WK_VC_crash_candidates, G->stats.candidate_pairs);
    /* motorcycle i is trace seg_id[i]; one whose vertex the collinear rule
    ** changed at t = 0 gets none.  The graph's frame is the wavefront's
    ** (both relative to wk_polygon_centre). */
    uint32_t *seg_id = G->n ? WK_NEW_ARRAY(R, uint32_t, G->n) : NULL;
    if (G->n && !seg_id) {
        wk_motorcycle_graph_free(R, G);
        return R->err.code;
    }
    for (uint32_t i = 0; st == WK_OK && i < G->n; i++) {
        const wk_motorcycle *m = &G->m[i];
        seg_id[i] = WK_NONE;
        if (!wk_wf_alive(W, m->vertex) || !wk_wf_reflex(W, m->vertex)) continue;
        uint32_t si;
        if ((st = new_segment(A, m->vertex, m->o, m->u, m->len, &si)) != WK_OK) break;
        seg_id[i] = si;
        if (m->kind != WK_MCG_WALL) {
            A->s[si].beyond = true;
        } else if (m->wall_edge != WK_NONE && wk_wf_alive(W, m->wall_edge) &&
                   wk_wf_start_time(W, m->wall_edge) == 0 &&
                   wk_wf_edge_out(W, m->wall_edge) == m->wall_edge) {
            link_f(A, W, si, m->wall_edge);
        } else {
            st = place_f(A, W, si, 0.0, true);
        }
    }
    /* the resting Steiner vertices: the traces ending on each trace, and
    ** each trace's own end on the trace (or with the traces) it met */
    for (uint32_t i = 0; st == WK_OK && i < G->n; i++) {
        uint32_t si = seg_id[i];
        if (si == WK_NONE) continue;
        for (uint32_t k = G->steiner_start[i]; st == WK_OK && k < G->steiner_start[i + 1]; k++) {
            uint32_t j = G->steiner[k].other;
            if (j < G->n && seg_id[j] != WK_NONE) st = add_cross(A, si, G->steiner[k].d, seg_id[j]);
        }
        const wk_motorcycle *m = &G->m[i];
        uint32_t on = m->kind == WK_MCG_TRACE ? m->other
                      : m->kind == WK_MCG_SIMULTANEOUS ? G->groups[m->group].on_other
                                                        : WK_NONE;
        if (st == WK_OK && on != WK_NONE && on < G->n && seg_id[on] != WK_NONE)
            st = add_cross(A, si, m->len, seg_id[on]);
    }
    /* a trace waiting at its end with no live guard there is shot now */
    for (uint32_t i = 0; st == WK_OK && i < G->n; i++) {
        uint32_t si = seg_id[i];
        if (si == WK_NONE || !A->s[si].beyond) continue;
        bool has_guard = false;
        const mc_seg *S = &A->s[si];
        for (uint32_t k = 0; k < S->nx && !has_guard; k++)
            has_guard = fabs(S->x[k].lam - S->len) <= WK_RELOCATE_SLACK * wk_wf_eps_d(W);
        if (!has_guard) st = place_f(A, W, si, 0.0, true);
    }
    if (seg_id) WK_FREE_ARRAY(R, seg_id, G->n);
    wk_motorcycle_graph_free(R, G);
    uint32_t n_graph = A->n_s;
    for (uint32_t si = 0; st == WK_OK && si < n_graph; si++) st = arm_segment(A, W, si);
    /* reflex vertices of t = 0 that are not motorcycles (the collinear rule) */
    for (uint32_t v = 0; st == WK_OK && v < wk_wf_vertex_count(W); v++)
        if (wk_wf_alive(W, v) && wk_wf_reflex(W, v) && A->seg_of[v] == WK_NONE)
            st = late_segment(A, W, v, 0.0);
    return st;
}

static bool relocate_locally(mc_state *A, wk_wavefront *W, uint32_t si, double t) {
    mc_seg *S = &A->s[si];
    double old = lambda_on_line(S, wk_wf_line(W, wk_wf_edge_out(W, S->pa)), t);
    if (!isfinite(old)) return false;
    double lv = lambda_v(W, S, t), best = INFINITY, mu;
    uint32_t pick = WK_NONE;
    const uint32_t *fresh, *ended;
    uint32_t n_fresh, n_ended;
    wk_wf_last_group(W, &fresh, &n_fresh, &ended, &n_ended);
    for (uint32_t i = 0; i < n_fresh; i++) {
        uint32_t g = fresh[i];
        if (!wk_wf_alive(W, g)) continue;
        uint32_t two[2] = {g, wk_wf_prev(W, g)};
        for (int j = 0; j < 2; j++) {
            uint32_t a = two[j];
            if (a == S->v || wk_wf_next(W, a) == S->v) continue;
            double lam = hit_piece(W, S, a, t, lv, &mu);
            if (lam < best && mu > WK_RAY_END_SNAP && mu < 1 - WK_RAY_END_SNAP) {
                best = lam;
                pick = a;
            }
        }
    }
    if (pick == WK_NONE || !(fabs(best - old) <= WK_RELOCATE_SLACK * wk_wf_eps_d(W))) return false;
    unlink_f(A, si);
    link_f(A, W, si, pick);
    return true;
}

static wk_status queue_todo(mc_state *A, uint32_t si) {
    if (A->s[si].mark == A->stamp || A->s[si].v == WK_NONE) return WK_OK;
    A->s[si].mark = A->stamp;
    if (WK_GROW(A->R, A->todo, A->cap_todo, A->n_todo + 1) != WK_OK) return A->R->err.code;
    A->todo[A->n_todo++] = si;
    return WK_OK;
}

static wk_status flush_extensions(mc_state *A, wk_wavefront *W, double t) {
    for (uint32_t i = 0; i < A->n_ext; i++)
        if (extend_segment(A, W, A->ext[i], t) != WK_OK) return A->R->err.code;
    A->n_ext = 0;
    return WK_OK;
}

static wk_status mc_after_group(void *ud, wk_wavefront *W, double t) {
    mc_state *A = ud;
    wk_run *R = A->R;
    if (ensure_vertex_arrays(A, wk_wf_vertex_count(W)) != WK_OK) return R->err.code;
    const uint32_t *fresh, *ended;
    uint32_t n_fresh, n_ended;
    wk_wf_last_group(W, &fresh, &n_fresh, &ended, &n_ended);
    A->stamp++;
    A->n_todo = 0;
    for (uint32_t i = 0; i < A->n_held; i++) {
        uint32_t si = A->held[i];
        A->s[si].hold = false;
        A->s[si].probe = WK_NONE;
        if (A->s[si].v != WK_NONE && queue_todo(A, si) != WK_OK) return R->err.code;
    }
    A->n_held = 0;
    for (int pass = 0; pass < 2; pass++) {
        uint32_t n = pass ? n_fresh : n_ended;
        const uint32_t *list = pass ? fresh : ended;
        for (uint32_t i = 0; i < n; i++) {
            uint32_t a = list[i];
            if (a >= A->cap_v) continue;
            for (uint32_t si = A->fhead[a]; si != WK_NONE; si = A->s[si].next_on)
                if (queue_todo(A, si) != WK_OK) return R->err.code;
        }
    }
    for (uint32_t i = 0; i < n_ended; i++) {
        uint32_t d = ended[i];
        if (d < A->cap_v && A->seg_of[d] != WK_NONE && remove_segment(A, W, A->seg_of[d], t) != WK_OK)
            return R->err.code;
    }
    /* rare: every F that became unknown is tried again */
    for (uint32_t i = 0; i < A->n_unknown; i++) {
        uint32_t si = A->unknown[i];
        if (A->s[si].v != WK_NONE && A->s[si].pa == WK_NONE && !A->s[si].beyond &&
            queue_todo(A, si) != WK_OK)
            return R->err.code;
    }
    A->n_unknown = 0;
    for (uint32_t i = 0; i < A->n_todo; i++) {
        uint32_t si = A->todo[i];
        mc_seg *S = &A->s[si];
        if (S->v == WK_NONE || !wk_wf_alive(W, S->v) || S->beyond) continue;
        if (S->pa != WK_NONE && wk_wf_alive(W, S->pa) && wk_wf_next(W, S->pa) == S->pb) {
            if (schedule_seg(A, W, si) != WK_OK) return R->err.code; /* released hold */
            continue;
        }
        if (S->pa != WK_NONE && relocate_locally(A, W, si, t)) {
            if (schedule_seg(A, W, si) != WK_OK || wk_wf_reschedule(W, A->s[si].v) != WK_OK)
                return R->err.code;
            continue;
        }
        if (place_f(A, W, si, t, true) != WK_OK || arm_segment(A, W, si) != WK_OK || wk_wf_reschedule(W, A->s[si].v) != WK_OK)
            return R->err.code;
    }
    for (uint32_t i = 0; i < n_fresh; i++) {
        uint32_t v = fresh[i];
        if (!wk_wf_alive(W, v) || !wk_wf_reflex(W, v) || A->seg_of[v] != WK_NONE) continue;
        if (late_segment(A, W, v, t) != WK_OK || wk_wf_reschedule(W, v) != WK_OK) return R->err.code;
    }
    return flush_extensions(A, W, t);
}

static double mc_next_time(void *ud) {
    mc_state *A = ud;
    if (!A->Q.size) return INFINITY;
    return A->Q.key[wk_event_queue_peek(&A->Q)].time;
}

/* Cut s' at lam (a crossing X): F' := X on piece a. */
static wk_status cut(mc_state *A, wk_wavefront *W, uint32_t sj, uint32_t a, double lam, uint32_t via) {
    mc_seg *T = &A->s[sj];
    DBG("  cut seg %u (v %u) at %.9g by piece %u via %u\n", sj, T->v, lam, a, via);
    double t = wk_wf_now(W);
    /* the part of s' beyond X is no longer reached from v': its guards go */
    if (release_guards(A, W, sj, lam + WK_RELOCATE_SLACK * wk_wf_eps_d(W)) != WK_OK)
        return A->R->err.code;
    T = &A->s[sj];
    unlink_f(A, sj);
    link_f(A, W, sj, a);
    double l0 = lambda_f(W, T, t), l1 = lambda_f(W, T, t + 1);
    T = &A->s[sj];
    if (!(l1 < l0) && fabs(lam - lambda_v(W, T, t)) <= WK_RELOCATE_SLACK * wk_wf_eps_d(W)) {
        /* v' is at X itself as the piece passes (two reflex vertices
        ** meeting; v' at its crash point): its split is with a piece next
        ** to the cutting one, found by the reference's test over those
        ** (mc_full) until the group that follows; no ray shot. */
        unlink_f(A, sj);
        T = &A->s[sj];
        T->probe = a;
        T->xf = NO_CROSS;
        if (hold(A, sj) != WK_OK) return A->R->err.code;
    } else if (!(l1 < l0)) {
        if (place_f(A, W, sj, t, true) != WK_OK) return A->R->err.code;
        T = &A->s[sj];
        double lf = lambda_f(W, T, t);
        T->xf = isfinite(lf) ? next_down(T, lf, WK_NONE) : NO_CROSS;
    } else {
        /* from the stored crossing (lam is recomputed from the geometry) */
        double at = lam, gap = INFINITY;
        for (uint32_t k = 0; k < T->nx; k++)
            if (T->x[k].other == via && fabs(T->x[k].lam - lam) < gap)
                gap = fabs(T->x[k].lam - lam), at = T->x[k].lam;
        T->xf = next_down(T, at, via);
    }
    if (schedule_seg(A, W, sj) != WK_OK) return A->R->err.code;
    if (wk_wf_reschedule(W, A->s[sj].v) != WK_OK) return A->R->err.code;
    return flush_extensions(A, W, t);
}

/* X (at lx on T) is in T's unswept part. */
static bool unswept(const wk_wavefront *W, const mc_seg *T, double lx, double t) {
    double lv = lambda_v(W, T, t), lf = lambda_f(W, T, t);
    return lx > lv - wk_wf_eps_d(W) && (!isfinite(lf) || lx < lf - wk_wf_eps_d(W));
}

static wk_status mc_process_next(void *ud, wk_wavefront *W) {
    mc_state *A = ud;
    wk_run *R = A->R;
    uint32_t si = wk_event_queue_pop(R, &A->Q);
    mc_seg *S = &A->s[si];
    double t = wk_wf_now(W);
    A->guard_n = t == A->guard_t ? A->guard_n + 1 : 0;
    A->guard_t = t;
    if (A->guard_n > 16 * ((uint64_t)A->n_s + wk_wf_vertex_count(W)) + 1024)
        return WK_FAIL(R, WK_EALGO, wk_wf_polygon(W)->name, 0, "motorcycle: no progress at t = %.17g", t);
    wk_event ev = {t, 0, 0, si, WK_NONE, WK_NONE};
    DBG("t=%.9g seg %u v %u kind %d pa %d beyond %d xf(%.6g,%d) xv(%.6g,%d) len %.6g\n", t, si, S->v, S->ev_kind, (int)S->pa, S->beyond, S->xf.lam, (int)S->xf.other, S->xv.lam, (int)S->xv.other, S->len);
    if (S->v == WK_NONE) return WK_OK;
    if (S->ev_kind == MC_SWITCH) {
        uint32_t old_pa = S->pa;
        uint32_t u = S->ev_end ? S->pb : S->pa;
        uint32_t a = S->ev_end ? S->pb : wk_wf_prev(W, S->pa);
        unlink_f(A, si);
        link_f(A, W, si, a);
        wk_notify_event(R, WK_VC_switch_events, &ev);
        seg_event(A, W, si);
        uint32_t v = A->s[si].v;
        bool own = a == v || wk_wf_next(W, a) == v;
        if (own && fabs(lambda_f(W, &A->s[si], t) - lambda_v(W, &A->s[si], t)) <=
                       WK_RELOCATE_SLACK * wk_wf_eps_d(W)) {
            /* F passes v's neighbour onto v's own piece where it meets v:
            ** v's event (the neighbour's edge collapsing) is now.  F stays
            ** on the piece it had; the group that follows places it. */
            unlink_f(A, si);
            link_f(A, W, si, old_pa);
            if (hold(A, si) != WK_OK) return R->err.code;
            if (schedule_seg(A, W, si) != WK_OK) return R->err.code;
            return wk_wf_reschedule(W, v);
        }
        bool bounce = A->s[si].ev_kind == MC_SWITCH && A->s[si].ev_t <= t;
        bool jump = wk_wf_reflex(W, u);
        if (jump && !own && !bounce) {
            /* Over a reflex vertex u the first wavefront point along the
            ** trace may jump elsewhere, unless u's other piece takes over at
            ** u itself: it does when its crossing with the trace moves
            ** towards v (u sits on the trace, at a resting Steiner vertex
            ** or the trace's end).  Then no ray shot is needed. */
            const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, a));
            double l0 = lambda_on_line(&A->s[si], L, t), l1 = lambda_on_line(&A->s[si], L, t + 1);
            jump = !(l1 < l0);
        }
        if (own || jump || bounce) {
            if (place_f(A, W, si, t, true) != WK_OK) return R->err.code;
            seg_event(A, W, si);
            if (A->s[si].pa == old_pa && A->s[si].ev_kind == MC_SWITCH && A->s[si].ev_t <= t) {
                unlink_f(A, si);
                if (note_unknown(A, si) != WK_OK) return R->err.code;
            }
            S = &A->s[si];
            double lf = lambda_f(W, S, t);
            S->xf = S->pa != WK_NONE && isfinite(lf) ? next_down(S, lf, WK_NONE) : NO_CROSS;
        }
        S = &A->s[si];
        if (schedule_seg(A, W, si) != WK_OK) return R->err.code;
        return wk_wf_reschedule(W, S->v);
    }
    uint8_t kind = S->ev_kind;
    mc_cross x = kind == MC_START ? S->xf : S->xv;
    wk_notify_event(R, WK_VC_start_events, &ev);
    uint32_t sj = x.other < A->n_s && A->s[x.other].v != WK_NONE ? x.other : WK_NONE;
    if (sj != WK_NONE) {
        const mc_seg *T = &A->s[sj];
        wk_point X = {S->o.x + x.lam * S->u.x, S->o.y + x.lam * S->u.y};
        double lx = lambda_of(T, X);
        if (unswept(W, T, lx, t)) {
            uint32_t pick = WK_NONE;
            if (kind == MC_START) {
                pick = S->pa;
            } else {
                /* which of v's pieces faces v': the one whose crossing with
                ** s' moves towards v' */
                uint32_t v = S->v, cand[2] = {wk_wf_prev(W, v), v};
                double best = INFINITY;
                for (int c = 0; c < 2; c++) {
                    const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, cand[c]));
                    double l1 = lambda_on_line(T, L, t + 1), l0 = lambda_on_line(T, L, t);
                    if (isfinite(l0) && isfinite(l1) && l1 - l0 < best) {
                        best = l1 - l0;
                        pick = cand[c];
                    }
                }
            }
            if (pick != WK_NONE && cut(A, W, sj, pick, lx, si) != WK_OK) return R->err.code;
        }
    }
    S = &A->s[si];
    if (kind == MC_START) S->xf = next_down(S, x.lam, x.other);
    else S->xv = next_up(S, x.lam, x.other);
    return schedule_seg(A, W, si);
}

static wk_status mc_check(void *ud, const wk_wavefront *W) {
    const mc_state *A = ud;
    const char *name = wk_wf_polygon(W)->name;
    for (uint32_t si = 0; si < A->n_s; si++) {
        const mc_seg *S = &A->s[si];
        if (S->v == WK_NONE) continue;
        if (!wk_wf_alive(W, S->v) || A->seg_of[S->v] != si)
            return WK_FAIL(A->R, WK_EALGO, name, 0, "invariant: trace %u's vertex %u is gone", si, S->v);
        if (S->pa != WK_NONE && (!wk_wf_alive(W, S->pa) || wk_wf_next(W, S->pa) != S->pb))
            return WK_FAIL(A->R, WK_EALGO, name, 0, "invariant: trace %u's F is on a dead piece", si);
        if (S->beyond && S->pa != WK_NONE)
            return WK_FAIL(A->R, WK_EALGO, name, 0, "invariant: trace %u's F is beyond and on a piece", si);
    }
    return WK_OK;
}

static const wk_split_finder motorcycle_finder = {
    .full = mc_full,
    .incremental = mc_incremental,
    .start = mc_start,
    .after_group = mc_after_group,
    .next_time = mc_next_time,
    .process_next = mc_process_next,
    .check = mc_check,
    .local_refresh = true,
};

static wk_status motorcycle_run(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    for (uint32_t i = 1; i < P->n; i++)
        if (P->w[i] != P->w[0])
            return WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                           "the motorcycle variant supports equal weights only (edge %u has weight "
                           "%g, edge %u %g): the motorcycle graph of P does not cover the reflex arcs "
                           "of a weighted skeleton (README); use --variant naive or arrangement",
                           wk_polygon_input_edge(P, i), P->w[i], wk_polygon_input_edge(P, 0), P->w[0]);
    mc_state A;
    memset(&A, 0, sizeof A);
    A.R = R;
    wk_event_queue_init(&A.Q);
    wk_status st = wk_wavefront_run(R, P, &motorcycle_finder, &A, out);
    wk_event_queue_clear(R, &A.Q);
    for (uint32_t si = 0; si < A.n_s; si++)
        if (A.s[si].capx) WK_FREE_ARRAY(R, A.s[si].x, A.s[si].capx);
    WK_FREE_ARRAY(R, A.s, A.cap_s);
    WK_FREE_ARRAY(R, A.todo, A.cap_todo);
    WK_FREE_ARRAY(R, A.ext, A.cap_ext);
    WK_FREE_ARRAY(R, A.unknown, A.cap_unknown);
    WK_FREE_ARRAY(R, A.held, A.cap_held);
    if (A.cap_v) {
        WK_FREE_ARRAY(R, A.seg_of, A.cap_v);
        WK_FREE_ARRAY(R, A.fhead, A.cap_v);
    }
    return st;
}

static const wk_counter_def mc_counters[] = WK_VARIANT_COUNTER_TABLE(MC_COUNTER_LIST);

const wk_variant wk_variant_motorcycle = {
    "motorcycle",
    "wavefront on the motorcycle graph M(P) (002); equal weights, polygons with holes",
    0,
    mc_counters,
    sizeof mc_counters / sizeof mc_counters[0],
    motorcycle_run,
};
