/*
** wskel_bench.c: bin/wskel-bench, the benchmark harness.
**
** A sweep is the cross product of families x n x r x weights x seeds x
** variants x k x repeats, given by flags or by a spec file (bench/sweeps/,
** "key = value" lines with the flags' names).  Every configuration runs in
** its own forked child under setrlimit limits:
**
**   child:  generate the polygon (not timed) -> wk_solve (timed: wall and CPU
**           of the construction only) -> wk_validate if asked (not timed),
**           writing a fixed-size record to a pipe after each phase;
**   parent: wait4 (peak RSS), read the last record, classify the status.
**
** Statuses: ok, timeout, out-of-memory, crash (with the signal), invalid
** (validator failed), rejected (generator or input refused), unsupported
** (the variant does not apply: monotone on a polygon monotone in no
** direction), algo-failed.
** A failing run never stops the sweep.
**
** The peer `cgal` runs bin/wskel-cgal (CGAL's straight skeleton, unit weights
** only) on the same polygon: the child writes a temporary .wpoly and execs the
** program; wall_s is the construction time the program reports (time_s),
** cpu_s is left empty (the program does not report it).
**
** Output: CSV (authoritative) with '#' comment lines recording the machine
** and the columns, plus the same rows as JSON lines in OUT.jsonl.  Rows are
** appended and flushed one by one in configuration order, so an interrupted
** sweep loses at most the runs in flight and --resume skips every
** configuration already in the CSV.
**
** Invariants: the configuration list depends only on the options (never on
** the machine or on results), so --shard I/N and --resume agree between runs;
** the parent holds no run context (each child builds its own wk_run).
*/
#define _GNU_SOURCE
#include "generators.h"
#include "wskel.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define EXIT_USAGE 64
#define MAX_LIST 256
#define K_NA WK_NONE /* variant without a k: the k column is empty (WK_K_MAX is "max") */

/* ------------------------------------------------------------ options */

typedef struct str_list { char *v[MAX_LIST]; int n; } str_list;
typedef struct u64_list { uint64_t v[MAX_LIST]; int n; } u64_list;

/* An r request: fraction of n (frac > 0), absolute (abs >= 0) or the
** family's default (both unset). */
typedef struct r_req { double frac; int64_t abs; } r_req;

typedef struct options {
    str_list families, variants, weights, k_spec;
    u64_list n, seeds;
    r_req r[MAX_LIST];
    int n_r;
    int repeats;
    double time_limit;     /* seconds per run, wall and CPU; 0: none */
    double mem_limit_mb;   /* MB added to the child's address space; 0: none */
    bool validate;
    int jobs;
    int shard_i, shard_n;
    bool resume;
    bool quiet;
    char out[1024];
    uint64_t cgal_max_n;   /* skip cgal above this n; 0: no cap */
    char self_test[16];    /* crash|hang|oom, test-only */
    long self_test_index;  /* configuration index it applies to; -1: all */
    char spec[1024];
} options;

/* One run to do.  k is WK_K_MAX for max, K_NA when the variant has none. */
typedef struct config {
    const char *variant;   /* points into options (or "cgal") */
    const char *family;
    const char *weights;   /* canonical text */
    uint32_t n;
    int64_t r_req;         /* -1: the family's default */
    uint32_t k;
    uint64_t seed;
    int repeat;
    long index;            /* position in the full list */
} config;

/* The record a child sends after each phase; small enough (< PIPE_BUF) that
** each write is atomic and never blocks. */
typedef struct child_rec {
    int phase;             /* 1 generated, 2 solved, 3 done */
    int status;            /* wk_status of the last phase */
    int what;              /* 0 generation, 1 solve, 2 validation */
    uint32_t n, r, nodes, arcs;
    double wall_s, cpu_s;
    uint64_t peak_tracked;
    wk_counters c;
    char msg[400];
} child_rec;

typedef struct result {
    char status[16];
    int sig;
    uint32_t r, nodes, arcs;
    bool have_counters, have_time, have_cpu, validated;
    double wall_s, cpu_s;
    uint64_t peak_rss, peak_tracked;
    wk_counters c;
    char msg[512];
} result;

