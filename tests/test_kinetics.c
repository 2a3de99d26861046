/*
** test_kinetics.c: offset lines and vertex velocities (engine/kinetics.c).
**
** Oracles: closed forms.  An edge with unit direction u has the inward normal
** n = (-u.y, u.x) and its offset line n.p = c + w t; a vertex between edges a
** and b (counter-clockwise) moves with
**     v = (w_a u_b - w_b u_a) / (u_a x u_b),
** which satisfies n_a.v = w_a and n_b.v = w_b (and, for unit weights and
** interior angle alpha, |v| = 1 / sin(alpha / 2) along n_a + n_b).  The
** unit square's corner moves at sqrt(2) along the diagonal; a right angle
** with weights w_a, w_b moves with components (w_a, w_b).  Parallel edges
** (|sin| at or below the bar) are straight, collinear or antiparallel; the
** bars are checked just above and just below, with lines built field by
** field so that the sine is exact.
*/
#include <criterion/criterion.h>
#include <math.h>

#include "kinetics.h"
#include "helpers.h"

/* The bars of engine/kinetics.c (private there): same-sense parallel below
** WK_PARALLEL_SIN, antiparallel below WK_ANTIPARALLEL_SIN.  A test below
** fails if kinetics.c changes them without this copy. */
#define PARALLEL_SIN 1e-9
#define ANTIPARALLEL_SIN 1e-12

