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
    ** rejected rather than mis-oriented (the input domain's bound on
    ** coordinates); a polygon of size 1e-150 is inside it and accepted. */
    const double ux[3] = {0, 1e-170, 0}, uy[3] = {0, 0, 1e-170};
    expect_reject(3, ux, uy, NULL, NULL, "coordinate too small (1e-170, 0)");
    const double sub[3] = {0, 4.9e-324, 0}, subf[3] = {0, 0, 1};
    expect_reject(3, sub, subf, NULL, NULL, "coordinates must have magnitude at least 1e-150");
    const double tx[3] = {1e-150, 3e-150, 1e-150}, ty[3] = {1e-150, 1e-150, 3e-150};
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_from_arrays(&R, 3, tx, ty, NULL, "t", NULL, &P), WK_OK, "%s",
                 R.err.msg);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
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
    /* vertex 2 is one ulp off the line through its neighbours: simple, and
    ** reflex (exact predicates) */
    const double x[5] = {0, 1, 0.5, 0.5, -1}, y[5] = {0, 0.25, 0.5 + u, 2, 2};
    wk_polygon *P = polygon(&R, 5, x, y, NULL);
    cr_assert_eq(P->n, 5);
    cr_assert(wk_polygon_is_reflex(P, 2));
    wk_polygon_free(&R, P);
    /* with vertex 1 at (1, 1) it is a needle (its edges antiparallel to a
    ** sine of 2.8e-16): still simple, but outside the input domain, and the
    ** message names the vertex and the bound */
    const double y2[5] = {0, 1, 0.5 + u, 2, 2};
    cr_assert_eq(wk_polygon_from_arrays(&R, 5, x, y2, NULL, "t.wpoly", NULL, &P), WK_EINPUT);
    cr_assert_null(P);
    cr_assert(strstr(R.err.msg, "vertex 1 is a needle") && strstr(R.err.msg, "1e-12"), "%s",
              R.err.msg);
    ASSERT_CLEAN_CLOSE(R);
}

/* The width bound (WK_POLYGON_MIN_WIDTH_REL, tolerance.h): a 1 x h strip
** (A = h, P = 2 (1 + h), no reflex vertex) is refused when h < 2c(1 + h),
** c = 1e-9 times its diagonal, i.e. below h = 2e-9; the bound does not
** depend on the orientation or on a translation, and wk_polygon_validate
** applies it to a stored polygon. */
Test(polygon, width_bound_refuses_a_strip_below_the_tolerance) {
    cr_assert_eq(WK_POLYGON_MIN_WIDTH_REL, 1e-9);
    for (int k = 0; k < 4; k++) {
        double h = k & 1 ? 2.1e-9 : 1.9e-9, dx = k & 2 ? 1e3 : 0;
        const double x[4] = {dx, dx + 1, dx + 1, dx}, y[4] = {0, 0, h, h};
        const double xr[4] = {dx, dx, dx + 1, dx + 1}, yr[4] = {0, h, h, 0};
        for (int cw = 0; cw < 2; cw++) {
            wk_run R;
            wk_run_init(&R);
            wk_polygon *P = NULL;
            wk_status st = wk_polygon_from_arrays(&R, 4, cw ? xr : x, cw ? yr : y, NULL, "t.wpoly",
                                                  NULL, &P);
            if (k & 1) {
                cr_assert_eq(st, WK_OK, "h %g: %s", h, R.err.msg);
                wk_polygon_free(&R, P);
            } else {
                cr_assert_eq(st, WK_EINPUT, "h %g accepted", h);
                cr_assert_null(P);
                cr_assert(strstr(R.err.msg, "polygon thinner than the tolerance") &&
                              strstr(R.err.msg, "mean width 2A/P = 1.9e-09 diagonals") &&
                              strstr(R.err.msg, "WK_POLYGON_MIN_WIDTH_REL") &&
                              strstr(R.err.msg, "input domain"),
                          "%s", R.err.msg);
            }
            ASSERT_CLEAN_CLOSE(R);
        }
    }
    wk_run R;
    wk_run_init(&R);
    const double x[4] = {0, 1, 1, 0}, y[4] = {0, 0, 1e-8, 1e-8};
    wk_polygon *P = polygon(&R, 4, x, y, NULL);
    cr_assert_eq(wk_polygon_validate(&R, P), WK_OK);
    P->p[2].y = P->p[3].y = 1.9e-9;
    cr_assert_eq(wk_polygon_validate(&R, P), WK_EINPUT);
    cr_assert(strstr(R.err.msg, "polygon thinner than the tolerance"), "%s", R.err.msg);
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
        /* a simple polygon with a needle vertex is outside the input domain
        ** (a separate check, after simplicity): it counts as simple here */
        bool simple = st == WK_OK || (st == WK_EINPUT && strstr(msg, "is a needle"));
        cr_assert_eq(simple, want, "trial %d (n=%u): sweep %s (%s), brute force %s", trial, n,
                     simple ? "accepts" : "rejects", msg, want ? "accepts" : "rejects");
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

/* ---- the readers: bytes (issue 11) ---- */

/* Reads the .wpoly text s[0..len) through wk_polygon_read_wpoly (a stream,
** so NUL bytes reach the reader) or, with graphml, the GraphML reader. */
static wk_status read_mem(wk_run *R, const char *s, size_t len, bool graphml, wk_polygon **P) {
    if (graphml) return wk_polygon_read_graphml(R, s, len, "mem", P);
    FILE *f = tmpfile();
    cr_assert_not_null(f);
    cr_assert_eq(fwrite(s, 1, len, f), len);
    rewind(f);
    wk_status st = wk_polygon_read_wpoly(R, f, "mem", P);
    fclose(f);
    return st;
}

/* The text is refused with `want` in the message, no polygon, no leak. */
static void expect_mem_reject(const char *s, size_t len, bool graphml, const char *want) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    wk_status st = read_mem(&R, s, len, graphml, &P);
    char msg[1024];
    err_text(&R, msg, sizeof msg);
    cr_assert_eq(st, WK_EINPUT, "expected '%s', got status %d (%s)", want, st, msg);
    cr_assert_null(P);
    cr_assert(strstr(msg, want), "message '%s' lacks '%s'", msg, want);
    ASSERT_CLEAN_CLOSE(R);
}

