/*
** polygon_read.c: the polygon readers, .wpoly and GraphML, and the choice of
** reader by content (GeoJSON and WKT: polygon_read_gis.c).
**
** .wpoly, line oriented:
**     # comment lines start with '#' (after optional blanks)
**     n                  vertex count, a positive integer, alone on its line
**     x y [w]            n lines; w (the weight of the edge from this vertex
**                        to the next) defaults to 1
**     m                  optional further rings (holes), each its own count
**     x y [w]            line and m vertex lines; the first ring is the
**                        outer boundary; any ring in either orientation
** Blank lines are ignored anywhere.  Numbers are C strtod syntax, and must be
** finite.  Every message carries the line it is about.
** Bytes: lines end in LF or CRLF; the blanks are space and tab.  No NUL byte
** and no other control character (0x01-0x1F but tab, LF and a CR before LF;
** 0x7F) may appear anywhere, comments included.  Outside comments the text is
** ASCII (a number is ASCII, so any other byte is a stray one); comments may
** hold any other byte, UTF-8 or not.  A UTF-8 byte order mark may open the
** file.  The byte checks run line by line as the file is parsed, so the
** first fault in the file is the one reported, with its line and column.
**
** GraphML (Salzburg database, surfer2, monos): <key> elements map attribute
** names to key ids; nodes carry <data key=ID> for "vertex-coordinate-x" and
** "vertex-coordinate-y", edges optionally for "edge-weight" (default: the
** key's <default>, else 1).  The edges must form disjoint simple cycles
** through all nodes (every node on exactly two edges): one is a simple
** polygon, several a polygon with holes, the cycle of largest area being the
** outer boundary.  Each cycle is walked from its first node in document
** order, leaving along that node's first edge in document order; input
** numbering is the outer cycle's vertices, then the holes' in the order of
** their first nodes in the document.
**
** Both readers only collect arrays and leave every geometric check to
** wk_polygon_from_arrays, passing the input line of each vertex (for GraphML
** the line of its <node> element) so its messages point into the file.
**
** GraphML bytes: the document must be UTF-8 (strictly: no overlong forms, no
** surrogates, nothing above U+10FFFF), comments included, with no NUL byte
** and no control character but tab, CR and LF (nor DEL or the C1 controls
** U+0080-U+009F); these are checked before libxml2 sees the text, with line
** and column, and a declared encoding other than UTF-8 (or US-ASCII) is
** refused.  Ambiguous documents are refused rather than read one way: two
** <key>s for one attribute, a second <graph>, a node or edge with two <data>
** for one key.
**
** Memory: the file text and all arrays come from the run's allocator.
** libxml2 allocates its document tree with its own allocator (changing that
** would mean a process-wide xmlMemSetup, i.e. a mutable global); the tree is
** freed before the reader returns, so it never outlives a call.
*/
#include "read_text.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlerror.h>

/* ---- whole-file input ---- */

typedef struct text {
    char *buf;  /* NUL-terminated: buf[len] == 0 */
    size_t len;
    size_t cap; /* allocated bytes, for the free */
} text;

static void text_free(wk_run *R, text *t) {
    wk_realloc(R, t->buf, t->cap, 0);
    t->buf = NULL;
    t->len = t->cap = 0;
}

/* Reads f to its end.  On failure t is empty and R->err says why. */
static wk_status slurp(wk_run *R, FILE *f, const char *name, text *t) {
    errno = 0;
    t->len = 0;
    t->cap = 1 << 16;
    t->buf = wk_realloc(R, NULL, 0, t->cap);
    if (!t->buf) {
        t->cap = 0;
        return WK_ENOMEM;
    }
    for (;;) {
        if (t->cap - t->len < 2) {
            char *q = wk_realloc(R, t->buf, t->cap, 2 * t->cap);
            if (!q) {
                text_free(R, t);
                return WK_ENOMEM;
            }
            t->buf = q;
            t->cap *= 2;
        }
        size_t got = fread(t->buf + t->len, 1, t->cap - 1 - t->len, f);
        t->len += got;
        if (got == 0) break;
    }
    if (ferror(f)) {
        int e = errno;
        text_free(R, t);
        return WK_FAIL(R, WK_EINPUT, name, 0, "read error: %s", e ? strerror(e) : "unknown");
    }
    t->buf[t->len] = '\0';
    return WK_OK;
}

/* ---- numbers ---- */

/* The blanks of a .wpoly line (CR only ends a line, before LF; \v and \f
** are refused as control characters). */
static bool is_blank(char c) { return c == ' ' || c == '\t'; }

/* ---- bytes ---- */

/* Length of the strict UTF-8 sequence at s[0..len) (1 to 4), with its code
** point in *cp; 0 if the bytes there are not one (a stray continuation byte,
** a truncated sequence, an overlong form, a surrogate, above U+10FFFF, or
** 0xC0, 0xC1, 0xF5-0xFF). */
static size_t utf8_seq(const unsigned char *s, size_t len, uint32_t *cp) {
    unsigned char c = s[0];
    size_t k;
    uint32_t v, min;
    if (c < 0x80) {
        *cp = c;
        return 1;
    } else if (c >= 0xC2 && c <= 0xDF) {
        k = 2, v = c & 0x1Fu, min = 0x80;
    } else if (c >= 0xE0 && c <= 0xEF) {
        k = 3, v = c & 0x0Fu, min = 0x800;
    } else if (c >= 0xF0 && c <= 0xF4) {
        k = 4, v = c & 0x07u, min = 0x10000;
    } else {
        return 0;
    }
    if (len < k) return 0;
    for (size_t i = 1; i < k; i++) {
        if ((s[i] & 0xC0) != 0x80) return 0;
        v = (v << 6) | (s[i] & 0x3Fu);
    }
    if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF)) return 0;
    *cp = v;
    return k;
}

/* A control character: C0 (0x00-0x1F), DEL and the C1 controls. */
static bool is_control(uint32_t cp) { return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F); }

/* Describes a refused byte or character into why: NUL, a control
** character, a lone CR. */
static void describe_control(uint32_t cp, char *why, size_t size) {
    if (cp == 0)
        snprintf(why, size, "NUL byte");
    else if (cp == '\r')
        snprintf(why, size, "carriage return (0x0D) not followed by a line feed (lines end in "
                            "LF or CRLF)");
    else if (cp < 0x80)
        snprintf(why, size, "control character 0x%02X", (unsigned)cp);
    else
        snprintf(why, size, "control character U+%04X", (unsigned)cp);
}

