#!/usr/bin/python3
"""test_python.py: the Python module python/wskel/ (built by `make python`).

  - skeleton: a square and a rectangle against the closed form, uniform
    weights scale t by 1/w, weights flat and per ring agree, polygons with
    holes and with weights agree node for node with bin/wskel's JSON (the
    same numbering), every variant on an L shape agrees with naive, k = 1
    and k = "max" agree;
  - errors: a self-intersecting polygon is InputError (exit 1) with the
    engine's message, input name and source location; a hole outside the
    polygon, a ring of two points, a wrong weight count are InputError; an
    unknown variant and a bad k are UsageError (exit 64); weights for a
    unit-weight variant are AlgorithmError (exit 2);
  - offset: a square and a regular hexagon against the closed form (area
    A (1 - t / inradius)^2, counter-clockwise), area decreasing in t, empty
    after the collapse; with holes (only once the engine's wk_offset
    replaces the stand-in): area decreasing, outer rings CCW, holes CW;
  - roof: one face per input edge, each starting with its edge, the faces'
    projected areas summing to the polygon's, z = t;
  - PSLGs: pslg_skeleton on every tests/data/pslg file (and the GraphML
    polygons of tests/data/good read as PSLGs), naive and motorcycle,
    default horizon and until = 0.3 diagonals, equal to bin/wskel
    --format json on the file (nodes bit for bit, arcs, horizon, rings,
    corner_node, edge_of; a variant the CLI refuses raises the same
    class); pslg_offset against the CLI's --offset geojson, pslg_roof
    against its OBJ (a roof the CLI refuses raises UnsupportedError);
    closed forms (a segment's swept region is the rectangle [-t, L + t] x
    [-t, t], its roof's edge faces lie on their planes); errors: crossing
    and touching edges, an isolated node, a duplicate point, bad shapes
    and indices are InputError naming the culprit, a polygon-only variant
    and motorcycle with weights UnsupportedError, until <= 0 UsageError,
    an offset past a given until UnsupportedError; allocation failures of
    the three calls;
  - the README's Python example, and its PSLG example, print what their
    comments say;
  - examples/plot_skeleton.py writes a PNG;
  - threads: four threads solving at once get the serial results;
  - allocation failures: each allocation request of a skeleton, offset and
    roof call refused in turn (debug backend): MemoryLimitError, no leak;
  - leaks: 10^4 small calls (skeleton, offset, roof and an error path):
    every run closes with 0 tracked bytes, and the process RSS after them is
    within 4 MiB of the RSS after the first 10^3.
With WSKEL_CHECKED_RUNS=1 every run uses the debug allocator backend (each
free's size checked; make test-py runs the file both ways).
Prints a line per test and 'N passed, N failed'; exits 1 on any failure.
usage: [WSKEL_CHECKED_RUNS=1] /usr/bin/python3 tests/test_python.py
"""
import json
import math
import os
import sys
import tempfile
import traceback

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
import testlib  # noqa: E402
import wskel  # noqa: E402

SQUARE = [(0, 0), (2, 0), (2, 2), (0, 2)]
L_SHAPE = [(0, 0), (5, 0), (5, 2), (2, 2), (2, 3.7), (0, 3.7)]
FRAME = ([(0, 0), (10, 0), (10, 10), (0, 10)], [[(3, 3), (3, 7), (7, 7), (7, 3)]])
TMP = tempfile.mkdtemp(prefix="wskel-test-python.")


