/*
** arrangement.c: A(P) (000, section 3.1), its initial crossing count, and
** the dynamic arrangement with next-crossing queries and the k cache (000,
** section 3.2).  Design, tolerances and the structure's invariants are in
** arrangement.h.
**
** Invariants between calls (checked by wk_arrangement_check):
**   - seg[0..n_live) are exactly the current segments and
**     ids[seg[i].id].slot == i; a removed id has slot WK_NONE and no cache;
**   - a valid cache is sorted by (s, other), and every entry lies in its
**     complete range (from, to]; within that range it lists every crossing
**     that existed when it was filled, minus tombstones for removed
**     segments; crossings that appeared since (insert, widening) cut the
**     range before them.  So, for a position p >= from, the first live
**     entry > p that passes the active-part check is the true next crossing
**     if it is <= to, and "none" is the truth when to is +infinity.
**   - n_cached is the number of valid caches.
*/
#include "bisector_arrangement.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* ================================================================== A(P) */

/* Velocity direction and speed of reflex vertex v. */
static void reflex_motion(const wk_polygon *P, uint32_t v, wk_aseg *g) {
    uint32_t prev = wk_polygon_prev(P, v);
    wk_offset_line la, lb;
    wk_offset_line_of_edge(P, prev, &la);
    wk_offset_line_of_edge(P, v, &lb);
    wk_point vel;
    g->vkind = wk_vertex_velocity(&la, &lb, &vel);
    double dx, dy, speed = hypot(vel.x, vel.y);
    if (g->vkind == WK_VEL_ANTIPARALLEL) {
        /* A needle notch: the edges fold back on each other and the vertex
        ** runs (infinitely fast) along the notch, away from its mouth. */
        dx = la.ux - lb.ux;
        dy = la.uy - lb.uy;
        speed = INFINITY;
    } else if (g->vkind == WK_VEL_REGULAR) {
        dx = vel.x;
        dy = vel.y;
    } else {
        /* Nearly straight (below kinetics.c's parallel sine) yet reflex by
        ** the exact test: the vertex moves along the mean normal; with
        ** different weights (COLLINEAR) its speed is unbounded. */
        dx = la.nx + lb.nx;
        dy = la.ny + lb.ny;
        if (!(speed > 0.0)) speed = INFINITY;
    }
    double len = hypot(dx, dy);
    g->u = (wk_point){dx / len, dy / len};
    g->speed = speed;
}


/* A ray that meets nothing: its origin, vertex v, lies within tol of an
** edge other than its own two (a tiny edge next to v: v's neighbour across
** it, and that neighbour's other edge, are within tol of v).  The shooter
** sees every point within tol of the ray and ignores hits at t <= 0, so the
** crossing right at the origin is lost.  The first boundary point is then v
** itself up to tol: a hit on the nearest endpoint w of the closest such edge,
** at distance max(0, projection of w), left ambiguous (a vertex hit) for the
** finder's own shot.  False if no edge is that close (a genuine miss). */
static bool hit_at_origin(const wk_polygon *P, double tol, uint32_t v, wk_point u, wk_ray_hit *h) {
    uint32_t prev = wk_polygon_prev(P, v);
    wk_point a = P->p[v];
    double best = INFINITY;
    uint32_t bw = WK_NONE;
    for (uint32_t e = 0; e < P->n; e++) {
        if (e == v || e == prev) continue;
        uint32_t f = wk_polygon_next(P, e);
        wk_point p = P->p[e], q = P->p[f];
        double d = wk_polygon_edge_distance(P, e, a);
        if (d <= tol && d < best) {
            best = d;
            bw = hypot(p.x - a.x, p.y - a.y) <= hypot(q.x - a.x, q.y - a.y) ? e : f;
        }
    }
    if (bw == WK_NONE) return false;
    wk_point w = P->p[bw];
    double t = (w.x - a.x) * u.x + (w.y - a.y) * u.y;
    *h = (wk_ray_hit){t > 0 ? t : 0, w, WK_NONE, bw};
    return true;
}

