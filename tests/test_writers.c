/*
** test_writers.c: the five output writers (engine/write_*.c).
**
** Oracles: hand-made skeletons (unit square, L shape with one reflex arc, a
** clockwise square that is stored reversed), the formats' own rules (JSON
** brackets balance outside strings and every contract key is there; the text
** format reads back to the same doubles; OBJ has one vertex per node and one
** face per input edge), geometry for input numbering (an arc's left face's
** edge midpoint lies left of the arc), a failing stream (/dev/full) and
** fault injection.  Every test owns its wk_run and ends with zero live bytes.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wskel.h"
#include "helpers.h"

/* The fixtures' skeleton, validated: writers are tested on valid input. */
static wk_skeleton *valid_skeleton(wk_run *R, const wk_polygon *P, uint32_t n_extra,
                                   const wk_node *extra, uint32_t n_arcs, const arc4 *arcs) {
    wk_skeleton *S = skeleton(R, P, n_extra, extra, n_arcs, arcs);
    cr_assert_eq(wk_validate(R, P, S, 0, NULL), WK_OK, "test skeleton invalid: %s", R->err.msg);
    return S;
}

/* The unit square (SQ_*) and the L shape (L_*) are in helpers.h. */

/* The same square given clockwise: stored reversed, so stored vertex j is
** input vertex 3 - j and every id differs between the two numberings. */
static const double CW_X[4] = {0, 0, 1, 1}, CW_Y[4] = {0, 1, 1, 0};

/* The square's skeleton in stored numbering: the arc from vertex j runs
** between edges j-1 (left) and j (right). */
static wk_skeleton *cw_square(wk_run *R, wk_polygon **P) {
    *P = polygon(R, 4, CW_X, CW_Y, NULL);
    cr_assert((*P)->reversed);
    return valid_skeleton(R, *P, 1, SQ_NODES, 4, SQ_ARCS);
}

/* Everything a writer wrote: f is a tmpfile, read back whole. */
static char *slurp(FILE *f) {
    long len = ftell(f);
    cr_assert_geq(len, 0);
    rewind(f);
    char *buf = malloc((size_t)len + 1);
    cr_assert_not_null(buf);
    cr_assert_eq(fread(buf, 1, (size_t)len, f), (size_t)len);
    buf[len] = '\0';
    fclose(f);
    return buf;
}

typedef enum { W_JSON, W_TEXT, W_SVG, W_OBJ, W_VTP, W_COUNT } writer;
static const char *const WRITER_NAME[W_COUNT] = {"json", "text", "svg", "obj", "vtp"};

static wk_status write_with(wk_run *R, writer w, FILE *f, const wk_polygon *P,
                            const wk_skeleton *S) {
    static const double offsets[2] = {0.1, 0.3};
    wk_run_info info = {"naive", WK_NONE, 0.5, 100, &R->counters, wk_variant_find("naive")};
    switch (w) {
    case W_JSON: return wk_write_json(R, f, P, S, &info);
    case W_TEXT: return wk_write_text(R, f, P, S);
    case W_SVG: return wk_write_svg(R, f, P, S, offsets, 2);
    case W_OBJ: return wk_write_obj(R, f, P, S);
    default: return wk_write_vtp(R, f, P, S);
    }
}

static char *write_to_string(wk_run *R, writer w, const wk_polygon *P, const wk_skeleton *S) {
    FILE *f = tmpfile();
    cr_assert_not_null(f);
    wk_status st = write_with(R, w, f, P, S);
    cr_assert_eq(st, WK_OK, "%s writer: %s", WRITER_NAME[w], R->err.msg);
    return slurp(f);
}

static int count_of(const char *s, const char *what) {
    int k = 0;
    for (const char *p = s; (p = strstr(p, what)); p += strlen(what)) k++;
    return k;
}

/* ---------------------------------------------------------------- JSON */

