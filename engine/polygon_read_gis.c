/*
** polygon_read_gis.c: polygons from GeoJSON (RFC 7946) and WKT (OGC Simple
** Features), the formats GIS tools write.
**
** Parts.  Either format may hold several polygons (a MultiPolygon, several
** Features, several WKT geometries one after the other); they are numbered
** from 0 in document order (a MultiPolygon's polygons in their order) and
** one run takes one of them: R->opt.part (the CLI's --part I).  With
** several and no part chosen, the reader refuses, naming the count; a part
** number beyond the count is refused too.
**
** GeoJSON (parsed by jansson, duplicate keys refused, so no document is read
** one of two ways): the top level is a Polygon, a MultiPolygon, a Feature
** whose geometry is one of them, or a FeatureCollection of such Features.
** Rings are arrays of positions [x, y] or [x, y, z] (z ignored), closed
** (the last position repeats the first exactly) as RFC 7946 requires; the
** closing position is dropped.  Ring 0 is the outer ring, the others holes;
** any orientation.  Weights: a Feature's properties may hold "weights":
** for a Polygon an array with one array per ring, weight i of a ring being
** that of the edge from its vertex i to vertex i+1 (as many weights as the
** ring has vertices, the closing position not counted); for a MultiPolygon
** one such array per polygon.  Without it every weight is 1.  Messages name
** the JSON path (features[2].geometry.coordinates[0][3]); jansson keeps no
** positions for values, so only syntax errors carry a line (jansson's).
**
** WKT (a small reader, not GEOS: GEOS 3.11, Debian 12's, reads POLYGON M
** as Z, losing the weights, and its parse errors name no position; this one
** names the line of every message): any number of
** POLYGON and MULTIPOLYGON geometries, keywords in any case, an optional
** dimension Z, M or ZM, each optionally after PostGIS's EWKT "SRID=n;"
** (ignored); points of 2, 3 (Z or M as tagged; untagged: Z) or
** 4 numbers; Z is ignored and M is the weight of the edge from that point to
** the next (the closing point's M is ignored).  Rings are closed as in
** GeoJSON.  EMPTY geometries are refused (no skeleton to compute).  Numbers
** are C strtod syntax limited to digits, sign, '.', 'e'; finite.
**
** Bytes (both): strict UTF-8, no NUL, no control character but tab, CR, LF
** (wk_read_utf8_bytes), checked first with line and column.  Every
** geometric check is left to wk_polygon_from_rings, the authority on
** validity (for WKT with the line of each vertex).
*/
#include "read_text.h"

#include <ctype.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the chosen part's vertices ---- */

typedef struct part_arrays {
    uint32_t n, n_rings;
    uint32_t cap_x, cap_y, cap_w, cap_line, cap_rings; /* each array's own capacity */
    double *x, *y, *w;
    long *line;
    uint32_t *ring_size;
    bool weighted;
} part_arrays;

static void part_free(wk_run *R, part_arrays *A) {
    WK_FREE_ARRAY(R, A->x, A->cap_x);
    WK_FREE_ARRAY(R, A->y, A->cap_y);
    WK_FREE_ARRAY(R, A->w, A->cap_w);
    WK_FREE_ARRAY(R, A->line, A->cap_line);
    WK_FREE_ARRAY(R, A->ring_size, A->cap_rings);
}

static wk_status part_push(wk_run *R, part_arrays *A, double x, double y, double w, long line) {
    uint32_t need = A->n + 1;
    if (WK_GROW(R, A->x, A->cap_x, need) != WK_OK || WK_GROW(R, A->y, A->cap_y, need) != WK_OK ||
        WK_GROW(R, A->w, A->cap_w, need) != WK_OK || WK_GROW(R, A->line, A->cap_line, need) != WK_OK)
        return WK_ENOMEM;
    A->x[A->n] = x;
    A->y[A->n] = y;
    A->w[A->n] = w;
    A->line[A->n] = line;
    A->n++;
    return WK_OK;
}

static wk_status part_end_ring(wk_run *R, part_arrays *A, uint32_t size) {
    if (WK_GROW(R, A->ring_size, A->cap_rings, A->n_rings + 1) != WK_OK) return WK_ENOMEM;
    A->ring_size[A->n_rings++] = size;
    return WK_OK;
}

