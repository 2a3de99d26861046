/*
** wavefront_group.c: the resolution of a group of simultaneous events (the
** heart of the reference; see wavefront.c for the model).  All events
** within the time tolerance of the earliest one form a group.  The group is
** resolved by geometry, not by event type, which makes every degenerate
** combination (multi-split, vanishing triangles and components, parallel
** edges meeting, several events at one point) one code path; plan() runs
** these steps, one function each:
**   1. nodes: cluster the event points (distance tolerance) and collect the
**      vertices that take part (plan_nodes);
**   2. every vertex of the touched cycles within tolerance of a node arrives
**      there (plan_arrivals), unless shielded from it: across a gap between
**      rings (plan_shields; two splits that cut both pieces of one vertex
**      get a node each), as a bystander of such a node (bystander) or by a
**      stretch that collapses later (plan_slow_stretches); every piece
**      passing through a node is cut there (plan_pinches, plan_seed_cuts);
**   3. the cycles become directed sub-pieces between points (nodes or
**      untouched vertices); zero-length sub-pieces vanish (edge events);
**      two opposite sub-pieces between the same two nodes cancel and leave a
**      skeleton arc (parallel edges that met) (plan_sub_pieces, plan_cancel);
**   4. at each node the remaining incoming and outgoing sub-pieces are
**      paired: an incoming one continues with the first outgoing one
**      clockwise from it (the wavefront interior lies in that sector), and
**      each pair becomes a new wavefront vertex (plan_slots, plan_pairs);
**   5. a vertex that meets the group without being at a node (a zero-area
**      triangle, a vertex on a cancelled stretch, overlapping antiparallel
**      pieces, a zero-width spike) is made a node and the group is planned
**      again (plan_force_touching, plan_force_overlaps, plan_pairs).
** commit() then turns the plan into skeleton nodes, arcs and new vertices.
** Collinear edges of different weight that become adjacent cannot share a
** moving vertex (000, section 1): the losing edge (higher weight by default,
** lower with --collinear higher) is removed at once, leaving an arc along it
** at the current time, and its far neighbour is joined to the winner
** (wf_collinear_rule).
**
** Tolerances: WK_TOL_REL times the polygon's scale for distances, divided by
** the largest weight for times (wskel.h).
*/
#include "wavefront_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ clusters */

/* The nearest node within r of p, WK_NONE if there is none.  Nearest, not
** the first found: a fast vertex's radius spans several nodes of the group
** (a vertex of speed 2e6 covers 18 units in eps_t), and the node it really
** reaches is the one closest to where it is.  Taking the first (in cluster
** order) sent the tip of a needle 1e6 long to the node of a split 5 units
** ahead of it, not to the collapse of its own triangle 2.5 units ahead: the
** plan failed at eps_d, and 4 eps_d gave a valid skeleton with unit-sized
** features resolved at t = 0
** (the fuzz findings integer_needles_a and _b,
** tests/data/degenerate/needle_tip_nearest_node.wpoly). */
/* A group of at least WF_GRID_MIN seeds and forced vertices looks its
** nodes up in a grid (point_grid.h, W->cg) instead of scanning them: a
** group of k events at k places (the comb's teeth, all at once) cost
** O(k^2) in the scans of plan_arrivals, plan_pinches and
** plan_force_touching.  The lookups return the candidates increasing, and
** every node a scan's test could accept is a candidate (the box is widened
** by tolerance.h's WK_GRID_*), so the loops below see the scan's
** sequence minus nodes that fail the test: the same plan.  Below that size
** the scans are cheaper than the grid. */
enum { WF_GRID_MIN = 64 };

/* The grid for this plan's nodes: cells about the spacing of its points
** (the seeds' event points and the forced vertices). */
static wk_status start_node_grid(wk_wavefront *W, double t) {
    W->cg_on = W->vg_on = false;
    uint32_t n = W->n_seeds + W->n_forced;
    if (n < WF_GRID_MIN) return WK_OK;
    wk_point lo = {INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY};
    for (uint32_t i = 0; i < n; i++) {
        wk_point p = i < W->n_seeds ? W->v[W->seeds[i]].ev_p
                                    : wk_wf_pos(&W->v[W->forced[i - W->n_seeds]], t);
        lo.x = fmin(lo.x, p.x);
        lo.y = fmin(lo.y, p.y);
        hi.x = fmax(hi.x, p.x);
        hi.y = fmax(hi.y, p.y);
    }
    double wx = hi.x - lo.x, wy = hi.y - lo.y;
    double h = fmax(fmax((wx + wy) / n, sqrt(wx * wy / n)), 4 * W->eps_gmax);
    if (!isfinite(h) || !isfinite(lo.x) || !isfinite(lo.y)) return WK_OK;
    if (wk_point_grid_reset(W->R, &W->cg, lo.x, lo.y, h) != WK_OK) return W->R->err.code;
    W->cg_on = true;
    return WK_OK;
}

/* Box [lo, hi] widened by r and the grid's margins (tolerance.h). */
static void widen(wk_point *lo, wk_point *hi, double r) {
    double m = r * (1 + WK_GRID_WIDEN) +
               WK_GRID_ULPS * DBL_EPSILON * (fabs(lo->x) + fabs(lo->y) + fabs(hi->x) + fabs(hi->y));
    lo->x -= m;
    lo->y -= m;
    hi->x += m;
    hi->y += m;
}

/* The nodes that may lie within r of box [lo, hi]: true with them in
** W->cg.out[0 .. n_out), increasing; false: every node may (scan). */
static bool near_nodes(wk_wavefront *W, wk_point lo, wk_point hi, double r) {
    if (!W->cg_on) return false;
    widen(&lo, &hi, r);
    return wk_point_grid_query(&W->cg, lo, hi, (uint64_t)W->n_cl + 16);
}

/* The box of the points q with s in [-e, len + e] and |off| <= e in the
** frame of line L from pa (plan_pinches' and local_walk_suffices' band). */
static void band_box(wk_point pa, const wk_offset_line *L, double len, double e, wk_point *lo,
                     wk_point *hi) {
    double x1 = pa.x - e * L->ux, x2 = pa.x + (len + e) * L->ux;
    double y1 = pa.y - e * L->uy, y2 = pa.y + (len + e) * L->uy;
    lo->x = fmin(x1, x2) - e * fabs(L->nx);
    hi->x = fmax(x1, x2) + e * fabs(L->nx);
    lo->y = fmin(y1, y2) - e * fabs(L->ny);
    hi->y = fmax(y1, y2) + e * fabs(L->ny);
}

/* The radius within which a vertex that covers `travel` in the group's
** time span arrives at a node of radius r: r and its travel, scaled as the
** node radius is to eps_d (a coarser node takes in proportionally more). */
static double arrival_radius(const wk_wavefront *W, double r, double travel) {
    return r + travel * (r / W->eps_d);
}

/* The node radius of a node made at p: eps_g, or the radius of a wide spot
** that covers p (the largest if several; wf_resolve_group). */
static double node_radius_at(const wk_wavefront *W, wk_point p) {
    double r = W->eps_g;
    for (uint32_t i = 0; i < W->n_wide; i++)
        if (W->wide[i].r > r && wf_dist2(p, W->wide[i].p) <= W->wide[i].r * W->wide[i].r) r = W->wide[i].r;
    return r;
}

/* The nearest node within r of p, WK_NONE if there is none.  Nearest, not
** the first found: a fast vertex's radius spans several nodes of the group
** (a vertex of speed 2e6 covers 18 units in eps_t), and the node it really
** reaches is the one closest to where it is.  Taking the first (in cluster
** order) sent the tip of a needle 1e6 long to the node of a split 5 units
** ahead of it, not to the collapse of its own triangle 2.5 units ahead: the
** plan failed at eps_d, and 4 eps_d gave a valid skeleton with unit-sized
** features resolved at t = 0
** (the fuzz findings integer_needles_a and _b,
** tests/data/degenerate/needle_tip_nearest_node.wpoly).  Ties: the last.
** The radius is node k's, arrival_radius(W, W->cl[k].r, travel). */
static uint32_t find_cluster_within(wk_wavefront *W, wk_point p, double travel) {
    double best = INFINITY;
    uint32_t k_best = WK_NONE;
    bool listed = near_nodes(W, p, p, arrival_radius(W, W->eps_gmax, travel));
    uint32_t n = listed ? W->cg.n_out : W->n_cl;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = listed ? W->cg.out[i] : i;
        double d2 = wf_dist2(W->cl[k].p, p), r = arrival_radius(W, W->cl[k].r, travel);
        if (d2 <= r * r && d2 <= best) {
            best = d2;
            k_best = k;
        }
    }
    return k_best;
}

/* The node within r of p (a vertex's place at the group's time t) that
** the vertex, moving at vel, passes nearest over the group's time span
** (t .. t + dt; plan_arrivals calls it for a vertex moving more than eps_g
** in it, find_cluster_within otherwise): a vertex
** that moves more than eps_g in that span is judged by its track, not by
** its place at t.  Candidates are the same as find_cluster_within's; the
** distance of node q is |q - c| for the point c of the track
** p + vel h, h in [0, dt], nearest to q; distances within eps_g of each
** other count as equal, and then the node reached first (smaller h) wins:
** the needle tip above has both nodes on its track and must stop at the
** first, the collapse of its own triangle (needle_tip_nearest_node.wpoly
** still passes); a node behind p (the vertex left it) comes after every
** node ahead (see the weighted H below).  Nearest to p picked the wrong node for a
** spike vertex of speed 1.6e8 (a weighted comb with one vertex 2.5e9
** away): at t it was 220 units beside an edge event's node and 510 units
** before the node of its own collapse, which it reached at the end of the
** span (3.2e-6 later); sent to the edge event, the skeleton closed a cycle
** (exit 3; the six comb_spike files of tests/data/fuzz). */
/* True if node q lies behind one of vertex u's own offset lines at t by
** more than the rounding of its place (WK_BEHIND_ULPS ulps of its
** coordinates): u's track runs along the front of both lines, so such a
** node lies across the outside of u's corner, not on the way of u, however
** near the track passes it.  find_cluster_on_track skips it (nominal and
** finer tolerances only, as its 2 eps_g rule).  A 12-gon H near (1e6, 1e6)
** with a vertex pulled to x = 5e11 (eps_d 500): at t = 0 the tip of the
** left bar's sliver (speed 2e6, up the bar to the bar's top node at
** t = 0.5) passed 3 units beside the node of the right bar's foot, across
** the gap between the bars and behind its own edge 1; taken there (reached
** first), it joined the two feet across the outside and the arcs closed a
** cycle (exit 3 in four variants with --check, CGAL valid;
** tests/data/fuzz/invalid_naive_h_far_tip_across_gap.wpoly). */
static bool behind_own_line(const wk_wavefront *W, const wk_wf_vertex *u, wk_point q, double t) {
    double bar = WK_BEHIND_ULPS * DBL_EPSILON * (fabs(q.x) + fabs(q.y));
    return wk_offset_distance(&W->L[u->ein], q, t) < -bar || wk_offset_distance(&W->L[u->eout], q, t) < -bar;
}

static uint32_t find_cluster_on_track(wk_wavefront *W, const wk_wf_vertex *u, double t, double dt,
                                      double travel) {
    wk_point p = wk_wf_pos(u, t), vel = u->vel;
    double best_d = INFINITY, best_h = INFINITY, best_a = INFINITY;
    double v2 = vel.x * vel.x + vel.y * vel.y;
    uint32_t k_best = WK_NONE;
    bool listed = near_nodes(W, p, p, arrival_radius(W, W->eps_gmax, travel));
    uint32_t n = listed ? W->cg.n_out : W->n_cl;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = listed ? W->cg.out[i] : i;
        wk_point q = W->cl[k].p;
        double a2 = wf_dist2(q, p), r = arrival_radius(W, W->cl[k].r, travel), e = W->cl[k].r;
        if (a2 > r * r) continue;
        double h = v2 > 0 ? ((q.x - p.x) * vel.x + (q.y - p.y) * vel.y) / v2 : 0;
        bool behind = h < 0; /* the vertex left the node, moves away from it */
        h = fmin(fmax(h, 0), dt);
        wk_point c = {p.x + vel.x * h, p.y + vel.y * h};
        double d = sqrt(wf_dist2(q, c));
        /* the track passes within the reach of find_cluster_within for a
        ** vertex that moves eps_g in the span (eps_g and its travel):
        ** within r of p alone, a node beside the track took the vertex
        ** sideways.  A 12-gon H with needles near (1e6, 1e6) and a vertex
        ** at y = 1e8 (eps_d 0.1): the vertex between edges 8 and 2 (speed
        ** 2e6, in a group spanning 1.1e-6: r = 2.2) arrived at an edge
        ** event's node 1.0 beside its track, 1.5 from its place; its arc
        ** went there and closed a cycle with the arcs of the needle it
        ** passes (exit 3 in all 5 variants;
        ** tests/data/fuzz/invalid_naive_h_needles_track_beside.wpoly).
        ** CGAL's vertex passes that node by.  At the nominal and finer
        ** tolerances only (W->input_sides), as the input-side rules: a
        ** coarse retry of wk_solve_checked took the 7-gon with spikes to
        ** 2e14 (invalid_naive_7gon_spikes_2e14.wpoly) to a node 3 eps_g
        ** behind a vertex of speed 1.25e8, and only that picture is
        ** valid there. */
        if (W->input_sides && d > 2 * e) continue;
        if (W->input_sides && behind_own_line(W, u, q, t)) continue;
        /* Among nodes equally near the track (within eps_g), one the vertex
        ** reaches (ahead of it, nearest along the track first) wins over one
        ** it has left behind (nearest of those if there is no other); a node
        ** behind, clamped to h = 0, counted as reached first.  A weighted
        ** 12-gon H near (1e6, 1e6) with a vertex at 1e13 (eps_d 1e4, eps_t
        ** 1.1: one group from t = 7e-7 to 0.4 takes the whole H) and edge 2
        ** of weight 9.04: the tip of the sliver between edges 11 and 0 (speed
        ** 2e8, 143 below its input vertex) went to the node of edges 8..10
        ** 148 behind it across the crack, not to its own collapse at the H's
        ** bottom node 1e6 ahead; the sliver became an arc between the top
        ** and bottom nodes beside edge 10's piece, whose collapse at t = 0.1
        ** closed a cycle at every rung of the tolerance ladder (exit 3 in 4
        ** variants; tests/data/fuzz/invalid_naive_h_weight9_sliver_cycle.wpoly). */
        double hk = behind ? -1 : h;
        bool better = d < best_d - e;
        if (!better && d <= best_d + e)
            better = best_h < 0 ? hk >= 0 || a2 <= best_a
                                : hk >= 0 && (hk < best_h || (hk == best_h && a2 <= best_a));
        if (better) {
            best_d = d;
            best_h = hk;
            best_a = a2;
            k_best = k;
        }
    }
    return k_best;
}

/* The first node within node radius of p (the node's, or a node made at p
** would have), WK_NONE if there is none. */
static uint32_t find_cluster(wk_wavefront *W, wk_point p) {
    double rp = W->n_wide ? node_radius_at(W, p) : W->eps_g;
    bool listed = near_nodes(W, p, p, W->eps_gmax);
    uint32_t n = listed ? W->cg.n_out : W->n_cl;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = listed ? W->cg.out[i] : i;
        double e = fmax(W->cl[k].r, rp);
        if (wf_dist2(W->cl[k].p, p) <= e * e) return k;
    }
    return WK_NONE;
}

/* A new node at p (own: the seed it belongs to alone, or WK_NONE). */
static wk_status new_cluster(wk_wavefront *W, wk_point p, uint32_t own, uint32_t *k) {
    if (WK_GROW(W->R, W->cl, W->cap_cl, W->n_cl + 1) != WK_OK) return W->R->err.code;
    W->cl[W->n_cl] = (wk_wf_cluster){p, WK_NONE, 0, 0, 0, 0, 0, 0, own, node_radius_at(W, p)};
    *k = W->n_cl++;
    if (own != WK_NONE) W->n_own++;
    if (W->cg_on && wk_point_grid_add(W->R, &W->cg, *k, p) != WK_OK) return W->R->err.code;
    return WK_OK;
}

static wk_status add_cluster(wk_wavefront *W, wk_point p, uint32_t *k) {
    *k = find_cluster(W, p);
    if (*k != WK_NONE) return WK_OK;
    return new_cluster(W, p, WK_NONE, k);
}

/* The node seed s has to itself (plan_shields), or WK_NONE. */
static uint32_t own_node(const wk_wavefront *W, uint32_t s) {
    for (uint32_t k = 0; W->n_own && k < W->n_cl; k++)
        if (W->cl[k].own == s) return k;
    return WK_NONE;
}

/* The node of seed s: its own or the node at its event point. */
static uint32_t seed_node(wk_wavefront *W, uint32_t s) {
    uint32_t k = own_node(W, s);
    return k != WK_NONE ? k : find_cluster(W, W->v[s].ev_p);
}

/* ----------------------------------------------------------- collect */

static double angle_of(const wk_offset_line *L, bool incoming) {
    return incoming ? atan2(-L->uy, -L->ux) : atan2(L->uy, L->ux);
}

