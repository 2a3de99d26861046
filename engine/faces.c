/*
** faces.c: face cycles of a skeleton, arc classification and the inverse of
** the input numbering (definitions in faces.h).
**
** Walking one face.  The k arcs labelled e give k half-arcs (from, to), each
** oriented with the face on its left.  Sorted by `from`, two half-arcs
** leaving the same node mean the face branches there.  The walk starts at
** node e+1 and follows the unique half-arc leaving the current node (binary
** search) until it reaches node e.  Each half-arc may be used once: using one
** twice means the walk circles without reaching e.  When the walk ends, all k
** half-arcs must have been used, else some arc labelled e is off the face's
** boundary.  A successful walk thus yields exactly k + 1 cycle nodes, which
** is what the bulk builder reserves per face.
**
** All ids in messages are stored ids (see wk_polygon_input_edge for the
** input numbering, which differs when the input was clockwise).
*/
#include "faces.h"

#include <stdlib.h>
#include <string.h>

/* One arc seen from one of its faces: walked from -> to, face on the left. */
typedef struct half {
    uint32_t from, to;
    uint32_t arc;   /* index in S->arcs, for messages */
    uint32_t used;  /* set once the walk has taken it */
} half;

/* Total order (from, arc), so equal `from`s end up adjacent and the first
** branch reported does not depend on qsort's internals. */
static int half_cmp(const void *pa, const void *pb) {
    const half *a = pa, *b = pb;
    if (a->from != b->from) return a->from < b->from ? -1 : 1;
    return (a->arc > b->arc) - (a->arc < b->arc);
}

static uint32_t find_from(const half *h, uint32_t k, uint32_t v) {
    uint32_t lo = 0, hi = k;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (h[mid].from < v) lo = mid + 1;
        else hi = mid;
    }
    return lo < k && h[lo].from == v ? lo : WK_NONE;
}

static half make_half(const wk_skeleton *S, uint32_t i, uint32_t e) {
    const wk_arc *c = &S->arcs[i];
    return c->left == e ? (half){c->a, c->b, i, 0} : (half){c->b, c->a, i, 0};
}

static wk_status check_arc(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t i,
                           const char *what) {
    const wk_arc *c = &S->arcs[i];
    if (c->a >= S->n_nodes || c->b >= S->n_nodes)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "%sarc %u [%u, %u, %u, %u] refers to a node beyond the %u nodes", what, i,
                       c->a, c->b, c->left, c->right, S->n_nodes);
    if (c->a == c->b)
        return WK_FAIL(R, WK_EINVALID, P->name, 0, "%sarc %u [%u, %u, %u, %u] is a loop", what, i,
                       c->a, c->b, c->left, c->right);
    if (c->left >= P->n || c->right >= P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "%sarc %u [%u, %u, %u, %u] names a face beyond the %u edges", what, i, c->a,
                       c->b, c->left, c->right, P->n);
    if (c->left == c->right)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "%sarc %u [%u, %u, %u, %u] has the same face on both sides", what, i, c->a,
                       c->b, c->left, c->right);
    return WK_OK;
}

static wk_status check_sizes(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                             const char *what) {
    if (S->n_input != P->n || S->n_nodes < P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "%sthe skeleton has %u input nodes and %u nodes for a polygon of %u "
                       "vertices",
                       what, S->n_input, S->n_nodes, P->n);
    return WK_OK;
}

wk_status wk_faces_check_ids(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                             const char *what) {
    if (check_sizes(R, P, S, what) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < S->n_arcs; i++)
        if (check_arc(R, P, S, i, what) != WK_OK) return R->err.code;
    return WK_OK;
}

