/*
** naive.c: the reference variant.  Classical event-driven wavefront
** simulation (engine/wavefront.c) with brute-force split detection
** (engine/split_brute.c): a reflex vertex is tested against every piece of
** its wavefront cycle.  Clarity beats speed: this is the oracle the other
** variants are tested against.
*/
#include "../variant.h"
#include "wavefront.h"

static wk_status naive_run(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    return wk_wavefront_run(R, P, &wk_split_finder_brute_force, NULL, out);
}

const wk_variant wk_variant_naive = {
    "naive",
    "reference: event-driven wavefront with brute-force split detection",
    WK_VARIANT_WEIGHTS,
    naive_run,
};
