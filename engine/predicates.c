/*
** predicates.c: exact geometric predicates on double coordinates.
**
** wk_orient2d is Shewchuk's two-stage idea written for wskel: evaluate the
** determinant in doubles, and trust its sign when |det| exceeds a bound on
** the rounding error (stage A); otherwise recompute the sign exactly with
** expansion arithmetic.  The exact stage is not adaptive beyond one shortcut:
** when the coordinate differences happen to be exact (the common case for
** near-degenerate inputs on a grid) the determinant is a 4-term expansion,
** else it is the 12-term expansion of the six products of the expanded
** determinant.  Both are exact, so the returned sign is always correct.
**
** Expansions: an expansion is an array of doubles e[0..len) whose exact sum
** is the value represented; the components are nonoverlapping and sorted by
** increasing magnitude, and zero components are dropped (a zero value is the
** one-element expansion {0}).  Then the sign of the value is the sign of the
** last (largest) component.
**
** Assumptions (the same as Shewchuk's, stated in his header): IEEE-754
** binary64, round to nearest even, no extended intermediate precision, and
** no fused multiply-add contraction (the build uses -ffp-contract=off; a
** contracted a*b-c silently breaks two_product).  Exactness also needs the
** products not to overflow or underflow: wk_polygon_from_arrays refuses
** coordinates above 1e150, far inside the overflow range; underflow would
** need nonzero coordinate differences below about 1e-150, which inputs do
** not have in practice, and is not checked.
**
** Error bounds are static const, computed at compile time from
** DBL_EPSILON / 2, so there is no init call and no mutable global.
*/
#include "wskel.h"

#include <float.h>

#if defined(FLT_EVAL_METHOD) && (FLT_EVAL_METHOD == 1 || FLT_EVAL_METHOD == 2)
#error "predicates.c needs double arithmetic without extended precision (FLT_EVAL_METHOD 0)"
#endif

/* Unit roundoff u = 2^-53: |fl(a op b) - (a op b)| <= u |a op b|.  A macro,
** because a static const double is not a constant expression in C. */
#define WK_EPS (DBL_EPSILON / 2.0)
/* Shewchuk's stage A bound for orient2d: |det - fl(det)| <= A * detsum where
** detsum = |detleft| + |detright|. */
static const double CCW_ERRBOUND_A = WK_ORIENT2D_ERRBOUND_A; /* (3 + 16 eps) eps */
/* Dekker's splitter 2^ceil(53/2) + 1: splits a double into two 26-bit halves
** whose products are exact. */
static const double SPLITTER = 134217729.0;

/* ---- error-free transformations (Knuth, Dekker) ---- */

/* x + y == a + b exactly, x = fl(a + b). */
static inline void two_sum(double a, double b, double *x, double *y) {
    double s = a + b;
    double bv = s - a;
    double av = s - bv;
    double br = b - bv;
    double ar = a - av;
    *x = s;
    *y = ar + br;
}

/* x + y == a - b exactly, x = fl(a - b). */
static inline void two_diff(double a, double b, double *x, double *y) {
    double s = a - b;
    double bv = a - s;
    double av = s + bv;
    double br = bv - b;
    double ar = a - av;
    *x = s;
    *y = ar + br;
}

static inline void split(double a, double *hi, double *lo) {
    double c = SPLITTER * a;
    double abig = c - a;
    *hi = c - abig;
    *lo = a - *hi;
}

/* x + y == a * b exactly, x = fl(a * b). */
static inline void two_product(double a, double b, double *x, double *y) {
    double p = a * b;
    double ah, al, bh, bl;
    split(a, &ah, &al);
    split(b, &bh, &bl);
    double err1 = p - ah * bh;
    double err2 = err1 - al * bh;
    double err3 = err2 - ah * bl;
    *x = p;
    *y = al * bl - err3;
}

