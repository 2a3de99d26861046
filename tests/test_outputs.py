#!/usr/bin/python3
"""test_outputs.py: bin/wskel's five output formats, read back by real consumers.

Run: /usr/bin/python3 tests/test_outputs.py [-v]   (from anywhere)

For every tests/data/good/*.wpoly and a few polygons generated here (regular,
L shape given clockwise, comb, seeded star, weighted square, a 400-vertex
star), bin/wskel writes json (with --check), text, obj, svg (with offset
curves) and vtp, and each file is checked against its contract:

  * json: exactly the contract keys (engine/write_json.c), "wskel-1", n and r,
    nodes[0..n) equal to the input vertices in input order with t = 0, the
    other nodes finite with t > 0, arcs in range with left != right, a tree
    (arcs = nodes - 1), stats with exactly the counters that
    `--list-counters` names for the variant, plus time_s and peak_bytes; in
    input numbering, every arc
    end lies at distance w t from both its faces' input edges, and the arc
    leaving input vertex v separates input edges v-1 and v;
  * text: the same nodes (same doubles) and arcs as the json;
  * obj: one vertex per node (x y t), one face per input edge whose face of
    input edge i contains input vertices i and i+1;
  * svg: well-formed XML, the polygon as one path with n points and a
    subpath per ring, one dot per node, the
    requested offset curves;
  * vtp: vtk.vtkXMLPolyDataReader reads it: points = nodes with z = t, point
    data "t" with range [0, max t], n + arcs lines, n polygons equal to the
    obj faces, cell data edge_id and kind (an arc leaving a reflex input
    vertex has kind 2, exactly r of them).

Counters: for naive, monotone and arrangement the JSON stats keys are
exactly the names of `bin/wskel --list-counters --variant V` plus time_s and
peak_bytes, and a counter of one variant (arrangement's cache_hits,
monotone's reference_fallbacks) is absent from the others' stats.

Without bin/wskel every test is skipped with a message saying so; once it
exists, a wrong output fails.  An input the variant declines (exit 2, e.g.
weights for a unit-weight variant) skips that input's subtest; exit 3 (the
validator rejected the skeleton) fails.  At least one input must be checked.

Environment: WSKEL_BIN overrides bin/wskel; WSKEL_VARIANT picks the variant
(default: the CLI's default).
"""

import json
import math
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import testlib as tl  # noqa: E402

VARIANT = os.environ.get("WSKEL_VARIANT")
GOOD = os.path.join(tl.DATA, "good")
OFFSETS = [0.05, 0.2]
CONTRACT_KEYS = {"format", "variant", "k", "n", "r", "rings", "nodes", "arcs", "stats"}


# ------------------------------------------------------------- polygons

def star(k, seed, r_in=(0.3, 0.5), r_out=(0.8, 1.0)):
    """Star with k spikes, radii from a small seeded LCG (deterministic)."""
    s = seed
    pts = []
    for i in range(2 * k):
        s = (s * 6364136223846793005 + 1442695040888963407) % (1 << 64)
        u = (s >> 11) / float(1 << 53)
        lo, hi = r_in if i % 2 else r_out
        r = lo + (hi - lo) * u
        a = math.pi * i / k
        pts.append((r * math.cos(a), r * math.sin(a)))
    return pts


def generated():
    """name -> (points, weights or None)."""
    comb = [(0, 0), (7, 0), (7, 4), (6, 4), (6, 1), (5, 1), (5, 4), (4, 4), (4, 1), (3, 1),
            (3, 4), (2, 4), (2, 1), (1, 1), (1, 4), (0, 4)]
    L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 3), (0, 3)]
    return {
        "regular12": ([(math.cos(2 * math.pi * i / 12), math.sin(2 * math.pi * i / 12))
                       for i in range(12)], None),
        "L_clockwise": (list(reversed(L)), None),
        "comb": ([(float(x), float(y)) for x, y in comb], None),
        "star20": (star(20, 7), None),
        "star200_clockwise": (list(reversed(star(200, 11))), None),
        "weighted_square": ([(0, 0), (1, 0), (1, 1), (0, 1)], [2.0, 1.0, 1.0, 1.0]),
    }


