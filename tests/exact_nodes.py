#!/usr/bin/python3
"""Exact check of a skeleton's nodes: every node where exactly three faces
meet must be where the three faces' offset lines meet, w_i t = signed
distance to edge i, solved in 80-digit decimal arithmetic.

    /usr/bin/python3 tests/exact_nodes.py POLY.wpoly SKEL.json [--tol REL]

Prints each such node's distance from the exact point (in units of the
polygon's diagonal) and exits 1 if one is farther than REL (default 1e-9,
eps_d).  Nodes of four or more faces (simultaneous events) and nodes whose
three lines are nearly dependent (|det| < 1e-9) are not checked.  The
lines are built from the file's coordinates as read (Decimal of the text),
one ring (.wpoly with an optional weight per vertex, '#' comments).  Used
by tests/test_exact_nodes.py; by hand on a mismatch between variants to
tell which one is right.
"""
import json
import sys
from decimal import Decimal, getcontext

getcontext().prec = 80


def read_wpoly(path):
    rows = []
    for raw in open(path):
        line = raw.split("#", 1)[0].strip()
        if line:
            rows.append(line.split())
    n = int(rows[0][0])
    pts = []
    for f in rows[1:1 + n]:
        x, y = Decimal(float.fromhex(f[0]) if "0x" in f[0] else f[0]), \
            Decimal(float.fromhex(f[1]) if "0x" in f[1] else f[1])
        w = Decimal(f[2]) if len(f) > 2 else Decimal(1)
        pts.append((x, y, w))
    area = sum(pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1] for i in range(n))
    return pts, area < 0


def offset_line(pts, i, cw):
    """(nx, ny, w, c): n . p - c = w t on edge i's offset line (n inward)."""
    n = len(pts)
    ax, ay, w = pts[i]
    bx, by, _ = pts[(i + 1) % n]
    dx, dy = bx - ax, by - ay
    ln = (dx * dx + dy * dy).sqrt()
    nx, ny = -dy / ln, dx / ln
    if cw:
        nx, ny = -nx, -ny
    return nx, ny, w, nx * ax + ny * ay


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def meet(pts, cw, edges):
    """(x, y, t) where the offset lines of the three edges meet, or None."""
    rows = [offset_line(pts, e, cw) for e in edges]
    m = [[r[0], r[1], -r[2]] for r in rows]
    rhs = [r[3] for r in rows]
    d = det3(m)
    if abs(d) < Decimal("1e-9") * sum(r[2] for r in rows):
        return None
    out = []
    for k in range(3):
        mk = [row[:] for row in m]
        for i in range(3):
            mk[i][k] = rhs[i]
        out.append(det3(mk) / d)
    return out


def check(poly, skel, tol):
    pts, cw = read_wpoly(poly)
    sk = json.load(open(skel))
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    diag = ((max(xs) - min(xs)) ** 2 + (max(ys) - min(ys)) ** 2).sqrt()
    wmax = max(p[2] for p in pts)
    faces = {}
    for a, b, left, right in sk["arcs"]:
        for v in (a, b):
            faces.setdefault(v, set()).update((left, right))
    worst, bad, checked = 0.0, [], 0
    for i, (x, y, t) in enumerate(sk["nodes"]):
        if i < len(pts) or len(faces.get(i, ())) != 3:
            continue
        q = meet(pts, cw, sorted(faces[i]))
        if q is None:
            continue
        checked += 1
        err = max(abs(Decimal(x) - q[0]), abs(Decimal(y) - q[1]), abs(Decimal(t) - q[2]) * wmax) / diag
        worst = max(worst, float(err))
        if err > tol:
            bad.append((i, sorted(faces[i]), (x, y, t), [float(v) for v in q], float(err)))
    return checked, worst, bad


def main(argv):
    tol = 1e-9
    if "--tol" in argv:
        k = argv.index("--tol")
        tol = float(argv[k + 1])
        del argv[k:k + 2]
    checked, worst, bad = check(argv[1], argv[2], Decimal(tol))
    for i, f, got, want, err in bad:
        print(f"node {i} faces {f}: at {got}, exact {want}: {err:.3g} diagonals off")
    print(f"{argv[2]}: {checked} three-face nodes checked, worst {worst:.3g} diagonals off (tol {tol:g})")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
