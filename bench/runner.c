/*
** runner.c: one configuration in a forked child, and what the parent makes
** of it (runner.h has the protocol and the invariants).
*/
#define _GNU_SOURCE
#include "runner.h"
#include "generators.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* The record a child sends after each phase; small enough (< PIPE_BUF) that
** each write is atomic and never blocks. */
typedef struct child_rec {
    int phase;             /* 1 generated, 2 solved, 3 done */
    int status;            /* wk_status of the last phase */
    int what;              /* 0 generation, 1 solve, 2 validation */
    uint32_t n, r, nodes, arcs;
    double wall_s, cpu_s;
    double phase_s;        /* R.phase_s: the variant's timed phase */
    uint64_t peak_tracked;
    wk_counters c;
    char msg[400];
} child_rec;
_Static_assert(sizeof(child_rec) <= PIPE_BUF, "child_rec must fit one atomic pipe write");

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
    g.holes = c->holes;
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
    rec.phase_s = R.phase_s;
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
    char *b = xmalloc(cap);
    size_t got;
    while ((got = fread(b + len, 1, cap - len - 1, f)) > 0) {
        len += got;
        if (cap - len < 2) b = xrealloc(b, cap *= 2);
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

void run_config(const options *o, const config *c, const char *cgal_bin, result *res) {
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
            res->phase_s = last.phase_s;
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
            res->phase_s = last.phase_s;
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

/* Find wskel-cgal beside this program (or $WSKEL_CGAL). */
void find_cgal(char *buf, size_t size) {
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