def signed_area(pts):
    return 0.5 * sum(pts[i][0] * pts[(i + 1) % len(pts)][1] -
                     pts[(i + 1) % len(pts)][0] * pts[i][1] for i in range(len(pts)))


def reflex_vertices(pts):
    """Input vertices whose interior angle exceeds pi (orientation-aware)."""
    n, ccw = len(pts), signed_area(pts) > 0
    out = set()
    for i in range(n):
        a, b, c = pts[i - 1], pts[i], pts[(i + 1) % n]
        cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        if (cross < 0) if ccw else (cross > 0):
            out.add(i)
    return out


def line_distance(pts, e, x, y):
    """Unsigned distance from (x, y) to the line of input edge e."""
    (ax, ay), (bx, by) = pts[e], pts[(e + 1) % len(pts)]
    return abs((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / math.hypot(bx - ax, by - ay)


class Outputs(unittest.TestCase):
    """One subtest per input; every format checked against the json."""

    @classmethod
    def setUpClass(cls):
        tl.need(tl.WSKEL)
        cls.tmp = tempfile.TemporaryDirectory(prefix="wskel-outputs-")
        cls.counters = [name for name, _ in tl.list_counters(VARIANT)]

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def inputs(self):
        """(name, path, points, weights) for the data files and the generated ones."""
        out = []
        for f in sorted(os.listdir(GOOD)) if os.path.isdir(GOOD) else []:
            if f.endswith(".wpoly"):
                path = os.path.join(GOOD, f)
                pts, ws = tl.read_wpoly(path)
                out.append((f, path, pts, ws))
        for name, (pts, ws) in generated().items():
            path = os.path.join(self.tmp.name, name + ".wpoly")
            tl.write_wpoly(path, pts, ws, "generated by tests/test_outputs.py")
            out.append((name, path, pts, ws if ws else [1.0] * len(pts)))
        return out

    def test_all_formats(self):
        self.computed = 0  # inputs the variant did not decline
        for name, path, pts, ws in self.inputs():
            with self.subTest(input=name):
                self.check_input(name, path, pts, ws)
        self.assertGreater(self.computed, 0, "the variant declined every input: nothing checked")

    # ---------------------------------------------------------- per input

    def produce(self, name, path, fmt, extra=()):
        out = os.path.join(self.tmp.name, "%s.%s" % (name, fmt))
        rc, _, err = tl.wskel(["--format", fmt, "-o", out] + list(extra) + [path], VARIANT)
        if rc == 2:
            self.skipTest("the variant declined %s (exit 2): %s" % (name, err.strip()))
        self.assertEqual(rc, 0, "wskel --format %s %s: exit %s: %s" % (fmt, name, rc, err))
        self.assertTrue(os.path.isfile(out), "no %s output for %s" % (fmt, name))
        if fmt == "json":
            self.computed += 1
        return out

    def check_input(self, name, path, pts, ws):
        with open(self.produce(name, path, "json", ["--check"])) as f:
            doc = json.load(f)
        self.check_json(doc, pts, ws)
        self.check_text(self.produce(name, path, "text"), doc)
        faces = self.check_obj(self.produce(name, path, "obj"), doc)
        self.check_svg(self.produce(name, path, "svg", ["--offsets", ",".join(map(str, OFFSETS))]),
                       doc)
        self.check_vtp(self.produce(name, path, "vtp"), doc, pts, faces)

    def check_json(self, doc, pts, ws):
        n = len(pts)
        self.assertEqual(set(doc), CONTRACT_KEYS)
        self.assertEqual(doc["format"], "wskel-1")
        self.assertIsInstance(doc["variant"], str)
        self.assertTrue(doc["k"] is None or doc["k"] == "max" or
                        (isinstance(doc["k"], int) and doc["k"] > 0), doc["k"])
        self.assertEqual(doc["n"], n)
        self.assertEqual(doc["rings"], [n], "one ring without holes")
        self.assertEqual(doc["r"], len(reflex_vertices(pts)))
        nodes, arcs = doc["nodes"], doc["arcs"]
        N = len(nodes)
        self.assertGreaterEqual(N, n)
        for i, v in enumerate(nodes):
            self.assertEqual(len(v), 3)
            self.assertTrue(all(isinstance(c, (int, float)) and math.isfinite(c) for c in v), v)
            if i < n:
                self.assertEqual((v[0], v[1], v[2]), (pts[i][0], pts[i][1], 0),
                                 "node %d is not input vertex %d" % (i, i))
            else:
                self.assertGreater(v[2], 0, "node %d" % i)
        self.assertEqual(len(arcs), N - 1, "a tree has nodes - 1 arcs")
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        tol = 1e-6 * math.hypot(max(xs) - min(xs), max(ys) - min(ys))
        for k, (a, b, left, right) in enumerate(arcs):
            self.assertTrue(0 <= a < N and 0 <= b < N and a != b, "arc %d" % k)
            self.assertTrue(0 <= left < n and 0 <= right < n and left != right, "arc %d" % k)
            for v in (a, b):
                for e in (left, right):
                    x, y, t = nodes[v]
                    self.assertAlmostEqual(line_distance(pts, e, x, y), ws[e] * t, delta=tol,
                                           msg="arc %d: node %d vs input edge %d" % (k, v, e))
            if (a < n) != (b < n):
                v = a if a < n else b
                self.assertEqual({left, right}, {(v - 1) % n, v},
                                 "arc %d leaves input vertex %d" % (k, v))
        stats = doc["stats"]
        self.assertIsInstance(stats, dict)
        self.assertEqual(set(stats), set(self.counters) | {"time_s", "peak_bytes"})
        for c in self.counters:
            self.assertTrue(isinstance(stats[c], int) and stats[c] >= 0, c)
        self.assertGreaterEqual(stats["time_s"], 0)
        self.assertGreaterEqual(stats["peak_bytes"], 0)

    def check_text(self, path, doc):
        with open(path) as f:
            lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
        self.assertEqual(lines[0], ["nodes", str(len(doc["nodes"]))])
        N = len(doc["nodes"])
        self.assertEqual([[float(c) for c in l] for l in lines[1:1 + N]],
                         [[float(c) for c in v] for v in doc["nodes"]])
        self.assertEqual(lines[1 + N], ["arcs", str(len(doc["arcs"]))])
        self.assertEqual([[int(c) for c in l] for l in lines[2 + N:]], doc["arcs"])

    def check_obj(self, path, doc):
        n, N = doc["n"], len(doc["nodes"])
        verts, faces = [], []
        with open(path) as f:
            for line in f:
                if line.startswith("v "):
                    verts.append([float(c) for c in line.split()[1:]])
                elif line.startswith("f "):
                    faces.append([int(c) for c in line.split()[1:]])
                else:
                    self.assertTrue(line.startswith("#"), "unexpected OBJ line %r" % line)
        self.assertEqual(verts, [[float(c) for c in v] for v in doc["nodes"]])
        self.assertEqual(len(faces), n)
        for i, face in enumerate(faces):
            self.assertTrue(all(1 <= v <= N for v in face), face)
            self.assertEqual(len(set(face)), len(face), "face %d repeats a vertex" % i)
            self.assertIn(i + 1, face, "face of input edge %d lacks its vertex %d" % (i, i))
            self.assertIn((i + 1) % n + 1, face, "face of input edge %d lacks its end" % i)
        return [[v - 1 for v in face] for face in faces]

    def check_svg(self, path, doc):
        root = ET.parse(path).getroot()
        self.assertTrue(root.tag.endswith("svg"), root.tag)
        ns = {"s": "http://www.w3.org/2000/svg"}
        polys = [p for p in root.findall(".//s:path", ns) if p.get("class") == "polygon"]
        self.assertEqual(len(polys), 1)
        d = polys[0].get("d")
        self.assertEqual(d.count("M") + d.count("L"), doc["n"])
        self.assertEqual(d.count("Z"), len(doc["rings"]))
        self.assertEqual(len(root.findall(".//s:circle", ns)), len(doc["nodes"]))
        classes = [p.get("class") for p in root.findall(".//s:path", ns)]
        self.assertEqual(classes.count("offset"), len(OFFSETS))
        self.assertIn("convex", classes)
        self.assertIn("reflex", classes)
        segments = sum(p.get("d").count("M") for p in root.findall(".//s:path", ns)
                       if p.get("class") in ("convex", "reflex"))
        self.assertEqual(segments, len(doc["arcs"]))

    def check_vtp(self, path, doc, pts, obj_faces):
        try:
            import vtk  # python3-vtk9
        except ImportError as e:
            self.skipTest("VTK for Python not installed (python3-vtk9): %s" % e)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        self.assertEqual(reader.GetErrorCode(), 0, "VTK could not read %s" % path)
        pd = reader.GetOutput()
        n, N, M = doc["n"], len(doc["nodes"]), len(doc["arcs"])
        self.assertEqual(pd.GetNumberOfPoints(), N)
        self.assertEqual(pd.GetNumberOfLines(), n + M)
        self.assertEqual(pd.GetNumberOfPolys(), n)
        self.assertEqual(pd.GetNumberOfVerts(), 0)
        for i in range(N):
            self.assertEqual(list(pd.GetPoint(i)), [float(c) for c in doc["nodes"][i]])
        t = pd.GetPointData().GetArray("t")
        self.assertIsNotNone(t, "no point data 't'")
        self.assertEqual(t.GetNumberOfTuples(), N)
        self.assertEqual(t.GetRange(), (0.0, max(v[2] for v in doc["nodes"])))
        cd = pd.GetCellData()
        edge_id, kind = cd.GetArray("edge_id"), cd.GetArray("kind")
        self.assertIsNotNone(edge_id, "no cell data 'edge_id'")
        self.assertIsNotNone(kind, "no cell data 'kind'")
        cells = 2 * n + M
        self.assertEqual(edge_id.GetNumberOfTuples(), cells)
        self.assertEqual(kind.GetNumberOfTuples(), cells)
        kinds = [int(kind.GetValue(i)) for i in range(cells)]
        edges = [int(edge_id.GetValue(i)) for i in range(cells)]
        self.assertEqual(kinds[:n], [0] * n)
        self.assertTrue(all(k in (1, 2) for k in kinds[n:n + M]))
        self.assertEqual(kinds[n + M:], [3] * n)
        self.assertEqual(edges, list(range(n)) + [-1] * M + list(range(n)))
        # Cells in VTK order: lines (boundary, then arcs), then polygons.
        ids = vtk.vtkIdList()
        lines = pd.GetLines()
        lines.InitTraversal()
        got_lines = []
        while lines.GetNextCell(ids):
            got_lines.append([ids.GetId(j) for j in range(ids.GetNumberOfIds())])
        self.assertEqual(got_lines[:n], [[i, (i + 1) % n] for i in range(n)])
        self.assertEqual(got_lines[n:], [[a, b] for a, b, _, _ in doc["arcs"]])
        polys = pd.GetPolys()
        polys.InitTraversal()
        got_polys = []
        while polys.GetNextCell(ids):
            got_polys.append([ids.GetId(j) for j in range(ids.GetNumberOfIds())])
        self.assertEqual(got_polys, obj_faces)
        # The arc leaving a reflex input vertex is drawn as reflex.
        reflex = reflex_vertices(pts)
        from_reflex = [k for k, (a, b, _, _) in enumerate(doc["arcs"])
                       if (a < n) != (b < n) and (a if a < n else b) in reflex]
        self.assertEqual(len(from_reflex), len(reflex))
        for k in from_reflex:
            self.assertEqual(kinds[n + k], 2, "arc %d leaves a reflex vertex" % k)


class Counters(unittest.TestCase):
    """The JSON stats of each variant hold exactly its declared counters."""

    VARIANTS = ["naive", "monotone", "arrangement"]
    # A counter only one variant declares, and that variant.
    OWN = {"cache_hits": "arrangement", "reference_fallbacks": "monotone"}

    @classmethod
    def setUpClass(cls):
        tl.need(tl.WSKEL)
        cls.listed, cls.stats = {}, {}
        for v in cls.VARIANTS:
            cls.listed[v] = tl.list_counters(v)
            # the plus-shaped cross: monotone, four reflex vertices, every
            # variant computes it
            rc, doc, err = tl.wskel_json([os.path.join(tl.DATA, "hand", "cross.wpoly")], v)
            if rc != 0:
                raise AssertionError("wskel --variant %s cross.wpoly: exit %s: %s"
                                     % (v, rc, err.strip()))
            cls.stats[v] = doc["stats"]

    def test_list_counters_lines(self):
        for v in self.VARIANTS:
            with self.subTest(variant=v):
                names = [name for name, _ in self.listed[v]]
                self.assertGreater(len(names), 0)
                self.assertEqual(len(names), len(set(names)), "a counter is listed twice")
                self.assertFalse({"time_s", "peak_bytes"} & set(names))
                for name, meaning in self.listed[v]:
                    self.assertTrue(meaning.strip(), "counter %s has no meaning" % name)

    def test_stats_keys_equal_list_counters(self):
        for v in self.VARIANTS:
            with self.subTest(variant=v):
                stats, names = self.stats[v], [name for name, _ in self.listed[v]]
                self.assertEqual(set(stats), set(names) | {"time_s", "peak_bytes"})
                for c in names:
                    self.assertTrue(isinstance(stats[c], int) and stats[c] >= 0,
                                    "%s: %s = %r" % (v, c, stats[c]))
                self.assertGreaterEqual(stats["time_s"], 0)
                self.assertGreater(stats["peak_bytes"], 0)
                self.assertGreater(stats["edge_events"], 0, "no edge event counted")

    def test_counter_of_one_variant_absent_from_others(self):
        for counter, owner in self.OWN.items():
            self.assertIn(counter, self.stats[owner], "%s lacks its counter %s" % (owner, counter))
            for v in self.VARIANTS:
                if v != owner:
                    with self.subTest(counter=counter, variant=v):
                        self.assertNotIn(counter, self.stats[v])
                        self.assertNotIn(counter, [name for name, _ in self.listed[v]])

    def test_default_variant_is_naive(self):
        self.assertEqual(tl.list_counters(), self.listed["naive"])


# ------------------------------------------------------------------ PSLGs

PSLG = os.path.join(tl.DATA, "pslg")


def graphml_weights(path):
    """The weight of each GraphML edge (document order; 1 without one)."""
    root = ET.parse(path).getroot()
    keys = {k.get("id"): k.get("attr.name") for k in root.iter() if k.tag.endswith("key")}
    out = []
    for e in root.iter():
        if e.tag.endswith("edge"):
            w = 1.0
            for d in e:
                if d.tag.endswith("data") and keys.get(d.get("key")) == "edge-weight":
                    w = float(d.text)
            out.append(w)
    return out


class PslgGeometry:
    """The stored edges of a PSLG's skeleton (its JSON): edge i runs from
    corner i to the next corner of its ring; a cap (edge_of -1) is the
    incoming half-edge's direction turned clockwise, with its weight."""

    def __init__(self, doc, weights):
        self.doc = doc
        self.n = doc["n"]
        nodes, edge_of = doc["nodes"], doc["pslg"]["edge_of"]
        self.T = doc["pslg"]["horizon"]
        self.nxt, self.prv = [0] * self.n, [0] * self.n
        s = 0
        for size in doc["rings"]:
            for i in range(s, s + size):
                self.nxt[i] = s + (i - s + 1) % size
                self.prv[i] = s + (i - s - 1) % size
            s += size
        self.dirs, self.w = [], []
        for i in range(self.n):
            if edge_of[i] >= 0:
                a, b = nodes[i], nodes[self.nxt[i]]
                self.dirs.append((b[0] - a[0], b[1] - a[1]))
                self.w.append(weights[edge_of[i]])
            else:
                p = self.prv[i]
                a, b = nodes[p], nodes[i]
                self.dirs.append((b[1] - a[1], -(b[0] - a[0])))
                self.w.append(weights[edge_of[p]])
        xs = [v[0] for v in nodes[:self.n]]
        ys = [v[1] for v in nodes[:self.n]]
        self.scale = math.hypot(max(xs) - min(xs), max(ys) - min(ys)) or 1.0

    def left_distance(self, e, x, y):
        """Signed distance of (x, y) from stored edge e's line, > 0 on its face's side."""
        ax, ay = self.doc["nodes"][e][:2]
        dx, dy = self.dirs[e]
        return (dx * (y - ay) - dy * (x - ax)) / math.hypot(dx, dy)


def ring_area(pts):
    return 0.5 * sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1]
                     for i in range(len(pts)))


