/*
** merge.c: the merge chain M' (001 sections 3-4), traced from v_w to v_e.
**
** M' is where the roofs of the two chains meet.  It starts at v_w in the
** faces of the two edges at v_w; inside a pair of faces (upper edge eu,
** lower edge eb) it runs along their weighted bisector
**     tau_u(q) = tau_b(q),  tau_e(q) = (n_e . q - c_e) / w_e,
** with the upper face on its left: heading east, or north / south along
** the axis of two walls perpendicular to the sweep that face each other
** from different chains (non-strict case: a bar of an H shape).  The next vertex is
** the first point east where this ray leaves the upper or the lower face
** through one of its walls (monotone.h); crossing a trace moves to
** the face on its other side.  The walk ends when the faces are those of the
** two edges at v_e and v_e comes before any crossing.
**
** How the next exit is found (instead of 001's trapezoidations, see
** README.md).  A face's slice at time tau is one segment between its walls;
** along the ray tau is linear, so the ray leaves the face at the first level,
** in the ray's direction of tau, where it passes a wall.  A wall is found at
** the current level by binary search over its traces' start times and
** walked in the ray's direction of tau until a crossing, or until its
** levels lie beyond the best exit found so far.  A face's level is crossed
** by M' at most twice inside the face (the final face's slice is one
** segment), so the walking is linear overall and each step costs
** O(log n) for the searches: O(n log n).
**
** Degenerate passes (M' through a chain node, or crossing both chains'
** skeletons at one point) are taken one crossing at a time: crossings within
** eps_d of the current merge node join it (no new node, no arc), and a
** trace already crossed at this node is not crossed again.
*/
#include "monotone.h"

#include <math.h>
#include <string.h>

/* At most this many crossings join one merge node: more means the walk is
** circling (a can't-happen that is reported, never looped on). */
#define CLUSTER_MAX 64

typedef struct hit {
    double lambda;      /* distance along the ray */
    double mu;          /* distance along the trace from its start */
    uint32_t chain, trace, face; /* face: the edge on the trace's other side */
    double uncertain;   /* where the ray meets a coplanar pair it cannot
                           follow (test_trace), INFINITY if nowhere */
    bool along;         /* the crossing is test_trace's "runs along" case */
} hit;

typedef struct walk {
    mono *M;
    wk_point p, dir;
    uint32_t cur;       /* merge node at p */
    uint32_t face[2];   /* current lower (0) and upper (1) face */
    uint32_t excl_c[CLUSTER_MAX], excl_v[CLUSTER_MAX];
    uint32_t n_excl;
    uint32_t arr_u, arr_b;    /* the faces M' came into cur between */
    uint32_t cl_c[CLUSTER_MAX + 2], cl_f[CLUSTER_MAX + 2]; /* faces met at cur */
    uint32_t n_cl;
} walk;

static double cross(wk_point a, wk_point b) { return a.x * b.y - a.y * b.x; }
static double dot(wk_point a, wk_point b) { return a.x * b.x + a.y * b.y; }
static wk_point sub(wk_point a, wk_point b) { return (wk_point){a.x - b.x, a.y - b.y}; }

static double level(const wk_offset_line *L, wk_point q) {
    return (L->nx * q.x + L->ny * q.y - L->c) / L->w;
}

/* Do the roof planes of edges a and b coincide (parallel, same side, equal
** weights, same line)?  Then their "bisector" is a whole plane and M' follows
** the wavefront vertex between them, which moves along their normal.  Same
** line: within eps_d (the offsets c are computed from the coordinates, so
** their rounding grows with the distance from the origin; a time tolerance
** here would shrink with WK_TOL_TIME). */
static bool coplanar(const mono *M, uint32_t a, uint32_t b) {
    const wk_offset_line *A = &M->L[a], *B = &M->L[b];
    double gx = A->nx / A->w - B->nx / B->w, gy = A->ny / A->w - B->ny / B->w;
    if (fabs(gx) + fabs(gy) > WK_MONO_COPLANAR_REL * (1 / A->w + 1 / B->w)) return false;
    return fabs(A->c - B->c) <= M->eps_d;
}

