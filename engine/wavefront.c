/*
** wavefront.c: the kinetic wavefront shared by the variants.  Event-driven
** simulation of the weighted wavefront of a simple polygon; how split events
** are found is the variant's business (a wk_split_finder: brute force in
** naive, the bisector arrangement in arrangement), everything else is here.
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
** Resolution (the heart of the reference).  All events within the time
** tolerance of the earliest one form a group.  The group is resolved by
** geometry, not by event type, which makes every degenerate combination
** (multi-split, vanishing triangles and components, parallel edges meeting,
** several events at one point) one code path:
**   1. nodes: cluster the event points (distance tolerance);
**   2. every vertex of the touched cycles within tolerance of a node arrives
**      there; every piece passing through a node is cut there (pinch);
**   3. the cycles become directed sub-pieces between points (nodes or
**      untouched vertices); zero-length sub-pieces vanish (edge events);
**      two opposite sub-pieces between the same two nodes cancel and leave a
**      skeleton arc (parallel edges that met);
**   4. at each node the remaining incoming and outgoing sub-pieces are
**      paired: an incoming one continues with the first outgoing one
**      clockwise from it (the wavefront interior lies in that sector), and
**      each pair becomes a new wavefront vertex;
**   5. a pair of antiparallel edges (a zero-width spike) means a vertex
**      lies on a piece without being a node yet: it is made a node and the
**      group is resolved again.
** Collinear edges of different weight that become adjacent cannot share a
** moving vertex (000, section 1): the losing edge (higher weight by default,
** lower with --collinear higher) is removed at once, leaving an arc along it
** at the current time, and its far neighbour is joined to the winner.
**
** Tolerances: WK_TOL_REL times the polygon's scale for distances, divided by
** the largest weight for times (wskel.h).
*/
#include "wavefront.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.283185307179586476925286766559

