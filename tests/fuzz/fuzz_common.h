/*
** fuzz_common.h: what the libFuzzer targets share (tests/fuzz/README.md).
** Header-only, included by each target after defining _GNU_SOURCE.
**
**   finding(fmt, ...)        report a finding on stderr and abort (libFuzzer
**                            then saves the input as crash-<sha1>)
**   check_status(R, st)      the reader's status is one it may return
**                            (WK_OK, or WK_EINPUT recorded with the input's
**                            name, a line > 0 and a reason that is UTF-8
**                            text without control characters)
**   check_accepted(R, P)     an accepted polygon passes wk_polygon_validate
**                            and reads back unchanged from what the .wpoly
**                            writer makes of it
**   bytes_wpoly_refusable()  the independent byte rules of .wpoly (the
**                            README's): true if the reader must refuse
**   bytes_graphml_refusable()  the same for GraphML (strict UTF-8, no NUL,
**                            no control character but tab, CR, LF)
**   close_run(R, what)       wk_run_close with no tracked byte left (the
**                            run is strict: a leak aborts in wk_run_close)
*/
#ifndef WK_FUZZ_COMMON_H
#define WK_FUZZ_COMMON_H

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wskel.h"

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2), noreturn))
#endif
static inline void finding(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "wskel-fuzz: FINDING: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n");
    va_end(ap);
    fflush(stderr);
    abort();
}

/* Length of the strict UTF-8 sequence at s (1..4), 0 if invalid.  Written
** apart from the reader's on purpose: the targets check the reader. */
static inline size_t fz_utf8_len(const unsigned char *s, size_t n, uint32_t *cp) {
    static const uint32_t min[5] = {0, 0, 0x80, 0x800, 0x10000};
    size_t k = s[0] < 0x80          ? 1
               : (s[0] >> 5) == 6  ? 2
               : (s[0] >> 4) == 14 ? 3
               : (s[0] >> 3) == 30 ? 4
                                   : 0;
    if (k == 0 || k > n) return 0;
    uint32_t v = k == 1 ? s[0] : k == 2 ? s[0] & 31u : k == 3 ? s[0] & 15u : s[0] & 7u;
    for (size_t i = 1; i < k; i++) {
        if ((s[i] & 0xC0) != 0x80) return 0;
        v = v << 6 | (s[i] & 63u);
    }
    if (v < min[k] || v > 0x10FFFF || (v >= 0xD800 && v < 0xE000)) return 0;
    *cp = v;
    return k;
}

/* s is UTF-8 text without control characters (C0, DEL, C1). */
static inline int fz_clean_text(const char *s) {
    const unsigned char *u = (const unsigned char *)s;
    size_t n = strlen(s);
    for (size_t i = 0; i < n;) {
        uint32_t cp;
        size_t k = fz_utf8_len(u + i, n - i, &cp);
        if (k == 0 || cp < 0x20 || (cp >= 0x7F && cp <= 0x9F)) return 0;
        i += k;
    }
    return 1;
}

/* GeoJSON's exception to the line rule: jansson keeps no positions for
** values, so a rejection after parsing names the JSON path instead (line 0);
** a byte fault or a JSON syntax error must still carry its line.  For a
** GeoJSON rejection without a line: a finding if it is one of those, else
** line 1 stands in so that check_status's other rules still apply. */
static inline void geojson_line_exception(wk_run *R, wk_status st) {
    if (st != WK_EINPUT || R->err.input_line > 0) return;
    if (!strncmp(R->err.msg, "JSON error", 10) || !strncmp(R->err.msg, "column", 6))
        finding("a syntax or byte error without a line: %s", R->err.msg);
    R->err.input_line = 1;
}

static inline void check_status(const wk_run *R, wk_status st, const wk_polygon *P,
                                const char *name) {
    if (st != R->err.code)
        finding("reader returned %s but recorded %s (%s)", wk_status_name(st),
                wk_status_name(R->err.code), R->err.msg);
    if (st == WK_OK) {
        if (!P) finding("reader returned WK_OK without a polygon");
        return;
    }
    if (P) finding("reader returned %s with a polygon", wk_status_name(st));
    if (st != WK_EINPUT)
        finding("reader returned %s (%s): only WK_OK or WK_EINPUT expected on small inputs",
                wk_status_name(st), R->err.msg);
    if (strcmp(R->err.input, name) != 0)
        finding("rejection names input '%s', not '%s' (%s)", R->err.input, name, R->err.msg);
    if (R->err.input_line <= 0)
        finding("rejection without a line number: %s", R->err.msg);
    if (!R->err.msg[0]) finding("rejection without a reason");
    if (!fz_clean_text(R->err.msg))
        finding("rejection reason is not clean UTF-8 text: '%s'", R->err.msg);
}

