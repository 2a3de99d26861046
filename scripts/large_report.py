#!/usr/bin/python3
"""large_report.py: the report of scripts/perf_large.sh from its sweep CSV.

Per variant and family (in the CSV's order): the time of each n, peak
tracked bytes per vertex, time / qsort (the CSV's qsort() reference: the
median of its `# qsort_ref_s:` lines, results.qsort_ref), time / qsort at
n = 10^6, and the exponent of time in n: the least-squares slope of log
time on log n (results.loglog_slope, as plot.py's legends) over the ok runs
with 10^3 <= n <= 10^6.  Each is set against the large-n targets (--ratio,
--bytes, --exponent; defaults 50 qsorts at 10^6, 1024 bytes per vertex at
10^6, exponent 1.15): "meets", "misses", or "not measured" when the run did
not reach n = 10^6 (or has fewer than two timed points for the exponent).

Writes OUTDIR/summary.csv (one row per variant and family) and
OUTDIR/REPORT.md.

usage: large_report.py SWEEP.csv OUTDIR [--command TEXT] [--caps TEXT]
                       [--ratio 50] [--bytes 1024] [--exponent 1.15]
"""
import argparse
import csv
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results import group_by, load_csv, loglog_slope, qsort_ref  # noqa: E402

N_TARGET = 1000000
FIT_LO, FIT_HI = 1000, 1000000


def comment_value(comments, key):
    for c in comments:
        if c.startswith(key + ":"):
            return c[len(key) + 1:].strip()
    return "unknown"


def per_n(rows):
    """{n: (status, wall_s or None, peak_tracked or None, r, message)}: the
    median over the ok rows of an n (repeats, seeds), else the first row."""
    out = {}
    for (n,), rs in sorted(group_by(rows, ("n",)).items()):
        ok = [r for r in rs if r["status"] == "ok" and r["wall_s"] is not None]
        if ok:
            wall = statistics.median(r["wall_s"] for r in ok)
            peaks = [r["peak_tracked_bytes"] for r in ok if r["peak_tracked_bytes"] is not None]
            peak = statistics.median(peaks) if peaks else None
            out[n] = ("ok", wall, peak, ok[0]["r"], "")
        else:
            r = rs[0]
            out[n] = (r["status"], None, r["peak_tracked_bytes"], r["r"], r["message"] or "")
    return out


def verdict(value, limit):
    if value is None:
        return "not measured"
    return "meets" if value <= limit else "misses"


def exponent_verdict(expo, pts, limit):
    """The exponent's verdict; one fitted below 10^6 only says so."""
    v = verdict(expo, limit)
    if expo is not None and max(n for n, _ in pts) < N_TARGET:
        v += " (fit below 10^6 only)"
    return v


def summarise(rows, q, targets):
    """[(variant, family, per_n dict, summary dict)] in first-seen order."""
    out = []
    for (v, fam), rs in group_by(rows, ("variant", "family")).items():
        pn = per_n(rs)
        pts = [(n, t[1]) for n, t in pn.items()
               if t[0] == "ok" and t[1] and FIT_LO <= n <= FIT_HI]
        expo = loglog_slope([n for n, _ in pts], [t for _, t in pts]) if len(pts) >= 2 else None
        if expo is not None and expo != expo:  # nan
            expo = None
        at = pn.get(N_TARGET)
        t6 = at[1] if at and at[0] == "ok" else None
        ratio = t6 / q if t6 is not None and q else None
        bpv = at[2] / N_TARGET if at and at[0] == "ok" and at[2] is not None else None
        ok_ns = [n for n, t in pn.items() if t[0] == "ok"]
        top = max(ok_ns) if ok_ns else None
        big = pn[top] if top else None
        s = {
            "max_n": top,
            "time_over_qsort_max_n": big[1] / q if big and big[1] is not None and q else None,
            "bytes_per_vertex_max_n": big[2] / top if big and big[2] is not None else None,
            "time_over_qsort_1e6": ratio,
            "bytes_per_vertex_1e6": bpv,
            "exponent": expo,
            "exponent_range": "%d..%d" % (min(n for n, _ in pts), max(n for n, _ in pts))
            if pts else "",
            "exponent_points": len(pts),
            "meets_time": verdict(ratio, targets["ratio"]),
            "meets_memory": verdict(bpv, targets["bytes"]),
            "meets_exponent": exponent_verdict(expo, pts, targets["exponent"]),
        }
        out.append((v, fam, pn, s))
    return out


