#!/usr/bin/python3
"""test_offset_cgal.py: wskel's offset polygons against CGAL's, and the GIS
formats read back.

Run: /usr/bin/python3 tests/test_offset_cgal.py [-v]   (from anywhere)

  * TestCgalOffsets: for unit weights, `bin/wskel --offset T.. --format wkt`
    against `bin/wskel-cgal --offset T..` (CGAL's create_offset_polygons_2 on
    its own skeleton, arranged into polygons with holes by
    arrange_offset_polygons_2) on bin/wskel-gen polygons with and without
    holes, at times that are fractions of the skeleton's height (odd ones,
    away from node times).  Compared: the number of components and of rings,
    the total signed area (relative 1e-6 of the polygon's area), and the
    vertices: every vertex of either lies within 1e-6 of the bounding-box
    diagonal of a vertex of the other (straight vertices, between collinear
    edges, may exist on one side only: those must lie on the other's
    boundary within the same tolerance).
  * TestRoundTrip: a polygon written as WKT (--offset 0 --format wkt gives
    the polygon itself) and as GeoJSON with its weights (built here) reads
    back to the same skeleton as the .wpoly.

A missing bin/wskel-cgal skips TestCgalOffsets (fails with CI=true).
Environment: WSKEL_OFFSET_SEEDS (seeds per family and size, default 3).
"""

import json
import math
import os
import re
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import testlib  # noqa: E402

SEEDS = int(os.environ.get("WSKEL_OFFSET_SEEDS", "3"))
FRACTIONS = (0.0, 0.0731, 0.2113, 0.4077, 0.6391, 0.8563)
CASES = [  # (family, n, holes, extra wskel-gen args)
    ("convex", 30, 0), ("star", 40, 0), ("star", 200, 0), ("comb", 40, 0), ("spiral", 40, 0),
    ("random", 60, 0), ("rectilinear", 40, 0), ("coastline", 100, 0),
    ("holes", 40, 2), ("holes", 80, 4), ("convex", 40, 3),
]


def parse_multipolygons(text):
    """WKT lines -> list (one per line) of polygons, each a list of rings,
    each a list of (x, y) without the closing point."""
    out = []
    for line in text.strip().splitlines():
        line = line.strip()
        if line == "MULTIPOLYGON EMPTY":
            out.append([])
            continue
        assert line.startswith("MULTIPOLYGON ((("), line[:60]
        body = line[len("MULTIPOLYGON ("):-1]
        polys = []
        for ptext in re.findall(r"\(((?:\([^()]*\)(?:,\s*)?)+)\)", body):
            rings = []
            for rtext in re.findall(r"\(([^()]*)\)", ptext):
                pts = [tuple(float(v) for v in p.split()) for p in rtext.split(",")]
                assert pts[0] == pts[-1], "ring not closed"
                rings.append(pts[:-1])
            polys.append(rings)
        out.append(polys)
    return out


def area(ring):
    return 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(ring, ring[1:] + ring[:1]))


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    s = 0.0 if L == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L))
    return math.hypot(p[0] - a[0] - s * dx, p[1] - a[1] - s * dy)


def vertex_mismatch(A, B, tol):
    """Vertices of A farther than tol from every vertex of B that are also
    not on B's boundary (within tol): [(point, distance)]."""
    bv = [p for poly in B for ring in poly for p in ring]
    bs = [(r[i], r[(i + 1) % len(r)]) for poly in B for r in poly for i in range(len(r))]
    bad, off_vertex = [], 0
    for poly in A:
        for ring in poly:
            for p in ring:
                d = min((math.hypot(p[0] - q[0], p[1] - q[1]) for q in bv), default=math.inf)
                if d <= tol:
                    continue
                off_vertex += 1
                e = min((seg_dist(p, a, b) for a, b in bs), default=math.inf)
                if e > tol:
                    bad.append((p, e))
    return bad, off_vertex


