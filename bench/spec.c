/*
** spec.c: the options of bin/wskel-bench from flags and spec files
** (spec.h has the format and the invariants).
*/
#define _GNU_SOURCE
#include "spec.h"
#include "generators.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const char bench_usage_text[] =
    "usage: wskel-bench [--spec FILE] [options] --out CSV\n"
    "Run a benchmark sweep; every configuration in its own child process.\n"
    "\n"
    "sweep (comma-separated lists; later options override earlier ones and the spec):\n"
    "  --family F,..       polygon families (bin/wskel-gen --list), or 'all'\n"
    "  --n N,..            vertex counts; A..B:C gives C values geometric from A to B\n"
    "  --r R,..            reflex vertices: absolute, a fraction of n ('0.25n'),\n"
    "                      or 'default' (the family's rule; the default)\n"
    "  --holes H,..        holes (default 0); H > 0 only for the families that take\n"
    "                      holes (holes, convex), left out for the others\n"
    "  --k K,..            cache sizes: integers, 'pow2' (1,2,4.. up to r), 'max'\n"
    "                      (only variants that use k; default 1)\n"
    "  --variant V,..      registered variants (--list-variants) and 'cgal'\n"
    "                      (bin/wskel-cgal, unit weights only; default naive)\n"
    "  --weights W,..      unit, uniform[:a:b], two[:a:b], int[:a:b] (default unit)\n"
    "  --seeds S,..        seeds, or A..B (default 1); --seeds-count C: 1..C\n"
    "  --repeats N         runs per configuration (default 1)\n"
    "  --cgal-max-n N      skip cgal configurations with n > N\n"
    "  --max-n V=N,..      skip configurations of variant V with n > N (a variant\n"
    "                      too slow for the top of the sweep)\n"
    "\n"
    "limits and checks:\n"
    "  --time-limit SEC    per run, wall clock and CPU (default 60; 0: none)\n"
    "  --mem-limit MB      per run, address space added to the child (default 4096;\n"
    "                      0: none)\n"
    "  --validate          run the validator on each output (not timed)\n"
    "\n"
    "execution and output:\n"
    "  --jobs J            configurations in parallel (OpenMP; default 1).  Parallel\n"
    "                      runs share caches and memory bandwidth and disturb the\n"
    "                      timings: use J > 1 for counters and smoke tests only.\n"
    "  --shard I/N         run only configurations with index = I (mod N)\n"
    "  --resume            keep CSV rows already present, run only the others\n"
    "  --out CSV           output; rows also go to CSV's .jsonl twin\n"
    "  --dry-run           list the configurations and exit\n"
    "  --quiet             no progress line\n"
    "  --qsort-ref         the machine's reference: qsort() of 10^6 random doubles\n"
    "                      (seed 1), median of 5 timings.  Alone (no --family, --n):\n"
    "                      print it in seconds and exit.  With a sweep: measured\n"
    "                      before the first run and after the last, written to the\n"
    "                      CSV as '# qsort_ref_s: SECONDS (...)' comment lines\n"
    "  --list-variants     registered variants\n"
    "\n"
    "statuses: ok timeout out-of-memory crash invalid rejected unsupported algo-failed\n"
    "exit codes: 0 sweep finished (whatever the statuses), 1 I/O error or out of\n"
    "            memory, 64 usage\n";

/* Split s on commas into l (strdup'ed). */
static void split_list(const char *s, str_list *l) {
    l->n = 0;
    char *copy = xstrdup(s), *save = NULL;
    for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        while (*t == ' ') t++;
        size_t len = strlen(t);
        while (len && t[len - 1] == ' ') t[--len] = 0;
        if (!*t) continue;
        if (l->n == MAX_LIST) die_usage("more than %d values in '%s'", MAX_LIST, s);
        l->v[l->n++] = xstrdup(t);
    }
    free(copy);
}

uint64_t parse_u64(const char *key, const char *s) {
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno || end == s || *end || s[0] == '-') die_usage("--%s: '%s' is not a non-negative integer", key, s);
    return v;
}