/* Clockwise turn from angle a to angle b in (0, 2 pi]. */
static double cw_turn(double a, double b) {
    double d = a - b;
    while (d <= WK_ANGLE_WRAP) d += TWO_PI;
    while (d > TWO_PI + WK_ANGLE_WRAP) d -= TWO_PI;
    return d;
}

bool wf_split_changes_nothing(const wk_wavefront *W, uint32_t ein, uint32_t eout, uint32_t e) {
    double a = angle_of(&W->L[ein], true), b = angle_of(&W->L[e], true);
    double to_eout = angle_of(&W->L[eout], false), to_e = angle_of(&W->L[e], false);
    return cw_turn(a, to_eout) < cw_turn(a, to_e) || cw_turn(b, to_e) < cw_turn(b, to_eout);
}

static wk_point point_pos(const wk_wavefront *W, uint32_t pt, double t) {
    return IS_NODE(pt) ? W->cl[NODE_OF(pt)].p : wk_wf_pos(&W->v[pt], t);
}

static int cmp_pinch(const void *a, const void *b) {
    const wk_wf_pinch *x = a, *y = b;
    if (x->piece != y->piece) return x->piece < y->piece ? -1 : 1;
    if (x->s != y->s) return x->s < y->s ? -1 : 1;
    return x->node < y->node ? -1 : x->node > y->node;
}

/* Walk the cycles of the seeds (and forced vertices) into W->comp. */
static wk_status push_local(wk_wavefront *W, uint32_t u) {
    if (W->v[u].seen == W->stamp) return WK_OK;
    W->v[u].seen = W->stamp;
    W->v[u].at = WK_NONE;
    W->v[u].cyc = WK_NONE;
    return wf_push_u32(W->R, &W->comp, &W->n_comp, &W->cap_comp, u);
}

/* A group of a few events touches a handful of vertices, not their whole
** cycles: each seed, the target piece of a split, and LOCAL_REACH
** neighbours on each side of them.  Walking whole cycles for each event
** made a big convex wavefront quadratic (a 100,000-gon: 10^10 steps), and
** so did groups of two events (the halves of a symmetric feature, the two
** traces of a vertex event) on a fractal coastline.  Groups with forced
** vertices are degenerate and walk whole cycles.
** Cycle ids: a cycle the walks cover completely gets its own id (1, 2, ..:
** it may vanish in this group); the open stretches of longer cycles share
** id 0, which counts as alive (it may even hold no vertex). */
#define LOCAL_REACH 3
static wk_status collect_local(wk_wavefront *W) {
    W->stamp++;
    W->n_comp = 0;
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        const wk_wf_vertex *S = &W->v[W->seeds[i]];
        uint32_t centres[3] = {W->seeds[i], WK_NONE, WK_NONE};
        if (S->ev_kind == WK_WF_SPLIT) {
            centres[1] = S->ev_a;
            centres[2] = S->ev_b;
        }
        for (int c = 0; c < 3; c++) {
            if (centres[c] == WK_NONE || !W->v[centres[c]].alive) continue;
            uint32_t a = centres[c], b = centres[c];
            if (push_local(W, a) != WK_OK) return W->R->err.code;
            for (int k = 0; k < LOCAL_REACH; k++) {
                a = W->v[a].prev;
                b = W->v[b].next;
                if (push_local(W, a) != WK_OK || push_local(W, b) != WK_OK) return W->R->err.code;
            }
        }
    }
    /* open stretches (their first vertex's prev is outside): id 0 */
    for (uint32_t i = 0; i < W->n_comp; i++) {
        uint32_t h = W->comp[i];
        if (W->v[W->v[h].prev].seen == W->stamp) continue;
        for (uint32_t u = h; W->v[u].seen == W->stamp && W->v[u].cyc == WK_NONE; u = W->v[u].next)
            W->v[u].cyc = 0;
    }
    /* the rest lies on cycles the walks cover completely */
    W->n_cyc = 1;
    for (uint32_t i = 0; i < W->n_comp; i++) {
        uint32_t h = W->comp[i];
        if (W->v[h].cyc != WK_NONE) continue;
        for (uint32_t u = h; W->v[u].cyc == WK_NONE; u = W->v[u].next) W->v[u].cyc = W->n_cyc;
        W->n_cyc++;
    }
    /* the vertices just outside take part as untouched ends of pieces */
    for (uint32_t i = 0, n = W->n_comp; i < n; i++) {
        uint32_t c = W->comp[i];
        if (W->v[W->v[c].next].seen != W->stamp) W->v[W->v[c].next].at = WK_NONE;
        if (W->v[W->v[c].prev].seen != W->stamp) W->v[W->v[c].prev].at = WK_NONE;
    }
    return WK_OK;
}

static wk_status collect_cycles(wk_wavefront *W) {
    W->stamp++;
    W->n_comp = 0;
    W->n_cyc = 0;
    /* pass 0: the seeds' cycles; 1: the forced vertices'; 2: the cycles of
    ** the split seeds' target pieces (with holes a split may join two
    ** cycles, and the target's cycle need hold no seed) */
    for (int pass = 0; pass < 3; pass++) {
        uint32_t n = pass == 1 ? W->n_forced : W->n_seeds;
        const uint32_t *src = pass == 1 ? W->forced : W->seeds;
        for (uint32_t i = 0; i < n; i++) {
            uint32_t s = src[i];
            if (pass == 2) {
                const wk_wf_vertex *S = &W->v[s];
                if (S->ev_kind != WK_WF_SPLIT || S->ev_a == WK_NONE || !W->v[S->ev_a].alive)
                    continue;
                s = S->ev_a;
            }
            if (W->v[s].seen == W->stamp) continue;
            uint32_t u = s;
            do {
                W->v[u].seen = W->stamp;
                W->v[u].at = WK_NONE;
                W->v[u].cyc = W->n_cyc;
                if (wf_push_u32(W->R, &W->comp, &W->n_comp, &W->cap_comp, u) != WK_OK)
                    return W->R->err.code;
                u = W->v[u].next;
            } while (u != s);
            W->n_cyc++;
        }
    }
    return WK_OK;
}

static wk_status add_sub(wk_wavefront *W, uint32_t from, uint32_t to, uint32_t edge) {
    if (from == to) return WK_OK; /* zero length: this piece collapsed */
    if (WK_GROW(W->R, W->sub, W->cap_sub, W->n_sub + 1) != WK_OK) return W->R->err.code;
    W->sub[W->n_sub++] = (wk_wf_sub){from, to, edge, WK_NONE, WK_NONE, 0};
    return WK_OK;
}

/* Order sub-pieces by their unordered pair of end points. */
static int cmp_sub_key(const wk_wavefront *W, uint32_t i, uint32_t j) {
    const wk_wf_sub *a = &W->sub[i], *b = &W->sub[j];
    uint32_t a0 = a->from < a->to ? a->from : a->to, a1 = a->from ^ a->to ^ a0;
    uint32_t b0 = b->from < b->to ? b->from : b->to, b1 = b->from ^ b->to ^ b0;
    if (a0 != b0) return a0 < b0 ? -1 : 1;
    if (a1 != b1) return a1 < b1 ? -1 : 1;
    return 0;
}

/* Heap sort of sub-piece ids by end points, ids breaking ties (qsort has
** no context argument and the order must be deterministic). */
static bool sub_less(const wk_wavefront *W, uint32_t i, uint32_t j) {
    int c = cmp_sub_key(W, i, j);
    return c ? c < 0 : i < j;
}
static void sift(const wk_wavefront *W, uint32_t *a, uint32_t i, uint32_t n) {
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= n) return;
        if (c + 1 < n && sub_less(W, a[c], a[c + 1])) c++;
        if (!sub_less(W, a[i], a[c])) return;
        uint32_t x = a[i];
        a[i] = a[c];
        a[c] = x;
        i = c;
    }
}
static void sort_by_endpoints(const wk_wavefront *W, uint32_t *a, uint32_t n) {
    for (uint32_t i = n / 2; i-- > 0;) sift(W, a, i, n);
    for (uint32_t m = n; m > 1; m--) {
        uint32_t x = a[0];
        a[0] = a[m - 1];
        a[m - 1] = x;
        sift(W, a, 0, m - 1);
    }
}


/* ---------------------------------------------------------------- plan */

/* The node a forced vertex f runs into within the simultaneity horizon:
** the first node (smallest h) whose distance to f's track p + vel h,
** 0 < h <= eps_t, is at most eps_g while f itself is farther than eps_g
** from it now (WK_NONE if none).  Such a vertex is the tip of a
** sub-tolerance spike collapsing along itself: it arrives at that node,
** not at a node of its own where it is.  A 12-gon H with needles near
** (1e6, 1e6): at t = 0.94 reflex vertex 7 split edge 0 next to the
** vertex between edges 0 and 2; the vertex between edges 2 and 6 (speed
** 4.2e4), 0.43 up a needle 2e-5 wide, became a spike tip and a node of
** its own, 1e-5 (in time) before it reached the split's node (CGAL's
** node there); the arcs 0.43 off closed a cycle (exit 3 in 4 variants;
** tests/data/fuzz/invalid_naive_h_needles_fold.wpoly). */
static uint32_t track_node_ahead(wk_wavefront *W, uint32_t f, double t) {
    const wk_wf_vertex *F = &W->v[f];
    wk_point p = wk_wf_pos(F, t), vel = F->vel;
    double v2 = vel.x * vel.x + vel.y * vel.y, best_h = INFINITY;
    if (!(v2 > 0)) return WK_NONE;
    wk_point e = {p.x + vel.x * W->eps_t, p.y + vel.y * W->eps_t};
    wk_point lo = {fmin(p.x, e.x), fmin(p.y, e.y)}, hi = {fmax(p.x, e.x), fmax(p.y, e.y)};
    bool listed = near_nodes(W, lo, hi, W->eps_gmax);
    uint32_t n = listed ? W->cg.n_out : W->n_cl, k_best = WK_NONE;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = listed ? W->cg.out[i] : i;
        wk_point q = W->cl[k].p;
        double e2 = W->cl[k].r * W->cl[k].r;
        if (wf_dist2(q, p) <= e2) continue;
        double h = ((q.x - p.x) * vel.x + (q.y - p.y) * vel.y) / v2;
        if (!(h > 0) || h > W->eps_t) continue;
        wk_point c = {p.x + vel.x * h, p.y + vel.y * h};
        if (wf_dist2(q, c) <= e2 && h < best_h) {
            best_h = h;
            k_best = k;
        }
    }
    return k_best;
}

/* True if vertex f passed within r (the node radius of node q) of point q
** at some moment of the last eps_t (its track p + vel h, h in
** [max(t0, t - eps_t) - t, 0]): it left q no longer ago than the time
** tolerance. */
static bool left_node_lately(const wk_wavefront *W, uint32_t f, wk_point q, double r, double t) {
    const wk_wf_vertex *F = &W->v[f];
    wk_point p = wk_wf_pos(F, t), vel = F->vel;
    double v2 = vel.x * vel.x + vel.y * vel.y, h_min = fmin(fmax(F->t0, t - W->eps_t) - t, 0);
    double h = v2 > 0 ? ((q.x - p.x) * vel.x + (q.y - p.y) * vel.y) / v2 : 0;
    h = fmin(fmax(h, h_min), 0);
    wk_point c = {p.x + vel.x * h, p.y + vel.y * h};
    return wf_dist2(q, c) <= r * r;
}

static bool is_swept(const wk_wavefront *W, uint32_t u) {
    for (uint32_t i = 0; i < W->n_swept; i++)
        if (W->swept[i] == u) return true;
    return false;
}

/* The node forced vertex f arrives at instead of a node of its own: for a
** crack tip of plan_force_touching (W->swept) the one it left within eps_t
** (farther than eps_g now), the latest if several, even when a node lies
** ahead of it (a seed's own, where its split would have been); else the
** one it runs into (track_node_ahead); WK_NONE if none. */
static uint32_t forced_track_node(wk_wavefront *W, uint32_t f, double t) {
    uint32_t k_best = WK_NONE;
    if (!W->n_swept || !is_swept(W, f)) return track_node_ahead(W, f, t);
    const wk_wf_vertex *F = &W->v[f];
    wk_point p = wk_wf_pos(F, t), vel = F->vel;
    double v2 = vel.x * vel.x + vel.y * vel.y, best_h = -INFINITY;
    for (uint32_t k = 0; k < W->n_cl; k++) {
        wk_point q = W->cl[k].p;
        double r = W->cl[k].r;
        if (wf_dist2(q, p) <= r * r || !left_node_lately(W, f, q, r, t)) continue;
        double h = v2 > 0 ? ((q.x - p.x) * vel.x + (q.y - p.y) * vel.y) / v2 : 0;
        if (h > best_h) {
            best_h = h;
            k_best = k;
        }
    }
    return k_best != WK_NONE ? k_best : track_node_ahead(W, f, t);
}

/* Vertex u is forced to become a node this round: pushed on W->forced and
** marked, so that asking is O(1) (plan_arrivals asks for every vertex that
** arrives nowhere in a group with forced vertices: a scan of the list each
** time was O(vertices x forced)). */
static wk_status wf_force(wk_wavefront *W, uint32_t u) {
    if (wf_push_u32(W->R, &W->forced, &W->n_forced, &W->cap_forced, u) != WK_OK) return W->R->err.code;
    W->v[u].forced = 1;
    return WK_OK;
}

/* Step 1: a node for every seed's event point and every forced vertex,
** then the vertices that take part (a local walk for a single event, the
** touched cycles otherwise). */
static wk_status plan_nodes(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    if (start_node_grid(W, t) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        uint32_t k;
        if (add_cluster(W, W->v[W->seeds[i]].ev_p, &k) != WK_OK) return R->err.code;
    }
    for (uint32_t i = 0; i < W->n_forced; i++) {
        uint32_t k;
        if (forced_track_node(W, W->forced[i], t) != WK_NONE) continue; /* it runs into a node */
        if (add_cluster(W, wk_wf_pos(&W->v[W->forced[i]], t), &k) != WK_OK) return R->err.code;
    }
    W->local_walk = W->n_forced == 0;
    if (W->local_walk) return collect_local(W);
    return collect_cycles(W);
}

/* ------------------------------------------------------------ shields */

/* The shield of vertex u against node k: the piece it belongs to that the
** node cuts instead (WK_NONE: not shielded).  A forced vertex is a node of
** its own and is never shielded. */
/* From WF_INDEX_MIN shields on they are hashed by vertex (W->shield_ix):
** shield_of scanned them all for each vertex it was asked about
** (plan_arrivals asks for nearly every vertex of the plan, plan_pinches,
** plan_seed_cuts and shield_slow_stretch for piece ends), and the slow
** stretches give up to four shields per seed, so a group of k seeds that
** plans whole cycles of m vertices cost O(k m): rectilinear 10^6, where
** groups with forced vertices plan whole cycles, spent a quarter of its run
** in those scans (perf).  The index answers what the scan did: the oldest
** shield of u with node k (its chain runs from the newest to the oldest,
** and the last match wins). */
enum { WF_INDEX_MIN = 16 };

static uint32_t hash_slot(uint32_t key, uint32_t size) {
    return (uint32_t)(((uint64_t)(key * 2654435761u) * size) >> 32);
}

static uint32_t shield_slot(const wk_wavefront *W, uint32_t u) {
    uint32_t h = hash_slot(u, W->n_shield_ix);
    while (W->shield_ix[h] != WK_NONE && W->shield[W->shield_ix[h]].vertex != u)
        h = h + 1 == W->n_shield_ix ? 0 : h + 1;
    return h;
}

static void shield_index_add(wk_wavefront *W, uint32_t i) {
    uint32_t h = shield_slot(W, W->shield[i].vertex);
    W->shield_older[i] = W->shield_ix[h];
    W->shield_ix[h] = i;
}

/* Append shield (x, k, piece); the index follows from WF_INDEX_MIN shields
** on, at a load of at most a half (rebuilt at twice the size beyond). */
static wk_status add_shield(wk_wavefront *W, uint32_t x, uint32_t k, uint32_t piece) {
    wk_run *R = W->R;
    if (WK_GROW(R, W->shield, W->cap_shield, W->n_shield + 1) != WK_OK) return R->err.code;
    W->shield[W->n_shield++] = (wk_wf_shield){x, k, piece};
    if (W->n_shield < WF_INDEX_MIN) return WK_OK;
    if (WK_GROW(R, W->shield_older, W->cap_shield_older, W->n_shield) != WK_OK) return R->err.code;
    if (W->n_shield_ix && 2 * W->n_shield <= W->n_shield_ix) {
        shield_index_add(W, W->n_shield - 1);
        return WK_OK;
    }
    uint32_t size = 64;
    while (size < 4 * W->n_shield) size *= 2;
    W->n_shield_ix = 0;
    if (WK_GROW(R, W->shield_ix, W->cap_shield_ix, size) != WK_OK) return R->err.code;
    for (uint32_t h = 0; h < size; h++) W->shield_ix[h] = WK_NONE;
    W->n_shield_ix = size;
    for (uint32_t i = 0; i < W->n_shield; i++) shield_index_add(W, i);
    return WK_OK;
}

static const wk_wf_shield *shield_of(const wk_wavefront *W, uint32_t u, uint32_t k) {
    if (W->n_shield_ix) {
        const wk_wf_shield *found = NULL;
        for (uint32_t i = W->shield_ix[shield_slot(W, u)]; i != WK_NONE; i = W->shield_older[i])
            if (W->shield[i].node == k) found = &W->shield[i];
        return found;
    }
    for (uint32_t i = 0; i < W->n_shield; i++)
        if (W->shield[i].vertex == u && W->shield[i].node == k) return &W->shield[i];
    return NULL;
}

