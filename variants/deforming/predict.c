/*
** predict.c: the predictor step of the deforming polygon (004, section
** 3.3): advance every vertex from the present t to t1 = t + dt by direct
** integration (P1 = P + dt v), then check whether the predicted polygon is
** admissible:
**   - no edge swap (004, 3.1): the projected length l of each piece on its
**     edge's direction keeps its sign; a piece with l0 > 0 and l1 <= 0
**     collapsed in between, at the time where the linear interpolation of l
**     is 0 (004 eq. 20-25);
**   - no penetration (004, 3.2, 3.5): no vertex crossed the offset line of
**     a piece other than its own two within the piece's extent; the
**     crossing time is again where the linear interpolation of the signed
**     gap (P - T) . n is 0 (004 eq. 26-30), checked against the extent at
**     that time.
** Both quantities are linear in time (vertices move at constant velocity),
** so the interpolation is exact: the corrector (deforming.c) moves the
** polygon to the earliest event time and resolve.c handles it.
**
** The penetration search: 004 tests every vertex against every piece and
** suggests bounding boxes or a spatial grid; here a uniform grid over the
** step's bounding box, each piece entered in the cells its swept area's
** box covers, each vertex testing the pieces of the cells its path's box
** covers (a piece stamped by the vertex is tested once).  A box over
** DF_GRID_BIG cells (a very fast vertex, a long piece) goes to a list
** tested against everything instead.
*/
#include "deforming.h"
#include "wavefront.h"

#include <math.h>
#include <stdlib.h>

/* Beyond this many cells an item is tested against all others instead:
** entering it in every cell would cost more than the tests it saves. */
#define DF_GRID_BIG 256u

typedef struct box { double x0, y0, x1, y1; } box;

static void box_add(box *b, wk_point p) {
    if (p.x < b->x0) b->x0 = p.x;
    if (p.x > b->x1) b->x1 = p.x;
    if (p.y < b->y0) b->y0 = p.y;
    if (p.y > b->y1) b->y1 = p.y;
}

static box box_of(wk_point p) { return (box){p.x, p.y, p.x, p.y}; }

static uint32_t clampi(double f, uint32_t g) {
    if (!(f > 0)) return 0;
    if (f >= (double)g) return g - 1;
    return (uint32_t)f;
}

/* Cell range of b in the window's grid (an item outside it clamps to its
** border cells); false if it covers more than DF_GRID_BIG cells. */
static bool cells(const df_state *D, box b, double pad, uint32_t *i0, uint32_t *j0, uint32_t *i1,
                  uint32_t *j1) {
    *i0 = clampi((b.x0 - pad - D->gx0) / D->gcw, D->g);
    *i1 = clampi((b.x1 + pad - D->gx0) / D->gcw, D->g);
    *j0 = clampi((b.y0 - pad - D->gy0) / D->gch, D->g);
    *j1 = clampi((b.y1 + pad - D->gy0) / D->gch, D->g);
    return (uint64_t)(*i1 - *i0 + 1) * (*j1 - *j0 + 1) <= DF_GRID_BIG;
}

/* Only the earliest events of a step matter (the corrector goes back to
** the first one): an event later than the best so far plus eps_t is
** dropped at once, so a long step does not collect every later event. */
static wk_status push_event(df_state *D, double t, uint32_t kind, uint32_t a, uint32_t b,
                            const wk_point *x) {
    if (!D->collect) { /* a prediction: only the earliest time */
        if (t < D->best) D->best = t;
        return WK_OK;
    }
    if (t > D->best + D->eps_t) return WK_OK;
    if (t < D->best) D->best = t;
    if (WK_GROW(D->R, D->ev, D->cap_ev, D->n_ev + 1) != WK_OK) return D->R->err.code;
    D->ev[D->n_ev++] = (df_event){t, kind, a, b, x ? *x : (wk_point){0, 0}, x != NULL};
    return WK_OK;
}

/* The time where the linear function f(t) = d . (x_a(t) - x_b(t)) - c
** vanishes, x(t) = p0 + (t - t0) v (b may be NULL: x_b = 0); rate is
** df/dt (plus any term in t the caller folded in).  f(t) = k + rate t with
** k = d . (p0_a - t0_a v_a - p0_b + t0_b v_b) - c. */
static double root(double dx, double dy, const df_vertex *a, const df_vertex *b, double c,
                   double rate) {
    double kx = a->p0.x - a->t0 * a->v.x, ky = a->p0.y - a->t0 * a->v.y;
    if (b) {
        kx -= b->p0.x - b->t0 * b->v.x;
        ky -= b->p0.y - b->t0 * b->v.y;
    }
    double k = dx * kx + dy * ky - c;
    return -k / rate;
}

/* The time t3 where three offset lines meet stands for the root tr of an
** interpolated quantity when the two are within a step of the step-size
** policy (D->dt_near: twice the time between the last two groups, as the
** predictor's increment of 004 would be) of each other: within a short
** step, as the predictor of one step at a time took it.  Farther apart,
** the lines' meeting is not this event (a vertex whose motion the lines do
** not give; a coastline with outward edges, n = 256, cut at 50, met at
** 31.8 by its lines and 27.2 by the root) and the root is taken, as the
** short steps did before the search spanned windows. */
static bool near_root(const df_state *D, double t3, double tr) {
    return fabs(t3 - tr) <= D->dt_near;
}

/* Where and when the offset lines of edges e1, e2, e3 meet: from the
** input points in long double (wk_three_edges_meet, as the engine's edge
** events), asked in one order (by edge id), so that an edge swap and a
** penetration that meet at the same three lines get the same time and
** point to the bit.  Asked on the double lines in each event's own order,
** Cramer's rule rounded differently, and where two of the lines are
** nearly parallel the times differed by far more than eps_t: a nearly
** straight vertex (edges 0, 1) reaching edge 4 where the piece of edge 0
** collapses got 3.4e-12 (1000 eps_t) before that collapse, resolved alone
** as a penetration just beyond the piece's end (two pieces leaving the
** point side by side, the reference: stress s1-c02552-mixed,
** tests/data/degenerate/deform_three_lines_one_order.wpoly).  The double
** lines in one order fixed that case but, their rounding moved, sent
** others to the reference (s1-c01517-mixed, s1-c02434-regular_4e9) or made
** them differ from naive (s1-c01072-nearly_straight); the long double
** lines do neither (stress --cases 3000). */
static bool df_three_lines_meet(const df_state *D, uint32_t e1, uint32_t e2, uint32_t e3,
                                wk_point *m, double *t) {
    uint32_t x;
    if (e1 > e2) x = e1, e1 = e2, e2 = x;
    if (e2 > e3) x = e2, e2 = e3, e3 = x;
    if (e1 > e2) x = e1, e1 = e2, e2 = x;
    return wk_three_edges_meet(D->P, e1, e2, e3, D->o, m, t);
}

