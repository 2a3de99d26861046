/*
** validate_arc_ends.c: stage (c) of the validators for capped roofs and for
** PSLGs (validate_internal.h).  One check, written once: an arc end lies at
** signed distance w(e) t from the line of each of its faces' edges, and an
** arc of the cap (one side WK_NONE) lies at the cap's time.
*/
#include "validate_internal.h"

#include <math.h>

double wk_edge_signed_distance(const wk_polygon *P, uint32_t e, double x, double y) {
    wk_point a = P->p[e], d = wk_polygon_edge_dir(P, e);
    double len = hypot(d.x, d.y);
    /* the swept side is on the left of the edge's direction: normal (-dy, dx) */
    return (-d.y * (x - a.x) + d.x * (y - a.y)) / len;
}

wk_status wk_validate_arc_ends(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t i,
                               double T, double tol, double tol_t, const char *name,
                               const char *stage, const char *t_name, const char *line_name,
                               wk_validate_report *rep) {
    const wk_arc *c = &S->arcs[i];
    bool cap = c->left == WK_NONE || c->right == WK_NONE;
    uint32_t ends[2] = {c->a, c->b}, sides[2] = {c->left, c->right};
    for (int j = 0; j < 2; j++) {
        const wk_node *v = &S->nodes[ends[j]];
        if (cap && !(T > 0 && fabs(v->t - T) <= tol_t))
            return WK_FAIL(R, WK_EINVALID, name, 0,
                           "validate (%s): cap arc %u ends at node %u at t = %.17g, not at %s %.17g",
                           stage, i, ends[j], v->t, t_name, T);
        for (int k = 0; k < 2; k++) {
            uint32_t e = sides[k];
            if (e == WK_NONE) continue;
            double err = fabs(wk_edge_signed_distance(P, e, v->x, v->y) - P->w[e] * v->t);
            if (err > rep->max_distance_error) rep->max_distance_error = err;
            if (!(err <= tol))
                return WK_FAIL(R, WK_EINVALID, name, 0,
                               "validate (%s): arc %u, node %u (%g, %g, t %g): off the %s of edge "
                               "%u by %.3g (tolerance %.3g)",
                               stage, i, ends[j], v->x, v->y, v->t, line_name, e, err, tol);
        }
    }
    return WK_OK;
}
