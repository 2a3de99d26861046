/*
** motorcycle_graph.c: M(P) of 002, section 2, by a time-ordered simulation
** over a uniform grid, and its brute-force twin.  Model, crash rules,
** tolerances and the algorithm are in motorcycle_graph.h.
**
** Invariants between events (the simulation state `sim`):
**   - crashed[i] == 0: m[i].len == m[i].wall_len and m[i].kind is unset;
**     crashed[i] == 1: m[i].len, kind, other / other_len or grp[i] are the
**     final crash record, except that a TRACE crash may still become
**     SIMULTANEOUS (joined by a motorcycle arriving at the same time);
**   - grp[i] != WK_NONE iff i is SIMULTANEOUS; then i is on the member list
**     of that group (head / next_member), and the group is alive; a merged
**     group is dead and has no members;
**   - grid only: every motorcycle that is alive at the heap's current key
**     has listed itself in all cells of the slabs before its cursor
**     slab[i], and its next registration (slab[i]) is queued, unless its
**     slabs are exhausted.
** The heap holds events keyed (t, kind, a, b): a registration of a at t
** (b == WK_NONE, before any crossing at the same t) or the crossing of the
** pair a < b at t = max of the two arrival times; one key per event, so
** the pop order is a total order independent of the push order.
*/
#include "motorcycle_graph.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ray_shoot.h"

/* Grid size: about this many cells per motorcycle.  Not a tolerance: a
** cost trade-off (fewer cells, more pairs tested per listing; more
** cells, more listings per trace).  Measured (session mchub2, CPU time of
** M(P), n = 10^5, seed 1): the cost of long traces was the listings, not
** the pair tests: monotone 10^5 (its origins on a circle refine the grid
** to 14 cells per motorcycle, traces cross the disc) listed 14.8M times,
** each a heap event and cache misses, for 240M pair tests of only 644k
** distinct pairs per 3*10^4 (near-parallel neighbours met again in every
** cell they share); a per-motorcycle memo of tested pairs cut the tests
** 50-fold and the time not at all.  Fewer, larger cells cut the listings,
** and the crowded cells' line index (MCG_INDEX_MIN) keeps their scans
** cheap: from 1 to 0.1, monotone 8.7 -> 3.8 s, star 3.2 -> 2.4 s, random
** 3.0 -> 2.2 s, comb and rectilinear equal (0.08 s), coastline 0.26 ->
** 0.30 s (its short traces near clustered origins like small cells; 0.03
** made it 0.40 s for monotone 2.4 s). */
#define MCG_CELLS_PER_MOTORCYCLE 0.1
/* ... times up to MCG_REFINE_MAX when the motorcycles' origins are
** clustered: with origins in a fraction f of the cells of that grid (per
** motorcycle), MCG_REFINE_OCCUPANCY / f.  A fractal coastline's reflex
** vertices crowd a vanishing share of its box (f = 0.026 at n = 10^5,
** 0.009 at 10^6) and its traces end close to their origins, so a finer
** grid cuts the pairs tested (coastline 10^6: 41.5M pairs and 11.5M queued
** events at 1 cell per motorcycle, 13.5M and 3.1M at 16); spread origins
** (star and random: f = 0.34) keep the base size, where a finer grid only
** lists the long traces into the hub in more cells (star 10^5: 42.7M pairs
** at 1, 89M at 16). */
#define MCG_REFINE_OCCUPANCY 0.25
#define MCG_REFINE_MAX 16.0
/* ... unless the traces turn out long: a refined grid that has made this
** many listings per motorcycle is dropped and the simulation starts again
** on the unrefined one (refine 1; the graph is the grid's no matter its
** size, only the work differs: the grid-vs-brute-force tests).  Clustered
** origins with short traces (the coastline: 2.0 listings per motorcycle at
** n = 10^5 on its grid 16 times finer) keep the fine grid; origins on a
** curve with traces across the box (monotone: mean trace about a quarter
** of the box, listings r^1.5: 31, 100 and 172 per motorcycle at 10^4,
** 10^5 and 3*10^5, 2.1 GB for M(P) alone at 3*10^5 and 11 GB at 10^6)
** pay at most this many for the try.  Measured (session mcmp, CPU of M(P)
** alone, monotone seed 1, load 10-15): 10^5 refine 16: 5.0M listings,
** 3.3 s, 400 MB; refine 1: 1.3M, 2.4 s, 120 MB; 3*10^5 refine 16: 25.9M,
** 28.4 s, 2.07 GB; refine 1: 6.6M, 16.1 s, 558 MB (0.03 and 0.01 cells per
** motorcycle: 3.7M and 2.2M listings but 56M and 120M pair tests, 21 and
** 48 s).  Not lower: a try costs up to this many listings' work (at 16,
** monotone 10^4 restarted and took 0.08 s instead of 0.05 s, and notched
** 10^4, 35 listings per motorcycle in a hub where pair tests dominate,
** restarted near its end and peaked 40% higher). */
#define MCG_REFINED_LISTINGS_MAX 40.0
/* Spread origins (an occupancy of at least MCG_REFINE_OCCUPANCY on a grid
** of one cell per motorcycle, the rule's first calibration: star and
** random, 0.34) get this coarser grid instead.  Their needle notches send
** long traces across the box into a hub, each listed in about sqrt(cells)
** cells, and since the scans' shortlist (short_skip) the pairs are cheap
** while each listing (a heap event, the cell's index walked bin by bin,
** its arrays cold) is not.  Measured (session mchub3, CPU time of the
** simulation, star n = 10^5, seed 1, load 10-12, +-30%): 0.43 cells per
** motorcycle (the refined 0.1) 2.5-4.9 s, 0.1 1.6-2.9 s, 0.03 1.1-1.8 s;
** random 3.4, 2.0, 1.8 s.  The clustered families (coastline, monotone,
** comb, notched: 0.03 to 0.08 on that grid) keep their refined grid:
** coastline 0.35 s refined, 1.2 s at 0.1, 1.9 s at 0.03. */
#define MCG_CELLS_PER_MOTORCYCLE_SPREAD 0.03
/* A cell listing this many motorcycles gets an index of their lines (and
** a new one each time the count doubles).  Not a tolerance: below it a
** scan of the cell's array is as cheap. */
#define MCG_INDEX_MIN 64u
#define MCG_PI 3.14159265358979323846
#define MCG_PI_2 1.57079632679489661923

/* ================================================================ events */

typedef struct mev {
    double t;   /* when */
    uint32_t a; /* registration: the motorcycle; crossing: the smaller id */
    uint32_t b; /* crossing: the larger id; WK_NONE for a registration */
} mev;

/* Total order on keys: time, registrations before crossings, ids. */
static inline bool ev_less(const mev *x, const mev *y) {
    if (x->t != y->t) return x->t < y->t;
    bool rx = x->b == WK_NONE, ry = y->b == WK_NONE;
    if (rx != ry) return rx;
    if (x->a != y->a) return x->a < y->a;
    return x->b < y->b;
}

typedef struct heap {
    mev *e;
    uint32_t size, cap;
} heap;

static wk_status heap_push(wk_run *R, heap *H, mev v) {
    if (H->size == UINT32_MAX - 1) return WK_FAIL(R, WK_ENOMEM, NULL, 0, "too many events");
    if (WK_GROW(R, H->e, H->cap, H->size + 1) != WK_OK) return WK_ENOMEM;
    uint32_t i = H->size++;
    while (i > 0) {
        uint32_t p = (i - 1) / 2;
        if (!ev_less(&v, &H->e[p])) break;
        H->e[i] = H->e[p];
        i = p;
    }
    H->e[i] = v;
    return WK_OK;
}

static mev heap_pop(heap *H) {
    mev top = H->e[0], v = H->e[--H->size];
    uint32_t i = 0, n = H->size;
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && ev_less(&H->e[c + 1], &H->e[c])) c++;
        if (!ev_less(&H->e[c], &v)) break;
        H->e[i] = H->e[c];
        i = c;
    }
    if (n > 0) H->e[i] = v;
    return top;
}

/* ============================================================ the state */

typedef struct sim_group {
    wk_point p;
    double t;
    uint32_t head, tail, count; /* member list through next_member */
    bool alive;                 /* false once merged into another */
    uint32_t on_other;
    double on_len;
    uint32_t on_edge, on_vertex;
} sim_group;

/* What a crossing needs of a motorcycle (meet): one compact array by id,
** read by the cell scans (56 bytes a motorcycle instead of m[]'s 88).
** clen is the crash length once crashed (m[id].len, final), INFINITY while
** alive: a scan's pair test then reads this copy alone, not crashed[] and
** m[] as well (in a hub most listed motorcycles have crashed).
** bound: a length that the motorcycle's final crash length will not exceed
** (by more than rounding), INFINITY until known: the smallest distance
** of a "sure" crash found by a pair test (see test_pair), whose event the
** grid pushes in the crossing's cell (or the motorcycle crashes earlier).
** A crossing beyond bound + 2 eps_d is then a no-op whenever it comes, so
** it is not pushed, and the crowded cells' scans skip the lines that can
** only cross the motorcycle there (cell_scan). */
typedef struct geo {
    wk_point o, u;
    double wall_len;
    double clen;
    double bound;
    uint32_t id;
} geo;

/* A crowded cell's index of its lines by direction and offset (see
** cell_scan and line_key): bucket (b, c) chains, through line[].next, the
** lines of canonical angle bin b (bmin[b] .. bmax[b] their actual angles)
** and offset bin c. */
/* A listing: the motorcycle's id and its line in the cell's frame, rounded
** to floats: n . (p - C) = c, n = (-u.y, u.x), C the cell's centre, and
** s = u . (C - o), the distance along u of C's foot (see short_skip: a scan
** decides most pairs from these 20 bytes, read in sequence, and the crash
** length, instead of loading geo[id] at random). */
typedef struct lrec {
    float nx, ny, c, s;
    uint32_t id;
} lrec;

typedef struct ix_line {
    uint32_t next;
    lrec rec; /* L->e[k], beside next: a chain walk reads one array */
} ix_line;

typedef struct cell_index {
    uint32_t gt, gh, built; /* bins in angle and offset; lines when built */
    uint32_t cap;           /* of line */
    double th0, dth;        /* angle bins: th0 + [b, b + 1) dth, clamped */
    double cx, cy, rho;     /* the cell's centre and the radius of its disk */
    double px, py;          /* the hub point (see hub_point), else cx, cy */
    double *bmin, *bmax;    /* gt */
    double *hmax;           /* gt: the largest distance from (px, py) of
                               the lines of each angle bin */
    uint32_t *cmin, *cmax;  /* gt: the occupied offset bins of each angle
                               bin lie in cmin[b] .. cmax[b] (none when
                               cmin > cmax), so a scan skips the empty
                               ones (a hub's lines all pass near its centre:
                               most of the 4 sqrt(k) offset bins are empty) */
    double *trig;           /* 4 gt: cos, sin of bmin and bmax */
    uint32_t *head;         /* gt * gh */
    ix_line *line;          /* cap */
} cell_index;

typedef struct cell_list {
    lrec *e; /* the listings, in order */
    uint32_t n, cap;
    cell_index *ix; /* NULL below MCG_INDEX_MIN lines and in the outer cells */
} cell_list;

typedef struct sim {
    wk_run *R;
    wk_motorcycle *m;
    uint32_t r;
    double eps_d, eps_t;
    uint8_t *crashed;      /* r */
    uint32_t *grp;         /* r: group or WK_NONE */
    uint32_t *next_member; /* r */
    sim_group *groups;
    uint32_t n_groups, cap_groups;
    heap H;
    uint64_t pairs;
    /* grid only */
    bool grid;
    double g0[2], cw[2], delta;
    uint32_t nc[2];        /* columns, rows */
    cell_list *cells;      /* nc[0] * nc[1]: the motorcycles listed there */
    geo *geo;              /* r */
    double *clen;          /* r: geo[i].clen, compact (short_skip) */
    uint64_t n_listed;
    uint64_t max_listed;   /* a refined grid's budget (MCG_REFINED_LISTINGS_MAX),
                              else UINT64_MAX */
    bool over_budget;      /* the refined grid passed it: start again */
    uint32_t *slab;        /* r: next slab along the major axis */
    uint32_t *slab_end;    /* r: last slab (inclusive) */
} sim;