static wk_status part_build(wk_run *R, part_arrays *A, const char *name, bool lines,
                            wk_polygon **out) {
    return wk_polygon_from_rings(R, A->n_rings, A->ring_size, A->x, A->y,
                                 A->weighted ? A->w : NULL, name, lines ? A->line : NULL, out);
}

/* The part to take, or a failure naming the count.  line: where the second
** polygon begins (the refusal of several points there), or the last line
** when there is none; 0 when unknown (GeoJSON). */
static wk_status choose_part(wk_run *R, const char *name, uint32_t count, const char *what,
                             long line) {
    uint32_t part = R->opt.part;
    if (count == 0) return WK_FAIL(R, WK_EINPUT, name, line, "no polygon in the input (%s)", what);
    if (part == WK_NONE && count > 1)
        return WK_FAIL(R, WK_EINPUT, name, line,
                       "the input holds %u polygons (%s): choose one with --part I (0 to %u)",
                       count, what, count - 1);
    if (part != WK_NONE && part >= count)
        return WK_FAIL(R, WK_EINPUT, name, line,
                       "--part %u, but the input holds %u polygon%s (%s; parts count from 0)", part,
                       count, count == 1 ? "" : "s", what);
    return WK_OK;
}

/* ================================================================ GeoJSON */

/* One polygon of the document: its rings and its weights (NULL: unit). */
typedef struct gj_part {
    json_t *rings;
    json_t *weights;
    char path[128];
} gj_part;

typedef struct gj_walk {
    uint32_t count, want; /* parts seen; the index to keep */
    gj_part kept;
} gj_walk;

static const char *type_of(json_t *o) {
    json_t *t = json_is_object(o) ? json_object_get(o, "type") : NULL;
    return json_is_string(t) ? json_string_value(t) : NULL;
}

static void see_part(gj_walk *W, json_t *rings, json_t *weights, const char *path) {
    if (W->count++ == W->want) {
        W->kept.rings = rings;
        W->kept.weights = weights;
        snprintf(W->kept.path, sizeof W->kept.path, "%s", path);
    }
}

/* A geometry (Polygon or MultiPolygon) with the weights of its Feature. */
static wk_status gj_geometry(wk_run *R, const char *name, gj_walk *W, json_t *g, json_t *weights,
                             const char *path) {
    const char *type = type_of(g);
    char p[128];
    if (!type)
        return WK_FAIL(R, WK_EINPUT, name, 0, "%s: expected a GeoJSON object with a \"type\"",
                       path[0] ? path : "top level");
    json_t *c = json_object_get(g, "coordinates");
    if (!strcmp(type, "Polygon")) {
        if (!json_is_array(c))
            return WK_FAIL(R, WK_EINPUT, name, 0, "%s.coordinates: expected an array of rings",
                           path[0] ? path : "Polygon");
        snprintf(p, sizeof p, "%s%scoordinates", path, path[0] ? "." : "");
        see_part(W, c, weights, p);
        return WK_OK;
    }
    if (!strcmp(type, "MultiPolygon")) {
        if (!json_is_array(c))
            return WK_FAIL(R, WK_EINPUT, name, 0, "%s.coordinates: expected an array of polygons",
                           path[0] ? path : "MultiPolygon");
        if (weights && (!json_is_array(weights) || json_array_size(weights) != json_array_size(c)))
            return WK_FAIL(R, WK_EINPUT, name, 0,
                           "%s: \"weights\" of a MultiPolygon must be an array with one entry per "
                           "polygon (%zu)",
                           path[0] ? path : "MultiPolygon", json_array_size(c));
        for (size_t i = 0; i < json_array_size(c); i++) {
            snprintf(p, sizeof p, "%s%scoordinates[%zu]", path, path[0] ? "." : "", i);
            see_part(W, json_array_get(c, i), weights ? json_array_get(weights, i) : NULL, p);
        }
        return WK_OK;
    }
    return WK_FAIL(R, WK_EINPUT, name, 0,
                   "%s: geometry type \"%.40s\" is not a Polygon or a MultiPolygon",
                   path[0] ? path : "top level", type);
}

