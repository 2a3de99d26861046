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
  - the README's Python example prints what its comments say;
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