/* The text is read as the unit square 0 0 / 1 0 / 1 1 / 0 1 with weights w. */
static void expect_mem_square(const char *s, size_t len, bool graphml, const double *w) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    wk_status st = read_mem(&R, s, len, graphml, &P);
    char msg[1024];
    err_text(&R, msg, sizeof msg);
    cr_assert_eq(st, WK_OK, "refused: %s", msg);
    cr_assert_eq(P->n, 4);
    for (uint32_t i = 0; i < 4; i++) {
        cr_assert_eq(P->p[i].x, SQ_X[i], "x[%u] = %.17g", i, P->p[i].x);
        cr_assert_eq(P->p[i].y, SQ_Y[i], "y[%u] = %.17g", i, P->p[i].y);
        cr_assert_eq(P->w[i], w ? w[i] : 1.0, "w[%u] = %.17g", i, P->w[i]);
    }
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

#define MEM(s) (s), sizeof(s) - 1

Test(polygon, wpoly_nul_inside_a_number_is_refused) {
    /* Once read as 0.70: strtod stopped at the NUL. */
    expect_mem_reject(MEM("4\n0 0\n1 0\n0.70\0\0\071067811865475 0.70\n0 1\n"), false,
                      "mem:4: column 5: NUL byte");
    expect_mem_reject(MEM("# a NUL\0 in a comment\n4\n0 0\n1 0\n1 1\n0 1\n"), false,
                      "mem:1: column 8: NUL byte");
    expect_mem_reject(MEM("4\n0 0\n1 0\n1 1\n0 1\n\0"), false, "mem:6: column 1: NUL byte");
    expect_mem_reject(MEM("\0"), false, "mem:1: column 1: NUL byte");
    expect_mem_reject(MEM("4\0\n0 0\n1 0\n1 1\n0 1\n"), false, "mem:1: column 2: NUL byte");
}

