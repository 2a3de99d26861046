/*
** piece_grid.c: ray shots over a grid of the regions wavefront pieces sweep
** (design in piece_grid.h).
**
** Invariants while G->valid, at any time t in [t_b, t_e] between groups:
** every current piece (a alive, b = next(a)) has an entry (a, b) of build
** G->gen in every cell its position at t comes within margin of (it was
** listed at the build, or at a shot after the group that made it current,
** with a hull over [then, t_x], t_x = t_e or, for a fast piece, its time
** on the expiry heap, where it stays until relist_expired lists it again
** from a shot's time, before that shot reads a cell), or is on the
** overflow list, or has an end on the pending list (a fresh vertex of a
** group since the last listing; flush_pending lists those pieces before a
** grid shot reads a cell); cells of another gen hold no entries.  At most
** G->budget entries are listed per build (give_up drops the grid).
*/
#include "piece_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "motorcycle.h"
#include "ray_shoot.h"
#include "tolerance.h"

/* Time window of a build, in cells of normal motion of the pieces (weight
** times time): longer windows mean fewer builds but wider hulls.  Not a
** tolerance: a cost trade-off, measured on coastline 10^5 (README). */
#define PG_WINDOW_CELLS 1.0
/* A piece whose hull covers more cells than this (plus 4 per cell of its
** length) is tested at every grid shot instead of listed.  Not a
** tolerance: a cost bound (an O(n) hull per piece made builds quadratic on
** nearly straight reflex corners, whose vertices are very fast). */
#define PG_OVERFLOW_CELLS 64.0
/* An end of a listed piece moves at most this many cells (its speed times
** the listing's time) before the piece is listed again: a faster piece is
** listed for a shorter time than the window and goes on the expiry heap,
** and the first grid shot after that time lists it again from its own time
** if it is still current.  Not a tolerance: a cost bound.  Without it a
** sharp reflex notch (speed 10^3..10^5 on random 3*10^5, whose vertices
** are nearly collinear spikes) was listed along its whole path over the
** window, across the box: 261M entries in one build, 3.05 GB peak (README,
** Cost, session mcgrid). */
#define PG_MOVE_CELLS 2.0
/* Entries a build may list over its window (the build, the fresh pieces,
** the relistings), per input vertex, at least PG_BUDGET_MIN: the listing
** that would pass it is not made, the grid is dropped (its cells freed)
** and the shots walk cycles until they have tested twice the pieces that
** the last try cost (so a run pays at most about three times the cheaper
** of the two, as before).  Not a tolerance: a memory bound (issue 13: at
** most 1 KiB per vertex in all).  Long pieces are what passes it: a piece
** is listed in every cell along it, and on random 3*10^5 (nearly radial
** spikes about 100 cells long) even with PG_MOVE_CELLS the build listed
** 26.6M entries and every shot relisted about 10M more (README, Cost). */
#define PG_BUDGET_PER_VERTEX 8u
#define PG_BUDGET_MIN 65536u
/* A build's cost estimate before any build: entries per input vertex. */
#define PG_FIRST_EST 4u

void mc_pg_init(mc_piece_grid *G) { memset(G, 0, sizeof *G); }

void mc_pg_clear(wk_run *R, mc_piece_grid *G) {
    if (G->cells) {
        size_t nc = (size_t)G->nx * G->ny;
        for (size_t c = 0; c < nc; c++) WK_FREE_ARRAY(R, G->cells[c].e, G->cells[c].cap);
        WK_FREE_ARRAY(R, G->cells, nc);
    }
    WK_FREE_ARRAY(R, G->over, G->cap_over);
    WK_FREE_ARRAY(R, G->pending, G->cap_pending);
    WK_FREE_ARRAY(R, G->exp, G->cap_exp);
    mc_pg_init(G);
}

static inline uint32_t index_of(double f, uint32_t n) {
    if (!(f >= 0.0)) return 0;
    if (f >= (double)n) return n - 1;
    return (uint32_t)f;
}
static inline uint32_t col_of(const mc_piece_grid *G, double x) {
    return index_of((x - G->x0) / G->cw, G->nx);
}
static inline uint32_t row_of(const mc_piece_grid *G, double y) {
    return index_of((y - G->y0) / G->ch, G->ny);
}

