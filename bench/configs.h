/*
** configs.h: the configurations of a sweep, the cartesian product of its
** axes, and their text key.
**
** The axes, outermost first (the last one varies fastest):
**
**   family > n > r > holes > weights > seed > variant > k > repeat
**
** Most axes are the option's list as given.  Two depend on the axes outside
** them: r (a fraction of n, an absolute count or the family default) is
** resolved against the n in force; the k values are expanded from --k for
** the r (or n) in force, and a variant without k has the single value
** K_NA.  Two axes also filter (the configuration is left out, not given an
** index): holes > 0 for a family without holes (only holes and convex take
** them), and on the variant axis the cgal peer for weights other than unit
** and for n above --cgal-max-n, and a variant named in --max-n for n above
** its bound.  A variant that refuses holes (monotone) is
** not filtered: its runs get the status 'unsupported'.  With the default
** single holes value 0 the list is the one of before the holes axis, in the
** same order (existing CSVs, shards and resumes stay valid).
**
** Invariants: the list and its order depend only on the options, never on
** the machine, the results or the output file, so --shard I/N, --resume and
** existing CSVs agree between runs; config.index is the position in the
** full list (before sharding and resuming); the key (config_key) is the
** first nine CSV columns, unique per configuration, and contains no comma
** inside a field.
*/
#ifndef WSKEL_BENCH_CONFIGS_H
#define WSKEL_BENCH_CONFIGS_H

#include "harness.h"

#include <stddef.h>

/* The full configuration list in its fixed order (xmalloc'ed; *count
** entries). */
config *build_configs(const options *o, long *count);

/* The k column: "" for K_NA, "max" for WK_K_MAX, else the number. */
void format_k(uint32_t k, char *buf, size_t size);

/* The resume key: the configuration columns as they appear in the CSV,
** "variant,family,n,r_req,holes,k,weights,seed,repeat". */
void config_key(const config *c, char *buf, size_t size);

#endif