static inline double tau(const wk_motorcycle *m, double d) { return wk_motorcycle_time_at(m, d); }

/* Whether i and j reach their crossing one after the other (arrival times
** ti, tj): more than eps_t apart, or apart by more than eps_d of travel of
** either (a finite speed; a degenerate vertex's INFINITY has tau = 0 on its
** whole trace and keeps the time rule).  The engine's own rule for such
** fast vertices (wavefront.c defers an event whose vertex is more than
** eps_d away at the group's time): at speed 1e5 eps_t is 1e-4 of travel,
** 100 eps_d.  Star n = 10^6 seed 1 (issue 13; reduced to the 8-gon
** tests/data/degenerate/mc_fast_valleys_near_simultaneous.wpoly): two needle
** valleys' motorcycles (speeds 9.5e4) cross at the centre 8.3e-10 apart
** (eps_t 1.1e-9): one SIMULTANEOUS group ended both traces there, but the
** first one's vertex runs on 8e-5 past the crossing before the other
** arrives, and 120 units further (naive: its reflex arc ends at t = 0.0035),
** off its trace: no split was ever offered for it, it was still alive when
** the queue ran empty and the reference answered. */
static bool sequential(const sim *S, uint32_t i, double ti, uint32_t j, double tj) {
    double dt = fabs(ti - tj);
    if (dt > S->eps_t) return true;
    double vi = S->m[i].speed, vj = S->m[j].speed;
    double v = isfinite(vi) && isfinite(vj) ? fmax(vi, vj) : isfinite(vi) ? vi : isfinite(vj) ? vj : 0;
    return dt * v > S->eps_d;
}

/* ======================================================= the candidates */

/* Where motorcycles i < j meet (see the header's candidates): distances
** *di, *dj clamped to [0, wall_len], the point *x.  A function of (i, j)
** and the motorcycles' start data alone. */
static inline geo geo_of(const sim *S, uint32_t i) {
    const wk_motorcycle *m = &S->m[i];
    return (geo){m->o, m->u, m->wall_len, INFINITY, INFINITY, i};
}

/* The same from the copies a (of the smaller id) and b. */
static bool meet_geo(const sim *S, const geo *a, const geo *b, double *di, double *dj,
                     wk_point *x) {
    double eps = S->eps_d;
    double dx = b->o.x - a->o.x, dy = b->o.y - a->o.y;
    /* Two motorcycles from one point (a PSLG's terminal: its two corners;
    ** a polygon's vertices are distinct) leave it into different angular
    ** gaps: they share the origin only, which is no crash. */
    if (dx == 0 && dy == 0) return false;
    double cr = a->u.x * b->u.y - a->u.y * b->u.x;
    double s, t;
    if (fabs(cr) > WK_MCG_PARALLEL_SIN) {
        s = (dx * b->u.y - dy * b->u.x) / cr;
        t = (dx * a->u.y - dy * a->u.x) / cr;
        if (!(s >= -eps && s <= a->wall_len + eps && t >= -eps && t <= b->wall_len + eps))
            return false;
        *x = (wk_point){a->o.x + s * a->u.x, a->o.y + s * a->u.y};
    } else {
        double h = a->u.x * dy - a->u.y * dx; /* b's origin off a's line */
        if (fabs(h) > eps) return false;
        double p = a->u.x * dx + a->u.y * dy; /* ... and along it */
        if (a->u.x * b->u.x + a->u.y * b->u.y > 0) {
            /* Same sense: the one behind reaches the front one's origin,
            ** which the front one left at time 0. */
            if (p >= 0) {
                s = p;
                t = 0;
                *x = b->o;
            } else {
                s = 0;
                t = -p;
                *x = a->o;
            }
        } else {
            if (p <= 0) return false; /* moving apart */
            /* Head-on: the point both reach at the same time. */
            double sa = S->m[a->id].speed, sb = S->m[b->id].speed;
            bool ia = sa == INFINITY, ib = sb == INFINITY;
            s = ia && ib ? 0.5 * p : ia ? p : ib ? 0.0 : p * (sa / (sa + sb));
            t = p - s;
            *x = (wk_point){a->o.x + s * a->u.x, a->o.y + s * a->u.y};
        }
        if (!(s <= a->wall_len + eps && t <= b->wall_len + eps)) return false;
    }
    *di = s < 0 ? 0 : s > a->wall_len ? a->wall_len : s;
    *dj = t < 0 ? 0 : t > b->wall_len ? b->wall_len : t;
    return true;
}

static bool meet(const sim *S, uint32_t i, uint32_t j, double *di, double *dj, wk_point *x) {
    geo a = geo_of(S, i), b = geo_of(S, j);
    return meet_geo(S, &a, &b, di, dj, x);
}

static inline double event_time(const sim *S, uint32_t i, uint32_t j, double di, double dj) {
    double ti = tau(&S->m[i], di), tj = tau(&S->m[j], dj);
    return ti > tj ? ti : tj;
}

/* ============================================================== crashes */

static void crash_trace(sim *S, uint32_t l, double dl, uint32_t w, double dw) {
    wk_motorcycle *m = &S->m[l];
    S->crashed[l] = 1;
    m->len = dl;
    if (S->geo) S->geo[l].clen = S->clen[l] = dl;
    m->kind = WK_MCG_TRACE;
    m->other = w;
    m->other_len = dw;
}

static wk_status new_group(sim *S, wk_point x, double t, uint32_t *g) {
    if (WK_GROW(S->R, S->groups, S->cap_groups, S->n_groups + 1) != WK_OK) return WK_ENOMEM;
    *g = S->n_groups++;
    S->groups[*g] = (sim_group){x, t, WK_NONE, WK_NONE, 0, true, WK_NONE, 0.0, WK_NONE, WK_NONE};
    return WK_OK;
}

static void link_member(sim *S, uint32_t g, uint32_t i) {
    sim_group *G = &S->groups[g];
    S->grp[i] = g;
    S->next_member[i] = WK_NONE;
    if (G->tail == WK_NONE)
        G->head = i;
    else
        S->next_member[G->tail] = i;
    G->tail = i;
    G->count++;
}

/* i (alive, or crashed at the group's point) becomes a member of g, and
** brings the trace it had crashed into (when it had) and its wall (when
** its point is its wall point) to the group. */
static void join(sim *S, uint32_t g, uint32_t i, double d) {
    wk_motorcycle *m = &S->m[i];
    sim_group *G = &S->groups[g];
    if (!S->crashed[i]) {
        S->crashed[i] = 1;
        m->len = d;
        if (S->geo) S->geo[i].clen = S->clen[i] = d;
    } else if (m->kind == WK_MCG_TRACE && G->on_other == WK_NONE) {
        G->on_other = m->other;
        G->on_len = m->other_len;
    }
    if (m->len >= m->wall_len - S->eps_d && G->on_edge == WK_NONE && G->on_vertex == WK_NONE) {
        G->on_edge = m->wall_edge;
        G->on_vertex = m->wall_vertex;
    }
    m->kind = WK_MCG_SIMULTANEOUS;
    m->other = WK_NONE;
    m->other_len = 0.0;
    link_member(S, g, i);
}

/* Merge the younger of groups g, h into the older. */
static void merge(sim *S, uint32_t g, uint32_t h) {
    if (h < g) {
        uint32_t k = g;
        g = h;
        h = k;
    }
    sim_group *A = &S->groups[g], *B = &S->groups[h];
    for (uint32_t i = B->head; i != WK_NONE;) {
        uint32_t nx = S->next_member[i];
        link_member(S, g, i);
        i = nx;
    }
    if (A->on_other == WK_NONE) {
        A->on_other = B->on_other;
        A->on_len = B->on_len;
    }
    if (A->on_edge == WK_NONE && A->on_vertex == WK_NONE) {
        A->on_edge = B->on_edge;
        A->on_vertex = B->on_vertex;
    }
    B->alive = false;
    B->head = B->tail = WK_NONE;
    B->count = 0;
}

enum { ST_ALIVE, ST_AT, ST_BEFORE, ST_BEYOND };

static int state_at(const sim *S, uint32_t i, double d) {
    if (!S->crashed[i]) return ST_ALIVE;
    double len = S->m[i].len;
    if (len < d - S->eps_d) return ST_BEFORE;
    if (len > d + S->eps_d) return ST_BEYOND;
    return ST_AT;
}

/* l crashes into w's trace at the crossing, unless it is l's wall point
** (the WALL crash wins there). */
static void loser(sim *S, uint32_t l, double dl, uint32_t w, double dw) {
    if (dl >= S->m[l].wall_len - S->eps_d) return;
    crash_trace(S, l, dl, w, dw);
}

/* The crossing event of i < j (the rules of the header). */
static wk_status process_crossing(sim *S, uint32_t i, uint32_t j) {
    double di, dj;
    wk_point x;
    if (!meet(S, i, j, &di, &dj, &x)) return WK_OK; /* defensive: pushed only if they meet */
    double ti = tau(&S->m[i], di), tj = tau(&S->m[j], dj);
    if (sequential(S, i, ti, j, tj)) {
        uint32_t w = ti < tj ? i : j, l = ti < tj ? j : i;
        double dw = ti < tj ? di : dj, dl = ti < tj ? dj : di;
        if (S->crashed[l]) return WK_OK;
        if (state_at(S, w, dw) == ST_BEFORE) return WK_OK;
        loser(S, l, dl, w, dw);
        return WK_OK;
    }
    int si = state_at(S, i, di), sj = state_at(S, j, dj);
    if (si == ST_BEFORE || sj == ST_BEFORE) return WK_OK;
    if (si == ST_BEYOND || sj == ST_BEYOND) {
        if (si == ST_BEYOND && sj == ST_ALIVE) loser(S, j, dj, i, di);
        if (sj == ST_BEYOND && si == ST_ALIVE) loser(S, i, di, j, dj);
        return WK_OK;
    }
    double T = ti > tj ? ti : tj;
    uint32_t gi = S->grp[i], gj = S->grp[j], g;
    if (si == ST_ALIVE && sj == ST_ALIVE) {
        if (new_group(S, x, T, &g) != WK_OK) return WK_ENOMEM;
        join(S, g, i, di);
        join(S, g, j, dj);
    } else if (si == ST_AT && sj == ST_AT) {
        if (gi == WK_NONE && gj == WK_NONE) {
            if (new_group(S, x, T, &g) != WK_OK) return WK_ENOMEM;
            join(S, g, i, di);
            join(S, g, j, dj);
        } else if (gi == WK_NONE) {
            join(S, gj, i, di);
        } else if (gj == WK_NONE) {
            join(S, gi, j, dj);
        } else if (gi != gj) {
            merge(S, gi, gj);
        }
    } else {
        /* One alive, one at x. */
        uint32_t at = si == ST_AT ? i : j, al = si == ST_AT ? j : i;
        double dat = si == ST_AT ? di : dj, dal = si == ST_AT ? dj : di;
        g = S->grp[at];
        if (g == WK_NONE) {
            if (new_group(S, x, T, &g) != WK_OK) return WK_ENOMEM;
            join(S, g, at, dat);
        }
        join(S, g, al, dal);
    }
    return WK_OK;
}

/* ================================================================= grid */

static inline uint32_t grid_index(const sim *S, int k, double v) {
    double f = (v - S->g0[k]) / S->cw[k];
    if (!(f >= 0.0)) return 0;
    if (f >= (double)S->nc[k]) return S->nc[k] - 1;
    return (uint32_t)f;
}