/* The grid over the input polygon's box (relative coordinates: every
** wavefront position lies in it), about one cell per input vertex. */
static wk_status grid_alloc(wk_run *R, mc_piece_grid *G, const wk_wavefront *W) {
    const wk_polygon *P = wk_wf_polygon(W);
    wk_point lo = {INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < P->n; i++) {
        wk_point p = wk_wf_position(W, i, wk_wf_start_time(W, i));
        lo.x = fmin(lo.x, p.x);
        lo.y = fmin(lo.y, p.y);
        hi.x = fmax(hi.x, p.x);
        hi.y = fmax(hi.y, p.y);
    }
    G->margin = WK_PIECE_GRID_MARGIN * wk_wf_eps_d(W);
    double m = G->margin, Wd = hi.x - lo.x + 4.0 * m, Hd = hi.y - lo.y + 4.0 * m;
    double target = P->n < 4 ? 4.0 : (double)P->n;
    double cell = sqrt(Wd * Hd / target);
    double fx = ceil(Wd / cell), fy = ceil(Hd / cell);
    G->nx = !(fx >= 1.0) ? 1u : fx >= target ? (uint32_t)target : (uint32_t)fx;
    G->ny = !(fy >= 1.0) ? 1u : fy >= target ? (uint32_t)target : (uint32_t)fy;
    if ((uint64_t)G->nx * G->ny >= UINT32_MAX / 2)
        return WK_FAIL(R, WK_ENOMEM, NULL, 0, "piece grid of %u x %u cells too large", G->nx,
                       G->ny);
    G->x0 = lo.x - 2.0 * m;
    G->y0 = lo.y - 2.0 * m;
    G->cw = Wd / G->nx;
    G->ch = Hd / G->ny;
    double w = wk_wf_line(W, 0)->w;
    G->window = PG_WINDOW_CELLS * fmax(G->cw, G->ch) / (w > 0 ? w : 1.0);
    G->budget = (uint64_t)PG_BUDGET_PER_VERTEX * P->n;
    if (G->budget < PG_BUDGET_MIN) G->budget = PG_BUDGET_MIN;
    G->cells = WK_NEW_ARRAY(R, mc_pg_cell, (size_t)G->nx * G->ny);
    if (!G->cells) return WK_ENOMEM;
    for (size_t c = 0; c < (size_t)G->nx * G->ny; c++) G->cells[c] = (mc_pg_cell){NULL, 0, 0, 0};
    return WK_OK;
}

/* Free every cell's entries (the cells stay, empty). */
static void free_entries(wk_run *R, mc_piece_grid *G) {
    size_t nc = (size_t)G->nx * G->ny;
    for (size_t c = 0; c < nc; c++) {
        WK_FREE_ARRAY(R, G->cells[c].e, G->cells[c].cap);
        G->cells[c].n = G->cells[c].cap = 0;
    }
    G->cap_ids = 0;
}

/* A listing would have passed the budget: drop the grid, and let the
** cycle walks test twice what this build's listings cost before the next
** build. */
static void give_up(wk_run *R, mc_piece_grid *G) {
    free_entries(R, G);
    G->valid = false;
    G->full = false;
    G->n_pending = 0;
    G->n_exp = 0;
    G->n_over = 0;
    G->est = 2 * (G->listed > G->budget ? G->listed : G->budget);
    G->since = 0;
}

static wk_status push_overflow(wk_run *R, mc_piece_grid *G, uint32_t a, uint32_t b) {
    if (G->listed + 1 > G->budget) {
        G->full = true;
        return WK_OK;
    }
    if (WK_GROW(R, G->over, G->cap_over, 2 * G->n_over + 2) != WK_OK) return WK_ENOMEM;
    G->over[2 * G->n_over] = a;
    G->over[2 * G->n_over + 1] = b;
    G->n_over++;
    G->listed++;
    return WK_OK;
}

