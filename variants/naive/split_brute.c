/*
** split_brute.c: the reference variant's split finder (the finder
** interface of engine/wavefront.h): a reflex vertex is tested against every
** piece of its wavefront cycle.
** Cost: O(cycle) per reflex vertex whose target disappears,
** O(new pieces) per reflex vertex of a touched cycle otherwise.
*/
#include "naive.h"

/* Every piece of vi's cycle. */
static void brute_full(void *ud, wk_wavefront *W, uint32_t vi) {
    (void)ud;
    wk_wavefront_split_scan(W, vi);
}

/* Only pieces next to fresh vertices are new. */
static void brute_incremental(void *ud, wk_wavefront *W, uint32_t vi) {
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

const wk_split_finder naive_split_finder = {
    brute_full, brute_incremental, NULL, NULL, NULL, NULL, false,
};
