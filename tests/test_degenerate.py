#!/usr/bin/python3
"""test_degenerate.py: every variant on degenerate inputs, against naive.

Four tests: the files of tests/data/degenerate; generated integer-grid
polygons; real-like polygons (fractal coastlines, glyph outlines, a
horseshoe, a tiny coastline 1e6 from the origin); monotone polygons turned
in random directions, with runs of collinear vertices (the monotone variant
must not refuse them).  Known failures, if any, are listed in KNOWN_FAILURES.

No input is skipped silently: every input is required (the reader rejecting
it fails the test) except a generated case that degenerates away (fewer than
three vertices left); skipped inputs and known failures are counted and each
is named on stderr, and each test asserts how many cases it ran.  The
monotone variant's refusals of polygons not known to be monotone are counted.

Polygons on small integer grids are as degenerate as real inputs get:
parallel and collinear edges, equal lengths, rays through vertices, several
events at one instant and one place.  Found this way (and kept in
tests/data/degenerate with a comment each): a head-on meeting of two reflex
vertices the arrangement variant lost, and monotone merges whose arcs folded
back along each other by 1e-16, which the validator now rejects.

Oracles: naive's skeleton must pass `--check`; arrangement (k = 1, k = max)
and monotone (where the polygon is monotone) must succeed, pass `--check`
and be the same skeleton (scripts/compare_skeletons.py).  CGAL is not an
oracle here: on collinear_same_direction.wpoly it outputs two overlapping
arcs.  Cases: the files in tests/data/degenerate, then WSKEL_DEGENERATE_CASES
(default 2000) generated polygons: random points of a G x G grid (G in 4, 6,
10, 20) sorted around a jittered centre (star-shaped), or x-monotone
rectilinear "double histograms"; unit, tied (1 or 2) or integer (1..5)
weights.  The generator is seeded per case, so a failure names the case.
"""
import math
import os
import random
import shutil
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import testlib as tl  # noqa: E402
from testlib import cs  # noqa: E402

CASES = int(os.environ.get("WSKEL_DEGENERATE_CASES", "2000"))
REAL_CASES = int(os.environ.get("WSKEL_REAL_CASES", "24"))
MONO_CASES = int(os.environ.get("WSKEL_MONO_CASES", "400"))
TURNED_CASES = int(os.environ.get("WSKEL_TURNED_CASES", "60"))
# Known open failures of the reference (and so of every variant), seed ->
# the text of the failure: the test asserts that exactly these fail, and in
# that way, so a fix shows too.  Empty now: seed 150 ("antiparallel
# wavefront vertex", walls at equal levels 1e5 from the origin) was fixed by
# collapsing flat cycles and is kept as tests/data/degenerate/flat_cycle_far.wpoly.
KNOWN_FAILURES = {}
# The same for the generated cases (test_generated), seed -> the text of the
# failure.  Empty now: 1893 (deforming's collinear rule covered a swept piece
# of weight 2 between weight-1 pieces by the piece after it) is fixed and
# kept as tests/data/degenerate/deform_collinear_run_cover.wpoly.
KNOWN_GENERATED = {}
# Files of tests/data/degenerate with a known failure (name -> the text every
# failure line must hold; the test fails when one passes or fails otherwise).
# Fixed and kept: the tiny reflex chamfers (arr_chamfer_contact,
# deform_*chamfer*), where deforming resolved the unchamfered corner while
# naive grows the chamfer into a face as CGAL does, agree since deforming
# asks the engine's exactly-behind rule (wk_input_vertex_never_reaches_line);
# comb_far_slow_stretch.wpoly (deforming merged a stretch of edge 7 that
# collapses later, a node 2% of the diagonal from naive's = CGAL's; before
# deform5's shared_end it went to the reference, which hid it) agrees since
# deforming applies the engine's slow-stretch rule (resolve.c,
# plan_slow_stretches); arr_headon_turned_needles*.wpoly (motorcycle let
# reflex vertex 9 run on through reflex vertex 2 where naive meets them
# head-on) agree since motorcycle cuts both traces (motorcycle.c, headon);
# mc_real_needle_passes_reflex.wpoly (deforming's node of faces 1, 9, 10 on
# all three lines, 2.4e-4 from naive's; lines 1 and 9 parallel to 5e-5 rad)
# agrees since deforming takes a three-line point only within the contact
# distance of the vertex (deform9, predict.c test_penetration).
# A file here fails only in the way named (a listed file that passes, or fails otherwise, fails the test).
KNOWN_FILES = {
    # stress s1-c00541-far (deform8): naive's (and arrangement's) node of faces 8, 44, 50 is
    # 1.0e-5 from where those offset lines meet (80 digits on the input doubles); deforming's
    # is at that point (tests/test_deforming.py, test_far_sliver_node_is_exact)
    "deform_far_sliver_between_points.wpoly": "deforming differs from naive",
    # stress s1-c01563-mixed: edge 10 (1.07e-9, collinear with 9 and 11, unit weights) is a
    # strip of width 1.07e-9 exactly; deforming and CGAL keep it (arcs 9|10, 10|11), naive
    # collapses it at t = 0 (arc 9|11): a face below the tolerance, the comparison's label differs
    "deform_sliver_collinear_face_01563.wpoly": "deforming differs from naive",
    # stress s1-c07842-mixed: the same with edge 40 (1.5e-9, collinear with 39 and 41 up to
    # rounding); 80 digits on the input doubles: deforming's node of faces 39, 40, 41, 43 is
    # 4.0e-12 from where lines 40, 41, 43 meet (4.8e-9 from 39, 40, 43), naive's 1.49e-5
    "deform_sliver_chamfer_face_07842.wpoly": "deforming differs from naive",
    # stress s1-c02889-nearly_straight: edges 13 and 17 parallel to 2.3e-9 rad; lines 2, 13,
    # 17 meet (80 digits) 5.6e-10 from deforming's node, 45 units from naive's (1.05e-7 off
    # line 17, within the validator's tolerance)
    "deform_nearly_parallel_far_node_02889.wpoly": "deforming differs from naive",
}
DATA = os.path.join(tl.DATA, "degenerate")
# Kinds of skipped inputs (Tally.skip): counted and every one named in the
# report; the tests say which inputs are required (a skip is a failure).
SKIPPED_INPUT = "skipped inputs (rejected by the reader)"
DEGENERATED = "skipped inputs (degenerated away)"
VARIANTS = [["arrangement", "--k", "1"], ["arrangement", "--k", "max"], ["monotone"],
            ["motorcycle"], ["deforming"]]