static wk_status push(wk_run *R, mc_piece_grid *G, uint32_t c, uint32_t a, uint32_t b) {
    mc_pg_cell *C = &G->cells[c];
    if (C->gen != G->gen) {
        C->gen = G->gen;
        C->n = 0;
    }
    uint32_t cap = C->cap;
    if (WK_GROW(R, C->e, C->cap, 2 * C->n + 2) != WK_OK) return WK_ENOMEM;
    G->cap_ids += C->cap - cap;
    C->e[2 * C->n] = a;
    C->e[2 * C->n + 1] = b;
    C->n++;
    G->listed++;
    return WK_OK;
}

/* The expiry heap (min by time; ties in any order: a relisting only adds
** entries, and a shot's answer does not depend on their order). */
static wk_status exp_push(wk_run *R, mc_piece_grid *G, double t, uint32_t a, uint32_t b) {
    if (WK_GROW(R, G->exp, G->cap_exp, G->n_exp + 1) != WK_OK) return WK_ENOMEM;
    uint32_t i = G->n_exp++;
    while (i > 0 && G->exp[(i - 1) / 2].t > t) {
        G->exp[i] = G->exp[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    G->exp[i] = (mc_pg_expiry){t, a, b};
    return WK_OK;
}

static mc_pg_expiry exp_pop(mc_piece_grid *G) {
    mc_pg_expiry top = G->exp[0], last = G->exp[--G->n_exp];
    uint32_t i = 0, n = G->n_exp;
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && G->exp[c + 1].t < G->exp[c].t) c++;
        if (!(G->exp[c].t < last.t)) break;
        G->exp[i] = G->exp[c];
        i = c;
    }
    if (n) G->exp[i] = last;
    return top;
}

/* When piece a -> b collapses (its ends meet along its line; they move
** linearly), or INFINITY if it does not shrink: the pair cannot outlive
** that moment (the edge event ends it), so its hull stops there, a few
** eps_t later for the engine's rounding of the event time.  Without this
** cap every short piece made by a group would be listed up to the end of
** the window (measured on coastline 10^5: 9 times the entries of the
** build).  The slack: tolerance.h. */
static double collapse_time(const wk_wavefront *W, uint32_t a, uint32_t b, double t0) {
    wk_point pa = wk_wf_position(W, a, t0), pb = wk_wf_position(W, b, t0);
    wk_point va = wk_wf_velocity(W, a), vb = wk_wf_velocity(W, b);
    const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, a));
    double s = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
    double rate = (vb.x - va.x) * L->ux + (vb.y - va.y) * L->uy;
    if (!(rate < 0)) return INFINITY;
    return t0 + (s > 0 ? s : 0) / -rate + WK_PIECE_GRID_COLLAPSE_SLACK * wk_wf_eps_t(W);
}

/* The hull of a piece's four end positions as the ten segments between
** them (the four points as degenerate ones): the hull's x range in a slab
** is the range of those segments' parts in it.  Each segment's y range and
** slope are computed once per listing, not once per row (list_piece asks
** for every row of the hull; the same bits as computing them per row). */
typedef struct hull_segs {
    double px[10], py[10], qx[10]; /* one end P, the other's x */
    double ylo[10], yhi[10], k[10]; /* k: dx / dy; NAN when flat (x range [px, qx]) */
} hull_segs;

static void hull_segs_of(hull_segs *H, const wk_point *p) {
    int n = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i; j < 4; j++, n++) {
            wk_point P = p[i], Q = p[j];
            H->px[n] = P.x;
            H->py[n] = P.y;
            H->qx[n] = Q.x;
            H->ylo[n] = P.y < Q.y ? P.y : Q.y;
            H->yhi[n] = P.y < Q.y ? Q.y : P.y;
            H->k[n] = P.y == Q.y ? NAN : (Q.x - P.x) / (Q.y - P.y);
        }
}