def area(ring):
    r = np.asarray(ring)
    x, y = r[:, 0], r[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def interior(sk):
    """The skeleton's nodes past the input ones, as sorted rounded tuples."""
    return sorted((round(float(x), 7), round(float(y), 7), round(float(t), 7))
                  for x, y, t in sk.nodes[sk.n:])


def read_rings(path):
    """The rings and weights of a .wpoly file (with holes)."""
    nums = [line.split() for line in open(path) if line.strip() and not line.startswith("#")]
    rings, weights, i = [], [], 0
    while i < len(nums):
        m = int(nums[i][0])
        rows = nums[i + 1:i + 1 + m]
        rings.append([(float(r[0]), float(r[1])) for r in rows])
        weights.append([float(r[2]) if len(r) > 2 else 1.0 for r in rows])
        i += 1 + m
    return rings, weights


# ---------------------------------------------------------------- skeleton

def test_square_closed_form():
    sk = wskel.skeleton(SQUARE)
    assert sk.n == 4
    assert np.allclose(sk.nodes[:4]["x"], [0, 2, 2, 0]) and np.all(sk.nodes[:4]["t"] == 0)
    inner = sk.nodes[4:]
    assert len(inner) >= 1 and np.allclose(inner["x"], 1) and np.allclose(inner["y"], 1) \
        and np.allclose(inner["t"], 1), inner
    # Every corner has one arc, between the faces of its two edges.
    for i in range(4):
        arcs = [a for a in sk.arcs if i in (a["a"], a["b"])]
        assert len(arcs) == 1, (i, arcs)
        assert {int(arcs[0]["left"]), int(arcs[0]["right"])} == {(i - 1) % 4, i}, arcs
    assert sk.counters["edge_events"] >= 1, sk.counters
    assert "queue_pops" in sk.counters


def test_rectangle_closed_form():
    sk = wskel.skeleton([(0, 0), (4, 0), (4, 2), (0, 2)])
    assert interior(sk) == [(1.0, 1.0, 1.0), (3.0, 1.0, 1.0)], interior(sk)
    assert len(sk.arcs) == 5


def test_uniform_weights_scale_time():
    sk = wskel.skeleton(SQUARE, weights=[2, 2, 2, 2])
    assert np.allclose(sk.nodes[4:]["t"], 0.5), sk.nodes
    assert np.allclose(sk.nodes[4:]["x"], 1)


def test_weights_flat_and_per_ring_agree():
    outer, holes = FRAME
    flat = [1, 2, 1, 3, 1, 1, 2, 1]
    a = wskel.skeleton(outer, holes, weights=flat)
    b = wskel.skeleton(outer, holes, weights=[flat[:4], flat[4:]])
    assert np.array_equal(a.nodes, b.nodes) and np.array_equal(a.arcs, b.arcs)
    c = wskel.skeleton(outer, holes)
    assert not np.array_equal(a.nodes, c.nodes)


def test_holes_and_weights_match_cli():
    testlib.need(testlib.WSKEL)
    files = [os.path.join(testlib.DATA, "holes", f) for f in
             ("triangle_hole.wpoly", "weighted_islands.wpoly", "square_hole_off_centre.wpoly")]
    for path in files:
        rings, weights = read_rings(path)
        sk = wskel.skeleton(rings[0], rings[1:], weights=weights)
        rc, doc, err = testlib.wskel_json([path])
        assert rc == 0, err
        assert np.allclose(np.column_stack([sk.nodes["x"], sk.nodes["y"], sk.nodes["t"]]),
                           np.asarray(doc["nodes"], dtype=float), rtol=0, atol=1e-12), path
        assert sk.arcs.tolist() == [tuple(a) for a in doc["arcs"]], path
        # Every input edge has a face: it is on some arc's side.
        faces = set(sk.arcs["left"].tolist()) | set(sk.arcs["right"].tolist())
        assert faces == set(range(sk.n)), (path, faces)


def test_every_variant_agrees_with_naive():
    ref = interior(wskel.skeleton(L_SHAPE))
    names = wskel.variants()
    assert "naive" in names and len(names) >= 2, names
    for v in names:
        got = interior(wskel.skeleton(L_SHAPE, variant=v))
        assert got == ref, (v, got, ref)


def test_k_values_agree():
    a = wskel.skeleton(L_SHAPE, variant="arrangement", k=1)
    b = wskel.skeleton(L_SHAPE, variant="arrangement", k="max")
    assert interior(a) == interior(b)


# ------------------------------------------------------------------ errors

def expect(cls, fn, *args, **kw):
    try:
        fn(*args, **kw)
    except cls as e:
        assert isinstance(e, wskel.Error)
        return e
    raise AssertionError("no %s raised" % cls.__name__)


def test_invalid_polygon_input_error():
    e = expect(wskel.InputError, wskel.skeleton, [(0, 0), (2, 2), (2, 0), (0, 2)], name="bowtie")
    assert e.exit_code == 1 and isinstance(e, ValueError)
    assert e.input == "bowtie", e.input
    assert "intersect" in e.message or "cross" in e.message or "simple" in e.message, e.message
    assert e.src_file.endswith(".c") and e.src_line > 0, (e.src_file, e.src_line)
    assert e.message in str(e) and "bowtie" in str(e)


def test_other_input_errors():
    outer, _ = FRAME
    e = expect(wskel.InputError, wskel.skeleton, outer, [[(20, 20), (21, 20), (21, 21)]])
    assert "inside" in e.message or "outside" in e.message, e.message
    expect(wskel.InputError, wskel.skeleton, [(0, 0), (1, 0)])
    expect(wskel.InputError, wskel.skeleton, SQUARE, weights=[1, 1, 1])
    e = expect(wskel.InputError, wskel.skeleton, SQUARE, weights=[1, -1, 1, 1])
    assert e.exit_code == 1 and e.src_line > 0
    expect(wskel.InputError, wskel.skeleton, [(0, 0), (1, 0), (float("nan"), 1)])


def test_unknown_variant_and_bad_k():
    e = expect(wskel.UsageError, wskel.skeleton, SQUARE, variant="no-such-variant")
    assert e.exit_code == 64 and "no-such-variant" in e.message, e
    expect(wskel.UsageError, wskel.skeleton, SQUARE, k=0)
    expect(wskel.UsageError, wskel.skeleton, SQUARE, k="many")


def test_unit_weight_variant_rejects_weights():
    unit_only = [v for v in wskel.variants() if v in ("motorcycle",)]
    for v in unit_only:
        e = expect(wskel.AlgorithmError, wskel.skeleton, SQUARE, weights=[1, 2, 1, 1], variant=v)
        assert e.exit_code == 2 and "unit weights" in e.message, e


def test_error_classes():
    assert issubclass(wskel.UnsupportedError, wskel.AlgorithmError)
    assert wskel.AlgorithmError.exit_code == 2 and wskel.InvalidOutputError.exit_code == 3
    for c in (wskel.InputError, wskel.AlgorithmError, wskel.InvalidOutputError, wskel.UsageError):
        assert issubclass(c, wskel.Error)


# ----------------------------------------------------------------- offsets

def test_offset_square_closed_form():
    ts = [0, 0.25, 0.5, 0.75, 0.999, 1.0, 1.5]
    res = wskel.offset(SQUARE, t=ts)
    assert len(res) == len(ts)
    for t, polys in zip(ts, res):
        if t >= 1:
            assert polys == [], (t, polys)
            continue
        assert len(polys) == 1 and len(polys[0]) == 1, (t, polys)
        ring = polys[0][0]
        assert abs(area(ring) - (2 - 2 * t) ** 2) < 1e-9, (t, area(ring))
        assert np.all(ring >= t - 1e-12) and np.all(ring <= 2 - t + 1e-12), ring
    one = wskel.offset(SQUARE, t=0.5)  # a number: the polygons themselves
    assert len(one) == 1 and abs(area(one[0][0]) - 1) < 1e-12


def test_offset_hexagon_closed_form():
    hexagon = [(math.cos(math.pi * i / 3), math.sin(math.pi * i / 3)) for i in range(6)]
    a0, rin = area(hexagon), math.cos(math.pi / 6)
    prev = a0
    for t in np.linspace(0.05, 0.8, 8):
        polys = wskel.offset(hexagon, t=t)
        a = area(polys[0][0])
        assert a > 0 and abs(a - a0 * (1 - t / rin) ** 2) < 1e-9, (t, a)
        assert a < prev
        prev = a
    assert wskel.offset(hexagon, t=rin + 1e-9) == []


def test_offset_with_holes():
    prev = None
    for t in (0.25, 0.5, 1.0, 1.4):
        polys = wskel.offset(FRAME[0], FRAME[1], t=t)
        assert polys, t
        total = 0
        for rings in polys:
            assert area(rings[0]) > 0, "outer ring not CCW"
            for h in rings[1:]:
                assert area(h) < 0, "hole not CW"
            total += sum(area(r) for r in rings)
        assert prev is None or total < prev, (t, total, prev)
        prev = total
    assert wskel.offset(FRAME[0], FRAME[1], t=1.5 + 1e-9) == []


# -------------------------------------------------------------------- roof

def test_roof_faces():
    for outer, holes in ((SQUARE, ()), (L_SHAPE, ()), FRAME):
        r = wskel.roof(outer, holes)
        rings = [outer] + list(holes)
        n = sum(len(x) for x in rings)
        assert len(r.faces) == n, (len(r.faces), n)
        assert r.vertices.shape[1] == 3 and np.all(r.vertices[:n, 2] == 0)
        assert np.all(r.vertices[:, 2] >= 0)
        start = 0
        total = 0.0
        for ring in rings:
            m = len(ring)
            for j in range(m):
                f = r.faces[start + j].tolist()
                # Face of edge i starts with the edge's endpoints (either
                # direction: a clockwise input ring is stored reversed).
                assert {f[0], f[1]} == {start + j, start + (j + 1) % m}, (start + j, f)
                total += abs(area(r.vertices[f, :2]))
            start += m
        poly_area = abs(area(outer)) - sum(abs(area(h)) for h in holes)
        assert abs(total - poly_area) < 1e-9 * poly_area, (total, poly_area)


# ------------------------------------------------------------------- PSLGs

PSLG_FILES = sorted(os.path.join(testlib.DATA, "pslg", f)
                    for f in os.listdir(os.path.join(testlib.DATA, "pslg"))
                    if f.endswith(".graphml"))
PSLG_POLYGONS = [os.path.join(testlib.DATA, "good", f)
                 for f in ("unweighted.graphml", "weighted.graphml")]
SEGMENT = ([(0, 0), (3, 0)], [(0, 1)])


def diagonal(points):
    p = np.asarray(points, dtype=float)
    return float(np.hypot(*(p.max(axis=0) - p.min(axis=0))))


def pslg_cases():
    """(path, points, edges, weights) of every PSLG test file, > 0 of them."""
    out = []
    for path in PSLG_FILES + PSLG_POLYGONS:
        pts, edges, w = wskel.read_graphml(path)
        out.append((path, pts, edges, w))
    assert len(out) >= 10, len(out)
    return out


def test_pslg_skeleton_matches_cli():
    """The binding gives bin/wskel's skeleton of the same file: nodes bit
    for bit (same arrays, same computation; %.17g round-trips), arcs with
    the cap as -1, horizon, rings, corners' nodes, edges' graph edges."""
    testlib.need(testlib.WSKEL)
    compared = refused = 0
    for path, pts, edges, w in pslg_cases():
        for variant in ("naive", "motorcycle"):
            for until in (None, 0.3 * diagonal(pts)):
                args = ["--pslg", path] + (["--until", repr(until)] if until else [])
                rc, doc, err = testlib.wskel_json(args, variant)
                if rc != 0:
                    e = expect(wskel.Error, wskel.pslg_skeleton, pts, edges, w, until=until,
                               variant=variant)
                    assert e.exit_code == rc, (path, variant, rc, err, e)
                    refused += 1
                    continue
                sk = wskel.pslg_skeleton(pts, edges, w, until=until, variant=variant, name=path)
                got = np.column_stack([sk.nodes["x"], sk.nodes["y"], sk.nodes["t"]])
                want = np.asarray(doc["nodes"], dtype=float)
                assert got.shape == want.shape and np.array_equal(got, want), (path, variant)
                assert sk.arcs.tolist() == [tuple(a) for a in doc["arcs"]], (path, variant)
                ps = doc["pslg"]
                assert sk.horizon == ps["horizon"] and sk.n == doc["n"], (path, variant)
                assert sk.rings.tolist() == doc["rings"], (path, variant)
                assert sk.corner_node.tolist() == ps["corner_node"], (path, variant)
                assert sk.edge_of.tolist() == ps["edge_of"], (path, variant)
                if until:
                    assert sk.horizon == until, (path, sk.horizon, until)
                # the cap: arcs with the unswept side (-1) on the left, at t = T
                cap = sk.arcs[sk.arcs["left"] == -1]
                assert len(cap) > 0 and (sk.arcs["right"] >= 0).all(), path
                assert np.all(sk.nodes["t"][cap["a"]] == sk.horizon), path
                compared += 1
    # the weighted files are refused by motorcycle (equal weights only)
    assert compared >= 30 and refused >= 4, (compared, refused)
    print("  (%d skeletons equal to the CLI's, %d refused by both)" % (compared, refused))


def geojson_rings(doc):
    """[[[rings as (m, 2) arrays, closing point dropped] per polygon] per t]."""
    out = []
    for feat in doc["features"]:
        out.append([[np.asarray(r, dtype=float)[:-1] for r in poly]
                    for poly in feat["geometry"]["coordinates"]])
    return out


def test_pslg_offset_matches_cli():
    testlib.need(testlib.WSKEL)
    compared = 0
    for path, pts, edges, w in pslg_cases():
        d = diagonal(pts)
        times = [0.05 * d, 0.2 * d, 0.6 * d]
        rc, out, err = testlib.wskel(["--pslg", "--format", "geojson", "--offset",
                                      ",".join(repr(t) for t in times), path])
        assert rc == 0, (path, err)
        want = geojson_rings(json.loads(out))
        got = wskel.pslg_offset(pts, edges, w, t=times)
        assert len(got) == len(want) == 3, path
        for ti, g, x in zip(times, got, want):
            assert len(g) == len(x) > 0, (path, ti, len(g), len(x))
            for gp, xp in zip(g, x):
                assert len(gp) == len(xp), (path, ti)
                for gr, xr in zip(gp, xp):
                    assert gr.shape == xr.shape and np.array_equal(gr, xr), (path, ti)
            compared += 1
        # one time alone: the same region (to rounding: the list's largest
        # time is past the default horizon, so its skeleton was followed
        # further, and its nodes at the same events can differ in the last bit)
        one = wskel.pslg_offset(pts, edges, w, t=times[0])
        assert len(one) == len(got[0]) and all(
            a.shape == b.shape and np.allclose(a, b, rtol=0, atol=1e-12 * diagonal(pts))
            for pa, pb in zip(one, got[0]) for a, b in zip(pa, pb)), path
    assert compared >= 30, compared


def read_obj(text):
    v, f = [], []
    for line in text.splitlines():
        if line.startswith("v "):
            v.append([float(x) for x in line.split()[1:]])
        elif line.startswith("f "):
            f.append([int(x) - 1 for x in line.split()[1:]])
    return np.asarray(v, dtype=float), f


def test_pslg_roof_matches_cli_obj():
    """pslg_roof is the CLI's OBJ roof (vertices bit for bit, faces), at
    the default horizon (no bounded wavefront left: edge faces only) and
    at 0.3 and 0.03 diagonals (cap faces at z = T closing the bounded
    faces still alive, a component inside one bridged in as its hole)."""
    testlib.need(testlib.WSKEL)
    compared = cap_faces = holed = 0
    for path, pts, edges, w in pslg_cases():
        for until in (None, 0.3 * diagonal(pts), 0.03 * diagonal(pts)):
            args = ["--pslg", "--format", "obj", path] + (["--until", repr(until)] if until else [])
            rc, out, err = testlib.wskel(args)
            # a cap face around a component still apart from it at T is
            # written with its hole bridged in, no longer refused (issues 13/14)
            assert rc == 0, (path, until, rc, err)
            verts, faces = read_obj(out)
            r = wskel.pslg_roof(pts, edges, w, until=until)
            assert np.array_equal(r.vertices, verts), path
            assert [f.tolist() for f in r.faces] == faces, (path, until)
            sk = wskel.pslg_skeleton(pts, edges, w, until=until)
            assert r.n_edge_faces == sk.n and r.horizon == sk.horizon, path
            # the cap faces lie at z = T
            for f in r.faces[r.n_edge_faces:]:
                assert np.all(r.vertices[f, 2] == r.horizon), path
                # a bridged hole visits its bridge's ends twice
                holed += len(set(f.tolist())) < len(f)
            cap_faces += len(r.faces) - r.n_edge_faces
            compared += 1
    assert compared >= 30 and cap_faces >= 5 and holed >= 1, (compared, cap_faces, holed)
    print("  (%d roofs equal to the CLI's OBJ, %d cap faces, %d with holes bridged in)"
          % (compared, cap_faces, holed))


def test_pslg_segment_closed_form():
    """A segment of length L: the region swept by t is the rectangle
    [-t, L + t] x [-t, t] (the caps move along the segment); its roof's
    faces lie on their planes (the sides z = |y|, the caps z = -x and
    z = x - L), weights scaling t."""
    pts, edges = [(0, 0), (3, 0)], [(0, 1)]
    for wt in (1.0, 2.5):
        for t in (0.1, 0.5, 2.0):
            polys = wskel.pslg_offset(pts, edges, [wt], t=t)
            assert len(polys) == 1 and len(polys[0]) == 1, polys
            ring = polys[0][0]
            d = wt * t
            want = {(-d, -d), (3 + d, -d), (3 + d, d), (-d, d)}
            got = {(round(float(x), 12), round(float(y), 12)) for x, y in ring}
            assert got == {(round(x, 12), round(y, 12)) for x, y in want}, (wt, t, ring)
            assert area(ring) > 0  # counter-clockwise
        r = wskel.pslg_roof(pts, edges, [wt], until=1.0)
        assert r.horizon == 1.0 and r.n_edge_faces == 4 and len(r.faces) == 4
        sk = wskel.pslg_skeleton(pts, edges, [wt], until=1.0)
        for i, f in enumerate(r.faces):
            e = sk.edge_of[i]
            v = r.vertices[f]
            if e >= 0:  # a side: distance from the segment's line = w t
                assert np.allclose(np.abs(v[:, 1]), wt * v[:, 2], atol=1e-12), (i, v)
            else:  # a cap: distance beyond its terminal = w t
                beyond = np.maximum(-v[:, 0], v[:, 0] - 3)
                assert np.allclose(beyond, wt * v[:, 2], atol=1e-12), (i, v)


def test_pslg_errors():
    e = expect(wskel.InputError, wskel.pslg_skeleton, [(0, 0), (2, 2), (2, 0), (0, 2)],
               [(0, 1), (2, 3)], name="x.graphml")
    assert e.exit_code == 1 and e.input == "x.graphml" and "cross" in e.message, e
    e = expect(wskel.InputError, wskel.pslg_skeleton, [(0, 0), (2, 0), (1, 0), (1, 1)],
               [(0, 1), (2, 3)])
    assert "touch" in e.message or "overlap" in e.message, e
    e = expect(wskel.InputError, wskel.pslg_skeleton, [(0, 0), (1, 0), (5, 5)], [(0, 1)])
    assert "isolated" in e.message or "no edge" in e.message, e
    e = expect(wskel.InputError, wskel.pslg_skeleton, [(0, 0), (1, 0), (1, 0)], [(0, 1), (0, 2)])
    assert e.exit_code == 1, e
    for pts, edges, w, what in (([(0, 0, 1)], [(0, 1)], None, "points must be"),
                                (SEGMENT[0], [(0, 1, 2)], None, "edges must be"),
                                (SEGMENT[0], [(0.0, 1.0)], None, "edges must be"),
                                (SEGMENT[0], [(0, 2)], None, "out of range"),
                                (SEGMENT[0], [(0, -1)], None, "out of range"),
                                (SEGMENT[0], SEGMENT[1], [1, 2], "weights"),
                                (SEGMENT[0], SEGMENT[1], [-1], "weight")):
        e = expect(wskel.InputError, wskel.pslg_skeleton, pts, edges, w)
        assert what in e.message, (what, e)
    e = expect(wskel.UnsupportedError, wskel.pslg_skeleton, *SEGMENT, variant="arrangement")
    assert e.exit_code == 2 and "does not take PSLG input" in e.message, e
    e = expect(wskel.UnsupportedError, wskel.pslg_skeleton, *SEGMENT, weights=[2.0],
               variant="motorcycle")
    assert "unit weights only" in e.message, e
    for bad in (0, -1, float("nan"), float("inf"), "x"):
        e = expect(wskel.UsageError, wskel.pslg_skeleton, *SEGMENT, until=bad)
        assert e.exit_code == 64, e
    e = expect(wskel.InputError, wskel.pslg_skeleton, *SEGMENT, until=1e12)
    assert e.exit_code == 1, e
    e = expect(wskel.UnsupportedError, wskel.pslg_offset, *SEGMENT, t=[0.5, 2.0], until=1.0)
    assert "beyond the horizon" in e.message, e
    # past the default horizon without until: followed up to the latest t
    polys = wskel.pslg_offset(*SEGMENT, t=50.0)
    assert len(polys) == 1 and abs(area(polys[0][0]) - 100 * 103) < 1e-6, polys
    e = expect(wskel.UsageError, wskel.pslg_skeleton, *SEGMENT, variant="nope")
    assert "unknown variant" in e.message, e
    e = expect(wskel.InputError, wskel.read_graphml, os.path.join(TMP, "missing.graphml"))
    assert "missing.graphml" in e.input, e


def fail_every_allocation(calls):
    """Run each call once to count its allocations, then once per allocation
    with that one failing: each failure must raise MemoryLimitError (exit 2),
    at least half of them must be refused that way (the rest are optional
    caches), and no tracked byte may leak over the whole loop."""
    before = wskel.run_stats()
    for call in calls:
        wskel._test_alloc["checked"] = True
        try:
            call()
            total = wskel.run_stats()["last_alloc_requests"]
            assert total > 5, total
            refused = 0
            for fail_at in range(1, total + 1):
                wskel._test_alloc["fail_at"] = fail_at
                try:
                    call()
                except wskel.MemoryLimitError as e:
                    assert e.exit_code == 2 and e.status == "out of memory", e
                    refused += 1
                finally:
                    wskel._test_alloc["fail_at"] = 0
            assert refused >= total // 2, (refused, total)
        finally:
            wskel._test_alloc["checked"] = False
    after = wskel.run_stats()
    assert after["leaked_bytes"] == before["leaked_bytes"] == 0, after


def test_pslg_allocation_failures_leave_nothing():
    pts, edges, w = wskel.read_graphml(os.path.join(testlib.DATA, "pslg", "square_dangling.graphml"))
    calls = [lambda: wskel.pslg_skeleton(pts, edges, w),
             lambda: wskel.pslg_offset(pts, edges, w, t=[0.1, 0.4]),
             lambda: wskel.pslg_roof(pts, edges, w)]
    fail_every_allocation(calls)


def test_readme_example_runs():
    """The README's Python example, run as given from the repository root,
    prints what its comments say."""
    text = open(os.path.join(ROOT, "README.md")).read()
    blocks = text.split("```python\n")
    assert len(blocks) == 2, "README.md should have one Python example"
    code = blocks[1].split("```")[0]
    rc, out, err = run_in_root(code)
    assert rc == 0, err
    lines = out.splitlines()
    assert lines[0] == "[(3., 1., 1.) (1., 1., 1.)]", lines
    assert lines[1] == "[(1, 4, 0, 1) (0, 5, 3, 0)]", lines
    assert lines[2] == "2" and lines[-2] == "4 [0 1 4 5]", lines
    assert lines[-1] == "1 edge 0 crosses edge 2", lines


def test_readme_pslg_example_runs():
    """The README's PSLG example (the indented block in the Python
    section) prints what the comment of each print line says before its
    last ': '."""
    text = open(os.path.join(ROOT, "README.md")).read()
    sec = text.split("## Python\n", 1)[1].split("\n## ", 1)[0]
    block = sec.split("gives the skeleton `bin/wskel --pslg`", 1)[1].split("\n\n", 2)[1]
    lines = [ln[6:] for ln in block.splitlines()]
    assert lines and all(ln.strip() for ln in lines), block
    want = [ln.split("#", 1)[1].strip().rsplit(": ", 1)[0] for ln in lines
            if ln.startswith("print(")]
    assert len(want) >= 5, want
    code = "import sys; sys.path.insert(0, 'python')\nimport wskel\n" + "\n".join(lines)
    rc, out, err = run_in_root(code)
    assert rc == 0, err
    assert out.splitlines() == want, (out.splitlines(), want)


def run_in_root(code):
    """(exit code, stdout, stderr) of Python code run from the repository root."""
    import subprocess
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                       timeout=60)
    return p.returncode, p.stdout, p.stderr


