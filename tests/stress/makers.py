"""makers.py: the polygons of the stress sweep (tests/stress/stress.py).

Every maker takes a random.Random and returns a Case: points, weights, a
description that says how it was made, and whether the polygon is monotone
by construction (then the monotone variant must not refuse it).  Makers do
not check simplicity: bin/wskel's reader is the judge (exit 1: the maker made
an invalid polygon, which the sweep drops and counts).

Classes (CLASSES, in the sweep's round-robin order):

  gen:FAMILY            every family of `bin/wskel-gen --list`, n log-uniform
                        up to NMAX, unit/uniform/two/int weights
  grid                  snapped to a coarse integer grid (G = 4..256): random
                        grid points sorted around a centre, double histograms,
                        generator polygons rounded onto the grid
  turned                grid, rectilinear, comb and monotone polygons turned
                        by a random angle (in doubles: collinear and parallel
                        only up to rounding), some by pi/2, pi/4, pi/6 exactly
  far                   any base polygon, scaled to 1e-3 .. 1e3, moved 1e6
                        from the origin
  tiny_edge             edges of 1e-9 .. 1e-15 of the diagonal: a vertex
                        inserted next to a vertex on its edge, or a corner cut
                        off (chamfer)
  nearly_straight       vertices inserted on edges, off the line by 1e-6 ..
                        1e-16 of the edge (convex or reflex)
  collinear_mixed       integer polygons whose edges are split into exactly
                        collinear runs (2..12 pieces) of mixed weights (the
                        issue's square with sides of six weights among them),
                        a quarter of them turned afterwards
  regular_far_vertex    regular 6..64-gons, one vertex pulled 2x .. 1000x out
  regular_nearly_straight  ... one coordinate of one vertex moved onto its
                        neighbours' chord, +- 0 .. 1e-10 of the radius
  regular_tiny_edge     ... one vertex moved to within ~1e-16 (or a few ulps)
                        of the next one
  regular_4e9           ... one vertex pulled out to 4e9 from the centre
  weight_ratio          any base polygon, weight ratios 10 .. 1e6 (log-uniform,
                        two-valued, one heavy, one light, alternating)
  turned_monotone       x-monotone polygons with runs of collinear vertices and
                        pairs of equal x (walls perpendicular to the sweep),
                        turned by a random angle, some moved 1e5 away
  mixed                 a base polygon through two or three of: snap, turn,
                        move far, tiny edges, nearly straight vertices, weight
                        ratios

Weights are normalised so that the smallest is 1 where a maker sets them
(times of the skeleton stay below the diagonal; the comparison's tolerance is
one number for positions and times).
"""

import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import testlib  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WSKEL_GEN = os.environ.get("WSKEL_GEN_BIN", os.path.join(ROOT, "bin", "wskel-gen"))

NMAX = 300  # largest n a maker asks a generator for
# Families that are monotone in some direction (x) by construction; comb and
# rectilinear only weakly (walls perpendicular to x).
MONOTONE_FAMILIES = {"monotone", "convex", "rectilinear", "comb"}
# Smallest n a family accepts (and rectilinear wants n even).
N_MIN = {"comb": 4, "spiral": 6, "notched": 5, "crossing": 4, "rectilinear": 4}


class MakerError(Exception):
    """The maker could not make its polygon (e.g. the generator refused);
    counted by the sweep as 'not made', not as an invalid polygon."""


class Case:
    def __init__(self, pts, ws, desc, monotone=False):
        self.pts = [(float(x), float(y)) for x, y in pts]
        self.ws = [float(w) for w in ws]
        self.desc = desc
        self.monotone = bool(monotone)


# ---------------------------------------------------------------- wpoly

def wpoly_body(pts, ws):
    """The .wpoly text without comments: n, then 'x y w' with 17 digits."""
    lines = ["%d" % len(pts)]
    for (x, y), w in zip(pts, ws):
        lines.append("%.17g %.17g %.17g" % (x, y, w))
    return "\n".join(lines) + "\n"


def parse_wpoly(text):
    """(points, weights, comment lines) of .wpoly text (testlib's parser)."""
    return testlib.parse_wpoly(text)


# ------------------------------------------------------------- geometry

def signed_area(pts):
    return 0.5 * sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1]
                     for i in range(len(pts)))