/* Brackets and braces balance outside strings, and the text is one value. */
static void assert_json_shape(const char *s) {
    char stack[64];
    int depth = 0;
    bool in_string = false;
    for (const char *p = s; *p; p++) {
        if (in_string) {
            if (*p == '\\') p++;
            else if (*p == '"') in_string = false;
            continue;
        }
        if (*p == '"') in_string = true;
        else if (*p == '{' || *p == '[') {
            cr_assert_lt(depth, 64);
            stack[depth++] = *p;
        } else if (*p == '}' || *p == ']') {
            cr_assert_gt(depth, 0, "unbalanced at offset %td", p - s);
            cr_assert_eq(stack[--depth], *p == '}' ? '{' : '[', "mismatch at offset %td", p - s);
            if (depth == 0) {
                while (p[1] == '\n' || p[1] == ' ') p++;
                cr_assert_eq(p[1], '\0', "text after the JSON value");
            }
        }
    }
    cr_assert_eq(depth, 0);
    cr_assert_not(in_string);
    cr_assert_null(strstr(s, "nan"));
    cr_assert_null(strstr(s, "inf"));
}

Test(write_json, contract_keys_and_round_trip) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 1, SQ_NODES, 4, SQ_ARCS);
    S->nodes[4].t = nextafter(0.5, 1); /* 0.50000000000000011: needs 17 digits */
    S->nodes[4].x = nextafter(0.5, 0);
    wk_event ev = {0, 0, 0, 0, 0, 0};
    wk_notify_event(&R, WK_COUNTER_edge_events, &ev);
    wk_notify_event(&R, WK_COUNTER_edge_events, &ev);
    const wk_variant *AR = wk_variant_find("arrangement");
    wk_count(&R, WK_ENGINE_COUNTERS + 1, 5); /* the arrangement's second counter */
    wk_run_info info = {"arrangement", WK_NONE, 0.25, 1234, &R.counters, AR};
    FILE *f = tmpfile();
    cr_assert_eq(wk_write_json(&R, f, P, S, &info), WK_OK, "%s", R.err.msg);
    char *s = slurp(f);
    assert_json_shape(s);
    const char *head = "{\"format\":\"wskel-1\",\"variant\":\"arrangement\",\"k\":null,\"n\":4,\"r\":0,\"rings\":[4],\n";
    cr_assert(!strncmp(s, head, strlen(head)), "%s", s);
    /* every counter of the engine and of the variant, and no other */
    for (uint32_t id = 0; id < wk_counter_count(AR); id++) {
        char key[80];
        snprintf(key, sizeof key, "\"%s\":", wk_counter_def_at(AR, id)->name);
        cr_assert(strstr(s, key), "no counter %s", key);
    }
    char key[80];
    snprintf(key, sizeof key, "\"%s\":5,", wk_counter_def_at(AR, WK_ENGINE_COUNTERS + 1)->name);
    cr_assert(strstr(s, key), "%s", s);
    cr_assert_null(strstr(s, "\"chain_edge_events_lower\""), "a monotone counter in an arrangement run");
    cr_assert(strstr(s, "\"edge_events\":2,"));
    cr_assert(strstr(s, "\"time_s\":0.25,\"peak_bytes\":1234}"));
    const char *p = strstr(s, "\"nodes\":[");
    cr_assert_not_null(p);
    p += strlen("\"nodes\":[");
    for (uint32_t i = 0; i < 5; i++) {
        char *end;
        while (*p == '\n' || *p == '[' || *p == ',' || *p == ']') p++;
        double x = strtod(p, &end);
        p = end + 1;
        double y = strtod(p, &end);
        p = end + 1;
        double t = strtod(p, &end);
        p = end;
        cr_assert(x == S->nodes[i].x && y == S->nodes[i].y && t == S->nodes[i].t,
                  "node %u read back as (%.17g, %.17g, %.17g)", i, x, y, t);
    }
    cr_assert(strstr(s, "\"arcs\":[\n[0,4,3,0],\n[1,4,0,1],\n[2,4,1,2],\n[3,4,2,3]\n]"), "%s", s);
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(write_json, k_variant_and_missing_info) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 1, SQ_NODES, 4, SQ_ARCS);
    FILE *f = tmpfile();
    cr_assert_eq(wk_write_json(&R, f, P, S, NULL), WK_OK);
    char *s = slurp(f);
    assert_json_shape(s);
    cr_assert(strstr(s, "\"variant\":\"unknown\",\"k\":null,"), "%s", s);
    cr_assert(strstr(s, "\"stats\":null}"), "%s", s);
    free(s);

    wk_run_info info = {"we\"ird\\name\n", 7, 0, 0, NULL, NULL};
    f = tmpfile();
    cr_assert_eq(wk_write_json(&R, f, P, S, &info), WK_OK);
    s = slurp(f);
    assert_json_shape(s);
    cr_assert(strstr(s, "\"variant\":\"we\\\"ird\\\\name\\u000a\",\"k\":7,"), "%s", s);
    cr_assert(strstr(s, "\"stats\":{\"time_s\":0,\"peak_bytes\":0}"), "%s", s);
    free(s);

    /* k: WK_K_MAX is "max", WK_NONE is null */
    wk_run_info vmax = {"arrangement", WK_K_MAX, 0, 0, NULL, NULL};
    f = tmpfile();
    cr_assert_eq(wk_write_json(&R, f, P, S, &vmax), WK_OK);
    s = slurp(f);
    cr_assert(strstr(s, "\"k\":\"max\","), "%s", s);
    free(s);
    wk_run_info vnone = {"naive", WK_NONE, 0, 0, NULL, NULL};
    f = tmpfile();
    cr_assert_eq(wk_write_json(&R, f, P, S, &vnone), WK_OK);
    s = slurp(f);
    cr_assert(strstr(s, "\"k\":null,"), "%s", s);
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------------- text */