/* Columns [*c0, *c1] of row r that the hull (widened by margin) meets;
** false if none.  The positions are finite (list_piece checks), so the
** comparisons below are fmin / fmax without their NaN cases. */
static bool row_span(const mc_piece_grid *G, const hull_segs *H, uint32_t r, uint32_t *c0,
                     uint32_t *c1) {
    double m = G->margin;
    double s0 = G->y0 + (double)r * G->ch - m, s1 = G->y0 + (double)(r + 1) * G->ch + m;
    double xlo = INFINITY, xhi = -INFINITY;
    for (int n = 0; n < 10; n++) {
        double lo = s0 > H->ylo[n] ? s0 : H->ylo[n], hi = s1 < H->yhi[n] ? s1 : H->yhi[n];
        if (lo > hi) continue;
        double x0, x1;
        if (isnan(H->k[n])) {
            x0 = H->px[n];
            x1 = H->qx[n];
        } else {
            x0 = H->px[n] + (lo - H->py[n]) * H->k[n];
            x1 = H->px[n] + (hi - H->py[n]) * H->k[n];
        }
        double a = x0 < x1 ? x0 : x1, b = x0 < x1 ? x1 : x0;
        if (a < xlo) xlo = a;
        if (b > xhi) xhi = b;
    }
    if (!(xlo <= xhi)) return false;
    *c0 = col_of(G, xlo - m);
    *c1 = col_of(G, xhi + m);
    return true;
}

/* Rows whose spans list_piece keeps from its counting pass for its listing
** pass (a taller hull computes them again).  Not a tolerance: a stack
** buffer's size; coastline 10^5 lists 1.4 rows per piece on average. */
#define PG_SPAN_ROWS 32

/* List piece a -> b in every cell its hull over [t0, min(t_e, collapse)]
** meets (widened by margin), up to the time its faster end has moved
** PG_MOVE_CELLS cells if that is earlier (then it goes on the expiry heap;
** a piece too fast to be listed past a shot's reshoot goes on the overflow
** list); a piece whose hull would cover more than
** PG_OVERFLOW_CELLS plus 4 cells per cell of its length (a vertex of very
** high speed: nearly straight reflex corners) goes on the overflow list
** instead, which every grid shot tests. */
static wk_status list_piece(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, uint32_t a,
                            uint32_t b, double t0) {
    double t1 = fmin(G->t_e, collapse_time(W, a, b, t0));
    if (t1 < t0) t1 = t0;
    wk_point va = wk_wf_velocity(W, a), vb = wk_wf_velocity(W, b);
    double speed = fmax(hypot(va.x, va.y), hypot(vb.x, vb.y));
    double reach = PG_MOVE_CELLS * fmax(G->cw, G->ch);
    bool expires = speed * (t1 - t0) > reach;
    if (expires) {
        /* the shot that relists it reshoots WK_RAY_RESHOOT_DELAY eps_t
        ** later over the same listing: it must last longer than that */
        t1 = t0 + reach / speed;
        if (!(t1 - t0 >= 2.0 * WK_RAY_RESHOOT_DELAY * wk_wf_eps_t(W)))
            return push_overflow(R, G, a, b);
    }
    wk_point p[4] = {wk_wf_position(W, a, t0), wk_wf_position(W, b, t0),
                     wk_wf_position(W, a, t1), wk_wf_position(W, b, t1)};
    double m = G->margin, ylo = INFINITY, yhi = -INFINITY;
    for (int k = 0; k < 4; k++) {
        if (!isfinite(p[k].x) || !isfinite(p[k].y)) return push_overflow(R, G, a, b);
        ylo = fmin(ylo, p[k].y);
        yhi = fmax(yhi, p[k].y);
    }
    double len = fmax(hypot(p[1].x - p[0].x, p[1].y - p[0].y),
                      hypot(p[3].x - p[2].x, p[3].y - p[2].y));
    double cap = PG_OVERFLOW_CELLS + 4.0 * len / fmin(G->cw, G->ch);
    hull_segs H;
    hull_segs_of(&H, p);
    uint32_t r0 = row_of(G, ylo - m), r1 = row_of(G, yhi + m), c0 = 0, c1 = 0;
    uint32_t span[PG_SPAN_ROWS][2];
    bool has[PG_SPAN_ROWS];
    double cells = 0;
    for (uint32_t r = r0; r <= r1 && cells <= cap; r++) {
        bool h = row_span(G, &H, r, &c0, &c1);
        if (h) cells += (double)(c1 - c0 + 1);
        if (r - r0 < PG_SPAN_ROWS) {
            has[r - r0] = h;
            span[r - r0][0] = c0;
            span[r - r0][1] = c1;
        }
    }
    if (cells > cap) return push_overflow(R, G, a, b);
    if (G->full || (double)G->listed + cells > (double)G->budget) {
        G->full = true;
        return WK_OK;
    }
    for (uint32_t r = r0; r <= r1; r++) {
        if (r - r0 < PG_SPAN_ROWS) {
            if (!has[r - r0]) continue;
            c0 = span[r - r0][0];
            c1 = span[r - r0][1];
        } else if (!row_span(G, &H, r, &c0, &c1)) {
            continue;
        }
        for (uint32_t c = c0; c <= c1; c++)
            if (push(R, G, r * G->nx + c, a, b) != WK_OK) return WK_ENOMEM;
    }
    return expires ? exp_push(R, G, t1, a, b) : WK_OK;
}