static inline void close_run(wk_run *R, const char *what) {
    size_t live = wk_run_close(R); /* strict: aborts itself on a leak */
    if (live) finding("%s: %zu tracked bytes live at close", what, live);
}

/* The accepted polygon passes the polygon checks again and survives the
** .wpoly writer and reader unchanged. */
/* An accepted PSLG (engine/pslg.c): every graph edge is stored twice (its
** two sides), every cap sits between two corners of one node, the ids are
** in range. */
static inline void check_accepted_pslg(const wk_polygon *P) {
    if (P->n < 4 || !P->dir || !P->corner_vertex || !P->edge_of)
        finding("accepted a PSLG of %u corners without its arrays", P->n);
    uint32_t *seen = calloc(P->n_graph_edges + 1, sizeof *seen);
    if (!seen) abort();
    for (uint32_t i = 0; i < P->n; i++) {
        uint32_t e = P->edge_of[i], nx = wk_polygon_next(P, i);
        if (P->corner_vertex[i] >= P->n_graph_vertices) finding("corner %u: node out of range", i);
        if (e == WK_NONE) {
            if (P->corner_vertex[i] != P->corner_vertex[nx] || P->p[i].x != P->p[nx].x ||
                P->p[i].y != P->p[nx].y)
                finding("cap %u does not join two corners of one node", i);
        } else if (e >= P->n_graph_edges) {
            finding("stored edge %u: graph edge %u out of range", i, e);
        } else {
            seen[e]++;
        }
    }
    for (uint32_t e = 0; e < P->n_graph_edges; e++)
        if (seen[e] != 2) finding("graph edge %u stored %u times, not twice", e, seen[e]);
    free(seen);
}

static inline void check_accepted(wk_run *R, const wk_polygon *P) {
    if (P->pslg) { /* no polygon: its own checks, no .wpoly round trip */
        check_accepted_pslg(P);
        return;
    }
    if (P->n < 3) finding("accepted a polygon of %u vertices", P->n);
    if (wk_polygon_validate(R, P) != WK_OK)
        finding("accepted polygon fails wk_polygon_validate: %s", R->err.msg);
    char *text = NULL;
    size_t len = 0;
    FILE *w = open_memstream(&text, &len);
    if (!w) abort();
    if (wk_polygon_write_wpoly(R, w, P) != WK_OK) finding("writer failed: %s", R->err.msg);
    fclose(w);
    FILE *f = fmemopen(text, len, "rb");
    if (!f) abort();
    wk_polygon *Q = NULL;
    wk_status st = wk_polygon_read_wpoly(R, f, "roundtrip", &Q);
    fclose(f);
    if (st != WK_OK) finding("the written polygon does not read back: %s\n%s", R->err.msg, text);
    if (Q->n != P->n || Q->reversed)
        finding("round trip: n %u -> %u, reversed %d", P->n, Q->n, Q->reversed);
    for (uint32_t i = 0; i < P->n; i++)
        if (Q->p[i].x != P->p[i].x || Q->p[i].y != P->p[i].y || Q->w[i] != P->w[i])
            finding("round trip changed vertex %u: (%.17g %.17g %.17g) -> (%.17g %.17g %.17g)", i,
                    P->p[i].x, P->p[i].y, P->w[i], Q->p[i].x, Q->p[i].y, Q->w[i]);
    wk_polygon_free(R, Q);
    free(text);
}

/* The .wpoly byte rules, stated independently of the reader: lines end in
** LF or CRLF; no byte 0x00-0x1F but tab, nor 0x7F, anywhere; outside
** comment lines (first non-blank '#') no byte >= 0x80; a UTF-8 byte order
** mark may open the file.  True: the reader must refuse the input. */
static inline int bytes_wpoly_refusable(const uint8_t *d, size_t n) {
    size_t i = 0;
    if (n >= 3 && d[0] == 0xEF && d[1] == 0xBB && d[2] == 0xBF) i = 3;
    while (i < n) {
        size_t e = i;
        while (e < n && d[e] != '\n') e++;
        size_t end = e;
        if (end > i && d[end - 1] == '\r') end--;
        size_t f = i;
        while (f < end && (d[f] == ' ' || d[f] == '\t')) f++;
        int comment = f < end && d[f] == '#';
        for (size_t k = i; k < end; k++) {
            if ((d[k] < 0x20 && d[k] != '\t') || d[k] == 0x7F) return 1;
            if (d[k] >= 0x80 && !comment) return 1;
        }
        i = e + 1;
    }
    return 0;
}

