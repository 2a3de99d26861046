/*
** generators.c: the generator front end: parameters, weight modes, the family
** table and wk_generate, which runs a family, draws the weights and has
** wk_polygon_from_rings validate the result.
**
** Determinism: everything is a function of (family, n, r, holes, seed,
** weight mode).
** Geometry draws from stream 1 of the seed, weights from stream 2, so the
** weight mode never changes a coordinate.
**
** Invariant of every polygon wk_generate hands out: it passed
** wk_polygon_from_rings (simple, exactly n vertices over 1 + holes rings),
** was already stored as generated (outer ring counter-clockwise, holes
** clockwise, none reversed, so w[i] is the weight drawn for edge i),
** and has exactly the reflex count its family promised, if it promised one.
** The families themselves live in gen_*.c (see gen_internal.h).
*/
#include "gen_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct family {
    const char *name;
    wk_gen_fn fn;            /* NULL: rings only */
    wk_gen_rings_fn rings;   /* holes > 0 (or always, when fn is NULL); NULL: no holes */
    const char *summary;
} family;

/* The order here is the order of --list and of wk_gen_families. */
static const family families[] = {
    {"star", wk_gen_star, NULL,
     "star-shaped, radii in [0.2,1]R; r random, or exactly --r (<= n/2) spikes"},
    {"comb", wk_gen_comb, NULL,
     "equal rectangular teeth on a bar, integer coordinates; r = 2*(floor(n/4)-1)"},
    {"spiral", wk_gen_spiral, NULL, "thick polygonal spiral, inner chain reflex; r = floor(n/2)-2"},
    {"notched", wk_gen_notched, NULL,
     "regular n-gon with r (<= n/2, default n/4) non-adjacent vertices pushed in"},
    {"crossing", wk_gen_crossing, NULL,
     "disc with r spikes at staggered depths, every pair of rays crosses: r(r-1)/2; n >= 3r+4"},
    {"random", wk_gen_random, NULL,
     "random simple polygon: 2-opt untangled points (n <= 5000), else random star"},
    {"monotone", wk_gen_monotone, NULL,
     "x-monotone, exactly r reflex (r <= n-3, default (n-2)/2)"},
    {"rectilinear", wk_gen_rectilinear, NULL,
     "axis-parallel, two staircases, integer coordinates; n even, r = n/2-2"},
    {"convex", wk_gen_convex, wk_gen_convex_holes,
     "points on a random ellipse; r = 0; --holes H: convex windows, r = hole vertices"},
    {"holes", NULL, wk_gen_holes,
     "--holes H star/convex holes in a star/convex outer ring; n >= 3H+3, holes get max(3H,n/2)"},
    {"coastline", wk_gen_coastline, NULL,
     "random Koch-like fractal curve closed over a k-gon, simple by construction; r about n/2"},
};

const char *const wk_gen_families[] = {
    "star", "comb", "spiral", "notched", "crossing", "random", "monotone", "rectilinear", "convex",
    "holes", "coastline", NULL,
};

_Static_assert(sizeof families / sizeof families[0] ==
                   sizeof wk_gen_families / sizeof wk_gen_families[0] - 1,
               "wk_gen_families must list the family table");

static const family *find_family(const char *name) {
    if (!name) return NULL;
    for (size_t i = 0; i < sizeof families / sizeof families[0]; i++)
        if (strcmp(families[i].name, name) == 0) return &families[i];
    return NULL;
}

const char *wk_gen_family_summary(const char *name) {
    const family *F = find_family(name);
    return F ? F->summary : NULL;
}

bool wk_gen_family_takes_holes(const char *name) {
    const family *F = find_family(name);
    return F && F->rings;
}

void wk_gen_params_init(wk_gen_params *g) {
    memset(g, 0, sizeof *g);
    g->family = NULL;
    g->n = 0;
    g->r = -1;
    g->holes = 0;
    g->seed = 1;
    g->weights = WK_W_UNIT;
    g->wa = 0.5;
    g->wb = 2.0;
}

wk_status wk_gen_fixed_r(wk_run *R, const wk_gen_params *g, int64_t r, const char *rule) {
    if (g->r < 0 || g->r == r) return WK_OK;
    if (!rule)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: r=%lld cannot be chosen: r = %lld always",
                       g->family, (long long)g->r, (long long)r);
    return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: r=%lld cannot be chosen: r = %s = %lld for n=%u",
                   g->family, (long long)g->r, rule, (long long)r, g->n);
}

