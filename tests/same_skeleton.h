/*
** same_skeleton.h: are two skeletons of one polygon the same skeleton, up to
** a tolerance?  Header-only, plain C (no Criterion): the Criterion tests
** (through helpers.h) and the fuzz target tests/fuzz/fuzz_variants.c share
** it, so the sweeps and the fuzzer apply one oracle.
**
**   sk_match         how nodes are matched (tolerances, translation, merging)
**   same_skeleton()  the verdict, with the first difference as text
**
** Two correct constructions may describe one skeleton differently: a vertex
** event where more than three arcs meet as one node or as several nodes
** joined by zero-length arcs, features below the tolerance merged at
** different places.  In merging mode both are brought to one canonical form
** before the arcs are compared: nodes of either skeleton within the
** tolerance are one node (transitively), and arcs whose ends fall into one
** node are dropped.  Times: a node's time errs by its position's error over
** the weight of its faces (the offset line of edge e moves at speed w(e)),
** so with a polygon given the time tolerance is per node (sk_match.P).
** Allocation failure aborts (test code: the tracked allocator is not used).
*/
#ifndef WK_TEST_SAME_SKELETON_H
#define WK_TEST_SAME_SKELETON_H
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "wskel.h"

/* How same_skeleton matches nodes. */
typedef struct sk_match {
    double tol;    /* nodes within tol in x and in y are the same point */
    double tol_t;  /* ... and within tol_t in t; < 0: times not compared */
    double dx, dy; /* B is A translated by (dx, dy) */
    bool merge;    /* false: one to one (equal node and arc counts, every node
                      paired with one of the other skeleton); true: as
                      scripts/compare_skeletons.py, nodes within tol merged
                      transitively (also within one skeleton) and the
                      zero-length arcs that leaves dropped */
    const wk_polygon *P; /* NULL: tol_t is the time tolerance of every pair.
                      Else A's and B's polygon (the same weights in the same
                      stored order): two nodes' time tolerance is tol_t / w,
                      w the smallest positive weight of the faces at either
                      node (its arcs' left and right edges) */
} sk_match;

typedef struct sk_cnode_ { double x, y, t, w; uint32_t id; } sk_cnode_;
typedef struct sk_carc_ { uint32_t u, v, l, r; } sk_carc_;

static inline int sk_cmp_cnode_(const void *a, const void *b) {
    const sk_cnode_ *p = a, *q = b;
    if (p->x != q->x) return p->x < q->x ? -1 : 1;
    return p->id < q->id ? -1 : p->id > q->id;
}
static inline int sk_cmp_carc_(const void *a, const void *b) {
    const sk_carc_ *p = a, *q = b;
    if (p->u != q->u) return p->u < q->u ? -1 : 1;
    if (p->v != q->v) return p->v < q->v ? -1 : 1;
    if (p->l != q->l) return p->l < q->l ? -1 : 1;
    return p->r < q->r ? -1 : p->r > q->r;
}
static inline uint32_t sk_find_(uint32_t *par, uint32_t x) {
    while (par[x] != x) x = par[x] = par[par[x]];
    return x;
}
static inline void *sk_calloc_(size_t n, size_t size) {
    void *p = calloc(n, size);
    if (!p) {
        fprintf(stderr, "same_skeleton: out of memory\n");
        abort();
    }
    return p;
}

/* The weight of node i's faces (m.P set): the smallest positive weight of
** an edge on either side of one of its arcs; the polygon's smallest
** positive weight for a node without such an arc. */
static inline void sk_node_weights_(const wk_skeleton *S, const wk_polygon *P, sk_cnode_ *c,
                                    uint32_t off) {
    double wmin = INFINITY;
    for (uint32_t e = 0; e < P->n; e++)
        if (P->w[e] > 0) wmin = fmin(wmin, P->w[e]);
    if (!isfinite(wmin)) wmin = 1;
    for (uint32_t i = 0; i < S->n_nodes; i++) c[off + i].w = INFINITY;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *x = &S->arcs[i];
        double w = INFINITY;
        if (x->left < P->n && P->w[x->left] > 0) w = fmin(w, P->w[x->left]);
        if (x->right < P->n && P->w[x->right] > 0) w = fmin(w, P->w[x->right]);
        if (x->a < S->n_nodes) c[off + x->a].w = fmin(c[off + x->a].w, w);
        if (x->b < S->n_nodes) c[off + x->b].w = fmin(c[off + x->b].w, w);
    }
    for (uint32_t i = 0; i < S->n_nodes; i++)
        if (!isfinite(c[off + i].w)) c[off + i].w = wmin;
}

