#!/usr/bin/python3
"""test_near_touch.py: rings whose vertices nearly touch, through every variant.

Run: /usr/bin/python3 tests/test_near_touch.py [-v]          (the test)
     /usr/bin/python3 tests/test_near_touch.py --sweep N     (N cases, counts)

The family of the fuzz findings ealgo_holes_vertices_1e-10_apart.wpoly and
mismatch_arrangement_motorcycle_holes_touching.wpoly (tests/data/fuzz): valid
polygons with holes where a vertex of one ring lies a gap of 1e-12 .. 1e-5
from a vertex or an edge of another ring, far below the simulation's eps_d
(1e-9 of the scale) in most cases.  The gap is closed by no event the
tolerance could merge away: on either side of it the skeleton differs by
whole faces (the stretch of an edge between the gap and the cut may grow into
a face as wide as the polygon), so the answer is the input's own, CGAL's
(engine/tolerance.h, WK_SPLIT_SIDE_ULPS).

Cases (seeded per case, so a failure names it): an outer square (a third of
them with a notch whose reflex tip is a ring vertex) and wedge-shaped holes
(triangles or quadrilaterals with one sharp apex):
  two_holes     two holes whose apexes lie the gap apart;
  three_holes   three holes around one point, apexes the gap apart;
  hole_notch    a hole's apex the gap from the notch's reflex tip;
  hole_corner   a hole's apex the gap from a convex corner of the outer ring;
  hole_edge     a hole's apex the gap from an edge of the outer ring or of
                another hole;
each ring in either orientation, a third of the cases turned by a random
angle and a third moved 1e6 from the origin (where a gap below the
coordinates' ulps closes: the reader refuses the rings as touching, counted
as dropped); half with unit weights, half with weights 0.5 .. 3.

Oracles: naive's skeleton must pass --check; arrangement (k = 1 and
k = max), motorcycle (unit weights; weighted cases it must refuse, exit 2)
and deforming must pass --check and be naive's skeleton
(testlib.same_skeleton); with unit weights naive's skeleton must be CGAL's
(bin/wskel-cgal, scripts/compare_skeletons.py).  monotone refuses holes and
is not run.  A case the reader refuses (exit 1: rings touching after
rounding) is dropped; more than a third dropped fails (the generator broke).
The test asserts how many cases it compared.

The cases fixed so far are files (tests/data/holes/near_touch_*.wpoly,
with what went wrong in their first line), checked the same way
(test_files; known failures in KNOWN_FILES).

Environment: WSKEL_NEAR_TOUCH_CASES (default 40) for the test.
"""
import argparse
import math
import os
import random
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import testlib as tl  # noqa: E402
from testlib import cs  # noqa: E402

CASES = int(os.environ.get("WSKEL_NEAR_TOUCH_CASES", "40"))
KINDS = ["two_holes", "three_holes", "hole_notch", "hole_corner", "hole_edge"]
# variant runs compared with naive: (label, variant, extra options)
VARIANTS = [("arrangement", "arrangement", ["--k", "1"]),
            ("arrangement-kmax", "arrangement", ["--k", "max"]),
            ("motorcycle", "motorcycle", []),
            ("deforming", "deforming", [])]


def _dir(a):
    return math.cos(a), math.sin(a)


def wedge(rnd, apex, theta):
    """A hole with its sharpest vertex at apex, extending in direction theta."""
    h = math.radians(rnd.uniform(4, 30))
    length = rnd.uniform(8, 30)
    ax, ay = apex
    pts = [apex]
    c1, s1 = _dir(theta - h)
    c2, s2 = _dir(theta + h)
    pts.append((ax + length * c1, ay + length * s1))
    if rnd.random() < 0.4:
        c0, s0 = _dir(theta)
        far = length * rnd.uniform(1.05, 1.4)
        pts.append((ax + far * c0, ay + far * s0))
    pts.append((ax + length * c2, ay + length * s2))
    return pts


