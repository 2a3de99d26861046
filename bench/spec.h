/*
** spec.h: the options of a sweep and their two spellings, command-line
** flags and spec files (--spec FILE, bench/sweeps/).
**
** Spec file format: one "key = value" per line, keys as the long flags
** without "--" (family, n, r, holes, k, variant, weights, seeds, seeds-count,
** repeats, cgal-max-n, max-n, time-limit, mem-limit, validate, jobs, shard, resume,
** quiet, qsort-ref, out, self-test); '#' starts a comment (to the end of the line);
** blank lines are ignored; spaces and tabs around keys and values are
** dropped; a key without '=' is a boolean flag set to true; "spec" is
** refused (a spec cannot include another).  Values as for the flags: lists
** are comma-separated, integer lists also take A..B and A..B:C (see
** --help).
**
** Invariants: options are applied in the order they are read (flags and
** the spec's lines, left to right): a later value of a key replaces the
** earlier one wholly (lists are not appended).  Any malformed value is a
** usage error (die_usage, exit 64) before anything runs.  After
** options_finish the lists hold only known families and variants, and the
** weight modes in their canonical text (so resume keys compare equal
** across spellings).
*/
#ifndef WSKEL_BENCH_SPEC_H
#define WSKEL_BENCH_SPEC_H

#include "harness.h"

/* --help. */
extern const char bench_usage_text[];

/* The defaults: variant naive, weights unit, k 1, seed 1, r default, holes 0,
** repeats 1, time limit 60 s, memory limit 4096 MB, one job, shard 0/1. */
void options_init(options *o);

/* Apply one option (key without "--"). */
void set_option(options *o, const char *key, const char *val);

/* Apply every line of a spec file. */
void load_spec(options *o, const char *path);

/* Apply argv.  Returns false when the program should stop now with
** *exit_code (--help, --list-variants were printed); *dry is set by
** --dry-run. */
bool options_from_argv(options *o, int argc, char **argv, bool *dry, int *exit_code);

/* A non-negative decimal integer, or a usage error naming --key. */
uint64_t parse_u64(const char *key, const char *s);

/* Check and normalise after the last option: --family and --n given,
** 'all' families expanded, unknown families and variants refused, the cgal
** peer dropped with a warning when cgal_bin is not executable, weight modes
** canonical. */
void options_finish(options *o, const char *cgal_bin);

#endif