/* Walk face e over its k half-arcs h (sorted here, in place) and write its
** cycle into cyc, which has room for k + 1 nodes. */
static wk_status walk_face(wk_run *R, const wk_polygon *P, uint32_t e, half *h, uint32_t k,
                           uint32_t *cyc, uint32_t *len, const char *what) {
    uint32_t first = wk_polygon_next(P, e);
    if (k > 1) qsort(h, k, sizeof *h, half_cmp);
    for (uint32_t i = 1; i < k; i++)
        if (h[i].from == h[i - 1].from)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "%sface of edge %u branches at node %u: arcs %u and %u both leave it "
                           "with the face on their left",
                           what, e, h[i].from, h[i - 1].arc, h[i].arc);
    uint32_t steps = 0, cur = first;
    cyc[0] = e;
    if (k > 0) cyc[1] = first; /* k == 0 stops at once: no arc leaves first */
    for (;;) {
        uint32_t j = find_from(h, k, cur);
        if (j == WK_NONE)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "%sface of edge %u: its path of arcs from node %u to node %u stops at "
                           "node %u (no arc labelled %u leaves it with the face on its left)",
                           what, e, first, e, cur, e);
        if (h[j].used)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "%sface of edge %u: its path of arcs from node %u circles through node "
                           "%u and never returns to node %u",
                           what, e, first, cur, e);
        h[j].used = 1;
        steps++;
        cur = h[j].to;
        if (cur == e) break;
        /* After k steps every half-arc is used, so the next lookup reports. */
        if (steps < k) cyc[steps + 1] = cur;
    }
    if (steps < k)
        for (uint32_t i = 0; i < k; i++)
            if (!h[i].used)
                return WK_FAIL(R, WK_EINVALID, P->name, 0,
                               "%sface of edge %u: arc %u labelled %u is not on the path from "
                               "node %u to node %u",
                               what, e, h[i].arc, e, first, e);
    *len = steps + 1;
    return WK_OK;
}

wk_status wk_face_cycle(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t e,
                        uint32_t **cycle, uint32_t *len) {
    *cycle = NULL;
    *len = 0;
    if (check_sizes(R, P, S, "") != WK_OK) return R->err.code;
    if (e >= P->n)
        return WK_FAIL(R, WK_EINVALID, P->name, 0, "no face %u: the polygon has %u edges", e, P->n);
    uint32_t k = 0;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        if (c->left != e && c->right != e) continue;
        if (check_arc(R, P, S, i, "") != WK_OK) return R->err.code;
        k++;
    }
    if (k == 0)
        return WK_FAIL(R, WK_EINVALID, P->name, 0, "face of edge %u: no arc is labelled %u", e, e);
    half *h = WK_NEW_ARRAY(R, half, k);
    uint32_t *cyc = h ? WK_NEW_ARRAY(R, uint32_t, (size_t)k + 1) : NULL;
    if (!cyc) {
        if (h) WK_FREE_ARRAY(R, h, k);
        return R->err.code;
    }
    uint32_t m = 0;
    for (uint32_t i = 0; i < S->n_arcs; i++)
        if (S->arcs[i].left == e || S->arcs[i].right == e) h[m++] = make_half(S, i, e);
    uint32_t got = 0;
    wk_status st = walk_face(R, P, e, h, k, cyc, &got, "");
    WK_FREE_ARRAY(R, h, k);
    if (st != WK_OK) {
        WK_FREE_ARRAY(R, cyc, (size_t)k + 1);
        return st;
    }
    /* got == k + 1 after a successful walk: the allocation size matches the
    ** length the caller frees with. */
    *cycle = cyc;
    *len = got;
    return WK_OK;
}

void wk_faces_clear(wk_run *R, wk_faces *F) {
    if (F->start) {
        WK_FREE_ARRAY(R, F->node, F->start[F->n]);
        WK_FREE_ARRAY(R, F->start, (size_t)F->n + 1);
    }
    F->n = 0;
}