/* Text m as one line of UTF-8 text in buf (for messages: libxml2's hold
** newlines, and quote the input, as do ours): runs of blanks and control
** characters become one space, bytes that are no UTF-8 (a quote cut inside
** a character) '?', and no blank is left at either end. */
void wk_read_clean_message(char *buf, size_t size, const char *m) {
    const unsigned char *u = (const unsigned char *)m;
    size_t len = strlen(m), n = 0;
    bool space = false;
    for (size_t i = 0; i < len && n + 5 < size;) {
        uint32_t cp;
        size_t k = utf8_seq(u + i, len - i, &cp);
        if (k != 0 && (cp == ' ' || is_control(cp))) {
            space = n > 0;
            i += k;
            continue;
        }
        if (space) buf[n++] = ' ';
        space = false;
        if (k == 0) {
            buf[n++] = '?';
            i++;
        } else {
            memcpy(buf + n, u + i, k);
            n += k;
            i += k;
        }
    }
    buf[n] = '\0';
}

/* A UTF-16 byte order mark (either order): the file is UTF-16, which
** neither reader takes; said as such rather than as a stray byte 0xFF. */
static bool is_utf16_bom(const char *s, size_t len) {
    const unsigned char *u = (const unsigned char *)s;
    return len >= 2 && ((u[0] == 0xFF && u[1] == 0xFE) || (u[0] == 0xFE && u[1] == 0xFF));
}
static wk_status utf16_refused(wk_run *R, const char *name) {
    return WK_FAIL(R, WK_EINPUT, name, 1,
                   "column 1: UTF-16 byte order mark; the input must be UTF-8 (or ASCII)");
}

/* Checks the bytes of one .wpoly line s[0..len) (its LF, and the CR of a
** CRLF, excluded).  Outside comments only printable ASCII and tab; in a
** comment also any byte >= 0x80.  On a fault: false, *col the 1-based column
** of the offending byte and why the reason. */
static bool wpoly_line_bytes(const char *s, size_t len, bool comment, size_t *col, char *why,
                             size_t size) {
    const unsigned char *u = (const unsigned char *)s;
    for (size_t i = 0; i < len; i++) {
        unsigned char c = u[i];
        if (c >= 0x20 && c < 0x7F) continue;
        if (c == '\t') continue;
        *col = i + 1;
        if (c < 0x80) {
            describe_control(c, why, size);
            return false;
        }
        if (comment) continue;
        uint32_t cp;
        size_t k = utf8_seq(u + i, len - i, &cp);
        if (k == 0)
            snprintf(why, size, "byte 0x%02X is not UTF-8 (outside comments the text is ASCII)", c);
        else if (is_control(cp))
            describe_control(cp, why, size);
        else
            snprintf(why, size,
                     "non-ASCII character U+%04X (outside comments the text is ASCII: numbers, "
                     "blanks)",
                     (unsigned)cp);
        return false;
    }
    return true;
}

/* The whole of s[0..len) must be one finite number. */
static bool parse_number(const char *s, size_t len, double *out) {
    if (len == 0) return false;
    char *end;
    double v = strtod(s, &end);
    if (end != s + len || !isfinite(v)) return false;
    *out = v;
    return true;
}

/* ---- .wpoly ---- */

#define MAX_TOKENS 4 /* x y w, and one more to say "too many" */

/* Splits the NUL-terminated line at blanks, terminating each token in place.
** Returns the number of tokens (may exceed MAX_TOKENS; only the first
** MAX_TOKENS are stored). */
static int tokenize(char *s, char **tok, size_t *len) {
    int count = 0;
    for (;;) {
        while (is_blank(*s)) s++;
        if (!*s) return count;
        char *start = s;
        while (*s && !is_blank(*s)) s++;
        if (count < MAX_TOKENS) {
            tok[count] = start;
            len[count] = (size_t)(s - start);
        }
        count++;
        if (*s) *s++ = '\0';
    }
}

/* Parses the vertex count; false if the token is not a positive integer.
** Values above WK_POLYGON_MAX_N saturate at WK_POLYGON_MAX_N + 1. */
static bool parse_count(const char *s, size_t len, uint32_t *n) {
    uint64_t v = 0;
    if (len == 0) return false;
    for (size_t i = 0; i < len; i++) {
        if (s[i] < '0' || s[i] > '9') return false;
        v = v * 10 + (uint64_t)(s[i] - '0');
        if (v > WK_POLYGON_MAX_N) v = (uint64_t)WK_POLYGON_MAX_N + 1;
    }
    if (v == 0) return false;
    *n = (uint32_t)v;
    return true;
}

typedef struct vertex_arrays {
    uint32_t cap;
    double *x, *y, *w;
    long *line;
} vertex_arrays;

static wk_status vertex_arrays_alloc(wk_run *R, vertex_arrays *A, uint32_t cap) {
    A->cap = cap;
    A->x = WK_NEW_ARRAY(R, double, cap);
    A->y = WK_NEW_ARRAY(R, double, cap);
    A->w = WK_NEW_ARRAY(R, double, cap);
    A->line = WK_NEW_ARRAY(R, long, cap);
    return A->x && A->y && A->w && A->line ? WK_OK : WK_ENOMEM;
}

static void vertex_arrays_free(wk_run *R, vertex_arrays *A) {
    WK_FREE_ARRAY(R, A->x, A->cap);
    WK_FREE_ARRAY(R, A->y, A->cap);
    WK_FREE_ARRAY(R, A->w, A->cap);
    WK_FREE_ARRAY(R, A->line, A->cap);
}