#define ASSERT_NEAR(a, b, eps)                                                          \
    cr_assert(fabs((double)(a) - (double)(b)) <= (eps), "%s = %.17g, want %.17g (tol %g)", \
              #a, (double)(a), (double)(b), (double)(eps))

static wk_point pt(double x, double y) { return (wk_point){x, y}; }

/* The offset line of the edge a -> b of weight w. */
static wk_offset_line line(wk_point a, wk_point b, double w) {
    wk_offset_line L;
    wk_offset_line_of_points(a, b, w, &L);
    return L;
}

/* An offset line through the origin with the exact unit direction (ux, uy):
** the fields are set here, so sines and dot products come out exact. */
static wk_offset_line dir_line(double ux, double uy, double w) {
    return (wk_offset_line){ux, uy, -uy, ux, 0, w};
}

/* The closed form of the velocity between a and b (see the top). */
static wk_point closed_velocity(const wk_offset_line *a, const wk_offset_line *b) {
    double s = a->ux * b->uy - a->uy * b->ux;
    return pt((a->w * b->ux - b->w * a->ux) / s, (a->w * b->uy - b->w * a->uy) / s);
}

/* ------------------------------------------------------ offset lines */

Test(kinetics, offset_line_unit_edges) {
    /* bottom edge of the unit square: u = (1, 0), n = (0, 1), c = 0 */
    wk_offset_line L = line(pt(0, 0), pt(1, 0), 1);
    cr_assert_eq(L.ux, 1.0);
    cr_assert_eq(L.uy, 0.0);
    cr_assert_eq(L.nx, 0.0);
    cr_assert_eq(L.ny, 1.0);
    cr_assert_eq(L.c, 0.0);
    cr_assert_eq(L.w, 1.0);
    /* a vertical edge going up at x = 3 faces left: n = (-1, 0), c = -3 */
    L = line(pt(3, 1), pt(3, 5), 1);
    cr_assert_eq(L.ux, 0.0);
    cr_assert_eq(L.uy, 1.0);
    cr_assert_eq(L.nx, -1.0);
    cr_assert_eq(L.ny, 0.0);
    cr_assert_eq(L.c, -3.0);
    /* a 3-4-5 edge: u = (0.6, 0.8), n = (-0.8, 0.6), through (3, 4) */
    L = line(pt(0, 0), pt(3, 4), 1);
    ASSERT_NEAR(L.ux, 0.6, 1e-16);
    ASSERT_NEAR(L.uy, 0.8, 1e-16);
    ASSERT_NEAR(L.nx, -0.8, 1e-16);
    ASSERT_NEAR(L.ny, 0.6, 1e-16);
    ASSERT_NEAR(hypot(L.ux, L.uy), 1.0, 1e-15);
    ASSERT_NEAR(L.c, 0.0, 1e-15);
    /* both endpoints on the line at t = 0; the left side is inside */
    ASSERT_NEAR(wk_offset_distance(&L, pt(0, 0), 0), 0, 1e-15);
    ASSERT_NEAR(wk_offset_distance(&L, pt(3, 4), 0), 0, 1e-15);
    ASSERT_NEAR(wk_offset_distance(&L, pt(-0.8, 0.6), 0), 1, 1e-15);
    ASSERT_NEAR(wk_offset_distance(&L, pt(0.8, -0.6), 0), -1, 1e-15);
    /* at time t the line has moved t inward: the point at distance t is on it */
    ASSERT_NEAR(wk_offset_distance(&L, pt(-0.8 * 2.5, 0.6 * 2.5), 2.5), 0, 1e-15);
}

Test(kinetics, offset_line_weighted_edges) {
    static const double ws[] = {0.25, 1, 2.5, 1e3};
    for (size_t i = 0; i < sizeof ws / sizeof ws[0]; i++) {
        double w = ws[i];
        wk_offset_line L = line(pt(1, 1), pt(4, 5), w);
        cr_assert_eq(L.w, w);
        /* direction and normal do not depend on the weight */
        ASSERT_NEAR(L.ux, 0.6, 1e-16);
        ASSERT_NEAR(L.ny, 0.6, 1e-16);
        ASSERT_NEAR(L.c, -0.8 * 1 + 0.6 * 1, 1e-15);
        /* at time t the offset line is w t inside: the edge's midpoint moved
        ** by w t along n lies on it, the midpoint itself is w t outside it */
        for (double t = 0; t <= 2; t += 0.5) {
            wk_point m = pt(2.5 + L.nx * w * t, 3 + L.ny * w * t);
            ASSERT_NEAR(wk_offset_distance(&L, m, t), 0, 1e-12 * (1 + w * t));
            ASSERT_NEAR(wk_offset_distance(&L, pt(2.5, 3), t), -w * t, 1e-12 * (1 + w * t));
        }
    }
}

/* Far from the origin both endpoints still lie within rounding of the line
** (c is taken at the midpoint). */
Test(kinetics, offset_line_far_from_origin) {
    wk_point a = pt(1e6 + 0.1, -2e6 + 0.3), b = pt(1e6 + 0.7, -2e6 + 1.1);
    wk_offset_line L = line(a, b, 1);
    double rnd = 4 * 0x1p-52 * 2e6;
    ASSERT_NEAR(wk_offset_distance(&L, a, 0), 0, rnd);
    ASSERT_NEAR(wk_offset_distance(&L, b, 0), 0, rnd);
    ASSERT_NEAR(hypot(L.ux, L.uy), 1.0, 1e-15);
    ASSERT_NEAR(L.nx * L.ux + L.ny * L.uy, 0.0, 1e-16);
}

Test(kinetics, offset_line_of_edge_and_centre) {
    wk_run R;
    wk_run_init(&R);
    /* the L shape with weights; edge e runs p[e] -> p[e+1] */
    static const double w[6] = {1, 2, 3, 0.5, 1.5, 4};
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, w);
    for (uint32_t e = 0; e < P->n; e++) {
        wk_offset_line L, M;
        wk_offset_line_of_edge(P, e, &L);
        wk_offset_line_of_points(P->p[e], P->p[(e + 1) % P->n], P->w[e], &M);
        cr_assert(L.ux == M.ux && L.uy == M.uy && L.nx == M.nx && L.ny == M.ny && L.c == M.c &&
                      L.w == M.w,
                  "edge %u: of_edge and of_points differ", e);
        cr_assert_eq(L.w, w[e], "edge %u weight %g, want %g", e, L.w, w[e]);
        /* the inward normal points into the polygon: (0.5, 0.5) is inside */
        cr_assert_gt(wk_offset_distance(&L, pt(0.5, 0.5), 0), 0, "edge %u: normal points out", e);
    }
    wk_point c = wk_polygon_centre(P);
    cr_assert(c.x == 1 && c.y == 1, "centre (%g, %g), want (1, 1)", c.x, c.y);
    wk_polygon_free(&R, P);
    /* clockwise input is stored counter-clockwise: normals still point in */
    static const double cx[4] = {10, 10, 14, 14}, cy[4] = {20, 23, 23, 20};
    P = polygon(&R, 4, cx, cy, NULL);
    cr_assert(P->reversed);
    for (uint32_t e = 0; e < P->n; e++) {
        wk_offset_line L;
        wk_offset_line_of_edge(P, e, &L);
        cr_assert_gt(wk_offset_distance(&L, pt(12, 21.5), 0), 0, "clockwise edge %u", e);
    }
    c = wk_polygon_centre(P);
    cr_assert(c.x == 12 && c.y == 21.5, "centre (%g, %g), want (12, 21.5)", c.x, c.y);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ------------------------------------------------- vertex velocities */

/* The unit square's corner (1, 0) between the bottom and the right edge
** moves at sqrt(2) along the diagonal towards the centre. */
Test(kinetics, square_corner_moves_along_diagonal) {
    wk_offset_line a = line(pt(0, 0), pt(1, 0), 1), b = line(pt(1, 0), pt(1, 1), 1);
    wk_point v;
    cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_REGULAR);
    cr_assert(v.x == -1 && v.y == 1, "v = (%g, %g), want (-1, 1)", v.x, v.y);
    ASSERT_NEAR(hypot(v.x, v.y), sqrt(2.0), 1e-15);
    cr_assert_not(wk_is_reflex_turn(&a, &b));
    /* every corner of the square: v points to the centre, at sqrt(2) */
    for (int i = 0; i < 4; i++) {
        wk_point p0 = pt(SQ_X[i], SQ_Y[i]), p1 = pt(SQ_X[(i + 1) % 4], SQ_Y[(i + 1) % 4]);
        wk_point p2 = pt(SQ_X[(i + 2) % 4], SQ_Y[(i + 2) % 4]);
        wk_offset_line ea = line(p0, p1, 1), eb = line(p1, p2, 1);
        cr_assert_eq(wk_vertex_velocity(&ea, &eb, &v), WK_VEL_REGULAR);
        ASSERT_NEAR(v.x, 2 * (0.5 - p1.x), 1e-15);
        ASSERT_NEAR(v.y, 2 * (0.5 - p1.y), 1e-15);
    }
}

