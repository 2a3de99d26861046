/*
** test_polygon_gis.c: the GeoJSON and WKT readers (engine/polygon_read_gis.c):
** parts and R->opt.part, weights (GeoJSON property, WKT M), holes, the
** messages' lines and paths, and the byte checks through the memory entry
** points.
*/
#include <criterion/criterion.h>

#include "helpers.h"

static wk_status geojson(wk_run *R, const char *s, wk_polygon **P) {
    return wk_polygon_read_geojson(R, s, strlen(s), "mem.geojson", P);
}
static wk_status wkt(wk_run *R, const char *s, wk_polygon **P) {
    return wk_polygon_read_wkt(R, s, strlen(s), "mem.wkt", P);
}

static const char MULTI[] =
    "{\"type\": \"FeatureCollection\", \"features\": [\n"
    " {\"type\": \"Feature\", \"properties\": {\"weights\": [[[1, 2, 3]], [[4, 5, 6, 7]]]},\n"
    "  \"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": [\n"
    "   [[[0, 0], [1, 0], [0, 1], [0, 0]]],\n"
    "   [[[5, 0], [6, 0], [6, 1], [5, 1], [5, 0]]]]}},\n"
    " {\"type\": \"Feature\", \"properties\": null,\n"
    "  \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [\n"
    "   [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]], [[4, 4], [4, 6], [6, 6], [6, 4], [4, 4]]]}}]}\n";

Test(polygon_gis, geojson_parts_weights_holes) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    char msg[1024];
    cr_assert_eq(geojson(&R, MULTI, &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "holds 3 polygons") && strstr(msg, "--part"), "%s", msg);
    wk_run_clear_error(&R);
    R.opt.part = 1; /* the MultiPolygon's second polygon, weights 4..7 */
    cr_assert_eq(geojson(&R, MULTI, &P), WK_OK);
    cr_assert_eq(P->n, 4);
    cr_assert_eq(P->n_rings, 1);
    for (uint32_t i = 0; i < 4; i++)
        cr_assert_eq(P->w[i], 4.0 + wk_polygon_input_edge(P, i), "edge %u: %g", i, P->w[i]);
    wk_polygon_free(&R, P);
    R.opt.part = 2; /* the square with a hole, unit weights */
    cr_assert_eq(geojson(&R, MULTI, &P), WK_OK);
    cr_assert_eq(P->n, 8);
    cr_assert_eq(P->n_rings, 2);
    cr_assert_float_eq(wk_polygon_area(P), 96.0, 1e-12);
    for (uint32_t i = 0; i < 8; i++) cr_assert_eq(P->w[i], 1.0);
    wk_polygon_free(&R, P);
    R.opt.part = 3;
    cr_assert_eq(geojson(&R, MULTI, &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "--part 3, but the input holds 3 polygons"), "%s", msg);
    cr_assert_null(P);
    wk_run_clear_error(&R);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon_gis, wkt_parts_weights_lines) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    char msg[1024];
    const char *two = "POLYGON ((0 0, 1 0, 0 1, 0 0))\n"
                      "multipolygon zm (((0 0 9 1, 4 0 9 2, 4 3 9 3, 0 3 9 4, 0 0 9 1)))\n";
    cr_assert_eq(wkt(&R, two, &P), WK_EINPUT);
    wk_run_clear_error(&R);
    R.opt.part = 1;
    cr_assert_eq(wkt(&R, two, &P), WK_OK);
    cr_assert_eq(P->n, 4);
    for (uint32_t i = 0; i < 4; i++) cr_assert_eq(P->w[i], 1.0 + wk_polygon_input_edge(P, i));
    wk_polygon_free(&R, P);
    R.opt.part = 0;
    cr_assert_eq(wkt(&R, two, &P), WK_OK);
    cr_assert_eq(P->n, 3);
    wk_polygon_free(&R, P);
    /* geometric faults name the vertices' lines */
    R.opt.part = WK_NONE;
    cr_assert_eq(wkt(&R, "POLYGON ((0 0,\n1 1,\n1 0,\n0 1,\n0 0))", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "(line 1)") && strstr(msg, "(line 3)"), "%s", msg);
    wk_run_clear_error(&R);
    /* EWKT's SRID prefix is skipped; a malformed one refused */
    cr_assert_eq(wkt(&R, "SRID=4326;POLYGON((0 0,1 0,0 1,0 0))", &P), WK_OK);
    wk_polygon_free(&R, P);
    cr_assert_eq(wkt(&R, "SRID=x;POLYGON((0 0,1 0,0 1,0 0))", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "SRID=<digits>;"), "%s", msg);
    wk_run_clear_error(&R);
    /* a hole inside, clockwise or not */
    cr_assert_eq(wkt(&R, "POLYGON((0 0,10 0,10 10,0 10,0 0),(4 4,6 4,6 6,4 6,4 4))", &P), WK_OK);
    cr_assert_eq(P->n_rings, 2);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(polygon_gis, bytes_and_syntax) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    char msg[1024];
    static const char nul[] = "POLYGON ((0 0, 1 0, 1\0 1, 0 0))";
    cr_assert_eq(wk_polygon_read_wkt(&R, nul, sizeof nul - 1, "nul.wkt", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "NUL byte"), "%s", msg);
    wk_run_clear_error(&R);
    static const char js[] = "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[1,1],[0,0]]]}\0";
    cr_assert_eq(wk_polygon_read_geojson(&R, js, sizeof js - 1, "nul.geojson", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "NUL byte"), "%s", msg);
    wk_run_clear_error(&R);
    cr_assert_eq(geojson(&R, "{\"type\": \"Polygon\",\n\"coordinates\": [[[0,0],[1,0],[1,1],[0,0]]]", &P),
                 WK_EINPUT);
    cr_assert_eq(R.err.input_line, 2);
    wk_run_clear_error(&R);
    cr_assert_eq(geojson(&R, "{\"type\": \"GeometryCollection\", \"geometries\": []}", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "not a Polygon or a MultiPolygon"), "%s", msg);
    wk_run_clear_error(&R);
    cr_assert_eq(geojson(&R, "{\"type\": \"FeatureCollection\", \"features\": []}", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "no polygon"), "%s", msg);
    wk_run_clear_error(&R);
    cr_assert_eq(wkt(&R, "POLYGON ((0 0, 1 0, 1 1, 0 0), (0 0, 1 0, 0 0))", &P), WK_EINPUT);
    err_text(&R, msg, sizeof msg);
    cr_assert(strstr(msg, "at least 3 vertices"), "%s", msg);
    wk_run_clear_error(&R);
    cr_assert_null(P);
    ASSERT_CLEAN_CLOSE(R);
}

/* Allocation failure k = 0, 1, ... on both readers, good and bad input. */
Test(polygon_gis, allocation_failures) {
    static const char *const docs[] = {
        MULTI,
        "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (4 4, 6 4, 6 6, 4 6, 4 4))",
        "POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))",
    };
    for (size_t d = 0; d < 3; d++) {
        int failed = 0;
        for (int64_t k = 0;; k++) {
            cr_assert_lt(k, 10000);
            wk_run R;
            wk_run_init(&R);
            R.opt.part = d == 0 ? 2 : WK_NONE;
            R.alloc.fail_after = k;
            wk_polygon *P = NULL;
            wk_status st = d == 0 ? geojson(&R, docs[d], &P) : wkt(&R, docs[d], &P);
            cr_assert_eq(st, R.err.code);
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
            if (st != WK_ENOMEM) {
                cr_assert_eq(st, d == 2 ? WK_EINPUT : WK_OK, "doc %zu: status %d", d, (int)st);
                break;
            }
            failed++;
        }
        cr_assert_gt(failed, 1, "doc %zu: no allocation failed", d);
    }
}
