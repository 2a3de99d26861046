/*
** harness.h: what the parts of bin/wskel-bench share: the options of a
** sweep, one configuration (one run to do), the result of a run, and the
** harness's two ways of giving up (a usage error, out of memory).
**
** The parts (each with its own header):
**   spec.c     the options: flags and spec files (--spec), defaults, checks;
**   configs.c  the sweep: the cartesian product of the axes, in a fixed order;
**   runner.c   one run in a forked child (limits, pipe records, rusage, the
**              CGAL subprocess) and the classification of its status;
**   rows.c     the output: CSV and JSON-lines rows, the header row, the '#'
**              comment block, and the keys of the rows already written
**              (--resume);
**   wskel_bench.c  main(): the order of the above, progress, summary.
**
** Invariants: the parent holds no run context (each child builds its own
** wk_run); every allocation of the harness goes through xmalloc and friends,
** which never return NULL: on failure they print "wskel-bench: out of
** memory" and end the process with exit code 1 before anything more is
** written (rows are formatted completely in memory before they are written,
** so no partial row reaches a file).
*/
#ifndef WSKEL_BENCH_HARNESS_H
#define WSKEL_BENCH_HARNESS_H

#include "wskel.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define EXIT_USAGE 64
#define EXIT_NOMEM 1 /* as an I/O error: the sweep did not finish */
#define MAX_LIST 256
#define K_NA WK_NONE /* variant without a k: the k column is empty (WK_K_MAX is "max") */

typedef struct str_list { char *v[MAX_LIST]; int n; } str_list;
typedef struct u64_list { uint64_t v[MAX_LIST]; int n; } u64_list;

/* An r request: fraction of n (frac > 0), absolute (abs >= 0) or the
** family's default (both unset). */
typedef struct r_req { double frac; int64_t abs; } r_req;

typedef struct options {
    str_list families, variants, weights, k_spec;
    u64_list n, seeds, holes;
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
    bool qsort_ref;        /* measure the qsort() reference (qsort_ref.h) */
    char out[1024];
    uint64_t cgal_max_n;   /* skip cgal above this n; 0: no cap */
    str_list max_n_variant; /* --max-n V=N: skip variant max_n_variant.v[i] */
    u64_list max_n;         /* above n = max_n.v[i] (a slow variant in a big sweep) */
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
    uint32_t holes;        /* holes asked of the generator (0: none) */
    uint32_t k;
    uint64_t seed;
    int repeat;
    long index;            /* position in the full list */
} config;

/* What the parent learnt about one run. */
typedef struct result {
    char status[16];
    int sig;
    uint32_t r, nodes, arcs;
    bool have_counters, have_time, have_cpu, validated;
    double wall_s, cpu_s;
    double phase_s;        /* the variant's timed phase (wk_variant.phase;
                              JSON lines only), valid with have_time */
    uint64_t peak_rss, peak_tracked;
    wk_counters c;
    char msg[512];
} result;

/* "wskel-bench: MESSAGE (see --help)" on stderr, exit EXIT_USAGE. */
_Noreturn void die_usage(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* "wskel-bench: out of memory" on stderr, exit EXIT_NOMEM at once (no stdio
** buffer is flushed: rows are flushed one by one, so nothing is lost, and
** nothing half-formatted is written). */
_Noreturn void die_nomem(void);

/* The C library's allocators, checked: never NULL (die_nomem instead). */
void *xmalloc(size_t size);
void *xcalloc(size_t count, size_t size);
void *xrealloc(void *p, size_t size);
/* xrealloc for count * size bytes, with the multiplication checked. */
void *xreallocarray(void *p, size_t count, size_t size);
char *xstrdup(const char *s);
char *xstrndup(const char *s, size_t n);

#endif
