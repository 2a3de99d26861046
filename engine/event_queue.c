/*
** event_queue.c: indexed binary heap (see event_queue.h for the invariants).
*/
#include "event_queue.h"

static bool less(const wk_event_entry *a, const wk_event_entry *b) {
    if (a->time != b->time) return a->time < b->time;
    if (a->kind != b->kind) return a->kind < b->kind;
    return a->id < b->id;
}

static void place(wk_event_queue *Q, uint32_t i, wk_event_entry e) {
    Q->heap[i] = e;
    Q->pos[e.id] = i;
}

static void sift_up(wk_event_queue *Q, uint32_t i) {
    wk_event_entry e = Q->heap[i];
    while (i > 0) {
        uint32_t p = (i - 1) / 2;
        if (!less(&e, &Q->heap[p])) break;
        place(Q, i, Q->heap[p]);
        i = p;
    }
    place(Q, i, e);
}

static void sift_down(wk_event_queue *Q, uint32_t i) {
    wk_event_entry e = Q->heap[i];
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= Q->size) break;
        if (c + 1 < Q->size && less(&Q->heap[c + 1], &Q->heap[c])) c++;
        if (!less(&Q->heap[c], &e)) break;
        place(Q, i, Q->heap[c]);
        i = c;
    }
    place(Q, i, e);
}

void wk_event_queue_init(wk_event_queue *Q) {
    Q->size = Q->cap = 0;
    Q->heap = NULL;
    Q->pos = NULL;
}

wk_status wk_event_queue_reserve(wk_run *R, wk_event_queue *Q, uint32_t cap) {
    if (cap <= Q->cap) return WK_OK;
    /* the first reservation is exact (callers reserve what they expect to
    ** need: one id per wavefront vertex, 2n + 16); later ones take the power
    ** of two that doubling from 16 gives, never more than before */
    uint32_t ncap = cap;
    if (Q->cap) {
        ncap = 16;
        while (ncap < cap || ncap <= Q->cap) ncap = ncap > UINT32_MAX / 2 ? cap : ncap * 2;
    }
    /* Allocate both before touching Q, so a failure leaves Q intact. */
    wk_event_entry *heap = WK_NEW_ARRAY(R, wk_event_entry, ncap);
    uint32_t *pos = heap ? WK_NEW_ARRAY(R, uint32_t, ncap) : NULL;
    if (!pos) {
        if (heap) WK_FREE_ARRAY(R, heap, ncap);
        return R->err.code;
    }
    for (uint32_t i = 0; i < ncap; i++) pos[i] = i < Q->cap ? Q->pos[i] : WK_NONE;
    for (uint32_t i = 0; i < Q->size; i++) heap[i] = Q->heap[i];
    uint32_t size = Q->size;
    wk_event_queue_clear(R, Q);
    Q->size = size;
    Q->heap = heap;
    Q->pos = pos;
    Q->cap = ncap;
    return WK_OK;
}

void wk_event_queue_clear(wk_run *R, wk_event_queue *Q) {
    WK_FREE_ARRAY(R, Q->heap, Q->cap);
    WK_FREE_ARRAY(R, Q->pos, Q->cap);
    Q->size = Q->cap = 0;
}

wk_status wk_event_queue_set(wk_run *R, wk_event_queue *Q, uint32_t id, wk_event_key k) {
    if (id >= Q->cap && wk_event_queue_reserve(R, Q, id + 1) != WK_OK) return R->err.code;
    uint32_t i = Q->pos[id];
    wk_event_entry e = {k.time, k.kind, id};
    if (i == WK_NONE) {
        place(Q, Q->size++, e);
        sift_up(Q, Q->size - 1);
        wk_count(R, WK_COUNTER_queue_pushes, 1);
    } else {
        Q->heap[i] = e;
        sift_up(Q, i);
        sift_down(Q, Q->pos[id]);
        wk_count(R, WK_COUNTER_queue_updates, 1);
    }
    return WK_OK;
}

void wk_event_queue_remove(wk_run *R, wk_event_queue *Q, uint32_t id) {
    if (id >= Q->cap || Q->pos[id] == WK_NONE) return;
    uint32_t i = Q->pos[id];
    Q->pos[id] = WK_NONE;
    Q->size--;
    if (i < Q->size) {
        wk_event_entry moved = Q->heap[Q->size];
        place(Q, i, moved);
        sift_up(Q, i);
        sift_down(Q, Q->pos[moved.id]);
    }
    wk_count(R, WK_COUNTER_queue_removes, 1);
}

uint32_t wk_event_queue_peek(const wk_event_queue *Q) { return Q->size ? Q->heap[0].id : WK_NONE; }

uint32_t wk_event_queue_pop(wk_run *R, wk_event_queue *Q) {
    if (!Q->size) return WK_NONE;
    uint32_t id = Q->heap[0].id;
    Q->pos[id] = WK_NONE;
    Q->size--;
    if (Q->size) {
        place(Q, 0, Q->heap[Q->size]);
        sift_down(Q, 0);
    }
    wk_count(R, WK_COUNTER_queue_pops, 1);
    return id;
}

bool wk_event_queue_contains(const wk_event_queue *Q, uint32_t id) {
    return id < Q->cap && Q->pos[id] != WK_NONE;
}

bool wk_event_queue_check(const wk_event_queue *Q) {
    for (uint32_t i = 0; i < Q->size; i++) {
        if (Q->heap[i].id >= Q->cap || Q->pos[Q->heap[i].id] != i) return false;
        if (i > 0 && less(&Q->heap[i], &Q->heap[(i - 1) / 2])) return false;
    }
    return true;
}
