/*
** monotone.c: the monotone variant's entry (001: O(n log n) positively
** weighted straight skeletons of monotone polygons).
**
** Steps (monotone.h has the shared model): find a direction of
** monotonicity or refuse (WK_EUNSUPPORTED, CLI exit 2); simulate the lower and the
** upper chain, each extended by rays (edge collapses only); walk the merge
** chain from v_w to v_e; clip the chain skeletons to their sides of it;
** validate the result.  A monotone polygon the merge cannot certify goes
** to the reference wavefront instead (monotone_run, below): never a wrong
** output, and no refusal except "monotone in no direction".  Every
** allocation goes through R and is freed before returning, so a failure at
** any point leaves no output and no live bytes.
*/
#include "monotone.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void mono_clear(mono *M) {
    wk_run *R = M->R;
    WK_FREE_ARRAY(R, M->L, M->P->n);
    for (int c = 0; c < 2; c++) wk_mono_chain_clear(R, &M->ch[c]);
    WK_FREE_ARRAY(R, M->mn, M->cap_mn);
    WK_FREE_ARRAY(R, M->cr, M->cap_cr);
    WK_FREE_ARRAY(R, M->ma, M->cap_ma);
}

/* 001's pipeline on P.  WK_EUNSUPPORTED: P is monotone in no direction (the
** variant's answer, not a failure).  WK_EALGO otherwise: the
** merge could not certify this input (see README.md); the caller falls back.
** Validates its own result. */
static wk_status monotone_merge_run(mono *M, bool reverse, wk_skeleton **out) {
    wk_run *R = M->R;
    const wk_polygon *P = M->P;
    double wmax = 0;
    for (uint32_t i = 0; i < P->n; i++) wmax = P->w[i] > wmax ? P->w[i] : wmax;
    /* the engine's policy (tolerance.h), as the wavefront has it */
    M->eps_d = R->opt.tol_scale * WK_TOL_REL * wk_polygon_scale(P);
    M->eps_t = WK_TOL_TIME * M->eps_d / wmax;
    wk_status st;
    M->L = WK_NEW_ARRAY(R, wk_offset_line, P->n);
    if (!M->L) return R->err.code;
    M->o = wk_polygon_centre(P);
    for (uint32_t i = 0; i < P->n; i++) wk_offset_line_of_edge_at(P, i, M->o, &M->L[i]);
    if ((st = wk_mono_direction(M)) != WK_OK) return st;
    if (reverse && (st = wk_mono_direction_reverse(M)) != WK_OK) return st;
    if (!M->strict) {
        /* Walls perpendicular to the sweep with weights: the merge walk's
        ** local decisions were seen to pass the validator with a skeleton
        ** other than naive's (rectilinear family, uniform weights). */
        for (uint32_t i = 1; i < P->n; i++)
            if (P->w[i] != P->w[0])
                return WK_FAIL(R, WK_EALGO, P->name, 0,
                               "monotone: the polygon is monotone only with edges perpendicular "
                               "to the sweep, and has unequal weights: not handled");
    }
    /* Sub-tolerance features (tolerance.h, WK_MONO_TINY_EDGE_REL): the
    ** reference resolves an edge far below eps_d by its groups, the chains
    ** by their own local decisions; both pass the validator, but only one
    ** can be the reference's skeleton, so such polygons go to the reference
    ** (27 of 28 stress differences had such an edge). */
    double tiny = R->opt.tol_scale * WK_MONO_TINY_EDGE_REL * wk_polygon_scale(P);
    for (uint32_t i = 0; i < P->n; i++) {
        wk_point a = P->p[i], b = P->p[wk_polygon_next(P, i)];
        if (hypot(b.x - a.x, b.y - a.y) < tiny)
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: edge %u is %.3g long, below the %.3g the chains resolve "
                           "like the reference", i, hypot(b.x - a.x, b.y - a.y), tiny);
    }
    uint32_t n = P->n;
    M->ch[0].first = M->vw; /* lower: v_w -> v_e */
    M->ch[0].m = (M->ve + n - M->vw) % n;
    M->ch[1].first = M->ve; /* upper: v_e -> v_w */
    M->ch[1].m = (M->vw + n - M->ve) % n;
    for (uint32_t c = 0; c < 2; c++)
        if ((st = wk_mono_chain_build(M, c)) != WK_OK) return st;
    if ((st = wk_mono_merge(M)) != WK_OK) return st;
    if ((st = wk_mono_assemble(M, out)) != WK_OK) return st;
    /* The last line of defence (STYLE.md: never a wrong skeleton): the
    ** validator is about linear, and degenerate inputs (walls facing each
    ** other, M' along chain arcs) and weights (README.md) are where the
    ** local decisions of merge.c and assemble.c can go wrong. */
    st = wk_validate(R, P, *out, 0, NULL);
    if (st != WK_OK) {
        wk_skeleton_free(R, *out);
        *out = NULL;
        if (st != WK_ENOMEM) {
            char msg[sizeof R->err.msg];
            snprintf(msg, sizeof msg, "%s", R->err.msg);
            memset(&R->err, 0, sizeof R->err); /* report it as this variant's failure */
            st = WK_FAIL(R, WK_EALGO, P->name, 0, "monotone: the result fails validation (%s)",
                         msg);
        }
    }
    return st;
}

