/*
** main.c: the command-line front end (bin/wskel).
** Reads one polygon, runs one variant, optionally validates, writes one
** output.  Output goes to FILE.tmp.PID and is renamed only on success, so a
** failed run leaves no partial file.  An existing FILE that is not a regular
** file (/dev/null, a FIFO, a terminal) is written directly: renaming over it
** would replace the device node with a plain file.  Exit codes: 0 ok, 1 invalid input,
** 2 the algorithm failed, 3 the validator found the output invalid (every
** skeleton is validated before it is written, unless --no-check: a wrong
** skeleton is never written silently), 64 usage.
*/
#define _POSIX_C_SOURCE 200809L
#include "wskel.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char usage_text[] =
    "usage: wskel [options] INPUT\n"
    "Compute the positively weighted straight skeleton of a simple polygon or a\n"
    "polygon with holes.\n"
    "\n"
    "INPUT is a .wpoly file, GraphML, GeoJSON or WKT (detected by content); '-'\n"
    "reads stdin.  GeoJSON: a Polygon, MultiPolygon, Feature or FeatureCollection;\n"
    "per-edge weights from a Feature's \"weights\" property (one array per ring,\n"
    "weight i for the edge from vertex i to the next).  WKT: POLYGON or MULTIPOLYGON.\n"
    "  GraphML: disjoint simple cycles are a polygon; any other planar\n"
    "  straight-line graph (or any graph with --pslg) is a PSLG, whose skeleton\n"
    "  (naive; motorcycle with equal weights) is followed up to a horizon\n"
    "  (--until).\n"
    "  .wpoly: '#' comment lines; first line n; then n lines 'x y [w]' where w\n"
    "  (default 1) weights the edge from this vertex to the next.  Holes follow\n"
    "  as further rings, each its own count line and vertex lines.  Any ring may\n"
    "  be clockwise; output keeps input numbering (over the rings in file order).\n"
    "\n"
    "options:\n"
    "  --variant V        algorithm (default naive); --list-variants shows all\n"
    "  --k K              arrangement cache size: a positive integer or 'max'\n"
    "                     (default 1; ignored by variants without a cache)\n"
    "  --format F         json (default), text, svg, obj (roof), vtp (VTK PolyData),\n"
    "                     geojson, wkt (the skeleton, or with --offset the offsets)\n"
    "  -o FILE            write to FILE instead of stdout (atomically)\n"
    "  --offset T1,T2..   offsets at these times (>= 0; distances for unit weights):\n"
    "                     with --format geojson or wkt, write the offset polygons\n"
    "                     (with holes) instead of the skeleton; with svg, draw them\n"
    "                     as curves over the skeleton.  --offsets is the same option\n"
    "                     (PSLG: the region swept by then, around each component;\n"
    "                     without --until, the skeleton is followed up to the\n"
    "                     latest time if that is past the default horizon)\n"
    "  --part I           the polygon to use (0-based) when INPUT holds several\n"
    "                     (a MultiPolygon or several features / WKT polygons)\n"
    "  --check            validate the skeleton, exit 3 and no output if invalid\n"
    "                     (the default; --stats prints the validator's figures)\n"
    "  --no-check         skip the validation (huge inputs, timing runs)\n"
    "  --validate SKEL    validate the wskel-1 JSON skeleton SKEL (written by -o,\n"
    "                     any variant or program) against INPUT instead of\n"
    "                     computing one: exit 0 and 'valid: ...' on stdout, or 3\n"
    "                     and the violated property (polygons, not PSLGs; with\n"
    "                     --height H for a roof cut at H)\n"
    "  --check-tol REL    the validator's tolerance as a fraction of the bounding-box\n"
    "                     diagonal (default 1e-6; smaller is stricter)\n"
    "  --stats            print counters, time and peak tracked bytes to stderr\n"
    "                     (with --offset and geojson/wkt also the offsets' time;\n"
    "                     for a variant with a timed phase, e.g. motorcycle's\n"
    "                     M(P), phase_s: that phase's share of time_s; when the\n"
    "                     reference answered for the variant, fallback_reason:\n"
    "                     why the variant's own run gave up)\n"
    "  --collinear RULE   parallel edges of different weight meeting collinearly:\n"
    "                     'lower' (default, the lower weight edge survives, as in\n"
    "                     the arrangement paper) or 'higher' (surfer2's default)\n"
    "  --threads N        OpenMP threads for variants that use them (default 1)\n"
    "  --angles           the third column (GraphML: edge-weight) is the roof's\n"
    "                     pitch in degrees (0..180), weight 1/tan(pitch): 90 a\n"
    "                     wall (0), above 90 an overhang (< 0)\n"
    "  --height H         stop at t = H and close the roof with a cap at t = H\n"
    "                     (deforming; required when a weight is <= 0)\n"
    "  --until T          PSLG input: follow the wavefront up to t = T; the arcs\n"
    "                     still alive end at nodes at t = T, the wavefront there is\n"
    "                     the cap (default: 0.25 diagonals / the largest weight\n"
    "                     after the last event)\n"
    "  --pslg             GraphML: read disjoint simple cycles as a PSLG (both\n"
    "                     sides of every edge) rather than a polygon\n"
    "  --step S           variants that advance in time steps (deforming): the\n"
    "                     first increment times S (default 1); the skeleton\n"
    "                     does not depend on it\n"
    "  --verbose          on failure, also say where in wskel it was raised\n"
    "  --check-invariants after every group of events, check the wavefront's and\n"
    "                     the variant's invariants (slow: O(n) per group; tests)\n"
    "  --list-variants    the variants, one per line: name and summary\n"
    "  --list-counters    the counters of --variant (default naive), one per line:\n"
    "                     name, tab, meaning (the keys of the JSON stats)\n"
    "  --help             this text\n"
    "\n"
    "exit codes: 0 ok, 1 invalid input, 2 the algorithm failed or does not apply\n"
    "            (monotone on a polygon monotone in no direction),\n"
    "            3 the output failed validation, 64 usage error\n";

