/*
** test_validate.c: the validator (engine/validate.c) and the face cycles
** (engine/faces.c).
**
** Oracles: skeletons computed by hand (unit square, 2x1 rectangle, a square
** whose bottom edge has weight 2, an L shape, a general quadrilateral whose
** nodes are solved from their three edges' offset lines, a collinear edge
** removed at t = 0), each accepted; doctored copies, each rejected with the
** property the contract at the top of validate.c assigns to the defect; and
** large skeletons built from closed forms (regular 10^5-gon with subdivided
** spokes, a long rectangle whose ridge has 10^5 arcs) that must pass
** quickly.  Every test owns its wk_run and ends with zero live bytes.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>
#include <math.h>
#include <stdarg.h>
#include <string.h>
#include <time.h>

#include "faces.h"
#include "wskel.h"
#include "helpers.h"

static void expect_valid(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                         wk_validate_report *rep) {
    wk_status st = wk_validate(R, P, S, 0, rep);
    cr_assert_eq(st, WK_OK, "rejected: %s", R->err.msg);
}

/* wk_validate fails with WK_EINVALID and a message containing each of the
** NULL-terminated strings; the run's error is reset afterwards so the test
** can go on. */
static void expect_invalid(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double tol, ...) {
    wk_status st = wk_validate(R, P, S, tol, NULL);
    cr_assert_eq(st, WK_EINVALID, "accepted (status %d), message '%s'", st, R->err.msg);
    va_list ap;
    va_start(ap, tol);
    for (const char *want; (want = va_arg(ap, const char *));)
        cr_assert(strstr(R->err.msg, want), "message '%s' lacks '%s'", R->err.msg, want);
    va_end(ap);
    memset(&R->err, 0, sizeof R->err);
}

/* ---------------------------------------------------------- the shapes */

/* The unit square (SQ_*) and the L shape (L_*) are in helpers.h. */

static const double RECT_X[4] = {0, 2, 2, 0}, RECT_Y[4] = {0, 0, 1, 1};
static const wk_node RECT_NODES[2] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}};
static const arc4 RECT_ARCS[5] = {
    {0, 4, 3, 0}, {3, 4, 2, 3}, {1, 5, 0, 1}, {2, 5, 1, 2}, {4, 5, 2, 0}};

/* ---------------------------------------------------------- accepted */

Test(validate, unit_square) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = skeleton(&R, P, 1, SQ_NODES, 4, SQ_ARCS);
    wk_validate_report rep;
    expect_valid(&R, P, S, &rep);
    cr_assert_eq(rep.nodes, 5);
    cr_assert_eq(rep.arcs, 4);
    cr_assert_eq(rep.faces, 4);
    cr_assert_leq(rep.max_distance_error, 1e-15);
    cr_assert_leq(rep.area_error, 1e-15);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, rectangle_ridge) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, RECT_X, RECT_Y, NULL);
    wk_skeleton *S = skeleton(&R, P, 2, RECT_NODES, 5, RECT_ARCS);
    wk_validate_report rep;
    expect_valid(&R, P, S, &rep);
    cr_assert_eq(rep.faces, 4);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Bottom edge weight 2: its offset line is y = 2t, the others x = t,
** x = 1 - t, y = 1 - t.  The side edges vanish at t = 1/3 (2t = 1 - t),
** leaving bottom and top coincident on y = 2/3 between x = 1/3 and 2/3: the
** ridge.  Unit weights would put the nodes elsewhere, so the same skeleton
** must fail then. */
Test(validate, weighted_square_by_hand) {
    wk_run R;
    wk_run_init(&R);
    const double w[4] = {2, 1, 1, 1};
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, w);
    const wk_node nodes[2] = {{1.0 / 3, 2.0 / 3, 1.0 / 3}, {2.0 / 3, 2.0 / 3, 1.0 / 3}};
    const arc4 arcs[5] = {{0, 4, 3, 0}, {3, 4, 2, 3}, {1, 5, 0, 1}, {2, 5, 1, 2}, {4, 5, 2, 0}};
    wk_skeleton *S = skeleton(&R, P, 2, nodes, 5, arcs);
    wk_validate_report rep;
    expect_valid(&R, P, S, &rep);
    cr_assert_leq(rep.max_distance_error, 1e-15);
    wk_polygon *U = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    expect_invalid(&R, U, S, 0, "validate (c)", "edge 0", NULL);
    wk_polygon_free(&R, U);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, l_shape_with_reflex_vertex) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    cr_assert_eq(P->r, 1);
    wk_skeleton *S = skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
    expect_valid(&R, P, S, NULL);
    for (uint32_t i = 0; i < 8; i++)
        cr_assert_eq(wk_arc_is_reflex(P, S, i), i == 3, "arc %u", i);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* The point at weighted distance t from the lines of edges e[0..3), all at