/* Step 1b, sub-tolerance splits of the input.  An input vertex v that hits
** a piece (a, b) of an input edge within eps_d of an end x that is an input
** vertex of another ring (two holes whose vertices lie 1e-10 apart, a hole's vertex
** next to a vertex of the outer ring) would make x arrive at v's node: the
** two rings then touch there, as if the gap were closed.  But the skeleton
** of the input is not that of the closed gap: v cuts the piece on x's one
** side, and the stretch of the piece between x and the cut may grow into a
** face as wide as the polygon (CGAL's skeleton of
** tests/data/fuzz/ealgo_holes_vertices_1e-10_apart.wpoly), so the tolerance
** picture is a different skeleton, and an inconsistent one: the vertex it
** puts between the two rings moves behind the piece's line at the piece's
** end, which the split test takes for a split now, again and again ("no
** progress at t = 0").  Both vertices are input vertices, so where v meets
** the piece's line relative to x follows from the input coordinates to
** rounding (wf_input_cut_side): when the cut lies inside the piece by more than
** WK_SPLIT_SIDE_ULPS ulps of that, and the stretch between x and the cut
** grows, x is shielded from the node: it does not arrive there, and the
** node cuts the piece next to it (plan_pinches, plan_seed_cuts).
** Otherwise (a cut at x within rounding: a true vertex event; a stretch
** that shrinks to an edge event at once) the tolerance picture stays. */
static wk_status plan_shields(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    W->n_shield = W->n_shield_ix = 0;
    for (uint32_t i = 0; W->input_sides && i < W->n_seeds; i++) {
        uint32_t v = W->seeds[i];
        const wk_wf_vertex *V = &W->v[v];
        if (V->ev_kind != WK_WF_SPLIT || !wf_is_input_vertex(W, v)) continue;
        uint32_t a = V->ev_a, b = V->ev_b;
        if (!W->v[a].alive || W->v[a].next != b) continue;
        uint32_t k = find_cluster(W, V->ev_p);
        if (k == WK_NONE) continue;
        uint32_t n0 = W->n_shield;
        const wk_offset_line *L = &W->L[W->v[a].eout];
        for (int end = 0; end < 2; end++) {
            uint32_t x = end ? b : a;
            /* rings that nearly touch only: a sub-tolerance feature of one
            ** ring (an edge of 1e-11 chamfering a reflex corner,
            ** tests/data/degenerate/arr_chamfer_contact.wpoly) is resolved
            ** at tolerance level, as README says */
            if (!wf_is_input_vertex(W, x) || wk_polygon_ring(W->P, x) == wk_polygon_ring(W->P, v)) continue;
            bool seed = false;
            for (uint32_t j = 0; j < W->n_seeds; j++) seed |= W->seeds[j] == x;
            seed |= W->v[x].forced;
            if (seed) continue;
            if (wf_input_cut_side(W, v, x, L, end, t) <= 0) continue;
            const wk_wf_vertex *X = &W->v[x];
            /* The stretch of the piece between x and the cut, between x and
            ** the vertex the split makes there, must grow: one that shrinks
            ** collapses a moment later, and that edge event joins the same
            ** vertices as the tolerance picture does now (a hole's vertex
            ** 1e-10 from a convex corner of the outer ring), while its
            ** sub-tolerance moment would merge the split's other new vertex
            ** into it (a cycle of two arcs). */
            wk_point vy;
            uint32_t f = end ? V->ein : V->eout;
            if ((end ? wk_vertex_velocity(&W->L[f], L, &vy) : wk_vertex_velocity(L, &W->L[f], &vy)) !=
                WK_VEL_REGULAR)
                continue;
            double grow = end ? L->ux * (X->vel.x - vy.x) + L->uy * (X->vel.y - vy.y)
                              : L->ux * (vy.x - X->vel.x) + L->uy * (vy.y - X->vel.y);
            double speeds = fabs(vy.x) + fabs(vy.y) + fabs(X->vel.x) + fabs(X->vel.y);
            if (!(grow > WK_SPLIT_SIDE_GROWTH_REL * speeds)) continue;
            /* x shielded from k on its other piece too, by another split:
            ** the two splits cut x's two pieces next to it, at two points
            ** below eps_d apart (x's corner between them).  One node would
            ** join them where the input keeps them apart: x's pieces
            ** k -> x -> k enclose its corner, which the pairing at one point
            ** closes (a cycle of two vertices), and with both cuts at one
            ** node the skeleton gains a cycle (--check: "closes cycle").
            ** This split gets a node of its own at its event point.  Three
            ** holes whose apexes lie 1e-9 apart, one apex in front of the
            ** other two's edges: the two others split its edges and it
            ** goes on (CGAL's skeleton, and the reference's with the gaps
            ** magnified 1e3..1e7 times, holes moved rigidly;
            ** tests/data/holes/near_touch_three_holes_both_sides.wpoly). */
            uint32_t other = end ? x : W->v[x].prev; /* x's other piece */
            bool both = false;
            for (uint32_t j = 0; j < n0; j++)
                both |= W->shield[j].vertex == x && W->shield[j].node == k && W->shield[j].piece == other;
            if (both) {
                uint32_t k2;
                if (new_cluster(W, V->ev_p, v, &k2) != WK_OK) return R->err.code;
                /* this seed's earlier shields (its piece's other end) follow it */
                for (uint32_t j = n0; j < W->n_shield; j++)
                    if (W->shield[j].node == k) W->shield[j].node = k2;
                k = k2;
            }
            if (add_shield(W, x, k, a) != WK_OK) return R->err.code;
        }
    }
    W->n_gap_shield = W->n_shield;
    return WK_OK;
}

/* Step 1c, slow stretches.  A vertex x that is no seed of the group (or a
** seed whose split lands beyond its target piece's end: an echo) lies
** within tolerance of a node only; where it is joined to the node by a
** stretch of an offset line (x a neighbour of the seed along the seed's
** line, or an end of a split's target piece), it arrives there only if that
** stretch collapses now.  The stretch runs between x and the new vertex the
** seed's event makes on its line; it collapses when the two meet, the same
** relative motion along the line as an edge event (edge_event in
** wavefront.c), and the same rule decides: a stretch that shrinks so slowly
** that it is still longer than rounding after eps_t collapses later, not
** now (x is shielded from the node).  Merged at once, the node joins the
** stretch's two other lines, and where those are nearly parallel the
** vertex between them then runs its whole life far from their crossing: a
** weighted comb whose tooth edge ends 5.1e-3 (0.6 eps_d) from a split,
** the stretch shrinking at 8.9e-5 (between edges of equal weight at a sine
** of 3e-5), put the vertex between those edges 173 units from their
** crossing and the spike meeting it 141 units off the exact node
** (tests/data/fuzz/mismatch_deforming_weighted_comb_spike.wpoly;
** tests/data/degenerate/comb_far_slow_stretch.wpoly: a node 2% of the diagonal
** from CGAL's).  Stretches that keep
** their length (slower than WK_SPLIT_SIDE_GROWTH_REL: parallel at the
** tolerance) or grow, and the coarser retries (input_sides), keep the
** tolerance picture, as do nodes with more than one seed or a forced
** vertex, where the new vertex at the node is not known before pairing. */
static wk_status shield_slow_stretch(wk_wavefront *W, uint32_t k, wk_point q, uint32_t x,
                                     uint32_t piece, uint32_t e, wk_point vnew, bool x_after,
                                     double t) {
    const wk_wf_vertex *X = &W->v[x];
    if (!X->alive || X->seen != W->stamp || shield_of(W, x, k)) return WK_OK;
    if (!wk_stretch_collapses_later(&W->L[e], q, vnew, wk_wf_pos(X, t), X->vel, x_after, W->eps_t))
        return WK_OK;
    return add_shield(W, x, k, piece);
}

/* True if seed x is a split that lands outside its target piece (beyond
** an end by more than rounding, within the split test's eps_d): it meets
** that end's vertex only at the tolerance, the echo of whatever that vertex
** does there. */
static bool split_misses_piece(const wk_wavefront *W, uint32_t x, double t) {
    const wk_wf_vertex *X = &W->v[x];
    if (X->ev_kind != WK_WF_SPLIT || !W->v[X->ev_a].alive || W->v[X->ev_a].next != X->ev_b) return false;
    const wk_offset_line *L = &W->L[W->v[X->ev_a].eout];
    wk_point pa = wk_wf_pos(&W->v[X->ev_a], t), pb = wk_wf_pos(&W->v[X->ev_b], t), q = X->ev_p;
    double sa = (q.x - pa.x) * L->ux + (q.y - pa.y) * L->uy;
    double sb = (pb.x - q.x) * L->ux + (pb.y - q.y) * L->uy;
    double ulp = DBL_EPSILON * (fabs(q.x) + fabs(q.y));
    return sa < -WK_BEHIND_ULPS * ulp || sb < -WK_BEHIND_ULPS * ulp;
}

/* True if split seed S, cutting a piece of line l at q, starts its two new
** vertices on l in reversed order: each starts where its lines meet when
** that is within eps_d of q (wk_vertex_start's snap), and the vertex
** (l, S.eout), which ends the stretch from the piece's start a, lies
** beyond the vertex (S.ein, l), which starts the stretch to its end b,
** by more than rounding.  The two stretches then overlap on l, and a
** shielded end meets the other stretch's new vertex inside its own
** stretch at once: the next group, at the same time, makes a second node
** within eps_d of this one, joined to it by two arcs (a cycle).  The ends
** are then left to the tolerance picture (they arrive at the node).  A
** weighted comb 20-gon with vertices pulled to 5e10 (eps_d 50): a reflex
** corner split a tooth edge's line at t = 8.0 nearly parallel to its own
** edge (1e-3 rad), the snapped new vertex on that edge 0.22 behind the
** cut, on the shielded tooth corner (exit 3, "closes a cycle";
** tests/data/fuzz/invalid_naive_wcomb_*.wpoly). */
static bool split_starts_reversed(const wk_wavefront *W, const wk_wf_vertex *S, uint32_t l, wk_point q,
                                  double t) {
    const wk_offset_line *L = &W->L[l];
    wk_point p1, p2;
    if (!wk_offset_lines_meet(L, &W->L[S->eout], t, &p1) || wf_dist2(p1, q) > W->eps_d * W->eps_d) p1 = q;
    if (!wk_offset_lines_meet(&W->L[S->ein], L, t, &p2) || wf_dist2(p2, q) > W->eps_d * W->eps_d) p2 = q;
    double ulp = DBL_EPSILON * (fabs(q.x) + fabs(q.y));
    return (p1.x - p2.x) * L->ux + (p1.y - p2.y) * L->uy > WK_BEHIND_ULPS * ulp;
}

/* The seed's stretches: for each vertex x joined to the seed's new vertex
** at its node (velocity vnew) along line e, shield x if that stretch
** collapses later.  O(seeds * nodes), as plan_nodes: each seed's node is
** found once and kept in its `at` (ECHO_BIT for an echo; plan_arrivals sets
** every `at` afresh, and they are reset here), the real seeds per node
** counted in the node's `count` (plan_slots resets it).  No scratch array:
** a group of a comb's 1500 teeth is 1% of the reference finder's peak memory. */
#define ECHO_BIT 0x80000000u
static wk_status plan_slow_stretches(wk_wavefront *W, double t) {
    if (!W->input_sides || W->n_forced) return WK_OK;
    for (uint32_t k = 0; k < W->n_cl; k++) W->cl[k].count = 0;
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        uint32_t s = W->seeds[i], k = seed_node(W, s);
        bool echo = split_misses_piece(W, s, t);
        W->v[s].at = k == WK_NONE ? WK_NONE : echo ? k | ECHO_BIT : k;
        if (k != WK_NONE && !echo) W->cl[k].count++;
    }
    wk_status st = WK_OK;
    for (uint32_t i = 0; i < W->n_seeds && st == WK_OK; i++) {
        /* s must be its node's only seed but for echoes, which are
        ** candidates like any other vertex */
        uint32_t s = W->seeds[i], k = W->v[s].at;
        if (k == WK_NONE || (k & ECHO_BIT) || W->cl[k].count != 1) continue;
        const wk_wf_vertex *S = &W->v[s];
        uint32_t n0 = W->n_shield;
        wk_point vy, q = S->ev_p;
        if (S->ev_kind == WK_WF_EDGE) {
            /* the piece s -> b collapses: the new vertex sits between
            ** s.ein and b.eout, s.prev comes to it along s.ein and b.next
            ** leaves it along b.eout */
            uint32_t b = S->next, xp = S->prev, xn = W->v[b].next;
            if (xp == b || xn == s || xp == xn) continue; /* a triangle collapses whole */
            if (wk_vertex_velocity(&W->L[S->ein], &W->L[W->v[b].eout], &vy) != WK_VEL_REGULAR) continue;
            if ((st = shield_slow_stretch(W, k, q, xp, xp, S->ein, vy, false, t)) == WK_OK)
                st = shield_slow_stretch(W, k, q, xn, b, W->v[b].eout, vy, true, t);
        } else if (S->ev_kind == WK_WF_SPLIT) {
            /* s cuts the piece a -> b of line l: a -> (l, s.eout) -> s.next
            ** and s.prev -> (s.ein, l) -> b */
            uint32_t a = S->ev_a, b = S->ev_b;
            if (!W->v[a].alive || W->v[a].next != b) continue;
            uint32_t l = W->v[a].eout;
            bool ends = !split_starts_reversed(W, S, l, q, t);
            if (wk_vertex_velocity(&W->L[l], &W->L[S->eout], &vy) == WK_VEL_REGULAR &&
                (st = ends ? shield_slow_stretch(W, k, q, a, a, l, vy, false, t) : WK_OK) == WK_OK)
                st = shield_slow_stretch(W, k, q, S->next, s, S->eout, vy, true, t);
            if (st == WK_OK && wk_vertex_velocity(&W->L[S->ein], &W->L[l], &vy) == WK_VEL_REGULAR &&
                (st = ends ? shield_slow_stretch(W, k, q, b, a, l, vy, true, t) : WK_OK) == WK_OK)
                st = shield_slow_stretch(W, k, q, S->prev, S->prev, S->ein, vy, false, t);
        }
        /* a shielded echo takes no part: the node is the stretch's end, the
        ** point of the seed that stays */
        for (uint32_t m = n0; m < W->n_shield; m++)
            if (W->v[W->shield[m].vertex].at == (k | ECHO_BIT)) W->cl[k].p = q;
    }
    for (uint32_t i = 0; i < W->n_seeds; i++) W->v[W->seeds[i]].at = WK_NONE;
    return st == WK_OK ? WK_OK : W->R->err.code;
}

/* True if a split of this group resolves a gap between rings at node k on
** the input's side (plan_shields shielded a vertex from it; not
** plan_slow_stretches, whose stretches are the tolerance's business). */
static bool input_side_node(const wk_wavefront *W, uint32_t k) {
    for (uint32_t i = 0; i < W->n_gap_shield; i++)
        if (W->shield[i].node == k) return true;
    return false;
}

/* True if u is a seed of the group or an end of a split seed's target. */
static bool seed_or_target(const wk_wavefront *W, uint32_t u) {
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        const wk_wf_vertex *S = &W->v[W->seeds[i]];
        if (W->seeds[i] == u || (S->ev_kind == WK_WF_SPLIT && (S->ev_a == u || S->ev_b == u))) return true;
    }
    return false;
}

/* A bystander of an input-side node: vertex u (not a seed, not an end of
** a split's target, not shielded by plan_shields) lies within tolerance of
** node k, where a split resolves a gap between rings on the input's side
** (input_side_node).  There the input's picture is finer than eps_d, and u
** takes part only if it is at the node's point to rounding at some moment
** of the group (t .. t_last; rounding: WK_SPLIT_SIDE_ULPS ulps of the
** points and of u's motion since it was made, its speed s counted as
** s + s^2 / w as in behind_offset_line).  Farther, it is shielded from the
** node (piece WK_NONE: the node cuts none of its pieces).  Three holes
** whose apexes lie 2.5e-9 apart: the first apex splits the second's edge
** next to its apex (an input-side split), and the third splits the
** second's other edge 1e-9 later, 5e-9 away: the vertices the first split
** made, 5e-9 from that node and moving away, arrived there, closed the
** second apex's corner into a triangle of no area (plan_force_touching)
** and the skeleton lost the second apex's arc (CGAL's skeleton keeps it;
** tests/data/holes/near_touch_three_holes_bystanders.wpoly).  Input
** vertices too: with only the made ones kept apart, the first apex
** (1e-7 from the node) arrived alone and the skeleton was not CGAL's
** (tests/data/holes/near_touch_three_holes_stale_target.wpoly).  And a
** vertex made at such a node (gap_made) at any later node: kept apart at
** one node, two such vertices 1e-7 from the next one (an edge event with
** a split of the same gap, 9e-8 later) arrived there by the tolerance, and
** the skeleton was not the one of the same input with the gaps magnified
** 10 .. 1000 times, where they do not (weighted three holes,
** tests/data/holes/near_touch_three_holes_gap_made.wpoly). */
static bool bystander(const wk_wavefront *W, uint32_t u, uint32_t k, double t) {
    const wk_wf_vertex *U = &W->v[u];
    if (!W->input_sides || !(U->gap_made || input_side_node(W, k)) || seed_or_target(W, u)) return false;
    wk_point q = W->cl[k].p, a = wk_wf_pos(U, t);
    /* the nearest point to q of u's track over the group's time span */
    double dt = W->t_last - t, v2 = U->vel.x * U->vel.x + U->vel.y * U->vel.y;
    double h = v2 > 0 ? ((q.x - a.x) * U->vel.x + (q.y - a.y) * U->vel.y) / v2 : 0;
    h = fmin(fmax(h, 0), dt);
    wk_point c = {a.x + U->vel.x * h, a.y + U->vel.y * h};
    double s = fabs(U->vel.x) + fabs(U->vel.y), w = fmin(W->L[U->ein].w, W->L[U->eout].w);
    double bar = WK_SPLIT_SIDE_ULPS * DBL_EPSILON *
                 (fabs(q.x) + fabs(q.y) + fabs(U->p0.x) + fabs(U->p0.y) + (s + s * s / w) * (t + dt - U->t0));
    return wf_dist2(c, q) > bar * bar;
}

