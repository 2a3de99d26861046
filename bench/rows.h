/*
** rows.h: the output of bin/wskel-bench: a CSV (authoritative) and its
** JSON-lines twin (OUT.jsonl: OUT without ".csv", plus ".jsonl").
**
** The CSV: a block of '#' comment lines (machine, compiler, git commit,
** generator version, command, limits, the meaning of the columns; with
** --qsort-ref the "# qsort_ref_s:" line of qsort_ref.h, and another after
** the last row), the header row, then one row per run:
**
**   variant,family,n,r_req,holes,k,weights,seed,repeat   the configuration
**                                                  (its key)
**   r,status,signal,wall_s,cpu_s,peak_rss_bytes,peak_tracked_bytes,
**   nodes,arcs,crossings,validated                 the result
**   one column per counter name of the union over the variant registry
**   (wk_counter_union, in its order), empty where the row's variant has no
**   such counter or the run produced no counters
**   message                                        quoted; newlines as spaces
**
** Each JSON line has the same fields, with null for the empty cells and a
** "counters" object holding only the row variant's own counters.  A resumed
** sweep appends "# resumed ..." and its rows to the same files.
**
** Invariants: every row of a CSV has the header's columns, whatever its
** variant; a row is formatted wholly in memory, then written and flushed
** (both files) before the next one, so an interrupted sweep leaves whole
** rows plus at most one partial last line, which trim_partial removes; the
** key of a row (its first nine fields, no comma inside) is config_key of
** its configuration, which is what --resume matches.
**
** CSVs written before the holes axis (no holes column: the committed
** baselines) are read by --resume as holes = 0 on every row (done_set.legacy),
** and a resumed sweep appends its rows to them in their columns, without
** holes; it refuses to (exit 1) when a configuration to run has holes > 0.
*/
#ifndef WSKEL_BENCH_ROWS_H
#define WSKEL_BENCH_ROWS_H

#include "harness.h"

#include <stdio.h>

/* The JSON-lines twin of the CSV path. */
void jsonl_path(const char *csv, char *buf, size_t size);

/* The comment block of a fresh CSV (total configurations, this shard's). */
void machine_header(FILE *f, int argc, char **argv, const options *o, long total, long todo);

/* The header row. */
void write_header_row(FILE *f);

/* The comment line a resumed sweep starts with. */
void write_resume_line(FILE *f, long todo, long shard, const char *argv0);

/* Format the run's CSV row and JSON line, write them and flush both;
** legacy: the CSV row without the holes column (a resumed legacy file). */
void write_rows(FILE *csv, FILE *js, const config *c, const result *r, bool legacy);

/* Cut a file back to its last newline (a run interrupted mid-write leaves a
** partial line, which must not glue onto the next row). */
void trim_partial(const char *path);

/* The keys of the rows already in a CSV (--resume).  Exits 1 when the CSV
** has another generator version or is not a wskel-bench CSV of this
** version; a missing file has no keys. */
typedef struct done_set {
    char **keys; /* sorted */
    long n;
    bool legacy; /* the CSV has no holes column (keys read with holes = 0) */
} done_set;
void done_set_read(done_set *d, const char *path);
bool done_set_has(const done_set *d, const config *c);

#endif