def test_example_script_writes_png():
    out = os.path.join(TMP, "skeleton.png")
    rc, so, se = testlib.run([sys.executable, os.path.join(ROOT, "examples", "plot_skeleton.py"),
                              out])
    assert rc == 0, se
    with open(out, "rb") as f:
        head = f.read(8)
    assert head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(out) > 10000, os.path.getsize(out)


# ------------------------------------------------------------------- leaks

def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def leak_round(i):
    tri = [(0, 0), (3 + i % 7, 0), (1, 2)]
    kind = i % 4
    if kind == 0:
        wskel.skeleton(L_SHAPE)
    elif kind == 1:
        wskel.offset(tri, t=[0.1, 0.3])
    elif kind == 2:
        wskel.roof(FRAME[0], FRAME[1])
    else:
        try:
            wskel.skeleton([(0, 0), (2, 2), (2, 0), (0, 2)])
        except wskel.InputError:
            pass


def test_allocation_failures_leave_nothing():
    """Every allocation of a skeleton, offset and roof call refused in turn
    (the debug backend's fault injection): each refusal is a
    MemoryLimitError or, where the engine recovers, a result; never a leak
    or a crash.  The debug backend also checks every free's size."""
    calls = [lambda: wskel.skeleton(FRAME[0], FRAME[1], weights=[1, 2, 1, 1, 1, 1, 1, 1]),
             lambda: wskel.offset([(0, 0), (3, 0), (3, 2), (0, 3)],
                                  t=[0.2, 0.6]),
             lambda: wskel.roof(FRAME[0], FRAME[1])]
    fail_every_allocation(calls)