/* A right angle with weights w_a, w_b: the corner (0, 0) between the left
** edge (going down, normal (1, 0)) and the bottom edge (normal (0, 1))
** moves with velocity (w_a, w_b). */
Test(kinetics, right_angle_weights_are_the_components) {
    static const double ws[][2] = {{1, 1}, {2, 1}, {1, 3}, {0.5, 4}, {1e-3, 1e3}};
    for (size_t i = 0; i < sizeof ws / sizeof ws[0]; i++) {
        double wa = ws[i][0], wb = ws[i][1];
        wk_offset_line a = line(pt(0, 1), pt(0, 0), wa), b = line(pt(0, 0), pt(1, 0), wb);
        wk_point v;
        cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_REGULAR);
        cr_assert(v.x == wa && v.y == wb, "weights (%g, %g): v = (%.17g, %.17g)", wa, wb, v.x,
                  v.y);
        /* and the vertex stays on both offset lines */
        for (double t = 0.5; t <= 2; t += 0.5) {
            wk_point q = pt(v.x * t, v.y * t);
            ASSERT_NEAR(wk_offset_distance(&a, q, t), 0, 1e-12);
            ASSERT_NEAR(wk_offset_distance(&b, q, t), 0, 1e-12);
        }
    }
}

/* Convex and reflex corners over a range of angles and weights: the
** velocity equals the closed form, solves both equations, and for unit
** weights has length 1 / sin(alpha / 2) along the inward bisector. */
Test(kinetics, velocity_closed_form_over_angles) {
    static const double ws[][2] = {{1, 1}, {1, 2}, {3, 0.5}, {1e-2, 10}};
    unsigned cases = 0;
    for (int k = 1; k < 36; k++) {
        if (k == 18) continue; /* straight: its own test */
        double theta = PI * (k - 18) / 18; /* turn from a to b, in (-pi, pi), not 0 */
        double alpha = PI - theta; /* interior angle: < pi convex, > pi reflex */
        for (size_t i = 0; i < sizeof ws / sizeof ws[0]; i++) {
            /* a arrives at the origin along direction 0.3 rad, b leaves turned by theta */
            double da = 0.3, db = 0.3 + theta;
            wk_offset_line a = line(pt(-cos(da), -sin(da)), pt(0, 0), ws[i][0]);
            wk_offset_line b = line(pt(0, 0), pt(cos(db), sin(db)), ws[i][1]);
            wk_point v, want = closed_velocity(&a, &b);
            cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_REGULAR, "theta %g", theta);
            double scale = hypot(want.x, want.y);
            ASSERT_NEAR(v.x, want.x, 1e-13 * scale);
            ASSERT_NEAR(v.y, want.y, 1e-13 * scale);
            ASSERT_NEAR(a.nx * v.x + a.ny * v.y, a.w, 1e-13 * scale);
            ASSERT_NEAR(b.nx * v.x + b.ny * v.y, b.w, 1e-13 * scale);
            cr_assert_eq(wk_is_reflex_turn(&a, &b), theta < 0, "theta %g: reflex %d", theta,
                         wk_is_reflex_turn(&a, &b));
            if (ws[i][0] == 1 && ws[i][1] == 1) {
                ASSERT_NEAR(hypot(v.x, v.y), 1 / sin(alpha / 2), 1e-13 * scale);
                /* along the bisector n_a + n_b, convex and reflex alike */
                double bx = a.nx + b.nx, by = a.ny + b.ny, bl = hypot(bx, by);
                ASSERT_NEAR(v.x / hypot(v.x, v.y), bx / bl, 1e-12);
                ASSERT_NEAR(v.y / hypot(v.x, v.y), by / bl, 1e-12);
            }
            cases++;
        }
    }
    cr_assert_eq(cases, 34 * 4);
}

