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

typedef struct grid {
    double x0, y0, cw, ch;
    uint32_t gx, gy;
} grid;

static uint32_t clampi(double f, uint32_t g) {
    if (!(f > 0)) return 0;
    if (f >= (double)g) return g - 1;
    return (uint32_t)f;
}

/* Cell range of b; false if it covers more than DF_GRID_BIG cells. */
static bool cells(const grid *G, box b, double pad, uint32_t *i0, uint32_t *j0, uint32_t *i1,
                  uint32_t *j1) {
    *i0 = clampi((b.x0 - pad - G->x0) / G->cw, G->gx);
    *i1 = clampi((b.x1 + pad - G->x0) / G->cw, G->gx);
    *j0 = clampi((b.y0 - pad - G->y0) / G->ch, G->gy);
    *j1 = clampi((b.y1 + pad - G->y0) / G->ch, G->gy);
    return (uint64_t)(*i1 - *i0 + 1) * (*j1 - *j0 + 1) <= DF_GRID_BIG;
}

/* Only the earliest events of a step matter (the corrector goes back to
** the first one): an event later than the best so far plus eps_t is
** dropped at once, so a long step does not collect every later event. */
static wk_status push_event(df_state *D, double t, uint32_t kind, uint32_t a, uint32_t b,
                            const wk_point *x) {
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
    ** edge events), so it is taken when it falls in the step. */
    wk_point m;
    double t3;
    if (l0 > 0 && wk_three_lines_meet(&D->L[A->ein], L, &D->L[B->eout], &m, &t3) && t3 >= t &&
        t3 <= t1)
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
** point: the edge is shorter than the contact distance, its direction
** the tolerance cannot tell, and v meets the piece at w at t = 0, as a
** reflex vertex
** within eps_d of a piece's line splits it at once in the engine's
** wavefront (whose split search asks reflex vertices only).  Skipping them
** kept a sub-tolerance chamfer of a reflex corner growing, and with
** weights its face took a wedge of the neighbours' regions
** (tests/data/degenerate/deform_tiny_reflex_chamfer_*.wpoly, stress cases
** of the quick sweep).  A convex or straight vertex at the
** end of a tiny edge stays: there the edge collapses or grows by the
** motion of its ends (an edge swap, or none), again as in the engine.
** Input vertices of two rings (holes nearly touching) keep the old rule:
** taking them as met put a node where CGAL and naive do not
** (tests/data/fuzz/mismatch_arrangement_motorcycle_holes_touching.wpoly). */
static bool together_since_birth(const df_state *D, uint32_t v, uint32_t w, double c2) {
    const df_vertex *V = &D->v[v], *W = &D->v[w];
    if (v < D->P->n && w < D->P->n &&
        (wk_polygon_next(D->P, v) == w || wk_polygon_prev(D->P, v) == w) &&
        wk_is_reflex_turn(&D->L[V->ein], &D->L[V->eout]))
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
    return push_event(D, te, kind, p, a, x);
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
    ** (tests/data/fuzz/mismatch_deforming_regular5_far_node.wpoly). */
    wk_point m;
    double t3;
    if (g0 > 0 && wk_three_lines_meet(&D->L[V->ein], &D->L[V->eout], L, &m, &t3) && t3 >= t &&
        t3 <= t1)
        return contact(D, p, a, t, t1, t3, &m, eps_c, DF_PENETRATION);
    return contact(D, p, a, t, t1, g0 <= 0 ? t : root(L->nx, L->ny, V, NULL, L->c, rate), NULL,
                   eps_c, DF_PENETRATION);
}

/* The event's configuration at te: a collapsing piece no longer than eps_c,
** a vertex within eps_c of the piece's line. */
static bool met_at(const df_state *D, const df_event *E, double te, double eps_c) {
    const df_vertex *A = &D->v[E->kind == DF_COLLAPSE ? E->a : E->b];
    const df_vertex *B = &D->v[A->next];
    const wk_offset_line *L = &D->L[A->eout];
    if (E->kind == DF_COLLAPSE) {
        wk_point pa = df_pos(A, te), pb = df_pos(B, te);
        return L->ux * (pb.x - pa.x) + L->uy * (pb.y - pa.y) <= eps_c;
    }
    return fabs(wk_offset_distance(L, df_pos(&D->v[E->a], te), te)) <= eps_c;
}

static int event_cmp(const df_event *x, const df_event *y) {
    if (x->kind != y->kind) return x->kind < y->kind ? -1 : 1;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return 0;
}

static int event_cmp_void(const void *x, const void *y) { return event_cmp(x, y); }