** the same t (Cramer's rule on d_e(x, y) = w_e t). */
static wk_node solve_node(const wk_polygon *P, const uint32_t e[3]) {
    double M[3][4];
    for (int k = 0; k < 3; k++) {
        wk_point p = P->p[e[k]], q = P->p[(e[k] + 1) % P->n];
        double dx = q.x - p.x, dy = q.y - p.y, l = hypot(dx, dy);
        /* d = (dx (y - p.y) - dy (x - p.x)) / l = w t */
        M[k][0] = -dy / l;
        M[k][1] = dx / l;
        M[k][2] = -P->w[e[k]];
        M[k][3] = (dx * p.y - dy * p.x) / l;
    }
    double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                 M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    double v[3];
    for (int c = 0; c < 3; c++) {
        double A[3][3];
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++) A[r][k] = k == c ? M[r][3] : M[r][k];
        v[c] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) /
               det;
    }
    return (wk_node){v[0], v[1], v[2]};
}

/* Quadrilateral (0,0) (3,0) (2,5) (0,2).  In its skeleton edges 0 and 2
** collapse, at the nodes of edges 3, 0, 1 and of 1, 2, 3, joined by a ridge
** between faces 1 and 3.  The other pairing (edges 1 and 3 collapse: nodes
** of 0, 1, 2 and of 2, 3, 0) satisfies every distance, is a tree and its
** faces close with positive areas, but the arcs from vertices 0 and 1 cross
** where the true node of edges 3, 0, 1 is: only planarity (f) rejects it. */
static const double Q_X[4] = {0, 3, 2, 0}, Q_Y[4] = {0, 0, 5, 2};

