/*
** fuzz_variants.c: libFuzzer target for reader + every variant + validator.
**
** The input is read by content (wk_polygon_read_file on a memfd, so the
** format detection is fuzzed too) and checked like the reader targets do.
** An accepted polygon of at most MAX_N vertices goes through every
** registered variant (wk_variant_at(i), default options, a fresh strict run
** each, wk_solve_checked: the validator checks each skeleton), and every
** valid skeleton is compared with the reference's (naive's).  Findings:
**   - a crash, UB, a leak (sanitizers; tracked bytes: each run is strict,
**     so wk_run_close aborts when bytes are left), a hang (-timeout);
**   - a status a variant may not return on a valid polygon: anything but
**     WK_OK, WK_EALGO, WK_EINVALID, or WK_EUNSUPPORTED from a non-reference
**     variant;
**   - "invalid": the validator rejected a skeleton (WK_EINVALID, exit 3;
**     also when the variant's own check returned it);
**   - "mismatch": a valid skeleton that is not the reference's valid
**     skeleton in canonical form (tests/same_skeleton.h, merging): nodes of
**     both within WK_SAME_SKELETON_TOL_REL * scale (tolerance.h: the
**     validator's tolerance) and within that over their faces' weight in
**     time are one node, arcs that leaves with both ends in one node
**     (zero-length) are dropped, the rest must be the same multiset of
**     (node, node, left face, right face).  Node and arc counts alone are
**     no oracle: valid skeletons differ in them where features below the
**     tolerance merge differently (a pass-through node, a zero-length arc);
**   - "ealgo": a variant gave up (WK_EALGO, exit 2).  Not a crash, but a
**     defect for a valid input: saved to $WSKEL_FUZZ_EALGO_DIR (when set)
**     and not aborted on, unless WSKEL_FUZZ_EALGO_ABORT=1.
** invalid and mismatch abort, unless WSKEL_FUZZ_COLLECT=DIR is set: then
** they are saved there (invalid-VARIANT-HASH.wpoly, ...) and the run goes
** on, for a fuzz run whose job is memory errors and hangs while the
** geometry findings are known.
*/
#define _GNU_SOURCE
#include "fuzz_common.h"
#include "../same_skeleton.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_N 64

static uint64_t fnv1a(const uint8_t *d, size_t n) {
    uint64_t h = 1469598103934665603u;
    for (size_t i = 0; i < n; i++) h = (h ^ d[i]) * 1099511628211u;
    return h;
}

static int is_graphml(const uint8_t *d, size_t n) {
    size_t i = n >= 3 && d[0] == 0xEF && d[1] == 0xBB && d[2] == 0xBF ? 3 : 0;
    while (i < n && (d[i] == ' ' || d[i] == '\t' || d[i] == '\r' || d[i] == '\n')) i++;
    return i < n && d[i] == '<';
}

/* Saves the input as DIR/KIND-VARIANT-HASH.EXT; 1 if it was new. */
static int save(const char *dir, const char *kind, const char *variant, const uint8_t *d,
                size_t n) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s-%s-%016llx.%s", dir, kind, variant,
             (unsigned long long)fnv1a(d, n), is_graphml(d, n) ? "graphml" : "wpoly");
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) {
        if (errno == EEXIST) return 0;
        fprintf(stderr, "wskel-fuzz: cannot write %s: %s\n", path, strerror(errno));
        abort();
    }
    if (write(fd, d, n) != (ssize_t)n) abort();
    close(fd);
    fprintf(stderr, "wskel-fuzz: %s (%s) saved as %s\n", kind, variant, path);
    return 1;
}

/* A geometry finding: kind "invalid", "mismatch" or "ealgo".  invalid and
** mismatch abort unless WSKEL_FUZZ_COLLECT=DIR (then saved there); ealgo is
** saved to $WSKEL_FUZZ_EALGO_DIR (else $WSKEL_FUZZ_COLLECT) and the run goes
** on; WSKEL_FUZZ_EALGO_ABORT=1 makes it fatal (to minimize one). */
static void geometry(const char *kind, const char *variant, const char *msg, const uint8_t *d,
                     size_t n) {
    int ealgo = strcmp(kind, "ealgo") == 0;
    const char *dir = getenv(ealgo ? "WSKEL_FUZZ_EALGO_DIR" : "WSKEL_FUZZ_COLLECT");
    if (!dir || !*dir) dir = ealgo ? getenv("WSKEL_FUZZ_COLLECT") : NULL;
    const char *abort_ealgo = getenv("WSKEL_FUZZ_EALGO_ABORT");
    int fatal = ealgo ? abort_ealgo && strcmp(abort_ealgo, "1") == 0 : !dir || !*dir;
    if (dir && *dir && save(dir, kind, variant, d, n) && !fatal)
        fprintf(stderr, "wskel-fuzz:   %s\n", msg);
    if (fatal) finding("%s (variant %s): %s", kind, variant, msg);
}

