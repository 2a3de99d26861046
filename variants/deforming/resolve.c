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

#include <float.h>
#include <math.h>
#include <stdlib.h>

/* What met at an event point: a penetration from the unswept side (the
** region splits there) and a merge (the region joins there) pair the rays
** differently, see 3. above. */
/* atan2's range is (-pi, pi]; M_PI is not C11 */
#define DF_PI 3.14159265358979323846

#define DF_POINT_SPLIT 1u
#define DF_POINT_MERGE 2u
/* an event that lands outside its piece (step 0) */
#define DF_ECHO_BIT 0x80000000u

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
    uint32_t far_k;      /* the event point at the other end (far_ray's), or WK_NONE */
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
    uint32_t *ek;      /* each event's point (step 0), DF_ECHO_BIT: an echo */
    uint32_t cap_ek;
    uint32_t *cseeds;  /* events at each point that are no echo */
    uint32_t cap_cseeds;
    uint32_t *shield;  /* pairs (vertex, event point): x does not arrive there */
    uint32_t n_sh, cap_shield;
    uint32_t *run, *run_node; /* the collinear rule's run and its nodes */
    uint32_t n_run, cap_run, cap_run_node;
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
    WK_FREE_ARRAY(R, S->ek, S->cap_ek);
    WK_FREE_ARRAY(R, S->cseeds, S->cap_cseeds);
    WK_FREE_ARRAY(R, S->shield, S->cap_shield);
    WK_FREE_ARRAY(R, S->run, S->cap_run);
    WK_FREE_ARRAY(R, S->run_node, S->cap_run_node);
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

/* True if vertex v is shielded from event point k (step 0). */
static bool shielded(struct df_resolve_scratch *S, uint32_t v, uint32_t k) {
    for (uint32_t i = 0; i < S->n_sh; i += 2)
        if (S->shield[i] == v && find(S, S->shield[i + 1]) == find(S, k)) return true;
    return false;
}

