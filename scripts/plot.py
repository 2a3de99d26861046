"""plot.py: figures from a wskel-bench CSV, as PNG and SVG.

Every figure is small multiples: one panel per family (and weight mode, or
per variant for the event counts), at most MAX_LINES data series per panel
(a group with more is split over several panels), each variant in the same
colour in every panel, the legend outside the panel so it covers no data.

    time_vs_n        time against n, log-log, one panel per family and
                     weight mode, one line per variant (median over seeds
                     and repeats; variants with a cache at their largest k),
                     the log-log slope in the legend and the NNLS model of
                     fit.py dashed beside its data, in the data's colour;
                     a variant with a timed phase (the motorcycle variant's
                     M(P)) also gets the phase's time, dash-dotted in its
                     colour, with its median share of the time in the
                     legend (phase_s of the CSV's JSON-lines twin, when it
                     is there and has it);
    phase_share      a timed phase's share of the construction time
                     (phase_s / wall_s: the motorcycle variant's M(P))
                     against n, log n by linear percent, one panel per
                     variant with a phase, one line per family and weight
                     mode (median over seeds and repeats);
    memory_vs_n      peak tracked bytes (solid) and peak RSS (dotted)
                     against n, the same panels;
    k_effect         per family: time against k (top) and peak tracked
                     bytes against k (bottom) at fixed n and r;
    k_tradeoff       per family: time against peak tracked bytes, points
                     labelled by k;
    events_vs_bounds switch events against n r, start events against r^2,
                     all events against n: one row per count, one column
                     per variant, one colour per family.
A figure whose data are absent (e.g. no variant with k yet) is skipped, and
said so.  Only rows with status ok are plotted; an empty counter cell (the
row's variant has no such counter) is no point, not a zero.  The model is
not refitted here: --fit reads fit.py's --json output, so the dashed curves
are exactly the fits that fit.txt and the report print.

usage: plot.py RESULTS.csv OUTDIR [--fit FIT.json]
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit  # noqa: E402  (the model's formula, fit.predict)
from results import config_key, group_by, k_order, k_value, load_csv, loglog_slope  # noqa: E402

MAX_LINES = 6       # data series per panel: more are not told apart at a glance
NCOLS = 3           # panels per figure row
PANEL = (4.4, 3.3)  # inches per panel (its data area and labels)
LEGEND_W = 2.3      # inches beside each panel for its legend
MARKERS = {"naive": "o", "cgal": "s", "arrangement": "^", "monotone": "v", "motorcycle": "D",
           "deforming": "P"}
STYLES = {"cgal": ":"}
VARIANT_ORDER = ["naive", "monotone", "arrangement", "motorcycle", "deforming", "cgal"]


def save(fig, outdir, name, written):
    for ext in ("png", "svg"):
        path = os.path.join(outdir, name + "." + ext)
        fig.savefig(path, dpi=110, bbox_inches="tight")
        written.append(path)
    plt.close(fig)


def median_by(rows, keyf, valf):
    """{key: median of valf} over the rows where valf is not None."""
    groups = group_by([r for r in rows if valf(r) is not None], keyf)
    return {k: float(np.median([valf(r) for r in rs])) for k, rs in groups.items()}


def variant_key(v):
    return (VARIANT_ORDER.index(v) if v in VARIANT_ORDER else len(VARIANT_ORDER), v)


def variant_colors(rows):
    """One colour per variant, the same in every panel and figure."""
    cmap = plt.get_cmap("tab10")
    names = sorted({r["variant"] for r in rows} | set(VARIANT_ORDER), key=variant_key)
    return {v: cmap(i % 10) for i, v in enumerate(names)}


def family_colors(rows):
    fams = sorted({r["family"] for r in rows})
    cmap = plt.get_cmap("tab10")
    return {f: cmap(i % 10) for i, f in enumerate(fams)}


def split(items, size=MAX_LINES):
    """items in consecutive chunks of at most size (one chunk per panel)."""
    return [items[i:i + size] for i in range(0, len(items), size)] or [[]]


def panels(n, ncols=NCOLS, rows_per=1, panel=PANEL):
    """A figure with n panel slots (rows_per stacked axes per slot), laid out
    ncols slots wide; unused axes are hidden.  Returns (fig, [slot axes]),
    each slot a list of rows_per axes."""
    ncols = max(1, min(ncols, n))
    nrows = math.ceil(n / ncols)
    fig, axes = plt.subplots(nrows * rows_per, ncols, squeeze=False, constrained_layout=True,
                             figsize=(ncols * (panel[0] + LEGEND_W), nrows * rows_per * panel[1]))
    slots = []
    for i in range(nrows * ncols):
        r, c = divmod(i, ncols)
        axs = [axes[r * rows_per + j][c] for j in range(rows_per)]
        if i < n:
            slots.append(axs)
        else:
            for ax in axs:
                ax.set_visible(False)
    return fig, slots


def legend_beside(ax, extra=()):
    """The axes' legend to its right, outside the data area."""
    handles, labels = ax.get_legend_handles_labels()
    for h in extra:
        handles.append(h)
        labels.append(h.get_label())
    if handles:
        ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=7,
                  frameon=False, borderaxespad=0.0)