/* Parses t (modified in place: tokens are terminated). */
static wk_status parse_wpoly(wk_run *R, text *t, const char *name, wk_polygon **out) {
    vertex_arrays A = {0, NULL, NULL, NULL, NULL};
    wk_status st = WK_OK;
    uint32_t m = 0, got = 0, total = 0; /* this ring's count, its vertices so far, all so far */
    uint32_t *rings = NULL, n_rings = 0, cap_rings = 0;
    long count_line = 0, ln = 0;
    char *s = t->buf, *end = t->buf + t->len;
    if (is_utf16_bom(s, t->len)) return utf16_refused(R, name);
    if (t->len >= 3 && memcmp(s, "\xEF\xBB\xBF", 3) == 0) s += 3; /* UTF-8 byte order mark */
    char *tok[MAX_TOKENS];
    size_t tl[MAX_TOKENS];

    /* The number of lines bounds the number of vertex lines, so a count of
    ** 50 million on top of a three-line file allocates three entries. */
    uint64_t nlines = 1;
    for (const char *c = s; (c = memchr(c, '\n', (size_t)(end - c))) != NULL; c++) nlines++;

    while (s < end || (s == end && ln == 0)) {
        char *nl = memchr(s, '\n', (size_t)(end - s));
        char *eol = nl ? nl : end;
        char *line = s;
        s = eol + 1;
        ln++;
        if (eol > line && eol[-1] == '\r') eol--; /* CRLF */
        *eol = '\0';
        /* The line is line[0..eol); it may hold NUL bytes, which the check
        ** below refuses before any string function looks at it. */
        char *first = line;
        while (first < eol && is_blank(*first)) first++;
        bool comment = first < eol && *first == '#';
        size_t col;
        char why[160];
        if (!wpoly_line_bytes(line, (size_t)(eol - line), comment, &col, why, sizeof why)) {
            st = WK_FAIL(R, WK_EINPUT, name, ln, "column %zu: %s", col, why);
            goto done;
        }
        line = first;
        if (comment || line == eol) {
            if (!nl) break;
            continue;
        }
        int k = tokenize(line, tok, tl);
        if (got == m) {
            /* a count line: the first ring's (the outer boundary) or a hole's */
            if (n_rings > 0 && k != 1) {
                st = WK_FAIL(R, WK_EINPUT, name, ln,
                             "extra line: the count on line %ld announces %u vertices (a hole "
                             "starts with its own vertex count line)",
                             count_line, m);
                goto done;
            }
            count_line = ln;
            if (k != 1 || !parse_count(tok[0], tl[0], &m)) {
                st = WK_FAIL(R, WK_EINPUT, name, ln,
                             "expected the %s, a positive integer alone on its line "
                             "(got '%.40s'%s)",
                             n_rings == 0 ? "vertex count" : "vertex count of a hole", tok[0],
                             k > 1 ? " and more" : "");
                goto done;
            }
            if (m > WK_POLYGON_MAX_N - total) {
                st = WK_FAIL(R, WK_EINPUT, name, ln,
                             "too many vertices (%.40s%s; the limit is %u)", tok[0],
                             n_rings ? " more" : "", WK_POLYGON_MAX_N);
                goto done;
            }
            if (m < 3) {
                st = n_rings == 0 ? WK_FAIL(R, WK_EINPUT, name, ln,
                                            "polygon needs at least 3 vertices (got %u)", m)
                                  : WK_FAIL(R, WK_EINPUT, name, ln,
                                            "hole %u needs at least 3 vertices (got %u)", n_rings,
                                            m);
                goto done;
            }
            if (n_rings == WK_POLYGON_MAX_RINGS) {
                st = WK_FAIL(R, WK_EINPUT, name, ln, "too many rings (the limit is %u)",
                             WK_POLYGON_MAX_RINGS);
                goto done;
            }
            if ((st = WK_GROW(R, rings, cap_rings, n_rings + 1)) != WK_OK) goto done;
            rings[n_rings++] = m;
            got = 0;
            if (!A.x) {
                uint64_t cap = nlines < WK_POLYGON_MAX_N ? nlines : WK_POLYGON_MAX_N;
                if ((st = vertex_arrays_alloc(R, &A, (uint32_t)cap)) != WK_OK) goto done;
            }
        } else {
            if (k < 2 || k > 3) {
                st = WK_FAIL(R, WK_EINPUT, name, ln,
                             "expected 'x y [weight]' (got %d field%s)", k, k == 1 ? "" : "s");
                goto done;
            }
            double v[3] = {0, 0, 1.0};
            for (int i = 0; i < k; i++)
                if (!parse_number(tok[i], tl[i], &v[i])) {
                    st = WK_FAIL(R, WK_EINPUT, name, ln, "'%.40s%s' is not a finite number",
                                 tok[i], tl[i] > 40 ? "..." : "");
                    goto done;
                }
            if (k == 3 && R->opt.angles &&
                (st = wk_weight_of_angle(R, v[2], name, ln, &v[2])) != WK_OK)
                goto done;
            /* total < nlines: every vertex has its own line */
            A.x[total] = v[0];
            A.y[total] = v[1];
            A.w[total] = v[2];
            A.line[total] = ln;
            got++;
            total++;
        }
        if (!nl) break;
    }
    if (n_rings == 0) {
        st = WK_FAIL(R, WK_EINPUT, name, ln > 0 ? ln : 1,
                     "no vertex count: the input is empty or only comments");
        goto done;
    }
    if (got < m) {
        st = WK_FAIL(R, WK_EINPUT, name, count_line,
                     "the count announces %u vertices but only %u vertex line%s follow%s", m,
                     got, got == 1 ? "" : "s", got == 1 ? "s" : "");
        goto done;
    }
    st = wk_polygon_from_rings(R, n_rings, rings, A.x, A.y, A.w, name, A.line, out);
done:
    vertex_arrays_free(R, &A);
    if (rings) WK_FREE_ARRAY(R, rings, cap_rings);
    return st;
}

wk_status wk_polygon_read_wpoly(wk_run *R, FILE *f, const char *name, wk_polygon **out) {
    *out = NULL;
    text t;
    wk_status st = slurp(R, f, name, &t);
    if (st != WK_OK) return st;
    st = parse_wpoly(R, &t, name, out);
    text_free(R, &t);
    return st;
}

/* ---- GraphML ----
** Strings are read from the tree in place (xstr.s borrowed) whenever the
** value is a single text node, which is every value without entity
** references; only the others are copied (xstr.copy, xmlFree'd).  With a
** copy per attribute, a million-vertex file spent seconds in malloc. */

typedef struct xstr {
    const xmlChar *s; /* NULL: absent */
    xmlChar *copy;    /* owned copy backing s, or NULL when s is borrowed */
} xstr;