static wk_status gj_feature(wk_run *R, const char *name, gj_walk *W, json_t *f, const char *path) {
    char p[128];
    json_t *g = json_object_get(f, "geometry"), *props = json_object_get(f, "properties");
    json_t *weights = json_is_object(props) ? json_object_get(props, "weights") : NULL;
    if (weights && json_is_null(weights)) weights = NULL;
    snprintf(p, sizeof p, "%s%sgeometry", path, path[0] ? "." : "");
    if (!json_is_object(g))
        return WK_FAIL(R, WK_EINPUT, name, 0, "%s: a Feature without a geometry object", p);
    return gj_geometry(R, name, W, g, weights, p);
}

static wk_status gj_top(wk_run *R, const char *name, gj_walk *W, json_t *root) {
    const char *type = type_of(root);
    if (type && !strcmp(type, "FeatureCollection")) {
        json_t *fs = json_object_get(root, "features");
        if (!json_is_array(fs))
            return WK_FAIL(R, WK_EINPUT, name, 0, "FeatureCollection: \"features\" is not an array");
        for (size_t i = 0; i < json_array_size(fs); i++) {
            char p[64];
            snprintf(p, sizeof p, "features[%zu]", i);
            json_t *f = json_array_get(fs, i);
            const char *ft = type_of(f);
            if (!ft || strcmp(ft, "Feature"))
                return WK_FAIL(R, WK_EINPUT, name, 0, "%s: expected a Feature", p);
            if (gj_feature(R, name, W, f, p) != WK_OK) return R->err.code;
        }
        return WK_OK;
    }
    if (type && !strcmp(type, "Feature")) return gj_feature(R, name, W, root, "");
    return gj_geometry(R, name, W, root, NULL, "");
}

/* A finite number, or false. */
static bool gj_number(json_t *v, double *out) {
    if (!json_is_number(v)) return false;
    *out = json_number_value(v);
    return isfinite(*out);
}

static wk_status gj_collect(wk_run *R, const char *name, const gj_part *K, part_arrays *A) {
    json_t *rings = K->rings, *ws = K->weights;
    if (!json_is_array(rings) || json_array_size(rings) == 0)
        return WK_FAIL(R, WK_EINPUT, name, 0, "%s: expected a non-empty array of rings", K->path);
    size_t nr = json_array_size(rings);
    if (nr > WK_POLYGON_MAX_RINGS)
        return WK_FAIL(R, WK_EINPUT, name, 0, "%s: %zu rings, more than %u", K->path, nr,
                       WK_POLYGON_MAX_RINGS);
    if (ws && (!json_is_array(ws) || json_array_size(ws) != nr))
        return WK_FAIL(R, WK_EINPUT, name, 0,
                       "%s: \"weights\" must be an array with one array per ring (%zu)", K->path,
                       nr);
    A->weighted = ws != NULL;
    for (size_t r = 0; r < nr; r++) {
        json_t *ring = json_array_get(rings, r), *rw = ws ? json_array_get(ws, r) : NULL;
        size_t m = json_is_array(ring) ? json_array_size(ring) : 0;
        if (!json_is_array(ring) || m < 4)
            return WK_FAIL(R, WK_EINPUT, name, 0,
                           "%s[%zu]: a ring is an array of at least 4 positions (3 vertices and "
                           "the closing one)",
                           K->path, r);
        if (m - 1 > WK_POLYGON_MAX_N - A->n)
            return WK_FAIL(R, WK_EINPUT, name, 0, "%s: more than %u vertices", K->path,
                           WK_POLYGON_MAX_N);
        if (rw && (!json_is_array(rw) || json_array_size(rw) != m - 1))
            return WK_FAIL(R, WK_EINPUT, name, 0,
                           "%s[%zu]: its weights must be an array of %zu numbers (one per vertex, "
                           "the closing position not counted)",
                           K->path, r, m - 1);
        double x0 = 0, y0 = 0;
        for (size_t i = 0; i < m; i++) {
            json_t *pos = json_array_get(ring, i);
            double x, y, w = 1;
            size_t np = json_is_array(pos) ? json_array_size(pos) : 0;
            if (np < 2 || np > 3 || !gj_number(json_array_get(pos, 0), &x) ||
                !gj_number(json_array_get(pos, 1), &y) ||
                (np == 3 && !gj_number(json_array_get(pos, 2), &w)))
                return WK_FAIL(R, WK_EINPUT, name, 0,
                               "%s[%zu][%zu]: a position is an array of 2 or 3 finite numbers",
                               K->path, r, i);
            if (i == 0) x0 = x, y0 = y;
            if (i + 1 == m) {
                if (x != x0 || y != y0)
                    return WK_FAIL(R, WK_EINPUT, name, 0,
                                   "%s[%zu]: the ring is not closed (its last position must repeat "
                                   "the first)",
                                   K->path, r);
                break;
            }
            w = 1;
            if (rw && !gj_number(json_array_get(rw, i), &w))
                return WK_FAIL(R, WK_EINPUT, name, 0,
                               "%s: weights[%zu][%zu] is not a finite number", K->path, r, i);
            if (part_push(R, A, x, y, w, 0) != WK_OK) return R->err.code;
        }
        if (part_end_ring(R, A, (uint32_t)(m - 1)) != WK_OK) return R->err.code;
    }
    return WK_OK;
}

