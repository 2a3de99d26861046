/*
** generators.h: seeded polygon families for tests and benchmarks.
** Every generator is deterministic in (family, n, r, seed, weights), returns a
** simple counter-clockwise polygon with exactly n vertices (and exactly r reflex
** vertices where the family controls r), validated by wk_polygon_from_arrays,
** or fails with WK_EINPUT naming the parameter it cannot honour.
** See bench/README.md for what each family looks like and why it exists.
*/
#ifndef WK_GENERATORS_H
#define WK_GENERATORS_H
#include "wskel.h"

typedef enum wk_weight_mode {
    WK_W_UNIT = 0,   /* all 1 */
    WK_W_UNIFORM,    /* uniform in [a, b] */
    WK_W_TWO,        /* a or b, each with probability 1/2 */
    WK_W_INT         /* integers uniform in [a, b] (rounded) */
} wk_weight_mode;

typedef struct wk_gen_params {
    const char *family; /* star comb spiral notched crossing random monotone rectilinear convex */
    uint32_t n;         /* vertices */
    int64_t r;          /* reflex vertices wanted; -1: the family's default */
    uint64_t seed;
    wk_weight_mode weights;
    double wa, wb;      /* weight range / values (defaults 0.5, 2 / 1, 3 for INT) */
} wk_gen_params;

/* Defaults: r = -1, seed = 1, unit weights, wa = 0.5, wb = 2. */
void wk_gen_params_init(wk_gen_params *g);
wk_status wk_generate(wk_run *R, const wk_gen_params *g, wk_polygon **out);
/* Parse a weight mode: "unit", "uniform[:a:b]", "two[:a:b]", "int[:a:b]". */
wk_status wk_gen_parse_weights(wk_run *R, const char *s, wk_gen_params *g);
/* NULL-terminated list of family names. */
extern const char *const wk_gen_families[];

#endif