/* True if edge e is one of the pieces the finder's near_split tests for v
** at t = 0 (wk_wf_near_split: the pieces next to v's own two, and on past
** neighbours within WK_ARR_NEAR_SLACK tol of v): those contacts have their
** own test, and v's ray still finds F (hit_at_origin). */
static bool near_chain_edge(const wk_polygon *P, uint32_t v, uint32_t e, double near) {
    wk_point pv = P->p[v];
    for (uint32_t a = wk_polygon_next(P, v); a != v && wk_polygon_next(P, a) != v;
         a = wk_polygon_next(P, a)) {
        if (e == a) return true;
        if (!(hypot(P->p[a].x - pv.x, P->p[a].y - pv.y) <= near)) break;
    }
    for (uint32_t b = wk_polygon_prev(P, v); b != v && wk_polygon_prev(P, b) != v;
         b = wk_polygon_prev(P, b)) {
        if (e == wk_polygon_prev(P, b)) return true;
        if (!(hypot(P->p[b].x - pv.x, P->p[b].y - pv.y) <= near)) break;
    }
    return false;
}

/* True if reflex vertex v lies within the shooter's tol of an edge other
** than its own two and the ones near_split covers: a contact at t = 0 with
** another part of the boundary (a pinch narrower than the tolerance).  The
** reference's split test takes such a vertex as splitting that edge's
** piece at once, but the ray along v's motion may miss it: a ray through a
** pinch 1.7e-10 wide (tol 0.43) passes the vertex on the other side within
** tol of the ray's line (no crossing of either of its edges) and met the
** boundary beyond the pinch, where v then split a piece it could never
** reach (tests/data/fuzz/ealgo_arrangement_still_alive.wpoly: a wavefront
** vertex left alive, exit 2).  The grid cell of v lists every edge within
** 2 tol of it, so O(cell) per vertex. */
static bool contact_at_origin(const wk_ray_shooter *sh, uint32_t v) {
    const wk_polygon *P = sh->P;
    const wk_seg_grid *G = &sh->G;
    wk_point a = P->p[v];
    uint32_t prev = wk_polygon_prev(P, v);
    uint32_t c = wk_seg_grid_row(G, a.y) * G->nx + wk_seg_grid_col(G, a.x);
    for (uint32_t k = G->start[c]; k < G->start[c + 1]; k++) {
        uint32_t e = G->items[k];
        if (e == v || e == prev || !(wk_polygon_edge_distance(P, e, a) <= sh->tol)) continue;
        if (!near_chain_edge(P, v, e, WK_ARR_NEAR_SLACK * sh->tol)) return true;
    }
    return false;
}

wk_status wk_arrangement_segments(wk_run *R, const wk_polygon *P, wk_aseg **out, uint32_t *r_out) {
    *out = NULL;
    *r_out = 0;
    uint32_t r = 0;
    for (uint32_t i = 0; i < P->n; i++) r += wk_polygon_is_reflex_counted(R, P, i);
    if (r == 0) return WK_OK;
    wk_aseg *S = WK_NEW_ARRAY(R, wk_aseg, r);
    if (!S) return R->err.code;
    wk_ray_shooter sh;
    wk_status st = wk_ray_shooter_init(R, &sh, P);
    if (st != WK_OK) {
        WK_FREE_ARRAY(R, S, r);
        return st;
    }
    for (uint32_t i = 0, j = 0; i < P->n; i++)
        if (wk_polygon_is_reflex_counted(R, P, i)) S[j++].vertex = i;
    int nt = R->opt.threads > 0 ? R->opt.threads : 1;
    /* Each iteration writes only S[j]; sh and P are read-only; R is not
    ** touched.  So the output does not depend on nt or the schedule. */
#pragma omp parallel for num_threads(nt) schedule(dynamic, 16)
    for (int64_t j = 0; j < (int64_t)r; j++) {
        wk_aseg *g = &S[j];
        reflex_motion(P, g->vertex, g);
        g->a = P->p[g->vertex];
        wk_ray_hit h = {0, g->a, WK_NONE, WK_NONE};
        /* The brute force is a defensive fallback: the grid walk finds a
        ** hit whenever one exists (ray_shoot.c), so it never runs.  A ray
        ** that meets nothing starts within tol of the boundary (a tiny edge
        ** next to its vertex): hit_at_origin. */
        if (!wk_ray_shoot(&sh, g->a, g->u, g->vertex, &h) &&
            !wk_ray_shoot_brute(P, sh.tol, g->a, g->u, g->vertex, &h))
            (void)hit_at_origin(P, sh.tol, g->vertex, g->u, &h);
        g->hit = h;
        g->b = h.p;
        g->len = h.t;
        g->contact = contact_at_origin(&sh, g->vertex);
    }
    wk_ray_shooter_clear(R, &sh);
    for (uint32_t j = 0; j < r; j++)
        if (S[j].hit.edge == WK_NONE && S[j].hit.vertex == WK_NONE) {
            uint32_t v = S[j].vertex;
            WK_FREE_ARRAY(R, S, r);
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "ray of reflex vertex %u (%.17g, %.17g) meets no edge", v, P->p[v].x,
                           P->p[v].y);
        }
    *out = S;
    *r_out = r;
    return WK_OK;
}

