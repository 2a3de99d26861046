/*
** variant.h: the interface every skeleton algorithm implements.  A variant
** (variants/<name>/) defines one const wk_variant and is listed in
** variants/registry.c; it includes engine headers only, never another
** variant's.  The engine calls a variant only through this struct, so it
** names none.
*/
#ifndef WK_VARIANT_H
#define WK_VARIANT_H
#include "wskel.h"

struct wk_variant {
    const char *name;
    const char *summary;
    unsigned flags; /* WK_VARIANT_* */
    /* The variant's own counters: counters[j] has id WK_ENGINE_COUNTERS + j
    ** (at most WK_VARIANT_COUNTERS_MAX).  Give them an enum in the variant's
    ** header; the JSON stats, the harness CSV, the regression check and the
    ** README's counter table all come from these declarations. */
    const wk_counter_def *counters;
    uint32_t n_counters;
    /* Compute P's skeleton; on failure R->err says why and *out stays NULL
    ** (wk_solve frees whatever is left).  WK_EUNSUPPORTED: the variant does
    ** not apply to P. */
    wk_status (*run)(wk_run *R, const wk_polygon *P, wk_skeleton **out);
    /* The variant's timed phase, a part of run whose wall time the variant
    ** adds to R->phase_s (wk_phase_begin / wk_phase_end), so benchmarks can
    ** show its share; a short name for plots and --stats, or NULL (none). */
    const char *phase;
};

/* A variant lists its counters once, as X(name, meaning), e.g.
**     #define AR_COUNTER_LIST(X) X(start_events, "a Steiner vertex started") ...
**     WK_VARIANT_COUNTER_ENUM(AR_COUNTER_LIST)   (in its header: WK_VC_name ids)
**     static const wk_counter_def ar_counters[] = {
**         AR_COUNTER_LIST(WK_VARIANT_COUNTER_DEF)};   (in the file of its wk_variant)
** A variant's files are compiled apart from every other variant's, so the
** WK_VC_ names never meet. */
#define WK_VARIANT_COUNTER_ID(name, meaning) WK_VC_##name,
#define WK_VARIANT_COUNTER_DEF(name, meaning) {#name, meaning},
#define WK_VARIANT_COUNTER_ENUM(LIST) \
    enum { WK_VC_BEFORE_FIRST_ = WK_ENGINE_COUNTERS - 1, LIST(WK_VARIANT_COUNTER_ID) WK_VC_END_ };
#define WK_VARIANT_COUNTER_TABLE(LIST) {LIST(WK_VARIANT_COUNTER_DEF)}

#endif
