/*
** test_polygon.c: polygon construction, validation, orientation and the
** readers.
**
** Oracles: the bad-input corpus tests/data/bad with its EXPECTED table (the
** same table the CLI test reads), hand-made shapes with known reflex counts,
** a brute-force O(n^2) simplicity check built on the exact segment predicate
** for random small polygons full of degeneracies, and geometry for the
** clockwise case (the weight of the edge between two given points must not
** change when the polygon is reversed).  Every test owns its wk_run and ends
** with zero live bytes.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wskel.h"
#include "helpers.h"

static wk_status read_data(wk_run *R, const char *rel, wk_polygon **P) {
    char path[512];
    data_path(path, sizeof path, rel);
    return wk_polygon_read_file(R, path, P);
}

/* Builds from arrays and expects WK_EINPUT with `want` in the formatted
** message. */
static void expect_reject(uint32_t n, const double *x, const double *y, const double *w,
                          const long *lines, const char *want) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_from_arrays(&R, n, x, y, w, "t.wpoly", lines, &P);
    char msg[1024];
    err_text(&R, msg, sizeof msg);
    cr_assert_eq(st, WK_EINPUT, "expected rejection '%s', got status %d", want, st);
    cr_assert_null(P);
    cr_assert(strstr(msg, want), "message '%s' lacks '%s'", msg, want);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- good files ---- */

Test(polygon, read_square) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    cr_assert_eq(read_data(&R, "good/square.wpoly", &P), WK_OK);
    cr_assert_eq(P->n, 4);
    cr_assert_eq(P->r, 0);
    cr_assert_not(P->reversed);
    cr_assert_eq(wk_polygon_area(P), 1.0);
    cr_assert_float_eq(wk_polygon_scale(P), sqrt(2.0), 1e-15);
    for (uint32_t i = 0; i < 4; i++) {
        cr_assert_eq(P->w[i], 1.0);
        cr_assert_eq(P->input_index[i], i);
        cr_assert_eq(wk_polygon_input_edge(P, i), i);
        cr_assert_eq(wk_polygon_output_node(P, i), i);
    }
    cr_assert_eq(wk_polygon_output_node(P, 7), 7, "non-input nodes keep their id");
    cr_assert(strstr(P->name, "square.wpoly"));
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, read_comments_blank_lines_default_weights) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    cr_assert_eq(read_data(&R, "good/comments.wpoly", &P), WK_OK);
    cr_assert_eq(P->n, 5);
    cr_assert_eq(P->r, 1);
    cr_assert_not(P->reversed);
    const double w[5] = {1.5, 1, 0.25, 1, 2};
    for (uint32_t i = 0; i < 5; i++) cr_assert_eq(P->w[i], w[i], "w[%u] = %g", i, P->w[i]);
    cr_assert(wk_polygon_is_reflex(P, 3));
    cr_assert_eq(P->p[2].x, 4);
    cr_assert_eq(P->p[2].y, 3);
    wk_polygon_free(&R, P);

    cr_assert_eq(read_data(&R, "good/straight_vertex.wpoly", &P), WK_OK);
    cr_assert_eq(P->n, 4);
    cr_assert_eq(P->r, 0, "a 180-degree vertex is not reflex");
    cr_assert_not(wk_polygon_is_reflex(P, 1));
    wk_polygon_free(&R, P);

    cr_assert_eq(read_data(&R, "good/crlf_default_weights.wpoly", &P), WK_OK);
    cr_assert_eq(P->n, 4);
    cr_assert_eq(P->w[0], 2);
    cr_assert_eq(P->w[1], 1);
    cr_assert_eq(P->w[2], 0.5);
    cr_assert_eq(P->w[3], 1);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* The weight of the edge whose endpoints are a and b (either direction). */
static double weight_between(const wk_polygon *P, wk_point a, wk_point b) {
    for (uint32_t i = 0; i < P->n; i++) {
        wk_point p = P->p[i], q = P->p[(i + 1) % P->n];
        if ((p.x == a.x && p.y == a.y && q.x == b.x && q.y == b.y) ||
            (p.x == b.x && p.y == b.y && q.x == a.x && q.y == a.y))
            return P->w[i];
    }
    return -1;
}

