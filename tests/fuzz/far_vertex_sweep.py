#!/usr/bin/python3
"""far_vertex_sweep.py: motorcycle against naive on polygons with one vertex
far away (issue 13's cut storm: a monotone 48-gon with a vertex pulled to
y = -1.8e12, tests/data/fuzz/ealgo_motorcycle_cut_storm.wpoly).

For every family (monotone, star, random), n, seed and distance D, a
wskel-gen polygon (unit weights) gets one vertex k (k from the seed) either
moved D away ("move") or a new vertex D away inserted before it ("spike",
the fuzz finding's shape): straight down or up for monotone (away from the
chain's side of the centroid, which keeps it x-monotone), radially from the
centroid for the others.  Inputs naive refuses (exit 1: not simple) are
skipped.  Each case runs naive and `--variant motorcycle --check --stats`
and is counted as ok, fallback (reference_fallbacks > 0), mismatch (valid
but not naive's skeleton, testlib.same_skeleton), fail (exit 2 or 3, with
the reference not answering) or timeout.

  far_vertex_sweep.py [--wskel BIN] [--seeds S] [--list-bad] [--keep DIR]

Prints the counts per family and outcome; with --list-bad every case that is
not ok.  Not part of `make test` (a survey; its counts are in
variants/motorcycle/README.md).
"""

import argparse
import os
import random
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import testlib as tl  # noqa: E402

FAMILIES = ("monotone", "star", "random")
NS = (16, 24, 32, 48, 64)
DISTANCES = (1e8, 1e9, 1e10, 1e11, 1e12, 1e13)
MODES = ("move", "spike")


def far_point(fam, pts, k, d):
    cx = sum(p[0] for p in pts) / len(pts)
    cy = sum(p[1] for p in pts) / len(pts)
    x, y = pts[k]
    if fam == "monotone":
        return (x, y - d) if y <= cy else (x, y + d)
    dx, dy = x - cx, y - cy
    h = (dx * dx + dy * dy) ** 0.5 or 1.0
    return (x + d * dx / h, y + d * dy / h)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--wskel", default=tl.WSKEL)
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--list-bad", action="store_true")
    ap.add_argument("--keep", help="copy the inputs that are not ok into this directory")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="wskel-far-")
    counts, bad, total = {}, [], 0
    for fam in FAMILIES:
        for n in NS:
            for seed in range(1, a.seeds + 1):
                src = os.path.join(tmp, "src.wpoly")
                rc, _, _ = tl.run([tl.WSKEL_GEN, fam, "--n", str(n), "--seed", str(seed),
                                   "--weights", "unit", "-o", src])
                if rc != 0:
                    continue
                pts, _ = tl.read_wpoly(src)
                k = random.Random(seed * 1000 + n).randrange(len(pts))
                for d in DISTANCES:
                    for mode in MODES:
                        q = far_point(fam, pts, k, d)
                        new = list(pts)
                        if mode == "move":
                            new[k] = q
                        else:
                            new.insert(k, q)
                        name = "%s-n%d-s%d-%s-%g" % (fam, n, seed, mode, d)
                        path = tl.write_wpoly(os.path.join(tmp, name + ".wpoly"), new,
                                              comment="far_vertex_sweep.py: %s (vertex %d)"
                                              % (name, k))
                        rc, out_n, _ = tl.run([a.wskel, "--check", path])
                        if rc != 0:
                            key = "naive exit %s" % rc
                        else:
                            total += 1
                            key = tl.variant_outcome(a.wskel, "motorcycle", path, out_n)
                            if key != "ok":
                                bad.append((name, key))
                                if a.keep:
                                    os.makedirs(a.keep, exist_ok=True)
                                    os.replace(path, os.path.join(a.keep, name + ".wpoly"))
                        counts.setdefault(fam, {}).setdefault(key, 0)
                        counts[fam][key] += 1
                        if os.path.exists(path):
                            os.remove(path)
    tl.sweep_report("compared %d cases (naive ran)" % total, FAMILIES, counts, 9, bad,
                         a.list_bad)
    return 0 if total > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