static inline uint32_t cell_of(const sim *S, wk_point p) {
    return grid_index(S, 1, p.y) * S->nc[0] + grid_index(S, 0, p.x);
}

static inline int major_axis(const wk_motorcycle *m) { return fabs(m->u.x) >= fabs(m->u.y) ? 0 : 1; }

/* The distance range [*d0, *d1] of motorcycle i's bounding segment inside
** slab s (of its major axis k) widened by delta; the outer slabs reach to
** infinity. */
static void slab_range(const sim *S, uint32_t i, uint32_t s, double *d0, double *d1) {
    const wk_motorcycle *m = &S->m[i];
    int k = major_axis(m);
    double o = k == 0 ? m->o.x : m->o.y, u = k == 0 ? m->u.x : m->u.y;
    double lo = s == 0 ? -INFINITY : S->g0[k] + (double)s * S->cw[k] - S->delta;
    double hi = s + 1 == S->nc[k] ? INFINITY : S->g0[k] + (double)(s + 1) * S->cw[k] + S->delta;
    double a = (lo - o) / u, b = (hi - o) / u;
    double lo_d = a < b ? a : b, hi_d = a < b ? b : a;
    *d0 = lo_d > 0 ? lo_d : 0;
    *d1 = hi_d < m->wall_len ? hi_d : m->wall_len;
    if (*d1 < *d0) *d1 = *d0;
}

static wk_status push_registration(sim *S, uint32_t i) {
    double d0, d1;
    slab_range(S, i, S->slab[i], &d0, &d1);
    return heap_push(S->R, &S->H, (mev){tau(&S->m[i], d0), i, WK_NONE});
}

/* The pair of the listing motorcycle i (copy gi, alive) and the listed
** copy gj, tested in cell `cell`: its event is pushed when the crossing lies
** in the cell, unless it is a no-op whenever it comes:
**   - j crashed before x (clen < d_j - eps_d; final): BEFORE, or a crashed
**     loser;
**   - x lies beyond bound + 2 eps_d of i or of j (see geo): that one has
**     crashed by then, no more than rounding past its bound, so it is
**     BEFORE there (a crashed loser, or a winner that never reached x).
** A sure crash sets i's bound: j crashed at or beyond x (not BEFORE), j
** reached x more than eps_t before i does and x is not i's wall point, so
** process_crossing crashes i there if it is still alive (the sequential
** rule), and i's trace ends no later.  Its event is pushed by the scan of
** x's cell, which both list before it comes (here, when x lies in this
** cell; else it was or will be tested there: the same pair, the same x),
** unless i crashes earlier or a sure crash nearer on i's trace dominates
** it; so the bound holds whatever cell found it. */
static wk_status test_pair(sim *S, geo *gi, const geo *gj, uint32_t cell) {
    uint32_t i = gi->id, j = gj->id, a = i < j ? i : j, b = i < j ? j : i;
    double da, db;
    wk_point x;
    S->pairs++;
    double lim_i = gi->bound + 2.0 * S->eps_d, lim_j = gj->bound + 2.0 * S->eps_d;
    if (gj->clen < INFINITY || lim_i < INFINITY || lim_j < INFINITY) {
        /* The rules below decided from the two distances alone, computed
        ** by meet_geo's very expressions, before the crossing point and
        ** its cell: in a hub most listed motorcycles have crashed and most
        ** crossings lie beyond their crash points. */
        const geo *A = i < j ? gi : gj, *B = i < j ? gj : gi;
        double cr = A->u.x * B->u.y - A->u.y * B->u.x;
        if (fabs(cr) > WK_MCG_PARALLEL_SIN) {
            double dx = B->o.x - A->o.x, dy = B->o.y - A->o.y;
            double sa = (dx * B->u.y - dy * B->u.x) / cr, tb = (dx * A->u.y - dy * A->u.x) / cr;
            double tj = j == B->id ? tb : sa, ti = j == B->id ? sa : tb;
            double dj = tj < 0 ? 0 : tj > gj->wall_len ? gj->wall_len : tj;
            double di = ti < 0 ? 0 : ti > gi->wall_len ? gi->wall_len : ti;
            if (gj->clen < dj - S->eps_d || lim_j < dj || lim_i < di) return WK_OK;
            /* The no-op rule below (a crashed j, one after the other),
            ** here before meet_geo: it sets no bound either (that wants
            ** tj < ti and di below the bound). */
            if (gj->clen < INFINITY) {
                double ui = tau(&S->m[i], di), uj = tau(&S->m[j], dj);
                if (sequential(S, i, ui, j, uj) &&
                    (uj > ui || (gi->bound < INFINITY && ui > tau(&S->m[i], gi->bound))))
                    return WK_OK;
            }
        }
    }
    if (!(i < j ? meet_geo(S, gi, gj, &da, &db, &x) : meet_geo(S, gj, gi, &da, &db, &x)))
        return WK_OK;
    double di = i == a ? da : db, dj = i == a ? db : da;
    if (gj->clen < INFINITY && !(gj->clen < dj - S->eps_d) && di < gi->bound &&
        !(di >= S->m[i].wall_len - S->eps_d)) {
        double ti = tau(&S->m[i], di), tj = tau(&S->m[j], dj);
        if (sequential(S, i, ti, j, tj) && tj < ti) gi->bound = di;
    }
    if (gi->bound + 2.0 * S->eps_d < di || lim_j < dj || cell_of(S, x) != cell) return WK_OK;
    if (gj->clen < dj - S->eps_d) return WK_OK;
    if (gj->clen < INFINITY) {
        /* j has crashed (for good).  If i and j reach x one after the
        ** other, process_crossing has a loser only: j, crashed already (a
        ** no-op), or i, which is crashed by then when x lies strictly later
        ** on its trace than its bound: the sure crash's event (time
        ** tau(bound), pushed as that rule says) pops before this one and
        ** crashes i if nothing did before.  So the event is a no-op and is
        ** not pushed.  The notched hub (issue 13, session mchub4): r/4
        ** traces cross within 1e-12 of one point, a scan there meets about
        ** k listed traces that have crashed at the point, each crossing
        ** within 2 eps_d of the bound, and pushed each (1.1G tests at
        ** n = 10^5). */
        double ti = tau(&S->m[i], di), tj = tau(&S->m[j], dj);
        if (sequential(S, i, ti, j, tj) &&
            (tj > ti || (gi->bound < INFINITY && ti > tau(&S->m[i], gi->bound))))
            return WK_OK;
    }
    return heap_push(S->R, &S->H, (mev){event_time(S, a, b, da, db), a, b});
}

/* Canonical angle in [0, pi) of g's line and the signed offset of (cx, cy)
** from it (flipped with the direction). */
static inline void line_key(const geo *g, double cx, double cy, double *th, double *h) {
    double t = atan2(g->u.y, g->u.x);
    double o = g->u.x * (cy - g->o.y) - g->u.y * (cx - g->o.x);
    if (t < 0) {
        t += MCG_PI;
        o = -o;
    }
    if (t >= MCG_PI) { /* the direction of angle 0 is the flipped one */
        t = 0.0;
        o = -o;
    }
    *th = t;
    *h = o;
}

static inline uint32_t bin_of(double v, double v0, double w, uint32_t n) {
    double f = (v - v0) / w;
    if (!(f >= 0.0)) return 0;
    if (f >= (double)n) return n - 1;
    return (uint32_t)f;
}

static void index_free(wk_run *R, cell_index *X) {
    if (!X) return;
    WK_FREE_ARRAY(R, X->bmin, X->gt);
    WK_FREE_ARRAY(R, X->bmax, X->gt);
    WK_FREE_ARRAY(R, X->hmax, X->gt);
    WK_FREE_ARRAY(R, X->cmin, X->gt);
    WK_FREE_ARRAY(R, X->cmax, X->gt);
    WK_FREE_ARRAY(R, X->trig, (size_t)4 * X->gt);
    WK_FREE_ARRAY(R, X->head, (size_t)X->gt * X->gh);
    WK_FREE_ARRAY(R, X->line, X->cap);
    WK_FREE_ARRAY(R, X, 1);
}

/* Line k of L (already in L->e) into L's index. */
static wk_status index_add(sim *S, cell_list *L, uint32_t k) {
    cell_index *X = L->ix;
    if (k >= X->cap) {
        uint32_t cap = L->cap; /* > k, a power of 2 below UINT32_MAX / 2 */
        ix_line *l = wk_realloc(S->R, X->line, (size_t)X->cap * sizeof *l, (size_t)cap * sizeof *l);
        if (!l) return WK_ENOMEM;
        X->line = l;
        X->cap = cap;
    }
    double th, h;
    line_key(&S->geo[L->e[k].id], X->cx, X->cy, &th, &h);
    uint32_t b = bin_of(th, X->th0, X->dth, X->gt);
    uint32_t c = bin_of(h, -X->rho, 2.0 * X->rho / X->gh, X->gh);
    X->line[k] = (ix_line){X->head[b * X->gh + c], L->e[k]};
    X->head[b * X->gh + c] = k;
    const geo *g = &S->geo[L->e[k].id];
    double hp = fabs(g->u.x * (X->py - g->o.y) - g->u.y * (X->px - g->o.x));
    if (hp > X->hmax[b]) X->hmax[b] = hp;
    if (c < X->cmin[b]) X->cmin[b] = c;
    if (c > X->cmax[b]) X->cmax[b] = c;
    if (th < X->bmin[b]) {
        X->bmin[b] = th;
        X->trig[4 * b] = cos(th);
        X->trig[4 * b + 1] = sin(th);
    }
    if (th > X->bmax[b]) {
        X->bmax[b] = th;
        X->trig[4 * b + 2] = cos(th);
        X->trig[4 * b + 3] = sin(th);
    }
    return WK_OK;
}

/* X's hub point (px, py): the point nearest to L's lines in the
** least-squares sense, when it lies within 2 rho of the cell's centre,
** else the centre.  In a hub (the star's: thousands of near-radial traces
** passing within about 0.03 of one point, in the cell or next to it) the
** lines' distances from it are small, which makes cell_scan's bound on
** where two lines can cross tight; any point is correct, only the
** pruning's strength depends on it. */
static void hub_point(const sim *S, const cell_list *L, cell_index *X) {
    X->px = X->cx;
    X->py = X->cy;
    double a00 = 0, a01 = 0, a11 = 0, b0 = 0, b1 = 0;
    for (uint32_t k = 0; k < L->n; k++) {
        const geo *g = &S->geo[L->e[k].id];
        double nx = -g->u.y, ny = g->u.x;
        double c = nx * (g->o.x - X->cx) + ny * (g->o.y - X->cy);
        a00 += nx * nx;
        a01 += nx * ny;
        a11 += ny * ny;
        b0 += nx * c;
        b1 += ny * c;
    }
    double det = a00 * a11 - a01 * a01;
    if (!(det > 1e-6 * (a00 + a11) * (a00 + a11))) return;
    double px = (a11 * b0 - a01 * b1) / det, py = (a00 * b1 - a01 * b0) / det;
    double off = hypot(px, py);
    if (!(off <= 2.0 * X->rho)) return;
    X->px += px;
    X->py += py;
}