def bbox(pts):
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return min(xs), min(ys), max(xs), max(ys)


def diagonal(pts):
    x0, y0, x1, y1 = bbox(pts)
    return math.hypot(x1 - x0, y1 - y0)


def ccw(pts, ws):
    """Counter-clockwise copy; weight i stays on the edge it weighted (the
    reversed edge from vertex i+1 to i)."""
    if signed_area(pts) >= 0:
        return list(pts), list(ws)
    n = len(pts)
    return [pts[n - 1 - i] for i in range(n)], [ws[(n - 2 - i) % n] for i in range(n)]


def clean(pts, ws):
    """Drop vertices that repeat the previous one exactly (after rounding or
    snapping), keeping the weight of the edge that survives."""
    out_p, out_w = [], []
    for p, w in zip(pts, ws):
        if out_p and p == out_p[-1]:
            out_w[-1] = w
            continue
        out_p.append(p)
        out_w.append(w)
    while len(out_p) > 1 and out_p[0] == out_p[-1]:
        out_p.pop()
        out_w.pop()
    return out_p, out_w


def rotate(pts, th, about=(0.0, 0.0)):
    c, s = math.cos(th), math.sin(th)
    ax, ay = about
    return [(ax + c * (x - ax) - s * (y - ay), ay + s * (x - ax) + c * (y - ay)) for x, y in pts]


def fit(pts, size, at=(0.0, 0.0)):
    """Scaled so that the diagonal is `size`, lower left corner at `at`."""
    x0, y0, _, _ = bbox(pts)
    d = diagonal(pts)
    k = size / d
    return [(at[0] + (x - x0) * k, at[1] + (y - y0) * k) for x, y in pts]


def loguniform(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def nudge(p, q, toward):
    """p moved a few ulps towards `toward` until it differs from q."""
    x, y = p
    for _ in range(64):
        if (x, y) != q:
            return (x, y)
        x = math.nextafter(x, toward[0])
        y = math.nextafter(y, toward[1])
    return (x, y)


# ------------------------------------------------------------ generators

_FAMILIES = None


def families():
    """The families of `bin/wskel-gen --list` (so a new family is swept)."""
    global _FAMILIES
    if _FAMILIES is None:
        p = subprocess.run([WSKEL_GEN, "--list"], capture_output=True, text=True, timeout=60)
        if p.returncode != 0:
            raise RuntimeError("%s --list: exit %d: %s" % (WSKEL_GEN, p.returncode, p.stderr))
        # Not "holes": without --holes it is a star/convex polygon the other
        # families already cover, and a new class would shift every case's
        # class (case i is class i mod the number of classes), invalidating
        # tests/data/stress/KNOWN.  Holes are swept by test_cgal_agreement.py.
        _FAMILIES = [line.split()[0] for line in p.stdout.splitlines()
                     if line.strip() and line.split()[0] != "holes"]
        if not _FAMILIES:
            raise RuntimeError("%s --list lists no family" % WSKEL_GEN)
    return _FAMILIES


def generate(family, n, seed, weights="unit"):
    """(points, weights, description) of bin/wskel-gen FAMILY."""
    cmd = [WSKEL_GEN, family, "--n", str(n), "--seed", str(seed), "--weights", weights]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    desc = "wskel-gen %s --n %d --seed %d --weights %s" % (family, n, seed, weights)
    if p.returncode != 0:
        raise MakerError("%s: exit %d: %s" % (desc, p.returncode, p.stderr.strip()))
    pts, ws, _ = parse_wpoly(p.stdout)
    return pts, ws, desc


def family_n(rng, family, nmax=NMAX):
    lo = N_MIN.get(family, 3)
    n = int(round(loguniform(rng, lo, max(lo, nmax))))
    if family == "rectilinear":
        n += n % 2
    return max(lo, n)


def gen_case(rng, family, nmax=NMAX, weights=None):
    n = family_n(rng, family, nmax)
    w = weights or rng.choice(["unit", "unit", "uniform", "two", "int"])
    pts, ws, desc = generate(family, n, rng.randrange(1, 2 ** 63), w)
    return Case(pts, ws, desc, family in MONOTONE_FAMILIES)


# ---------------------------------------------------------------- shapes

def regular(k, r=1.0, th=0.0, c=(0.0, 0.0)):
    return [(c[0] + r * math.cos(th + 2 * math.pi * i / k),
             c[1] + r * math.sin(th + 2 * math.pi * i / k)) for i in range(k)]


SHAPES = {
    "square": ([(0, 0), (1, 0), (1, 1), (0, 1)], True),
    "rect": ([(0, 0), (3, 0), (3, 1), (0, 1)], True),
    "L": ([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)], True),
    "cross": ([(1, 0), (2, 0), (2, 1), (3, 1), (3, 2), (2, 2), (2, 3), (1, 3), (1, 2), (0, 2),
               (0, 1), (1, 1)], False),
    "H": ([(0, 0), (1, 0), (1, 1), (2, 1), (2, 0), (3, 0), (3, 3), (2, 3), (2, 2), (1, 2),
           (1, 3), (0, 3)], True),
    "comb3": ([(0, 0), (5, 0), (5, 3), (4, 3), (4, 1), (3, 1), (3, 3), (2, 3), (2, 1), (1, 1),
               (1, 3), (0, 3)], True),
    "triangle": ([(0, 0), (4, 0), (1, 3)], True),
}