/* True if x is a seed of the group: its candidate was popped for it
** (between groups every alive vertex with a finite candidate is queued,
** wavefront_internal.h; the deferred ones are queued again). */
static bool is_seed(const wk_wavefront *W, uint32_t x) {
    const wk_wf_vertex *X = &W->v[x];
    return X->ev_kind != WK_WF_NONE && isfinite(X->ev_t) && !wk_event_queue_contains(&W->Q, x);
}

/* The part of the group's time span (t .. t_last) that vertex u, not a
** seed, lives through as it is: up to the earliest event that the group
** leaves out and that ends u, its own candidate or its predecessor's edge
** event (the piece ending at u collapses), when none of that event's other
** vertices is a seed (a seed's event supersedes it).  An event of a fast
** vertex can be left out of the group (wavefront.c, simulate: it would be
** resolved where it is not yet), and u's track must then stop where that
** event stops u, not run on to a node beyond it.  A cross whose arms are
** 1-2 wide with vertices pulled out to 1.3e14, 7.8e8, 3.4e10 and 4.3e10:
** the tip of a sliver 2 wide and 3.3e10 long (speed 3.4e10) reaches the
** sliver's reflex foot, 7.8e8 from the group's node, at t = 1 (that edge
** event left out), but over the group's span of 2.02 its track ran on to
** the node; it arrived there, the sliver's edge (not its neighbour along
** the polygon's side) was joined to the node, and the last triangle
** collapsed 3.9e8 outside the polygon (exit 3 in every variant;
** tests/data/fuzz/invalid_naive_cross_far_sliver_tip.wpoly). */
static double track_span(const wk_wavefront *W, uint32_t u, double t) {
    const wk_wf_vertex *U = &W->v[u], *P = &W->v[U->prev];
    double end = W->t_last;
    if (is_seed(W, u)) return end - t;
    if (U->ev_kind != WK_WF_NONE && U->ev_t < end && !is_seed(W, U->ev_b) &&
        (U->ev_kind == WK_WF_EDGE || !is_seed(W, U->ev_a)))
        end = U->ev_t;
    if (P->ev_kind == WK_WF_EDGE && P->ev_b == u && P->ev_t < end && !is_seed(W, U->prev)) end = P->ev_t;
    return end > t ? end - t : 0;
}

/* Step 2a: every vertex within tolerance of a node arrives there (unless
** shielded from it, or a bystander of it). */
static wk_status plan_arrivals(wk_wavefront *W, double t) {
    for (uint32_t i = 0; i < W->n_comp; i++) {
        wk_wf_vertex *u = &W->v[W->comp[i]];
        /* within the group's time span (its seeds' times, t .. t_last <=
        ** t + eps_t) a vertex covers |vel| (t_last - t): a fast vertex that
        ** close to a node arrives there in the same instant.  Not |vel|
        ** eps_t: a reflex vertex of speed 4e5 then arrived at a node 2.4
        ** units away, in a group of one event (the same H with needles) */
        double speed = fabs(u->vel.x) + fabs(u->vel.y), dt = track_span(W, W->comp[i], t);
        u->at = speed * dt > W->eps_g ? find_cluster_on_track(W, u, t, dt, speed * dt)
                                      : find_cluster_within(W, wk_wf_pos(u, t), speed * dt);
        if (u->at == WK_NONE && u->forced)
            u->at = forced_track_node(W, W->comp[i], t);
        if (u->at != WK_NONE && W->n_shield && shield_of(W, W->comp[i], u->at)) u->at = WK_NONE;
        if (u->at != WK_NONE && (W->n_shield || u->gap_made) && bystander(W, W->comp[i], u->at, t)) {
            if (add_shield(W, W->comp[i], u->at, WK_NONE) != WK_OK) return W->R->err.code;
            u = &W->v[W->comp[i]];
            u->at = WK_NONE;
        }
        /* a seed with a node of its own arrives there, wherever it is now */
        uint32_t own = own_node(W, W->comp[i]);
        if (own != WK_NONE) u->at = own;
        /* a crack tip arrives at the node it left (plan_force_touching),
        ** a seed too */
        if (W->n_swept && is_swept(W, W->comp[i])) {
            uint32_t k = forced_track_node(W, W->comp[i], t);
            if (k != WK_NONE) u->at = k;
        }
    }
    /* a free vertex whose two neighbours arrive at the same node closes a
    ** triangle of zero size with it: it arrives too */
    for (uint32_t i = 0; i < W->n_comp; i++) {
        wk_wf_vertex *u = &W->v[W->comp[i]];
        uint32_t kp = W->v[u->prev].at;
        if (u->at == WK_NONE && kp != WK_NONE && kp == W->v[u->next].at && u->prev != u->next &&
            !(W->n_shield && shield_of(W, W->comp[i], kp)))
            u->at = kp;
    }
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        wk_wf_vertex *u = &W->v[W->seeds[i]];
        if (u->at == WK_NONE && !(W->n_shield && shield_of(W, W->seeds[i], seed_node(W, W->seeds[i]))))
            u->at = seed_node(W, W->seeds[i]);
        if (u->ev_kind == WK_WF_EDGE && W->v[u->next].at == WK_NONE) W->v[u->next].at = u->at;
    }
    return WK_OK;
}

/* The piece leaving the last vertex c of a stretch (its next lies outside
** the walk) is planned, but its far end is not: a node within eps_g of that
** end on the piece's line makes plan_pinches take the end as arriving
** there, and the outside vertex's own piece would not leave the node.
** False when that can happen (local_walk_suffices then walks whole
** cycles).  A weighted comb 20-gon with vertices pulled to 5e10 (eps_d 50,
** teeth 110 apart): the edge event of a tooth's collapse at t = 10.26 lay
** 48 from the next tooth's reflex corner, three steps beyond the walk
** ("2 pieces arrive, 1 leave" up to eps_g 200; at 400 the node swallowed
** edge 1's piece 209 away, and the arcs closed a cycle, exit 3;
** tests/data/fuzz/invalid_naive_wcomb_*.wpoly). */
static bool end_arrives_outside(wk_wavefront *W, const wk_wf_vertex *c, double t) {
    const wk_wf_vertex *n = &W->v[c->next];
    if (n->seen == W->stamp) return true;
    wk_point a = c->at != WK_NONE ? W->cl[c->at].p : wk_wf_pos(c, t), b = wk_wf_pos(n, t);
    const wk_offset_line *L = &W->L[c->eout];
    double len = (b.x - a.x) * L->ux + (b.y - a.y) * L->uy;
    wk_point e = {a.x + len * L->ux, a.y + len * L->uy}, lo, hi;
    band_box(e, L, 0, W->eps_gmax, &lo, &hi);
    bool listed = near_nodes(W, lo, hi, W->eps_gmax);
    uint32_t m = listed ? W->cg.n_out : W->n_cl;
    for (uint32_t i = 0; i < m; i++) {
        uint32_t k = listed ? W->cg.out[i] : i;
        if (k == c->at) continue;
        wk_point q = W->cl[k].p;
        double s = (q.x - a.x) * L->ux + (q.y - a.y) * L->uy, r = W->cl[k].r;
        double off = (q.x - a.x) * L->nx + (q.y - a.y) * L->ny;
        if (s >= len - r && s <= len + r && fabs(off) <= r) return false;
    }
    return true;
}

/* A local walk (collect_local) is enough only if the group stays inside
** it: the pieces that enter the walk from outside (outside vertex -> first
** vertex of a stretch) are not part of the plan, so the first vertex of a
** stretch must not arrive at a node, and no node may lie on such a piece.
** Near-degenerate inputs break that (a regular 24-gon with one coordinate
** moved by 1e-12: all 24 vertices meet within eps_d of the centre, but the
** events come one by one, eps_t apart). */
static bool local_walk_suffices(wk_wavefront *W, double t) {
    for (uint32_t i = 0; i < W->n_comp; i++) {
        const wk_wf_vertex *c = &W->v[W->comp[i]];
        if (!end_arrives_outside(W, c, t)) return false;
        const wk_wf_vertex *o = &W->v[c->prev];
        if (o->seen == W->stamp) continue; /* not the first of a stretch */
        if (c->at != WK_NONE) return false;
        wk_point a = wk_wf_pos(o, t), b = wk_wf_pos(c, t);
        const wk_offset_line *L = &W->L[o->eout];
        double len = (b.x - a.x) * L->ux + (b.y - a.y) * L->uy;
        wk_point lo, hi;
        band_box(a, L, len, W->eps_gmax, &lo, &hi);
        bool listed = near_nodes(W, lo, hi, W->eps_gmax);
        uint32_t n = listed ? W->cg.n_out : W->n_cl;
        for (uint32_t i = 0; i < n; i++) {
            uint32_t k = listed ? W->cg.out[i] : i;
            wk_point q = W->cl[k].p;
            double s = (q.x - a.x) * L->ux + (q.y - a.y) * L->uy, r = W->cl[k].r;
            double off = (q.x - a.x) * L->nx + (q.y - a.y) * L->ny;
            if (s >= -r && s <= len + r && fabs(off) <= r) return false;
        }
    }
    return true;
}

/* The pinches (plan_pinches, plan_seed_cuts) can still take the local
** walk beyond itself after local_walk_suffices passed: a node within eps_g
** of the far end of a stretch's last piece makes the vertex just outside
** arrive (its own outgoing piece is not in the plan: "2 pieces arrive, 1
** leave"), and one near the first vertex of a stretch makes that vertex
** arrive.  True if either happened: the group then takes whole cycles.
** A weighted 12-gon H with a vertex pulled out to a spike 5e8 long
** (eps_d 0.5, the H 6 wide): at t = 0.63 reflex vertex 10 lies 0.05 from
** the node of an edge event and a split, one vertex beyond the walk; the
** plan failed at eps_d and at 2 eps_d, and 4 eps_d swallowed a piece 2.3
** long, so the vertex it made raced up the spike 1.6 off its edge's line
** and put the spike's node 3.5e7 low: at t = 0.68, where the spike's three
** edges meet at t = 1.38 (exit 0 and valid at the validator's tolerance of
** 50; issue 11.  A finder whose split candidate named another piece got
** a forced vertex there, took whole cycles and was right;
** tests/data/fuzz/mismatch_naive_h_spike_local_walk.wpoly). */
static bool local_walk_outgrown(const wk_wavefront *W) {
    for (uint32_t i = 0; i < W->n_comp; i++) {
        const wk_wf_vertex *c = &W->v[W->comp[i]];
        if (W->v[c->prev].seen != W->stamp && c->at != WK_NONE) return true;
        if (W->v[c->next].seen != W->stamp && W->v[c->next].at != WK_NONE) return true;
    }
    return false;
}

/* True if node k, off (< 0: behind) from the line L of a piece, only
** looks like it touches the piece: it lies clearly behind the line (more
** than the rounding of its place, WK_BEHIND_ULPS ulps of its coordinates)
** and no vertex arriving at it comes from the line's front (each moves
** away from the line, along it, or towards it from behind).  A node that
** meets a piece is reached from the piece's interior side.  The collapse
** of a needle 2e-6 wide, 1.2e-5 behind a non-adjacent edge across a crack
** outside the polygon, pinched that edge and closed a cycle
** (the fuzz finding of an H at 1e6 with needles 1e5..8e6 long, issue 11). */
/* True if vertex u, now (t) behind the line of piece a by more than
** rounding (bar) and moving further behind it (rate < 0), never met the
** piece: it was behind the line since it was made, or it crossed the line
** before now outside the piece (at the crossing time t_c, u and both
** ends of the piece already existed and u's crossing point lay beyond an
** end by more than the node radius: it crossed no piece of the line then,
** as it lives on).  It is behind the piece across something else, not
** come from its front.  A 12-gon H with needles near (1e6, 1e6): reflex
** tip 7 (speed 3.9e4) crossed the line of edge 3 at t = 5e-6, 6.5 beyond
** crack tip 3 (speed 6.7e5, the piece's start); at t = 1.5e-5 tip 3, past
** it, split edge 6 0.38 above it, and tip 7 lay 1.9e-5 behind edge 3's
** piece across the crack between edges 2 and 3.  Taken for a vertex from
** the front, its node pinched edge 3 (and the split's node edge 7): the
** cracks' walls cancelled, each node paired its crack's edges again, two
** reflex vertices ran on through each other ("vertex 12 still alive when
** the queue ran empty", exit 2 in 3 variants, exit 3 in a fourth;
** tests/data/fuzz/ealgo_naive_h_needles_tips_pass.wpoly; CGAL's tips make
** one spike 2e-5 wide that collapses at tip 7).  Made behind: the same H
** with edge 4 of weight 1000, the tip of that spike (edges 2, 6), made
** 2e-5 behind edge 7's line, runs along it (rate -5e-7); at t = 0.94 its
** node pinched edge 7 and the arcs closed a cycle (exit 3;
** invalid_naive_h_needles_spike_in_needle.wpoly, with cancel_across). */
static bool crossed_beyond_piece(const wk_wavefront *W, const wk_wf_vertex *u, uint32_t a, double rate,
                                 double t, double bar, double r) {
    const wk_wf_vertex *A = &W->v[a], *B = &W->v[A->next];
    const wk_offset_line *L = &W->L[A->eout];
    double d = wk_offset_distance(L, wk_wf_pos(u, t), t);
    if (!(d < -bar) || !(rate < 0)) return false;
    double tc = t + d / -rate;
    /* behind it since it was made, by more than rounding: never in front */
    if (!(u->t0 < tc)) return d + rate * (u->t0 - t) < -bar;
    if (A->t0 > tc || B->t0 > tc) return false;
    wk_point pu = wk_wf_pos(u, tc), pa = wk_wf_pos(A, tc), pb = wk_wf_pos(B, tc);
    double s = (pu.x - pa.x) * L->ux + (pu.y - pa.y) * L->uy;
    double len = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
    return s < -r || s > len + r;
}

static bool node_behind_piece(const wk_wavefront *W, uint32_t k, uint32_t a, double off, wk_point q,
                              double t) {
    uint32_t e = W->v[a].eout;
    const wk_offset_line *L = &W->L[e];
    double ulp = DBL_EPSILON * (fabs(q.x) + fabs(q.y));
    if (!(off < -WK_BEHIND_ULPS * ulp)) return false;
    bool any = false;
    for (uint32_t i = 0; i < W->n_comp; i++) {
        const wk_wf_vertex *u = &W->v[W->comp[i]];
        if (u->at != k) continue;
        any = true;
        /* approaching from behind the line all along is not from its front:
        ** an input vertex on the line's input edge's line, receding from it
        ** (the H with needles of wf_never_reaches_line) */
        double rate = L->nx * u->vel.x + L->ny * u->vel.y - L->w;
        if (rate < 0 && !wf_never_reaches_line(W, W->comp[i], e) &&
            !crossed_beyond_piece(W, u, a, rate, t, WK_BEHIND_ULPS * ulp, W->cl[k].r))
            return false;
    }
    return any;
}