static void xstr_free(xstr *v) {
    xmlFree(v->copy);
    v->copy = NULL;
    v->s = NULL;
}

static bool is_element(const xmlNode *e, const char *local) {
    return e->type == XML_ELEMENT_NODE && xmlStrEqual(e->name, BAD_CAST local);
}

/* Attribute `name` without namespace (as xmlGetProp).  If libxml2 cannot
** allocate a needed copy, the value reads as "" and fails as input. */
static xstr attr_value(xmlNode *e, const char *name) {
    xstr v = {NULL, NULL};
    for (xmlAttr *a = e->properties; a; a = a->next) {
        if (a->ns || !xmlStrEqual(a->name, BAD_CAST name)) continue;
        xmlNode *c = a->children;
        if (c && c->type == XML_TEXT_NODE && !c->next && c->content) {
            v.s = c->content;
        } else {
            v.copy = xmlNodeListGetString(e->doc, c, 1);
            v.s = v.copy ? v.copy : BAD_CAST "";
        }
        return v;
    }
    return v;
}

static bool attr_is(xmlNode *e, const char *name, const xmlChar *value) {
    xstr v = attr_value(e, name);
    bool eq = v.s && xmlStrEqual(v.s, value);
    xstr_free(&v);
    return eq;
}

/* The text content of element e (never NULL). */
static xstr text_value(xmlNode *e) {
    xstr v = {BAD_CAST "", NULL};
    xmlNode *c = e->children;
    if (!c) return v;
    if (c->type == XML_TEXT_NODE && !c->next && c->content) {
        v.s = c->content;
    } else {
        v.copy = xmlNodeGetContent(e);
        if (v.copy) v.s = v.copy;
    }
    return v;
}

/* One GraphML attribute we read: its key id and default text. */
typedef struct gkey {
    xstr id;   /* id.s NULL if the file has no such key */
    xstr dflt; /* <default> text, dflt.s NULL if none */
} gkey;

static void gkey_clear(gkey *k) {
    xstr_free(&k->id);
    xstr_free(&k->dflt);
}

/* Finds <key attr.name=NAME for=FOR|all id=...> among the children of root.
** Returns NULL, or the second such key (the file is ambiguous; *first is
** then the first one). */
static xmlNode *find_key(xmlNode *root, const char *attr_name, const char *for_what, gkey *k,
                         xmlNode **first) {
    k->id = k->dflt = (xstr){NULL, NULL};
    *first = NULL;
    for (xmlNode *c = root->children; c; c = c->next) {
        if (!is_element(c, "key") || !attr_is(c, "attr.name", BAD_CAST attr_name)) continue;
        xstr f = attr_value(c, "for");
        bool ok = !f.s || xmlStrEqual(f.s, BAD_CAST for_what) || xmlStrEqual(f.s, BAD_CAST "all");
        xstr_free(&f);
        if (!ok) continue;
        xstr id = attr_value(c, "id");
        if (!id.s) continue;
        if (*first) {
            xstr_free(&id);
            return c;
        }
        *first = c;
        k->id = id;
        for (xmlNode *d = c->children; d; d = d->next)
            if (is_element(d, "default")) {
                k->dflt = text_value(d);
                break;
            }
    }
    return NULL;
}

/* At most max bytes of s into buf (size > max), cut before a partial UTF-8
** sequence so that a message stays UTF-8. */
static void clip_utf8(char *buf, size_t size, const char *s, size_t max) {
    size_t n = strlen(s);
    if (n > max) {
        n = max;
        while (n > 0 && ((unsigned char)s[n] & 0xC0) == 0x80) n--;
    }
    if (n >= size) n = size - 1;
    memcpy(buf, s, n);
    buf[n] = '\0';
}

static bool parse_text_number(const xmlChar *s, double *out) {
    const char *b = (const char *)s;
    while (*b == ' ' || *b == '\t' || *b == '\n' || *b == '\r') b++;
    size_t len = strlen(b);
    while (len > 0 && (b[len - 1] == ' ' || b[len - 1] == '\t' || b[len - 1] == '\n' ||
                       b[len - 1] == '\r'))
        len--;
    if (len == 0 || len > 1000) return false;
    char tmp[1001];
    memcpy(tmp, b, len);
    tmp[len] = '\0';
    return parse_number(tmp, len, out);
}

/* K's value at element e, from its <data key=K> child or else K's default:
** 1 when *v was set, 0 when there is neither, -1 when the text is not a
** finite number (then bad holds it), -2 when e has two <data key=K> (then
** *where is the second, and bad holds the line of the first).  *where: the
** element the value came from (for the line number). */
static int key_number(xmlNode *e, const gkey *K, double *v, xmlNode **where, char *bad,
                      size_t bad_size) {
    *where = e;
    if (!K->id.s) return 0;
    xstr t = {NULL, NULL};
    for (xmlNode *d = e->children; d; d = d->next)
        if (is_element(d, "data") && attr_is(d, "key", K->id.s)) {
            if (t.s) {
                snprintf(bad, bad_size, "%ld", xmlGetLineNo(*where));
                *where = d;
                xstr_free(&t);
                return -2;
            }
            *where = d;
            t = text_value(d);
        }
    if (!t.s) {
        if (!K->dflt.s) return 0;
        t.s = K->dflt.s; /* borrowed from K */
    }
    bool ok = parse_text_number(t.s, v);
    if (!ok) {
        char one_line[64];
        wk_read_clean_message(one_line, sizeof one_line, (const char *)t.s);
        clip_utf8(bad, bad_size, one_line, 40);
    }
    xstr_free(&t);
    return ok ? 1 : -1;
}

/* "node 'n3'" / "edge 'e3'" or, without an id, "edge 7 (from 'a' to 'b')".
** Only for messages. */
static const char *describe_element(xmlNode *e, const char *kind, uint32_t index, char *buf,
                                    size_t size) {
    xstr id = attr_value(e, "id");
    if (id.s) {
        snprintf(buf, size, "%s '%.60s'", kind, (const char *)id.s);
    } else if (is_element(e, "edge")) {
        xstr s = attr_value(e, "source"), t = attr_value(e, "target");
        snprintf(buf, size, "%s %u (from '%.40s' to '%.40s')", kind, index,
                 s.s ? (const char *)s.s : "?", t.s ? (const char *)t.s : "?");
        xstr_free(&s);
        xstr_free(&t);
    } else {
        snprintf(buf, size, "%s %u", kind, index);
    }
    xstr_free(&id);
    return buf;
}

