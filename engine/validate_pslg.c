/*
** validate_pslg.c: the validator for the skeleton of a planar straight-line
** graph (P->pslg, engine/pslg.c) up to its horizon T = S->horizon, the
** path wk_validate takes for a PSLG.  Stored numbering throughout: P's
** edges are the half-edges and caps of the initial wavefront, its
** vertices the corners, and face e is the region swept by edge e by t = T.
**
** Checks, in this order (the first violation is WK_EINVALID, "validate
** (pslg x): ..."), with tol as in validate.c and tol_t = tol / max w:
**   (a) input nodes: S->n_input == P->n, node i < n is corner i exactly,
**       t = 0; S->horizon T > 0 and finite.
**   (b) other nodes: finite, -tol_t <= t <= T + tol_t.
**   (c) arcs: node ids valid, a != b; each side an edge (< n) or WK_NONE
**       (the cap, the wavefront at T: only on the left, the unswept side),
**       left != right; at both ends v and for each side e that is an edge,
**       |d_e(v) - w(e) t_v| <= tol, d_e the signed distance from e's
**       supporting line (a cap's: through its terminal, perpendicular to
**       the segment), positive on the side e sweeps; a cap arc has both
**       ends at t = T (within tol_t).  At most one arc at a corner leaves
**       it for a node later than t ~ 0 (tol_t): one wavefront vertex starts
**       at each corner (the argument is above the check).
**   (d) faces: for every edge e, the darts of face e (edge e from corner e
**       to corner next(e); each arc with e on its left a -> b, with e on
**       its right b -> a) form closed loops: every node of them has one
**       dart out and the walks use each dart once; the first loop runs
**       through corner e (the face's boundary), any others are islands
**       (with unequal weights a fast edge can sweep round a slow segment
**       and close behind it, as round a hole: tests/test_pslg.c).
**   (e) each loop, repeated points merged (a cap is a side of length 0 at
**       t = 0), is a simple polygon (no two sides meet but adjacent ones at
**       their shared end; a contact is ignored where an end of one side lies
**       within tol of the other: rounding); the boundary is
**       counter-clockwise, each island clockwise, inside the boundary and
**       in no other island, and no two loops of a face meet.  So the
**       face's winding number is 0 or 1 everywhere.  Except: a face whose
**       only loop has all its nodes at t <= tol_t is empty (the edge was
**       swept at t = 0 by the collinear rule: collinear edges of
**       different weights at a node of degree 2), winding number 0.
**   (f) the cap: its darts (each cap arc b -> a, as the boundary of the
**       face on its right) form closed cycles, each simple, pairwise
**       disjoint (within tol as in (e)), and the winding number of the cap
**       cycles is 0 or 1 everywhere: for each cycle c, with s(c) = +1 if
**       counter-clockwise, -1 otherwise, the sum of s over the cycles that
**       contain c is 0 or 1, and so is that sum plus s(c).
**   (g) the face areas sum to the signed area of the cap cycles (reported
**       as area_error; failure above 1e-6 relative plus tol times the
**       cap's length).
** What this proves.  The faces' boundary cycles sum, as 1-chains, to the
** cap cycles: every arc lies on its two faces once in each direction, the
** two half-edges of a segment run along it in opposite directions and a
** cap's side at t = 0 has length 0.  So for every point x off the arcs and
** edges, the sum over faces of wind(face, x) = wind(cap, x).  By (e) each
** face has winding number 0 or 1, by (f) the cap too, so no point lies in
** two faces: the faces (simple polygons, some with islands) have disjoint
** interiors, no two
** arcs cross, and together they cover exactly the region the cap encloses
** (where the cap's winding number is 1), the region swept by T.  By (c)
** every node lies on the offset lines, at its time, of the edges whose
** faces it bounds, so each face lies on its edge's roof plane where its
** corners do and the roof is continuous across every arc.  Not proven:
** that these faces are the ones the wavefront defines rather than another
** partition with the same properties (as for polygons), that no event
** before T is missing where the roof planes would allow a different
** continuation, or anything beyond T.  Cost: O(sum over faces of their
** sides squared) for (e) and O(cap sides squared) for (f): a check for
** tests and moderate inputs, as is the reference it checks.
*/
#include "validate_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct dart { uint32_t face, from, to; } dart;

