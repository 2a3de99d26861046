/*
** counters.c: the counter declarations (the engine's list in wskel.h, each
** variant's in its wk_variant) and the counting observer, the only code
** that writes wk_counters.
*/
#include "variant.h"

#include <string.h>

static const wk_counter_def engine_counters[WK_ENGINE_COUNTERS] = {
#define WK_ENGINE_COUNTER_DEF(name, meaning) {#name, meaning},
    WK_ENGINE_COUNTER_LIST(WK_ENGINE_COUNTER_DEF)
#undef WK_ENGINE_COUNTER_DEF
};

uint32_t wk_counter_count(const wk_variant *V) {
    return WK_ENGINE_COUNTERS + (V ? V->n_counters : 0);
}

const wk_counter_def *wk_counter_def_at(const wk_variant *V, uint32_t id) {
    if (id < WK_ENGINE_COUNTERS) return &engine_counters[id];
    if (V && id - WK_ENGINE_COUNTERS < V->n_counters) return &V->counters[id - WK_ENGINE_COUNTERS];
    return NULL;
}

bool wk_counter_find(const wk_variant *V, const char *name, uint32_t *id) {
    for (uint32_t i = 0; i < wk_counter_count(V); i++)
        if (strcmp(wk_counter_def_at(V, i)->name, name) == 0) {
            *id = i;
            return true;
        }
    return false;
}

bool wk_counter_lookup(const wk_run *R, const char *name, uint64_t *value) {
    uint32_t id;
    if (!wk_counter_find(R->variant, name, &id)) return false;
    *value = R->counters.c[id];
    return true;
}

/* Adds name to names[0..*n) unless it is there (a name two variants share
** is one column). */
static void add_name(const char **names, uint32_t cap, uint32_t *n, const char *name) {
    for (uint32_t j = 0; j < *n && j < cap; j++)
        if (strcmp(names[j], name) == 0) return;
    if (*n < cap) names[*n] = name;
    (*n)++;
}

uint32_t wk_counter_union(const char **names, uint32_t cap) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < WK_ENGINE_COUNTERS; i++) add_name(names, cap, &n, engine_counters[i].name);
    for (size_t v = 0; wk_variant_at(v); v++) {
        const wk_variant *V = wk_variant_at(v);
        for (uint32_t j = 0; j < V->n_counters; j++) add_name(names, cap, &n, V->counters[j].name);
    }
    return n;
}

/* ---- the counting observer ---- */

static void count_event(void *ud, uint32_t counter, const wk_event *e) {
    (void)e;
    if (counter < WK_COUNTERS_MAX) ((wk_counters *)ud)->c[counter]++;
}

static void count_work(void *ud, uint32_t counter, uint64_t n) {
    if (counter < WK_COUNTERS_MAX) ((wk_counters *)ud)->c[counter] += n;
}

const wk_observer wk_observer_counting = {count_event, count_work, NULL};

/* ---- what callers may ask of a variant ---- */

const char *wk_variant_name(const wk_variant *V) { return V->name; }
const char *wk_variant_summary(const wk_variant *V) { return V->summary; }
unsigned wk_variant_flags(const wk_variant *V) { return V->flags; }
const char *wk_variant_phase(const wk_variant *V) { return V->phase; }

const char *wk_variant_with_flags(unsigned flags) {
    for (size_t i = 0; wk_variant_at(i); i++)
        if ((wk_variant_at(i)->flags & flags) == flags) return wk_variant_at(i)->name;
    return NULL;
}