/* h := e + b (Shewchuk's Grow-Expansion with zero elimination).  e has elen
** components; h needs room for elen + 1 and may alias e (h[i] is written
** only after e[i] was read).  Returns the length of h. */
static int grow_expansion(int elen, const double *e, double b, double *h) {
    double q = b;
    int hlen = 0;
    for (int i = 0; i < elen; i++) {
        double hh;
        two_sum(q, e[i], &q, &hh);
        if (hh != 0.0) h[hlen++] = hh;
    }
    if (q != 0.0 || hlen == 0) h[hlen++] = q;
    return hlen;
}

static int sign_of(double d) { return (d > 0.0) - (d < 0.0); }

/* Exact sign of the determinant, no filter.  Two routes, both exact. */
static int orient2d_exact(wk_point a, wk_point b, wk_point c) {
    double acx, acxt, bcx, bcxt, acy, acyt, bcy, bcyt;
    two_diff(a.x, c.x, &acx, &acxt);
    two_diff(b.x, c.x, &bcx, &bcxt);
    two_diff(a.y, c.y, &acy, &acyt);
    two_diff(b.y, c.y, &bcy, &bcyt);
    double e[13];
    int len = 1;
    e[0] = 0.0;
    if (acxt == 0.0 && bcxt == 0.0 && acyt == 0.0 && bcyt == 0.0) {
        /* The differences are exact: det = acx*bcy - acy*bcx, four terms. */
        double p[4];
        two_product(acx, bcy, &p[0], &p[1]);
        two_product(acy, bcx, &p[2], &p[3]);
        p[2] = -p[2];
        p[3] = -p[3];
        for (int i = 0; i < 4; i++) len = grow_expansion(len, e, p[i], e);
    } else {
        /* det = ax*by - ax*cy - cx*by - ay*bx + ay*cx + cy*bx (the cx*cy
        ** terms cancel): six exact products, twelve doubles. */
        const double f[6][3] = {
            {a.x, b.y, 1.0},  {a.x, c.y, -1.0}, {c.x, b.y, -1.0},
            {a.y, b.x, -1.0}, {a.y, c.x, 1.0},  {c.y, b.x, 1.0},
        };
        for (int i = 0; i < 6; i++) {
            double hi, lo;
            two_product(f[i][0], f[i][1], &hi, &lo);
            /* Negation is exact, so multiplying by the sign +-1 is too. */
            len = grow_expansion(len, e, f[i][2] * lo, e);
            len = grow_expansion(len, e, f[i][2] * hi, e);
        }
    }
    return sign_of(e[len - 1]);
}

int wk_orient2d(wk_point a, wk_point b, wk_point c, bool *exact_used) {
    if (exact_used) *exact_used = false;
    double detleft = (a.x - c.x) * (b.y - c.y);
    double detright = (a.y - c.y) * (b.x - c.x);
    double det = detleft - detright;
    double detsum;
    /* Rounding keeps the sign of each difference and each product, so when
    ** the two products differ in sign (or one is zero) the sign of det is
    ** already right. */
    if (detleft > 0.0) {
        if (detright <= 0.0) return sign_of(det);
        detsum = detleft + detright;
    } else if (detleft < 0.0) {
        if (detright >= 0.0) return sign_of(det);
        detsum = -detleft - detright;
    } else {
        return sign_of(det);
    }
    double errbound = CCW_ERRBOUND_A * detsum;
    if (det >= errbound || -det >= errbound) return sign_of(det);
    if (exact_used) *exact_used = true;
    return orient2d_exact(a, b, c);
}

int wk_orient2d_fast(wk_point a, wk_point b, wk_point c) {
    double det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
    return sign_of(det);
}

/* ---- exact sums ---- */

