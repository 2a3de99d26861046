/*
** test_fuzz_findings.c: every fuzz finding in tests/data/fuzz/ stays a test
** (tests/data/fuzz/README.md, tests/fuzz/README.md).
**
**   - reader findings, listed in tests/data/fuzz/EXPECTED (file, exit code,
**     message substring, as tests/data/bad/EXPECTED): the reader refuses the
**     file with that exit code and message, returns no polygon and leaves
**     no tracked byte;
**   - every other file is a variant finding: the reader accepts it, and it
**     passes when every registered variant returns a skeleton the validator
**     accepts and that is the reference's (naive's) in canonical form (as
**     the variants fuzz target compares them, tests/same_skeleton.h), or
**     declines it with WK_EUNSUPPORTED (a non-reference variant).  Each
**     variant runs in a child process with a time limit
**     (WSKEL_FINDINGS_TIMEOUT seconds, default 30), so a hang or a crash is
**     an outcome, not a stuck test.  Entries of tests/data/fuzz/KNOWN (file,
**     outcome) are the ones not fixed yet: the test fails when a KNOWN entry
**     passes (remove it from KNOWN) and when a file not in KNOWN fails; an
**     outcome that differs from the KNOWN one is only logged;
**   - every finding carries its one-line comment: a first line starting
**     with '#' (.wpoly), or a sidecar NAME.txt.
*/
#define _POSIX_C_SOURCE 200809L
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <dirent.h>
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "wskel.h"
#include "helpers.h"

#define MAX_ROWS 512

typedef struct table {
    int n;
    char file[MAX_ROWS][128];
    char rest[MAX_ROWS][512]; /* EXPECTED: "code\tmessage"; KNOWN: outcome */
} table;

/* Reads tests/data/fuzz/NAME: rows "file<TAB>rest"; '#' lines and blank
** lines skipped.  A missing file is an empty table. */
static void read_table(const char *name, table *t) {
    char rel[64], path[512], line[1024];
    snprintf(rel, sizeof rel, "fuzz/%s", name);
    data_path(path, sizeof path, rel);
    t->n = 0;
    FILE *f = fopen(path, "r");
    if (!f) return;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        if (!line[0] || line[0] == '#') continue;
        char *tab = strchr(line, '\t');
        cr_assert_not_null(tab, "%s: row '%s' has no tab", name, line);
        *tab = '\0';
        cr_assert_lt(t->n, MAX_ROWS);
        snprintf(t->file[t->n], sizeof t->file[0], "%.120s", line);
        snprintf(t->rest[t->n], sizeof t->rest[0], "%.500s", tab + 1);
        t->n++;
    }
    fclose(f);
}

static int find_row(const table *t, const char *file) {
    for (int i = 0; i < t->n; i++)
        if (strcmp(t->file[i], file) == 0) return i;
    return -1;
}

static bool ends_with(const char *s, const char *suffix) {
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

/* The findings: every file of tests/data/fuzz but the tables, the README and
** the sidecars.  Returns how many (sorted names in names). */
static int list_findings(char names[][128], int cap) {
    char path[512];
    data_path(path, sizeof path, "fuzz");
    DIR *d = opendir(path);
    if (!d) return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *f = e->d_name;
        if (f[0] == '.' || !strcmp(f, "EXPECTED") || !strcmp(f, "KNOWN") ||
            !strcmp(f, "README.md") || ends_with(f, ".txt"))
            continue;
        cr_assert_lt(n, cap);
        snprintf(names[n++], 128, "%.120s", f);
    }
    closedir(d);
    qsort(names, (size_t)n, 128, (int (*)(const void *, const void *))strcmp);
    return n;
}

static char g_names[MAX_ROWS][128];

Test(fuzz_findings, every_finding_is_listed_and_commented) {
    table expected, known;
    read_table("EXPECTED", &expected);
    read_table("KNOWN", &known);
    int n = list_findings(g_names, MAX_ROWS);
    char path[512], rel[300], line[256];
    for (int i = 0; i < n; i++) {
        const char *f = g_names[i];
        cr_assert(find_row(&expected, f) < 0 || find_row(&known, f) < 0,
                  "%s is in both EXPECTED (reader) and KNOWN (variants)", f);
        snprintf(rel, sizeof rel, "fuzz/%.120s.txt", f);
        data_path(path, sizeof path, rel);
        FILE *side = fopen(path, "r");
        if (side) {
            cr_assert_not_null(fgets(line, sizeof line, side), "%s.txt is empty", f);
            fclose(side);
            continue;
        }
        snprintf(rel, sizeof rel, "fuzz/%.120s", f);
        data_path(path, sizeof path, rel);
        FILE *in = fopen(path, "rb");
        cr_assert_not_null(in);
        bool hash = fgets(line, sizeof line, in) && line[0] == '#' && line[1];
        fclose(in);
        cr_assert(hash && ends_with(f, ".wpoly"),
                  "%s: a finding needs its comment: a first line '# ...' (.wpoly) or %s.txt", f,
                  f);
    }
    /* Every row names a file that is there. */
    for (int i = 0; i < expected.n; i++) {
        bool there = false;
        for (int j = 0; j < n && !there; j++) there = !strcmp(g_names[j], expected.file[i]);
        cr_assert(there, "EXPECTED lists %s, which is not in tests/data/fuzz", expected.file[i]);
    }
    for (int i = 0; i < known.n; i++) {
        bool there = false;
        for (int j = 0; j < n && !there; j++) there = !strcmp(g_names[j], known.file[i]);
        cr_assert(there, "KNOWN lists %s, which is not in tests/data/fuzz", known.file[i]);
    }
}