/* A new index of L's lines (replacing the old), over their angle range;
** none for the outer cells, whose crossings may lie outside the grid's
** box (grid_index clamps). */
static wk_status index_build(sim *S, cell_list *L, uint32_t cell) {
    uint32_t cx = cell % S->nc[0], cy = cell / S->nc[0];
    if (cx == 0 || cy == 0 || cx + 1 >= S->nc[0] || cy + 1 >= S->nc[1]) return WK_OK;
    index_free(S->R, L->ix);
    L->ix = NULL;
    cell_index *X = WK_NEW_ARRAY(S->R, cell_index, 1);
    if (!X) return WK_ENOMEM;
    L->ix = X;
    uint32_t g = (uint32_t)ceil(sqrt((double)L->n));
    X->gt = g;
    X->gh = 4 * g;
    X->built = L->n;
    X->cap = L->cap;
    X->cx = S->g0[0] + ((double)cx + 0.5) * S->cw[0];
    X->cy = S->g0[1] + ((double)cy + 0.5) * S->cw[1];
    X->rho = 0.5 * hypot(S->cw[0], S->cw[1]);
    hub_point(S, L, X);
    X->bmin = WK_NEW_ARRAY(S->R, double, X->gt);
    X->bmax = WK_NEW_ARRAY(S->R, double, X->gt);
    X->hmax = WK_NEW_ARRAY(S->R, double, X->gt);
    X->cmin = WK_NEW_ARRAY(S->R, uint32_t, X->gt);
    X->cmax = WK_NEW_ARRAY(S->R, uint32_t, X->gt);
    X->trig = WK_NEW_ARRAY(S->R, double, (size_t)4 * X->gt);
    X->head = WK_NEW_ARRAY(S->R, uint32_t, (size_t)X->gt * X->gh);
    X->line = WK_NEW_ARRAY(S->R, ix_line, X->cap);
    if (!X->bmin || !X->bmax || !X->hmax || !X->cmin || !X->cmax || !X->trig || !X->head ||
        !X->line)
        return WK_ENOMEM;
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t k = 0; k < L->n; k++) {
        double th, h;
        line_key(&S->geo[L->e[k].id], X->cx, X->cy, &th, &h);
        lo = th < lo ? th : lo;
        hi = th > hi ? th : hi;
    }
    X->th0 = lo;
    X->dth = hi > lo ? (hi - lo) / X->gt : 1.0;
    for (uint32_t b = 0; b < X->gt; b++) {
        X->bmin[b] = INFINITY;
        X->bmax[b] = -INFINITY;
        X->hmax[b] = 0.0;
        X->cmin[b] = UINT32_MAX;
        X->cmax[b] = 0;
    }
    for (size_t q = 0; q < (size_t)X->gt * X->gh; q++) X->head[q] = WK_NONE;
    for (uint32_t k = 0; k < L->n; k++)
        if (index_add(S, L, k) != WK_OK) return WK_ENOMEM;
    /* The chains relocated bucket by bucket, each in its order, to
    ** consecutive slots 0 .. built - 1 (the lines added later take slots
    ** built.. as before): a scan then reads a bucket's links from adjacent
    ** slots instead of one cache line per link (the links were the hot loads
    ** of cell_scan, perf). */
    ix_line *nl = WK_NEW_ARRAY(S->R, ix_line, X->cap);
    if (!nl) return WK_ENOMEM;
    uint32_t pos = 0;
    for (size_t q = 0; q < (size_t)X->gt * X->gh; q++) {
        uint32_t k = X->head[q];
        if (k == WK_NONE) continue;
        X->head[q] = pos;
        for (; k != WK_NONE; k = X->line[k].next, pos++)
            nl[pos] = (ix_line){X->line[k].next == WK_NONE ? WK_NONE : pos + 1, X->line[k].rec};
    }
    WK_FREE_ARRAY(S->R, X->line, X->cap);
    X->line = nl;
    return WK_OK;
}

/* The centre of cell (col, row). */
static inline void cell_centre(const sim *S, uint32_t cell, double *cx, double *cy) {
    *cx = S->g0[0] + ((double)(cell % S->nc[0]) + 0.5) * S->cw[0];
    *cy = S->g0[1] + ((double)(cell / S->nc[0]) + 0.5) * S->cw[1];
}

/* g's listing in the cell of centre (cx, cy). */
static inline lrec listing(const geo *g, double cx, double cy) {
    double nx = -g->u.y, ny = g->u.x;
    return (lrec){(float)nx, (float)ny, (float)(nx * (g->o.x - cx) + ny * (g->o.y - cy)),
                  (float)(g->u.x * (cx - g->o.x) + g->u.y * (cy - g->o.y)), g->id};
}

/* A scan's shortlist: the listing motorcycle's line n . q = c (q = p - C,
** C the cell's centre, doubles), the cell's half sides, and the margin
** numerator (see short_skip). */
typedef struct shortlist {
    bool on;
    double nx, ny, c, s, hx, hy, margin;
} shortlist;

static void shortlist_start(const sim *S, uint32_t cell, const geo *gi, shortlist *F) {
    uint32_t col = cell % S->nc[0], row = cell / S->nc[0];
    *F = (shortlist){0};
    /* the outer cells reach to infinity (grid_index clamps): never
    ** shortlisted */
    F->on = col > 0 && row > 0 && col + 1 < S->nc[0] && row + 1 < S->nc[1];
    if (!F->on) return;
    double cx, cy;
    cell_centre(S, cell, &cx, &cy);
    F->nx = -gi->u.y;
    F->ny = gi->u.x;
    F->c = F->nx * (gi->o.x - cx) + F->ny * (gi->o.y - cy);
    F->s = gi->u.x * (cx - gi->o.x) + gi->u.y * (cy - gi->o.y);
    F->hx = 0.5 * S->cw[0];
    F->hy = 0.5 * S->cw[1];
    double ext = fmax(fabs(S->g0[0]), fabs(S->g0[1])) +
                 hypot(S->cw[0] * S->nc[0], S->cw[1] * S->nc[1]);
    double rho = hypot(F->hx, F->hy);
    F->margin = WK_MCG_SHORTLIST_REL * (rho + S->delta) + S->delta + WK_MCG_SHORTLIST_EXT * ext;
}

/* True when the pair of the scanning motorcycle and the listing r is a
** no-op that test_pair would only count: it neither pushes the pair nor
** sets a bound.  Decided from the rounded lines' crossing q (in the cell's
** frame) and the listed motorcycle's crash length cl (S->clen):
**   - q lies outside the cell by more than the margin and r's motorcycle
**     has not crashed: then the computed crossing (meet_geo) does not lie
**     in the cell (no push), and only a crashed listed trace sets a bound;
**   - q lies more than the margin plus 2 eps_d beyond cl along r's line:
**     r's motorcycle stopped before the crossing (BEFORE; or the crossing
**     lies past r's wall and they do not meet), which pushes nothing and
**     sets no bound, wherever q lies.
** The margin: rounding to floats moves r's line by at most about
** 2e-7 (|q| + rho + delta) near q (|dn| <= 8.4e-8, |dc| <= 6e-8 |c|, |c|
** <= rho + delta for a line listed in the cell), so q by at most sqrt(2)
** times that over |det| (det the 2x2 system's, of the rounded data: the
** bound holds for the perturbed system's inverse); delta covers a
** collinear pair's meeting point (within eps_d of both lines), the
** WK_MCG_SHORTLIST_EXT term the rounding of meet_geo's crossing and of
** cell_of (ulps of the box's coordinates over |sin D|); along r, s and u
** add 6e-8 |s| and 8.4e-8 |q|.  WK_MCG_SHORTLIST_REL keeps 5 times those
** factors.  |det| at or below WK_MCG_SHORTLIST_SIN: not decided here. */
static inline bool short_skip(const sim *S, const shortlist *F, const geo *gi, const lrec *r) {
    double nx = r->nx, ny = r->ny, c = r->c;
    double det = F->nx * ny - F->ny * nx, ad = fabs(det);
    if (!(ad > WK_MCG_SHORTLIST_SIN)) return false;
    double qx = (F->c * ny - F->ny * c) / det, qy = (F->nx * c - nx * F->c) / det;
    double qn = fabs(qx) + fabs(qy);
    double eq = (F->margin + WK_MCG_SHORTLIST_REL * qn) / ad;
    if (gi->bound < INFINITY) {
        double di = F->s + F->ny * qx - F->nx * qy - eq;
        if (fmin(di, gi->wall_len) > gi->bound + 2.0 * S->eps_d) return true;
    }
    double cl = S->clen[r->id];
    if (cl == INFINITY) return !(fabs(qx) <= F->hx + eq && fabs(qy) <= F->hy + eq);
    double s = r->s, t = s + ny * qx - nx * qy;
    return t - (eq + WK_MCG_SHORTLIST_REL * (fabs(s) + qn)) > cl + 2.0 * S->eps_d;
}

/* Test gi against every motorcycle listed in L (cell `cell`), or, when L
** is indexed, against those whose line can cross gi's line in the index's
** disk (reference point C, radius rho; it holds the cell): with canonical
** angles (difference D = th_j - th_i) and offsets h of C, two lines cross
** at distance r from C only if |h_i - h_j cos D| <= r |sin D|.  So an angle
** bin whose D range [bmin - th_i, bmax - th_i] misses +-pi/2 (cos of one
** sign, between cmin and cmax, |sin| at most smax) holds candidates only
** with h_j cos D in h_i -+ (rho smax + sigma): the offset bins of h_j
** between the four quotients.  sigma (1e-9 of the box, plus 4 eps_d)
** covers the rounding of the computed crossing (about 1e-16 of the box
** over |sin D|: 1e-16 of the box on this scale) and of the keys; skipped
** pairs cannot have their computed crossing in the cell, so they are
** pairs the full scan would not push.
**
** Pruning by gi's bound (see geo, test_pair): the crossing X of two lines
** at distances h_i, h_j from the hub point P lies within
** 2 max(h_i, h_j) / |sin D| of P (the inverse of the 2x2 system of the two
** unit normals has norm 1 / sqrt(1 - |cos D|) <= sqrt(2) / |sin D|), so at
** a distance along gi of at least d_P - (2 max(h_i, hmax[b]) + sigma) /
** smin - sigma, d_P the distance of P's foot, smin the least |sin D| of the
** bin (less 1e-14 for its rounding).  A bin whose bound lies beyond gi's bound + 2 eps_d (and
** below its wall_len, past which distances clamp) holds only no-op pairs
** and is skipped.  The angle bins are visited from gi's outwards (bins
** cyclic, as the canonical angles wrap at pi): in a hub the nearest
** directions cross gi farthest from C, that is first, and the first crash
** into a crashed trace bounds gi, so the rest of the hub is skipped (star
** 10^5: the centre cell's pairs 19.0M -> 0.8M, all pairs 42.7M -> 21.4M,
** the same graph). */
static wk_status cell_scan(sim *S, cell_list *L, uint32_t cell, geo *gi) {
    cell_index *X = L->ix;
    shortlist F;
    shortlist_start(S, cell, gi, &F);
    if (!X) {
        for (uint32_t e = 0; e < L->n; e++) {
            const lrec *r = &L->e[e];
            if (F.on && short_skip(S, &F, gi, r)) continue;
            if (test_pair(S, gi, &S->geo[r->id], cell) != WK_OK) return WK_ENOMEM;
        }
        return WK_OK;
    }
    double ext = fmax(fabs(S->g0[0]), fabs(S->g0[1])) +
                 hypot(S->cw[0] * S->nc[0], S->cw[1] * S->nc[1]);
    double sigma = 1e-9 * ext + 4.0 * S->eps_d;
    double thi, hi_;
    line_key(gi, X->cx, X->cy, &thi, &hi_);
    double ci = cos(thi), si = sin(thi);
    double hw = 2.0 * X->rho / X->gh;
    double dP = (X->px - gi->o.x) * gi->u.x + (X->py - gi->o.y) * gi->u.y;
    double hP = fabs(gi->u.x * (X->py - gi->o.y) - gi->u.y * (X->px - gi->o.x));
    uint32_t bi = bin_of(thi, X->th0, X->dth, X->gt);
    for (uint32_t step = 0; step < X->gt; step++) {
        uint32_t off = (step + 1) / 2 % X->gt;
        uint32_t b = step & 1 ? (bi + off) % X->gt : (bi + X->gt - off) % X->gt;
        if (!(X->bmin[b] <= X->bmax[b])) continue;
        double D0 = X->bmin[b] - thi, D1 = X->bmax[b] - thi;
        /* cos, sin of D0 and D1 from those of the bin's bounds (a few
        ** ulps: far below sigma's share). */
        const double *tg = X->trig + 4 * b;
        double cs0 = tg[0] * ci + tg[1] * si, cs1 = tg[2] * ci + tg[3] * si;
        double sn0 = tg[1] * ci - tg[0] * si, sn1 = tg[3] * ci - tg[2] * si;
        double lim = gi->bound + 2.0 * S->eps_d;
        if (lim < gi->wall_len && !(D0 <= 0 && D1 >= 0)) {
            double smin = fmin(fabs(sn0), fabs(sn1)) - 1e-14;
            if (smin > 2.0 * WK_MCG_PARALLEL_SIN &&
                dP - (2.0 * fmax(hP, X->hmax[b]) + sigma) / smin - sigma > lim)
                continue;
        }
        uint32_t c0 = 0, c1 = X->gh - 1;
        bool full = (D0 <= MCG_PI_2 && D1 >= MCG_PI_2) || (D0 <= -MCG_PI_2 && D1 >= -MCG_PI_2);
        if (!full) {
            double cmin = cs0 < cs1 ? cs0 : cs1, cmax = cs0 < cs1 ? cs1 : cs0;
            if (D0 <= 0 && D1 >= 0) cmax = 1.0;
            double smax = fmax(fabs(sn0), fabs(sn1));
            if (fmin(fabs(cmin), fabs(cmax)) < 1e-3 || (cmin < 0) != (cmax < 0)) {
                full = true;
            } else {
                double lo = hi_ - X->rho * smax - sigma, hi = hi_ + X->rho * smax + sigma;
                double q[4] = {lo / cmin, lo / cmax, hi / cmin, hi / cmax};
                double wlo = q[0], whi = q[0];
                for (int t = 1; t < 4; t++) {
                    wlo = q[t] < wlo ? q[t] : wlo;
                    whi = q[t] > whi ? q[t] : whi;
                }
                wlo -= sigma;
                whi += sigma;
                c0 = bin_of(wlo, -X->rho, hw, X->gh);
                c1 = bin_of(whi, -X->rho, hw, X->gh);
            }
        }
        if (c0 < X->cmin[b]) c0 = X->cmin[b];
        if (c1 > X->cmax[b]) c1 = X->cmax[b];
        for (uint32_t c = c0; c <= c1; c++)
            for (uint32_t k = X->head[b * X->gh + c]; k != WK_NONE; k = X->line[k].next) {
                const lrec *r = &X->line[k].rec;
                if (F.on && short_skip(S, &F, gi, r)) continue;
                if (test_pair(S, gi, &S->geo[r->id], cell) != WK_OK) return WK_ENOMEM;
            }
    }
    return WK_OK;
}