/* Step 2b: a node inside a piece cuts it (a pinch). */
static wk_status plan_pinches(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    for (uint32_t i = 0; i < W->n_comp; i++) {
        uint32_t a = W->comp[i];
        const wk_wf_vertex *A = &W->v[a], *B = &W->v[A->next];
        /* an end that arrives at a node is taken at the node, so pinches and
        ** arrivals see the same geometry */
        wk_point pa = A->at != WK_NONE ? W->cl[A->at].p : wk_wf_pos(A, t);
        wk_point pb = B->at != WK_NONE ? W->cl[B->at].p : wk_wf_pos(B, t);
        const wk_offset_line *L = &W->L[A->eout];
        double len = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
        wk_point lo, hi;
        band_box(pa, L, len, W->eps_gmax, &lo, &hi);
        bool listed = near_nodes(W, lo, hi, W->eps_gmax);
        uint32_t n = listed ? W->cg.n_out : W->n_cl;
        for (uint32_t ki = 0; ki < n; ki++) {
            uint32_t k = listed ? W->cg.out[ki] : ki;
            if (k == A->at || k == B->at) continue;
            wk_point q = W->cl[k].p;
            double s = (q.x - pa.x) * L->ux + (q.y - pa.y) * L->uy, r = W->cl[k].r;
            if (s < -r || s > len + r) continue;
            double off = (q.x - pa.x) * L->nx + (q.y - pa.y) * L->ny;
            if (fabs(off) > r) continue;
            if (node_behind_piece(W, k, a, off, q, t)) continue;
            /* A node on the line within tolerance of an end of the piece: that
            ** end arrives at the node (else the node would touch the piece
            ** without cutting it, and the group would change nothing).  A
            ** shielded end does not: the node cuts the piece it is shielded
            ** on next to it, and misses its other piece (plan_shields). */
            const wk_wf_shield *sh = NULL;
            if (s <= r && !(W->n_shield && (sh = shield_of(W, a, k)))) {
                if (A->at == WK_NONE) W->v[a].at = k;
                continue;
            }
            if (s >= len - r && !(W->n_shield && (sh = shield_of(W, A->next, k)))) {
                if (B->at == WK_NONE) W->v[A->next].at = k;
                continue;
            }
            if (sh && sh->piece != a) continue;
            if (WK_GROW(R, W->pin, W->cap_pin, W->n_pin + 1) != WK_OK) return R->err.code;
            W->pin[W->n_pin++] = (wk_wf_pinch){a, s, k};
        }
    }
    return WK_OK;
}

/* Step 2c, the progress guarantee: a split seed always cuts its target
** piece at its node, even when rounding put the node a little more than the
** tolerance off the piece's line (detection and resolution must agree, or
** the same event would be found again and again).  Then the pinches are
** sorted by piece. */
/* plan_seed_cuts' pinches by (piece, node), from WF_INDEX_MIN pinches on
** (else 0 slots: it scans them).  It asked for an existing pinch by a scan
** of all pinches per split seed, O(seeds x pinches): 10% of rectilinear
** 10^6 (perf), where groups with forced vertices pinch whole cycles. */
static uint32_t pin_slot(const wk_wavefront *W, uint32_t size, uint32_t a, uint32_t k) {
    uint32_t h = hash_slot(a ^ (k * 0x9E3779B9u), size);
    while (W->pin_ix[h] != WK_NONE && (W->pin[W->pin_ix[h]].piece != a || W->pin[W->pin_ix[h]].node != k))
        h = h + 1 == size ? 0 : h + 1;
    return h;
}

static wk_status plan_seed_cuts(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    /* at most one pinch per seed joins those of plan_pinches: a load of at
    ** most a half */
    uint32_t size = 0;
    if (W->n_pin >= WF_INDEX_MIN) {
        for (size = 64; size < 2 * (W->n_pin + W->n_seeds); size *= 2) {}
        if (WK_GROW(R, W->pin_ix, W->cap_pin_ix, size) != WK_OK) return R->err.code;
        for (uint32_t h = 0; h < size; h++) W->pin_ix[h] = WK_NONE;
        for (uint32_t j = 0; j < W->n_pin; j++) {
            uint32_t h = pin_slot(W, size, W->pin[j].piece, W->pin[j].node);
            if (W->pin_ix[h] == WK_NONE) W->pin_ix[h] = j;
        }
    }
    for (uint32_t i = 0; i < W->n_seeds; i++) {
        const wk_wf_vertex *u = &W->v[W->seeds[i]];
        if (u->ev_kind != WK_WF_SPLIT || u->at == WK_NONE || (W->n_swept && is_swept(W, W->seeds[i]))) continue;
        uint32_t a = u->ev_a, k = u->at;
        const wk_wf_vertex *A = &W->v[a];
        if (!A->alive || A->next != u->ev_b || A->seen != W->stamp) continue;
        const wk_wf_vertex *B = &W->v[A->next];
        if (k == A->at || k == B->at) continue;
        bool have = false;
        if (size) {
            have = W->pin_ix[pin_slot(W, size, a, k)] != WK_NONE;
        } else {
            for (uint32_t j = 0; j < W->n_pin; j++) have |= W->pin[j].piece == a && W->pin[j].node == k;
        }
        if (have) continue;
        const wk_offset_line *L = &W->L[A->eout];
        wk_point pa = A->at != WK_NONE ? W->cl[A->at].p : wk_wf_pos(A, t);
        wk_point pb = B->at != WK_NONE ? W->cl[B->at].p : wk_wf_pos(B, t);
        wk_point q = W->cl[k].p;
        double len = (pb.x - pa.x) * L->ux + (pb.y - pa.y) * L->uy;
        double sq = (q.x - pa.x) * L->ux + (q.y - pa.y) * L->uy;
        bool shielded = W->n_shield && (shield_of(W, a, k) || shield_of(W, A->next, k));
        if (sq <= W->cl[k].r && !shielded) {
            W->v[a].at = k;
        } else if (sq >= len - W->cl[k].r && !shielded) {
            W->v[A->next].at = k;
        } else {
            if (WK_GROW(R, W->pin, W->cap_pin, W->n_pin + 1) != WK_OK) return R->err.code;
            W->pin[W->n_pin++] = (wk_wf_pinch){a, sq, k};
            if (size) W->pin_ix[pin_slot(W, size, a, k)] = W->n_pin - 1;
        }
    }
    if (W->n_pin > 1) qsort(W->pin, W->n_pin, sizeof *W->pin, cmp_pinch);
    return WK_OK;
}

/* Step 3a: the sub-pieces of every piece that touches a node, between
** points (nodes or untouched vertices); zero-length ones vanish. */
static wk_status plan_sub_pieces(wk_wavefront *W) {
    for (uint32_t i = 0; i < W->n_comp; i++) {
        uint32_t a = W->comp[i];
        const wk_wf_vertex *A = &W->v[a];
        uint32_t b = A->next;
        /* pinches are sorted by piece id: binary search this piece's run */
        uint32_t lo = 0, hi = W->n_pin;
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (W->pin[mid].piece < a) lo = mid + 1;
            else hi = mid;
        }
        uint32_t pi0 = lo, pi1 = pi0;
        while (pi1 < W->n_pin && W->pin[pi1].piece == a) pi1++;
        if (A->at == WK_NONE && W->v[b].at == WK_NONE && pi1 == pi0) continue;
        uint32_t from = A->at != WK_NONE ? (A->at | NODE_BIT) : a;
        for (uint32_t j = pi0; j < pi1; j++) {
            uint32_t to = W->pin[j].node | NODE_BIT;
            if (add_sub(W, from, to, A->eout) != WK_OK) return W->R->err.code;
            from = to;
        }
        uint32_t to = W->v[b].at != WK_NONE ? (W->v[b].at | NODE_BIT) : b;
        if (add_sub(W, from, to, A->eout) != WK_OK) return W->R->err.code;
    }
    return WK_OK;
}

/* True if a vertex of the plan between the edges of sub-pieces a and b
** (one's ein, the other's eout) arrives at one of a's two nodes: the two
** pieces are the sides of a spike whose tip is that node. */
static bool spike_tip_at(const wk_wavefront *W, const wk_wf_sub *a, const wk_wf_sub *b) {
    uint32_t p = NODE_OF(a->from), q = NODE_OF(a->to);
    for (uint32_t i = 0; i < W->n_comp; i++) {
        const wk_wf_vertex *u = &W->v[W->comp[i]];
        if ((u->at == p || u->at == q) && ((u->ein == a->edge && u->eout == b->edge) ||
                                           (u->ein == b->edge && u->eout == a->edge)))
            return true;
    }
    return false;
}

/* True if sub-piece a (between two nodes) and its opposite b, sin_ab apart
** in direction, bound a long thin sliver (tolerance.h,
** WK_CANCEL_SLIVER_RADII), or a short one that is a spike: the vertex
** between their edges is at one node and both sides pass within 2 node
** radii of the other (sin L <= 2 r).  Such a spike collapses along itself,
** its tip running to the other node along the bisector of its two edges,
** which is the arc the cancellation leaves.  Refused, the retries merged
** the two nodes at 4 or 8 times the radius, and the merged node took in
** vertices around it that were not part of the spike: a weighted 12-gon H
** with a spike to 5e8 (eps_d 0.5; edges 10 and 11 cancel between nodes 2.6
** apart at t = 0.0096) put the spike's node at y 1.77e8, where paper 004's
** variant (its own wavefront) has the exact one at 4.87e8
** (tests/data/fuzz/mismatch_deforming_h_spike_weights_120.wpoly), and a
** weighted comb with a vertex at 5e10 (eps_d 50; edges 9 and 10, nodes 269
** apart at t = 5.79, merged only at 400) ended faces 5, 6, 7 at t = 5.79,
** where papers 000's and 004's variants end them at t = 28.3
** (mismatch_arrangement_wcomb_32dfdbca.wpoly).  With the rule both are
** planned at eps_d and every variant agrees. */
static bool is_sliver(const wk_wavefront *W, const wk_wf_sub *a, const wk_wf_sub *b, double sin_ab) {
    const wk_wf_cluster *P = &W->cl[NODE_OF(a->from)], *Q = &W->cl[NODE_OF(a->to)];
    double len = sqrt(wf_dist2(P->p, Q->p)), r = fmax(P->r, Q->r);
    if (!(sin_ab * len <= 2 * r)) return false;
    return len >= WK_CANCEL_SLIVER_RADII * r || spike_tip_at(W, a, b);
}

/* Cancel sub-pieces a and b (opposite, between the same two nodes). */
static wk_status cancel_pair(wk_wavefront *W, wk_wf_sub *a, wk_wf_sub *b) {
    /* Only antiparallel pieces can cancel between two distinct
    ** nodes (parallel edges meeting).  Non-parallel ones doing so
    ** mean the two nodes are one point seen at too fine a scale
    ** (a skeleton feature below eps_d next to a sub-tolerance
    ** input feature): the group is planned again, coarser.  A
    ** long thin sliver between them is a crack closing along its
    ** length (tolerance.h, WK_CANCEL_SLIVER_RADII). */
    const wk_offset_line *La = &W->L[a->edge], *Lb = &W->L[b->edge];
    double sin_ab = fabs(La->ux * Lb->uy - La->uy * Lb->ux);
    if (a->edge != b->edge &&
        (La->ux * Lb->ux + La->uy * Lb->uy > 0 || (sin_ab > WK_CANCEL_SIN && !is_sliver(W, a, b, sin_ab)))) {
        W->fail_node[0] = NODE_OF(a->from);
        W->fail_node[1] = NODE_OF(a->to);
        return WK_FAIL(W->R, WK_EALGO, W->P->name, 0,
                       "wavefront: pieces of non-parallel edges %u and %u cancel between "
                       "two nodes",
                       a->edge, b->edge);
    }
    /* 2: cancelled, leaves an arc; 1: one edge folded onto
    ** itself within tolerance, which traces nothing */
    a->dead = b->dead = a->edge == b->edge ? 1 : 2;
    return WK_OK;
}

/* Three or more sub-pieces between two nodes P and Q, both ways
** (W->slot[i0 .. i1)), cancel as the wavefront's interior says: across
** the stretch each piece's line lies at its own offset (at the nodes'
** midpoint), the interior on its left; a piece from P to Q and one from Q
** to P cancel only when the interior lies between them (a sliver
** closing), matched like parentheses across the stretch; a piece left over
** passes both nodes.  The first opposite piece found (the rule for two
** pieces) cancelled across a crack: a 12-gon H with needles near (1e6,
** 1e6), edge 4 of weight 1000: at t = 0.94 reflex vertex 7 (edges 6, 7)
** splits edge 0 beside a spike 0.43 long and 2e-5 wide between edges 6
** and 2, inside a needle between edges 0 and 2, all within eps_d (3e-3)
** of the split's node and the spike tip's.  Across the stretch: edge 0,
** (the crack above vertex 7, outside), edge 6, edge 2.  Edge 0 cancelled
** with edge 2, edge 6 was left to pass on, the split was undone (vertex
** 7's edges paired again) and the arcs closed a cycle (exit 3 in 3
** variants; tests/data/fuzz/invalid_naive_h_needles_spike_in_needle.wpoly).
** Matched across, the spike (edges 6, 2) cancels and edge 0 runs on to
** the split's node; paper 004's variant (its own wavefront) agrees
** (no CGAL: weighted).  Nothing is
** decided (*done false; the rule for two pieces then applies) when the
** order is not clear: two places within rounding, a piece against its
** nodes' direction, one edge twice, or more than MAX_ACROSS pieces (a
** bound on the scratch arrays; such a bundle was never seen). */
static wk_status cancel_across(wk_wavefront *W, uint32_t i0, uint32_t i1, double t, bool *done) {
    *done = false;
    enum { MAX_ACROSS = 16 };
    uint32_t n = i1 - i0;
    if (n < 3 || n > MAX_ACROSS) return WK_OK;
    uint32_t id[MAX_ACROSS];
    double pos[MAX_ACROSS];
    const wk_wf_sub *s0 = &W->sub[W->slot[i0]];
    uint32_t P = s0->from < s0->to ? s0->from : s0->to;
    wk_point p = W->cl[NODE_OF(P)].p, q = W->cl[NODE_OF(s0->from ^ s0->to ^ P)].p;
    wk_point m = {0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
    double dx = q.x - p.x, dy = q.y - p.y;
    uint32_t fwd = 0;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t i = W->slot[i0 + k];
        const wk_wf_sub *a = &W->sub[i];
        const wk_offset_line *L = &W->L[a->edge];
        for (uint32_t j = 0; j < k; j++)
            if (W->sub[id[j]].edge == a->edge) return WK_OK;
        double along = L->ux * dx + L->uy * dy;
        bool from_p = a->from == P;
        if (a->dead || !(from_p ? along > 0 : along < 0)) return WK_OK;
        fwd += from_p;
        /* the line's place across the stretch, P -> Q's left positive: a
        ** piece from P to Q has the interior on that side */
        double d = wk_offset_distance(L, m, t);
        pos[k] = from_p ? -d : d;
        id[k] = i;
    }
    if (fwd == 0 || fwd == n) return WK_OK;
    /* sort by place (insertion sort, n <= 16) */
    for (uint32_t k = 1; k < n; k++)
        for (uint32_t j = k; j > 0 && pos[j - 1] > pos[j]; j--) {
            double x = pos[j];
            pos[j] = pos[j - 1];
            pos[j - 1] = x;
            uint32_t y = id[j];
            id[j] = id[j - 1];
            id[j - 1] = y;
        }
    /* places apart by more than their rounding (WK_SPLIT_SIDE_ULPS ulps of
    ** the point, the line's constant and its travel) */
    for (uint32_t k = 0; k + 1 < n; k++) {
        const wk_offset_line *L = &W->L[W->sub[id[k]].edge];
        double bar = WK_SPLIT_SIDE_ULPS * DBL_EPSILON * (fabs(m.x) + fabs(m.y) + fabs(L->c) + L->w * t);
        if (!(pos[k + 1] - pos[k] > bar)) return WK_OK;
    }
    uint32_t open[MAX_ACROSS], n_open = 0;
    for (uint32_t k = 0; k < n; k++) {
        wk_wf_sub *a = &W->sub[id[k]];
        if (a->from == P) {
            open[n_open++] = id[k];
        } else if (n_open) {
            uint32_t b = open[--n_open];
            if (cancel_pair(W, &W->sub[b], a) != WK_OK) return W->R->err.code;
            W->sub[b].pair_in = id[k]; /* the partner, for commit's arc */
            a->pair_in = b;
        }
    }
    *done = true;
    return WK_OK;
}

/* Step 3b, cancellation: opposite sub-pieces between the same two nodes
** (parallel edges that met) leave an arc. */
static wk_status plan_cancel(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    if (W->n_sub <= 1) return WK_OK;
    if (WK_GROW(R, W->slot, W->cap_slot, W->n_sub) != WK_OK) return R->err.code;
    W->n_slot = 0;
    for (uint32_t i = 0; i < W->n_sub; i++)
        if (IS_NODE(W->sub[i].from) && IS_NODE(W->sub[i].to)) W->slot[W->n_slot++] = i;
    sort_by_endpoints(W, W->slot, W->n_slot);
    for (uint32_t i = 0; i < W->n_slot; i++) {
        if (i == 0 || cmp_sub_key(W, W->slot[i - 1], W->slot[i]) != 0) {
            uint32_t i1 = i + 1;
            while (i1 < W->n_slot && cmp_sub_key(W, W->slot[i], W->slot[i1]) == 0) i1++;
            bool done;
            if (cancel_across(W, i, i1, t, &done) != WK_OK) return R->err.code;
            if (done) {
                i = i1 - 1;
                continue;
            }
        }
        wk_wf_sub *a = &W->sub[W->slot[i]];
        if (a->dead) continue;
        for (uint32_t j = i + 1; j < W->n_slot && cmp_sub_key(W, W->slot[i], W->slot[j]) == 0; j++) {
            wk_wf_sub *b = &W->sub[W->slot[j]];
            if (!b->dead && b->from == a->to && b->to == a->from) {
                if (cancel_pair(W, a, b) != WK_OK) return R->err.code;
                break;
            }
        }
    }
    return WK_OK;
}

static int cmp_by_from(const void *x, const void *y, const wk_wavefront *W) {
    uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    uint32_t fa = W->sub[a].from, fb = W->sub[b].from;
    if (fa != fb) return fa < fb ? -1 : 1;
    return a < b ? -1 : a > b;
}

