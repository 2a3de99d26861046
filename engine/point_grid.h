/*
** point_grid.h: points by place, for the few-neighbours queries of a large
** group of simultaneous events (wavefront_group.c: the nodes near a point
** or a piece, the untouched vertices near a sub-piece).  A scan over all
** nodes per query made a group of k events cost O(k^2): the comb's teeth
** all collapse at once, k = n/4.
**
** A uniform grid of square cells of side h from (x0, y0), hashed (open
** addressing on the cell's integer coordinates), so only occupied cells
** cost memory; each cell chains the ids added in it.  A query returns the
** ids in the cells that meet a box, each once, increasing, or says that the
** box covers too many cells to be worth it (then the caller scans).
**
** Exactness: a point p is in cell (floor((p.x - x0) / h), ...), computed
** the same way for the box's corners; both maps are non-decreasing in the
** coordinate, so every point inside the box (as doubles) lies in a cell the
** query visits.  The callers widen their boxes beyond the rounding of their
** own tests (wavefront_group.c).
**
** Not a general spatial index: no removal, ids below UINT32_MAX / 2.
*/
#ifndef WK_POINT_GRID_H
#define WK_POINT_GRID_H
#include "wskel.h"

typedef struct wk_point_grid {
    double x0, y0, h;  /* cell (i, j) = [x0 + i h, x0 + (i + 1) h) x ... */
    int64_t *key;      /* per slot: cell coordinates (2 per slot) */
    uint32_t *head;    /* per slot: first id of the cell, WK_NONE if free */
    uint32_t cap, used; /* slots (a power of two), occupied slots */
    uint32_t *next;    /* per id: next id of its cell */
    uint32_t cap_next;
    uint32_t *out;     /* the last query's ids */
    uint32_t n_out, cap_out;
    uint32_t n_ids;    /* ids added since the reset (for the caller) */
} wk_point_grid;

void wk_point_grid_init(wk_point_grid *G);
void wk_point_grid_free(wk_run *R, wk_point_grid *G);
/* Forget every point; cells of side h > 0 from (x0, y0). */
wk_status wk_point_grid_reset(wk_run *R, wk_point_grid *G, double x0, double y0, double h);
/* Point id at p (each id once per reset). */
wk_status wk_point_grid_add(wk_run *R, wk_point_grid *G, uint32_t id, wk_point p);
/* The ids in the cells meeting [lo, hi]: G->out[0 .. G->n_out), increasing,
** each once, and true; or false (nothing listed) when the box covers more
** than max_cells cells or is not finite.  Cannot fail (out holds every id
** added, sized by wk_point_grid_add). */
bool wk_point_grid_query(wk_point_grid *G, wk_point lo, wk_point hi, uint64_t max_cells);

#endif