/* Edges a and b (of different chains, so they meet at v_w or v_e) meet at a
** vertex the wavefront treats as straight (equal weights, directions within
** WK_PARALLEL_SIN: kinetics.c): *s is that vertex.  The reference moves it
** along the normal, so M' between their faces is that normal line, however
** the rounding of the two nearly equal gradients points their bisector. */
static bool straight_pair(const mono *M, uint32_t a, uint32_t b, uint32_t *s) {
    const wk_polygon *P = M->P;
    uint32_t in = a, out = b;
    if (wk_polygon_next(P, b) == a) in = b, out = a;
    else if (wk_polygon_next(P, a) != b) return false;
    wk_point v;
    if (wk_vertex_velocity(&M->L[in], &M->L[out], &v) != WK_VEL_STRAIGHT) return false;
    *s = out; /* edge out starts at the shared vertex */
    return true;
}

/* Where wall w[0..k) of a face is at level tau: *q, false if the wall has
** no non-flat trace alive then (the face's piece is gone); an empty wall
** (the chain's end rays) bounds nothing: *unbounded. */
static bool wall_at(const mono_chain *C, const uint32_t *w, uint32_t k, double tau, wk_point *q,
                    bool *unbounded) {
    *unbounded = k == 0;
    if (k == 0) return true;
    uint32_t lo = 0, hi = k;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (C->v[w[mid]].t1 < tau) lo = mid + 1;
        else hi = mid;
    }
    while (lo < k && C->v[w[lo]].flat) lo++;
    if (lo == k || C->v[w[lo]].t0 > tau) return false;
    *q = wk_mono_trace_at(&C->v[w[lo]], tau);
    return true;
}

/* Is q inside the face of edge e in chain c's skeleton: between the face's
** walls at q's level? */
static bool in_chain_face(const mono *M, uint32_t c, uint32_t e, wk_point q) {
    const mono_chain *C = &M->ch[c];
    const wk_offset_line *L = &M->L[e];
    double tau = level(L, q);
    if (!(tau > 0)) return false;
    uint32_t k = wk_mono_chain_local(M, C, e);
    if (k == WK_NONE) return false;
    wk_point a, b, u = {L->ny, -L->nx}; /* e's direction: its face on the left */
    bool ua, ub;
    if (!wall_at(C, C->lw + C->lw_start[k], C->lw_start[k + 1] - C->lw_start[k], tau, &a, &ua) ||
        !wall_at(C, C->rw + C->rw_start[k], C->rw_start[k + 1] - C->rw_start[k], tau, &b, &ub))
        return false;
    return (ua || dot(sub(q, a), u) > 0) && (ub || dot(sub(b, q), u) > 0);
}

/* Do the regions of upper face u and lower face b overlap next to node p
** (probed at WK_MONO_PROBE_REL * eps_d around it)?  Coplanar faces that
** only touch at p (the four arms' sides of a symmetric cross at its centre,
** tests/data/hand/cross.wpoly) have no common vertex to follow there. */
static bool overlap_at(const mono *M, uint32_t u, uint32_t b, wk_point p) {
    double r = WK_MONO_PROBE_REL * M->eps_d;
    for (int k = 0; k < 16; k++) {
        double a = 2 * 3.14159265358979323846 * (k + 0.37) / 16; /* off the axes */
        wk_point q = {p.x + r * cos(a), p.y + r * sin(a)};
        if (in_chain_face(M, 1, u, q) && in_chain_face(M, 0, b, q)) return true;
    }
    return false;
}

/* Leaving node cur between faces eu / eb: did the walk meet there an upper
** and a lower face that are coplanar, other than the pair it came in or
** leaves by?  Then several traces meet at cur and one of the coplanar
** pairs' common vertex ran somewhere near: where M' turns onto it depends
** on where that pair first touched, as for a pair entered from its later
** side (wk_mono_merge), and which crossings at cur the walk took first was
** decided by their order, not by the geometry.  A survey case
** (tests/fuzz/cross_far_vertex_sweep.py, a plus of arms 1 wide whose
** vertex 4 is moved to (270, 1341),
** tests/data/fuzz/mismatch_monotone_plus_far_vertex.wpoly): at (0, 0),
** t = 1, faces 6 / 2 (y = 1 - t) and 8 / 0 (y = -1 + t) all meet with
** faces 5, 9 and 11; M' should leave west between 2 and 8 and turn north
** between 2 and 6 at x = -0.099, the walk left between 5 and 2 and the
** skeleton (valid) missed the pair's arc. */
static bool cluster_uncertain(const walk *W, uint32_t eu, uint32_t eb) {
    for (uint32_t i = 0; i < W->n_cl; i++) {
        if (W->cl_c[i] != 1) continue;
        for (uint32_t j = 0; j < W->n_cl; j++) {
            if (W->cl_c[j] != 0) continue;
            uint32_t u = W->cl_f[i], b = W->cl_f[j];
            if ((u == W->arr_u && b == W->arr_b) || (u == eu && b == eb)) continue;
            if (coplanar(W->M, u, b) && overlap_at(W->M, u, b, W->p)) return true;
        }
    }
    return false;
}

