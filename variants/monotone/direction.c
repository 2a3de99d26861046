/*
** direction.c: find a direction in which the polygon is monotone, or refuse.
**
** A simple polygon is monotone in direction d (every line perpendicular to d
** meets it in a connected set) iff no reflex vertex has both neighbours
** strictly on one side of the line through it perpendicular to d (with the
** plateaus of the non-strict case checked globally, below).  Directions are
** taken modulo pi (d and -d are the same sweep).  For a reflex vertex with
** neighbour offsets u1, u2 the good directions form one closed arc of the
** circle R / pi Z: between the two directions perpendicular to u1 and u2, on
** the side where d.u1 and d.u2 differ in sign; its length is the vertex's
** exterior angle (< pi).  The good set is the intersection of these r arcs,
** found by sorting their 2 r ends and sweeping once around the circle:
** O(n log n).
**
** Within the tolerance.  P is taken as monotone in d when moving each vertex
** by at most tol = WK_MONO_DIR_TOL * eps_d along d makes it monotone
** (tolerance.h says why): in each chain no vertex lies more than tol behind
** the running extreme of the vertices before it.  check_direction tests
** exactly that on the computed projections.  Its necessary local form widens
** each arc end by asin(2 tol / |u|) (u the offset whose perpendicular ends
** it): without it, polygons monotone only with edges perpendicular to the
** sweep, turned in doubles, had arcs that missed each other by rounding and
** were refused.
**
** Which good direction.  001's lemmas need strict monotonicity: no edge
** perpendicular to d (here: none within sine WK_PARALLEL_SIN of it, and none
** going back within tol).
** Candidates per run of the good set, widest run first: if the run is wider
** than WK_MONO_DIR_WIDE (tolerance.h), the middle of the widest gap, inside it, between
** directions perpendicular to any edge; the exact unit normals of the edges
** nearest in angle to the run's middle and ends (exactly an axis for an
** axis-parallel edge, so projections are exact there: combs, rectilinear
** staircases monotone in x only, and such polygons turned); the run's
** middle.  The first candidate that checks out strictly monotone wins, else
** the first one that checks out with plateaus (non-strict).  So the choice
** never rests on the angles alone.
**
** Refusal.  WK_EUNSUPPORTED when the widened arcs have no common direction,
** or when every candidate of every run leaves a vertex more than
** 2 tol + width * scale behind (no direction of the run can then be good,
** see wk_mono_direction); otherwise, if no candidate checks out, WK_EALGO
** and the caller falls back to the reference: a polygon monotone within the
** tolerance is never refused.
**
** Chain ends.  v_w is the last vertex, counter-clockwise, of the westmost
** plateau and v_e the first of the eastmost one (plateaus: equal computed
** projections), so the lower chain (v_w to v_e) starts and ends with edges
** that go east and any edge exactly perpendicular to d at the extremes
** belongs to the upper chain.
*/
#include "monotone.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

typedef struct ang_ev {
    double a;   /* angle in [0, pi) */
    int delta;  /* +1 an arc starts, -1 it ends */
    uint32_t id;
} ang_ev;

/* A maximal interval [lo, hi] (hi may exceed pi: it wraps) of directions
** good for every reflex vertex. */
typedef struct run {
    double lo, hi;
} run;

static int cmp_ev(const void *x, const void *y) {
    const ang_ev *a = x, *b = y;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    /* closed arcs: a start before an end at the same angle */
    if (a->delta != b->delta) return a->delta > b->delta ? -1 : 1;
    return a->id < b->id ? -1 : a->id > b->id;
}

static int cmp_double(const void *x, const void *y) {
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}

/* widest first; ties by position (deterministic) */
static int cmp_run(const void *x, const void *y) {
    const run *a = x, *b = y;
    double wa = a->hi - a->lo, wb = b->hi - b->lo;
    if (wa != wb) return wa > wb ? -1 : 1;
    return a->lo < b->lo ? -1 : a->lo > b->lo;
}

