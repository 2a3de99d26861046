/*
** faces.c: face cycles of a skeleton, arc classification and the inverse of
** the input numbering (definitions in faces.h).
**
** Walking one face.  The k arcs labelled e give k half-arcs (from, to), each
** oriented with the face on its left.  Sorted by `from`, two half-arcs
** leaving the same node mean the face branches there.  The walk starts at
** node next(e) and follows the unique half-arc leaving the current node
** (binary search) until it reaches node e.  Each half-arc may be used once:
** using one twice means the walk circles without reaching e.  When the walk
** ends, every unused half-arc must lie on a closed loop of unused ones (an
** island, possible only with holes: walk_loops, wk_bridge_loop), else some arc
** labelled e is off the face's boundary.  A face without islands thus
** yields exactly k + 1 cycle nodes, each island 2 more (its bridge); the bulk
** builder starts from the sum of k + 1 and grows for islands.
**
** All ids in messages are stored ids (see wk_polygon_input_edge for the
** input numbering, which differs when the input was clockwise).
*/
#include "faces.h"

#include <math.h>
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
    /* a PSLG's cap (the wavefront at its horizon) has no face on its left */
    bool cap = P->pslg && c->left == WK_NONE;
    if ((c->left >= P->n && !cap) || c->right >= P->n)
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

/* Room a face of k half-arcs needs: its k + 1 path nodes, or fewer path
** nodes plus loops of >= 3 half-arcs each, every loop adding 2 bridge
** nodes. */
static uint32_t face_room(uint32_t k) { return k + 1 + 2 * (k / 3); }
/* Scratch for the loops: their nodes (k), starts and done flags (k/3 + 2
** each). */
static uint32_t face_scratch(uint32_t k) { return k + 2 * (k / 3 + 2); }

/* The loops of face e (an island inside the face, weighted skeletons with
** holes): after the main walk, every unused half-arc must lie on a closed
** loop of unused half-arcs.  Loop nodes go to loop[] (room k), their starts
** to ls[] (room k / 3 + 2, ls[m] = end). */
static wk_status walk_loops(wk_run *R, const wk_polygon *P, uint32_t e, half *h, uint32_t k,
                            uint32_t *loop, uint32_t *ls, uint32_t *n_loops, const char *what) {
    uint32_t m = 0, pos = 0;
    for (uint32_t i = 0; i < k; i++) {
        if (h[i].used) continue;
        if (P->n_rings == 1)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "%sface of edge %u: arc %u labelled %u is not on the path from node "
                           "%u to node %u",
                           what, e, h[i].arc, e, wk_polygon_next(P, e), e);
        ls[m] = pos;
        uint32_t start = h[i].from, j = i;
        for (;;) {
            h[j].used = 1;
            loop[pos++] = h[j].from;
            uint32_t cur = h[j].to;
            if (cur == start) break;
            j = find_from(h, k, cur);
            if (j == WK_NONE || h[j].used)
                return WK_FAIL(R, WK_EINVALID, P->name, 0,
                               "%sface of edge %u: arc %u labelled %u is neither on the path from "
                               "node %u to node %u nor on a closed loop (an island) of the face",
                               what, e, h[i].arc, e, wk_polygon_next(P, e), e);
        }
        if (pos - ls[m] < 3)
            return WK_FAIL(R, WK_EINVALID, P->name, 0,
                           "%sface of edge %u: a loop of %u arcs through node %u", what, e,
                           pos - ls[m], start);
        m++;
    }
    ls[m] = pos;
    *n_loops = m;
    return WK_OK;
}

static wk_point node_xy(const wk_skeleton *S, uint32_t v) {
    return (wk_point){S->nodes[v].x, S->nodes[v].y};
}