/* The L shape's reflex corner (1, 1) moves towards (0, 0) at sqrt(2). */
Test(kinetics, reflex_corner_of_l_shape) {
    wk_offset_line a = line(pt(2, 1), pt(1, 1), 1), b = line(pt(1, 1), pt(1, 2), 1);
    wk_point v;
    cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_REGULAR);
    cr_assert(v.x == -1 && v.y == -1, "v = (%g, %g), want (-1, -1)", v.x, v.y);
    cr_assert(wk_is_reflex_turn(&a, &b));
    /* weighted: (-w_b, -w_a) */
    a.w = 2;
    b.w = 3;
    cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_REGULAR);
    cr_assert(v.x == -3 && v.y == -2, "v = (%g, %g), want (-3, -2)", v.x, v.y);
}

Test(kinetics, straight_vertex_moves_with_the_normal) {
    static const double ws[] = {1, 2.5, 1e-3};
    for (size_t i = 0; i < 3; i++) {
        wk_offset_line a = line(pt(0, 0), pt(1, 0), ws[i]), b = line(pt(1, 0), pt(3, 0), ws[i]);
        wk_point v = {7, 7};
        cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_STRAIGHT);
        cr_assert(v.x == 0 && v.y == ws[i], "v = (%g, %g), want (0, %g)", v.x, v.y, ws[i]);
        cr_assert_not(wk_is_reflex_turn(&a, &b));
        wk_point q;
        cr_assert_not(wk_offset_lines_meet(&a, &b, 1, &q), "parallel lines met");
    }
    /* turned: v = w n */
    double c = cos(1.1), s = sin(1.1);
    wk_offset_line a = line(pt(0, 0), pt(c, s), 2), b = line(pt(c, s), pt(3 * c, 3 * s), 2);
    wk_point v;
    cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_STRAIGHT);
    ASSERT_NEAR(v.x, -2 * s, 1e-15);
    ASSERT_NEAR(v.y, 2 * c, 1e-15);
}

Test(kinetics, collinear_edges_of_different_weights) {
    wk_offset_line a = line(pt(0, 0), pt(1, 0), 1), b = line(pt(1, 0), pt(2, 0), 3);
    wk_point v = {7, 7};
    cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_COLLINEAR);
    cr_assert(v.x == 0 && v.y == 0, "v = (%g, %g): undefined, want 0", v.x, v.y);
    /* the weights in the other order too */
    cr_assert_eq(wk_vertex_velocity(&b, &a, &v), WK_VEL_COLLINEAR);
    cr_assert_not(wk_is_reflex_turn(&a, &b));
}

Test(kinetics, antiparallel_edges_are_a_spike) {
    static const double ws[][2] = {{1, 1}, {1, 2}};
    for (size_t i = 0; i < 2; i++) {
        wk_offset_line a = line(pt(0, 0), pt(1, 0), ws[i][0]), b = line(pt(1, 0), pt(0, 0), ws[i][1]);
        wk_point v = {7, 7};
        cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_ANTIPARALLEL);
        cr_assert(v.x == 0 && v.y == 0, "v = (%g, %g), want 0", v.x, v.y);
        cr_assert_not(wk_is_reflex_turn(&a, &b));
        wk_point q;
        cr_assert_not(wk_offset_lines_meet(&a, &b, 1, &q));
    }
}