/* The GraphML byte rules: strict UTF-8; no C0 control but tab, CR, LF; no
** DEL, no C1 control. */
static inline int bytes_graphml_refusable(const uint8_t *d, size_t n) {
    for (size_t i = 0; i < n;) {
        uint32_t cp;
        size_t k = fz_utf8_len(d + i, n - i, &cp);
        if (k == 0) return 1;
        if ((cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') || (cp >= 0x7F && cp <= 0x9F))
            return 1;
        i += k;
    }
    return 0;
}

/* Independent reading of an accepted .wpoly (after bytes_wpoly_refusable
** said the bytes are fine): per ring a count, then x y [w] per line,
** compared with P in input numbering (ring k's count is its size in P).
** strtod as the format says. */
static inline void check_wpoly_values(const uint8_t *d, size_t n, const wk_polygon *P) {
    char *buf = malloc(n + 1);
    if (!buf) abort();
    memcpy(buf, d, n);
    buf[n] = '\0';
    char *s = buf;
    if (n >= 3 && memcmp(s, "\xEF\xBB\xBF", 3) == 0) s += 3;
    long count = -1, got = 0, in_ring = 0;
    uint32_t ring = 0;
    /* Stored vertex of each input vertex, stored edge of each input edge. */
    uint32_t *vj = calloc(P->n, sizeof *vj), *ej = calloc(P->n, sizeof *ej);
    if (!vj || !ej) abort();
    for (uint32_t j = 0; j < P->n; j++) {
        vj[P->input_index[j]] = j;
        ej[wk_polygon_input_edge(P, j)] = j;
    }
    for (char *line = s; line;) {
        char *nl = strchr(line, '\n'), *next = nl ? nl + 1 : NULL;
        if (nl) *nl = '\0';
        size_t len = strlen(line);
        if (len && line[len - 1] == '\r') line[--len] = '\0';
        char *t = line;
        while (*t == ' ' || *t == '\t') t++;
        if (*t && *t != '#') {
            char *tok[4];
            int k = 0;
            for (char *c = strtok(t, " \t"); c; c = strtok(NULL, " \t")) {
                if (k == 4) finding("accepted a line with more than 3 fields");
                tok[k++] = c;
            }
            if (count < 0 || in_ring == count) {
                if (k != 1) finding("accepted a count line of %d fields", k);
                if (ring >= P->n_rings) finding("accepted more rings than the polygon's %u",
                                                P->n_rings);
                count = strtol(tok[0], NULL, 10);
                uint32_t size = P->ring_start[ring + 1] - P->ring_start[ring];
                if ((uint32_t)count != size)
                    finding("count %ld for ring %u, polygon's ring has %u", count, ring, size);
                ring++;
                in_ring = 0;
            } else {
                if (k < 2 || k > 3) finding("accepted a vertex line of %d fields", k);
                in_ring++;
                double v[3] = {0, 0, 1};
                for (int i = 0; i < k; i++) {
                    char *end;
                    v[i] = strtod(tok[i], &end);
                    if (*end) finding("accepted a token '%s' strtod stops in", tok[i]);
                }
                uint32_t j = vj[got], e = ej[got];
                if (P->p[j].x != v[0] || P->p[j].y != v[1] || P->w[e] != v[2])
                    finding("input vertex %ld is (%.17g %.17g w %.17g) in the file, read as "
                            "(%.17g %.17g w %.17g)",
                            got, v[0], v[1], v[2], P->p[j].x, P->p[j].y, P->w[e]);
                got++;
            }
        }
        line = next;
    }
    if (got != (long)P->n) finding("%ld vertex lines, polygon has %u", got, P->n);
    if (ring != P->n_rings) finding("%u rings in the file, polygon has %u", ring, P->n_rings);
    free(vj);
    free(ej);
    free(buf);
}

#endif
