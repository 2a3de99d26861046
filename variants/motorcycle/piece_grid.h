/*
** piece_grid.h: the first wavefront piece along a ray at time t (the
** motorcycle finder's ray shots: trace extensions, late traces, F lost by a
** group) without walking a whole wavefront cycle.
**
** Design
** ------
** A uniform grid over the polygon's box (about one cell per input vertex)
** whose cells list wavefront pieces a -> b (two vertex ids) by the region
** the piece sweeps over a time window [t_b, t_e]: both ends move linearly,
** so at any time in the window the piece lies in the convex hull of a(t0),
** b(t0), a(t_e), b(t_e) (t0 its insertion time).  A cell lists the piece
** when that hull, widened by `margin`, meets the cell (row by row: the hull's
** x range in the row's slab, from the six segments between the four points,
** which include the hull's edges).  The grid is built for all alive pieces
** at t_b (a "build"), valid until t_e = t_b + window, and kept valid after
** every group by listing the pieces next to the group's fresh vertices from
** that moment on.  That listing is lazy: the groups only note their fresh
** vertices, and the next grid shot lists the pieces next to those still
** alive, from the shot's time on (coastline 10^6: 900k groups against 10k
** shots; most pieces a group makes are gone before the next shot, and the
** hulls of the others are shorter).  A piece whose ends changed is not current any more
** ("piece (a, b) exists" is "a alive and next(a) == b", wavefront.h); its
** entries are stale and are dropped when a shot meets them.  A piece whose
** hull would cover many more cells than its length (a very fast vertex: a
** nearly straight reflex corner) goes on an overflow list instead, tested
** by every grid shot.
**
** Fast and long pieces (issue 13, session mcgrid).  A piece is listed only
** until its faster end has moved PG_MOVE_CELLS cells (or the window ends,
** or it collapses); a piece cut short so goes on an expiry heap, and the
** next grid shot after that time lists it again from the shot's time if it
** is still current (its old entries stay: they are of a current piece, so
** they are tested, and cost only memory until the next build).  And the
** entries of one build, its fresh pieces and its relistings together are
** bounded (PG_BUDGET_PER_VERTEX per input vertex): a listing that would pass
** the bound is not made, the grid is dropped and its cells freed, and the
** shots walk cycles until they have tested twice the bound (the build rule
** below).  A grid only pays for pieces short against the box; on polygons
** of long spikes (random, star: pieces about 0.3 sqrt(n) cells long, their
** vertices at speeds 10^3..10^5) a build lists n^1.5 entries (random
** 3*10^5: 261M entries, 3.05 GB, before the bound).
**
** A shot walks the cells along the ray from where it starts (Amanatides-Woo,
** as engine/ray_shoot.c), tests the current pieces listed there with the
** engine's wk_wf_ray_hit_piece (the same bits as the walk over the cycle),
** and stops after a cell whose exit distance is at least the best hit:
** every piece with an earlier hit has its hit point (within margin of the
** piece, so of its hull) in a cell visited before.  Ties: the lower piece id.
**
** When to build.  A build costs about the cells its hulls cover, a shot
** over the cycle about the cycle; few shots (the star family: 3 at n = 10^5)
** never pay for a build.  So shots outside a valid window walk the cycle
** (wk_wf_ray_shoot's semantics: v's cycle, every alive piece with holes)
** until the pieces they tested since the last build reach the entries of
** the last build (at first: 4 per input vertex; after a build dropped at
** the bound: twice the bound); then the next shot builds.  Over a run that
** costs at most about twice the cheaper of the two.
**
** Differences from the walk over v's cycle: pieces of other cycles are
** candidates too (as wk_wf_ray_shoot does with holes): the first piece a
** ray from v meets is on the boundary of v's own region anyway, and ties
** between equal hits go to the lower piece id.
*/
#ifndef MC_PIECE_GRID_H
#define MC_PIECE_GRID_H
#include "wavefront.h"

typedef struct mc_pg_cell {
    uint32_t *e;         /* entries (a, b): 2 ids each */
    uint32_t n, cap;     /* entries; capacity in ids */
    uint32_t gen;        /* entries are of build `gen`, else the cell is empty */
} mc_pg_cell;

typedef struct mc_pg_expiry {
    double t;            /* the piece's listing covers it until t */
    uint32_t a, b;
} mc_pg_expiry;

typedef struct mc_piece_grid {
    double x0, y0, cw, ch; /* cell (0, 0)'s lower-left corner, cell size */
    uint32_t nx, ny;
    double margin;         /* hull widening (distance) */
    double window;         /* a build's time window */
    mc_pg_cell *cells;     /* nx * ny, NULL until the first build */
    uint32_t gen;          /* the current build */
    bool valid;            /* the build covers [t_b, t_e] and is kept up to date */
    double t_b, t_e;
    uint64_t listed;       /* entries listed since the build */
    uint64_t since;        /* pieces tested by cycle walks since the build */
    uint64_t est;          /* entries of the last build (the cost of the next) */
    uint32_t *over;        /* overflow: pieces tested at every grid shot (a, b) */
    uint32_t n_over, cap_over; /* pairs; capacity in ids */
    uint32_t *pending;     /* fresh vertices of the groups since the last shot or build,
                              whose pieces are listed at the next grid shot */
    uint32_t n_pending, cap_pending;
    struct mc_pg_expiry *exp; /* min-heap by time: pieces listed for less than the
                                 window (fast ends), relisted by the shot after */
    uint32_t n_exp, cap_exp;
    uint64_t budget;       /* entries a build may list over its window, all listings */
    uint64_t cap_ids;      /* the cells' capacity in ids, over all builds */
    bool full;             /* a listing would have passed the budget */
} mc_piece_grid;

/* Empty, closable, no allocation. */
void mc_pg_init(mc_piece_grid *G);
void mc_pg_clear(wk_run *R, mc_piece_grid *G);
/* After a group at time t: note its fresh vertices, whose pieces the next
** grid shot lists (if the grid is valid and t within its window). */
wk_status mc_pg_after_group(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, double t);
/* The first piece the ray o + lambda u (lambda > lambda0) meets at time t,
** over the grid or v's cycle (see above), with wk_wf_ray_shoot's reshoot
** a moment later for a hit at a piece's end.  WK_NONE if none; *st is
** WK_ENOMEM if a build ran out of memory (then the shot is a cycle walk). */
uint32_t mc_pg_shoot(wk_run *R, mc_piece_grid *G, const wk_wavefront *W, wk_point o, wk_point u,
                     uint32_t v, double t, double lambda0, wk_status *st);

#endif