Test(polygon, wpoly_every_control_byte_is_refused) {
    char buf[64], want[64];
    for (int b = 0; b < 0x80; b++) {
        if ((b >= 0x20 && b < 0x7F) || b == '\t' || b == '\n') continue;
        /* In a data line, and in a comment. */
        int len = snprintf(buf, sizeof buf, "4\n0 0\n1 0\n1X1\n0 1\n");
        buf[11] = (char)b;
        if (b == 0)
            snprintf(want, sizeof want, "mem:4: column 2: NUL byte");
        else if (b == '\r')
            snprintf(want, sizeof want, "mem:4: column 2: carriage return (0x0D) not followed");
        else
            snprintf(want, sizeof want, "mem:4: column 2: control character 0x%02X", b);
        expect_mem_reject(buf, (size_t)len, false, want);
        len = snprintf(buf, sizeof buf, "#Xc\n4\n0 0\n1 0\n1 1\n0 1\n");
        buf[1] = (char)b;
        want[4] = '1';
        expect_mem_reject(buf, (size_t)len, false, want);
    }
}

Test(polygon, wpoly_non_ascii_refused_outside_comments_only) {
    char buf[64];
    for (int b = 0x80; b < 0x100; b++) {
        int len = snprintf(buf, sizeof buf, "4\n0 0\n1 0\n1 1\n0 1X\n");
        buf[len - 2] = (char)b;
        expect_mem_reject(buf, (size_t)len, false, "mem:5: column 4: byte 0x");
        /* Any byte >= 0x80 in a comment, UTF-8 or not. */
        len = snprintf(buf, sizeof buf, "# cXX\n4\n0 0\n1 0\n1 1\n0 1\n");
        buf[3] = (char)b;
        buf[4] = (char)(0x80 | (b & 0x3F));
        expect_mem_square(buf, (size_t)len, false, NULL);
    }
    expect_mem_reject(MEM("4\n0 0\n1 0\n1 1\n0 \xe2\x88\x92" "1\n"), false,
                      "mem:5: column 3: non-ASCII character U+2212");
    expect_mem_reject(MEM("4\n0 0\n1\xc2\xa0" "0\n1 1\n0 1\n"), false,
                      "mem:3: column 2: non-ASCII character U+00A0");
    expect_mem_reject(MEM("4\n0 0\n1 0\n1 1\n0 1\xc2\x85\n"), false,
                      "mem:5: column 4: control character U+0085");
    /* A byte order mark is allowed at the start only. */
    expect_mem_reject(MEM("4\n\xEF\xBB\xBF" "0 0\n1 0\n1 1\n0 1\n"), false,
                      "mem:2: column 1: non-ASCII character U+FEFF");
    expect_mem_reject(MEM("\xFF\xFE" "4\0\n\0"), false, "mem:1: column 1: UTF-16 byte order mark");
}

Test(polygon, wpoly_bytes_accepted) {
    const double w[4] = {2, 1, 0.5, 1};
    /* UTF-8 and Latin-1 comments, tabs, CRLF, a byte order mark, a CR ending
    ** the last line without LF. */
    expect_mem_square(MEM("\xEF\xBB\xBF# caf\xc3\xa9 \xe2\x86\x92 na\xefve\r\n4\r\n\t0 0 2\r\n"
                          "1\t0\r\n# \xff\xfe\r\n1 1  0.5\t\r\n0 1\r"),
                      false, w);
    expect_mem_square(MEM("4\n0 0\n1 0\n1 1\n0 1"), false, NULL);
    expect_mem_reject(MEM("4\n0 0 1\n1 0 1;\n1 1\n0 1\n"), false, "mem:3: '1;' is not a finite");
    expect_mem_reject(MEM("4\n0 0\n1 0\n1 1\r\r\n0 1\n"), false,
                      "mem:4: column 4: carriage return (0x0D) not followed by a line feed");
}

/* A GraphML square with TEXT spliced in as node c's x coordinate. */
static size_t graphml_with(char *buf, size_t size, const char *head, const char *text,
                           size_t text_len) {
    const char *pre =
        "<graphml>\n<key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/>\n<graph>\n"
        "<node id='a'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "<node id='b'><data key='x'>1</data><data key='y'>0</data></node>\n"
        "<node id='c'><data key='x'>";
    const char *post =
        "</data><data key='y'>1</data></node>\n"
        "<node id='d'><data key='x'>0</data><data key='y'>1</data></node>\n"
        "<edge source='a' target='b'/><edge source='b' target='c'/>\n"
        "<edge source='c' target='d'/><edge source='d' target='a'/>\n</graph></graphml>\n";
    size_t n = 0;
    const char *part[4] = {head, pre, text, post};
    size_t len[4] = {strlen(head), strlen(pre), text_len, strlen(post)};
    for (int i = 0; i < 4; i++) {
        cr_assert_lt(n + len[i], size);
        memcpy(buf + n, part[i], len[i]);
        n += len[i];
    }
    return n;
}