static double dist2(wk_point a, wk_point b) {
    double dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

static uint32_t new_vertex(wk_wavefront *N, uint32_t ein, uint32_t eout, wk_point p, double t,
                           uint32_t node) {
    if (WK_GROW(N->R, N->v, N->cap_v, N->nv + 1) != WK_OK) return WK_NONE;
    uint32_t id = N->nv++;
    wk_wf_vertex *x = &N->v[id];
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
    x->vkind = (uint8_t)wk_vertex_start(N->L, ein, eout, p, t, N->eps_d, &x->p0, &x->vel, &reflex);
    x->reflex = reflex;
    return id;
}

static wk_status add_arc(wk_wavefront *N, uint32_t a, uint32_t b, uint32_t left, uint32_t right) {
    if (a == b) return WK_OK; /* zero-length: nothing traced */
    if (left == right)
        return WK_FAIL(N->R, WK_EALGO, N->P->name, 0,
                       "wavefront: arc between nodes %u and %u would have face %u on both sides", a, b,
                       left);
    return wk_skeleton_add_arc(N->R, N->S, a, b, left, right);
}

/* Kill v at node sk: its arc runs from where it started to sk. */
static wk_status terminate(wk_wavefront *N, uint32_t v, uint32_t sk) {
    wk_wf_vertex *x = &N->v[v];
    x->alive = 0;
    wk_event_queue_remove(N->R, &N->Q, v);
    if (wk_grow(N->R, (void **)&N->dead, &N->cap_dead, N->n_dead + 1, sizeof *N->dead) != WK_OK)
        return N->R->err.code;
    N->dead[N->n_dead++] = v;
    return add_arc(N, x->node, sk, x->ein, x->eout);
}

/* -------------------------------------------------------------- events */

/* Replace a kinematic estimate (t, p) of the event where offset lines e1,
** e2, e3 meet by their exact meeting point when that system is well
** conditioned and agrees with the estimate: the event then depends on input
** edges only, as in CGAL's trisegments. */
static void refine(const wk_wavefront *N, const wk_wf_vertex *V, uint32_t e1, uint32_t e2, uint32_t e3,
                   double *t, wk_point *p) {
    if (e1 == e2 || e2 == e3 || e1 == e3 || V->vkind != WK_VEL_REGULAR) return;
    wk_point q;
    double tq;
    if (!wk_three_lines_meet(&N->L[e1], &N->L[e2], &N->L[e3], &q, &tq)) return;
    double speed = fabs(V->vel.x) + fabs(V->vel.y);
    if (fabs(tq - *t) > 16 * N->eps_t || dist2(q, *p) > 256 * N->eps_d * N->eps_d * (1 + speed * speed))
        return;
    if (tq < N->t_now) tq = N->t_now;
    *t = tq;
    *p = q;
}

/* Collapse time of the piece a -> a.next, relative motion along the edge. */
static void edge_event(wk_wavefront *N, uint32_t a, double *t, wk_point *p) {
    const wk_wf_vertex *A = &N->v[a], *B = &N->v[A->next];
    const wk_offset_line *L = &N->L[A->eout];
    double t0 = N->t_now;
    wk_point pa = wk_wf_pos(A, t0), pb = wk_wf_pos(B, t0);
    double d = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
    double rate = (B->vel.x - A->vel.x) * L->ux + (B->vel.y - A->vel.y) * L->uy;
    *t = INFINITY;
    if (d <= N->eps_d && rate <= 0) {
        *t = t0;
    } else if (rate < 0) {
        *t = t0 + (d > 0 ? d : 0) / -rate;
    } else {
        return;
    }
    wk_point qa = wk_wf_pos(A, *t), qb = wk_wf_pos(B, *t);
    *p = (wk_point){0.5 * (qa.x + qb.x), 0.5 * (qa.y + qb.y)};
    if (B->vkind == WK_VEL_REGULAR) refine(N, A, A->ein, A->eout, B->eout, t, p);
}

void wk_wavefront_split_test(wk_wavefront *N, uint32_t vi, uint32_t a, double *best,
                             wk_point *bp, uint32_t *ta, uint32_t *tb) {
    const wk_wf_vertex *V = &N->v[vi], *A = &N->v[a];
    uint32_t b = A->next;
    if (a == vi || b == vi) return; /* its own pieces */
    const wk_wf_vertex *B = &N->v[b];
    const wk_offset_line *L = &N->L[A->eout];
    double rate = L->nx * V->vel.x + L->ny * V->vel.y - L->w;
    if (rate >= -1e-12 * (L->w + fabs(V->vel.x) + fabs(V->vel.y))) return;
    wk_point pv = wk_wf_pos(V, N->t_now);
    double d0 = wk_offset_distance(L, pv, N->t_now);
    if (d0 < -N->eps_d) return; /* already beyond the line: moving away */
    double t = N->t_now + (d0 > 0 ? d0 : 0) / -rate;
    if (t > *best) return;
    wk_point p = wk_wf_pos(V, t), pa = wk_wf_pos(A, t), pb = wk_wf_pos(B, t);
    double sa = (p.x - pa.x) * L->ux + (p.y - pa.y) * L->uy;
    double sb = (pb.x - p.x) * L->ux + (pb.y - p.y) * L->uy;
    if (sa < -N->eps_d || sb < -N->eps_d) return;
    if (t == *best && *ta != WK_NONE && a > *ta) return; /* deterministic tie */
    refine(N, V, V->ein, V->eout, A->eout, &t, &p);
    *best = t;
    *bp = p;
    *ta = a;
    *tb = b;
}

static wk_status schedule(wk_wavefront *N, uint32_t vi) {
    wk_wf_vertex *V = &N->v[vi];
    double t = V->ev_t;
    if (V->ev_kind == WK_WF_NONE || !isfinite(t)) {
        wk_event_queue_remove(N->R, &N->Q, vi);
        return WK_OK;
    }
    if (t < N->t_now) t = N->t_now;
    return wk_event_queue_set(N->R, &N->Q, vi, (wk_event_key){t, V->ev_kind});
}

/* Full recomputation of vi's candidate: its edge event and, if reflex, the
** split event the finder reports. */
static void full_candidate(wk_wavefront *N, uint32_t vi) {
    wk_wf_vertex *V = &N->v[vi];
    double t;
    wk_point p = {0, 0};
    edge_event(N, vi, &t, &p);
    V->ev_kind = isfinite(t) ? WK_WF_EDGE : WK_WF_NONE;
    V->ev_t = t;
    V->ev_p = p;
    V->ev_a = vi;
    V->ev_b = V->next;
    V->cand_next = V->next;
    V->fresh = 0;
    if (V->reflex) N->finder->full(N->finder_ud, N, vi);
}

void wk_wavefront_split_scan(wk_wavefront *N, uint32_t vi) {
    double best = N->v[vi].ev_t;
    wk_point bp = N->v[vi].ev_p;
    uint32_t ta = WK_NONE, tb = WK_NONE;
    for (uint32_t a = N->v[vi].next; a != vi; a = N->v[a].next)
        wk_wavefront_split_test(N, vi, a, &best, &bp, &ta, &tb);
    wk_wavefront_offer_split(N, vi, best, bp, ta, tb);
}

void wk_wavefront_offer_split(wk_wavefront *N, uint32_t vi, double t, wk_point p, uint32_t a,
                              uint32_t b) {
    wk_wf_vertex *V = &N->v[vi];
    if (a == WK_NONE || !(t < V->ev_t)) return;
    V->ev_kind = WK_WF_SPLIT;
    V->ev_t = t;
    V->ev_p = p;
    V->ev_a = a;
    V->ev_b = b;
}

wk_status wk_wavefront_reschedule(wk_wavefront *N, uint32_t vi) {
    full_candidate(N, vi);
    return schedule(N, vi);
}

bool wk_wavefront_target_alive(const wk_wavefront *N, const wk_wf_vertex *V) {
    if (V->ev_kind == WK_WF_NONE) return true; /* nothing to lose */
    const wk_wf_vertex *A = &N->v[V->ev_a];
    return A->alive && A->next == V->ev_b;
}

/* ------------------------------------------------------------ clusters */

static uint32_t find_cluster_within(const wk_wavefront *N, wk_point p, double r) {
    double e2 = r * r;
    for (uint32_t k = 0; k < N->n_cl; k++)
        if (dist2(N->cl[k].p, p) <= e2) return k;
    return WK_NONE;
}

static uint32_t find_cluster(const wk_wavefront *N, wk_point p) {
    double e2 = N->eps_d * N->eps_d;
    for (uint32_t k = 0; k < N->n_cl; k++)
        if (dist2(N->cl[k].p, p) <= e2) return k;
    return WK_NONE;
}

static wk_status add_cluster(wk_wavefront *N, wk_point p, uint32_t *k) {
    *k = find_cluster(N, p);
    if (*k != WK_NONE) return WK_OK;
    if (WK_GROW(N->R, N->cl, N->cap_cl, N->n_cl + 1) != WK_OK) return N->R->err.code;
    N->cl[N->n_cl] = (wk_wf_cluster){p, WK_NONE, 0, 0, 0, 0, 0, 0};
    *k = N->n_cl++;
    return WK_OK;
}

static wk_status push_u32(wk_run *R, uint32_t **a, uint32_t *n, uint32_t *cap, uint32_t x) {
    if (wk_grow(R, (void **)a, cap, *n + 1, sizeof **a) != WK_OK) return R->err.code;
    (*a)[(*n)++] = x;
    return WK_OK;
}

/* ---------------------------------------------------------- resolution */

static double angle_of(const wk_offset_line *L, bool incoming) {
    return incoming ? atan2(-L->uy, -L->ux) : atan2(L->uy, L->ux);
}

/* Clockwise turn from angle a to angle b in (0, 2 pi]. */
static double cw_turn(double a, double b) {
    double d = a - b;
    while (d <= 1e-13) d += TWO_PI;
    while (d > TWO_PI + 1e-13) d -= TWO_PI;
    return d;
}

static wk_point point_pos(const wk_wavefront *N, uint32_t pt, double t) {
    return IS_NODE(pt) ? N->cl[NODE_OF(pt)].p : wk_wf_pos(&N->v[pt], t);
}

static int cmp_pinch(const void *a, const void *b) {
    const wk_wf_pinch *x = a, *y = b;
    if (x->piece != y->piece) return x->piece < y->piece ? -1 : 1;
    if (x->s != y->s) return x->s < y->s ? -1 : 1;
    return x->node < y->node ? -1 : x->node > y->node;
}

/* Walk the cycles of the seeds (and forced vertices) into N->comp. */
static wk_status push_local(wk_wavefront *N, uint32_t u) {
    if (N->v[u].seen == N->stamp) return WK_OK;
    N->v[u].seen = N->stamp;
    N->v[u].at = WK_NONE;
    N->v[u].cyc = 0;
    return push_u32(N->R, &N->comp, &N->n_comp, &N->cap_comp, u);
}

/* A group of one event touches a handful of vertices, not its whole cycle:
** the seed, the target piece of a split, and LOCAL_REACH neighbours on each
** side of them.  Walking the whole cycle for each event made a big convex
** wavefront quadratic (a 100,000-gon: 10^10 steps).  Groups of several
** events, or with forced vertices, are degenerate and walk whole cycles. */
#define LOCAL_REACH 3
static wk_status collect_local(wk_wavefront *N, bool *closed) {
    N->stamp++;
    N->n_comp = 0;
    N->n_cyc = 1;
    const wk_wf_vertex *S = &N->v[N->seeds[0]];
    uint32_t centres[3] = {N->seeds[0], WK_NONE, WK_NONE};
    if (S->ev_kind == WK_WF_SPLIT) {
        centres[1] = S->ev_a;
        centres[2] = S->ev_b;
    }
    /* closed: the walk from the seed went round its whole cycle */
    *closed = false;
    uint32_t u = N->seeds[0];
    for (int k = 0; k <= 2 * LOCAL_REACH + 1; k++) {
        u = N->v[u].next;
        if (u == N->seeds[0]) {
            *closed = true;
            break;
        }
    }
    for (int c = 0; c < 3; c++) {
        if (centres[c] == WK_NONE || !N->v[centres[c]].alive) continue;
        uint32_t a = centres[c], b = centres[c];
        if (push_local(N, a) != WK_OK) return N->R->err.code;
        for (int k = 0; k < LOCAL_REACH; k++) {
            a = N->v[a].prev;
            b = N->v[b].next;
            if (push_local(N, a) != WK_OK || push_local(N, b) != WK_OK) return N->R->err.code;
        }
    }
    /* the vertices just outside take part as untouched ends of pieces */
    for (uint32_t i = 0, n = N->n_comp; i < n; i++) {
        uint32_t c = N->comp[i];
        if (N->v[N->v[c].next].seen != N->stamp) N->v[N->v[c].next].at = WK_NONE;
        if (N->v[N->v[c].prev].seen != N->stamp) N->v[N->v[c].prev].at = WK_NONE;
    }
    return WK_OK;
}

static wk_status collect_cycles(wk_wavefront *N) {
    N->stamp++;
    N->n_comp = 0;
    N->n_cyc = 0;
    for (int pass = 0; pass < 2; pass++) {
        uint32_t n = pass ? N->n_forced : N->n_seeds;
        const uint32_t *src = pass ? N->forced : N->seeds;
        for (uint32_t i = 0; i < n; i++) {
            uint32_t s = src[i];
            if (N->v[s].seen == N->stamp) continue;
            uint32_t u = s;
            do {
                N->v[u].seen = N->stamp;
                N->v[u].at = WK_NONE;
                N->v[u].cyc = N->n_cyc;
                if (push_u32(N->R, &N->comp, &N->n_comp, &N->cap_comp, u) != WK_OK)
                    return N->R->err.code;
                u = N->v[u].next;
            } while (u != s);
            N->n_cyc++;
        }
    }
    return WK_OK;
}

static wk_status add_sub(wk_wavefront *N, uint32_t from, uint32_t to, uint32_t edge) {
    if (from == to) return WK_OK; /* zero length: this piece collapsed */
    if (WK_GROW(N->R, N->sub, N->cap_sub, N->n_sub + 1) != WK_OK) return N->R->err.code;
    N->sub[N->n_sub++] = (wk_wf_sub){from, to, edge, WK_NONE, WK_NONE, 0};
    return WK_OK;
}

/* Order sub-pieces by their unordered pair of end points. */
static int cmp_sub_key(const wk_wavefront *N, uint32_t i, uint32_t j) {
    const wk_wf_sub *a = &N->sub[i], *b = &N->sub[j];
    uint32_t a0 = a->from < a->to ? a->from : a->to, a1 = a->from ^ a->to ^ a0;
    uint32_t b0 = b->from < b->to ? b->from : b->to, b1 = b->from ^ b->to ^ b0;
    if (a0 != b0) return a0 < b0 ? -1 : 1;
    if (a1 != b1) return a1 < b1 ? -1 : 1;
    return 0;
}

/* Heap sort of sub-piece ids by end points, ids breaking ties (qsort has
** no context argument and the order must be deterministic). */
static bool sub_less(const wk_wavefront *N, uint32_t i, uint32_t j) {
    int c = cmp_sub_key(N, i, j);
    return c ? c < 0 : i < j;
}
static void sift(const wk_wavefront *N, uint32_t *a, uint32_t i, uint32_t n) {
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= n) return;
        if (c + 1 < n && sub_less(N, a[c], a[c + 1])) c++;
        if (!sub_less(N, a[i], a[c])) return;
        uint32_t x = a[i];
        a[i] = a[c];
        a[c] = x;
        i = c;
    }
}
static void sort_by_endpoints(const wk_wavefront *N, uint32_t *a, uint32_t n) {
    for (uint32_t i = n / 2; i-- > 0;) sift(N, a, i, n);
    for (uint32_t m = n; m > 1; m--) {
        uint32_t x = a[0];
        a[0] = a[m - 1];
        a[m - 1] = x;
        sift(N, a, 0, m - 1);
    }
}