/* Bridge loop lp[0..L) into the cycle cyc[0..*len) (flags: bridge sides),
** the classic hole-to-outer bridge of ear clipping: from the loop's
** rightmost node q, a ray to +x meets the cycle first at a side; its end of
** larger x, or the cycle vertex inside the triangle (q, hit, that end) with
** the smallest angle to the ray, sees q.  The cycle becomes
** ... u q (loop) q u ..., the two new sides u->q and q->u are flagged.
** Loops are taken by decreasing max x, so the ray meets no loop not yet
** bridged.  Also bridges a cap face's holes (e == WK_NONE, write_obj_capped.c). */
wk_status wk_bridge_loop(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t e,
                         uint32_t *cyc, uint8_t *flag, uint32_t *len, const uint32_t *lp,
                         uint32_t L, const char *what) {
    uint32_t qi = 0;
    for (uint32_t i = 1; i < L; i++) {
        wk_point a = node_xy(S, lp[i]), b = node_xy(S, lp[qi]);
        if (a.x > b.x || (a.x == b.x && a.y > b.y)) qi = i;
    }
    wk_point q = node_xy(S, lp[qi]);
    uint32_t n = *len, best = WK_NONE;
    double bx = INFINITY;
    for (uint32_t i = 0; i < n; i++) {
        wk_point a = node_xy(S, cyc[i]), b = node_xy(S, cyc[i + 1 == n ? 0 : i + 1]);
        if ((a.y > q.y && b.y > q.y) || (a.y < q.y && b.y < q.y)) continue;
        double x;
        if (a.y == b.y) x = fmin(a.x, b.x) >= q.x ? fmin(a.x, b.x) : fmax(a.x, b.x);
        else x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x >= q.x && x < bx) {
            bx = x;
            best = i;
        }
    }
    if (best == WK_NONE && e == WK_NONE)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "%sthe cap: a hole (cycle through node %u) lies outside its cap face's "
                       "outer cycle",
                       what, lp[qi]);
    if (best == WK_NONE)
        return WK_FAIL(R, WK_EINVALID, P->name, 0,
                       "%sface of edge %u: an island (loop through node %u) lies outside the "
                       "face's outer cycle",
                       what, e, lp[qi]);
    uint32_t b1 = best + 1 == n ? 0 : best + 1;
    wk_point hit = {bx, q.y};
    uint32_t u = node_xy(S, cyc[best]).x >= node_xy(S, cyc[b1]).x ? best : b1;
    wk_point pu = node_xy(S, cyc[u]);
    if (!(pu.x == hit.x && pu.y == hit.y)) {
        /* a vertex strictly inside the triangle (q, hit, pu) would block
        ** the view: take the one closest in angle to the ray */
        int turn = wk_orient2d(q, hit, pu, NULL);
        double best_t = INFINITY, best_d = INFINITY;
        for (uint32_t i = 0; i < n; i++) {
            wk_point c = node_xy(S, cyc[i]);
            if (i == u || (c.x == pu.x && c.y == pu.y)) continue;
            if (wk_orient2d(q, hit, c, NULL) != turn || wk_orient2d(hit, pu, c, NULL) != turn ||
                wk_orient2d(pu, q, c, NULL) != turn)
                continue;
            double dx = c.x - q.x, dy = fabs(c.y - q.y), tn = dy / dx, d = dx * dx + dy * dy;
            if (tn < best_t || (tn == best_t && d < best_d)) {
                best_t = tn;
                best_d = d;
                u = i;
            }
        }
    }
    /* ... cyc[u], lp[qi], lp[qi+1], ..., lp[qi-1], lp[qi], cyc[u], cyc[u+1] ... */
    uint32_t add = L + 2;
    memmove(cyc + u + 1 + add, cyc + u + 1, (size_t)(n - u - 1) * sizeof *cyc);
    memmove(flag + u + 1 + add, flag + u + 1, (size_t)(n - u - 1) * sizeof *flag);
    for (uint32_t j = 0; j <= L; j++) {
        cyc[u + 1 + j] = lp[(qi + j) % L];
        flag[u + 1 + j] = 0;
    }
    cyc[u + 2 + L] = cyc[u];
    flag[u + 2 + L] = flag[u]; /* the side u -> old next keeps its flag */
    flag[u] = 1;               /* u -> q */
    flag[u + 1 + L] = 1;       /* q -> u */
    *len = n + add;
    return WK_OK;
}

