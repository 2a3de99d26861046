#!/usr/bin/python3
"""report.py: REPORT.md for a wskel-bench run: machine, statuses, fit, plots.

usage: report.py RESULTS.csv PLOTDIR OUT.md [--fit FIT.txt] [--roof ROOF.png]
The plots are linked relative to OUT.md's folder; only those present are
embedded (plot.py skips figures whose data are absent).  --roof embeds a
rendered roof (`make roof`: results/roof/roof_holes.png, of
results/roof/roof_holes.wpoly) at the end, when the file exists.
"""
import argparse
import math
import os
import sys
from collections import Counter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit  # noqa: E402  (the fit, when no fit.txt is given)
from results import cell, config_key, group_by, k_order, load_csv, loglog_slope  # noqa: E402

FIGURES = [
    ("time_vs_n", "Construction time against n, one panel per family (log-log; slope in "
     "the legend, dashed: the NNLS model of fit.py)"),
    ("phase_share", "A timed phase's share of the construction time against n (the motorcycle "
     "variant's M(P)), one line per family"),
    ("memory_vs_n", "Peak tracked bytes (solid) and peak RSS (dotted) against n, one panel "
     "per family"),
    ("k_effect", "The k tradeoff per family: time and peak memory against k at fixed n and r"),
    ("k_tradeoff", "Time against peak memory per family, points labelled by k"),
    ("events_vs_bounds", "Event counts against their bounds (switch: n r, start: r^2), one "
     "column per variant"),
]


def k_sweeps(rows):
    """Markdown lines: one table per configuration run at several numeric k
    (time, peak tracked bytes, start events), with the least-squares slope of
    log time against log k over the range where the r^3/k term dominates:
    the fastest run of the sweep estimates the time that does not fall with
    k, and the range is the k from 1 up to the last one where more than half
    of the time is above that (k = 1..4 on bench/sweeps/curves_k.spec's
    polygons); the slope over k = 1..8 is given too."""
    swept = [r for r in rows if r["status"] == "ok" and r.get("k") and r["wall_s"] is not None]
    # One table per configuration but for k; repeats share it.
    groups = group_by(swept, lambda r: config_key(r, drop=("k", "repeat")))
    out = []
    for rs in sorted(groups.values(), key=lambda rs: (rs[0]["variant"], rs[0]["family"],
                                                       rs[0]["n"], config_key(rs[0]))):
        numeric = [r for r in rs if str(r["k"]) != "max"]
        if len(numeric) < 3:
            continue
        rs.sort(key=lambda r: k_order(r["k"]))
        floor = min(r["wall_s"] for r in rs)
        numeric.sort(key=lambda r: k_order(r["k"]))
        kmax = 1
        for r in numeric:
            if r["wall_s"] > 0 and (r["wall_s"] - floor) / r["wall_s"] > 0.5:
                kmax = int(r["k"])
            else:
                break

        def slope_upto(kk, col="wall_s"):
            pts = [r for r in numeric if int(r["k"]) <= kk and r.get(col)]
            s = loglog_slope([int(r["k"]) for r in pts], [r[col] for r in pts])
            return "n/a" if math.isnan(s) else "%.3f" % s
        x0 = rs[0]
        out.append("**%s, %s n=%s r=%s %s seed %s** (%s crossings at t = 0): slope of log "
                   "time in log k %s over k = 1..%d, where more than half of the time is "
                   "above the fastest run's %.3f s (the r^3/k term dominates); %s over "
                   "k = 1..8" %
                   (x0["variant"], x0["family"], x0["n"], x0["r"], x0["weights"], x0["seed"],
                    cell(x0.get("crossings")) or "?", slope_upto(kmax), kmax, floor,
                    slope_upto(8)))
        out.append("")
        out.append("In CPU time (cpu_s, steadier than wall time on a loaded machine): %s over "
                   "k = 1..4, %s over k = 1..8." % (slope_upto(4, "cpu_s"), slope_upto(8, "cpu_s")))
        out.append("")
        out.append("| k | time (s) | CPU (s) | peak tracked (MB) | start events |")
        out.append("|---|---|---|---|---|")
        for x in rs:
            mb = x["peak_tracked_bytes"]
            cpu = x.get("cpu_s")
            # An empty cell stays empty: the variant does not count start events.
            out.append("| %s | %.3f | %s | %s | %s |" % (
                x["k"], x["wall_s"], "" if cpu is None else "%.3f" % cpu,
                "" if mb is None else "%.2f" % (mb / 1e6), cell(x.get("start_events"))))
        out.append("")
    return out