static void cluster_start(walk *W, uint32_t eu, uint32_t eb) {
    W->arr_u = eu, W->arr_b = eb;
    W->cl_c[0] = 1, W->cl_f[0] = eu;
    W->cl_c[1] = 0, W->cl_f[1] = eb;
    W->n_cl = 2;
}

static bool excluded(const walk *W, uint32_t c, uint32_t v) {
    for (uint32_t i = 0; i < W->n_excl; i++)
        if (W->excl_c[i] == c && W->excl_v[i] == v) return true;
    return false;
}

/* The ray runs back along trace T (from A in unit direction D, len long;
** den = cross(D, ray)) towards T's end, and the face `beyond` T is coplanar
** with the other chain's face: then the faces' common plane is entered from
** the far side of their common region, and where M' turns off T onto the
** wavefront vertex between them depends on where the two coplanar pieces
** first touched, which this walk has not reached.  A fuzz finding: an
** integer 12-gon with collinear edges 5 and 9 in different chains
** (tests/data/fuzz/mismatch_monotone_integer_12gon.wpoly), where M' ran on
** past T's end and gave a skeleton the validator accepts but that is not
** the polygon's (CGAL's and naive's agree).  Not certified: *best records
** where (best->uncertain), and the walk gives up if nothing comes first.
** "Along" is parallel up to rounding or, for a finite trace, both ends
** within eps_d of the ray's line: T's direction is a difference of points
** relative to an origin 15000 away there, and its sine with an exactly
** parallel ray came out 3.9e-14, above WK_MONO_RAY_PARALLEL_SIN. */
static bool runs_back_into_coplanar(const walk *W, uint32_t c, const mono_trace *T,
                                    uint32_t beyond, wk_point A, wk_point D, double len,
                                    double den, hit *best) {
    const mono *M = W->M;
    const mono_chain *C = &M->ch[c];
    wk_point Ap = sub(A, W->p);
    if (!(fabs(cross(D, Ap)) <= M->eps_d) || !isfinite(len)) return false;
    wk_point E = C->node[T->end].p;
    bool along = fabs(den) <= WK_MONO_RAY_PARALLEL_SIN ||
                 (fabs(cross(W->dir, Ap)) <= M->eps_d &&
                  fabs(cross(W->dir, sub(E, W->p))) <= M->eps_d);
    if (!along || !(-dot(D, Ap) > len + M->eps_d) || !coplanar(M, beyond, W->face[1 - c]))
        return false;
    double lend = dot(sub(E, W->p), W->dir);
    if (lend > -M->eps_d && lend < best->uncertain) best->uncertain = lend < 0 ? 0 : lend;
    return true;
}