wk_status wk_polygon_read_geojson(wk_run *R, const char *buf, size_t len, const char *name,
                                  wk_polygon **out) {
    *out = NULL;
    if (!name) name = "";
    if (wk_read_utf8_bytes(R, buf, len, name, "GeoJSON") != WK_OK) return R->err.code;
    json_error_t jerr;
    /* Duplicate keys refused: a document must not be read one of two ways. */
    json_t *root = json_loadb(buf, len, JSON_REJECT_DUPLICATES | JSON_DECODE_INT_AS_REAL, &jerr);
    if (!root) {
        char text[JSON_ERROR_TEXT_LENGTH + 1]; /* jansson quotes the input: clean it */
        wk_read_clean_message(text, sizeof text, jerr.text);
        return WK_FAIL(R, WK_EINPUT, name, jerr.line > 0 ? jerr.line : 0, "JSON error: %s", text);
    }
    bool first_failure = R->err.code == WK_OK;
    part_arrays A = {0};
    gj_walk W = {0, R->opt.part == WK_NONE ? 0 : R->opt.part, {NULL, NULL, ""}};
    wk_status st = gj_top(R, name, &W, root);
    if (st == WK_OK) st = choose_part(R, name, W.count, "GeoJSON polygons, in document order", 0);
    if (st == WK_OK) st = gj_collect(R, name, &W.kept, &A);
    if (st == WK_OK) st = part_build(R, &A, name, false, out);
    part_free(R, &A);
    json_decref(root);
    if (st != WK_OK && first_failure && R->err.code != WK_OK) {
        /* Messages quote the document (a type name may hold any escaped
        ** character, a quote may be cut inside one): one line of UTF-8. */
        char tmp[sizeof R->err.msg];
        wk_read_clean_message(tmp, sizeof tmp, R->err.msg);
        memcpy(R->err.msg, tmp, sizeof tmp);
    }
    return st;
}

/* ==================================================================== WKT */

typedef struct wkt {
    const char *s;
    size_t len, i;
    long line;
    const char *name;
    wk_run *R;
    uint32_t count, want; /* polygons seen; the one to keep */
    part_arrays *A;
    long second_line;     /* where the second polygon begins */
} wkt;

static void wkt_skip(wkt *T) {
    while (T->i < T->len) {
        char c = T->s[T->i];
        if (c == '\n') T->line++;
        else if (c != ' ' && c != '\t' && c != '\r') break;
        T->i++;
    }
}

/* The next token quoted for a message. */
static void wkt_token(const wkt *T, char *buf, size_t size) {
    if (T->i >= T->len) {
        snprintf(buf, size, "the end of the input");
        return;
    }
    size_t k = 0;
    buf[k++] = '\'';
    for (size_t j = T->i; j < T->len && k + 2 < size && j < T->i + 24; j++) {
        unsigned char c = (unsigned char)T->s[j];
        if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || (j > T->i && strchr("(),", c))) break;
        buf[k++] = c < 0x80 ? (char)c : '?';
        if (strchr("(),", c)) break;
    }
    buf[k++] = '\'';
    buf[k] = '\0';
}