def make_case(seed):
    """(kind, gap, rings, weights per ring): a polygon with holes."""
    rnd = random.Random("near-touch:%d" % seed)
    kind = KINDS[seed % len(KINDS)]
    gap = 10 ** rnd.uniform(-12, -5)
    notch = kind == "hole_notch" or rnd.random() < 0.3
    outer = [(-100.0, -100.0)]
    tip = (0.0, -100.0 + rnd.uniform(30, 60))
    if notch:
        outer += [(-12.0, -100.0), tip, (12.0, -100.0)]
    outer += [(100.0, -100.0), (100.0, 100.0), (-100.0, 100.0)]
    holes = []
    if kind == "two_holes":
        p = (rnd.uniform(-20, 20), rnd.uniform(0, 20))
        t1 = rnd.uniform(0, 2 * math.pi)
        phi = rnd.uniform(0, 2 * math.pi)
        c, s = _dir(phi)
        holes.append(wedge(rnd, p, t1))
        holes.append(wedge(rnd, (p[0] + gap * c, p[1] + gap * s), t1 + math.pi + rnd.uniform(-1, 1)))
    elif kind == "three_holes":
        p = (rnd.uniform(-20, 20), rnd.uniform(0, 20))
        t1 = rnd.uniform(0, 2 * math.pi)
        for j in range(3):
            phi = rnd.uniform(0, 2 * math.pi)
            c, s = _dir(phi)
            g = gap * (1 if j == 0 else 10 ** rnd.uniform(0, 1))
            q = p if j == 0 else (p[0] + g * c, p[1] + g * s)
            holes.append(wedge(rnd, q, t1 + j * 2 * math.pi / 3 + rnd.uniform(-0.3, 0.3)))
    elif kind == "hole_notch":
        phi = math.pi / 2 + rnd.uniform(-1.2, 1.2)
        c, s = _dir(phi)
        holes.append(wedge(rnd, (tip[0] + gap * c, tip[1] + gap * s), math.pi / 2 + rnd.uniform(-0.6, 0.6)))
    elif kind == "hole_corner":
        corner = (-100.0, 100.0)  # the top left corner: interior towards -45 degrees
        phi = -math.pi / 4 + rnd.uniform(-0.7, 0.7)
        c, s = _dir(phi)
        holes.append(wedge(rnd, (corner[0] + gap * c, corner[1] + gap * s), -math.pi / 4 + rnd.uniform(-0.3, 0.3)))
    else:  # hole_edge
        if rnd.random() < 0.5:
            x = rnd.uniform(-60, 60)  # below the top edge y = 100
            holes.append(wedge(rnd, (x, 100.0 - gap), -math.pi / 2 + rnd.uniform(-0.8, 0.8)))
        else:
            big = [(-40.0, -10.0), (40.0, -10.0), (0.0, 30.0)]  # a triangle hole
            u = rnd.uniform(0.2, 0.8)
            q = (big[0][0] + u * (big[2][0] - big[0][0]), big[0][1] + u * (big[2][1] - big[0][1]))
            nx, ny = -40.0, 40.0  # outward normal of the edge big[0] -> big[2]
            nl = math.hypot(nx, ny)
            holes.append(big)
            holes.append(wedge(rnd, (q[0] + gap * nx / nl, q[1] + gap * ny / nl),
                               math.atan2(ny, nx) + rnd.uniform(-0.8, 0.8)))
    rings = [outer] + holes
    # turned a third of the time, moved far from the origin a third
    mode = rnd.choice(["plain", "turned", "moved"])
    if mode == "turned":
        a = rnd.uniform(0, 2 * math.pi)
        c, s = math.cos(a), math.sin(a)
        rings = [[(c * x - s * y, s * x + c * y) for x, y in r] for r in rings]
    elif mode == "moved":
        dx, dy = rnd.choice([-1, 1]) * 1e6, rnd.choice([-1, 1]) * 1e6 * rnd.random()
        rings = [[(x + dx, y + dy) for x, y in r] for r in rings]
    rings = [r[::-1] if rnd.random() < 0.5 else r for r in rings]
    weighted = rnd.random() < 0.5
    ws = [[round(rnd.uniform(0.5, 3), 3) if weighted else 1 for _ in r] for r in rings]
    return kind, gap, mode, weighted, rings, ws