/* Does the ray leave face e through trace v (outward: left walls have the
** face on their right, right walls on their left)?  Updates *best. */
static void test_trace(const walk *W, uint32_t c, uint32_t v, bool left_wall, uint32_t e,
                       hit *best) {
    const mono *M = W->M;
    const mono_chain *C = &M->ch[c];
    const mono_trace *T = &C->v[v];
    if (excluded(W, c, v)) return;
    wk_point A = C->node[T->start].p, D;
    double len;
    bool infinite = T->end == WK_NONE;
    if (infinite) {
        double s = hypot(T->vel.x, T->vel.y);
        if (!(s > 0)) return;
        D = (wk_point){T->vel.x / s, T->vel.y / s};
        len = INFINITY;
    } else {
        D = sub(C->node[T->end].p, A);
        len = hypot(D.x, D.y);
        if (len <= M->eps_d) return; /* a point: its neighbours decide */
        D.x /= len, D.y /= len;
    }
    double den = cross(D, W->dir);
    wk_point Ap = sub(A, W->p);
    uint32_t beyond = left_wall ? T->ein : T->eout, sv;
    if (fabs(den) <= WK_PARALLEL_SIN && fabs(cross(D, Ap)) <= M->eps_d &&
        straight_pair(M, beyond, W->face[1 - c], &sv)) {
        /* The ray runs along this trace into the face of an edge that is
        ** straight with the other chain's face (the two edges at v_w or v_e,
        ** up to 1e-9 rad apart): that is a stress finding where the crossing
        ** of two lines 1.3e-12 rad apart came out 2.2e-5 off
        ** (s6-c02038-nearly_straight).  M' leaves the trace where the
        ** normal through the straight vertex crosses it. */
        const wk_offset_line *L = &M->L[beyond];
        wk_point S = wk_mono_vertex(M, sv), nrm = {L->nx, L->ny};
        double dd = cross(W->dir, nrm);
        if (!(fabs(dd) > WK_PARALLEL_SIN)) return;
        double lambda = cross(sub(S, W->p), nrm) / dd;
        wk_point X = {W->p.x + lambda * W->dir.x, W->p.y + lambda * W->dir.y};
        double mu = dot(sub(X, A), D);
        if (lambda < -M->eps_d || mu < -M->eps_d || mu > len + M->eps_d) return;
        if (lambda < best->lambda) {
            best->lambda = lambda < 0 ? 0 : lambda;
            best->mu = mu < 0 ? 0 : mu > len ? len : mu;
            best->chain = c;
            best->trace = v;
            best->face = beyond;
        }
        return;
    }
    if (!T->flat && runs_back_into_coplanar(W, c, T, beyond, A, D, len, den, best)) return;
    /* Along by distance too (both ends of a finite trace within eps_d of
    ** the ray's line), where it matters, into a coplanar pair: the trace's
    ** direction is a difference of constructed nodes, each up to ~1e-12
    ** off.  A survey case (tests/fuzz/cross_far_vertex_sweep.py, a T with
    ** a vertex at 6.4e4, tests/data/fuzz/mismatch_monotone_t_far_vertex.wpoly):
    ** the bisector of faces 6 / 1 ran along the trace of faces 1 / 2 (2
    ** coplanar with 6) at sine 1e-12, so the trace was neither along nor
    ** crossed, and M' ran on to the trace's end without faces 2 / 6 ever
    ** meeting: valid, not the polygon's skeleton. */
    bool along_by_distance =
        isfinite(len) && fabs(cross(W->dir, Ap)) <= M->eps_d &&
        fabs(cross(W->dir, sub(C->node[T->end].p, W->p))) <= M->eps_d &&
        coplanar(M, beyond, W->face[1 - c]);
    if ((fabs(den) <= WK_MONO_RAY_PARALLEL_SIN && fabs(cross(D, Ap)) <= M->eps_d) ||
        along_by_distance) {
        /* The ray runs along this trace.  If the face beyond is coplanar with
        ** the other chain's face, M' really continues between those two
        ** (the trace is where that coincidence starts): cross here. */
        if (!coplanar(M, beyond, W->face[1 - c])) return;
        double mu = -dot(D, Ap), lambda = 0;
        if (mu < -M->eps_d) { /* ahead of us: where the trace starts */
            lambda = dot(Ap, W->dir);
            mu = 0;
        }
        if (mu > len + M->eps_d || lambda < -M->eps_d) return;
        if (mu > len) mu = len;
        /* A crossing of the other kind within eps_d comes first (below) */
        if (lambda < best->lambda &&
            (best->chain == WK_NONE || best->along || best->lambda > lambda + M->eps_d)) {
            best->lambda = lambda < 0 ? 0 : lambda;
            best->mu = mu;
            best->chain = c;
            best->trace = v;
            best->face = beyond;
            best->along = true;
        }
        return;
    }
    if (left_wall ? den <= WK_MONO_RAY_PARALLEL_SIN : den >= -WK_MONO_RAY_PARALLEL_SIN)
        return; /* not outward */
    double lambda = cross(D, Ap) / den;
    double mu = cross(W->dir, Ap) / den;
    if (lambda < -M->eps_d || mu < -M->eps_d || mu > len + M->eps_d) return;
    if (lambda < 0) lambda = 0;
    if (mu < 0) mu = 0;
    if (mu > len) mu = len;
    /* Before a crossing "along" a trace into a coplanar pair within eps_d
    ** (several traces meeting at the current node): that one says the ray
    ** stays inside the other chain's face, this one says the ray leaves
    ** it, and only this one can be right.  A fuzz finding's second walk
    ** (tests/data/fuzz/mismatch_monotone_cross_far_vertex.wpoly, swept
    ** east): at (0, 0), t = 1, the bisector of faces 2 / 9 runs along the
    ** trace of faces 2 / 5, whose face 5 is coplanar with 9, and through
    ** the lower chain's node where faces 9, 11 and 0 meet; taking the
    ** trace first sent M' round the node through faces 5 and 3 and then
    ** nowhere, while the ray leaves face 9 there at once (face 0 lies
    ** lower on it). */
    if (lambda < best->lambda || (best->along && lambda <= best->lambda + M->eps_d)) {
        best->lambda = lambda;
        best->mu = mu;
        best->chain = c;
        best->trace = v;
        best->face = left_wall ? T->ein : T->eout;
        best->along = false;
    }
    (void)e;
}