/* ---- weights ---- */

static const char *const mode_names[] = {"unit", "uniform", "two", "int"};

/* The one check of a weight range, for parsed and hand-filled params. */
static wk_status check_weights(wk_run *R, wk_weight_mode m, double a, double b) {
    const char *name = (unsigned)m < 4 ? mode_names[m] : "?";
    if ((unsigned)m > WK_W_INT) return WK_FAIL(R, WK_EUSAGE, NULL, 0, "unknown weight mode %d", m);
    if (m == WK_W_UNIT) return WK_OK;
    if (!isfinite(a) || !isfinite(b) || !(a > 0) || !(b > 0))
        return WK_FAIL(R, WK_EUSAGE, NULL, 0, "weights %s:%g:%g: weights must be finite and > 0",
                       name, a, b);
    if (m != WK_W_TWO && a > b)
        return WK_FAIL(R, WK_EUSAGE, NULL, 0, "weights %s:%g:%g: need a <= b", name, a, b);
    if (m == WK_W_INT && (a != floor(a) || b != floor(b) || b > 1e15))
        return WK_FAIL(R, WK_EUSAGE, NULL, 0, "weights int:%g:%g: bounds must be integers", a, b);
    return WK_OK;
}

wk_status wk_gen_parse_weights(wk_run *R, const char *s, wk_gen_params *g) {
    static const double defaults[4][2] = {{1, 1}, {0.5, 2}, {1, 3}, {1, 4}};
    size_t len = strcspn(s, ":");
    int m = -1;
    for (int i = 0; i < 4; i++)
        if (strlen(mode_names[i]) == len && strncmp(s, mode_names[i], len) == 0) m = i;
    if (m < 0)
        return WK_FAIL(R, WK_EUSAGE, NULL, 0,
                       "unknown weight mode '%s' (unit, uniform[:a:b], two[:a:b], int[:a:b])", s);
    double a = defaults[m][0], b = defaults[m][1];
    if (s[len] == ':') {
        if (m == WK_W_UNIT)
            return WK_FAIL(R, WK_EUSAGE, NULL, 0, "weights '%s': unit takes no range", s);
        const char *as = s + len + 1, *bs = NULL;
        char *end;
        a = strtod(as, &end);
        if (end != as && *end == ':') {
            bs = end + 1;
            b = strtod(bs, &end);
        }
        if (!bs || end == bs || *end != '\0')
            return WK_FAIL(R, WK_EUSAGE, NULL, 0, "weights '%s': expected %s:a:b", s,
                           mode_names[m]);
    }
    wk_status st = check_weights(R, (wk_weight_mode)m, a, b);
    if (st != WK_OK) return st;
    g->weights = (wk_weight_mode)m;
    g->wa = a;
    g->wb = b;
    return WK_OK;
}

/* Shortest of %.15g and %.17g that reads back to v. */
static void format_number(char *buf, size_t size, double v) {
    snprintf(buf, size, "%.15g", v);
    if (strtod(buf, NULL) != v) snprintf(buf, size, "%.17g", v);
}

void wk_gen_weights_format(const wk_gen_params *g, char *buf, size_t size) {
    if (g->weights == WK_W_UNIT || (unsigned)g->weights > WK_W_INT) {
        snprintf(buf, size, "unit");
        return;
    }
    char a[32], b[32];
    format_number(a, sizeof a, g->wa);
    format_number(b, sizeof b, g->wb);
    snprintf(buf, size, "%s:%s:%s", mode_names[g->weights], a, b);
}

static double draw_weight(wk_rng *rng, const wk_gen_params *g) {
    switch (g->weights) {
    case WK_W_UNIT: return 1.0;
    case WK_W_UNIFORM: return wk_rng_range(rng, g->wa, g->wb);
    case WK_W_TWO: return wk_rng_below(rng, 2) ? g->wb : g->wa;
    case WK_W_INT: return g->wa + (double)wk_rng_below(rng, (uint64_t)(g->wb - g->wa) + 1);
    }
    return 1.0;
}

/* ---- generation ---- */