def base(rng, nmax=80, integer=False):
    """A polygon to be modified: a generator family (n <= nmax), a regular
    polygon or a small hand shape.  integer=True: integer coordinates only
    (grid-snapped families, rectilinear, comb, hand shapes).
    Returns a Case with unit or generator weights."""
    kind = rng.choice(["gen", "gen", "gen", "regular", "shape"])
    if kind == "regular" and not integer:
        k = rng.randint(3, 64)
        return Case(regular(k, rng.choice([1.0, 100.0]), rng.uniform(0, 2 * math.pi)), [1] * k,
                    "regular %d-gon" % k, True)
    if kind == "shape" or (kind == "regular" and integer):
        name = rng.choice(sorted(SHAPES))
        pts, mono = SHAPES[name]
        return Case(pts, [1] * len(pts), "shape %s" % name, mono)
    fams = families()
    if integer:
        fam = rng.choice(["rectilinear", "comb", "snap"])
        if fam == "snap":
            c = gen_case(rng, rng.choice(fams), min(nmax, 40))
            g = rng.choice([16, 32, 64, 128, 256])
            pts, ws = clean(snap(c.pts, g), c.ws)
            return Case(pts, ws, "%s, snapped to a %dx%d grid" % (c.desc, g, g), c.monotone)
        return gen_case(rng, fam, nmax)
    return gen_case(rng, rng.choice(fams), nmax)


def snap(pts, g):
    """Scaled into [0, g]^2 (aspect kept) and rounded to integers."""
    x0, y0, x1, y1 = bbox(pts)
    k = g / max(x1 - x0, y1 - y0)
    return [(float(round((x - x0) * k)), float(round((y - y0) * k))) for x, y in pts]


# ------------------------------------------------------------ modifiers

def mod_tiny_edges(rng, pts, ws, count=None):
    """count vertices each get a tiny edge, 1e-9 .. 1e-15 of the diagonal:
    'split' inserts a vertex on the vertex's edge, 'chamfer' cuts the corner
    off.  Returns (pts, ws, description)."""
    d = diagonal(pts)
    count = count or rng.choice([1, 1, 2, 3])
    chosen = sorted(rng.sample(range(len(pts)), min(count, len(pts))), reverse=True)
    notes = []
    pts, ws = list(pts), list(ws)
    for i in chosen:
        n = len(pts)
        eps = 10 ** -rng.uniform(9, 15)
        mode = rng.choice(["split", "chamfer"])
        a, b, c = pts[i - 1], pts[i], pts[(i + 1) % n]
        wnew = rng.choice([ws[i], ws[i - 1], 1.0, 2.0])

        def toward(p, q):
            L = math.hypot(q[0] - p[0], q[1] - p[1])
            t = min(0.25, eps * d / L)
            return nudge((p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t), p, q)
        if mode == "split":  # b, b' (tiny edge b b' of edge i's weight), c
            pts.insert(i + 1, toward(b, c))
            ws.insert(i + 1, ws[i])
            ws[i] = wnew
        else:  # a, b1, b2, c: b replaced by the tiny edge b1 b2
            b1, b2 = toward(b, a), toward(b, c)
            pts[i:i + 1] = [b1, b2]
            ws[i:i + 1] = [wnew, ws[i]]
        notes.append("%s at %d (%.1e)" % (mode, i, eps))
    return pts, ws, "tiny edges: " + ", ".join(notes)


