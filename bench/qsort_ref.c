/*
** qsort_ref.c: the qsort() reference timing of bin/wskel-bench
** (qsort_ref.h).
*/
#define _GNU_SOURCE
#include "qsort_ref.h"
#include "harness.h"
#include "rng.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

static int cmp_double(const void *a, const void *b) {
    double p = *(const double *)a, q = *(const double *)b;
    return (p > q) - (p < q);
}

static double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double qsort_ref_measure(double *times) {
    double *src = xmalloc(QSORT_REF_N * sizeof *src), *a = xmalloc(QSORT_REF_N * sizeof *a);
    wk_rng g;
    wk_rng_seed(&g, QSORT_REF_SEED, 3);
    for (uint32_t i = 0; i < QSORT_REF_N; i++) src[i] = wk_rng_unit(&g);
    double t[QSORT_REF_REPS];
    for (int k = 0; k < QSORT_REF_REPS; k++) {
        memcpy(a, src, QSORT_REF_N * sizeof *a);
        double t0 = now_s();
        qsort(a, QSORT_REF_N, sizeof *a, cmp_double);
        t[k] = now_s() - t0;
        if (times) times[k] = t[k];
    }
    free(src);
    free(a);
    qsort(t, QSORT_REF_REPS, sizeof *t, cmp_double);
    return t[QSORT_REF_REPS / 2];
}

void qsort_ref_comment(FILE *f, const char *when) {
    double t[QSORT_REF_REPS], med = qsort_ref_measure(t);
    fprintf(f, "# qsort_ref_s: %.6g (%s; qsort() of %u doubles, seed %u, median of %d:", med, when,
            QSORT_REF_N, QSORT_REF_SEED, QSORT_REF_REPS);
    for (int k = 0; k < QSORT_REF_REPS; k++) fprintf(f, " %.6g", t[k]);
    fprintf(f, ")\n");
    fflush(f);
}