static double parse_double(const char *key, const char *s) {
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !(v >= 0) || !isfinite(v))
        die_usage("--%s: '%s' is not a non-negative number", key, s);
    return v;
}

static void u64_push(u64_list *l, uint64_t v, const char *key) {
    if (l->n == MAX_LIST) die_usage("--%s: more than %d values", key, MAX_LIST);
    l->v[l->n++] = v;
}

/* "A,B,..", "A..B" (every integer, for seeds) or "A..B:C" (C geometric). */
static void parse_u64_list(const char *key, const char *s, u64_list *l) {
    str_list parts;
    split_list(s, &parts);
    l->n = 0;
    for (int i = 0; i < parts.n; i++) {
        char *dots = strstr(parts.v[i], "..");
        if (!dots) {
            u64_push(l, parse_u64(key, parts.v[i]), key);
            continue;
        }
        *dots = 0;
        char *colon = strchr(dots + 2, ':');
        if (colon) *colon = 0;
        uint64_t a = parse_u64(key, parts.v[i]), b = parse_u64(key, dots + 2);
        if (a > b || a == 0) die_usage("--%s: bad range %s..%s", key, parts.v[i], dots + 2);
        if (!colon) {
            if (b - a >= MAX_LIST) die_usage("--%s: range too long", key);
            for (uint64_t v = a; v <= b; v++) u64_push(l, v, key);
        } else {
            uint64_t c = parse_u64(key, colon + 1);
            if (c < 2) die_usage("--%s: A..B:C needs C >= 2", key);
            uint64_t prev = 0;
            for (uint64_t j = 0; j < c; j++) {
                double v = (double)a * pow((double)b / (double)a, (double)j / (double)(c - 1));
                uint64_t x = (uint64_t)llround(v);
                if (j == c - 1) x = b;
                if (x != prev) u64_push(l, x, key);
                prev = x;
            }
        }
    }
    for (int i = 0; i < parts.n; i++) free(parts.v[i]);
}

static bool parse_bool(const char *key, const char *s) {
    if (!strcmp(s, "1") || !strcmp(s, "true") || !strcmp(s, "yes") || !strcmp(s, "on")) return true;
    if (!strcmp(s, "0") || !strcmp(s, "false") || !strcmp(s, "no") || !strcmp(s, "off")) return false;
    die_usage("--%s: '%s' is not true or false", key, s);
    return false;
}

/* Spec files: "key = value" lines (keys as the long flags), '#' comments,
** blank lines; a key without '=' is a boolean flag set to true. */
void load_spec(options *o, const char *path) {
    FILE *f = fopen(path, "r");
    if (!f) die_usage("--spec: %s: %s", path, strerror(errno));
    char line[4096];
    long lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *h = strchr(line, '#');
        if (h) *h = 0;
        char *s = line;
        while (*s == ' ' || *s == '\t') s++;
        size_t len = strlen(s);
        while (len && (s[len - 1] == '\n' || s[len - 1] == '\r' || s[len - 1] == ' ' || s[len - 1] == '\t'))
            s[--len] = 0;
        if (!*s) continue;
        char *eq = strchr(s, '=');
        const char *val = "true";
        if (eq) {
            *eq = 0;
            val = eq + 1;
            while (*val == ' ' || *val == '\t') val++;
            size_t kl = strlen(s);
            while (kl && (s[kl - 1] == ' ' || s[kl - 1] == '\t')) s[--kl] = 0;
        }
        if (!strcmp(s, "spec")) die_usage("%s:%ld: a spec cannot include another", path, lineno);
        set_option(o, s, val);
    }
    fclose(f);
}