typedef struct parsed {
    uint32_t n_nodes, n_arcs;
    wk_node nodes[16];
    arc4 arcs[16];
} parsed;

static void parse_text(const char *s, parsed *out) {
    while (*s == '#') s = strchr(s, '\n') + 1;
    int used;
    cr_assert_eq(sscanf(s, "nodes %u%n", &out->n_nodes, &used), 1, "%s", s);
    cr_assert_leq(out->n_nodes, 16);
    s += used;
    for (uint32_t i = 0; i < out->n_nodes; i++) {
        wk_node *v = &out->nodes[i];
        cr_assert_eq(sscanf(s, "%lf %lf %lf%n", &v->x, &v->y, &v->t, &used), 3);
        s += used;
    }
    cr_assert_eq(sscanf(s, " arcs %u%n", &out->n_arcs, &used), 1, "%s", s);
    cr_assert_leq(out->n_arcs, 16);
    s += used;
    for (uint32_t i = 0; i < out->n_arcs; i++) {
        arc4 *c = &out->arcs[i];
        cr_assert_eq(sscanf(s, "%u %u %u %u%n", &c->a, &c->b, &c->l, &c->r, &used), 4);
        s += used;
    }
    while (*s == '\n') s++;
    cr_assert_eq(*s, '\0', "trailing text '%s'", s);
}