def fmt(v, spec="%.3g"):
    return "" if v is None else spec % v


def write_summary_csv(path, groups, ns, q):
    cols = ["variant", "family", "max_n_ok", "qsort_ref_s"]
    for n in ns:
        cols += ["status_n%d" % n, "time_s_n%d" % n, "time_over_qsort_n%d" % n,
                 "bytes_per_vertex_n%d" % n]
    cols += ["time_over_qsort_max_n", "bytes_per_vertex_max_n", "time_over_qsort_1e6",
             "bytes_per_vertex_1e6", "exponent", "exponent_range",
             "exponent_points", "meets_time", "meets_memory", "meets_exponent"]
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for v, fam, pn, s in groups:
            row = [v, fam, s["max_n"], fmt(q, "%.6g")]
            for n in ns:
                st, t, peak, _, _ = pn.get(n, ("", None, None, None, ""))
                row += [st, fmt(t, "%.6g"), fmt(t / q if t is not None and q else None, "%.4g"),
                        fmt(peak / n if peak is not None else None, "%.1f")]
            row += [fmt(s["time_over_qsort_max_n"], "%.4g"), fmt(s["bytes_per_vertex_max_n"], "%.1f"),
                    fmt(s["time_over_qsort_1e6"], "%.4g"), fmt(s["bytes_per_vertex_1e6"], "%.1f"),
                    fmt(s["exponent"], "%.3f"), s["exponent_range"], s["exponent_points"],
                    s["meets_time"], s["meets_memory"], s["meets_exponent"]]
            w.writerow(row)