/* Where 001's merge cannot certify its result (weighted inputs whose chain
** skeletons do not describe the polygon, walls perpendicular to the sweep
** with weights, a walk that gets lost in a degenerate pass), the input goes
** to the reference variant (wk_variant_reference(), through its registry
** entry, not its code): a right skeleton at the reference's cost, never
** a wrong one and never a refusal of a monotone polygon.  The
** reference_fallbacks counter says when that happened, and the first
** attempt's memory is freed before the fallback starts. */
static wk_status monotone_run(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    *out = NULL;
    /* 001 is about monotone polygons: one boundary chain pair, no holes */
    if (P->n_rings > 1)
        return WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                       "variant monotone does not apply to polygons with holes (this one has %u); "
                       "use --variant naive or arrangement",
                       P->n_rings - 1);
    mono M;
    memset(&M, 0, sizeof M);
    M.R = R;
    M.P = P;
    *out = NULL;
    wk_status st = monotone_merge_run(&M, false, out);
    bool again = st == WK_EALGO && M.coplanar_later;
    mono_clear(&M);
    if (again) {
        /* The walk entered a coplanar pair of faces from its later side,
        ** where it cannot place M' (merge.c).  Swept the other way, M'
        ** meets that pair first where the two faces first touch, which the
        ** walk finds (a crossing of two traces), and then follows their
        ** vertex forwards in time.  Once: if that walk fails too, the
        ** reference.  tests/data/fuzz/mismatch_monotone_cross_far_vertex.wpoly
        ** and mismatch_monotone_integer_12gon.wpoly take this path. */
        wk_run_clear_error(R);
        memset(&M, 0, sizeof M);
        M.R = R;
        M.P = P;
        st = monotone_merge_run(&M, true, out);
        mono_clear(&M);
    }
    if (st != WK_EALGO) return st; /* ok, no memory, or WK_EUNSUPPORTED */
    return wk_solve_by_reference(R, P, WK_VC_reference_fallbacks, out);
}

static const wk_counter_def mono_counters[] = WK_VARIANT_COUNTER_TABLE(MONO_COUNTER_LIST);

const wk_variant wk_variant_monotone = {
    "monotone",
    "001: monotone polygons only, chain skeletons merged along the merge chain, O(n log n)",
    WK_VARIANT_WEIGHTS,
    mono_counters,
    sizeof mono_counters / sizeof mono_counters[0],
    monotone_run,
    NULL, /* no timed phase */
};
