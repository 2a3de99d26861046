/*
** wskel_gen.c: bin/wskel-gen, the command-line face of the polygon
** generators (bench/gen/generators.h): one family, one polygon, written as
** .wpoly or as GraphML in the Salzburg/surfer2 format.
**
** Output goes to FILE.tmp.PID and is renamed to FILE only on success, so a
** failed run leaves no partial file.  An existing FILE that is not a regular
** file (/dev/null, a FIFO) is written directly: renaming over it would
** replace the device node with a plain file.  Exit codes: 0 ok, 1 parameters the
** family cannot honour (e.g. "notched: r=60 > n/2=50"), 2 out of memory or
** a write failure, 64 usage.
*/
#define _POSIX_C_SOURCE 200809L
#include "generators.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static const char usage_text[] =
    "usage: wskel-gen FAMILY --n N [options]\n"
    "Write one seeded polygon of a benchmark family (see bench/README.md).\n"
    "\n"
    "options:\n"
    "  --n N              number of vertices (required)\n"
    "  --r R              reflex vertices, for the families that take it\n"
    "                     (star, notched, crossing, monotone; the others check\n"
    "                     it against their fixed rule)\n"
    "  --holes H          holes (default 0), for the families that take them\n"
    "                     (holes, convex); n >= 3H+3\n"
    "  --seed S           unsigned 64-bit seed (default 1)\n"
    "  --weights MODE     unit (default), uniform[:a:b] (0.5..2), two[:a:b] (1|3),\n"
    "                     int[:a:b] (1..4); weights never change the geometry\n"
    "  --format F         wpoly (default) or graphml (Salzburg/surfer2 keys)\n"
    "  -o FILE            write to FILE instead of stdout (atomically)\n"
    "  --list             list the families\n"
    "  --help             this text\n"
    "\n"
    "exit codes: 0 ok, 1 impossible parameters, 2 out of memory or write error,\n"
    "            64 usage error\n";

static int usage_error(const char *fmt, const char *arg) {
    fprintf(stderr, "wskel-gen: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry 'wskel-gen --help'.\n");
    return 64;
}

static int report(wk_run *R) {
    char buf[1024];
    wk_error_format(R, buf, sizeof buf);
    fprintf(stderr, "wskel-gen: %s\n", buf);
    return wk_status_exit_code(R->err.code);
}

/* Decimal unsigned integer, no sign, no junk; false if not one. */
static bool parse_u64(const char *s, uint64_t max, uint64_t *out) {
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (*s < '0' || *s > '9' || *end || errno || v > max) return false;
    *out = v;
    return true;
}

/* GraphML as the Salzburg database and surfer2 read it: string-typed
** coordinate and weight keys, one node per vertex, one edge per polygon
** edge (i -> the next vertex of its ring) carrying its weight; holes are
** further cycles (the reader takes the cycle of largest area as the outer
** ring). */
static void write_graphml(FILE *f, const wk_polygon *P, const char *header) {
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- %s -->\n", header);
    fprintf(f,
            "<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\" "
            "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
            "xsi:schemaLocation=\"http://graphml.graphdrawing.org/xmlns "
            "http://graphml.graphdrawing.org/xmlns/1.0/graphml.xsd\">\n"
            "  <key id=\"x\" for=\"node\" attr.name=\"vertex-coordinate-x\" "
            "attr.type=\"string\"/>\n"
            "  <key id=\"y\" for=\"node\" attr.name=\"vertex-coordinate-y\" "
            "attr.type=\"string\"/>\n"
            "  <key id=\"w\" for=\"edge\" attr.name=\"edge-weight\" attr.type=\"string\">\n"
            "    <default>1.0</default>\n  </key>\n"
            "  <key id=\"wa\" for=\"edge\" attr.name=\"edge-weight-additive\" "
            "attr.type=\"string\">\n    <default>0.0</default>\n  </key>\n"
            "  <graph id=\"G\" edgedefault=\"undirected\">\n");
    for (uint32_t i = 0; i < P->n; i++)
        fprintf(f,
                "    <node id=\"%u\"><data key=\"x\">%.17g</data><data key=\"y\">%.17g</data>"
                "</node>\n",
                i, P->p[i].x, P->p[i].y);
    for (uint32_t i = 0; i < P->n; i++)
        fprintf(f, "    <edge source=\"%u\" target=\"%u\"><data key=\"w\">%.17g</data></edge>\n",
                i, wk_polygon_next(P, i), P->w[i]);
    fprintf(f, "  </graph>\n</graphml>\n");
}