Test(fuzz_findings, reader_findings_are_refused_as_expected) {
    table expected;
    read_table("EXPECTED", &expected);
    for (int i = 0; i < expected.n; i++) {
        const char *f = expected.file[i];
        char *code = expected.rest[i], *tab = strchr(code, '\t');
        cr_assert_not_null(tab, "EXPECTED row %s: 'file<TAB>exit<TAB>message'", f);
        *tab = '\0';
        const char *want = tab + 1;
        char rel[300], path[512], msg[1024];
        snprintf(rel, sizeof rel, "fuzz/%.120s", f);
        data_path(path, sizeof path, rel);
        wk_run R;
        wk_run_init(&R);
        wk_polygon *P = NULL;
        wk_status st = wk_polygon_read_file(&R, path, &P);
        err_text(&R, msg, sizeof msg);
        cr_assert_neq(st, WK_OK, "%s was accepted", f);
        cr_assert_null(P);
        cr_assert_eq(wk_status_exit_code(st), atoi(code), "%s: exit code %d, want %s (%s)", f,
                     wk_status_exit_code(st), code, msg);
        cr_assert(strstr(msg, want), "%s: message '%s' lacks '%s'", f, msg, want);
        ASSERT_CLEAN_CLOSE(R);
    }
}

/* ---- variant findings ---- */

/* S, a valid skeleton of P by a non-reference variant, against the
** reference's valid skeleton as the variants fuzz target compares them
** (tests/same_skeleton.h, merging within WK_SAME_SKELETON_TOL_REL * scale,
** time tolerance over the faces' weight): out becomes "mismatch WHY" when
** they differ.  When the reference fails, S is only validated. */
static void compare_with_reference(const wk_polygon *P, const wk_skeleton *S, char *out,
                                   size_t size) {
    wk_run Rr;
    wk_run_init(&Rr);
    wk_skeleton *Sr = NULL;
    if (wk_solve_checked(&Rr, wk_variant_reference(), P, 0, &Sr, NULL, NULL, NULL) == WK_OK) {
        double tol = WK_SAME_SKELETON_TOL_REL * wk_polygon_scale(P);
        sk_match m = {.tol = tol, .tol_t = tol, .merge = true, .P = P};
        char why[900];
        if (!same_skeleton(Sr, S, m, why, sizeof why))
            snprintf(out, size, "mismatch %.1000s", why);
        wk_skeleton_free(&Rr, Sr);
    }
    wk_run_close(&Rr);
}