static wk_status build(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, double t) {
    if (!G->cells && grid_alloc(R, G, W) != WK_OK) return WK_ENOMEM;
    wk_count(R, WK_VC_piece_grid_builds, 1);
    G->gen++;
    G->valid = false;
    G->t_b = t;
    G->t_e = t + G->window;
    G->listed = 0;
    G->n_over = 0;
    G->n_pending = 0; /* every alive piece is listed below */
    G->n_exp = 0;
    G->full = false;
    /* capacity left by earlier builds in other cells counts too */
    if (G->cap_ids > 4 * G->budget) free_entries(R, G);
    for (uint32_t a = 0; a < wk_wf_vertex_count(W) && !G->full; a++)
        if (wk_wf_alive(W, a) && list_piece(R, G, W, a, wk_wf_next(W, a), t) != WK_OK)
            return WK_ENOMEM;
    wk_count(R, WK_VC_piece_grid_entries, G->listed);
    if (G->full) {
        give_up(R, G);
        return WK_OK;
    }
    G->est = G->listed;
    G->since = 0;
    G->valid = true;
    return WK_OK;
}

wk_status mc_pg_after_group(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, double t) {
    if (!G->valid) return WK_OK;
    if (t > G->t_e) {
        G->valid = false;
        G->n_pending = 0;
        return WK_OK;
    }
    const uint32_t *fresh, *ended;
    uint32_t n_fresh, n_ended;
    wk_wf_last_group(W, &fresh, &n_fresh, &ended, &n_ended);
    if (n_fresh == 0) return WK_OK;
    if (WK_GROW(R, G->pending, G->cap_pending, G->n_pending + n_fresh) != WK_OK) {
        G->valid = false; /* a partial update is no index */
        G->n_pending = 0;
        return WK_ENOMEM;
    }
    memcpy(G->pending + G->n_pending, fresh, (size_t)n_fresh * sizeof *fresh);
    G->n_pending += n_fresh;
    return WK_OK;
}