Test(write_text, round_trip_l_shape) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
    S->nodes[7].x = 1.5 + 1e-16 * 3; /* round trip, not equality by luck */
    char *s = write_to_string(&R, W_TEXT, P, S);
    cr_assert_eq(s[0], '#');
    parsed got;
    parse_text(s, &got);
    cr_assert_eq(got.n_nodes, S->n_nodes);
    cr_assert_eq(got.n_arcs, S->n_arcs);
    for (uint32_t i = 0; i < S->n_nodes; i++)
        cr_assert(got.nodes[i].x == S->nodes[i].x && got.nodes[i].y == S->nodes[i].y &&
                      got.nodes[i].t == S->nodes[i].t,
                  "node %u", i);
    for (uint32_t i = 0; i < S->n_arcs; i++)
        cr_assert(got.arcs[i].a == S->arcs[i].a && got.arcs[i].b == S->arcs[i].b &&
                      got.arcs[i].l == S->arcs[i].left && got.arcs[i].r == S->arcs[i].right,
                  "arc %u", i);
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* A clockwise input: the text output must be in input numbering.  Nodes
** 0..3 are the input vertices in input order; every arc has its left face's
** input edge midpoint on its left and its right face's on its right. */
Test(write_text, clockwise_input_uses_input_numbering) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P;
    wk_skeleton *S = cw_square(&R, &P);
    char *s = write_to_string(&R, W_TEXT, P, S);
    parsed got;
    parse_text(s, &got);
    for (uint32_t i = 0; i < 4; i++) {
        cr_assert_eq(got.nodes[i].x, CW_X[i], "node %u", i);
        cr_assert_eq(got.nodes[i].y, CW_Y[i], "node %u", i);
    }
    for (uint32_t i = 0; i < got.n_arcs; i++) {
        const arc4 *c = &got.arcs[i];
        wk_point a = {got.nodes[c->a].x, got.nodes[c->a].y};
        wk_point b = {got.nodes[c->b].x, got.nodes[c->b].y};
        wk_point ml = {(CW_X[c->l] + CW_X[(c->l + 1) % 4]) / 2,
                       (CW_Y[c->l] + CW_Y[(c->l + 1) % 4]) / 2};
        wk_point mr = {(CW_X[c->r] + CW_X[(c->r + 1) % 4]) / 2,
                       (CW_Y[c->r] + CW_Y[(c->r + 1) % 4]) / 2};
        cr_assert_gt(wk_orient2d(a, b, ml, NULL), 0, "arc %u [%u %u %u %u]: left", i, c->a, c->b,
                     c->l, c->r);
        cr_assert_lt(wk_orient2d(a, b, mr, NULL), 0, "arc %u: right", i);
        /* The arc from input vertex v lies between input edges v-1 and v. */
        uint32_t v = c->a < 4 ? c->a : c->b;
        cr_assert((c->l == v && c->r == (v + 3) % 4) || (c->r == v && c->l == (v + 3) % 4),
                  "arc %u from vertex %u has faces %u, %u", i, v, c->l, c->r);
    }
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------------- OBJ */

Test(write_obj, one_vertex_per_node_one_face_per_edge) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
    char *s = write_to_string(&R, W_OBJ, P, S);
    cr_assert_eq(s[0], '#');
    cr_assert_eq(count_of(s, "\nv "), 9);
    cr_assert_eq(count_of(s, "\nf "), 6);
    cr_assert(strstr(s, "\nv 0.5 0.5 0.5\n"));
    /* Face of edge 0: vertices 0, 1, then B and A (1-based 1 2 8 7). */
    cr_assert(strstr(s, "\nf 1 2 8 7\n"), "%s", s);
    for (const char *p = strstr(s, "\nf "); p; p = strstr(p + 1, "\nf ")) {
        unsigned v;
        int used;
        for (const char *q = p + 3; sscanf(q, "%u%n", &v, &used) == 1 && *q != '\n'; q += used) {
            cr_assert(v >= 1 && v <= 9, "vertex %u", v);
            if (q[used] == '\n') break;
        }
    }
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);

    /* Clockwise input: faces in input edge order, input vertex ids. */
    S = cw_square(&R, &P);
    s = write_to_string(&R, W_OBJ, P, S);
    cr_assert(strstr(s, "\nv 0 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nv 0.5 0.5 0.5\n"), "%s", s);
    /* Input edge 0 runs (0,0) -> (0,1); counter-clockwise from above its
    ** face is 2 1 5. */
    cr_assert(strstr(s, "\nf 2 1 5\nf 3 2 5\nf 4 3 5\nf 1 4 5\n"), "%s", s);
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------------- SVG */

Test(write_svg, layers_and_reflex_arc) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
    char *s = write_to_string(&R, W_SVG, P, S);
    cr_assert(!strncmp(s, "<?xml", 5));
    cr_assert(strstr(s, "<svg xmlns=\"http://www.w3.org/2000/svg\""));
    cr_assert(strstr(s, "</svg>\n"));
    cr_assert(strstr(s, "d=\"M0,0 L2,0 L2,-1 L1,-1 L1,-2 L0,-2 Z\""), "%s", s);
    cr_assert_eq(count_of(s, "<circle"), 9);
    const char *reflex = strstr(s, "class=\"reflex\"");
    const char *convex = strstr(s, "class=\"convex\"");
    cr_assert(reflex && convex);
    /* One reflex arc (from vertex 3), seven convex ones. */
    cr_assert(strstr(reflex, "d=\"M1,-1L0.5,-0.5\"/>"), "%s", reflex);
    cr_assert_eq(count_of(convex, "M") - count_of(reflex, "M"), 7);
    cr_assert_eq(count_of(s, "class=\"offset\""), 2);
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