/* Walk face e over its k half-arcs h (sorted here, in place) and write its
** cycle into cyc (room face_room(k)), with flag[i] set for bridge sides
** (cyc[i] -> cyc[i+1]) when the face has islands.  scratch: room
** face_scratch(k). */
static wk_status walk_face(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t e,
                           half *h, uint32_t k, uint32_t *cyc, uint8_t *flag, uint32_t *scratch,
                           uint32_t *len, uint32_t *n_loops, const char *what) {
    uint32_t first = wk_polygon_next(P, e);
    *n_loops = 0;
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
    *len = steps + 1;
    for (uint32_t i = 0; i < *len; i++) flag[i] = 0;
    if (steps == k) return WK_OK;
    uint32_t *loop = scratch, *ls = scratch + k, *done = ls + (k / 3 + 2), m = 0;
    if (walk_loops(R, P, e, h, k, loop, ls, &m, what) != WK_OK) return R->err.code;
    /* bridge by decreasing max x, a selection: faces with islands are rare
    ** and have few loops */
    for (uint32_t l = 0; l < m; l++) done[l] = 0;
    for (uint32_t round = 0; round < m; round++) {
        uint32_t pick = WK_NONE;
        double px = -INFINITY;
        for (uint32_t l = 0; l < m; l++) {
            double mx = -INFINITY;
            for (uint32_t i = ls[l]; i < ls[l + 1]; i++) mx = fmax(mx, S->nodes[loop[i]].x);
            if (!done[l] && mx > px) {
                px = mx;
                pick = l;
            }
        }
        if (pick == WK_NONE) break; /* defensive: a NaN coordinate; (b) reports it */
        if (wk_bridge_loop(R, P, S, e, cyc, flag, len, loop + ls[pick], ls[pick + 1] - ls[pick],
                        what) != WK_OK)
            return R->err.code;
        done[pick] = 1;
    }
    *n_loops = m;
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
    uint32_t room = face_room(k);
    half *h = WK_NEW_ARRAY(R, half, k);
    uint32_t *cyc = h ? WK_NEW_ARRAY(R, uint32_t, room) : NULL;
    uint8_t *flag = cyc ? WK_NEW_ARRAY(R, uint8_t, room) : NULL;
    uint32_t *scratch = flag ? WK_NEW_ARRAY(R, uint32_t, face_scratch(k)) : NULL;
    wk_status st = scratch ? WK_OK : R->err.code;
    uint32_t got = 0, loops = 0;
    if (st == WK_OK) {
        uint32_t m = 0;
        for (uint32_t i = 0; i < S->n_arcs; i++)
            if (S->arcs[i].left == e || S->arcs[i].right == e) h[m++] = make_half(S, i, e);
        st = walk_face(R, P, S, e, h, k, cyc, flag, scratch, &got, &loops, "");
    }
    uint32_t *out = NULL;
    if (st == WK_OK && !(out = WK_NEW_ARRAY(R, uint32_t, got))) st = R->err.code;
    if (st == WK_OK) memcpy(out, cyc, (size_t)got * sizeof *out);
    if (scratch) WK_FREE_ARRAY(R, scratch, face_scratch(k));
    if (flag) WK_FREE_ARRAY(R, flag, room);
    if (cyc) WK_FREE_ARRAY(R, cyc, room);
    if (h) WK_FREE_ARRAY(R, h, k);
    if (st != WK_OK) return st;
    /* the allocation's size is the length the caller frees with */
    *cycle = out;
    *len = got;
    return WK_OK;
}

void wk_faces_clear(wk_run *R, wk_faces *F) {
    if (F->start) WK_FREE_ARRAY(R, F->start, (size_t)F->n + 1);
    if (F->node) WK_FREE_ARRAY(R, F->node, F->cap_node);
    if (F->bridge) WK_FREE_ARRAY(R, F->bridge, F->cap_bridge);
    memset(F, 0, sizeof *F);
}

