#!/usr/bin/python3
"""plot_skeleton.py: the skeleton of a polygon and its offsets, drawn with
matplotlib (Agg backend) to a PNG, through the Python module (make python).

usage: /usr/bin/python3 examples/plot_skeleton.py [OUT.png]   (default skeleton.png)

The polygon: an L shape with a square hole, its top edge twice as heavy.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import wskel  # noqa: E402


def polygon():
    outer = [(0, 0), (10, 0), (10, 6), (6, 6), (6, 9), (0, 9)]
    hole = [(2, 2), (2, 4), (4, 4), (4, 2)]
    # one weight list per ring; edge 4 (the top, (6, 9) -> (0, 9)) moves twice as fast
    return outer, [hole], [[1, 1, 1, 1, 2, 1], [1, 1, 1, 1]]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "skeleton.png"
    outer, holes, weights = polygon()
    sk = wskel.skeleton(outer, holes, weights=weights)
    t_max = float(sk.nodes["t"].max())
    times = np.linspace(0, t_max, 8)[1:-1]
    offsets = wskel.offset(outer, holes, weights=weights, t=times)

    fig, ax = plt.subplots(figsize=(7, 6))
    for ring in [outer] + list(holes):
        r = np.asarray(ring + ring[:1])
        ax.plot(r[:, 0], r[:, 1], color="black", linewidth=1.5)
    cmap = plt.get_cmap("viridis")
    for t, polys in zip(times, offsets):
        for rings in polys:
            for r in rings:
                r = np.vstack([r, r[:1]])
                ax.plot(r[:, 0], r[:, 1], color=cmap(t / t_max), linewidth=0.9)
    for a in sk.arcs:
        p, q = sk.nodes[a["a"]], sk.nodes[a["b"]]
        ax.plot([p["x"], q["x"]], [p["y"], q["y"]], color="tab:red", linewidth=1.2)
    sc = ax.scatter(sk.nodes["x"][sk.n:], sk.nodes["y"][sk.n:], c=sk.nodes["t"][sk.n:],
                    cmap=cmap, vmin=0, vmax=t_max, s=18, zorder=3)
    fig.colorbar(sc, ax=ax, label="t (node time; offset curves coloured by their t)")
    ax.set_aspect("equal")
    ax.set_title("straight skeleton (red), offsets at %d times\n(%s)"
                 % (len(times), "the top edge has weight 2" if weights else "unit weights"))
    fig.savefig(out, dpi=110, bbox_inches="tight")
    print("wrote", out, "(%d nodes, %d arcs)" % (len(sk.nodes), len(sk.arcs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
