#!/usr/bin/python3
"""cross_far_vertex_sweep.py: monotone against naive on crosses, plus, L and
T shapes with one vertex moved far away (issue 11's fuzz finding: a 12-gon
cross with vertex 8 at x = -3e5,
tests/data/fuzz/mismatch_monotone_cross_far_vertex.wpoly).

Each case (seeded by its number): a shape of integer coordinates (a cross
with arms of random lengths and widths, a plus with equal arms, an L, a T),
sometimes with one or two vertices jittered by a few units (as the fuzzer
mutates them), turned by a random angle (a quarter of the cases not turned,
so their walls stay exactly perpendicular), then one vertex moved a
distance D in 1e3..1e8 (log-uniform) along an arm's axis or in a random
direction, or a new vertex D away inserted before it; a quarter of the
cases get random integer weights 1..3.  Inputs naive refuses (exit 1: not
simple) are skipped.  Each case runs naive and `--variant monotone --check
--stats` and is counted as ok, fallback (reference_fallbacks > 0: a right
skeleton at the reference's cost), unsupported (exit 2, monotone in no
direction), mismatch (valid but not naive's skeleton, testlib.same_skeleton),
fail (exit 2 or 3 otherwise) or timeout.

  cross_far_vertex_sweep.py [--wskel BIN] [--cases N] [--first K] [--seconds S]
                            [--list-bad] [--keep DIR]

Prints the counts per shape and outcome; with --list-bad every mismatch,
fail and timeout.  Not part of `make test` (a survey; its counts are in
variants/monotone/README.md).
"""

import argparse
import math
import os
import random
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import testlib as tl  # noqa: E402

SHAPES = ("cross", "plus", "L", "T")


def shape(kind, rng):
    """Counter-clockwise integer polygon and the unit axes of its arms."""
    if kind in ("cross", "plus"):
        a = rng.randint(1, 3) if kind == "cross" else 1
        b = rng.randint(1, 3) if kind == "cross" else a
        arms = [rng.randint(1, 10) for _ in range(4)]
        if kind == "plus":
            arms = [arms[0]] * 4
        e, nn, w, s = (a + arms[0], b + arms[1], a + arms[2], b + arms[3])
        pts = [(a, -b), (e, -b), (e, b), (a, b), (a, nn), (-a, nn), (-a, b), (-w, b),
               (-w, -b), (-a, -b), (-a, -s), (a, -s)]
        return pts, [(1, 0), (0, 1), (-1, 0), (0, -1)]
    if kind == "L":
        w, h = rng.randint(1, 4), rng.randint(1, 4)
        l1, l2 = w + rng.randint(1, 10), h + rng.randint(1, 10)
        return [(0, 0), (l1, 0), (l1, h), (w, h), (w, l2), (0, l2)], [(1, 0), (0, 1)]
    # T: a stem of width 2 s up to y = h, a bar of half width B and height t on top
    s, h = rng.randint(1, 3), rng.randint(1, 10)
    bar, t = s + rng.randint(1, 10), rng.randint(1, 4)
    pts = [(-s, 0), (s, 0), (s, h), (bar, h), (bar, h + t), (-bar, h + t), (-bar, h), (-s, h)]
    return pts, [(0, -1), (1, 0), (-1, 0), (0, 1)]


def make_case(i):
    rng = random.Random(i)
    kind = SHAPES[i % len(SHAPES)]
    pts, axes = shape(kind, rng)
    pts = [list(p) for p in pts]
    for _ in range(rng.choice((0, 0, 1, 2))):
        p = rng.choice(pts)
        p[0] += rng.randint(-3, 3)
        p[1] += rng.randint(-3, 3)
    k = rng.randrange(len(pts))
    d = 10 ** rng.uniform(3, 8)
    if rng.random() < 0.6:
        u = rng.choice(axes)
    else:
        a = rng.uniform(0, 2 * math.pi)
        u = (math.cos(a), math.sin(a))
    if rng.random() < 0.5:
        d = float(round(d))  # integer distances, as the fuzzer writes them
    far = (pts[k][0] + d * u[0], pts[k][1] + d * u[1])
    mode = rng.choice(("move", "spike"))
    if mode == "move":
        pts[k] = list(far)
    else:
        pts.insert(k, list(far))
    if rng.random() < 0.75:
        th = rng.uniform(0, 2 * math.pi)
        c, sn = math.cos(th), math.sin(th)
        pts = [[c * x - sn * y, sn * x + c * y] for x, y in pts]
    else:
        th = 0.0
    ws = [float(rng.randint(1, 3)) for _ in pts] if rng.random() < 0.25 else None
    name = "%s-%d-%s-v%d-%.3g-th%.3f%s" % (kind, i, mode, k, d, th, "-w" if ws else "")
    return kind, name, [tuple(p) for p in pts], ws


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--wskel", default=tl.WSKEL)
    ap.add_argument("--cases", type=int, default=2000)
    ap.add_argument("--first", type=int, default=1)
    ap.add_argument("--seconds", type=float, default=0, help="stop after this much wall time")
    ap.add_argument("--list-bad", action="store_true")
    ap.add_argument("--keep", help="copy the inputs that are mismatch, fail or timeout here")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="wskel-cross-")
    counts, bad, total, t_start = {}, [], 0, time.time()
    for i in range(a.first, a.first + a.cases):
        if a.seconds and time.time() - t_start > a.seconds:
            break
        kind, name, pts, ws = make_case(i)
        path = tl.write_wpoly(os.path.join(tmp, "case.wpoly"), pts, ws,
                              comment="cross_far_vertex_sweep.py: case %d, %s" % (i, name))
        rc, out_n, _ = tl.run([a.wskel, "--check", path])
        if rc != 0:
            key = "naive exit %s" % rc
        else:
            total += 1
            key = tl.variant_outcome(a.wskel, "monotone", path, out_n,
                                     refused="not monotone in any direction")
            if key not in ("ok", "fallback", "unsupported"):
                bad.append((name, key))
                if a.keep:
                    os.makedirs(a.keep, exist_ok=True)
                    os.replace(path, os.path.join(a.keep, name + ".wpoly"))
        counts.setdefault(kind, {}).setdefault(key, 0)
        counts[kind][key] += 1
    tl.sweep_report("compared %d cases (naive ran), cases %d..%d" % (total, a.first, i),
                         SHAPES, counts, 6, bad, a.list_bad)
    return 0 if total > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
