#!/usr/bin/python3
"""plot.py: figures from a wskel-bench CSV, as PNG and SVG.

    time_vs_n        time against n, log-log, one line per variant and family
                     (median over seeds and repeats, weights split into
                     panels), the log-log slope in the legend and the NNLS
                     model of fit.py as a dashed curve;
    memory_vs_n      peak tracked bytes and peak RSS against n;
    k_effect         time and peak tracked bytes against k at fixed n and r;
    k_tradeoff       time against peak tracked bytes, points labelled by k;
    events_vs_bounds switch events against n r, start events against r^2,
                     all events against n.
A figure whose data are absent (e.g. no variant with k yet) is skipped, and
said so.  Only rows with status ok are plotted; an empty counter cell (the
row's variant has no such counter) is no point, not a zero.  The model is
not refitted here: --fit reads fit.py's --json output, so the dashed curves
are exactly the fits that fit.txt and the report print.

usage: plot.py RESULTS.csv OUTDIR [--fit FIT.json]
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit  # noqa: E402  (the model's formula, fit.predict)
from results import group_by, k_order, k_value, load_csv, loglog_slope  # noqa: E402

MARKERS = {"naive": "o", "cgal": "s", "arrangement": "^"}
STYLES = {"cgal": ":"}


def save(fig, outdir, name, written):
    for ext in ("png", "svg"):
        path = os.path.join(outdir, name + "." + ext)
        fig.savefig(path, dpi=120, bbox_inches="tight")
        written.append(path)
    plt.close(fig)


def median_by(rows, keyf, valf):
    """{key: median of valf} over the rows where valf is not None."""
    groups = group_by([r for r in rows if valf(r) is not None], keyf)
    return {k: float(np.median([valf(r) for r in rs])) for k, rs in groups.items()}


def family_colors(rows):
    fams = sorted({r["family"] for r in rows})
    cmap = plt.get_cmap("tab10")
    return {f: cmap(i % 10) for i, f in enumerate(fams)}


def plot_time_vs_n(rows, outdir, written, fits):
    # One k per line: variants with a cache use their largest k (else k is empty).
    weights = sorted({r["weights"] for r in rows})
    colors = family_colors(rows)
    fig, axes = plt.subplots(1, len(weights), figsize=(7 * len(weights), 5.5), squeeze=False)
    for ax, w in zip(axes[0], weights):
        wr = [r for r in rows if r["weights"] == w]
        lines = sorted({(r["variant"], r["family"]) for r in wr})
        for var, fam in lines:
            lr = [r for r in wr if r["variant"] == var and r["family"] == fam]
            kbig = max((r["k"] for r in lr), key=k_order)
            lr = [r for r in lr if r["k"] == kbig]
            med = median_by(lr, lambda r: r["n"], lambda r: r["wall_s"])
            if len(med) < 2:
                continue
            ns = sorted(med)
            ts = [med[n] for n in ns]
            label = "%s %s (slope %.2f)" % (var, fam, loglog_slope(ns, ts))
            ax.plot(ns, ts, marker=MARKERS.get(var, "d"), linestyle=STYLES.get(var, "-"),
                    color=colors[fam], label=label, markersize=4)
            f = fits.get(var + "/" + fam + "/" + w)
            if f:
                rmed = median_by(lr, lambda r: r["n"], lambda r: r["r"])
                kmed = median_by(lr, lambda r: r["n"], k_value)
                grid = np.geomspace(ns[0], ns[-1], 40)
                rr = np.interp(grid, ns, [rmed[n] for n in ns])
                kk = np.interp(grid, ns, [kmed[n] for n in ns])
                ax.plot(grid, [fit.predict(f, n, r, k) for n, r, k in zip(grid, rr, kk)],
                        linestyle="--", linewidth=0.8, color=colors[fam], alpha=0.7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n (vertices)")
        ax.set_ylabel("construction wall time (s)")
        ax.set_title("time vs n, weights %s%s" % (w, " (dashed: NNLS model)" if fits else ""))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    save(fig, outdir, "time_vs_n", written)


def plot_memory_vs_n(rows, outdir, written):
    colors = family_colors(rows)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    for ax, col, title in ((axes[0], "peak_tracked_bytes", "peak tracked bytes (construction)"),
                           (axes[1], "peak_rss_bytes", "peak RSS of the child (wait4)")):
        for var, fam in sorted({(r["variant"], r["family"]) for r in rows}):
            lr = [r for r in rows if r["variant"] == var and r["family"] == fam]
            med = median_by(lr, lambda r: r["n"], lambda r: r[col])
            if len(med) < 2:
                continue
            ns = sorted(med)
            ax.plot(ns, [med[n] for n in ns], marker=MARKERS.get(var, "d"),
                    linestyle=STYLES.get(var, "-"), color=colors[fam], markersize=4,
                    label="%s %s (slope %.2f)" % (var, fam,
                                                   loglog_slope(ns, [med[n] for n in ns])))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n")
        ax.set_ylabel("bytes")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    save(fig, outdir, "memory_vs_n", written)


def k_groups(rows):
    """(variant, family, n, r_req, holes, weights) groups with two or more k values."""
    groups = group_by([r for r in rows if r["k"] != ""],
                      ("variant", "family", "n", "r_req", "holes", "weights"))
    out = {g: rs for g, rs in groups.items() if len({r["k"] for r in rs}) >= 2}
    # Keep one n per (variant, family, r_req, holes, weights): the one with
    # the most k values (a k sweep beats a k = 1 / max pair), then the largest n.
    best = {}
    for g in out:
        key = (g[0], g[1], g[3], g[4], g[5])
        score = (len({r["k"] for r in out[g]}), g[2])
        if key not in best or score > best[key][0]:
            best[key] = (score, g)
    best = {key: g for key, (score, g) in best.items()}
    return {g: out[g] for g in sorted(best.values())}


def k_points(rs):
    kk = sorted({r["k"] for r in rs}, key=k_order)
    t = median_by(rs, lambda r: r["k"], lambda r: r["wall_s"])
    m = median_by(rs, lambda r: r["k"], lambda r: r["peak_tracked_bytes"])
    x = [max(k_value(next(r for r in rs if r["k"] == k)), 1) for k in kk]
    return kk, x, [t.get(k) for k in kk], [m.get(k) for k in kk]


def plot_k(rows, outdir, written):
    groups = k_groups(rows)
    if not groups:
        return "k_effect, k_tradeoff: skipped (no variant with two or more k values)"
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    fig2, ax2 = plt.subplots(figsize=(7, 5.5))
    for (var, fam, n, r_req, h, w), rs in groups.items():
        kk, x, t, m = k_points(rs)
        label = "%s %s n=%d r=%s%s %s" % (var, fam, n, "default" if r_req == -1 else r_req,
                                          " holes=%d" % h if h else "", w)
        axes[0].plot(x, t, marker="o", label=label)
        axes[1].plot(x, m, marker="o", label=label)
        ax2.plot(m, t, marker="o", label=label)
        for k, mi, ti in zip(kk, m, t):
            if mi is not None and ti is not None:
                ax2.annotate("k=%s" % k, (mi, ti), fontsize=7, textcoords="offset points",
                             xytext=(3, 3))
    for ax, yl in ((axes[0], "construction wall time (s)"), (axes[1], "peak tracked bytes")):
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("k (cache size; max plotted at r)")
        ax.set_ylabel(yl)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_title("time vs k at fixed n, r")
    axes[1].set_title("peak memory vs k at fixed n, r")
    save(fig, outdir, "k_effect", written)
    ax2.set_xscale("log")
    ax2.set_yscale("log")
    ax2.set_xlabel("peak tracked bytes")
    ax2.set_ylabel("construction wall time (s)")
    ax2.set_title("time / memory tradeoff (labels: k)")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=7)
    save(fig2, outdir, "k_tradeoff", written)
    return None


EVENT_COLS = ("edge_events", "split_events", "multi_split_events", "switch_events",
              "start_events")


def event_value(r, col):
    """A row's count for a panel, None where the variant has no such counter
    (an empty cell, or a column this CSV does not have)."""
    if col != "all events":
        return r.get(col)
    vals = [r.get(c) for c in EVENT_COLS if r.get(c) is not None]
    return sum(vals) if vals else None


def plot_events(rows, outdir, written):
    rs = [r for r in rows if any(r.get(c) is not None for c in EVENT_COLS)]
    if not rs:
        return "events_vs_bounds: skipped (no event counters)"
    panels = [("switch_events", lambda r: r["n"] * max(r["r"], 1), "n r"),
              ("start_events", lambda r: max(r["r"], 1) ** 2, "r^2"),
              ("all events", lambda r: r["n"], "n")]
    colors = family_colors(rs)
    fig, axes = plt.subplots(1, 3, figsize=(18, 5))
    drawn = 0
    for ax, (col, bound, bname) in zip(axes, panels):
        for var, fam in sorted({(r["variant"], r["family"]) for r in rs}):
            pts = [(bound(r), event_value(r, col)) for r in rs
                   if r["variant"] == var and r["family"] == fam]
            # Absent counters are no points; zeros have no place on a log axis.
            pts = [(b, v) for b, v in pts if v is not None and v > 0]
            if not pts:
                continue
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=12, color=colors[fam],
                       marker=MARKERS.get(var, "d"), label="%s %s" % (var, fam))
        if ax.collections:
            drawn += 1
            lo = min(min(c.get_offsets()[:, 0]) for c in ax.collections)
            hi = max(max(c.get_offsets()[:, 0]) for c in ax.collections)
            ax.plot([lo, hi], [lo, hi], "k--", linewidth=0.8, label="= bound")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.legend(fontsize=7)
        else:
            ax.text(0.5, 0.5, "no %s recorded\n(zero or absent in every run)" % col,
                    ha="center", va="center", transform=ax.transAxes)
        ax.set_xlabel(bname)
        ax.set_ylabel(col)
        ax.set_title("%s vs %s" % (col, bname))
        ax.grid(True, which="both", alpha=0.3)
    if drawn == 0:
        plt.close(fig)
        return "events_vs_bounds: skipped (all event counters zero or absent)"
    save(fig, outdir, "events_vs_bounds", written)
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("outdir")
    ap.add_argument("--fit", help="fit.py --json output: draw its model as dashed curves")
    args = ap.parse_args()
    _, rows = load_csv(args.csv)
    fits, notes = {}, []
    if args.fit:
        with open(args.fit) as f:
            fits = json.load(f)
    else:
        notes.append("time_vs_n: no --fit FIT.json, so no model curves")
    os.makedirs(args.outdir, exist_ok=True)
    ok = [r for r in rows if r["status"] == "ok" and r["wall_s"] is not None and r["wall_s"] > 0]
    written = []
    if not ok:
        print("plot.py: no ok rows, nothing to plot")
        return 0
    plot_time_vs_n(ok, args.outdir, written, fits)
    plot_memory_vs_n(ok, args.outdir, written)
    for f in (plot_k, plot_events):
        note = f(ok, args.outdir, written)
        if note:
            notes.append(note)
    for w in written:
        print("wrote", w)
    for n in notes:
        print(n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