/* Edge swap of the piece a -> next(a) within [t, t1]. */
static wk_status test_swap(df_state *D, uint32_t a, double t, double t1) {
    const df_vertex *A = &D->v[a], *B = &D->v[A->next];
    const wk_offset_line *L = &D->L[A->eout];
    wk_point pa = df_pos(A, t), pb = df_pos(B, t), qa = df_pos(A, t1), qb = df_pos(B, t1);
    double l0 = L->ux * (pb.x - pa.x) + L->uy * (pb.y - pa.y);
    double l1 = L->ux * (qb.x - qa.x) + L->uy * (qb.y - qa.y);
    /* shrinking at all (a piece of constant length never swaps) */
    double rate = L->ux * (B->v.x - A->v.x) + L->uy * (B->v.y - A->v.y);
    double speed = fabs(A->v.x) + fabs(A->v.y) + fabs(B->v.x) + fabs(B->v.y) + D->wmax;
    if (!(rate < -WK_APPROACH_REL * speed) || l1 > 0) return WK_OK;
    /* 004 eq. 22-25: xi_c = -l_m / l_d, dt_c = (1 + xi_c) dt / 2, i.e. the
    ** root of the linear l(t).  Evaluated on l's own coefficients (from the
    ** vertices' births), not on l0 and l1, so that the time does not depend
    ** on where the step started (simultaneous events stay simultaneous
    ** whatever the increment); l0 <= 0 is an event now. */
    double te = l0 <= 0 ? t : root(L->ux, L->uy, B, A, 0, rate);
    /* Between nearly parallel edges the vertices are fast and l's root is
    ** ill-conditioned; the time where the three offset lines meet comes
    ** from the input lines alone (as CGAL's trisegments and the engine's
    ** edge events), so it is taken when it falls in the step (see
    ** near_root).  Solved as the engine's edge events are, on lines built
    ** from the input points in long double (wk_three_edges_meet): on the
    ** double offset lines (wk_three_lines_meet) a point on an ellipse of
    ** 3000 vertices (bin/wskel-gen convex --n 3000 --seed 1), three nearly
    ** parallel lines, came out 1e-6 off; the vertex born there missed its
    ** lines by more than the snap, its later collapses were 1e-3 off in
    ** time (slowly shrinking pieces), and 12 nodes were 2e-3 from naive's
    ** and CGAL's (tests/test_deforming.py, test_ellipse_same_as_naive). */
    wk_point m;
    double t3;
    if (l0 > 0 && df_three_lines_meet(D, A->ein, A->eout, B->eout, &m, &t3) && t3 >= t &&
        t3 <= t1 && near_root(D, t3, te))
        return push_event(D, t3, DF_COLLAPSE, a, WK_NONE, &m);
    if (te < t) te = t;
    if (te > t1) te = t1;
    return push_event(D, te, DF_COLLAPSE, a, WK_NONE, NULL);
}

