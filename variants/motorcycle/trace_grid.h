/*
** trace_grid.h: which traces may cross a given part of a trace (the
** motorcycle finder lists the crossings of every part added to a trace,
** trace extensions and late traces, with the live traces; a scan over all
** traces made that O(r) per extension: 6,430 extensions over 500,000 traces
** at coastline n = 10^6).
**
** A uniform grid (about one cell per trace at the build, over the given
** box) whose cells list the ids of the traces, or parts of traces, that come
** within the grid's delta of them; insert-only (a trace only grows).
** Membership is the engine's (wk_seg_grid_rows / wk_seg_grid_row_span on
** the grid's geometry), for inserts and queries alike, so a point within
** delta of both an inserted part and a queried part lies in a cell listed
** by both (up to the rounding of the cell walls, far below delta).
** A query returns each id listed in the cells of the queried part once, in
** increasing order (so its callers see the order of a scan over all ids).
*/
#ifndef MC_TRACE_GRID_H
#define MC_TRACE_GRID_H
#include "ray_shoot.h"

typedef struct mc_tg_cell {
    uint32_t *e;
    uint32_t n, cap;
} mc_tg_cell;

typedef struct mc_trace_grid {
    wk_seg_grid geo;     /* geometry only (no start / items) */
    mc_tg_cell *cells;   /* geo.nx * geo.ny, NULL until built */
    uint32_t *mark;      /* per id: stamp of the last query that returned it */
    uint32_t cap_mark, stamp;
    uint32_t *out;       /* the last query's ids */
    uint32_t n_out, cap_out;
} mc_trace_grid;

void mc_tg_init(mc_trace_grid *T);
void mc_tg_clear(wk_run *R, mc_trace_grid *T);
static inline bool mc_tg_built(const mc_trace_grid *T) { return T->cells != NULL; }
/* The empty grid of about `cells` cells over [lo, hi], delta > 0. */
wk_status mc_tg_build(wk_run *R, mc_trace_grid *T, wk_point lo, wk_point hi, uint32_t cells,
                      double delta);
/* List id in the cells of segment ab. */
wk_status mc_tg_add(wk_run *R, mc_trace_grid *T, uint32_t id, wk_point a, wk_point b);
/* The ids listed in the cells of segment ab: T->out[0 .. T->n_out),
** increasing, each once. */
wk_status mc_tg_query(wk_run *R, mc_trace_grid *T, wk_point a, wk_point b);

#endif