/* Plan the group: clusters, arrivals, pinches, sub-pieces, cancellation and
** pairing.  Returns WK_OK with *again set when a spike forced a new node. */
static wk_status plan(wk_wavefront *N, double t, bool *again) {
    wk_run *R = N->R;
    *again = false;
    N->n_cl = N->n_pin = N->n_sub = N->n_pair = 0;
    for (uint32_t i = 0; i < N->n_seeds; i++) {
        uint32_t k;
        if (add_cluster(N, N->v[N->seeds[i]].ev_p, &k) != WK_OK) return R->err.code;
    }
    for (uint32_t i = 0; i < N->n_forced; i++) {
        uint32_t k;
        if (add_cluster(N, wk_wf_pos(&N->v[N->forced[i]], t), &k) != WK_OK) return R->err.code;
    }
    N->local_open = false;
    if (N->n_seeds == 1 && N->n_forced == 0) {
        bool closed;
        if (collect_local(N, &closed) != WK_OK) return R->err.code;
        N->local_open = !closed;
    } else if (collect_cycles(N) != WK_OK) {
        return R->err.code;
    }
    /* arrivals */
    for (uint32_t i = 0; i < N->n_comp; i++) {
        wk_wf_vertex *u = &N->v[N->comp[i]];
        /* within the time tolerance a vertex covers |vel| eps_t: a fast
        ** vertex that close to a node arrives there in the same instant */
        double speed = fabs(u->vel.x) + fabs(u->vel.y);
        u->at = find_cluster_within(N, wk_wf_pos(u, t), N->eps_d + speed * N->eps_t);
    }
    /* a free vertex whose two neighbours arrive at the same node closes a
    ** triangle of zero size with it: it arrives too */
    for (uint32_t i = 0; i < N->n_comp; i++) {
        wk_wf_vertex *u = &N->v[N->comp[i]];
        uint32_t kp = N->v[u->prev].at;
        if (u->at == WK_NONE && kp != WK_NONE && kp == N->v[u->next].at && u->prev != u->next)
            u->at = kp;
    }
    for (uint32_t i = 0; i < N->n_seeds; i++) {
        wk_wf_vertex *u = &N->v[N->seeds[i]];
        if (u->at == WK_NONE) u->at = find_cluster(N, u->ev_p);
        if (u->ev_kind == WK_WF_EDGE && N->v[u->next].at == WK_NONE) N->v[u->next].at = u->at;
    }
    /* pinches: a node inside a piece cuts it */
    for (uint32_t i = 0; i < N->n_comp; i++) {
        uint32_t a = N->comp[i];
        const wk_wf_vertex *A = &N->v[a], *B = &N->v[A->next];
        /* an end that arrives at a node is taken at the node, so pinches and
        ** arrivals see the same geometry */
        wk_point pa = A->at != WK_NONE ? N->cl[A->at].p : wk_wf_pos(A, t);
        wk_point pb = B->at != WK_NONE ? N->cl[B->at].p : wk_wf_pos(B, t);
        const wk_offset_line *L = &N->L[A->eout];
        double len = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
        for (uint32_t k = 0; k < N->n_cl; k++) {
            if (k == A->at || k == B->at) continue;
            wk_point q = N->cl[k].p;
            double s = (q.x - pa.x) * L->ux + (q.y - pa.y) * L->uy;
            if (s < -N->eps_d || s > len + N->eps_d) continue;
            double off = (q.x - pa.x) * L->nx + (q.y - pa.y) * L->ny;
            if (fabs(off) > N->eps_d) continue;
            /* A node on the line within tolerance of an end of the piece: that
            ** end arrives at the node (else the node would touch the piece
            ** without cutting it, and the group would change nothing). */
            if (s <= N->eps_d) {
                if (A->at == WK_NONE) N->v[a].at = k;
                continue;
            }
            if (s >= len - N->eps_d) {
                if (B->at == WK_NONE) N->v[A->next].at = k;
                continue;
            }
            if (WK_GROW(R, N->pin, N->cap_pin, N->n_pin + 1) != WK_OK) return R->err.code;
            N->pin[N->n_pin++] = (wk_wf_pinch){a, s, k};
        }
    }
    /* Progress guarantee: a split seed always cuts its target piece at its
    ** node, even when rounding put the node a little more than the tolerance
    ** off the piece's line (detection and resolution must agree, or the
    ** same event would be found again and again). */
    for (uint32_t i = 0; i < N->n_seeds; i++) {
        const wk_wf_vertex *u = &N->v[N->seeds[i]];
        if (u->ev_kind != WK_WF_SPLIT || u->at == WK_NONE) continue;
        uint32_t a = u->ev_a, k = u->at;
        const wk_wf_vertex *A = &N->v[a];
        if (!A->alive || A->next != u->ev_b || A->seen != N->stamp) continue;
        const wk_wf_vertex *B = &N->v[A->next];
        if (k == A->at || k == B->at) continue;
        bool have = false;
        for (uint32_t j = 0; j < N->n_pin; j++) have |= N->pin[j].piece == a && N->pin[j].node == k;
        if (have) continue;
        const wk_offset_line *L = &N->L[A->eout];
        wk_point pa = A->at != WK_NONE ? N->cl[A->at].p : wk_wf_pos(A, t);
        wk_point pb = B->at != WK_NONE ? N->cl[B->at].p : wk_wf_pos(B, t);
        wk_point q = N->cl[k].p;
        double len = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
        double sq = (q.x - pa.x) * L->ux + (q.y - pa.y) * L->uy;
        if (sq <= N->eps_d) {
            N->v[a].at = k;
        } else if (sq >= len - N->eps_d) {
            N->v[A->next].at = k;
        } else {
            if (WK_GROW(R, N->pin, N->cap_pin, N->n_pin + 1) != WK_OK) return R->err.code;
            N->pin[N->n_pin++] = (wk_wf_pinch){a, sq, k};
        }
    }
    if (N->n_pin > 1) qsort(N->pin, N->n_pin, sizeof *N->pin, cmp_pinch);
    /* sub-pieces of every piece that touches a node */
    for (uint32_t i = 0; i < N->n_comp; i++) {
        uint32_t a = N->comp[i];
        const wk_wf_vertex *A = &N->v[a];
        uint32_t b = A->next;
        /* pinches are sorted by piece id: binary search this piece's run */
        uint32_t lo = 0, hi = N->n_pin;
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (N->pin[mid].piece < a) lo = mid + 1;
            else hi = mid;
        }
        uint32_t pi0 = lo, pi1 = pi0;
        while (pi1 < N->n_pin && N->pin[pi1].piece == a) pi1++;
        if (A->at == WK_NONE && N->v[b].at == WK_NONE && pi1 == pi0) continue;
        uint32_t from = A->at != WK_NONE ? (A->at | NODE_BIT) : a;
        for (uint32_t j = pi0; j < pi1; j++) {
            uint32_t to = N->pin[j].node | NODE_BIT;
            if (add_sub(N, from, to, A->eout) != WK_OK) return R->err.code;
            from = to;
        }
        uint32_t to = N->v[b].at != WK_NONE ? (N->v[b].at | NODE_BIT) : b;
        if (add_sub(N, from, to, A->eout) != WK_OK) return R->err.code;
    }
    /* cancellation: opposite sub-pieces between the same two nodes */
    if (N->n_sub > 1) {
        if (wk_grow(R, (void **)&N->slot, &N->cap_slot, N->n_sub, sizeof *N->slot) != WK_OK)
            return R->err.code;
        N->n_slot = 0;
        for (uint32_t i = 0; i < N->n_sub; i++)
            if (IS_NODE(N->sub[i].from) && IS_NODE(N->sub[i].to)) N->slot[N->n_slot++] = i;
        sort_by_endpoints(N, N->slot, N->n_slot);
        for (uint32_t i = 0; i < N->n_slot; i++) {
            wk_wf_sub *a = &N->sub[N->slot[i]];
            if (a->dead) continue;
            for (uint32_t j = i + 1; j < N->n_slot && cmp_sub_key(N, N->slot[i], N->slot[j]) == 0; j++) {
                wk_wf_sub *b = &N->sub[N->slot[j]];
                if (!b->dead && b->from == a->to && b->to == a->from) {
                    /* 2: cancelled, leaves an arc; 1: one edge folded onto
                    ** itself within tolerance, which traces nothing */
                    a->dead = b->dead = a->edge == b->edge ? 1 : 2;
                    break;
                }
            }
        }
    }
    /* An untouched vertex whose pieces both lead to the same node closes a
    ** triangle of no area with it (its two edges lie on one line there): it
    ** arrives too.  Plan again with it as a node. */
    bool forced_tri = false;
    for (uint32_t i = 0; i < N->n_sub; i++) {
        const wk_wf_sub *x = &N->sub[i];
        if (x->dead || !IS_NODE(x->from) || IS_NODE(x->to)) continue;
        for (uint32_t j = 0; j < N->n_sub; j++) {
            const wk_wf_sub *y = &N->sub[j];
            if (y->dead || y->from != x->to || y->to != x->from) continue;
            if (push_u32(R, &N->forced, &N->n_forced, &N->cap_forced, x->to) != WK_OK)
                return R->err.code;
            forced_tri = true;
            break;
        }
    }
    if (forced_tri) {
        *again = true;
        return WK_OK;
    }
    /* A sub-piece between two nodes is where parallel edges met; an
    ** untouched vertex lying on it (an end of a collinear step of the other
    ** side) meets it too: make it a node and plan again. */
    bool forced_any = false;
    for (uint32_t i = 0; i < N->n_sub; i++) {
        const wk_wf_sub *x = &N->sub[i];
        if (x->dead || !IS_NODE(x->from) || !IS_NODE(x->to)) continue;
        wk_point a = N->cl[NODE_OF(x->from)].p, b = N->cl[NODE_OF(x->to)].p;
        const wk_offset_line *L = &N->L[x->edge];
        double len = (b.x - a.x) * L->ux + (b.y - a.y) * L->uy;
        for (uint32_t j = 0; j < N->n_comp; j++) {
            const wk_wf_vertex *u = &N->v[N->comp[j]];
            if (u->at != WK_NONE) continue;
            wk_point q = wk_wf_pos(u, t);
            double sq = (q.x - a.x) * L->ux + (q.y - a.y) * L->uy;
            double off = (q.x - a.x) * L->nx + (q.y - a.y) * L->ny;
            if (sq <= -N->eps_d || sq >= len + N->eps_d || fabs(off) > N->eps_d) continue;
            if (push_u32(R, &N->forced, &N->n_forced, &N->cap_forced, N->comp[j]) != WK_OK)
                return R->err.code;
            forced_any = true;
        }
    }
    if (forced_any) {
        *again = true;
        return WK_OK;
    }
    /* pairing at each node */
    for (uint32_t k = 0; k < N->n_cl; k++) N->cl[k].count = 0;
    for (uint32_t i = 0; i < N->n_sub; i++) {
        wk_wf_sub *s = &N->sub[i];
        if (s->dead) continue;
        if (IS_NODE(s->from)) N->cl[NODE_OF(s->from)].count++;
        if (IS_NODE(s->to)) N->cl[NODE_OF(s->to)].count++;
    }
    uint32_t total = 0;
    for (uint32_t k = 0; k < N->n_cl; k++) {
        N->cl[k].first = total;
        total += N->cl[k].count;
        N->cl[k].count = 0;
    }
    if (wk_grow(R, (void **)&N->slot, &N->cap_slot, total + 1, sizeof *N->slot) != WK_OK)
        return R->err.code;
    for (uint32_t i = 0; i < N->n_sub; i++) {
        wk_wf_sub *s = &N->sub[i];
        if (s->dead) continue;
        if (IS_NODE(s->from)) {
            wk_wf_cluster *c = &N->cl[NODE_OF(s->from)];
            N->slot[c->first + c->count++] = i; /* outgoing at from */
        }
        if (IS_NODE(s->to)) {
            wk_wf_cluster *c = &N->cl[NODE_OF(s->to)];
            N->slot[c->first + c->count++] = i | NODE_BIT; /* incoming at to */
        }
    }
    /* Overlap: an incoming and an outgoing sub-piece leaving a node in the
    ** same direction are antiparallel edges lying on each other.  Their
    ** common part vanishes now, so the nearer far end (an untouched vertex
    ** lying on the other piece) meets it: make it a node and plan again. */
    for (uint32_t k = 0; k < N->n_cl; k++) {
        wk_wf_cluster *c = &N->cl[k];
        for (uint32_t j = 0; j < c->count; j++) {
            uint32_t in = N->slot[c->first + j];
            if (!(in & NODE_BIT)) continue;
            in &= ~NODE_BIT;
            double a = angle_of(&N->L[N->sub[in].edge], true);
            for (uint32_t m = 0; m < c->count; m++) {
                uint32_t out = N->slot[c->first + m];
                if (out & NODE_BIT) continue;
                double d = fabs(a - angle_of(&N->L[N->sub[out].edge], false));
                if (d > 1e-12 && fabs(d - TWO_PI) > 1e-12) continue;
                wk_point pin = point_pos(N, N->sub[in].from, t);
                wk_point pout = point_pos(N, N->sub[out].to, t);
                uint32_t far = dist2(pin, c->p) < dist2(pout, c->p) ? N->sub[in].from : N->sub[out].to;
                if (IS_NODE(far)) continue; /* equal pieces were cancelled; spike check below */
                if (push_u32(R, &N->forced, &N->n_forced, &N->cap_forced, far) != WK_OK)
                    return R->err.code;
                *again = true;
            }
        }
    }
    if (*again) return WK_OK;
    for (uint32_t k = 0; k < N->n_cl; k++) {
        wk_wf_cluster *c = &N->cl[k];
        uint32_t nin = 0, nout = 0;
        for (uint32_t j = 0; j < c->count; j++) (N->slot[c->first + j] & NODE_BIT) ? nin++ : nout++;
        if (nin != nout)
            return WK_FAIL(R, WK_EALGO, N->P->name, 0,
                           "wavefront: inconsistent wavefront at (%.17g, %.17g), t = %.17g: %u pieces "
                           "arrive, %u leave",
                           c->p.x, c->p.y, t, nin, nout);
        for (uint32_t j = 0; j < c->count; j++) {
            uint32_t in = N->slot[c->first + j];
            if (!(in & NODE_BIT)) continue;
            in &= ~NODE_BIT;
            double a = angle_of(&N->L[N->sub[in].edge], true);
            uint32_t best = WK_NONE;
            double bturn = INFINITY;
            for (uint32_t m = 0; m < c->count; m++) {
                uint32_t out = N->slot[c->first + m];
                if (out & NODE_BIT) continue;
                if (N->sub[out].pair_out != WK_NONE) continue;
                double turn = cw_turn(a, angle_of(&N->L[N->sub[out].edge], false));
                if (turn < bturn) {
                    bturn = turn;
                    best = out;
                }
            }
            if (best == WK_NONE)
                return WK_FAIL(R, WK_EALGO, N->P->name, 0,
                               "wavefront: cannot pair wavefront pieces at (%.17g, %.17g), t = %.17g",
                               c->p.x, c->p.y, t);
            /* A turn of (nearly) 2 pi is a zero-width spike: some vertex lies on
            ** one of the two sub-pieces; make the nearer far end a node. */
            if (bturn > TWO_PI - 1e-9) {
                wk_wf_sub *si = &N->sub[in], *so = &N->sub[best];
                wk_point pin = point_pos(N, si->from, t), pout = point_pos(N, so->to, t);
                uint32_t far = dist2(pin, c->p) < dist2(pout, c->p) ? si->from : so->to;
                if (IS_NODE(far))
                    return WK_FAIL(R, WK_EALGO, N->P->name, 0,
                                   "wavefront: unresolved spike at (%.17g, %.17g), t = %.17g", c->p.x,
                                   c->p.y, t);
                if (push_u32(R, &N->forced, &N->n_forced, &N->cap_forced, far) != WK_OK)
                    return R->err.code;
                *again = true; /* collect every spike of this round, then replan */
                N->sub[in].pair_in = N->sub[best].pair_out = N->n_pair;
                continue;
            }
            if (WK_GROW(R, N->pair, N->cap_pair, N->n_pair + 1) != WK_OK) return R->err.code;
            N->sub[in].pair_in = N->n_pair;
            N->sub[best].pair_out = N->n_pair;
            N->pair[N->n_pair++] = (wk_wf_pair){in, best, k, WK_NONE};
        }
    }
    return WK_OK;
}