/* Motorcycle i lists itself in the cells of its current slab, testing the
** motorcycles already listed there, then queues its next slab. */
static wk_status process_registration(sim *S, uint32_t i) {
    if (S->crashed[i]) return WK_OK;
    const wk_motorcycle *m = &S->m[i];
    int k = major_axis(m), q = 1 - k;
    uint32_t s = S->slab[i];
    double d0, d1;
    slab_range(S, i, s, &d0, &d1);
    double oq = q == 0 ? m->o.x : m->o.y, uq = q == 0 ? m->u.x : m->u.y;
    double p0 = oq + d0 * uq, p1 = oq + d1 * uq;
    uint32_t c0 = grid_index(S, q, (p0 < p1 ? p0 : p1) - S->delta);
    uint32_t c1 = grid_index(S, q, (p0 < p1 ? p1 : p0) + S->delta);
    geo *gi = &S->geo[i];
    for (uint32_t c = c0; c <= c1; c++) {
        uint32_t cell = k == 0 ? c * S->nc[0] + s : s * S->nc[0] + c;
        cell_list *L = &S->cells[cell];
        if (cell_scan(S, L, cell, gi) != WK_OK) return WK_ENOMEM;
        if (L->n == L->cap) {
            /* Doubling from 2 (most cells list a few motorcycles). */
            if (L->cap >= UINT32_MAX / 2)
                return WK_FAIL(S->R, WK_ENOMEM, NULL, 0, "too many motorcycles in a cell");
            uint32_t cap = L->cap ? 2 * L->cap : 2;
            lrec *e = wk_realloc(S->R, L->e, (size_t)L->cap * sizeof *e, (size_t)cap * sizeof *e);
            if (!e) return WK_ENOMEM;
            L->e = e;
            L->cap = cap;
        }
        double ccx, ccy;
        cell_centre(S, cell, &ccx, &ccy);
        L->e[L->n++] = listing(gi, ccx, ccy);
        if (++S->n_listed > S->max_listed) S->over_budget = true;
        if (L->ix && index_add(S, L, L->n - 1) != WK_OK) return WK_ENOMEM;
        if (L->n >= MCG_INDEX_MIN && L->n >= 2 * (L->ix ? L->ix->built : 0) &&
            index_build(S, L, cell) != WK_OK)
            return WK_ENOMEM;
    }
    if (s == S->slab_end[i]) return WK_OK;
    int u_sign = (k == 0 ? m->u.x : m->u.y) > 0 ? 1 : -1;
    S->slab[i] = u_sign > 0 ? s + 1 : s - 1;
    return push_registration(S, i);
}

/* How much finer than MCG_CELLS_PER_MOTORCYCLE the grid is made (see
** MCG_REFINE_OCCUPANCY): the share of the cells of the coarse grid over the
** box (W x H from lo) that hold a motorcycle's origin, per motorcycle. */
static wk_status origin_occupancy(sim *S, wk_point lo, double W, double H, double target,
                                  double *refine, double *occupancy) {
    *refine = 1.0;
    *occupancy = -1.0;
    if (S->r < 64 || target < 1.0) return WK_OK;
    double cell = sqrt(W * H / target);
    double fx = ceil(W / cell), fy = ceil(H / cell);
    if (!(fx >= 1.0 && fy >= 1.0 && fx * fy <= 4.0 * target + 4.0 * (fx + fy))) return WK_OK;
    uint32_t nx = (uint32_t)fx, ny = (uint32_t)fy;
    uint8_t *occ = WK_NEW_ARRAY(S->R, uint8_t, (size_t)nx * ny);
    if (!occ) return WK_ENOMEM;
    memset(occ, 0, (size_t)nx * ny);
    uint32_t k = 0;
    for (uint32_t i = 0; i < S->r; i++) {
        double x = (S->m[i].o.x - (lo.x - S->delta)) / cell;
        double y = (S->m[i].o.y - (lo.y - S->delta)) / cell;
        uint32_t cx = !(x >= 0) ? 0 : x >= fx ? nx - 1 : (uint32_t)x;
        uint32_t cy = !(y >= 0) ? 0 : y >= fy ? ny - 1 : (uint32_t)y;
        uint8_t *c = &occ[(size_t)cy * nx + cx];
        if (!*c) {
            *c = 1;
            k++;
        }
    }
    WK_FREE_ARRAY(S->R, occ, (size_t)nx * ny);
    double f = (double)k / S->r;
    *occupancy = f;
    double q = MCG_REFINE_OCCUPANCY / f;
    *refine = q < 1.0 ? 1.0 : q > MCG_REFINE_MAX ? MCG_REFINE_MAX : q;
    return WK_OK;
}

/* The grid over the box [lo, hi] (relative coordinates, containing every
** bounding segment), the cursors, and every motorcycle's first
** registration. */
static wk_status grid_start(sim *S, wk_point lo, wk_point hi, bool may_refine) {
    double d = S->delta;
    double W = hi.x - lo.x + 2.0 * d, H = hi.y - lo.y + 2.0 * d;
    double target = MCG_CELLS_PER_MOTORCYCLE * (double)S->r;
    double refine, f1, f;
    S->max_listed = UINT64_MAX;
    S->over_budget = false;
    S->n_listed = 0;
    if (origin_occupancy(S, lo, W, H, (double)S->r, &refine, &f1) != WK_OK) return WK_ENOMEM;
    if (f1 >= MCG_REFINE_OCCUPANCY) {
        target = MCG_CELLS_PER_MOTORCYCLE_SPREAD * (double)S->r;
    } else if (may_refine) {
        if (origin_occupancy(S, lo, W, H, target, &refine, &f) != WK_OK) return WK_ENOMEM;
        target *= refine;
        if (refine > 1.0) S->max_listed = (uint64_t)(MCG_REFINED_LISTINGS_MAX * (double)S->r);
    }
    if (target < 1.0) target = 1.0;
    double cell = sqrt(W * H / target);
    double fx = ceil(W / cell), fy = ceil(H / cell);
    S->nc[0] = !(fx >= 1.0) ? 1u : fx >= target ? (uint32_t)target : (uint32_t)fx;
    S->nc[1] = !(fy >= 1.0) ? 1u : fy >= target ? (uint32_t)target : (uint32_t)fy;
    if ((uint64_t)S->nc[0] * S->nc[1] >= UINT32_MAX / 2)
        return WK_FAIL(S->R, WK_ENOMEM, NULL, 0, "grid of %u x %u cells too large", S->nc[0],
                       S->nc[1]);
    S->g0[0] = lo.x - d;
    S->g0[1] = lo.y - d;
    S->cw[0] = W / S->nc[0];
    S->cw[1] = H / S->nc[1];
    uint32_t cells = S->nc[0] * S->nc[1];
    S->cells = WK_NEW_ARRAY(S->R, cell_list, cells);
    S->geo = WK_NEW_ARRAY(S->R, geo, S->r);
    S->clen = WK_NEW_ARRAY(S->R, double, S->r);
    S->slab = WK_NEW_ARRAY(S->R, uint32_t, S->r);
    S->slab_end = WK_NEW_ARRAY(S->R, uint32_t, S->r);
    if (!S->cells || !S->geo || !S->clen || !S->slab || !S->slab_end) return WK_ENOMEM;
    for (uint32_t i = 0; i < S->r; i++) {
        S->geo[i] = geo_of(S, i);
        S->clen[i] = INFINITY;
    }
    /* The cells start empty: WK_NEW_ARRAY zeroes them ({NULL, 0, 0, NULL}),
    ** and a second pass over the refined grid (16 cells per motorcycle on a
    ** coastline) cost 1-2% of the run. */
    for (uint32_t i = 0; i < S->r; i++) {
        const wk_motorcycle *m = &S->m[i];
        int k = major_axis(m);
        double o = k == 0 ? m->o.x : m->o.y, u = k == 0 ? m->u.x : m->u.y;
        double e = o + m->wall_len * u, sg = u > 0 ? 1.0 : -1.0;
        S->slab[i] = grid_index(S, k, o - sg * d);
        S->slab_end[i] = grid_index(S, k, e + sg * d);
        if (push_registration(S, i) != WK_OK) return WK_ENOMEM;
    }
    return WK_OK;
}

/* All pairs' events up front. */
static wk_status brute_start(sim *S) {
    for (uint32_t i = 0; i < S->r; i++)
        for (uint32_t j = i + 1; j < S->r; j++) {
            double di, dj;
            wk_point x;
            S->pairs++;
            if (!meet(S, i, j, &di, &dj, &x)) continue;
            if (heap_push(S->R, &S->H, (mev){event_time(S, i, j, di, dj), i, j}) != WK_OK)
                return WK_ENOMEM;
        }
    return WK_OK;
}

/* The events in order; stops early (with S->over_budget) when a refined
** grid passes its listing budget. */
static wk_status run_events(sim *S) {
    while (S->H.size > 0 && !S->over_budget) {
        mev e = heap_pop(&S->H);
        wk_status st =
            e.b == WK_NONE ? process_registration(S, e.a) : process_crossing(S, e.a, e.b);
        if (st != WK_OK) return st;
    }
    return WK_OK;
}

