/*
** counters.c: the counting observer, the only code that writes wk_counters.
*/
#include "wskel.h"

/* ---- counting observer: the only writer of wk_counters ---- */

static void count_event(void *ud, wk_event_kind kind, const wk_event *e) {
    wk_counters *c = ud;
    switch (kind) {
    case WK_EV_EDGE: c->edge_events++; break;
    case WK_EV_SPLIT: c->split_events++; break;
    case WK_EV_MULTI_SPLIT: c->multi_split_events++; break;
    case WK_EV_SWITCH: c->switch_events++; break;
    case WK_EV_START: c->start_events++; break;
    case WK_EV_REFLEX_EDGE: c->reflex_preserving_edge_events++; break;
    case WK_EV_VANISH: c->vanishing_components++; break;
    case WK_EV_GROUP: c->simultaneous_event_groups++; break;
    case WK_EV_COLLINEAR: c->collinear_resolutions++; break;
    case WK_EV_CHAIN_EDGE:
        c->edge_events++;
        if (e->c == 0) c->chain_edge_events_lower++;
        else c->chain_edge_events_upper++;
        break;
    case WK_EV_MERGE_VERTEX: c->merge_chain_vertices++; break;
    case WK_EV_MERGE_CELL: c->merge_cells_visited++; break;
    case WK_EV_FALLBACK: c->reference_fallbacks++; break;
    case WK_EV_BRUTE_SPLIT: c->brute_force_split_scans++; break;
    case WK_EV_KIND_COUNT: break;
    }
}
static void count_queue(void *ud, wk_queue_op op) {
    wk_counters *c = ud;
    switch (op) {
    case WK_Q_PUSH: c->queue_pushes++; break;
    case WK_Q_POP: c->queue_pops++; break;
    case WK_Q_UPDATE: c->queue_updates++; break;
    case WK_Q_REMOVE: c->queue_removes++; break;
    }
}
static void count_cache(void *ud, wk_cache_op op) {
    wk_counters *c = ud;
    switch (op) {
    case WK_C_HIT: c->cache_hits++; break;
    case WK_C_MISS: c->cache_misses++; break;
    case WK_C_REFILL: c->cache_refills++; break;
    case WK_C_INVALIDATE: c->cache_invalidations++; break;
    }
}
static void count_arrangement(void *ud, wk_arr_op op, uint64_t n) {
    wk_counters *c = ud;
    switch (op) {
    case WK_A_INSERT: c->arrangement_inserts += n; break;
    case WK_A_REMOVE: c->arrangement_removes += n; break;
    case WK_A_QUERY: c->intersection_queries += n; break;
    case WK_A_SCANNED: c->segments_scanned += n; break;
    case WK_A_INITIAL_CROSSING: c->arrangement_crossings_initial += n; break;
    }
}
static void count_exact(void *ud) { ((wk_counters *)ud)->exact_fallbacks++; }
static void count_stale(void *ud) { ((wk_counters *)ud)->stale_events++; }

const wk_observer wk_observer_counting = {
    count_event, count_queue, count_cache, count_arrangement, count_exact, count_stale, NULL,
};

