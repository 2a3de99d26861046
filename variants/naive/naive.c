/*
** naive.c: the reference variant.  Classical event-driven wavefront
** simulation (engine/wavefront.c) with brute-force split detection: a
** reflex vertex is tested against every piece of its wavefront cycle.
** Clarity beats speed: this is the oracle the other variants are tested
** against.  Cost: O(n) per reflex vertex whose target disappears, O(new
** pieces) per reflex vertex of a touched cycle otherwise.
*/
#include "../variant.h"
#include "wavefront.h"

/* Every piece of vi's cycle. */
static void naive_full(void *ud, wk_wavefront *W, uint32_t vi) {
    (void)ud;
    wk_wavefront_split_scan(W, vi);
}

/* Only pieces next to fresh vertices are new. */
static void naive_incremental(void *ud, wk_wavefront *W, uint32_t vi) {
    (void)ud;
    double best = W->v[vi].ev_t;
    wk_point bp = W->v[vi].ev_p;
    uint32_t ta = WK_NONE, tb = WK_NONE;
    for (uint32_t j = 0; j < W->n_fresh; j++) {
        uint32_t g = W->fresh[j];
        if (!W->v[g].alive) continue;
        wk_wavefront_split_test(W, vi, g, &best, &bp, &ta, &tb);
        wk_wavefront_split_test(W, vi, W->v[g].prev, &best, &bp, &ta, &tb);
    }
    wk_wavefront_offer_split(W, vi, best, bp, ta, tb);
}

static const wk_split_finder brute_force = {naive_full, naive_incremental, NULL, NULL, NULL, NULL, false};

static wk_status naive_run(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    return wk_wavefront_run(R, P, &brute_force, NULL, out);
}

const wk_variant wk_variant_naive = {
    "naive",
    "reference: event-driven wavefront with brute-force split detection",
    WK_VARIANT_WEIGHTS,
    naive_run,
};