/* The grid's part of the state (cells, copies, cursors). */
static void grid_clear(sim *S) {
    wk_run *R = S->R;
    if (S->cells) {
        size_t cells = (size_t)S->nc[0] * S->nc[1];
        for (size_t c = 0; c < cells; c++) {
            WK_FREE_ARRAY(R, S->cells[c].e, S->cells[c].cap);
            index_free(R, S->cells[c].ix);
        }
        WK_FREE_ARRAY(R, S->cells, cells);
        S->cells = NULL;
    }
    WK_FREE_ARRAY(R, S->geo, S->r);
    WK_FREE_ARRAY(R, S->clen, S->r);
    WK_FREE_ARRAY(R, S->slab, S->r);
    WK_FREE_ARRAY(R, S->slab_end, S->r);
    S->geo = NULL;
    S->clen = NULL;
    S->slab = S->slab_end = NULL;
}

static void sim_clear(sim *S) {
    wk_run *R = S->R;
    WK_FREE_ARRAY(R, S->crashed, S->r);
    WK_FREE_ARRAY(R, S->grp, S->r);
    WK_FREE_ARRAY(R, S->next_member, S->r);
    WK_FREE_ARRAY(R, S->groups, S->cap_groups);
    WK_FREE_ARRAY(R, S->H.e, S->H.cap);
    grid_clear(S);
}

/* Back to the state before the first event (the refined grid passed its
** budget): every motorcycle alive with its wall crash (shoot_all's
** record), no group, no event, no grid; the pairs tested stay counted. */
static void sim_restart(sim *S) {
    grid_clear(S);
    S->H.size = 0;
    S->n_groups = 0;
    for (uint32_t i = 0; i < S->r; i++) {
        wk_motorcycle *m = &S->m[i];
        S->crashed[i] = 0;
        S->grp[i] = S->next_member[i] = WK_NONE;
        m->len = m->wall_len;
        m->kind = WK_MCG_WALL;
        m->other = WK_NONE;
        m->other_len = 0.0;
        m->group = WK_NONE;
    }
}

/* ============================================================ the rays */

/* A PSLG's cap (a terminal's edge of length 0, engine/pslg.c) or a polygon
** edge of length 0 (none: polygons have distinct consecutive vertices). */
static bool is_cap(const wk_polygon *P, uint32_t e) {
    return P->pslg && P->edge_of && P->edge_of[e] == WK_NONE;
}

/* The corner v turns right (reflex), exactly.  A polygon's vertex: its
** two neighbours (wk_polygon_is_reflex).  A PSLG's corner next to a cap
** has a neighbour at its own point (the terminal's other corner), so the
** points say "straight"; the cap turns its segment's direction by exactly
** 90 degrees clockwise (its stored direction is (dy, -dx)), so both
** corners of a terminal are reflex: 002's two motorcycles per terminal. */
static bool corner_is_reflex(wk_run *R, const wk_polygon *P, uint32_t v) {
    if (P->pslg && (is_cap(P, v) || is_cap(P, wk_polygon_prev(P, v)))) return true;
    return R ? wk_polygon_is_reflex_counted(R, P, v) : wk_polygon_is_reflex(P, v);
}

/* A motorcycle starts at v when the wavefront's vertex at v is reflex:
** exactly reflex and its edges not parallel or antiparallel below the
** wavefront's bar (wk_vertex_start: a vertex between edges parallel below
** WK_PARALLEL_SIN moves with its edges and traces no reflex arc, a
** stress finding: such a vertex's instant trace blocked a real motorcycle,
** whose vertex then outlived its trace). */
static bool launches(wk_run *R, const wk_polygon *P, uint32_t v) {
    if (!corner_is_reflex(R, P, v)) return false;
    wk_offset_line la, lb;
    wk_point o = {0, 0}, vel;
    wk_offset_line_of_edge_at(P, wk_polygon_prev(P, v), o, &la);
    wk_offset_line_of_edge_at(P, v, o, &lb);
    return wk_vertex_velocity(&la, &lb, &vel) == WK_VEL_REGULAR;
}

/* Direction and speed of reflex vertex v (coordinates relative to c). */
static void motion(const wk_polygon *P, uint32_t v, wk_point c, wk_motorcycle *m) {
    wk_offset_line la, lb;
    wk_offset_line_of_edge_at(P, wk_polygon_prev(P, v), c, &la);
    wk_offset_line_of_edge_at(P, v, c, &lb);
    wk_point vel;
    wk_velocity_kind kind = wk_vertex_velocity(&la, &lb, &vel);
    double dx, dy, speed = hypot(vel.x, vel.y);
    if (kind == WK_VEL_ANTIPARALLEL) {
        /* A zero-width spike: the vertex runs back along it. */
        dx = la.ux - lb.ux;
        dy = la.uy - lb.uy;
        speed = INFINITY;
    } else if (kind == WK_VEL_REGULAR) {
        dx = vel.x;
        dy = vel.y;
    } else {
        /* Straight or collinear below the parallel bar yet reflex by the
        ** exact test: along the mean normal, unbounded speed. */
        dx = la.nx + lb.nx;
        dy = la.ny + lb.ny;
        speed = INFINITY;
    }
    double len = hypot(dx, dy);
    m->u = (wk_point){dx / len, dy / len};
    m->speed = speed;
}

/* A ray that meets nothing starts within tol of an edge other than its own
** two (a tiny edge next to its vertex): the shooter ignores hits at t <= 0.
** Its first boundary point is then its origin up to tol: the nearest
** endpoint w of the closest such edge, at max(0, projection of w).  False
** if no edge is that close. */
static bool hit_at_origin(const wk_polygon *Q, double tol, uint32_t v, wk_point u, wk_ray_hit *h) {
    uint32_t prev = wk_polygon_prev(Q, v);
    wk_point a = Q->p[v];
    double best = INFINITY;
    uint32_t bw = WK_NONE;
    for (uint32_t e = 0; e < Q->n; e++) {
        if (e == v || e == prev) continue;
        uint32_t f = wk_polygon_next(Q, e);
        wk_point p = Q->p[e], q = Q->p[f];
        /* a PSLG's node is one corner per angular gap, all at one point:
        ** the edges at the node only touch the ray's origin */
        if (Q->pslg && ((p.x == a.x && p.y == a.y) || (q.x == a.x && q.y == a.y))) continue;
        double dx = q.x - p.x, dy = q.y - p.y, l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? ((a.x - p.x) * dx + (a.y - p.y) * dy) / l2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        double d = hypot(p.x + t * dx - a.x, p.y + t * dy - a.y);
        if (d <= tol && d < best) {
            best = d;
            bw = hypot(p.x - a.x, p.y - a.y) <= hypot(q.x - a.x, q.y - a.y) ? e : f;
        }
    }
    if (bw == WK_NONE) return false;
    double t = (Q->p[bw].x - a.x) * u.x + (Q->p[bw].y - a.y) * u.y;
    *h = (wk_ray_hit){t > 0 ? t : 0, Q->p[bw], WK_NONE, bw};
    return true;
}

/* The length of an escaping motorcycle's trace (a PSLG's ray that meets no
** wall): the distance it covers up to the time after which the wavefront
** takes no event, R->opt.until or else WK_PSLG_DEFAULT_EVENTS_REL diagonals
** over the smallest weight (engine/wavefront_horizon.c), with a margin of
** WK_PSLG_HORIZON_MARGIN of that time and diagonals.  Crashes later than
** that time change nothing the wavefront uses (a crash at time T only ends
** a trace after T), so the graph up to it is M(G) up to it. */
static double escape_len(const wk_run *R, const wk_polygon *P, double speed) {
    double scale = wk_polygon_scale(P), wmin = INFINITY;
    for (uint32_t e = 0; e < P->n; e++) wmin = fmin(wmin, P->w[e]);
    double T = R->opt.until > 0 ? R->opt.until : WK_PSLG_DEFAULT_EVENTS_REL * scale / wmin;
    if (speed == INFINITY) return WK_PSLG_MAX_HORIZON_REL * scale;
    return (1 + WK_PSLG_HORIZON_MARGIN) * (speed * T + scale);
}

/* The stored edge on the other side of a PSLG segment: twin[e] for every
** stored edge e that is not a cap (engine/pslg.c stores each segment as
** two half-edges of opposite direction).  NULL for a polygon. */
static wk_status pslg_twins(wk_run *R, const wk_polygon *P, uint32_t **out) {
    *out = NULL;
    if (!P->pslg) return WK_OK;
    uint32_t *first = WK_NEW_ARRAY(R, uint32_t, P->n_graph_edges ? P->n_graph_edges : 1);
    uint32_t *twin = WK_NEW_ARRAY(R, uint32_t, P->n);
    if (!first || !twin) {
        if (first) WK_FREE_ARRAY(R, first, P->n_graph_edges ? P->n_graph_edges : 1);
        if (twin) WK_FREE_ARRAY(R, twin, P->n);
        return R->err.code ? R->err.code : WK_ENOMEM;
    }
    for (uint32_t k = 0; k < P->n_graph_edges; k++) first[k] = WK_NONE;
    for (uint32_t e = 0; e < P->n; e++) {
        twin[e] = WK_NONE;
        uint32_t k = P->edge_of[e];
        if (k == WK_NONE) continue;
        if (first[k] == WK_NONE) {
            first[k] = e;
        } else {
            twin[e] = first[k];
            twin[first[k]] = e;
        }
    }
    WK_FREE_ARRAY(R, first, P->n_graph_edges ? P->n_graph_edges : 1);
    *out = twin;
    return WK_OK;
}

/* The motorcycles of P (relative to c) with their wall hits, shot on the
** translated copy Q.  A PSLG's segment is two walls at one place (its
** half-edges): the one facing the motorcycle is the one whose left side
** (the side its offset line sweeps) the ray comes from, i.e. the ray turns
** right across it.  A PSLG's ray that meets no wall escapes (the outer
** face): its trace ends at escape_len, no wall. */
static wk_status shoot_all(wk_run *R, const wk_polygon *P, const wk_polygon *Q, wk_point c,
                           wk_motorcycle *m, uint32_t r) {
    wk_ray_shooter sh;
    uint32_t *twin = NULL;
    wk_status st = pslg_twins(R, P, &twin);
    if (st != WK_OK) return st;
    if ((st = wk_ray_shooter_init(R, &sh, Q)) != WK_OK) {
        if (twin) WK_FREE_ARRAY(R, twin, P->n);
        return st;
    }
    for (uint32_t i = 0, j = 0; i < P->n && j < r; i++) {
        if (!launches(R, P, i)) continue;
        wk_motorcycle *g = &m[j++];
        g->vertex = i;
        g->o = Q->p[i];
        motion(P, i, c, g);
        wk_ray_hit h;
        if (!wk_ray_shoot(&sh, g->o, g->u, i, &h) &&
            !wk_ray_shoot_brute(Q, sh.tol, g->o, g->u, i, &h) &&
            !hit_at_origin(Q, sh.tol, i, g->u, &h)) {
            if (P->pslg) {
                h = (wk_ray_hit){escape_len(R, P, g->speed), {0, 0}, WK_NONE, WK_NONE};
            } else {
                wk_ray_shooter_clear(R, &sh);
                return WK_FAIL(R, WK_EALGO, P->name, 0,
                               "ray of reflex vertex %u (%.17g, %.17g) meets no wall", i,
                               P->p[i].x, P->p[i].y);
            }
        }
        if (twin && h.edge != WK_NONE && twin[h.edge] != WK_NONE) {
            wk_point d = wk_polygon_edge_dir(P, h.edge);
            if (d.x * g->u.y - d.y * g->u.x > 0) h.edge = twin[h.edge];
        }
        g->wall_len = h.t;
        g->len = h.t;
        g->wall_edge = h.edge;
        g->wall_vertex = h.vertex;
        g->kind = WK_MCG_WALL;
        g->other = WK_NONE;
        g->other_len = 0.0;
        g->group = WK_NONE;
    }
    wk_ray_shooter_clear(R, &sh);
    if (twin) WK_FREE_ARRAY(R, twin, P->n);
    return WK_OK;
}