/* In a child: variant V on the file; writes one line to fd:
** "ok NODES ARCS", "mismatch WHY" (valid, but not the reference's
** skeleton), "invalid MSG", "ealgo MSG", "unsupported MSG", "reader MSG"
** (the reader refused it) or "status NAME MSG". */
static void child_run(const char *path, const wk_variant *V, int fd) {
    char out[1200], msg[1024];
    wk_run R;
    wk_run_init(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_file(&R, path, &P);
    if (st != WK_OK) {
        err_text(&R, msg, sizeof msg);
        snprintf(out, sizeof out, "reader %s", msg);
    } else {
        wk_run Rv;
        wk_run_init(&Rv);
        wk_skeleton *S = NULL;
        st = wk_solve_checked(&Rv, V, P, 0, &S, NULL, NULL, NULL);
        err_text(&Rv, msg, sizeof msg);
        if (st == WK_OK) {
            wk_status v = wk_validate(&Rv, P, S, 0, NULL);
            err_text(&Rv, msg, sizeof msg);
            if (v == WK_OK)
                snprintf(out, sizeof out, "ok %u %u", S->n_nodes, S->n_arcs);
            else
                snprintf(out, sizeof out, "%s %s", v == WK_EINVALID ? "invalid" : "status",
                         msg);
            if (v == WK_OK && V != wk_variant_reference())
                compare_with_reference(P, S, out, sizeof out);
            wk_skeleton_free(&Rv, S);
        } else if (st == WK_EINVALID) { /* the variant checked its own output */
            snprintf(out, sizeof out, "invalid %s", msg);
        } else if (st == WK_EALGO) {
            snprintf(out, sizeof out, "ealgo %s", msg);
        } else if (st == WK_EUNSUPPORTED) {
            snprintf(out, sizeof out, "unsupported %s", msg);
        } else {
            snprintf(out, sizeof out, "status %s %s", wk_status_name(st), msg);
        }
        wk_run_close(&Rv); /* strict: a leak aborts, and is a crash outcome */
        wk_polygon_free(&R, P);
    }
    wk_run_close(&R);
    size_t len = strlen(out);
    out[len++] = '\n';
    if (write(fd, out, len) != (ssize_t)len) _exit(3);
}

static double timeout_s(void) {
    const char *t = getenv("WSKEL_FINDINGS_TIMEOUT");
    double v = t ? atof(t) : 0;
    return v > 0 ? v : 30;
}

/* Runs V on path in a child with the time limit; the child's line in buf,
** or "timeout", or "crash (signal N)" / "crash (exit N)". */
static void run_limited(const char *path, const wk_variant *V, char *buf, size_t size) {
    int p[2];
    cr_assert_eq(pipe(p), 0);
    fflush(NULL);
    pid_t pid = fork();
    cr_assert_geq(pid, 0);
    if (pid == 0) {
        close(p[0]);
        child_run(path, V, p[1]);
        _exit(0);
    }
    close(p[1]);
    size_t n = 0;
    double end = now_s() + timeout_s();
    bool timed_out = false;
    for (;;) {
        double left = end - now_s();
        if (left <= 0) {
            timed_out = true;
            break;
        }
        struct pollfd q = {p[0], POLLIN, 0};
        int r = poll(&q, 1, (int)(left * 1000) + 1);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue; /* the time is checked above */
        ssize_t got = read(p[0], buf + n, size - 1 - n);
        if (got <= 0) break; /* EOF: the child is done */
        n += (size_t)got;
        if (n == size - 1) break;
    }
    close(p[0]);
    if (timed_out) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    buf[n] = '\0';
    buf[strcspn(buf, "\n")] = '\0';
    if (timed_out)
        snprintf(buf, size, "timeout");
    else if (WIFSIGNALED(status))
        snprintf(buf, size, "crash (signal %d)", WTERMSIG(status));
    else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !buf[0])
        snprintf(buf, size, "crash (exit %d)", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

/* The first word of a child's line: ok, invalid, ealgo, ... */
static void first_word(const char *line, char *w, size_t size) {
    size_t k = strcspn(line, " ");
    if (k >= size) k = size - 1;
    memcpy(w, line, k);
    w[k] = '\0';
}

Test(fuzz_findings, variant_findings_pass_unless_known, .timeout = 3600) {
    table expected, known;
    read_table("EXPECTED", &expected);
    read_table("KNOWN", &known);
    int n = list_findings(g_names, MAX_ROWS);
    int failures = 0, checked = 0, known_failing = 0;
    char report[8192] = "";
    size_t rl = 0;
    for (int i = 0; i < n; i++) {
        const char *f = g_names[i];
        if (find_row(&expected, f) >= 0) continue;
        checked++;
        char rel[300], path[512];
        snprintf(rel, sizeof rel, "fuzz/%.120s", f);
        data_path(path, sizeof path, rel);
        /* Outcome "naive=ok monotone=unsupported arrangement=invalid". */
        char outcome[512] = "", line[1200], word[32];
        size_t ol = 0;
        /* Each variant's skeleton must pass the validator (through
        ** wk_solve_checked, the entry point bin/wskel uses) and be the
        ** reference's skeleton in canonical form (compare_with_reference:
        ** node and arc counts alone differ where features below the
        ** tolerance merge differently, a pass-through node, a zero-length
        ** arc). */
        bool pass = true;
        const wk_variant *V;
        for (size_t v = 0; (V = wk_variant_at(v)) != NULL; v++) {
            run_limited(path, V, line, sizeof line);
            first_word(line, word, sizeof word);
            unsigned nodes = 0, arcs = 0;
            bool ok = !strcmp(word, "ok") && sscanf(line, "ok %u %u", &nodes, &arcs) == 2;
            const char *what = word;
            (void)nodes;
            (void)arcs;
            if (!ok && !strcmp(word, "unsupported") && V != wk_variant_reference()) {
                ok = true;
            }
            if (!strcmp(word, "crash") || !strcmp(word, "timeout")) what = word;
            if (!ok) pass = false;
            ol += (size_t)snprintf(outcome + ol, sizeof outcome - ol, "%s%s=%s", ol ? " " : "",
                                   wk_variant_name(V), what);
            if (!ok) cr_log_info("%s: %s: %s", f, wk_variant_name(V), line);
        }
        int k = find_row(&known, f);
        if (pass && k >= 0) {
            failures++;
            rl += (size_t)snprintf(report + rl, sizeof report - rl,
                                   "  %s passes now (%s): remove it from tests/data/fuzz/KNOWN\n",
                                   f, outcome);
        } else if (!pass && k < 0) {
            failures++;
            rl += (size_t)snprintf(report + rl, sizeof report - rl,
                                   "  %s fails (%s) and is not in tests/data/fuzz/KNOWN\n", f,
                                   outcome);
        } else if (!pass) {
            known_failing++;
            if (strcmp(known.rest[k], outcome) != 0)
                cr_log_warn("%s: KNOWN says '%s', now '%s'", f, known.rest[k], outcome);
        }
        if (rl >= sizeof report) rl = sizeof report - 1;
    }
    cr_log_info("variant findings: %d checked, %d known failing, %d unexpected", checked,
                known_failing, failures);
    cr_assert_eq(failures, 0, "variant findings:\n%s", report);
}