/* Runs variant V on P in a fresh strict run *Rv (the caller closes it):
** wk_solve_checked, which validates the skeleton (the validator's default
** tolerance) and tries the tolerance ladder before it gives up.  Returns
** the valid skeleton, or NULL after filing the outcome: "invalid" (the
** validator rejected every attempt), "ealgo", WK_EUNSUPPORTED (allowed for
** a non-reference variant), or a finding for any other status. */
static wk_skeleton *solve(wk_run *Rv, const wk_variant *V, const wk_polygon *P,
                          const uint8_t *data, size_t size) {
    const char *name = wk_variant_name(V);
    char msg[1024];
    wk_run_init_checked(Rv);
    wk_skeleton *S = NULL;
    wk_status s = wk_solve_checked(Rv, V, P, 0, &S, NULL, NULL, NULL);
    wk_error_format(Rv, msg, sizeof msg);
    if (s != Rv->err.code)
        finding("variant %s returned %s but recorded %s", name, wk_status_name(s),
                wk_status_name(Rv->err.code));
    if (s == WK_OK) {
        if (!S) finding("variant %s: WK_OK without a skeleton", name);
        return S;
    }
    if (S) finding("variant %s: %s with a skeleton", name, wk_status_name(s));
    if (s == WK_EALGO)
        geometry("ealgo", name, msg, data, size);
    else if (s == WK_EINVALID) /* the validator (or the variant's own check) rejected it */
        geometry("invalid", name, msg, data, size);
    else if (!(s == WK_EUNSUPPORTED && V != wk_variant_reference()))
        finding("variant %s returned %s on a valid polygon: %s", name, wk_status_name(s), msg);
    return NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    int fd = memfd_create("wskel-fuzz", MFD_CLOEXEC);
    if (fd < 0) abort();
    if (size && write(fd, data, size) != (ssize_t)size) abort();
    char path[64];
    snprintf(path, sizeof path, "/proc/self/fd/%d", fd);

    wk_run R;
    wk_run_init_checked(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_file(&R, path, &P);
    close(fd);
    /* the reader picks GeoJSON for a first non-blank byte '{' (a fuzz
    ** finding: "{}" was refused by path, without a line, as documented) */
    size_t i = size >= 3 && data[0] == 0xEF && data[1] == 0xBB && data[2] == 0xBF ? 3 : 0;
    while (i < size && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n')) i++;
    if (i < size && data[i] == '{') geojson_line_exception(&R, st);
    check_status(&R, st, P, path);
    if (st != WK_OK) {
        close_run(&R, "reader");
        return 0;
    }
    if (is_graphml(data, size) ? bytes_graphml_refusable(data, size)
                               : bytes_wpoly_refusable(data, size))
        finding("accepted an input with bytes the format does not allow");
    check_accepted(&R, P);
    if (P->n <= MAX_N) {
        /* The reference first (registry entry 0): its valid skeleton, kept
        ** in its own run until every other variant is compared with it. */
        const wk_variant *ref = wk_variant_reference(), *V;
        wk_run Rr;
        wk_skeleton *Sr = solve(&Rr, ref, P, data, size);
        double tol = WK_SAME_SKELETON_TOL_REL * wk_polygon_scale(P);
        sk_match m = {.tol = tol, .tol_t = tol, .merge = true, .P = P};
        for (size_t i = 0; (V = wk_variant_at(i)) != NULL; i++) {
            if (V == ref) continue;
            wk_run Rv;
            wk_skeleton *S = solve(&Rv, V, P, data, size);
            char why[1024], msg[1200];
            if (S && Sr && !same_skeleton(Sr, S, m, why, sizeof why)) {
                snprintf(msg, sizeof msg, "%u nodes %u arcs, %s %u nodes %u arcs: %s",
                         S->n_nodes, S->n_arcs, wk_variant_name(ref), Sr->n_nodes, Sr->n_arcs,
                         why);
                geometry("mismatch", wk_variant_name(V), msg, data, size);
            }
            if (S) wk_skeleton_free(&Rv, S);
            close_run(&Rv, wk_variant_name(V));
        }
        if (Sr) wk_skeleton_free(&Rr, Sr);
        close_run(&Rr, wk_variant_name(ref));
    }
    wk_polygon_free(&R, P);
    close_run(&R, "reader");
    return 0;
}