def plain_ticks(axis):
    """Ticks at 1, 2, 5 times powers of ten, written as plain numbers (n
    from 200 to 3000 otherwise shows only the label 10^3)."""
    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: "%g" % v))
    axis.set_minor_formatter(NullFormatter())


def loglog(ax, xlabel, ylabel):
    ax.set_xscale("log")
    ax.set_yscale("log")
    if xlabel in ("n", "n (vertices)"):
        plain_ticks(ax.xaxis)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_ylabel(ylabel, fontsize=8)
    ax.tick_params(labelsize=7)
    ax.grid(True, which="both", alpha=0.3)


def largest_k(rows):
    """The rows of the largest k (all rows when the variant has none)."""
    kbig = max((r["k"] for r in rows), key=k_order)
    return [r for r in rows if r["k"] == kbig]


def family_panels(rows):
    """[(family, weights)] in order: the time and memory panels."""
    return sorted({(r["family"], r["weights"]) for r in rows})


def panel_slots(rows, keys, series_of):
    """One slot per chunk of at most MAX_LINES series of each key: [(key,
    title suffix, series)]."""
    out = []
    for key in keys:
        chunks = split(series_of(key))
        for i, ch in enumerate(chunks):
            out.append((key, " (%d/%d)" % (i + 1, len(chunks)) if len(chunks) > 1 else "", ch))
    return out


def attach_phases(csv_path, rows):
    """Set r["phase"], r["phase_s"] from the JSON-lines twin of the CSV
    (wskel-bench writes the timed phase there only); None where absent.
    Returns how many rows got a phase time."""
    for r in rows:
        r["phase"] = r["phase_s"] = None
    twin = (csv_path[:-4] if csv_path.endswith(".csv") else csv_path) + ".jsonl"
    if not os.path.exists(twin):
        return 0
    got = {}
    with open(twin) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            try:
                j = json.loads(line)
            except ValueError:
                continue  # a partial last line of an interrupted sweep
            if j.get("phase_s") is not None:
                got[config_key(j)] = (j["phase"], float(j["phase_s"]))
    n = 0
    for r in rows:
        ph = got.get(config_key(r))
        if ph:
            r["phase"], r["phase_s"] = ph
            n += 1
    return n