/* Heap sort of sub-piece ids by (start, id) (no qsort_r in C11). */
static void sort_by_from(const wk_wavefront *W, uint32_t *a, uint32_t n) {
    for (uint32_t k = n / 2; k-- > 0;)
        for (uint32_t i = k;;) {
            uint32_t c = 2 * i + 1;
            if (c >= n) break;
            if (c + 1 < n && cmp_by_from(&a[c], &a[c + 1], W) < 0) c++;
            if (cmp_by_from(&a[i], &a[c], W) >= 0) break;
            uint32_t tmp = a[i];
            a[i] = a[c];
            a[c] = tmp;
            i = c;
        }
    for (uint32_t m = n; m-- > 1;) {
        uint32_t tmp = a[0];
        a[0] = a[m];
        a[m] = tmp;
        for (uint32_t i = 0;;) {
            uint32_t c = 2 * i + 1;
            if (c >= m) break;
            if (c + 1 < m && cmp_by_from(&a[c], &a[c + 1], W) < 0) c++;
            if (cmp_by_from(&a[i], &a[c], W) >= 0) break;
            tmp = a[i];
            a[i] = a[c];
            a[c] = tmp;
            i = c;
        }
    }
}

/* Some live sub-piece runs from x's end back to x's start.  In a large
** group (WF_GRID_MIN sub-pieces) the live ones are looked up by start in
** W->by_from (built by the caller), else scanned. */
static bool has_reverse(const wk_wavefront *W, const wk_wf_sub *x, uint32_t n_by) {
    if (!n_by) {
        for (uint32_t j = 0; j < W->n_sub; j++) {
            const wk_wf_sub *y = &W->sub[j];
            if (!y->dead && y->from == x->to && y->to == x->from) return true;
        }
        return false;
    }
    uint32_t lo = 0, hi = n_by;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (W->sub[W->by_from[mid]].from < x->to) lo = mid + 1;
        else hi = mid;
    }
    for (; lo < n_by && W->sub[W->by_from[lo]].from == x->to; lo++)
        if (W->sub[W->by_from[lo]].to == x->from) return true;
    return false;
}

/* The untouched vertices of the group by place (W->vg, per plan): id j is
** W->comp[j]. */
static wk_status start_vertex_grid(wk_wavefront *W, double t) {
    if (wk_point_grid_reset(W->R, &W->vg, W->cg.x0, W->cg.y0, W->cg.h) != WK_OK)
        return W->R->err.code;
    for (uint32_t j = 0; j < W->n_comp; j++) {
        const wk_wf_vertex *u = &W->v[W->comp[j]];
        if (u->at != WK_NONE) continue;
        wk_point q = wk_wf_pos(u, t);
        if (!isfinite(q.x) || !isfinite(q.y)) return WK_OK; /* scan instead */
        if (wk_point_grid_add(W->R, &W->vg, j, q) != WK_OK) return W->R->err.code;
    }
    W->vg_on = true;
    return WK_OK;
}

/* Step 5a: vertices that meet the group without being at a node yet.  An
** untouched vertex whose pieces both lead to the same node closes a
** triangle of no area with it; an untouched vertex lying on a sub-piece
** between two nodes (where parallel edges met: an end of a collinear step
** of the other side) meets it too, unless it is an input vertex that
** never reaches the piece's line (wf_never_reaches_line).  Each becomes a node
** (*again).
** But a reflex vertex x whose two pieces lead from and back to one node k,
** the tip of a crack outside the wavefront (sub-pieces k -> x -> k, or a
** seed at a node of its own whose pieces k -> node -> k cancel), arrives
** at k if it left k's place within eps_t (left_node_lately; W->swept,
** forced_track_node; a seed's split then cuts nothing, plan_seed_cuts):
** the crack opened within the time tolerance, from a place where eps_d
** makes one point of everything, and closes there.  Kept apart from k, the
** tip ends the crack's two pieces between two nodes, where a third piece
** along them cancels one or the other: a 7-gon with a unit core and
** spikes to 7.4e10 and 2.25e14 (eps_d 2.25e5, eps_t 225), where at
** t = 0.34 a needle collapses at the core while the reflex vertex between
** the two other needles (speed 1.25e8) runs 4.2e7 below it, 1 unit beside
** edge 6's piece: made a node there, edge 6 cancelled the crack's far side
** and faces 2 and 6 met at the core and at the tip
** (tests/data/fuzz/invalid_naive_7gon_spikes_2e14.wpoly); with the first
** spike at x = 6.3 the vertex (speed 4.4e9) splits edge 5 at the far
** spike's tip 8.2e8 below at t = 0.19, in the core's group, and the
** crack's two pieces cancelled into a second arc of faces 1, 2 beside the
** vertex's own, crossing edges 5 and 6's arcs at the tip
** (invalid_naive_7gon_spikes_seed_split.wpoly).  Both closed a cycle
** (exit 3 in four variants).  At the core's node the vertex ends faces 1
** and 2 there (the fifth variant's skeleton before; CGAL keeps two core
** nodes 1.2 apart with the vertex's arc between them, which no node of
** radius eps_d can). */
static wk_status plan_force_touching(wk_wavefront *W, double t, bool *again) {
    wk_run *R = W->R;
    /* a crack tip at a node of its own (its pieces, not pinched, run to k
    ** and back) */
    for (uint32_t i = 0; i < W->n_comp; i++) {
        uint32_t x = W->comp[i];
        const wk_wf_vertex *X = &W->v[x];
        uint32_t k = W->v[X->prev].at;
        if (X->at == WK_NONE || !X->reflex || k == WK_NONE || k == X->at || W->v[X->next].at != k ||
            X->prev == X->next || is_swept(W, x) || !left_node_lately(W, x, W->cl[k].p, W->cl[k].r, t))
            continue;
        bool pinched = false;
        for (uint32_t j = 0; j < W->n_pin; j++) pinched |= W->pin[j].piece == X->prev || W->pin[j].piece == x;
        if (pinched) continue;
        if (wf_push_u32(R, &W->swept, &W->n_swept, &W->cap_swept, x) != WK_OK ||
            wf_force(W, x) != WK_OK)
            return R->err.code;
        *again = true;
    }
    if (*again) return WK_OK;
    uint32_t n_by = 0;
    if (W->n_sub >= WF_GRID_MIN) {
        if (WK_GROW(R, W->by_from, W->cap_by_from, W->n_sub) != WK_OK) return R->err.code;
        for (uint32_t j = 0; j < W->n_sub; j++)
            if (!W->sub[j].dead) W->by_from[n_by++] = j;
        sort_by_from(W, W->by_from, n_by);
    }
    for (uint32_t i = 0; i < W->n_sub; i++) {
        const wk_wf_sub *x = &W->sub[i];
        if (x->dead || !IS_NODE(x->from) || IS_NODE(x->to)) continue;
        if (!has_reverse(W, x, n_by)) continue;
        /* an untouched crack tip */
        if (W->v[x->to].reflex && !is_swept(W, x->to) &&
            left_node_lately(W, x->to, W->cl[NODE_OF(x->from)].p, W->cl[NODE_OF(x->from)].r, t) &&
            wf_push_u32(R, &W->swept, &W->n_swept, &W->cap_swept, x->to) != WK_OK)
            return R->err.code;
        if (wf_force(W, x->to) != WK_OK) return R->err.code;
        *again = true;
    }
    if (*again) return WK_OK;
    for (uint32_t i = 0; i < W->n_sub; i++) {
        const wk_wf_sub *x = &W->sub[i];
        if (x->dead || !IS_NODE(x->from) || !IS_NODE(x->to)) continue;
        wk_point a = W->cl[NODE_OF(x->from)].p, b = W->cl[NODE_OF(x->to)].p;
        const wk_offset_line *L = &W->L[x->edge];
        double len = (b.x - a.x) * L->ux + (b.y - a.y) * L->uy;
        double r = fmax(W->cl[NODE_OF(x->from)].r, W->cl[NODE_OF(x->to)].r);
        if (W->cg_on && !W->vg_on && W->n_comp >= WF_GRID_MIN && start_vertex_grid(W, t) != WK_OK)
            return R->err.code;
        bool listed = false;
        if (W->vg_on) {
            wk_point lo, hi;
            band_box(a, L, len, r, &lo, &hi);
            widen(&lo, &hi, r);
            listed = wk_point_grid_query(&W->vg, lo, hi, (uint64_t)W->n_comp + 16);
        }
        uint32_t n = listed ? W->vg.n_out : W->n_comp;
        for (uint32_t ji = 0; ji < n; ji++) {
            uint32_t j = listed ? W->vg.out[ji] : ji;
            const wk_wf_vertex *u = &W->v[W->comp[j]];
            if (u->at != WK_NONE) continue;
            wk_point q = wk_wf_pos(u, t);
            double sq = (q.x - a.x) * L->ux + (q.y - a.y) * L->uy;
            double off = (q.x - a.x) * L->nx + (q.y - a.y) * L->ny;
            if (sq <= -r || sq >= len + r || fabs(off) > r) continue;
            if (wf_never_reaches_line(W, W->comp[j], x->edge)) continue;
            if (wf_force(W, W->comp[j]) != WK_OK) return R->err.code;
            *again = true;
        }
    }
    return WK_OK;
}

/* Step 4a: each node's incoming and outgoing sub-pieces in its slots
** (slot[first .. first + count); incoming ones flagged with NODE_BIT). */
static wk_status plan_slots(wk_wavefront *W) {
    wk_run *R = W->R;
    for (uint32_t k = 0; k < W->n_cl; k++) W->cl[k].count = 0;
    for (uint32_t i = 0; i < W->n_sub; i++) {
        wk_wf_sub *s = &W->sub[i];
        if (s->dead) continue;
        if (IS_NODE(s->from)) W->cl[NODE_OF(s->from)].count++;
        if (IS_NODE(s->to)) W->cl[NODE_OF(s->to)].count++;
    }
    uint32_t total = 0;
    for (uint32_t k = 0; k < W->n_cl; k++) {
        W->cl[k].first = total;
        total += W->cl[k].count;
        W->cl[k].count = 0;
    }
    if (WK_GROW(R, W->slot, W->cap_slot, total + 1) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < W->n_sub; i++) {
        wk_wf_sub *s = &W->sub[i];
        if (s->dead) continue;
        if (IS_NODE(s->from)) {
            wk_wf_cluster *c = &W->cl[NODE_OF(s->from)];
            W->slot[c->first + c->count++] = i; /* outgoing at from */
        }
        if (IS_NODE(s->to)) {
            wk_wf_cluster *c = &W->cl[NODE_OF(s->to)];
            W->slot[c->first + c->count++] = i | NODE_BIT; /* incoming at to */
        }
    }
    return WK_OK;
}

/* True if piece a -> a.next has a pinch in this plan (pinches sorted by
** piece: binary search, as plan_sub_pieces). */
static bool piece_pinched(const wk_wavefront *W, uint32_t a) {
    uint32_t lo = 0, hi = W->n_pin;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (W->pin[mid].piece < a) lo = mid + 1;
        else hi = mid;
    }
    return lo < W->n_pin && W->pin[lo].piece == a;
}

/* Vertex u (not a node) is a plain member of the plan: walked, untouched,
** not already forced this round (zip marks those with ZIP_MARK in `at`). */
#define ZIP_MARK (WK_NONE - 1)
static bool zip_plain(const wk_wavefront *W, uint32_t u) {
    return !IS_NODE(u) && W->v[u].alive && W->v[u].seen == W->stamp && W->v[u].at == WK_NONE;
}

/* The incoming direction of edge ea equals the outgoing one of eb (the
** overlap test of plan_force_overlaps). */
static bool zip_overlap_dirs(const wk_wavefront *W, uint32_t ea, uint32_t eb) {
    double d = fabs(angle_of(&W->L[ea], true) - angle_of(&W->L[eb], false));
    return d <= WK_ANGLE_EQ || fabs(d - TWO_PI) <= WK_ANGLE_EQ;
}

/* The radius within which untouched vertex u arrives at a node of radius r
** (plan_arrivals). */
static double zip_arrival_radius(const wk_wavefront *W, uint32_t u, double r, double t) {
    const wk_wf_vertex *U = &W->v[u];
    double speed = fabs(U->vel.x) + fabs(U->vel.y);
    return arrival_radius(W, r, speed * (W->t_last - t));
}

static wk_status zip_force(wk_wavefront *W, uint32_t u) {
    W->v[u].at = ZIP_MARK;
    return wf_force(W, u);
}

/* Step 5b's zipper.  Two antiparallel chains of pieces lying on one line
** (a corridor of a rectilinear polygon whose two walls, stepped, meet along
** their whole length at once: rectilinear n = 10^5 ends in one group whose
** cycle of 12,487 vertices lies flat on a line) meet at node P: the A chain
** arrives there along ea from fa, the B chain leaves along eb to fb, and
** `far` (the nearer of fa, fb) was just forced.  The next round would make
** far a node Q, pinch the other chain's piece at Q, cancel the two
** stretches P..Q, and find the same overlap at Q with the next vertex: one
** vertex per round, each round a plan of the whole cycle (6,052 rounds
** there, 98% of the run).  This walks the chains on, forcing what those
** rounds would force at this frontier, in their order, while the picture
** is that simple: both chains' next vertices plain members of the plan,
** their pieces not pinched, on the line to rounding (WK_BEHIND_ULPS, so no
** node is behind a piece), and the next points clear of each other and of
** the last node (WK_ZIP_CLEAR).  Otherwise it stops, and the rounds go on
** from the last forced vertex as before.  The forced set is the rounds';
** only its order across frontiers differs (several frontiers are zipped
** one after the other, not a vertex each per round), which leaves the
** plan's nodes, arcs and pairs the same (eight generator families at
** 10^3 and 10^4, rectilinear 10^5: JSON identical to the rounds'). */
static wk_status zip_overlap(wk_wavefront *W, double t, wk_point P, uint32_t fa, uint32_t ea,
                             uint32_t fb, uint32_t eb, uint32_t far) {
    for (uint32_t guard = 0; guard < W->n_comp; guard++) {
        wk_point Q = wk_wf_pos(&W->v[far], t);
        uint32_t other = far == fa ? fb : fa;
        if (IS_NODE(other) || W->v[other].seen != W->stamp) return WK_OK;
        double rq = node_radius_at(W, Q), clear = WK_ZIP_CLEAR * zip_arrival_radius(W, far, rq, t);
        if (wf_dist2(P, Q) <= clear * clear) return WK_OK;
        if (find_cluster(W, Q) != WK_NONE) return WK_OK;
        wk_point po = wk_wf_pos(&W->v[other], t);
        double d_o = sqrt(wf_dist2(Q, po)), r_o = zip_arrival_radius(W, other, rq, t);
        bool both = d_o <= r_o; /* other arrives at Q too (a tie) */
        if (!both) {
            if (d_o <= WK_ZIP_CLEAR * fmax(r_o, clear / WK_ZIP_CLEAR)) return WK_OK;
            /* the other chain's piece is pinched at Q: Q on its line */
            const wk_offset_line *L = &W->L[other == fa ? ea : eb];
            double off = (Q.x - po.x) * L->nx + (Q.y - po.y) * L->ny;
            double ulp = DBL_EPSILON * (fabs(Q.x) + fabs(Q.y));
            if (!(fabs(off) <= fmin(WK_BEHIND_ULPS * ulp, rq))) return WK_OK;
        }
        /* advance the chains whose end arrives at Q */
        if (far == fa || both) {
            uint32_t na = W->v[fa].prev;
            if (!zip_plain(W, na) || piece_pinched(W, na) || na == fb) return WK_OK;
            ea = W->v[fa].ein;
            fa = na;
        }
        if (far == fb || both) {
            uint32_t nb = W->v[fb].next;
            if (!zip_plain(W, nb) || piece_pinched(W, fb) || nb == fa) return WK_OK;
            eb = W->v[fb].eout;
            fb = nb;
        }
        if (fa == fb || !zip_overlap_dirs(W, ea, eb)) return WK_OK;
        P = Q;
        far = wf_dist2(wk_wf_pos(&W->v[fa], t), P) < wf_dist2(wk_wf_pos(&W->v[fb], t), P) ? fa : fb;
        if (zip_force(W, far) != WK_OK) return W->R->err.code;
    }
    return WK_OK;
}