static int dart_cmp(const void *x, const void *y) {
    const dart *a = x, *b = y;
    if (a->face != b->face) return a->face < b->face ? -1 : 1;
    if (a->from != b->from) return a->from < b->from ? -1 : 1;
    return a->to < b->to ? -1 : a->to > b->to;
}

static double seg_dist(wk_point p, wk_point a, wk_point b) {
    double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double s = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return hypot(p.x - a.x - s * dx, p.y - a.y - s * dy);
}

/* Sides i (q[i] -> q[i+1]) and j of point rings meet where they must not:
** adjacent ones beyond their shared end, others at all; a contact within
** tol of an end is rounding. */
static bool sides_meet(const wk_point *q, uint32_t i, uint32_t j, uint32_t ni, const wk_point *r,
                       uint32_t nj, bool adjacent, double tol) {
    wk_point a = q[i], b = q[(i + 1) % ni], c = r[j], d = r[(j + 1) % nj];
    wk_seg_meet m = wk_segments_meet(a, b, c, d);
    if (m == WK_SEG_DISJOINT) return false;
    if (adjacent && m == WK_SEG_TOUCH) return false;
    if (seg_dist(a, c, d) <= tol || seg_dist(b, c, d) <= tol || seg_dist(c, a, b) <= tol ||
        seg_dist(d, a, b) <= tol) {
        if (!adjacent || m != WK_SEG_OVERLAP) return false;
        /* adjacent sides folding back onto each other: only below tol */
        double la = hypot(b.x - a.x, b.y - a.y), lc = hypot(d.x - c.x, d.y - c.y);
        return fmin(la, lc) > tol;
    }
    return true;
}

/* A ring of m points is simple (see sides_meet); returns the first bad
** pair in *bi, *bj. */
static bool ring_simple(const wk_point *q, uint32_t m, double tol, uint32_t *bi, uint32_t *bj) {
    for (uint32_t i = 0; i < m; i++)
        for (uint32_t j = i + 1; j < m; j++) {
            bool adjacent = j == i + 1 || (i == 0 && j == m - 1);
            if (sides_meet(q, i, j, m, q, m, adjacent, tol)) {
                *bi = i;
                *bj = j;
                return false;
            }
        }
    return true;
}

/* Exact point-in-ring by crossings (q not on the ring: cycles are disjoint). */
static bool ring_contains(const wk_point *q, uint32_t m, wk_point p) {
    bool in = false;
    for (uint32_t i = 0; i < m; i++) {
        wk_point a = q[i], b = q[(i + 1) % m];
        if ((a.y > p.y) == (b.y > p.y)) continue;
        int o = wk_orient2d(a, b, p, NULL);
        if ((b.y > a.y) ? o > 0 : o < 0) in = !in;
    }
    return in;
}

/* The loops of the darts d[lo, hi) (sorted by from, one face or the cap):
** first the one through `start` (WK_NONE: none required), then every other,
** each as points in q from qs[k] (repeated consecutive points merged).  A
** used dart gets face `used`.  False (*bad = the node) if a node has two
** darts out of it or a walk comes to a node with none left. */
static bool walk_loops(const wk_skeleton *S, dart *d, size_t lo, size_t hi, uint32_t start,
                       uint32_t used, wk_point *q, uint32_t *qs, uint32_t *n_loops, uint32_t *bad,
                       double *t_max0) {
    *t_max0 = 0;
    for (size_t i = lo + 1; i < hi; i++)
        if (d[i].from == d[i - 1].from) {
            *bad = d[i].from;
            return false;
        }
    uint32_t nq = 0, nl = 0;
    size_t next_unused = lo;
    for (;;) {
        uint32_t u = start;
        if (nl > 0 || start == WK_NONE) {
            while (next_unused < hi && d[next_unused].face == used) next_unused++;
            if (next_unused == hi) break;
            u = d[next_unused].from;
        }
        uint32_t first = u, q0 = nq;
        qs[nl++] = nq;
        do {
            size_t a = lo, b = hi;
            while (a < b) {
                size_t mid = a + (b - a) / 2;
                if (d[mid].from < u) a = mid + 1;
                else b = mid;
            }
            if (a == hi || d[a].from != u || d[a].face == used) {
                *bad = u;
                return false;
            }
            d[a].face = used;
            if (nl == 1 && S->nodes[u].t > *t_max0) *t_max0 = S->nodes[u].t;
            wk_point p = {S->nodes[u].x, S->nodes[u].y};
            if (nq == q0 || q[nq - 1].x != p.x || q[nq - 1].y != p.y) q[nq++] = p;
            u = d[a].to;
        } while (u != first);
        while (nq > q0 + 1 && q[nq - 1].x == q[q0].x && q[nq - 1].y == q[q0].y) nq--;
    }
    qs[nl] = nq;
    *n_loops = nl;
    return true;
}

