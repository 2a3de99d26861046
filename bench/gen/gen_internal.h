/*
** gen_internal.h: what the generator files share; not for callers (they use
** generators.h).
**
** A family is one function filling x[0..n) and y[0..n) with a simple
** counter-clockwise polygon (or, for the families with holes, a
** wk_gen_rings_fn filling the rings and their sizes).  It draws only from the geometry stream it is
** handed (never the weight stream), checks the parameters it cannot honour
** itself (WK_EINPUT, message "family: what > limit"), and reports through
** *r_out the exact number of reflex vertices it promises, or -1 when the
** count is whatever the randomness gives.  wk_generate then validates the
** polygon and holds the family to that promise.
*/
#ifndef WK_GEN_INTERNAL_H
#define WK_GEN_INTERNAL_H
#include "generators.h"
#include "rng.h"

typedef wk_status (*wk_gen_fn)(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                               double *y, int64_t *r_out);

wk_status wk_gen_convex(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                        int64_t *r_out);
wk_status wk_gen_star(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                      int64_t *r_out);
wk_status wk_gen_notched(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                         int64_t *r_out);
wk_status wk_gen_spiral(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                        int64_t *r_out);
wk_status wk_gen_comb(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                      int64_t *r_out);
wk_status wk_gen_rectilinear(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                             double *y, int64_t *r_out);
wk_status wk_gen_crossing(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                          int64_t *r_out);
wk_status wk_gen_monotone(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                          int64_t *r_out);
wk_status wk_gen_random(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                        int64_t *r_out);
wk_status wk_gen_coastline(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                           int64_t *r_out);

/* A family with holes fills the rings one after the other (outer ring
** counter-clockwise, then each hole clockwise) and their sizes into
** ring_size[0..g->holes] (the split of gen_holes.c). */
typedef wk_status (*wk_gen_rings_fn)(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                                     double *y, uint32_t *ring_size, int64_t *r_out);

wk_status wk_gen_holes(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x, double *y,
                       uint32_t *ring_size, int64_t *r_out);
wk_status wk_gen_convex_holes(wk_run *R, const wk_gen_params *g, wk_rng *rng, double *x,
                              double *y, uint32_t *ring_size, int64_t *r_out);
/* The vertex split of the families with holes (gen_holes.c): fails with
** WK_EINPUT unless n >= 3 holes + 3. */
wk_status wk_gen_ring_split(wk_run *R, const wk_gen_params *g, uint32_t *ring_size);

/* For the families whose r follows from n: fail unless g->r is -1 or equal
** to the rule's value; rule is the formula as text, for the message (NULL
** when r is a constant). */
wk_status wk_gen_fixed_r(wk_run *R, const wk_gen_params *g, int64_t r, const char *rule);

/* The half-size of the box most families fill: coordinates lie in about
** [-WK_GEN_BOX, WK_GEN_BOX]^2 (README.md lists each family's box). */
#define WK_GEN_BOX 1000.0
#define WK_GEN_PI 3.14159265358979323846

#endif