def mod_nearly_straight(rng, pts, ws, lo=6, hi=16, count=None):
    """count vertices inserted on edges, off the edge's line by 1e-lo ..
    1e-hi of the edge length, to either side.  Returns (pts, ws, desc, the
    largest relative offset)."""
    count = count or rng.choice([1, 1, 2, 3])
    chosen = sorted(rng.sample(range(len(pts)), min(count, len(pts))), reverse=True)
    notes, worst = [], 0.0
    pts, ws = list(pts), list(ws)
    for i in chosen:
        a, b = pts[i], pts[(i + 1) % len(pts)]
        dx, dy = b[0] - a[0], b[1] - a[1]
        t = rng.uniform(0.05, 0.95)
        delta = rng.choice([-1, 1]) * 10 ** -rng.uniform(lo, hi)
        worst = max(worst, abs(delta))
        p = (a[0] + t * dx - delta * dy, a[1] + t * dy + delta * dx)
        pts.insert(i + 1, p)
        ws.insert(i + 1, rng.choice([ws[i], ws[i], 1.0, 3.0]))
        notes.append("%d (t %.2f, off %.1e)" % (i, t, delta))
    return pts, ws, "nearly straight vertices on edges " + ", ".join(notes), worst


def ratio_weights(rng, n, ratio=None):
    """Weights with max/min = ratio (10 .. 1e6; smallest 1), and the mode."""
    ratio = ratio or rng.choice([1e6, 10 ** rng.uniform(1, 6)])
    mode = rng.choice(["loguniform", "two", "one_heavy", "one_light", "alternating"])
    if mode == "loguniform":
        ws = [loguniform(rng, 1, ratio) for _ in range(n)]
        ws[rng.randrange(n)] = 1.0
        ws[rng.randrange(n)] = ratio
    elif mode == "two":
        ws = [rng.choice([1.0, ratio]) for _ in range(n)]
    elif mode == "one_heavy":
        ws = [1.0] * n
        ws[rng.randrange(n)] = ratio
    elif mode == "one_light":
        ws = [ratio] * n
        ws[rng.randrange(n)] = 1.0
    else:
        ws = [1.0 if i % 2 else ratio for i in range(n)]
    m = min(ws)
    return [w / m for w in ws], "weights %s, ratio up to %.3g" % (mode, ratio)


def far_offset(rng):
    th = rng.choice([0.0, -math.atan2(2, 1), rng.uniform(0, 2 * math.pi)])
    r = rng.choice([1e6, 1e6 * math.sqrt(5)])
    return (r * math.cos(th), r * math.sin(th))


# ---------------------------------------------------------------- makers