def phase_tables(csv_path, rows):
    """Markdown lines: per variant with a timed phase (the motorcycle
    variant's M(P); phase_s of the CSV's JSON-lines twin), the phase's time,
    the construction time and the share, per family and n (medians over
    seeds and repeats, as plot.py's phase_share)."""
    import plot  # noqa: E402  (matplotlib; only when the report has phase times)
    ok = [r for r in rows if r["status"] == "ok" and r["wall_s"] is not None and r["wall_s"] > 0]
    if not plot.attach_phases(csv_path, ok):
        return []
    out = []
    for (var, phase), fams in sorted(plot.phase_shares(ok).items()):
        out.append("**%s**: %s time, construction time and %s's share of it (wall clock; "
                   "median over seeds)" % (var, phase, phase))
        out.append("")
        out.append("| family | weights | n | %s (s) | construction (s) | share |" % phase)
        out.append("|---|---|---|---|---|---|")
        for (fam, w), pts in sorted(fams.items()):
            for n in sorted(pts):
                share, ph, wall = pts[n]
                out.append("| %s | %s | %d | %.4g | %.4g | %.0f%% |" % (fam, w, n, ph, wall,
                                                                         100 * share))
        out.append("")
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("plotdir")
    ap.add_argument("out")
    ap.add_argument("--fit", help="fit.py output to embed (recomputed if absent)")
    ap.add_argument("--roof", help="a rendered roof PNG to embed (make roof)")
    args = ap.parse_args()
    comments, rows = load_csv(args.csv)
    outdir = os.path.dirname(os.path.abspath(args.out))
    lines = ["# wskel benchmark report", ""]
    lines.append("Source: `%s`, %d runs." % (os.path.relpath(args.csv, outdir), len(rows)))
    lines.append("")
    lines.append("## Machine and build")
    lines.append("")
    for c in comments:
        if c.split(":")[0] in ("date", "cpu", "cores", "memory", "compiler", "cflags", "git",
                               "generator version", "command", "limits"):
            lines.append("- " + c)
    load = [r["wall_s"] / r["cpu_s"] for r in rows
            if r["status"] == "ok" and r["variant"] != "cgal" and r.get("cpu_s")
            and r["wall_s"] and r["cpu_s"] >= 0.5]
    if load:
        load.sort()
        lines.append("- wall time / CPU time of the runs of at least 0.5 s CPU: median %.2f "
                     "(%.2f..%.2f, %d runs; about 1 on an idle machine for these single-threaded "
                     "runs, more when other work shares the cores: wall times are then inflated "
                     "by about that factor)" % (load[len(load) // 2], load[0], load[-1], len(load)))
    lines.append("")
    lines.append("## Statuses")
    lines.append("")
    counts = Counter((r["variant"], r["status"]) for r in rows)
    lines.append("| variant | status | runs |")
    lines.append("|---|---|---|")
    for (v, s), c in sorted(counts.items()):
        lines.append("| %s | %s | %d |" % (v, s, c))
    bad = [r for r in rows if r["status"] != "ok"]
    if bad:
        lines.append("")
        lines.append("Runs that did not finish ok (first 20):")
        lines.append("")
        for r in bad[:20]:
            lines.append("- %s %s n=%d seed=%s %s: %s %s" % (r["variant"], r["family"], r["n"],
                         r["seed"], r["weights"], r["status"], r["message"]))
    lines.append("")
    lines.append("## Model fit")
    lines.append("")
    if args.fit and os.path.exists(args.fit):
        text = open(args.fit).read()
    else:
        text = fit.format_fits(fit.fit_groups(rows))
    lines.append("```")
    lines.append(text.rstrip())
    lines.append("```")
    lines.append("")
    lines.append("Shares are each term's part of the predicted time at the group's largest n. "
                 "The naive reference variant has no arrangement, so its r^3/k term only says "
                 "that its time grows like a power of r between 2 and 3 on these families.")
    lines.append("")
    pt = phase_tables(args.csv, rows)
    if pt:
        lines.append("## Timed phases")
        lines.append("")
        lines.extend(pt)
    ks = k_sweeps(rows)
    if ks:
        lines.append("## k sweeps")
        lines.append("")
        lines.extend(ks)
    lines.append("## Figures")
    lines.append("")
    for name, caption in FIGURES:
        png = os.path.join(args.plotdir, name + ".png")
        if os.path.exists(png):
            rel = os.path.relpath(png, outdir)
            lines.append("### " + caption)
            lines.append("")
            lines.append("![%s](%s) ([SVG](%s))" % (name, rel, rel[:-4] + ".svg"))
            lines.append("")
    if args.roof and os.path.exists(args.roof):
        rel = os.path.relpath(os.path.abspath(args.roof), outdir)
        src = os.path.splitext(args.roof)[0] + ".wpoly"
        lines.append("## A roof")
        lines.append("")
        lines.append("The roof (the skeleton lifted by its time t, coloured by height, arcs "
                     "dark) of a polygon with holes%s, rendered by `make roof` "
                     "(`scripts/render.py`, VTK under xvfb-run)." %
                     (" (`%s`)" % os.path.relpath(os.path.abspath(src), outdir)
                      if os.path.exists(src) else ""))
        lines.append("")
        lines.append("![roof of a polygon with holes](%s)" % rel)
        lines.append("")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
