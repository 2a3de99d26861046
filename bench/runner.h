/*
** runner.h: one configuration run in its own forked child.
**
**   child:  setrlimit/setitimer limits -> generate the polygon (not timed)
**           -> wk_solve (timed: wall and CPU of the construction only) ->
**           wk_validate if asked (not timed, a fresh time budget), writing a
**           fixed-size record to a pipe after each phase;
**   parent: read records until EOF, wait4 (peak RSS), classify the status
**           from the last record and the way the child ended.
**
** Statuses: ok, timeout (SIGALRM: wall clock; SIGXCPU or SIGKILL: CPU),
** out-of-memory, crash (with the signal), invalid (validator failed),
** rejected (generator or input refused), unsupported (the variant does not
** apply), algo-failed.  A failing run never stops the sweep.
**
** The peer "cgal": the child writes the polygon to a temporary .wpoly
** ($TMPDIR or /tmp, named after the parent's pid and the configuration
** index) and execs bin/wskel-cgal --stats on it; the parent reads the
** program's "nodes=.. arcs=.. time_s=.." line from its stderr: wall_s is
** that reported time, cpu_s stays empty.  The temporary files are removed.
**
** Invariants: run_config is safe to call from several threads at once (one
** child each; the child closes every other descriptor, so it holds no other
** job's pipe); the parent holds no run context; the record is smaller than
** PIPE_BUF, so each write is atomic and never blocks, and the parent keeps
** only whole records; a child that ends without a record is a crash.
*/
#ifndef WSKEL_BENCH_RUNNER_H
#define WSKEL_BENCH_RUNNER_H

#include "harness.h"

#include <stddef.h>

/* Run c in a child and fill *res (status, times, peak RSS, counters). */
void run_config(const options *o, const config *c, const char *cgal_bin, result *res);

/* Where bin/wskel-cgal is: $WSKEL_CGAL, else beside this program. */
void find_cgal(char *buf, size_t size);

#endif
