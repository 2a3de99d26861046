/*
** validate_arc_ends.c: stage (c) of the validators for capped roofs and for
** PSLGs (validate_internal.h).  One check, written once: an arc end lies at
** signed distance w(e) t from the line of each of its faces' edges, and an
** arc of the cap (one side WK_NONE) lies at the cap's time; and the check
** that pins what those distances leave free, an arc between two faces of
** equal weight whose edges are nearly parallel and face the same way
** (wk_validate_arc_bisector, used by every validator).
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

/* Why this check: stage (c) puts both ends of an arc within tol of both
** faces' offset lines, |n_e . p + c_e - w t| <= tol.  Subtracting, the
** ends' displacement d obeys |(n_e - n_f) . d| <= 4 tol (equal weights), so
** across the faces' bisector, the direction m_perp perpendicular to
** m = n_e + n_f, the arc may stray up to 4 tol / |n_e - n_f|.  When the
** edges are nearly parallel and face the same way (collinear up to
** rounding: a border snapped to a 0.01-degree grid, whose decimal corners
** are collinear before rounding), |n_e - n_f| ~ 1e-14 and the distances
** pin nothing: an arc from the vertex between two such edges may leave in
** any direction and still pass (c).  The wavefront vertex starting there
** moves along m (the limit of the bisector, speed 1 / cos(angle / 2)), so
** its arc strays across m by at most 4 tol here too: the bound (c) implies
** when |n_e - n_f| >= 1, kept for every smaller angle.  Met first in CGAL
** 5.5.1's skeleton of a 0.01-grid border (Benin, countries-land-10km):
** its arc from such a vertex ran 0.3 degrees off the normal, 1.9e-4 across
** it at tol 3e-6, and passed (c), (e) and (f).
** Only arcs leaving an input vertex between its own two edges: that end is
** exact, so the direction is the bisector's whatever the other end.  An
** arc between two later nodes is not checked: a node where nearly parallel
** lines meet is placed within tol of its lines but, by the tolerance
** policy, anywhere along them within eps_d / angle (tests/data/skeletons:
** comb_spike.*.json: a node 173 units along two lines 3e-5 rad
** apart, both ends within tol).  Unequal weights (the collinear rule's
** runs: the vertex there moves along the line), zero weights (walls meet
** at a point) and edges facing apart (n_e . n_f <= 0, where (c) already
** bounds the stray by 2.9 tol) are left to (c). */
wk_status wk_validate_arc_bisector(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                   uint32_t i, double tol, const char *name, const char *stage) {
    const wk_arc *c = &S->arcs[i];
    uint32_t e = c->left, f = c->right;
    if (e == WK_NONE || f == WK_NONE || !(P->w[e] == P->w[f]) || P->w[e] == 0) return WK_OK;
    /* the end at an input vertex v whose two edges are the arc's faces */
    uint32_t v = c->a < P->n ? c->a : c->b;
    if (v >= P->n) return WK_OK;
    uint32_t in = wk_polygon_prev(P, v);
    if (!((e == v && f == in) || (e == in && f == v))) return WK_OK;
    wk_point de = wk_polygon_edge_dir(P, e), df = wk_polygon_edge_dir(P, f);
    double le = hypot(de.x, de.y), lf = hypot(df.x, df.y);
    if (!(le > 0) || !(lf > 0)) return WK_OK;
    /* inward normals (-dy, dx) / len; their sum is the bisector's direction */
    double mx = -de.y / le - df.y / lf, my = de.x / le + df.x / lf;
    double dot = de.x * df.x + de.y * df.y, cross = de.x * df.y - de.y * df.x;
    if (!(dot > 0)) return WK_OK;
    double ml = hypot(mx, my);
    const wk_node *a = &S->nodes[c->a], *b = &S->nodes[c->b];
    double across = ((b->x - a->x) * -my + (b->y - a->y) * mx) / ml;
    if (fabs(across) <= 4 * tol) return WK_OK;
    return WK_FAIL(R, WK_EINVALID, name, 0,
                   "validate (%s): arc %u [%u, %u, %u, %u] leaves input vertex %u %.3g off the "
                   "bisector of its edges %u and %u (equal weights, %.3g rad apart: it must run "
                   "along the sum of their normals; tolerance 4 tol = %.3g)",
                   stage, i, c->a, c->b, e, f, v, fabs(across), e, f, atan2(fabs(cross), dot),
                   4 * tol);
}
