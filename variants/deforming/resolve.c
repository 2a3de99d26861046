/*
** resolve.c: the topology change at an event time te (004, section 3.4):
** the corrected polygon has one or more event points where vertices met
** each other (edge collapse, vertex-on-vertex) or met the interior of a
** piece (vertex-in-edge).  004 updates its linked list event by event and
** resolves simultaneous vertex-on-vertex collisions recursively; here every
** event of the group is resolved at once by the rule those updates
** implement, local to each event point X:
**
**   1. event points: each event's point (a collapse: the midpoint of its
**      piece; a penetration: the vertex), points within the contact
**      distance merged (union-find); the vertices of the events, and their
**      neighbours within the contact distance of the point, are its
**      members (they end at X);
**   2. rays: every piece touched by a member or cut by a penetration is cut
**      at the event points on it; each part that leaves an event point is
**      a ray there: an out-ray (the piece leaves X, direction +u(e)) or an
**      in-ray (the piece arrives at X, direction -u(e)); a part with both
**      ends at one point (a collapsed piece) vanishes;
**   3. pairing: around X the unswept region lies counter-clockwise of each
**      out-ray and clockwise of each in-ray, so sorted counter-clockwise
**      the rays alternate out, in, out, in, ... and each out-ray and the
**      in-ray after it bound one wedge of the region: a new vertex between
**      the in-ray's edge and the out-ray's edge (equal directions: the
**      out-ray first, so a zero-width sliver between two antiparallel
**      pieces stays one wedge, closed below as a two-vertex cycle);
**      where the wavefront merges (a vertex reached a piece from the swept
**      side, weights <= 0), the mirror: each in-ray and the out-ray after
**      it bound one wedge of the swept region, which closes, and the new
**      vertex turns from the one to the other (equal directions: the
**      in-ray first, so that a zero-width swept sliver between two
**      antiparallel pieces closes the same way); a point where the region
**      splits and joins at once pairs as a split;
**   4. linking: a new vertex is linked to the vertex at the far end of its
**      rays (an untouched vertex, or the new vertex of the ray's other end
**      at another event point);
**   5. clean-up: a new vertex between two parts of one edge is spliced out
**      (the piece goes on); a cycle of one vertex ends; a cycle of two
**      vertices (two antiparallel pieces that met along a segment) ends
**      with an arc along it.
** Members end with an arc from their birth node to X's node (left face:
** the edge before them, right face: the edge after them).
**
** A zero-width spike left inside a longer cycle (antiparallel pieces of
** different lengths) is left to the next step: the nearer end lies on the
** other piece, a penetration at te.  What it cannot resolve (rays that do
** not alternate around a point) is WK_EALGO: the variant then answers with
** the reference, counted (deforming.c).
*/
#include "deforming.h"
#include "wavefront.h"

#include <math.h>
#include <stdlib.h>

/* What met at an event point: a penetration from the unswept side (the
** region splits there) and a merge (the region joins there) pair the rays
** differently, see 3. above. */
/* atan2's range is (-pi, pi]; M_PI is not C11 */
#define DF_PI 3.14159265358979323846

#define DF_POINT_SPLIT 1u
#define DF_POINT_MERGE 2u

typedef struct df_cut {
    double s;       /* position along the piece */
    uint32_t order; /* 0: the piece's start, 1: interior, 2: its end */
    uint32_t k;     /* event point (root) */
} df_cut;

typedef struct df_ray {
    double angle;
    double lateral;      /* how far clockwise of X the ray's line was just
                            before te, per time (ties of angle, see ray_cmp) */
    uint32_t k, edge;
    uint32_t out;        /* 1: leaves X along +u(edge); 0: arrives (-u) */
    uint32_t far_vertex; /* untouched vertex at the other end, or WK_NONE */
    uint32_t far_ray;    /* else the ray at the other end's event point */
    uint32_t newv;
    uint32_t first;      /* sorts first among rays of one direction */
} df_ray;

struct df_resolve_scratch {
    wk_point *cx;      /* event points */
    uint32_t *cpar;    /* union-find parent */
    uint32_t *cnode;   /* skeleton node, WK_NONE until needed */
    uint32_t *ckind;   /* DF_POINT_* bits of the events found at the point */
    uint32_t n_cl, cap_cx, cap_cpar, cap_cnode, cap_ckind;
    uint32_t *mlist;   /* members, in the order found */
    uint32_t n_m, cap_mlist;
    uint32_t *split;   /* pairs (piece start, event point) */
    uint32_t n_split, cap_split;
    uint32_t *pieces;  /* touched pieces (start vertices) */
    uint32_t n_p, cap_pieces;
    df_cut *cuts;
    uint32_t cap_cuts;
    df_ray *rays;
    uint32_t n_r, cap_rays;
    uint32_t *fresh;   /* new vertices */
    uint32_t n_f, cap_fresh;
};