/* The walk's unit of work (001's trapezoid cell): one wall trace looked at. */
static void visit(const walk *W, uint32_t c, uint32_t v) {
    wk_event ev = {0, 0, 0, v, WK_NONE, c};
    wk_notify_event(W->M->R, WK_VC_merge_cells_visited, &ev);
}

/* Walk one wall of face e (trace ids w[0..k)) from the current level. */
static void walk_wall(const walk *W, uint32_t c, const uint32_t *w, uint32_t k, bool left_wall,
                      uint32_t e, double tau_p, double kappa, hit *best) {
    const mono *M = W->M;
    const mono_chain *C = &M->ch[c];
    if (k == 0) return;
    double tol = WK_MONO_LEVEL_SLACK * M->eps_t + WK_MONO_LEVEL_REL * fabs(tau_p);
    if (kappa >= 0) {
        /* first trace whose end level reaches tau_p - tol */
        uint32_t lo = 0, hi = k;
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (C->v[w[mid]].t1 < tau_p - tol) lo = mid + 1;
            else hi = mid;
        }
        for (uint32_t j = lo; j < k; j++) {
            double lim = isfinite(best->lambda) ? tau_p + kappa * best->lambda : INFINITY;
            if (kappa == 0) lim = tau_p;
            if (C->v[w[j]].t0 > lim + tol) break;
            visit(W, c, w[j]);
            test_trace(W, c, w[j], left_wall, e, best);
        }
    } else {
        /* last trace whose start level is at most tau_p + tol */
        uint32_t lo = 0, hi = k;
        while (lo < hi) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (C->v[w[mid]].t0 <= tau_p + tol) lo = mid + 1;
            else hi = mid;
        }
        for (uint32_t j = lo; j-- > 0;) {
            double lim = isfinite(best->lambda) ? tau_p + kappa * best->lambda : -INFINITY;
            if (C->v[w[j]].t1 < lim - tol) break;
            visit(W, c, w[j]);
            test_trace(W, c, w[j], left_wall, e, best);
        }
    }
}

static void walk_face(const walk *W, uint32_t c, uint32_t e, hit *best) {
    const mono *M = W->M;
    const mono_chain *C = &M->ch[c];
    uint32_t k = wk_mono_chain_local(M, C, e);
    const wk_offset_line *L = &M->L[e];
    double tau_p = level(L, W->p), kappa = (L->nx * W->dir.x + L->ny * W->dir.y) / L->w;
    walk_wall(W, c, C->lw + C->lw_start[k], C->lw_start[k + 1] - C->lw_start[k], true, e, tau_p,
              kappa, best);
    walk_wall(W, c, C->rw + C->rw_start[k], C->rw_start[k + 1] - C->rw_start[k], false, e, tau_p,
              kappa, best);
}

/* May M''s next vertex move from the crossing the walk found (best, along
** the ray) to q, the exact meeting point of the three offset lines?  Only
** if no other wall of the two faces is crossed on the way: the walk goes on
** from the new vertex and looks ahead only, so a wall passed by the snap
** would never be crossed, and M' would run on inside a face it has left.
** A trace between two nearly parallel edges (two upper edges 0.0014 rad
** apart) lies up to WK_MONO_EXACT_SLACK * eps_d off the exact bisector of
** its edges: its start node joins two collapses whose times differ by less
** than eps_d, and that time difference over the sine of the angle puts the
** node 17.6 off the lines' meeting point at eps_d = 0.05, as naive's
** node is.  A snap to the exact point then jumped 15 units along M', over
** a reflex vertex's trace 6.7 units ahead; M' ran on in the face it had
** left and ended "nowhere" (tests/data/monotone/walk_snap_skips_wall.wpoly,
** a window of mono_gen.py 10^6 seed 8: the variant fell back to the
** reference, about an hour at that n).  A snap back behind the current
** vertex is refused too (M' would turn back).  When refused, the vertex
** stays where the ray crosses the trace as the chain built it, which is
** what the assembly clips that trace at.  Costs a second look at the two
** faces' walls, only for snaps longer than eps_d. */
static bool snap_keeps_order(const walk *W, const hit *best, wk_point X, wk_point q) {
    const mono *M = W->M;
    if (hypot(q.x - X.x, q.y - X.y) <= M->eps_d) return true; /* nothing can lie between */
    double lq = dot(sub(q, W->p), W->dir);
    if (lq < -M->eps_d) return false;
    if (lq <= best->lambda) return true; /* back along the ray, not behind p: passes nothing */
    if (W->n_excl == CLUSTER_MAX) return false;
    walk V = *W; /* the same walk with best's trace crossed */
    V.excl_c[V.n_excl] = best->chain;
    V.excl_v[V.n_excl++] = best->trace;
    hit other = {lq - M->eps_d, 0, WK_NONE, WK_NONE, WK_NONE, INFINITY, false};
    walk_face(&V, 1, V.face[1], &other);
    walk_face(&V, 0, V.face[0], &other);
    return other.chain == WK_NONE;
}