/* Node ids sorted for lookup: merge sort of node indices by id. */
static uint32_t *sort_ids(const xstr *id, uint32_t *a, uint32_t *tmp, uint32_t n) {
    for (size_t width = 1; width < n; width *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * width) {
            size_t mid = lo + width < n ? lo + width : n;
            size_t hi = lo + 2 * width < n ? lo + 2 * width : n;
            size_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi)
                tmp[k++] = xmlStrcmp(id[a[j]].s, id[a[i]].s) < 0 ? a[j++] : a[i++];
            while (i < mid) tmp[k++] = a[i++];
            while (j < hi) tmp[k++] = a[j++];
        }
        uint32_t *t = a;
        a = tmp;
        tmp = t;
    }
    return a;
}

static uint32_t find_id(const xstr *id, const uint32_t *sorted, uint32_t n, const xmlChar *key) {
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        int c = xmlStrcmp(id[sorted[mid]].s, key);
        if (c == 0) return sorted[mid];
        if (c < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return WK_NONE;
}

typedef struct graph {
    uint32_t nn, ne;      /* nodes, edges */
    xmlNode **node, **edge;
    xstr *id;             /* node ids */
    uint32_t *idx, *tmp;  /* sort scratch */
    uint32_t *src, *dst;  /* edge endpoints (node indices) */
    double *nx, *ny, *ew; /* node coordinates, edge weights */
    uint32_t *inc;        /* inc[2i], inc[2i+1]: the edges at node i */
    uint32_t *deg;
    vertex_arrays cyc;    /* the cycle, in order */
} graph;

static void graph_free(wk_run *R, graph *G) {
    if (G->id)
        for (uint32_t i = 0; i < G->nn; i++) xstr_free(&G->id[i]);
    WK_FREE_ARRAY(R, G->node, G->nn);
    WK_FREE_ARRAY(R, G->edge, G->ne);
    WK_FREE_ARRAY(R, G->id, G->nn);
    WK_FREE_ARRAY(R, G->idx, G->nn);
    WK_FREE_ARRAY(R, G->tmp, G->nn);
    WK_FREE_ARRAY(R, G->src, G->ne);
    WK_FREE_ARRAY(R, G->dst, G->ne);
    WK_FREE_ARRAY(R, G->nx, G->nn);
    WK_FREE_ARRAY(R, G->ny, G->nn);
    WK_FREE_ARRAY(R, G->ew, G->ne);
    WK_FREE_ARRAY(R, G->inc, 2 * (size_t)G->nn);
    WK_FREE_ARRAY(R, G->deg, G->nn);
    vertex_arrays_free(R, &G->cyc);
}

/* Reads coordinate K of node i, failing with a message naming the node. */
static wk_status node_coordinate(wk_run *R, const char *name, graph *G, uint32_t i,
                                 const gkey *K, const char *attr_name, double *v) {
    char bad[48], d[160];
    xmlNode *where;
    int got = key_number(G->node[i], K, v, &where, bad, sizeof bad);
    if (got == 1) return WK_OK;
    describe_element(G->node[i], "node", i, d, sizeof d);
    if (got == 0) return WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where), "%s has no %s", d, attr_name);
    if (got == -2)
        return WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where),
                       "%s has a second %s (the first on line %s)", d, attr_name, bad);
    return WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where), "%s: %s '%s' is not a finite number",
                   d, attr_name, bad);
}