void df_resolve_free(df_state *D) {
    struct df_resolve_scratch *S = D->rs;
    if (!S) return;
    wk_run *R = D->R;
    WK_FREE_ARRAY(R, S->cx, S->cap_cx);
    WK_FREE_ARRAY(R, S->cpar, S->cap_cpar);
    WK_FREE_ARRAY(R, S->cnode, S->cap_cnode);
    WK_FREE_ARRAY(R, S->ckind, S->cap_ckind);
    WK_FREE_ARRAY(R, S->mlist, S->cap_mlist);
    WK_FREE_ARRAY(R, S->split, S->cap_split);
    WK_FREE_ARRAY(R, S->pieces, S->cap_pieces);
    WK_FREE_ARRAY(R, S->cuts, S->cap_cuts);
    WK_FREE_ARRAY(R, S->rays, S->cap_rays);
    WK_FREE_ARRAY(R, S->fresh, S->cap_fresh);
    WK_FREE_ARRAY(R, D->rs, 1);
}

static uint32_t find(struct df_resolve_scratch *S, uint32_t k) {
    while (S->cpar[k] != k) {
        S->cpar[k] = S->cpar[S->cpar[k]];
        k = S->cpar[k];
    }
    return k;
}

static double dist2(wk_point a, wk_point b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

/* The event point within eps_c of X, or a new one. */
static wk_status point_at(df_state *D, wk_point X, double eps_c, uint32_t *k) {
    struct df_resolve_scratch *S = D->rs;
    for (uint32_t i = 0; i < S->n_cl; i++)
        if (S->cpar[i] == i && dist2(S->cx[i], X) <= eps_c * eps_c) {
            *k = i;
            return WK_OK;
        }
    wk_run *R = D->R;
    if (WK_GROW(R, S->cx, S->cap_cx, S->n_cl + 1) != WK_OK ||
        WK_GROW(R, S->cpar, S->cap_cpar, S->n_cl + 1) != WK_OK ||
        WK_GROW(R, S->cnode, S->cap_cnode, S->n_cl + 1) != WK_OK ||
        WK_GROW(R, S->ckind, S->cap_ckind, S->n_cl + 1) != WK_OK)
        return R->err.code;
    S->cx[S->n_cl] = X;
    S->cpar[S->n_cl] = S->n_cl;
    S->cnode[S->n_cl] = WK_NONE;
    S->ckind[S->n_cl] = 0;
    *k = S->n_cl++;
    return WK_OK;
}

static wk_status add_member(df_state *D, uint32_t v, uint32_t k) {
    struct df_resolve_scratch *S = D->rs;
    k = find(S, k);
    if (D->member[v] != WK_NONE) {
        uint32_t j = find(S, D->member[v]);
        if (j != k) S->cpar[k] = j; /* one vertex at two points: they are one */
        return WK_OK;
    }
    if (WK_GROW(D->R, S->mlist, S->cap_mlist, S->n_m + 1) != WK_OK) return D->R->err.code;
    D->member[v] = k;
    S->mlist[S->n_m++] = v;
    return WK_OK;
}

static wk_status node_of(df_state *D, uint32_t k, double te, uint32_t *node) {
    struct df_resolve_scratch *S = D->rs;
    k = find(S, k);
    if (S->cnode[k] == WK_NONE &&
        wk_skeleton_add_node(D->R, D->S, S->cx[k].x + D->o.x, S->cx[k].y + D->o.y, te,
                             &S->cnode[k]) != WK_OK)
        return D->R->err.code;
    *node = S->cnode[k];
    return WK_OK;
}

static wk_status add_ray(df_state *D, uint32_t k, uint32_t edge, uint32_t out, uint32_t far_vertex,
                         uint32_t *id) {
    struct df_resolve_scratch *S = D->rs;
    if (WK_GROW(D->R, S->rays, S->cap_rays, S->n_r + 1) != WK_OK) return D->R->err.code;
    const wk_offset_line *L = &D->L[edge];
    double dx = out ? L->ux : -L->ux, dy = out ? L->uy : -L->uy;
    dy += 0.0; /* -0.0 would put a direction of angle pi at -pi */
    /* the line's offset at te - dt from X, on the clockwise normal of the
    ** ray's direction (dy, -dx): -w n . (dy, -dx) dt */
    double lateral = -L->w * (L->nx * dy - L->ny * dx) + 0.0;
    S->rays[S->n_r] =
        (df_ray){atan2(dy, dx), lateral, k, edge, out, far_vertex, WK_NONE, WK_NONE, out};
    *id = S->n_r++;
    return WK_OK;
}

/* The piece's start first, its end last, interior cuts by position. */
static int cut_cmp(const void *x, const void *y) {
    const df_cut *a = x, *b = y;
    if (a->order != b->order) return a->order < b->order ? -1 : 1;
    if (a->s != b->s) return a->s < b->s ? -1 : 1;
    return a->k < b->k ? -1 : a->k > b->k;
}

/* Sort rays by event point, then counter-clockwise.  Rays of one
** direction lie on parallel lines through X; just before te these lines
** were apart, and seen from X a line further clockwise is earlier
** counter-clockwise: so equal directions sort by that offset (for two
** antiparallel pieces this puts the out-ray first if weights are
** positive, the in-ray if negative: see 3. above).  Lines that stay
** together (parallel, same speed) put the out-ray first (the in-ray at a
** merge point), then sort by edge. */
static int ray_cmp(const void *x, const void *y) {
    const df_ray *a = x, *b = y;
    if (a->k != b->k) return a->k < b->k ? -1 : 1;
    if (a->angle != b->angle) return a->angle < b->angle ? -1 : 1;
    if (a->lateral != b->lateral) return a->lateral > b->lateral ? -1 : 1;
    if (a->first != b->first) return a->first > b->first ? -1 : 1;
    return a->edge < b->edge ? -1 : a->edge > b->edge;
}

/* Cut the piece a -> next(a) at its event points and make its rays. */
static wk_status cut_piece(df_state *D, uint32_t a, double te) {
    struct df_resolve_scratch *S = D->rs;
    wk_run *R = D->R;
    uint32_t b = D->v[a].next, e = D->v[a].eout;
    const wk_offset_line *L = &D->L[e];
    wk_point pa = df_pos(&D->v[a], te), pb = df_pos(&D->v[b], te);
    double len = L->ux * (pb.x - pa.x) + L->uy * (pb.y - pa.y);
    uint32_t n = 0;
    uint32_t ka = D->member[a] == WK_NONE ? WK_NONE : find(S, D->member[a]);
    uint32_t kb = D->member[b] == WK_NONE ? WK_NONE : find(S, D->member[b]);
    if (WK_GROW(R, S->cuts, S->cap_cuts, 2 + S->n_split / 2) != WK_OK) return R->err.code;
    if (ka != WK_NONE) S->cuts[n++] = (df_cut){0, 0, ka};
    if (kb != WK_NONE) S->cuts[n++] = (df_cut){len, 2, kb};
    for (uint32_t i = 0; i < S->n_split; i += 2) {
        if (S->split[i] != a) continue;
        uint32_t k = find(S, S->split[i + 1]);
        if (k == ka || k == kb) continue;
        double s = L->ux * (S->cx[k].x - pa.x) + L->uy * (S->cx[k].y - pa.y);
        if (s < 0) s = 0;
        if (s > len) s = len;
        S->cuts[n++] = (df_cut){s, 1, k};
    }
    if (n == 0) return WK_OK;
    if (n > 1) qsort(S->cuts, n, sizeof *S->cuts, cut_cmp);
    /* the same point twice in a row is one cut */
    uint32_t m = 1;
    for (uint32_t i = 1; i < n; i++)
        if (S->cuts[i].k != S->cuts[m - 1].k) S->cuts[m++] = S->cuts[i];
    uint32_t id, id2;
    if (ka == WK_NONE && add_ray(D, S->cuts[0].k, e, 0, a, &id) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i + 1 < m; i++) {
        if (add_ray(D, S->cuts[i].k, e, 1, WK_NONE, &id) != WK_OK ||
            add_ray(D, S->cuts[i + 1].k, e, 0, WK_NONE, &id2) != WK_OK)
            return R->err.code;
        S->rays[id].far_ray = id2;
        S->rays[id2].far_ray = id;
    }
    if (kb == WK_NONE && add_ray(D, S->cuts[m - 1].k, e, 1, b, &id) != WK_OK) return R->err.code;
    return WK_OK;
}

static void unlink_vertex(df_state *D, uint32_t x) {
    df_vertex *X = &D->v[x];
    df_touch(D, x);
    df_touch(D, X->prev);
    df_touch(D, X->next);
    D->v[X->prev].next = X->next;
    D->v[X->next].prev = X->prev;
    X->alive = 0;
    D->n_alive--;
}

/* End vertex x at time te at its position there: the arc of its trace. */
static wk_status end_at(df_state *D, uint32_t x, uint32_t node) {
    df_vertex *X = &D->v[x];
    if (X->node != node &&
        wk_skeleton_add_arc(D->R, D->S, X->node, node, X->ein, X->eout) != WK_OK)
        return D->R->err.code;
    return WK_OK;
}

static wk_status fresh_node_at(df_state *D, uint32_t x, double te, uint32_t *node) {
    df_vertex *X = &D->v[x];
    if (X->t0 == te) {
        *node = X->node;
        return WK_OK;
    }
    wk_point q = df_pos(X, te);
    if (wk_skeleton_add_node(D->R, D->S, q.x + D->o.x, q.y + D->o.y, te, node) != WK_OK)
        return D->R->err.code;
    return end_at(D, x, *node);
}

/* The collinear rule (000, section 1), as the engine applies it: a vertex
** x between parallel edges of different weight (same sense) cannot move
** with both.  The piece of the losing weight next to x (the higher weight
** by default, the lower with --collinear higher) is swept at once: an arc
** along it at time te between its face (right) and the winner's (left),
** its far vertex ends there, and a new vertex at that far end joins the
** winner's edge to the edge beyond; that vertex may again lie between
** parallel edges of different weight, so the rule repeats.  fresh: push
** the new vertices on the resolution's list (false at t = 0, where no
** resolution runs). */
static bool df_is_collinear(const df_state *D, uint32_t x) {
    const df_vertex *X = &D->v[x];
    wk_point vel;
    return X->alive &&
           wk_vertex_velocity(&D->L[X->ein], &D->L[X->eout], &vel) == WK_VEL_COLLINEAR;
}

wk_status df_collinear_rule(df_state *D, uint32_t x, double te, bool fresh) {
    wk_run *R = D->R;
    uint32_t x0 = x; /* asked for; done once it is no longer collinear */
    for (uint32_t guard = 0; guard <= 2 * D->nv + 2; guard++) {
        if (!df_is_collinear(D, x)) {
            if (x == x0 || !df_is_collinear(D, x0)) return WK_OK;
            x = x0; /* the rule ran from a vertex before x0: x0 is left */
        }
        df_vertex *X = &D->v[x];
        uint32_t y = X->next, w = X->prev;
        if (y == w || y == x) return WK_OK; /* a cycle of two: the clean-up's */
        double w_in = D->L[X->ein].w, w_out = D->L[X->eout].w;
        bool lower = R->opt.collinear == WK_COLLINEAR_LOWER;
        bool out_loses = lower ? w_out > w_in : w_out < w_in;
        /* A losing piece between two parallel ones is covered by the piece
        ** before it, as the engine's rule (wf_collinear_rule) does on a run
        ** of parallel pieces: the rule runs from the vertex at the losing
        ** piece's start.  Covering it by the piece after moved the boundary
        ** of their faces from one end of the swept piece to the other
        ** (tests/test_degenerate.py generated case 1893: weights 1, 2, 1). */
        if (!out_loses && w != x0 && df_is_collinear(D, w)) {
            x = w;
            continue;
        }
        /* the losing piece runs a -> b; the far vertex f is b or a */
        uint32_t a = out_loses ? x : w, b = out_loses ? y : x, f = out_loses ? y : w;
        uint32_t win = out_loses ? X->ein : X->eout, lose = out_loses ? X->eout : X->ein;
        uint32_t na, nb;
        if (fresh_node_at(D, a, te, &na) != WK_OK || fresh_node_at(D, b, te, &nb) != WK_OK)
            return R->err.code;
        if (na != nb && wk_skeleton_add_arc(R, D->S, na, nb, win, lose) != WK_OK) return R->err.code;
        wk_event ev = {te, 0, 0, lose, win, WK_NONE};
        wk_notify_event(R, WK_COUNTER_collinear_resolutions, &ev);
        uint32_t nf = out_loses ? nb : na;
        df_vertex Z = {{0, 0}, {0, 0}, te, out_loses ? win : D->v[f].ein,
                       out_loses ? D->v[f].eout : win, WK_NONE, WK_NONE, nf, 1};
        bool reflex;
        wk_point q = df_pos(&D->v[f], te);
        double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
        (void)wk_vertex_start(D->L, Z.ein, Z.eout, q, te, eps_c, &Z.p0, &Z.v, &reflex);
        uint32_t z;
        if (df_add_vertex(D, &Z, &z) != WK_OK) return R->err.code;
        /* splice: before(a) -> z -> after(b) */
        uint32_t before = D->v[out_loses ? x : w].prev, after = D->v[out_loses ? y : x].next;
        D->v[x].alive = D->v[f].alive = 0;
        D->n_alive -= 2;
        df_touch(D, x);
        df_touch(D, f);
        df_touch(D, before);
        df_touch(D, after);
        D->v[z].prev = before;
        D->v[z].next = after;
        D->v[before].next = z;
        D->v[after].prev = z;
        if (fresh) {
            struct df_resolve_scratch *S = D->rs;
            if (WK_GROW(R, S->fresh, S->cap_fresh, S->n_f + 1) != WK_OK) return R->err.code;
            S->fresh[S->n_f++] = z;
        }
        x = z;
    }
    return WK_FAIL(R, WK_EALGO, D->P->name, 0, "deforming: the collinear rule does not end at t = %.17g",
                   te);
}

/* Where the ends of a collapsing piece meet, each end's place weighted by
** the other's speed (as the engine's edge event): a vertex of speed s is
** off by s times the rounding of te, so the slow end is the better
** witness.  A vertex born between sides antiparallel to 1.7e-11 moves at
** 5e10, and the midpoint put the node 3.5e-6 off
** (tests/data/degenerate/antiparallel_birth_comb.wpoly).  Equal speeds
** give the midpoint. */
static wk_point collapse_point(const df_vertex *A, const df_vertex *B, double te) {
    wk_point pa = df_pos(A, te), pb = df_pos(B, te);
    double sa = fabs(A->v.x) + fabs(A->v.y), sb = fabs(B->v.x) + fabs(B->v.y);
    double fa = sa + sb > 0 ? sb / (sa + sb) : 0.5;
    return (wk_point){fa * pa.x + (1 - fa) * pb.x, fa * pa.y + (1 - fa) * pb.y};
}

/* The end of the piece a -> next(a) that vertex p's penetration meets, when
** that piece is the one before p's previous piece (next(a) == prev(p)) or
** after its next piece (a == next(p)), its line is not parallel to the line
** of the piece q between them, and q collapses within eps_t of te (its
** length then within the contact distance); else WK_NONE.  p and that end
** both lie on q's line, and p reaches a's line only where the two lines
** cross, that is where the end is: the contact is the collapse of q, and
** the end is a member of its event point.  With p moving nearly along a's
** line (the sides of a long thin spike) its gap stays within the contact
** distance for longer than eps_t, and the group took the penetration while
** q was still 5e-6 long (eps_d 2e-6), the end out of reach: two pieces
** left the event point side by side (star n = 2e4 and 3e4, seed 1,
** t = 0.1596, handed to the reference:
** tests/data/degenerate/deform_star_spike_next_but_one.wpoly).  A q that
** does not collapse by then is left alone: p is near a's line only within
** the tolerance (holes whose vertices are 4.7e-6 apart, eps_d 1.7e-6:
** forcing the end 2.1e-6 away in gave a skeleton unlike CGAL's,
** tests/data/fuzz/mismatch_arrangement_motorcycle_holes_touching.wpoly).
** Parallel lines (a zero-width spike, see the clean-up) meet along a
** segment: there the contact is the penetration that zips the spike up. */
static uint32_t shared_end(const df_state *D, uint32_t p, uint32_t a, double te, double eps_c) {
    const df_vertex *V = &D->v[p], *A = &D->v[a];
    uint32_t q, end;
    if (A->next == V->prev) {
        q = V->ein;
        end = A->next;
    } else if (a == V->next) {
        q = V->eout;
        end = a;
    } else {
        return WK_NONE;
    }
    const wk_offset_line *La = &D->L[A->eout], *Lq = &D->L[q];
    if (!(fabs(La->ux * Lq->uy - La->uy * Lq->ux) > WK_PARALLEL_SIN)) return WK_NONE;
    /* q runs s -> f: its length along its direction now and its rate */
    const df_vertex *S = end == a ? V : &D->v[end], *F = end == a ? &D->v[end] : V;
    wk_point ps = df_pos(S, te), pf = df_pos(F, te);
    double len = Lq->ux * (pf.x - ps.x) + Lq->uy * (pf.y - ps.y);
    double rate = Lq->ux * (F->v.x - S->v.x) + Lq->uy * (F->v.y - S->v.y);
    double reach = eps_c + (rate < 0 ? -rate * D->eps_t : 0);
    return len <= reach ? end : WK_NONE;
}

/* Rings that nearly touch: end x of piece a (end 0: its start, 1: its
** end), an input vertex, within the contact distance of the point where an
** input vertex p of another ring penetrates the piece, does not end there
** when the input says p meets the piece's line inside the piece by more
** than rounding and the stretch of the piece between x and the cut grows:
** the engine's rule (wavefront_group.c, plan_shields; wk_input_cut_side),
** at the nominal tolerance and finer as there.  A member, x joined the two
** rings where naive and CGAL keep them apart: two holes whose apexes lie
** 1e-6 apart (3.4 eps_d), one apex splitting the other's edge 4e-8 from
** its apex (tests/test_near_touch.py --sweep 1000 case 40, 6 more). */
static bool passed_by(const df_state *D, uint32_t a, int end, double te) {
    const df_vertex *A = &D->v[a];
    uint32_t x = end ? A->next : a;
    const df_vertex *X = &D->v[x];
    if (D->R->opt.tol_scale > 1 || x >= D->P->n || X->t0 != 0) return false;
    const wk_offset_line *L = &D->L[A->eout];
    for (uint32_t i = 0; i < D->n_ev; i++) {
        const df_event *E = &D->ev[i];
        if (E->kind != DF_PENETRATION || E->b != a) continue;
        uint32_t p = E->a;
        const df_vertex *V = &D->v[p];
        if (p >= D->P->n || V->t0 != 0 || wk_polygon_ring(D->P, p) == wk_polygon_ring(D->P, x)) continue;
        if (wk_input_cut_side(D->P, p, V->v, x, X->v, L, end, te) <= 0) continue;
        /* the stretch between x and the vertex the cut makes there grows */
        wk_point vy;
        const wk_offset_line *Lf = &D->L[end ? V->ein : V->eout];
        if ((end ? wk_vertex_velocity(Lf, L, &vy) : wk_vertex_velocity(L, Lf, &vy)) != WK_VEL_REGULAR)
            continue;
        double grow = end ? L->ux * (X->v.x - vy.x) + L->uy * (X->v.y - vy.y)
                          : L->ux * (vy.x - X->v.x) + L->uy * (vy.y - X->v.y);
        double speeds = fabs(vy.x) + fabs(vy.y) + fabs(X->v.x) + fabs(X->v.y);
        if (grow > WK_SPLIT_SIDE_GROWTH_REL * speeds) return true;
    }
    return false;
}

static wk_status resolve(df_state *D, double te) {
    struct df_resolve_scratch *S = D->rs;
    wk_run *R = D->R;
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    /* 1. event points and members */
    for (uint32_t i = 0; i < D->n_ev; i++) {
        const df_event *E = &D->ev[i];
        uint32_t k;
        if (E->kind == DF_COLLAPSE) {
            uint32_t a = E->a, b = D->v[a].next;
            wk_point X = E->at_x ? E->x : collapse_point(&D->v[a], &D->v[b], te);
            if (point_at(D, X, eps_c, &k) != WK_OK || add_member(D, a, k) != WK_OK ||
                add_member(D, b, k) != WK_OK)
                return R->err.code;
            wk_notify_event(R, WK_VC_edge_swaps, &(wk_event){te, X.x + D->o.x, X.y + D->o.y, a, b, WK_NONE});
        } else {
            wk_point X = E->at_x ? E->x : df_pos(&D->v[E->a], te);
            uint32_t end =
                E->kind == DF_PENETRATION ? shared_end(D, E->a, E->b, te, eps_c) : WK_NONE;
            if (point_at(D, X, eps_c, &k) != WK_OK || add_member(D, E->a, k) != WK_OK ||
                (end != WK_NONE && add_member(D, end, k) != WK_OK))
                return R->err.code;
            S->ckind[k] |= E->kind == DF_MERGE ? DF_POINT_MERGE : DF_POINT_SPLIT;
            if (WK_GROW(R, S->split, S->cap_split, S->n_split + 2) != WK_OK) return R->err.code;
            S->split[S->n_split++] = E->b;
            S->split[S->n_split++] = k;
            wk_notify_event(R, E->kind == DF_MERGE ? WK_VC_merges : WK_VC_penetrations,
                            &(wk_event){te, X.x + D->o.x, X.y + D->o.y, E->a, E->b, WK_NONE});
        }
    }
    /* ends of cut pieces at the point, and neighbours within reach */
    for (int round = 0; round < 2; round++) {
        for (uint32_t i = 0; i < S->n_split; i += 2) {
            uint32_t a = S->split[i], k = find(S, S->split[i + 1]);
            uint32_t ends[2] = {a, D->v[a].next};
            for (int j = 0; j < 2; j++)
                if (D->member[ends[j]] == WK_NONE &&
                    dist2(df_pos(&D->v[ends[j]], te), S->cx[k]) <= eps_c * eps_c && !passed_by(D, a, j, te) &&
                    add_member(D, ends[j], k) != WK_OK)
                    return R->err.code;
        }
        for (uint32_t i = 0; i < S->n_m; i++) {
            uint32_t v = S->mlist[i], k = find(S, D->member[v]);
            uint32_t nb[2] = {D->v[v].prev, D->v[v].next};
            for (int j = 0; j < 2; j++)
                if (D->member[nb[j]] == WK_NONE &&
                    dist2(df_pos(&D->v[nb[j]], te), S->cx[k]) <= eps_c * eps_c &&
                    add_member(D, nb[j], k) != WK_OK)
                    return R->err.code;
        }
    }
    /* 2. touched pieces and their rays */
    for (uint32_t i = 0; i < S->n_m + S->n_split / 2; i++) {
        uint32_t cand[2];
        uint32_t nc = 0;
        if (i < S->n_m) {
            cand[nc++] = D->v[S->mlist[i]].prev;
            cand[nc++] = S->mlist[i];
        } else {
            cand[nc++] = S->split[2 * (i - S->n_m)];
        }
        for (uint32_t j = 0; j < nc; j++) {
            if (D->mark[cand[j]]) continue;
            D->mark[cand[j]] = 1;
            if (WK_GROW(R, S->pieces, S->cap_pieces, S->n_p + 1) != WK_OK) return R->err.code;
            S->pieces[S->n_p++] = cand[j];
        }
    }
    for (uint32_t i = 0; i < S->n_p; i++)
        if (cut_piece(D, S->pieces[i], te) != WK_OK) return R->err.code;
    /* 3. pairing; ray ids change with the sort, so far_ray is mapped */
    /* the kinds of the merged points go to their roots */
    for (uint32_t k = 0; k < S->n_cl; k++) S->ckind[find(S, k)] |= S->ckind[k];
    for (uint32_t i = 0; i < S->n_r; i++) {
        S->rays[i].newv = i; /* old id, for now */
        if (S->ckind[S->rays[i].k] == DF_POINT_MERGE) S->rays[i].first = !S->rays[i].out;
        /* a direction just below pi is one with those just above -pi */
        if (S->rays[i].angle > DF_PI - WK_PARALLEL_SIN) S->rays[i].angle -= 2 * DF_PI;
    }
    if (S->n_r > 1) qsort(S->rays, S->n_r, sizeof *S->rays, ray_cmp); /* rays may be NULL when empty */
    /* Directions within WK_PARALLEL_SIN of each other are one (lines the
    ** engine calls parallel; their order is the rounding's): each run of
    ** them takes its first ray's angle and sorts again, by the lines'
    ** offsets just before te (ray_cmp), as exactly parallel ones do. */
    bool runs = false;
    for (uint32_t i = 1; i < S->n_r; i++) {
        uint32_t j = i;
        while (j < S->n_r && S->rays[j].k == S->rays[i - 1].k &&
               S->rays[j].angle - S->rays[i - 1].angle <= WK_PARALLEL_SIN) {
            runs |= S->rays[j].angle != S->rays[i - 1].angle;
            S->rays[j].angle = S->rays[i - 1].angle;
            j++;
        }
        if (j > i) i = j - 1;
    }
    if (runs) qsort(S->rays, S->n_r, sizeof *S->rays, ray_cmp);
    if (WK_GROW(R, S->cuts, S->cap_cuts, S->n_r / 2 + 1) != WK_OK) return R->err.code;
    uint32_t *where = WK_NEW_ARRAY(R, uint32_t, S->n_r + 1);
    if (!where) return R->err.code;
    for (uint32_t i = 0; i < S->n_r; i++) where[S->rays[i].newv] = i;
    for (uint32_t i = 0; i < S->n_r; i++) {
        if (S->rays[i].far_ray != WK_NONE) S->rays[i].far_ray = where[S->rays[i].far_ray];
        S->rays[i].newv = WK_NONE;
    }
    WK_FREE_ARRAY(R, where, S->n_r + 1);
    for (uint32_t lo = 0, hi; lo < S->n_r; lo = hi) {
        uint32_t k = S->rays[lo].k, outs = 0;
        for (hi = lo; hi < S->n_r && S->rays[hi].k == k; hi++) outs += S->rays[hi].out;
        if (2 * outs != hi - lo)
            return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                           "deforming: %u rays leave and %u arrive at an event point at t = %.17g",
                           outs, hi - lo - outs, te);
        uint32_t kind = S->ckind[find(S, k)];
        bool merge = kind == DF_POINT_MERGE;
        uint32_t node;
        if (node_of(D, k, te, &node) != WK_OK) return R->err.code;
        for (uint32_t jj = lo; jj < hi; jj++) {
            /* j: the out-ray of the new vertex, i: its in-ray */
            uint32_t j = jj, i = jj + 1 == hi ? lo : jj + 1;
            if (merge) {
                if (S->rays[jj].out) continue;
                j = i;
                i = jj;
                if (!S->rays[j].out)
                    return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                                   "deforming: two pieces arrive at a merge point side by side at "
                                   "t = %.17g",
                                   te);
            } else if (!S->rays[j].out) {
                continue;
            }
            if (!merge && S->rays[i].out)
                return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                               "deforming: two pieces leave an event point side by side at t = %.17g",
                               te);
            df_vertex V = {{0, 0}, {0, 0}, te, S->rays[i].edge, S->rays[j].edge, WK_NONE, WK_NONE,
                           node, 1};
            bool reflex;
            wk_velocity_kind kind =
                wk_vertex_start(D->L, V.ein, V.eout, S->cx[k], te, eps_c, &V.p0, &V.v, &reflex);
            (void)kind; /* a collinear vertex is taken by the collinear rule below */
            uint32_t id;
            if (df_add_vertex(D, &V, &id) != WK_OK) return R->err.code;
            S->rays[i].newv = S->rays[j].newv = id;
            if (WK_GROW(R, S->fresh, S->cap_fresh, S->n_f + 1) != WK_OK) return R->err.code;
            S->fresh[S->n_f++] = id;
        }
    }
    /* 4. linking */
    for (uint32_t i = 0; i < S->n_r; i++) {
        const df_ray *Y = &S->rays[i];
        uint32_t far = Y->far_vertex != WK_NONE ? Y->far_vertex : S->rays[Y->far_ray].newv;
        df_touch(D, far);
        if (Y->out) {
            D->v[Y->newv].next = far;
            D->v[far].prev = Y->newv;
        } else {
            D->v[Y->newv].prev = far;
            D->v[far].next = Y->newv;
        }
    }
    /* members end */
    for (uint32_t i = 0; i < S->n_m; i++) {
        uint32_t v = S->mlist[i], node;
        if (node_of(D, D->member[v], te, &node) != WK_OK || end_at(D, v, node) != WK_OK)
            return R->err.code;
        D->v[v].alive = 0;
        D->n_alive--;
        df_touch(D, v);
    }
    /* 5. clean-up: pass-through vertices, cycles of one and two */
    for (uint32_t i = 0; i < S->n_f; i++) {
        uint32_t x = S->fresh[i];
        if (!D->v[x].alive || D->v[x].ein != D->v[x].eout) continue;
        if (D->v[x].next == x) {
            D->v[x].alive = 0;
            D->n_alive--;
            df_touch(D, x);
        } else {
            unlink_vertex(D, x);
        }
    }
    for (uint32_t i = 0; i < S->n_f; i++) {
        uint32_t x = S->fresh[i];
        if (D->v[x].alive && df_collinear_rule(D, x, te, true) != WK_OK) return R->err.code;
    }
    for (uint32_t i = 0; i < S->n_f; i++) {
        uint32_t x = S->fresh[i];
        if (!D->v[x].alive) continue;
        uint32_t y = D->v[x].next;
        if (y == x) {
            D->v[x].alive = 0;
            D->n_alive--;
            df_touch(D, x);
            continue;
        }
        if (D->v[y].next == x) {
            uint32_t nx, ny;
            if (fresh_node_at(D, x, te, &nx) != WK_OK || fresh_node_at(D, y, te, &ny) != WK_OK)
                return R->err.code;
            if (nx != ny &&
                wk_skeleton_add_arc(R, D->S, nx, ny, D->v[y].eout, D->v[x].eout) != WK_OK)
                return R->err.code;
            D->v[x].alive = D->v[y].alive = 0;
            D->n_alive -= 2;
            df_touch(D, x);
            df_touch(D, y);
            continue;
        }
        /* A zero-width spike (antiparallel pieces leaving x along one line)
        ** left in a longer cycle: the nearer end of the two pieces lies on
        ** the other piece now, a penetration the next step finds at te and
        ** resolves (the spike zips up to there, an arc along it). */
    }
    uint32_t roots = 0;
    for (uint32_t k = 0; k < S->n_cl; k++) roots += find(S, k) == k;
    wk_count(R, WK_VC_event_points, roots);
    return WK_OK;
}

wk_status df_resolve(df_state *D, double te) {
    if (!D->rs) {
        D->rs = WK_NEW_ARRAY(D->R, struct df_resolve_scratch, 1);
        if (!D->rs) return D->R->err.code;
    }
    struct df_resolve_scratch *S = D->rs;
    S->n_cl = S->n_m = S->n_split = S->n_p = S->n_r = S->n_f = 0;
    wk_status st = resolve(D, te);
    /* reset the per-vertex scratch that this call touched */
    for (uint32_t i = 0; i < S->n_m; i++) D->member[S->mlist[i]] = WK_NONE;
    for (uint32_t i = 0; i < S->n_p; i++) D->mark[S->pieces[i]] = 0;
    return st;
}
