/*
** direction.c: find a direction in which the polygon is monotone, or refuse.
**
** A simple polygon is monotone in direction d (every line perpendicular to d
** meets it in a connected set) iff no reflex vertex has both neighbours
** strictly on one side of the line through it perpendicular to d.  Directions
** are taken modulo pi (d and -d are the same sweep).  For a reflex vertex
** with neighbour offsets u1, u2 the good directions form one closed arc of
** the circle R / pi Z: between the two directions perpendicular to u1 and u2,
** on the side where d.u1 and d.u2 differ in sign; its length is the vertex's
** exterior angle (< pi).  The good set is the intersection of these r arcs,
** found by sorting their 2 r ends and sweeping once around the circle:
** O(n log n).
**
** Which good direction.  001's lemmas need strict monotonicity: no edge
** perpendicular to d.  If the good set has an interval wider than
** WIDE_ENOUGH, d is the middle of the widest gap, inside that interval,
** between directions perpendicular to any edge (sort again); the chains are
** then checked to be strictly monotone in the computed projections, so the
** choice never rests on the angles alone.  Otherwise the good set is made of
** single directions (a comb, a rectilinear staircase monotone in x only):
** each is perpendicular to some edge, d is taken as that edge's exact unit
** normal (exactly an axis for an axis-parallel edge, so projections are
** exact there), and monotonicity is checked on the projections with
** plateaus of equal projection (edges perpendicular to d) allowed.
**
** Chain ends.  v_w is the last vertex, counter-clockwise, of the westmost
** plateau and v_e the first of the eastmost one, so the lower chain (v_w to
** v_e) starts and ends with edges that go strictly east and any edge
** perpendicular to d at the extremes belongs to the upper chain.
*/
#include "monotone.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* An interval of good directions narrower than this (radians) is treated
** as a single direction: projections along a direction that close to an
** edge's perpendicular would decide that edge's orientation by rounding. */
#define WIDE_ENOUGH 1e-7

typedef struct ang_ev {
    double a;   /* angle in [0, pi) */
    int delta;  /* +1 an arc starts, -1 it ends */
    uint32_t id;
} ang_ev;

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

static double mod_pi(double a) {
    a = fmod(a, PI);
    if (a < 0) a += PI;
    if (a >= PI) a -= PI;
    return a;
}

/* Direction perpendicular to vector u, as an angle modulo pi. */
static double perp_angle(wk_point u) { return mod_pi(atan2(u.y, u.x) + 0.5 * PI); }

static double proj(wk_point d, wk_point p) { return d.x * p.x + d.y * p.y; }

/* Check monotonicity of P along d on the computed projections and find the
** chain ends.  strict: every edge must change the projection.  Returns true
** and sets *vw, *ve, *is_strict if P is monotone. */
static bool check_direction(const wk_polygon *P, wk_point d, bool strict, uint32_t *vw,
                            uint32_t *ve, bool *is_strict) {
    uint32_t n = P->n;
    /* sign of each edge's change; count the sign changes around the cycle,
    ** skipping zero edges (plateaus) */
    uint32_t imin = 0, imax = 0;
    for (uint32_t i = 1; i < n; i++) {
        if (proj(d, P->p[i]) < proj(d, P->p[imin])) imin = i;
        if (proj(d, P->p[i]) > proj(d, P->p[imax])) imax = i;
    }
    double xmin = proj(d, P->p[imin]), xmax = proj(d, P->p[imax]);
    if (!(xmax > xmin)) return false;
    /* v_w: walk forward from imin over the plateau; v_e: walk backward from
    ** imax to the plateau's first vertex */
    uint32_t a = imin, guard = 0;
    while (proj(d, P->p[(a + 1) % n]) == xmin && guard++ < n) a = (a + 1) % n;
    /* first vertex of the plateau containing imin must precede a; also the
    ** vertex before the plateau must be above it (else not the minimum) */
    uint32_t b = imax;
    guard = 0;
    while (proj(d, P->p[(b + n - 1) % n]) == xmax && guard++ < n) b = (b + n - 1) % n;
    bool any_zero = false;
    /* lower chain a -> b strictly increasing except plateaus (non-strict) */
    for (uint32_t i = a; i != b; i = (i + 1) % n) {
        double x0 = proj(d, P->p[i]), x1 = proj(d, P->p[(i + 1) % n]);
        if (x1 < x0) return false;
        if (x1 == x0) {
            if (strict) return false;
            any_zero = true;
        }
    }
    for (uint32_t i = b; i != a; i = (i + 1) % n) {
        double x0 = proj(d, P->p[i]), x1 = proj(d, P->p[(i + 1) % n]);
        if (x1 > x0) return false;
        if (x1 == x0) {
            if (strict) return false;
            any_zero = true;
        }
    }
    *vw = a;
    *ve = b;
    *is_strict = !any_zero;
    return true;
}