def m_grid(rng):
    g = rng.choice([4, 6, 8, 10, 16, 20, 32, 64, 128, 256])
    kind = rng.choice(["star", "histogram", "snap"])
    mono = False
    if kind == "star":
        m = rng.randint(4, min(30, (g + 1) ** 2 // 2))
        pts = set()
        while len(pts) < m:
            pts.add((rng.randint(0, g), rng.randint(0, g)))
        pts = list(pts)
        cx = sum(p[0] for p in pts) / m + rng.uniform(-0.3, 0.3)
        cy = sum(p[1] for p in pts) / m + rng.uniform(-0.3, 0.3)
        pts.sort(key=lambda p: (math.atan2(p[1] - cy, p[0] - cx), (p[0] - cx) ** 2
                                + (p[1] - cy) ** 2))
        desc = "%d grid points sorted around a centre" % m
    elif kind == "histogram":
        k = rng.randint(2, max(2, min(g - 1, 12)))
        xs = sorted(rng.sample(range(0, g + 1), k + 1))
        lo = [rng.randint(0, g // 2 - 1) for _ in range(k)]
        hi = [rng.randint(g // 2 + 1, g) for _ in range(k)]
        pts = []
        for i in range(k):
            pts += [(xs[i], lo[i]), (xs[i + 1], lo[i])]
        for i in reversed(range(k)):
            pts += [(xs[i + 1], hi[i]), (xs[i], hi[i])]
        desc, mono = "double histogram of %d columns" % k, True
    else:
        c = gen_case(rng, rng.choice(families()), 40)
        pts, desc, mono = snap(c.pts, g), c.desc + ", snapped", c.monotone
    mode = rng.choice(["unit", "unit", "tie", "int"])
    ws = ([1] * len(pts) if mode == "unit" else [rng.choice([1, 2]) for _ in pts]
          if mode == "tie" else [rng.randint(1, 5) for _ in pts])
    pts, ws = clean([(float(x), float(y)) for x, y in pts], ws)
    return Case(pts, ws, "%s on a %dx%d grid, %s weights" % (desc, g, g, mode), mono)


def turn_angle(rng):
    return rng.choice([math.pi / 2, math.pi / 4, math.pi / 6, rng.uniform(0, 2 * math.pi),
                       rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)])


def m_turned(rng):
    src = rng.choice(["grid", "grid", "rectilinear", "comb", "monotone"])
    c = m_grid(rng) if src == "grid" else gen_case(rng, src, 120)
    th = turn_angle(rng)
    about = rng.choice([(0.0, 0.0), tuple(x / 2 for x in bbox(c.pts)[2:])])
    return Case(rotate(c.pts, th, about), c.ws, "%s, turned by %.17g" % (c.desc, th), c.monotone)


def m_far(rng):
    c = base(rng, 120)
    size = rng.choice([5e-3, 1e-2, 1.0, 1e3])  # 5e-3 at 2.2e6: at most 4.5e8 diagonals (input domain)
    off = far_offset(rng)
    pts = fit(c.pts, size, off)
    if rng.random() < 0.3:
        th = turn_angle(rng)
        pts = rotate(pts, th, off)
        c.desc += ", turned by %.17g" % th
    return Case(pts, c.ws, "%s, diagonal %g, moved to (%.6g, %.6g)" % (c.desc, size, *off),
                c.monotone and far_keeps_shape(off, size))


def far_keeps_shape(off, size):
    """Coordinates near off carry a rounding of ulp(|off|): against a
    diagonal `size` that stays below the tolerance policy's 1e-9 (with room,
    1e-11) only for large enough polygons; a smaller one is no longer
    monotone by construction (walls perpendicular to the sweep lean by the
    rounding)."""
    return max(abs(off[0]), abs(off[1])) * 2.0 ** -52 / size < 1e-11


def m_tiny_edge(rng):
    c = base(rng, 150)
    pts, ws, d = mod_tiny_edges(rng, c.pts, c.ws)
    return Case(pts, ws, "%s, %s" % (c.desc, d), c.monotone)


def m_nearly_straight(rng):
    c = base(rng, 150)
    pts, ws, d, worst = mod_nearly_straight(rng, c.pts, c.ws)
    # Off the line by more than the tolerance (1e-9), the polygon may truly
    # stop being monotone (a vertex inserted on a wall perpendicular to the
    # sweep): no longer monotone by construction.
    return Case(pts, ws, "%s, %s" % (c.desc, d), c.monotone and worst < 1e-10)


def split_collinear(rng, pts, ws, kmax=12, same=False):
    """Every edge of an integer polygon split into k exactly collinear pieces
    (k divides the edge's gcd after scaling the polygon by 12); weights of the
    pieces mixed from the weight set."""
    scale = 12
    pts = [(x * scale, y * scale) for x, y in pts]
    wset = rng.choice([[1, 2], [1, 2, 3], [0.5, 1, 1.5, 2, 3, 4], [1, 10, 100], [1, 7, 1000]])
    out_p, out_w = [], []
    n = len(pts)
    for i in range(n):
        a, b = pts[i], pts[(i + 1) % n]
        dx, dy = int(b[0] - a[0]), int(b[1] - a[1])
        g = math.gcd(abs(dx), abs(dy))
        divs = [k for k in range(1, kmax + 1) if g % k == 0]
        k = rng.choice(divs) if not same else max(divs)
        for j in range(k):
            out_p.append((a[0] + j * dx // k, a[1] + j * dy // k))
            out_w.append(rng.choice(wset) if not same else wset[j % len(wset)])
    m = min(out_w)
    return [(float(x), float(y)) for x, y in out_p], [w / m for w in out_w], str(wset)


def m_collinear_mixed(rng):
    kind = rng.choice(["square6", "base", "base", "grid"])
    if kind == "square6":  # the example: each side six weights
        L = rng.choice([1, 6, 12])
        sq = [(0, 0), (L, 0), (L, L), (0, L)]
        pts, ws, wset = split_collinear(rng, sq, [1] * 4, kmax=6, same=rng.random() < 0.5)
        c = Case(pts, ws, "square, sides split into 6 collinear edges", True)
    else:
        b = base(rng, 60, integer=True) if kind == "base" else m_grid(rng)
        pts, ws, wset = split_collinear(rng, b.pts, b.ws)
        c = Case(pts, ws, "%s, edges split into collinear runs" % b.desc, b.monotone)
    c.desc += ", weights from %s" % wset
    if rng.random() < 0.25:
        th = turn_angle(rng)
        c.pts = rotate(c.pts, th)
        c.desc += ", turned by %.17g" % th
    return c


def _regular_base(rng):
    k = rng.randint(6, 64)
    r = rng.choice([1.0, 1.0, 100.0, 1e3, 1e-3])
    th = rng.choice([0.0, rng.uniform(0, 2 * math.pi)])
    c = rng.choice([(0.0, 0.0), (0.0, 0.0), (rng.uniform(-10, 10) * r, rng.uniform(-10, 10) * r)])
    ws = [1.0] * k if rng.random() < 0.7 else [rng.choice([1.0, 2.0, 0.5]) for _ in range(k)]
    m = min(ws)
    return k, r, c, regular(k, r, th, c), [w / m for w in ws], \
        "regular %d-gon r %g rotated %.17g centre (%.6g, %.6g)" % (k, r, th, *c)


def m_regular_far_vertex(rng):
    k, r, c, pts, ws, desc = _regular_base(rng)
    i = rng.randrange(k)
    f = loguniform(rng, 2, 1000)
    x, y = pts[i]
    if rng.random() < 0.6:  # radially
        pts[i] = (c[0] + (x - c[0]) * f, c[1] + (y - c[1]) * f)
        return Case(pts, ws, "%s, vertex %d pulled out radially x%.4g" % (desc, i, f), True)
    if rng.random() < 0.5:  # one coordinate
        pts[i] = (c[0] + (x - c[0]) * f, y)
        what = "x"
    else:
        pts[i] = (x, c[1] + (y - c[1]) * f)
        what = "y"
    return Case(pts, ws, "%s, vertex %d: %s pulled out x%.4g" % (desc, i, what, f), False)


def m_regular_nearly_straight(rng):
    k, r, c, pts, ws, desc = _regular_base(rng)
    i = rng.randrange(k)
    a, b = pts[i - 1], pts[(i + 1) % k]
    x, y = pts[i]
    delta = rng.choice([0.0, 1.0, -1.0]) * r * 10 ** -rng.uniform(10, 17)
    # One coordinate moved onto the neighbours' line: the one whose other
    # coordinate lies between the neighbours' (the move stays on the chord).
    if abs(b[1] - a[1]) >= abs(b[0] - a[0]):
        x = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) + delta
        what = "x"
    else:
        y = a[1] + (x - a[0]) * (b[1] - a[1]) / (b[0] - a[0]) + delta
        what = "y"
    pts[i] = (x, y)
    return Case(pts, ws, "%s, vertex %d: %s onto the neighbours' chord %+.1e" % (desc, i, what,
                                                                               delta), True)


def m_regular_tiny_edge(rng):
    k, r, c, pts, ws, desc = _regular_base(rng)
    i = rng.randrange(k)
    p, q = pts[i], pts[(i + 1) % k]
    if rng.random() < 0.5:  # along the old edge, ~1e-16 of the radius
        L = r * 10 ** -rng.uniform(15.5, 16.5)
        e = math.hypot(p[0] - q[0], p[1] - q[1])
        new = nudge((q[0] + (p[0] - q[0]) * L / e, q[1] + (p[1] - q[1]) * L / e), q, p)
        what = "within %.1e of vertex %d along the edge" % (L, (i + 1) % k)
    else:  # one coordinate a few ulps off the next vertex's
        u = rng.randint(1, 4)
        x, y = q
        if abs(p[0] - q[0]) >= abs(p[1] - q[1]):
            for _ in range(u):
                x = math.nextafter(x, p[0])
            what = "x %d ulps off vertex %d" % (u, (i + 1) % k)
        else:
            for _ in range(u):
                y = math.nextafter(y, p[1])
            what = "y %d ulps off vertex %d" % (u, (i + 1) % k)
        new = (x, y)
    pts[i] = new
    return Case(pts, ws, "%s, vertex %d moved %s" % (desc, i, what), True)


def m_regular_4e9(rng):
    k, r, c, pts, ws, desc = _regular_base(rng)
    i = rng.randrange(k)
    x, y = pts[i]
    d = math.hypot(x - c[0], y - c[1])
    if rng.random() < 0.7:
        pts[i] = (c[0] + (x - c[0]) * 4e9 / d, c[1] + (y - c[1]) * 4e9 / d)
        return Case(pts, ws, "%s, vertex %d pulled out to 4e9" % (desc, i), True)
    if abs(x - c[0]) >= abs(y - c[1]):
        pts[i] = (math.copysign(4e9, x - c[0]), y)
    else:
        pts[i] = (x, math.copysign(4e9, y - c[1]))
    return Case(pts, ws, "%s, vertex %d: one coordinate set to +-4e9" % (desc, i), False)


def m_weight_ratio(rng):
    c = base(rng, 200)
    ws, d = ratio_weights(rng, len(c.pts))
    return Case(c.pts, ws, "%s, %s" % (c.desc, d), c.monotone)


def m_turned_monotone(rng):
    n = rng.choice([5, 6, 8, 12, 20, 50, 100])
    style = rng.choice(["random", "zigzag", "levels", "pairs"])
    if style == "pairs":  # pairs of equal x: walls perpendicular to the sweep
        xs = sorted(rng.sample(range(1, 100), (n - 2 + 1) // 2))
        xs = sorted([float(x) for x in xs] * 2)[: n - 2]
    else:
        xs = sorted(rng.uniform(0, 100) for _ in range(n - 2))
    idx = list(range(len(xs)))
    low = set(rng.sample(idx, rng.randint(1, len(xs) - 1)))

    def h(sign):
        if style in ("random", "pairs"):
            return sign * rng.uniform(1, 30)
        if style == "zigzag":
            return sign * (10 + (rng.uniform(5, 20) if rng.random() < 0.5 else 0))
        return sign * rng.choice([5, 10, 15])
    lower = [(xs[j], h(-1)) for j in idx if j in low]
    upper = [(xs[j], h(1)) for j in reversed(idx) if j not in low]
    pts = [(-1.0, 0.0)] + lower + [(101.0, 0.0)] + upper
    th = rng.choice([0.0, math.pi / 2, rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)])
    off = rng.choice([0.0, 0.0, 1e5])
    pts = [(off + x, off + y) for x, y in rotate(pts, th)]
    mode = rng.choice(["unit", "unit", "tie", "real"])
    ws = ([1] * len(pts) if mode == "unit" else [rng.choice([1, 2]) for _ in pts]
          if mode == "tie" else [rng.uniform(1, 4) for _ in pts])
    return Case(pts, ws, "x-monotone n=%d (%s chains, %s weights), turned by %.17g, moved %g"
                % (len(pts), style, mode, th, off), True)


def m_mixed(rng):
    c = base(rng, 100)
    pts, ws, mono, notes = c.pts, c.ws, c.monotone, [c.desc]
    mods = rng.sample(["snap", "turn", "far", "tiny", "straight", "ratio"], rng.randint(2, 3))
    order = ["snap", "tiny", "straight", "turn", "far", "ratio"]
    turned = False
    for m in sorted(mods, key=order.index):
        if m == "snap":
            g = rng.choice([8, 16, 32, 64])
            pts, ws = clean(snap(pts, g), ws)
            notes.append("snapped to %dx%d" % (g, g))
        elif m == "tiny":
            pts, ws, d = mod_tiny_edges(rng, pts, ws)
            notes.append(d)
        elif m == "straight":
            pts, ws, d, worst = mod_nearly_straight(rng, pts, ws)
            mono = mono and worst < 1e-10
            notes.append(d)
        elif m == "turn":
            th = turn_angle(rng)
            pts = rotate(pts, th)
            turned = True
            notes.append("turned by %.17g" % th)
        elif m == "far":
            off = far_offset(rng)
            size = rng.choice([1e-2, 1.0, 1e3])
            pts = fit(pts, size, off)
            mono = mono and far_keeps_shape(off, size)
            notes.append("diagonal %g moved to (%.6g, %.6g)" % (size, *off))
        elif m == "ratio":
            ws, d = ratio_weights(rng, len(pts))
            notes.append(d)
    del turned
    pts, ws = clean(pts, ws)  # moved far, tiny edges may round away
    return Case(pts, ws, ", ".join(notes), mono)


def _gen_maker(family):
    def make(rng):
        return gen_case(rng, family)
    make.__name__ = "m_gen_" + family
    return make


def classes():
    """[(class name, maker)] in the sweep's round-robin order."""
    out = [("gen:" + f, _gen_maker(f)) for f in families()]
    out += [("grid", m_grid), ("turned", m_turned), ("far", m_far), ("tiny_edge", m_tiny_edge),
            ("nearly_straight", m_nearly_straight), ("collinear_mixed", m_collinear_mixed),
            ("regular_far_vertex", m_regular_far_vertex),
            ("regular_nearly_straight", m_regular_nearly_straight),
            ("regular_tiny_edge", m_regular_tiny_edge), ("regular_4e9", m_regular_4e9),
            ("weight_ratio", m_weight_ratio), ("turned_monotone", m_turned_monotone),
            ("mixed", m_mixed)]
    return out


# ------------------------------------------------------- monotonicity

def exact_monotone_direction(pts):
    """A direction (dx, dy) in which the polygon is (weakly) monotone,
    decided exactly on the doubles, or None.  Candidates: the normals of the
    edges (where the order of projections changes) and a direction between
    each two neighbouring ones.  A float filter (numpy) drops the candidates
    that are certainly not monotone first: a subsequence of the projections'
    differences, those larger than their rounding error, that already
    changes sign more than twice."""
    from fractions import Fraction
    import numpy as np
    fr = [(Fraction(x), Fraction(y)) for x, y in pts]
    den = 1
    for x, y in fr:
        den = max(den, x.denominator, y.denominator)
    P = [(int(x * den), int(y * den)) for x, y in fr]
    n = len(P)

    def monotone(dx, dy):
        pr = [x * dx + y * dy for x, y in P]
        signs = [s for s in ((pr[(i + 1) % n] > pr[i]) - (pr[(i + 1) % n] < pr[i])
                             for i in range(n)) if s]
        changes = sum(1 for i in range(len(signs)) if signs[i] != signs[i - 1])
        return changes <= 2

    normals = set()
    for i in range(n):
        ex, ey = P[(i + 1) % n][0] - P[i][0], P[(i + 1) % n][1] - P[i][1]
        g = math.gcd(ex, ey) or 1
        dx, dy = -ey // g, ex // g
        if dy < 0 or (dy == 0 and dx < 0):
            dx, dy = -dx, -dy
        normals.add((dx, dy))
    normals = sorted(normals, key=lambda d: math.atan2(d[1], d[0]))
    cands = list(normals)
    for i in range(len(normals)):
        a, b = normals[i - 1], normals[i]
        if i == 0:  # across angle pi: b and -a
            a = (-a[0], -a[1])
        la, lb = math.hypot(*a), math.hypot(*b)
        # scaled to about equal length (integers: exact, roughly bisecting)
        ka, kb = max(1, round(lb)), max(1, round(la))
        cands.append((a[0] * ka + b[0] * kb, a[1] * ka + b[1] * kb))
    cands = [d for d in cands if d != (0, 0)]
    # float filter over unit directions
    xy = np.array(pts, dtype=float)
    D = np.array([(d[0] / math.hypot(*d), d[1] / math.hypot(*d)) for d in cands])
    proj = D @ xy.T                                   # candidates x vertices
    diff = np.roll(proj, -1, axis=1) - proj
    margin = 64 * 2.0 ** -52 * float(np.max(np.abs(xy).sum(axis=1)))
    sig = np.where(diff > margin, 1, np.where(diff < -margin, -1, 0))
    for k, d in enumerate(cands):
        s = sig[k][sig[k] != 0]
        if len(s) and int(np.count_nonzero(s != np.roll(s, 1))) > 2:
            continue  # certainly not monotone in d
        if monotone(*d):
            return d
    return None