/* Skeletons A and B (of the same polygon, or of polygons m.dx, m.dy apart)
** are the same skeleton:
**   - the same input vertices: node j < n_input of A, moved by (dx, dy), is
**     within tol of node j of B, and the two are one node;
**   - interior nodes within tol (and tol_t, per node with m.P) are one node
**     (a class): one to one, every class holds as many nodes of A as of B
**     (and only interior ones); merging, any nodes within tol join,
**     transitively;
**   - the arcs, as (class, class, left face, right face) with the ends in a
**     fixed order, are the same multiset (merging: without those whose ends
**     fall in one class).
** Returns false with the first difference in why. */
static inline bool same_skeleton(const wk_skeleton *A, const wk_skeleton *B, sk_match m,
                                 char *why, size_t size) {
    uint32_t na = A->n_nodes, nb = B->n_nodes, N = na + nb, n = A->n_input;
    if (A->n_input != B->n_input)
        return snprintf(why, size, "%u vs %u input vertices", A->n_input, B->n_input), false;
    if (!m.merge && (na != nb || A->n_arcs != B->n_arcs))
        return snprintf(why, size, "%u nodes %u arcs vs %u nodes %u arcs", na, A->n_arcs, nb,
                        B->n_arcs),
               false;
    sk_cnode_ *c = sk_calloc_(N + 1, sizeof *c);
    uint32_t *par = sk_calloc_(N + 1, sizeof *par);
    int32_t *cnt = sk_calloc_(N + 1, sizeof *cnt);
    sk_carc_ *aa = sk_calloc_(A->n_arcs + 1, sizeof *aa);
    sk_carc_ *bb = sk_calloc_(B->n_arcs + 1, sizeof *bb);
    bool ok = true;
#define SK_NODE_(i) ((i) < na ? &A->nodes[(i)] : &B->nodes[(i) - na])
    for (uint32_t i = 0; i < N; i++) {
        const wk_node *q = SK_NODE_(i);
        c[i] = i < na ? (sk_cnode_){q->x + m.dx, q->y + m.dy, q->t, 1, i}
                      : (sk_cnode_){q->x, q->y, q->t, 1, i};
        par[i] = i;
    }
    if (m.P) {
        sk_node_weights_(A, m.P, c, 0);
        sk_node_weights_(B, m.P, c, na);
    }
    for (uint32_t j = 0; j < n && ok; j++) {
        const sk_cnode_ *p = &c[j], *q = &c[na + j];
        if (!(fabs(p->x - q->x) <= m.tol && fabs(p->y - q->y) <= m.tol && p->t == q->t)) {
            snprintf(why, size, "input vertex %u: (%.17g, %.17g, t %g) vs (%.17g, %.17g, t %g)", j,
                     p->x, p->y, p->t, q->x, q->y, q->t);
            ok = false;
        }
        par[na + j] = j;
    }
    qsort(c, N, sizeof *c, sk_cmp_cnode_);
    for (uint32_t i = 0; i < N && ok; i++)
        for (uint32_t j = i + 1; j < N && c[j].x - c[i].x <= m.tol; j++) {
            const sk_cnode_ *p = &c[i], *q = &c[j];
            double tol_t = m.P ? m.tol_t / fmin(p->w, q->w) : m.tol_t;
            if (!(fabs(p->y - q->y) <= m.tol) || (m.tol_t >= 0 && !(fabs(p->t - q->t) <= tol_t)))
                continue;
            if (!m.merge) { /* one of A and one of B, both interior */
                bool pa = p->id < na, qa = q->id < na;
                uint32_t pj = pa ? p->id : p->id - na, qj = qa ? q->id : q->id - na;
                if (pa == qa || pj < n || qj < n) continue;
            }
            par[sk_find_(par, p->id)] = sk_find_(par, q->id);
        }
    if (ok && !m.merge) { /* one to one: each class as many nodes of A as of B */
        for (uint32_t i = n; i < na; i++) cnt[sk_find_(par, i)]++;
        for (uint32_t i = na + n; i < N; i++) cnt[sk_find_(par, i)]--;
        for (uint32_t i = n; i < N && ok; i++) {
            if (i >= na && i < na + n) continue; /* B's input vertices */
            int32_t d = cnt[sk_find_(par, i)];
            if (d == 0 || (d > 0) != (i < na)) continue; /* name a node of the surplus side */
            const wk_node *q = SK_NODE_(i);
            snprintf(why, size,
                     "node %u (%.17g, %.17g, t %.17g) of %s has no partner in %s (tol %g, t %g)",
                     i < na ? i : i - na, q->x, q->y, q->t, i < na ? "A" : "B",
                     i < na ? "B" : "A", m.tol, m.tol_t);
            ok = false;
        }
    }
    uint32_t ka = 0, kb = 0;
    for (int s = 0; s < 2 && ok; s++) {
        const wk_skeleton *S = s ? B : A;
        sk_carc_ *out = s ? bb : aa;
        uint32_t *k = s ? &kb : &ka, off = s ? na : 0;
        for (uint32_t i = 0; i < S->n_arcs; i++) {
            const wk_arc *x = &S->arcs[i];
            uint32_t u = sk_find_(par, x->a + off), v = sk_find_(par, x->b + off);
            if (u == v && m.merge) continue;
            out[(*k)++] = u <= v ? (sk_carc_){u, v, x->left, x->right}
                                 : (sk_carc_){v, u, x->right, x->left};
        }
    }
    if (ok) {
        qsort(aa, ka, sizeof *aa, sk_cmp_carc_);
        qsort(bb, kb, sizeof *bb, sk_cmp_carc_);
        uint32_t i = 0, j = 0;
        while (ok && (i < ka || j < kb)) {
            int d = i == ka ? 1 : j == kb ? -1 : sk_cmp_carc_(&aa[i], &bb[j]);
            if (d == 0) {
                i++, j++;
                continue;
            }
            const sk_carc_ *x = d < 0 ? &aa[i] : &bb[j];
            const wk_node *u = SK_NODE_(x->u), *v = SK_NODE_(x->v);
            snprintf(why, size,
                     "an arc of %s has no partner in %s: (%.9g, %.9g, t %.9g) - (%.9g, %.9g, "
                     "t %.9g), faces %u | %u (%u arcs vs %u%s)",
                     d < 0 ? "A" : "B", d < 0 ? "B" : "A", u->x, u->y, u->t, v->x, v->y, v->t,
                     x->l, x->r, ka, kb, m.merge ? " after merging" : "");
            ok = false;
        }
    }
#undef SK_NODE_
    free(c);
    free(par);
    free(cnt);
    free(aa);
    free(bb);
    return ok;
}

#endif