class TestCgalOffsets(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        testlib.need(testlib.WSKEL, testlib.WSKEL_GEN, testlib.WSKEL_CGAL)

    def test_generated(self):
        tally = testlib.Tally("offsets against CGAL")
        compared = off_vertex_total = 0
        with tempfile.TemporaryDirectory() as tmp:
            for family, n, holes in CASES:
                for seed in range(1, SEEDS + 1):
                    path = os.path.join(tmp, "%s_%d_%d_%d.wpoly" % (family, n, holes, seed))
                    args = [testlib.WSKEL_GEN, family, "--n", str(n), "--seed", str(seed), "-o", path]
                    if holes:
                        args += ["--holes", str(holes)]
                    rc, _, err = testlib.run(args)
                    if rc != 0:
                        tally.skip("%s n=%d: %s" % (family, n, err.strip()), "not generated")
                        continue
                    rc, doc, err = testlib.wskel_json([path])
                    self.assertEqual(rc, 0, err)
                    height = max(nd[2] for nd in doc["nodes"])
                    xs = [nd[0] for nd in doc["nodes"]]
                    ys = [nd[1] for nd in doc["nodes"]]
                    scale = math.hypot(max(xs) - min(xs), max(ys) - min(ys))
                    times = ",".join("%.17g" % (f * height) for f in FRACTIONS)
                    rc1, w_out, err1 = testlib.wskel(["--offset", times, "--format", "wkt", path])
                    rc2, c_out, err2 = testlib.run([testlib.WSKEL_CGAL, "--offset", times, path])
                    fails = []
                    if rc1 != 0 or rc2 != 0:
                        fails.append("%s: wskel exit %s (%s), cgal exit %s (%s)"
                                     % (path, rc1, err1.strip(), rc2, err2.strip()))
                    else:
                        W, C = parse_multipolygons(w_out), parse_multipolygons(c_out)
                        poly_area = sum(area(r) for poly in W[0] for r in poly)
                        tol = 1e-6 * scale
                        for f, w, c in zip(FRACTIONS, W, C):
                            what = "%s t=%.4g*height" % (os.path.basename(path), f)
                            if len(w) != len(c):
                                fails.append("%s: %d components, CGAL %d" % (what, len(w), len(c)))
                                continue
                            nw = sorted(len(p) for p in w)
                            nc = sorted(len(p) for p in c)
                            if nw != nc:
                                fails.append("%s: rings per component %s, CGAL %s" % (what, nw, nc))
                            aw = sum(area(r) for p in w for r in p)
                            ac = sum(area(r) for p in c for r in p)
                            if abs(aw - ac) > 1e-6 * abs(poly_area):
                                fails.append("%s: area %.12g, CGAL %.12g" % (what, aw, ac))
                            for A, B, who in ((w, c, "wskel"), (c, w, "CGAL")):
                                bad, off = vertex_mismatch(A, B, tol)
                                off_vertex_total += off
                                if off and os.environ.get("WSKEL_OFFSET_VERBOSE"):
                                    sys.stderr.write("%s: %d %s vertices on the other's boundary "
                                                     "only\n" % (what, off, who))
                                if bad:
                                    fails.append("%s: %d %s vertices off the other's boundary "
                                                 "(first %s, %.3g away)" % (what, len(bad), who,
                                                                            bad[0][0], bad[0][1]))
                            compared += 1
                    tally.case(fails, path)
        sys.stderr.write("offsets against CGAL: %d offsets compared, %d vertices matched on "
                         "the other's boundary instead of a vertex\n" % (compared, off_vertex_total))
        self.assertGreater(compared, 100)
        tally.report(self)


class TestRoundTrip(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        testlib.need(testlib.WSKEL, testlib.WSKEL_GEN)

    def same(self, a, b, what):
        rc1, d1, e1 = testlib.wskel_json([a])
        rc2, d2, e2 = testlib.wskel_json([b])
        self.assertEqual((rc1, rc2), (0, 0), "%s: %s %s" % (what, e1, e2))
        self.assertEqual(d1["nodes"], d2["nodes"], what)
        self.assertEqual(d1["arcs"], d2["arcs"], what)

    def test_wkt_and_geojson(self):
        cases = 0
        with tempfile.TemporaryDirectory() as tmp:
            for family, n, holes in (("star", 30, 0), ("holes", 40, 2), ("convex", 20, 1),
                                     ("coastline", 60, 0)):
                for weights in ("unit", "uniform"):
                    path = os.path.join(tmp, "%s.wpoly" % family)
                    args = [testlib.WSKEL_GEN, family, "--n", str(n), "--weights", weights, "-o", path]
                    if holes:
                        args += ["--holes", str(holes)]
                    rc, _, err = testlib.run(args)
                    self.assertEqual(rc, 0, err)
                    # GeoJSON with the weights property, rings as in the file
                    with open(path) as f:
                        text = f.read()
                    lines = [l.split() for l in text.splitlines() if l.strip() and not l.startswith("#")]
                    rings, ws, i = [], [], 0
                    while i < len(lines):
                        m = int(lines[i][0])
                        pts = [[float(v[0]), float(v[1])] for v in lines[i + 1:i + 1 + m]]
                        ws.append([float(v[2]) if len(v) > 2 else 1.0 for v in lines[i + 1:i + 1 + m]])
                        rings.append(pts + [pts[0]])
                        i += 1 + m
                    gj = os.path.join(tmp, "p.geojson")
                    with open(gj, "w") as f:
                        json.dump({"type": "Feature", "properties": {"weights": ws},
                                   "geometry": {"type": "Polygon", "coordinates": rings}}, f)
                    self.same(path, gj, "%s %s GeoJSON" % (family, weights))
                    if weights == "unit":
                        # WKT through the offset writer at t = 0 (the polygon itself); the
                        # writer stores rings oriented, so compare skeleton geometry only
                        rc, out, err = testlib.wskel(["--offset", "0", "--format", "wkt", path])
                        self.assertEqual(rc, 0, err)
                        wk = os.path.join(tmp, "p.wkt")
                        with open(wk, "w") as f:
                            f.write(out)
                        rc1, d1, _ = testlib.wskel_json([path])
                        rc2, d2, e2 = testlib.wskel_json([wk])
                        self.assertEqual(rc2, 0, e2)
                        key = lambda d: sorted(tuple(nd) for nd in d["nodes"])
                        self.assertEqual(key(d1), key(d2), "%s WKT round trip" % family)
                    cases += 1
        self.assertEqual(cases, 8)


if __name__ == "__main__":
    unittest.main()
