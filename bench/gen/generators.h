/*
** generators.h: seeded polygon families for tests and benchmarks.
** Every generator is deterministic in (family, n, r, holes, seed, weights),
** returns a simple polygon with exactly n vertices over 1 + holes rings (the
** outer ring counter-clockwise, holes clockwise, as stored; exactly r reflex
** vertices where the family controls r), validated by wk_polygon_from_rings,
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
    const char *family; /* star comb spiral notched crossing random monotone rectilinear convex
                           holes coastline */
    uint32_t n;         /* vertices, over all rings */
    uint32_t holes;     /* holes wanted (default 0); only the families for which
                           wk_gen_family_takes_holes is true take holes > 0 */
    int64_t r;          /* reflex vertices wanted; -1: the family's default */
    uint64_t seed;
    wk_weight_mode weights;
    double wa, wb;      /* weight range (UNIFORM, INT) or the two values (TWO);
                           wk_gen_parse_weights sets them: uniform 0.5..2,
                           two 1|3, int 1..4 unless given */
} wk_gen_params;

/* Bumped whenever some family's output changes for the same parameters, so a
** file's header says which generator made it. */
#define WK_GEN_VERSION 2
/* Largest n any family accepts: the curved families keep every turn far
** above double rounding up to here (see bench/README.md). */
#define WK_GEN_N_MAX 10000000u

/* Defaults: r = -1, holes = 0, seed = 1, unit weights, wa = 0.5, wb = 2. */
void wk_gen_params_init(wk_gen_params *g);
/* Generate g's polygon; on success *out is owned by the caller (free with
** wk_polygon_free).  Failures leave *out NULL: WK_EUSAGE for an unknown
** family or a bad weight range, WK_EINPUT for an n or r the family cannot
** honour (the message names both, e.g. "notched: r=60 > n/2=50"), WK_ENOMEM,
** and WK_EALGO only if a family broke its own promise (a generator bug). */
wk_status wk_generate(wk_run *R, const wk_gen_params *g, wk_polygon **out);
/* Parse a weight mode: "unit", "uniform[:a:b]", "two[:a:b]", "int[:a:b]"
** into g->weights, g->wa, g->wb; WK_EUSAGE if malformed. */
wk_status wk_gen_parse_weights(wk_run *R, const char *s, wk_gen_params *g);
/* Canonical text of g's weight mode ("unit", "uniform:0.5:2", ...), which
** wk_gen_parse_weights reads back to the same mode. */
void wk_gen_weights_format(const wk_gen_params *g, char *buf, size_t size);
/* NULL-terminated list of family names. */
extern const char *const wk_gen_families[];
/* One-line description of a family (for --list); NULL if unknown. */
const char *wk_gen_family_summary(const char *family);
/* Whether the family takes holes > 0 (holes, convex); false if unknown. */
bool wk_gen_family_takes_holes(const char *family);

#endif
