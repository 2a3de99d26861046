/*
** validate_internal.h: what the validators for capped roofs
** (validate_general.c) and for PSLGs (validate_pslg.c) share: stage (c),
** every arc end on the offset lines of both of the arc's faces, and each
** arc from an input vertex along its bisector, and the overlap of collinear
** face sides (validate.c uses both too).
*/
#ifndef WK_VALIDATE_INTERNAL_H
#define WK_VALIDATE_INTERNAL_H

#include <math.h>
#include "wskel.h"

/* Signed distance of (x, y) from edge e's supporting line, positive on the
** side the edge sweeps (left of its direction; a PSLG's zero-length cap has
** its direction in P->dir). */
double wk_edge_signed_distance(const wk_polygon *P, uint32_t e, double x, double y);

/* Stage (c) for arc i, whose ends and faces are already checked to be in
** range: both ends within tol of the offset line d_e = w(e) t of each face
** e (WK_NONE: the cap, no face), and a cap arc's ends at time T within
** tol_t (T > 0; a cap with T <= 0 is refused).  Records the largest
** distance error in rep.  Messages read "validate (STAGE): ...", name the
** cap's time as T_NAME ("the horizon", "the height") and a face's offset
** line as LINE_NAME. */
wk_status wk_validate_arc_ends(wk_run *R, const wk_polygon *P, const wk_skeleton *S, uint32_t i,
                               double T, double tol, double tol_t, const char *name,
                               const char *stage, const char *t_name, const char *line_name,
                               wk_validate_report *rep);

/* For an arc leaving input vertex v between v's two edges, of equal nonzero
** weight and facing the same way (inward normals n_e . n_f > 0): the arc's
** displacement across n_e + n_f is at most 4 tol (validate_arc_ends.c says
** why: for nearly parallel edges stage (c)'s distances do not pin the
** arc's direction).  Polygons only (P's rings give v's edges). */
wk_status wk_validate_arc_bisector(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                   uint32_t i, double tol, const char *name, const char *stage);

/* Distance from z to the segment p-q (a point when p == q). */
static inline double wk_segment_point_distance(wk_point p, wk_point q, wk_point z) {
    double dx = q.x - p.x, dy = q.y - p.y, len2 = dx * dx + dy * dy;
    double u = len2 > 0 ? ((z.x - p.x) * dx + (z.y - p.y) * dy) / len2 : 0.0;
    if (u < 0) u = 0;
    if (u > 1) u = 1;
    return hypot(z.x - (p.x + u * dx), z.y - (p.y + u * dy));
}

/* Length of the common part of two collinear segments a-b and c-d (both
** validators' face tests: sides that run along each other), measured along
** the direction of the one with the larger coordinate extents. */
static inline double wk_collinear_overlap(wk_point a, wk_point b, wk_point c, wk_point d) {
    double dx = b.x - a.x, dy = b.y - a.y;
    if (fabs(dx) < fabs(d.x - c.x) || fabs(dy) < fabs(d.y - c.y)) {
        dx = d.x - c.x;
        dy = d.y - c.y;
    }
    double len = hypot(dx, dy);
    if (!(len > 0)) return 0.0;
    dx /= len;
    dy /= len;
    double a0 = a.x * dx + a.y * dy, a1 = b.x * dx + b.y * dy;
    double c0 = c.x * dx + c.y * dy, c1 = d.x * dx + d.y * dy;
    double lo = fmax(fmin(a0, a1), fmin(c0, c1)), hi = fmin(fmax(a0, a1), fmax(c0, c1));
    return hi > lo ? hi - lo : 0.0;
}

#endif
