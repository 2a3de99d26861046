#!/usr/bin/python3
"""plot_offsets.py: a picture of a skeleton and its offset polygons, from
bin/wskel's GeoJSON output (a person's view of --offset).

usage: /usr/bin/python3 scripts/plot_offsets.py OFFSETS.geojson [--skeleton SKELETON.geojson]
                                                 -o OUT.png [--title TEXT]

OFFSETS.geojson is `bin/wskel --offset T1,T2,... --format geojson` output
(one MultiPolygon Feature per time; the first time is best 0, the polygon
itself); SKELETON.geojson (optional) is `bin/wskel --format geojson` output
(one LineString per arc).  Each offset is filled, darker as t grows, with
its outline, opaque and in increasing t, so the band between two offsets
has the colour of the earlier time (a contour map of the roof); holes are
cut out; the skeleton's arcs are drawn thin on top.  A colour bar gives t.
"""
import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.path import Path  # noqa: E402
from matplotlib.patches import PathPatch  # noqa: E402


def polygon_path(rings):
    """A matplotlib Path of closed rings (GeoJSON positions, closed)."""
    verts, codes = [], []
    for ring in rings:
        pts = [tuple(p[:2]) for p in ring]
        verts += pts
        codes += [Path.MOVETO] + [Path.LINETO] * (len(pts) - 2) + [Path.CLOSEPOLY]
    return Path(verts, codes)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("offsets")
    ap.add_argument("--skeleton")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--title", default="")
    a = ap.parse_args(argv)
    with open(a.offsets) as f:
        feats = json.load(f)["features"]
    if not feats:
        sys.exit("plot_offsets: no offsets in %s" % a.offsets)
    ts = [ft["properties"]["t"] for ft in feats]
    tmax = max(ts) or 1.0
    cmap = plt.get_cmap("YlGnBu")
    fig, ax = plt.subplots(figsize=(7, 6))
    for ft, t in sorted(zip(feats, ts), key=lambda x: x[1]):
        colour = cmap(t / tmax)
        for poly in ft["geometry"]["coordinates"]:
            path = polygon_path(poly)
            ax.add_patch(PathPatch(path, facecolor=colour, edgecolor="black", linewidth=0.6))
    if a.skeleton:
        with open(a.skeleton) as f:
            for arc in json.load(f)["features"]:
                (x0, y0, _), (x1, y1, _) = arc["geometry"]["coordinates"]
                ax.plot([x0, x1], [y0, y1], color="#c0392b", linewidth=0.6)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    if a.title:
        ax.set_title(a.title, fontsize=10)
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(0, tmax))
    fig.colorbar(sm, ax=ax, label="offset time t")
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1:])