wk_status wk_generate(wk_run *R, const wk_gen_params *g, wk_polygon **out) {
    *out = NULL;
    const family *F = find_family(g->family);
    if (!F)
        return WK_FAIL(R, WK_EUSAGE, NULL, 0, "unknown family '%s' (see --list)",
                       g->family ? g->family : "(none)");
    if (g->n < 3 || g->n > WK_GEN_N_MAX)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: n=%u is outside [3, %u]", F->name, g->n,
                       WK_GEN_N_MAX);
    if (g->r < -1)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: r=%lld must be >= 0", F->name,
                       (long long)g->r);
    wk_status st = check_weights(R, g->weights, g->wa, g->wb);
    if (st != WK_OK) return st;

    bool rings = F->rings && (g->holes > 0 || !F->fn);
    if (g->holes > 0 && !F->rings)
        return WK_FAIL(R, WK_EINPUT, NULL, 0,
                       "%s: holes=%u: this family has no holes (families with holes: convex, "
                       "holes)",
                       F->name, g->holes);
    if ((uint64_t)g->holes + 1 > WK_POLYGON_MAX_RINGS)
        return WK_FAIL(R, WK_EINPUT, NULL, 0, "%s: holes=%u > %u", F->name, g->holes,
                       WK_POLYGON_MAX_RINGS - 1);

    uint32_t n = g->n, n_rings = rings ? g->holes + 1 : 1;
    wk_polygon *P = NULL;
    double *x = WK_NEW_ARRAY(R, double, n);
    double *y = WK_NEW_ARRAY(R, double, n);
    double *w = WK_NEW_ARRAY(R, double, n);
    uint32_t *ring_size = WK_NEW_ARRAY(R, uint32_t, n_rings);
    if (!x || !y || !w || !ring_size) {
        st = WK_ENOMEM;
        goto fail;
    }

    wk_rng geo, wr;
    wk_rng_seed(&geo, g->seed, 1);
    wk_rng_seed(&wr, g->seed, 2);
    int64_t r_promised = -1;
    if (rings) st = F->rings(R, g, &geo, x, y, ring_size, &r_promised);
    else {
        ring_size[0] = n;
        st = F->fn(R, g, &geo, x, y, &r_promised);
    }
    if (st != WK_OK) goto fail;
    uint64_t total = 0;
    for (uint32_t k = 0; k < n_rings; k++) total += ring_size[k];
    if (total != n) {
        st = WK_FAIL(R, WK_EALGO, NULL, 0, "generator bug: %s: rings hold %llu vertices, not %u",
                     F->name, (unsigned long long)total, n);
        goto fail;
    }
    for (uint32_t i = 0; i < n; i++) w[i] = draw_weight(&wr, g);

    char name[128];
    if (g->holes > 0)
        snprintf(name, sizeof name, "%s(n=%u,holes=%u,seed=%llu)", F->name, n, g->holes,
                 (unsigned long long)g->seed);
    else
        snprintf(name, sizeof name, "%s(n=%u,seed=%llu)", F->name, n,
                 (unsigned long long)g->seed);
    if ((st = wk_polygon_from_rings(R, n_rings, ring_size, x, y, w, name, NULL, &P)) != WK_OK)
        goto fail;
    /* Defensive: the families build the outer ring counter-clockwise and the
    ** holes clockwise, with a known reflex count, by construction; a
    ** mismatch is a generator bug, and a wrong polygon must not reach a
    ** benchmark under a false label. */
    if (P->reversed) {
        st = WK_FAIL(R, WK_EALGO, name, 0, "generator bug: %s produced a clockwise polygon",
                     F->name);
        goto fail;
    }
    for (uint32_t i = 0; n_rings > 1 && i < n; i++)
        if (P->input_index[i] != i) {
            st = WK_FAIL(R, WK_EALGO, name, 0,
                         "generator bug: %s produced a counter-clockwise hole (ring %u)",
                         F->name, wk_polygon_ring(P, i));
            goto fail;
        }
    if (r_promised >= 0 && (int64_t)P->r != r_promised) {
        st = WK_FAIL(R, WK_EALGO, name, 0,
                     "generator bug: %s has %u reflex vertices, promised %lld", F->name, P->r,
                     (long long)r_promised);
        goto fail;
    }
    *out = P;
    P = NULL;
    goto done;
fail:
    /* st is the failing call's status (R->err may hold an earlier failure,
    ** as the first one wins). */
    wk_polygon_free(R, P);
done:
    WK_FREE_ARRAY(R, x, n);
    WK_FREE_ARRAY(R, y, n);
    WK_FREE_ARRAY(R, w, n);
    if (ring_size) WK_FREE_ARRAY(R, ring_size, n_rings);
    return st;
}