static double mod_pi(double a) {
    a = fmod(a, PI);
    if (a < 0) a += PI;
    if (a >= PI) a -= PI;
    return a;
}

/* Direction perpendicular to vector u, as an angle modulo pi. */
static double perp_angle(wk_point u) { return mod_pi(atan2(u.y, u.x) + 0.5 * PI); }

static double proj(wk_point d, wk_point p) { return d.x * p.x + d.y * p.y; }

/* Does edge p -> q point within sine WK_PARALLEL_SIN of the perpendicular
** to d, or against d?  dx is its projection's change (the sense the chain
** needs: + lower, - upper).  Such an edge is a wall of the non-strict case
** (exactly perpendicular, or so up to rounding once turned), not 001's. */
static bool wall_or_back(wk_point p, wk_point q, double dx) {
    return dx <= WK_PARALLEL_SIN * hypot(q.x - p.x, q.y - p.y);
}

/* Is P monotone along d within tol (see the top: every vertex at most tol
** behind the vertices before it in its chain)?  On the computed
** projections.  Sets the chain ends *vw, *ve, *is_strict (no chain edge is
** a wall or goes back, wall_or_back) and *viol (the largest distance a
** vertex lies behind) and returns true if so. */
static bool check_direction(const mono *M, wk_point d, double tol, uint32_t *vw, uint32_t *ve,
                            bool *is_strict, double *viol) {
    uint32_t n = M->P->n;
    *viol = 0;
    uint32_t imin = 0, imax = 0;
    for (uint32_t i = 1; i < n; i++) {
        if (proj(d, wk_mono_vertex(M, i)) < proj(d, wk_mono_vertex(M, imin))) imin = i;
        if (proj(d, wk_mono_vertex(M, i)) > proj(d, wk_mono_vertex(M, imax))) imax = i;
    }
    double xmin = proj(d, wk_mono_vertex(M, imin)), xmax = proj(d, wk_mono_vertex(M, imax));
    if (!(xmax - xmin > 2 * tol)) return false; /* a sliver: no verdict (*viol = 0) */
    /* v_w: the last vertex (counter-clockwise) of the plateau of equal
    ** projections at imin; v_e: the first of the one at imax.  Then the
    ** lower chain v_w -> v_e starts and ends with an edge going east (a wall
    ** turned in doubles lands in either chain, by its rounding: both are
    ** right within tol). */
    uint32_t a = imin, b = imax, guard = 0;
    while (proj(d, wk_mono_vertex(M, (a + 1) % n)) == xmin && guard++ < n) a = (a + 1) % n;
    guard = 0;
    while (proj(d, wk_mono_vertex(M, (b + n - 1) % n)) == xmax && guard++ < n) b = (b + n - 1) % n;
    if (a == b) return false;
    bool any_flat = false;
    /* lower chain a -> b: no vertex more than tol west of the running
    ** maximum; upper chain b -> a: none more than tol east of the running
    ** minimum */
    double hi = xmin, lo = xmax;
    for (uint32_t i = a; i != b; i = (i + 1) % n) {
        wk_point p = wk_mono_vertex(M, i), q = wk_mono_vertex(M, (i + 1) % n);
        double x1 = proj(d, q);
        if (hi - x1 > *viol) *viol = hi - x1;
        if (wall_or_back(p, q, x1 - proj(d, p))) any_flat = true;
        if (x1 > hi) hi = x1;
    }
    for (uint32_t i = b; i != a; i = (i + 1) % n) {
        wk_point p = wk_mono_vertex(M, i), q = wk_mono_vertex(M, (i + 1) % n);
        double x1 = proj(d, q);
        if (x1 - lo > *viol) *viol = x1 - lo;
        if (wall_or_back(p, q, proj(d, p) - x1)) any_flat = true;
        if (x1 < lo) lo = x1;
    }
    if (*viol > tol) return false;
    *vw = a;
    *ve = b;
    *is_strict = !any_flat;
    return true;
}