static void die_usage(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fputs("wskel-bench: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputs(" (see --help)\n", stderr);
    va_end(ap);
    exit(EXIT_USAGE);
}

static const char usage_text[] =
    "usage: wskel-bench [--spec FILE] [options] --out CSV\n"
    "Run a benchmark sweep; every configuration in its own child process.\n"
    "\n"
    "sweep (comma-separated lists; later options override earlier ones and the spec):\n"
    "  --family F,..       polygon families (bin/wskel-gen --list), or 'all'\n"
    "  --n N,..            vertex counts; A..B:C gives C values geometric from A to B\n"
    "  --r R,..            reflex vertices: absolute, a fraction of n ('0.25n'),\n"
    "                      or 'default' (the family's rule; the default)\n"
    "  --k K,..            cache sizes: integers, 'pow2' (1,2,4.. up to r), 'max'\n"
    "                      (only variants that use k; default 1)\n"
    "  --variant V,..      registered variants (--list-variants) and 'cgal'\n"
    "                      (bin/wskel-cgal, unit weights only; default naive)\n"
    "  --weights W,..      unit, uniform[:a:b], two[:a:b], int[:a:b] (default unit)\n"
    "  --seeds S,..        seeds, or A..B (default 1); --seeds-count C: 1..C\n"
    "  --repeats N         runs per configuration (default 1)\n"
    "  --cgal-max-n N      skip cgal configurations with n > N\n"
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
    "  --list-variants     registered variants\n"
    "\n"
    "statuses: ok timeout out-of-memory crash invalid rejected unsupported algo-failed\n"
    "exit codes: 0 sweep finished (whatever the statuses), 1 I/O error, 64 usage\n";

/* Split s on commas into l (strdup'ed). */
static void split_list(const char *s, str_list *l) {
    l->n = 0;
    char *copy = strdup(s), *save = NULL;
    for (char *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        while (*t == ' ') t++;
        size_t len = strlen(t);
        while (len && t[len - 1] == ' ') t[--len] = 0;
        if (!*t) continue;
        if (l->n == MAX_LIST) die_usage("more than %d values in '%s'", MAX_LIST, s);
        l->v[l->n++] = strdup(t);
    }
    free(copy);
}

static uint64_t parse_u64(const char *key, const char *s) {
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

static void set_option(options *o, const char *key, const char *val);

/* Spec files: "key = value" lines (keys as the long flags), '#' comments,
** blank lines; a key without '=' is a boolean flag set to true. */
static void load_spec(options *o, const char *path) {
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

static void set_option(options *o, const char *key, const char *val) {
    if (!strcmp(key, "family")) split_list(val, &o->families);
    else if (!strcmp(key, "variant")) split_list(val, &o->variants);
    else if (!strcmp(key, "weights")) split_list(val, &o->weights);
    else if (!strcmp(key, "k")) split_list(val, &o->k_spec);
    else if (!strcmp(key, "n")) parse_u64_list(key, val, &o->n);
    else if (!strcmp(key, "seeds")) parse_u64_list(key, val, &o->seeds);
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
    else if (!strcmp(key, "jobs")) {
        o->jobs = (int)parse_u64(key, val);
        if (o->jobs < 1) die_usage("--jobs must be >= 1");
    } else if (!strcmp(key, "cgal-max-n")) o->cgal_max_n = parse_u64(key, val);
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

/* ------------------------------------------------------------ configs */

static bool variant_uses_k(const char *name) {
    const wk_variant *V = wk_variant_find(name);
    return V && (V->flags & WK_VARIANT_USES_K);
}

static int64_t resolve_r(const r_req *q, uint64_t n) {
    if (q->frac > 0) return (int64_t)floor(q->frac * (double)n);
    return q->abs;
}

/* Append the k values of k_spec for a run with requested r (or n). */
static int expand_k(const str_list *ks, int64_t r, uint64_t n, uint32_t *out) {
    int c = 0;
    uint64_t top = r >= 0 ? (uint64_t)r : n;
    if (top < 1) top = 1;
    for (int i = 0; i < ks->n; i++) {
        const char *s = ks->v[i];
        if (!strcmp(s, "max")) out[c++] = WK_K_MAX;
        else if (!strcmp(s, "pow2")) {
            for (uint64_t k = 1; k <= top && c < MAX_LIST; k *= 2) out[c++] = (uint32_t)k;
        } else {
            uint64_t k = parse_u64("k", s);
            if (k < 1 || k >= WK_K_MAX) die_usage("--k: %s out of range", s);
            out[c++] = (uint32_t)k;
        }
        if (c >= MAX_LIST - 1) break;
    }
    /* drop duplicates, keeping the first occurrence (deterministic) */
    int m = 0;
    for (int i = 0; i < c; i++) {
        bool dup = false;
        for (int j = 0; j < m; j++) dup |= out[j] == out[i];
        if (!dup) out[m++] = out[i];
    }
    return m;
}

/* The full configuration list in its fixed order:
** family > n > r > weights > seed > variant > k > repeat. */
static config *build_configs(const options *o, long *count) {
    size_t cap = 1024, c = 0;
    config *v = malloc(cap * sizeof *v);
    uint32_t ks[MAX_LIST];
    for (int fi = 0; fi < o->families.n; fi++)
        for (int ni = 0; ni < o->n.n; ni++)
            for (int ri = 0; ri < o->n_r; ri++)
                for (int wi = 0; wi < o->weights.n; wi++)
                    for (int si = 0; si < o->seeds.n; si++)
                        for (int vi = 0; vi < o->variants.n; vi++) {
                            const char *var = o->variants.v[vi];
                            uint64_t n = o->n.v[ni];
                            int64_t r = resolve_r(&o->r[ri], n);
                            bool cgal = !strcmp(var, "cgal");
                            if (cgal && strcmp(o->weights.v[wi], "unit")) continue;
                            if (cgal && o->cgal_max_n && n > o->cgal_max_n) continue;
                            int nk = 1;
                            if (variant_uses_k(var)) nk = expand_k(&o->k_spec, r, n, ks);
                            else ks[0] = K_NA;
                            for (int ki = 0; ki < nk; ki++)
                                for (int rep = 0; rep < o->repeats; rep++) {
                                    if (c == cap) v = realloc(v, (cap *= 2) * sizeof *v);
                                    v[c] = (config){var, o->families.v[fi], o->weights.v[wi],
                                                    (uint32_t)n, r, ks[ki], o->seeds.v[si], rep,
                                                    (long)c};
                                    c++;
                                }
                        }
    *count = (long)c;
    return v;
}

static void format_k(uint32_t k, char *buf, size_t size) {
    if (k == K_NA) snprintf(buf, size, "%s", "");
    else if (k == WK_K_MAX) snprintf(buf, size, "max");
    else snprintf(buf, size, "%u", k);
}

/* The resume key: the configuration columns as they appear in the CSV. */
static void config_key(const config *c, char *buf, size_t size) {
    char k[24];
    format_k(c->k, k, sizeof k);
    snprintf(buf, size, "%s,%s,%u,%lld,%s,%s,%llu,%d", c->variant, c->family, c->n,
             (long long)c->r_req, k, c->weights, (unsigned long long)c->seed, c->repeat);
}

/* --------------------------------------------------------------- child */

static void send_rec(int fd, const child_rec *rec) {
    ssize_t w = write(fd, rec, sizeof *rec);
    (void)w; /* the parent treats a missing record as a crash */
}

static void limit_child(const options *o) {
    if (o->time_limit > 0) {
        struct itimerval it = {{0, 0}, {(time_t)o->time_limit,
                                        (suseconds_t)((o->time_limit - floor(o->time_limit)) * 1e6)}};
        if (it.it_value.tv_sec == 0 && it.it_value.tv_usec == 0) it.it_value.tv_usec = 1;
        setitimer(ITIMER_REAL, &it, NULL); /* SIGALRM kills: wall-clock limit */
        struct rusage ru;
        getrusage(RUSAGE_SELF, &ru);
        rlim_t used = (rlim_t)ru.ru_utime.tv_sec + (rlim_t)ru.ru_stime.tv_sec;
        rlim_t cpu = used + (rlim_t)ceil(o->time_limit) + 1;
        struct rlimit rl = {cpu, cpu + 1}; /* SIGXCPU, then SIGKILL */
        setrlimit(RLIMIT_CPU, &rl);
    }
    if (o->mem_limit_mb > 0) {
        /* The limit is on top of the address space the child starts with
        ** (libraries, OpenMP runtime), so it means "memory the run may add". */
        unsigned long vsz = 0;
        FILE *f = fopen("/proc/self/statm", "r");
        if (f) {
            if (fscanf(f, "%lu", &vsz) != 1) vsz = 0;
            fclose(f);
        }
        rlim_t as = (rlim_t)vsz * (rlim_t)sysconf(_SC_PAGESIZE) + (rlim_t)(o->mem_limit_mb * 1048576.0);
        struct rlimit rl = {as, as};
        setrlimit(RLIMIT_AS, &rl);
    }
}

static double cpu_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void copy_err(const wk_run *R, child_rec *rec) {
    char buf[1024];
    wk_error_format(R, buf, sizeof buf);
    snprintf(rec->msg, sizeof rec->msg, "%.399s", buf);
}

static void self_test(wk_run *R, const char *mode) {
    if (!strcmp(mode, "crash")) raise(SIGSEGV);
    if (!strcmp(mode, "hang")) {
        volatile uint64_t x = 0;
        for (;;) x++;
    }
    if (!strcmp(mode, "oom")) {
        /* Grow through the run's allocator until the address-space limit
        ** refuses; touch the memory so peak RSS shows it.  Leaked on
        ** purpose: the child exits right after. */
        for (;;) {
            size_t sz = (size_t)64 << 20;
            char *p = wk_realloc(R, NULL, 0, sz);
            if (!p) return;
            memset(p, 1, sz);
        }
    }
}

/* Runs in the child; never returns. */
static void child_main(const options *o, const config *c, int fd, const char *cgal_bin,
                       const char *tmp_poly, const char *tmp_out, const char *tmp_err) {
    child_rec rec;
    memset(&rec, 0, sizeof rec);
    wk_run R;
    wk_run_init(&R);
    R.opt.threads = 1;
    wk_gen_params g;
    wk_gen_params_init(&g);
    g.family = c->family;
    g.n = c->n;
    g.r = c->r_req;
    g.seed = c->seed;
    limit_child(o);
    wk_status st = wk_gen_parse_weights(&R, c->weights, &g);
    wk_polygon *P = NULL;
    if (st == WK_OK) st = wk_generate(&R, &g, &P);
    rec.phase = 1;
    rec.what = 0;
    rec.status = st;
    if (st != WK_OK) {
        copy_err(&R, &rec);
        send_rec(fd, &rec);
        _exit(0);
    }
    rec.n = P->n;
    rec.r = P->r;
    send_rec(fd, &rec);

    bool self = o->self_test[0] && (o->self_test_index < 0 || o->self_test_index == c->index);
    if (self) self_test(&R, o->self_test);

    if (!strcmp(c->variant, "cgal")) {
        FILE *f = fopen(tmp_poly, "w");
        if (!f || wk_polygon_write_wpoly(&R, f, P) != WK_OK || fclose(f) != 0) _exit(120);
        int out = open(tmp_out, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        int err = open(tmp_err, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (out < 0 || err < 0) _exit(120);
        dup2(out, 1);
        dup2(err, 2);
        close(out);
        close(err);
        close(fd);
        execl(cgal_bin, cgal_bin, "--stats", tmp_poly, (char *)NULL);
        _exit(121);
    }

    const wk_variant *V = wk_variant_find(c->variant);
    R.opt.variant = V->name;
    R.opt.k = c->k == K_NA ? 1 : c->k;
    wk_skeleton *S = NULL;
    double wall = 0;
    size_t peak = 0;
    double c0 = cpu_now();
    if (self && !strcmp(o->self_test, "oom")) st = R.err.code != WK_OK ? R.err.code : WK_ENOMEM;
    else st = wk_solve(&R, V, P, &S, &wall, &peak);
    double c1 = cpu_now();
    rec.phase = 2;
    rec.what = 1;
    rec.status = st;
    rec.wall_s = wall;
    rec.cpu_s = c1 - c0;
    rec.peak_tracked = peak;
    rec.c = R.counters;
    if (S) {
        rec.nodes = S->n_nodes;
        rec.arcs = S->n_arcs;
    }
    if (st != WK_OK) copy_err(&R, &rec);
    if (st == WK_OK && o->validate) {
        send_rec(fd, &rec);
        if (o->time_limit > 0) limit_child(o); /* a fresh budget for validation */
        wk_status vs = wk_validate(&R, P, S, 0, NULL);
        rec.what = 2;
        rec.status = vs;
        if (vs != WK_OK) copy_err(&R, &rec);
    }
    rec.phase = 3;
    send_rec(fd, &rec);
    _exit(0);
}

/* -------------------------------------------------------------- parent */

static const char *status_of(int what, wk_status st) {
    switch (st) {
    case WK_OK: return "ok";
    case WK_ENOMEM: return "out-of-memory";
    case WK_EINVALID: return "invalid";
    case WK_EINPUT: case WK_EUSAGE: return what == 0 || what == 1 ? "rejected" : "algo-failed";
    case WK_EALGO: return what == 0 ? "rejected" : "algo-failed";
    case WK_EUNSUPPORTED: return "unsupported";
    }
    return "algo-failed";
}

static char *slurp(const char *path) {
    FILE *f = fopen(path, "r");
    if (!f) return NULL;
    size_t cap = 4096, len = 0;
    char *b = malloc(cap);
    size_t got;
    while ((got = fread(b + len, 1, cap - len - 1, f)) > 0) {
        len += got;
        if (cap - len < 2) b = realloc(b, cap *= 2);
    }
    b[len] = 0;
    fclose(f);
    return b;
}

/* Fill res from wskel-cgal's --stats line on stderr. */
static void parse_cgal(const char *tmp_err, int code, result *res) {
    char *e = slurp(tmp_err);
    const char *s = e ? strstr(e, "nodes=") : NULL;
    unsigned nodes, arcs;
    double t;
    if (code == 0 && s && sscanf(s, "nodes=%u arcs=%u time_s=%lf", &nodes, &arcs, &t) == 3) {
        strcpy(res->status, "ok");
        res->nodes = nodes;
        res->arcs = arcs;
        res->wall_s = t;
        res->have_time = true;
    } else {
        if (e && strstr(e, "bad_alloc")) strcpy(res->status, "out-of-memory");
        else if (code == 1) strcpy(res->status, "rejected");
        else strcpy(res->status, "algo-failed");
        if (e) {
            char *nl;
            while ((nl = strchr(e, '\n'))) *nl = ' ';
        }
        snprintf(res->msg, sizeof res->msg, "wskel-cgal exit %d: %.400s", code, e ? e : "");
    }
    free(e);
}

static void run_config(const options *o, const config *c, const char *cgal_bin, result *res) {
    memset(res, 0, sizeof *res);
    int p[2];
    if (pipe(p) != 0) {
        strcpy(res->status, "crash");
        snprintf(res->msg, sizeof res->msg, "pipe: %s", strerror(errno));
        return;
    }
    char tmp_poly[256] = "", tmp_out[256] = "", tmp_err[256] = "";
    const char *tdir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    snprintf(tmp_poly, sizeof tmp_poly, "%s/wskel-bench.%ld.%ld.wpoly", tdir, (long)getpid(), c->index);
    snprintf(tmp_out, sizeof tmp_out, "%s/wskel-bench.%ld.%ld.json", tdir, (long)getpid(), c->index);
    snprintf(tmp_err, sizeof tmp_err, "%s/wskel-bench.%ld.%ld.err", tdir, (long)getpid(), c->index);
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        /* Other jobs' pipes must not stay open in this child. */
        for (int fd = 3; fd < 1024; fd++)
            if (fd != p[1]) close(fd);
        child_main(o, c, p[1], cgal_bin, tmp_poly, tmp_out, tmp_err);
    }
    close(p[1]);
    if (pid < 0) {
        close(p[0]);
        strcpy(res->status, "crash");
        snprintf(res->msg, sizeof res->msg, "fork: %s", strerror(errno));
        return;
    }
    /* Read records until EOF (the child exited or exec'd) or the pipe stays
    ** silent; records are atomic, so partial reads cannot happen. */
    child_rec rec, last;
    memset(&last, 0, sizeof last);
    ssize_t got;
    while ((got = read(p[0], &rec, sizeof rec)) != 0) {
        if (got < 0) {
            if (errno == EINTR) continue;
            break;
        }
        if (got == (ssize_t)sizeof rec) last = rec;
    }
    close(p[0]);
    int wst = 0;
    struct rusage ru;
    while (wait4(pid, &wst, 0, &ru) < 0 && errno == EINTR) {
    }
    res->peak_rss = (uint64_t)ru.ru_maxrss * 1024u;
    res->r = last.r;
    bool cgal = !strcmp(c->variant, "cgal");

    if (WIFSIGNALED(wst)) {
        int sig = WTERMSIG(wst);
        const char *phase = last.phase == 0 ? "generation" : last.phase == 1 ? "construction" : "validation";
        if (sig == SIGALRM || sig == SIGXCPU || (sig == SIGKILL && o->time_limit > 0)) {
            strcpy(res->status, "timeout");
            snprintf(res->msg, sizeof res->msg, "time limit %gs exceeded during %s", o->time_limit, phase);
        } else {
            char *e = cgal ? slurp(tmp_err) : NULL;
            if (e && strstr(e, "bad_alloc")) {
                strcpy(res->status, "out-of-memory");
                snprintf(res->msg, sizeof res->msg, "std::bad_alloc in wskel-cgal (limit %g MB)", o->mem_limit_mb);
            } else {
                strcpy(res->status, "crash");
                res->sig = sig;
                snprintf(res->msg, sizeof res->msg, "signal %d (%s) during %s", sig, strsignal(sig), phase);
            }
            free(e);
        }
        if (last.phase >= 2) {
            res->have_counters = true;
            res->c = last.c;
            res->wall_s = last.wall_s;
            res->cpu_s = last.cpu_s;
            res->have_time = res->have_cpu = true;
            res->peak_tracked = last.peak_tracked;
            res->nodes = last.nodes;
            res->arcs = last.arcs;
        }
    } else if (cgal && last.phase == 1 && last.status == WK_OK) {
        int code = WEXITSTATUS(wst);
        if (code == 120 || code == 121) {
            strcpy(res->status, "crash");
            snprintf(res->msg, sizeof res->msg, "could not %s", code == 120 ? "write the temporary polygon" : "exec wskel-cgal");
        } else parse_cgal(tmp_err, code, res);
    } else if (last.phase == 0 || WEXITSTATUS(wst) != 0) {
        strcpy(res->status, "crash");
        snprintf(res->msg, sizeof res->msg, "child exited with code %d without a result", WEXITSTATUS(wst));
    } else {
        strcpy(res->status, status_of(last.what, (wk_status)last.status));
        snprintf(res->msg, sizeof res->msg, "%s", last.msg);
        if (last.what >= 1) {
            res->have_counters = true;
            res->c = last.c;
            res->wall_s = last.wall_s;
            res->cpu_s = last.cpu_s;
            res->have_time = res->have_cpu = last.status == WK_OK || last.what == 2;
            res->peak_tracked = last.peak_tracked;
            res->nodes = last.nodes;
            res->arcs = last.arcs;
        }
        res->validated = last.what == 2;
        if (last.what == 0 && last.status == WK_OK) {
            strcpy(res->status, "crash");
            snprintf(res->msg, sizeof res->msg, "child stopped after generation");
        }
    }
    if (cgal) {
        unlink(tmp_poly);
        unlink(tmp_out);
        unlink(tmp_err);
    }
}

/* -------------------------------------------------------------- output */

static const char *const counter_names[] = {
#define WK_COUNTER_NAME(name) #name,
    WK_COUNTER_LIST(WK_COUNTER_NAME)
#undef WK_COUNTER_NAME
};
#define N_COUNTERS (sizeof counter_names / sizeof counter_names[0])

static void counters_array(const wk_counters *c, uint64_t *out) {
    size_t i = 0;
#define WK_COUNTER_COPY(name) out[i++] = c->name;
    WK_COUNTER_LIST(WK_COUNTER_COPY)
#undef WK_COUNTER_COPY
}

static const char base_columns[] =
    "variant,family,n,r_req,k,weights,seed,repeat,r,status,signal,wall_s,cpu_s,"
    "peak_rss_bytes,peak_tracked_bytes,nodes,arcs,crossings,validated";

/* A growable string for one output row. */
typedef struct sbuf { char *s; size_t len, cap; } sbuf;
static void sb_printf(sbuf *b, const char *fmt, ...) {
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int need = vsnprintf(b->s ? b->s + b->len : NULL, b->s ? b->cap - b->len : 0, fmt, ap);
        va_end(ap);
        if (b->s && (size_t)need < b->cap - b->len) {
            b->len += (size_t)need;
            return;
        }
        b->cap = (b->cap + (size_t)need + 1) * 2;
        b->s = realloc(b->s, b->cap);
        if (b->len == 0) b->s[0] = 0;
    }
}

static void sb_num(sbuf *b, bool have, double v) {
    if (have) sb_printf(b, "%.9g", v);
}

/* CSV quoting; newlines become spaces. */
static void sb_csv_str(sbuf *b, const char *s) {
    sb_printf(b, "\"");
    for (; *s; s++) {
        if (*s == '"') sb_printf(b, "\"\"");
        else if (*s == '\n' || *s == '\r') sb_printf(b, " ");
        else sb_printf(b, "%c", *s);
    }
    sb_printf(b, "\"");
}

static void sb_json_str(sbuf *b, const char *s) {
    sb_printf(b, "\"");
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') sb_printf(b, "\\%c", ch);
        else if (ch < 0x20) sb_printf(b, "\\u%04x", ch);
        else sb_printf(b, "%c", ch);
    }
    sb_printf(b, "\"");
}

static void format_rows(const config *c, const result *r, sbuf *csv, sbuf *js) {
    char key[512], k[24];
    config_key(c, key, sizeof key);
    format_k(c->k, k, sizeof k);
    uint64_t cv[N_COUNTERS];
    counters_array(&r->c, cv);
    bool hc = r->have_counters;
    sb_printf(csv, "%s,%u,%s,", key, r->r, r->status);
    if (r->sig) sb_printf(csv, "%d", r->sig);
    sb_printf(csv, ",");
    sb_num(csv, r->have_time, r->wall_s);
    sb_printf(csv, ",");
    sb_num(csv, r->have_cpu, r->cpu_s);
    sb_printf(csv, ",%llu,", (unsigned long long)r->peak_rss);
    if (hc) sb_printf(csv, "%llu", (unsigned long long)r->peak_tracked);
    sb_printf(csv, ",%u,%u,", r->nodes, r->arcs);
    if (hc) sb_printf(csv, "%llu", (unsigned long long)r->c.arrangement_crossings_initial);
    sb_printf(csv, ",%d", r->validated ? 1 : 0);
    for (size_t i = 0; i < N_COUNTERS; i++) {
        sb_printf(csv, ",");
        if (hc) sb_printf(csv, "%llu", (unsigned long long)cv[i]);
    }
    sb_printf(csv, ",");
    sb_csv_str(csv, r->msg);
    sb_printf(csv, "\n");

    sb_printf(js, "{\"variant\":");
    sb_json_str(js, c->variant);
    sb_printf(js, ",\"family\":");
    sb_json_str(js, c->family);
    sb_printf(js, ",\"n\":%u,\"r_req\":%lld,\"k\":", c->n, (long long)c->r_req);
    if (c->k == K_NA) sb_printf(js, "null");
    else sb_json_str(js, k);
    sb_printf(js, ",\"weights\":");
    sb_json_str(js, c->weights);
    sb_printf(js, ",\"seed\":%llu,\"repeat\":%d,\"r\":%u,\"status\":\"%s\",\"signal\":",
              (unsigned long long)c->seed, c->repeat, r->r, r->status);
    if (r->sig) sb_printf(js, "%d", r->sig);
    else sb_printf(js, "null");
    sb_printf(js, ",\"wall_s\":");
    if (r->have_time) sb_printf(js, "%.9g", r->wall_s);
    else sb_printf(js, "null");
    sb_printf(js, ",\"cpu_s\":");
    if (r->have_cpu) sb_printf(js, "%.9g", r->cpu_s);
    else sb_printf(js, "null");
    sb_printf(js, ",\"peak_rss_bytes\":%llu,\"peak_tracked_bytes\":", (unsigned long long)r->peak_rss);
    if (hc) sb_printf(js, "%llu", (unsigned long long)r->peak_tracked);
    else sb_printf(js, "null");
    sb_printf(js, ",\"nodes\":%u,\"arcs\":%u,\"validated\":%s,\"counters\":", r->nodes, r->arcs,
              r->validated ? "true" : "false");
    if (hc) {
        sb_printf(js, "{");
        for (size_t i = 0; i < N_COUNTERS; i++)
            sb_printf(js, "%s\"%s\":%llu", i ? "," : "", counter_names[i], (unsigned long long)cv[i]);
        sb_printf(js, "}");
    } else sb_printf(js, "null");
    sb_printf(js, ",\"message\":");
    sb_json_str(js, r->msg);
    sb_printf(js, "}\n");
}

static void read_first_line(const char *cmd, char *buf, size_t size) {
    buf[0] = 0;
    FILE *p = popen(cmd, "r");
    if (!p) return;
    if (fgets(buf, (int)size, p)) buf[strcspn(buf, "\n")] = 0;
    pclose(p);
}

static void machine_header(FILE *f, int argc, char **argv, const options *o, long total, long todo) {
    char cpu[256] = "unknown", mem[64] = "unknown", line[512];
    FILE *ci = fopen("/proc/cpuinfo", "r");
    if (ci) {
        while (fgets(line, sizeof line, ci))
            if (!strncmp(line, "model name", 10)) {
                char *c = strchr(line, ':');
                if (c) {
                    c++;
                    while (*c == ' ') c++;
                    c[strcspn(c, "\n")] = 0;
                    snprintf(cpu, sizeof cpu, "%s", c);
                }
                break;
            }
        fclose(ci);
    }
    FILE *mi = fopen("/proc/meminfo", "r");
    if (mi) {
        unsigned long kb;
        while (fgets(line, sizeof line, mi))
            if (sscanf(line, "MemTotal: %lu kB", &kb) == 1) {
                snprintf(mem, sizeof mem, "%.1f GiB", (double)kb / 1048576.0);
                break;
            }
        fclose(mi);
    }
    char commit[128], dirty[16];
    read_first_line("git rev-parse HEAD 2>/dev/null", commit, sizeof commit);
    read_first_line("git status --porcelain --untracked-files=no 2>/dev/null | head -1 | wc -l", dirty, sizeof dirty);
    time_t now = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    const char *cflags = getenv("WSKEL_CFLAGS");
    fprintf(f, "# wskel-bench results (CSV; lines starting with '#' are comments)\n");
    fprintf(f, "# date: %s\n", date);
    fprintf(f, "# cpu: %s\n", cpu);
    fprintf(f, "# cores: %ld\n", sysconf(_SC_NPROCESSORS_ONLN));
    fprintf(f, "# memory: %s\n", mem);
    fprintf(f, "# compiler: %s\n", __VERSION__);
    fprintf(f, "# cflags: %s\n", cflags ? cflags : "unknown (set WSKEL_CFLAGS)");
    fprintf(f, "# git: %s%s\n", commit[0] ? commit : "unknown", atoi(dirty) > 0 ? " (uncommitted changes)" : "");
    fprintf(f, "# generator version: %d\n", WK_GEN_VERSION);
    fprintf(f, "# command:");
    for (int i = 0; i < argc; i++) fprintf(f, " %s", argv[i]);
    fprintf(f, "\n# limits: time %gs, memory %g MB; validate %s; jobs %d; shard %d/%d; "
               "configurations %ld (this shard %ld)\n",
            o->time_limit, o->mem_limit_mb, o->validate ? "on" : "off", o->jobs, o->shard_i,
            o->shard_n, total, todo);
    fprintf(f, "# columns: variant, family, n (vertices asked), r_req (reflex asked, -1: family "
               "default), k (empty: variant has no k), weights, seed, repeat: the configuration;\n"
               "#   r: actual reflex vertices; status: ok|timeout|out-of-memory|crash|invalid|"
               "rejected|unsupported|algo-failed; signal: for crash;\n"
               "#   wall_s, cpu_s: the construction alone (cgal: its reported time, no cpu); "
               "peak_rss_bytes: child peak RSS (wait4);\n"
               "#   peak_tracked_bytes: peak bytes through the run allocator during the "
               "construction; nodes, arcs: skeleton size;\n"
               "#   crossings: initial arrangement crossings; validated: 1 if the validator "
               "ran and passed or failed (see status);\n"
               "#   then every counter of wk_counters by name; message: the error, if any.\n");
}

static void write_header_row(FILE *f) {
    fprintf(f, "%s", base_columns);
    for (size_t i = 0; i < N_COUNTERS; i++) fprintf(f, ",%s", counter_names[i]);
    fprintf(f, ",message\n");
}

/* Cut a file back to its last newline (a run interrupted mid-write leaves a
** partial line, which must not glue onto the next row). */
static void trim_partial(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    long keep = len;
    while (keep > 0) {
        fseek(f, keep - 1, SEEK_SET);
        if (fgetc(f) == '\n') break;
        keep--;
    }
    fclose(f);
    if (keep != len && truncate(path, keep) != 0)
        fprintf(stderr, "wskel-bench: %s: cannot truncate: %s\n", path, strerror(errno));
}

/* Keys of the rows already in path (resume). */
static char **read_done_keys(const char *path, long *count) {
    *count = 0;
    FILE *f = fopen(path, "r");
    if (!f) return NULL;
    size_t cap = 256;
    char **keys = malloc(cap * sizeof *keys);
    char line[8192];
    bool header_seen = false;
    while (fgets(line, sizeof line, f)) {
        int gv;
        if (sscanf(line, "# generator version: %d", &gv) == 1 && gv != WK_GEN_VERSION) {
            /* its rows describe other polygons under the same keys */
            fprintf(stderr,
                    "wskel-bench: %s: written with generator version %d, this is %d: "
                    "--resume would mix polygons; remove it or choose another --out\n",
                    path, gv, WK_GEN_VERSION);
            exit(1);
        }
        if (line[0] == '#' || line[0] == '\n') continue;
        if (!header_seen) {
            header_seen = true;
            if (strncmp(line, base_columns, strlen(base_columns)) != 0) {
                fprintf(stderr, "wskel-bench: %s: not a wskel-bench CSV of this version\n", path);
                exit(1);
            }
            continue;
        }
        /* the key is the first 8 fields (none of them contains a comma) */
        char *p = line;
        for (int i = 0; i < 8 && p; i++) p = strchr(p + (i ? 1 : 0), ',');
        if (!p) continue;
        if ((size_t)*count == cap) keys = realloc(keys, (cap *= 2) * sizeof *keys);
        keys[(*count)++] = strndup(line, (size_t)(p - line));
    }
    fclose(f);
    return keys;
}

static int cmp_str(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void fmt_dur(double s, char *buf, size_t size) {
    long v = (long)(s + 0.5);
    if (v >= 3600) snprintf(buf, size, "%ldh%02ldm", v / 3600, v / 60 % 60);
    else if (v >= 60) snprintf(buf, size, "%ldm%02lds", v / 60, v % 60);
    else snprintf(buf, size, "%lds", v);
}

/* Find wskel-cgal beside this program (or $WSKEL_CGAL). */
static void find_cgal(char *buf, size_t size) {
    const char *env = getenv("WSKEL_CGAL");
    if (env) {
        snprintf(buf, size, "%s", env);
        return;
    }
    char self[1024];
    ssize_t l = readlink("/proc/self/exe", self, sizeof self - 1);
    if (l <= 0) {
        snprintf(buf, size, "bin/wskel-cgal");
        return;
    }
    self[l] = 0;
    char *slash = strrchr(self, '/');
    if (slash) *slash = 0;
    snprintf(buf, size, "%s/wskel-cgal", self);
}

int main(int argc, char **argv) {
    options o;
    memset(&o, 0, sizeof o);
    o.repeats = 1;
    o.time_limit = 60;
    o.mem_limit_mb = 4096;
    o.jobs = 1;
    o.shard_n = 1;
    o.self_test_index = -1;
    split_list("naive", &o.variants);
    split_list("unit", &o.weights);
    split_list("1", &o.k_spec);
    o.seeds.n = 1;
    o.seeds.v[0] = 1;
    o.n_r = 1;
    o.r[0] = (r_req){0, -1};
    bool dry = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage_text, stdout);
            return 0;
        }
        if (!strcmp(a, "--list-variants")) {
            for (size_t j = 0; wk_variant_at(j); j++)
                printf("%-14s %s\n", wk_variant_at(j)->name, wk_variant_at(j)->summary);
            printf("%-14s %s\n", "cgal", "CGAL 5.5 straight skeleton via bin/wskel-cgal (unit weights)");
            return 0;
        }
        if (!strcmp(a, "--dry-run")) {
            dry = true;
            continue;
        }
        if (strncmp(a, "--", 2) != 0) die_usage("unexpected argument '%s'", a);
        const char *key = a + 2;
        if (!strcmp(key, "validate") || !strcmp(key, "resume") || !strcmp(key, "quiet")) {
            set_option(&o, key, "true");
            continue;
        }
        if (i + 1 >= argc) die_usage("%s needs a value", a);
        if (!strcmp(key, "spec")) {
            snprintf(o.spec, sizeof o.spec, "%s", argv[i + 1]);
            load_spec(&o, argv[++i]);
        } else set_option(&o, key, argv[++i]);
    }
    if (o.families.n == 0) die_usage("no --family");
    if (o.n.n == 0) die_usage("no --n");
    if (o.families.n == 1 && !strcmp(o.families.v[0], "all")) {
        o.families.n = 0;
        for (int i = 0; wk_gen_families[i]; i++) o.families.v[o.families.n++] = (char *)wk_gen_families[i];
    }
    for (int i = 0; i < o.families.n; i++)
        if (!wk_gen_family_summary(o.families.v[i])) die_usage("unknown family '%s'", o.families.v[i]);
    char cgal_bin[1100];
    find_cgal(cgal_bin, sizeof cgal_bin);
    {
        int m = 0;
        for (int i = 0; i < o.variants.n; i++) {
            const char *v = o.variants.v[i];
            if (!strcmp(v, "cgal")) {
                if (access(cgal_bin, X_OK) != 0) {
                    fprintf(stderr, "wskel-bench: warning: %s not found (libcgal-dev missing?): "
                                    "skipping the cgal peer\n", cgal_bin);
                    continue;
                }
            } else if (!wk_variant_find(v)) die_usage("unknown variant '%s'", v);
            o.variants.v[m++] = o.variants.v[i];
        }
        o.variants.n = m;
    }
    /* Canonical weight texts, so keys compare equal across spellings. */
    for (int i = 0; i < o.weights.n; i++) {
        wk_run R;
        wk_run_init(&R);
        wk_gen_params g;
        wk_gen_params_init(&g);
        if (wk_gen_parse_weights(&R, o.weights.v[i], &g) != WK_OK) die_usage("bad weight mode '%s'", o.weights.v[i]);
        char buf[128];
        wk_gen_weights_format(&g, buf, sizeof buf);
        o.weights.v[i] = strdup(buf);
    }

    long total;
    config *all = build_configs(&o, &total);
    /* This shard, minus what is done. */
    long done_n = 0;
    char **done = NULL;
    if (o.resume && o.out[0]) {
        trim_partial(o.out);
        done = read_done_keys(o.out, &done_n);
        if (done_n) qsort(done, (size_t)done_n, sizeof *done, cmp_str);
    }
    config *todo = malloc(((size_t)total + 1) * sizeof *todo);
    long n_todo = 0, n_shard = 0;
    for (long i = 0; i < total; i++) {
        if (i % o.shard_n != o.shard_i) continue;
        n_shard++;
        if (done_n) {
            char key[512], *kp = key;
            config_key(&all[i], key, sizeof key);
            if (bsearch(&kp, done, (size_t)done_n, sizeof *done, cmp_str)) continue;
        }
        todo[n_todo++] = all[i];
    }
    if (dry) {
        for (long i = 0; i < n_todo; i++) {
            char key[512];
            config_key(&todo[i], key, sizeof key);
            printf("%ld %s\n", todo[i].index, key);
        }
        return 0;
    }
    if (!o.out[0]) die_usage("no --out");

    char jpath[1100];
    size_t ol = strlen(o.out);
    if (ol > 4 && !strcmp(o.out + ol - 4, ".csv")) snprintf(jpath, sizeof jpath, "%.*sjsonl", (int)(ol - 3), o.out);
    else snprintf(jpath, sizeof jpath, "%s.jsonl", o.out);
    struct stat sb;
    bool fresh = !(o.resume && stat(o.out, &sb) == 0 && sb.st_size > 0);
    if (o.resume) trim_partial(jpath);
    FILE *csv = fopen(o.out, fresh ? "w" : "a");
    FILE *js = fopen(jpath, fresh ? "w" : "a");
    if (!csv || !js) {
        fprintf(stderr, "wskel-bench: %s: %s\n", !csv ? o.out : jpath, strerror(errno));
        return 1;
    }
    if (fresh) {
        machine_header(csv, argc, argv, &o, total, n_shard);
        write_header_row(csv);
    } else fprintf(csv, "# resumed %ld of %ld configurations left, by: %s\n", n_todo, n_shard, argv[0]);
    fflush(csv);
    fflush(js);

    bool tty = !o.quiet && isatty(2);
    double t0 = now_s();
    long finished = 0, next_emit = 0;
    static const char *const names[] = {"ok",       "timeout",     "out-of-memory", "crash",
                                        "invalid",  "rejected",    "unsupported",   "algo-failed"};
    enum { N_STATUS = sizeof names / sizeof names[0] };
    long counts[N_STATUS] = {0};
    result *results = calloc((size_t)n_todo + 1, sizeof *results);
    bool *ready = calloc((size_t)n_todo + 1, sizeof *ready);
    signal(SIGPIPE, SIG_IGN);

    /* Each iteration forks its own child and fills its own slot; rows are
    ** emitted in configuration order from the critical section. */
#pragma omp parallel for schedule(dynamic, 1) num_threads(o.jobs)
    for (long i = 0; i < n_todo; i++) {
        if (tty) {
#pragma omp critical(progress)
            {
                char key[512], el[32], eta[32] = "?";
                config_key(&todo[i], key, sizeof key);
                double e = now_s() - t0;
                fmt_dur(e, el, sizeof el);
                if (finished > 0) fmt_dur(e / (double)finished * (double)(n_todo - finished), eta, sizeof eta);
                fprintf(stderr, "\r\033[K[%ld/%ld] %s  elapsed %s  ETA %s", finished, n_todo, key, el, eta);
                fflush(stderr);
            }
        }
        run_config(&o, &todo[i], cgal_bin, &results[i]);
#pragma omp critical(emit)
        {
            ready[i] = true;
            finished++;
            for (int s = 0; s < N_STATUS; s++)
                if (!strcmp(results[i].status, names[s])) counts[s]++;
            while (next_emit < n_todo && ready[next_emit]) {
                sbuf a = {0}, b = {0};
                format_rows(&todo[next_emit], &results[next_emit], &a, &b);
                fputs(a.s, csv);
                fputs(b.s, js);
                fflush(csv);
                fflush(js);
                free(a.s);
                free(b.s);
                next_emit++;
            }
        }
    }
    if (tty) fprintf(stderr, "\r\033[K");
    char el[32];
    fmt_dur(now_s() - t0, el, sizeof el);
    if (!o.quiet) {
        fprintf(stderr, "wskel-bench: %ld runs in %s:", n_todo, el);
        for (int s = 0; s < N_STATUS; s++)
            if (counts[s]) fprintf(stderr, " %s %ld", names[s], counts[s]);
        fprintf(stderr, " -> %s\n", o.out);
    }
    int rc = 0;
    if (ferror(csv) || ferror(js)) rc = 1;
    if (fclose(csv) != 0 || fclose(js) != 0) rc = 1;
    if (rc) fprintf(stderr, "wskel-bench: write error on %s\n", o.out);
    return rc;
}