def write_report(path, groups, comments, q, qvals, targets, command, caps, csv_name):
    L = []
    variants = []
    for v, _, _, _ in groups:
        if v not in variants:
            variants.append(v)
    fams = []
    for _, f, _, _ in groups:
        if f not in fams:
            fams.append(f)
    L.append("# Large n: %s on %s" % (", ".join(variants), ", ".join(fams)))
    L.append("")
    L.append("Written by `scripts/perf_large.sh` (`scripts/large_report.py`) from `%s`." % csv_name)
    L.append("")
    L.append("* command: `%s`" % (command or "scripts/perf_large.sh ..."))
    if caps.strip():
        L.append("* max n per variant: %s" % caps.strip())
    for key in ("date", "cpu", "cores", "memory", "compiler", "cflags", "git"):
        L.append("* %s: %s" % (key, comment_value(comments, key)))
    L.append("* qsort reference (`wskel-bench --qsort-ref`: qsort() of 10^6 uniform doubles, "
             "seed 1, median of 5, measured before and after each variant's runs): "
             "median **%s s** of %s" % (fmt(q, "%.4g"), ", ".join("%.4g" % x for x in qvals)
                                         or "none"))
    L.append("* time: the construction alone (wskel-bench's wall_s: no generation, no "
             "validation), one child per run, one run at a time; peak tracked bytes: the run "
             "allocator's peak during the construction")
    L.append("* exponent: least-squares slope of log time on log n over the ok runs with "
             "10^3 <= n <= 10^6 (`results.loglog_slope`)")
    L.append("* targets: time at n = 10^6 <= %g qsorts; peak tracked bytes at 10^6 <= %g per "
             "vertex; exponent <= %g" % (targets["ratio"], targets["bytes"], targets["exponent"]))
    L.append("")
    L.append("## Summary")
    L.append("")
    L.append("| variant | family | largest n with status ok | time / qsort, bytes / vertex there | "
             "time / qsort at 10^6 | bytes / vertex at 10^6 | exponent (n range, points) | "
             "time target | memory target | exponent target |")
    L.append("|---|---|---|---|---|---|---|---|---|---|")
    for v, fam, pn, s in groups:
        ex = "%s (%s, %d)" % (fmt(s["exponent"], "%.3f"), s["exponent_range"],
                              s["exponent_points"]) if s["exponent"] is not None else "n/a"
        L.append("| %s | %s | %s | %s, %s | %s | %s | %s | %s | %s | %s |" % (
            v, fam, s["max_n"] or "none", fmt(s["time_over_qsort_max_n"], "%.3g") or "n/a",
            fmt(s["bytes_per_vertex_max_n"], "%.0f") or "n/a",
            fmt(s["time_over_qsort_1e6"], "%.3g") or "n/a",
            fmt(s["bytes_per_vertex_1e6"], "%.0f") or "n/a", ex, s["meets_time"],
            s["meets_memory"], s["meets_exponent"]))
    L.append("")
    L.append("## Runs")
    L.append("")
    L.append("| variant | family | n | r | status | time (s) | time / qsort | peak tracked bytes "
             "| bytes / vertex |")
    L.append("|---|---|---|---|---|---|---|---|---|")
    for v, fam, pn, s in groups:
        for n, (st, t, peak, r, msg) in sorted(pn.items()):
            status = st if not msg else "%s (%s)" % (st, msg.replace("|", "/")[:80])
            L.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s |" % (
                v, fam, n, "" if r is None else r, status, fmt(t, "%.4g"),
                fmt(t / q if t is not None and q else None, "%.3g"),
                "" if peak is None else "%d" % peak, fmt(peak / n if peak is not None else None,
                                                         "%.0f")))
    L.append("")
    with open(path, "w") as f:
        f.write("\n".join(L))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("outdir")
    ap.add_argument("--command", default="")
    ap.add_argument("--caps", default="")
    ap.add_argument("--ratio", type=float, default=50.0)
    ap.add_argument("--bytes", type=float, default=1024.0)
    ap.add_argument("--exponent", type=float, default=1.15)
    a = ap.parse_args()
    comments, rows = load_csv(a.csv)
    if not rows:
        print("large_report.py: %s has no rows" % a.csv, file=sys.stderr)
        return 1
    q = qsort_ref(comments)
    if q is None:
        print("large_report.py: warning: %s has no qsort_ref_s line: no ratios" % a.csv,
              file=sys.stderr)
    qvals = [float(c.split()[1]) for c in comments if c.startswith("qsort_ref_s:")]
    targets = {"ratio": a.ratio, "bytes": a.bytes, "exponent": a.exponent}
    groups = summarise(rows, q, targets)
    ns = sorted({r["n"] for r in rows})
    os.makedirs(a.outdir, exist_ok=True)
    write_summary_csv(os.path.join(a.outdir, "summary.csv"), groups, ns, q)
    write_report(os.path.join(a.outdir, "REPORT.md"), groups, comments, q, qvals, targets,
                 a.command, a.caps, os.path.basename(a.csv))
    for v, fam, _, s in groups:
        print("%-14s %-10s max ok n %-8s time/qsort@1e6 %-8s bytes/vertex@1e6 %-6s exponent %s" % (
            v, fam, s["max_n"], fmt(s["time_over_qsort_1e6"]) or "n/a",
            fmt(s["bytes_per_vertex_1e6"], "%.0f") or "n/a",
            fmt(s["exponent"], "%.3f") or "n/a"))
    print("-> %s, %s" % (os.path.join(a.outdir, "summary.csv"),
                         os.path.join(a.outdir, "REPORT.md")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