/* Everything after parsing: keys, nodes, edges, the cycle. */
static wk_status graphml_polygon(wk_run *R, xmlDoc *doc, const char *name, wk_polygon **out) {
    char d1[160], bad[48];
    const gkey none = {{NULL, NULL}, {NULL, NULL}};
    gkey kx = none, ky = none, kw = none, ka = none;
    graph G;
    memset(&G, 0, sizeof G);
    wk_status st = WK_OK;
    xmlNode *root = xmlDocGetRootElement(doc);
    if (!root || !is_element(root, "graphml")) {
        st = WK_FAIL(R, WK_EINPUT, name, root ? xmlGetLineNo(root) : 0,
                     "the root element is <%s>, not <graphml>",
                     root ? (const char *)root->name : "(none)");
        goto done;
    }
    {
        static const char *const key_name[4] = {"vertex-coordinate-x", "vertex-coordinate-y",
                                                "edge-weight", "edge-weight-additive"};
        gkey *key[4] = {&kx, &ky, &kw, &ka};
        for (int i = 0; i < 4; i++) {
            xmlNode *first, *second = find_key(root, key_name[i], i < 2 ? "node" : "edge",
                                                key[i], &first);
            if (second) {
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(second),
                             "a second <key> for attr.name=\"%s\" (the first on line %ld)",
                             key_name[i], xmlGetLineNo(first));
                goto done;
            }
        }
    }
    xmlNode *graph_el = NULL;
    for (xmlNode *c = root->children; c; c = c->next)
        if (is_element(c, "node") || is_element(c, "edge")) {
            st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(c),
                         "<%s> element outside <graph> (a child of <graphml>)",
                         (const char *)c->name);
            goto done;
        } else if (is_element(c, "graph")) {
            if (graph_el) {
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(c),
                             "a second <graph> element (one polygon per file; the first on "
                             "line %ld)",
                             xmlGetLineNo(graph_el));
                goto done;
            }
            graph_el = c;
        }
    if (!graph_el) {
        st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(root), "no <graph> element in <graphml>");
        goto done;
    }
    if (!kx.id.s || !ky.id.s) {
        st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(root),
                     "no <key for=\"node\" attr.name=\"%s\">",
                     !kx.id.s ? "vertex-coordinate-x" : "vertex-coordinate-y");
        goto done;
    }

    /* Count, then collect, nodes and edges in document order. */
    for (xmlNode *c = graph_el->children; c; c = c->next) {
        if (is_element(c, "node")) {
            if (G.nn == WK_POLYGON_MAX_N) {
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(c),
                             "too many vertices (more than %u)", WK_POLYGON_MAX_N);
                goto done;
            }
            G.nn++;
        } else if (is_element(c, "edge")) {
            if (G.ne == WK_POLYGON_MAX_N) {
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(c),
                             "too many edges (more than %u)", WK_POLYGON_MAX_N);
                goto done;
            }
            G.ne++;
        }
    }
    if (G.nn == 0) {
        st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(graph_el), "the graph has no nodes");
        goto done;
    }
    G.node = WK_NEW_ARRAY(R, xmlNode *, G.nn);
    G.edge = WK_NEW_ARRAY(R, xmlNode *, G.ne);
    G.id = WK_NEW_ARRAY(R, xstr, G.nn);
    G.idx = WK_NEW_ARRAY(R, uint32_t, G.nn);
    G.tmp = WK_NEW_ARRAY(R, uint32_t, G.nn);
    G.src = WK_NEW_ARRAY(R, uint32_t, G.ne);
    G.dst = WK_NEW_ARRAY(R, uint32_t, G.ne);
    G.nx = WK_NEW_ARRAY(R, double, G.nn);
    G.ny = WK_NEW_ARRAY(R, double, G.nn);
    G.ew = WK_NEW_ARRAY(R, double, G.ne);
    G.inc = WK_NEW_ARRAY(R, uint32_t, 2 * (size_t)G.nn);
    G.deg = WK_NEW_ARRAY(R, uint32_t, G.nn);
    if (!G.node || !G.edge || !G.id || !G.idx || !G.tmp || !G.src || !G.dst || !G.nx ||
        !G.ny || !G.ew || !G.inc || !G.deg) {
        st = WK_ENOMEM;
        goto done;
    }
    uint32_t in = 0, ie = 0;
    for (xmlNode *c = graph_el->children; c; c = c->next) {
        if (is_element(c, "node")) G.node[in++] = c;
        if (is_element(c, "edge")) G.edge[ie++] = c;
    }

    /* Nodes: ids (unique), coordinates. */
    for (uint32_t i = 0; i < G.nn; i++) {
        G.id[i] = attr_value(G.node[i], "id");
        if (!G.id[i].s) {
            st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(G.node[i]), "node %u has no id attribute",
                         i);
            goto done;
        }
        if ((st = node_coordinate(R, name, &G, i, &kx, "vertex-coordinate-x", &G.nx[i])) != WK_OK ||
            (st = node_coordinate(R, name, &G, i, &ky, "vertex-coordinate-y", &G.ny[i])) != WK_OK)
            goto done;
        G.idx[i] = i;
    }
    const uint32_t *sorted = sort_ids(G.id, G.idx, G.tmp, G.nn);
    for (uint32_t k = 1; k < G.nn; k++) {
        uint32_t a = sorted[k - 1], b = sorted[k];
        if (!xmlStrEqual(G.id[a].s, G.id[b].s)) continue;
        if (a > b) {
            uint32_t t = a;
            a = b;
            b = t;
        }
        st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(G.node[b]),
                     "duplicate node id '%.60s' (first on line %ld)", (const char *)G.id[a].s,
                     xmlGetLineNo(G.node[a]));
        goto done;
    }

    /* Edges: endpoints, weights, degrees. */
    for (uint32_t i = 0; i < G.ne; i++) {
        xmlNode *e = G.edge[i], *where;
        const char *end_name[2] = {"source", "target"};
        uint32_t end[2];
        for (int j = 0; j < 2; j++) {
            xstr v = attr_value(e, end_name[j]);
            end[j] = v.s ? find_id(G.id, sorted, G.nn, v.s) : WK_NONE;
            if (end[j] == WK_NONE) {
                describe_element(e, "edge", i, d1, sizeof d1);
                if (v.s)
                    st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(e),
                                 "%s: %s '%.60s' is not a node id", d1, end_name[j],
                                 (const char *)v.s);
                else
                    st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(e), "%s has no %s attribute",
                                 d1, end_name[j]);
                xstr_free(&v);
                goto done;
            }
            xstr_free(&v);
        }
        if (end[0] == end[1]) {
            st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(e), "%s is a loop at node '%.60s'",
                         describe_element(e, "edge", i, d1, sizeof d1),
                         (const char *)G.id[end[0]].s);
            goto done;
        }
        G.src[i] = end[0];
        G.dst[i] = end[1];
        int got = key_number(e, &kw, &G.ew[i], &where, bad, sizeof bad);
        if (got == 0) G.ew[i] = 1.0;
        if (got > 0 && R->opt.angles &&
            (st = wk_weight_of_angle(R, G.ew[i], name, xmlGetLineNo(where), &G.ew[i])) != WK_OK)
            goto done;
        if (got < 0 || (got > 0 && !(G.ew[i] > 0) && !R->opt.nonpositive_weights)) {
            describe_element(e, "edge", i, d1, sizeof d1);
            if (got == -2)
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where),
                             "%s has a second edge-weight (the first on line %s)", d1, bad);
            else if (got < 0)
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where),
                             "%s: edge-weight '%s' is not a finite number", d1, bad);
            else
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where),
                             "weight of %s must be > 0 (got %g); zero and negative weights "
                             "need --variant %s (with --height H)",
                             d1, G.ew[i],
                             wk_variant_with_flags(WK_VARIANT_NONPOSITIVE_WEIGHTS)
                                 ? wk_variant_with_flags(WK_VARIANT_NONPOSITIVE_WEIGHTS)
                                 : "(none registered)");
            goto done;
        }
        double add = 0;
        got = key_number(e, &ka, &add, &where, bad, sizeof bad);
        if (got < 0 || add != 0) { /* a second one included: also not supported */
            st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(where),
                         "%s: non-zero edge-weight-additive is not supported",
                         describe_element(e, "edge", i, d1, sizeof d1));
            goto done;
        }
        for (int j = 0; j < 2; j++) {
            uint32_t v = end[j];
            if (G.deg[v] < 2) G.inc[2 * (size_t)v + G.deg[v]] = i;
            if (G.deg[v] < UINT32_MAX) G.deg[v]++;
        }
    }
    /* Disjoint simple cycles through every node are a polygon (with holes),
    ** unless R->opt.pslg asks for a PSLG; anything else is a PSLG
    ** (engine/pslg.c checks it). */
    bool cycles = !R->opt.pslg;
    for (uint32_t v = 0; v < G.nn && cycles; v++) cycles = G.deg[v] == 2;
    if (!cycles) {
        long *lines = WK_NEW_ARRAY(R, long, (size_t)G.nn + G.ne);
        if (!lines) {
            st = WK_ENOMEM;
            goto done;
        }
        for (uint32_t v = 0; v < G.nn; v++) lines[v] = xmlGetLineNo(G.node[v]);
        for (uint32_t e = 0; e < G.ne; e++) lines[G.nn + e] = xmlGetLineNo(G.edge[e]);
        st = wk_pslg_from_arrays(R, G.nn, G.nx, G.ny, G.ne, G.src, G.dst, G.ew, name, lines,
                                 lines + G.nn, out);
        WK_FREE_ARRAY(R, lines, (size_t)G.nn + G.ne);
        goto done;
    }

    /* Walk every cycle: from the first node in document order not yet on
    ** one, along its first edge.  Then the ring of largest area (the one
    ** that contains all others, if the input is valid) goes first as the
    ** outer boundary; the others follow in the order walked.  Containment
    ** itself is checked by wk_polygon_from_rings. */
    if ((st = vertex_arrays_alloc(R, &G.cyc, G.nn)) != WK_OK) goto done;
    uint32_t cap_rings = G.nn / 3 + 1, n_rings = 0;
    uint32_t *ring = WK_NEW_ARRAY(R, uint32_t, cap_rings);
    if (!ring) {
        st = WK_ENOMEM;
        goto done;
    }
    uint32_t *seen = G.deg; /* reused: 2 = not yet visited, 0 = visited */
    uint32_t k = 0, start = 0, outer = 0;
    double best = -1.0;
    while (k < G.nn) {
        while (seen[start] == 0) start++;
        uint32_t cur = start, e = G.inc[2 * (size_t)start], k0 = k;
        for (;;) {
            seen[cur] = 0;
            G.cyc.x[k] = G.nx[cur];
            G.cyc.y[k] = G.ny[cur];
            G.cyc.w[k] = G.ew[e];
            G.cyc.line[k] = xmlGetLineNo(G.node[cur]);
            k++;
            uint32_t nxt = G.src[e] == cur ? G.dst[e] : G.src[e];
            if (nxt == start) break;
            if (seen[nxt] == 0) { /* defensive: a 2-regular walk returns to its start */
                st = WK_FAIL(R, WK_EINPUT, name, xmlGetLineNo(G.node[nxt]),
                             "the edges do not form a simple cycle at node '%.60s'",
                             (const char *)G.id[nxt].s);
                WK_FREE_ARRAY(R, ring, cap_rings);
                goto done;
            }
            e = G.inc[2 * (size_t)nxt] == e ? G.inc[2 * (size_t)nxt + 1] : G.inc[2 * (size_t)nxt];
            cur = nxt;
        }
        /* |area| in doubles: only to pick the outer ring; a wrong pick on a
        ** near-tie means an invalid input, which the checks then reject */
        double area = 0.0;
        for (uint32_t i = k0; i < k; i++) {
            uint32_t j = i + 1 == k ? k0 : i + 1;
            area += (G.cyc.x[i] - G.cyc.x[k0]) * (G.cyc.y[j] - G.cyc.y[k0]) -
                    (G.cyc.x[j] - G.cyc.x[k0]) * (G.cyc.y[i] - G.cyc.y[k0]);
        }
        if (fabs(area) > best) {
            best = fabs(area);
            outer = n_rings;
        }
        ring[n_rings++] = k - k0; /* n_rings <= nn / 3: every cycle has >= 3 nodes */
    }
    if (outer != 0) {
        /* rotate the outer ring's block to the front: reverse the blocks
        ** [0, a) and [a, a + m), then both together */
        uint32_t a = 0;
        for (uint32_t r = 0; r < outer; r++) a += ring[r];
        uint32_t m = ring[outer];
        vertex_arrays *C = &G.cyc;
        uint32_t spans[3][2] = {{0, a}, {a, a + m}, {0, a + m}};
        for (int pass = 0; pass < 3; pass++)
            for (uint32_t i = spans[pass][0], j = spans[pass][1]; i + 1 < j; i++, j--) {
                double t;
                long l;
                t = C->x[i], C->x[i] = C->x[j - 1], C->x[j - 1] = t;
                t = C->y[i], C->y[i] = C->y[j - 1], C->y[j - 1] = t;
                t = C->w[i], C->w[i] = C->w[j - 1], C->w[j - 1] = t;
                l = C->line[i], C->line[i] = C->line[j - 1], C->line[j - 1] = l;
            }
        for (uint32_t r = outer; r > 0; r--) ring[r] = ring[r - 1];
        ring[0] = m;
    }
    st = wk_polygon_from_rings(R, n_rings, ring, G.cyc.x, G.cyc.y, G.cyc.w, name, G.cyc.line,
                               out);
    WK_FREE_ARRAY(R, ring, cap_rings);
