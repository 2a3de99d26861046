/*
** trace_grid.c: the insert-only grid of trace parts (trace_grid.h).
**
** Invariants: every id added with segment ab is listed in each cell
** (col, row) with row in wk_seg_grid_rows(ab) and col in
** wk_seg_grid_row_span(ab, row) (possibly more than once, if added twice);
** mark[id] <= stamp for every id below cap_mark.
*/
#include "trace_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void mc_tg_init(mc_trace_grid *T) {
    memset(T, 0, sizeof *T);
    wk_seg_grid_init(&T->geo);
}

void mc_tg_clear(wk_run *R, mc_trace_grid *T) {
    if (T->cells) {
        size_t nc = (size_t)T->geo.nx * T->geo.ny;
        for (size_t c = 0; c < nc; c++) WK_FREE_ARRAY(R, T->cells[c].e, T->cells[c].cap);
        WK_FREE_ARRAY(R, T->cells, nc);
    }
    WK_FREE_ARRAY(R, T->mark, T->cap_mark);
    WK_FREE_ARRAY(R, T->out, T->cap_out);
    mc_tg_init(T);
}

wk_status mc_tg_build(wk_run *R, mc_trace_grid *T, wk_point lo, wk_point hi, uint32_t cells,
                      double delta) {
    wk_seg_grid *G = &T->geo;
    if (cells < 1) cells = 1;
    /* the shape of wk_seg_grid_build's grid: square-ish cells */
    double W = hi.x - lo.x + 2.0 * delta, H = hi.y - lo.y + 2.0 * delta;
    double cell = sqrt(W * H / (double)cells);
    double fx = ceil(W / cell), fy = ceil(H / cell);
    G->nx = !(fx >= 1.0) ? 1u : fx >= (double)cells ? cells : (uint32_t)fx;
    G->ny = !(fy >= 1.0) ? 1u : fy >= (double)cells ? cells : (uint32_t)fy;
    if ((uint64_t)G->nx * G->ny >= UINT32_MAX / 2)
        return WK_FAIL(R, WK_ENOMEM, NULL, 0, "trace grid of %u x %u cells too large", G->nx,
                       G->ny);
    G->x0 = lo.x - delta;
    G->y0 = lo.y - delta;
    G->cw = W / G->nx;
    G->ch = H / G->ny;
    G->delta = delta;
    G->n_cells = G->nx * G->ny;
    T->cells = WK_NEW_ARRAY(R, mc_tg_cell, G->n_cells);
    if (!T->cells) return WK_ENOMEM;
    for (uint32_t c = 0; c < G->n_cells; c++) T->cells[c] = (mc_tg_cell){NULL, 0, 0};
    return WK_OK;
}

wk_status mc_tg_add(wk_run *R, mc_trace_grid *T, uint32_t id, wk_point a, wk_point b) {
    const wk_seg_grid *G = &T->geo;
    uint32_t r0, r1, c0, c1;
    wk_seg_grid_rows(G, a, b, &r0, &r1);
    for (uint32_t row = r0; row <= r1; row++) {
        if (!wk_seg_grid_row_span(G, a, b, row, &c0, &c1)) continue;
        for (uint32_t c = c0; c <= c1; c++) {
            mc_tg_cell *C = &T->cells[(size_t)row * G->nx + c];
            if (C->n && C->e[C->n - 1] == id) continue; /* just listed */
            if (WK_GROW(R, C->e, C->cap, C->n + 1) != WK_OK) return WK_ENOMEM;
            C->e[C->n++] = id;
        }
    }
    return WK_OK;
}

static int cmp_u32(const void *x, const void *y) {
    uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return a < b ? -1 : a > b;
}

wk_status mc_tg_query(wk_run *R, mc_trace_grid *T, wk_point a, wk_point b) {
    const wk_seg_grid *G = &T->geo;
    T->n_out = 0;
    if (++T->stamp == 0) { /* wrapped: forget every mark */
        memset(T->mark, 0, (size_t)T->cap_mark * sizeof *T->mark);
        T->stamp = 1;
    }
    uint32_t r0, r1, c0, c1;
    wk_seg_grid_rows(G, a, b, &r0, &r1);
    for (uint32_t row = r0; row <= r1; row++) {
        if (!wk_seg_grid_row_span(G, a, b, row, &c0, &c1)) continue;
        for (uint32_t c = c0; c <= c1; c++) {
            const mc_tg_cell *C = &T->cells[(size_t)row * G->nx + c];
            for (uint32_t k = 0; k < C->n; k++) {
                uint32_t id = C->e[k];
                if (id >= T->cap_mark) {
                    uint32_t old = T->cap_mark;
                    if (WK_GROW(R, T->mark, T->cap_mark, id + 1) != WK_OK) return WK_ENOMEM;
                    memset(T->mark + old, 0, (size_t)(T->cap_mark - old) * sizeof *T->mark);
                }
                if (T->mark[id] == T->stamp) continue;
                T->mark[id] = T->stamp;
                if (WK_GROW(R, T->out, T->cap_out, T->n_out + 1) != WK_OK) return WK_ENOMEM;
                T->out[T->n_out++] = id;
            }
        }
    }
    qsort(T->out, T->n_out, sizeof *T->out, cmp_u32);
    return WK_OK;
}