def write_case(path, seed):
    kind, gap, mode, weighted, rings, ws = make_case(seed)
    with open(path, "w") as f:
        f.write("# near-touch case %d: %s, gap %.3g, %s, %s\n" % (
            seed, kind, gap, mode, "weighted" if weighted else "unit weights"))
        for r, w in zip(rings, ws):
            f.write("%d\n" % len(r))
            for (x, y), wi in zip(r, w):
                f.write("%.17g %.17g %r\n" % (x, y, wi))
    return kind, weighted, [wi for w in ws for wi in w]


def check_case(path, weighted, weights, bin_path=None, cgal=True):
    """Outcome of one case: ('dropped', why), or (failures, per-check verdicts).
    verdicts: {label: 'ok' | 'unsupported' | reason} for the variants and
    'cgal' (unit weights)."""
    b = bin_path or tl.WSKEL
    rc, out, err = tl.run([b, "--check", "--format", "json", path])
    if rc == 1:
        return "dropped", err.strip()
    verdicts = {}
    if rc != 0:
        verdicts["naive"] = "exit %s: %s" % (rc, err.strip()[-160:])
        return [("naive", verdicts["naive"])], verdicts
    verdicts["naive"] = "ok"
    import json
    ref = json.loads(out)
    fails = []
    for label, variant, opts in VARIANTS:
        rc, out, err = tl.run([b, "--variant", variant, "--check", "--format", "json"] + opts + [path])
        if variant == "motorcycle" and weighted:
            v = "unsupported" if rc == 2 else "exit %s (weighted: must refuse, exit 2)" % rc
        elif rc != 0:
            v = "exit %s: %s" % (rc, err.strip()[-160:])
        else:
            same, why = tl.same_skeleton(ref, json.loads(out), weights=weights)
            v = "ok" if same else "not naive's: " + why[:200]
        verdicts[label] = v
        if v not in ("ok", "unsupported"):
            fails.append((label, v))
    if cgal and not weighted:
        with tempfile.TemporaryDirectory() as d:
            a, c = os.path.join(d, "a.json"), os.path.join(d, "c.json")
            with open(a, "w") as f:
                json.dump(ref, f)
            rc, _, err = tl.run([tl.WSKEL_CGAL, "-o", c, path])
            if rc != 0:
                v = "wskel-cgal exit %s: %s" % (rc, err.strip()[-120:])
            else:
                r = cs.compare(cs.load(a), cs.load(c))
                v = "ok" if r.identical else "naive not CGAL's: " + r.summary()[:200]
        verdicts["cgal"] = v
        if v != "ok":
            fails.append(("cgal", v))
    return fails, verdicts


# The cases fixed so far, kept in tests/data/holes (test_holes.py checks
# naive, arrangement and motorcycle there; this test adds deforming and CGAL).
FILES_DIR = os.path.join(tl.DATA, "holes")
FILES_PREFIX = "near_touch_"
# Files with a known failure: name -> the check (label) every failure of the
# file must come from; the test fails when one passes or fails otherwise.
# Empty: deforming's contacts between rings follow the engine's side rule
# now (wk_input_cut_side in its contact test and its members, issue 11).
KNOWN_FILES = {}


def file_weights(path):
    """(weighted, the weights in file order) of a .wpoly file."""
    ws, left = [], 0
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            if not line:
                continue
            if left == 0:
                left = int(line[0])
                continue
            ws.append(float(line[2]) if len(line) > 2 else 1.0)
            left -= 1
    return any(w != 1 for w in ws), ws