void set_option(options *o, const char *key, const char *val) {
    if (!strcmp(key, "family")) split_list(val, &o->families);
    else if (!strcmp(key, "variant")) split_list(val, &o->variants);
    else if (!strcmp(key, "weights")) split_list(val, &o->weights);
    else if (!strcmp(key, "k")) split_list(val, &o->k_spec);
    else if (!strcmp(key, "n")) parse_u64_list(key, val, &o->n);
    else if (!strcmp(key, "seeds")) parse_u64_list(key, val, &o->seeds);
    else if (!strcmp(key, "holes")) {
        parse_u64_list(key, val, &o->holes);
        for (int i = 0; i < o->holes.n; i++)
            if (o->holes.v[i] >= WK_POLYGON_MAX_RINGS)
                die_usage("--holes: %llu is too many (at most %u)",
                          (unsigned long long)o->holes.v[i], WK_POLYGON_MAX_RINGS - 1);
        if (o->holes.n == 0) die_usage("--holes: no value");
    }
    else if (!strcmp(key, "seeds-count")) {
        uint64_t c = parse_u64(key, val);
        if (c < 1 || c > MAX_LIST) die_usage("--seeds-count: 1..%d", MAX_LIST);
        o->seeds.n = 0;
        for (uint64_t s = 1; s <= c; s++) u64_push(&o->seeds, s, key);
    } else if (!strcmp(key, "r")) {
        str_list l;
        split_list(val, &l);
        o->n_r = 0;
        for (int i = 0; i < l.n; i++) {
            r_req q = {0, -1};
            size_t len = strlen(l.v[i]);
            if (!strcmp(l.v[i], "default")) {
            } else if (len > 1 && l.v[i][len - 1] == 'n') {
                l.v[i][len - 1] = 0;
                q.frac = parse_double(key, l.v[i]);
                if (q.frac <= 0 || q.frac > 1) die_usage("--r: fraction %sn out of (0, 1]", l.v[i]);
            } else {
                q.abs = (int64_t)parse_u64(key, l.v[i]);
            }
            o->r[o->n_r++] = q;
            free(l.v[i]);
        }
    } else if (!strcmp(key, "repeats")) {
        o->repeats = (int)parse_u64(key, val);
        if (o->repeats < 1) die_usage("--repeats must be >= 1");
    } else if (!strcmp(key, "time-limit")) o->time_limit = parse_double(key, val);
    else if (!strcmp(key, "mem-limit")) o->mem_limit_mb = parse_double(key, val);
    else if (!strcmp(key, "validate")) o->validate = parse_bool(key, val);
    else if (!strcmp(key, "resume")) o->resume = parse_bool(key, val);
    else if (!strcmp(key, "quiet")) o->quiet = parse_bool(key, val);
    else if (!strcmp(key, "qsort-ref")) o->qsort_ref = parse_bool(key, val);
    else if (!strcmp(key, "jobs")) {
        o->jobs = (int)parse_u64(key, val);
        if (o->jobs < 1) die_usage("--jobs must be >= 1");
    } else if (!strcmp(key, "cgal-max-n")) o->cgal_max_n = parse_u64(key, val);
    else if (!strcmp(key, "max-n")) {
        str_list l;
        split_list(val, &l);
        o->max_n_variant.n = o->max_n.n = 0;
        for (int i = 0; i < l.n; i++) {
            char *c = strchr(l.v[i], '=');
            if (!c || c == l.v[i]) die_usage("--max-n: '%s' is not VARIANT=N", l.v[i]);
            *c = 0;
            o->max_n_variant.v[o->max_n_variant.n++] = l.v[i];
            u64_push(&o->max_n, parse_u64(key, c + 1), key);
        }
    }
    else if (!strcmp(key, "out")) snprintf(o->out, sizeof o->out, "%s", val);
    else if (!strcmp(key, "shard")) {
        int i, n;
        char extra;
        if (sscanf(val, "%d/%d%c", &i, &n, &extra) != 2 || n < 1 || i < 0 || i >= n)
            die_usage("--shard: '%s' is not I/N with 0 <= I < N", val);
        o->shard_i = i;
        o->shard_n = n;
    } else if (!strcmp(key, "self-test")) {
        /* Test-only: MODE or MODE:INDEX (the configuration it applies to). */
        char mode[16] = "";
        long idx = -1;
        const char *c = strchr(val, ':');
        size_t ml = c ? (size_t)(c - val) : strlen(val);
        if (ml >= sizeof mode) ml = sizeof mode - 1;
        memcpy(mode, val, ml);
        mode[ml] = 0;
        if (c) idx = (long)parse_u64(key, c + 1);
        if (strcmp(mode, "crash") && strcmp(mode, "hang") && strcmp(mode, "oom"))
            die_usage("--self-test: crash, hang or oom");
        snprintf(o->self_test, sizeof o->self_test, "%s", mode);
        o->self_test_index = idx;
    } else die_usage("unknown option '%s'", key);
}