/* ======================================================= initial crossings */

/* Shewchuk's stage-A bound for orient2d (as in predicates.c), repeated here
** so that the pair loop, which runs ~K times, can decide most pairs inline;
** undecided pairs go to the exact wk_segments_meet. */
static const double ORIENT_ERR = (3.0 + 16.0 * (DBL_EPSILON / 2.0)) * (DBL_EPSILON / 2.0);

/* A segment of A(P) as the pair loop reads it. */
typedef struct cseg {
    wk_point a, b;
    double xl, xh, yl, yh; /* bounding box */
    double len;            /* |b - a| */
} cseg;

static void cseg_of(const void *ud, uint32_t i, wk_point *a, wk_point *b) {
    const cseg *S = ud;
    *a = S[i].a;
    *b = S[i].b;
}

/* orient(a, b, c) in double, Shewchuk's expression, and its stage-A
** certainty: *sure = the sign when certain, else 2. */
static inline double orient_det(wk_point a, wk_point b, wk_point c, int *sure) {
    double l = (a.x - c.x) * (b.y - c.y), rr = (a.y - c.y) * (b.x - c.x);
    double det = l - rr, bound = ORIENT_ERR * (fabs(l) + fabs(rr));
    *sure = det > bound ? 1 : -det > bound ? -1 : 2;
    return det;
}

/* The cell of a point by comparison with the walls x0 + k cw (the first
** and last columns extend to infinity).  The hot loop decides "p is in cell
** c" with the same comparisons, without a division. */
static uint32_t col_of(const wk_seg_grid *G, double x) {
    uint32_t k = wk_seg_grid_col(G, x);
    while (k > 0 && x < G->x0 + (double)k * G->cw) k--;
    while (k + 1 < G->nx && x >= G->x0 + (double)(k + 1) * G->cw) k++;
    return k;
}

static uint32_t row_of(const wk_seg_grid *G, double y) {
    uint32_t k = wk_seg_grid_row(G, y);
    while (k > 0 && y < G->y0 + (double)k * G->ch) k--;
    while (k + 1 < G->ny && y >= G->y0 + (double)(k + 1) * G->ch) k++;
    return k;
}

/* Counting each crossing once.  For a pair i < j listed together in some
** cell, let p be its crossing point computed in double on i, where j's line
** meets it (lam = d3 / (d3 - d4) clamped to [0, 1], always from (i, j) in
** this order, so every cell gets the same bits).  Its canonical cell is
** the cell of p if both segments are listed there, else the first cell in
** row-major order listing both: a function of the pair alone, so exactly
** one of the cells the pair shares counts it.
**
** Fast evaluation: p lies on i up to rounding, so i is listed in p's cell
** (buckets cover delta around a segment).  If p is within delta / 2 of
** segment j (checked in double with a margin far above its rounding), j is
** listed there too, and the canonical cell is p's cell: decided by four
** comparisons, without table lookups.  Only a stray p (nearly parallel
** segments crossing near an end) needs the span table. */
static uint32_t canonical_slow(const wk_seg_grid *G, uint32_t i, uint32_t j, wk_point p) {
    uint32_t col = col_of(G, p.x), row = row_of(G, p.y);
    if (wk_seg_grid_touches_id(G, i, col, row) && wk_seg_grid_touches_id(G, j, col, row))
        return row * G->nx + col;
    uint32_t ri = G->row0[i], rj = G->row0[j];
    uint32_t ni = G->soff[i + 1] - G->soff[i], nj = G->soff[j + 1] - G->soff[j];
    uint32_t r0 = ri > rj ? ri : rj, r1 = ri + ni < rj + nj ? ri + ni : rj + nj; /* [r0, r1) */
    for (row = r0; row < r1; row++) {
        const uint32_t *si = G->span + 2 * ((size_t)G->soff[i] + (row - ri));
        const uint32_t *sj = G->span + 2 * ((size_t)G->soff[j] + (row - rj));
        uint32_t c0 = si[0] > sj[0] ? si[0] : sj[0], c1 = si[1] < sj[1] ? si[1] : sj[1];
        if (c0 <= c1) return row * G->nx + c0;
    }
    return UINT32_MAX; /* not reached: the pair shares the asking cell */
}