/* ------------------------------------------------------ parallel bars */

/* The vertex between a = direction (1, 0) and b turned from a by the sine s,
** of the same sense (sense 1) or running back along a (sense -1); the lines
** are built field by field, so the sine is exact.  *reflex: a reflex turn;
** *meets: the two offset lines meet (at t = 1). */
typedef struct turned { wk_velocity_kind kind; wk_point v; bool reflex, meets; } turned;
static turned turn(double sense, double s, double wa, double wb) {
    wk_offset_line a = dir_line(1, 0, wa), b = dir_line(sense * sqrt(1 - s * s), s, wb);
    turned r;
    wk_point q;
    r.kind = wk_vertex_velocity(&a, &b, &r.v);
    r.reflex = wk_is_reflex_turn(&a, &b);
    r.meets = wk_offset_lines_meet(&a, &b, 1, &q);
    return r;
}

Test(kinetics, parallel_bar_same_sense) {
    const double above = PARALLEL_SIN * (1 + 1e-6), below = PARALLEL_SIN * (1 - 1e-6);
    /* above the bar: a regular vertex, however fast; the offset lines meet */
    turned r = turn(1, above, 1, 2);
    cr_assert_eq(r.kind, WK_VEL_REGULAR);
    cr_assert(!r.reflex && r.meets);
    ASSERT_NEAR(r.v.x, -1 / above, 1e-6 / above); /* (w_a u_b - w_b u_a) / s: x = (c - 2) / s */
    ASSERT_NEAR(r.v.y, 1, 1e-6);
    r = turn(1, -above, 1, 2);
    cr_assert_eq(r.kind, WK_VEL_REGULAR);
    cr_assert(r.reflex, "a right turn above the bar is reflex");
    r = turn(1, above, 1, 1);
    cr_assert_eq(r.kind, WK_VEL_REGULAR);
    ASSERT_NEAR(hypot(r.v.x, r.v.y), 1, 1e-9);
    /* at and below the bar: parallel, straight for equal weights, else
    ** collinear; never reflex, the offset lines do not meet */
    const double sines[] = {below, -below, PARALLEL_SIN, -PARALLEL_SIN, 1e-12, 0};
    for (size_t i = 0; i < sizeof sines / sizeof sines[0]; i++) {
        r = turn(1, sines[i], 1, 1);
        cr_assert_eq(r.kind, WK_VEL_STRAIGHT, "sine %g", sines[i]);
        cr_assert(!r.reflex && !r.meets, "sine %g: reflex %d, meets %d", sines[i], r.reflex,
                  r.meets);
        ASSERT_NEAR(r.v.x, 0, 1e-9);
        ASSERT_NEAR(r.v.y, 1, 1e-15);
        r = turn(1, sines[i], 1, 2);
        cr_assert_eq(r.kind, WK_VEL_COLLINEAR, "sine %g", sines[i]);
        cr_assert(r.v.x == 0 && r.v.y == 0);
    }
}

Test(kinetics, parallel_bar_antiparallel) {
    const double above = ANTIPARALLEL_SIN * (1 + 1e-6), below = ANTIPARALLEL_SIN * (1 - 1e-6);
    turned r = turn(-1, above, 1, 1);
    cr_assert_eq(r.kind, WK_VEL_REGULAR);
    cr_assert(!r.reflex && r.meets);
    r = turn(-1, -above, 1, 1);
    cr_assert_eq(r.kind, WK_VEL_REGULAR);
    cr_assert(r.reflex, "a right turn back above the bar is reflex");
    const double sines[] = {below, -below, ANTIPARALLEL_SIN, -ANTIPARALLEL_SIN, 0};
    for (size_t i = 0; i < sizeof sines / sizeof sines[0]; i++) {
        r = turn(-1, sines[i], 1, 2);
        cr_assert_eq(r.kind, WK_VEL_ANTIPARALLEL, "sine %g", sines[i]);
        cr_assert(r.v.x == 0 && r.v.y == 0);
        cr_assert(!r.reflex && !r.meets, "sine %g: reflex %d, meets %d", sines[i], r.reflex,
                  r.meets);
    }
    /* between the two bars the senses differ: a sine of 1e-10 is parallel
    ** for edges of the same sense and regular for opposite ones */
    cr_assert_eq(turn(1, 1e-10, 1, 1).kind, WK_VEL_STRAIGHT);
    cr_assert_eq(turn(-1, 1e-10, 1, 1).kind, WK_VEL_REGULAR);
}