wk_status df_predict(df_state *D, double *t_event) {
    wk_run *R = D->R;
    /* The search reaches eps_t past the step's end: the events of one group
    ** may straddle it (a collapse whose interpolated time is the end, 1e-15
    ** before 2, and a head-on contact at 2 from the input lines: resolved
    ** apart, the collinear rule of the first swept a piece the second
    ** should have ended, and the skeleton failed the validator; the
    ** integer-weighted rectilinear polygon of the family sweep, n = 1000,
    ** went to the reference). */
    double t = D->t, t1 = D->t + D->dt + D->eps_t;
    if (D->R->opt.height > 0 && t1 > D->R->opt.height) t1 = D->R->opt.height; /* the cap's time */
    double eps_c = WK_DEFORM_CONTACT_SLACK * D->eps_d;
    D->n_ev = 0;
    D->best = INFINITY;
    *t_event = INFINITY;
    wk_count(R, WK_VC_steps, 1);
    /* alive vertices in id order (deterministic) */
    uint32_t m = 0;
    if (WK_GROW(R, D->ids, D->cap_ids, D->n_alive + 1) != WK_OK) return R->err.code;
    for (uint32_t i = 0; i < D->nv; i++)
        if (D->v[i].alive) D->ids[m++] = i;
    if (m == 0) return WK_OK;
    /* edge swaps */
    for (uint32_t k = 0; k < m; k++)
        if (test_swap(D, D->ids[k], t, t1) != WK_OK) return R->err.code;
    /* the grid over the step's bounding box */
    box all = box_of(df_pos(&D->v[D->ids[0]], t));
    for (uint32_t k = 0; k < m; k++) {
        box_add(&all, df_pos(&D->v[D->ids[k]], t));
        box_add(&all, df_pos(&D->v[D->ids[k]], t1));
    }
    grid G;
    uint32_t g = (uint32_t)ceil(sqrt((double)m));
    G.gx = G.gy = g;
    G.x0 = all.x0;
    G.y0 = all.y0;
    G.cw = (all.x1 - all.x0) / g;
    G.ch = (all.y1 - all.y0) / g;
    if (!(G.cw > 0)) G.cw = 1;
    if (!(G.ch > 0)) G.ch = 1;
    uint32_t nc = g * g;
    if (WK_GROW(R, D->cell_start, D->cap_cell_start, nc + 1) != WK_OK ||
        WK_GROW(R, D->stamp, D->cap_stamp, D->nv) != WK_OK)
        return R->err.code;
    for (uint32_t c = 0; c <= nc; c++) D->cell_start[c] = 0;
    for (uint32_t i = 0; i < D->nv; i++) D->stamp[i] = WK_NONE;
    uint32_t n_big = 0;
    /* Pass 0 counts the cells of each piece, pass 1 fills them.  A long
    ** piece is cut into parts about one cell long, each entered in the
    ** cells of its swept box (a long diagonal piece would otherwise fill a
    ** square of cells); a cell takes a piece once (cell_mark). */
    if (WK_GROW(R, D->cell_mark, D->cap_cell_mark, nc) != WK_OK) return R->err.code;
    double cell = G.cw < G.ch ? G.cw : G.ch;
    for (int pass = 0; pass < 2; pass++) {
        for (uint32_t c = 0; c < nc; c++) D->cell_mark[c] = WK_NONE;
        for (uint32_t k = 0; k < m; k++) {
            uint32_t a = D->ids[k];
            const df_vertex *A = &D->v[a], *B = &D->v[A->next];
            wk_point a0 = df_pos(A, t), a1 = df_pos(A, t1), b0 = df_pos(B, t), b1 = df_pos(B, t1);
            double len = fmax(hypot(b0.x - a0.x, b0.y - a0.y), hypot(b1.x - a1.x, b1.y - a1.y));
            double parts = ceil(len / cell);
            uint32_t np = !(parts >= 1) ? 1 : parts > 4.0 * g ? 4 * g : (uint32_t)parts;
            bool big = false;
            for (uint32_t s = 0; s < np && !big; s++) {
                double f0 = (double)s / np, f1 = (double)(s + 1) / np;
                box b = box_of((wk_point){a0.x + f0 * (b0.x - a0.x), a0.y + f0 * (b0.y - a0.y)});
                box_add(&b, (wk_point){a0.x + f1 * (b0.x - a0.x), a0.y + f1 * (b0.y - a0.y)});
                box_add(&b, (wk_point){a1.x + f0 * (b1.x - a1.x), a1.y + f0 * (b1.y - a1.y)});
                box_add(&b, (wk_point){a1.x + f1 * (b1.x - a1.x), a1.y + f1 * (b1.y - a1.y)});
                uint32_t i0, j0, i1, j1;
                if (!cells(&G, b, eps_c, &i0, &j0, &i1, &j1)) {
                    big = true;
                    break;
                }
                for (uint32_t j = j0; j <= j1; j++)
                    for (uint32_t i = i0; i <= i1; i++) {
                        uint32_t c = j * g + i;
                        if (D->cell_mark[c] == a) continue;
                        D->cell_mark[c] = a;
                        if (pass == 0)
                            D->cell_start[c + 1]++;
                        else
                            D->cell_items[D->cell_start[c]++] = a;
                    }
            }
            if (big && pass == 0) {
                if (WK_GROW(R, D->big, D->cap_big, n_big + 1) != WK_OK) return R->err.code;
                D->big[n_big++] = a;
            }
        }
        if (pass == 0) {
            for (uint32_t c = 0; c < nc; c++) D->cell_start[c + 1] += D->cell_start[c];
            if (WK_GROW(R, D->cell_items, D->cap_cell_items, D->cell_start[nc] + 1) != WK_OK)
                return R->err.code;
        } else {
            /* filling advanced each start to the next cell's: shift back */
            for (uint32_t c = nc; c > 0; c--) D->cell_start[c] = D->cell_start[c - 1];
            D->cell_start[0] = 0;
        }
    }
    uint64_t tests = 0;
    for (uint32_t k = 0; k < m; k++) {
        uint32_t p = D->ids[k];
        const df_vertex *V = &D->v[p];
        /* the path, cut into parts about one cell long (a fast vertex's
        ** path crosses many cells, its box far more) */
        wk_point p0 = df_pos(V, t), p1 = df_pos(V, t1);
        double parts = ceil(hypot(p1.x - p0.x, p1.y - p0.y) / cell);
        uint32_t np = !(parts >= 1) ? 1 : parts > 4.0 * g ? 4 * g : (uint32_t)parts;
        bool all = false;
        for (uint32_t s = 0; s < np && !all; s++) {
            double f0 = (double)s / np, f1 = (double)(s + 1) / np;
            box b = box_of((wk_point){p0.x + f0 * (p1.x - p0.x), p0.y + f0 * (p1.y - p0.y)});
            box_add(&b, (wk_point){p0.x + f1 * (p1.x - p0.x), p0.y + f1 * (p1.y - p0.y)});
            uint32_t i0, j0, i1, j1;
            if (!cells(&G, b, eps_c, &i0, &j0, &i1, &j1)) {
                all = true;
                break;
            }
            for (uint32_t j = j0; j <= j1; j++)
                for (uint32_t i = i0; i <= i1; i++) {
                    uint32_t c = j * g + i;
                    for (uint32_t q = D->cell_start[c]; q < D->cell_start[c + 1]; q++) {
                        uint32_t a = D->cell_items[q];
                        if (D->stamp[a] == p) continue;
                        D->stamp[a] = p;
                        tests++;
                        if (test_penetration(D, p, a, t, t1, eps_c) != WK_OK) return R->err.code;
                    }
                }
        }
        if (all) {
            for (uint32_t q = 0; q < m; q++) {
                if (D->stamp[D->ids[q]] == p) continue;
                tests++;
                if (test_penetration(D, p, D->ids[q], t, t1, eps_c) != WK_OK) return R->err.code;
            }
            continue;
        }
        for (uint32_t q = 0; q < n_big; q++) {
            tests++;
            if (test_penetration(D, p, D->big[q], t, t1, eps_c) != WK_OK) return R->err.code;
        }
    }
    wk_count(R, WK_VC_pair_tests, tests);
    D->last_tests = tests;
    if (D->n_ev == 0) return WK_OK;
    /* keep the earliest events and those within eps_t of them: one group;
    ** but only those whose configuration has met at te within the contact
    ** distance (a piece's length, a vertex's gap), since eps_t times a
    ** fast vertex's speed can be far more: a piece that a very fast vertex
    ** (a long spike's tip) would collapse eps_t later is still long at te,
    ** and grouping it ended its far vertex at the event point (a fuzz
    ** finding).  Such an event is found again by the next step. */
    double te = INFINITY;
    for (uint32_t k = 0; k < D->n_ev; k++)
        if (D->ev[k].t < te) te = D->ev[k].t;
    uint32_t kept = 0;
    for (uint32_t k = 0; k < D->n_ev; k++)
        if (D->ev[k].t == te || (D->ev[k].t <= te + D->eps_t && met_at(D, &D->ev[k], te, eps_c)))
            D->ev[kept++] = D->ev[k];
    D->n_ev = kept;
    if (D->n_ev > 1) qsort(D->ev, D->n_ev, sizeof *D->ev, event_cmp_void);
    *t_event = te;
    return WK_OK;
}