/* Is q, the meeting point of the three offset lines, on the ray's line and
** on the crossed trace's line (within eps_d of each, and within the trace's
** extent), however far along them from the crossing X the walk computed?
** Then X and q are the same crossing, and X's place along the ray is
** decided by rounding: where the ray and the trace are nearly parallel, a
** perpendicular error e moves their crossing by e / sin(angle) along them.
** A fuzz finding: a 12-gon near x = 1e6, 1e6 tall and a few units wide
** (tests/data/fuzz/mismatch_monotone_thin_wedge_1e6.wpoly), whose M'
** between faces 0 and 10 crosses the trace of the 2e-6 rad spike vertex 0 (speed 1e6) at an angle
** of 1e-6 rad: X came out 1.005 from q along both (q 1e-6 off the ray's
** line, 1e-8 off the trace's; 60-digit arithmetic agrees with q), above
** WK_MONO_EXACT_SLACK * eps_d = 1.0, so the node stayed 1e-6 off in time,
** 1 unit off in place: a skeleton the validator accepts but not naive's
** (nor arrangement's, motorcycle's, deforming's).  snap_keeps_order still
** checks that no other wall lies between X and q.  *mu: q's distance along
** the trace (the crossing's place on it for the assembly, which orders the
** crossings of a trace by it). */
static bool on_both_lines(const walk *W, const hit *best, wk_point q, double *mu) {
    const mono *M = W->M;
    const mono_chain *C = &M->ch[best->chain];
    const mono_trace *T = &C->v[best->trace];
    if (T->flat) return false;
    wk_point A = C->node[T->start].p, D;
    double len;
    if (T->end == WK_NONE) {
        double s = hypot(T->vel.x, T->vel.y);
        if (!(s > 0)) return false;
        D = (wk_point){T->vel.x / s, T->vel.y / s};
        len = INFINITY;
    } else {
        D = sub(C->node[T->end].p, A);
        len = hypot(D.x, D.y);
        if (!(len > M->eps_d)) return false;
        D.x /= len, D.y /= len;
    }
    wk_point Aq = sub(q, A), Pq = sub(q, W->p);
    double m = dot(Aq, D);
    if (!(fabs(cross(W->dir, Pq)) <= M->eps_d && fabs(cross(D, Aq)) <= M->eps_d &&
          m >= -M->eps_d && m <= len + M->eps_d))
        return false;
    *mu = m < 0 ? 0 : m > len ? len : m;
    return true;
}

static wk_status add_mnode(mono *M, wk_point p, double t, uint32_t sk, uint32_t *id) {
    if (WK_GROW(M->R, M->mn, M->cap_mn, M->n_mn + 1) != WK_OK) return M->R->err.code;
    memset(&M->mn[M->n_mn], 0, sizeof M->mn[0]);
    M->mn[M->n_mn].p = p;
    M->mn[M->n_mn].t = t;
    M->mn[M->n_mn].sk = sk;
    *id = M->n_mn++;
    wk_event ev = {t, p.x, p.y, *id, sk, WK_NONE};
    wk_notify_event(M->R, WK_VC_merge_chain_vertices, &ev);
    return WK_OK;
}

