/*
** kinetics.c: offset lines and vertex velocities (see kinetics.h).
** Parallel lines: |cross(n_a, n_b)| below WK_PARALLEL_SIN (same sense) or
** WK_ANTIPARALLEL_SIN (opposite senses), both sines, counts as parallel: a
** vertex between edges that differ by less than that would move at the
** inverse times the edge speed, which doubles cannot follow, and the
** skeleton it traces differs from the parallel case's by less than the
** tolerance (the bars and why below).
*/
#include "kinetics.h"

#include <float.h>
#include <math.h>

/* The parallel bars WK_PARALLEL_SIN and WK_ANTIPARALLEL_SIN, and why they
** differ, are in tolerance.h. */

/* The line of direction (dx, dy) through the midpoint (mx, my): c from the
** midpoint, so both endpoints lie within rounding of the line. */
static void line_from(double dx, double dy, double mx, double my, double w, wk_offset_line *L) {
    double len = hypot(dx, dy);
    L->ux = dx / len;
    L->uy = dy / len;
    L->nx = -L->uy;
    L->ny = L->ux;
    L->c = L->nx * mx + L->ny * my;
    L->w = w;
}

void wk_offset_line_of_points(wk_point a, wk_point b, double w, wk_offset_line *L) {
    line_from(b.x - a.x, b.y - a.y, 0.5 * (a.x + b.x), 0.5 * (a.y + b.y), w, L);
}

void wk_offset_line_of_edge_at(const wk_polygon *P, uint32_t e, wk_point o, wk_offset_line *L) {
    /* wk_polygon_edge_dir: a PSLG's cap has length 0 and a stored direction */
    wk_point a = P->p[e], b = P->p[wk_polygon_next(P, e)], d = wk_polygon_edge_dir(P, e);
    line_from(d.x, d.y, 0.5 * ((a.x - o.x) + (b.x - o.x)), 0.5 * ((a.y - o.y) + (b.y - o.y)),
              P->w[e], L);
}

void wk_offset_line_of_edge(const wk_polygon *P, uint32_t e, wk_offset_line *L) {
    wk_point a = P->p[e], b = P->p[wk_polygon_next(P, e)], d = wk_polygon_edge_dir(P, e);
    line_from(d.x, d.y, 0.5 * (a.x + b.x), 0.5 * (a.y + b.y), P->w[e], L);
}

wk_point wk_polygon_centre(const wk_polygon *P) {
    wk_point lo, hi;
    wk_polygon_bbox(P, &lo, &hi);
    return (wk_point){0.5 * lo.x + 0.5 * hi.x, 0.5 * lo.y + 0.5 * hi.y};
}

/* The parallel bar for two directions with this dot product. */
static double parallel_bar(double dot) { return dot > 0 ? WK_PARALLEL_SIN : WK_ANTIPARALLEL_SIN; }

wk_velocity_kind wk_vertex_velocity(const wk_offset_line *a, const wk_offset_line *b,
                                    wk_point *v) {
    double det = a->nx * b->ny - a->ny * b->nx;
    double dot = a->nx * b->nx + a->ny * b->ny;
    if (fabs(det) <= parallel_bar(dot)) {
        if (dot < 0) {
            v->x = v->y = 0;
            return WK_VEL_ANTIPARALLEL;
        }
        if (a->w == b->w) {
            v->x = a->w * 0.5 * (a->nx + b->nx);
            v->y = a->w * 0.5 * (a->ny + b->ny);
            return WK_VEL_STRAIGHT;
        }
        v->x = v->y = 0;
        return WK_VEL_COLLINEAR;
    }
    /* Cramer on [n_a; n_b] v = [w_a; w_b] */
    v->x = (a->w * b->ny - a->ny * b->w) / det;
    v->y = (a->nx * b->w - a->w * b->nx) / det;
    return WK_VEL_REGULAR;
}

bool wk_offset_lines_meet(const wk_offset_line *a, const wk_offset_line *b, double t,
                          wk_point *p) {
    double det = a->nx * b->ny - a->ny * b->nx;
    double dot = a->nx * b->nx + a->ny * b->ny;
    if (fabs(det) <= parallel_bar(dot)) return false;
    double ca = a->c + a->w * t, cb = b->c + b->w * t;
    p->x = (ca * b->ny - a->ny * cb) / det;
    p->y = (a->nx * cb - ca * b->nx) / det;
    return true;
}

bool wk_stretch_collapses_later(const wk_offset_line *L, wk_point q, wk_point vq, wk_point px,
                                wk_point vx, bool x_after, double eps_t) {
    double d = (px.x - q.x) * L->ux + (px.y - q.y) * L->uy;
    double rate = (vx.x - vq.x) * L->ux + (vx.y - vq.y) * L->uy;
    if (!x_after) {
        d = -d;
        rate = -rate;
    }
    double speeds = fabs(vq.x) + fabs(vq.y) + fabs(vx.x) + fabs(vx.y);
    double ulp = DBL_EPSILON * (fabs(q.x) + fabs(q.y));
    if (!(rate < -WK_SPLIT_SIDE_GROWTH_REL * speeds)) return false; /* grows or keeps its length */
    return d + rate * eps_t > WK_BEHIND_ULPS * ulp;
}