def plot_time_vs_n(rows, outdir, written, fits):
    colors = variant_colors(rows)
    by = group_by(rows, ("family", "weights", "variant"))

    def series(key):
        return sorted({v for (f, w, v) in by if (f, w) == key}, key=variant_key)
    slots = panel_slots(rows, family_panels(rows), series)
    fig, axes = panels(len(slots))
    for (key, suffix, variants), (ax,) in zip(slots, axes):
        fam, w = key
        dashed = False
        for var in variants:
            lr = largest_k(by[(fam, w, var)])
            med = median_by(lr, lambda r: r["n"], lambda r: r["wall_s"])
            if not med:
                continue
            ns = sorted(med)
            ts = [med[n] for n in ns]
            slope = loglog_slope(ns, ts) if len(ns) >= 2 else float("nan")
            k = lr[0]["k"]
            label = "%s%s (slope %.2f)" % (var, " k=%s" % k if k != "" else "", slope)
            ax.plot(ns, ts, marker=MARKERS.get(var, "d"), linestyle=STYLES.get(var, "-"),
                    color=colors[var], label=label, markersize=4)
            pr = [r for r in lr if r.get("phase_s") is not None]
            pmed = median_by(pr, lambda r: r["n"], lambda r: r["phase_s"])
            if pmed:
                pns = sorted(pmed)
                share = median_by(pr, lambda r: r["n"], lambda r: r["phase_s"] / r["wall_s"])
                shares = [share[n] for n in pns]
                ax.plot(pns, [pmed[n] for n in pns], linestyle="-.", linewidth=1.0,
                        color=colors[var], label="%s: %s (%.0f..%.0f%% of it)" % (
                            var, pr[0]["phase"], 100 * min(shares), 100 * max(shares)))
            f = fits.get(var + "/" + fam + "/" + w)
            if f and len(ns) >= 2:
                rmed = median_by(lr, lambda r: r["n"], lambda r: r["r"])
                kmed = median_by(lr, lambda r: r["n"], k_value)
                grid = np.geomspace(ns[0], ns[-1], 40)
                rr = np.interp(grid, ns, [rmed[n] for n in ns])
                kk = np.interp(grid, ns, [kmed[n] for n in ns])
                ax.plot(grid, [fit.predict(f, n, r, k) for n, r, k in zip(grid, rr, kk)],
                        linestyle="--", linewidth=1.0, color=colors[var], alpha=0.8)
                dashed = True
        loglog(ax, "n (vertices)", "construction time (s)")
        ax.set_title("%s, weights %s%s" % (fam, w, suffix), fontsize=9)
        legend_beside(ax, [Line2D([], [], color="gray", linestyle="--",
                                  label="fit.py model (dashed)")] if dashed else [])
    fig.suptitle("Construction time against n, one panel per family (median over seeds)",
                 fontsize=11)
    save(fig, outdir, "time_vs_n", written)


def phase_shares(rows):
    """{(variant, phase): {(family, weights): {n: (median share, median
    phase_s, median wall_s)}}} over the rows with a phase time (largest k
    per variant, as time_vs_n).  Shared with report.py's table."""
    out = {}
    with_phase = [r for r in rows if r.get("phase_s") is not None and r["wall_s"]]
    for (var, fam, w), rs in sorted(group_by(with_phase, ("variant", "family", "weights")).items()):
        lr = largest_k(rs)
        share = median_by(lr, lambda r: r["n"], lambda r: r["phase_s"] / r["wall_s"])
        ph = median_by(lr, lambda r: r["n"], lambda r: r["phase_s"])
        wall = median_by(lr, lambda r: r["n"], lambda r: r["wall_s"])
        out.setdefault((var, lr[0]["phase"]), {})[(fam, w)] = {
            n: (share[n], ph[n], wall[n]) for n in sorted(share)}
    return out


