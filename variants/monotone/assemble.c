/*
** assemble.c: the final skeleton from the two chain skeletons and M'
** (001 Theorem 8: north of M' the polygon's roof is the upper chain's, south
** of it the lower chain's, and M' itself is made of ridges).
**
** Each trace of a chain is cut at the points where M' crossed it (merge.c
** recorded them with their distance along the trace), and each piece is kept
** iff it lies on its chain's side of M'.  The side is decided locally:
**   - a piece that starts where M' crossed the trace's interior is not kept:
**     M' passed from one of the trace's faces to the other there, so the
**     trace changes sides, and the piece before must have been kept (else
**     the merge is not certified, below);
**   - a piece that starts at a chain node inherits the side from the traces
**     that ended there (input vertices are on their own side), or, if M'
**     passes through that node (merge node m), it is kept iff its direction
**     lies strictly inside m's sector on the chain's side: for the upper
**     chain counter-clockwise from M''s outgoing direction to its reversed
**     incoming one, for the lower chain the other way round; a piece along
**     M' itself is not kept (M''s arc stands for it).
** Traces are created in time order, so every start node is decided before
** the traces leaving it are cut.  Nodes and arcs the pieces need are
** created on demand; then M''s arcs; then pass-through nodes are merged and
** cheap sanity checks run (tree count, both faces of every arc at the right
** distance from both ends), so a failure of the local decisions shows as
** WK_EALGO, never as a wrong skeleton.
*/
#include "monotone.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.283185307179586476925286766559

enum { ST_UNKNOWN = 0, ST_KEPT, ST_CUT };

static int cmp_cross(const void *a, const void *b) {
    const mono_cross *x = a, *y = b;
    if (x->chain != y->chain) return x->chain < y->chain ? -1 : 1;
    if (x->trace != y->trace) return x->trace < y->trace ? -1 : 1;
    if (x->mu != y->mu) return x->mu < y->mu ? -1 : 1;
    return x->mnode < y->mnode ? -1 : x->mnode > y->mnode;
}

static double ccw_angle(wk_point a, wk_point b) {
    double ang = atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    if (ang < 0) ang += TWO_PI;
    return ang;
}

/* Is direction D strictly on chain c's side of M' at merge node m? */
static bool on_side(const mono *M, uint32_t c, uint32_t m, wk_point D) {
    const mono_mnode *N = &M->mn[m];
    wk_point in = N->has_in ? N->in_dir : (wk_point){M->d.x, M->d.y};
    wk_point out = N->has_out ? N->out_dir : (wk_point){M->d.x, M->d.y};
    wk_point back = {-in.x, -in.y};
    /* strictly: by more than the engine's parallel bar (an angle this small
    ** is its sine), so a piece along M' is not on either side */
    const double margin = WK_PARALLEL_SIN;
    if (c == 1) {
        double lim = ccw_angle(out, back), a = ccw_angle(out, D);
        return a > margin && a < lim - margin;
    }
    double lim = ccw_angle(back, out), a = ccw_angle(back, D);
    return a > margin && a < lim - margin;
}

typedef struct asm_ctx {
    mono *M;
    wk_skeleton *S;
    uint32_t *sk[2];     /* chain node -> skeleton node (WK_NONE: not yet) */
    uint32_t *on[2];     /* chain node -> merge node through it, or WK_NONE */
    uint8_t *st[2];      /* chain node side status */
} asm_ctx;

static uint32_t chain_node_sk(asm_ctx *A, uint32_t c, uint32_t node) {
    mono *M = A->M;
    if (A->on[c][node] != WK_NONE) return M->mn[A->on[c][node]].sk;
    if (A->sk[c][node] == WK_NONE) {
        const mono_node *N = &M->ch[c].node[node];
        if (N->input != WK_NONE) {
            A->sk[c][node] = N->input;
        } else {
            uint32_t id;
            if (wk_skeleton_add_node(M->R, A->S, N->p.x + M->o.x, N->p.y + M->o.y, N->t, &id) !=
                WK_OK)
                return WK_NONE;
            A->sk[c][node] = id;
        }
    }
    return A->sk[c][node];
}

