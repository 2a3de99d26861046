/*
** rows.c: the CSV and JSON-lines output of bin/wskel-bench (rows.h has the
** format and the invariants), and the reading back of a CSV's keys for
** --resume.
*/
#define _GNU_SOURCE
#include "rows.h"
#include "configs.h"
#include "generators.h"

#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* The counter columns: the union over the registry (wk_counter_union), so
** every row of a CSV has the same columns whatever its variant. */
#define MAX_COUNTER_COLUMNS 256
typedef struct counter_columns {
    const char *name[MAX_COUNTER_COLUMNS];
    uint32_t n;
} counter_columns;

static void counter_columns_get(counter_columns *cc) {
    cc->n = wk_counter_union(cc->name, MAX_COUNTER_COLUMNS);
    if (cc->n > MAX_COUNTER_COLUMNS) cc->n = MAX_COUNTER_COLUMNS;
}

/* Column j's value for a row of variant V: false when V has no such counter
** (an empty cell, not 0). */
static bool counter_value(const counter_columns *cc, uint32_t j, const wk_variant *V,
                          const wk_counters *c, uint64_t *value) {
    uint32_t id;
    if (!wk_counter_find(V, cc->name[j], &id)) return false;
    *value = c->c[id];
    return true;
}

static const char base_columns[] =
    "variant,family,n,r_req,holes,k,weights,seed,repeat,r,status,signal,wall_s,cpu_s,"
    "peak_rss_bytes,peak_tracked_bytes,nodes,arcs,crossings,validated";
/* The columns of a CSV written before the holes axis: the same without
** holes.  --resume reads such a file as holes = 0 everywhere and appends its
** rows in the same columns (write_rows with legacy set). */
static const char legacy_base_columns[] =
    "variant,family,n,r_req,k,weights,seed,repeat,r,status,signal,wall_s,cpu_s,"
    "peak_rss_bytes,peak_tracked_bytes,nodes,arcs,crossings,validated";
#define KEY_FIELDS 9        /* config_key's fields */
#define HOLES_FIELD 4       /* where holes sits among them */

/* A growable string for one output row. */
typedef struct sbuf { char *s; size_t len, cap; } sbuf;
static void sb_printf(sbuf *b, const char *fmt, ...) {
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int need = vsnprintf(b->s ? b->s + b->len : NULL, b->s ? b->cap - b->len : 0, fmt, ap);
        va_end(ap);
        if (b->s && (size_t)need < b->cap - b->len) {
            b->len += (size_t)need;
            return;
        }
        b->cap = (b->cap + (size_t)need + 1) * 2;
        b->s = xrealloc(b->s, b->cap);
        if (b->len == 0) b->s[0] = 0;
    }
}

static void sb_num(sbuf *b, bool have, double v) {
    if (have) sb_printf(b, "%.9g", v);
}

/* CSV quoting; newlines become spaces. */
static void sb_csv_str(sbuf *b, const char *s) {
    sb_printf(b, "\"");
    for (; *s; s++) {
        if (*s == '"') sb_printf(b, "\"\"");
        else if (*s == '\n' || *s == '\r') sb_printf(b, " ");
        else sb_printf(b, "%c", *s);
    }
    sb_printf(b, "\"");
}

static void sb_json_str(sbuf *b, const char *s) {
    sb_printf(b, "\"");
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') sb_printf(b, "\\%c", ch);
        else if (ch < 0x20) sb_printf(b, "\\u%04x", ch);
        else sb_printf(b, "%c", ch);
    }
    sb_printf(b, "\"");
}

/* The key without its holes field (legacy CSVs; holes is 0 there). */
static void drop_holes_field(char *key) {
    char *p = key;
    for (int i = 0; i < HOLES_FIELD && p; i++) p = strchr(p + (i ? 1 : 0), ',');
    if (!p) return;
    char *q = strchr(p + 1, ',');
    if (q) memmove(p, q, strlen(q) + 1);
}