/* ------------------------------------------------ lines meeting */

Test(kinetics, offset_lines_meet_where_the_vertex_is) {
    /* a vertex at (2, 1) between a 3-4-5 edge and a weighted horizontal one */
    wk_offset_line a = line(pt(-1, -3), pt(2, 1), 1.5), b = line(pt(2, 1), pt(0, 1), 0.75);
    wk_point v, q;
    cr_assert_eq(wk_vertex_velocity(&a, &b, &v), WK_VEL_REGULAR);
    for (double t = 0; t <= 3; t += 0.75) {
        cr_assert(wk_offset_lines_meet(&a, &b, t, &q));
        ASSERT_NEAR(q.x, 2 + v.x * t, 1e-12);
        ASSERT_NEAR(q.y, 1 + v.y * t, 1e-12);
        ASSERT_NEAR(wk_offset_distance(&a, q, t), 0, 1e-12);
        ASSERT_NEAR(wk_offset_distance(&b, q, t), 0, 1e-12);
    }
}

Test(kinetics, three_lines_meet) {
    /* right triangle (0,0) (4,0) (0,3), unit weights: the incircle, r = 1 */
    wk_point A = pt(0, 0), B = pt(4, 0), C = pt(0, 3);
    wk_offset_line a = line(A, B, 1), b = line(B, C, 1), c = line(C, A, 1);
    wk_point p;
    double t;
    cr_assert(wk_three_lines_meet(&a, &b, &c, &p, &t));
    ASSERT_NEAR(p.x, 1, 1e-14);
    ASSERT_NEAR(p.y, 1, 1e-14);
    ASSERT_NEAR(t, 1, 1e-14);
    /* weighted: the point is at distance w t from each line */
    a.w = 2;
    b.w = 0.5;
    c.w = 3;
    cr_assert(wk_three_lines_meet(&a, &b, &c, &p, &t));
    cr_assert_gt(t, 0);
    ASSERT_NEAR(wk_offset_distance(&a, p, t), 0, 1e-13);
    ASSERT_NEAR(wk_offset_distance(&b, p, t), 0, 1e-13);
    ASSERT_NEAR(wk_offset_distance(&c, p, t), 0, 1e-13);
    /* three parallel lines never meet */
    wk_offset_line d = line(pt(0, 0), pt(1, 0), 1), e = line(pt(0, 1), pt(1, 1), 2),
                   f = line(pt(0, 2), pt(1, 2), 3);
    cr_assert_not(wk_three_lines_meet(&d, &e, &f, &p, &t));
}