Test(polygon, graphml_bytes) {
    char buf[2048], want[80];
    size_t n = graphml_with(buf, sizeof buf, "", MEM("1"));
    expect_mem_square(buf, n, true, NULL);
    n = graphml_with(buf, sizeof buf, "<?xml version='1.0' encoding='utf-8'?>\n", MEM(" 1\t"));
    expect_mem_square(buf, n, true, NULL);
    n = graphml_with(buf, sizeof buf, "<?xml version='1.0' encoding='US-ASCII'?>\n", MEM("1"));
    expect_mem_square(buf, n, true, NULL);
    n = graphml_with(buf, sizeof buf, "\xEF\xBB\xBF<!-- caf\xc3\xa9 \xf0\x9f\x97\xba -->\n",
                     MEM("1"));
    expect_mem_square(buf, n, true, NULL);
    /* Line 7 of the document, column 28 is the x of node c. */
    for (int b = 0; b < 0x100; b++) {
        if ((b >= 0x20 && b < 0x7F) || b == '\t' || b == '\n' || b == '\r') continue;
        char t[2] = {'1', (char)b};
        n = graphml_with(buf, sizeof buf, "", t, 2);
        if (b == 0)
            snprintf(want, sizeof want, "mem:7: column 29: NUL byte");
        else if (b < 0x80)
            snprintf(want, sizeof want, "mem:7: column 29: control character 0x%02X", b);
        else
            snprintf(want, sizeof want, "mem:7: column 29: byte 0x%02X is not UTF-8", b);
        expect_mem_reject(buf, n, true, want);
    }
    n = graphml_with(buf, sizeof buf, "", MEM("1\xc2\x9f"));
    expect_mem_reject(buf, n, true, "mem:7: column 29: control character U+009F");
    n = graphml_with(buf, sizeof buf, "", MEM("1\xed\xa0\x80")); /* a surrogate */
    expect_mem_reject(buf, n, true, "mem:7: column 29: byte 0xED is not UTF-8");
    n = graphml_with(buf, sizeof buf, "", MEM("1\xe0\x80\xaf")); /* overlong */
    expect_mem_reject(buf, n, true, "mem:7: column 29: byte 0xE0 is not UTF-8");
    n = graphml_with(buf, sizeof buf, "", MEM("1\xf4\x90\x80\x80")); /* above U+10FFFF */
    expect_mem_reject(buf, n, true, "mem:7: column 29: byte 0xF4 is not UTF-8");
    n = graphml_with(buf, sizeof buf, "", MEM("1\xe2\x88")); /* truncated */
    expect_mem_reject(buf, n, true, "mem:7: column 29: byte 0xE2 is not UTF-8");
    /* Valid UTF-8 that is no number. */
    n = graphml_with(buf, sizeof buf, "", MEM("\xe2\x88\x92" "1"));
    expect_mem_reject(buf, n, true, "node 'c': vertex-coordinate-x '\xe2\x88\x92" "1' is not");
    n = graphml_with(buf, sizeof buf, "", MEM("1 2"));
    expect_mem_reject(buf, n, true, "node 'c': vertex-coordinate-x '1 2' is not a finite");
    n = graphml_with(buf, sizeof buf, "", MEM("1&#0;"));
    expect_mem_reject(buf, n, true, "mem:7: XML error");
    n = graphml_with(buf, sizeof buf, "<?xml version='1.0' encoding='ISO-8859-1'?>\n", MEM("1"));
    expect_mem_reject(buf, n, true, "mem:1: the document declares encoding 'ISO-8859-1'");
    /* The length is the document: a NUL byte inside it is refused, not an end. */
    n = graphml_with(buf, sizeof buf, "", MEM("1"));
    buf[n++] = '\0';
    expect_mem_reject(buf, n, true, "mem:12: column 1: NUL byte");
}