wk_status wk_faces_build(wk_run *R, const wk_polygon *P, const wk_skeleton *S, wk_faces *F,
                         const char *what) {
    memset(F, 0, sizeof *F);
    if (wk_faces_check_ids(R, P, S, what) != WK_OK)
        return R->err.code;
    uint32_t n = P->n, A = S->n_arcs;
    if (A > (UINT32_MAX - n) / 4)
        return WK_FAIL(R, WK_ENOMEM, P->name, 0, "%u arcs: too many faces' nodes to index", A);
    size_t nh = 2 * (size_t)A;
    uint32_t *hs = WK_NEW_ARRAY(R, uint32_t, (size_t)n + 1);
    half *h = hs ? WK_NEW_ARRAY(R, half, nh) : NULL;
    uint32_t *start = h ? WK_NEW_ARRAY(R, uint32_t, (size_t)n + 1) : NULL;
    uint32_t *cyc = NULL, *scratch = NULL, room = 0, maxk = 0;
    uint8_t *flag = NULL;
    wk_status st = start ? WK_OK : R->err.code;
    if (st != WK_OK) goto done;

    /* Bucket the half-arcs by face: counts, prefix sums, fill (hs[e] then
    ** points one past bucket e), shift back. */
    for (uint32_t i = 0; i < A; i++) {
        if (S->arcs[i].left != WK_NONE) hs[S->arcs[i].left + 1]++; /* a PSLG's cap: one face */
        hs[S->arcs[i].right + 1]++;
    }
    for (uint32_t e = 0; e < n; e++) hs[e + 1] += hs[e];
    for (uint32_t i = 0; i < A; i++) {
        const wk_arc *c = &S->arcs[i];
        if (c->left != WK_NONE) h[hs[c->left]++] = make_half(S, i, c->left);
        h[hs[c->right]++] = make_half(S, i, c->right);
    }
    for (uint32_t e = n; e > 0; e--) hs[e] = hs[e - 1];
    hs[0] = 0;
    for (uint32_t e = 0; e < n; e++)
        if (hs[e + 1] - hs[e] > maxk) maxk = hs[e + 1] - hs[e];

    /* Face e has k = hs[e+1] - hs[e] half-arcs, hence k + 1 cycle nodes,
    ** plus 2 per island (bridged, see wk_bridge_loop): node[] starts at the
    ** sum of k + 1 and grows only for faces with islands. */
    room = face_room(maxk);
    cyc = WK_NEW_ARRAY(R, uint32_t, room);
    flag = cyc ? WK_NEW_ARRAY(R, uint8_t, room) : NULL;
    scratch = flag ? WK_NEW_ARRAY(R, uint32_t, face_scratch(maxk)) : NULL;
    if (!scratch || WK_GROW(R, F->node, F->cap_node, (uint32_t)(nh + n)) != WK_OK) {
        st = R->err.code ? R->err.code : WK_ENOMEM;
        goto done;
    }
    uint32_t pos = 0;
    for (uint32_t e = 0; e < n && st == WK_OK; e++) {
        uint32_t k = hs[e + 1] - hs[e], got = 0, loops = 0;
        st = walk_face(R, P, S, e, h + hs[e], k, cyc, flag, scratch, &got, &loops, what);
        if (st != WK_OK) break;
        if ((st = WK_GROW(R, F->node, F->cap_node, pos + got)) != WK_OK) break;
        /* bridge[] exists from the first face with an island on and keeps
        ** node[]'s size; the faces before that one have no bridge (zeroed
        ** once), each face's own flags are copied below */
        if (loops || F->bridge) {
            bool first = !F->bridge;
            if ((st = WK_GROW(R, F->bridge, F->cap_bridge, F->cap_node)) != WK_OK) break;
            if (first) memset(F->bridge, 0, pos);
        }
        start[e] = pos;
        memcpy(F->node + pos, cyc, (size_t)got * sizeof *cyc);
        if (F->bridge) memcpy(F->bridge + pos, flag, got);
        pos += got;
    }
    start[n] = pos;
done:
    if (scratch) WK_FREE_ARRAY(R, scratch, face_scratch(maxk));
    if (flag) WK_FREE_ARRAY(R, flag, room);
    if (cyc) WK_FREE_ARRAY(R, cyc, room);
    if (hs) WK_FREE_ARRAY(R, hs, (size_t)n + 1);
    if (h) WK_FREE_ARRAY(R, h, nh);
    if (st == WK_OK) {
        F->n = n;
        F->start = start;
    } else {
        if (start) WK_FREE_ARRAY(R, start, (size_t)n + 1);
        wk_faces_clear(R, F);
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
