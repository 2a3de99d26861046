/*
** test_event_queue.c: the indexed heap against a brute-force model: random
** pushes, key updates, removals and pops must give the same order as a
** linear scan with the (time, kind, id) order, and the invariants must hold
** after every operation.
*/
#include <criterion/criterion.h>

#include "event_queue.h"
#include "helpers.h"

static uint64_t rng(uint64_t *s) {
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 33;
}

static bool before(wk_event_key a, uint32_t ia, wk_event_key b, uint32_t ib) {
    if (a.time != b.time) return a.time < b.time;
    if (a.kind != b.kind) return a.kind < b.kind;
    return ia < ib;
}

Test(event_queue, matches_brute_force_model) {
    wk_run R;
    wk_run_init(&R);
    wk_event_queue Q;
    wk_event_queue_init(&Q);
    enum { IDS = 300 };
    bool in[IDS] = {false};
    wk_event_key key[IDS];
    uint64_t s = 42;
    for (int step = 0; step < 20000; step++) {
        uint32_t id = (uint32_t)(rng(&s) % IDS);
        int op = (int)(rng(&s) % 4);
        if (op <= 1) {
            /* few distinct times so that ties on time and kind happen */
            wk_event_key k = {(double)(rng(&s) % 20), (uint32_t)(rng(&s) % 3)};
            cr_assert_eq(wk_event_queue_set(&R, &Q, id, k), WK_OK);
            in[id] = true;
            key[id] = k;
        } else if (op == 2) {
            wk_event_queue_remove(&R, &Q, id);
            in[id] = false;
        } else {
            uint32_t best = WK_NONE;
            for (uint32_t i = 0; i < IDS; i++)
                if (in[i] && (best == WK_NONE || before(key[i], i, key[best], best))) best = i;
            uint32_t got = wk_event_queue_pop(&R, &Q);
            cr_assert_eq(got, best, "step %d: popped %u, model says %u", step, got, best);
            if (best != WK_NONE) in[best] = false;
        }
        cr_assert(wk_event_queue_check(&Q), "heap invariant broken at step %d", step);
        for (uint32_t i = 0; i < IDS; i++) cr_assert_eq(wk_event_queue_contains(&Q, i), in[i]);
    }
    cr_assert_gt(counter(&R, "queue_pushes"), 0);
    cr_assert_gt(counter(&R, "queue_updates"), 0);
    cr_assert_gt(counter(&R, "queue_removes"), 0);
    cr_assert_gt(counter(&R, "queue_pops"), 0);
    wk_event_queue_clear(&R, &Q);
    ASSERT_CLEAN_CLOSE(R);
}

Test(event_queue, reserve_failure_leaves_queue_intact) {
    wk_run R;
    wk_run_init(&R);
    wk_event_queue Q;
    wk_event_queue_init(&Q);
    for (uint32_t i = 0; i < 16; i++)
        cr_assert_eq(wk_event_queue_set(&R, &Q, i, (wk_event_key){(double)(16 - i), 0}), WK_OK);
    R.alloc.fail_after = (int64_t)R.alloc.calls; /* the next allocation fails */
    cr_assert_eq(wk_event_queue_set(&R, &Q, 1000, (wk_event_key){0.5, 0}), WK_ENOMEM);
    cr_assert(wk_event_queue_check(&Q));
    cr_assert_eq(Q.size, 16);
    cr_assert_eq(wk_event_queue_pop(&R, &Q), 15); /* time 1 */
    wk_event_queue_clear(&R, &Q);
    ASSERT_CLEAN_CLOSE(R);
}