static uint32_t sk_node(wk_wavefront *N, uint32_t k, double t) {
    wk_wf_cluster *c = &N->cl[k];
    if (c->sk == WK_NONE) {
        uint32_t id;
        if (wk_skeleton_add_node(N->R, N->S, c->p.x + N->origin.x, c->p.y + N->origin.y, t, &id) !=
            WK_OK)
            return WK_NONE;
        c->sk = id;
    }
    return c->sk;
}

static void link(wk_wavefront *N, uint32_t a, uint32_t b) {
    N->v[a].next = b;
    N->v[b].prev = a;
}

static wk_status mark_fresh(wk_wavefront *N, uint32_t v) {
    return push_u32(N->R, &N->fresh, &N->n_fresh, &N->cap_fresh, v);
}

/* Parallel edges that share a vertex lie on one line: the vertex between
** them has WK_VEL_STRAIGHT (equal weights) or WK_VEL_COLLINEAR kinetics. */
static bool on_one_line(const wk_wf_vertex *u) {
    return u->alive && (u->vkind == WK_VEL_COLLINEAR || u->vkind == WK_VEL_STRAIGHT);
}

/* The node where run vertex i (N->run[i]) is at time t, created once: its
** own start node if it was born now, else a new node at its position. */
static wk_status run_node(wk_wavefront *N, uint32_t i, double t, uint32_t *node) {
    if (N->run_node[i] == WK_NONE) {
        wk_wf_vertex *U = &N->v[N->run[i]];
        if (U->t0 == t) {
            N->run_node[i] = U->node;
        } else {
            wk_point q = wk_wf_pos(U, t);
            if (wk_skeleton_add_node(N->R, N->S, q.x + N->origin.x, q.y + N->origin.y, t,
                                     &N->run_node[i]) != WK_OK)
                return N->R->err.code;
        }
    }
    *node = N->run_node[i];
    return WK_OK;
}