/* The unit normal of edge e pointing along angle th (mod pi): exact axes for
** axis-parallel edges, so their projections are exact. */
static wk_point edge_normal(const wk_polygon *P, uint32_t e, double th) {
    wk_point a = P->p[e], b = P->p[(e + 1) % P->n];
    double ex = b.x - a.x, ey = b.y - a.y, len = hypot(ex, ey);
    wk_point d = {-ey / len, ex / len};
    if (ex == 0) d = (wk_point){1.0, 0.0};
    if (ey == 0) d = (wk_point){0.0, 1.0};
    if (d.x * cos(th) + d.y * sin(th) < 0) d.x = -d.x, d.y = -d.y;
    return d;
}

/* The edge whose perpendicular is nearest to angle th (mod pi). */
static uint32_t nearest_perp_edge(const wk_polygon *P, double th) {
    uint32_t be = 0;
    double bd = INFINITY;
    for (uint32_t e = 0; e < P->n; e++) {
        wk_point a = P->p[e], b = P->p[(e + 1) % P->n];
        double dd = fabs(perp_angle((wk_point){b.x - a.x, b.y - a.y}) - mod_pi(th));
        if (PI - dd < dd) dd = PI - dd;
        if (dd < bd) bd = dd, be = e;
    }
    return be;
}

/* Half-width, in radians, by which a good arc's end defined by neighbour
** offset u is widened: directions d with |d . u| <= 2 tol (both ends of an
** edge may move by tol, see the top); the whole half circle if |u| <= 2 tol. */
static double widen(wk_point u, double tol) {
    double l = hypot(u.x, u.y);
    return l > 2 * tol ? asin(2 * tol / l) : 0.5 * PI;
}

