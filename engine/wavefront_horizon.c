/*
** wavefront_horizon.c: the end of a PSLG's wavefront at its time horizon.
** A PSLG's skeleton is unbounded (the outer face's wavefront grows
** forever), so the simulation stops at a horizon T: R->opt.until (--until),
** or by default WK_PSLG_HORIZON_MARGIN diagonals (for the fastest edge)
** after the last event up to WK_PSLG_DEFAULT_EVENTS_REL diagonals over the
** slowest weight, when every bounded wavefront component has vanished (and,
** unless an event of the unbounded wavefront comes later still, every node
** of the unbounded skeleton exists).
**
** Invariant on return: no vertex is alive; every vertex alive at T has an
** arc from where it started to its node at T (faces ein, eout), a vertex
** born at T ends at its own node; the piece a -> next(a) of each such
** vertex is a cap arc from a's node at T to next(a)'s, left WK_NONE (the
** unswept side), right the piece's edge (the swept face), as a roof cut at
** a height stores its cap; S->horizon = T.
*/
#include "wavefront_internal.h"

#include <math.h>

static double weight_min(const wk_polygon *P) {
    double w = INFINITY;
    for (uint32_t e = 0; e < P->n; e++) w = fmin(w, P->w[e]);
    return w;
}

double wf_event_limit(const wk_wavefront *W) {
    if (W->R->opt.until > 0) return W->R->opt.until;
    return WK_PSLG_DEFAULT_EVENTS_REL * wk_polygon_scale(W->P) / weight_min(W->P);
}

wk_status wf_check_horizon(const wk_wavefront *W) {
    double until = W->R->opt.until, bound = WK_PSLG_MAX_HORIZON_REL * wk_polygon_scale(W->P) / weight_min(W->P);
    if (until > bound)
        return WK_FAIL(W->R, WK_EINPUT, W->P->name, 0,
                       "--until %g is beyond the horizon the output resolves, %g diagonals over the "
                       "smallest weight (%g; input domain)",
                       until, WK_PSLG_MAX_HORIZON_REL, bound);
    return WK_OK;
}

double wf_default_horizon(const wk_wavefront *W) {
    double wmax = 0;
    for (uint32_t e = 0; e < W->P->n; e++) wmax = fmax(wmax, W->P->w[e]);
    return W->t_group + WK_PSLG_HORIZON_MARGIN * wk_polygon_scale(W->P) / wmax;
}

wk_status wf_close_at_horizon(wk_wavefront *W, double T) {
    wk_run *R = W->R;
    /* the last group may sit up to eps_t after the horizon it was taken at */
    if (T < W->t_group) T = W->t_group;
    /* The outer face's wavefront grows forever: if nothing is alive, a group
    ** resolved a feature at the tolerance wrongly (a unit 64-gon next to a
    ** vertex 4e9 away, at the first tolerance); no skeleton, so that
    ** wk_solve_checked retries and --no-check writes nothing wrong. */
    uint32_t alive = 0;
    for (uint32_t v = 0; v < W->nv; v++) alive += W->v[v].alive;
    if (alive == 0)
        return WK_FAIL(R, WK_EALGO, W->P->name, 0,
                       "wavefront: the PSLG's unbounded wavefront vanished by t = %.17g", W->t_now);
    for (uint32_t v = 0; v < W->nv; v++) {
        wk_wf_vertex *V = &W->v[v];
        if (!V->alive) continue;
        if (V->t0 >= T) {
            V->at = V->node;
            continue;
        }
        wk_point q = wk_wf_pos(V, T);
        if (wk_skeleton_add_node(R, W->S, q.x + W->origin.x, q.y + W->origin.y, T, &V->at) != WK_OK)
            return R->err.code;
        if (wf_add_arc(W, V->node, V->at, V->ein, V->eout) != WK_OK) return R->err.code;
    }
    for (uint32_t v = 0; v < W->nv; v++) {
        wk_wf_vertex *V = &W->v[v];
        if (!V->alive) continue;
        if (wf_add_arc(W, V->at, W->v[V->next].at, WK_NONE, V->eout) != WK_OK) return R->err.code;
    }
    for (uint32_t v = 0; v < W->nv; v++) W->v[v].alive = 0;
    W->S->horizon = T;
    return WK_OK;
}