bool wk_is_reflex_turn(const wk_offset_line *a, const wk_offset_line *b) {
    double cross = a->ux * b->uy - a->uy * b->ux;
    double dot = a->ux * b->ux + a->uy * b->uy;
    return cross < -parallel_bar(dot);
}

bool wk_three_lines_meet(const wk_offset_line *a, const wk_offset_line *b,
                         const wk_offset_line *c, wk_point *p, double *t) {
    /* rows (nx, ny, -w) . (x, y, t) = c; Cramer's rule */
    double m[3][3] = {{a->nx, a->ny, -a->w}, {b->nx, b->ny, -b->w}, {c->nx, c->ny, -c->w}};
    double r[3] = {a->c, b->c, c->c};
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                 m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    double scale = (a->w + b->w + c->w);
    if (!(fabs(det) > WK_MEET_DET_REL * scale)) return false;
    double dx = r[0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                m[0][1] * (r[1] * m[2][2] - m[1][2] * r[2]) +
                m[0][2] * (r[1] * m[2][1] - m[1][1] * r[2]);
    double dy = m[0][0] * (r[1] * m[2][2] - m[1][2] * r[2]) -
                r[0] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                m[0][2] * (m[1][0] * r[2] - r[1] * m[2][0]);
    double dt = m[0][0] * (m[1][1] * r[2] - r[1] * m[2][1]) -
                m[0][1] * (m[1][0] * r[2] - r[1] * m[2][0]) +
                r[0] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    p->x = dx / det;
    p->y = dy / det;
    *t = dt / det;
    return isfinite(p->x) && isfinite(p->y) && isfinite(*t);
}

bool wk_three_edges_meet(const wk_polygon *P, uint32_t e1, uint32_t e2, uint32_t e3, wk_point o,
                         wk_point *p, double *t) {
    /* rows (nx, ny, -w) . (x, y, t) = c, each line built from the input
    ** points in long double: n's rounding times the distance from the
    ** midpoint to the event is then 2^-64, not 2^-53, of that distance */
    typedef long double ld;
    const uint32_t e[3] = {e1, e2, e3};
    ld m[3][3], r[3];
    double scale = 0;
    for (int i = 0; i < 3; i++) {
        wk_point a = P->p[e[i]], b = P->p[wk_polygon_next(P, e[i])], d = wk_polygon_edge_dir(P, e[i]);
        ld len = sqrtl((ld)d.x * d.x + (ld)d.y * d.y);
        ld nx = -(ld)d.y / len, ny = (ld)d.x / len;
        ld mx = 0.5L * (((ld)a.x - o.x) + ((ld)b.x - o.x));
        ld my = 0.5L * (((ld)a.y - o.y) + ((ld)b.y - o.y));
        m[i][0] = nx;
        m[i][1] = ny;
        m[i][2] = -(ld)P->w[e[i]];
        r[i] = nx * mx + ny * my;
        scale += P->w[e[i]];
    }
    ld det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(fabsl(det) > WK_MEET_DET_REL * scale)) return false;
    ld dx = r[0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
            m[0][1] * (r[1] * m[2][2] - m[1][2] * r[2]) +
            m[0][2] * (r[1] * m[2][1] - m[1][1] * r[2]);
    ld dy = m[0][0] * (r[1] * m[2][2] - m[1][2] * r[2]) -
            r[0] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * r[2] - r[1] * m[2][0]);
    ld dt = m[0][0] * (m[1][1] * r[2] - r[1] * m[2][1]) -
            m[0][1] * (m[1][0] * r[2] - r[1] * m[2][0]) +
            r[0] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    p->x = (double)(dx / det);
    p->y = (double)(dy / det);
    *t = (double)(dt / det);
    return isfinite(p->x) && isfinite(p->y) && isfinite(*t);
}

wk_velocity_kind wk_vertex_start(const wk_offset_line *L, uint32_t ein, uint32_t eout, wk_point p,
                                 double t, double snap, wk_point *p0, wk_point *vel, bool *reflex) {
    wk_velocity_kind k = wk_vertex_velocity(&L[ein], &L[eout], vel);
    *reflex = k == WK_VEL_REGULAR && wk_is_reflex_turn(&L[ein], &L[eout]);
    *p0 = p;
    wk_point q;
    if (k == WK_VEL_REGULAR && t > 0 && wk_offset_lines_meet(&L[ein], &L[eout], t, &q) &&
        (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) <= snap * snap)
        *p0 = q;
    return k;
}