Test(validate, quadrilateral_solved_nodes) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, Q_X, Q_Y, NULL);
    const uint32_t ea[3] = {3, 0, 1}, eb[3] = {1, 2, 3};
    wk_node nodes[2] = {solve_node(P, ea), solve_node(P, eb)};
    const arc4 arcs[5] = {{0, 4, 3, 0}, {1, 4, 0, 1}, {2, 5, 1, 2}, {3, 5, 2, 3}, {5, 4, 1, 3}};
    wk_skeleton *S = skeleton(&R, P, 2, nodes, 5, arcs);
    expect_valid(&R, P, S, NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, quadrilateral_wrong_event_order_crosses) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, Q_X, Q_Y, NULL);
    const uint32_t ea[3] = {0, 1, 2}, eb[3] = {2, 3, 0};
    wk_node nodes[2] = {solve_node(P, ea), solve_node(P, eb)};
    const arc4 arcs[5] = {{1, 4, 0, 1}, {2, 4, 1, 2}, {3, 5, 2, 3}, {0, 5, 3, 0}, {4, 5, 0, 2}};
    wk_skeleton *S = skeleton(&R, P, 2, nodes, 5, arcs);
    expect_invalid(&R, P, S, 0, "validate (f)", "face of edge 0", "cross", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* (0,0) (1,0) (2,0) (2,1) (0,1): edges 0 and 1 are collinear, weights 1
** and 2; the lower weight survives, so edge 1 is removed at t = 0 and traced
** by the arc 1-2 along it; edge 0 takes over the 2x1 rectangle's bottom.
** Node 2 has two arcs and face 1 is the 2-cycle [1, 2]. */
Test(validate, collinear_edge_removed_at_zero) {
    wk_run R;
    wk_run_init(&R);
    const double x[5] = {0, 1, 2, 2, 0}, y[5] = {0, 0, 0, 1, 1}, w[5] = {1, 2, 1, 1, 1};
    wk_polygon *P = polygon(&R, 5, x, y, w);
    const wk_node nodes[2] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}};
    const arc4 arcs[6] = {{1, 2, 0, 1}, {0, 5, 4, 0}, {4, 5, 3, 4},
                          {2, 6, 0, 2}, {3, 6, 2, 3}, {5, 6, 3, 0}};
    wk_skeleton *S = skeleton(&R, P, 2, nodes, 6, arcs);
    wk_validate_report rep;
    expect_valid(&R, P, S, &rep);
    uint32_t *cyc, len;
    cr_assert_eq(wk_face_cycle(&R, P, S, 1, &cyc, &len), WK_OK);
    cr_assert_eq(len, 2);
    cr_assert_eq(cyc[0], 1);
    cr_assert_eq(cyc[1], 2);
    WK_FREE_ARRAY(&R, cyc, len);
    cr_assert_eq(wk_face_cycle(&R, P, S, 0, &cyc, &len), WK_OK);
    const uint32_t want[5] = {0, 1, 2, 6, 5};
    cr_assert_eq(len, 5);
    for (uint32_t i = 0; i < 5; i++) cr_assert_eq(cyc[i], want[i]);
    WK_FREE_ARRAY(&R, cyc, len);
    /* Without the arc along edge 1, node 1 is on no arc. */
    S->arcs[0] = S->arcs[5];
    S->n_arcs = 5;
    expect_invalid(&R, P, S, 0, "validate (d)", "node 1 is on no arc", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------- doctored */

/* Fresh copies of the square and rectangle skeletons for each defect. */
static wk_skeleton *square(wk_run *R, const wk_polygon *P) {
    return skeleton(R, P, 1, SQ_NODES, 4, SQ_ARCS);
}
static wk_skeleton *rect(wk_run *R, const wk_polygon *P) {
    return skeleton(R, P, 2, RECT_NODES, 5, RECT_ARCS);
}

Test(validate, input_nodes_a) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = square(&R, P);
    S->nodes[2].x = 1.0000001;
    expect_invalid(&R, P, S, 0, "validate (a)", "node 2", NULL);
    S->nodes[2].x = 1;
    S->nodes[1].t = 1e-300;
    expect_invalid(&R, P, S, 0, "validate (a)", "node 1", NULL);
    S->nodes[1].t = 0;
    S->n_input = 3;
    expect_invalid(&R, P, S, 0, "validate (a)", "3 input nodes", NULL);
    S->n_input = 4;
    expect_valid(&R, P, S, NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, node_positions_b) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = square(&R, P);
    S->nodes[4].y = 1.5; /* outside, above */
    expect_invalid(&R, P, S, 0, "validate (b)", "node 4", "outside", NULL);
    S->nodes[4].y = 0.5;
    S->nodes[4].t = 0;
    expect_invalid(&R, P, S, 0, "validate (b)", "t = 0", NULL);
    S->nodes[4].t = -0.5;
    expect_invalid(&R, P, S, 0, "validate (b)", NULL);
    S->nodes[4].t = NAN;
    expect_invalid(&R, P, S, 0, "validate (b)", "not finite", NULL);
    S->nodes[4].t = 0.5;
    S->nodes[4].x = INFINITY;
    expect_invalid(&R, P, S, 0, "validate (b)", "not finite", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* A node in the L's notch is inside the bounding box but outside the
** polygon; on the boundary (within tol) it is accepted by (b). */
Test(validate, node_in_notch_b) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    wk_skeleton *S = skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
    S->nodes[7] = (wk_node){1.5, 1.5, 0.5};
    expect_invalid(&R, P, S, 0, "validate (b)", "node 7", "outside", NULL);
    S->nodes[7] = (wk_node){1.5, 1.0 + 1e-9, 0.5}; /* within tol of edge 2 */
    expect_invalid(&R, P, S, 0, "validate (c)", NULL);
    S->nodes[7] = (wk_node){1.5, 1.0 + 1e-3, 0.5};
    expect_invalid(&R, P, S, 0, "validate (b)", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, moved_node_and_wrong_t_c) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = square(&R, P);
    S->nodes[4].x = 0.6;
    expect_invalid(&R, P, S, 0, "validate (c)", "node 4", "expected w t", NULL);
    S->nodes[4].x = 0.5;
    S->nodes[4].t = 0.6;
    expect_invalid(&R, P, S, 0, "validate (c)", "node 4", NULL);
    /* Tolerance: 1e-7 off passes the default (1e-6 * scale), not 1e-8. */
    S->nodes[4].t = 0.5 + 1e-7;
    expect_valid(&R, P, S, NULL);
    expect_invalid(&R, P, S, 1e-8, "validate (c)", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, arc_ids_and_labels_c) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = square(&R, P);
    S->arcs[1].right = 2; /* wrong face: node 1 is not on edge 2's line */
    expect_invalid(&R, P, S, 0, "validate (c)", "arc 1", "edge 2", NULL);
    S->arcs[1].right = 0;
    expect_invalid(&R, P, S, 0, "validate (c)", "same face on both sides", NULL);
    S->arcs[1].right = 4;
    expect_invalid(&R, P, S, 0, "validate (c)", "beyond the 4 edges", NULL);
    S->arcs[1].right = 1;
    S->arcs[1].b = 9;
    expect_invalid(&R, P, S, 0, "validate (c)", "beyond the 5 nodes", NULL);
    S->arcs[1].b = 1;
    expect_invalid(&R, P, S, 0, "validate (c)", "loop", NULL);
    S->arcs[1].b = 4;
    expect_valid(&R, P, S, NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, missing_and_extra_arcs_d) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, RECT_X, RECT_Y, NULL);
    wk_skeleton *S = rect(&R, P);
    S->n_arcs = 4; /* no ridge */
    expect_invalid(&R, P, S, 0, "validate (d)", "do not connect", "4 arcs for 6 nodes", NULL);
    S->n_arcs = 5;
    S->arcs[2] = S->arcs[4]; /* vertex 1 loses its arc */
    expect_invalid(&R, P, S, 0, "validate (d)", "node 1 is on no arc", NULL);
    wk_skeleton_free(&R, S);

    S = rect(&R, P);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 4, 5, 2, 0), WK_OK); /* the ridge twice */
    expect_invalid(&R, P, S, 0, "validate (d)", "arc 5", "closes a cycle", NULL);
    wk_skeleton_free(&R, S);

    /* An extra arc between two input vertices across the polygon: its
    ** labels cannot fit both ends, whatever they are. */
    S = rect(&R, P);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 0, 2, 0, 1), WK_OK);
    expect_invalid(&R, P, S, 0, "validate (c)", "arc 5", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(validate, swapped_left_right_e) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = square(&R, P);
    S->arcs[0] = (wk_arc){0, 4, 0, 3}; /* distances are symmetric: only faces notice */
    expect_invalid(&R, P, S, 0, "validate (e)", "face of edge", NULL);
    S->arcs[0] = (wk_arc){4, 0, 3, 0}; /* reversed arc, same labels: left/right swap too */
    expect_invalid(&R, P, S, 0, "validate (e)", NULL);
    S->arcs[0] = (wk_arc){4, 0, 0, 3}; /* reversed with swapped labels: the same arc */
    expect_valid(&R, P, S, NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* The ridge split at D = (1.9, 0.5) and walked A -> D -> B: every node sits
** on its faces' lines, it is a tree, the faces close with the right areas,
** but the face cycles fold back on themselves. */
Test(validate, folded_ridge_f) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, RECT_X, RECT_Y, NULL);
    const wk_node nodes[3] = {{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {1.9, 0.5, 0.5}};
    const arc4 arcs[6] = {{0, 4, 3, 0}, {3, 4, 2, 3}, {1, 5, 0, 1},
                          {2, 5, 1, 2}, {4, 6, 2, 0}, {6, 5, 2, 0}};
    wk_skeleton *S = skeleton(&R, P, 3, nodes, 6, arcs);
    expect_invalid(&R, P, S, 0, "validate (f)", "overlap", NULL);
    S->nodes[6].x = 1.0; /* D between A and B: fine */
    expect_valid(&R, P, S, NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Found by degenerate fuzzing (integer grid, integer weights): edges 1, 8
** and 11 lie on parallel lines that the weights make meet at one instant.
** A merge once produced arc 20 -> 18 along the flat event and arc 17 -> 18
** folding back along it; the three nodes are collinear only up to 1e-16, so
** the exact segment tests see the two sides touch at node 18, nothing more.
** naive's skeleton of the same polygon is accepted. */
static const double FOLD_X[12] = {0, 1, 0, 1, 3, 4, 3, 4, 3, 4, 0, 1};
static const double FOLD_Y[12] = {2, 2, 1, 0, 0, 1, 2, 3, 3, 4, 4, 3};
static const double FOLD_W[12] = {1, 2, 2, 2, 4, 5, 1, 2, 1, 2, 3, 5};
static const wk_node FOLD_BAD_NODES[9] = {
    {1.649165125326326, 0.73879612503625858, 0.36939806251812929},
    {1.3347351072153746, 0.80812203564176843, 0.40406101782088422},
    {1.2857142857142856, 0.8571428571428571, 0.40406101782088422},
    {1.333333333333333, 1, 0.47140452079103157},
    {2.3905242917512703, 2.0571909584179369, 0.47140452079103157},
    {2.1952621458756347, 2.5285954792089687, 0.23570226039551581},
    {2.3333333333333335, 2.666666666666667, 0.23570226039551587},
    {2.5857864376269046, 3.1715728752538097, 0.41421356237309498},
    {1.9023689270621824, 2.2357022603955152, 0.23570226039551581}};
static const arc4 FOLD_BAD_ARCS[20] = {
    {5, 12, 4, 5},    {6, 14, 5, 6},    {7, 16, 6, 7},    {8, 17, 7, 8},   {9, 19, 8, 9},
    {11, 18, 10, 11}, {0, 20, 11, 0},   {1, 20, 0, 1},    {2, 15, 1, 2},   {3, 13, 2, 3},
    {20, 18, 11, 1},  {4, 12, 3, 4},    {12, 13, 3, 5},   {13, 14, 2, 5},  {14, 15, 2, 6},
    {15, 16, 1, 6},   {16, 17, 1, 7},   {17, 18, 1, 8},   {18, 19, 10, 8}, {19, 10, 10, 9}};
static const wk_node FOLD_GOOD_NODES[9] = {
    {1.9023689270621826, 2.2357022603955157, 0.23570226039551581},
    {2.1952621458756352, 2.5285954792089687, 0.23570226039551581},
    {2.333333333333333, 2.6666666666666665, 0.23570226039551581},
    {1.6491651253263262, 0.73879612503625847, 0.36939806251812923},
    {1.3347351072153741, 0.80812203564176865, 0.40406101782088433},
    {1.2857142857142856, 0.85714285714285721, 0.40406101782088433},
    {2.5857864376269051, 3.1715728752538102, 0.41421356237309498},
    {1.3333333333333333, 1, 0.47140452079103162},
    {2.3905242917512699, 2.0571909584179369, 0.47140452079103162}};
static const arc4 FOLD_GOOD_ARCS[20] = {
    {0, 12, 11, 0},  {1, 12, 0, 1},   {8, 13, 7, 8},   {11, 14, 10, 11}, {13, 14, 11, 8},
    {13, 12, 1, 11}, {4, 15, 3, 4},   {5, 15, 4, 5},   {3, 16, 2, 3},    {15, 16, 3, 5},
    {6, 17, 5, 6},   {16, 17, 2, 5},  {9, 18, 8, 9},   {10, 18, 9, 10},  {14, 18, 10, 8},
    {2, 19, 1, 2},   {17, 19, 2, 6},  {7, 20, 6, 7},   {13, 20, 7, 1},   {19, 20, 1, 6}};

Test(validate, fold_back_by_rounding_f) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 12, FOLD_X, FOLD_Y, FOLD_W);
    wk_skeleton *bad = skeleton(&R, P, 9, FOLD_BAD_NODES, 20, FOLD_BAD_ARCS);
    expect_invalid(&R, P, bad, 0, "validate (f)", "overlap", NULL);
    wk_skeleton *good = skeleton(&R, P, 9, FOLD_GOOD_NODES, 20, FOLD_GOOD_ARCS);
    expect_valid(&R, P, good, NULL);
    wk_skeleton_free(&R, good);
    wk_skeleton_free(&R, bad);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------- face cycles */

Test(faces, square_cycles_and_errors) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = square(&R, P);
    for (uint32_t e = 0; e < 4; e++) {
        uint32_t *cyc, len;
        cr_assert_eq(wk_face_cycle(&R, P, S, e, &cyc, &len), WK_OK, "%s", R.err.msg);
        cr_assert_eq(len, 3);
        cr_assert_eq(cyc[0], e);
        cr_assert_eq(cyc[1], (e + 1) % 4);
        cr_assert_eq(cyc[2], 4);
        WK_FREE_ARRAY(&R, cyc, len);
    }
    uint32_t *cyc = (uint32_t *)1, len = 7;
    cr_assert_eq(wk_face_cycle(&R, P, S, 4, &cyc, &len), WK_EINVALID);
    cr_assert_null(cyc);
    cr_assert_eq(len, 0);
    cr_assert(strstr(R.err.msg, "no face 4"), "%s", R.err.msg);
    memset(&R.err, 0, sizeof R.err);

    /* Branch: a second arc labelled 0 leaving node 1 with face 0 on its left. */
    uint32_t id;
    cr_assert_eq(wk_skeleton_add_node(&R, S, 0.5, 0.25, 0.25, &id), WK_OK);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 1, id, 0, 1), WK_OK);
    cr_assert_eq(wk_face_cycle(&R, P, S, 0, &cyc, &len), WK_EINVALID);
    cr_assert(strstr(R.err.msg, "branches at node 1"), "%s", R.err.msg);
    memset(&R.err, 0, sizeof R.err);
    /* Circling: 1 -> 4 -> 5 -> 4 on face 0, no way back to node 0. */
    S->arcs[0].right = 2;
    S->arcs[4] = (wk_arc){4, id, 0, 2};
    cr_assert_eq(wk_skeleton_add_arc(&R, S, id, 4, 0, 3), WK_OK);
    cr_assert_eq(wk_face_cycle(&R, P, S, 0, &cyc, &len), WK_EINVALID);
    cr_assert(strstr(R.err.msg, "circles"), "%s", R.err.msg);
    memset(&R.err, 0, sizeof R.err);
    /* Dead end: face 1 loses the arc from the centre back to node 1. */
    S->n_arcs = 4;
    S->arcs[0].right = 0;
    S->arcs[1].right = 3;
    cr_assert_eq(wk_face_cycle(&R, P, S, 1, &cyc, &len), WK_EINVALID);
    cr_assert(strstr(R.err.msg, "stops at node 4"), "%s", R.err.msg);
    memset(&R.err, 0, sizeof R.err);
    /* Stray arc: an extra arc labelled 2 off face 2's path. */
    S->arcs[1].right = 1;
    cr_assert_eq(wk_skeleton_add_arc(&R, S, id, 0, 2, 3), WK_OK);
    cr_assert_eq(wk_face_cycle(&R, P, S, 2, &cyc, &len), WK_EINVALID);
    cr_assert(strstr(R.err.msg, "arc 4 labelled 2 is not on the path"), "%s", R.err.msg);
    memset(&R.err, 0, sizeof R.err);

    wk_faces F;
    cr_assert_eq(wk_faces_build(&R, P, S, &F, "x: "), WK_EINVALID);
    cr_assert(strstr(R.err.msg, "x: face of edge"), "%s", R.err.msg);
    cr_assert_null(F.start);
    memset(&R.err, 0, sizeof R.err);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Fault injection: every allocation of the validator may fail; each failure