wk_status wk_mono_direction(mono *M) {
    wk_run *R = M->R;
    const wk_polygon *P = M->P;
    uint32_t n = P->n, r = 0, r_all = 0;
    wk_status st = WK_OK;
    const double tol = WK_MONO_DIR_TOL * M->eps_d;
    ang_ev *ev = WK_NEW_ARRAY(R, ang_ev, 2 * (size_t)n + 2);
    double *perp = WK_NEW_ARRAY(R, double, n + 2);
    run *runs = NULL;
    uint32_t n_runs = 0, cap_runs = 0;
    if (!ev || !perp) {
        st = R->err.code;
        goto done;
    }
    /* one good arc per reflex vertex, widened by the tolerance */
    uint32_t n_ev = 0, covering0 = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (!wk_polygon_is_reflex_counted(R, P, i)) continue;
        r_all++;
        wk_point pi = P->p[i], pp = P->p[(i + n - 1) % n], pn = P->p[(i + 1) % n];
        wk_point u1 = {pp.x - pi.x, pp.y - pi.y}, u2 = {pn.x - pi.x, pn.y - pi.y};
        double g1 = perp_angle(u1), g2 = perp_angle(u2);
        double len = mod_pi(g2 - g1), mid = g1 + 0.5 * len;
        wk_point dm = {cos(mid), sin(mid)};
        double start = g1;
        wk_point us = u1, ue = u2; /* the offsets whose perpendiculars end the arc */
        if (len < WK_MONO_DIR_FLAT_ARC || len > PI - WK_MONO_DIR_FLAT_ARC) {
            /* u1 and u2 (nearly) on one line: the midpoint test would be
            ** decided by rounding.  A nearly flat vertex (u1 . u2 < 0) is
            ** bad only for d nearly perpendicular to its edges: the long
            ** arc; a nearly 0-degree spike is good only there: the short. */
            bool flat = u1.x * u2.x + u1.y * u2.y < 0;
            bool first_long = len > 0.5 * PI;
            if (flat != first_long) {
                start = g2;
                len = PI - len;
                us = u2, ue = u1;
            }
        } else if (proj(dm, u1) * proj(dm, u2) > 0) { /* the other arc */
            start = g2;
            len = PI - len;
            us = u2, ue = u1;
        }
        double w0 = widen(us, tol), w1 = widen(ue, tol);
        if (len + w0 + w1 >= PI) continue; /* good in every direction within tol */
        r++;
        start = mod_pi(start - w0);
        len += w0 + w1;
        double end = start + len;
        ev[n_ev++] = (ang_ev){start, +1, i};
        if (end >= PI) {
            covering0++; /* wraps: covers angle 0 */
            ev[n_ev++] = (ang_ev){end - PI, -1, i};
        } else {
            ev[n_ev++] = (ang_ev){end, -1, i};
        }
    }
    /* the runs of directions covered by all r arcs */
    uint32_t top = 0;
    if (r == 0) {
        if (WK_GROW(R, runs, cap_runs, 1) != WK_OK) {
            st = R->err.code;
            goto done;
        }
        runs[n_runs++] = (run){0.0, PI};
    } else {
        qsort(ev, n_ev, sizeof *ev, cmp_ev);
        uint32_t count = covering0;
        top = covering0;
        double open_at = count == r ? 0.0 : -1.0; /* start of the current full run */
        double first_close = -1.0; /* end of a full run that began at 0 */
        for (uint32_t k = 0; k < n_ev; k++) {
            if (ev[k].delta > 0) {
                count++;
                if (count > top) top = count;
                if (count == r) open_at = ev[k].a;
            } else {
                if (count == r) {
                    double lo = open_at, hi = ev[k].a;
                    if (lo == 0.0 && first_close < 0 && covering0 == r) {
                        first_close = hi; /* joined to the run that reaches pi, below */
                    } else {
                        if (WK_GROW(R, runs, cap_runs, n_runs + 1) != WK_OK) {
                            st = R->err.code;
                            goto done;
                        }
                        runs[n_runs++] = (run){lo, hi};
                    }
                }
                count--;
            }
        }
        if (first_close >= 0 || (count == r && open_at >= 0)) {
            /* a run through angle 0: [open_at, pi + first_close] */
            double lo = count == r && open_at >= 0 ? open_at : PI;
            double hi = PI + (first_close >= 0 ? first_close : 0.0);
            if (WK_GROW(R, runs, cap_runs, n_runs + 1) != WK_OK) {
                st = R->err.code;
                goto done;
            }
            runs[n_runs++] = (run){lo, hi};
        }
        if (n_runs == 0) {
            st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                         "monotone: the polygon is not monotone in any direction (no direction "
                         "suits all %u reflex vertices at once, even within the tolerance "
                         "%.3g; at most %u do)",
                         r_all, tol, top + (r_all - r));
            goto done;
        }
    }
    qsort(runs, n_runs, sizeof *runs, cmp_run);
    /* Candidates, best first; the first strictly monotone one wins, else the
    ** first non-strict one. */
    bool have = false;
    wk_point d_ns = {1, 0};
    uint32_t vw_ns = 0, ve_ns = 0;
    /* for the refusal: the smallest violation seen in the current run, and
    ** whether every run tried failed by more than it can explain (below) */
    double run_viol = INFINITY;
    bool all_clear = n_runs <= MONO_DIR_RUNS_MAX;
#define TRY(D)                                                                  \
    do {                                                                        \
        wk_point d_ = (D);                                                      \
        uint32_t vw_, ve_;                                                      \
        bool strict_;                                                           \
        double v_;                                                              \
        if (check_direction(M, d_, tol, &vw_, &ve_, &strict_, &v_)) {           \
            if (strict_) {                                                      \
                M->d = d_, M->vw = vw_, M->ve = ve_, M->strict = true;          \
                goto done;                                                      \
            }                                                                   \
            if (!have) have = true, d_ns = d_, vw_ns = vw_, ve_ns = ve_;        \
        }                                                                       \
        if (v_ < run_viol) run_viol = v_;                                       \
    } while (0)
    /* A run's middle is inside it, so if P were monotone within tol in some
    ** direction of the run, the middle would leave no vertex more than
    ** tol + width * scale behind (turning d by an angle a moves each
    ** projection difference by at most a times the diameter): a violation
    ** beyond that (plus rounding) at every candidate of every run means P is
    ** clearly not monotone, and it is refused; else it goes to the
    ** reference (WK_EALGO). */
    const double scale = wk_polygon_scale(P);