static void format_rows(const config *c, const result *r, bool legacy, sbuf *csv, sbuf *js) {
    char key[512], k[24];
    config_key(c, key, sizeof key);
    if (legacy) drop_holes_field(key);
    format_k(c->k, k, sizeof k);
    counter_columns cc;
    counter_columns_get(&cc);
    const wk_variant *V = wk_variant_find(c->variant); /* NULL for cgal */
    uint64_t cv;
    bool hc = r->have_counters;
    sb_printf(csv, "%s,%u,%s,", key, r->r, r->status);
    if (r->sig) sb_printf(csv, "%d", r->sig);
    sb_printf(csv, ",");
    sb_num(csv, r->have_time, r->wall_s);
    sb_printf(csv, ",");
    sb_num(csv, r->have_cpu, r->cpu_s);
    sb_printf(csv, ",%llu,", (unsigned long long)r->peak_rss);
    if (hc) sb_printf(csv, "%llu", (unsigned long long)r->peak_tracked);
    sb_printf(csv, ",%u,%u,", r->nodes, r->arcs);
    uint32_t crossings_id;
    if (hc && wk_counter_find(V, "arrangement_crossings_initial", &crossings_id))
        sb_printf(csv, "%llu", (unsigned long long)r->c.c[crossings_id]);
    sb_printf(csv, ",%d", r->validated ? 1 : 0);
    for (uint32_t i = 0; i < cc.n; i++) {
        sb_printf(csv, ",");
        if (hc && counter_value(&cc, i, V, &r->c, &cv)) sb_printf(csv, "%llu", (unsigned long long)cv);
    }
    sb_printf(csv, ",");
    sb_csv_str(csv, r->msg);
    sb_printf(csv, "\n");

    sb_printf(js, "{\"variant\":");
    sb_json_str(js, c->variant);
    sb_printf(js, ",\"family\":");
    sb_json_str(js, c->family);
    sb_printf(js, ",\"n\":%u,\"r_req\":%lld,\"holes\":%u,\"k\":", c->n, (long long)c->r_req,
              c->holes);
    if (c->k == K_NA) sb_printf(js, "null");
    else sb_json_str(js, k);
    sb_printf(js, ",\"weights\":");
    sb_json_str(js, c->weights);
    sb_printf(js, ",\"seed\":%llu,\"repeat\":%d,\"r\":%u,\"status\":\"%s\",\"signal\":",
              (unsigned long long)c->seed, c->repeat, r->r, r->status);
    if (r->sig) sb_printf(js, "%d", r->sig);
    else sb_printf(js, "null");
    sb_printf(js, ",\"wall_s\":");
    if (r->have_time) sb_printf(js, "%.9g", r->wall_s);
    else sb_printf(js, "null");
    sb_printf(js, ",\"cpu_s\":");
    if (r->have_cpu) sb_printf(js, "%.9g", r->cpu_s);
    else sb_printf(js, "null");
    /* The variant's timed phase (wk_variant.phase), in the JSON lines only:
    ** the CSV's columns stay those of the committed baselines. */
    sb_printf(js, ",\"phase\":");
    if (V && wk_variant_phase(V)) sb_json_str(js, wk_variant_phase(V));
    else sb_printf(js, "null");
    sb_printf(js, ",\"phase_s\":");
    if (V && wk_variant_phase(V) && r->have_time) sb_printf(js, "%.9g", r->phase_s);
    else sb_printf(js, "null");
    sb_printf(js, ",\"peak_rss_bytes\":%llu,\"peak_tracked_bytes\":", (unsigned long long)r->peak_rss);
    if (hc) sb_printf(js, "%llu", (unsigned long long)r->peak_tracked);
    else sb_printf(js, "null");
    sb_printf(js, ",\"nodes\":%u,\"arcs\":%u,\"validated\":%s,\"counters\":", r->nodes, r->arcs,
              r->validated ? "true" : "false");
    if (hc) {
        sb_printf(js, "{");
        bool first = true;
        for (uint32_t i = 0; i < cc.n; i++)
            if (counter_value(&cc, i, V, &r->c, &cv)) {
                sb_printf(js, "%s\"%s\":%llu", first ? "" : ",", cc.name[i], (unsigned long long)cv);
                first = false;
            }
        sb_printf(js, "}");
    } else sb_printf(js, "null");
    sb_printf(js, ",\"message\":");
    sb_json_str(js, r->msg);
    sb_printf(js, "}\n");
}