wk_status wk_mono_direction(mono *M) {
    wk_run *R = M->R;
    const wk_polygon *P = M->P;
    uint32_t n = P->n, r = 0;
    wk_status st = WK_OK;
    ang_ev *ev = WK_NEW_ARRAY(R, ang_ev, 2 * (size_t)n + 2);
    double *perp = WK_NEW_ARRAY(R, double, n + 2);
    double *cand = NULL;
    uint32_t n_cand = 0, cap_cand = 0;
    if (!ev || !perp) {
        st = R->err.code;
        goto done;
    }
    /* one good arc per reflex vertex */
    uint32_t n_ev = 0, covering0 = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (!wk_polygon_is_reflex_counted(R, P, i)) continue;
        r++;
        wk_point pi = P->p[i], pp = P->p[(i + n - 1) % n], pn = P->p[(i + 1) % n];
        wk_point u1 = {pp.x - pi.x, pp.y - pi.y}, u2 = {pn.x - pi.x, pn.y - pi.y};
        double g1 = perp_angle(u1), g2 = perp_angle(u2);
        double len = mod_pi(g2 - g1), mid = g1 + 0.5 * len;
        wk_point dm = {cos(mid), sin(mid)};
        double start = g1;
        if (len < 1e-6 || len > PI - 1e-6) {
            /* u1 and u2 (nearly) on one line: the midpoint test would be
            ** decided by rounding.  A nearly flat vertex (u1 . u2 < 0) is
            ** bad only for d nearly perpendicular to its edges: the long
            ** arc; a nearly 0-degree spike is good only there: the short. */
            bool flat = u1.x * u2.x + u1.y * u2.y < 0;
            bool first_long = len > 0.5 * PI;
            if (flat != first_long) {
                start = g2;
                len = PI - len;
            }
        } else if (proj(dm, u1) * proj(dm, u2) > 0) { /* the other arc */
            start = g2;
            len = PI - len;
        }
        double end = start + len;
        ev[n_ev++] = (ang_ev){start, +1, i};
        if (end >= PI) {
            covering0++; /* wraps: covers angle 0 */
            ev[n_ev++] = (ang_ev){end - PI, -1, i};
        } else {
            ev[n_ev++] = (ang_ev){end, -1, i};
        }
    }
    /* intervals covered by all r arcs: [lo, hi] */
    double best_lo = 0, best_hi = PI, best_w = -1;
    if (r == 0) {
        best_w = PI;
    } else {
        qsort(ev, n_ev, sizeof *ev, cmp_ev);
        uint32_t count = covering0, top = covering0;
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
                    if (lo == 0.0 && first_close < 0 && covering0 == r) first_close = hi;
                    if (hi - lo > best_w) best_w = hi - lo, best_lo = lo, best_hi = hi;
                    if (WK_GROW(R, cand, cap_cand, n_cand + 2) != WK_OK) {
                        st = R->err.code;
                        goto done;
                    }
                    cand[n_cand++] = lo;
                    cand[n_cand++] = hi;
                }
                count--;
            }
        }
        if (count == r && open_at >= 0) { /* a run reaching pi: joins the one from 0 */
            double lo = open_at, hi = PI + (first_close >= 0 ? first_close : 0.0);
            if (hi - lo > best_w) best_w = hi - lo, best_lo = lo, best_hi = hi;
        }
        if (best_w < 0) {
            st = WK_FAIL(R, WK_EUNSUPPORTED, P->name, 0,
                         "monotone: the polygon is not monotone in any direction (no direction "
                         "suits all %u reflex vertices at once; at most %u do)",
                         r, top);
            goto done;
        }
    }
    if (best_w > WIDE_ENOUGH) {
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
        M->d = (wk_point){cos(th), sin(th)};
        bool strict;
        if (check_direction(P, M->d, true, &M->vw, &M->ve, &strict)) {
            M->strict = true;
            goto done;
        }
        /* rounding disagreed with the angles: try the single directions */
    }
    /* Single good directions: each interval end is perpendicular to an edge;
    ** snap to the exact normal of the edge nearest in angle and check. */
    for (uint32_t c = 0; c < n_cand || (r == 0 && c == 0); c++) {
        double th = r == 0 ? 0.0 : cand[c];
        uint32_t be = 0;
        double bd = INFINITY;
        for (uint32_t e = 0; e < n; e++) {
            wk_point a = P->p[e], b = P->p[(e + 1) % n];
            double g = perp_angle((wk_point){b.x - a.x, b.y - a.y});
            double dd = fabs(g - th);
            if (PI - dd < dd) dd = PI - dd;
            if (dd < bd) bd = dd, be = e;
        }
        wk_point a = P->p[be], b = P->p[(be + 1) % n];
        double ex = b.x - a.x, ey = b.y - a.y, len = hypot(ex, ey);
        wk_point d = {-ey / len, ex / len};
        if (ex == 0) d = (wk_point){ey > 0 ? -1.0 : 1.0, 0.0};
        if (ey == 0) d = (wk_point){0.0, ex > 0 ? 1.0 : -1.0};
        for (int s = 0; s < 2; s++) {
            bool strict;
            if (check_direction(P, d, false, &M->vw, &M->ve, &strict)) {
                M->d = d;
                M->strict = strict;
                goto done;
            }
            d.x = -d.x, d.y = -d.y;
        }
    }
    st = WK_FAIL(R, WK_EALGO, P->name, 0,
                 "monotone: the polygon is monotone only in a range of directions too narrow "
                 "(%.3g rad) to decide with doubles",
                 best_w);
done:
    if (ev) WK_FREE_ARRAY(R, ev, 2 * (size_t)n + 2);
    if (perp) WK_FREE_ARRAY(R, perp, n + 2);
    if (cand) WK_FREE_ARRAY(R, cand, cap_cand);
    return st;
}