Test(polygon, clockwise_is_reversed_keeping_weights_on_edges) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    cr_assert_eq(read_data(&R, "good/cw_weights.wpoly", &P), WK_OK);
    /* The file, in input order: vertex i and the weight of input edge i. */
    const double x[6] = {0, 0, 1, 1, 2, 2}, y[6] = {0, 2, 2, 1, 1, 0};
    const double w[6] = {1, 2, 3, 4, 5, 6};
    cr_assert(P->reversed);
    cr_assert_eq(P->n, 6);
    cr_assert_eq(P->r, 1, "an L-shape has one reflex vertex");
    cr_assert_gt(wk_polygon_area(P), 0);
    cr_assert_eq(wk_polygon_area(P), 3.0);
    for (uint32_t i = 0; i < 6; i++) {
        wk_point a = {x[i], y[i]}, b = {x[(i + 1) % 6], y[(i + 1) % 6]};
        cr_assert_eq(weight_between(P, a, b), w[i], "input edge %u keeps weight %g", i, w[i]);
    }
    for (uint32_t j = 0; j < 6; j++) {
        uint32_t iv = P->input_index[j];
        cr_assert_eq(iv, 5 - j);
        cr_assert_eq(P->p[j].x, x[iv]);
        cr_assert_eq(P->p[j].y, y[iv]);
        uint32_t ie = wk_polygon_input_edge(P, j);
        cr_assert_eq(P->w[j], w[ie], "stored edge %u is input edge %u", j, ie);
        cr_assert_eq(ie, (6 + 6 - 2 - j) % 6);
        /* The input edge's endpoints are the stored edge's, swapped. */
        cr_assert_eq(P->input_index[(j + 1) % 6], ie);
        cr_assert_eq(P->input_index[j], (ie + 1) % 6);
        cr_assert_eq(wk_polygon_output_node(P, j), iv);
    }
    /* The reflex vertex is input vertex 3, (1, 1). */
    for (uint32_t j = 0; j < 6; j++)
        cr_assert_eq(wk_polygon_is_reflex(P, j), P->input_index[j] == 3, "vertex %u", j);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, read_graphml_with_weights) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    cr_assert_eq(read_data(&R, "good/weighted.graphml", &P), WK_OK);
    /* Cycle from node a along its first edge: a(0,0) b(2,0) c(2,2) d(0,2). */
    const double x[4] = {0, 2, 2, 0}, y[4] = {0, 0, 2, 2}, w[4] = {1, 2, 3, 4};
    cr_assert_eq(P->n, 4);
    cr_assert_not(P->reversed);
    for (uint32_t i = 0; i < 4; i++) {
        cr_assert_eq(P->p[i].x, x[i]);
        cr_assert_eq(P->p[i].y, y[i]);
        cr_assert_eq(P->w[i], w[i]);
    }
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, read_graphml_without_weights) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    cr_assert_eq(read_data(&R, "good/unweighted.graphml", &P), WK_OK);
    cr_assert_eq(P->n, 4);
    cr_assert(P->reversed, "n0 (0,0) -> n1 (0,3) -> ... is clockwise");
    cr_assert_eq(wk_polygon_area(P), 9);
    for (uint32_t i = 0; i < 4; i++) cr_assert_eq(P->w[i], 1.0);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, graphml_from_memory_with_default_weight) {
    wk_run R;
    wk_run_init(&R);
    const char *doc =
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/>"
        "<key id='w' for='edge' attr.name='edge-weight'><default>2.5</default></key>"
        "<graph>"
        "<node id='p'><data key='x'>0</data><data key='y'>0</data></node>"
        "<node id='q'><data key='x'>1</data><data key='y'>0</data></node>"
        "<node id='r'><data key='x'>0</data><data key='y'>1</data></node>"
        "<edge source='r' target='p'/>"
        "<edge source='p' target='q'><data key='w'>7</data></edge>"
        "<edge source='q' target='r'/>"
        "</graph></graphml>";
    wk_polygon *P;
    cr_assert_eq(wk_polygon_read_graphml(&R, doc, strlen(doc), "mem", &P), WK_OK);
    /* p's first edge goes to r: p(0,0) r(0,1) q(1,0), clockwise, reversed
    ** to q r p... whatever the order, weights stay on their edges. */
    cr_assert(P->reversed);
    cr_assert_eq(weight_between(P, (wk_point){0, 0}, (wk_point){1, 0}), 7);
    cr_assert_eq(weight_between(P, (wk_point){1, 0}, (wk_point){0, 1}), 2.5);
    cr_assert_eq(weight_between(P, (wk_point){0, 1}, (wk_point){0, 0}), 2.5);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Values holding entity references are not single text nodes in the tree:
** the reader's copying path. */
Test(polygon, graphml_with_internal_entities) {
    wk_run R;
    wk_run_init(&R);
    const char *doc =
        "<?xml version='1.0'?>\n"
        "<!DOCTYPE graphml [<!ENTITY pre 'node-'> <!ENTITY two '2'>]>\n"
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/>\n"
        "<graph>\n"
        "<node id='&pre;a'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "<node id='&pre;b'><data key='x'>&two;</data><data key='y'>0</data></node>\n"
        "<node id='&pre;c'><data key='x'>0</data><data key='y'>1&two;</data></node>\n"
        "<edge source='node-a' target='&pre;b'/>\n"
        "<edge source='&pre;b' target='node-c'/>\n"
        "<edge source='&pre;c' target='&pre;a'/>\n"
        "</graph></graphml>\n";
    wk_polygon *P;
    wk_status st = wk_polygon_read_graphml(&R, doc, strlen(doc), "ent", &P);
    cr_assert_eq(st, WK_OK, "%s", R.err.msg);
    cr_assert_eq(P->n, 3);
    cr_assert_eq(P->p[1].x, 2);
    cr_assert_eq(P->p[2].y, 12);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, read_wpoly_from_stream_and_write_round_trip) {
    wk_run R;
    wk_run_init(&R);
    FILE *f = tmpfile();
    cr_assert_not_null(f);
    fputs("# cw triangle\n3\n0 0 2\n0.1 0.7 3\n0.3 0.2 0.5\n", f);
    rewind(f);
    wk_polygon *P, *Q;
    cr_assert_eq(wk_polygon_read_wpoly(&R, f, "stream", &P), WK_OK);
    fclose(f);
    cr_assert(P->reversed);
    f = tmpfile();
    cr_assert_eq(wk_polygon_write_wpoly(&R, f, P), WK_OK);
    rewind(f);
    cr_assert_eq(wk_polygon_read_wpoly(&R, f, "again", &Q), WK_OK);
    fclose(f);
    cr_assert_not(Q->reversed, "written counter-clockwise");
    cr_assert_eq(Q->n, P->n);
    for (uint32_t i = 0; i < P->n; i++) {
        cr_assert_eq(Q->p[i].x, P->p[i].x, "%%.17g round-trips");
        cr_assert_eq(Q->p[i].y, P->p[i].y);
        cr_assert_eq(Q->w[i], P->w[i]);
    }
    wk_polygon_free(&R, P);
    wk_polygon_free(&R, Q);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, read_stdin_and_byte_order_mark) {
    wk_run R;
    wk_run_init(&R);
    char path[512];
    data_path(path, sizeof path, "good/square.wpoly");
    /* Criterion runs each test in its own process, so stdin is ours. */
    cr_assert_not_null(freopen(path, "r", stdin));
    wk_polygon *P;
    cr_assert_eq(wk_polygon_read_file(&R, "-", &P), WK_OK);
    cr_assert_eq(P->n, 4);
    cr_assert_str_eq(P->name, "<stdin>");
    wk_polygon_free(&R, P);

    FILE *f = tmpfile();
    fputs("\xEF\xBB\xBF" "3\n0 0\n1 0\n0 1\n", f);
    rewind(f);
    cr_assert_eq(wk_polygon_read_wpoly(&R, f, "bom", &P), WK_OK);
    fclose(f);
    cr_assert_eq(P->n, 3);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, validate_existing_polygon) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    cr_assert_eq(read_data(&R, "good/comments.wpoly", &P), WK_OK);
    cr_assert_eq(wk_polygon_validate(&R, P), WK_OK);
    P->r = 3;
    cr_assert_eq(wk_polygon_validate(&R, P), WK_EINPUT);
    cr_assert(strstr(R.err.msg, "reflex count is 1, stored 3"), "%s", R.err.msg);
    P->r = 1;
    R.err.code = WK_OK;
    wk_point t = P->p[1]; /* swap two vertices: (4,0) and (4,3) make a bow tie */
    P->p[1] = P->p[2];
    P->p[2] = t;
    cr_assert_eq(wk_polygon_validate(&R, P), WK_EINPUT);
    cr_assert(strstr(R.err.msg, "crosses"), "%s", R.err.msg);
    R.err.code = WK_OK;
    P->p[2] = P->p[1];
    P->p[1] = t;
    for (uint32_t i = 0, j = P->n - 1; i < j; i++, j--) { /* reverse: clockwise */
        t = P->p[i];
        P->p[i] = P->p[j];
        P->p[j] = t;
    }
    cr_assert_eq(wk_polygon_validate(&R, P), WK_EINPUT);
    cr_assert(strstr(R.err.msg, "clockwise"), "%s", R.err.msg);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- the bad corpus ---- */

Test(polygon, bad_corpus_matches_expected) {
    char path[512], line[1024];
    data_path(path, sizeof path, "bad/EXPECTED");
    FILE *f = fopen(path, "r");
    cr_assert_not_null(f, "cannot open %s", path);
    int rows = 0;
    char listed[128][128];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (!line[0]) continue;
        char *name = line, *t1 = strchr(line, '\t');
        cr_assert_not_null(t1, "EXPECTED line '%s' has no tab", line);
        *t1 = '\0';
        char *code = t1 + 1, *t2 = strchr(code, '\t');
        cr_assert_not_null(t2);
        *t2 = '\0';
        const char *want = t2 + 1;
        cr_assert_lt(rows, 128);
        snprintf(listed[rows++], sizeof listed[0], "%.120s", name);

        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = NULL;
        char rel[256], msg[1024];
        snprintf(rel, sizeof rel, "bad/%.200s", name);
        wk_status st = read_data(&R, rel, &P);
        err_text(&R, msg, sizeof msg);
        cr_assert_neq(st, WK_OK, "%s was accepted", name);
        cr_assert_null(P);
        cr_assert_eq(wk_status_exit_code(st), atoi(code), "%s: exit code %d, want %s", name,
                     wk_status_exit_code(st), code);
        cr_assert(strstr(msg, want), "%s: message '%s' lacks '%s'", name, msg, want);
        ASSERT_CLEAN_CLOSE(R);
    }
    fclose(f);
    cr_assert_gt(rows, 20);
    /* Every file of the corpus is in the table. */
    data_path(path, sizeof path, "bad");
    DIR *d = opendir(path);
    cr_assert_not_null(d);
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.' || strcmp(e->d_name, "EXPECTED") == 0) continue;
        bool found = false;
        for (int i = 0; i < rows && !found; i++) found = strcmp(listed[i], e->d_name) == 0;
        cr_assert(found, "%s is not listed in EXPECTED", e->d_name);
    }
    closedir(d);
}