/* The collinear rule (000, section 1).  Vertex vi sits between parallel
** edges of different weight, which no moving vertex can join.  Take the
** maximal run of consecutive pieces on that line (a run, not one pair: three
** parallel walls can meet at once); the winning weight (lowest by default,
** highest with --collinear higher) survives, every other piece of the run is
** swept at once, leaving an arc along it at time t between its face and the
** surviving piece that extends over it (the one before it, else the one
** after it).  Vertices of the run that touch a swept piece end here; new
** vertices join the surviving pieces. */
static wk_status slide(wk_wavefront *N, uint32_t vi, double t) {
    wk_run *R = N->R;
    if (!on_one_line(&N->v[vi])) return WK_OK;
    /* run[0]: the vertex before the run's first piece; run[m]: after its
    ** last; run[1..m-1] lie between pieces of the run */
    uint32_t u0 = vi, um = vi, guard = 0;
    while (on_one_line(&N->v[u0])) {
        u0 = N->v[u0].prev;
        if (++guard > N->nv) goto cyclic;
    }
    while (on_one_line(&N->v[um])) {
        um = N->v[um].next;
        if (++guard > N->nv) goto cyclic;
    }
    N->n_run = 0;
    for (uint32_t u = u0;; u = N->v[u].next) {
        if (WK_GROW(R, N->run, N->cap_run, N->n_run + 1) != WK_OK ||
            WK_GROW(R, N->run_node, N->cap_run_node, N->n_run + 1) != WK_OK)
            return R->err.code;
        N->run[N->n_run] = u;
        N->run_node[N->n_run++] = WK_NONE;
        if (u == um) break;
    }
    uint32_t m = N->n_run - 1;
    /* piece i (1..m) runs run[i-1] -> run[i] on edge piece_edge(i) */
#define PIECE_EDGE(i) (N->v[N->run[(i) - 1]].eout)
    bool lower = R->opt.collinear == WK_COLLINEAR_LOWER;
    double best = N->L[PIECE_EDGE(1)].w;
    for (uint32_t i = 2; i <= m; i++) {
        double w = N->L[PIECE_EDGE(i)].w;
        if (lower ? w < best : w > best) best = w;
    }
    uint32_t first_winner = WK_NONE;
    for (uint32_t i = 1; i <= m && first_winner == WK_NONE; i++)
        if (N->L[PIECE_EDGE(i)].w == best) first_winner = PIECE_EDGE(i);
    /* arcs along the losing pieces */
    uint32_t ext = first_winner;
    bool changed = false;
    for (uint32_t i = 1; i <= m; i++) {
        uint32_t e = PIECE_EDGE(i);
        if (N->L[e].w == best) {
            ext = e;
            continue;
        }
        uint32_t a, b;
        if (run_node(N, i - 1, t, &a) != WK_OK || run_node(N, i, t, &b) != WK_OK) return R->err.code;
        if (add_arc(N, a, b, ext, e) != WK_OK) return R->err.code;
        wk_event ev = {t, 0, 0, e, ext, WK_NONE};
        wk_notify_event(R, WK_COUNTER_collinear_resolutions, &ev);
        changed = true;
    }
    if (!changed) return WK_OK;
    /* rebuild: cur is the last vertex of the new wavefront, cur_out the
    ** edge leaving it */
    uint32_t cur = N->v[u0].prev, cur_out = N->v[u0].ein;
    for (uint32_t i = 0; i <= m; i++) {
        uint32_t u = N->run[i];
        wk_wf_vertex *U = &N->v[u];
        uint32_t ein = i == 0 ? U->ein : PIECE_EDGE(i);
        uint32_t eout = i == m ? U->eout : PIECE_EDGE(i + 1);
        bool lost_before = i > 0 && N->L[ein].w != best;
        bool lost_after = i < m && N->L[eout].w != best;
        if (!lost_before && !lost_after) {
            link(N, cur, u); /* untouched */
            cur = u;
            cur_out = U->eout;
            continue;
        }
        uint32_t nd;
        if (run_node(N, i, t, &nd) != WK_OK) return R->err.code;
        wk_point q = wk_wf_pos(U, t);
        uint32_t p_next = U->next;
        if (terminate(N, u, nd) != WK_OK) return R->err.code;
        /* the edge that leaves this point in the new wavefront */
        uint32_t leave = i == m ? eout : (lost_after ? cur_out : eout);
        if (i == 0) leave = first_winner;
        if (lost_after && i > 0 && i < m && N->L[ein].w == best) leave = ein;
        if (i < m && !lost_after) leave = eout;
        if (leave != cur_out) {
            uint32_t g = new_vertex(N, cur_out, leave, q, t, nd);
            if (g == WK_NONE || mark_fresh(N, g) != WK_OK) return R->err.code;
            link(N, cur, g);
            cur = g;
            cur_out = leave;
        }
        if (i == m) link(N, cur, p_next);
    }
#undef PIECE_EDGE
    return WK_OK;
cyclic:
    return WK_FAIL(R, WK_EALGO, N->P->name, 0,
                   "wavefront: a whole wavefront cycle lies on one line at t = %.17g", t);
}

