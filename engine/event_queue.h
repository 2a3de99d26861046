/*
** event_queue.h: pending kinetic events, earliest first.
** An indexed binary min-heap over ids 0..cap-1 (one slot per id, e.g. one per
** wavefront vertex); pos[id] finds an entry so its key can be updated or the
** entry removed in O(log n) when a neighbour changes.
** Invariants between calls: heap order on (time, kind, id), the id breaking
** every tie, so pops are deterministic; heap[pos[id]].id == id for a queued id,
** pos[id] == WK_NONE otherwise.  Every operation is reported to the run's
** observer (queue counters).
*/
#ifndef WK_EVENT_QUEUE_H
#define WK_EVENT_QUEUE_H
#include "wskel.h"

typedef struct wk_event_key {
    double time;   /* when the event happens */
    uint32_t kind; /* orders simultaneous events of different kinds */
} wk_event_key;

/* A heap entry holds its key: comparisons read the heap array only.  They
** read key[id] in an array indexed by id, one cache miss per comparison on
** a big wavefront (coastline 10^6: the sifts were 9% of the run, perf). */
typedef struct wk_event_entry {
    double time;
    uint32_t kind, id;
} wk_event_entry;

typedef struct wk_event_queue {
    uint32_t size, cap;   /* queued entries; ids are < cap */
    wk_event_entry *heap; /* heap[i]: the entry at heap position i */
    uint32_t *pos;        /* pos[id]: heap position or WK_NONE */
} wk_event_queue;

void wk_event_queue_init(wk_event_queue *Q);
/* Make room for ids < cap (keeps the entries). */
wk_status wk_event_queue_reserve(wk_run *R, wk_event_queue *Q, uint32_t cap);
void wk_event_queue_clear(wk_run *R, wk_event_queue *Q);
/* Insert id or, if queued, change its key. */
wk_status wk_event_queue_set(wk_run *R, wk_event_queue *Q, uint32_t id, wk_event_key k);
/* Remove id if queued (no-op otherwise). */
void wk_event_queue_remove(wk_run *R, wk_event_queue *Q, uint32_t id);
/* Smallest id or WK_NONE when empty; pop removes it. */
uint32_t wk_event_queue_peek(const wk_event_queue *Q);
uint32_t wk_event_queue_pop(wk_run *R, wk_event_queue *Q);
bool wk_event_queue_contains(const wk_event_queue *Q, uint32_t id);
/* The time of queued id (it must be queued). */
static inline double wk_event_queue_time(const wk_event_queue *Q, uint32_t id) {
    return Q->heap[Q->pos[id]].time;
}
/* Check the heap invariants (tests and debug builds). */
bool wk_event_queue_check(const wk_event_queue *Q);

#endif
