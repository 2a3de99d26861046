/*
** test_same_skeleton.c: the skeleton comparison the sweeps and the variants
** fuzz target share (tests/same_skeleton.h), on hand-made skeletons of the
** unit square: merging of nodes within the tolerance, zero-length arcs, and
** the weight-aware time tolerance (sk_match.P: tol_t over the weight of a
** node's faces; with weight 0.01 a position error of d is a time error of
** 100 d).
*/
#include <criterion/criterion.h>
#include <math.h>

#include "wskel.h"
#include "helpers.h"

static const double W_SMALL[4] = {0.01, 0.01, 0.01, 0.01};

/* The square with weights w: its one node at the centre, t = 0.5 / w. */
static wk_skeleton *centre_at(wk_run *R, const wk_polygon *P, double dx, double t) {
    wk_node c = {0.5 + dx, 0.5, t};
    return skeleton(R, P, 1, &c, 4, SQ_ARCS);
}

Test(same_skeleton, time_tolerance_scales_with_the_weight) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, W_SMALL);
    double tol = 1e-7, d = tol / 2;
    wk_skeleton *A = centre_at(&R, P, 0, 50);
    /* moved by d along x: its time moves by d / w = 50 tol */
    wk_skeleton *B = centre_at(&R, P, d, 50 + d / 0.01);
    /* ... and by 2 tol / w: beyond what a position within tol explains */
    wk_skeleton *C = centre_at(&R, P, d, 50 + 2 * tol / 0.01);
    char why[512] = "";
    sk_match weighted = {.tol = tol, .tol_t = tol, .merge = true, .P = P};
    sk_match plain = {.tol = tol, .tol_t = tol, .merge = true};
    cr_expect(same_skeleton(A, B, weighted, why, sizeof why), "weighted: %s", why);
    cr_expect_not(same_skeleton(A, B, plain, why, sizeof why),
                  "without the weights a time 50 tol apart must not match");
    cr_expect_not(same_skeleton(A, C, weighted, why, sizeof why),
                  "a time 2 tol / w apart must not match");
    wk_skeleton_free(&R, A);
    wk_skeleton_free(&R, B);
    wk_skeleton_free(&R, C);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(same_skeleton, zero_length_arc_merged_with_weights) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, W_SMALL);
    double tol = 1e-7, d = tol / 2;
    wk_skeleton *A = centre_at(&R, P, 0, 50);
    /* B: the centre as two nodes d apart joined by a zero-length arc, the
    ** second one's time d / w later */
    const wk_node two[2] = {{0.5, 0.5, 50}, {0.5 + d, 0.5, 50 + d / 0.01}};
    const arc4 arcs[5] = {{0, 4, 3, 0}, {1, 5, 0, 1}, {2, 5, 1, 2}, {3, 4, 2, 3}, {4, 5, 0, 2}};
    wk_skeleton *B = skeleton(&R, P, 2, two, 5, arcs);
    char why[512] = "";
    sk_match weighted = {.tol = tol, .tol_t = tol, .merge = true, .P = P};
    sk_match plain = {.tol = tol, .tol_t = tol, .merge = true};
    cr_expect(same_skeleton(A, B, weighted, why, sizeof why), "weighted: %s", why);
    /* without the weights the two nodes stay apart: B keeps an extra arc */
    cr_expect_not(same_skeleton(A, B, plain, why, sizeof why), "unweighted must differ");
    /* a real difference: an arc with other faces */
    const arc4 wrong[5] = {{0, 4, 3, 0}, {1, 5, 0, 1}, {2, 5, 1, 2}, {3, 4, 2, 3}, {4, 5, 1, 3}};
    const wk_node apart[2] = {{0.4, 0.5, 40}, {0.6, 0.5, 40}};
    wk_skeleton *C = skeleton(&R, P, 2, apart, 5, wrong);
    cr_expect_not(same_skeleton(A, C, weighted, why, sizeof why), "an extra arc must differ");
    wk_skeleton_free(&R, A);
    wk_skeleton_free(&R, B);
    wk_skeleton_free(&R, C);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}