wk_status wk_faces_build(wk_run *R, const wk_polygon *P, const wk_skeleton *S, wk_faces *F,
                         const char *what) {
    memset(F, 0, sizeof *F);
    if (wk_faces_check_ids(R, P, S, what) != WK_OK)
        return R->err.code;
    uint32_t n = P->n, A = S->n_arcs;
    if (A > (UINT32_MAX - n) / 2)
        return WK_FAIL(R, WK_ENOMEM, P->name, 0, "%u arcs: too many faces' nodes to index", A);
    size_t nh = 2 * (size_t)A;
    uint32_t *hs = WK_NEW_ARRAY(R, uint32_t, (size_t)n + 1);
    half *h = hs ? WK_NEW_ARRAY(R, half, nh) : NULL;
    uint32_t *start = h ? WK_NEW_ARRAY(R, uint32_t, (size_t)n + 1) : NULL;
    uint32_t *node = start ? WK_NEW_ARRAY(R, uint32_t, nh + n) : NULL;
    wk_status st = node ? WK_OK : R->err.code;
    if (st != WK_OK) goto done;

    /* Bucket the half-arcs by face: counts, prefix sums, fill (hs[e] then
    ** points one past bucket e), shift back. */
    for (uint32_t i = 0; i < A; i++) {
        hs[S->arcs[i].left + 1]++;
        hs[S->arcs[i].right + 1]++;
    }
    for (uint32_t e = 0; e < n; e++) hs[e + 1] += hs[e];
    for (uint32_t i = 0; i < A; i++) {
        const wk_arc *c = &S->arcs[i];
        h[hs[c->left]++] = make_half(S, i, c->left);
        h[hs[c->right]++] = make_half(S, i, c->right);
    }
    for (uint32_t e = n; e > 0; e--) hs[e] = hs[e - 1];
    hs[0] = 0;

    /* Face e has k = hs[e+1] - hs[e] half-arcs, hence k + 1 cycle nodes. */
    for (uint32_t e = 0; e <= n; e++) start[e] = hs[e] + e;
    for (uint32_t e = 0; e < n && st == WK_OK; e++) {
        uint32_t k = hs[e + 1] - hs[e], got = 0;
        st = walk_face(R, P, e, h + hs[e], k, node + start[e], &got, what);
    }
done:
    if (hs) WK_FREE_ARRAY(R, hs, (size_t)n + 1);
    if (h) WK_FREE_ARRAY(R, h, nh);
    if (st == WK_OK) {
        F->n = n;
        F->start = start;
        F->node = node;
    } else {
        if (node) WK_FREE_ARRAY(R, node, nh + n);
        if (start) WK_FREE_ARRAY(R, start, (size_t)n + 1);
    }
    return st;
}

double wk_cycle_area(const wk_skeleton *S, const uint32_t *cycle, uint32_t len) {
    if (len < 3) return 0.0;
    const wk_node *o = &S->nodes[cycle[0]];
    double s = 0.0;
    for (uint32_t i = 1; i + 1 < len; i++) {
        const wk_node *a = &S->nodes[cycle[i]], *b = &S->nodes[cycle[i + 1]];
        s += (a->x - o->x) * (b->y - o->y) - (a->y - o->y) * (b->x - o->x);
    }
    return 0.5 * s;
}

bool wk_arc_is_reflex(const wk_polygon *P, const wk_skeleton *S, uint32_t i) {
    const wk_arc *c = &S->arcs[i];
    if (c->a >= S->n_nodes || c->b >= S->n_nodes || c->left >= P->n || c->right >= P->n)
        return false;
    double ta = S->nodes[c->a].t, tb = S->nodes[c->b].t;
    if (!(ta != tb)) return false; /* constant time, or NaN */
    uint32_t before = ta < tb ? c->left : c->right, after = ta < tb ? c->right : c->left;
    wk_point p0 = P->p[before], p1 = P->p[wk_polygon_next(P, before)];
    wk_point q0 = P->p[after], q1 = P->p[wk_polygon_next(P, after)];
    double cross = (p1.x - p0.x) * (q1.y - q0.y) - (p1.y - p0.y) * (q1.x - q0.x);
    return cross < 0;
}

wk_status wk_input_order(wk_run *R, const wk_polygon *P, uint32_t **vertex_of,
                         uint32_t **edge_of) {
    uint32_t n = P->n, *v = NULL, *e = NULL;
    if (vertex_of) *vertex_of = NULL;
    if (edge_of) *edge_of = NULL;
    if ((vertex_of && !(v = WK_NEW_ARRAY(R, uint32_t, n))) ||
        (edge_of && !(e = WK_NEW_ARRAY(R, uint32_t, n))))
        goto fail;
    for (uint32_t i = 0; i < n; i++) {
        if (v) v[i] = WK_NONE;
        if (e) e[i] = WK_NONE;
    }
    for (uint32_t j = 0; j < n; j++) {
        uint32_t iv = wk_polygon_output_node(P, j), ie = wk_polygon_input_edge(P, j);
        if ((v && (iv >= n || v[iv] != WK_NONE)) || (e && (ie >= n || e[ie] != WK_NONE))) {
            WK_FAIL(R, WK_EALGO, P->name, 0,
                    "the polygon's input numbering is not a permutation (stored vertex %u)", j);
            goto fail;
        }
        if (v) v[iv] = j;
        if (e) e[ie] = j;
    }
    if (vertex_of) *vertex_of = v;
    if (edge_of) *edge_of = e;
    return WK_OK;
fail:
    if (v) WK_FREE_ARRAY(R, v, n);
    if (e) WK_FREE_ARRAY(R, e, n);
    return R->err.code;
}