static int usage_error(const char *fmt, const char *arg) {
    fprintf(stderr, "wskel: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\nTry 'wskel --help'.\n");
    return 64;
}

static int report(wk_run *R, bool verbose) {
    char buf[1024];
    wk_error_format(R, buf, sizeof buf);
    fprintf(stderr, "wskel: %s\n", buf);
    if (verbose && R->err.src_file)
        fprintf(stderr, "wskel: (%s, raised at %s:%d)\n", wk_status_name(R->err.code),
                R->err.src_file, R->err.src_line);
    return wk_status_exit_code(R->err.code);
}

static int parse_offsets(const char *s, double **out, uint32_t *n) {
    uint32_t cap = 1;
    for (const char *c = s; *c; c++) cap += (*c == ',');
    double *v = calloc(cap, sizeof *v);
    if (!v) return -1;
    uint32_t k = 0;
    const char *c = s;
    while (*c) {
        char *end;
        errno = 0;
        double t = strtod(c, &end);
        if (end == c || errno || !(t >= 0) || t > 1e300 || (*end && *end != ',')) {
            free(v);
            return -1;
        }
        v[k++] = t;
        c = *end ? end + 1 : end;
    }
    *out = v;
    *n = k;
    return 0;
}

/* --validate: read SKEL against P and run the validator on it. */
static int validate_file(wk_run *R, const wk_polygon *P, const char *path, double check_tol,
                         bool verbose) {
    wk_skeleton *S = NULL;
    wk_validate_report rep;
    if (wk_skeleton_read_json(R, P, path, &S) != WK_OK ||
        wk_validate(R, P, S, check_tol * wk_polygon_scale(P), &rep) != WK_OK) {
        wk_skeleton_free(R, S);
        return report(R, verbose);
    }
    printf("valid: %s against %s (%u nodes, %u arcs, %u faces, max distance error %.3g, area "
           "error %.3g)\n",
           path, P->name, rep.nodes, rep.arcs, rep.faces, rep.max_distance_error, rep.area_error);
    wk_skeleton_free(R, S);
    return 0;
}

