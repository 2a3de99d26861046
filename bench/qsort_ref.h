/*
** qsort_ref.h: the machine's reference speed, measured by bin/wskel-bench
** in the same process as a sweep: the time of the C library's qsort() on
** QSORT_REF_N uniform doubles in [0, 1) drawn from the generators' seeded
** generator (bench/gen/rng.h, seed QSORT_REF_SEED, stream 3), the median of
** QSORT_REF_REPS timings.  Reports state a variant's time as a multiple of
** it (time / qsort), which moves far less between machines and loads than
** seconds do.
**
** Where it goes: `wskel-bench --qsort-ref` alone (no --family, --n) prints
** the median in seconds on stdout and exits 0; with a sweep (flag or spec key
** `qsort-ref`) the parent measures it while no child runs, before the first
** run and after the last, and writes one comment line each into the CSV's
** '#' block:
**
**   # qsort_ref_s: 0.0823 (before the runs; qsort() of 1000000 doubles,
**   #   seed 1, median of 5: 0.0821 0.0823 ...)        <- one line in the file
**
** so the rows and their columns do not change (old CSVs, --resume,
** regress.py); scripts/results.py's qsort_ref() reads the lines back
** (their median).
**
** Invariants: the input is the same on every call and every platform (only
** the generator's integer arithmetic and an exact conversion); each timing
** sorts a fresh copy of it and covers qsort() alone.
*/
#ifndef WSKEL_BENCH_QSORT_REF_H
#define WSKEL_BENCH_QSORT_REF_H

#include <stdint.h>
#include <stdio.h>

#define QSORT_REF_N 1000000u
#define QSORT_REF_SEED 1u
#define QSORT_REF_REPS 5

/* The median of QSORT_REF_REPS timings in seconds; times[0..REPS) gets
** each one, in the order measured (NULL: not wanted). */
double qsort_ref_measure(double *times);

/* Measure and write "# qsort_ref_s: MEDIAN (WHEN; ...)" to f. */
void qsort_ref_comment(FILE *f, const char *when);

#endif
