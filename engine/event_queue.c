/*
** event_queue.c: indexed binary heap (see event_queue.h for the invariants).
*/
#include "event_queue.h"

static bool less(const wk_event_queue *Q, uint32_t a, uint32_t b) {
    const wk_event_key *ka = &Q->key[a], *kb = &Q->key[b];
    if (ka->time != kb->time) return ka->time < kb->time;
    if (ka->kind != kb->kind) return ka->kind < kb->kind;
    return a < b;
}

static void place(wk_event_queue *Q, uint32_t i, uint32_t id) {
    Q->heap[i] = id;
    Q->pos[id] = i;
}

static void sift_up(wk_event_queue *Q, uint32_t i) {
    uint32_t id = Q->heap[i];
    while (i > 0) {
        uint32_t p = (i - 1) / 2;
        if (!less(Q, id, Q->heap[p])) break;
        place(Q, i, Q->heap[p]);
        i = p;
    }
    place(Q, i, id);
}

static void sift_down(wk_event_queue *Q, uint32_t i) {
    uint32_t id = Q->heap[i];
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= Q->size) break;
        if (c + 1 < Q->size && less(Q, Q->heap[c + 1], Q->heap[c])) c++;
        if (!less(Q, Q->heap[c], id)) break;
        place(Q, i, Q->heap[c]);
        i = c;
    }
    place(Q, i, id);
}

void wk_event_queue_init(wk_event_queue *Q) {
    Q->size = Q->cap = 0;
    Q->heap = Q->pos = NULL;
    Q->key = NULL;
}

wk_status wk_event_queue_reserve(wk_run *R, wk_event_queue *Q, uint32_t cap) {
    if (cap <= Q->cap) return WK_OK;
    uint32_t ncap = Q->cap ? Q->cap : 16;
    while (ncap < cap) ncap = ncap > UINT32_MAX / 2 ? cap : ncap * 2;
    /* Allocate all three before touching Q, so a failure leaves Q intact. */
    uint32_t *heap = WK_NEW_ARRAY(R, uint32_t, ncap);
    uint32_t *pos = heap ? WK_NEW_ARRAY(R, uint32_t, ncap) : NULL;
    wk_event_key *key = pos ? WK_NEW_ARRAY(R, wk_event_key, ncap) : NULL;
    if (!key) {
        if (heap) WK_FREE_ARRAY(R, heap, ncap);
        if (pos) WK_FREE_ARRAY(R, pos, ncap);
        return R->err.code;
    }
    for (uint32_t i = 0; i < ncap; i++) pos[i] = i < Q->cap ? Q->pos[i] : WK_NONE;
    for (uint32_t i = 0; i < Q->size; i++) heap[i] = Q->heap[i];
    for (uint32_t i = 0; i < Q->cap; i++) key[i] = Q->key[i];
    uint32_t size = Q->size;
    wk_event_queue_clear(R, Q);
    Q->size = size;
    Q->heap = heap;
    Q->pos = pos;
    Q->key = key;
    Q->cap = ncap;
    return WK_OK;
}

void wk_event_queue_clear(wk_run *R, wk_event_queue *Q) {
    WK_FREE_ARRAY(R, Q->heap, Q->cap);
    WK_FREE_ARRAY(R, Q->pos, Q->cap);
    WK_FREE_ARRAY(R, Q->key, Q->cap);
    Q->size = Q->cap = 0;
}

wk_status wk_event_queue_set(wk_run *R, wk_event_queue *Q, uint32_t id, wk_event_key k) {
    if (id >= Q->cap && wk_event_queue_reserve(R, Q, id + 1) != WK_OK) return R->err.code;
    uint32_t i = Q->pos[id];
    Q->key[id] = k;
    if (i == WK_NONE) {
        place(Q, Q->size++, id);
        sift_up(Q, Q->size - 1);
        wk_count(R, WK_COUNTER_queue_pushes, 1);
    } else {
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
        uint32_t moved = Q->heap[Q->size];
        place(Q, i, moved);
        sift_up(Q, i);
        sift_down(Q, Q->pos[moved]);
    }
    wk_count(R, WK_COUNTER_queue_removes, 1);
}

uint32_t wk_event_queue_peek(const wk_event_queue *Q) { return Q->size ? Q->heap[0] : WK_NONE; }

uint32_t wk_event_queue_pop(wk_run *R, wk_event_queue *Q) {
    if (!Q->size) return WK_NONE;
    uint32_t id = Q->heap[0];
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
        if (Q->pos[Q->heap[i]] != i) return false;
        if (i > 0 && less(Q, Q->heap[i], Q->heap[(i - 1) / 2])) return false;
    }
    return true;
}