double wk_shoelace_exact(const wk_point *p, uint32_t n) {
    /* A nonoverlapping expansion has components on disjoint bit ranges
    ** within the 2098 bit positions of a double (2^-1074 to 2^1023), so
    ** 2100 slots always suffice; in practice it stays a few components
    ** long, so each addition is cheap. */
    double e[2100];
    int len = 1;
    e[0] = 0.0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t j = i + 1 == n ? 0 : i + 1;
        double hi, lo;
        two_product(p[i].x, p[j].y, &hi, &lo);
        len = grow_expansion(len, e, lo, e);
        len = grow_expansion(len, e, hi, e);
        two_product(p[j].x, p[i].y, &hi, &lo);
        len = grow_expansion(len, e, -lo, e);
        len = grow_expansion(len, e, -hi, e);
    }
    /* Smallest first: the result has the sign of the largest component and
    ** is within a few ulps of the exact value. */
    double s = 0.0;
    for (int k = 0; k < len; k++) s += e[k];
    return s;
}

/* ---- segments ---- */

int wk_point_lex_cmp(wk_point p, wk_point q) {
    if (p.x < q.x) return -1;
    if (p.x > q.x) return 1;
    if (p.y < q.y) return -1;
    if (p.y > q.y) return 1;
    return 0;
}

/* For p collinear with segment [a, b]: p lies on the closed segment iff it
** lies between the endpoints in lexicographic order. */
static bool between(wk_point a, wk_point b, wk_point p) {
    if (wk_point_lex_cmp(a, b) > 0) {
        wk_point t = a;
        a = b;
        b = t;
    }
    return wk_point_lex_cmp(a, p) <= 0 && wk_point_lex_cmp(p, b) <= 0;
}

wk_seg_meet wk_segments_meet_ex(wk_point a, wk_point b, wk_point c, wk_point d,
                                uint32_t *exact_stages) {
    bool x1, x2, x3, x4;
    int o1 = wk_orient2d(a, b, c, &x1);
    int o2 = wk_orient2d(a, b, d, &x2);
    int o3 = wk_orient2d(c, d, a, &x3);
    int o4 = wk_orient2d(c, d, b, &x4);
    if (exact_stages) *exact_stages = (uint32_t)x1 + x2 + x3 + x4;
    if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) {
        /* All four points on one line (or degenerate segments): compare the
        ** lexicographic extents. */
        wk_point s0 = a, s1 = b, t0 = c, t1 = d;
        if (wk_point_lex_cmp(s0, s1) > 0) { wk_point t = s0; s0 = s1; s1 = t; }
        if (wk_point_lex_cmp(t0, t1) > 0) { wk_point t = t0; t0 = t1; t1 = t; }
        if (wk_point_lex_cmp(s1, t0) < 0 || wk_point_lex_cmp(t1, s0) < 0) return WK_SEG_DISJOINT;
        /* They meet in a single point when one ends where the other starts
        ** or when one of them is a point; else in a segment. */
        if (wk_point_lex_cmp(s1, t0) == 0 || wk_point_lex_cmp(t1, s0) == 0 || wk_point_lex_cmp(s0, s1) == 0 ||
            wk_point_lex_cmp(t0, t1) == 0)
            return WK_SEG_TOUCH;
        return WK_SEG_OVERLAP;
    }
    if (o1 * o2 > 0 || o3 * o4 > 0) return WK_SEG_DISJOINT;
    if (o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) return WK_SEG_CROSS;
    /* One endpoint lies on the other segment's line; it meets the segment
    ** only if it lies within it. */
    if ((o1 == 0 && between(a, b, c)) || (o2 == 0 && between(a, b, d)) ||
        (o3 == 0 && between(c, d, a)) || (o4 == 0 && between(c, d, b)))
        return WK_SEG_TOUCH;
    return WK_SEG_DISJOINT;
}

wk_seg_meet wk_segments_meet(wk_point a, wk_point b, wk_point c, wk_point d) {
    return wk_segments_meet_ex(a, b, c, d, NULL);
}

bool wk_segments_intersect(wk_point a, wk_point b, wk_point c, wk_point d) {
    return wk_segments_meet(a, b, c, d) != WK_SEG_DISJOINT;
}