Test(write_svg, offset_curve_of_square) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 1, SQ_NODES, 4, SQ_ARCS);
    const double t[3] = {0.25, 0, 0.75}; /* t = 0 draws nothing; 0.75 is past the end */
    FILE *f = tmpfile();
    cr_assert_eq(wk_write_svg(&R, f, P, S, t, 3), WK_OK, "%s", R.err.msg);
    char *s = slurp(f);
    cr_assert_eq(count_of(s, "class=\"offset\""), 2);
    /* The bottom edge's wavefront at t = 0.25: y = 0.25 from x = 0.25 to 0.75. */
    cr_assert(strstr(s, "M0.25,-0.25L0.75,-0.25"), "%s", s);
    cr_assert(strstr(s, "data-t=\"0.75\" fill=\"none\" stroke=\"#8a8a8a\" stroke-width=\"0.001414\" d=\"\"/>"),
              "%s", s);
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------------- VTP */

Test(write_vtp, counts_and_cell_data) {
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
    wk_skeleton *S = valid_skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
    char *s = write_to_string(&R, W_VTP, P, S);
    cr_assert(strstr(s, "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">"));
    cr_assert(strstr(s, "NumberOfPoints=\"9\" NumberOfVerts=\"0\" NumberOfLines=\"14\" "
                        "NumberOfStrips=\"0\" NumberOfPolys=\"6\""),
              "%s", s);
    const char *kind = strstr(s, "Name=\"kind\"");
    cr_assert_not_null(kind);
    /* kind: 6 boundary, arcs 0..7 (arc 3 reflex), 6 roof faces. */
    cr_assert(strstr(kind, ">\n0\n0\n0\n0\n0\n0\n1\n1\n1\n2\n1\n1\n1\n1\n3\n3\n3\n3\n3\n3\n</DataArray>"),
              "%s", kind);
    cr_assert(strstr(s, "Name=\"edge_id\" format=\"ascii\">\n0\n1\n2\n3\n4\n5\n-1\n"));
    /* Roof face of edge 0 in the polys: nodes 0 1 7 6. */
    const char *polys = strstr(s, "<Polys>");
    cr_assert(polys && strstr(polys, "\n0 1 7 6\n"), "%s", polys);
    cr_assert(strstr(s, "</VTKFile>\n"));
    free(s);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    ASSERT_CLEAN_CLOSE(R);
}

/* ---------------------------------------------------------------- errors */

Test(writers, failing_stream_is_reported) {
    for (writer w = 0; w < W_COUNT; w++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, 6, L_X, L_Y, NULL);
        wk_skeleton *S = valid_skeleton(&R, P, 3, L_NODES, 8, L_ARCS);
        FILE *f = fopen("/dev/full", "w");
        cr_assert_not_null(f);
        wk_status st = write_with(&R, w, f, P, S);
        fclose(f);
        cr_assert_eq(st, WK_EALGO, "%s writer on /dev/full: status %d", WRITER_NAME[w], st);
        cr_assert(strstr(R.err.msg, "write failed"), "%s", R.err.msg);
        cr_assert(strstr(R.err.msg, WRITER_NAME[w]), "%s", R.err.msg);
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

Test(writers, bad_ids_refused_before_writing) {
    for (writer w = 0; w < W_COUNT; w++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
        wk_skeleton *S = valid_skeleton(&R, P, 1, SQ_NODES, 4, SQ_ARCS);
        S->arcs[2].b = 99;
        FILE *f = tmpfile();
        wk_status st = write_with(&R, w, f, P, S);
        cr_assert_eq(st, WK_EINVALID, "%s writer", WRITER_NAME[w]);
        cr_assert(strstr(R.err.msg, "arc 2"), "%s", R.err.msg);
        cr_assert_eq(ftell(f), 0, "%s writer wrote before refusing", WRITER_NAME[w]);
        fclose(f);
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

/* Faces that do not close: the writers that need them (obj, vtp, svg with
** offsets) fail cleanly before writing; json and text still write. */
Test(writers, broken_faces) {
    for (writer w = 0; w < W_COUNT; w++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
        wk_skeleton *S = valid_skeleton(&R, P, 1, SQ_NODES, 4, SQ_ARCS);
        S->arcs[0] = (wk_arc){0, 4, 0, 3};
        FILE *f = tmpfile();
        wk_status st = write_with(&R, w, f, P, S);
        if (w == W_JSON || w == W_TEXT) {
            cr_assert_eq(st, WK_OK, "%s writer: %s", WRITER_NAME[w], R.err.msg);
        } else {
            cr_assert_eq(st, WK_EINVALID, "%s writer", WRITER_NAME[w]);
            cr_assert(strstr(R.err.msg, "face of edge"), "%s", R.err.msg);
            cr_assert_eq(ftell(f), 0, "%s writer wrote before refusing", WRITER_NAME[w]);
        }
        fclose(f);
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}

Test(writers, out_of_memory_at_every_allocation) {
    for (writer w = 0; w < W_COUNT; w++) {
        for (int64_t k = 0;; k++) {
            wk_run R;
            wk_run_init(&R);
            wk_polygon *P;
            wk_skeleton *S = cw_square(&R, &P);
            R.alloc.fail_after = (int64_t)R.alloc.calls + k;
            FILE *f = tmpfile();
            wk_status st = write_with(&R, w, f, P, S);
            fclose(f);
            R.alloc.fail_after = -1;
            wk_skeleton_free(&R, S);
            wk_polygon_free(&R, P);
            ASSERT_CLEAN_CLOSE(R);
            if (st == WK_OK) break;
            cr_assert_eq(st, WK_ENOMEM, "%s writer, allocation %lld: %s", WRITER_NAME[w],
                         (long long)k, R.err.msg);
            cr_assert_lt(k, 100);
        }
    }
}

/* The unit square's roof cut at H = 0.25 (a capped skeleton, as the deforming
** variant writes it): four corner arcs up to the cap's nodes, and the cap's
** four arcs with no face (WK_NONE) on their left.  SVG draws the cap and the
** wavefront at t = 0.125 from the capped faces; every allocation failure of
** that path is clean. */
static const wk_node CAP_NODES[4] = {
    {0.25, 0.25, 0.25}, {0.75, 0.25, 0.25}, {0.75, 0.75, 0.25}, {0.25, 0.75, 0.25}};
static const arc4 CAP_ARCS[8] = {{0, 4, 3, 0},       {1, 5, 0, 1},       {2, 6, 1, 2},
                                 {3, 7, 2, 3},       {4, 5, WK_NONE, 0}, {5, 6, WK_NONE, 1},
                                 {6, 7, WK_NONE, 2}, {7, 4, WK_NONE, 3}};

Test(write_svg, capped_roof_and_its_offsets) {
    for (int64_t k = 0;; k++) {
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = polygon(&R, 4, SQ_X, SQ_Y, NULL);
        wk_skeleton *S = skeleton(&R, P, 4, CAP_NODES, 8, CAP_ARCS);
        const double t[1] = {0.125};
        FILE *f = tmpfile();
        R.alloc.fail_after = (int64_t)R.alloc.calls + k;
        wk_status st = wk_write_svg(&R, f, P, S, t, 1);
        R.alloc.fail_after = -1;
        if (st == WK_OK) {
            char *s = slurp(f);
            const char *cap = strstr(s, "class=\"cap\"");
            cr_assert(cap, "%s", s);
            cr_assert(strstr(cap, "M0.25,-0.25L0.75,-0.25"), "%s", s);
            cr_assert_eq(count_of(cap, "M"), 4);
            /* the bottom edge's wavefront at t = 0.125 */
            cr_assert(strstr(s, "M0.125,-0.125L0.875,-0.125"), "%s", s);
            free(s);
        } else {
            fclose(f);
            cr_assert_eq(st, WK_ENOMEM, "allocation %lld: %s", (long long)k, R.err.msg);
            cr_assert_lt(k, 100);
        }
        wk_skeleton_free(&R, S);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
        if (st == WK_OK) break;
    }
}
