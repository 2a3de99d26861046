/*
** ray_shoot.c: the uniform bucket grid and ray shooting against a polygon's
** boundary (000, section 3.1: each segment of A(P) ends where its ray first
** meets the boundary).  See the design note in ray_shoot.h.
**
** Invariants of a built wk_seg_grid: start[0] = 0, start is non-decreasing,
** start[n_cells] = n_items; the ids of cell c are increasing; segment i is
** listed in cell (col, row) iff wk_seg_grid_row_span(G, a_i, b_i, row)
** returns a column range containing col (the grid is filled with that very
** function, so membership can be re-decided later with the same bits).
** Membership is conservative: every cell that comes within delta of a
** segment lists it, up to rounding errors of a few ulps of the coordinates,
** far below delta (the row's slab is widened by delta before the segment's
** x range in it is computed, so an error in a slab height only moves the
** covered range along the segment, never inside the true slab).
**
** Ray shooting correctness: the walk visits, in order of distance, the cells
** the ray passes through.  A candidate hit at distance t' has its defining
** point (the crossing, or the vertex within tol of the ray) within tol of
** the ray point at t', hence within delta = 2 tol of the cell that ray point
** lies in, so its edge is listed there.  The walk stops after a cell whose
** exit distance is >= the best distance found, so every candidate at a
** distance <= best was tested: the result is the minimum over all edges
** under the same total order as the brute force, i.e. the same bits.
*/
#include "ray_shoot.h"

#include <math.h>
#include <string.h>

/* ================================================================== grid */

void wk_seg_grid_init(wk_seg_grid *G) { memset(G, 0, sizeof *G); }

void wk_seg_grid_clear(wk_run *R, wk_seg_grid *G) {
    if (G->start) WK_FREE_ARRAY(R, G->start, (size_t)G->n_cells + 1);
    if (G->items) WK_FREE_ARRAY(R, G->items, G->n_items ? G->n_items : 1);
    if (G->row0) WK_FREE_ARRAY(R, G->row0, G->nseg ? G->nseg : 1);
    if (G->soff) WK_FREE_ARRAY(R, G->soff, (size_t)G->nseg + 1);
    if (G->span) WK_FREE_ARRAY(R, G->span, G->n_rows ? 2 * (size_t)G->n_rows : 1);
    wk_seg_grid_init(G);
}

void wk_seg_grid_rows(const wk_seg_grid *G, wk_point a, wk_point b, uint32_t *r0, uint32_t *r1) {
    double ylo = a.y < b.y ? a.y : b.y, yhi = a.y < b.y ? b.y : a.y;
    *r0 = wk_seg_grid_row(G, ylo - G->delta);
    *r1 = wk_seg_grid_row(G, yhi + G->delta);
}

/* x of segment ab at height y, ylo <= y <= yhi, a.y != b.y.  At an
** endpoint's height the endpoint's own x (no rounding there). */
static double x_at(wk_point a, wk_point b, double y) {
    if (y == a.y) return a.x;
    if (y == b.y) return b.x;
    return a.x + (y - a.y) * ((b.x - a.x) / (b.y - a.y));
}

bool wk_seg_grid_row_span(const wk_seg_grid *G, wk_point a, wk_point b, uint32_t row, uint32_t *c0,
                          uint32_t *c1) {
    double d = G->delta;
    double ylo = a.y < b.y ? a.y : b.y, yhi = a.y < b.y ? b.y : a.y;
    double xlo = a.x < b.x ? a.x : b.x, xhi = a.x < b.x ? b.x : a.x;
    /* The row's slab widened by delta, clipped to the segment's heights. */
    double s0 = G->y0 + (double)row * G->ch - d, s1 = G->y0 + (double)(row + 1) * G->ch + d;
    double lo = s0 > ylo ? s0 : ylo, hi = s1 < yhi ? s1 : yhi;
    if (lo > hi) return false;
    double x0, x1;
    if (a.y == b.y) {
        x0 = xlo;
        x1 = xhi;
    } else {
        double p = x_at(a, b, lo), q = x_at(a, b, hi);
        x0 = p < q ? p : q;
        x1 = p < q ? q : p;
        /* never beyond the segment's own extent (rounding in x_at) */
        if (x0 < xlo) x0 = xlo;
        if (x1 > xhi) x1 = xhi;
    }
    *c0 = wk_seg_grid_col(G, x0 - d);
    *c1 = wk_seg_grid_col(G, x1 + d);
    return true;
}