/* Loops k = 0 .. nl-1 of points q[qs[k] .. qs[k+1]): each simple with
** nonzero area, no two meeting (within tol, as sides_meet).  On failure
** *la, *lb name the loops (equal: one loop is not simple). */
static bool loops_simple_disjoint(const wk_point *q, const uint32_t *qs, uint32_t nl, double tol,
                                  uint32_t *la, uint32_t *lb) {
    for (uint32_t k = 0; k < nl; k++) {
        uint32_t m = qs[k + 1] - qs[k], bi, bj;
        *la = *lb = k;
        if (m < 3 || wk_shoelace_exact(q + qs[k], m) == 0 || !ring_simple(q + qs[k], m, tol, &bi, &bj))
            return false;
    }
    for (uint32_t k = 0; k < nl; k++)
        for (uint32_t k2 = k + 1; k2 < nl; k2++) {
            const wk_point *qa = q + qs[k], *qb = q + qs[k2];
            uint32_t ma = qs[k + 1] - qs[k], mb = qs[k2 + 1] - qs[k2];
            for (uint32_t i = 0; i < ma; i++)
                for (uint32_t j = 0; j < mb; j++)
                    if (sides_meet(qa, i, j, ma, qb, mb, false, tol)) {
                        *la = k;
                        *lb = k2;
                        return false;
                    }
        }
    return true;
}