def star_grid(rng, m, g):
    pts = set()
    while len(pts) < m:
        pts.add((rng.randint(0, g), rng.randint(0, g)))
    pts = list(pts)
    cx = sum(p[0] for p in pts) / len(pts) + rng.uniform(-0.3, 0.3)
    cy = sum(p[1] for p in pts) / len(pts) + rng.uniform(-0.3, 0.3)
    pts.sort(key=lambda p: (math.atan2(p[1] - cy, p[0] - cx), (p[0] - cx) ** 2 + (p[1] - cy) ** 2))
    return pts


def double_histogram(rng, m, g):
    k = max(2, min(g - 1, m // 4 + 1))
    xs = sorted(rng.sample(range(0, g + 1), k + 1))
    b = [rng.randint(0, g // 2 - 1) for _ in range(k)]
    h = [rng.randint(g // 2 + 1, g) for _ in range(k)]
    poly = []
    for i in range(k):
        poly += [(xs[i], b[i]), (xs[i + 1], b[i])]
    for i in reversed(range(k)):
        poly += [(xs[i + 1], h[i]), (xs[i], h[i])]
    return poly


def drop_flat(poly):
    """Remove repeated points and 180/0-degree vertices until none is left."""
    changed = True
    while changed and len(poly) >= 3:
        changed = False
        out = []
        for i in range(len(poly)):
            a, b, c = poly[i - 1], poly[i], poly[(i + 1) % len(poly)]
            cr = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            if b == a or cr == 0:
                changed = True
                continue
            out.append(b)
        poly = out
    return poly


def generated(seed):
    """(points, weights) of case `seed`, or None when it degenerates away."""
    rng = random.Random(seed)
    kind = rng.choice(["star", "star", "histogram"])
    g = rng.choice([4, 6, 10, 20])
    m = rng.randint(4, 16 if g < 10 else 30)
    pts = drop_flat(star_grid(rng, m, g) if kind == "star" else double_histogram(rng, m, g))
    if len(pts) < 3:
        return None
    if sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts))) < 0:
        pts.reverse()
    mode = rng.choice(["unit", "unit", "tie", "int"])
    if mode == "unit":
        w = [1] * len(pts)
    elif mode == "tie":
        w = [rng.choice([1, 2]) for _ in pts]
    else:
        w = [rng.randint(1, 5) for _ in pts]
    return pts, w


def coast(rng, n):
    """A fractal coastline: midpoint displacement of radii around a circle."""
    k = 8
    r = [1.0 + rng.uniform(-0.2, 0.2) for _ in range(k)]
    while len(r) < n:
        nr = []
        amp = 0.35 * (k / len(r))
        for i in range(len(r)):
            a, b = r[i], r[(i + 1) % len(r)]
            nr += [a, (a + b) / 2 + rng.uniform(-amp, amp)]
        r = nr
    r = r[:n]
    return [(max(0.05, r[i]) * math.cos(2 * math.pi * i / n),
             max(0.05, r[i]) * math.sin(2 * math.pi * i / n)) for i in range(n)]


def glyph_c(m):
    """A thick C: two concentric arcs of m points, nearly collinear runs."""
    a0, a1 = 0.6, 2 * math.pi - 0.6
    out = [(100 * math.cos(a0 + (a1 - a0) * i / (m - 1)), 100 * math.sin(a0 + (a1 - a0) * i / (m - 1)))
           for i in range(m)]
    return out + [(60 * math.cos(a1 - (a1 - a0) * i / (m - 1)), 60 * math.sin(a1 - (a1 - a0) * i / (m - 1)))
                  for i in range(m)]


def horseshoe(m):
    """A U with round bottom and straight legs."""
    pts = [(50 * math.cos(math.pi + math.pi * i / (m - 1)), 50 * math.sin(math.pi + math.pi * i / (m - 1)))
           for i in range(m)]
    pts += [(50, 100), (30, 100)]
    pts += [(30 * math.cos(2 * math.pi - math.pi * i / (m - 1)),
             30 * math.sin(2 * math.pi - math.pi * i / (m - 1))) for i in range(m)]
    return pts + [(-30, 100), (-50, 100)]


def real_like(seed):
    """(name, points, weights): coastlines, glyphs, a horseshoe, a coastline
    shrunk to 2e-3 and moved 1e6 from the origin; unit or weighted."""
    rng = random.Random(seed)
    kind = ["coast", "glyph_c", "horseshoe", "offset"][seed % 4]
    n = rng.choice([50, 200, 1000])
    if kind == "coast":
        pts = coast(rng, n)
    elif kind == "glyph_c":
        pts = glyph_c(n // 2)
    elif kind == "horseshoe":
        pts = horseshoe(n // 2)
    else:
        pts = [(x * 1e-3 + 1e6, y * 1e-3 - 2e6) for x, y in coast(rng, n)]
    w = [1] * len(pts) if seed % 8 < 4 else [rng.choice([1, 1, 2, 0.5, 3]) for _ in pts]
    return "%s n=%d seed %d" % (kind, len(pts), seed), pts, w


def monotone_any_direction(seed):
    """An x-monotone polygon (random, zig-zag or three-level chains: runs of
    collinear vertices) turned by a random angle, sometimes moved 1e5 away:
    after rounding, its collinear runs are collinear only up to 1e-16."""
    rng = random.Random(seed)
    n = rng.choice([5, 6, 8, 12, 20, 50, 100])
    xs = sorted(rng.uniform(0, 100) for _ in range(n - 2))
    lower = sorted(rng.sample(xs, rng.randint(1, n - 3)))
    upper = sorted((x for x in xs if x not in lower), reverse=True)
    style = rng.choice(["random", "zigzag", "levels"])

    def y(sign):
        if style == "random":
            return sign * rng.uniform(1, 30)
        if style == "zigzag":
            return sign * (10 + (rng.uniform(5, 20) if rng.random() < 0.5 else 0))
        return sign * rng.choice([5, 10, 15])
    pts = [(-1.0, 0.0)] + [(x, y(-1)) for x in lower] + [(101.0, 0.0)] + [(x, y(1)) for x in upper]
    th = rng.choice([0.0, math.pi / 2, rng.uniform(0, 2 * math.pi)])
    off = rng.choice([0.0, 1e5])
    c, s = math.cos(th), math.sin(th)
    pts = [(off + c * x - s * yy, off + s * x + c * yy) for x, yy in pts]
    mode = rng.choice(["unit", "unit", "tie", "real"])
    w = ([1] * len(pts) if mode == "unit" else [rng.choice([1, 2]) for _ in pts] if mode == "tie"
         else [rng.uniform(0.5, 2) for _ in pts])
    return "monotone n=%d seed %d (%s, %s weights)" % (len(pts), seed, style, mode), pts, w


# A glyph 'F' (DejaVu Sans Bold's outline, font units / 10): the bar's two
# reflex vertices meet head-on as the bar collapses, between the stem's
# collinear edges, the same instant as its walls meet.
GLYPH_F = [(9.1875, 72.90625), (59.90625, 72.90625), (59.90625, 58.6875), (27.984375, 58.6875),
           (27.984375, 45.125), (58.015625, 45.125), (58.015625, 30.90625),
           (27.984375, 30.90625), (27.984375, 0.0), (9.1875, 0.0)]


def turned_copy(seed):
    """(name, points, weights, angle, shift): a polygon that is degenerate on
    purpose (the glyph F, or a grid polygon of generated()) and the rigid
    motion applied to it (turned by a random angle, sometimes moved 1e6):
    after rounding, its collinear edges and simultaneous events are so only
    up to 1e-16 relative."""
    rng = random.Random(seed)
    if seed % 3 == 0:
        pts, w = GLYPH_F, [1] * len(GLYPH_F)
        name = "glyph F"
    else:
        g = None
        k = seed
        while g is None:
            g = generated(10000 + k)
            k += 7919
        pts, w = g
        name = "grid polygon %d" % k
    th = rng.uniform(0, 2 * math.pi)
    shift = rng.choice([0.0, 1e6])
    return "%s turned by %.6f, moved %g (seed %d)" % (name, th, shift, seed), pts, w, th, shift


class Degenerate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        tl.need(tl.WSKEL)
        cls.work = tempfile.mkdtemp(prefix="wskel-degenerate-")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def run_variant(self, args, poly, out):
        rc, _, err = tl.wskel(["--check", "-o", out] + args + [poly])
        return rc, err.strip()

    def check_case(self, t, name, poly, required=True, monotone_required=False):
        """Run naive and every variant on poly and record the case in the
        Tally t.  An input the reader rejects (naive exit 1) is a failure
        when required, else a skipped input (counted, named in the report).
        The monotone variant's refusal of a polygon not known to be monotone
        is noted too (the other variants are still compared)."""
        fails = []
        ref = os.path.join(self.work, "naive.json")
        rc, err = self.run_variant(["--variant", "naive"], poly, ref)
        if rc == 1:
            if required:
                t.case(["%s: the reader rejects a required input: %s" % (name, err)], poly)
            else:
                t.skip("%s (%s)" % (name, err), SKIPPED_INPUT)
            return
        if rc != 0:
            t.case(["%s: naive exit %s: %s" % (name, rc, err)], poly)
            return
        a = cs.load(ref)
        for v in VARIANTS:
            out = os.path.join(self.work, "v.json")
            rc, err = self.run_variant(["--variant"] + v, poly, out)
            if v[0] == "monotone" and rc == 2 and "not monotone" in err and not monotone_required:
                t.skip(name, "refused by monotone (not monotone; naive and arrangement compared)")
                continue
            if v[0] == "motorcycle" and rc == 2 and "equal weights only" in err:
                t.skip(name, "refused by motorcycle (weighted; the others compared)")
                continue
            if rc != 0:
                fails.append("%s: %s exit %s: %s" % (name, " ".join(v), rc, err))
                continue
            res = cs.compare(a, cs.load(out))
            if not res.identical:
                fails.append("%s: %s differs from naive: %s" % (name, " ".join(v), res.summary()))
        if name in KNOWN_FILES:
            if fails and all(KNOWN_FILES[name] in f for f in fails):
                t.skip(name, "known failures (KNOWN_FILES)")
                return
            fails = fails or ["%s: known failure '%s' passes now: remove it from KNOWN_FILES"
                              % (name, KNOWN_FILES[name])]
        t.case(fails, poly)

    def test_files(self):
        names = sorted(f for f in os.listdir(DATA) if f.endswith(".wpoly"))
        self.assertGreaterEqual(len(names), 4)
        t = tl.Tally("degenerate files")
        for f in names:
            path = os.path.join(DATA, f)
            self.check_case(t, f, path)
        t.report(self, limit=len(names), list_skipped=[SKIPPED_INPUT])
        self.assertEqual(t.cases + len(KNOWN_FILES), len(names), t.summary())

    def write(self, pts, w, comment=None):
        return tl.write_wpoly(os.path.join(self.work, "case.wpoly"), pts, w, comment)

    def test_generated(self):
        """Every case is required: the generator's 2000 polygons are all valid
        (a rejection means the reader changed); a case that degenerates away
        (fewer than 3 vertices left) is a skipped input, named in the report."""
        t = tl.Tally("degenerate generated")
        for seed in range(1, CASES + 1):
            case = generated(seed)
            if case is None:
                t.skip("case %d" % seed, DEGENERATED)
                continue
            pts, w = case
            path = self.write(pts, w, "test_degenerate.py case %d" % seed)
            if seed in KNOWN_GENERATED:
                sub = tl.Tally("case %d" % seed)
                self.check_case(sub, "case %d" % seed, path)
                got = sub.failures
                if not got or not all(KNOWN_GENERATED[seed] in g for g in got):
                    t.case(["case %d: known failure '%s' changed: %s" %
                            (seed, KNOWN_GENERATED[seed], got or "now passes")], path)
                else:
                    t.skip("case %d" % seed, "known failures")
                continue
            self.check_case(t, "case %d" % seed, path)
        t.report(self, list_skipped=[DEGENERATED, "known failures"])
        self.assertGreater(t.cases, 0, t.summary())
        # A few may degenerate away; most must run.
        self.assertGreaterEqual(t.cases, 0.9 * CASES, t.summary())

    def test_real_like(self):
        """Coastlines, glyph outlines, a far-off tiny polygon: every variant
        equals naive (the validator once rejected naive's skeleton of the
        far-off one).  Every input is required."""
        t = tl.Tally("degenerate real-like")
        for seed in range(REAL_CASES):
            name, pts, w = real_like(seed)
            path = self.write(pts, w, name)
            self.check_case(t, name, path)
        t.report(self)
        self.assertEqual(t.cases, REAL_CASES, t.summary())

    def test_turned_copies(self):
        """Rounding does not change the answer: a degenerate polygon turned
        by an angle (and moved 1e6) in doubles has the turned skeleton of the
        polygon itself (naive on both, compared after moving the first one's
        nodes).  An exact program follows the rounding instead (CGAL keeps
        slivers 1e-10 wide that run for units; see README, tolerance
        policy).  Every variant equals naive on the turned copy."""
        t = tl.Tally("turned copies")
        tv = tl.Tally("turned copies, variants against naive")
        for seed in range(TURNED_CASES):
            name, pts, w, th, shift = turned_copy(seed)
            ref = os.path.join(self.work, "plain.json")
            rc, err = self.run_variant(["--variant", "naive"], self.write(pts, w, name), ref)
            if rc != 0:
                t.case(["%s: naive on the unturned polygon: exit %s: %s" % (name, rc, err)], None)
                continue
            c, s_ = math.cos(th), math.sin(th)
            moved = [(shift + c * x - s_ * y, shift + s_ * x + c * y) for x, y in pts]
            poly = tl.write_wpoly(os.path.join(self.work, "turned.wpoly"), moved, w, name)
            out = os.path.join(self.work, "turned.json")
            rc, err = self.run_variant(["--variant", "naive"], poly, out)
            if rc != 0:
                t.case(["%s: naive exit %s: %s" % (name, rc, err)], poly)
                continue
            a = cs.load(ref)
            a["nodes"] = [[shift + c * x - s_ * y, shift + s_ * x + c * y, tt] for x, y, tt in a["nodes"]]
            b = cs.load(out)
            res = cs.compare(a, b, tol=max(cs.default_tol(b), 1e-7 * shift))
            fails = [] if res.identical else ["%s: the skeleton is not the turned one: %s" % (name, res.summary())]
            t.case(fails, poly)
            self.check_case(tv, name, poly)
        t.report(self)
        tv.report(self)
        self.assertEqual(t.cases, TURNED_CASES, t.summary())
        self.assertEqual(tv.cases, TURNED_CASES, tv.summary())

    def test_monotone_any_direction(self):
        """Monotone by construction, so the monotone variant must not refuse;
        nearly flat reflex vertices once made it do so, and naive failed on
        nearly collinear edges of different weight.  Every input is
        required; a known failure (KNOWN_FAILURES) must fail as listed and is
        named in the report."""
        t = tl.Tally("degenerate monotone in any direction")
        for seed in range(1, MONO_CASES + 1):
            name, pts, w = monotone_any_direction(seed)
            path = self.write(pts, w, name)
            if seed in KNOWN_FAILURES:
                sub = tl.Tally(name)
                self.check_case(sub, name, path, monotone_required=True)
                got = sub.failures
                if not got or not all(KNOWN_FAILURES[seed] in g for g in got):
                    t.case(["%s: known failure '%s' changed: %s" %
                            (name, KNOWN_FAILURES[seed], got or "now passes")], path)
                else:
                    t.skip(name, "known failures")
                continue
            self.check_case(t, name, path, monotone_required=True)
        t.report(self, list_skipped=["known failures"])
        self.assertEqual(t.cases + len(t.skipped.get("known failures", [])), MONO_CASES,
                         t.summary())
        self.assertGreater(t.cases, 0, t.summary())


if __name__ == "__main__":
    unittest.main()
