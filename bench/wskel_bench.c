/*
** wskel_bench.c: bin/wskel-bench, the benchmark harness.
**
** A sweep is the cross product of families x n x r x holes x weights x seeds
** x variants x k x repeats, given by flags or by a spec file (bench/sweeps/,
** "key = value" lines with the flags' names: spec.h).  Every configuration
** (configs.h) runs in its own forked child under setrlimit limits
** (runner.h); the rows go to a CSV and its JSON-lines twin (rows.h).  The
** parts share the types of harness.h.
**
** main: options -> the full configuration list -> this shard minus the
** rows already in the CSV (--resume) -> --dry-run lists them, or they run
** (--jobs in parallel) and their rows are written in configuration order.
**
** Invariants: the configuration list depends only on the options (never on
** the machine or on results), so --shard I/N and --resume agree between runs;
** rows are appended and flushed one by one in configuration order, so an
** interrupted sweep loses at most the runs in flight and --resume skips
** every configuration already in the CSV; a failing run never stops the
** sweep; the parent holds no run context (each child builds its own wk_run).
*/
#define _GNU_SOURCE
#include "configs.h"
#include "harness.h"
#include "qsort_ref.h"
#include "rows.h"
#include "runner.h"
#include "spec.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

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

static const char *const status_names[] = {"ok",      "timeout",  "out-of-memory", "crash",
                                           "invalid", "rejected", "unsupported",   "algo-failed"};
enum { N_STATUS = sizeof status_names / sizeof status_names[0] };

/* Run todo[0..n_todo) (o->jobs at a time) and write their rows in order;
** results and ready have n_todo zeroed slots; counts[s] gets the number of
** runs with status_names[s]. */
static void run_sweep(const options *o, const config *todo, long n_todo, const char *cgal_bin,
                      result *results, bool *ready, FILE *csv, FILE *js, bool legacy,
                      long counts[N_STATUS]) {
    bool tty = !o->quiet && isatty(2);
    double t0 = now_s();
    long finished = 0, next_emit = 0;

    /* Each iteration forks its own child and fills its own slot; rows are
    ** emitted in configuration order from the critical section. */
#pragma omp parallel for schedule(dynamic, 1) num_threads(o->jobs)
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
        run_config(o, &todo[i], cgal_bin, &results[i]);
#pragma omp critical(emit)
        {
            ready[i] = true;
            finished++;
            for (int s = 0; s < N_STATUS; s++)
                if (!strcmp(results[i].status, status_names[s])) counts[s]++;
            while (next_emit < n_todo && ready[next_emit]) {
                write_rows(csv, js, &todo[next_emit], &results[next_emit], legacy);
                next_emit++;
            }
        }
    }
    if (tty) fprintf(stderr, "\r\033[K");
}

int main(int argc, char **argv) {
    options o;
    options_init(&o);
    bool dry;
    int code;
    if (!options_from_argv(&o, argc, argv, &dry, &code)) return code;
    /* --qsort-ref alone: the reference, nothing else. */
    if (o.qsort_ref && !dry && o.families.n == 0 && o.n.n == 0) {
        printf("%.6g\n", qsort_ref_measure(NULL));
        return 0;
    }
    char cgal_bin[1100];
    find_cgal(cgal_bin, sizeof cgal_bin);
    options_finish(&o, cgal_bin);

    long total;
    config *all = build_configs(&o, &total);
    /* This shard, minus what is done. */
    done_set done = {NULL, 0, false};
    if (o.resume && o.out[0]) {
        trim_partial(o.out);
        done_set_read(&done, o.out);
    }
    config *todo = xmalloc(((size_t)total + 1) * sizeof *todo);
    long n_todo = 0, n_shard = 0;
    for (long i = 0; i < total; i++) {
        if (i % o.shard_n != o.shard_i) continue;
        n_shard++;
        if (!done_set_has(&done, &all[i])) todo[n_todo++] = all[i];
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
    /* A CSV of before the holes axis can take only rows with holes = 0. */
    for (long i = 0; done.legacy && i < n_todo; i++)
        if (todo[i].holes > 0) {
            fprintf(stderr,
                    "wskel-bench: %s: written before the holes column: --resume cannot add "
                    "configurations with holes > 0 to it; remove it or choose another --out\n",
                    o.out);
            return 1;
        }

    /* Allocated before the output is opened: out of memory leaves it as it was. */
    result *results = xcalloc((size_t)n_todo + 1, sizeof *results);
    bool *ready = xcalloc((size_t)n_todo + 1, sizeof *ready);
    char jpath[1100];
    jsonl_path(o.out, jpath, sizeof jpath);
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
        if (o.qsort_ref) qsort_ref_comment(csv, "before the runs");
        write_header_row(csv);
    } else {
        write_resume_line(csv, n_todo, n_shard, argv[0]);
        if (o.qsort_ref) qsort_ref_comment(csv, "before the runs");
    }
    fflush(csv);
    fflush(js);
    signal(SIGPIPE, SIG_IGN);

    double t0 = now_s();
    long counts[N_STATUS] = {0};
    run_sweep(&o, todo, n_todo, cgal_bin, results, ready, csv, js, done.legacy, counts);
    if (o.qsort_ref) qsort_ref_comment(csv, "after the runs");
    char el[32];
    fmt_dur(now_s() - t0, el, sizeof el);
    if (!o.quiet) {
        fprintf(stderr, "wskel-bench: %ld runs in %s:", n_todo, el);
        for (int s = 0; s < N_STATUS; s++)
            if (counts[s]) fprintf(stderr, " %s %ld", status_names[s], counts[s]);
        fprintf(stderr, " -> %s\n", o.out);
    }
    int rc = 0;
    if (ferror(csv) || ferror(js)) rc = 1;
    if (fclose(csv) != 0 || fclose(js) != 0) rc = 1;
    if (rc) fprintf(stderr, "wskel-bench: write error on %s\n", o.out);
    return rc;
}