static void read_first_line(const char *cmd, char *buf, size_t size) {
    buf[0] = 0;
    FILE *p = popen(cmd, "r");
    if (!p) return;
    if (fgets(buf, (int)size, p)) buf[strcspn(buf, "\n")] = 0;
    pclose(p);
}

void machine_header(FILE *f, int argc, char **argv, const options *o, long total, long todo) {
    char cpu[256] = "unknown", mem[64] = "unknown", line[512];
    FILE *ci = fopen("/proc/cpuinfo", "r");
    if (ci) {
        while (fgets(line, sizeof line, ci))
            if (!strncmp(line, "model name", 10)) {
                char *c = strchr(line, ':');
                if (c) {
                    c++;
                    while (*c == ' ') c++;
                    c[strcspn(c, "\n")] = 0;
                    snprintf(cpu, sizeof cpu, "%s", c);
                }
                break;
            }
        fclose(ci);
    }
    FILE *mi = fopen("/proc/meminfo", "r");
    if (mi) {
        unsigned long kb;
        while (fgets(line, sizeof line, mi))
            if (sscanf(line, "MemTotal: %lu kB", &kb) == 1) {
                snprintf(mem, sizeof mem, "%.1f GiB", (double)kb / 1048576.0);
                break;
            }
        fclose(mi);
    }
    char commit[128], dirty[16];
    read_first_line("git rev-parse HEAD 2>/dev/null", commit, sizeof commit);
    read_first_line("git status --porcelain --untracked-files=no 2>/dev/null | head -1 | wc -l", dirty, sizeof dirty);
    time_t now = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    const char *cflags = getenv("WSKEL_CFLAGS");
    fprintf(f, "# wskel-bench results (CSV; lines starting with '#' are comments)\n");
    fprintf(f, "# date: %s\n", date);
    fprintf(f, "# cpu: %s\n", cpu);
    fprintf(f, "# cores: %ld\n", sysconf(_SC_NPROCESSORS_ONLN));
    fprintf(f, "# memory: %s\n", mem);
    fprintf(f, "# compiler: %s\n", __VERSION__);
    fprintf(f, "# cflags: %s\n", cflags ? cflags : "unknown (set WSKEL_CFLAGS)");
    fprintf(f, "# git: %s%s\n", commit[0] ? commit : "unknown", atoi(dirty) > 0 ? " (uncommitted changes)" : "");
    fprintf(f, "# generator version: %d\n", WK_GEN_VERSION);
    fprintf(f, "# command:");
    for (int i = 0; i < argc; i++) fprintf(f, " %s", argv[i]);
    fprintf(f, "\n# limits: time %gs, memory %g MB; validate %s; jobs %d; shard %d/%d; "
               "configurations %ld (this shard %ld)\n",
            o->time_limit, o->mem_limit_mb, o->validate ? "on" : "off", o->jobs, o->shard_i,
            o->shard_n, total, todo);
    fprintf(f, "# columns: variant, family, n (vertices asked), r_req (reflex asked, -1: family "
               "default), holes (asked), k (empty: variant has no k), weights, seed, repeat: the "
               "configuration;\n"
               "#   r: actual reflex vertices; status: ok|timeout|out-of-memory|crash|invalid|"
               "rejected|unsupported|algo-failed; signal: for crash;\n"
               "#   wall_s, cpu_s: the construction alone (cgal: its reported time, no cpu); "
               "peak_rss_bytes: child peak RSS (wait4);\n"
               "#   peak_tracked_bytes: peak bytes through the run allocator during the "
               "construction; nodes, arcs: skeleton size;\n"
               "#   crossings: initial arrangement crossings; validated: 1 if the validator "
               "ran and passed or failed (see status);\n"
               "#   then every counter of every variant by name (the union over the registry;\n"
               "#   empty where the row's variant has no such counter); message: the error, if any.\n");
}

void write_header_row(FILE *f) {
    fprintf(f, "%s", base_columns);
    counter_columns cc;
    counter_columns_get(&cc);
    for (uint32_t i = 0; i < cc.n; i++) fprintf(f, ",%s", cc.name[i]);
    fprintf(f, ",message\n");
}

