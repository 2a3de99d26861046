/*
** configs.h: the configurations of a sweep, the cartesian product of its
** axes, and their text key.
**
** The axes, outermost first (the last one varies fastest):
**
**   family > n > r > weights > seed > variant > k > repeat
**
** Most axes are the option's list as given.  Two depend on the axes outside
** them: r (a fraction of n, an absolute count or the family default) is
** resolved against the n in force; the k values are expanded from --k for
** the r (or n) in force, and a variant without k has the single value
** K_NA.  The variant axis also filters: the cgal peer is skipped for
** weights other than unit and for n above --cgal-max-n (the configuration
** is left out, not given an index).
**
** Invariants: the list and its order depend only on the options, never on
** the machine, the results or the output file, so --shard I/N, --resume and
** existing CSVs agree between runs; config.index is the position in the
** full list (before sharding and resuming); the key (config_key) is the
** first eight CSV columns, unique per configuration, and contains no comma
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
** "variant,family,n,r_req,k,weights,seed,repeat". */
void config_key(const config *c, char *buf, size_t size);

#endif