void options_init(options *o) {
    memset(o, 0, sizeof *o);
    o->repeats = 1;
    o->time_limit = 60;
    o->mem_limit_mb = 4096;
    o->jobs = 1;
    o->shard_n = 1;
    o->self_test_index = -1;
    split_list("naive", &o->variants);
    split_list("unit", &o->weights);
    split_list("1", &o->k_spec);
    o->seeds.n = 1;
    o->seeds.v[0] = 1;
    o->holes.n = 1;
    o->holes.v[0] = 0;
    o->n_r = 1;
    o->r[0] = (r_req){0, -1};
}

bool options_from_argv(options *o, int argc, char **argv, bool *dry, int *exit_code) {
    *dry = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(bench_usage_text, stdout);
            *exit_code = 0;
            return false;
        }
        if (!strcmp(a, "--list-variants")) {
            for (size_t j = 0; wk_variant_at(j); j++)
                printf("%-14s %s\n", wk_variant_name(wk_variant_at(j)),
                       wk_variant_summary(wk_variant_at(j)));
            printf("%-14s %s\n", "cgal", "CGAL 5.5 straight skeleton via bin/wskel-cgal (unit weights)");
            *exit_code = 0;
            return false;
        }
        if (!strcmp(a, "--dry-run")) {
            *dry = true;
            continue;
        }
        if (strncmp(a, "--", 2) != 0) die_usage("unexpected argument '%s'", a);
        const char *key = a + 2;
        if (!strcmp(key, "validate") || !strcmp(key, "resume") || !strcmp(key, "quiet") ||
            !strcmp(key, "qsort-ref")) {
            set_option(o, key, "true");
            continue;
        }
        if (i + 1 >= argc) die_usage("%s needs a value", a);
        if (!strcmp(key, "spec")) {
            snprintf(o->spec, sizeof o->spec, "%s", argv[i + 1]);
            load_spec(o, argv[++i]);
        } else set_option(o, key, argv[++i]);
    }
    return true;
}

void options_finish(options *o, const char *cgal_bin) {
    if (o->families.n == 0) die_usage("no --family");
    if (o->n.n == 0) die_usage("no --n");
    if (o->families.n == 1 && !strcmp(o->families.v[0], "all")) {
        o->families.n = 0;
        for (int i = 0; wk_gen_families[i]; i++) o->families.v[o->families.n++] = (char *)wk_gen_families[i];
    }
    for (int i = 0; i < o->families.n; i++)
        if (!wk_gen_family_summary(o->families.v[i])) die_usage("unknown family '%s'", o->families.v[i]);
    int m = 0;
    for (int i = 0; i < o->variants.n; i++) {
        const char *v = o->variants.v[i];
        if (!strcmp(v, "cgal")) {
            if (access(cgal_bin, X_OK) != 0) {
                fprintf(stderr, "wskel-bench: warning: %s not found (libcgal-dev missing?): "
                                "skipping the cgal peer\n", cgal_bin);
                continue;
            }
        } else if (!wk_variant_find(v)) die_usage("unknown variant '%s'", v);
        o->variants.v[m++] = o->variants.v[i];
    }
    o->variants.n = m;
    /* Canonical weight texts, so keys compare equal across spellings. */
    for (int i = 0; i < o->weights.n; i++) {
        wk_run R;
        wk_run_init(&R);
        wk_gen_params g;
        wk_gen_params_init(&g);
        if (wk_gen_parse_weights(&R, o->weights.v[i], &g) != WK_OK) die_usage("bad weight mode '%s'", o->weights.v[i]);
        char buf[128];
        wk_gen_weights_format(&g, buf, sizeof buf);
        o->weights.v[i] = xstrdup(buf);
    }
}
