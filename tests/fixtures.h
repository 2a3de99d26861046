/*
** fixtures.h: small helpers shared by the Criterion tests that build
** polygons and skeletons by hand.  Header-only (static functions), included
** by test files after <criterion/criterion.h>.
*/
#ifndef WK_TEST_FIXTURES_H
#define WK_TEST_FIXTURES_H
#include "wskel.h"

/* Every test closes its run with no live bytes left. */
#define ASSERT_CLEAN_CLOSE(R) cr_assert_eq(wk_run_close(&(R)), 0, "leaked %zu bytes", (R).alloc.live)

/* Counter `name` of variant V (NULL: the engine's) in c; fails the test if V
** has no such counter. */
static inline uint64_t counter_in(const wk_counters *c, const wk_variant *V, const char *name) {
    uint32_t id = 0;
    cr_assert(wk_counter_find(V, name, &id), "no counter %s", name);
    return c->c[id];
}
/* Counter `name` of the run's variant (R->variant, set by wk_solve). */
static inline uint64_t counter(const wk_run *R, const char *name) {
    return counter_in(&R->counters, R->variant, name);
}

typedef struct arc4 { uint32_t a, b, l, r; } arc4;

/* A validated polygon from arrays (w may be NULL); fails the test if rejected. */
static inline wk_polygon *polygon(wk_run *R, uint32_t n, const double *x, const double *y,
                                  const double *w) {
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_from_arrays(R, n, x, y, w, "t.wpoly", NULL, &P);
    cr_assert_eq(st, WK_OK, "polygon rejected: %s", R->err.msg);
    return P;
}

/* A skeleton of P with extra nodes (x, y, t) and the given arcs, not validated. */
static inline wk_skeleton *skeleton(wk_run *R, const wk_polygon *P, uint32_t n_extra,
                                    const wk_node *extra, uint32_t n_arcs, const arc4 *arcs) {
    wk_skeleton *S;
    cr_assert_eq(wk_skeleton_new(R, P, &S), WK_OK);
    for (uint32_t i = 0; i < n_extra; i++) {
        uint32_t id;
        cr_assert_eq(wk_skeleton_add_node(R, S, extra[i].x, extra[i].y, extra[i].t, &id), WK_OK);
    }
    for (uint32_t i = 0; i < n_arcs; i++)
        cr_assert_eq(wk_skeleton_add_arc(R, S, arcs[i].a, arcs[i].b, arcs[i].l, arcs[i].r), WK_OK);
    return S;
}

#endif
