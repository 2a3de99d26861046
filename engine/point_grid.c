/*
** point_grid.c: the hashed uniform grid of points (point_grid.h).
**
** Invariants: a slot is free iff head[slot] == WK_NONE; an occupied slot
** holds its cell's two coordinates in key[2 slot ..] and the first id of a
** chain through next[] that ends in WK_NONE; used <= cap / 2 (so a probe
** always ends at a free slot).
*/
#include "point_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Cell coordinates are kept within +-2^52 (far beyond any grid that is
** queried cell by cell: the caller's max_cells bounds that). */
#define PG_COORD_MAX 4503599627370496.0

void wk_point_grid_init(wk_point_grid *G) {
    memset(G, 0, sizeof *G);
    G->h = 1;
}

void wk_point_grid_free(wk_run *R, wk_point_grid *G) {
    if (G->cap) {
        WK_FREE_ARRAY(R, G->key, 2 * (size_t)G->cap);
        WK_FREE_ARRAY(R, G->head, G->cap);
    }
    WK_FREE_ARRAY(R, G->next, G->cap_next);
    WK_FREE_ARRAY(R, G->out, G->cap_out);
    wk_point_grid_init(G);
}

static int64_t cell_of(double x, double x0, double h) {
    double c = floor((x - x0) / h);
    if (!(c > -PG_COORD_MAX)) return (int64_t)-PG_COORD_MAX; /* also NaN */
    if (c > PG_COORD_MAX) return (int64_t)PG_COORD_MAX;
    return (int64_t)c;
}

static uint32_t slot_of(const wk_point_grid *G, int64_t i, int64_t j) {
    uint64_t z = (uint64_t)i * 0x9E3779B97F4A7C15u ^ (uint64_t)j * 0xC2B2AE3D27D4EB4Fu;
    z ^= z >> 29;
    uint32_t s = (uint32_t)(z & (G->cap - 1));
    while (G->head[s] != WK_NONE && (G->key[2 * (size_t)s] != i || G->key[2 * (size_t)s + 1] != j))
        s = (s + 1) & (G->cap - 1);
    return s;
}

static wk_status alloc_table(wk_run *R, wk_point_grid *G, uint32_t cap) {
    G->key = WK_NEW_ARRAY(R, int64_t, 2 * (size_t)cap);
    G->head = WK_NEW_ARRAY(R, uint32_t, cap);
    if (!G->key || !G->head) {
        if (G->key) WK_FREE_ARRAY(R, G->key, 2 * (size_t)cap);
        if (G->head) WK_FREE_ARRAY(R, G->head, cap);
        G->key = NULL;
        G->head = NULL;
        G->cap = 0;
        return WK_ENOMEM;
    }
    G->cap = cap;
    for (uint32_t s = 0; s < cap; s++) G->head[s] = WK_NONE;
    G->used = 0;
    return WK_OK;
}

wk_status wk_point_grid_reset(wk_run *R, wk_point_grid *G, double x0, double y0, double h) {
    G->x0 = x0;
    G->y0 = y0;
    G->h = h;
    G->n_ids = 0;
    if (!G->cap) return alloc_table(R, G, 64);
    for (uint32_t s = 0; s < G->cap; s++) G->head[s] = WK_NONE;
    G->used = 0;
    return WK_OK;
}

/* Twice the slots, every cell moved (its chain stays). */
static wk_status grow_table(wk_run *R, wk_point_grid *G) {
    int64_t *key = G->key;
    uint32_t *head = G->head, cap = G->cap;
    if (cap >= 0x40000000u) return WK_FAIL(R, WK_ENOMEM, NULL, 0, "point grid too large");
    if (alloc_table(R, G, 2 * cap) != WK_OK) {
        G->key = key;
        G->head = head;
        G->cap = cap;
        return WK_ENOMEM;
    }
    for (uint32_t s = 0; s < cap; s++) {
        if (head[s] == WK_NONE) continue;
        uint32_t d = slot_of(G, key[2 * (size_t)s], key[2 * (size_t)s + 1]);
        G->key[2 * (size_t)d] = key[2 * (size_t)s];
        G->key[2 * (size_t)d + 1] = key[2 * (size_t)s + 1];
        G->head[d] = head[s];
        G->used++;
    }
    WK_FREE_ARRAY(R, key, 2 * (size_t)cap);
    WK_FREE_ARRAY(R, head, cap);
    return WK_OK;
}

wk_status wk_point_grid_add(wk_run *R, wk_point_grid *G, uint32_t id, wk_point p) {
    if (id >= G->cap_next && WK_GROW(R, G->next, G->cap_next, id + 1) != WK_OK) return WK_ENOMEM;
    if (WK_GROW(R, G->out, G->cap_out, G->n_ids + 1) != WK_OK) return WK_ENOMEM;
    if (2 * (G->used + 1) > G->cap && grow_table(R, G) != WK_OK) return WK_ENOMEM;
    int64_t i = cell_of(p.x, G->x0, G->h), j = cell_of(p.y, G->y0, G->h);
    uint32_t s = slot_of(G, i, j);
    if (G->head[s] == WK_NONE) {
        G->key[2 * (size_t)s] = i;
        G->key[2 * (size_t)s + 1] = j;
        G->used++;
    }
    G->next[id] = G->head[s];
    G->head[s] = id;
    G->n_ids++;
    return WK_OK;
}

static int cmp_u32(const void *x, const void *y) {
    uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return a < b ? -1 : a > b;
}

bool wk_point_grid_query(wk_point_grid *G, wk_point lo, wk_point hi, uint64_t max_cells) {
    G->n_out = 0;
    if (!(isfinite(lo.x) && isfinite(lo.y) && isfinite(hi.x) && isfinite(hi.y))) return false;
    int64_t i0 = cell_of(lo.x, G->x0, G->h), i1 = cell_of(hi.x, G->x0, G->h);
    int64_t j0 = cell_of(lo.y, G->y0, G->h), j1 = cell_of(hi.y, G->y0, G->h);
    if (i1 < i0 || j1 < j0) return false;
    double cells = ((double)(i1 - i0) + 1.0) * ((double)(j1 - j0) + 1.0);
    if (cells > (double)max_cells) return false;
    if (!G->cap) return true;
    for (int64_t i = i0; i <= i1; i++)
        for (int64_t j = j0; j <= j1; j++) {
            uint32_t s = slot_of(G, i, j);
            for (uint32_t id = G->head[s]; id != WK_NONE; id = G->next[id]) G->out[G->n_out++] = id;
        }
    if (G->n_out > 1) qsort(G->out, G->n_out, sizeof *G->out, cmp_u32);
    return true;
}
