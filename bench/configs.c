/*
** configs.c: the configurations of a sweep (configs.h): the axes and their
** cartesian product.
**
** The product is one odometer over the table of axes: the outermost axis is
** first, each axis is asked for its number of values only when the axes
** outside it have theirs (so an axis may depend on them, as r on n and k on
** the variant and r), and an axis may leave a value out together with
** everything inside it (the holes and cgal filters).  The order is that of
** the nested loops family > n > r > holes > weights > seed > variant > k >
** repeat, which existing CSVs and --resume rely on.
*/
#define _GNU_SOURCE
#include "configs.h"
#include "generators.h"
#include "spec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static bool variant_uses_k(const char *name) {
    const wk_variant *V = wk_variant_find(name);
    return V && (wk_variant_flags(V) & WK_VARIANT_USES_K);
}

static int64_t resolve_r(const r_req *q, uint64_t n) {
    if (q->frac > 0) return (int64_t)floor(q->frac * (double)n);
    return q->abs;
}

/* Append the k values of k_spec for a run with requested r (or n). */
static int expand_k(const str_list *ks, int64_t r, uint64_t n, uint32_t *out) {
    int c = 0;
    uint64_t top = r >= 0 ? (uint64_t)r : n;
    if (top < 1) top = 1;
    for (int i = 0; i < ks->n; i++) {
        const char *s = ks->v[i];
        if (!strcmp(s, "max")) out[c++] = WK_K_MAX;
        else if (!strcmp(s, "pow2")) {
            for (uint64_t k = 1; k <= top && c < MAX_LIST; k *= 2) out[c++] = (uint32_t)k;
        } else {
            uint64_t k = parse_u64("k", s);
            if (k < 1 || k >= WK_K_MAX) die_usage("--k: %s out of range", s);
            out[c++] = (uint32_t)k;
        }
        if (c >= MAX_LIST - 1) break;
    }
    /* drop duplicates, keeping the first occurrence (deterministic) */
    int m = 0;
    for (int i = 0; i < c; i++) {
        bool dup = false;
        for (int j = 0; j < m; j++) dup |= out[j] == out[i];
        if (!dup) out[m++] = out[i];
    }
    return m;
}

/* The product under construction: the values of the axes entered so far. */
typedef struct expansion {
    const options *o;
    config c;              /* the axes' values so far */
    uint64_t n;            /* the n axis at full width (c.n has 32 bits) */
    uint32_t ks[MAX_LIST]; /* the k axis's values for the axes outside it */
} expansion;

/* One axis: how many values it has, given the axes outside it, and how to
** take value i (false: leave the value out, with everything inside it). */
typedef struct axis {
    const char *name;
    int (*count)(expansion *e);
    bool (*take)(expansion *e, int i);
} axis;

static int family_count(expansion *e) { return e->o->families.n; }
static bool family_take(expansion *e, int i) {
    e->c.family = e->o->families.v[i];
    return true;
}

static int n_count(expansion *e) { return e->o->n.n; }
static bool n_take(expansion *e, int i) {
    e->n = e->o->n.v[i];
    e->c.n = (uint32_t)e->n;
    return true;
}

static int r_count(expansion *e) { return e->o->n_r; }
static bool r_take(expansion *e, int i) {
    e->c.r_req = resolve_r(&e->o->r[i], e->n);
    return true;
}

/* holes > 0 only for the families that take holes. */
static int holes_count(expansion *e) { return e->o->holes.n; }
static bool holes_take(expansion *e, int i) {
    e->c.holes = (uint32_t)e->o->holes.v[i];
    return e->c.holes == 0 || wk_gen_family_takes_holes(e->c.family);
}

static int weights_count(expansion *e) { return e->o->weights.n; }
static bool weights_take(expansion *e, int i) {
    e->c.weights = e->o->weights.v[i];
    return true;
}

static int seed_count(expansion *e) { return e->o->seeds.n; }
static bool seed_take(expansion *e, int i) {
    e->c.seed = e->o->seeds.v[i];
    return true;
}

/* cgal: unit weights only, and not above --cgal-max-n; a variant without
** WK_VARIANT_WEIGHTS (motorcycle): unit weights only (it takes equal ones,
** but the weight modes other than unit are unequal); a variant named in
** --max-n: not above its n. */
static int variant_count(expansion *e) { return e->o->variants.n; }
static bool variant_take(expansion *e, int i) {
    const char *var = e->o->variants.v[i];
    e->c.variant = var;
    for (int j = 0; j < e->o->max_n_variant.n; j++)
        if (!strcmp(var, e->o->max_n_variant.v[j]) && e->n > e->o->max_n.v[j]) return false;
    if (!strcmp(var, "cgal")) {
        if (strcmp(e->c.weights, "unit")) return false;
        if (e->o->cgal_max_n && e->n > e->o->cgal_max_n) return false;
    }
    const wk_variant *V = wk_variant_find(var);
    if (V && !(wk_variant_flags(V) & WK_VARIANT_WEIGHTS) && strcmp(e->c.weights, "unit")) return false;
    return true;
}

static int k_count(expansion *e) {
    if (variant_uses_k(e->c.variant)) return expand_k(&e->o->k_spec, e->c.r_req, e->n, e->ks);
    e->ks[0] = K_NA;
    return 1;
}
static bool k_take(expansion *e, int i) {
    e->c.k = e->ks[i];
    return true;
}

static int repeat_count(expansion *e) { return e->o->repeats; }
static bool repeat_take(expansion *e, int i) {
    e->c.repeat = i;
    return true;
}

/* Outermost first: this order is the order of every configuration list. */
static const axis axes[] = {
    {"family", family_count, family_take},    {"n", n_count, n_take},
    {"r", r_count, r_take},                   {"holes", holes_count, holes_take},
    {"weights", weights_count, weights_take},
    {"seed", seed_count, seed_take},          {"variant", variant_count, variant_take},
    {"k", k_count, k_take},                   {"repeat", repeat_count, repeat_take},
};
enum { N_AXES = sizeof axes / sizeof axes[0] };

config *build_configs(const options *o, long *count) {
    size_t cap = 1024, c = 0;
    config *v = xmalloc(cap * sizeof *v);
    expansion e;
    memset(&e, 0, sizeof e);
    e.o = o;
    int idx[N_AXES], cnt[N_AXES];
    int d = 0;
    cnt[0] = axes[0].count(&e);
    idx[0] = -1;
    while (d >= 0) {
        if (++idx[d] >= cnt[d]) { /* this axis is done: back to the next outer one */
            d--;
            continue;
        }
        if (!axes[d].take(&e, idx[d])) continue;
        if (d < N_AXES - 1) {
            d++;
            cnt[d] = axes[d].count(&e);
            idx[d] = -1;
            continue;
        }
        if (c == cap) v = xreallocarray(v, cap *= 2, sizeof *v);
        v[c] = e.c;
        v[c].index = (long)c;
        c++;
    }
    *count = (long)c;
    return v;
}

void format_k(uint32_t k, char *buf, size_t size) {
    if (k == K_NA) snprintf(buf, size, "%s", "");
    else if (k == WK_K_MAX) snprintf(buf, size, "max");
    else snprintf(buf, size, "%u", k);
}

/* The resume key: the configuration columns as they appear in the CSV. */
void config_key(const config *c, char *buf, size_t size) {
    char k[24];
    format_k(c->k, k, sizeof k);
    snprintf(buf, size, "%s,%s,%u,%lld,%u,%s,%s,%llu,%d", c->variant, c->family, c->n,
             (long long)c->r_req, c->holes, k, c->weights, (unsigned long long)c->seed,
             c->repeat);
}