int main(int argc, char **argv) {
    const char *variant = "naive", *format = "json", *outpath = NULL, *input = NULL;
    const char *offsets_arg = NULL, *validate_path = NULL;
    bool check = true, stats = false, k_given = false, verbose = false, list_counters = false;
    bool check_invariants = false;
    double check_tol = WK_VALIDATE_TOL_REL;
    uint32_t k = 1;
    wk_collinear_rule collinear = WK_COLLINEAR_LOWER;
    int threads = 1;
    uint32_t part = WK_NONE;
    double step_scale = 1;
    double height = 0;
    double until = 0;
    bool angles = false, pslg = false;

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
#define NEED_ARG()                                                          \
    do {                                                                    \
        if (i + 1 >= argc) return usage_error("option %s needs a value", a); \
    } while (0)
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage_text, stdout);
            return 0;
        } else if (!strcmp(a, "--list-variants")) {
            for (size_t j = 0; wk_variant_at(j); j++)
                printf("%-12s %s\n", wk_variant_name(wk_variant_at(j)),
                       wk_variant_summary(wk_variant_at(j)));
            return 0;
        } else if (!strcmp(a, "--list-counters")) {
            list_counters = true;
        } else if (!strcmp(a, "--verbose")) {
            verbose = true;
        } else if (!strcmp(a, "--check-invariants")) {
            check_invariants = true;
        } else if (!strcmp(a, "--variant")) {
            NEED_ARG();
            variant = argv[++i];
        } else if (!strcmp(a, "--k")) {
            NEED_ARG();
            const char *v = argv[++i];
            k_given = true;
            if (!strcmp(v, "max")) {
                k = WK_K_MAX;
            } else {
                char *end;
                errno = 0;
                unsigned long long x = strtoull(v, &end, 10);
                if (*v == '-' || end == v || *end || errno || x == 0 || x >= WK_K_MAX)
                    return usage_error("--k must be a positive integer or 'max' (got '%s')", v);
                k = (uint32_t)x;
            }
        } else if (!strcmp(a, "--format")) {
            NEED_ARG();
            format = argv[++i];
            if (strcmp(format, "json") && strcmp(format, "svg") && strcmp(format, "obj") &&
                strcmp(format, "vtp") && strcmp(format, "text") && strcmp(format, "geojson") &&
                strcmp(format, "wkt"))
                return usage_error("unknown format '%s' (json, text, svg, obj, vtp, geojson, wkt)",
                                   format);
        } else if (!strcmp(a, "-o")) {
            NEED_ARG();
            outpath = argv[++i];
        } else if (!strcmp(a, "--offsets") || !strcmp(a, "--offset")) {
            NEED_ARG();
            offsets_arg = argv[++i];
        } else if (!strcmp(a, "--check")) {
            check = true;
        } else if (!strcmp(a, "--validate")) {
            NEED_ARG();
            validate_path = argv[++i];
        } else if (!strcmp(a, "--no-check")) {
            check = false;
        } else if (!strcmp(a, "--check-tol")) {
            NEED_ARG();
            const char *v = argv[++i];
            char *end;
            errno = 0;
            check_tol = strtod(v, &end);
            if (end == v || *end || errno || !(check_tol > 0) || !(check_tol < 1))
                return usage_error("--check-tol must be a number in (0, 1) (got '%s')", v);
        } else if (!strcmp(a, "--stats")) {
            stats = true;
        } else if (!strcmp(a, "--collinear")) {
            NEED_ARG();
            const char *v = argv[++i];
            if (!strcmp(v, "lower")) collinear = WK_COLLINEAR_LOWER;
            else if (!strcmp(v, "higher")) collinear = WK_COLLINEAR_HIGHER;
            else return usage_error("--collinear must be 'lower' or 'higher' (got '%s')", v);
        } else if (!strcmp(a, "--part")) {
            NEED_ARG();
            const char *v = argv[++i];
            char *end;
            errno = 0;
            unsigned long long x = strtoull(v, &end, 10);
            if (*v == '-' || end == v || *end || errno || x >= WK_NONE)
                return usage_error("--part must be an integer >= 0 (got '%s')", v);
            part = (uint32_t)x;
        } else if (!strcmp(a, "--threads")) {
            NEED_ARG();
            const char *v = argv[++i];
            char *end;
            long x = strtol(v, &end, 10);
            if (end == v || *end || x < 1 || x > 1024)
                return usage_error("--threads must be an integer in 1..1024 (got '%s')", v);
            threads = (int)x;
        } else if (!strcmp(a, "--angles")) {
            angles = true;
        } else if (!strcmp(a, "--height")) {
            NEED_ARG();
            const char *v = argv[++i];
            char *end;
            double x = strtod(v, &end);
            if (end == v || *end || !(x > 0) || !isfinite(x))
                return usage_error("--height must be a positive number (got '%s')", v);
            height = x;
        } else if (!strcmp(a, "--until")) {
            NEED_ARG();
            const char *v = argv[++i];
            char *end;
            double x = strtod(v, &end);
            if (end == v || *end || !(x > 0) || !isfinite(x))
                return usage_error("--until must be a positive number (got '%s')", v);
            until = x;
        } else if (!strcmp(a, "--pslg")) {
            pslg = true;
        } else if (!strcmp(a, "--step")) {
            NEED_ARG();
            const char *v = argv[++i];
            char *end;
            double x = strtod(v, &end);
            if (end == v || *end || !(x >= 1e-6 && x <= 1e6))
                return usage_error("--step must be a number in [1e-6, 1e6] (got '%s')", v);
            step_scale = x;
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else {
            if (input) return usage_error("more than one input given ('%s')", a);
            input = a;
        }
#undef NEED_ARG
    }
    const wk_variant *V = wk_variant_find(variant);
    if (!V) return usage_error("unknown variant '%s' (see --list-variants)", variant);
    if (list_counters) {
        for (uint32_t j = 0; j < wk_counter_count(V); j++)
            printf("%s\t%s\n", wk_counter_def_at(V, j)->name, wk_counter_def_at(V, j)->meaning);
        return 0;
    }
    if (!input) return usage_error("%s", "no input file given");
    bool offset_polygons = offsets_arg && (!strcmp(format, "geojson") || !strcmp(format, "wkt"));
    if (offsets_arg && !offset_polygons && strcmp(format, "svg") != 0)
        fprintf(stderr, "wskel: note: --offset only affects --format svg, geojson and wkt\n");
    if (k_given && !(wk_variant_flags(V) & WK_VARIANT_USES_K))
        fprintf(stderr, "wskel: note: variant %s ignores --k\n", wk_variant_name(V));
    double *offsets = NULL;
    uint32_t n_offsets = 0;
    if (offsets_arg && parse_offsets(offsets_arg, &offsets, &n_offsets) != 0)
        return usage_error("--offset/--offsets must be a comma-separated list of times >= 0 (got '%s')",
                           offsets_arg);

    wk_run R;
    wk_run_init(&R);
    R.opt.k = k;
    R.opt.collinear = collinear;
    R.opt.threads = threads;
    R.opt.step_scale = step_scale;
    R.opt.height = height;
    R.opt.until = until;
    R.opt.pslg = pslg;
    R.opt.angles = angles;
    /* weights <= 0 are input only for a variant that takes them: the
    ** readers refuse them otherwise, naming the edge */
    R.opt.nonpositive_weights = (wk_variant_flags(V) & WK_VARIANT_NONPOSITIVE_WEIGHTS) != 0;
    if (validate_path) R.opt.nonpositive_weights = true; /* the skeleton says what it is */
    if (height > 0 && !R.opt.nonpositive_weights)
        return usage_error("variant %s does not take --height (deforming does)", wk_variant_name(V));
    R.opt.check_invariants = check_invariants;
    R.opt.part = part;

    int rc = 0;
    wk_polygon *P = NULL;
    wk_skeleton *S = NULL;
    wk_output out = {NULL, NULL, false, ""};
    double time_s = 0;
    size_t peak = 0;
    wk_offset_set **sets = NULL;
    double offset_s = -1; /* time of the wk_offset calls (--stats), < 0: none */

    if (wk_polygon_read_file(&R, input, &P) != WK_OK) {
        rc = report(&R, verbose);
        goto done;
    }
    if (validate_path) {
        rc = validate_file(&R, P, validate_path, check_tol, verbose);
        goto done;
    }
    if (until > 0 && !P->pslg)
        fprintf(stderr, "wskel: note: --until only affects PSLG input (a polygon's wavefront vanishes)\n");
    for (uint32_t i = 0; i < P->n && !(height > 0); i++)
        if (!(P->w[i] > 0)) {
            WK_FAIL(&R, WK_EINPUT, P->name, 0,
                    "edge %u has weight %g <= 0: the wavefront need not vanish, so --height H "
                    "(where the roof is cut) is required",
                    wk_polygon_input_edge(P, i), P->w[i]);
            rc = report(&R, verbose);
            goto done;
        }
    wk_validate_report rep;
    if (check ? wk_solve_checked(&R, V, P, check_tol * wk_polygon_scale(P), &S, &time_s, &peak,
                                 &rep) != WK_OK
              : wk_solve(&R, V, P, &S, &time_s, &peak) != WK_OK) {
        rc = report(&R, verbose);
        goto done;
    }
    double latest = 0; /* the latest offset time drawn or cut */
    if (offset_polygons || !strcmp(format, "svg"))
        for (uint32_t j = 0; j < n_offsets; j++) latest = offsets[j] > latest ? offsets[j] : latest;
    if (P->pslg && latest > S->horizon && until > 0) {
        WK_FAIL(&R, WK_EUNSUPPORTED, P->name, 0,
                "offset time %g is beyond the horizon --until %g up to which the PSLG's skeleton "
                "is computed: raise --until or leave it out",
                latest, until);
        rc = report(&R, verbose);
        goto done;
    }
    if (P->pslg && latest > S->horizon) {
        /* offsets past the default horizon: the skeleton up to the latest
        ** offset time instead */
        wk_skeleton_free(&R, S);
        S = NULL;
        R.opt.until = latest;
        if (check ? wk_solve_checked(&R, V, P, check_tol * wk_polygon_scale(P), &S, &time_s, &peak,
                                     &rep) != WK_OK
                  : wk_solve(&R, V, P, &S, &time_s, &peak) != WK_OK) {
            rc = report(&R, verbose);
            goto done;
        }
    }
    if (check && stats)
        fprintf(stderr, "check: ok (%u nodes, %u arcs, max distance error %.3g, area error %.3g)\n",
                rep.nodes, rep.arcs, rep.max_distance_error, rep.area_error);

    if (wk_output_open(&R, &out, outpath) != WK_OK) {
        rc = report(&R, verbose);
        goto done;
    }
    wk_run_info info = {wk_variant_name(V), (wk_variant_flags(V) & WK_VARIANT_USES_K) ? k : WK_NONE, time_s, peak,
                        &R.counters, V};
    wk_status st = WK_OK;
    if (offset_polygons) {
        sets = calloc(n_offsets ? n_offsets : 1, sizeof *sets);
        if (!sets) st = WK_FAIL(&R, WK_ENOMEM, NULL, 0, "out of memory (offset list)");
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        for (uint32_t j = 0; j < n_offsets && st == WK_OK; j++)
            st = wk_offset(&R, P, S, offsets[j], &sets[j]);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        offset_s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
        if (st == WK_OK)
            st = !strcmp(format, "wkt") ? wk_write_offsets_wkt(&R, out.f, sets, n_offsets)
                                        : wk_write_offsets_geojson(&R, out.f, P, sets, n_offsets);
    } else if (!strcmp(format, "geojson")) st = wk_write_geojson(&R, out.f, P, S);
    else if (!strcmp(format, "wkt")) st = wk_write_wkt(&R, out.f, P, S);
    else if (!strcmp(format, "json")) st = wk_write_json(&R, out.f, P, S, &info);
    else if (!strcmp(format, "text")) st = wk_write_text(&R, out.f, P, S);
    else if (!strcmp(format, "svg")) st = wk_write_svg(&R, out.f, P, S, offsets, n_offsets);
    else if (!strcmp(format, "obj")) st = wk_write_obj(&R, out.f, P, S);
    else st = wk_write_vtp(&R, out.f, P, S);
    st = wk_output_close(&R, &out, st);
    if (st != WK_OK) {
        rc = report(&R, verbose);
        goto done;
    }
    if (stats) {
        fprintf(stderr, "variant %s  n %u  r %u  nodes %u  arcs %u\n", wk_variant_name(V), P->n, P->r,
                S->n_nodes, S->n_arcs);
        fprintf(stderr, "time_s %.6f  peak_bytes %zu\n", time_s, peak);
        if (wk_variant_phase(V))
            fprintf(stderr, "phase_s %.6f  (%s)\n", R.phase_s, wk_variant_phase(V));
        if (R.fallback_reason[0]) fprintf(stderr, "fallback_reason %s\n", R.fallback_reason);
        if (offset_s >= 0)
            fprintf(stderr, "offset_time_s %.6f  (%u offset times)\n", offset_s, n_offsets);
        for (uint32_t j = 0; j < wk_counter_count(V); j++)
            if (R.counters.c[j])
                fprintf(stderr, "%-32s %llu\n", wk_counter_def_at(V, j)->name,
                        (unsigned long long)R.counters.c[j]);
    }

done:
    wk_output_close(&R, &out, WK_EALGO); /* no-op unless a failure left it open */
    if (sets)
        for (uint32_t j = 0; j < n_offsets; j++) wk_offset_set_free(&R, sets[j]);
    free(sets);
    free(offsets);
    wk_skeleton_free(&R, S);
    wk_polygon_free(&R, P);
    size_t left = wk_run_close(&R);
    if (left != 0 && rc == 0) {
        fprintf(stderr, "wskel: internal error: %zu bytes leaked\n", left);
        rc = 2;
    }
    return rc;
}