bool wk_seg_grid_touches(const wk_seg_grid *G, wk_point a, wk_point b, uint32_t col, uint32_t row) {
    uint32_t r0, r1, c0, c1;
    wk_seg_grid_rows(G, a, b, &r0, &r1);
    if (row < r0 || row > r1) return false;
    if (!wk_seg_grid_row_span(G, a, b, row, &c0, &c1)) return false;
    return col >= c0 && col <= c1;
}

/* Columns of segment i (endpoints a, b) in row `row` of its rows
** [r0, ...]: from the span table when there is one (filled by pass 0 with
** the same function), else computed. */
static inline bool span_of(const wk_seg_grid *G, uint32_t i, wk_point a, wk_point b, uint32_t r0,
                           uint32_t row, uint32_t *c0, uint32_t *c1) {
    if (!G->span) return wk_seg_grid_row_span(G, a, b, row, c0, c1);
    const uint32_t *sp = G->span + 2 * ((size_t)G->soff[i] + (row - r0));
    *c0 = sp[0];
    *c1 = sp[1];
    return sp[0] <= sp[1];
}

static wk_status build_fail(wk_run *R, wk_seg_grid *G) {
    wk_status st = R->err.code != WK_OK ? R->err.code : WK_ENOMEM;
    wk_seg_grid_clear(R, G);
    return st;
}

wk_status wk_seg_grid_build(wk_run *R, wk_seg_grid *G, uint32_t nseg, wk_seg_get_fn get,
                            const void *ud, wk_point lo, wk_point hi, uint32_t target_cells,
                            double delta, bool keep_spans) {
    wk_seg_grid_init(G);
    if (target_cells < 1) target_cells = 1;
    double W = hi.x - lo.x + 2.0 * delta, H = hi.y - lo.y + 2.0 * delta;
    /* Square-ish cells, about target_cells of them; a very flat box gets a
    ** single row (or column) of at most target_cells cells. */
    double cell = sqrt(W * H / (double)target_cells);
    double fx = ceil(W / cell), fy = ceil(H / cell);
    uint32_t nx = fx >= (double)target_cells ? target_cells : fx < 1.0 ? 1u : (uint32_t)fx;
    uint32_t ny = fy >= (double)target_cells ? target_cells : fy < 1.0 ? 1u : (uint32_t)fy;
    if ((uint64_t)nx * ny >= UINT32_MAX)
        return WK_FAIL(R, WK_ENOMEM, NULL, 0, "grid of %u x %u cells too large", nx, ny);
    G->x0 = lo.x - delta;
    G->y0 = lo.y - delta;
    G->nx = nx;
    G->ny = ny;
    G->cw = W / nx;
    G->ch = H / ny;
    G->delta = delta;
    G->n_cells = nx * ny;
    G->nseg = nseg;
    G->start = WK_NEW_ARRAY(R, uint32_t, (size_t)G->n_cells + 1);
    if (!G->start) return build_fail(R, G);
    uint32_t *start = G->start;
    /* Pass 0 (span table only): rows per segment, then every row's span. */
    if (keep_spans) {
        G->row0 = WK_NEW_ARRAY(R, uint32_t, nseg ? nseg : 1);
        G->soff = WK_NEW_ARRAY(R, uint32_t, (size_t)nseg + 1);
        if (!G->row0 || !G->soff) return build_fail(R, G);
        uint64_t rows = 0;
        for (uint32_t i = 0; i < nseg; i++) {
            wk_point a, b;
            get(ud, i, &a, &b);
            uint32_t r0, r1;
            wk_seg_grid_rows(G, a, b, &r0, &r1);
            G->row0[i] = r0;
            rows += r1 - r0 + 1;
            if (rows >= UINT32_MAX / 2) {
                WK_FAIL(R, WK_ENOMEM, NULL, 0, "grid span table too large");
                return build_fail(R, G);
            }
            G->soff[i + 1] = (uint32_t)rows;
        }
        G->n_rows = (uint32_t)rows;
        G->span = WK_NEW_ARRAY(R, uint32_t, rows ? 2 * rows : 1);
        if (!G->span) return build_fail(R, G);
        for (uint32_t i = 0; i < nseg; i++) {
            wk_point a, b;
            get(ud, i, &a, &b);
            uint32_t r0 = G->row0[i], nr = G->soff[i + 1] - G->soff[i];
            for (uint32_t k = 0; k < nr; k++) {
                uint32_t *sp = G->span + 2 * ((size_t)G->soff[i] + k);
                if (!wk_seg_grid_row_span(G, a, b, r0 + k, &sp[0], &sp[1])) {
                    sp[0] = 1;
                    sp[1] = 0;
                }
            }
        }
    }
    /* Pass 1: count into start[c + 1]. */
    uint64_t total = 0;
    for (uint32_t i = 0; i < nseg; i++) {
        wk_point a, b;
        get(ud, i, &a, &b);
        uint32_t r0, r1, c0, c1;
        wk_seg_grid_rows(G, a, b, &r0, &r1);
        for (uint32_t row = r0; row <= r1; row++) {
            if (!span_of(G, i, a, b, r0, row, &c0, &c1)) continue;
            for (uint32_t c = c0; c <= c1; c++) start[(size_t)row * nx + c + 1]++;
            total += c1 - c0 + 1;
        }
    }
    if (total >= UINT32_MAX) {
        WK_FAIL(R, WK_ENOMEM, NULL, 0, "grid with %llu entries too large",
                (unsigned long long)total);
        return build_fail(R, G);
    }
    for (uint32_t c = 0; c < G->n_cells; c++) start[c + 1] += start[c];
    G->items = WK_NEW_ARRAY(R, uint32_t, total ? total : 1);
    if (!G->items) return build_fail(R, G);
    G->n_items = (uint32_t)total;
    /* Pass 2: fill, using start[c] as the cursor of cell c; afterwards
    ** start[c] is the end of cell c, so shift by one. */
    for (uint32_t i = 0; i < nseg; i++) {
        wk_point a, b;
        get(ud, i, &a, &b);
        uint32_t r0, r1, c0, c1;
        wk_seg_grid_rows(G, a, b, &r0, &r1);
        for (uint32_t row = r0; row <= r1; row++) {
            if (!span_of(G, i, a, b, r0, row, &c0, &c1)) continue;
            for (uint32_t c = c0; c <= c1; c++) G->items[start[(size_t)row * nx + c]++] = i;
        }
    }
    memmove(start + 1, start, (size_t)G->n_cells * sizeof *start);
    start[0] = 0;
    return WK_OK;
}