Test(polygon, graphml_ambiguous_documents) {
    char buf[2048];
    size_t n = graphml_with(buf, sizeof buf, "", MEM("1</data><data key='x'>2"));
    expect_mem_reject(buf, n, true, "mem:7: node 'c' has a second vertex-coordinate-x");
    const char *two_keys =
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='x2' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/>\n<graph>\n"
        "<node id='p'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "</graph></graphml>";
    expect_mem_reject(two_keys, strlen(two_keys), true,
                      "mem:2: a second <key> for attr.name=\"vertex-coordinate-x\" (the first on "
                      "line 1)");
    /* A key for edges only does not clash with one for nodes. */
    const char *edge_key =
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='x2' for='edge' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/>\n"
        "<key id='w' for='edge' attr.name='edge-weight'/>\n<graph>\n"
        "<node id='p'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "<node id='q'><data key='x'>1</data><data key='y'>0</data></node>\n"
        "<node id='r'><data key='x'>0</data><data key='y'>1</data></node>\n"
        "<edge source='p' target='q'><data key='w'>2</data><data key='w'>3</data></edge>\n"
        "<edge source='q' target='r'/><edge source='r' target='p'/>\n"
        "</graph></graphml>";
    expect_mem_reject(edge_key, strlen(edge_key), true,
                      "mem:9: edge 0 (from 'p' to 'q') has a second edge-weight");
}

/* Issue 11: a graph whose edges are not in it (no edge in <graph>: every
** edge array is empty) once leaked 24 tracked bytes on its error path. */
Test(polygon, graphml_without_edges_in_the_graph) {
    const char *nodes =
        "<node id='p'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "<node id='q'><data key='x'>1</data><data key='y'>0</data></node>\n"
        "<node id='r'><data key='x'>0</data><data key='y'>1</data></node>\n";
    const char *edges = "<edge source='p' target='q'/><edge source='q' target='r'/>\n"
                        "<edge source='r' target='p'/>\n";
    const char *keys = "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
                       "<key id='y' for='node' attr.name='vertex-coordinate-y'/>\n";
    char buf[2048];
    int n = snprintf(buf, sizeof buf, "%s<graph>\n%s</graph></graphml>\n", keys, nodes);
    expect_mem_reject(buf, (size_t)n, true, "mem:4: node 0 (document order) is isolated");
    n = snprintf(buf, sizeof buf, "%s<graph>\n%s</graph>\n%s</graphml>\n", keys, nodes, edges);
    expect_mem_reject(buf, (size_t)n, true, "mem:8: <edge> element outside <graph>");
    n = snprintf(buf, sizeof buf, "%s%s<graph>\n%s</graph></graphml>\n", keys, nodes, edges);
    expect_mem_reject(buf, (size_t)n, true, "mem:3: <node> element outside <graph>");
    n = snprintf(buf, sizeof buf, "%s<graph>\n%s</graph><graph>%s</graph></graphml>\n", keys,
                 nodes, edges);
    expect_mem_reject(buf, (size_t)n, true,
                      "mem:7: a second <graph> element (one polygon per file; the first on line 3)");
    n = snprintf(buf, sizeof buf,
                 "%s<graph>\n%s%s<edge source='p' target='x'/></graph></graphml>\n", keys, nodes,
                 edges);
    expect_mem_reject(buf, (size_t)n, true, "target 'x' is not a node id");
}

/* ---- the readers under allocation failure, on good and bad inputs ---- */

/* One reader call: a file by content (path set) or text through a reader. */
typedef struct reader_case {
    const char *path; /* tests/data/ relative, or NULL */
    const char *text;
    size_t len;
    bool graphml;
} reader_case;

static wk_status run_case(wk_run *R, const reader_case *c, wk_polygon **P) {
    return c->path ? read_data(R, c->path, P) : read_mem(R, c->text, c->len, c->graphml, P);
}