/* Follow pass-through pairs (same edge on both sides: no vertex) to the
** vertex at the head of sub-piece s. */
static uint32_t head_vertex(wk_wavefront *N, uint32_t s) {
    for (uint32_t guard = 0; guard <= N->n_sub; guard++) {
        wk_wf_sub *x = &N->sub[s];
        if (!IS_NODE(x->to)) return x->to;
        wk_wf_pair *p = &N->pair[x->pair_in];
        if (p->vertex != WK_NONE) return p->vertex;
        s = p->out;
    }
    return WK_NONE;
}

static wk_status commit(wk_wavefront *N, double t) {
    wk_run *R = N->R;
    /* skeleton nodes and arcs of arriving vertices */
    for (uint32_t i = 0; i < N->n_comp; i++) {
        uint32_t u = N->comp[i];
        if (N->v[u].at == WK_NONE) continue;
        uint32_t sk = sk_node(N, N->v[u].at, t);
        if (sk == WK_NONE || terminate(N, u, sk) != WK_OK) return R->err.code;
    }
    /* cancelled pairs leave arcs: face of x->y on its right */
    for (uint32_t i = 0; i < N->n_sub; i++) {
        wk_wf_sub *a = &N->sub[i];
        if (a->dead != 2) continue;
        a->dead = 1;
        for (uint32_t j = 0; j < N->n_sub; j++) {
            wk_wf_sub *b = &N->sub[j];
            if (b->dead == 2 && b->from == a->to && b->to == a->from) {
                b->dead = 1;
                uint32_t x = sk_node(N, NODE_OF(a->from), t), y = sk_node(N, NODE_OF(a->to), t);
                if (x == WK_NONE || y == WK_NONE || add_arc(N, x, y, b->edge, a->edge) != WK_OK)
                    return R->err.code;
                break;
            }
        }
    }
    /* new vertices */
    for (uint32_t i = 0; i < N->n_pair; i++) {
        wk_wf_pair *p = &N->pair[i];
        uint32_t ein = N->sub[p->in].edge, eout = N->sub[p->out].edge;
        if (ein == eout) continue; /* the piece just passes through */
        uint32_t sk = sk_node(N, p->node, t);
        if (sk == WK_NONE) return R->err.code;
        uint32_t v = new_vertex(N, ein, eout, N->cl[p->node].p, t, sk);
        if (v == WK_NONE || mark_fresh(N, v) != WK_OK) return R->err.code;
        p = &N->pair[i];
        p->vertex = v;
    }
    /* links: every live sub-piece joins the vertex at its tail to the one at
    ** its head; pass-through pairs are followed */
    for (uint32_t i = 0; i < N->n_sub; i++) {
        wk_wf_sub *s = &N->sub[i];
        if (s->dead) continue;
        uint32_t tail;
        if (IS_NODE(s->from)) {
            tail = N->pair[s->pair_out].vertex;
            if (tail == WK_NONE) continue; /* inside a pass-through chain */
        } else {
            tail = s->from;
        }
        uint32_t head = head_vertex(N, i);
        if (head == WK_NONE)
            return WK_FAIL(R, WK_EALGO, N->P->name, 0, "wavefront: broken wavefront cycle at t = %.17g", t);
        link(N, tail, head);
        /* tail's next changed: its cycle is walked again by refresh */
        if (mark_fresh(N, tail) != WK_OK) return R->err.code;
    }
    wk_event e = {t, 0, 0, WK_NONE, WK_NONE, WK_NONE};
    wk_notify_event(R, WK_COUNTER_simultaneous_event_groups, &e);
    return WK_OK;
}

/* Count what happened in this group for the observer (counts only). */
static wk_status count_group(wk_wavefront *N, double t) {
    wk_run *R = N->R;
    for (uint32_t i = 0; i < N->n_comp; i++) {
        const wk_wf_vertex *u = &N->v[N->comp[i]];
        if (u->at == WK_NONE) continue;
        N->cl[u->at].arrive++;
        N->cl[u->at].reflex += u->reflex;
    }
    for (uint32_t i = 0; i < N->n_pin; i++) N->cl[N->pin[i].node].pinches++;
    for (uint32_t i = 0; i < N->n_pair; i++)
        if (N->sub[N->pair[i].in].edge != N->sub[N->pair[i].out].edge) N->cl[N->pair[i].node].pairs++;
    for (uint32_t k = 0; k < N->n_cl; k++) {
        const wk_wf_cluster *c = &N->cl[k];
        wk_event e = {t, c->p.x, c->p.y, k, c->arrive, c->reflex};
        if (c->reflex >= 2) wk_notify_event(R, WK_COUNTER_multi_split_events, &e);
        else if (c->reflex == 1 && c->pinches) wk_notify_event(R, WK_COUNTER_split_events, &e);
        else if (c->arrive >= 2) wk_notify_event(R, WK_COUNTER_edge_events, &e);
    }
    /* a touched cycle vanished if every vertex of it arrived at a node and
    ** none of its nodes starts a new vertex (flag 1: alive) */
    if (wk_grow(R, (void **)&N->cycflag, &N->cap_cycflag, N->n_cyc + 1, 1) != WK_OK) return R->err.code;
    memset(N->cycflag, 0, N->n_cyc);
    if (N->local_open) N->cycflag[0] = 1; /* only part of its cycle was looked at */
    for (uint32_t i = 0; i < N->n_comp; i++) {
        const wk_wf_vertex *u = &N->v[N->comp[i]];
        if (u->at == WK_NONE || N->cl[u->at].pairs) N->cycflag[u->cyc] = 1;
    }
    for (uint32_t c = 0; c < N->n_cyc; c++) {
        if (N->cycflag[c]) continue;
        wk_event e = {t, 0, 0, c, WK_NONE, WK_NONE};
        wk_notify_event(R, WK_COUNTER_vanishing_components, &e);
    }
    /* an edge event (no piece cut) whose one new vertex is reflex: 000's
    ** reflex-preserving edge event */
    for (uint32_t i = 0; i < N->n_pair; i++) {
        const wk_wf_pair *p = &N->pair[i];
        const wk_wf_cluster *c = &N->cl[p->node];
        if (p->vertex == WK_NONE || c->pinches || c->arrive < 2 || c->pairs != 1) continue;
        if (!N->v[p->vertex].reflex) continue;
        wk_event e = {t, c->p.x, c->p.y, p->node, c->arrive, c->reflex};
        wk_notify_event(R, WK_COUNTER_reflex_preserving_edge_events, &e);
    }
    return WK_OK;
}