class PslgOutputs(unittest.TestCase):
    """obj, vtp, svg and --offset (svg, geojson, wkt) of every
    tests/data/pslg file, at the default horizon and at --until 0.3
    diagonals (where bounded faces still have a wavefront, so their cap
    faces are written)."""

    TIMES = [0.02, 0.1, 0.25]  # offset times, in diagonals over the largest weight

    @classmethod
    def setUpClass(cls):
        tl.need(tl.WSKEL)
        cls.tmp = tempfile.TemporaryDirectory(prefix="wskel-pslg-outputs-")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def files(self):
        out = sorted(f for f in os.listdir(PSLG) if f.endswith(".graphml"))
        self.assertGreater(len(out), 3, "too few PSLG test files")
        return out

    def run_wskel(self, args):
        out = os.path.join(self.tmp.name, "out")
        if os.path.exists(out):
            os.remove(out)
        rc, _, err = tl.wskel(["-o", out] + args)
        self.assertEqual(rc, 0, "wskel %s: exit %s: %s" % (" ".join(args), rc, err))
        with open(out) as f:
            return f.read()

    def test_all(self):
        for f in self.files():
            path = os.path.join(PSLG, f)
            weights = graphml_weights(path)
            doc = json.loads(self.run_wskel(["--check", path]))
            G = PslgGeometry(doc, weights)
            for until in (None, 0.3 * G.scale / max(weights)):
                extra = ["--until", repr(until)] if until else []
                with self.subTest(input=f, until=until):
                    d = json.loads(self.run_wskel(["--check"] + extra + [path])) if until else doc
                    G = PslgGeometry(d, weights)
                    faces = self.roof(G, extra + [path])
                    times = [k * G.scale / max(weights) for k in self.TIMES]
                    times = [t for t in times if t <= G.T] + [G.T]
                    arg = ",".join(repr(t) for t in times)
                    rings = self.check_svg(G, self.run_wskel(["--format", "svg", "--offset", arg] +
                                                             extra + [path]), times)
                    gj = json.loads(self.run_wskel(["--format", "geojson", "--offset", arg] + extra +
                                                   [path]))
                    wkt = self.run_wskel(["--format", "wkt", "--offset", arg] + extra + [path])
                    self.check_offsets(G, gj, wkt, times, faces)
                    self.assertEqual(rings, [sum(len(p) for p in f["geometry"]["coordinates"])
                                             for f in gj["features"]], "svg and geojson rings")
        self.assertGreater(self.roofs, 3, "too few PSLG roofs written")

    roofs = 0

    def roof(self, G, args):
        """The OBJ faces, checked, and the VTP's against them (a face with an
        island has it bridged in: weighted_island.graphml, a slow segment
        inside a fast one's face)."""
        out = os.path.join(self.tmp.name, "roof.obj")
        rc, _, err = tl.wskel(["--format", "obj", "-o", out] + args)
        self.assertEqual(rc, 0, err)
        with open(out) as f:
            faces = self.check_obj(G, f.read())
        os.remove(out)
        self.check_vtp(G, faces, args)
        self.roofs += 1
        return faces

    def check_obj(self, G, text):
        """One face per stored edge on its plane z = d / w, counter-clockwise,
        with the edge's corners; then the cap's bounded faces at z = T.
        Returns the faces (0-based)."""
        nodes = G.doc["nodes"]
        verts, faces = [], []
        for line in text.splitlines():
            if line.startswith("v "):
                verts.append([float(c) for c in line.split()[1:]])
            elif line.startswith("f "):
                faces.append([int(c) - 1 for c in line.split()[1:]])
            else:
                self.assertTrue(line.startswith("#"), line)
        self.assertEqual(verts, [[float(c) for c in v] for v in nodes])
        self.assertGreaterEqual(len(faces), G.n)
        tol = 1e-6 * G.scale
        for i, face in enumerate(faces):
            pts = [verts[v] for v in face]
            self.assertGreater(ring_area(pts), -tol * tol, "face %d is clockwise" % i)
            if i < G.n:
                self.assertIn(i, face)
                self.assertIn(G.nxt[i], face)
                for v in face:
                    x, y, z = verts[v]
                    self.assertLessEqual(z, G.T * (1 + 1e-12))
                    self.assertAlmostEqual(G.left_distance(i, x, y), G.w[i] * z, delta=tol,
                                           msg="face %d vertex %d off its plane" % (i, v))
            else:
                self.assertEqual({verts[v][2] for v in face}, {G.T}, "cap face %d" % i)
        return faces

    def check_vtp(self, G, faces, args):
        try:
            import vtk  # python3-vtk9
        except ImportError:
            return
        path = os.path.join(self.tmp.name, "roof.vtp")
        rc, _, err = tl.wskel(["--format", "vtp", "-o", path] + args)
        self.assertEqual(rc, 0, err)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        self.assertEqual(reader.GetErrorCode(), 0)
        pd = reader.GetOutput()
        self.assertEqual(pd.GetNumberOfPoints(), len(G.doc["nodes"]))
        self.assertEqual(pd.GetNumberOfLines(), G.n + len(G.doc["arcs"]))
        ids = vtk.vtkIdList()
        polys = pd.GetPolys()
        polys.InitTraversal()
        got = []
        while polys.GetNextCell(ids):
            got.append([ids.GetId(j) for j in range(ids.GetNumberOfIds())])
        self.assertEqual(got, faces, "vtp polygons differ from the obj faces")

    def check_svg(self, G, text, times):
        root = ET.fromstring(text)
        ns = {"s": "http://www.w3.org/2000/svg"}
        paths = root.findall(".//s:path", ns)
        classes = [p.get("class") for p in paths]
        self.assertNotIn("polygon", classes, "a PSLG has no region to fill")
        seg = [p for p in paths if p.get("class") == "segments"]
        self.assertEqual(len(seg), 1)
        self.assertEqual(seg[0].get("d").count("M"), G.doc["pslg"]["graph_edges"])
        caps = sum(1 for a in G.doc["arcs"] if a[2] == -1)
        got = sum(p.get("d").count("M") for p in paths if p.get("class") == "cap")
        self.assertEqual(got, caps)
        offs = [p for p in paths if p.get("class") == "offset"]
        self.assertEqual(len(offs), len(times))
        counts = []
        for p, t in zip(offs, times):
            self.assertAlmostEqual(float(p.get("data-t")), t, delta=1e-9 * t)
            segs = p.get("d").split("M")[1:]
            self.assertGreater(len(segs), 0, "no offset curve at t = %g" % t)
            counts.append(len(segs))
            for s in segs:
                self.assertTrue(s.endswith("Z"), "an offset ring is not closed")
                for xy in s[:-1].split("L"):
                    x, y = (float(c) for c in xy.split(","))
                    self.assertTrue(self.on_wavefront(G, x, -y, t, 1e-6),
                                    "svg offset point (%g, %g) at t = %g" % (x, -y, t))
        return counts

    def on_wavefront(self, G, x, y, t, rel):
        """(x, y) at distance w t from some stored edge's line, on its face's side."""
        return any(abs(G.left_distance(e, x, y) - G.w[e] * t) <= rel * G.scale
                   for e in range(G.n))

    def check_offsets(self, G, gj, wkt, times, faces):
        self.assertEqual(gj["type"], "FeatureCollection")
        feats = gj["features"]
        self.assertEqual([f["properties"]["t"] for f in feats], times)
        lines = [l for l in wkt.splitlines() if l.strip()]
        self.assertEqual(len(lines), len(times))
        for f, line, t in zip(feats, lines, times):
            polys = f["geometry"]["coordinates"]
            self.assertGreater(len(polys), 0, "no offset polygon at t = %g" % t)
            self.assertTrue(line.startswith("MULTIPOLYGON ((("), line[:40])
            self.assertEqual(line.count("(("), len(polys), "wkt and geojson disagree")
            area = 0.0
            for rings in polys:
                for k, ring in enumerate(rings):
                    self.assertEqual(ring[0], ring[-1], "ring not closed")
                    a = ring_area(ring[:-1])
                    self.assertTrue(a > 0 if k == 0 else a < 0, "ring %d orientation" % k)
                    area += a
                    for x, y in ring:
                        self.assertTrue(self.on_wavefront(G, x, y, t, 1e-6),
                                        "offset point (%g, %g) at t = %g" % (x, y, t))
            if t == G.T:
                # the region swept by T is the roof's edge faces, seen from above
                verts = G.doc["nodes"]
                roof = sum(ring_area([verts[v] for v in face]) for face in faces[:G.n])
                self.assertAlmostEqual(area, roof, delta=1e-9 * G.scale ** 2 + 1e-9 * roof)


if __name__ == "__main__":
    unittest.main()