/* Three edges of an H at 1e6 with a needle (TestNeedles needle_h_22 in
** tests/test_cgal_agreement.py): edges 9 (x = 1000001, up), 10 (y =
** 1000006, leftwards) and 11, 1e6 long from (1e6, 1000006) to (1000,
** 1000001.01), at a sine of 5e-6 to edge 10.  Their offset lines meet at
** p = (1000001 - t, 1000006 - t) with edge 11's condition n11 . (p - v11)
** = t, i.e. t = 1 / (1 + |dy| / (L + |dx|)), (dx, dy) edge 11's direction
** and L its length: a closed form with no cancellation, good to a few ulps.
** The double lines of wk_offset_line_of_edge_at (anchored at the
** midpoints, 5e5 away) gave t 5.5e-6 early through wk_three_lines_meet,
** which the refinement of the wavefront took as the event (5 eps_t). */
Test(kinetics, three_edges_meet_far_from_the_midpoints) {
    static const double x[] = {1000, 1000000.99, 1000001, 1000003, 1000003, 1000003.99,
                               1000004, 1000003, 1000003, 1000001, 1000001, 1000000};
    static const double y[] = {1000001.01, 865441, 1000002, 1000002, 1000000, 637378,
                               1000006, 1000006, 1000004, 1000004, 1000006, 1000006};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 12, x, y, NULL);
    cr_assert(P->p[11].x == 1000000 && P->p[0].x == 1000, "stored in input order");
    double dx = P->p[0].x - P->p[11].x, dy = P->p[0].y - P->p[11].y; /* exact (Sterbenz) */
    double t_exact = 1 / (1 + fabs(dy) / (hypot(dx, dy) + fabs(dx)));
    wk_point o = wk_polygon_centre(P), q;
    double t;
    cr_assert(wk_three_edges_meet(P, 9, 10, 11, o, &q, &t));
    /* long double lines: 2^-64 x 5e5 / 5e-6 = 5e-9 at worst (measured
    ** 4.7e-10), 1000 times below the double lines' miss */
    ASSERT_NEAR(t, t_exact, 5e-9);
    ASSERT_NEAR(q.x + o.x, 1000001 - t_exact, 5e-9);
    ASSERT_NEAR(q.y + o.y, 1000006 - t_exact, 5e-9);
    /* the tolerance tells the two constructions apart: the double lines
    ** miss by more than 1e-7 (measured: 5.5e-6) */
    wk_offset_line l9, l10, l11;
    wk_offset_line_of_edge_at(P, 9, o, &l9);
    wk_offset_line_of_edge_at(P, 10, o, &l10);
    wk_offset_line_of_edge_at(P, 11, o, &l11);
    cr_assert(wk_three_lines_meet(&l9, &l10, &l11, &q, &t));
    cr_assert_gt(fabs(t - t_exact), 1e-7, "double lines: t = %.17g, exact %.17g", t, t_exact);
    /* weights enter as speeds: edge 10 at weight 2 meets the others where
    ** each offset distance is its weight times t */
    wk_polygon_free(&R, P);
    double w[12] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 1};
    P = polygon(&R, 12, x, y, w);
    cr_assert(wk_three_edges_meet(P, 9, 10, 11, o, &q, &t));
    wk_offset_line_of_edge_at(P, 9, o, &l9);
    wk_offset_line_of_edge_at(P, 10, o, &l10);
    ASSERT_NEAR(wk_offset_distance(&l9, q, t), 0, 1e-9);
    ASSERT_NEAR(wk_offset_distance(&l10, q, t), 0, 1e-9);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------- wk_vertex_start */

Test(kinetics, vertex_start_snaps_regular_vertices) {
    /* the lines of the square's edges 0 (bottom) and 1 (right) */
    wk_offset_line L[2] = {line(pt(0, 0), pt(1, 0), 1), line(pt(1, 0), pt(1, 1), 1)};
    wk_point p0, vel;
    bool reflex = true;
    /* born at t = 0.25 near (0.75, 0.25), 1e-10 off: snapped onto both lines */
    wk_velocity_kind k =
        wk_vertex_start(L, 0, 1, pt(0.75 + 1e-10, 0.25 - 1e-10), 0.25, 1e-9, &p0, &vel, &reflex);
    cr_assert_eq(k, WK_VEL_REGULAR);
    cr_assert_not(reflex);
    cr_assert(vel.x == -1 && vel.y == 1, "vel (%g, %g)", vel.x, vel.y);
    cr_assert(p0.x == 0.75 && p0.y == 0.25, "not snapped: (%.17g, %.17g)", p0.x, p0.y);
    /* farther than snap: kept where it was born */
    wk_point p = pt(0.75 + 1e-6, 0.25);
    wk_vertex_start(L, 0, 1, p, 0.25, 1e-9, &p0, &vel, &reflex);
    cr_assert(p0.x == p.x && p0.y == p.y, "snapped from beyond snap: (%.17g, %.17g)", p0.x, p0.y);
    /* at t = 0 (an input vertex) never moved */
    p = pt(1 + 1e-12, 1e-12);
    wk_vertex_start(L, 0, 1, p, 0, 1, &p0, &vel, &reflex);
    cr_assert(p0.x == p.x && p0.y == p.y, "input vertex moved: (%.17g, %.17g)", p0.x, p0.y);
}