static wk_status wkt_expected(wkt *T, const char *what) {
    char tok[40];
    wkt_token(T, tok, sizeof tok);
    return WK_FAIL(T->R, WK_EINPUT, T->name, T->line, "WKT: expected %s, found %s", what, tok);
}

/* A keyword (letters), case-insensitive; false (nothing consumed) if the
** next word is not kw. */
static bool wkt_word(wkt *T, const char *kw) {
    wkt_skip(T);
    size_t k = strlen(kw);
    if (T->len - T->i < k) return false;
    for (size_t j = 0; j < k; j++)
        if (toupper((unsigned char)T->s[T->i + j]) != kw[j]) return false;
    if (T->i + k < T->len && isalpha((unsigned char)T->s[T->i + k])) return false;
    T->i += k;
    return true;
}

static bool wkt_char(wkt *T, char c) {
    wkt_skip(T);
    if (T->i < T->len && T->s[T->i] == c) {
        T->i++;
        return true;
    }
    return false;
}

static wk_status wkt_number(wkt *T, double *v) {
    wkt_skip(T);
    char num[80];
    size_t k = 0;
    while (T->i + k < T->len && strchr("0123456789+-.eE", T->s[T->i + k]) && T->s[T->i + k])
        if (++k >= sizeof num) break;
    if (k == 0 || k >= sizeof num) return wkt_expected(T, "a number");
    memcpy(num, T->s + T->i, k);
    num[k] = '\0';
    char *end;
    *v = strtod(num, &end);
    if (end != num + k || !isfinite(*v)) return wkt_expected(T, "a finite number");
    T->i += k;
    return WK_OK;
}

/* dims: 2 + Z + M of the geometry's tag; 0 untagged (2 or 3 numbers, Z). */
static wk_status wkt_polygon_text(wkt *T, int dims, bool has_m) {
    bool keep = T->count == T->want;
    if (T->count == 1) T->second_line = (wkt_skip(T), T->line);
    T->count++;
    if (wkt_word(T, "EMPTY"))
        return WK_FAIL(T->R, WK_EINPUT, T->name, T->line,
                       "WKT: an EMPTY polygon (polygon %u) has no skeleton", T->count - 1);
    if (!wkt_char(T, '(')) return wkt_expected(T, "'(' or EMPTY");
    do {
        if (!wkt_char(T, '(')) return wkt_expected(T, "'(' opening a ring");
        uint32_t m = 0;
        double x0 = 0, y0 = 0;
        long line0 = T->line;
        bool closed = false;
        do {
            double c[4] = {0, 0, 0, 0};
            long line = (wkt_skip(T), T->line);
            int n = 0;
            for (; n < 4; n++) {
                wkt_skip(T);
                if (n >= 2 && (T->i >= T->len || !strchr("0123456789+-.", T->s[T->i]))) break;
                if (wkt_number(T, &c[n]) != WK_OK) return T->R->err.code;
            }
            if ((dims && n != dims) || (!dims && n > 3))
                return WK_FAIL(T->R, WK_EINPUT, T->name, line,
                               "WKT: a point has %d coordinates, the geometry's dimension %d", n,
                               dims ? dims : 2);
            double w = has_m ? c[dims - 1] : 1;
            if (m == 0) x0 = c[0], y0 = c[1], line0 = line;
            closed = m > 0 && c[0] == x0 && c[1] == y0;
            if (!closed && keep) {
                if (m >= WK_POLYGON_MAX_N - T->A->n)
                    return WK_FAIL(T->R, WK_EINPUT, T->name, line, "more than %u vertices",
                                   WK_POLYGON_MAX_N);
                if (part_push(T->R, T->A, c[0], c[1], w, line) != WK_OK) return T->R->err.code;
            }
            if (!closed) m++;
            if (closed && !wkt_char(T, ')'))
                return WK_FAIL(T->R, WK_EINPUT, T->name, line,
                               "WKT: a point repeats the ring's first point (line %ld) before its "
                               "end",
                               line0);
        } while (!closed && wkt_char(T, ','));
        if (!closed) {
            if (!wkt_char(T, ')')) return wkt_expected(T, "',' or ')' in a ring");
            return WK_FAIL(T->R, WK_EINPUT, T->name, T->line,
                           "WKT: the ring is not closed (its last point must repeat the first, "
                           "line %ld)",
                           line0);
        }
        if (m < 3)
            return WK_FAIL(T->R, WK_EINPUT, T->name, T->line,
                           "WKT: a ring needs at least 3 vertices and the closing point (got %u)",
                           m);
        if (keep && part_end_ring(T->R, T->A, m) != WK_OK) return T->R->err.code;
        if (keep) T->A->weighted = has_m;
    } while (wkt_char(T, ','));
    if (!wkt_char(T, ')')) return wkt_expected(T, "',' or ')' after a ring");
    return WK_OK;
}

