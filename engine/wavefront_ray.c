/*
** wavefront_ray.c: static rays through the kinetic wavefront, for finders
** that follow a moving Steiner vertex along a segment (000's A(P)
** segments, 002's traces): where the ray o + lambda u meets an
** offset line or a piece at time t, the first piece it meets over a cycle,
** when a moving Steiner vertex leaves its piece, and the reference's split
** test on the pieces next to a vertex (contacts across sub-tolerance
** edges that no ray along the vertex's motion sees).  wavefront.h has the
** contracts; the tolerances are tolerance.h's WK_RAY_* and WK_ARR_*.
*/
#include "tolerance.h"
#include "wavefront.h"

#include <math.h>

double wk_wf_ray_on_line(wk_point o, wk_point u, const wk_offset_line *L, double t) {
    double den = L->nx * u.x + L->ny * u.y;
    if (fabs(den) < WK_ARR_PARALLEL) return NAN;
    return (L->c + L->w * t - (L->nx * o.x + L->ny * o.y)) / den;
}

double wk_wf_ray_hit_piece(const wk_wavefront *W, wk_point o, wk_point u, uint32_t a, double t,
                           double lambda0, double *mu) {
    uint32_t b = wk_wf_next(W, a);
    wk_point pa = wk_wf_position(W, a, t), pb = wk_wf_position(W, b, t);
    double dx = pb.x - pa.x, dy = pb.y - pa.y;
    double den = u.x * dy - u.y * dx;
    if (fabs(den) < WK_DIV_GUARD) return INFINITY;
    double ex = pa.x - o.x, ey = pa.y - o.y;
    double lam = (ex * dy - ey * dx) / den;
    *mu = (ex * u.y - ey * u.x) / den;
    if (*mu < -WK_RAY_PIECE_SLACK || *mu > 1 + WK_RAY_PIECE_SLACK ||
        lam <= lambda0 - wk_wf_eps_d(W) * WK_RAY_BEHIND_SLACK)
        return INFINITY;
    return lam;
}

/* The point a shot is restricted to (the reshoot below): a piece counts
** only if at time t0 it passes within r of x. */
typedef struct ray_near {
    wk_point x;
    double t0, r;
} ray_near;

static bool piece_near(const wk_wavefront *W, uint32_t a, const ray_near *n) {
    wk_point pa = wk_wf_position(W, a, n->t0), pb = wk_wf_position(W, wk_wf_next(W, a), n->t0);
    double dx = pb.x - pa.x, dy = pb.y - pa.y, ex = n->x.x - pa.x, ey = n->x.y - pa.y;
    double l2 = dx * dx + dy * dy, s = l2 > 0 ? (ex * dx + ey * dy) / l2 : 0;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    return hypot(ex - s * dx, ey - s * dy) <= n->r;
}

static void shoot_piece(const wk_wavefront *W, wk_point o, wk_point u, uint32_t v, uint32_t a,
                        double t, double lambda0, const ray_near *near, uint32_t *best, double *bl,
                        bool *at_end) {
    double mu;
    if (v != WK_NONE && (a == v || wk_wf_next(W, a) == v)) return; /* v's own pieces */
    double lam = wk_wf_ray_hit_piece(W, o, u, a, t, lambda0, &mu);
    if (lam < *bl && (!near || piece_near(W, a, near))) {
        *bl = lam;
        *best = a;
        *at_end = mu < WK_RAY_END_SNAP || mu > 1 - WK_RAY_END_SNAP;
    }
}

/* One shot at time t over v's cycle (every alive piece with holes). */
static uint32_t shoot_at(const wk_wavefront *W, wk_point o, wk_point u, uint32_t v, double t,
                         double lambda0, const ray_near *near, bool *at_end, double *bl_out) {
    uint32_t best = WK_NONE;
    double bl = INFINITY;
    if (wk_wf_polygon(W)->n_rings == 1 && v != WK_NONE) {
        for (uint32_t a = wk_wf_next(W, v); a != v; a = wk_wf_next(W, a))
            shoot_piece(W, o, u, v, a, t, lambda0, near, &best, &bl, at_end);
    } else {
        for (uint32_t a = 0; a < wk_wf_vertex_count(W); a++)
            if (wk_wf_alive(W, a)) shoot_piece(W, o, u, v, a, t, lambda0, near, &best, &bl, at_end);
    }
    if (bl_out) *bl_out = bl;
    return best;
}

/* The delay of a reshoot at a corner: WK_RAY_RESHOOT_DELAY * eps_t, unless
** v reaches the line of a piece at the hit corner within that delay (the
** line's crossing with the ray and v close in on each other): then
** WK_RAY_RESHOOT_GAP_SHARE of the time to that meeting, and never below
** eps_t.  Only those shots change: a reshoot after the meeting finds the
** piece behind v, never the one v meets.  eps_t * 1e3 is eps_d /
** wmax: with a vertex 5e10 away (eps_d 50, unit weights) that is 50 time
** units, and a reflex vertex whose ray passed a reflex corner at
** t = 15.2 was shot again at t = 65.4, after its own split of the corner's
** piece at t = 46.3: the hit was behind it, the whole cycle gave a piece
** beyond that v never meets, its split was lost and the run looped until
** "no progress" at t = 55.4 (exit 2; solved only at 16 times coarser
** tolerances, not as the reference: tests/data/fuzz/
** mismatch_arrangement_monotone48_far_5e10.wpoly, issue 11). */
static double reshoot_delay(const wk_wavefront *W, wk_point o, wk_point u, uint32_t v, uint32_t a,
                            double t, double lambda0, double bl) {
    double eps_t = wk_wf_eps_t(W), delay = WK_RAY_RESHOOT_DELAY * eps_t, cap = delay;
    wk_point vel = wk_wf_velocity(W, v);
    double rv = vel.x * u.x + vel.y * u.y;
    /* the corner: a's end nearer the hit, and the pieces on both sides */
    uint32_t b = wk_wf_next(W, a);
    wk_point pa = wk_wf_position(W, a, t), pb = wk_wf_position(W, b, t);
    wk_point x = {o.x + bl * u.x, o.y + bl * u.y};
    uint32_t c = hypot(pa.x - x.x, pa.y - x.y) <= hypot(pb.x - x.x, pb.y - x.y) ? a : b;
    uint32_t two[2] = {wk_wf_prev(W, c), c};
    for (int i = 0; i < 2; i++) {
        const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, two[i]));
        double l0 = wk_wf_ray_on_line(o, u, L, t), l1 = wk_wf_ray_on_line(o, u, L, t + 1);
        if (!isfinite(l0) || !isfinite(l1)) continue;
        double gap = l0 - lambda0, close = rv - (l1 - l0);
        if (!(gap > 0) || !(close > 0)) continue;
        double meet = gap / close;
        if (meet <= delay && WK_RAY_RESHOOT_GAP_SHARE * meet < cap) cap = WK_RAY_RESHOOT_GAP_SHARE * meet;
    }
    return cap > eps_t ? cap : eps_t;
}

