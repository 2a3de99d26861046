#!/usr/bin/python3
"""cap_faces.py: check the cap faces of a PSLG roof (OBJ or VTP) against
the skeleton's own cap (issues 13/14, tests/cli_tests.sh).

    cap_faces.py ROOF.obj|ROOF.vtp SKEL.json [--area A] [--out x,y ...] [--in x,y ...]

The roof's cap faces are its faces whose every vertex is at the horizon
t = T (an edge's face has its corners at t = 0).  Checks, each printed as
"FAIL ..." (exit 1) or all together as "ok ..." (exit 0):
  * the cap faces' total signed area equals the area the skeleton's own cap
    bounds: its cap arcs (left -1, walked a -> b with the unswept side on
    the left) form cycles; the counter-clockwise ones count positive, a
    clockwise one negative when it lies inside a counter-clockwise one (a
    component's wavefront inside a face still alive at T: the face's hole)
    and not at all otherwise (the rim of the unbounded face);
  * --area A: that area is also A (within 1e-9 relative; a figure from
    the geometry, e.g. the shrunk square minus the segment's wavefront);
  * --out x,y: no cap face covers the point (winding number 0 summed over
    the cap faces; a point on a segment, which the cap must leave open);
  * --in x,y: the cap faces cover the point exactly once.
"""
import json
import sys
import xml.etree.ElementTree as ET


def read_obj(path):
    verts, faces = [], []
    for line in open(path):
        if line.startswith("v "):
            verts.append(tuple(float(x) for x in line.split()[1:4]))
        elif line.startswith("f "):
            faces.append([int(x) - 1 for x in line.split()[1:]])
    return verts, faces


def read_vtp(path):
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    nums = piece.find("Points/DataArray").text.split()
    verts = [tuple(float(x) for x in nums[i : i + 3]) for i in range(0, len(nums), 3)]
    arrays = {a.get("Name"): [int(x) for x in a.text.split()] for a in piece.find("Polys")}
    faces, start = [], 0
    for end in arrays["offsets"]:
        faces.append(arrays["connectivity"][start:end])
        start = end
    return verts, faces


def signed_area(pts):
    return 0.5 * sum(pts[i - 1][0] * p[1] - p[0] * pts[i - 1][1] for i, p in enumerate(pts))


def winding(pts, x, y):
    """Winding number of the closed polyline pts around (x, y)."""
    w = 0
    for i, b in enumerate(pts):
        a = pts[i - 1]
        side = (b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])
        if a[1] <= y < b[1] and side > 0:
            w += 1
        elif b[1] <= y < a[1] and side < 0:
            w -= 1
    return w


def skeleton_cap_area(skel):
    nodes = skel["nodes"]
    succ = {a: b for a, b, left, right in skel["arcs"] if left == -1}
    cycles, seen = [], set()
    for s in succ:
        if s in seen:
            continue
        cyc, v = [], s
        while v not in seen:
            seen.add(v)
            cyc.append(nodes[v][:2])
            v = succ[v]
        cycles.append(cyc)
    ccw = [c for c in cycles if signed_area(c) > 0]
    total = sum(signed_area(c) for c in ccw)
    for c in cycles:
        if signed_area(c) < 0 and any(winding(o, *c[0]) for o in ccw):
            total += signed_area(c)
    return total, len(cycles)


def main(argv):
    roof, skel_path, rest = argv[0], argv[1], argv[2:]
    skel = json.load(open(skel_path))
    T = skel["pslg"]["horizon"]
    verts, faces = (read_vtp if roof.endswith(".vtp") else read_obj)(roof)
    caps = [[verts[i][:2] for i in f] for f in faces if all(verts[i][2] == T for i in f)]
    errors = []
    if not caps:
        errors.append("no cap face")
    got = sum(signed_area(c) for c in caps)
    want, n_cycles = skeleton_cap_area(skel)
    if abs(got - want) > 1e-9 * max(1.0, abs(want)):
        errors.append(f"cap faces' area {got!r}, the skeleton's cap bounds {want!r}")
    i = 0
    while i < len(rest):
        opt, val = rest[i], rest[i + 1]
        i += 2
        if opt == "--area":
            if abs(want - float(val)) > 1e-9 * max(1.0, abs(float(val))):
                errors.append(f"the skeleton's cap bounds {want!r}, not {val}")
            continue
        x, y = (float(t) for t in val.split(","))
        w = sum(winding(c, x, y) for c in caps)
        if opt == "--out" and w != 0:
            errors.append(f"({x}, {y}) is covered by the cap (winding {w})")
        if opt == "--in" and w != 1:
            errors.append(f"({x}, {y}) is not covered once by the cap (winding {w})")
    for e in errors:
        print("FAIL", roof, e)
    if not errors:
        print(f"ok {roof}: {len(caps)} cap faces of area {got!r} = the skeleton's cap "
              f"({n_cycles} cycles)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