Test(polygon, missing_file) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_file(&R, "/nonexistent/dir/x.wpoly", &P);
    char msg[1024];
    err_text(&R, msg, sizeof msg);
    cr_assert_eq(st, WK_EINPUT);
    cr_assert_null(P);
    cr_assert(strstr(msg, "/nonexistent/dir/x.wpoly: cannot open: No such file"), "%s", msg);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, read_error_on_directory) {
    wk_run R;
    wk_run_init(&R);
    char path[512];
    data_path(path, sizeof path, "good");
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_file(&R, path, &P);
    cr_assert_eq(st, WK_EINPUT);
    cr_assert_null(P);
    cr_assert(strstr(R.err.msg, "read error") || strstr(R.err.msg, "cannot open"), "%s",
              R.err.msg);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- every rejection path through the array interface ---- */

Test(polygon, reject_counts) {
    const double x[3] = {0, 1, 0}, y[3] = {0, 0, 1};
    expect_reject(2, x, y, NULL, NULL, "t.wpoly: polygon needs at least 3 vertices (got 2)");
    expect_reject(0, x, y, NULL, NULL, "at least 3 vertices (got 0)");
    /* Refused before the arrays are read, so 3-element arrays are safe. */
    expect_reject(WK_POLYGON_MAX_N + 1, x, y, NULL, NULL, "too many vertices (50000001");
}

Test(polygon, reject_values) {
    const long lines[4] = {10, 11, 12, 13};
    double x[4] = {0, 1, 1, 0}, y[4] = {0, 0, 1, 1}, w[4] = {1, 1, 1, 1};
    x[2] = NAN;
    expect_reject(4, x, y, NULL, lines, "t.wpoly:12: vertex 2 has a coordinate that is not a finite number");
    x[2] = 1;
    y[3] = -INFINITY;
    expect_reject(4, x, y, NULL, NULL, "t.wpoly: vertex 3 has a coordinate that is not a finite");
    y[3] = 1;
    x[1] = 2e150;
    expect_reject(4, x, y, NULL, lines, "t.wpoly:11: vertex 1: coordinate too large");
    x[1] = 1;
    w[2] = 0;
    expect_reject(4, x, y, w, lines, "t.wpoly:12: weight of edge 2 must be > 0 (got 0)");
    w[2] = -1;
    expect_reject(4, x, y, w, NULL, "weight of edge 2 must be > 0 (got -1)");
    w[2] = 1;
    w[0] = NAN;
    expect_reject(4, x, y, w, lines, "t.wpoly:10: weight of edge 0 is not a finite number");
    w[0] = INFINITY;
    expect_reject(4, x, y, w, lines, "weight of edge 0 is not a finite number (got inf)");
}

Test(polygon, reject_repeated_vertices) {
    const long lines[5] = {3, 4, 5, 6, 7};
    const double x[5] = {0, 1, 1, 1, 0}, y[5] = {0, 0, 0, 1, 1};
    expect_reject(5, x, y, NULL, lines, "t.wpoly:5: vertex 2 repeats vertex 1 (zero-length edge 1)");
    const double cx[5] = {0, 1, 1, 0, 0}, cy[5] = {0, 0, 1, 1, 0};
    expect_reject(5, cx, cy, NULL, lines, "t.wpoly:7: the last vertex (4) repeats the first");
    expect_reject(5, cx, cy, NULL, NULL, "do not repeat vertex 0");
    /* -0.0 and 0.0 are the same point. */
    const double zx[5] = {0, 1, 1, 0, -0.0}, zy[5] = {0, 0, 1, 1, -0.0};
    expect_reject(5, zx, zy, NULL, NULL, "repeats the first");
    /* Non-consecutive: two triangles sharing a vertex. */
    const double tx[6] = {0, 1, 2, 2, 1, 0}, ty[6] = {0, 1, 0, 2, 1, 2};
    expect_reject(6, tx, ty, NULL, NULL, "vertex 1 coincides with vertex 4");
}

Test(polygon, reject_degenerate_shapes) {
    const double x[4] = {0, 1, 2, 3}, y[4] = {0, 1, 2, 3};
    expect_reject(4, x, y, NULL, NULL, "polygon has zero area (all 4 vertices are collinear)");
    const double lx[3] = {0, 2, 1}, ly[3] = {0, 0, 0};
    expect_reject(3, lx, ly, NULL, NULL, "zero area");
    /* Products that underflow to zero: outside the predicates' domain, and
    ** rejected rather than mis-oriented. */
    const double ux[3] = {0, 1e-170, 0}, uy[3] = {0, 0, 1e-170};
    expect_reject(3, ux, uy, NULL, NULL, "area");
    /* 0-degree spike: edge 2 goes back along edge 1. */
    const long lines[5] = {2, 3, 4, 5, 6};
    const double sx[5] = {0, 2, 4, 3, 0}, sy[5] = {0, 0, 0, 0, 3};
    expect_reject(5, sx, sy, NULL, lines,
                  "t.wpoly:4: edge 1 (line 3) and edge 2 (line 4) fold back on each other at "
                  "vertex 2 (0-degree spike)");
    /* A spike at vertex 0 across the wrap-around. */
    const double wx[4] = {0, 3, 3, 2}, wy[4] = {0, 0, 3, 0};
    expect_reject(4, wx, wy, NULL, NULL, "edge 3 and edge 0 fold back on each other at vertex 0");
    /* A spike along a vertical edge. */
    const double vx[4] = {0, 0, 0, -2}, vy[4] = {0, 3, 1, 1};
    expect_reject(4, vx, vy, NULL, NULL, "edge 0 and edge 1 fold back on each other at vertex 1");
}

Test(polygon, reject_intersections) {
    const long lines[8] = {3, 4, 5, 6, 7, 8, 9, 10};
    /* Bow tie. */
    const double bx[4] = {0, 1, 1, 0}, by[4] = {0, 1, 0, 1};
    expect_reject(4, bx, by, NULL, lines, "t.wpoly:3: edge 0 (line 3) crosses edge 2 (line 5)");
    expect_reject(4, bx, by, NULL, NULL, "t.wpoly: edge 0 crosses edge 2");
    /* Vertex 3 on edge 0. */
    const double vx[6] = {0, 4, 4, 2, 1, 0}, vy[6] = {0, 0, 2, 0, 2, 2};
    expect_reject(6, vx, vy, NULL, lines, "touches edge 0 (line 3): vertex 3 (line 6) lies on it");
    /* A vertex on a vertical edge, reached from the right. */
    const double wx[7] = {0, 4, 4, 0, 4, 4, 0}, wy[7] = {0, 0, 1, 2, 3, 4, 4};
    expect_reject(7, wx, wy, NULL, NULL, "touches edge 6: vertex 3 lies on it");
    /* Overlapping collinear edges. */
    const double ox[8] = {0, 4, 4, 3, 3, 1, 1, 0}, oy[8] = {0, 0, 2, 2, 0, 0, 2, 2};
    expect_reject(8, ox, oy, NULL, lines, "edge 0 (line 3) overlaps edge 4 (line 7) (collinear)");
    /* Collinear overlap of two vertical edges. */
    const double px[8] = {0, 2, 2, 0, 0, -2, -2, 0}, py[8] = {0, 0, 4, 4, 1, 1, 3, 3};
    expect_reject(8, px, py, NULL, NULL, "edge 3 overlaps edge 7 (collinear)");
    /* Vertex 2 one ulp below the line y = x: edge 2 rises through edge 0. */
    const double u = 0x1p-52;
    const double ex[5] = {0, 1, 0.5, 0.5, -1}, ey[5] = {0, 1, 0.5 - u, 2, 2};
    expect_reject(5, ex, ey, NULL, NULL, "crosses");
}

/* The same shape with vertex 2 one ulp above the line y = x is simple. */
Test(polygon, accept_near_degenerate_valid) {
    wk_run R;
    wk_run_init(&R);
    const double u = 0x1p-52;
    const double x[5] = {0, 1, 0.5, 0.5, -1}, y[5] = {0, 1, 0.5 + u, 2, 2};
    wk_polygon *P = polygon(&R, 5, x, y, NULL);
    cr_assert_eq(P->n, 5);
    cr_assert(wk_polygon_is_reflex(P, 2));
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Collinear but disjoint non-adjacent edges are fine: a 2x4 rectangle with
** a 2x2 one attached on its left; edges 3 and 7 lie on x = 0 apart. */
Test(polygon, accept_collinear_disjoint_edges) {
    wk_run R;
    wk_run_init(&R);
    const double x[8] = {0, 2, 2, 0, 0, -2, -2, 0}, y[8] = {0, 0, 4, 4, 3, 3, 1, 1};
    wk_polygon *P = polygon(&R, 8, x, y, NULL);
    cr_assert_eq(P->r, 2);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- reflex counts ---- */

Test(polygon, reflex_counts_of_known_shapes) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    /* Square, ccw and cw. */
    const double sx[4] = {0, 1, 1, 0}, sy[4] = {0, 0, 1, 1};
    P = polygon(&R, 4, sx, sy, NULL);
    cr_assert_eq(P->r, 0);
    wk_polygon_free(&R, P);
    const double cx[4] = {0, 0, 1, 1}, cy[4] = {0, 1, 1, 0};
    P = polygon(&R, 4, cx, cy, NULL);
    cr_assert_eq(P->r, 0);
    cr_assert(P->reversed);
    wk_polygon_free(&R, P);
    /* Straight-on vertices (180 degrees) are valid and not reflex. */
    const double tx[6] = {0, 1, 2, 2, 1, 0}, ty[6] = {0, 0, 0, 1, 1, 1};
    P = polygon(&R, 6, tx, ty, NULL);
    cr_assert_eq(P->r, 0);
    cr_assert_not(wk_polygon_is_reflex(P, 1));
    cr_assert_not(wk_polygon_is_reflex(P, 4));
    wk_polygon_free(&R, P);
    /* A comb with k teeth has k - 1 notches, each with 2 reflex vertices. */
    for (uint32_t k = 2; k <= 6; k++) {
        double x[64], y[64];
        uint32_t n = 0;
        x[n] = 0, y[n++] = 0;
        x[n] = 2 * k - 1, y[n++] = 0;
        for (uint32_t t = k; t-- > 0;) {
            /* tooth t spans x in [2t, 2t+1], top at y = 3; notch at y = 1 */
            x[n] = 2 * t + 1, y[n++] = 3;
            x[n] = 2 * t, y[n++] = 3;
            if (t > 0) x[n] = 2 * t, y[n++] = 1, x[n] = 2 * t - 1, y[n++] = 1;
        }
        P = polygon(&R, n, x, y, NULL);
        cr_assert_eq(P->r, 2 * (k - 1), "comb %u: r = %u", k, P->r);
        cr_assert_not(P->reversed);
        wk_polygon_free(&R, P);
    }
    /* Stars: k points have k reflex vertices, also when given clockwise. */
    for (uint32_t k = 3; k <= 9; k++) {
        double x[32], y[32];
        for (uint32_t i = 0; i < 2 * k; i++) {
            double a = PI * i / k, rad = i % 2 ? 0.4 : 1.0;
            x[i] = rad * cos(a);
            y[i] = rad * sin(a);
        }
        P = polygon(&R, 2 * k, x, y, NULL);
        cr_assert_eq(P->r, k);
        wk_polygon_free(&R, P);
        for (uint32_t i = 0; i < 2 * k; i++) y[i] = -y[i]; /* mirrored: clockwise */
        P = polygon(&R, 2 * k, x, y, NULL);
        cr_assert(P->reversed);
        cr_assert_eq(P->r, k);
        wk_polygon_free(&R, P);
    }
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- brute force against the sweep ---- */

static bool brute_simple(uint32_t n, const wk_point *p) {
    for (uint32_t i = 0; i < n; i++) {
        wk_point a = p[i], b = p[(i + 1) % n];
        if (a.x == b.x && a.y == b.y) return false;
    }
    uint32_t k = 2;
    while (k < n && wk_orient2d(p[0], p[1], p[k], NULL) == 0) k++;
    if (k == n) return false;
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t j = i + 1; j < n; j++) {
            wk_seg_meet m = wk_segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]);
            bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if (adjacent ? m == WK_SEG_OVERLAP : m != WK_SEG_DISJOINT) return false;
        }
    return true;
}