def test_threads_share_nothing():
    """Runs in several threads at once (ctypes drops the GIL in the C calls;
    each call has its own run) give the serial results."""
    import threading
    polys = [[(0, 0), (4 + i, 0), (4 + i, 2 + (i % 3)), (2, 1.5), (0, 2 + i % 2)]
             for i in range(8)]
    want = [interior(wskel.skeleton(p, variant="arrangement")) for p in polys]
    got, errors = {}, []

    def work(j):
        try:
            for rep in range(25):
                i = (j + rep) % len(polys)
                r = interior(wskel.skeleton(polys[i], variant="arrangement"))
                if r != want[i]:
                    errors.append((j, i, r))
            got[j] = True
        except Exception as e:  # noqa: BLE001  (reported below)
            errors.append((j, repr(e)))
    ts = [threading.Thread(target=work, args=(j,)) for j in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    assert not errors and len(got) == 4, errors[:3]


def test_no_leaks_over_10000_calls():
    before = wskel.run_stats()
    for i in range(1000):
        leak_round(i)
    rss0 = rss_bytes()
    for i in range(1000, 10000):
        leak_round(i)
    rss1 = rss_bytes()
    after = wskel.run_stats()
    assert after["runs"] - before["runs"] == 10000, after
    assert after["leaked_bytes"] == before["leaked_bytes"] == 0, after
    assert rss1 - rss0 < 4 << 20, "RSS grew by %d bytes over 9000 calls" % (rss1 - rss0)
    print("  (RSS after 10^3 calls %.1f MiB, after 10^4 %.1f MiB)" % (rss0 / 2**20, rss1 / 2**20))


def main():
    tests = [(k, v) for k, v in globals().items() if k.startswith("test_") and callable(v)]
    passed = failed = 0
    for name, fn in tests:
        try:
            fn()
            print("PASS", name)
            passed += 1
        except testlib.unittest.SkipTest as e:
            print("SKIP", name, e)
        except Exception:
            print("FAIL", name)
            traceback.print_exc()
            failed += 1
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