** is WK_ENOMEM and leaks nothing. */
Test(validate, out_of_memory_at_every_allocation) {
    for (int64_t k = 0;; k++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
        wk_skeleton *S = skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
        R.alloc.fail_after = (int64_t)R.alloc.calls + k;
        wk_status st = wk_validate(&R, P, S, 0, NULL);
        R.alloc.fail_after = -1;
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
        if (st == WK_OK) break;
        cr_assert_eq(st, WK_ENOMEM, "allocation %lld: %s", (long long)k, R.err.msg);
        cr_assert_lt(k, 1000);
    }
}

/* ---------------------------------------------------------- large */

/* Regular n-gon, n = 10^5: every spoke (vertex -> centre) split at its
** midpoint, so 2n arcs, n + 1 interior nodes for (b), and n triangular
** faces with 5 sides; all arcs meet at the centre. */
Test(validate, regular_polygon_1e5_spokes, .timeout = 60) {
    const uint32_t n = 100000;
    wk_run R;
    wk_run_init(&R);
    double *x = WK_NEW_ARRAY(&R, double, n), *y = WK_NEW_ARRAY(&R, double, n);
    for (uint32_t i = 0; i < n; i++) {
        x[i] = cos(2 * PI * i / n);
        y[i] = sin(2 * PI * i / n);
    }
    wk_polygon *P = polygon(&R, n, x, y, NULL);
    wk_skeleton *S;
    cr_assert_eq(wk_skeleton_new(&R, P, &S), WK_OK);
    double apothem = cos(PI / n);
    uint32_t centre, mid;
    cr_assert_eq(wk_skeleton_add_node(&R, S, 0, 0, apothem, &centre), WK_OK);
    for (uint32_t i = 0; i < n; i++) {
        uint32_t prev = (i + n - 1) % n;
        cr_assert_eq(wk_skeleton_add_node(&R, S, x[i] / 2, y[i] / 2, apothem / 2, &mid), WK_OK);
        cr_assert_eq(wk_skeleton_add_arc(&R, S, i, mid, prev, i), WK_OK);
        cr_assert_eq(wk_skeleton_add_arc(&R, S, mid, centre, prev, i), WK_OK);
    }
    double t0 = now_s();
    wk_validate_report rep;
    expect_valid(&R, P, S, &rep);
    double dt = now_s() - t0;
    cr_log_info("regular 1e5-gon, 2e5 arcs: validated in %.3f s (max distance error %.3g)", dt,
                rep.max_distance_error);
    cr_assert_eq(rep.arcs, 2 * n);
    cr_assert_lt(dt, 10.0);
    /* One spoke midpoint pushed just outside the polygon. */
    S->nodes[n + 1 + 777].x *= 2.0002;
    S->nodes[n + 1 + 777].y *= 2.0002;
    expect_invalid(&R, P, S, 0, "validate (b)", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    WK_FREE_ARRAY(&R, x, n);
    WK_FREE_ARRAY(&R, y, n);
    ASSERT_CLEAN_CLOSE(R);
}

/* Rectangle 1e5 x 1 whose ridge is split into 10^5 arcs: faces 0 and 2
** have 10^5 + 3 sides, so the per-face grid of (f) runs. */
Test(validate, long_ridge_1e5_arcs, .timeout = 60) {
    const uint32_t K = 100000;
    const double L = 1e5;
    wk_run R;
    wk_run_init(&R);
    const double x[4] = {0, L, L, 0}, y[4] = {0, 0, 1, 1};
    wk_polygon *P = polygon(&R, 4, x, y, NULL);
    wk_skeleton *S;
    cr_assert_eq(wk_skeleton_new(&R, P, &S), WK_OK);
    uint32_t first = S->n_nodes, id;
    for (uint32_t k = 0; k <= K; k++)
        cr_assert_eq(wk_skeleton_add_node(&R, S, 0.5 + (L - 1) * k / K, 0.5, 0.5, &id), WK_OK);
    for (uint32_t k = 0; k < K; k++)
        cr_assert_eq(wk_skeleton_add_arc(&R, S, first + k, first + k + 1, 2, 0), WK_OK);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 0, first, 3, 0), WK_OK);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 3, first, 2, 3), WK_OK);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 1, first + K, 0, 1), WK_OK);
    cr_assert_eq(wk_skeleton_add_arc(&R, S, 2, first + K, 1, 2), WK_OK);
    double t0 = now_s();
    expect_valid(&R, P, S, NULL);
    double dt = now_s() - t0;
    cr_log_info("ridge of 1e5 arcs: validated in %.3f s", dt);
    cr_assert_lt(dt, 10.0);
    /* Swap two ridge nodes far apart: still a path on the ridge line, but it
    ** now runs back and forth. */
    wk_node tmp = S->nodes[first + 10];
    S->nodes[first + 10] = S->nodes[first + 90000];
    S->nodes[first + 90000] = tmp;
    expect_invalid(&R, P, S, 0, "validate (f)", "overlap", NULL);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* (b) against a brute-force crossing number: a star with 64 random spikes,