/* Step 5b, overlap: an incoming and an outgoing sub-piece leaving a node in
** the same direction are antiparallel edges lying on each other.  Their
** common part vanishes now, so the nearer far end (an untouched vertex
** lying on the other piece) meets it: it becomes a node (*again).  The
** vertices a long overlap would reveal one round after another are forced
** now (zip_overlap). */
static wk_status plan_force_overlaps(wk_wavefront *W, double t, bool *again) {
    wk_status st = WK_OK;
    uint32_t nf0 = W->n_forced;
    for (uint32_t k = 0; k < W->n_cl && st == WK_OK; k++) {
        wk_wf_cluster *c = &W->cl[k];
        for (uint32_t j = 0; j < c->count; j++) {
            uint32_t in = W->slot[c->first + j];
            if (!(in & NODE_BIT)) continue;
            in &= ~NODE_BIT;
            double a = angle_of(&W->L[W->sub[in].edge], true);
            for (uint32_t m = 0; m < c->count; m++) {
                uint32_t out = W->slot[c->first + m];
                if (out & NODE_BIT) continue;
                double d = fabs(a - angle_of(&W->L[W->sub[out].edge], false));
                if (d > WK_ANGLE_EQ && fabs(d - TWO_PI) > WK_ANGLE_EQ) continue;
                wk_point pin = point_pos(W, W->sub[in].from, t);
                wk_point pout = point_pos(W, W->sub[out].to, t);
                uint32_t far = wf_dist2(pin, c->p) < wf_dist2(pout, c->p) ? W->sub[in].from : W->sub[out].to;
                if (IS_NODE(far)) continue; /* equal pieces were cancelled; spike check below */
                *again = true;
                if (W->v[far].at == ZIP_MARK) continue; /* zipped from another node */
                if ((st = zip_force(W, far)) != WK_OK) break;
                st = zip_overlap(W, t, c->p, W->sub[in].from, W->sub[in].edge, W->sub[out].to,
                                 W->sub[out].edge, far);
                if (st != WK_OK) break;
            }
            if (st != WK_OK) break;
        }
    }
    for (uint32_t i = nf0; i < W->n_forced; i++) W->v[W->forced[i]].at = WK_NONE;
    return st == WK_OK ? WK_OK : W->R->err.code;
}

/* Step 4b, pairing at each node: an incoming sub-piece continues with the
** first free outgoing one clockwise from it (the wavefront interior lies in
** that sector); each pair becomes a new wavefront vertex.  Step 5c: a turn
** of (nearly) 2 pi is a zero-width spike, some vertex lies on one of the two
** sub-pieces: the nearer far end becomes a node (*again; every spike of the
** round is collected before planning again). */
static wk_status plan_pairs(wk_wavefront *W, double t, bool *again) {
    wk_run *R = W->R;
    for (uint32_t k = 0; k < W->n_cl; k++) {
        wk_wf_cluster *c = &W->cl[k];
        W->fail_node[0] = k; /* a failure here names node k */
        uint32_t nin = 0, nout = 0;
        for (uint32_t j = 0; j < c->count; j++) (W->slot[c->first + j] & NODE_BIT) ? nin++ : nout++;
        if (nin != nout)
            return WK_FAIL(R, WK_EALGO, W->P->name, 0,
                           "wavefront: inconsistent wavefront at (%.17g, %.17g), t = %.17g: %u pieces "
                           "arrive, %u leave",
                           c->p.x, c->p.y, t, nin, nout);
        for (uint32_t j = 0; j < c->count; j++) {
            uint32_t in = W->slot[c->first + j];
            if (!(in & NODE_BIT)) continue;
            in &= ~NODE_BIT;
            double a = angle_of(&W->L[W->sub[in].edge], true);
            uint32_t best = WK_NONE;
            double bturn = INFINITY;
            for (uint32_t m = 0; m < c->count; m++) {
                uint32_t out = W->slot[c->first + m];
                if (out & NODE_BIT) continue;
                if (W->sub[out].pair_out != WK_NONE) continue;
                double turn = cw_turn(a, angle_of(&W->L[W->sub[out].edge], false));
                if (turn < bturn) {
                    bturn = turn;
                    best = out;
                }
            }
            if (best == WK_NONE)
                return WK_FAIL(R, WK_EALGO, W->P->name, 0,
                               "wavefront: cannot pair wavefront pieces at (%.17g, %.17g), t = %.17g",
                               c->p.x, c->p.y, t);
            if (bturn > TWO_PI - WK_SPIKE_TURN) {
                wk_wf_sub *si = &W->sub[in], *so = &W->sub[best];
                wk_point pin = point_pos(W, si->from, t), pout = point_pos(W, so->to, t);
                uint32_t far = wf_dist2(pin, c->p) < wf_dist2(pout, c->p) ? si->from : so->to;
                if (IS_NODE(far))
                    return WK_FAIL(R, WK_EALGO, W->P->name, 0,
                                   "wavefront: unresolved spike at (%.17g, %.17g), t = %.17g", c->p.x,
                                   c->p.y, t);
                if (wf_force(W, far) != WK_OK) return R->err.code;
                *again = true;
                W->sub[in].pair_in = W->sub[best].pair_out = W->n_pair;
                continue;
            }
            if (WK_GROW(R, W->pair, W->cap_pair, W->n_pair + 1) != WK_OK) return R->err.code;
            W->sub[in].pair_in = W->n_pair;
            W->sub[best].pair_out = W->n_pair;
            W->pair[W->n_pair++] = (wk_wf_pair){in, best, k, WK_NONE};
        }
    }
    W->fail_node[0] = WK_NONE;
    return WK_OK;
}

/* Plan the group (the steps of the note at the top).  Returns WK_OK with
** *again set when a vertex was forced to become a node: plan again. */
static wk_status plan(wk_wavefront *W, double t, bool *again) {
    wk_run *R = W->R;
    *again = false;
    W->n_cl = W->n_pin = W->n_sub = W->n_pair = W->n_own = 0;
    W->fail_node[0] = W->fail_node[1] = WK_NONE;
    if (plan_nodes(W, t) != WK_OK || plan_shields(W, t) != WK_OK || plan_slow_stretches(W, t) != WK_OK)
        return R->err.code;
    if (plan_arrivals(W, t) != WK_OK) return R->err.code;
    if (W->local_walk && !local_walk_suffices(W, t)) {
        /* the group reaches beyond the local walk: take whole cycles */
        W->local_walk = false;
        if (collect_cycles(W) != WK_OK) return R->err.code;
        if (plan_arrivals(W, t) != WK_OK) return R->err.code;
    }
    if (plan_pinches(W, t) != WK_OK || plan_seed_cuts(W, t) != WK_OK) return R->err.code;
    if (W->local_walk && local_walk_outgrown(W)) {
        W->local_walk = false;
        W->n_pin = 0;
        if (collect_cycles(W) != WK_OK || plan_arrivals(W, t) != WK_OK) return R->err.code;
        if (plan_pinches(W, t) != WK_OK || plan_seed_cuts(W, t) != WK_OK) return R->err.code;
    }
    if (plan_sub_pieces(W) != WK_OK || plan_cancel(W, t) != WK_OK) return R->err.code;
    if (plan_force_touching(W, t, again) != WK_OK) return R->err.code;
    if (*again) return WK_OK;
    if (plan_slots(W) != WK_OK || plan_force_overlaps(W, t, again) != WK_OK) return R->err.code;
    if (*again) return WK_OK;
    return plan_pairs(W, t, again);
}

/* -------------------------------------------------------------- commit */

/* The time of node k: the group's, or for a node of one seed (plan_shields)
** its seed's event time (t .. t_last).  The vertices a split makes there
** start on their lines at that time: a split of a hole's edge eps_t early
** (1.4e-10, the apex 1e-9 short of the edge) puts the two new vertices on
** the edge's line in the wrong order (the apex's two lines cross it on the
** other side of each other until it arrives), and the apex in front of
** the other two then met one of them (three holes, apexes 6e-10 apart;
** test_near_touch.py --sweep 1000 case 701, not CGAL's). */
static double node_time(const wk_wavefront *W, uint32_t k, double t) {
    uint32_t s = W->cl[k].own;
    return s == WK_NONE || !(W->v[s].ev_t > t) ? t : W->v[s].ev_t;
}

static uint32_t sk_node(wk_wavefront *W, uint32_t k, double t) {
    wk_wf_cluster *c = &W->cl[k];
    t = node_time(W, k, t);
    if (c->sk == WK_NONE) {
        uint32_t id;
        if (wk_skeleton_add_node(W->R, W->S, c->p.x + W->origin.x, c->p.y + W->origin.y, t, &id) !=
            WK_OK)
            return WK_NONE;
        c->sk = id;
    }
    return c->sk;
}

/* Parallel edges that share a vertex lie on one line: the vertex between
** them has WK_VEL_STRAIGHT (equal weights) or WK_VEL_COLLINEAR kinetics. */
static bool on_one_line(const wk_wf_vertex *u) {
    return u->alive && (u->vkind == WK_VEL_COLLINEAR || u->vkind == WK_VEL_STRAIGHT);
}

/* The node where run vertex i (W->run[i]) is at time t, created once: its
** own start node if it was born now, else a new node at its position. */
static wk_status run_node(wk_wavefront *W, uint32_t i, double t, uint32_t *node) {
    if (W->run_node[i] == WK_NONE) {
        wk_wf_vertex *U = &W->v[W->run[i]];
        if (U->t0 == t) {
            W->run_node[i] = U->node;
        } else {
            wk_point q = wk_wf_pos(U, t);
            if (wk_skeleton_add_node(W->R, W->S, q.x + W->origin.x, q.y + W->origin.y, t,
                                     &W->run_node[i]) != WK_OK)
                return W->R->err.code;
        }
    }
    *node = W->run_node[i];
    return WK_OK;
}

/* Link a -> b in the collinear rule's rebuild, listing a as fresh when its
** next changes (wk_wf_last_group: "created or relinked"), as commit() does
** for every tail.  The vertex before the run (prev(u0)) is an old vertex
** that gets a new next here.  Unlisted, a finder that files what it tracks
** on a piece under the piece's start vertex (paper 000's finder: its
** moving Steiner vertex F on prev(u0) -> u0, u0 swept by the rule)
** never heard that the piece had ended: F stayed on it, later switched
** from it onto an unrelated piece of the same edge, and a reflex vertex
** split there, 124 units off its line (stress s1-c04321-weight_ratio,
** exit 3 on valid input: the rule on edges 4 and 8 at t = 6.5e-4 relinked
** vertex 243; tests/data/degenerate/arr_collinear_relink_stale_piece.wpoly). */
static wk_status relink(wk_wavefront *W, uint32_t a, uint32_t b) {
    bool changed = W->v[a].next != b;
    wf_link(W, a, b);
    return changed ? wf_mark_fresh(W, a) : WK_OK;
}

/* The collinear rule (000, section 1).  Vertex vi sits between parallel
** edges of different weight, which no moving vertex can join.  Take the
** maximal run of consecutive pieces on that line (a run, not one pair: three
** parallel walls can meet at once); the winning weight (lowest by default,
** highest with --collinear higher) survives, every other piece of the run is
** swept at once, leaving an arc along it at time t between its face and the
** surviving piece that extends over it (the one before it, else the one
** after it).  Vertices of the run that touch a swept piece end here; new
** vertices join the surviving pieces. */
wk_status wf_collinear_rule(wk_wavefront *W, uint32_t vi, double t) {
    wk_run *R = W->R;
    if (!on_one_line(&W->v[vi])) return WK_OK;
    /* run[0]: the vertex before the run's first piece; run[m]: after its
    ** last; run[1..m-1] lie between pieces of the run */
    uint32_t u0 = vi, um = vi, guard = 0;
    while (on_one_line(&W->v[u0])) {
        u0 = W->v[u0].prev;
        if (++guard > W->nv) goto cyclic;
    }
    while (on_one_line(&W->v[um])) {
        um = W->v[um].next;
        if (++guard > W->nv) goto cyclic;
    }
    W->n_run = 0;
    for (uint32_t u = u0;; u = W->v[u].next) {
        if (WK_GROW(R, W->run, W->cap_run, W->n_run + 1) != WK_OK ||
            WK_GROW(R, W->run_node, W->cap_run_node, W->n_run + 1) != WK_OK)
            return R->err.code;
        W->run[W->n_run] = u;
        W->run_node[W->n_run++] = WK_NONE;
        if (u == um) break;
    }
    uint32_t m = W->n_run - 1;
    /* piece i (1..m) runs run[i-1] -> run[i] on edge piece_edge(i) */
#define PIECE_EDGE(i) (W->v[W->run[(i) - 1]].eout)
    bool lower = R->opt.collinear == WK_COLLINEAR_LOWER;
    double best = W->L[PIECE_EDGE(1)].w;
    for (uint32_t i = 2; i <= m; i++) {
        double w = W->L[PIECE_EDGE(i)].w;
        if (lower ? w < best : w > best) best = w;
    }
    uint32_t first_winner = WK_NONE;
    for (uint32_t i = 1; i <= m && first_winner == WK_NONE; i++)
        if (W->L[PIECE_EDGE(i)].w == best) first_winner = PIECE_EDGE(i);
    /* arcs along the losing pieces */
    uint32_t ext = first_winner;
    bool changed = false;
    for (uint32_t i = 1; i <= m; i++) {
        uint32_t e = PIECE_EDGE(i);
        if (W->L[e].w == best) {
            ext = e;
            continue;
        }
        uint32_t a, b;
        if (run_node(W, i - 1, t, &a) != WK_OK || run_node(W, i, t, &b) != WK_OK) return R->err.code;
        if (wf_add_arc(W, a, b, ext, e) != WK_OK) return R->err.code;
        wk_event ev = {t, 0, 0, e, ext, WK_NONE};
        wk_notify_event(R, WK_COUNTER_collinear_resolutions, &ev);
        changed = true;
    }
    if (!changed) return WK_OK;
    /* rebuild: cur is the last vertex of the new wavefront, cur_out the
    ** edge leaving it */
    uint32_t cur = W->v[u0].prev, cur_out = W->v[u0].ein;
    for (uint32_t i = 0; i <= m; i++) {
        uint32_t u = W->run[i];
        wk_wf_vertex *U = &W->v[u];
        uint32_t ein = i == 0 ? U->ein : PIECE_EDGE(i);
        uint32_t eout = i == m ? U->eout : PIECE_EDGE(i + 1);
        bool lost_before = i > 0 && W->L[ein].w != best;
        bool lost_after = i < m && W->L[eout].w != best;
        if (!lost_before && !lost_after) {
            wf_link(W, cur, u); /* untouched */
            cur = u;
            cur_out = U->eout;
            continue;
        }
        uint32_t nd;
        if (run_node(W, i, t, &nd) != WK_OK) return R->err.code;
        wk_point q = wk_wf_pos(U, t);
        uint32_t p_next = U->next;
        if (wf_terminate(W, u, nd) != WK_OK) return R->err.code;
        /* the edge that leaves this point in the new wavefront */
        uint32_t leave = i == m ? eout : (lost_after ? cur_out : eout);
        if (i == 0) leave = first_winner;
        if (lost_after && i > 0 && i < m && W->L[ein].w == best) leave = ein;
        if (i < m && !lost_after) leave = eout;
        if (leave != cur_out) {
            uint32_t g = wf_new_vertex(W, cur_out, leave, q, t, nd);
            if (g == WK_NONE || wf_mark_fresh(W, g) != WK_OK || relink(W, cur, g) != WK_OK)
                return R->err.code;
            cur = g;
            cur_out = leave;
        }
        if (i == m && relink(W, cur, p_next) != WK_OK) return R->err.code;
    }
#undef PIECE_EDGE
    return WK_OK;
cyclic:
    return WK_FAIL(R, WK_EALGO, W->P->name, 0,
                   "wavefront: a whole wavefront cycle lies on one line at t = %.17g", t);
}

/* Follow pass-through pairs (same edge on both sides: no vertex) to the
** vertex at the head of sub-piece s. */
static uint32_t head_vertex(wk_wavefront *W, uint32_t s) {
    for (uint32_t guard = 0; guard <= W->n_sub; guard++) {
        wk_wf_sub *x = &W->sub[s];
        if (!IS_NODE(x->to)) return x->to;
        wk_wf_pair *p = &W->pair[x->pair_in];
        if (p->vertex != WK_NONE) return p->vertex;
        s = p->out;
    }
    return WK_NONE;
}