/* After a group: new candidates for fresh vertices, their predecessors and
** every reflex vertex of the touched cycles. */
static wk_status refresh(wk_wavefront *N) {
    wk_run *R = N->R;
    N->stamp++;
    if (N->finder->local_refresh) {
        /* The finder keeps its split candidates current itself: only the
        ** fresh vertices and the ones whose next changed need new
        ** candidates, and a predecessor's edge event depends on its next. */
        for (uint32_t i = 0; i < N->n_fresh; i++) {
            uint32_t f = N->fresh[i];
            if (!N->v[f].alive) continue;
            uint32_t two[2] = {f, N->v[f].prev};
            for (int j = 0; j < 2; j++) {
                wk_wf_vertex *U = &N->v[two[j]];
                if (U->seen == N->stamp) continue;
                U->seen = N->stamp;
                full_candidate(N, two[j]);
                if (schedule(N, two[j]) != WK_OK) return R->err.code;
            }
        }
        return WK_OK;
    }
    for (uint32_t i = 0; i < N->n_fresh; i++) {
        uint32_t f = N->fresh[i];
        if (!N->v[f].alive || N->v[f].seen == N->stamp) continue;
        uint32_t u = f;
        do {
            wk_wf_vertex *U = &N->v[u];
            U->seen = N->stamp;
            if (U->fresh || U->next != U->cand_next || !wk_wavefront_target_alive(N, U)) {
                full_candidate(N, u);
            } else if (U->reflex) {
                N->finder->incremental(N->finder_ud, N, u);
            }
            if (schedule(N, u) != WK_OK) return R->err.code;
            u = U->next;
        } while (u != f);
    }
    return WK_OK;
}

static wk_status check_cycles_sane(wk_wavefront *N) {
    for (uint32_t i = 0; i < N->n_fresh; i++) {
        uint32_t f = N->fresh[i];
        if (!N->v[f].alive) continue;
        /* a few steps around each fresh vertex: enough to see a cycle of
        ** fewer than 3 vertices or a broken link next to the change */
        uint32_t len = 0, u = f;
        do {
            if (!N->v[u].alive || N->v[N->v[u].next].prev != u)
                return WK_FAIL(N->R, WK_EALGO, N->P->name, 0,
                               "wavefront: broken wavefront cycle after t = %.17g", N->t_now);
            u = N->v[u].next;
            ++len;
        } while (u != f && len < 3);
        if (len < 3 && u == f)
            return WK_FAIL(N->R, WK_EALGO, N->P->name, 0,
                           "wavefront: wavefront cycle of %u vertices after t = %.17g", len, N->t_now);
    }
    return WK_OK;
}

/* A cycle that the group left with zero area: every vertex on one line
** (within a tolerance) and its pieces covering the line from both sides
** exactly once, as two walls met flat (the group resolution, working with
** nodes eps_d apart, can leave one with a zero-length piece and an
** antiparallel vertex: walls at equal levels far from the origin meeting
** 1e-10 apart in time).  The whole cycle vanishes now: each vertex ends at
** the node of its place, and each stretch of the line gets one arc between
** the faces of the piece covering it from either side (the piece's face lies
** on its right).  *done is false, and nothing is changed, if the cycle is not
** of that kind. */
static wk_status collapse_flat_cycle(wk_wavefront *N, uint32_t f, double t, bool *done) {
    wk_run *R = N->R;
    *done = false;
    const wk_offset_line *L = &N->L[N->v[f].ein];
    wk_point o = wk_wf_pos(&N->v[f], t);
    double tol = 1e3 * N->eps_d;
    /* the cycle's places along L's direction (s) and its pieces */
    uint32_t len = 0, u = f;
    do {
        wk_point q = wk_wf_pos(&N->v[u], t);
        double off = (q.x - o.x) * L->nx + (q.y - o.y) * L->ny;
        if (fabs(off) > tol || ++len > 64) return WK_OK; /* not flat, or too big to care */
        u = N->v[u].next;
    } while (u != f);
    double sv[64];
    uint32_t cyc[64];
    u = f;
    for (uint32_t i = 0; i < len; i++, u = N->v[u].next) {
        wk_point q = wk_wf_pos(&N->v[u], t);
        cyc[i] = u;
        sv[i] = (q.x - o.x) * L->ux + (q.y - o.y) * L->uy;
    }
    /* distinct breakpoints (within tol), sorted */
    double bp[64];
    uint32_t nb = 0;
    for (uint32_t i = 0; i < len; i++) {
        bool have = false;
        for (uint32_t j = 0; j < nb; j++) have |= fabs(bp[j] - sv[i]) <= tol;
        if (!have) bp[nb++] = sv[i];
    }
    for (uint32_t i = 1; i < nb; i++)
        for (uint32_t j = i; j > 0 && bp[j - 1] > bp[j]; j--) {
            double x = bp[j];
            bp[j] = bp[j - 1];
            bp[j - 1] = x;
        }
    if (nb < 2) return WK_OK;
    /* every elementary stretch covered once forwards and once backwards */
    uint32_t fwd[64], bwd[64];
    for (uint32_t k = 0; k + 1 < nb; k++) {
        uint32_t nf = 0, nbk = 0;
        double mid = 0.5 * (bp[k] + bp[k + 1]);
        for (uint32_t i = 0; i < len; i++) {
            double a = sv[i], b = sv[(i + 1) % len];
            if (mid > fmin(a, b) && mid < fmax(a, b)) {
                if (b > a) nf++, fwd[k] = N->v[cyc[i]].eout;
                else nbk++, bwd[k] = N->v[cyc[i]].eout;
            }
        }
        if (nf != 1 || nbk != 1) return WK_OK;
    }
    /* nodes at the breakpoints, vertices end there, arcs along the line */
    uint32_t node[64];
    for (uint32_t k = 0; k < nb; k++) {
        wk_point q = {o.x + bp[k] * L->ux, o.y + bp[k] * L->uy};
        if (wk_skeleton_add_node(R, N->S, q.x + N->origin.x, q.y + N->origin.y, t, &node[k]) != WK_OK)
            return R->err.code;
    }
    for (uint32_t i = 0; i < len; i++) {
        uint32_t k = 0;
        while (k + 1 < nb && fabs(bp[k] - sv[i]) > tol) k++;
        if (terminate(N, cyc[i], node[k]) != WK_OK) return R->err.code;
    }
    for (uint32_t k = 0; k + 1 < nb; k++)
        /* going forwards, the backward piece's face is on the left */
        if (add_arc(N, node[k], node[k + 1], bwd[k], fwd[k]) != WK_OK) return R->err.code;
    wk_event e = {t, o.x, o.y, f, WK_NONE, WK_NONE};
    wk_notify_event(R, WK_COUNTER_vanishing_components, &e);
    *done = true;
    return WK_OK;
}