/* Cut chain c's traces at their crossings and emit the kept pieces. */
static wk_status clip_chain(asm_ctx *A, uint32_t c, uint32_t *ci) {
    mono *M = A->M;
    wk_run *R = M->R;
    const mono_chain *C = &M->ch[c];
    for (uint32_t v = 0; v < C->nv; v++) {
        const mono_trace *T = &C->v[v];
        uint32_t c0 = *ci, c1 = c0;
        while (c1 < M->n_cr && M->cr[c1].chain == c && M->cr[c1].trace == v) c1++;
        *ci = c1;
        wk_point D;
        double len;
        wk_point a = C->node[T->start].p;
        if (T->end == WK_NONE) {
            D = T->vel;
            len = INFINITY;
        } else {
            wk_point b = C->node[T->end].p;
            D = (wk_point){b.x - a.x, b.y - a.y};
            len = hypot(D.x, D.y);
        }
        double dl = hypot(D.x, D.y);
        if (dl > 0) D.x /= dl, D.y /= dl;
        /* the side of the first piece */
        uint8_t side;
        uint32_t from;
        if (A->on[c][T->start] != WK_NONE) {
            side = on_side(M, c, A->on[c][T->start], D) ? ST_KEPT : ST_CUT;
        } else {
            side = A->st[c][T->start];
            if (side == ST_UNKNOWN)
                return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                               "monotone: chain %u node %u reached before it was decided", c,
                               T->start);
        }
        from = WK_NONE; /* skeleton id of the current piece's start, lazily */
        bool from_is_start = true;
        for (uint32_t k = c0; k <= c1; k++) {
            bool last = k == c1;
            uint32_t m = last ? WK_NONE : M->cr[k].mnode;
            if (!last && A->on[c][T->start] == m) continue; /* the start itself */
            if (!last && T->end != WK_NONE && A->on[c][T->end] == m) continue; /* the end */
            if (side == ST_KEPT) {
                if (from == WK_NONE)
                    from = from_is_start ? chain_node_sk(A, c, T->start) : WK_NONE;
                uint32_t to;
                if (last) {
                    if (T->end == WK_NONE)
                        return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                                       "monotone: an unbounded trace of chain %u stays on its "
                                       "side of the merge chain",
                                       c);
                    to = chain_node_sk(A, c, T->end);
                } else {
                    to = M->mn[m].sk;
                }
                if (from == WK_NONE || to == WK_NONE) return R->err.code ? R->err.code : WK_EALGO;
                if (from != to && wk_skeleton_add_arc(R, A->S, from, to, T->ein, T->eout) != WK_OK)
                    return R->err.code;
            }
            if (last) break;
            /* A trace that reaches M' from the far side was born in a part
            ** of the chain's wavefront that the polygon's does not have (the
            ** polygon's wavefront lost those pieces where M' crossed them);
            ** with weights it can reach across M' and 001's lower-envelope
            ** argument fails (README.md): give up rather than guess
            ** (monotone.c hands the polygon to the reference). */
            if (side == ST_CUT)
                return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                               "monotone: the chain skeletons do not describe this weighted "
                               "polygon near (%.17g, %.17g): a part of chain %u that the "
                               "polygon's wavefront loses reaches the merge chain (001's "
                               "merge assumes it cannot)",
                               M->mn[m].p.x + M->o.x, M->mn[m].p.y + M->o.y, c);
            /* Past a crossing inside the trace the trace is on the other side
            ** of M': M' crossed it there (it left one of the trace's faces
            ** for the other, and each face lies on one side of the trace),
            ** and the piece before was kept (just checked).  Not decided by
            ** the directions at the merge node: several crossings within
            ** eps_d join one node, so the node is up to eps_d off this
            ** crossing, and where M' and the traces are nearly parallel (the
            ** thin faces between nearly vertical edges of a polygon with
            ** 10^5 and more vertices) a piece's direction from the node then
            ** differs from the true one by more than its angle to M': the
            ** pieces of two traces ending at one node were put on different
            ** sides ("on both sides of the merge chain"), and the polygon
            ** went to the reference wavefront at O(n r) (README.md). */
            side = ST_CUT;
            from = M->mn[m].sk;
            from_is_start = false;
        }
        if (T->end != WK_NONE && A->on[c][T->end] == WK_NONE) {
            uint8_t *s = &A->st[c][T->end];
            if (*s == ST_UNKNOWN) *s = side;
            else if (*s != side)
                return WK_FAIL(R, WK_EALGO, M->P->name, 0,
                               "monotone: chain %u node %u is on both sides of the merge chain",
                               c, T->end);
        }
        (void)len;
    }
    return WK_OK;
}