/* The dimension tag after the keyword: Z, M, ZM or nothing. */
static void wkt_dims(wkt *T, int *dims, bool *has_m) {
    *has_m = false;
    *dims = 0;
    if (wkt_word(T, "ZM")) *dims = 4, *has_m = true;
    else if (wkt_word(T, "Z")) *dims = 3;
    else if (wkt_word(T, "M")) *dims = 3, *has_m = true;
}

wk_status wk_polygon_read_wkt(wk_run *R, const char *buf, size_t len, const char *name,
                              wk_polygon **out) {
    *out = NULL;
    if (!name) name = "";
    if (wk_read_utf8_bytes(R, buf, len, name, "WKT") != WK_OK) return R->err.code;
    part_arrays A = {0};
    wkt T = {buf, len, 0, 1, name, R, 0, R->opt.part == WK_NONE ? 0 : R->opt.part, &A, 0};
    wk_status st = WK_OK;
    if (len >= 3 && (unsigned char)buf[0] == 0xEF && (unsigned char)buf[1] == 0xBB &&
        (unsigned char)buf[2] == 0xBF)
        T.i = 3;
    while (st == WK_OK && (wkt_skip(&T), T.i < T.len)) {
        int dims;
        bool has_m;
        if (wkt_word(&T, "SRID")) { /* EWKT (PostGIS): SRID=n; before a geometry, ignored */
            if (!wkt_char(&T, '=')) {
                st = wkt_expected(&T, "'=' after SRID");
                break;
            }
            wkt_skip(&T);
            size_t d = T.i;
            while (T.i < T.len && T.s[T.i] >= '0' && T.s[T.i] <= '9') T.i++;
            if (T.i == d || !wkt_char(&T, ';')) {
                st = wkt_expected(&T, "SRID=<digits>;");
                break;
            }
            continue;
        }
        if (wkt_word(&T, "POLYGON")) {
            wkt_dims(&T, &dims, &has_m);
            st = wkt_polygon_text(&T, dims, has_m);
        } else if (wkt_word(&T, "MULTIPOLYGON")) {
            wkt_dims(&T, &dims, &has_m);
            if (wkt_word(&T, "EMPTY")) {
                st = WK_FAIL(R, WK_EINPUT, name, T.line, "WKT: MULTIPOLYGON EMPTY holds no polygon");
                break;
            }
            if (!wkt_char(&T, '(')) {
                st = wkt_expected(&T, "'(' or EMPTY");
                break;
            }
            do st = wkt_polygon_text(&T, dims, has_m);
            while (st == WK_OK && wkt_char(&T, ','));
            if (st == WK_OK && !wkt_char(&T, ')')) st = wkt_expected(&T, "',' or ')' after a polygon");
        } else {
            st = wkt_expected(&T, "POLYGON or MULTIPOLYGON");
        }
    }
    if (st == WK_OK) st = choose_part(R, name, T.count, "WKT polygons, in document order",
                                          T.count > 1 ? T.second_line : T.line);
    if (st == WK_OK) st = part_build(R, &A, name, true, out);
    part_free(R, &A);
    return st;
}