class NearTouch(unittest.TestCase):
    def test_files(self):
        """The fixed cases (tests/data/holes/near_touch_*.wpoly) under
        the same oracles as the generated ones; every file is required."""
        tl.need(tl.WSKEL, tl.WSKEL_CGAL)
        names = sorted(f for f in os.listdir(FILES_DIR)
                       if f.startswith(FILES_PREFIX) and f.endswith(".wpoly"))
        self.assertGreaterEqual(len(names), 4, "tests/data/holes lost its near_touch_ files")
        t = tl.Tally("near-touching rings, files")
        for name in names:
            path = os.path.join(FILES_DIR, name)
            weighted, weights = file_weights(path)
            res = check_case(path, weighted, weights)
            if res[0] == "dropped":
                t.case(["%s: the reader rejects it: %s" % (name, res[1])], path)
                continue
            fails = ["%s %s: %s" % (name, label, why) for label, why in res[0]]
            if name in KNOWN_FILES:
                if fails and all(label == KNOWN_FILES[name] for label, _ in res[0]):
                    t.skip(name, "known failures (KNOWN_FILES)")
                    continue
                fails = fails or ["%s: known failure of %s passes now: remove it from KNOWN_FILES"
                                  % (name, KNOWN_FILES[name])]
            t.case(fails, path)
        t.report(self, list_skipped=["known failures (KNOWN_FILES)"])
        self.assertEqual(t.cases + len(KNOWN_FILES), len(names), t.summary())

    def test_generated(self):
        tl.need(tl.WSKEL, tl.WSKEL_CGAL)
        t = tl.Tally("near-touching rings")
        dropped = 0
        with tempfile.TemporaryDirectory() as d:
            for seed in range(CASES):
                path = os.path.join(d, "near_touch_%d.wpoly" % seed)
                _, weighted, weights = write_case(path, seed)
                res = check_case(path, weighted, weights)
                if res[0] == "dropped":
                    dropped += 1
                    t.skip("case %d: %s" % (seed, res[1]), "dropped (the reader refuses the rounded rings)")
                    continue
                fails, _ = res
                t.case(["case %d %s: %s" % (seed, label, why) for label, why in fails], path)
        self.assertLessEqual(dropped, CASES // 3, "too many cases dropped: the generator broke")
        self.assertGreater(t.cases, 0)
        t.report(self)


def sweep(n, bin_path, cgal, keep):
    """Run n cases and print the counts per check (for the report)."""
    counts = {}
    dropped = 0
    kinds = {}
    os.makedirs(keep, exist_ok=True) if keep else None
    with tempfile.TemporaryDirectory() as d:
        for seed in range(n):
            path = os.path.join(d, "near_touch_%d.wpoly" % seed)
            kind, weighted, weights = write_case(path, seed)
            res = check_case(path, weighted, weights, bin_path, cgal)
            if res[0] == "dropped":
                dropped += 1
                continue
            fails, verdicts = res
            kinds.setdefault(kind, [0, 0])
            kinds[kind][0] += 1
            kinds[kind][1] += bool(fails)
            for label, v in verdicts.items():
                key = "ok" if v in ("ok", "unsupported") else ("not naive's" if v.startswith("not naive")
                                                             else "exit " + v.split()[1].rstrip(":")
                                                             if v.startswith("exit") else v.split(":")[0])
                counts.setdefault(label, {}).setdefault(key, 0)
                counts[label][key] += 1
            if fails and keep:
                import shutil
                shutil.copy(path, keep)
                print("case %d (%s): %s" % (seed, kind, "; ".join("%s %s" % f for f in fails))[:300])
    print("cases %d, dropped %d (reader: rings touch after rounding)" % (n, dropped))
    for kind, (m, f) in sorted(kinds.items()):
        print("  %-12s %3d compared, %3d with a failure" % (kind, m, f))
    for label in ["naive"] + [v[0] for v in VARIANTS] + ["cgal"]:
        if label in counts:
            print("  %-17s %s" % (label, ", ".join("%s %d" % kv for kv in sorted(counts[label].items()))))


if __name__ == "__main__":
    ap = argparse.ArgumentParser(add_help=False)
    ap.add_argument("--sweep", type=int)
    ap.add_argument("--bin")
    ap.add_argument("--no-cgal", action="store_true")
    ap.add_argument("--keep")
    args, rest = ap.parse_known_args()
    if args.sweep:
        sweep(args.sweep, args.bin, not args.no_cgal, args.keep)
    else:
        unittest.main(argv=[sys.argv[0]] + rest)
