/*
** naive.c: the reference variant.  Classical event-driven wavefront
** simulation (engine/wavefront.c) with brute-force split detection
** (split_brute.c): a reflex vertex is tested against every piece of its
** wavefront cycle.  Clarity beats speed: this is the oracle the other
** variants are tested against, and the fallback a variant hands an input
** to when its own algorithm cannot certify the result
** (wk_variant_reference()).  It has no counters of its own.
*/
#include "naive.h"
#include "variant.h"

static wk_status naive_run(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    return wk_wavefront_run(R, P, &naive_split_finder, NULL, out);
}

const wk_variant wk_variant_naive = {
    "naive",
    "reference: event-driven wavefront with brute-force split detection",
    WK_VARIANT_WEIGHTS | WK_VARIANT_PSLG,
    NULL,
    0,
    naive_run,
    NULL, /* no timed phase */
};
