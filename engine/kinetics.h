/*
** kinetics.h: constructions of the weighted wavefront (000, section 1).
** Constructions compute numbers in double; decisions that must not go wrong
** from rounding use engine/predicates (see tolerance policy in wskel.h).
**
** An edge e of the polygon has a supporting line l(e) and an inward unit
** normal n(e); its offset line at time t is { p : n.p - c = w t } with
** c = n.p0, i.e. it moves inward at speed w(e).  A wavefront vertex between
** edges a (before it, counter-clockwise) and b (after it) moves with the
** velocity v solving n(a).v = w(a), n(b).v = w(b), so it stays on both
** offset lines.
*/
#ifndef WK_KINETICS_H
#define WK_KINETICS_H
#include "wskel.h"

typedef struct wk_offset_line {
    double ux, uy; /* unit direction of the edge (counter-clockwise) */
    double nx, ny; /* inward unit normal = (-uy, ux) */
    double c;      /* n . (a point of the edge) */
    double w;      /* weight: inward speed */
} wk_offset_line;

typedef enum wk_velocity_kind {
    WK_VEL_REGULAR = 0,  /* the two offset lines cross: v is their crossing's speed */
    WK_VEL_STRAIGHT,     /* parallel, same direction, equal weights: v = w n */
    WK_VEL_COLLINEAR,    /* parallel, same direction, different weights: undefined,
                            resolved by the collinear rule (000, section 1) */
    WK_VEL_ANTIPARALLEL  /* parallel, opposite directions: a zero-width spike */
} wk_velocity_kind;

void wk_offset_line_of_edge(const wk_polygon *P, uint32_t e, wk_offset_line *L);
/* The same for the edge a -> b of weight w (e.g. in translated coordinates). */
void wk_offset_line_of_points(wk_point a, wk_point b, double w, wk_offset_line *L);
/* Edge e's offset line in coordinates relative to o (the wavefront's
** frame): the direction from the input coordinates (b - a of two nearby
** doubles is exact, and never 0 for distinct vertices, where (b - o) -
** (a - o) can round to 0: an edge of one ulp), c from the translated
** midpoint. */
void wk_offset_line_of_edge_at(const wk_polygon *P, uint32_t e, wk_point o, wk_offset_line *L);
/* The centre of P's bounding box.  Variants compute in coordinates relative
** to it: far from the origin (a map in UTM metres, say) the absolute
** rounding of each coordinate would otherwise swamp small features. */
wk_point wk_polygon_centre(const wk_polygon *P);
/* Velocity of a vertex between offset lines a (before) and b (after). */
wk_velocity_kind wk_vertex_velocity(const wk_offset_line *a, const wk_offset_line *b,
                                    wk_point *v);
/* Signed distance of p from L's offset line at time t (positive: inside,
** i.e. not yet swept). */
static inline double wk_offset_distance(const wk_offset_line *L, wk_point p, double t) {
    return L->nx * p.x + L->ny * p.y - L->c - L->w * t;
}
/* The point on both offset lines a and b at time t; false if they are
** (nearly) parallel. */
bool wk_offset_lines_meet(const wk_offset_line *a, const wk_offset_line *b, double t,
                          wk_point *p);
/* The point and time where three offset lines meet (an event defined by its
** input edges, as in CGAL's trisegments, so no rounding piles up from
** earlier events).  False if the system is (nearly) singular. */
/* A wavefront vertex between edges ein and eout born at p at time t: its
** kind (the return value), velocity and reflexness, and *p0 = p snapped onto
** both offset lines where they meet within `snap` of p (regular vertices,
** t > 0): later constructions then depend on the input lines, not on the
** rounding of the event that made the vertex. */
wk_velocity_kind wk_vertex_start(const wk_offset_line *L, uint32_t ein, uint32_t eout, wk_point p,
                                 double t, double snap, wk_point *p0, wk_point *vel, bool *reflex);

bool wk_three_lines_meet(const wk_offset_line *a, const wk_offset_line *b,
                         const wk_offset_line *c, wk_point *p, double *t);
/* The same for input edges e1, e2, e3 of P, in coordinates relative to o,
** with the lines built from the input points in long double: the offset
** lines of wk_offset_line_of_edge_at carry the rounding of their unit
** normal (2^-53) times the distance from the edge's midpoint, and where two
** of the three lines are nearly parallel the meeting point moves by that
** over their sine.  An H with a needle (TestNeedles in
** tests/test_cgal_agreement.py): an edge 1e6 long, its midpoint 5e5 from
** the event, at a sine of 5e-6 to another edge: wk_three_lines_meet on the
** double lines put the event 5.5e-6 early (5 eps_t), this 4.7e-10 early. */
bool wk_three_edges_meet(const wk_polygon *P, uint32_t e1, uint32_t e2, uint32_t e3, wk_point o,
                         wk_point *p, double *t);
/* A stretch of offset line L joins a vertex born now at q (velocity vq) to
** vertex x at px (velocity vx), x after q along L (x_after) or before it;
** x is within the tolerance of q.  True if the stretch collapses later, not
** now: it shrinks faster than parallel motion at the tolerance
** (WK_SPLIT_SIDE_GROWTH_REL of the two speeds) and is still longer than the
** rounding of q (WK_BEHIND_ULPS ulps) after eps_t.  The same relative motion
** along the line as an edge event, so the same rule as the wavefront's edge
** events: x then does not arrive at q, and the stretch's own collapse is a
** later event.  A stretch that grows or keeps its length is left to the
** tolerance picture (false). */
bool wk_stretch_collapses_later(const wk_offset_line *L, wk_point q, wk_point vq, wk_point px,
                                wk_point vx, bool x_after, double eps_t);
/* True if turning from edge direction a to edge direction b is a right turn
** (the vertex between them is reflex).  Exact on the input directions. */
bool wk_is_reflex_turn(const wk_offset_line *a, const wk_offset_line *b);

#endif