static int cmp_u32(const void *a, const void *b) {
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

static bool pending_has(const mc_piece_grid *G, uint32_t v) {
    return bsearch(&v, G->pending, G->n_pending, sizeof v, cmp_u32) != NULL;
}

/* List the pieces next to the pending fresh vertices still alive, with
** hulls from t (the shot's time: they are current now, so their positions
** from t on are what the shots of this window can meet).  Each piece once:
** (f, next) for every pending f, (prev, f) unless prev is pending (a vertex
** is fresh in one group only, so the list has no repeats). */
static wk_status flush_pending(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, double t) {
    uint64_t before = G->listed;
    qsort(G->pending, G->n_pending, sizeof *G->pending, cmp_u32);
    for (uint32_t i = 0; i < G->n_pending; i++) {
        uint32_t f = G->pending[i];
        if (!wk_wf_alive(W, f)) continue;
        uint32_t p = wk_wf_prev(W, f);
        if (list_piece(R, G, W, f, wk_wf_next(W, f), t) != WK_OK ||
            (!pending_has(G, p) && list_piece(R, G, W, p, f, t) != WK_OK)) {
            G->valid = false; /* a partial update is no index */
            G->n_pending = 0;
            return WK_ENOMEM;
        }
        if (G->full) break;
    }
    G->n_pending = 0;
    wk_count(R, WK_VC_piece_grid_entries, G->listed - before);
    if (G->full) give_up(R, G);
    return WK_OK;
}

/* List again, from t, the current pieces whose listing ends before
** `later` (the shot's reshoot time). */
static wk_status relist_expired(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, double t,
                                double later) {
    uint64_t before = G->listed;
    while (G->n_exp && G->exp[0].t < later) {
        mc_pg_expiry e = exp_pop(G);
        if (!wk_wf_alive(W, e.a) || wk_wf_next(W, e.a) != e.b) continue;
        if (list_piece(R, G, W, e.a, e.b, t) != WK_OK) {
            G->valid = false; /* a partial update is no index */
            G->n_pending = 0;
            G->n_exp = 0;
            return WK_ENOMEM;
        }
        if (G->full) break;
    }
    wk_count(R, WK_VC_piece_grid_entries, G->listed - before);
    if (G->full) give_up(R, G);
    return WK_OK;
}

/* ------------------------------------------------------------- shots */

typedef struct hit {
    uint32_t a;
    double lam;
    bool at_end;
} hit;

static inline void offer(const wk_wavefront *W, wk_point o, wk_point u, uint32_t v, uint32_t a,
                         double t, double lambda0, hit *best) {
    uint32_t b = wk_wf_next(W, a);
    if (v != WK_NONE && (a == v || b == v)) return; /* v's own pieces */
    double mu, lam = wk_wf_ray_hit_piece(W, o, u, a, t, lambda0, &mu);
    if (lam < best->lam || (lam == best->lam && lam < INFINITY && a < best->a)) {
        best->lam = lam;
        best->a = a;
        best->at_end = mu < WK_RAY_END_SNAP || mu > 1 - WK_RAY_END_SNAP;
    }
}

/* wk_wf_ray_shoot's shot at one time: v's cycle with one ring, every
** alive piece with holes or without v; counts the pieces tested. */
static hit walk_cycle(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, wk_point o, wk_point u,
                      uint32_t v, double t, double lambda0) {
    hit best = {WK_NONE, INFINITY, false};
    uint64_t k = 0;
    if (wk_wf_polygon(W)->n_rings == 1 && v != WK_NONE) {
        for (uint32_t a = wk_wf_next(W, v); a != v; a = wk_wf_next(W, a), k++) {
            if (a == v || wk_wf_next(W, a) == v) continue;
            double mu, lam = wk_wf_ray_hit_piece(W, o, u, a, t, lambda0, &mu);
            if (lam < best.lam) { /* cycle order breaks ties, as the engine's */
                best.lam = lam;
                best.a = a;
                best.at_end = mu < WK_RAY_END_SNAP || mu > 1 - WK_RAY_END_SNAP;
            }
        }
    } else {
        for (uint32_t a = 0; a < wk_wf_vertex_count(W); a++)
            if (wk_wf_alive(W, a)) {
                k++;
                offer(W, o, u, v, a, t, lambda0, &best);
            }
    }
    G->since += k;
    wk_count(R, WK_VC_ray_shot_pieces, k);
    return best;
}

/* Offer the current pieces of entries e[0 .. *n) (pairs a, b); stale ones
** (not current for good: ids are never reused) are dropped. */
static void scan_entries(const wk_wavefront *W, uint32_t *e, uint32_t *n, wk_point o, wk_point u,
                         uint32_t v, double t, double lambda0, hit *best, uint64_t *k) {
    for (uint32_t i = 0; i < *n;) {
        uint32_t a = e[2 * i], b = e[2 * i + 1];
        if (!wk_wf_alive(W, a) || wk_wf_next(W, a) != b) {
            (*n)--;
            e[2 * i] = e[2 * *n];
            e[2 * i + 1] = e[2 * *n + 1];
            continue;
        }
        (*k)++;
        offer(W, o, u, v, a, t, lambda0, best);
        i++;
    }
}

/* The shot over the grid (valid at t): false if the ray starts outside
** the grid's box (then the caller walks the cycle). */
static bool walk_grid(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, wk_point o, wk_point u,
                      uint32_t v, double t, double lambda0, hit *best) {
    *best = (hit){WK_NONE, INFINITY, false};
    wk_point q = {o.x + lambda0 * u.x, o.y + lambda0 * u.y};
    if (!(q.x >= G->x0 && q.x <= G->x0 + G->nx * G->cw && q.y >= G->y0 &&
          q.y <= G->y0 + G->ny * G->ch))
        return false;
    uint32_t cx = col_of(G, q.x), cy = row_of(G, q.y);
    int sx = (u.x > 0) - (u.x < 0), sy = (u.y > 0) - (u.y < 0);
    uint64_t k = 0;
    scan_entries(W, G->over, &G->n_over, o, u, v, t, lambda0, best, &k);
    for (;;) {
        mc_pg_cell *C = &G->cells[cy * G->nx + cx];
        if (C->gen == G->gen) scan_entries(W, C->e, &C->n, o, u, v, t, lambda0, best, &k);
        /* exit distances (from o) through the cell's walls */
        double tx = wk_grid_exit(G->x0, G->cw, cx, sx, o.x, u.x);
        double ty = wk_grid_exit(G->y0, G->ch, cy, sy, o.y, u.y);
        double texit = tx < ty ? tx : ty;
        if (best->a != WK_NONE && best->lam <= texit) break;
        if (tx < ty) {
            if (sx > 0 ? cx + 1 >= G->nx : cx == 0) break;
            cx = sx > 0 ? cx + 1 : cx - 1;
        } else {
            if (sy == 0 || (sy > 0 ? cy + 1 >= G->ny : cy == 0)) break;
            cy = sy > 0 ? cy + 1 : cy - 1;
        }
    }
    wk_count(R, WK_VC_ray_shot_pieces, k);
    return true;
}

static hit shoot_at(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, wk_point o, wk_point u,
                    uint32_t v, double t, double lambda0) {
    hit h;
    if (G->valid && t >= G->t_b && t <= G->t_e && walk_grid(R, G, W, o, u, v, t, lambda0, &h))
        return h;
    return walk_cycle(R, G, W, o, u, v, t, lambda0);
}

uint32_t mc_pg_shoot(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, wk_point o, wk_point u,
                     uint32_t v, double t, double lambda0, wk_status *st) {
    *st = WK_OK;
    double later = t + WK_RAY_RESHOOT_DELAY * wk_wf_eps_t(W);
    if (G->valid && later > G->t_e) G->valid = false;
    if (!G->valid) {
        uint64_t est = G->est ? G->est : (uint64_t)PG_FIRST_EST * wk_wf_polygon(W)->n;
        /* --check-invariants (the tests' small cases) takes the grid at
        ** every shot, so that the grid path is what they compare */
        if (R->opt.check_invariants) est = 0;
        if (G->since >= est && (*st = build(R, G, W, t)) != WK_OK) G->valid = false;
    }
    /* the reshoot below (at `later`, within the window) reads the same
    ** listing: hulls from t cover it */
    if (G->valid && t >= G->t_b && G->n_pending) *st = flush_pending(R, G, W, t);
    if (G->valid && t >= G->t_b && G->n_exp && *st == WK_OK)
        *st = relist_expired(R, G, W, t, later);
    hit h = shoot_at(R, G, W, o, u, v, t, lambda0);
    if (h.a != WK_NONE && h.at_end && v != WK_NONE) {
        /* a hit at a vertex is ambiguous: again a moment later, when that
        ** vertex has moved off the ray (wk_wf_ray_shoot's rule) */
        wk_point pv = wk_wf_position(W, v, later);
        double l1 = (pv.x - o.x) * u.x + (pv.y - o.y) * u.y;
        hit g = shoot_at(R, G, W, o, u, v, later, l1);
        /* a PSLG's ray may leave into the outer face: a vertex hit that a
        ** moment later leaves nothing ahead was a contact only (at t = 0
        ** another corner of v's own node) */
        if (g.a != WK_NONE || wk_wf_polygon(W)->pslg) h = g;
    }
    return h.a;
}