wk_status wk_validate_pslg(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol,
                           wk_validate_report *rep) {
    wk_validate_report local;
    if (!rep) rep = &local;
    memset(rep, 0, sizeof *rep);
    rep->nodes = S->n_nodes;
    rep->arcs = S->n_arcs;
    rep->faces = P->n;
    const char *name = P->name;
    if (!(tol > 0)) tol = WK_VALIDATE_TOL_REL * wk_polygon_scale(P);
    double wmax = 0, T = S->horizon;
    for (uint32_t e = 0; e < P->n; e++) wmax = fmax(wmax, P->w[e]);
    double tol_t = tol / wmax;
    /* (a) */
    if (!(T > 0) || !isfinite(T))
        return WK_FAIL(R, WK_EINVALID, name, 0, "validate (pslg a): the horizon %g is not positive", T);
    if (S->n_input != P->n || S->n_nodes < P->n)
        return WK_FAIL(R, WK_EINVALID, name, 0, "validate (pslg a): %u input nodes for %u corners",
                       S->n_input, P->n);
    for (uint32_t i = 0; i < P->n; i++)
        if (S->nodes[i].x != P->p[i].x || S->nodes[i].y != P->p[i].y || S->nodes[i].t != 0)
            return WK_FAIL(R, WK_EINVALID, name, 0,
                           "validate (pslg a): node %u is not corner %u at t = 0", i, i);
    /* (b) */
    for (uint32_t i = P->n; i < S->n_nodes; i++) {
        const wk_node *v = &S->nodes[i];
        if (!isfinite(v->x) || !isfinite(v->y) || !isfinite(v->t) || v->t < -tol_t ||
            v->t > T + tol_t)
            return WK_FAIL(R, WK_EINVALID, name, 0,
                           "validate (pslg b): node %u (%g, %g, t %g) is not finite or not in "
                           "0 <= t <= %g",
                           i, v->x, v->y, v->t, T);
    }
    /* (c) */
    uint32_t *leaving = WK_NEW_ARRAY(R, uint32_t, P->n); /* arcs leaving each corner */
    if (!leaving) return R->err.code;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        wk_status bad_arc = WK_OK;
        if (c->a >= S->n_nodes || c->b >= S->n_nodes || c->a == c->b)
            bad_arc = WK_FAIL(R, WK_EINVALID, name, 0,
                              "validate (pslg c): arc %u [%u, %u] has bad ends", i, c->a, c->b);
        else if (c->left == c->right || c->right >= P->n ||
                 (c->left >= P->n && c->left != WK_NONE))
            bad_arc = WK_FAIL(R, WK_EINVALID, name, 0,
                              "validate (pslg c): arc %u has faces %u, %u (the cap, %u, only on "
                              "the left)",
                              i, c->left, c->right, WK_NONE);
        else if (wk_validate_arc_ends(R, P, S, i, T, tol, tol_t, name, "pslg c", "the horizon",
                                      "offset line", rep) != WK_OK)
            bad_arc = R->err.code;
        if (bad_arc != WK_OK) {
            WK_FREE_ARRAY(R, leaving, P->n);
            return bad_arc;
        }
        /* an arc at corner a whose other end b is later than t ~ 0 */
        if (c->a < P->n && !(fabs(S->nodes[c->b].t) <= tol_t)) leaving[c->a]++;
        if (c->b < P->n && !(fabs(S->nodes[c->a].t) <= tol_t)) leaving[c->b]++;
    }
    /* One wavefront vertex starts at each corner, so at most one arc leaves
    ** it for t > tol_t (the others, any number, run at t ~ 0: edges swept at
    ** once by the collinear rule, sub-tolerance features).  Why: near the
    ** corner, inside its wedge (the angle between its two edges, which no
    ** other edge's face enters: the segments bounding the wedge separate
    ** it from the other wedges at that point), the faces met going round
    ** are the two edges' own and, by (c), faces of edges whose lines pass
    ** through the corner at t ~ 0; a second arc leaving for t > tol_t would
    ** be a second wavefront vertex, i.e. a face between the corner's two
    ** that reaches beyond t ~ 0 (the same rule as validate.c's (d)). */
    for (uint32_t v = 0; v < P->n; v++)
        if (leaving[v] > 1) {
            uint32_t count = leaving[v];
            WK_FREE_ARRAY(R, leaving, P->n);
            return WK_FAIL(R, WK_EINVALID, name, 0,
                           "validate (pslg c): corner %u has %u arcs that leave it (to nodes later "
                           "than t = %.3g); one wavefront vertex starts there",
                           v, count, tol_t);
        }
    WK_FREE_ARRAY(R, leaving, P->n);
    /* (d) darts: faces 0..n-1, the cap as face n; used darts get face n + 1 */
    size_t m = 2 * (size_t)S->n_arcs + P->n;
    dart *d = WK_NEW_ARRAY(R, dart, m);
    wk_point *q = WK_NEW_ARRAY(R, wk_point, m + 1);
    uint32_t *qs = WK_NEW_ARRAY(R, uint32_t, m + 2);
    wk_status st = WK_OK;
    if (!d || !q || !qs) {
        st = R->err.code;
        goto done;
    }
    size_t k = 0;
    const uint32_t CAP = P->n, USED = P->n + 1;
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        if (c->left == WK_NONE) d[k++] = (dart){CAP, c->b, c->a};
        else d[k++] = (dart){c->left, c->a, c->b};
        d[k++] = (dart){c->right, c->b, c->a};
    }
    for (uint32_t e = 0; e < P->n; e++) d[k++] = (dart){e, e, wk_polygon_next(P, e)};
    qsort(d, m, sizeof *d, dart_cmp);
    double face_area = 0;
    size_t lo = 0;
    uint32_t nl, bad, la, lb;
    for (uint32_t e = 0; e < P->n; e++) {
        size_t hi = lo;
        while (hi < m && d[hi].face == e) hi++;
        double t_max0;
        if (!walk_loops(S, d, lo, hi, e, USED, q, qs, &nl, &bad, &t_max0)) {
            st = WK_FAIL(R, WK_EINVALID, name, 0,
                         "validate (pslg d): the face of edge %u is not closed at node %u", e, bad);
            goto done;
        }
        /* an edge swept at t = 0 by the collinear rule: its face is empty,
        ** a loop of arcs at t = 0 along it (as validate.c allows) */
        if (nl == 1 && t_max0 <= tol_t) {
            lo = hi;
            continue;
        }
        /* (e) */
        if (!loops_simple_disjoint(q, qs, nl, tol, &la, &lb)) {
            if (la == lb)
                st = WK_FAIL(R, WK_EINVALID, name, 0,
                             "validate (pslg e): face %u is not simple (%s %u)", e,
                             la ? "its island" : "its boundary", la);
            else
                st = WK_FAIL(R, WK_EINVALID, name, 0,
                             "validate (pslg e): face %u's loops %u and %u meet", e, la, lb);
            goto done;
        }
        for (uint32_t l = 0; l < nl; l++) {
            double area = 0.5 * wk_shoelace_exact(q + qs[l], qs[l + 1] - qs[l]);
            bool inside_outer = l == 0 || ring_contains(q, qs[1], q[qs[l]]);
            bool in_island = false;
            for (uint32_t l2 = 1; l2 < nl && l > 0; l2++)
                if (l2 != l && ring_contains(q + qs[l2], qs[l2 + 1] - qs[l2], q[qs[l]])) in_island = true;
            if ((l == 0) != (area > 0) || !inside_outer || in_island) {
                st = WK_FAIL(R, WK_EINVALID, name, 0,
                             "validate (pslg e): face %u: %s %u has area %.3g%s", e,
                             l ? "island" : "boundary", l, area,
                             !inside_outer ? " and lies outside the boundary"
                             : in_island   ? " and lies inside another island"
                                           : " (the boundary must be counter-clockwise, islands "
                                             "clockwise)");
                goto done;
            }
            face_area += area;
        }
        lo = hi;
    }
    /* (f) the cap */
    if (lo == m) {
        st = WK_FAIL(R, WK_EINVALID, name, 0,
                     "validate (pslg f): no cap: a PSLG's outer wavefront never vanishes");
        goto done;
    }
    double t_unused;
    if (!walk_loops(S, d, lo, m, WK_NONE, USED, q, qs, &nl, &bad, &t_unused)) {
        st = WK_FAIL(R, WK_EINVALID, name, 0, "validate (pslg f): the cap is not closed at node %u", bad);
        goto done;
    }
    if (!loops_simple_disjoint(q, qs, nl, tol, &la, &lb)) {
        if (la == lb)
            st = WK_FAIL(R, WK_EINVALID, name, 0,
                         "validate (pslg f): cap cycle %u is not a simple polygon", la);
        else
            st = WK_FAIL(R, WK_EINVALID, name, 0, "validate (pslg f): cap cycles %u and %u meet",
                         la, lb);
        goto done;
    }
    double cap_sum = 0, cap_len = 0;
    for (uint32_t c = 0; c < nl; c++) {
        uint32_t mc = qs[c + 1] - qs[c];
        const wk_point *qc = q + qs[c];
        double area = 0.5 * wk_shoelace_exact(qc, mc);
        cap_sum += area;
        for (uint32_t i = 0; i < mc; i++)
            cap_len += hypot(qc[(i + 1) % mc].x - qc[i].x, qc[(i + 1) % mc].y - qc[i].y);
        int outside = 0, sgn = area > 0 ? 1 : -1;
        for (uint32_t c2 = 0; c2 < nl; c2++)
            if (c2 != c && ring_contains(q + qs[c2], qs[c2 + 1] - qs[c2], qc[0]))
                outside += wk_shoelace_exact(q + qs[c2], qs[c2 + 1] - qs[c2]) > 0 ? 1 : -1;
        if (outside < 0 || outside > 1 || outside + sgn < 0 || outside + sgn > 1) {
            st = WK_FAIL(R, WK_EINVALID, name, 0,
                         "validate (pslg f): the cap's winding number is %d next to cap cycle %u "
                         "(faces overlap)",
                         outside < 0 || outside > 1 ? outside : outside + sgn, c);
            goto done;
        }
    }
    /* (g) the polygon validator's area tolerance (tolerance.h), named there
    ** rather than a literal here so the one policy holds for PSLGs too */
    rep->area_error = fabs(face_area - cap_sum);
    if (rep->area_error > WK_VALIDATE_AREA_REL * fabs(cap_sum) + tol * cap_len)
        st = WK_FAIL(R, WK_EINVALID, name, 0,
                     "validate (pslg g): the faces' areas sum to %.17g, the cap encloses %.17g",
                     face_area, cap_sum);
done:
    WK_FREE_ARRAY(R, d, m);
    WK_FREE_ARRAY(R, q, m + 1);
    WK_FREE_ARRAY(R, qs, m + 2);
    return st;
}