uint32_t wk_wf_ray_shoot(const wk_wavefront *W, wk_point o, wk_point u, uint32_t v, double t,
                         double lambda0) {
    bool at_end = false;
    double bl;
    uint32_t a = shoot_at(W, o, u, v, t, lambda0, NULL, &at_end, &bl);
    if (a != WK_NONE && at_end && v != WK_NONE) {
        /* a hit at a vertex is ambiguous (the ray passes through a wavefront
        ** vertex right now): shoot again a moment later, when that vertex has
        ** moved off the ray.  Only the pieces at the hit point now (within
        ** WK_RAY_RESHOOT_NEAR * eps_d) count: the question is which of them
        ** the ray enters, and a fast vertex elsewhere may sweep its piece
        ** across the ray in the delay (tolerance.h) */
        double later = t + reshoot_delay(W, o, u, v, a, t, lambda0, bl);
        wk_point pv = wk_wf_position(W, v, later);
        double l1 = (pv.x - o.x) * u.x + (pv.y - o.y) * u.y;
        ray_near near = {{o.x + bl * u.x, o.y + bl * u.y}, t, WK_RAY_RESHOOT_NEAR * wk_wf_eps_d(W)};
        uint32_t b = shoot_at(W, o, u, v, later, l1, &near, &at_end, NULL);
        if (b == WK_NONE) b = shoot_at(W, o, u, v, later, l1, NULL, &at_end, NULL);
        if (b != WK_NONE) a = b;
    }
    return a;
}

void wk_wf_ray_exit(const wk_wavefront *W, wk_point o, wk_point u, uint32_t a, double now,
                    double l0, double l1, double *te, uint8_t *end) {
    uint32_t b = wk_wf_next(W, a);
    const wk_offset_line *L = wk_wf_line(W, wk_wf_edge_out(W, a));
    *te = INFINITY;
    wk_point f0 = {o.x + l0 * u.x, o.y + l0 * u.y};
    wk_point f1 = {o.x + l1 * u.x, o.y + l1 * u.y};
    wk_point a0 = wk_wf_position(W, a, now), a1 = wk_wf_position(W, a, now + 1);
    wk_point b0 = wk_wf_position(W, b, now), b1 = wk_wf_position(W, b, now + 1);
    double sa0 = (f0.x - a0.x) * L->ux + (f0.y - a0.y) * L->uy;
    double sa1 = (f1.x - a1.x) * L->ux + (f1.y - a1.y) * L->uy;
    double sb0 = (b0.x - f0.x) * L->ux + (b0.y - f0.y) * L->uy;
    double sb1 = (b1.x - f1.x) * L->ux + (b1.y - f1.y) * L->uy;
    double ra = sa1 - sa0, rb = sb1 - sb0;
    /* riding along with an end vertex (that vertex moves on the ray itself:
    ** head-on reflex vertices) never leaves the piece */
    double tiny = WK_RIDE_ALONG_REL * (fabs(l1 - l0) + L->w);
    if (ra < -tiny) {
        double t = now + (sa0 > 0 ? sa0 : 0) / -ra;
        if (t < *te) *te = t, *end = 0;
    }
    if (rb < -tiny) {
        double t = now + (sb0 > 0 ? sb0 : 0) / -rb;
        if (t < *te) *te = t, *end = 1;
    }
}

void wk_wf_near_split(wk_wavefront *W, uint32_t v) {
    double t = wk_wf_now(W), near = WK_ARR_NEAR_SLACK * wk_wf_eps_d(W);
    wk_point pv = wk_wf_position(W, v, t);
    wk_wf_split_search s;
    wk_wf_split_begin(W, v, &s);
    for (uint32_t a = wk_wf_next(W, v); a != v && wk_wf_next(W, a) != v; a = wk_wf_next(W, a)) {
        wk_wf_split_test(W, &s, a);
        wk_point pa = wk_wf_position(W, a, t);
        if (!(hypot(pa.x - pv.x, pa.y - pv.y) <= near)) break;
    }
    for (uint32_t b = wk_wf_prev(W, v); b != v && wk_wf_prev(W, b) != v; b = wk_wf_prev(W, b)) {
        wk_wf_split_test(W, &s, wk_wf_prev(W, b));
        wk_point pb = wk_wf_position(W, b, t);
        if (!(hypot(pb.x - pv.x, pb.y - pv.y) <= near)) break;
    }
    wk_wf_split_offer(W, &s);
}