static wk_status commit(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    /* skeleton nodes and arcs of arriving vertices */
    for (uint32_t i = 0; i < W->n_comp; i++) {
        uint32_t u = W->comp[i];
        if (W->v[u].at == WK_NONE) continue;
        uint32_t sk = sk_node(W, W->v[u].at, t);
        if (sk == WK_NONE || wf_terminate(W, u, sk) != WK_OK) return R->err.code;
    }
    /* cancelled pairs leave arcs: face of x->y on its right.  a's partner
    ** is the first cancelled sub-piece from a's end to its start; in a large
    ** group they are looked up by start (W->by_from, increasing ids within a
    ** start, so the same first one), else scanned. */
    uint32_t n_by = 0;
    for (uint32_t i = 0; i < W->n_sub; i++) n_by += W->sub[i].dead == 2;
    if (n_by >= WF_GRID_MIN) {
        if (WK_GROW(R, W->by_from, W->cap_by_from, n_by) != WK_OK) return R->err.code;
        n_by = 0;
        for (uint32_t i = 0; i < W->n_sub; i++)
            if (W->sub[i].dead == 2) W->by_from[n_by++] = i;
        sort_by_from(W, W->by_from, n_by);
    } else {
        n_by = 0;
    }
    for (uint32_t i = 0; i < W->n_sub; i++) {
        wk_wf_sub *a = &W->sub[i];
        if (a->dead != 2) continue;
        a->dead = 1;
        uint32_t j0 = 0, j1 = W->n_sub;
        if (n_by) {
            uint32_t lo = 0, hi = n_by;
            while (lo < hi) {
                uint32_t mid = lo + (hi - lo) / 2;
                if (W->sub[W->by_from[mid]].from < a->to) lo = mid + 1;
                else hi = mid;
            }
            j0 = lo;
            j1 = n_by;
        }
        /* a partner cancel_across matched (the first found otherwise) */
        if (a->pair_in != WK_NONE) j0 = j1 = 0;
        if (a->pair_in != WK_NONE && W->sub[a->pair_in].dead == 2) {
            W->sub[a->pair_in].dead = 1;
            uint32_t x = sk_node(W, NODE_OF(a->from), t), y = sk_node(W, NODE_OF(a->to), t);
            if (x == WK_NONE || y == WK_NONE || wf_add_arc(W, x, y, W->sub[a->pair_in].edge, a->edge) != WK_OK)
                return R->err.code;
        }
        for (uint32_t jj = j0; jj < j1; jj++) {
            uint32_t j = n_by ? W->by_from[jj] : jj;
            wk_wf_sub *b = &W->sub[j];
            if (n_by && b->from != a->to) break;
            if (b->dead == 2 && b->from == a->to && b->to == a->from) {
                b->dead = 1;
                uint32_t x = sk_node(W, NODE_OF(a->from), t), y = sk_node(W, NODE_OF(a->to), t);
                if (x == WK_NONE || y == WK_NONE || wf_add_arc(W, x, y, b->edge, a->edge) != WK_OK)
                    return R->err.code;
                break;
            }
        }
    }
    /* new vertices */
    for (uint32_t i = 0; i < W->n_pair; i++) {
        wk_wf_pair *p = &W->pair[i];
        uint32_t ein = W->sub[p->in].edge, eout = W->sub[p->out].edge;
        if (ein == eout) continue; /* the piece just passes through */
        uint32_t sk = sk_node(W, p->node, t);
        if (sk == WK_NONE) return R->err.code;
        uint32_t v = wf_new_vertex(W, ein, eout, W->cl[p->node].p, node_time(W, p->node, t), sk);
        if (v == WK_NONE || wf_mark_fresh(W, v) != WK_OK) return R->err.code;
        W->v[v].gap_made = W->n_gap_shield && input_side_node(W, p->node);
        p = &W->pair[i];
        p->vertex = v;
    }
    /* links: every live sub-piece joins the vertex at its tail to the one at
    ** its head; pass-through pairs are followed */
    for (uint32_t i = 0; i < W->n_sub; i++) {
        wk_wf_sub *s = &W->sub[i];
        if (s->dead) continue;
        uint32_t tail;
        if (IS_NODE(s->from)) {
            tail = W->pair[s->pair_out].vertex;
            if (tail == WK_NONE) continue; /* inside a pass-through chain */
        } else {
            tail = s->from;
        }
        uint32_t head = head_vertex(W, i);
        if (head == WK_NONE)
            return WK_FAIL(R, WK_EALGO, W->P->name, 0, "wavefront: broken wavefront cycle at t = %.17g", t);
        wf_link(W, tail, head);
        /* tail's next changed: its cycle is walked again by refresh */
        if (wf_mark_fresh(W, tail) != WK_OK) return R->err.code;
    }
    wk_event e = {t, 0, 0, WK_NONE, WK_NONE, WK_NONE};
    wk_notify_event(R, WK_COUNTER_simultaneous_event_groups, &e);
    return WK_OK;
}

/* Count what happened in this group for the observer (counts only). */
static wk_status count_group(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    for (uint32_t i = 0; i < W->n_comp; i++) {
        const wk_wf_vertex *u = &W->v[W->comp[i]];
        if (u->at == WK_NONE) continue;
        W->cl[u->at].arrive++;
        W->cl[u->at].reflex += u->reflex;
    }
    for (uint32_t i = 0; i < W->n_pin; i++) W->cl[W->pin[i].node].pinches++;
    for (uint32_t i = 0; i < W->n_pair; i++)
        if (W->sub[W->pair[i].in].edge != W->sub[W->pair[i].out].edge) W->cl[W->pair[i].node].pairs++;
    for (uint32_t k = 0; k < W->n_cl; k++) {
        const wk_wf_cluster *c = &W->cl[k];
        wk_event e = {t, c->p.x, c->p.y, k, c->arrive, c->reflex};
        if (c->reflex >= 2) wk_notify_event(R, WK_COUNTER_multi_split_events, &e);
        else if (c->reflex == 1 && c->pinches) wk_notify_event(R, WK_COUNTER_split_events, &e);
        else if (c->arrive >= 2) wk_notify_event(R, WK_COUNTER_edge_events, &e);
    }
    /* a touched cycle vanished if every vertex of it arrived at a node and
    ** none of its nodes starts a new vertex (flag 1: alive) */
    if (WK_GROW(R, W->cycflag, W->cap_cycflag, W->n_cyc + 1) != WK_OK) return R->err.code;
    memset(W->cycflag, 0, W->n_cyc);
    if (W->local_walk) W->cycflag[0] = 1; /* id 0: stretches of cycles looked at in part */
    for (uint32_t i = 0; i < W->n_comp; i++) {
        const wk_wf_vertex *u = &W->v[W->comp[i]];
        if (u->at == WK_NONE || W->cl[u->at].pairs) W->cycflag[u->cyc] = 1;
    }
    for (uint32_t c = 0; c < W->n_cyc; c++) {
        if (W->cycflag[c]) continue;
        wk_event e = {t, 0, 0, c, WK_NONE, WK_NONE};
        wk_notify_event(R, WK_COUNTER_vanishing_components, &e);
    }
    /* an edge event (no piece cut) whose one new vertex is reflex: 000's
    ** reflex-preserving edge event */
    for (uint32_t i = 0; i < W->n_pair; i++) {
        const wk_wf_pair *p = &W->pair[i];
        const wk_wf_cluster *c = &W->cl[p->node];
        if (p->vertex == WK_NONE || c->pinches || c->arrive < 2 || c->pairs != 1) continue;
        if (!W->v[p->vertex].reflex) continue;
        wk_event e = {t, c->p.x, c->p.y, p->node, c->arrive, c->reflex};
        wk_notify_event(R, WK_COUNTER_reflex_preserving_edge_events, &e);
    }
    return WK_OK;
}

static wk_status check_cycles_sane(wk_wavefront *W) {
    for (uint32_t i = 0; i < W->n_fresh; i++) {
        uint32_t f = W->fresh[i];
        if (!W->v[f].alive) continue;
        /* a few steps around each fresh vertex: enough to see a cycle of
        ** fewer than 3 vertices or a broken link next to the change */
        uint32_t len = 0, u = f;
        do {
            if (!W->v[u].alive || W->v[W->v[u].next].prev != u)
                return WK_FAIL(W->R, WK_EALGO, W->P->name, 0,
                               "wavefront: broken wavefront cycle after t = %.17g", W->t_now);
            u = W->v[u].next;
            ++len;
        } while (u != f && len < 3);
        if (len < 3 && u == f)
            return WK_FAIL(W->R, WK_EALGO, W->P->name, 0,
                           "wavefront: wavefront cycle of %u vertices after t = %.17g", len, W->t_now);
    }
    /* No live vertex may still link to a vertex the group ended.  The walk
    ** above starts at the fresh vertices only: a group that ended a vertex
    ** without relinking its live neighbour left that neighbour's next on
    ** the dead vertex, and a later cycle walk over the broken links
    ** (wk_wf_near_split's) never came back: a star 32-gon with a vertex
    ** moved 1e11 out, eps_d 100, a local-walk group widened to eps_g 200
    ** whose pinches made the first vertex of a stretch arrive at the node
    ** after local_walk_suffices had passed
    ** (tests/data/fuzz/timeout_motorcycle_star_far_vertex_1e11.wpoly).
    ** Failing here (WK_EALGO) hands the input to the caller's fallback. */
    for (uint32_t i = 0; i < W->n_dead; i++) {
        const wk_wf_vertex *d = &W->v[W->dead[i]];
        if ((W->v[d->next].alive && W->v[d->next].prev == W->dead[i]) ||
            (W->v[d->prev].alive && W->v[d->prev].next == W->dead[i]))
            return WK_FAIL(W->R, WK_EALGO, W->P->name, 0,
                           "wavefront: a live vertex links to an ended one after t = %.17g", W->t_now);
    }
    return WK_OK;
}

/* A cycle that the group left with zero area: every vertex on one line
** (within a tolerance) and its pieces covering the line from both sides
** exactly once, as two walls met flat (the group resolution, working with
** nodes eps_d apart, can leave one with a zero-length piece and an
** antiparallel vertex: walls at equal levels far from the origin meeting
** 1e-10 apart in time).  The whole cycle vanishes now: each vertex ends at
** the node of its place, and each stretch of the line gets one arc between
** the faces of the piece covering it from either side (the piece's face lies
** on its right).  *done is false, and nothing is changed, if the cycle is not
** of that kind. */
static wk_status collapse_flat_cycle(wk_wavefront *W, uint32_t f, double t, bool *done) {
    wk_run *R = W->R;
    *done = false;
    const wk_offset_line *L = &W->L[W->v[f].ein];
    wk_point o = wk_wf_pos(&W->v[f], t);
    double tol = WK_FLAT_CYCLE_SLACK * W->eps_d;
    /* the cycle's places along L's direction (s) and its pieces */
    uint32_t len = 0, u = f;
    do {
        wk_point q = wk_wf_pos(&W->v[u], t);
        double off = (q.x - o.x) * L->nx + (q.y - o.y) * L->ny;
        if (fabs(off) > tol || ++len > 64) return WK_OK; /* not flat, or too big to care */
        u = W->v[u].next;
    } while (u != f);
    double sv[64];
    uint32_t cyc[64];
    u = f;
    for (uint32_t i = 0; i < len; i++, u = W->v[u].next) {
        wk_point q = wk_wf_pos(&W->v[u], t);
        cyc[i] = u;
        sv[i] = (q.x - o.x) * L->ux + (q.y - o.y) * L->uy;
    }
    /* distinct breakpoints (within tol), sorted */
    double bp[64];
    uint32_t nb = 0;
    for (uint32_t i = 0; i < len; i++) {
        bool have = false;
        for (uint32_t j = 0; j < nb; j++) have |= fabs(bp[j] - sv[i]) <= tol;
        if (!have) bp[nb++] = sv[i];
    }
    for (uint32_t i = 1; i < nb; i++)
        for (uint32_t j = i; j > 0 && bp[j - 1] > bp[j]; j--) {
            double x = bp[j];
            bp[j] = bp[j - 1];
            bp[j - 1] = x;
        }
    if (nb < 2) return WK_OK;
    /* every elementary stretch covered once forwards and once backwards */
    uint32_t fwd[64], bwd[64];
    for (uint32_t k = 0; k + 1 < nb; k++) {
        uint32_t nf = 0, nbk = 0;
        double mid = 0.5 * (bp[k] + bp[k + 1]);
        for (uint32_t i = 0; i < len; i++) {
            double a = sv[i], b = sv[(i + 1) % len];
            if (mid > fmin(a, b) && mid < fmax(a, b)) {
                if (b > a) nf++, fwd[k] = W->v[cyc[i]].eout;
                else nbk++, bwd[k] = W->v[cyc[i]].eout;
            }
        }
        if (nf != 1 || nbk != 1) return WK_OK;
    }
    /* nodes at the breakpoints, vertices end there, arcs along the line */
    uint32_t node[64];
    for (uint32_t k = 0; k < nb; k++) {
        wk_point q = {o.x + bp[k] * L->ux, o.y + bp[k] * L->uy};
        if (wk_skeleton_add_node(R, W->S, q.x + W->origin.x, q.y + W->origin.y, t, &node[k]) != WK_OK)
            return R->err.code;
    }
    for (uint32_t i = 0; i < len; i++) {
        uint32_t k = 0;
        while (k + 1 < nb && fabs(bp[k] - sv[i]) > tol) k++;
        if (wf_terminate(W, cyc[i], node[k]) != WK_OK) return R->err.code;
    }
    for (uint32_t k = 0; k + 1 < nb; k++)
        /* going forwards, the backward piece's face is on the left */
        if (wf_add_arc(W, node[k], node[k + 1], bwd[k], fwd[k]) != WK_OK) return R->err.code;
    wk_event e = {t, o.x, o.y, f, WK_NONE, WK_NONE};
    wk_notify_event(R, WK_COUNTER_vanishing_components, &e);
    *done = true;
    return WK_OK;
}

/* Plan the group at node radius W->eps_g: rounds until no vertex is forced
** to become a node.  Changes only the group's scratch state. */
static wk_status plan_rounds(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    /* the last plan's forced vertices (this group's earlier try, or the
    ** last group's) are no longer marked */
    for (uint32_t i = 0; i < W->n_forced; i++) W->v[W->forced[i]].forced = 0;
    W->n_forced = W->n_swept = 0;
    for (int round = 0;; round++) {
        bool again;
        if (plan(W, t, &again) != WK_OK) return R->err.code;
        if (!again) return WK_OK;
        if (round > 64 + (int)W->n_comp)
            return WK_FAIL(R, WK_EALGO, W->P->name, 0, "wavefront: too many spikes at t = %.17g", t);
    }
}

/* The wide spot a failed plan asks for at node k (false: none): k's place
** with twice its radius, while that stays within WK_GROUP_WIDEN_MAX eps_d. */
static bool wide_spot_for(const wk_wavefront *W, uint32_t k, wk_wf_wide *spot) {
    if (k == WK_NONE || k >= W->n_cl) return false;
    *spot = (wk_wf_wide){W->cl[k].p, 2 * W->cl[k].r};
    return spot->r <= WK_GROUP_WIDEN_MAX * W->eps_d;
}

wk_status wf_resolve_group(wk_wavefront *W, double t) {
    wk_run *R = W->R;
    W->n_fresh = 0;
    W->n_dead = 0;
    /* A group that cannot be planned consistently at eps_d (nodes of a
    ** skeleton feature below the tolerance, split between clusters) is
    ** planned again with a coarser node where the plan failed: the node (or
    ** the two nodes) the failure names gets twice its radius, and so does
    ** every node made within that radius of its place on the next try (a
    ** wide spot, node_radius_at), up to WK_GROUP_WIDEN_MAX eps_d: a coarser
    ** picture of that event, still far inside the validator's tolerance,
    ** while every other node of the group keeps eps_d.  Widening the whole
    ** group made every node of it coarse, so that a node far from the
    ** failing event could take in vertices that were not part of its own.
    ** Measured: a weighted comb with a vertex at 5e10 (eps_d 50) failed at
    ** t = 5.79 until its nodes were 400 wide; before is_sliver's spike rule
    ** (which now plans it at eps_d) the whole group at 400 ended faces 5, 6,
    ** 7 at t = 5.79 and the widened pair alone at t = 20.5, the exact node
    ** being at t = 28.3 (tests/data/fuzz/mismatch_arrangement_wcomb_32dfdbca.wpoly).
    ** The failing node itself still takes in what lies within its new
    ** radius (there vertices 157 and 180 away at 200).
    ** The whole group is still widened, as before (the spots dropped), as
    ** the last resort: when the failure names no node ("too many spikes"),
    ** when the named nodes are already WK_GROUP_WIDEN_MAX eps_d wide, or after
    ** WK_NODE_WIDEN_SPOTS spots (a failure that moves on at every try);
    ** that ladder is the old rule, so a group it planned is still planned.
    ** Planning changes nothing but scratch state, so a retry starts from
    ** the same wavefront. */
    W->n_wide = 0;
    W->eps_g = W->eps_gmax = W->eps_d;
    bool whole = false; /* the last resort's ladder has begun */
    for (;;) {
        if (plan_rounds(W, t) == WK_OK) break;
        if (R->err.code != WK_EALGO) return R->err.code;
        wk_wf_wide spot[2];
        uint32_t n_spot = 0;
        for (int i = 0; i < 2 && !whole && W->n_wide + 2 <= WK_NODE_WIDEN_SPOTS; i++)
            if (wide_spot_for(W, W->fail_node[i], &spot[n_spot])) n_spot++;
        if (!n_spot && whole && W->eps_g >= WK_GROUP_WIDEN_MAX * W->eps_d) return R->err.code;
        wk_run_clear_error(R);
        if (!n_spot) {
            W->eps_g = W->eps_gmax = whole ? 2 * W->eps_g : 2 * W->eps_d;
            W->n_wide = 0;
            whole = true;
            continue;
        }
        if (WK_GROW(R, W->wide, W->cap_wide, W->n_wide + n_spot) != WK_OK) return R->err.code;
        for (uint32_t i = 0; i < n_spot; i++) {
            W->wide[W->n_wide++] = spot[i];
            W->eps_gmax = fmax(W->eps_gmax, spot[i].r);
        }
    }
    if (commit(W, t) != WK_OK || count_group(W, t) != WK_OK) return R->err.code;
    /* collinear rule for fresh vertices between parallel edges */
    for (uint32_t i = 0; i < W->n_fresh; i++) {
        uint32_t f = W->fresh[i];
        if (W->v[f].alive && W->v[f].vkind == WK_VEL_COLLINEAR && wf_collinear_rule(W, f, t) != WK_OK)
            return R->err.code;
        if (W->v[f].alive && W->v[f].vkind == WK_VEL_ANTIPARALLEL) {
            bool done;
            if (collapse_flat_cycle(W, f, t, &done) != WK_OK) return R->err.code;
            if (done) continue;
        }
        if (W->v[f].alive && W->v[f].vkind == WK_VEL_ANTIPARALLEL)
            return WK_FAIL(R, WK_EALGO, W->P->name, 0,
                           "wavefront: antiparallel wavefront vertex at t = %.17g", t);
    }
    return check_cycles_sane(W);
}
