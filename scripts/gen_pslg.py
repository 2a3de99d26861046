#!/usr/bin/env python3
"""gen_pslg.py: a seeded PSLG of random non-crossing unit-weight segments as
GraphML (the keys bin/wskel reads), for timing PSLG runs.

    scripts/gen_pslg.py N [--seed S] [-o FILE]

About N segments of length 2..9 in a square of side 10 sqrt(N), each at
least 0.5 from every other (far above the input's clearance bound, so every
output is accepted); a segment that would cross or come closer is redrawn,
up to 20 N draws.  Every segment is its own component: 2N terminals, so
4N reflex corners (two motorcycles per terminal).  Python's random with the
seed: the same N and seed give the same file.
"""
import argparse
import math
import random
import sys


def _orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def _dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1])


def segments(n, seed, clearance=0.5):
    """The segments [((x0, y0), (x1, y1)), ...] (a bucket grid of cell 10
    finds the candidates: segments are shorter than a cell)."""
    rng = random.Random(seed)
    side = math.sqrt(n) * 10
    cells, out = {}, []

    def cells_of(p, q):
        x0, x1 = sorted((p[0], q[0]))
        y0, y1 = sorted((p[1], q[1]))
        return [(i, j) for i in range(int(x0 // 10), int(x1 // 10) + 1)
                for j in range(int(y0 // 10), int(y1 // 10) + 1)]

    def fits(p, q):
        seen = set()
        for (ci, cj) in cells_of(p, q):
            for k in ((ci + a, cj + b) for a in (-1, 0, 1) for b in (-1, 0, 1)):
                for s in cells.get(k, ()):
                    if s in seen:
                        continue
                    seen.add(s)
                    a, b = out[s]
                    if _orient(p, q, a) * _orient(p, q, b) < 0 and _orient(a, b, p) * _orient(a, b, q) < 0:
                        return False
                    if min(_dist(p, a, b), _dist(q, a, b), _dist(a, p, q), _dist(b, p, q)) < clearance:
                        return False
        return True

    for _ in range(20 * n):
        if len(out) >= n:
            break
        p = (rng.uniform(0, side), rng.uniform(0, side))
        ang, ln = rng.uniform(0, 2 * math.pi), rng.uniform(2, 9)
        q = (p[0] + ln * math.cos(ang), p[1] + ln * math.sin(ang))
        if fits(p, q):
            for c in cells_of(p, q):
                cells.setdefault(c, []).append(len(out))
            out.append((p, q))
    return out


def graphml(segs):
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             '<graphml xmlns="http://graphml.graphdrawing.org/xmlns">',
             '<key id="x" for="node" attr.name="vertex-coordinate-x" attr.type="double"/>',
             '<key id="y" for="node" attr.name="vertex-coordinate-y" attr.type="double"/>',
             '<graph id="G" edgedefault="undirected">']
    for i, (p, q) in enumerate(segs):
        for tag, r in (("a", p), ("b", q)):
            lines.append('<node id="%s%d"><data key="x">%.17g</data><data key="y">%.17g</data></node>'
                         % (tag, i, r[0], r[1]))
    lines += ['<edge source="a%d" target="b%d"></edge>' % (i, i) for i in range(len(segs))]
    lines += ["</graph>", "</graphml>"]
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("n", type=int, help="segments (>= 1)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("-o", dest="out", help="output file (default stdout)")
    a = ap.parse_args(argv)
    if a.n < 1:
        ap.error("N must be >= 1")
    text = graphml(segments(a.n, a.seed))
    if a.out:
        with open(a.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