static double dist2(wk_point a, wk_point b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

/* Two vertices within the contact distance now that were so when the
** younger was born came out of one event point resolved already: no new
** contact between a vertex and the piece that ends at the other.  Two
** that came together since (vertex-on-vertex; the far ends of a region
** collapsing along its whole length, as in integer-weighted combs) meet
** now: skipping them would lose the event and leave a spike alive.
** A reflex input vertex v and another input vertex w (ids below the
** input's n) at the ends of one input edge did not come out of one
** point: the edge is shorter than the contact distance, and v meets the
** piece at w at t = 0, as a reflex vertex within eps_d of a piece's line
** splits it at once in the engine's wavefront (whose split search asks
** reflex vertices only), unless v lies exactly behind that piece's input
** line (test_penetration asks the engine's rule,
** wk_input_vertex_never_reaches_line): then, as in the engine and CGAL,
** the tiny edge (a reflex corner's chamfer) grows into a face
** (tests/data/degenerate/deform_tiny_reflex_chamfer_*.wpoly).  A convex
** or straight vertex at the end of a tiny edge stays: there the edge
** collapses or grows by the motion of its ends (an edge swap, or none),
** again as in the engine.
** The same holds for any two input vertices, of one ring or of two, not
** only the ends of one edge (session deform11): a reflex input vertex
** within the contact distance of another (a pinch: the ring touches
** itself, or two holes touch) did not come out of one point either, and
** skipped, its split at t = 0 was lost and (in six of these) the
** wavefront crossed itself from the first step on
** (ealgo_arrangement_pinch, vertices 1e-6 apart, eps_d 0.4;
** ub_deforming_nan_step, 4e-12; ealgo_holes_vertices_1e-10_apart;
** mismatch_arrangement_motorcycle_holes_touching, 4.7e-6; and
** ealgo_arrangement_still_alive, invalid_naive_7gon_spikes_2e14,
** invalid_naive_h_weight9_sliver_cycle in tests/data/fuzz: each went to
** the reference, rays side by side or a vertex alive too long; now each
** equals naive).  Between rings the side rule (contact below) still
** decides which piece at w it meets.  (Two rings' vertices were kept
** together since birth because taking them as met put a node of
** holes_touching where CGAL and naive do not; with the side rule it and
** holes_vertices_1e-10_apart now equal CGAL.) */
static bool together_since_birth(const df_state *D, uint32_t v, uint32_t w, double c2) {
    const df_vertex *V = &D->v[v], *W = &D->v[w];
    if (v < D->P->n && w < D->P->n && wk_is_reflex_turn(&D->L[V->ein], &D->L[V->eout]))
        return false;
    double tb = V->t0 > W->t0 ? V->t0 : W->t0;
    return dist2(df_pos(V, tb), df_pos(W, tb)) <= c2;
}

/* A vertex p reaching the line of the piece a -> next(a) at te (004 eq.
** 28-30 on g's own coefficients, see test_swap): an event of the given
** kind if p lies within the piece's extent then and did not come out of an
** end of the piece (see together_since_birth). */
static wk_status contact(df_state *D, uint32_t p, uint32_t a, double t, double t1, double te,
                         const wk_point *x, double eps_c, uint32_t kind) {
    const df_vertex *V = &D->v[p], *A = &D->v[a], *B = &D->v[A->next];
    const wk_offset_line *L = &D->L[A->eout];
    wk_point p0 = df_pos(V, t), a0 = df_pos(A, t), b0 = df_pos(B, t);
    double c2 = eps_c * eps_c;
    if ((dist2(p0, a0) <= c2 && together_since_birth(D, p, a, c2)) ||
        (dist2(p0, b0) <= c2 && together_since_birth(D, p, A->next, c2)))
        return WK_OK;
    if (te < t) te = t;
    if (te > t1) te = t1;
    wk_point q = df_pos(V, te), qa = df_pos(A, te), qb = df_pos(B, te);
    double s = L->ux * (q.x - qa.x) + L->uy * (q.y - qa.y);
    double len = L->ux * (qb.x - qa.x) + L->uy * (qb.y - qa.y);
    if (s < -eps_c || s > len + eps_c) return WK_OK;
    /* A vertex reaching the near end of the piece after its own (or before
    ** it) reaches it along its own piece as that piece collapses: the edge
    ** swap of that piece, not a merge (seen from behind, such a vertex
    ** looks like one). */
    if (kind == DF_MERGE && ((a == V->next && s <= eps_c) || (A->next == V->prev && s >= len - eps_c)))
        return WK_OK;
    /* Rings that nearly touch: an input vertex meeting the line of another
    ** ring's piece within the contact distance of an end that is an input
    ** vertex passes that end when the input says it meets the line outside
    ** the piece, past the end, by more than rounding: no contact with this
    ** piece (the engine's split test, wk_input_cut_side; at the nominal
    ** tolerance and finer, as there).  Taken for a contact, the two rings
    ** joined where naive and CGAL keep them apart: a hole's apex 1e-9..1e-6
    ** from another hole's apex (tests/test_near_touch.py --sweep 1000, 7
    ** cases; tests/data/holes/near_touch_two_holes_deforming_contact.wpoly,
    ** near_touch_tip_passes_apex_above_tol.wpoly). */
    if (kind == DF_PENETRATION && D->R->opt.tol_scale <= 1 && p < D->P->n && V->t0 == 0 &&
        wk_polygon_ring(D->P, p) != wk_polygon_ring(D->P, A->eout) &&
        ((s <= eps_c && a < D->P->n && A->t0 == 0 &&
          wk_input_cut_side(D->P, p, V->v, a, A->v, L, 0, te) < 0) ||
         (s >= len - eps_c && A->next < D->P->n && B->t0 == 0 &&
          wk_input_cut_side(D->P, p, V->v, A->next, B->v, L, 1, te) < 0)))
        return WK_OK;
    return push_event(D, te, kind, p, a, x);
}

/* The rounding of a vertex's terms in a root (p0 - t0 v, then v t), up to
** the unit roundoff: what the root's numerator may be off by. */
static double root_terms(const df_vertex *V, double t) {
    return fabs(V->p0.x) + fabs(V->p0.y) + (fabs(V->v.x) + fabs(V->v.y)) * (fabs(V->t0) + fabs(t));
}

/* The time tr of vertex p reaching the line of the piece a -> next(a) at
** the shared end of its own piece (the piece is the next one along the
** cycle, or the one before the previous): the three lines are the
** collapse's of the piece between, so the event is that collapse, which
** test_swap times by the root of the piece's length.  When the three
** lines are too nearly dependent to solve (wk_three_edges_meet declines)
** the two roots are estimates of one time, and the better conditioned is
** taken (the rounding of the terms over the rate).  The gap's rate is the
** worse one where the vertex runs nearly along the line: between three
** edges 1e-5..1e-3 apart in direction (random points on ellipses:
** test_deforming.py test_flat_ellipse_same_as_naive; bin/wskel-gen convex
** --n 10000 --seed 1, 2, 3) the gap closed at ~1e-7 of the speed, the
** length at ~1e-3; the gap's root came first, 3e-5 to 1e-3 early, and the
** group placed the collapse's node up to 4e-4 from naive's and CGAL's.
** Such a vertex is within the contact distance of the line long before
** (eps_d over 1e-7 of the speed), so g0 <= 0 takes the collapse's root
** too.  Where the shared end is a fast spike tip the length's root is the
** worse one and the gap's stays
** (tests/data/fuzz/mismatch_deforming_weighted_comb_spike.wpoly). */
static double shared_end_root(const df_state *D, uint32_t p, uint32_t a, double t, double tr,
                              double rate) {
    const df_vertex *V = &D->v[p];
    uint32_t x, y;
    const wk_offset_line *Lc;
    if (a == V->next) { /* the piece p -> a collapses */
        x = p;
        y = a;
        Lc = &D->L[V->eout];
    } else if (D->v[a].next == V->prev) { /* the piece prev(p) -> p collapses */
        x = V->prev;
        y = p;
        Lc = &D->L[V->ein];
    } else {
        return tr;
    }
    const df_vertex *X = &D->v[x], *Y = &D->v[y];
    double rc = Lc->ux * (Y->v.x - X->v.x) + Lc->uy * (Y->v.y - X->v.y);
    double speed = fabs(X->v.x) + fabs(X->v.y) + fabs(Y->v.x) + fabs(Y->v.y) + D->wmax;
    if (!(rc < -WK_APPROACH_REL * speed)) return tr; /* no swap (test_swap's bar) */
    double tc = root(Lc->ux, Lc->uy, Y, X, 0, rc);
    if (!(tc >= t)) return tr;
    const wk_offset_line *L = &D->L[D->v[a].eout];
    double tg = root(L->nx, L->ny, V, NULL, L->c, rate);
    double err_p = (root_terms(V, tg) + fabs(L->c) + fabs(L->w) * fabs(tg)) / fabs(rate);
    double err_c = (root_terms(X, tc) + root_terms(Y, tc)) / fabs(rc);
    return err_c < err_p ? tc : tr;
}

/* Input edges f and e lie on one input line (exact orientations), facing
** each other (antiparallel), both of positive weight: a vertex on f's
** offset line is (w_f + w_e) t behind e's offset line at every t > 0, and
** never meets e's piece.  The engine's split test asks reflex vertices
** only, and an input vertex on e's input line is its rule
** (wk_input_vertex_never_reaches_line); this variant asks every vertex,
** and the vertex the split of a reflex vertex on f makes there is no input
** vertex: in the H with needles whose edges 3 and 7 are collinear and
** face each other, reflex vertex 3 split edge 6 at t = 8e-6 and the new
** vertex of edges 6 and 3, 1.6e-5 (eps_d 3e-3) behind edge 7's line,
** "penetrated" edge 7's piece: two pieces left the point side by side
** (the reference; tests/data/fuzz/invalid_naive_h_needles_pass_by.wpoly).
** Cheap tests first (directions within WK_PARALLEL_SIN of antiparallel),
** then the exact orientations. */
static bool facing_on_one_line(const df_state *D, uint32_t f, uint32_t e) {
    const wk_offset_line *Lf = &D->L[f], *Le = &D->L[e];
    if (f == e || !(Lf->w > 0) || !(Le->w > 0)) return false;
    if (!(Lf->ux * Le->ux + Lf->uy * Le->uy < 0) ||
        !(fabs(Lf->ux * Le->uy - Lf->uy * Le->ux) <= WK_PARALLEL_SIN))
        return false;
    const wk_polygon *P = D->P;
    wk_point a = P->p[e], b = P->p[wk_polygon_next(P, e)];
    return wk_orient2d_counted(D->R, a, b, P->p[f]) == 0 &&
           wk_orient2d_counted(D->R, a, b, P->p[wk_polygon_next(P, f)]) == 0;
}

/* Penetration of vertex p through the piece a -> next(a) within [t, t1]. */
static wk_status test_penetration(df_state *D, uint32_t p, uint32_t a, double t, double t1,
                                  double eps_c) {
    const df_vertex *A = &D->v[a];
    if (p == a || p == A->next) return WK_OK;
    const df_vertex *V = &D->v[p];
    const wk_offset_line *L = &D->L[A->eout];
    double g0 = wk_offset_distance(L, df_pos(V, t), t);
    double g1 = wk_offset_distance(L, df_pos(V, t1), t1);
    double rate = L->nx * V->v.x + L->ny * V->v.y - L->w;
    double speed = fabs(V->v.x) + fabs(V->v.y) + fabs(L->w);
    /* From the outside (004 Fig. 11b, "from outside inside"): with outward
    ** edges two parts of the wavefront can meet across the swept region
    ** (the exterior between them closes).  The mirror of the contact
    ** below: the vertex is on the swept side of the line (or on it),
    ** approaching, and one of its own pieces leaves it into the swept side
    ** or along the line (else it touches the line with its back).  Only
    ** with weights <= 0: with positive weights the unswept region only
    ** shrinks, so a vertex never reaches a piece from behind. */
    if (D->nonpositive && g0 <= eps_c && rate > WK_APPROACH_REL * speed && g1 >= 0) {
        const wk_offset_line *Li = &D->L[V->ein], *Lo = &D->L[V->eout];
        if (L->nx * Lo->ux + L->ny * Lo->uy > WK_PARALLEL_SIN &&
            -(L->nx * Li->ux + L->ny * Li->uy) > WK_PARALLEL_SIN)
            return WK_OK;
        return contact(D, p, a, t, t1, g0 >= 0 ? t : root(L->nx, L->ny, V, NULL, L->c, rate),
                       NULL, eps_c, DF_MERGE);
    }
    /* approaching from the inside (the wavefront is on the inner side of
    ** each of its pieces) and on the line by t1 */
    if (g0 < -eps_c || !(rate < -WK_APPROACH_REL * speed) || g1 > 0) return WK_OK;
    /* An input vertex strictly behind the input line of the piece's edge,
    ** moving away from it, is within the contact distance only because the
    ** input puts it there: the engine's rule (its split test asks the same
    ** function), so that a reflex corner's chamfer shorter than eps_d grows
    ** into a face as in the engine and CGAL, instead of its vertex meeting
    ** the piece across it at t = 0
    ** (tests/data/degenerate/deform_tiny_reflex_chamfer_*.wpoly). */
    if (g0 <= eps_c && p < D->P->n && V->t0 == 0 &&
        wk_input_vertex_never_reaches_line(D->R, D->P, p, V->v, L, A->eout))
        return WK_OK;
    /* on its own edge's input line, which faces the piece's (see there) */
    if (t > 0 && (facing_on_one_line(D, V->ein, A->eout) || facing_on_one_line(D, V->eout, A->eout)))
        return WK_OK;
    /* Behind the line by more than rounding and receding, having crossed
    ** it at t_c before an end of the piece was made: the piece was not
    ** there when the vertex crossed its line, and is near it now only
    ** because that end came out of a point near the vertex (the engine's
    ** rule, wk_passed_line_before_piece).  Star n = 10^4 seed 7
    ** (bin/wskel-gen star), t = 0.2506: a spike's tip (edges 254, 255)
    ** split the piece of edge 400 1.9e-5 from its start, vertex 11362
    ** (edges 325, 400), the lines of 254 and 400 crossing there at 0.09 rad,
    ** so 11362 lay 1.7e-6 (eps_d 2.8e-6) behind the line of the new piece
    ** of edge 254, which it had crossed at t = 0.2498; taken as a
    ** penetration, two pieces left the point side by side (the reference;
    ** tests/test_deforming.py test_star_same_as_naive).  A wall (weight 0)
    ** has no rounding bound: the rule does not apply. */
    if (g0 < 0 && rate < 0) {
        double wu = fmin(fabs(D->L[V->ein].w), fabs(D->L[V->eout].w));
        if (wu > 0 && wk_passed_line_before_piece(df_pos(V, t), t, g0, rate,
                                                  wk_speed_rounding(V->v, wu), fabs(L->w), V->t0,
                                                  A->t0, D->v[A->next].t0))
            return WK_OK;
        /* Born behind the line (it crossed it before its birth, at
        ** t_c <= t0), behind by more than rounding now and receding, and an
        ** end of the piece made after its birth: it was never in front of
        ** the line, and the piece is near it only because that end came
        ** out of a point near it (the rule above, with the vertex's birth
        ** for t_c).  The H with needles at 1e6: vertex 12 (edges 11 and 1,
        ** the sides of a needle 1e6 long), born at t = 1.0e-6 1.2e-5 behind
        ** edge 2's line, "penetrated" at t = 1.0e-5 the piece of edge 2 whose
        ** start was made then, 3e-5 (eps_d 9e-3) away: two pieces left the
        ** point side by side (the reference;
        ** tests/data/fuzz/invalid_naive_h_needles.wpoly, _fold.wpoly). */
        double tc = t - g0 / rate, a0 = A->t0, b0 = D->v[A->next].t0;
        if (wu > 0 && tc <= V->t0 && V->t0 < t && (a0 > V->t0 || b0 > V->t0) &&
            wk_passed_line_before_piece(df_pos(V, t), t, g0, rate, wk_speed_rounding(V->v, wu),
                                        fabs(L->w), -INFINITY, a0, b0))
            return WK_OK;
    }
    /* The vertex must meet the piece from the unswept side: one of its own
    ** pieces leaves it into that side or along the line (n . direction >
    ** -WK_PARALLEL_SIN, on the input directions; along the line: the two
    ** overlap).  A vertex on the line whose pieces all lie beyond it
    ** touches the piece's back: no contact (and resolving it would change
    ** nothing, again and again). */
    const wk_offset_line *Lin = &D->L[V->ein], *Lout = &D->L[V->eout];
    if (L->nx * Lout->ux + L->ny * Lout->uy < -WK_PARALLEL_SIN &&
        -(L->nx * Lin->ux + L->ny * Lin->uy) < -WK_PARALLEL_SIN)
        return WK_OK;
    /* The vertex lies on the lines of its two edges, so it reaches the
    ** piece's line where the three lines meet: taken from the input lines
    ** when that falls in the step (as test_swap does, and the engine's
    ** refine for splits).  The root of the gap needs the vertex's velocity,
    ** which between nearly antiparallel edges is huge and inexact: a vertex
    ** racing up a spike 1e10 long whose sides are 1e-10 apart met the far
    ** side at t 0.78 instead of 0.93, 1e5 short of the node
    ** (tests/data/fuzz/mismatch_deforming_regular5_far_node.wpoly).  The
    ** lines in long double, as in test_swap. */
    /* A vertex near the line of the piece after its next piece (or before
    ** its previous one) lies on the line of the piece q between, which
    ** crosses that line at the shared end only (the lines not parallel):
    ** it reaches the line there, when q collapses, and nowhere else.
    ** While q is longer than the contact distance and not shrinking, the
    ** vertex is near the line only because the two lines are nearly
    ** parallel: no contact.  In a random polygon (bin/wskel-gen random
    ** --n 100000 --seed 1, t = 0.013653) a vertex born between edges
    ** 0.008 rad apart sat 2.8e-6 (eps_d 2.8e-6) behind the line of the
    ** piece after its next, whose shared end, a notch tip between lines
    ** 1.3e-4 rad apart, ran away from it 0.02 ahead: taken as a
    ** penetration, three rays left the point within 0.008 rad, not
    ** alternating (the reference;
    ** tests/data/degenerate/deform_random_notch_tip_runs_away.wpoly). */
    if (a == V->next || A->next == V->prev) {
        uint32_t x = a == V->next ? p : V->prev, y = a == V->next ? a : p;
        const wk_offset_line *Lq = &D->L[a == V->next ? V->eout : V->ein];
        const df_vertex *X = &D->v[x], *Y = &D->v[y];
        wk_point px = df_pos(X, t), py = df_pos(Y, t);
        double len_q = Lq->ux * (py.x - px.x) + Lq->uy * (py.y - px.y);
        double rc = Lq->ux * (Y->v.x - X->v.x) + Lq->uy * (Y->v.y - X->v.y);
        double sq = fabs(X->v.x) + fabs(X->v.y) + fabs(Y->v.x) + fabs(Y->v.y) + D->wmax;
        if (fabs(Lq->ux * L->uy - Lq->uy * L->ux) > WK_PARALLEL_SIN && len_q > eps_c &&
            !(rc < -WK_APPROACH_REL * sq))
            return WK_OK;
    }
    wk_point m;
    double t3;
    double tr = g0 <= 0 ? t : root(L->nx, L->ny, V, NULL, L->c, rate);
    /* Beyond the piece's ends at tr by more than its ends and the vertex
    ** move in D->dt_near (the farthest t3 may be from tr and still be
    ** taken), plus the contact distance, the vertex misses the piece at t3
    ** as at tr (contact's extent test): no event, and no long double
    ** solve.  A vertex crosses the lines of most pieces of a convex
    ** polygon far from them: on an ellipse of 5000 vertices (bin/wskel-gen
    ** convex --n 5000) 8.3 million solves, a fifth of the variant's time.
    ** Not for the shared-end pairs, where tr may be far from the time
    ** taken (shared_end_root). */
    if (a != V->next && A->next != V->prev) {
        const df_vertex *B = &D->v[A->next];
        double tq = tr < t ? t : tr > t1 ? t1 : tr;
        wk_point q = df_pos(V, tq), qa = df_pos(A, tq), qb = df_pos(B, tq);
        double s = L->ux * (q.x - qa.x) + L->uy * (q.y - qa.y);
        double len = L->ux * (qb.x - qa.x) + L->uy * (qb.y - qa.y);
        double move = fabs(V->v.x) + fabs(V->v.y) + fabs(A->v.x) + fabs(A->v.y) + fabs(B->v.x) +
                      fabs(B->v.y);
        double M = 2 * (eps_c + move * D->dt_near);
        if (s < -M || s > len + M) return WK_OK;
    }
    if (g0 > 0 && df_three_lines_meet(D, V->ein, V->eout, A->eout, &m, &t3) && t3 >= t &&
        t3 <= t1 && near_root(D, t3, tr) &&
        /* The three-line point stands for the vertex only within the
        ** contact distance of where the vertex is at t3: the vertex's
        ** pieces end where it is, and an event point farther off gives rays
        ** that do not match them.  Between upper edges 0.0014 rad apart a
        ** vertex born eps_d off their meeting line was 12.5 units (250
        ** eps_d) from its penetration's three-line point, and the rays there
        ** did not alternate (the reference; mono_snap_skips_wall.wpoly,
        ** mono_snap_window.wpoly); the root of its own gap equals naive.  On
        ** a cut of Australia's ring (mc_real_needle_passes_reflex.wpoly) the
        ** three-line point put a node 2.4e-4 from naive's; now as naive. */
        dist2(df_pos(V, t3), m) <= eps_c * eps_c)
        return contact(D, p, a, t, t1, t3, &m, eps_c, DF_PENETRATION);
    double tc = shared_end_root(D, p, a, t, tr, rate);
    if (tc != tr) {
        if (tc > t1) return WK_OK; /* the collapse after the search's end: a later window's */
        tr = tc;
    }
    return contact(D, p, a, t, t1, tr, NULL, eps_c, DF_PENETRATION);
}

/* The event's configuration at te: a collapsing piece no longer than eps_c,
** a vertex within eps_c of the piece's line and of its extent (within eps_c
** of its ends along the line).  The extent matters for a fast vertex moving
** nearly along the piece's line: the tip of a spike 5e6 long beside an edge
** 4e-7 rad from its side (tests/data/fuzz/mismatch_deforming_cross_far_vertex_5e6.wpoly)
** is within eps_c of that edge's line all the way down the spike and
** reaches the piece's start 3.6e-6 (eps_t 5e-3) after it ends 18 units
** away where the spike closes; grouped, the piece's start vertex ended
** at the spike's node (faces 2, 4, 5 there, where naive and CGAL have
** that vertex cut edge 2 at t = 1.895). */
static bool met_at(const df_state *D, const df_event *E, double te, double eps_c) {
    const df_vertex *A = &D->v[E->kind == DF_COLLAPSE ? E->a : E->b];
    const df_vertex *B = &D->v[A->next];
    const wk_offset_line *L = &D->L[A->eout];
    if (E->kind == DF_COLLAPSE) {
        wk_point pa = df_pos(A, te), pb = df_pos(B, te);
        return L->ux * (pb.x - pa.x) + L->uy * (pb.y - pa.y) <= eps_c;
    }
    wk_point x = df_pos(&D->v[E->a], te), pa = df_pos(A, te), pb = df_pos(B, te);
    if (!(fabs(wk_offset_distance(L, x, te)) <= eps_c)) return false;
    double sa = L->ux * (x.x - pa.x) + L->uy * (x.y - pa.y);
    double sb = L->ux * (pb.x - x.x) + L->uy * (pb.y - x.y);
    return sa >= -eps_c && sb >= -eps_c;
}

static int event_cmp(const df_event *x, const df_event *y) {
    if (x->kind != y->kind) return x->kind < y->kind ? -1 : 1;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return 0;
}

static int event_cmp_void(const void *x, const void *y) { return event_cmp(x, y); }

/* ------------------------------------------------------------------
** The kinetic search.  A window [t, T1] (T1 = t + dt, the step-size
** policy's increment) has a uniform grid over the bounding box of the
** alive vertices at t and t1 = T1 + eps_t, and two kinds of cell lists:
** each piece in the cells its swept area meets over the rest of the window,
** each vertex path in the cells it crosses.  Every alive vertex p is queued
** with a lower bound of the time of its earliest own event (the edge swap
** of its piece p -> next(p), its penetrations and merges), from a
** prediction: the tests of the step above at the present, against the
** pieces in the cells of its path.  The bound holds because what p's
** events depend on only changes in a resolution, and df_update re-predicts
** then: a vertex whose links changed (resolve.c touches it) fully, and a
** vertex whose path meets a new or changed piece against that piece (its
** key lowered to the pair's event if earlier).  A piece that changed or
** ended leaves keys that are too early, never too late: the group's
** search (df_next_group) takes vertices off the queue earliest first,
** predicts each again at the present, collecting its events, until the
** next key is later than the earliest event found plus eps_t: every event
** of the group is then found, as the step over every vertex found it.
** So a step costs what changes (the vertices of the group and their
** neighbours, the paths near the new pieces), not every alive vertex.
** Invariants between groups: every alive vertex with an event in the
** window is queued with a key no later than that event; every alive
** piece and path is in the cells of its swept box from its version's
** birth (or the window's start) to t1; entries of ended or changed pieces
** stay in the lists and are skipped (their version is old).
*/

static uint32_t next_gen(df_state *D) {
    if (D->gen >= UINT32_MAX - 2) { /* wrap: no stamp may equal a new one */
        for (uint32_t i = 0; i < D->nv; i++) D->k[i].stamp = 0;
        for (uint32_t c = 0; c < D->cap_cell_mark; c++) D->cell_mark[c] = 0;
        D->gen = 0;
    }
    return ++D->gen;
}

static wk_point lerp(wk_point a, wk_point b, double f) {
    return (wk_point){a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
}

static uint32_t parts_of(const df_state *D, double len) {
    double parts = ceil(len / D->gcell);
    return !(parts >= 1) ? 1 : parts > 4.0 * D->g ? 4 * D->g : (uint32_t)parts;
}

/* The cells (into D->cl, each once: marked with gen) met by a segment moving
** linearly from a0 b0 at ta to a1 b1 at tb: cut into parts about one cell
** along the segment and one cell along the motion, each part within the box
** of its four corners (a point of the segment moves linearly, so the part
** lies in their convex hull).  A path is a segment of length 0.  False if
** some part's box covers more than DF_GRID_BIG cells (test against all). */
static wk_status collect_cells(df_state *D, wk_point a0, wk_point b0, wk_point a1, wk_point b1,
                               uint32_t gen, bool *big) {
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    double ls = fmax(hypot(b0.x - a0.x, b0.y - a0.y), hypot(b1.x - a1.x, b1.y - a1.y));
    double lt = fmax(hypot(a1.x - a0.x, a1.y - a0.y), hypot(b1.x - b0.x, b1.y - b0.y));
    uint32_t ns = parts_of(D, ls), nt = parts_of(D, lt);
    D->n_cl = 0;
    *big = (uint64_t)ns * nt > 16u * D->g + 64;
    for (uint32_t u = 0; u < nt && !*big; u++) {
        double g0 = (double)u / nt, g1 = (double)(u + 1) / nt;
        wk_point c0 = lerp(a0, a1, g0), c1 = lerp(a0, a1, g1), d0 = lerp(b0, b1, g0),
                 d1 = lerp(b0, b1, g1);
        for (uint32_t s = 0; s < ns; s++) {
            double f0 = (double)s / ns, f1 = (double)(s + 1) / ns;
            box b = box_of(lerp(c0, d0, f0));
            box_add(&b, lerp(c0, d0, f1));
            box_add(&b, lerp(c1, d1, f0));
            box_add(&b, lerp(c1, d1, f1));
            uint32_t i0, j0, i1, j1;
            if (!cells(D, b, eps_c, &i0, &j0, &i1, &j1)) {
                *big = true;
                break;
            }
            for (uint32_t j = j0; j <= j1; j++)
                for (uint32_t i = i0; i <= i1; i++) {
                    uint32_t c = j * D->g + i;
                    if (D->cell_mark[c] == gen) continue;
                    D->cell_mark[c] = gen;
                    if (WK_GROW(D->R, D->cl, D->cap_cl, D->n_cl + 1) != WK_OK)
                        return D->R->err.code;
                    D->cl[D->n_cl++] = c;
                }
        }
    }
    return WK_OK;
}

/* collect_cells for the region piece a -> next(a) sweeps over [t, t1]. */
static wk_status collect_piece_cells(df_state *D, uint32_t a, uint32_t gen, bool *big) {
    const df_vertex *A = &D->v[a], *B = &D->v[A->next];
    return collect_cells(D, df_pos(A, D->t), df_pos(B, D->t), df_pos(A, D->t1), df_pos(B, D->t1), gen,
                         big);
}

static wk_status put(df_state *D, uint32_t *head, uint32_t c, uint32_t item, uint32_t ver) {
    if (WK_GROW(D->R, D->ent, D->cap_ent, D->n_ent + 1) != WK_OK) return D->R->err.code;
    D->ent[D->n_ent] = (df_entry){item, ver, head[c]};
    head[c] = D->n_ent++;
    return WK_OK;
}

static bool piece_valid(const df_state *D, uint32_t a, uint32_t ver) {
    return D->v[a].alive && D->k[a].pver == ver;
}

/* Enter the piece a -> next(a) (its present version) from t to t1. */
static wk_status insert_piece(df_state *D, uint32_t a) {
    uint32_t gen = next_gen(D);
    bool big;
    if (collect_piece_cells(D, a, gen, &big) != WK_OK) return D->R->err.code;
    if (big) {
        if (WK_GROW(D->R, D->big_piece, D->cap_big_piece, D->n_big_piece + 1) != WK_OK)
            return D->R->err.code;
        D->big_piece[D->n_big_piece++] = (df_entry){a, D->k[a].pver, 0};
        return WK_OK;
    }
    for (uint32_t q = 0; q < D->n_cl; q++)
        if (put(D, D->head_piece, D->cl[q], a, D->k[a].pver) != WK_OK) return D->R->err.code;
    return WK_OK;
}

/* Enter the path of vertex p from t to t1. */
static wk_status insert_path(df_state *D, uint32_t p) {
    const df_vertex *V = &D->v[p];
    wk_point p0 = df_pos(V, D->t), p1 = df_pos(V, D->t1);
    uint32_t gen = next_gen(D);
    bool big;
    D->k[p].inpath = D->wgen;
    if (collect_cells(D, p0, p0, p1, p1, gen, &big) != WK_OK) return D->R->err.code;
    if (big) {
        if (WK_GROW(D->R, D->big_path, D->cap_big_path, D->n_big_path + 1) != WK_OK)
            return D->R->err.code;
        D->big_path[D->n_big_path++] = p;
        return WK_OK;
    }
    for (uint32_t q = 0; q < D->n_cl; q++)
        if (put(D, D->head_path, D->cl[q], p, 0) != WK_OK) return D->R->err.code;
    return WK_OK;
}

/* Every event of vertex p from the present to t1 (its piece's edge swap,
** its penetrations and merges through the pieces near its path): pushed
** (D->collect) or only the earliest time kept in D->best. */
static wk_status predict_vertex(df_state *D, uint32_t p) {
    double t = D->t, t1 = D->t1, eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    if (test_swap(D, p, t, t1) != WK_OK) return D->R->err.code;
    const df_vertex *V = &D->v[p];
    wk_point p0 = df_pos(V, t), p1 = df_pos(V, t1);
    uint32_t gen = next_gen(D);
    bool big;
    if (collect_cells(D, p0, p0, p1, p1, gen, &big) != WK_OK) return D->R->err.code;
    uint64_t tests = 0;
    if (big) {
        for (uint32_t a = 0; a < D->nv; a++) {
            if (!D->v[a].alive) continue;
            tests++;
            if (test_penetration(D, p, a, t, t1, eps_c) != WK_OK) return D->R->err.code;
        }
        D->tests += tests;
        return WK_OK;
    }
    for (uint32_t q = 0; q < D->n_cl; q++)
        for (uint32_t e = D->head_piece[D->cl[q]]; e != WK_NONE; e = D->ent[e].next) {
            uint32_t a = D->ent[e].item;
            if (!piece_valid(D, a, D->ent[e].ver) || D->k[a].stamp == gen) continue;
            D->k[a].stamp = gen;
            tests++;
            if (test_penetration(D, p, a, t, t1, eps_c) != WK_OK) return D->R->err.code;
        }
    for (uint32_t q = 0; q < D->n_big_piece; q++) {
        uint32_t a = D->big_piece[q].item;
        if (!piece_valid(D, a, D->big_piece[q].ver) || D->k[a].stamp == gen) continue;
        D->k[a].stamp = gen;
        tests++;
        if (test_penetration(D, p, a, t, t1, eps_c) != WK_OK) return D->R->err.code;
    }
    D->tests += tests;
    return WK_OK;
}

/* Predict p afresh and queue it with its earliest event (none: off the
** queue until the next window). */
static wk_status requeue(df_state *D, uint32_t p) {
    D->best = INFINITY;
    if (predict_vertex(D, p) != WK_OK) return D->R->err.code;
    if (D->best == INFINITY) {
        wk_event_queue_remove(D->R, &D->Q, p);
        return WK_OK;
    }
    return wk_event_queue_set(D->R, &D->Q, p, (wk_event_key){D->best, 0});
}

/* Lower p's key to its event with the piece a -> next(a), if any. */
static wk_status pair_update(df_state *D, uint32_t p, uint32_t a) {
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    D->best = INFINITY;
    D->tests++;
    if (test_penetration(D, p, a, D->t, D->t1, eps_c) != WK_OK) return D->R->err.code;
    if (D->best == INFINITY ||
        (wk_event_queue_contains(&D->Q, p) && wk_event_queue_time(&D->Q, p) <= D->best))
        return WK_OK;
    return wk_event_queue_set(D->R, &D->Q, p, (wk_event_key){D->best, 0});
}

/* The vertices whose paths meet the (new) piece a -> next(a): each tested
** against it. */
static wk_status piece_against_paths(df_state *D, uint32_t a) {
    uint32_t gen = next_gen(D);
    bool big;
    if (collect_piece_cells(D, a, gen, &big) != WK_OK) return D->R->err.code;
    if (big) {
        for (uint32_t p = 0; p < D->nv; p++)
            if (D->v[p].alive && pair_update(D, p, a) != WK_OK) return D->R->err.code;
        return WK_OK;
    }
    for (uint32_t q = 0; q < D->n_cl; q++)
        for (uint32_t e = D->head_path[D->cl[q]]; e != WK_NONE; e = D->ent[e].next) {
            uint32_t p = D->ent[e].item;
            if (!D->v[p].alive || D->k[p].stamp == gen) continue;
            D->k[p].stamp = gen;
            if (pair_update(D, p, a) != WK_OK) return D->R->err.code;
        }
    for (uint32_t q = 0; q < D->n_big_path; q++) {
        uint32_t p = D->big_path[q];
        if (!D->v[p].alive || D->k[p].stamp == gen) continue;
        D->k[p].stamp = gen;
        if (pair_update(D, p, a) != WK_OK) return D->R->err.code;
    }
    return WK_OK;
}

/* Empty the touched list into D->tl (each vertex once). */
static wk_status take_touched(df_state *D) {
    D->n_tl = 0;
    for (uint32_t x = D->touch_head; x != DF_TOUCH_END;) {
        uint32_t nx = D->k[x].tnext;
        D->k[x].tnext = WK_NONE;
        if (WK_GROW(D->R, D->tl, D->cap_tl, D->n_tl + 1) != WK_OK) return D->R->err.code;
        D->tl[D->n_tl++] = x;
        x = nx;
    }
    D->touch_head = DF_TOUCH_END;
    return WK_OK;
}

wk_status df_window(df_state *D) {
    wk_run *R = D->R;
    double H = R->opt.height;
    /* The window's length: the time in which a vertex of the mean speed
    ** crosses D->dt cells of a grid of sqrt(alive) cells a side over the
    ** alive vertices now: longer, and the paths and swept areas cover many
    ** cells (every query tests more pairs); shorter, and the windows are
    ** many (each predicts every vertex). */
    box now = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    double speed = 0;
    for (uint32_t i = 0; i < D->nv; i++)
        if (D->v[i].alive) {
            box_add(&now, df_pos(&D->v[i], D->t));
            speed += hypot(D->v[i].v.x, D->v[i].v.y);
        }
    uint32_t g = (uint32_t)ceil(sqrt((double)D->n_alive));
    if (g < 1) g = 1;
    double side = fmax(now.x1 - now.x0, now.y1 - now.y0);
    double W = D->dt * side / g / (speed / (D->n_alive ? D->n_alive : 1));
    if (!(W > 0) || !isfinite(W)) W = D->dt * D->scale / (g * D->wmax);
    D->T1 = D->t + W;
    if (H > 0 && D->T1 > H) D->T1 = H;
    D->t1 = D->T1 + D->eps_t;
    if (H > 0 && D->t1 > H) D->t1 = H; /* the cap's time */
    D->window = true;
    D->wgen++;
    D->win_groups = 0;
    D->win_alive = D->n_alive;
    wk_count(R, WK_VC_steps, 1);
    if (take_touched(D) != WK_OK) return R->err.code;
    while (wk_event_queue_peek(&D->Q) != WK_NONE) (void)wk_event_queue_pop(R, &D->Q);
    /* the grid over the alive vertices at t and t1 */
    box all = now;
    for (uint32_t i = 0; i < D->nv; i++)
        if (D->v[i].alive) box_add(&all, df_pos(&D->v[i], D->t1));
    if (!(all.x1 >= all.x0)) all = (box){0, 0, 0, 0};
    D->g = g;
    D->gx0 = all.x0;
    D->gy0 = all.y0;
    D->gcw = (all.x1 - all.x0) / g;
    D->gch = (all.y1 - all.y0) / g;
    if (!(D->gcw > 0)) D->gcw = 1;
    if (!(D->gch > 0)) D->gch = 1;
    D->gcell = D->gcw < D->gch ? D->gcw : D->gch;
    uint32_t nc = g * g;
    if (WK_GROW(R, D->head_piece, D->cap_head_piece, nc) != WK_OK ||
        WK_GROW(R, D->head_path, D->cap_head_path, nc) != WK_OK)
        return R->err.code;
    if (nc > D->cap_cell_mark) {
        uint32_t old = D->cap_cell_mark;
        if (WK_GROW(R, D->cell_mark, D->cap_cell_mark, nc) != WK_OK) return R->err.code;
        for (uint32_t c = old; c < D->cap_cell_mark; c++) D->cell_mark[c] = 0;
    }
    for (uint32_t c = 0; c < nc; c++) D->head_piece[c] = D->head_path[c] = WK_NONE;
    D->n_ent = D->n_big_piece = D->n_big_path = 0;
    for (uint32_t i = 0; i < D->nv; i++)
        if (D->v[i].alive && (insert_piece(D, i) != WK_OK || insert_path(D, i) != WK_OK))
            return R->err.code;
    for (uint32_t i = 0; i < D->nv; i++)
        if (D->v[i].alive && requeue(D, i) != WK_OK) return R->err.code;
    wk_count(R, WK_VC_pair_tests, D->tests);
    D->tests = 0;
    return WK_OK;
}

wk_status df_next_group(df_state *D, double *t_event) {
    wk_run *R = D->R;
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    D->n_ev = 0;
    D->n_popped = 0;
    D->best = INFINITY;
    *t_event = INFINITY;
    D->collect = true;
    for (uint32_t p; (p = wk_event_queue_peek(&D->Q)) != WK_NONE;) {
        if (wk_event_queue_time(&D->Q, p) > D->best + D->eps_t) break;
        (void)wk_event_queue_pop(R, &D->Q);
        if (WK_GROW(R, D->popped, D->cap_popped, D->n_popped + 1) != WK_OK ||
            predict_vertex(D, p) != WK_OK) {
            D->collect = false;
            return R->err.code;
        }
        D->popped[D->n_popped++] = p;
    }
    D->collect = false;
    wk_count(R, WK_VC_pair_tests, D->tests);
    D->tests = 0;
    if (D->n_ev == 0) return WK_OK;
    /* keep the earliest events and those within eps_t of them: one group;
    ** but only those whose configuration has met at te within the contact
    ** distance (a piece's length, a vertex's gap), since eps_t times a
    ** fast vertex's speed can be far more: a piece that a very fast vertex
    ** (a long spike's tip) would collapse eps_t later is still long at te,
    ** and grouping it ended its far vertex at the event point (a fuzz
    ** finding).  Such an event is found again (its vertex was taken off
    ** the queue and is predicted again after the resolution). */
    double te = INFINITY;
    for (uint32_t k = 0; k < D->n_ev; k++)
        if (D->ev[k].t < te) te = D->ev[k].t;
    /* A group after the window's end may reach past the search's end: the
    ** next window finds it whole. */
    if (te > D->T1) {
        D->n_ev = 0;
        return WK_OK;
    }
    uint32_t kept = 0;
    for (uint32_t k = 0; k < D->n_ev; k++)
        if (D->ev[k].t == te || (D->ev[k].t <= te + D->eps_t && met_at(D, &D->ev[k], te, eps_c)))
            D->ev[kept++] = D->ev[k];
    D->n_ev = kept;
    if (D->n_ev > 1) qsort(D->ev, D->n_ev, sizeof *D->ev, event_cmp_void);
    *t_event = te;
    return WK_OK;
}

wk_status df_update(df_state *D) {
    wk_run *R = D->R;
    if (take_touched(D) != WK_OK) return R->err.code;
    /* ended vertices leave the queue; a changed piece is entered again
    ** under a new version (its old entries are skipped), a new vertex's
    ** path is entered */
    for (uint32_t i = 0; i < D->n_tl; i++) {
        uint32_t x = D->tl[i];
        if (!D->v[x].alive) {
            wk_event_queue_remove(R, &D->Q, x);
            continue;
        }
        D->k[x].pver++;
        if (insert_piece(D, x) != WK_OK) return R->err.code;
        if (D->k[x].inpath != D->wgen && insert_path(D, x) != WK_OK) return R->err.code;
    }
    /* the touched vertices and those the group's search took off the queue:
    ** predicted afresh (a vertex on both lists twice: harmless) */
    for (uint32_t i = 0; i < D->n_tl; i++)
        if (D->v[D->tl[i]].alive && requeue(D, D->tl[i]) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < D->n_popped; i++)
        if (D->v[D->popped[i]].alive && requeue(D, D->popped[i]) != WK_OK) return R->err.code;
    /* every path near a changed piece: tested against it */
    for (uint32_t i = 0; i < D->n_tl; i++)
        if (D->v[D->tl[i]].alive && piece_against_paths(D, D->tl[i]) != WK_OK) return R->err.code;
    wk_count(R, WK_VC_pair_tests, D->tests);
    D->tests = 0;
    return WK_OK;
}

wk_status df_vertices_near(df_state *D, wk_point X, double r) {
    D->n_near = 0;
    uint32_t gen = next_gen(D), i0, j0, i1, j1;
    if (!cells(D, box_of(X), r, &i0, &j0, &i1, &j1)) { /* a box over DF_GRID_BIG cells: all */
        for (uint32_t p = 0; p < D->nv; p++) {
            if (!D->v[p].alive) continue;
            if (WK_GROW(D->R, D->near, D->cap_near, D->n_near + 1) != WK_OK) return D->R->err.code;
            D->near[D->n_near++] = p;
        }
        return WK_OK;
    }
    for (uint32_t j = j0; j <= j1; j++)
        for (uint32_t i = i0; i <= i1; i++)
            for (uint32_t e = D->head_path[j * D->g + i]; e != WK_NONE; e = D->ent[e].next) {
                uint32_t p = D->ent[e].item;
                if (!D->v[p].alive || D->k[p].stamp == gen) continue;
                D->k[p].stamp = gen;
                if (WK_GROW(D->R, D->near, D->cap_near, D->n_near + 1) != WK_OK) return D->R->err.code;
                D->near[D->n_near++] = p;
            }
    for (uint32_t q = 0; q < D->n_big_path; q++) {
        uint32_t p = D->big_path[q];
        if (!D->v[p].alive || D->k[p].stamp == gen) continue;
        D->k[p].stamp = gen;
        if (WK_GROW(D->R, D->near, D->cap_near, D->n_near + 1) != WK_OK) return D->R->err.code;
        D->near[D->n_near++] = p;
    }
    return WK_OK;
}

void df_predict_free(df_state *D) {
    wk_run *R = D->R;
    wk_event_queue_clear(R, &D->Q);
    WK_FREE_ARRAY(R, D->head_piece, D->cap_head_piece);
    WK_FREE_ARRAY(R, D->head_path, D->cap_head_path);
    WK_FREE_ARRAY(R, D->cell_mark, D->cap_cell_mark);
    WK_FREE_ARRAY(R, D->cl, D->cap_cl);
    WK_FREE_ARRAY(R, D->ent, D->cap_ent);
    WK_FREE_ARRAY(R, D->big_piece, D->cap_big_piece);
    WK_FREE_ARRAY(R, D->big_path, D->cap_big_path);
    WK_FREE_ARRAY(R, D->popped, D->cap_popped);
    WK_FREE_ARRAY(R, D->tl, D->cap_tl);
    WK_FREE_ARRAY(R, D->near, D->cap_near);
}