/* Fails allocation k for k = 0, 1, 2, ... until the call ends otherwise:
** every failing call must report WK_ENOMEM (and record it), return no
** polygon and close clean; the final one must give the status of a run
** without failures (want).  Returns the number of failing runs. */
static int64_t fault_loop_case(const char *what, const reader_case *c, wk_status want) {
    for (int64_t k = 0;; k++) {
        cr_assert_lt(k, 100000, "%s never got past the failures", what);
        wk_run R;
        wk_run_init(&R);
        R.alloc.fail_after = k;
        wk_polygon *P = NULL;
        wk_status st = run_case(&R, c, &P);
        char msg[1024];
        err_text(&R, msg, sizeof msg);
        cr_assert_eq(st, R.err.code, "%s, fail_after %lld: returned %d, recorded %d (%s)", what,
                     (long long)k, st, R.err.code, msg);
        if (st == WK_ENOMEM) {
            cr_assert_null(P, "%s, fail_after %lld: a polygon on failure", what, (long long)k);
            ASSERT_CLEAN_CLOSE(R);
            continue;
        }
        cr_assert_eq(st, want, "%s, fail_after %lld: status %d (%s), want %d", what, (long long)k,
                     st, msg, want);
        if (st == WK_OK) {
            cr_assert_not_null(P);
            wk_polygon_free(&R, P);
        } else {
            cr_assert_null(P);
        }
        ASSERT_CLEAN_CLOSE(R);
        return k;
    }
}

Test(polygon, fault_injection_readers_good_inputs) {
    static const char *const files[] = {
        "good/cw_weights.wpoly",   "good/comments.wpoly",   "good/crlf_default_weights.wpoly",
        "good/square.wpoly",       "good/straight_vertex.wpoly", "good/weighted.graphml",
        "good/unweighted.graphml", "hand/regular_64.wpoly", "hand/comb_equal.wpoly",
        "good/square_hole_weighted.geojson", "good/one_feature.geojson",
        "good/square_hole.wkt", "good/weighted_m.wkt",
    };
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        reader_case c = {files[i], NULL, 0, false};
        cr_assert_gt(fault_loop_case(files[i], &c, WK_OK), 1, "%s: no allocation failed",
                     files[i]);
    }
    /* The stream and memory entry points. */
    reader_case w = {NULL, MEM("# c\r\n4\r\n0 0 2\n1 0\n1 1\n0 1 3\n"), false};
    cr_assert_gt(fault_loop_case("wpoly stream", &w, WK_OK), 1);
    char buf[2048];
    size_t n = graphml_with(buf, sizeof buf, "<?xml version='1.0'?>\n", MEM("1"));
    reader_case g = {NULL, buf, n, true};
    cr_assert_gt(fault_loop_case("graphml memory", &g, WK_OK), 1);
    const char *ent =
        "<?xml version='1.0'?>\n<!DOCTYPE graphml [<!ENTITY pre 'node-'>]>\n"
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/>\n"
        "<key id='w' for='edge' attr.name='edge-weight'><default>2</default></key><graph>\n"
        "<node id='&pre;a'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "<node id='&pre;b'><data key='x'>1</data><data key='y'>0</data></node>\n"
        "<node id='&pre;c'><data key='x'>0</data><data key='y'>1</data></node>\n"
        "<edge source='node-a' target='&pre;b'/><edge source='&pre;b' target='node-c'/>\n"
        "<edge source='&pre;c' target='&pre;a'/></graph></graphml>\n";
    reader_case e = {NULL, ent, strlen(ent), true};
    cr_assert_gt(fault_loop_case("graphml entities", &e, WK_OK), 1);
}