done:
    graph_free(R, &G);
    gkey_clear(&kx);
    gkey_clear(&ky);
    gkey_clear(&kw);
    gkey_clear(&ka);
    return st;
}

/* The bytes of a GraphML, GeoJSON or WKT document: strict UTF-8 throughout,
** no NUL, no control character but tab, LF and CR (see the header).  WK_OK
** or WK_EINPUT naming the line and column (in bytes) of the first fault;
** format names the format in the message (read_text.h). */
wk_status wk_read_utf8_bytes(wk_run *R, const char *buf, size_t len, const char *name,
                             const char *format) {
    const unsigned char *u = (const unsigned char *)buf;
    if (is_utf16_bom(buf, len)) return utf16_refused(R, name);
    long line = 1;
    size_t line_start = 0;
    for (size_t i = 0; i < len;) {
        unsigned char c = u[i];
        if (c >= 0x20 && c < 0x7F) {
            i++;
            continue;
        }
        if (c == '\n') {
            line++;
            line_start = ++i;
            continue;
        }
        if (c == '\t' || c == '\r') {
            i++;
            continue;
        }
        uint32_t cp;
        size_t k = utf8_seq(u + i, len - i, &cp);
        char why[160];
        if (k == 0)
            snprintf(why, sizeof why, "byte 0x%02X is not UTF-8 (%s input must be UTF-8)", c,
                     format);
        else if (is_control(cp))
            describe_control(cp, why, sizeof why);
        else {
            i += k;
            continue;
        }
        return WK_FAIL(R, WK_EINPUT, name, line, "column %zu: %s", i - line_start + 1, why);
    }
    return WK_OK;
}