#define RUN_DONE(W)                                                                   \
    do {                                                                              \
        if (!(run_viol > 2 * tol + (W) * scale)) all_clear = false;                   \
        run_viol = INFINITY;                                                          \
    } while (0)
    double best_lo = runs[0].lo, best_hi = runs[0].hi;
    if (best_hi - best_lo > WK_MONO_DIR_WIDE) {
        /* the widest gap between edge perpendiculars inside (lo, hi) */
        uint32_t k = 0;
        for (uint32_t e = 0; e < n; e++) {
            wk_point a = P->p[e], b = P->p[(e + 1) % n];
            double g = perp_angle((wk_point){b.x - a.x, b.y - a.y});
            if (g < best_lo) g += PI;
            if (g > best_lo && g < best_hi) perp[k++] = g;
        }
        qsort(perp, k, sizeof *perp, cmp_double);
        double prev = best_lo, glo = best_lo, ghi = best_lo;
        for (uint32_t j = 0; j <= k; j++) {
            double x = j < k ? perp[j] : best_hi;
            if (x - prev > ghi - glo) glo = prev, ghi = x;
            prev = x;
        }
        double th = 0.5 * (glo + ghi);
        TRY(((wk_point){cos(th), sin(th)}));
        RUN_DONE(best_hi - best_lo);
    }
    /* Narrow runs (single directions up to the tolerance: combs, rectilinear
    ** staircases, such polygons turned in doubles): the exact normal of the
    ** edge nearest in angle to the run's middle and to its ends (walls
    ** perpendicular to the sweep are plateaus there: exactly for
    ** axis-parallel edges, within tol for turned ones), then the middle
    ** itself (a narrow run of strict directions). */
    for (uint32_t c = 0; c < n_runs && c < MONO_DIR_RUNS_MAX; c++) {
        double th3[3] = {0.5 * (runs[c].lo + runs[c].hi), runs[c].lo, runs[c].hi};
        for (int j = 0; j < 3; j++) TRY(edge_normal(P, nearest_perp_edge(P, th3[j]), th3[j]));
        TRY(((wk_point){cos(th3[0]), sin(th3[0])}));
        RUN_DONE(runs[c].hi - runs[c].lo);
    }
#undef TRY
#undef RUN_DONE
    if (have) {
        M->d = d_ns, M->vw = vw_ns, M->ve = ve_ns, M->strict = false;
        goto done;
    }
    if (all_clear) {
        st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                     "monotone: the polygon is not monotone in any direction (the directions "
                     "that suit each of its %u reflex vertices leave other vertices farther "
                     "behind than the tolerance %.3g)",
                     r_all, tol);
        goto done;
    }
    st = WK_FAIL(R, WK_EALGO, P->name, 0,
                 "monotone: the polygon is monotone within the tolerance %.3g only in "
                 "directions (best range %.3g rad) where no direction checks out in doubles",
                 tol, best_hi - best_lo);
done:
    if (ev) WK_FREE_ARRAY(R, ev, 2 * (size_t)n + 2);
    if (perp) WK_FREE_ARRAY(R, perp, n + 2);
    if (runs) WK_FREE_ARRAY(R, runs, cap_runs);
    return st;
}

wk_status wk_mono_direction_reverse(mono *M) {
    wk_point d = {-M->d.x, -M->d.y};
    uint32_t vw, ve;
    bool strict;
    double viol;
    if (!check_direction(M, d, WK_MONO_DIR_TOL * M->eps_d, &vw, &ve, &strict, &viol))
        return WK_FAIL(M->R, WK_EALGO, M->P->name, 0,
                       "monotone: the reversed sweep direction does not check out");
    M->d = d, M->vw = vw, M->ve = ve, M->strict = strict, M->reversed = true;
    return WK_OK;
}
