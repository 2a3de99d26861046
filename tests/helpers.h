/*
** helpers.h: what the Criterion tests share.  Header-only (static inline
** functions), included by test files after <criterion/criterion.h>.
**
**   quick()               WSKEL_TEST_QUICK is set, not empty and not "0" (the
**                         ASan run sets it): sweeps drop their largest sizes
**   now_s()               seconds of a monotonic clock, for timing lines
**   err_text()            R's first failure as text ("file:line: message")
**   ASSERT_CLEAN_CLOSE(R) the run closes with no live bytes left
**   counter(), counter_in()  a counter by name
**   variant()             a registered variant by name (asserted)
**   data_path(), read_hand()  files of tests/data
**   polygon(), polygon_named()  a validated polygon from arrays (asserted)
**   max_weight()          a polygon's largest weight
**   gen(), gen_polygon()  a polygon of a generator family (bench/gen)
**   arc4, skeleton(), has_arc()  skeletons built and searched by hand
**   SQ_*, L_*             the unit square and the L shape with their skeletons
**   same_skeleton()       two skeletons compared within a tolerance
*/
#ifndef WK_TEST_HELPERS_H
#define WK_TEST_HELPERS_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "generators.h"
#include "wskel.h"

static const double PI = 3.14159265358979323846;

/* ------------------------------------------------------------ run */

/* Quick mode: WSKEL_TEST_QUICK set to anything but "" or "0". */
static inline bool quick(void) {
    const char *q = getenv("WSKEL_TEST_QUICK");
    return q && *q && strcmp(q, "0") != 0;
}

/* Seconds of a monotonic clock (CLOCK_MONOTONIC where <time.h> has it, that
** is when the test file asks for POSIX; else C11's timespec_get). */
static inline double now_s(void) {
    struct timespec ts;
#ifdef CLOCK_MONOTONIC
    clock_gettime(CLOCK_MONOTONIC, &ts);
#else
    timespec_get(&ts, TIME_UTC);
#endif
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* R's first failure formatted into buf, "(no error recorded)" if none. */
static inline void err_text(const wk_run *R, char *buf, size_t size) {
    if (R->err.code == WK_OK && !R->err.msg[0])
        snprintf(buf, size, "(no error recorded)");
    else
        wk_error_format(R, buf, size);
}

/* Every test closes its run with no live bytes left. */
#define ASSERT_CLEAN_CLOSE(R) \
    cr_assert_eq(wk_run_close(&(R)), 0, "leaked %zu bytes", (R).alloc.live)

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

/* The registered variant `name`; fails the test if there is none. */
static inline const wk_variant *variant(const char *name) {
    const wk_variant *V = wk_variant_find(name);
    cr_assert_not_null(V, "variant %s is not registered", name);
    return V;
}

/* ------------------------------------------------------- polygons */

/* tests/data/REL, found next to this header so the runner works from the
** repository root (make) or from anywhere when compiled with a full path. */
static inline void data_path(char *buf, size_t size, const char *rel) {
    const char *f = __FILE__;
    const char *slash = strrchr(f, '/');
    if (slash)
        snprintf(buf, size, "%.*s/data/%s", (int)(slash - f), f, rel);
    else
        snprintf(buf, size, "data/%s", rel);
}

/* tests/data/hand/NAME.wpoly, read; fails the test if it cannot be read. */
static inline wk_polygon *read_hand(wk_run *R, const char *name) {
    char rel[256], path[512], msg[1024];
    snprintf(rel, sizeof rel, "hand/%s.wpoly", name);
    data_path(path, sizeof path, rel);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_file(R, path, &P);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "%s: cannot read: %s", path, msg);
    return P;
}

/* A validated polygon from arrays (w may be NULL), named `name` in
** messages; fails the test if rejected. */
static inline wk_polygon *polygon_named(wk_run *R, uint32_t n, const double *x, const double *y,
                                        const double *w, const char *name) {
    wk_polygon *P = NULL;
    char msg[1024];
    wk_status st = wk_polygon_from_arrays(R, n, x, y, w, name, NULL, &P);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "%s rejected: %s", name, msg);
    return P;
}
static inline wk_polygon *polygon(wk_run *R, uint32_t n, const double *x, const double *y,
                                  const double *w) {
    return polygon_named(R, n, x, y, w, "t.wpoly");
}