/* Case-insensitive ASCII comparison. */
static bool ascii_caseeq(const char *a, const char *b) {
    for (; *a && *b; a++, b++) {
        char x = *a >= 'A' && *a <= 'Z' ? (char)(*a - 'A' + 'a') : *a;
        char y = *b >= 'A' && *b <= 'Z' ? (char)(*b - 'A' + 'a') : *b;
        if (x != y) return false;
    }
    return *a == *b;
}

wk_status wk_polygon_read_graphml(wk_run *R, const char *buf, size_t len, const char *name,
                                  wk_polygon **out) {
    *out = NULL;
    if (!name) name = "";
    if (len > INT_MAX)
        return WK_FAIL(R, WK_EINPUT, name, 0, "GraphML input too large (%zu bytes)", len);
    wk_status bytes = wk_read_utf8_bytes(R, buf, len, name, "GraphML");
    if (bytes != WK_OK) return bytes;
    bool first_failure = R->err.code == WK_OK;
    xmlParserCtxtPtr ctx = xmlNewParserCtxt();
    if (!ctx) return WK_FAIL(R, WK_ENOMEM, name, 0, "out of memory (libxml2 parser context)");
    /* NONET: never fetch anything; no NOENT/DTDLOAD, so no external entities.
    ** NOERROR/NOWARNING: the library never prints; the error is taken from
    ** the context instead.  NOBLANKS drops the indentation text nodes, a
    ** third of the tree (the tree costs about 3 KB per polygon vertex).
    ** BIG_LINES: line numbers past 65535 in messages. */
    const int options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING |
                        XML_PARSE_NOBLANKS | XML_PARSE_BIG_LINES;
    xmlDoc *doc = xmlCtxtReadMemory(ctx, buf, (int)len, name, NULL, options);
    wk_status st;
    if (!doc || !ctx->wellFormed) {
        const xmlError *err = xmlCtxtGetLastError(ctx);
        char msg[256] = "not well-formed";
        long line = 0;
        if (err && err->message) {
            wk_read_clean_message(msg, sizeof msg, err->message);
            line = err->line;
        }
        st = WK_FAIL(R, WK_EINPUT, name, line, "XML error: %s", msg);
    } else if (doc->encoding && !ascii_caseeq((const char *)doc->encoding, "UTF-8") &&
               !ascii_caseeq((const char *)doc->encoding, "UTF8") &&
               !ascii_caseeq((const char *)doc->encoding, "US-ASCII") &&
               !ascii_caseeq((const char *)doc->encoding, "ASCII")) {
        /* The bytes are UTF-8 (checked above) but libxml2 decoded them as
        ** declared: refuse rather than read something else than the file. */
        st = WK_FAIL(R, WK_EINPUT, name, 1,
                     "the document declares encoding '%.40s'; GraphML input must be UTF-8",
                     (const char *)doc->encoding);
    } else {
        st = graphml_polygon(R, doc, name, out);
    }
    xmlFreeDoc(doc);
    xmlFreeParserCtxt(ctx);
    if (st != WK_OK && first_failure && R->err.code != WK_OK) {
        /* Messages quote the document (ids, values): one line of UTF-8. */
        char tmp[sizeof R->err.msg];
        wk_read_clean_message(tmp, sizeof tmp, R->err.msg);
        memcpy(R->err.msg, tmp, sizeof tmp);
    }
    return st;
}

/* ---- by content ---- */

wk_status wk_weight_of_angle(wk_run *R, double degrees, const char *name, long line, double *w) {
    if (!(degrees > 0 && degrees < 180))
        return WK_FAIL(R, WK_EINPUT, name, line,
                       "pitch %g degrees: --angles takes pitches strictly between 0 and 180", degrees);
    /* 90 exactly is a wall: cos(pi / 2) in doubles is 6e-17, not 0 */
    *w = degrees == 90 ? 0.0 : 1.0 / tan(degrees * (3.14159265358979323846 / 180.0));
    return WK_OK;
}

wk_status wk_polygon_read_file(wk_run *R, const char *path, wk_polygon **out) {
    *out = NULL;
    bool use_stdin = strcmp(path, "-") == 0;
    const char *name = use_stdin ? "<stdin>" : path;
    FILE *f = use_stdin ? stdin : fopen(path, "rb");
    if (!f) return WK_FAIL(R, WK_EINPUT, path, 0, "cannot open: %s", strerror(errno));
    text t;
    wk_status st = slurp(R, f, name, &t);
    if (!use_stdin) fclose(f);
    if (st != WK_OK) return st;
    /* GraphML if the first non-blank character is '<' (after a UTF-8 byte
    ** order mark, if any). */
    const char *c = t.buf;
    if ((unsigned char)c[0] == 0xEF && (unsigned char)c[1] == 0xBB && (unsigned char)c[2] == 0xBF)
        c += 3;
    while (is_blank(*c) || *c == '\r' || *c == '\n') c++;
    /* GeoJSON at '{', WKT at a letter (a .wpoly starts with '#' or a count) */
    if (*c == '<')
        st = wk_polygon_read_graphml(R, t.buf, t.len, name, out);
    else if (*c == '{')
        st = wk_polygon_read_geojson(R, t.buf, t.len, name, out);
    else if ((*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z'))
        st = wk_polygon_read_wkt(R, t.buf, t.len, name, out);
    else
        st = parse_wpoly(R, &t, name, out);
    bool single = *c != '{' && !((*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z'));
    text_free(R, &t);
    /* .wpoly and GraphML hold one polygon: part 0 is it, any other is refused
    ** as the GeoJSON and WKT readers refuse a part beyond their count. */
    if (st == WK_OK && single && R->opt.part != WK_NONE && R->opt.part > 0) {
        wk_polygon_free(R, *out);
        *out = NULL;
        st = WK_FAIL(R, WK_EINPUT, name, 0,
                     "--part %u, but the input holds 1 polygon (parts count from 0)", R->opt.part);
    }
    return st;
}
