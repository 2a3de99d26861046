/*
** deforming.c: the deforming-polygon variant (paper 004): the wavefront
** as a polygon whose vertices move at constant velocity, advanced by
** a kinetic search over predictor windows (predict.c), corrected back to
** the earliest event and changed there (resolve.c), until every cycle has vanished.
** Positive weights only; polygons with holes (every cycle is one more
** linked list, and the penetration search covers them all).
**
** The step-size policy (README, predict.c): a window lasts while a vertex
** of the mean speed crosses DF_WINDOW_CELLS grid cells, times --step (1 by
** default); after a window without events it doubles, after one closed
** because half its vertices changed it halves.  Event times come from the
** exact interpolation, not from the windows, so the skeleton does
** not depend on the increment (tests/test_deforming.py halves and doubles
** it).
**
** The result is certified: the skeleton must pass wk_validate; when it
** does not, or the resolution meets a configuration it does not handle
** (WK_EALGO), the input goes to the reference variant (counted on
** reference_fallbacks): never a wrong skeleton.
*/
#include "deforming.h"

#include <math.h>
#include <string.h>

wk_status df_add_vertex(df_state *D, const df_vertex *V, uint32_t *id) {
    wk_run *R = D->R;
    if (WK_GROW(R, D->v, D->cap_v, D->nv + 1) != WK_OK ||
        WK_GROW(R, D->member, D->cap_member, D->nv + 1) != WK_OK ||
        WK_GROW(R, D->mark, D->cap_mark, D->nv + 1) != WK_OK ||
        WK_GROW(R, D->k, D->cap_k, D->nv + 1) != WK_OK)
        return R->err.code;
    D->v[D->nv] = *V;
    D->member[D->nv] = WK_NONE;
    D->mark[D->nv] = 0;
    D->k[D->nv] = (df_kin){0, 0, WK_NONE, 0};
    df_touch(D, D->nv);
    *id = D->nv++;
    D->n_alive++;
    return WK_OK;
}

static void df_free(df_state *D) {
    wk_run *R = D->R;
    df_resolve_free(D);
    df_predict_free(D);
    WK_FREE_ARRAY(R, D->L, D->P->n);
    WK_FREE_ARRAY(R, D->v, D->cap_v);
    WK_FREE_ARRAY(R, D->member, D->cap_member);
    WK_FREE_ARRAY(R, D->mark, D->cap_mark);
    WK_FREE_ARRAY(R, D->ev, D->cap_ev);
    WK_FREE_ARRAY(R, D->k, D->cap_k);
}

/* The input vertices: vertex i between edges prev(i) and i. */
static wk_status df_start(df_state *D) {
    wk_run *R = D->R;
    const wk_polygon *P = D->P;
    D->o = wk_polygon_centre(P);
    D->L = WK_NEW_ARRAY(R, wk_offset_line, P->n);
    if (!D->L) return R->err.code;
    D->wmax = 0;
    for (uint32_t e = 0; e < P->n; e++) {
        if (!(P->w[e] > 0)) {
            D->nonpositive = true;
            if (!(R->opt.height > 0))
                return WK_FAIL(R, WK_EINPUT, P->name, 0,
                               "edge %u has weight %g <= 0: the wavefront need not vanish, so a "
                               "height (--height H) is required",
                               wk_polygon_input_edge(P, e), P->w[e]);
        }
        wk_offset_line_of_edge_at(P, e, D->o, &D->L[e]);
        if (fabs(P->w[e]) > D->wmax) D->wmax = fabs(P->w[e]);
    }
    if (!(D->wmax > 0)) D->wmax = 1; /* every edge a wall: times are heights */
    double scale = wk_polygon_scale(P);
    /* With positive weights every point of P is within scale of every
    ** edge's line, so the wavefront has vanished by scale / wmin: a vertex
    ** alive after twice that lost an event (the run fails, and the input
    ** goes to the reference) rather than doubling the step to infinity. */
    if (!D->nonpositive) {
        double wmin = INFINITY;
        for (uint32_t e = 0; e < P->n; e++)
            if (P->w[e] < wmin) wmin = P->w[e];
        D->t_vanish = 2 * scale / wmin;
    }
    D->eps_d = R->opt.tol_scale * WK_TOL_REL * scale;
    D->eps_t = WK_TOL_TIME * D->eps_d / D->wmax;
    if (wk_skeleton_new(R, P, &D->S) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < P->n; i++) {
        uint32_t ein = wk_polygon_prev(P, i), id;
        df_vertex V = {{P->p[i].x - D->o.x, P->p[i].y - D->o.y}, {0, 0}, 0, ein, i,
                       ein, wk_polygon_next(P, i), i, 1};
        wk_velocity_kind kind = wk_vertex_velocity(&D->L[ein], &D->L[i], &V.v);
        if (kind == WK_VEL_ANTIPARALLEL)
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "deforming: vertex %u lies between antiparallel edges",
                           P->input_index[i]);
        if (df_add_vertex(D, &V, &id) != WK_OK) return R->err.code;
    }
    /* input vertices between parallel edges of different weight: the
    ** collinear rule at t = 0 */
    for (uint32_t i = 0; i < P->n; i++)
        if (D->v[i].alive && df_collinear_rule(D, i, 0.0, false) != WK_OK) return R->err.code;
    D->scale = scale;
    D->dt_near = R->opt.step_scale * scale / (ceil(sqrt((double)P->n)) * D->wmax);
    D->dt = R->opt.step_scale * DF_WINDOW_CELLS;
    return WK_OK;
}

