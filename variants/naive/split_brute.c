/*
** split_brute.c: the reference variant's split finder (the finder
** interface of engine/wavefront.h): a reflex vertex is tested against every
** piece of its wavefront cycle.
** Cost: O(cycle) per reflex vertex whose target disappears,
** O(new pieces) per reflex vertex of a touched cycle otherwise.
*/
#include "naive.h"

/* Every piece of v's cycle. */
static void brute_full(void *ud, wk_wavefront *W, uint32_t v) {
    (void)ud;
    wk_wf_split_scan(W, v);
}

/* Only pieces next to the vertices the last group created or relinked are
** new: the rest were tested when v's candidate was computed. */
static void brute_incremental(void *ud, wk_wavefront *W, uint32_t v) {
    (void)ud;
    const uint32_t *fresh, *ended;
    uint32_t n_fresh, n_ended;
    wk_wf_last_group(W, &fresh, &n_fresh, &ended, &n_ended);
    wk_wf_split_search s;
    wk_wf_split_begin(W, v, &s);
    for (uint32_t j = 0; j < n_fresh; j++) {
        uint32_t g = fresh[j];
        if (!wk_wf_alive(W, g)) continue;
        wk_wf_split_test(W, &s, g);
        wk_wf_split_test(W, &s, wk_wf_prev(W, g));
    }
    wk_wf_split_offer(W, &s);
}

const wk_split_finder naive_split_finder = {
    .full = brute_full,
    .incremental = brute_incremental,
};