/* Every file of the bad corpus through the loop: each error path is also
** taken after each possible allocation failure before it. */
Test(polygon, fault_injection_readers_bad_corpus) {
    char path[512];
    data_path(path, sizeof path, "bad");
    DIR *d = opendir(path);
    cr_assert_not_null(d);
    struct dirent *e;
    int files = 0;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.' || strcmp(e->d_name, "EXPECTED") == 0) continue;
        char rel[300];
        snprintf(rel, sizeof rel, "bad/%.250s", e->d_name);
        reader_case c = {rel, NULL, 0, false};
        fault_loop_case(rel, &c, WK_EINPUT);
        files++;
    }
    closedir(d);
    cr_assert_gt(files, 40);
    /* The memory entry points on bad text. */
    reader_case w = {NULL, MEM("4\n0 0\n1 0\n0.70\0\0\071067811865475 0.70\n0 1\n"), false};
    fault_loop_case("wpoly NUL", &w, WK_EINPUT);
    reader_case x = {NULL, MEM("4\n0 0\n1 0\n1 1\n0 1\n1 1\n"), false};
    fault_loop_case("wpoly extra line", &x, WK_EINPUT);
    reader_case s = {NULL, MEM("4\n0 0\n1 1\n1 0\n0 1\n"), false};
    fault_loop_case("wpoly bow tie", &s, WK_EINPUT);
    const char *dangling =
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/><graph>\n"
        "<node id='p'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "<node id='q'><data key='x'>1</data><data key='y'>0</data></node>\n"
        "<node id='r'><data key='x'>0</data><data key='y'>1</data></node>\n"
        "<edge source='p' target='q'/><edge source='q' target='r'/>\n"
        "<edge source='r' target='s'/></graph></graphml>\n";
    reader_case g = {NULL, dangling, strlen(dangling), true};
    fault_loop_case("graphml dangling edge", &g, WK_EINPUT);
    const char *no_edges =
        "<graphml><key id='x' for='node' attr.name='vertex-coordinate-x'/>\n"
        "<key id='y' for='node' attr.name='vertex-coordinate-y'/><graph>\n"
        "<node id='p'><data key='x'>0</data><data key='y'>0</data></node>\n"
        "</graph></graphml>\n";
    reader_case h = {NULL, no_edges, strlen(no_edges), true};
    fault_loop_case("graphml no edges", &h, WK_EINPUT);
}