static wk_status process_group(wk_wavefront *N, double t) {
    wk_run *R = N->R;
    N->n_forced = 0;
    N->n_fresh = 0;
    N->n_dead = 0;
    for (int round = 0;; round++) {
        bool again;
        if (plan(N, t, &again) != WK_OK) return R->err.code;
        if (!again) break;
        if (round > 64 + (int)N->n_comp)
            return WK_FAIL(R, WK_EALGO, N->P->name, 0, "wavefront: too many spikes at t = %.17g", t);
    }
    if (commit(N, t) != WK_OK || count_group(N, t) != WK_OK) return R->err.code;
    /* collinear rule for fresh vertices between parallel edges */
    for (uint32_t i = 0; i < N->n_fresh; i++) {
        uint32_t f = N->fresh[i];
        if (N->v[f].alive && N->v[f].vkind == WK_VEL_COLLINEAR && slide(N, f, t) != WK_OK)
            return R->err.code;
        if (N->v[f].alive && N->v[f].vkind == WK_VEL_ANTIPARALLEL) {
            bool done;
            if (collapse_flat_cycle(N, f, t, &done) != WK_OK) return R->err.code;
            if (done) continue;
        }
        if (N->v[f].alive && N->v[f].vkind == WK_VEL_ANTIPARALLEL)
            return WK_FAIL(R, WK_EALGO, N->P->name, 0,
                           "wavefront: antiparallel wavefront vertex at t = %.17g", t);
    }
    if (check_cycles_sane(N) != WK_OK) return R->err.code;
    if (N->finder->after_group && N->finder->after_group(N->finder_ud, N, t) != WK_OK)
        return R->err.code;
    return refresh(N);
}

static wk_status simulate(wk_wavefront *N) {
    wk_run *R = N->R;
    const wk_polygon *P = N->P;
    uint32_t n = P->n;
    /* the initial wavefront: one vertex per input vertex */
    for (uint32_t i = 0; i < n; i++) {
        wk_point q = {P->p[i].x - N->origin.x, P->p[i].y - N->origin.y};
        uint32_t id = new_vertex(N, (i + n - 1) % n, i, q, 0.0, i);
        if (id == WK_NONE) return R->err.code;
    }
    for (uint32_t i = 0; i < n; i++) link(N, i, (i + 1) % n);
    N->t_now = 0;
    N->n_fresh = 0;
    N->n_dead = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (N->v[i].vkind == WK_VEL_COLLINEAR && slide(N, i, 0.0) != WK_OK) return R->err.code;
        if (N->v[i].alive && N->v[i].vkind == WK_VEL_ANTIPARALLEL)
            return WK_FAIL(R, WK_EALGO, P->name, 0, "wavefront: input vertex %u is a spike", i);
    }
    if (wk_event_queue_reserve(R, &N->Q, 2 * n + 16) != WK_OK) return R->err.code;
    if (N->finder->start && N->finder->start(N->finder_ud, N) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < N->nv; i++) {
        if (!N->v[i].alive) continue;
        full_candidate(N, i);
        if (schedule(N, i) != WK_OK) return R->err.code;
    }
    uint64_t same_time = 0;
    for (;;) {
        /* the finder's own events (arrangement bookkeeping) go first when
        ** they are not later than the next wavefront event */
        double tq = N->Q.size ? N->Q.key[wk_event_queue_peek(&N->Q)].time : INFINITY;
        if (N->finder->next_time) {
            double tf = N->finder->next_time(N->finder_ud);
            if (tf <= tq && isfinite(tf)) {
                if (tf > N->t_now) N->t_now = tf;
                if (N->finder->process_next(N->finder_ud, N) != WK_OK) return R->err.code;
                continue;
            }
        }
        if (!N->Q.size) break;
        uint32_t first = wk_event_queue_pop(R, &N->Q);
        double t = N->v[first].ev_t;
        if (t < N->t_now) t = N->t_now;
        same_time = (t <= N->t_now + N->eps_t) ? same_time + 1 : 0;
        if (same_time > 4 * (uint64_t)P->n + 64)
            return WK_FAIL(R, WK_EALGO, P->name, 0, "wavefront: no progress at t = %.17g", t);
        N->t_now = t;
        N->n_seeds = 0;
        if (push_u32(R, &N->seeds, &N->n_seeds, &N->cap_seeds, first) != WK_OK) return R->err.code;
        while (N->Q.size) {
            uint32_t id = wk_event_queue_peek(&N->Q);
            if (N->Q.key[id].time > t + N->eps_t) break;
            wk_event_queue_pop(R, &N->Q);
            if (push_u32(R, &N->seeds, &N->n_seeds, &N->cap_seeds, id) != WK_OK)
                return R->err.code;
        }
        if (process_group(N, t) != WK_OK) return R->err.code;
    }
    for (uint32_t i = 0; i < N->nv; i++)
        if (N->v[i].alive) {
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "wavefront: wavefront vertex %u still alive when the queue ran empty", i);
        }
    return WK_OK;
}

wk_status wk_wavefront_run(wk_run *R, const wk_polygon *P, const wk_split_finder *finder,
                           void *finder_ud, wk_skeleton **out) {
    wk_wavefront N;
    memset(&N, 0, sizeof N);
    N.finder = finder;
    N.finder_ud = finder_ud;
    N.R = R;
    N.P = P;
    wk_event_queue_init(&N.Q);
    double wmax = 0;
    for (uint32_t i = 0; i < P->n; i++) wmax = P->w[i] > wmax ? P->w[i] : wmax;
    N.eps_d = WK_TOL_REL * wk_polygon_scale(P);
    /* Simultaneous means equal up to the rounding of a constructed time
    ** (~1e-15 relative); a looser window would merge events that happen in
    ** sequence, and fast vertices move far in between (a vertex of speed s
    ** covers s * eps_t). */
    N.eps_t = 1e-3 * N.eps_d / wmax;
    wk_status st = WK_OK;
    N.L = WK_NEW_ARRAY(R, wk_offset_line, P->n);
    if (!N.L) {
        st = R->err.code;
        goto done;
    }
    N.origin = wk_polygon_centre(P);
    for (uint32_t i = 0; i < P->n; i++) {
        const wk_point *a = &P->p[i], *b = &P->p[(i + 1) % P->n];
        wk_offset_line_of_points((wk_point){a->x - N.origin.x, a->y - N.origin.y},
                                 (wk_point){b->x - N.origin.x, b->y - N.origin.y}, P->w[i], &N.L[i]);
    }
    if ((st = wk_skeleton_new(R, P, &N.S)) != WK_OK) goto done;
    st = simulate(&N);
    if (st == WK_OK) st = wk_skeleton_merge_pass_through(R, N.S);
done:
    wk_event_queue_clear(R, &N.Q);
    WK_FREE_ARRAY(R, N.L, P->n);
    WK_FREE_ARRAY(R, N.v, N.cap_v);
    WK_FREE_ARRAY(R, N.seeds, N.cap_seeds);
    WK_FREE_ARRAY(R, N.forced, N.cap_forced);
    WK_FREE_ARRAY(R, N.comp, N.cap_comp);
    WK_FREE_ARRAY(R, N.cl, N.cap_cl);
    WK_FREE_ARRAY(R, N.pin, N.cap_pin);
    WK_FREE_ARRAY(R, N.sub, N.cap_sub);
    WK_FREE_ARRAY(R, N.pair, N.cap_pair);
    WK_FREE_ARRAY(R, N.slot, N.cap_slot);
    WK_FREE_ARRAY(R, N.fresh, N.cap_fresh);
    WK_FREE_ARRAY(R, N.cycflag, N.cap_cycflag);
    WK_FREE_ARRAY(R, N.run, N.cap_run);
    WK_FREE_ARRAY(R, N.run_node, N.cap_run_node);
    WK_FREE_ARRAY(R, N.dead, N.cap_dead);
    if (st != WK_OK) {
        wk_skeleton_free(R, N.S);
        return st;
    }
    *out = N.S;
    return WK_OK;
}