/* The roof cut at height H: every alive vertex ends at its position at H
** (an arc of its trace), and every piece becomes a cap arc between the
** nodes of its ends, its edge's face on the right (behind the piece) and
** the cap (WK_NONE) on the left (the unswept region). */
static wk_status df_cap(df_state *D, double H) {
    wk_run *R = D->R;
    uint32_t *node = WK_NEW_ARRAY(R, uint32_t, D->nv);
    if (!node) return R->err.code;
    wk_status st = WK_OK;
    for (uint32_t i = 0; i < D->nv && st == WK_OK; i++) {
        const df_vertex *V = &D->v[i];
        if (!V->alive) continue;
        if (V->t0 == H) {
            node[i] = V->node;
            continue;
        }
        wk_point q = df_pos(V, H);
        if ((st = wk_skeleton_add_node(R, D->S, q.x + D->o.x, q.y + D->o.y, H, &node[i])) == WK_OK)
            st = wk_skeleton_add_arc(R, D->S, V->node, node[i], V->ein, V->eout);
    }
    for (uint32_t i = 0; i < D->nv && st == WK_OK; i++) {
        const df_vertex *V = &D->v[i];
        if (V->alive && node[i] != node[V->next])
            st = wk_skeleton_add_arc(R, D->S, node[i], node[V->next], WK_NONE, V->eout);
    }
    WK_FREE_ARRAY(R, node, D->nv);
    return st;
}

static wk_status df_simulate(df_state *D) {
    wk_run *R = D->R;
    /* Each resolution at one time ends at least one vertex of the input's
    ** O(n) events; many more resolutions at one time than that is a loop. */
    uint64_t same_time = 0;
    double H = R->opt.height;
    while (D->n_alive > 0 && !(H > 0 && D->t >= H)) {
        double te;
        if (D->t_vanish > 0 && D->t > D->t_vanish)
            return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                           "deforming: %u vertices still alive at t = %.17g, after the wavefront "
                           "must have vanished (t <= %.17g)",
                           D->n_alive, D->t, D->t_vanish);
        if (!D->window && df_window(D) != WK_OK) return R->err.code;
        if (df_next_group(D, &te) != WK_OK) return R->err.code;
        if (D->n_ev == 0) {
            /* the window holds no more events: the present moves to its
            ** end; a window of few events doubles (004's increment after
            ** an admissible step) */
            if (D->win_groups == 0) wk_count(R, WK_VC_event_free_steps, 1);
            if (D->win_groups == 0) D->dt *= 2;
            D->dt_near *= 2;
            D->t = D->T1;
            D->window = false;
            if (!isfinite(D->t))
                return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                               "deforming: %u vertices still alive at t = infinity", D->n_alive);
            continue;
        }
        /* the corrector: P_c = P_p + (dt_c - dt) v, i.e. the polygon at te
        ** (positions are kept as p0 + (t - t0) v, so this moves the present) */
        wk_count(R, WK_VC_corrections, 1);
        same_time = te == D->t ? same_time + 1 : 0;
        if (same_time > 8 * (uint64_t)D->P->n + 64)
            return WK_FAIL(R, WK_EALGO, D->P->name, 0,
                           "deforming: events at t = %.17g do not end (resolution loop)", te);
        if (te > D->t) D->dt_near = 2 * (te - D->t);
        D->t = te;
        if (df_resolve(D, te) != WK_OK || df_update(D) != WK_OK) return R->err.code;
        /* A window in which half its vertices changed has a grid of the
        ** past: it closes, and the next is half as long. */
        if (2 * ++D->win_groups > D->win_alive + 1) {
            D->window = false;
            D->dt /= 2;
        }
    }
    if (D->n_alive > 0 && df_cap(D, H) != WK_OK) return R->err.code;
    return wk_skeleton_merge_pass_through(R, D->S);
}

static wk_status deforming_run(wk_run *R, const wk_polygon *P, wk_skeleton **out) {
    df_state D;
    memset(&D, 0, sizeof D);
    D.R = R;
    D.P = P;
    D.touch_head = DF_TOUCH_END;
    wk_event_queue_init(&D.Q);
    wk_status st = df_start(&D);
    if (st == WK_OK) st = df_simulate(&D);
    if (st == WK_OK) {
        *out = D.S;
        D.S = NULL;
    }
    if (D.S) wk_skeleton_free(R, D.S);
    df_free(&D);
    if (st == WK_EUNSUPPORTED) return st;
    /* Certify: the skeleton must pass the validator; a configuration the
    ** resolution does not handle, or a skeleton that fails, goes to the
    ** reference (never a wrong skeleton). */
    if (st == WK_OK && (st = wk_validate(R, P, *out, 0, NULL)) != WK_OK) {
        wk_skeleton_free(R, *out);
        *out = NULL;
    }
    if (st != WK_EALGO && st != WK_EINVALID) return st;
    /* the reference takes positive weights and no height only */
    if (R->opt.height > 0) return st;
    for (uint32_t e = 0; e < P->n; e++)
        if (!(P->w[e] > 0)) return st;
    return wk_solve_by_reference(R, P, WK_VC_reference_fallbacks, out);
}

static const wk_counter_def df_counters[] = WK_VARIANT_COUNTER_TABLE(DF_COUNTER_LIST);

const wk_variant wk_variant_deforming = {
    "deforming",
    "deforming polygon, predictor-corrector steps (004); any weights (<= 0 with --height), holes",
    WK_VARIANT_WEIGHTS | WK_VARIANT_NONPOSITIVE_WEIGHTS,
    df_counters,
    sizeof df_counters / sizeof df_counters[0],
    deforming_run,
    NULL, /* no timed phase */
};