Test(kinetics, vertex_start_kinds_and_reflexness) {
    wk_offset_line L[5] = {
        line(pt(2, 1), pt(1, 1), 1), /* 0 -> 1: the L shape's reflex corner */
        line(pt(1, 1), pt(1, 2), 1),
        line(pt(0, 0), pt(1, 0), 1), /* 2 -> 3: straight; 2 -> 4: collinear */
        line(pt(1, 0), pt(2, 0), 1),
        line(pt(1, 0), pt(2, 0), 2),
    };
    wk_point p0, vel;
    bool reflex = false;
    cr_assert_eq(wk_vertex_start(L, 0, 1, pt(0.5, 0.5), 0.5, 1e-9, &p0, &vel, &reflex),
                 WK_VEL_REGULAR);
    cr_assert(reflex, "the reflex corner is not reflex");
    cr_assert(vel.x == -1 && vel.y == -1);
    cr_assert(p0.x == 0.5 && p0.y == 0.5);
    /* straight and collinear vertices: velocity as wk_vertex_velocity, no
    ** snapping, never reflex */
    wk_point p = pt(1 + 1e-12, 0.5);
    reflex = true;
    cr_assert_eq(wk_vertex_start(L, 2, 3, p, 0.5, 1, &p0, &vel, &reflex), WK_VEL_STRAIGHT);
    cr_assert_not(reflex);
    cr_assert(vel.x == 0 && vel.y == 1);
    cr_assert(p0.x == p.x && p0.y == p.y);
    reflex = true;
    cr_assert_eq(wk_vertex_start(L, 2, 4, p, 0.5, 1, &p0, &vel, &reflex), WK_VEL_COLLINEAR);
    cr_assert_not(reflex);
    cr_assert(p0.x == p.x && p0.y == p.y);
    /* the velocity is wk_vertex_velocity's */
    wk_point v;
    cr_assert_eq(wk_vertex_start(L, 1, 0, pt(0, 0), 0.1, 0, &p0, &vel, &reflex),
                 wk_vertex_velocity(&L[1], &L[0], &v));
    cr_assert(vel.x == v.x && vel.y == v.y);
}

/* wk_stretch_collapses_later, on the stretch of the comb spike
** (tests/data/fuzz/mismatch_deforming_weighted_comb_spike.wpoly at
** t = 110/7): a wall x = 660 + 3t going down (weight 3), the vertex born
** on it 5.14e-3 above the vertex x at its lower end, the born one between
** the wall and an edge at a sine of 3e-5 to x's other edge (both weight
** 3), so the two close in at 8.9e-5: 58 time units, not now.  The closed
** form: the stretch's length d (from the born vertex towards x along the
** line's direction, or back) shrinks at -rate; it collapses later iff
** rate < 0 beyond the parallel bar and d + rate eps_t exceeds rounding. */
Test(kinetics, stretch_collapses_later_only_when_it_shrinks_slowly) {
    wk_offset_line L = line(pt(660, 709), pt(660, 259), 3); /* direction (0, -1) */
    double eps_t = 2.02e-6;
    wk_point q = pt(707.1428571428571, 211.86228043697596), vq = pt(3, -3.0000891);
    wk_point px = pt(707.1428571428571, 211.85714285714286), vx = pt(3, -3);
    /* x after the born vertex along the line (below it): slow, later */
    cr_assert(wk_stretch_collapses_later(&L, q, vq, px, vx, true, eps_t));
    /* the same stretch seen from the other end (x before q along the line:
    ** swap the roles), still later */
    cr_assert(wk_stretch_collapses_later(&L, px, vx, q, vq, false, eps_t));
    /* fast: shrinking at 4, gone within a window of 2e-3 (now), not within
    ** 2e-6 (later) */
    wk_point vfast = pt(3, -7);
    cr_assert_not(wk_stretch_collapses_later(&L, q, vfast, px, vx, true, 2e-3));
    cr_assert(wk_stretch_collapses_later(&L, q, vfast, px, vx, true, eps_t));
    /* growing, or keeping its length (parallel motion): the tolerance
    ** picture, false */
    cr_assert_not(wk_stretch_collapses_later(&L, q, pt(3, 1), px, vx, true, eps_t));
    cr_assert_not(wk_stretch_collapses_later(&L, q, vx, px, vx, true, eps_t));
    cr_assert_not(wk_stretch_collapses_later(&L, q, pt(3, -3 - 1e-12), px, vx, true, eps_t));
    /* x on the wrong side (the stretch has negative length: already
    ** collapsed) or within rounding of q: now */
    cr_assert_not(wk_stretch_collapses_later(&L, q, vq, px, vx, false, eps_t));
    wk_point far = pt(4e6, 0), vfar = pt(0, 1);
    wk_offset_line H = line(pt(0, 0), pt(1, 0), 1); /* direction (1, 0) */
    cr_assert_not(wk_stretch_collapses_later(&H, far, vfar, pt(4e6 + 1e-10, 0), pt(-1, 1), true, 1e-20));
    cr_assert(wk_stretch_collapses_later(&H, far, vfar, pt(4e6 + 1e-3, 0), pt(-1, 1), true, 1e-20));
}