** 3000 random points, each as the one extra node of an arc-less skeleton, so
** wk_validate stops at (b) when the point is outside and at (d) otherwise.
** Points within 10 tol of the boundary are skipped (either answer is right),
** and every vertex and edge midpoint must be accepted. */
static bool brute_inside(const wk_polygon *P, double x, double y) {
    bool in = false;
    for (uint32_t i = 0, j = P->n - 1; i < P->n; j = i++) {
        wk_point a = P->p[i], b = P->p[j];
        if ((a.y > y) != (b.y > y) && x < a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

static double brute_dist(const wk_polygon *P, double x, double y) {
    double best = INFINITY;
    for (uint32_t i = 0; i < P->n; i++) {
        wk_point a = P->p[i], b = P->p[(i + 1) % P->n];
        double dx = b.x - a.x, dy = b.y - a.y;
        double u = ((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy);
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        best = fmin(best, hypot(x - a.x - u * dx, y - a.y - u * dy));
    }
    return best;
}

Test(validate, point_location_matches_brute_force, .timeout = 60) {
    wk_run R;
    wk_run_init(&R);
    enum { N = 128 };
    double x[N], y[N];
    uint64_t s = 12345;
#define RND() ((double)((s = s * 6364136223846793005ull + 1442695040888963407ull) >> 11) / 9007199254740992.0)
    for (int i = 0; i < N; i++) {
        double r = i % 2 ? 0.2 + 0.3 * RND() : 0.6 + 0.4 * RND();
        x[i] = r * cos(2 * PI * i / N);
        y[i] = r * sin(2 * PI * i / N);
    }
    wk_polygon *P = polygon(&R, N, x, y, NULL);
    double tol = 1e-6 * wk_polygon_scale(P);
    wk_skeleton *S;
    cr_assert_eq(wk_skeleton_new(&R, P, &S), WK_OK);
    uint32_t id;
    cr_assert_eq(wk_skeleton_add_node(&R, S, 0, 0, 1, &id), WK_OK);
    int checked = 0;
    for (int k = 0; k < 3000 + 2 * N; k++) {
        double px, py;
        bool on_boundary = k >= 3000;
        if (!on_boundary) {
            px = 2.2 * RND() - 1.1;
            py = 2.2 * RND() - 1.1;
            if (brute_dist(P, px, py) < 10 * tol) continue;
        } else { /* a vertex, or the midpoint of an edge */
            int i = (k - 3000) / 2;
            wk_point a = P->p[i], b = P->p[(i + 1) % N];
            px = k % 2 ? a.x : 0.5 * (a.x + b.x);
            py = k % 2 ? a.y : 0.5 * (a.y + b.y);
        }
        S->nodes[id] = (wk_node){px, py, 1};
        wk_status st = wk_validate(&R, P, S, 0, NULL);
        cr_assert_eq(st, WK_EINVALID);
        bool rejected_b = strstr(R.err.msg, "validate (b)") != NULL;
        bool inside = on_boundary || brute_inside(P, px, py);
        cr_assert_eq(rejected_b, !inside, "point (%.17g, %.17g): brute force says %s; %s", px,
                     py, inside ? "inside" : "outside", R.err.msg);
        memset(&R.err, 0, sizeof R.err);
        checked++;
    }
#undef RND
    cr_assert_gt(checked, 2500);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- islands (weighted skeletons of polygons with holes) ---- */

/* tests/data/holes/weighted_islands.wpoly: edge 14 (weight 3) sweeps round
** holes 2 and 4, whose faces are islands inside face 14.  The solved
** skeleton is valid (3 components, face 14 bridged to two loops); dropping an
** island's arc, or relabelling one, must be caught by the faces (e). */
Test(validate, islands_valid_and_broken_ones_caught) {
    wk_run R;
    wk_run_init(&R);
    char path[512];
    data_path(path, sizeof path, "holes/weighted_islands.wpoly");
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_read_file(&R, path, &P), WK_OK, "%s", R.err.msg);
    wk_skeleton *S = NULL;
    cr_assert_eq(wk_solve(&R, wk_variant_reference(), P, &S, NULL, NULL), WK_OK, "%s", R.err.msg);
    wk_validate_report rep;
    expect_valid(&R, P, S, &rep);
    wk_faces F;
    cr_assert_eq(wk_faces_build(&R, P, S, &F, ""), WK_OK, "%s", R.err.msg);
    cr_assert_not_null(F.bridge, "face 14 has islands: bridged");
    uint32_t bridges = 0;
    for (uint32_t e = 0; e < F.n; e++)
        for (uint32_t i = F.start[e]; i < F.start[e + 1]; i++) bridges += F.bridge[i];
    cr_assert_eq(bridges, 4, "two islands, two bridge sides each (got %u)", bridges);
    wk_faces_clear(&R, &F);
    /* an arc of the island around hole 2 (input vertices 16..19), removed */
    uint32_t victim = WK_NONE;
    for (uint32_t i = 0; i < S->n_arcs && victim == WK_NONE; i++)
        if (S->arcs[i].a >= 16 && S->arcs[i].a <= 19) victim = i;
    cr_assert_neq(victim, WK_NONE);
    wk_arc keep = S->arcs[victim];
    S->arcs[victim] = S->arcs[S->n_arcs - 1];
    S->n_arcs--;
    wk_status st = wk_validate(&R, P, S, 0, NULL);
    cr_assert_eq(st, WK_EINVALID, "a missing island arc passed: %s", R.err.msg);
    memset(&R.err, 0, sizeof R.err);
    S->n_arcs++;
    S->arcs[S->n_arcs - 1] = S->arcs[victim];
    S->arcs[victim] = keep;
    expect_valid(&R, P, S, &rep);
    /* the same arc with its faces swapped */
    S->arcs[victim].left = keep.right;
    S->arcs[victim].right = keep.left;
    expect_invalid(&R, P, S, 0, "validate", NULL);
    S->arcs[victim] = keep;
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}