/* ============================================================ finishing */

static int cmp_u32(const void *a, const void *b) {
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

static int cmp_steiner(const void *a, const void *b) {
    const wk_motorcycle_steiner *x = a, *y = b;
    if (x->d != y->d) return x->d < y->d ? -1 : 1;
    return x->other < y->other ? -1 : x->other > y->other;
}

/* Call f(ud, i, d, k) for every Steiner entry (k ends on i's trace at d). */
typedef void (*steiner_fn)(void *ud, uint32_t i, double d, uint32_t k);
static void each_steiner(const wk_motorcycle_graph *G, steiner_fn f, void *ud) {
    for (uint32_t k = 0; k < G->n; k++) {
        const wk_motorcycle *m = &G->m[k];
        if (m->kind == WK_MCG_TRACE) f(ud, m->other, m->other_len, k);
    }
    for (uint32_t g = 0; g < G->n_groups; g++) {
        const wk_motorcycle_group *Gr = &G->groups[g];
        const uint32_t *mem = G->group_members + Gr->first;
        if (Gr->on_other != WK_NONE && G->m[Gr->on_other].group != g)
            for (uint32_t a = 0; a < Gr->count; a++) f(ud, Gr->on_other, Gr->on_len, mem[a]);
        for (uint32_t a = 0; a < Gr->count; a++)
            for (uint32_t b = 0; b < Gr->count; b++)
                if (a != b) f(ud, mem[a], G->m[mem[a]].len, mem[b]);
    }
}

static void steiner_count(void *ud, uint32_t i, double d, uint32_t k) {
    (void)d;
    (void)k;
    ((uint32_t *)ud)[i + 1]++;
}

typedef struct steiner_fill_ud {
    wk_motorcycle_steiner *out;
    uint32_t *cursor;
} steiner_fill_ud;

static void steiner_fill(void *ud, uint32_t i, double d, uint32_t k) {
    steiner_fill_ud *F = ud;
    F->out[F->cursor[i]++] = (wk_motorcycle_steiner){d, k};
}

/* Wall crashes for the survivors, the groups compacted, the Steiner lists
** and the stats. */
static wk_status finish(sim *S, wk_motorcycle_graph *G) {
    wk_run *R = S->R;
    uint32_t ng = 0, nm = 0;
    for (uint32_t g = 0; g < S->n_groups; g++)
        if (S->groups[g].alive) {
            ng++;
            nm += S->groups[g].count;
        }
    G->groups = WK_NEW_ARRAY(R, wk_motorcycle_group, ng);
    if (!G->groups) return WK_ENOMEM;
    G->n_groups = ng;
    G->group_members = WK_NEW_ARRAY(R, uint32_t, nm);
    if (!G->group_members) return WK_ENOMEM;
    G->n_group_members = nm;
    for (uint32_t g = 0, k = 0, at = 0; g < S->n_groups; g++) {
        const sim_group *A = &S->groups[g];
        if (!A->alive) continue;
        wk_motorcycle_group *B = &G->groups[k];
        *B = (wk_motorcycle_group){A->p, A->t, at, A->count, A->on_other, A->on_len, A->on_edge,
                                   A->on_vertex};
        for (uint32_t i = A->head; i != WK_NONE; i = S->next_member[i]) {
            G->group_members[at++] = i;
            G->m[i].group = k;
        }
        qsort(G->group_members + B->first, B->count, sizeof(uint32_t), cmp_u32);
        k++;
    }
    wk_motorcycle_stats *st = &G->stats;
    st->motorcycles = G->n;
    st->candidate_pairs = S->pairs;
    st->simultaneous_groups = ng;
    st->simultaneous_motorcycles = nm;
    for (uint32_t i = 0; i < G->n; i++) {
        wk_motorcycle *m = &G->m[i];
        if (!S->crashed[i]) {
            m->kind = WK_MCG_WALL;
            m->len = m->wall_len;
        }
        if (m->kind == WK_MCG_WALL) st->wall_crashes++;
        if (m->kind == WK_MCG_TRACE) st->trace_crashes++;
    }
    G->steiner_start = WK_NEW_ARRAY(R, uint32_t, (size_t)G->n + 1);
    if (!G->steiner_start) return WK_ENOMEM;
    each_steiner(G, steiner_count, G->steiner_start);
    for (uint32_t i = 0; i < G->n; i++) {
        if (G->steiner_start[i + 1] > UINT32_MAX - 1 - G->steiner_start[i])
            return WK_FAIL(R, WK_ENOMEM, NULL, 0, "too many Steiner points");
        G->steiner_start[i + 1] += G->steiner_start[i];
    }
    uint32_t ns = G->steiner_start[G->n];
    G->steiner = WK_NEW_ARRAY(R, wk_motorcycle_steiner, ns);
    if (!G->steiner) return WK_ENOMEM;
    G->n_steiner = ns;
    uint32_t *cursor = WK_NEW_ARRAY(R, uint32_t, G->n ? G->n : 1);
    if (!cursor) return WK_ENOMEM;
    memcpy(cursor, G->steiner_start, (size_t)G->n * sizeof *cursor);
    steiner_fill_ud F = {G->steiner, cursor};
    each_steiner(G, steiner_fill, &F);
    WK_FREE_ARRAY(R, cursor, G->n ? G->n : 1);
    for (uint32_t i = 0; i < G->n; i++)
        qsort(G->steiner + G->steiner_start[i], G->steiner_start[i + 1] - G->steiner_start[i],
              sizeof(wk_motorcycle_steiner), cmp_steiner);
    return WK_OK;
}

/* ================================================================ build */

static wk_status build(wk_run *R, const wk_polygon *P, bool use_grid, wk_motorcycle_graph **out) {
    *out = NULL;
    wk_status st = WK_OK;
    wk_motorcycle_graph *G = WK_NEW_ARRAY(R, wk_motorcycle_graph, 1);
    if (!G) return R->err.code ? R->err.code : WK_ENOMEM;
    sim S;
    memset(&S, 0, sizeof S);
    S.R = R;
    wk_point *qp = NULL;
    wk_polygon Q = *P;

    double wmax = 0;
    for (uint32_t i = 0; i < P->n; i++)
        if (P->w[i] > wmax) wmax = P->w[i];
    double ts = R->opt.tol_scale > 0 ? R->opt.tol_scale : 1.0;
    G->centre = wk_polygon_centre(P);
    G->eps_d = ts * WK_TOL_REL * wk_polygon_scale(P);
    G->eps_t = WK_TOL_TIME * G->eps_d / wmax;
    uint32_t r = 0;
    for (uint32_t i = 0; i < P->n; i++) r += launches(NULL, P, i);
    G->m = WK_NEW_ARRAY(R, wk_motorcycle, r);
    if (!G->m) goto fail;
    G->n = r;

    /* The walls in the relative frame, for the shooter. */
    qp = WK_NEW_ARRAY(R, wk_point, P->n);
    if (!qp) goto fail;
    wk_point lo = {INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < P->n; i++) {
        qp[i] = (wk_point){P->p[i].x - G->centre.x, P->p[i].y - G->centre.y};
        lo.x = fmin(lo.x, qp[i].x);
        lo.y = fmin(lo.y, qp[i].y);
        hi.x = fmax(hi.x, qp[i].x);
        hi.y = fmax(hi.y, qp[i].y);
    }
    Q.p = qp;
    if ((st = shoot_all(R, P, &Q, G->centre, G->m, r)) != WK_OK) goto fail;
    WK_FREE_ARRAY(R, qp, P->n);

    S.m = G->m;
    S.r = r;
    S.eps_d = G->eps_d;
    S.eps_t = G->eps_t;
    S.grid = use_grid;
    S.delta = WK_MCG_GRID_DELTA * G->eps_d;
    S.crashed = WK_NEW_ARRAY(R, uint8_t, r);
    S.grp = WK_NEW_ARRAY(R, uint32_t, r);
    S.next_member = WK_NEW_ARRAY(R, uint32_t, r);
    if (!S.crashed || !S.grp || !S.next_member) goto fail;
    for (uint32_t i = 0; i < r; i++) S.grp[i] = S.next_member[i] = WK_NONE;
    if (r > 0) {
        st = use_grid ? grid_start(&S, lo, hi, true) : brute_start(&S);
        if (st != WK_OK) goto fail;
        if ((st = run_events(&S)) != WK_OK) goto fail;
        if (S.over_budget) {
            sim_restart(&S);
            if ((st = grid_start(&S, lo, hi, false)) != WK_OK) goto fail;
            if ((st = run_events(&S)) != WK_OK) goto fail;
        }
    }
    if ((st = finish(&S, G)) != WK_OK) goto fail;
    sim_clear(&S);
    *out = G;
    return WK_OK;

fail:
    if (st == WK_OK) st = R->err.code != WK_OK ? R->err.code : WK_ENOMEM;
    WK_FREE_ARRAY(R, qp, P->n);
    sim_clear(&S);
    wk_motorcycle_graph_free(R, G);
    return st;
}

wk_status wk_motorcycle_graph_build(wk_run *R, const wk_polygon *P, wk_motorcycle_graph **out) {
    return build(R, P, true, out);
}

wk_status wk_motorcycle_graph_build_brute(wk_run *R, const wk_polygon *P,
                                          wk_motorcycle_graph **out) {
    return build(R, P, false, out);
}

void wk_motorcycle_graph_free(wk_run *R, wk_motorcycle_graph *G) {
    if (!G) return;
    WK_FREE_ARRAY(R, G->m, G->n);
    WK_FREE_ARRAY(R, G->groups, G->n_groups);
    WK_FREE_ARRAY(R, G->group_members, G->n_group_members);
    if (G->steiner_start) WK_FREE_ARRAY(R, G->steiner_start, (size_t)G->n + 1);
    WK_FREE_ARRAY(R, G->steiner, G->n_steiner);
    WK_FREE_ARRAY(R, G, 1);
}

/* ================================================================ check */

static bool fail_why(char *why, size_t size, const char *fmt, ...) {
    if (why && size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(why, size, fmt, ap);
        va_end(ap);
    }
    return false;
}

/* Distance from p to the segment a + [0, len] u (u a unit vector). */
static double dist_to_trace(wk_point p, wk_point a, wk_point u, double len) {
    double t = (p.x - a.x) * u.x + (p.y - a.y) * u.y;
    t = t < 0 ? 0 : t > len ? len : t;
    return hypot(p.x - (a.x + t * u.x), p.y - (a.y + t * u.y));
}

/* Distance from p to the segment [a, b]. */
static double dist_to_segment(wk_point p, wk_point a, wk_point b) {
    double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

static bool same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Whether (d, k) is a Steiner entry that G's records give on i's trace. */
static bool steiner_expected(const wk_motorcycle_graph *G, uint32_t i, double d, uint32_t k) {
    if (k >= G->n || k == i) return false;
    const wk_motorcycle *mk = &G->m[k];
    if (mk->kind == WK_MCG_TRACE && mk->other == i && same_bits(mk->other_len, d)) return true;
    if (mk->kind != WK_MCG_SIMULTANEOUS) return false;
    const wk_motorcycle_group *g = &G->groups[mk->group];
    if (g->on_other == i && G->m[i].group != mk->group && same_bits(g->on_len, d)) return true;
    return G->m[i].group == mk->group && same_bits(G->m[i].len, d);
}

/* How far m's wall point is from the wall its ray hit (0 for an escaping
** ray). */
static double wall_distance(const wk_motorcycle *m, const wk_polygon *P, wk_point c) {
    wk_point wx = {m->o.x + m->wall_len * m->u.x, m->o.y + m->wall_len * m->u.y};
    if (m->wall_edge != WK_NONE) {
        uint32_t e = m->wall_edge, f = wk_polygon_next(P, e);
        wk_point a = {P->p[e].x - c.x, P->p[e].y - c.y}, b = {P->p[f].x - c.x, P->p[f].y - c.y};
        return dist_to_segment(wx, a, b);
    }
    if (m->wall_vertex != WK_NONE) {
        wk_point a = {P->p[m->wall_vertex].x - c.x, P->p[m->wall_vertex].y - c.y};
        return hypot(wx.x - a.x, wx.y - a.y);
    }
    return 0;
}

bool wk_motorcycle_graph_check(const wk_motorcycle_graph *G, const wk_polygon *P, char *why,
                               size_t size) {
    double tol_d = WK_MCG_CHECK_SLACK * G->eps_d, tol_t = WK_MCG_CHECK_SLACK * G->eps_t;
    wk_point c = G->centre;
    uint32_t r = 0;
    for (uint32_t v = 0; v < P->n; v++) {
        if (!launches(NULL, P, v)) continue;
        if (r >= G->n) return fail_why(why, size, "more reflex vertices than %u motorcycles", G->n);
        if (G->m[r].vertex != v)
            return fail_why(why, size, "motorcycle %u starts at vertex %u, want %u", r,
                            G->m[r].vertex, v);
        r++;
    }
    if (r != G->n) return fail_why(why, size, "%u motorcycles for %u reflex vertices", G->n, r);
    uint64_t walls = 0, traces = 0, members = 0;
    for (uint32_t i = 0; i < G->n; i++) {
        const wk_motorcycle *m = &G->m[i];
        wk_point o = {P->p[m->vertex].x - c.x, P->p[m->vertex].y - c.y};
        if (!same_bits(o.x, m->o.x) || !same_bits(o.y, m->o.y))
            return fail_why(why, size, "motorcycle %u: origin is not its vertex", i);
        if (!(fabs(hypot(m->u.x, m->u.y) - 1.0) <= WK_ANGLE_EQ))
            return fail_why(why, size, "motorcycle %u: direction not a unit vector", i);
        if (!(m->speed > 0))
            return fail_why(why, size, "motorcycle %u: speed %g", i, m->speed);
        if (!(m->len >= 0 && m->len <= m->wall_len))
            return fail_why(why, size, "motorcycle %u: len %.17g outside [0, wall_len %.17g]", i,
                            m->len, m->wall_len);
        wk_point x = wk_motorcycle_crash_point(m);
        double tx = wk_motorcycle_time_at(m, m->len);
        if (m->kind == WK_MCG_WALL) {
            walls++;
            if (m->len != m->wall_len)
                return fail_why(why, size, "motorcycle %u: wall crash before its wall", i);
        }
        /* The ray's wall hit, whatever the kind (none: a PSLG's escaping
        ** ray, see shoot_all). */
        if (wk_motorcycle_escapes(m) && !P->pslg)
            return fail_why(why, size, "motorcycle %u: escapes a polygon", i);
        if (m->wall_edge != WK_NONE && m->wall_vertex != WK_NONE)
            return fail_why(why, size, "motorcycle %u: wall hit is both edge and vertex", i);
        double dw = wall_distance(m, P, c);
        if (!(dw <= tol_d))
            return fail_why(why, size, "motorcycle %u: wall point %.3g off its wall", i, dw);
        if (m->kind == WK_MCG_TRACE) {
            traces++;
            if (m->other >= G->n || m->other == i)
                return fail_why(why, size, "motorcycle %u: crashes into motorcycle %u", i, m->other);
            const wk_motorcycle *w = &G->m[m->other];
            double d = dist_to_trace(x, w->o, w->u, w->len);
            if (!(d <= tol_d))
                return fail_why(why, size, "motorcycle %u: crash point %.3g off the trace of %u",
                                i, d, m->other);
            if (!(m->other_len <= w->len + tol_d))
                return fail_why(why, size, "motorcycle %u: %u never reached the crash point", i,
                                m->other);
            if (!(wk_motorcycle_time_at(w, m->other_len) <= tx + tol_t))
                return fail_why(why, size, "motorcycle %u: %u reached the crash point later", i,
                                m->other);
            if (m->group != WK_NONE)
                return fail_why(why, size, "motorcycle %u: a trace crash in a group", i);
        } else if (m->kind == WK_MCG_SIMULTANEOUS) {
            if (m->group >= G->n_groups)
                return fail_why(why, size, "motorcycle %u: no group", i);
            const wk_motorcycle_group *g = &G->groups[m->group];
            double d = hypot(x.x - g->p.x, x.y - g->p.y);
            if (!(d <= g->count * tol_d))
                return fail_why(why, size, "motorcycle %u: crash point %.3g from its group's", i, d);
            if (!(fabs(tx - g->t) <= g->count * tol_t))
                return fail_why(why, size, "motorcycle %u: crash time %.17g, group's %.17g", i, tx,
                                g->t);
        } else if (m->kind != WK_MCG_WALL) {
            return fail_why(why, size, "motorcycle %u: crash kind %d", i, (int)m->kind);
        }
        if (m->kind != WK_MCG_SIMULTANEOUS && m->group != WK_NONE)
            return fail_why(why, size, "motorcycle %u: in a group but kind %d", i, (int)m->kind);
    }
    uint32_t at = 0;
    for (uint32_t k = 0; k < G->n_groups; k++) {
        const wk_motorcycle_group *g = &G->groups[k];
        if (g->first != at || g->count < 2 || g->count > G->n_group_members - at)
            return fail_why(why, size, "group %u: members [%u, +%u) malformed", k, g->first,
                            g->count);
        for (uint32_t a = 0; a < g->count; a++) {
            uint32_t id = G->group_members[at + a];
            if (id >= G->n || G->m[id].group != k || (a > 0 && id <= G->group_members[at + a - 1]))
                return fail_why(why, size, "group %u: member %u wrong", k, id);
        }
        if (g->on_other != WK_NONE) {
            if (g->on_other >= G->n) return fail_why(why, size, "group %u: on %u", k, g->on_other);
            const wk_motorcycle *w = &G->m[g->on_other];
            double d = dist_to_trace(g->p, w->o, w->u, w->len);
            if (!(d <= tol_d))
                return fail_why(why, size, "group %u: point %.3g off the trace of %u", k, d,
                                g->on_other);
        }
        at += g->count;
        members += g->count;
    }
    if (at != G->n_group_members)
        return fail_why(why, size, "%u group members listed, %u in groups", G->n_group_members, at);
    /* Steiner lists: sorted, each entry one the records give, and as many
    ** as they give. */
    if (G->steiner_start[0] != 0 || G->steiner_start[G->n] != G->n_steiner)
        return fail_why(why, size, "Steiner offsets malformed");
    uint64_t want = 0;
    for (uint32_t k = 0; k < G->n; k++) {
        const wk_motorcycle *m = &G->m[k];
        if (m->kind == WK_MCG_TRACE) want++;
    }
    for (uint32_t k = 0; k < G->n_groups; k++) {
        const wk_motorcycle_group *g = &G->groups[k];
        if (g->on_other != WK_NONE && G->m[g->on_other].group != k) want += g->count;
        want += (uint64_t)g->count * (g->count - 1);
    }
    if (want != G->n_steiner)
        return fail_why(why, size, "%u Steiner points, the records give %llu", G->n_steiner,
                        (unsigned long long)want);
    for (uint32_t i = 0; i < G->n; i++) {
        if (G->steiner_start[i + 1] < G->steiner_start[i])
            return fail_why(why, size, "Steiner offsets decrease at %u", i);
        for (uint32_t s = G->steiner_start[i]; s < G->steiner_start[i + 1]; s++) {
            const wk_motorcycle_steiner *e = &G->steiner[s];
            if (!steiner_expected(G, i, e->d, e->other))
                return fail_why(why, size, "motorcycle %u: Steiner point (%.17g, %u) unexplained",
                                i, e->d, e->other);
            if (s > G->steiner_start[i] && cmp_steiner(&G->steiner[s - 1], e) >= 0)
                return fail_why(why, size, "motorcycle %u: Steiner points not sorted", i);
        }
    }
    const wk_motorcycle_stats *st = &G->stats;
    if (st->motorcycles != G->n || st->wall_crashes != walls || st->trace_crashes != traces ||
        st->simultaneous_groups != G->n_groups || st->simultaneous_motorcycles != members ||
        walls + traces + members != G->n)
        return fail_why(why, size, "stats do not match the records");
    return true;
}

bool wk_motorcycle_graph_same(const wk_motorcycle_graph *A, const wk_motorcycle_graph *B,
                              char *why, size_t size) {
    if (A->n != B->n || A->n_groups != B->n_groups || A->n_group_members != B->n_group_members ||
        A->n_steiner != B->n_steiner)
        return fail_why(why, size, "sizes differ: %u/%u/%u/%u vs %u/%u/%u/%u", A->n, A->n_groups,
                        A->n_group_members, A->n_steiner, B->n, B->n_groups, B->n_group_members,
                        B->n_steiner);
    if (!same_bits(A->centre.x, B->centre.x) || !same_bits(A->centre.y, B->centre.y) ||
        !same_bits(A->eps_d, B->eps_d) || !same_bits(A->eps_t, B->eps_t))
        return fail_why(why, size, "frames differ");
    for (uint32_t i = 0; i < A->n; i++) {
        const wk_motorcycle *a = &A->m[i], *b = &B->m[i];
        if (!same_bits(a->o.x, b->o.x) || !same_bits(a->o.y, b->o.y) ||
            !same_bits(a->u.x, b->u.x) || !same_bits(a->u.y, b->u.y) ||
            !same_bits(a->speed, b->speed) || !same_bits(a->len, b->len) ||
            !same_bits(a->wall_len, b->wall_len) || !same_bits(a->other_len, b->other_len) ||
            a->vertex != b->vertex || a->wall_edge != b->wall_edge ||
            a->wall_vertex != b->wall_vertex || a->kind != b->kind || a->other != b->other ||
            a->group != b->group)
            return fail_why(why, size,
                            "motorcycle %u (vertex %u) differs: kind %d/%d other %u/%u len "
                            "%.17g/%.17g group %u/%u",
                            i, a->vertex, (int)a->kind, (int)b->kind, a->other, b->other, a->len,
                            b->len, a->group, b->group);
    }
    for (uint32_t k = 0; k < A->n_groups; k++) {
        const wk_motorcycle_group *a = &A->groups[k], *b = &B->groups[k];
        if (!same_bits(a->p.x, b->p.x) || !same_bits(a->p.y, b->p.y) || !same_bits(a->t, b->t) ||
            a->first != b->first || a->count != b->count || a->on_other != b->on_other ||
            !same_bits(a->on_len, b->on_len) || a->on_edge != b->on_edge ||
            a->on_vertex != b->on_vertex)
            return fail_why(why, size, "group %u differs", k);
    }
    for (uint32_t k = 0; k < A->n_group_members; k++)
        if (A->group_members[k] != B->group_members[k])
            return fail_why(why, size, "group member %u differs", k);
    for (uint32_t i = 0; i <= A->n; i++)
        if (A->steiner_start[i] != B->steiner_start[i])
            return fail_why(why, size, "Steiner offset %u differs", i);
    for (uint32_t k = 0; k < A->n_steiner; k++)
        if (!same_bits(A->steiner[k].d, B->steiner[k].d) ||
            A->steiner[k].other != B->steiner[k].other)
            return fail_why(why, size, "Steiner point %u differs", k);
    const wk_motorcycle_stats *x = &A->stats, *y = &B->stats;
    if (x->motorcycles != y->motorcycles || x->wall_crashes != y->wall_crashes ||
        x->trace_crashes != y->trace_crashes || x->simultaneous_groups != y->simultaneous_groups ||
        x->simultaneous_motorcycles != y->simultaneous_motorcycles)
        return fail_why(why, size, "stats differ");
    return true;
}