/* ========================================================== ray shooting */

/* Total order on hits: distance, then vertex before edge interior, then
** id.  True if h comes before best. */
static inline bool hit_before(const wk_ray_hit *h, const wk_ray_hit *best) {
    if (h->t != best->t) return h->t < best->t;
    bool hv = h->vertex != WK_NONE, bv = best->vertex != WK_NONE;
    if (hv != bv) return hv;
    return (hv ? h->vertex : h->edge) < (bv ? best->vertex : best->edge);
}

static inline void offer(const wk_ray_hit *h, wk_ray_hit *best, bool *found) {
    if (!*found || hit_before(h, best)) {
        *best = *h;
        *found = true;
    }
}

/* Test edge e against the ray o + t u (see the tolerance rules in
** ray_shoot.h).  Every quantity of a vertex candidate is computed from
** the vertex alone, so both edges at a vertex offer the same bits. */
static inline void test_edge(const wk_polygon *P, double tol, wk_point o, wk_point u, uint32_t skip,
                             uint32_t e, wk_ray_hit *best, bool *found) {
    uint32_t f = wk_polygon_next(P, e);
    if (skip != WK_NONE && (e == skip || f == skip)) return;
    wk_point a = P->p[e], b = P->p[f];
    double ax = a.x - o.x, ay = a.y - o.y, bx = b.x - o.x, by = b.y - o.y;
    double ha = u.x * ay - u.y * ax, hb = u.x * by - u.y * bx; /* left of the ray: > 0 */
    double ta = u.x * ax + u.y * ay, tb = u.x * bx + u.y * by; /* along the ray */
    wk_ray_hit h;
    if (fabs(ha) <= tol && ta > 0.0) {
        h = (wk_ray_hit){ta, a, WK_NONE, e};
        offer(&h, best, found);
    }
    if (fabs(hb) <= tol && tb > 0.0) {
        h = (wk_ray_hit){tb, b, WK_NONE, f};
        offer(&h, best, found);
    }
    if ((ha > tol && hb < -tol) || (ha < -tol && hb > tol)) {
        double lam = ha / (ha - hb); /* in [0, 1]: opposite signs */
        double t = ta + lam * (tb - ta);
        if (t > 0.0) {
            h = (wk_ray_hit){t, {a.x + lam * (b.x - a.x), a.y + lam * (b.y - a.y)}, e, WK_NONE};
            offer(&h, best, found);
        }
    }
}

bool wk_ray_shoot_brute(const wk_polygon *P, double tol, wk_point o, wk_point u,
                        uint32_t from_vertex, wk_ray_hit *hit) {
    wk_ray_hit best = {0};
    bool found = false;
    for (uint32_t e = 0; e < P->n; e++) test_edge(P, tol, o, u, from_vertex, e, &best, &found);
    if (found) *hit = best;
    return found;
}