/* Cheap checks: a tree's count, and every arc's ends at the right distance
** from both its faces' lines. */
static wk_status sanity(mono *M, const wk_skeleton *S) {
    const wk_polygon *P = M->P;
    if (S->n_arcs + 1 != S->n_nodes)
        return WK_FAIL(M->R, WK_EALGO, P->name, 0,
                       "monotone: %u nodes but %u arcs (not a tree)", S->n_nodes, S->n_arcs);
    double tol = WK_VALIDATE_TOL_REL * wk_polygon_scale(P); /* the validator's default */
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *a = &S->arcs[i];
        uint32_t f[2] = {a->left, a->right}, nd[2] = {a->a, a->b};
        for (int j = 0; j < 2; j++)
            for (int k = 0; k < 2; k++) {
                const wk_offset_line *L = &M->L[f[j]];
                const wk_node *q = &S->nodes[nd[k]];
                double err =
                    L->nx * (q->x - M->o.x) + L->ny * (q->y - M->o.y) - L->c - L->w * q->t;
                if (!(fabs(err) <= tol))
                    return WK_FAIL(M->R, WK_EALGO, P->name, 0,
                                   "monotone: arc %u (%u -> %u) is off face %u by %.3g at node %u",
                                   i, a->a, a->b, f[j], fabs(err), nd[k]);
            }
    }
    return WK_OK;
}

wk_status wk_mono_assemble(mono *M, wk_skeleton **out) {
    wk_run *R = M->R;
    asm_ctx A;
    memset(&A, 0, sizeof A);
    A.M = M;
    *out = NULL;
    wk_status st = WK_OK;
    uint32_t nn[2] = {M->ch[0].nn, M->ch[1].nn};
    if ((st = wk_skeleton_new(R, M->P, &A.S)) != WK_OK) goto done;
    for (int c = 0; c < 2; c++) {
        uint32_t k = nn[c] ? nn[c] : 1;
        A.sk[c] = WK_NEW_ARRAY(R, uint32_t, k);
        A.on[c] = WK_NEW_ARRAY(R, uint32_t, k);
        A.st[c] = WK_NEW_ARRAY(R, uint8_t, k);
        if (!A.sk[c] || !A.on[c] || !A.st[c]) {
            st = R->err.code;
            goto done;
        }
        for (uint32_t i = 0; i < nn[c]; i++) {
            A.sk[c][i] = A.on[c][i] = WK_NONE;
            A.st[c][i] = M->ch[c].node[i].input != WK_NONE ? ST_KEPT : ST_UNKNOWN;
        }
    }
    /* merge nodes (v_w and v_e are input vertices already) */
    for (uint32_t i = 0; i < M->n_mn; i++) {
        mono_mnode *N = &M->mn[i];
        if (N->sk != WK_NONE) continue;
        if ((st = wk_skeleton_add_node(R, A.S, N->p.x + M->o.x, N->p.y + M->o.y, N->t, &N->sk)) !=
            WK_OK)
            goto done;
    }
    /* crossings at a trace's ends put M' through that chain node */
    for (uint32_t i = 0; i < M->n_cr; i++) {
        const mono_cross *x = &M->cr[i];
        const mono_chain *C = &M->ch[x->chain];
        const mono_trace *T = &C->v[x->trace];
        if (x->mu <= M->eps_d) A.on[x->chain][T->start] = x->mnode;
        if (T->end != WK_NONE) {
            wk_point a = C->node[T->start].p, b = C->node[T->end].p;
            if (x->mu >= hypot(b.x - a.x, b.y - a.y) - M->eps_d) A.on[x->chain][T->end] = x->mnode;
        }
    }
    if (M->n_cr > 1) qsort(M->cr, M->n_cr, sizeof *M->cr, cmp_cross);
    uint32_t ci = 0;
    for (uint32_t c = 0; c < 2; c++)
        if ((st = clip_chain(&A, c, &ci)) != WK_OK) goto done;
    for (uint32_t i = 0; i < M->n_ma; i++) {
        const mono_marc *a = &M->ma[i];
        if ((st = wk_skeleton_add_arc(R, A.S, M->mn[a->a].sk, M->mn[a->b].sk, a->left, a->right)) !=
            WK_OK)
            goto done;
    }
    if ((st = wk_skeleton_merge_pass_through(R, A.S)) != WK_OK) goto done;
    st = sanity(M, A.S);
done:
    for (int c = 0; c < 2; c++) {
        uint32_t k = nn[c] ? nn[c] : 1;
        if (A.sk[c]) WK_FREE_ARRAY(R, A.sk[c], k);
        if (A.on[c]) WK_FREE_ARRAY(R, A.on[c], k);
        if (A.st[c]) WK_FREE_ARRAY(R, A.st[c], k);
    }
    if (st != WK_OK) {
        wk_skeleton_free(R, A.S);
        return st;
    }
    *out = A.S;
    return WK_OK;
}