/* v ends at event point k, unless it is shielded from it (step 0). */
static wk_status add_member(df_state *D, uint32_t v, uint32_t k) {
    struct df_resolve_scratch *S = D->rs;
    if (S->n_sh && shielded(S, v, k)) return WK_OK;
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
        (df_ray){atan2(dy, dx), lateral, k, edge, out, far_vertex, WK_NONE, WK_NONE, out, WK_NONE};
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

/* Two rays whose other ends are one point: the same event point, or the
** same untouched vertex (its two pieces both run to X). */
static bool same_far_end(const df_ray *a, const df_ray *b) {
    return (a->far_k != WK_NONE && a->far_k == b->far_k) ||
           (a->far_vertex != WK_NONE && a->far_vertex == b->far_vertex);
}

/* Where P lies from the piece of ray Y's edge at te: > 0 counter-clockwise
** of the ray (its left), < 0 clockwise, 0 within rounding (WK_BEHIND_ULPS
** ulps of the terms). */
static int side_of_ray_line(const df_state *D, const df_ray *Y, wk_point P, double te) {
    const wk_offset_line *L = &D->L[Y->edge];
    double d = L->nx * P.x + L->ny * P.y - L->c - L->w * te;
    double ulp = DBL_EPSILON * (fabs(L->nx * P.x) + fabs(L->ny * P.y) + fabs(L->c) +
                                fabs(L->w * te));
    if (fabs(d) <= WK_BEHIND_ULPS * ulp) return 0;
    return (d > 0) == (Y->out != 0) ? 1 : -1;
}

/* Two rays of one point that run to one far end (an untouched vertex or
** another event point) within WK_CANCEL_SIN are the two sides of a sliver
** between X and that end P: nothing lies between them, whatever their
** directions say.  Where other rays sort between them (their directions
** lie inside the sliver's), the sliver goes before all of them if P lies
** clockwise of each one's line at te, after all of them if
** counter-clockwise (else the order stays: WK_EALGO if it does not
** alternate).  The lines are what count, not the directions: X stands for
** an event point up to the contact distance wide, and lines that pass it
** that far apart keep their order over the sliver's length.  Found by the
** variants fuzz target: a monotone 48-gon with needles 3.2e8, 1e6 and
** 4.3e12 long (eps_d 4300, the body of the polygon 2000 across): the body
** collapses at one point, the 1e6 needle's sides leave it 8.9e-5 apart in
** direction, the 4.3e12 needle's between them (its lines 300 .. 450 west
** of the short needle's tip); sorted by direction the short needle's sides
** paired with the long one's (a cycle through the point twice, then a
** skeleton with a cycle: the reference answered), or two pieces left the
** point side by side
** (tests/data/fuzz/mismatch_deforming_monotone_spike_3e8.wpoly).
** Returns true if a ray's angle changed (sort again). */
static bool place_slivers(df_state *D, double te) {
    struct df_resolve_scratch *S = D->rs;
    bool moved = false;
    for (uint32_t a = 0; a < S->n_r; a++) {
        for (uint32_t b = a + 2; b < S->n_r && S->rays[b].k == S->rays[a].k; b++) {
            if (S->rays[b].angle - S->rays[a].angle > WK_CANCEL_SIN) break; /* sorted */
            if (!same_far_end(&S->rays[a], &S->rays[b])) continue;
            wk_point P = S->rays[a].far_vertex != WK_NONE
                             ? df_pos(&D->v[S->rays[a].far_vertex], te)
                             : S->cx[S->rays[a].far_k];
            int cw = 0, ccw = 0;
            for (uint32_t m = a + 1; m < b; m++) {
                if (same_far_end(&S->rays[m], &S->rays[a])) break;
                int side = side_of_ray_line(D, &S->rays[m], P, te);
                cw += side < 0;
                ccw += side > 0;
            }
            if (cw == (int)(b - a - 1)) {
                double to = nextafter(S->rays[a].angle, -INFINITY);
                S->rays[a].angle = S->rays[b].angle = to;
                moved = true;
            } else if (ccw == (int)(b - a - 1)) {
                double to = nextafter(S->rays[b].angle, INFINITY);
                S->rays[a].angle = S->rays[b].angle = to;
                moved = true;
            }
            break;
        }
    }
    return moved;
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

/* The collinear rule (000, section 1), as the engine applies it
** (wf_collinear_rule): a vertex x between parallel edges of different
** weight (same sense) cannot move with both.  The maximal run of
** consecutive pieces on that line is taken (vertices between parallel
** edges of equal weight included: three parallel walls can meet at once);
** its winning weight (the lowest by default, the highest with --collinear
** higher) survives, every other piece of the run is swept at once, an arc
** along it at time te between its face (right) and the face of the
** surviving piece that extends over it (the one before it, else the first
** one after it).  The run's vertices that touch a swept piece end there;
** new vertices join the surviving pieces.  Taken pair by pair (the losing
** piece next to x swept, the rule repeated at the new vertex), a run of
** weights 4, 8, 8, 1 let the piece of weight 4 cover the two of weight 8
** before the one of weight 1 covered it: one arc along three input edges,
** which the validator rejects, and faces unlike the engine's (the 11
** collinear_mixed cases of the quick stress sweep went to the reference,
** e.g. tests/data/degenerate/deform_collinear_run_lowest.wpoly).  fresh:
** push the new vertices on the resolution's list (false at t = 0, where no
** resolution runs). */
static bool df_is_collinear(const df_state *D, uint32_t x) {
    const df_vertex *X = &D->v[x];
    wk_point vel;
    return X->alive &&
           wk_vertex_velocity(&D->L[X->ein], &D->L[X->eout], &vel) == WK_VEL_COLLINEAR;
}

/* x lies between parallel edges of one sense (any weights). */
static bool df_on_one_line(const df_state *D, uint32_t x) {
    const df_vertex *X = &D->v[x];
    wk_point vel;
    if (!X->alive) return false;
    wk_velocity_kind k = wk_vertex_velocity(&D->L[X->ein], &D->L[X->eout], &vel);
    return k == WK_VEL_COLLINEAR || k == WK_VEL_STRAIGHT;
}

static wk_status df_scratch(df_state *D) {
    if (!D->rs) {
        D->rs = WK_NEW_ARRAY(D->R, struct df_resolve_scratch, 1);
        if (!D->rs) return D->R->err.code;
    }
    return WK_OK;
}

/* The node of run vertex i at te, made once (fresh_node_at). */
static wk_status df_run_node(df_state *D, uint32_t i, double te, uint32_t *node) {
    struct df_resolve_scratch *S = D->rs;
    if (S->run_node[i] == WK_NONE && fresh_node_at(D, S->run[i], te, &S->run_node[i]) != WK_OK)
        return D->R->err.code;
    *node = S->run_node[i];
    return WK_OK;
}

wk_status df_collinear_rule(df_state *D, uint32_t x, double te, bool fresh) {
    wk_run *R = D->R;
    if (!df_is_collinear(D, x)) return WK_OK;
    if (df_scratch(D) != WK_OK) return R->err.code;
    struct df_resolve_scratch *S = D->rs;
    /* run[0]: the vertex before the run's first piece; run[m]: after its
    ** last; run[1..m-1] lie between pieces of the run */
    uint32_t u0 = x, um = x, guard = 0;
    while (df_on_one_line(D, u0)) {
        u0 = D->v[u0].prev;
        if (++guard > D->nv) goto cyclic;
    }
    while (df_on_one_line(D, um)) {
        um = D->v[um].next;
        if (++guard > D->nv) goto cyclic;
    }
    S->n_run = 0;
    for (uint32_t u = u0;; u = D->v[u].next) {
        if (WK_GROW(R, S->run, S->cap_run, S->n_run + 1) != WK_OK ||
            WK_GROW(R, S->run_node, S->cap_run_node, S->n_run + 1) != WK_OK)
            return R->err.code;
        S->run[S->n_run] = u;
        S->run_node[S->n_run++] = WK_NONE;
        if (u == um) break;
    }
    uint32_t m = S->n_run - 1;
    /* piece i (1..m) runs run[i-1] -> run[i] on edge PIECE_EDGE(i) */
#define PIECE_EDGE(i) (D->v[S->run[(i) - 1]].eout)
    bool lower = R->opt.collinear == WK_COLLINEAR_LOWER;
    double best = D->L[PIECE_EDGE(1)].w;
    for (uint32_t i = 2; i <= m; i++) {
        double w = D->L[PIECE_EDGE(i)].w;
        if (lower ? w < best : w > best) best = w;
    }
    uint32_t first_winner = WK_NONE;
    for (uint32_t i = 1; i <= m && first_winner == WK_NONE; i++)
        if (D->L[PIECE_EDGE(i)].w == best) first_winner = PIECE_EDGE(i);
    /* arcs along the losing pieces */
    uint32_t ext = first_winner;
    bool changed = false;
    for (uint32_t i = 1; i <= m; i++) {
        uint32_t e = PIECE_EDGE(i), a, b;
        if (D->L[e].w == best) {
            ext = e;
            continue;
        }
        if (df_run_node(D, i - 1, te, &a) != WK_OK || df_run_node(D, i, te, &b) != WK_OK)
            return R->err.code;
        if (a != b && wk_skeleton_add_arc(R, D->S, a, b, ext, e) != WK_OK) return R->err.code;
        wk_event ev = {te, 0, 0, e, ext, WK_NONE};
        wk_notify_event(R, WK_COUNTER_collinear_resolutions, &ev);
        changed = true;
    }
    if (!changed) return WK_OK;
    /* rebuild: cur is the last vertex of the new wavefront, cur_out the
    ** edge leaving it */
    uint32_t cur = D->v[u0].prev, cur_out = D->v[u0].ein;
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    for (uint32_t i = 0; i <= m; i++) {
        uint32_t u = S->run[i];
        uint32_t ein = i == 0 ? D->v[u].ein : PIECE_EDGE(i);
        uint32_t eout = i == m ? D->v[u].eout : PIECE_EDGE(i + 1);
        bool lost_before = i > 0 && D->L[ein].w != best;
        bool lost_after = i < m && D->L[eout].w != best;
        if (!lost_before && !lost_after) {
            D->v[cur].next = u; /* untouched */
            D->v[u].prev = cur;
            df_touch(D, cur);
            df_touch(D, u);
            cur = u;
            cur_out = D->v[u].eout;
            continue;
        }
        uint32_t nd;
        if (df_run_node(D, i, te, &nd) != WK_OK) return R->err.code;
        wk_point q = df_pos(&D->v[u], te);
        uint32_t p_next = D->v[u].next;
        D->v[u].alive = 0;
        D->n_alive--;
        df_touch(D, u);
        /* the edge that leaves this point in the new wavefront */
        uint32_t leave = i == m ? eout : (lost_after ? cur_out : eout);
        if (i == 0) leave = first_winner;
        if (lost_after && i > 0 && i < m && D->L[ein].w == best) leave = ein;
        if (i < m && !lost_after) leave = eout;
        if (leave != cur_out) {
            df_vertex Z = {{0, 0}, {0, 0}, te, cur_out, leave, WK_NONE, WK_NONE, nd, 1};
            bool reflex;
            (void)wk_vertex_start(D->L, Z.ein, Z.eout, q, te, eps_c, &Z.p0, &Z.v, &reflex);
            uint32_t z;
            if (df_add_vertex(D, &Z, &z) != WK_OK) return R->err.code;
            D->v[cur].next = z;
            D->v[z].prev = cur;
            df_touch(D, cur);
            cur = z;
            cur_out = leave;
            if (fresh) {
                if (WK_GROW(R, S->fresh, S->cap_fresh, S->n_f + 1) != WK_OK) return R->err.code;
                S->fresh[S->n_f++] = z;
            }
        }
        if (i == m) {
            D->v[cur].next = p_next;
            D->v[p_next].prev = cur;
            df_touch(D, cur);
            df_touch(D, p_next);
        }
    }
#undef PIECE_EDGE
    return WK_OK;
cyclic:
    return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                   "deforming: a whole wavefront cycle lies on one line at t = %.17g", te);
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

/* The vertex of event i is the vertex of another event of the group (a
** collapse of one of its pieces, another penetration): it ends in this
** resolution whatever this event is. */
static bool ends_elsewhere(const df_state *D, uint32_t i) {
    uint32_t p = D->ev[i].a;
    for (uint32_t j = 0; j < D->n_ev; j++) {
        const df_event *F = &D->ev[j];
        if (j == i) continue;
        if (F->a == p || (F->kind == DF_COLLAPSE && D->v[F->a].next == p)) return true;
    }
    return false;
}

/* X lies beyond an end of the piece a -> next(a) at te by more than eps_c. */
static bool outside_piece(const df_state *D, uint32_t a, wk_point X, double te, double eps_c) {
    const df_vertex *A = &D->v[a];
    const wk_offset_line *L = &D->L[A->eout];
    wk_point pa = df_pos(A, te), pb = df_pos(&D->v[A->next], te);
    double s = (X.x - pa.x) * L->ux + (X.y - pa.y) * L->uy;
    double len = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
    return s < -eps_c || s > len + eps_c;
}

/* x is an end of a piece cut at event point k that passed_by keeps apart. */
static bool end_passed_by(const df_state *D, uint32_t x, uint32_t k, double te) {
    struct df_resolve_scratch *S = D->rs;
    for (uint32_t i = 0; i < S->n_split; i += 2) {
        uint32_t a = S->split[i];
        if (find(S, S->split[i + 1]) != find(S, k)) continue;
        if ((a == x && passed_by(D, a, 0, te)) || (D->v[a].next == x && passed_by(D, a, 1, te)))
            return true;
    }
    return false;
}

/* Where event E happens at te. */
static wk_point event_point(const df_state *D, const df_event *E, double te) {
    if (E->at_x) return E->x;
    if (E->kind == DF_COLLAPSE) return collapse_point(&D->v[E->a], &D->v[D->v[E->a].next], te);
    return df_pos(&D->v[E->a], te);
}

/* True if penetration E, at X, lands outside its piece b -> next(b) (beyond
** an end by more than rounding, WK_BEHIND_ULPS ulps of X): its vertex meets
** that end only within the contact distance, the echo of what the end does
** there (the engine's split_misses_piece). */
static bool penetration_misses_piece(const df_state *D, const df_event *E, wk_point X, double te) {
    const df_vertex *A = &D->v[E->b];
    const wk_offset_line *L = &D->L[A->eout];
    wk_point pa = df_pos(A, te), pb = df_pos(&D->v[A->next], te);
    double sa = (X.x - pa.x) * L->ux + (X.y - pa.y) * L->uy;
    double sb = (pb.x - X.x) * L->ux + (pb.y - X.y) * L->uy;
    double ulp = DBL_EPSILON * (fabs(X.x) + fabs(X.y));
    return sa < -WK_BEHIND_ULPS * ulp || sb < -WK_BEHIND_ULPS * ulp;
}

/* Shield x from event point k if the stretch of line e joining x to the new
** vertex at q (velocity of lines ein, eout) collapses later (step 0). */
static wk_status shield_slow_stretch(df_state *D, uint32_t k, wk_point q, uint32_t x, uint32_t e,
                                     uint32_t ein, uint32_t eout, bool x_after, double te,
                                     double eps_c) {
    struct df_resolve_scratch *S = D->rs;
    const df_vertex *X = &D->v[x];
    wk_point vy, px = df_pos(X, te);
    /* farther than this, x joins no point near q: the list stays short */
    if (!X->alive || dist2(px, q) > 4 * eps_c * eps_c) return WK_OK;
    /* The vertex beyond x within the contact distance too: a run of
    ** vertices gathers at the point (a regular polygon vanishing at its
    ** centre), each with its own event there, where the engine's node has
    ** more than one seed and keeps the tolerance picture.  Deforming's
    ** group holds only the events found first: shielded, the 64-gon
    ** perturbed by 1e-12 (tests/data/degenerate/reg64_eps.wpoly) kept
    ** vertices 1 and 4 alive, 4e-13 from the point, once the three lines
    ** came from the input points (predict.c) and went to the reference. */
    uint32_t beyond = x_after ? X->next : X->prev;
    if (dist2(df_pos(&D->v[beyond], te), q) <= eps_c * eps_c) return WK_OK;
    if (wk_vertex_velocity(&D->L[ein], &D->L[eout], &vy) != WK_VEL_REGULAR) return WK_OK;
    if (!wk_stretch_collapses_later(&D->L[e], q, vy, px, X->v, x_after, D->eps_t)) return WK_OK;
    if (WK_GROW(D->R, S->shield, S->cap_shield, S->n_sh + 2) != WK_OK) return D->R->err.code;
    S->shield[S->n_sh++] = x;
    S->shield[S->n_sh++] = k;
    return WK_OK;
}

/* True if vertex p has a penetration in the group of each piece that ends
** at x (x -> next(x) and prev(x) -> x): p meets x itself, vertex on
** vertex, whatever the stretch between them does (see plan_slow_stretches). */
static bool meets_both_pieces_at(const df_state *D, uint32_t p, uint32_t x) {
    bool before = false, after = false;
    for (uint32_t i = 0; i < D->n_ev; i++) {
        const df_event *E = &D->ev[i];
        if (E->kind != DF_PENETRATION || E->a != p) continue;
        after |= E->b == x;
        before |= D->v[E->b].next == x;
    }
    return before && after;
}

/* Step 0, slow stretches: the engine's rule (plan_slow_stretches in
** engine/wavefront_group.c; see there).  At an event point with one seed
** (events that land outside their piece, echoes, not counted) a vertex x
** joined to the seed's new vertex by a stretch of an offset line (a
** neighbour of the seed along the seed's line, or an end of the piece it
** penetrates) is within the contact distance of the point only; it arrives
** there only if that stretch collapses within eps_t
** (wk_stretch_collapses_later), else it is shielded: it is no member of
** the point and its echo there is dropped, and the stretch's collapse is a
** later event.  Taken at once, the comb 0.004 across at 1e6
** (tests/data/degenerate/comb_far_slow_stretch.wpoly: the end of a
** tooth's wall 4.96e-12 from the split, eps_d 5.07e-12, the stretch of
** edge 7 shrinking at 3e-8) lost face 7 between edges 4 and 8 and put the
** node of faces 0, 4, 8 2% of the diagonal from where naive and CGAL put
** theirs.  As in the engine, coarser retries keep the tolerance picture. */
static wk_status plan_slow_stretches(df_state *D, double te, double eps_c) {
    struct df_resolve_scratch *S = D->rs;
    wk_run *R = D->R;
    if (WK_GROW(R, S->ek, S->cap_ek, D->n_ev + 1) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < D->n_ev; i++) {
        const df_event *E = &D->ev[i];
        wk_point X = event_point(D, E, te);
        uint32_t k = 0;
        if (point_at(D, X, eps_c, &k) != WK_OK) return R->err.code;
        bool echo = E->kind == DF_PENETRATION && penetration_misses_piece(D, E, X, te);
        S->ek[i] = k | (echo ? DF_ECHO_BIT : 0);
    }
    if (R->opt.tol_scale > 1) return WK_OK;
    if (WK_GROW(R, S->cseeds, S->cap_cseeds, S->n_cl + 1) != WK_OK) return R->err.code;
    for (uint32_t k = 0; k < S->n_cl; k++) S->cseeds[k] = 0;
    for (uint32_t i = 0; i < D->n_ev; i++)
        if (!(S->ek[i] & DF_ECHO_BIT)) S->cseeds[S->ek[i]]++;
    for (uint32_t i = 0; i < D->n_ev; i++) {
        const df_event *E = &D->ev[i];
        uint32_t k = S->ek[i];
        if ((k & DF_ECHO_BIT) || S->cseeds[k] != 1 || E->kind == DF_MERGE) continue;
        const df_vertex *V = &D->v[E->a];
        wk_point q = event_point(D, E, te);
        wk_status st;
        if (E->kind == DF_COLLAPSE) {
            /* the piece s -> b collapses: the new vertex sits between
            ** s.ein and b.eout, s.prev comes to it along s.ein and b.next
            ** leaves it along b.eout */
            uint32_t b = V->next, xp = V->prev, xn = D->v[b].next;
            uint32_t ein = V->ein, eout = D->v[b].eout;
            if (xp == b || xn == E->a || xp == xn) continue; /* a triangle collapses whole */
            if ((st = shield_slow_stretch(D, k, q, xp, ein, ein, eout, false, te, eps_c)) != WK_OK ||
                (st = shield_slow_stretch(D, k, q, xn, eout, ein, eout, true, te, eps_c)) != WK_OK)
                return st;
        } else {
            /* s cuts the piece a -> b of line l: a -> (l, s.eout) -> s.next
            ** and s.prev -> (s.ein, l) -> b */
            uint32_t a = E->b, b = D->v[a].next, l = D->v[a].eout;
            /* An end of the piece that the vertex also penetrates the other
            ** piece of (the echo at that end) is met head-on: a needle's tip
            ** (speed 1e6, eps_d 1e-3) reaching a convex vertex 5e-6 from
            ** the point of its penetration of the vertex's one piece and an
            ** echo at the other; shielded, that vertex stayed alive beside
            ** the point, its pieces' parts 4.7e-6 long sorted by direction,
            ** and two pieces left the point side by side (the reference;
            ** tests/data/fuzz/needle_vertex_beyond_edge.wpoly, session
            ** deform11). */
            bool head_a = meets_both_pieces_at(D, E->a, a), head_b = meets_both_pieces_at(D, E->a, b);
            if ((!head_a && (st = shield_slow_stretch(D, k, q, a, l, l, V->eout, false, te, eps_c)) != WK_OK) ||
                (st = shield_slow_stretch(D, k, q, V->next, V->eout, l, V->eout, true, te, eps_c)) !=
                    WK_OK ||
                (!head_b && (st = shield_slow_stretch(D, k, q, b, l, V->ein, l, true, te, eps_c)) != WK_OK) ||
                (st = shield_slow_stretch(D, k, q, V->prev, V->ein, V->ein, l, false, te, eps_c)) !=
                    WK_OK)
                return st;
        }
    }
    return WK_OK;
}

/* Collapse i shares an end with a collapse j of the group that happens
** strictly earlier at a point beyond the contact distance of i's (see
** resolve, step 1). */
static bool superseded_collapse(const df_state *D, uint32_t i, double te, double eps_c) {
    const df_event *E = &D->ev[i];
    uint32_t a = E->a, b = D->v[a].next;
    wk_point X = event_point(D, E, te);
    for (uint32_t j = 0; j < D->n_ev; j++) {
        const df_event *F = &D->ev[j];
        if (j == i || F->kind != DF_COLLAPSE) continue;
        uint32_t fa = F->a, fb = D->v[fa].next;
        if (fa != a && fa != b && fb != a && fb != b) continue;
        wk_point Y = event_point(D, F, te);
        if (dist2(Y, X) <= eps_c * eps_c) continue;
        /* Within eps_t the shared end's two contacts are ordered by where
        ** they lie along its path, not by their times: at ~1e11 the times
        ** are off by more than the gap between them.  The glyph 'a' turned
        ** and moved to 1e6 (DejaVuSans_normal_c97_1): vertex 165, between
        ** lines 57 and 59 at 3.3e11, reaches vertex 57 (slow) before its
        ** other end, 6.2 units on, yet the computed times put the farther
        ** collapse first by 4.5e-11; taken by time, it ended at the farther
        ** point and left 57's piece behind (validate (f), the reference). */
        bool earlier = F->t < E->t;
        if (fabs(F->t - E->t) <= D->eps_t) {
            const df_vertex *V = &D->v[(fa == a || fa == b) ? fa : fb];
            double d = (Y.x - X.x) * V->v.x + (Y.y - X.y) * V->v.y;
            earlier = d < 0 || (d == 0 && F->t < E->t);
        }
        if (earlier) return true;
    }
    return false;
}

/* Vertex x is within the contact distance of X at te, or within what it
** covers in the group's span after te (see "neighbours within reach"). */
static bool within_reach(const df_state *D, uint32_t x, wk_point X, double te, double eps_c,
                         double span) {
    const df_vertex *V = &D->v[x];
    double r = eps_c + (fabs(V->v.x) + fabs(V->v.y)) * span;
    return dist2(df_pos(V, te), X) <= r * r;
}

static wk_status resolve(df_state *D, double te) {
    struct df_resolve_scratch *S = D->rs;
    wk_run *R = D->R;
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    /* 0. event points, slow stretches */
    if (plan_slow_stretches(D, te, eps_c) != WK_OK) return R->err.code;
    /* 1. members */
    for (uint32_t i = 0; i < D->n_ev; i++) {
        const df_event *E = &D->ev[i];
        uint32_t k = S->ek[i] & ~DF_ECHO_BIT;
        /* an echo of a shielded vertex takes no part */
        if ((S->ek[i] & DF_ECHO_BIT) && S->n_sh && shielded(S, E->a, k)) continue;
        if (E->kind == DF_COLLAPSE) {
            uint32_t a = E->a, b = D->v[a].next;
            wk_point X = event_point(D, E, te);
            /* A collapse that shares an end with an earlier collapse of the
            ** group at another point (beyond the contact distance) collapses
            ** nothing: that end is a fast vertex between nearly antiparallel
            ** lines, whose meeting point races along them at ~1/sin, and it
            ** ends at the earlier point, where its line leaves this part of
            ** the wavefront; this piece's other end arrives later.  A
            ** glyph's stroke 8.1 wide, its sides 1e-11 rad from antiparallel
            ** (turned and moved to 1e6: coordinates rounded to 1e-10),
            ** collapsed along its length at t = 4.0547; its fast vertex's two
            ** pieces "collapsed" 1e-12 apart at points 0.32 apart, the
            ** vertex at both made them one node, and the slow end of the
            ** later piece came into it 0.009 off its lines (validate (c),
            ** the reference; tests/data/holes/deform_glyph_moved_fast_collapse.wpoly). */
            if (superseded_collapse(D, i, te, eps_c)) continue;
            if (add_member(D, a, k) != WK_OK || add_member(D, b, k) != WK_OK)
                return R->err.code;
            wk_notify_event(R, WK_VC_edge_swaps, &(wk_event){te, X.x + D->o.x, X.y + D->o.y, a, b, WK_NONE});
        } else {
            wk_point X = event_point(D, E, te);
            uint32_t end =
                E->kind == DF_PENETRATION ? shared_end(D, E->a, E->b, te, eps_c) : WK_NONE;
            if (add_member(D, E->a, k) != WK_OK ||
                (end != WK_NONE && add_member(D, end, k) != WK_OK))
                return R->err.code;
            /* A penetration whose point lies beyond its piece by more than
            ** the contact distance, by a vertex that ends at another event
            ** of the group anyway, cuts nothing: its vertex meets the
            ** piece's line only later (within eps_t: a fast vertex moves
            ** far in it), where the piece no longer is.  Cut there (the cut
            ** clamped to the piece's end), the piece got rays from a point
            ** it does not reach: in the turned H with needles a reflex
            ** vertex of speed 1e6, ending where its own piece collapses,
            ** "penetrated" a piece 1.2 units beyond that piece's end
            ** 1e-6 later, and two pieces left the point side by side (the
            ** reference; tests/data/degenerate/arr_headon_turned_needles.wpoly).
            ** A vertex with no other event keeps its cut (the vertex
            ** between lines 0.0014 rad apart that was 12 units from its
            ** three-line point, mono_snap_*.wpoly, no longer takes that
            ** point: predict.c, test_penetration). */
            if (E->kind == DF_PENETRATION && outside_piece(D, E->b, X, te, eps_c) &&
                ends_elsewhere(D, i))
                continue;
            S->ckind[k] |= E->kind == DF_MERGE ? DF_POINT_MERGE : DF_POINT_SPLIT;
            if (WK_GROW(R, S->split, S->cap_split, S->n_split + 2) != WK_OK) return R->err.code;
            S->split[S->n_split++] = E->b;
            S->split[S->n_split++] = k;
            wk_notify_event(R, E->kind == DF_MERGE ? WK_VC_merges : WK_VC_penetrations,
                            &(wk_event){te, X.x + D->o.x, X.y + D->o.y, E->a, E->b, WK_NONE});
        }
    }
    /* ends of cut pieces at the point, and neighbours within reach: the
    ** contact distance plus what the vertex covers in the group's span
    ** (te .. its latest event), as the engine's arrivals (plan_arrivals):
    ** a fast vertex that near arrives in the same instant.  The tip of a
    ** spike 4e9 long (speed 2.1e8) was 133 units (eps_d 4) from the point
    ** where its base closed, which it reaches 6.3e-7 later, within the
    ** group's span of 6.7e-7; left out, the spike's two sides left the point
    ** side by side (WK_EALGO, the reference: stress s1-c00203-regular_4e9,
    ** tests/data/degenerate/deform_spike_tip_arrives.wpoly). */
    double span = 0;
    for (uint32_t i = 0; i < D->n_ev; i++)
        if (D->ev[i].t - te > span) span = D->ev[i].t - te;
    for (int round = 0; round < 2; round++) {
        for (uint32_t i = 0; i < S->n_split; i += 2) {
            uint32_t a = S->split[i], k = find(S, S->split[i + 1]);
            uint32_t ends[2] = {a, D->v[a].next};
            for (int j = 0; j < 2; j++)
                if (D->member[ends[j]] == WK_NONE && within_reach(D, ends[j], S->cx[k], te, eps_c, span) &&
                    !passed_by(D, a, j, te) &&
                    add_member(D, ends[j], k) != WK_OK)
                    return R->err.code;
        }
        for (uint32_t i = 0; i < S->n_m; i++) {
            uint32_t v = S->mlist[i], k = find(S, D->member[v]);
            uint32_t nb[2] = {D->v[v].prev, D->v[v].next};
            for (int j = 0; j < 2; j++)
                if (D->member[nb[j]] == WK_NONE && within_reach(D, nb[j], S->cx[k], te, eps_c, span) &&
                    add_member(D, nb[j], k) != WK_OK)
                    return R->err.code;
        }
    }
    /* Arrivals, as the engine's (plan_arrivals: every vertex of the
    ** touched cycles within tolerance of a node arrives there): any alive
    ** vertex within reach of an event point (the candidates: the paths in
    ** the window's grid near it) is a member, not only the events'
    ** vertices and their neighbours.  In a cross whose arms are 1 wide,
    ** a nearly straight vertex (2.4e-11 off its edge) turns an arm's side
    ** by 2.4e-11, and three of the four reflex vertices meet at the centre
    ** 2e-11 (5 eps_t) before the fourth, which is then 2.8e-11 (0.007
    ** eps_d) from the point but no neighbour of a member: left alive, its
    ** pieces passed through the point, a new vertex there ran along the
    ** wrong pair of edges and a node came out at t = 1.5 where the cross
    ** vanishes at 0.5 (the validator, the reference; stress
    ** s1-c01693-nearly_straight,
    ** tests/data/degenerate/deform_cross_late_reflex_arrives.wpoly).
    ** Not the vertices born at te (they came out of an event point
    ** resolved at this time: their events are the predictor's), nor an
    ** end of a cut piece that passed_by keeps apart (holes nearly
    ** touching, as in the loop above); shields hold (add_member). */
    for (uint32_t k = 0; k < S->n_cl; k++) {
        if (find(S, k) != k) continue;
        if (df_vertices_near(D, S->cx[k], eps_c) != WK_OK) return R->err.code;
        for (uint32_t i = 0; i < D->n_near; i++) {
            uint32_t x = D->near[i];
            if (D->member[x] != WK_NONE || D->v[x].t0 == te ||
                !within_reach(D, x, S->cx[k], te, eps_c, span) || end_passed_by(D, x, k, te))
                continue;
            if (add_member(D, x, k) != WK_OK) return R->err.code;
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
    for (uint32_t i = 0; i < S->n_r; i++)
        if (S->rays[i].far_ray != WK_NONE) S->rays[i].far_k = S->rays[S->rays[i].far_ray].k;
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
    ** offsets just before te (ray_cmp), as exactly parallel ones do.  So
    ** are two rays that run to the same event point within WK_CANCEL_SIN
    ** (the engine's bar for opposite pieces that cancel between two
    ** nodes): both lie along the one segment between the two points, a
    ** sliver closing, whatever their lines' directions.  A rectilinear
    ** polygon turned in doubles 1e6 from the origin (edges 1e-3 long,
    ** coordinates rounded to 1.2e-10) has antiparallel edges 1.1e-8 apart
    ** in direction; their pieces met along a stretch 1e-10 long between
    ** two points, and sorted by their lines' angles an out-ray and an
    ** in-ray there swapped: two pieces left a point side by side (the
    ** reference; stress s1-c00541-far,
    ** tests/data/degenerate/deform_far_sliver_between_points.wpoly). */
    bool runs = false;
    for (uint32_t i = 1; i < S->n_r; i++) {
        uint32_t j = i;
        while (j < S->n_r && S->rays[j].k == S->rays[i - 1].k &&
               (S->rays[j].angle - S->rays[i - 1].angle <= WK_PARALLEL_SIN ||
                (same_far_end(&S->rays[j], &S->rays[i - 1]) &&
                 S->rays[j].angle - S->rays[i - 1].angle <= WK_CANCEL_SIN))) {
            runs |= S->rays[j].angle != S->rays[i - 1].angle;
            S->rays[j].angle = S->rays[i - 1].angle;
            j++;
        }
        if (j > i) i = j - 1;
    }
    if (runs) qsort(S->rays, S->n_r, sizeof *S->rays, ray_cmp);
    if (place_slivers(D, te)) qsort(S->rays, S->n_r, sizeof *S->rays, ray_cmp);
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
    if (df_scratch(D) != WK_OK) return D->R->err.code;
    struct df_resolve_scratch *S = D->rs;
    S->n_cl = S->n_m = S->n_split = S->n_p = S->n_r = S->n_f = S->n_sh = 0;
    wk_status st = resolve(D, te);
    /* reset the per-vertex scratch that this call touched */
    for (uint32_t i = 0; i < S->n_m; i++) D->member[S->mlist[i]] = WK_NONE;
    for (uint32_t i = 0; i < S->n_p; i++) D->mark[S->pieces[i]] = 0;
    return st;
}