/* The format is chosen by the first character that is not a blank, CR or
** LF (after a byte order mark): CRLF line ends before the root element
** still mean GraphML. */
Test(polygon, read_file_detects_graphml_after_blank_lines) {
    char doc[2048];
    size_t n = graphml_with(doc, sizeof doc, "\xEF\xBB\xBF\r\n \t\r\n",
                            MEM("1"));
    char path[] = "/tmp/wskel-test-XXXXXX";
    int fd = mkstemp(path);
    cr_assert_geq(fd, 0);
    FILE *f = fdopen(fd, "wb");
    cr_assert_eq(fwrite(doc, 1, n, f), n);
    fclose(f);
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_file(&R, path, &P);
    char msg[1024];
    err_text(&R, msg, sizeof msg);
    remove(path);
    cr_assert_eq(st, WK_OK, "%s", msg);
    cr_assert_eq(P->n, 4);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---- polygons with holes ---- */

/* A square (counter-clockwise) with two holes: a triangle given
** counter-clockwise (so it is reversed) and a square given clockwise (kept). */
static const double HX[11] = {0, 10, 10, 0, 2, 4, 3, 6, 6, 8, 8};
static const double HY[11] = {0, 0, 10, 10, 2, 2, 4, 6, 8, 8, 6};
static const double HW[11] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
static const uint32_t HR[3] = {4, 3, 4};

Test(polygon, holes_numbering_orientation_area) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    cr_assert_eq(wk_polygon_from_rings(&R, 3, HR, HX, HY, HW, "h", NULL, &P), WK_OK, "%s",
                 R.err.msg);
    cr_assert_eq(P->n, 11);
    cr_assert_eq(P->n_rings, 3);
    cr_assert_not_null(P->ring_of);
    cr_assert(!P->reversed);
    /* area: 100 - 2 (triangle) - 4 (square) */
    cr_assert_float_eq(wk_polygon_area(P), 94.0, 1e-12);
    /* every stored edge keeps its input edge's weight and endpoints */
    for (uint32_t j = 0; j < P->n; j++) {
        uint32_t ie = wk_polygon_input_edge(P, j), k = wk_polygon_ring(P, j);
        cr_assert_eq(P->w[j], HW[ie], "stored edge %u is input edge %u", j, ie);
        cr_assert(j >= P->ring_start[k] && j < P->ring_start[k + 1]);
        /* input edge ie runs from input vertex ie to the next of its ring */
        uint32_t a = ie, b = ie + 1 == P->ring_start[k + 1] ? P->ring_start[k] : ie + 1;
        uint32_t sa = P->input_index[j], sb = P->input_index[wk_polygon_next(P, j)];
        cr_assert((sa == a && sb == b) || (sa == b && sb == a), "edge %u: %u-%u vs %u-%u", j, sa,
                  sb, a, b);
        cr_assert_eq(wk_polygon_prev(P, wk_polygon_next(P, j)), j);
    }
    /* the triangle was counter-clockwise: reversed in its own index range */
    cr_assert_eq(P->input_index[4], 6);
    cr_assert_eq(P->input_index[6], 4);
    cr_assert_eq(P->input_index[7], 7, "the clockwise hole is kept");
    /* holes' corners are reflex for the region: 3 + 4 */
    cr_assert_eq(P->r, 7);
    cr_assert_eq(wk_polygon_validate(&R, P), WK_OK, "%s", R.err.msg);
    /* the writer emits rings, which the reader reads back to the same polygon */
    FILE *f = tmpfile();
    cr_assert_eq(wk_polygon_write_wpoly(&R, f, P), WK_OK);
    rewind(f);
    wk_polygon *Q = NULL;
    cr_assert_eq(wk_polygon_read_wpoly(&R, f, "round", &Q), WK_OK, "%s", R.err.msg);
    fclose(f);
    cr_assert_eq(Q->n_rings, 3);
    for (uint32_t j = 0; j < P->n; j++) {
        cr_assert_eq(Q->p[j].x, P->p[j].x);
        cr_assert_eq(Q->p[j].y, P->p[j].y);
        cr_assert_eq(Q->w[j], P->w[j]);
    }
    wk_polygon_free(&R, Q);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon, holes_rejected_with_reasons) {
    struct {
        uint32_t n_rings, sizes[3];
        double x[12], y[12];
        const char *want;
    } cases[] = {
        {2, {4, 3}, {0, 10, 10, 0, 20, 22, 21}, {0, 0, 10, 10, 20, 20, 22},
         "hole 1 (ring 1, vertices 4..6) is not inside the outer ring"},
        {3, {4, 4, 3}, {0, 10, 10, 0, 2, 2, 8, 8, 4, 6, 5}, {0, 0, 10, 10, 2, 8, 8, 2, 4, 4, 6},
         "hole 2 (ring 2) lies inside hole 1"},
        {2, {3, 4}, {4, 6, 5, 0, 10, 10, 0}, {4, 4, 6, 0, 0, 10, 10},
         "the outer ring (ring 0, the first) lies inside ring 1"},
        {2, {4, 3}, {0, 10, 10, 0, 5, 6, 4}, {0, 0, 10, 10, 0, 3, 3}, "touches"},
        {2, {4, 3}, {0, 10, 10, 0, 0, 3, 1}, {0, 0, 10, 10, 0, 1, 3}, "coincides"},
        {2, {4, 2}, {0, 10, 10, 0, 2, 3}, {0, 0, 10, 10, 2, 3}, "ring 1 needs at least 3"},
        {3, {4, 3, 3}, {0, 10, 10, 0, 2, 6, 4, 3, 7, 5}, {0, 0, 10, 10, 2, 2, 6, 3, 3, 7},
         "crosses"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = NULL;
        wk_status st = wk_polygon_from_rings(&R, cases[c].n_rings, cases[c].sizes, cases[c].x,
                                             cases[c].y, NULL, "t", NULL, &P);
        cr_assert_eq(st, WK_EINPUT, "case %zu: status %d", c, st);
        cr_assert_null(P);
        cr_assert(strstr(R.err.msg, cases[c].want), "case %zu: '%s' lacks '%s'", c, R.err.msg,
                  cases[c].want);
        ASSERT_CLEAN_CLOSE(R);
    }
}

static wk_status op_rings(wk_run *R, wk_polygon **P) {
    return wk_polygon_from_rings(R, 3, HR, HX, HY, HW, "h", NULL, P);
}
static wk_status op_holes_file(wk_run *R, wk_polygon **P) {
    return read_data(R, "holes/triangle_hole.wpoly", P);
}
static wk_status op_holes_graphml(wk_run *R, wk_polygon **P) {
    return read_data(R, "holes/triangle_hole_hole_first.graphml", P);
}
Test(polygon, fault_injection_rings) { fault_loop("rings", op_rings); }
Test(polygon, fault_injection_holes_wpoly) { fault_loop("holes wpoly", op_holes_file); }
Test(polygon, fault_injection_holes_graphml) { fault_loop("holes graphml", op_holes_graphml); }