/* Arc of M' from merge node a to b (upper face left). */
static wk_status add_marc(mono *M, uint32_t a, uint32_t b, uint32_t eu, uint32_t eb) {
    if (WK_GROW(M->R, M->ma, M->cap_ma, M->n_ma + 1) != WK_OK) return M->R->err.code;
    M->ma[M->n_ma++] = (mono_marc){a, b, eu, eb};
    wk_point v = sub(M->mn[b].p, M->mn[a].p);
    double l = hypot(v.x, v.y);
    if (l > 0) v.x /= l, v.y /= l;
    M->mn[a].out_dir = v;
    M->mn[a].has_out = 1;
    M->mn[b].in_dir = v;
    M->mn[b].has_in = 1;
    return WK_OK;
}

wk_status wk_mono_merge(mono *M) {
    wk_run *R = M->R;
    const wk_polygon *P = M->P;
    uint32_t n = P->n;
    walk W;
    memset(&W, 0, sizeof W);
    W.M = M;
    uint32_t eu = (M->vw + n - 1) % n, eb = M->vw; /* the edges at v_w */
    uint32_t eu_end = M->ve, eb_end = (M->ve + n - 1) % n;
    if (add_mnode(M, wk_mono_vertex(M, M->vw), 0.0, M->vw, &W.cur) != WK_OK) return R->err.code;
    W.p = wk_mono_vertex(M, M->vw);
    cluster_start(&W, eu, eb);
    uint64_t max_steps = 16 * (uint64_t)n + 64;
    for (uint64_t step = 0; step < max_steps; step++) {
        const wk_offset_line *Lu = &M->L[eu], *Lb = &M->L[eb];
        wk_point g = {Lu->nx / Lu->w - Lb->nx / Lb->w, Lu->ny / Lu->w - Lb->ny / Lb->w};
        wk_point dir = {-g.y, g.x};
        double gl = hypot(dir.x, dir.y);
        /* M' runs back in time through a coplanar pair (below) */
        bool backwards = false;
        if (coplanar(M, eu, eb)) {
            /* one plane: M' follows the vertex between them, along the normal */
            dir = (wk_point){Lu->nx, Lu->ny};
            if (dot(dir, M->d) < 0) {
                /* Against the normal, M' runs back along that vertex's
                ** trace from its end, where the walk came in, to its start,
                ** where the two coplanar faces first touched.  The walk
                ** cannot place that end: it came in along a trace of the
                ** third face there, whose line is the bisector it ran on
                ** (the third face's bisector with either coplanar face is
                ** one line), so the crossing is decided by the start,
                ** which the walk reaches only later.  A fuzz finding
                ** (tests/data/fuzz/mismatch_monotone_cross_far_vertex.wpoly,
                ** a cross whose arm of edges 6, 7, 8 is a wedge to
                ** x = -3e5): faces 5 and 9 on x = -1 first touch at
                ** t = 0.45 where vertices (5, 6) and (8, 9) meet, and their
                ** vertex runs at y = 0.45 to x = 0; the walk reached x = 0 at
                ** (0, 0), t = 1 (where the flat trace of faces 3 / 5 meets
                ** face 2's traces), turned into faces 9 / 5 there and ran
                ** west along y = 0: a skeleton the validator accepts, not
                ** the polygon's (naive, arrangement, deforming, CGAL agree).
                ** Not certified when it runs back more than eps_d (a pair
                ** that touches at one point is left at once).  Not even
                ** where M' came in forwards between another coplanar pair
                ** on the same line: in bin/wskel-gen rectilinear --n 20
                ** --seed 1 the vertices of faces 1 / 15 and 7 / 11 meet
                ** head-on at (450, 0) (so taking it would be right there),
                ** but in a cross of the survey
                ** (tests/fuzz/cross_far_vertex_sweep.py case 168,
                ** tests/data/fuzz/mismatch_monotone_cross_two_pairs.wpoly)
                ** the pair 5 / 9 runs at y = 0.039, not on the line y = 0
                ** of the pair 3 / 11 that came in. */
                dir.x = -dir.x, dir.y = -dir.y;
                backwards = true;
            }
            gl = 1;
        } else if (!(gl > WK_MONO_COPLANAR_REL * (1 / Lu->w + 1 / Lb->w))) {
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: edges %u and %u have no bisector", eu, eb);
        }
        dir.x /= gl, dir.y /= gl;
        /* dir = g rotated by +90 degrees keeps tau_u < tau_b (the upper
        ** face) on the left: east when M' is strictly monotone, and the
        ** right way along a wall pair perpendicular to the sweep (two walls
        ** facing each other from different chains, non-strict case; walls
        ** are edges within sine WK_PARALLEL_SIN of the perpendicular to d,
        ** direction.c, so M' between them may point that far west) */
        if (dot(dir, M->d) < -WK_PARALLEL_SIN)
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: the merge chain turns west between edges %u and %u", eu, eb);
        W.dir = dir;
        W.face[0] = eb;
        W.face[1] = eu;
        hit best = {INFINITY, 0, WK_NONE, WK_NONE, WK_NONE, INFINITY, false};
        walk_face(&W, 1, eu, &best);
        walk_face(&W, 0, eb, &best);
        if (eu == eu_end && eb == eb_end) {
            double lend = dot(sub(wk_mono_vertex(M, M->ve), W.p), dir);
            if (lend <= best.lambda + M->eps_d) {
                uint32_t m;
                if (add_mnode(M, wk_mono_vertex(M, M->ve), 0.0, M->ve, &m) != WK_OK ||
                    add_marc(M, W.cur, m, eu, eb) != WK_OK)
                    return R->err.code;
                return WK_OK;
            }
        }
        if (isfinite(best.uncertain) && best.uncertain <= best.lambda + M->eps_d) {
            M->coplanar_later = true;
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: the merge chain between faces %u / %u runs back along a "
                           "trace into a coplanar pair of faces (at %.17g, %.17g): not certified",
                           eu, eb, W.p.x + M->o.x, W.p.y + M->o.y);
        }
        if (backwards && best.lambda > M->eps_d) {
            M->coplanar_later = true;
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: the merge chain enters the coplanar faces %u / %u from "
                           "their later side (at %.17g, %.17g): not certified",
                           eu, eb, W.p.x + M->o.x, W.p.y + M->o.y);
        }
        if (best.chain == WK_NONE)
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: the merge chain leaves faces %u / %u nowhere (at %.17g, "
                           "%.17g)",
                           eu, eb, W.p.x + M->o.x, W.p.y + M->o.y);
        /* the new merge vertex: where the offset lines of eu, eb and the
        ** crossed trace's other edge meet, if that agrees with the ray */
        wk_point X = {W.p.x + best.lambda * dir.x, W.p.y + best.lambda * dir.y};
        double t = 0.5 * (level(Lu, X) + level(Lb, X));
        wk_point q;
        double tq, mu_q = best.mu;
        if (wk_three_lines_meet(Lu, Lb, &M->L[best.face], &q, &tq) && tq >= 0 &&
            (hypot(q.x - X.x, q.y - X.y) <= WK_MONO_EXACT_SLACK * M->eps_d ||
             on_both_lines(&W, &best, q, &mu_q)) &&
            snap_keeps_order(&W, &best, X, q)) {
            X = q;
            t = tq;
            best.mu = mu_q;
        }
        if (hypot(X.x - W.p.x, X.y - W.p.y) > M->eps_d) {
            uint32_t m;
            if (W.n_cl > 2 && cluster_uncertain(&W, eu, eb)) {
                M->coplanar_later = true;
                return WK_FAIL(R, WK_EALGO, P->name, 0,
                               "monotone: the merge chain leaves a node of several traces where "
                               "coplanar faces meet (at %.17g, %.17g): not certified",
                               W.p.x + M->o.x, W.p.y + M->o.y);
            }
            if (add_mnode(M, X, t, WK_NONE, &m) != WK_OK || add_marc(M, W.cur, m, eu, eb) != WK_OK)
                return R->err.code;
            W.cur = m;
            W.p = X;
            W.n_excl = 0;
            cluster_start(&W, eu, eb);
        }
        if (W.n_excl == CLUSTER_MAX)
            return WK_FAIL(R, WK_EALGO, P->name, 0,
                           "monotone: the merge chain circles at (%.17g, %.17g)",
                           W.p.x + M->o.x, W.p.y + M->o.y);
        W.excl_c[W.n_excl] = best.chain;
        W.excl_v[W.n_excl++] = best.trace;
        if (WK_GROW(R, M->cr, M->cap_cr, M->n_cr + 1) != WK_OK) return R->err.code;
        M->cr[M->n_cr++] = (mono_cross){best.chain, best.trace, W.cur, best.mu};
        if (best.chain == 1) eu = best.face;
        else eb = best.face;
        W.cl_c[W.n_cl] = best.chain; /* n_excl <= CLUSTER_MAX bounds n_cl */
        W.cl_f[W.n_cl++] = best.face;
    }
    return WK_FAIL(R, WK_EALGO, P->name, 0, "monotone: the merge chain does not reach v_e");
}