def plot_phase_share(rows, outdir, written):
    shares = phase_shares(rows)
    if not shares:
        return "phase_share: skipped (no phase times)"
    colors = family_colors(rows)
    slots = [(key, ch) for key in sorted(shares) for ch in split(sorted(shares[key]))]
    fig, axes = panels(len(slots))
    for ((var, phase), series), (ax,) in zip(slots, axes):
        for fam, w in series:
            pts = shares[(var, phase)][(fam, w)]
            ns = sorted(pts)
            ax.plot(ns, [100 * pts[n][0] for n in ns], marker=MARKERS.get(var, "d"),
                    color=colors[fam], markersize=4,
                    label="%s, %s (%.0f..%.0f%%)" % (fam, w, 100 * min(p[0] for p in pts.values()),
                                                      100 * max(p[0] for p in pts.values())))
        ax.set_xscale("log")
        plain_ticks(ax.xaxis)
        ax.set_ylim(0, 100)
        ax.set_xlabel("n (vertices)", fontsize=8)
        ax.set_ylabel("%s time / construction time (%%)" % phase, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title("%s: share of %s" % (var, phase), fontsize=9)
        legend_beside(ax)
    fig.suptitle("A variant's timed phase as a share of its construction time against n "
                 "(median over seeds)", fontsize=11)
    save(fig, outdir, "phase_share", written)
    return None


def plot_memory_vs_n(rows, outdir, written):
    colors = variant_colors(rows)
    by = group_by(rows, ("family", "weights", "variant"))
    cols = (("peak_tracked_bytes", "-", "tracked"), ("peak_rss_bytes", ":", "RSS"))

    def series(key):
        out = []
        for v in sorted({v for (f, w, v) in by if (f, w) == key}, key=variant_key):
            for col, style, what in cols:
                if any(r[col] for r in by[key + (v,)]):
                    out.append((v, col, style, what))
        return out
    slots = panel_slots(rows, family_panels(rows), series)
    fig, axes = panels(len(slots))
    for (key, suffix, ser), (ax,) in zip(slots, axes):
        for var, col, style, what in ser:
            lr = largest_k(by[key + (var,)])
            med = median_by(lr, lambda r: r["n"], lambda r: r[col] or None)
            if not med:
                continue
            ns = sorted(med)
            ys = [med[n] for n in ns]
            slope = loglog_slope(ns, ys) if len(ns) >= 2 else float("nan")
            ax.plot(ns, ys, marker=MARKERS.get(var, "d"), linestyle=style, color=colors[var],
                    markersize=4, label="%s %s (slope %.2f)" % (var, what, slope))
        loglog(ax, "n (vertices)", "bytes")
        ax.set_title("%s, weights %s%s" % (key[0], key[1], suffix), fontsize=9)
        legend_beside(ax)
    fig.suptitle("Peak tracked bytes of the construction (solid) and peak RSS of the child "
                 "(dotted) against n", fontsize=11)
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


def k_label(g):
    var, fam, n, r_req, h, w = g
    return "%s n=%d r=%s%s %s" % (var, n, "default" if r_req == -1 else r_req,
                                  " holes=%d" % h if h else "", w)


def plot_k(rows, outdir, written):
    groups = k_groups(rows)
    if not groups:
        return "k_effect, k_tradeoff: skipped (no variant with two or more k values)"
    fams = sorted({g[1] for g in groups})
    slots = panel_slots(rows, fams, lambda fam: [g for g in groups if g[1] == fam])
    cmap = plt.get_cmap("tab10")
    # k_effect: time (top) and memory (bottom) against k, one column per family.
    fig, axes = panels(len(slots), ncols=len(slots) if len(slots) <= 4 else NCOLS, rows_per=2)
    fig2, axes2 = panels(len(slots), ncols=len(slots) if len(slots) <= 4 else NCOLS)
    for (fam, suffix, gs), (at, am), (ax2,) in zip(slots, axes, axes2):
        for i, g in enumerate(gs):
            kk, x, t, m = k_points(groups[g])
            c = cmap(i % 10)
            num = [i for i, k in enumerate(kk) if k != "max"]
            at.plot([x[i] for i in num], [t[i] for i in num], marker="o", color=c,
                    label=k_label(g), markersize=4)
            am.plot([x[i] for i in num], [m[i] for i in num], marker="o", color=c,
                    label=k_label(g), markersize=4)
            # k = max sits at its numeric value (r), among the numeric k: a
            # hollow marker off the line tells it apart.
            for k, xi, ti, mi in zip(kk, x, t, m):
                if k == "max":
                    for ax, y in ((at, ti), (am, mi)):
                        if y is not None:
                            ax.plot([xi], [y], marker="o", markersize=8, linestyle="None",
                                    markerfacecolor="white", markeredgecolor=c, zorder=3)
                            ax.annotate("max", (xi, y), fontsize=6, textcoords="offset points",
                                        xytext=(4, -9))
            ax2.plot(m, t, marker="o", color=c, label=k_label(g), markersize=4)
            for k, mi, ti in zip(kk, m, t):
                if mi is not None and ti is not None:
                    ax2.annotate(str(k), (mi, ti), fontsize=6, textcoords="offset points",
                                 xytext=(3, 3))
        for ax, yl in ((at, "construction time (s)"), (am, "peak tracked bytes")):
            loglog(ax, "k (cache size; max, hollow, plotted at r)", yl)
            ax.set_xscale("log", base=2)
        at.set_title("%s%s: time against k" % (fam, suffix), fontsize=9)
        am.set_title("%s%s: peak memory against k" % (fam, suffix), fontsize=9)
        legend_beside(at)
        loglog(ax2, "peak tracked bytes", "construction time (s)")
        ax2.set_title("%s%s (point labels: k)" % (fam, suffix), fontsize=9)
        legend_beside(ax2)
    fig.suptitle("The k tradeoff per family at fixed n and r: time falls, memory grows with k",
                 fontsize=11)
    save(fig, outdir, "k_effect", written)
    fig2.suptitle("Time against peak memory per family, one point per k", fontsize=11)
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


EVENT_PANELS = [("switch_events", lambda r: r["n"] * max(r["r"], 1), "n r"),
                ("start_events", lambda r: max(r["r"], 1) ** 2, "r^2"),
                ("all events", lambda r: r["n"], "n")]


def plot_events(rows, outdir, written):
    rs = [r for r in rows if any(r.get(c) is not None for c in EVENT_COLS)]
    if not rs:
        return "events_vs_bounds: skipped (no event counters)"
    colors = family_colors(rs)
    variants = sorted({r["variant"] for r in rs}, key=variant_key)
    fams = sorted({r["family"] for r in rs})
    # One column per variant and chunk of at most MAX_LINES families.
    cols = [(v, ch) for v in variants for ch in split(fams)]
    fig, axes = plt.subplots(len(EVENT_PANELS), len(cols), squeeze=False, constrained_layout=True,
                             figsize=(len(cols) * (PANEL[0] + 0.3) + LEGEND_W,
                                      len(EVENT_PANELS) * PANEL[1]))
    drawn = 0
    for j, (var, chunk) in enumerate(cols):
        for i, (col, bound, bname) in enumerate(EVENT_PANELS):
            ax = axes[i][j]
            for fam in chunk:
                pts = [(bound(r), event_value(r, col)) for r in rs
                       if r["variant"] == var and r["family"] == fam]
                # Absent counters are no points; zeros have no place on a log axis.
                pts = [(b, v) for b, v in pts if v is not None and v > 0]
                if pts:
                    ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=10,
                               color=colors[fam], label=fam)
            ax.set_title("%s: %s vs %s" % (var, col, bname), fontsize=9)
            if ax.collections:
                drawn += 1
                lo = min(min(c.get_offsets()[:, 0]) for c in ax.collections)
                hi = max(max(c.get_offsets()[:, 0]) for c in ax.collections)
                ax.plot([lo, hi], [lo, hi], "k--", linewidth=0.8, label="= bound")
                loglog(ax, bname, col)
            else:
                ax.text(0.5, 0.5, "no %s recorded\n(zero or absent in every run)" % col,
                        ha="center", va="center", transform=ax.transAxes, fontsize=8)
                ax.set_xticks([])
                ax.set_yticks([])
    if drawn == 0:
        plt.close(fig)
        return "events_vs_bounds: skipped (all event counters zero or absent)"
    # One legend for the whole figure (the families' colours are shared),
    # to the right of the last column.
    handles = [Line2D([], [], marker="o", linestyle="", color=colors[f], label=f) for f in fams]
    handles.append(Line2D([], [], color="k", linestyle="--", linewidth=0.8, label="= bound"))
    axes[0][-1].legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                       fontsize=8, frameon=False, borderaxespad=0.0)
    fig.suptitle("Event counts against their bounds, one column per variant", fontsize=11)
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
    if not attach_phases(args.csv, ok):
        notes.append("time_vs_n: no phase times (phase_s) in the JSON-lines twin, so no "
                     "phase curves")
    plot_time_vs_n(ok, args.outdir, written, fits)
    plot_memory_vs_n(ok, args.outdir, written)
    for f in (plot_phase_share, plot_k, plot_events):
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