/* Cut a file back to its last newline (a run interrupted mid-write leaves a
** partial line, which must not glue onto the next row). */
void trim_partial(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    long keep = len;
    while (keep > 0) {
        fseek(f, keep - 1, SEEK_SET);
        if (fgetc(f) == '\n') break;
        keep--;
    }
    fclose(f);
    if (keep != len && truncate(path, keep) != 0)
        fprintf(stderr, "wskel-bench: %s: cannot truncate: %s\n", path, strerror(errno));
}

/* Keys of the rows already in path (resume); *legacy: the file has the
** columns of before the holes axis (its keys get holes = 0). */
static char **read_done_keys(const char *path, long *count, bool *legacy) {
    *count = 0;
    *legacy = false;
    FILE *f = fopen(path, "r");
    if (!f) return NULL;
    size_t cap = 256;
    char **keys = xmalloc(cap * sizeof *keys);
    char line[8192];
    bool header_seen = false;
    while (fgets(line, sizeof line, f)) {
        int gv;
        if (sscanf(line, "# generator version: %d", &gv) == 1 && gv != WK_GEN_VERSION) {
            /* its rows describe other polygons under the same keys */
            fprintf(stderr,
                    "wskel-bench: %s: written with generator version %d, this is %d: "
                    "--resume would mix polygons; remove it or choose another --out\n",
                    path, gv, WK_GEN_VERSION);
            exit(1);
        }
        if (line[0] == '#' || line[0] == '\n') continue;
        if (!header_seen) {
            header_seen = true;
            if (!strncmp(line, legacy_base_columns, strlen(legacy_base_columns)))
                *legacy = true;
            else if (strncmp(line, base_columns, strlen(base_columns)) != 0) {
                fprintf(stderr, "wskel-bench: %s: not a wskel-bench CSV of this version\n", path);
                exit(1);
            }
            continue;
        }
        /* the key is the first 9 fields (8 in a legacy file; none of them
        ** contains a comma) */
        int fields = *legacy ? KEY_FIELDS - 1 : KEY_FIELDS;
        char *p = line;
        for (int i = 0; i < fields && p; i++) p = strchr(p + (i ? 1 : 0), ',');
        if (!p) continue;
        if ((size_t)*count == cap) keys = xreallocarray(keys, cap *= 2, sizeof *keys);
        if (*legacy) {
            /* insert ",0" after the r_req field */
            char *q = line;
            for (int i = 0; i < HOLES_FIELD && q; i++) q = strchr(q + (i ? 1 : 0), ',');
            size_t head = (size_t)(q - line), tail = (size_t)(p - q);
            char *k = xmalloc(head + 2 + tail + 1);
            memcpy(k, line, head);
            memcpy(k + head, ",0", 2);
            memcpy(k + head + 2, q, tail);
            k[head + 2 + tail] = 0;
            keys[(*count)++] = k;
        } else
            keys[(*count)++] = xstrndup(line, (size_t)(p - line));
    }
    fclose(f);
    return keys;
}

static int cmp_str(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

void done_set_read(done_set *d, const char *path) {
    d->keys = read_done_keys(path, &d->n, &d->legacy);
    if (d->n) qsort(d->keys, (size_t)d->n, sizeof *d->keys, cmp_str);
}

bool done_set_has(const done_set *d, const config *c) {
    if (!d->n) return false;
    char key[512], *kp = key;
    config_key(c, key, sizeof key);
    return bsearch(&kp, d->keys, (size_t)d->n, sizeof *d->keys, cmp_str) != NULL;
}

void jsonl_path(const char *csv, char *buf, size_t size) {
    size_t ol = strlen(csv);
    if (ol > 4 && !strcmp(csv + ol - 4, ".csv")) snprintf(buf, size, "%.*sjsonl", (int)(ol - 3), csv);
    else snprintf(buf, size, "%s.jsonl", csv);
}

void write_resume_line(FILE *f, long todo, long shard, const char *argv0) {
    fprintf(f, "# resumed %ld of %ld configurations left, by: %s\n", todo, shard, argv0);
}

void write_rows(FILE *csv, FILE *js, const config *c, const result *r, bool legacy) {
    sbuf a = {0}, b = {0};
    format_rows(c, r, legacy, &a, &b);
    fputs(a.s, csv);
    fputs(b.s, js);
    fflush(csv);
    fflush(js);
    free(a.s);
    free(b.s);
}