/* Entries of wk_ray_shoot's memo of tested edges (a power of 2; not a
** tolerance: 16 KiB of stack cleared per shot, about 0.2 us, against the
** edge tests it saves).  256 entries collided on large stars, whose shots
** walk beside more than 256 long edges of consecutive ids: star 3*10^5
** (133k shots), the shots were 33% of the CPU time of a finder's trace graph, M(P)
** (perf) with 256 entries, 11% with 1024 and 9% with 4096. */
#define RAY_MEMO 4096u

bool wk_ray_shoot(const wk_ray_shooter *S, wk_point o, wk_point u, uint32_t from_vertex,
                  wk_ray_hit *hit) {
    const wk_seg_grid *G = &S->G;
    /* Defensive: the walk must start in the cell holding o. */
    if (!(o.x >= G->x0 && o.x <= G->x0 + G->nx * G->cw && o.y >= G->y0 &&
          o.y <= G->y0 + G->ny * G->ch))
        return wk_ray_shoot_brute(S->P, S->tol, o, u, from_vertex, hit);
    wk_ray_hit best = {0};
    bool found = false;
    /* A long edge is listed in every cell along it, and a ray running
    ** beside it (a star's notch edges, nearly parallel to the rays of the
    ** reflex vertices between them) meets it in cell after cell: each edge
    ** is tested once per shot, as far as this small direct-mapped memo of
    ** the edges already tested tells (a collision only tests an edge again,
    ** which offers the same hit: the answer does not depend on the memo). */
    uint32_t tested[RAY_MEMO];
    memset(tested, 0xff, sizeof tested);
    uint32_t cx = wk_seg_grid_col(G, o.x), cy = wk_seg_grid_row(G, o.y);
    int sx = (u.x > 0) - (u.x < 0), sy = (u.y > 0) - (u.y < 0);
    /* At most nx + ny cells: each step moves one column or one row, always
    ** the same way. */
    for (;;) {
        uint32_t c = cy * G->nx + cx;
        for (uint32_t k = G->start[c]; k < G->start[c + 1]; k++) {
            uint32_t e = G->items[k], *memo = &tested[e & (RAY_MEMO - 1)];
            if (*memo == e) continue;
            *memo = e;
            test_edge(S->P, S->tol, o, u, from_vertex, e, &best, &found);
        }
        /* Exit distances through the cell's x and y walls, recomputed from
        ** the wall (no accumulated increments). */
        double tx = wk_grid_exit(G->x0, G->cw, cx, sx, o.x, u.x);
        double ty = wk_grid_exit(G->y0, G->ch, cy, sy, o.y, u.y);
        double texit = tx < ty ? tx : ty;
        if (found && best.t <= texit) break;
        if (tx < ty) {
            if (sx > 0 ? cx + 1 >= G->nx : cx == 0) break;
            cx = sx > 0 ? cx + 1 : cx - 1;
        } else {
            if (sy == 0 || (sy > 0 ? cy + 1 >= G->ny : cy == 0)) break;
            cy = sy > 0 ? cy + 1 : cy - 1;
        }
    }
    if (found) *hit = best;
    return found;
}

/* ========================================================== shooter */

static void edge_of(const void *ud, uint32_t i, wk_point *a, wk_point *b) {
    const wk_polygon *P = ud;
    *a = P->p[i];
    *b = P->p[wk_polygon_next(P, i)];
}

wk_status wk_ray_shooter_init(wk_run *R, wk_ray_shooter *S, const wk_polygon *P) {
    S->P = P;
    wk_seg_grid_init(&S->G);
    wk_point lo = P->p[0], hi = P->p[0];
    for (uint32_t i = 1; i < P->n; i++) {
        if (P->p[i].x < lo.x) lo.x = P->p[i].x;
        if (P->p[i].x > hi.x) hi.x = P->p[i].x;
        if (P->p[i].y < lo.y) lo.y = P->p[i].y;
        if (P->p[i].y > hi.y) hi.y = P->p[i].y;
    }
    S->tol = WK_TOL_REL * hypot(hi.x - lo.x, hi.y - lo.y);
    /* 2 tol: the tol band around the ray plus room for the rounding of the
    ** cell walls (a few ulps of the coordinates). */
    return wk_seg_grid_build(R, &S->G, P->n, edge_of, P, lo, hi, P->n, 2.0 * S->tol, false);
}

void wk_ray_shooter_clear(wk_run *R, wk_ray_shooter *S) { wk_seg_grid_clear(R, &S->G); }