int main(int argc, char **argv) {
    const char *outpath = NULL, *format = "wpoly";
    bool have_n = false;
    wk_gen_params g;
    wk_gen_params_init(&g);
    wk_run R;
    wk_run_init(&R);

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        uint64_t v;
#define NEED_ARG()                                                          \
    do {                                                                    \
        if (i + 1 >= argc) return usage_error("option %s needs a value", a); \
    } while (0)
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage_text, stdout);
            return 0;
        } else if (!strcmp(a, "--list")) {
            for (size_t j = 0; wk_gen_families[j]; j++)
                printf("%-12s %s\n", wk_gen_families[j], wk_gen_family_summary(wk_gen_families[j]));
            return 0;
        } else if (!strcmp(a, "--n")) {
            NEED_ARG();
            if (!parse_u64(argv[++i], UINT32_MAX, &v) || v == 0)
                return usage_error("--n must be a positive integer (got '%s')", argv[i]);
            g.n = (uint32_t)v;
            have_n = true;
        } else if (!strcmp(a, "--r")) {
            NEED_ARG();
            if (!parse_u64(argv[++i], UINT32_MAX, &v))
                return usage_error("--r must be an integer >= 0 (got '%s')", argv[i]);
            g.r = (int64_t)v;
        } else if (!strcmp(a, "--holes")) {
            NEED_ARG();
            if (!parse_u64(argv[++i], UINT32_MAX, &v))
                return usage_error("--holes must be an integer >= 0 (got '%s')", argv[i]);
            g.holes = (uint32_t)v;
        } else if (!strcmp(a, "--seed")) {
            NEED_ARG();
            if (!parse_u64(argv[++i], UINT64_MAX, &v))
                return usage_error("--seed must be an unsigned 64-bit integer (got '%s')",
                                   argv[i]);
            g.seed = v;
        } else if (!strcmp(a, "--weights")) {
            NEED_ARG();
            if (wk_gen_parse_weights(&R, argv[++i], &g) != WK_OK)
                return usage_error("%s", R.err.msg);
        } else if (!strcmp(a, "--format")) {
            NEED_ARG();
            format = argv[++i];
            if (strcmp(format, "wpoly") && strcmp(format, "graphml"))
                return usage_error("unknown format '%s' (wpoly, graphml)", format);
        } else if (!strcmp(a, "-o")) {
            NEED_ARG();
            outpath = argv[++i];
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else {
            if (g.family) return usage_error("more than one family given ('%s')", a);
            g.family = a;
        }
#undef NEED_ARG
    }
    if (!g.family) return usage_error("%s", "no family given (see --list)");
    if (!wk_gen_family_summary(g.family))
        return usage_error("unknown family '%s' (see --list)", g.family);
    if (!have_n) return usage_error("%s", "--n is required");
    int rc = 0;
    wk_polygon *P = NULL;
    wk_output out = {NULL, NULL, false, ""};
    if (wk_generate(&R, &g, &P) != WK_OK) {
        rc = report(&R);
        goto done;
    }

    char wtext[96], htext[32] = "", header[256];
    wk_gen_weights_format(&g, wtext, sizeof wtext);
    /* holes=H only where holes are possible, so the other families' headers
    ** stay as they were */
    if (wk_gen_family_takes_holes(g.family) && (g.holes > 0 || !strcmp(g.family, "holes")))
        snprintf(htext, sizeof htext, " holes=%u", g.holes);
    snprintf(header, sizeof header, "wskel-gen %d: family=%s n=%u%s r=%u seed=%llu weights=%s",
             WK_GEN_VERSION, g.family, P->n, htext, P->r, (unsigned long long)g.seed, wtext);

    if (wk_output_open(&R, &out, outpath) != WK_OK) {
        rc = report(&R);
        goto done;
    }
    wk_status st = WK_OK;
    if (!strcmp(format, "graphml")) {
        write_graphml(out.f, P, header);
    } else {
        fprintf(out.f, "# %s\n", header);
        st = wk_polygon_write_wpoly(&R, out.f, P);
    }
    st = wk_output_close(&R, &out, st);
    if (st != WK_OK) rc = report(&R);

done:
    wk_output_close(&R, &out, WK_EALGO); /* no-op unless a failure left it open */
    wk_polygon_free(&R, P);
    size_t left = wk_run_close(&R);
    if (left != 0 && rc == 0) {
        fprintf(stderr, "wskel-gen: internal error: %zu bytes leaked\n", left);
        rc = 2;
    }
    return rc;
}