/* Crossings counted for the entry x of the grid (segment i = items[x] in
** cell c): pairs (i, j) with j listed after i in c that cross properly and
** whose canonical cell is c.  Summed over all entries: every crossing once.
** The loop runs over entries rather than cells so that threads can share
** a crowded cell (star polygons put thousands of segments in one). */
static uint64_t count_entry(const wk_seg_grid *G, const cseg *S, uint32_t x) {
    /* the cell of entry x: the last c with start[c] <= x */
    uint32_t lo = 0, hi = G->n_cells;
    while (hi - lo > 1) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (G->start[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    uint32_t c = lo, e = G->start[c + 1];
    if (e - x < 2) return 0;
    uint32_t col = c % G->nx, row = c / G->nx;
    /* p is in cell c iff these hold: the comparisons of col_of / row_of. */
    bool xfirst = col == 0, xlast = col + 1 == G->nx, yfirst = row == 0, ylast = row + 1 == G->ny;
    double xa = G->x0 + (double)col * G->cw, xb = G->x0 + (double)(col + 1) * G->cw;
    double ya = G->y0 + (double)row * G->ch, yb = G->y0 + (double)(row + 1) * G->ch;
    double m = 0.25 * G->delta; /* near: within m of j's line and span */
    uint64_t total = 0;
    uint32_t i = G->items[x];
    const cseg *P = &S[i];
    for (uint32_t y = x + 1; y < e; y++) {
        uint32_t j = G->items[y];
        const cseg *Q = &S[j];
        if (Q->xh < P->xl || Q->xl > P->xh || Q->yh < P->yl || Q->yl > P->yh) continue;
        int o1, o2, o3, o4;
        double d3 = orient_det(Q->a, Q->b, P->a, &o3), d4 = orient_det(Q->a, Q->b, P->b, &o4);
        if (o3 != 2 && o3 == o4) continue; /* P on one side of Q's line */
        double lam = d3 / (d3 - d4);
        if (!(lam >= 0.0)) lam = 0.0; /* also NaN */
        if (lam > 1.0) lam = 1.0;
        wk_point p = {P->a.x + lam * (P->b.x - P->a.x), P->a.y + lam * (P->b.y - P->a.y)};
        double ex = Q->b.x - Q->a.x, ey = Q->b.y - Q->a.y;
        double px = p.x - Q->a.x, py = p.y - Q->a.y;
        double h = ex * py - ey * px, g = ex * px + ey * py, ml = m * Q->len;
        if (fabs(h) <= ml && g >= -ml && g <= Q->len * Q->len + ml) {
            /* canonical cell = p's cell: is it c? */
            if (!((xfirst || p.x >= xa) && (xlast || p.x < xb) && (yfirst || p.y >= ya) &&
                  (ylast || p.y < yb)))
                continue;
            (void)orient_det(P->a, P->b, Q->a, &o1);
            (void)orient_det(P->a, P->b, Q->b, &o2);
            if (o1 != 2 && o1 == o2) continue; /* Q on one side of P's line */
        } else {
            (void)orient_det(P->a, P->b, Q->a, &o1);
            (void)orient_det(P->a, P->b, Q->b, &o2);
            if (o1 != 2 && o1 == o2) continue;
            if (canonical_slow(G, i, j, p) != c) continue;
        }
        if (o1 != 2 && o2 != 2 && o3 != 2 && o4 != 2)
            total++; /* all four sure and o1 != o2, o3 != o4: a proper crossing */
        else
            total += wk_segments_meet(P->a, P->b, Q->a, Q->b) == WK_SEG_CROSS;
    }
    return total;
}

/* Grid resolution for the crossing count: about 4 r cells.  Each segment
** then lies in O(sqrt r) cells (O(r^1.5) entries), and a pair is tested in
** the few cells around its crossing plus the cells where the two pass
** within a cell width of each other, so the work is O(r^1.5 + K) for
** segments spread over the box (segments through one small region, as in
** star polygons, still cost a test per pair that meets there). */
#define WK_CROSS_CELLS_PER_SEG 4u

wk_status wk_arrangement_count_crossings(wk_run *R, const wk_aseg *segs, uint32_t r,
                                         uint64_t *count) {
    *count = 0;
    if (r < 2) {
        wk_count(R, WK_VC_arrangement_crossings_initial, 0);
        return WK_OK;
    }
    cseg *S = WK_NEW_ARRAY(R, cseg, r);
    if (!S) return R->err.code;
    wk_point lo = segs[0].a, hi = segs[0].a;
    for (uint32_t i = 0; i < r; i++) {
        wk_point a = segs[i].a, b = segs[i].b;
        S[i] = (cseg){a,
                      b,
                      a.x < b.x ? a.x : b.x,
                      a.x < b.x ? b.x : a.x,
                      a.y < b.y ? a.y : b.y,
                      a.y < b.y ? b.y : a.y,
                      hypot(b.x - a.x, b.y - a.y)};
        if (S[i].xl < lo.x) lo.x = S[i].xl;
        if (S[i].xh > hi.x) hi.x = S[i].xh;
        if (S[i].yl < lo.y) lo.y = S[i].yl;
        if (S[i].yh > hi.y) hi.y = S[i].yh;
    }
    double diag = hypot(hi.x - lo.x, hi.y - lo.y);
    double delta = diag > 0.0 ? WK_TOL_REL * diag : 1.0;
    uint64_t target = (uint64_t)r * WK_CROSS_CELLS_PER_SEG;
    if (target > (1u << 26)) target = 1u << 26;
    wk_seg_grid G;
    wk_status st = wk_seg_grid_build(R, &G, r, cseg_of, S, lo, hi, (uint32_t)target, delta, true);
    if (st != WK_OK) {
        WK_FREE_ARRAY(R, S, r);
        return st;
    }
    int nt = R->opt.threads > 0 ? R->opt.threads : 1;
    uint64_t total = 0;
    const wk_seg_grid *g = &G;
    /* Entries are independent and the grid is read-only; the integer sum
    ** is the same in any order, so the count does not depend on nt. */
#pragma omp parallel for num_threads(nt) schedule(dynamic, 64) reduction(+ : total)
    for (int64_t x = 0; x < (int64_t)g->n_items; x++) total += count_entry(g, S, (uint32_t)x);
    wk_seg_grid_clear(R, &G);
    WK_FREE_ARRAY(R, S, r);
    *count = total;
    wk_count(R, WK_VC_arrangement_crossings_initial, total);
    return WK_OK;
}

/* ===================================================== dynamic arrangement */

/* (s1, i1) < (s2, i2), lexicographically. */
static inline bool pos_less(double s1, uint32_t i1, double s2, uint32_t i2) {
    return s1 < s2 || (s1 == s2 && i1 < i2);
}

static inline bool cr_less(const wk_crossing *a, const wk_crossing *b) {
    return pos_less(a->s, a->other, b->s, b->other);
}

bool wk_arrangement_crossing(const wk_arr_seg *a, const wk_arr_seg *b, double *s, double *t) {
    double den = a->ux * b->uy - a->uy * b->ux;
    if (fabs(den) <= WK_ARR_PARALLEL) return false;
    double wx = b->ax - a->ax, wy = b->ay - a->ay;
    *s = (wx * b->uy - wy * b->ux) / den;
    *t = (wx * a->uy - wy * a->ux) / den;
    return true;
}

void wk_arrangement_init(wk_arrangement *A) { memset(A, 0, sizeof *A); }

static void cache_drop(wk_run *R, wk_arrangement *A, wk_arr_cache *C) {
    if (C->cap) WK_FREE_ARRAY(R, C->e, C->cap);
    if (C->valid) A->n_cached--;
    memset(C, 0, sizeof *C);
}

void wk_arrangement_clear(wk_run *R, wk_arrangement *A) {
    for (uint32_t i = 0; i < A->n_ids; i++) cache_drop(R, A, &A->ids[i].cache);
    if (A->seg) WK_FREE_ARRAY(R, A->seg, A->cap_seg);
    if (A->ids) WK_FREE_ARRAY(R, A->ids, A->cap_ids);
    if (A->scratch) WK_FREE_ARRAY(R, A->scratch, A->cap_scratch);
    wk_arrangement_init(A);
}

const wk_arr_seg *wk_arrangement_get(const wk_arrangement *A, uint32_t id) {
    if (id >= A->n_ids || A->ids[id].slot == WK_NONE) return NULL;
    return &A->seg[A->ids[id].slot];
}

static wk_status not_current(wk_run *R, const char *what, uint32_t id) {
    return WK_FAIL(R, WK_EALGO, NULL, 0, "arrangement %s: segment %u is not current", what, id);
}

/* First entry of C at a position > (s, id).  Entries are sorted by (s,
** other); tombstones keep their other, so the order holds for them too. */
static uint32_t cache_upper(const wk_arr_cache *C, double s, uint32_t id) {
    uint32_t lo = 0, hi = C->n;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (pos_less(s, id, C->e[mid].s, C->e[mid].other))
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* First entry of C at a position >= (s, id). */
static uint32_t cache_lower(const wk_arr_cache *C, double s, uint32_t id) {
    uint32_t lo = 0, hi = C->n;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (pos_less(C->e[mid].s, C->e[mid].other, s, id))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Segment N = seg[nslot] gained the part of its active interval [lo, hi]
** outside [old_lo, old_hi] (all of it for an insert: old_lo > old_hi).
** Every cache that N now crosses inside its complete range loses the
** entries from that crossing on; its range ends just before it. */
static void invalidate_for(wk_run *R, wk_arrangement *A, uint32_t nslot, double old_lo,
                           double old_hi) {
    if (A->n_cached == 0) return;
    const wk_arr_seg *N = &A->seg[nslot];
    for (uint32_t j = 0; j < A->n_live; j++) {
        if (j == nslot) continue;
        const wk_arr_seg *S = &A->seg[j];
        wk_arr_cache *C = &A->ids[S->id].cache;
        if (!C->valid) continue;
        double s, t;
        if (!wk_arrangement_crossing(S, N, &s, &t)) continue;
        if (t < N->lo || t > N->hi || (t >= old_lo && t <= old_hi)) continue;
        if (s < S->lo || s > S->hi) continue;
        if (!pos_less(C->from_s, C->from_id, s, N->id)) continue;
        if (pos_less(C->to_s, C->to_id, s, N->id)) continue;
        /* Keep the entries before (s, N->id); the range now ends at the
        ** position just before it.  If the entry is there already (N was
        ** narrowed after the refill, then widened again), nothing changed. */
        uint32_t keep = cache_lower(C, s, N->id);
        if (keep < C->n && C->e[keep].s == s && C->e[keep].other == N->id && !C->e[keep].dead)
            continue;
        wk_count(R, WK_VC_cache_invalidations, 1);
        if (keep == 0) {
            cache_drop(R, A, C);
            continue;
        }
        C->n = keep;
        if (N->id > 0) {
            C->to_s = s;
            C->to_id = N->id - 1;
        } else {
            C->to_s = nextafter(s, -INFINITY);
            C->to_id = WK_NONE;
        }
    }
}

wk_status wk_arrangement_insert(wk_run *R, wk_arrangement *A, wk_point a, wk_point dir, double len,
                                uint32_t *id) {
    double norm = hypot(dir.x, dir.y);
    if (!isfinite(a.x) || !isfinite(a.y) || !isfinite(norm) || !(norm > 0.0) || !isfinite(len) ||
        !(len >= 0.0))
        return WK_FAIL(R, WK_EINPUT, NULL, 0,
                       "arrangement insert: bad segment (start (%g, %g), direction (%g, %g), "
                       "length %g)",
                       a.x, a.y, dir.x, dir.y, len);
    if (A->n_ids >= UINT32_MAX - 1)
        return WK_FAIL(R, WK_ENOMEM, NULL, 0, "arrangement: out of segment ids");
    wk_status st;
    if ((st = WK_GROW(R, A->ids, A->cap_ids, A->n_ids + 1)) != WK_OK ||
        (st = WK_GROW(R, A->seg, A->cap_seg, A->n_live + 1)) != WK_OK)
        return st;
    uint32_t nid = A->n_ids++, slot = A->n_live++;
    A->seg[slot] = (wk_arr_seg){a.x, a.y, dir.x / norm, dir.y / norm, len, 0.0, len, nid};
    memset(&A->ids[nid], 0, sizeof A->ids[nid]);
    A->ids[nid].slot = slot;
    invalidate_for(R, A, slot, 1.0, 0.0);
    wk_count(R, WK_VC_arrangement_inserts, 1);
    if (id) *id = nid;
    return WK_OK;
}

wk_status wk_arrangement_insert_aseg(wk_run *R, wk_arrangement *A, const wk_aseg *segs,
                                     uint32_t r) {
    for (uint32_t i = 0; i < r; i++) {
        wk_status st = wk_arrangement_insert(R, A, segs[i].a, segs[i].u, segs[i].len, NULL);
        if (st != WK_OK) return st;
    }
    return WK_OK;
}

wk_status wk_arrangement_remove(wk_run *R, wk_arrangement *A, uint32_t id) {
    if (!wk_arrangement_get(A, id)) return not_current(R, "remove", id);
    uint32_t slot = A->ids[id].slot;
    /* Entries of other caches that name this segment are not touched: ids
    ** are never reused, so a reader sees that the other segment is gone and
    ** skips the entry (cache_lookup).  Tombstoning them here cost a scan of
    ** every cache per removal, half the run time of a 10,000-vertex star
    ** with --k max. */
    cache_drop(R, A, &A->ids[id].cache);
    uint32_t last = A->n_live - 1;
    if (slot != last) {
        A->seg[slot] = A->seg[last];
        A->ids[A->seg[slot].id].slot = slot;
    }
    A->n_live--;
    A->ids[id].slot = WK_NONE;
    wk_count(R, WK_VC_arrangement_removes, 1);
    return WK_OK;
}

wk_status wk_arrangement_set_active(wk_run *R, wk_arrangement *A, uint32_t id, double lo,
                                    double hi) {
    if (!wk_arrangement_get(A, id)) return not_current(R, "set_active", id);
    uint32_t slot = A->ids[id].slot;
    wk_arr_seg *S = &A->seg[slot];
    if (!(lo >= 0.0) || !(lo <= hi) || !(hi <= S->len))
        return WK_FAIL(R, WK_EINPUT, NULL, 0,
                       "arrangement set_active: segment %u: [%.17g, %.17g] not within [0, %.17g]",
                       id, lo, hi, S->len);
    double old_lo = S->lo, old_hi = S->hi;
    S->lo = lo;
    S->hi = hi;
    if (lo < old_lo || hi > old_hi) {
        wk_arr_cache *C = &A->ids[id].cache;
        if (C->valid) wk_count(R, WK_VC_cache_invalidations, 1);
        cache_drop(R, A, C);
        invalidate_for(R, A, slot, old_lo, old_hi);
    }
    return WK_OK;
}

/* ---- the scan ---- */

/* Max-heap on (s, other) in h[0..n). */
static void sift_down(wk_crossing *h, uint32_t n, uint32_t i) {
    wk_crossing x = h[i];
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && cr_less(&h[c], &h[c + 1])) c++;
        if (!cr_less(&x, &h[c])) break;
        h[i] = h[c];
        i = c;
    }
    h[i] = x;
}

static void sift_up(wk_crossing *h, uint32_t i) {
    wk_crossing x = h[i];
    while (i > 0) {
        uint32_t p = (i - 1) / 2;
        if (!cr_less(&h[p], &x)) break;
        h[i] = h[p];
        i = p;
    }
    h[i] = x;
}

wk_status wk_arrangement_next_crossings_after(wk_run *R, wk_arrangement *A, uint32_t seg,
                                              double s_from, uint32_t after, uint32_t k,
                                              wk_crossing *out, uint32_t *count) {
    *count = 0;
    if (!wk_arrangement_get(A, seg)) return not_current(R, "query", seg);
    if (k == 0) k = 1;
    uint32_t slot = A->ids[seg].slot;
    const wk_arr_seg *Q = &A->seg[slot];
    uint32_t n = 0;
    for (uint32_t j = 0; j < A->n_live; j++) {
        if (j == slot) continue;
        const wk_arr_seg *O = &A->seg[j];
        double s, t;
        if (!wk_arrangement_crossing(Q, O, &s, &t)) continue;
        if (s < Q->lo || s > Q->hi || t < O->lo || t > O->hi) continue;
        if (!pos_less(s_from, after, s, O->id)) continue;
        wk_crossing c = {s, t, O->id};
        if (n < k) {
            out[n] = c;
            if (k > 1) sift_up(out, n);
            n++;
        } else if (cr_less(&c, &out[0])) {
            out[0] = c; /* k == 1: the running minimum; else the heap's root */
            if (k > 1) sift_down(out, n, 0);
        }
    }
    /* Heap sort the k survivors into increasing order. */
    if (k > 1)
        for (uint32_t m = n; m > 1; m--) {
            wk_crossing x = out[0];
            out[0] = out[m - 1];
            out[m - 1] = x;
            sift_down(out, m - 1, 0);
        }
    *count = n;
    wk_count(R, WK_VC_intersection_queries, 1);
    wk_count(R, WK_VC_segments_scanned, A->n_live - 1);
    return WK_OK;
}

wk_status wk_arrangement_next_crossings(wk_run *R, wk_arrangement *A, uint32_t seg, double s_from,
                                        uint32_t k, wk_crossing *out, uint32_t *count) {
    return wk_arrangement_next_crossings_after(R, A, seg, s_from, WK_NONE, k, out, count);
}

/* ---- the cache ---- */

/* The cached answer for the position (s_from, after), if the cache can
** give it: true with *c set (other = WK_NONE for "none"), false for a
** miss. */
static bool cache_lookup(const wk_arrangement *A, const wk_arr_seg *Q, const wk_arr_cache *C,
                         double s_from, uint32_t after, wk_crossing *c) {
    if (!C->valid || pos_less(s_from, after, C->from_s, C->from_id)) return false;
    for (uint32_t k = cache_upper(C, s_from, after); k < C->n; k++) {
        const wk_arr_centry *e = &C->e[k];
        if (pos_less(C->to_s, C->to_id, e->s, e->other)) return false; /* defensive */
        if (e->dead || e->s < Q->lo || e->s > Q->hi) continue;
        /* The other segment's active part may have shrunk since. */
        const wk_arr_seg *O = wk_arrangement_get(A, e->other);
        double s, t;
        if (!O || !wk_arrangement_crossing(Q, O, &s, &t) || t < O->lo || t > O->hi) continue;
        *c = (wk_crossing){e->s, t, e->other};
        return true;
    }
    if (C->to_s == INFINITY) {
        *c = (wk_crossing){INFINITY, INFINITY, WK_NONE};
        return true;
    }
    return false;
}

wk_status wk_arrangement_cache_next_after(wk_run *R, wk_arrangement *A, uint32_t seg, double s_from,
                                          uint32_t after, wk_crossing *c) {
    if (!wk_arrangement_get(A, seg)) return not_current(R, "cache query", seg);
    const wk_arr_seg *Q = &A->seg[A->ids[seg].slot];
    wk_arr_cache *C = &A->ids[seg].cache;
    if (cache_lookup(A, Q, C, s_from, after, c)) {
        wk_count(R, WK_VC_cache_hits, 1);
        return WK_OK;
    }
    wk_count(R, WK_VC_cache_misses, 1);
    cache_drop(R, A, C);
    uint32_t k = R->opt.k ? R->opt.k : 1;
    uint32_t room = k < A->n_live ? k : A->n_live;
    wk_status st = WK_GROW(R, A->scratch, A->cap_scratch, room ? room : 1);
    if (st != WK_OK) return st;
    uint32_t n;
    st = wk_arrangement_next_crossings_after(R, A, seg, s_from, after, k, A->scratch, &n);
    if (st != WK_OK) return st;
    wk_count(R, WK_VC_cache_refills, 1);
    if (n) {
        C->e = WK_NEW_ARRAY(R, wk_arr_centry, n);
        if (!C->e) return R->err.code;
        C->cap = n;
        for (uint32_t i = 0; i < n; i++)
            C->e[i] = (wk_arr_centry){A->scratch[i].s, A->scratch[i].other, 0};
    }
    C->n = n;
    C->valid = true;
    A->n_cached++;
    C->from_s = s_from;
    C->from_id = after;
    if (n < k) {
        C->to_s = INFINITY;
        C->to_id = WK_NONE;
    } else {
        C->to_s = A->scratch[n - 1].s;
        C->to_id = A->scratch[n - 1].other;
    }
    *c = n ? A->scratch[0] : (wk_crossing){INFINITY, INFINITY, WK_NONE};
    return WK_OK;
}

wk_status wk_arrangement_cache_next(wk_run *R, wk_arrangement *A, uint32_t seg, double s_from,
                                    wk_crossing *c) {
    return wk_arrangement_cache_next_after(R, A, seg, s_from, WK_NONE, c);
}

bool wk_arrangement_check(const wk_arrangement *A) {
    if (A->n_live > A->n_ids) return false;
    for (uint32_t i = 0; i < A->n_live; i++) {
        uint32_t id = A->seg[i].id;
        if (id >= A->n_ids || A->ids[id].slot != i) return false;
        const wk_arr_seg *S = &A->seg[i];
        if (!(S->lo >= 0.0 && S->lo <= S->hi && S->hi <= S->len)) return false;
    }
    uint32_t cached = 0, live = 0;
    for (uint32_t id = 0; id < A->n_ids; id++) {
        const wk_arr_id *I = &A->ids[id];
        const wk_arr_cache *C = &I->cache;
        if (I->slot != WK_NONE) {
            live++;
            if (I->slot >= A->n_live || A->seg[I->slot].id != id) return false;
        }
        if (!C->valid) {
            if (C->n || C->e) return false;
            continue;
        }
        cached++;
        if (I->slot == WK_NONE || C->n > C->cap) return false;
        for (uint32_t k = 0; k < C->n; k++) {
            const wk_arr_centry *e = &C->e[k];
            if (!pos_less(C->from_s, C->from_id, e->s, e->other)) return false;
            if (pos_less(C->to_s, C->to_id, e->s, e->other)) return false;
            if (k && !pos_less(C->e[k - 1].s, C->e[k - 1].other, e->s, e->other)) return false;
        }
    }
    return cached == A->n_cached && live == A->n_live;
}