static uint64_t rng_next(uint64_t *s) {
    uint64_t z = (*s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

Test(polygon, sweep_agrees_with_brute_force) {
    wk_run R;
    wk_run_init(&R);
    uint64_t s = 2024;
    int accepted = 0, total = 30000;
    for (int trial = 0; trial < total; trial++) {
        uint32_t n = 3 + (uint32_t)(rng_next(&s) % 10);
        double x[16], y[16];
        wk_point p[16];
        int mode = trial % 3;
        for (uint32_t i = 0; i < n; i++) {
            if (mode == 0) { /* any points on a 5x5 grid: mostly invalid */
                x[i] = (double)(rng_next(&s) % 5);
                y[i] = (double)(rng_next(&s) % 5);
            } else { /* radially sorted around a centre: often valid, with
                        collinear and coinciding points from the grid */
                double a = 2 * PI * (i + (rng_next(&s) % 100) / 100.0) / n;
                double r = 1 + (double)(rng_next(&s) % 4);
                x[i] = round(r * cos(a) * (mode == 1 ? 1 : 3)) / (mode == 1 ? 1 : 3);
                y[i] = round(r * sin(a) * (mode == 1 ? 1 : 3)) / (mode == 1 ? 1 : 3);
            }
            p[i] = (wk_point){x[i], y[i]};
        }
        bool want = brute_simple(n, p);
        wk_polygon *P = NULL;
        wk_status st = wk_polygon_from_arrays(&R, n, x, y, NULL, "r", NULL, &P);
        char msg[1024];
        err_text(&R, msg, sizeof msg);
        cr_assert_eq(st == WK_OK, want, "trial %d (n=%u): sweep %s (%s), brute force %s", trial,
                     n, st == WK_OK ? "accepts" : "rejects", msg, want ? "accepts" : "rejects");
        if (st == WK_OK) {
            accepted++;
            cr_assert_gt(wk_polygon_area(P), 0);
            wk_polygon_free(&R, P);
        }
        R.err.code = WK_OK; /* reuse the run: clear the recorded failure */
    }
    cr_assert(accepted > total / 10 && accepted < total * 9 / 10, "accepted %d of %d", accepted,
              total);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- scale ---- */

static void star(uint32_t n, double *x, double *y) {
    for (uint32_t i = 0; i < n; i++) {
        double a = 2 * PI * i / n, r = i % 2 ? 0.5 : 1.0;
        x[i] = r * cos(a);
        y[i] = r * sin(a);
    }
}

Test(polygon, million_vertex_star_validates) {
    wk_run R;
    wk_run_init(&R);
    const uint32_t n = 1000000;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    cr_assert(x && y);
    star(n, x, y);
    wk_polygon *P = polygon(&R, n, x, y, NULL);
    cr_assert_eq(P->r, n / 2);
    wk_polygon_free(&R, P);
    /* One outer vertex thrown across the centre, twice as far out: its two
    ** edges cross the spikes on the other side. */
    const uint32_t k = 333334;
    x[k] = -2 * x[k];
    y[k] = -2 * y[k];
    wk_status st = wk_polygon_from_arrays(&R, n, x, y, NULL, "big", NULL, &P);
    char msg[1024];
    err_text(&R, msg, sizeof msg);
    cr_assert_eq(st, WK_EINPUT);
    cr_assert(strstr(msg, "crosses") || strstr(msg, "touches"), "%s", msg);
    free(x);
    free(y);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- out of memory ---- */

/* Fails allocation N for N = 0, 1, 2, ... until the operation succeeds:
** every failing run must report WK_ENOMEM and leave no live bytes. */
static void fault_loop(const char *what, wk_status (*op)(wk_run *R, wk_polygon **P)) {
    for (int64_t n = 0;; n++) {
        cr_assert_lt(n, 10000, "%s never succeeded", what);
        wk_run R;
        wk_run_init(&R);
        R.alloc.fail_after = n;
        wk_polygon *P = NULL;
        wk_status st = op(&R, &P);
        if (st == WK_OK) {
            cr_assert_not_null(P);
            cr_assert_gt(n, 1, "%s: the loop must fail at least once", what);
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
            return;
        }
        cr_assert_eq(st, WK_ENOMEM, "%s, fail_after %lld: status %d (%s)", what, (long long)n,
                     st, R.err.msg);
        cr_assert_eq(R.err.code, WK_ENOMEM);
        cr_assert_null(P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

static wk_status op_wpoly(wk_run *R, wk_polygon **P) {
    return read_data(R, "good/cw_weights.wpoly", P);
}
static wk_status op_graphml(wk_run *R, wk_polygon **P) {
    return read_data(R, "good/weighted.graphml", P);
}
static wk_status op_arrays(wk_run *R, wk_polygon **P) {
    double x[50], y[50];
    star(50, x, y);
    return wk_polygon_from_arrays(R, 50, x, y, NULL, "star", NULL, P);
}

Test(polygon, fault_injection_wpoly) { fault_loop("wpoly", op_wpoly); }
Test(polygon, fault_injection_graphml) { fault_loop("graphml", op_graphml); }
Test(polygon, fault_injection_arrays) { fault_loop("arrays", op_arrays); }