/* P's largest weight. */
static inline double max_weight(const wk_polygon *P) {
    double m = 0;
    for (uint32_t i = 0; i < P->n; i++) m = fmax(m, P->w[i]);
    return m;
}

/* The polygon of generator family `family` with n vertices, r reflex ones
** (-1: the family's default), `holes` holes (gen: none), seed and weight
** mode `weights` (NULL: unit; see wk_gen_parse_weights).  Returns
** wk_generate's status: WK_EINPUT when the family cannot make this n or r. */
static inline wk_status gen_holes(wk_run *R, const char *family, uint32_t n, int64_t r,
                                  uint32_t holes, uint64_t seed, const char *weights,
                                  wk_polygon **P) {
    wk_gen_params g;
    wk_gen_params_init(&g);
    g.family = family;
    g.n = n;
    g.r = r;
    g.holes = holes;
    g.seed = seed;
    if (weights && wk_gen_parse_weights(R, weights, &g) != WK_OK) return R->err.code;
    return wk_generate(R, &g, P);
}
static inline wk_status gen(wk_run *R, const char *family, uint32_t n, int64_t r, uint64_t seed,
                            const char *weights, wk_polygon **P) {
    return gen_holes(R, family, n, r, 0, seed, weights, P);
}
/* The same with the family's r, asserted to succeed. */
static inline wk_polygon *gen_polygon(wk_run *R, const char *family, uint32_t n, uint64_t seed,
                                      const char *weights) {
    wk_polygon *P = NULL;
    char msg[1024];
    wk_status st = gen(R, family, n, -1, seed, weights, &P);
    err_text(R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "%s n=%u seed=%llu weights=%s: %s", family, n,
                 (unsigned long long)seed, weights ? weights : "unit", msg);
    return P;
}

/* ------------------------------------------------------ skeletons */

typedef struct arc4 { uint32_t a, b, l, r; } arc4;

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

/* The arc a-b with face l on the left of a->b and r on the right exists
** (in either direction). */
static inline bool has_arc(const wk_skeleton *S, uint32_t a, uint32_t b, uint32_t l, uint32_t r) {
    for (uint32_t i = 0; i < S->n_arcs; i++) {
        const wk_arc *c = &S->arcs[i];
        if ((c->a == a && c->b == b && c->left == l && c->right == r) ||
            (c->a == b && c->b == a && c->left == r && c->right == l))
            return true;
    }
    return false;
}

/* The unit square and its skeleton (one node at the centre). */
static const double SQ_X[4] = {0, 1, 1, 0}, SQ_Y[4] = {0, 0, 1, 1};
static const wk_node SQ_NODES[1] = {{0.5, 0.5, 0.5}};
static const arc4 SQ_ARCS[4] = {{0, 4, 3, 0}, {1, 4, 0, 1}, {2, 4, 1, 2}, {3, 4, 2, 3}};

/* L shape: the horizontal arm [0,2]x[0,1], the vertical arm [0,1]x[0,2];
** vertex 3 is reflex. */
static const double L_X[6] = {0, 2, 2, 1, 1, 0}, L_Y[6] = {0, 0, 1, 1, 2, 2};
static const wk_node L_NODES[3] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {0.5, 1.5, 0.5}};
static const arc4 L_ARCS[8] = {{0, 6, 5, 0}, {1, 7, 0, 1}, {2, 7, 1, 2}, {3, 6, 2, 3},
                               {4, 8, 3, 4}, {5, 8, 4, 5}, {6, 7, 2, 0}, {6, 8, 5, 3}};

/* ------------------------------------------------ skeleton comparison */

/* same_skeleton() and sk_match: tests/same_skeleton.h (shared with the fuzz
** target, which has no Criterion). */
#include "same_skeleton.h"

#endif
