#!/usr/bin/python3
"""regress.py: compare a wskel-bench run with the committed baseline.

usage: regress.py RUN.csv BASELINE.csv [--time-tol 2.0] [--min-time 0.05] [--all]
                  [--confirm BENCH] [--confirm-rounds 3]

Per configuration (results.CONFIG_COLS but repeat; repeats grouped; a CSV
without the holes column, such as a baseline written before it, has holes 0):
  - status, r, nodes, arcs and every counter must be equal: they are
    deterministic (counts only, ties broken by ids), so any difference means
    the algorithm now does different work.  An empty counter cell (the
    variant has no such counter) equals only another empty cell: a counter
    that appears or disappears is a change of what is counted;
  - peak tracked bytes within 1% (deterministic too, except for allocator
    growth policies that depend on nothing but the input; 1% leaves room for
    an incidental change of a struct's padding, not for a new array);
  - time: the fastest repeat of the run over the fastest of the baseline,
    divided by the machine's speed ratio, the median of that quotient over
    every timed configuration; the result may exceed 1 by at most a factor
    --time-tol (2.0).  The fastest repeat, not the median: a neighbour's
    burst of load only ever adds time, so the minimum is the estimate least
    disturbed by it.  Why the median over all configurations and not one
    reference polygon: on the shared 2-core VM the baseline comes from, the
    reference (naive star n=3000, 5 repeats, 50 ms) itself came out at
    0.052, 0.066, 0.079 and 0.055 s in four runs on the same day (two of them
    back to back on a quiet machine), so dividing by it shifted every ratio
    by up to x1.44 and failed CI on code that had not changed.  The median of
    35 timed configurations does not move with one of them.  (The reference
    is still printed, for the absolute speed; with fewer than 3 timed
    configurations it is the divisor.)  What the median cannot see is a
    slowdown of every configuration alike: the counters catch extra work,
    the time check catches one configuration going wrong.
Why 2.0: two back-to-back runs of the same binary on a quiet machine gave
quotients (over the median) from x0.70 to x1.53 for the 35 timed
configurations of regress.spec; a tolerance under that fails honest code.
The regressions that matter are larger (an extra O(n) scan per event costs
far more than x2 at n = 3000).
Runs under --min-time seconds (0.05) are not timed for the check: at that
scale the spread between processes is larger still (arrangement notched
n=1000 k=1, 20 ms: x1.56 between the baseline and a CI run of the same code).
Confirmation (--confirm BENCH): a configuration flagged for time alone is
run again --confirm-rounds times (5 repeats each), each round beside a re-run
of the reference that gives that round's machine speed, and judged by its
best round (or the sweep, if better).  A real slowdown survives every
round; a burst of load from a neighbour does not, and a load that differs
between the sweep and the re-runs cancels out.
Run and baseline must have the same
set of counter columns (in any order); otherwise regenerate the baseline.
Prints a table (only the interesting lines unless --all) and exits 1 on any
regression, 2 on a usage error or a missing reference.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results import cell, config_key, counter_columns, group_by, load_csv  # noqa: E402

REFERENCE = {"variant": "naive", "family": "star", "n": 3000, "weights": "unit", "seed": 1,
             "r_req": -1, "holes": 0}
TRACKED_TOL = 0.01


def group(rows):
    return group_by(rows, lambda r: config_key(r, drop=("repeat",)))


def reference_time(rows):
    ts = [r["wall_s"] for r in rows if all(r[k] == v for k, v in REFERENCE.items())
          and r["status"] == "ok" and r["wall_s"]]
    k1 = [r for r in rows if all(r[k] == v for k, v in REFERENCE.items())]
    if not ts:
        return None, k1
    return min(ts), k1


def bench_args(key, repeats=5):
    """wskel-bench options that run exactly the configuration key (as
    config_key(row, drop=("repeat",)) gives it)."""
    v, fam, n, rr, h, k, w, s = key
    a = ["--variant", v, "--family", fam, "--n", n, "--weights", w, "--seeds", s,
         "--repeats", str(repeats), "--quiet"]
    if rr != "-1":
        a += ["--r", rr]
    if h != "0":
        a += ["--holes", h]
    if k != "":
        a += ["--k", k]
    return a


def rerun(bench, key, tmpdir, tag):
    """Run one configuration again; its ok wall times (may be empty)."""
    out = os.path.join(tmpdir, "%s.csv" % tag)
    subprocess.run([bench] + bench_args(key) + ["--out", out], check=True,
                   stdout=subprocess.DEVNULL)
    _, rows = load_csv(out)
    return [x["wall_s"] for x in rows if x["status"] == "ok" and x["wall_s"]]


def fmt_key(key):
    v, fam, n, rr, h, k, w, s = key
    return "%s %s n=%s%s%s%s %s s%s" % (v, fam, n, "" if rr == "-1" else " r=" + rr,
                                        "" if h == "0" else " holes=" + h,
                                        "" if k == "" else " k=" + k, w, s)


def main():
    ap = argparse.ArgumentParser(description="compare a run with the baseline")
    ap.add_argument("run")
    ap.add_argument("baseline")
    ap.add_argument("--time-tol", type=float, default=2.0)
    ap.add_argument("--min-time", type=float, default=0.05)
    ap.add_argument("--confirm", metavar="BENCH",
                    help="re-measure time-only regressions with this wskel-bench")
    ap.add_argument("--confirm-rounds", type=int, default=3)
    ap.add_argument("--all", action="store_true", help="print every configuration")
    args = ap.parse_args()
    counters = counter_columns(args.baseline)
    run_counters = counter_columns(args.run)
    if set(counters) != set(run_counters):
        print("regress: the counter columns differ between run and baseline "
              "(regenerate the baseline when counters change): only in the run: %s; "
              "only in the baseline: %s" % (
                  " ".join(c for c in run_counters if c not in counters) or "-",
                  " ".join(c for c in counters if c not in run_counters) or "-"))
        return 1
    _, run_rows = load_csv(args.run)
    _, base_rows = load_csv(args.baseline)
    run_ref, _ = reference_time(run_rows)
    base_ref, base_ref_rows = reference_time(base_rows)
    if not run_ref or not base_ref:
        print("regress: reference %s missing or not ok in %s" % (
            REFERENCE, "the run" if not run_ref else "the baseline"))
        return 2
    run_g, base_g = group(run_rows), group(base_rows)
    ref_key = config_key(base_ref_rows[0], drop=("repeat",))

    def ok_times(rows):
        return [x["wall_s"] for x in rows if x["status"] == "ok" and x["wall_s"]]

    quotients = []
    for key, b in base_g.items():
        bt, rt = ok_times(b), ok_times(run_g.get(key, []))
        if bt and rt and statistics.median(bt) >= args.min_time:
            quotients.append(min(rt) / min(bt))
    if len(quotients) >= 3:
        speed, speed_from = statistics.median(quotients), \
            "median over %d timed configurations" % len(quotients)
    else:
        speed, speed_from = run_ref / base_ref, "the reference (too few timed configurations)"
    failures, lines = 0, []
    hdr = "%-46s %-8s %-10s %9s %9s %7s  %s" % ("configuration", "counters", "tracked",
                                              "base/ref", "run/ref", "change", "verdict")
    for key in sorted(base_g):
        b = base_g[key]
        r = run_g.get(key)
        if not r:
            lines.append("%-46s %s" % (fmt_key(key), "MISSING from the run  REGRESSION"))
            failures += 1
            continue
        problems = []
        b0, r0 = b[0], r[0]
        det = ["status", "r", "nodes", "arcs"] + counters
        # Equal only as the same int or both None (an empty cell: the variant
        # has no such counter); None != 0, so a counter that appears or
        # vanishes for a variant is a difference.
        diffs = [c for c in det if b0[c] != r0[c]]
        diffs += [c for c in det for x in r[1:] if x[c] != r0[c] and c not in diffs]
        cnt = "ok" if not diffs else "DIFF"
        if diffs:
            problems.append("differs: " + ", ".join(
                "%s %s->%s" % (c, cell(b0[c]) or "empty", cell(r0[c]) or "empty")
                for c in diffs[:4]))
        tracked = "-"
        if b0["peak_tracked_bytes"] is not None and r0["peak_tracked_bytes"] is not None:
            rel = (r0["peak_tracked_bytes"] - b0["peak_tracked_bytes"]) / max(
                b0["peak_tracked_bytes"], 1)
            tracked = "%+.2f%%" % (100 * rel)
            if abs(rel) > TRACKED_TOL:
                problems.append("peak tracked bytes %+.1f%% (tolerance 1%%)" % (100 * rel))
        bt, rt = ok_times(b), ok_times(r)
        bq = rq = ch = None
        confirmed = ""
        if bt and rt:
            bq = min(bt) / base_ref
            rq = min(rt) / run_ref
            ch = min(rt) / min(bt) / speed
            timed = statistics.median(bt) >= args.min_time
            if timed and ch > args.time_tol and not problems and args.confirm:
                # Each round re-runs the reference beside the configuration and
                # scales by that round's own speed: the load during the sweep
                # (which set `speed`) is not the load now, and a quieter or
                # busier machine must not clear or keep a flag by itself.
                best = ch
                with tempfile.TemporaryDirectory() as tmpdir:
                    for i in range(args.confirm_rounds):
                        ref_t = rerun(args.confirm, ref_key, tmpdir, "ref%d" % i)
                        cfg_t = rerun(args.confirm, key, tmpdir, "cfg%d" % i)
                        if ref_t and cfg_t:
                            best = min(best, min(cfg_t) / min(bt) / (min(ref_t) / base_ref))
                confirmed = " (x%.2f in the sweep, re-measured %d rounds)" % (
                    ch, args.confirm_rounds)
                ch = best
            if timed and ch > args.time_tol:
                problems.append("time x%.2f (tolerance x%.2f)%s" % (
                    ch, args.time_tol, confirmed))
        verdict = "REGRESSION: " + "; ".join(problems) if problems else \
            ("ok" + confirmed)
        if ch is not None and ch < 1 / args.time_tol and not problems and \
                statistics.median(bt) >= args.min_time:
            verdict = "ok (faster)"
        failures += bool(problems)
        line = "%-46s %-8s %-10s %9s %9s %7s  %s" % (
            fmt_key(key), cnt, tracked, "%.3g" % bq if bq else "-", "%.3g" % rq if rq else "-",
            "x%.2f" % ch if ch else "-", verdict)
        if args.all or verdict != "ok":
            lines.append(line)
    extra = [k for k in run_g if k not in base_g]
    print("reference: %s: baseline %.4gs, this run %.4gs (ratio %.2f)" % (
        fmt_key(config_key(dict(REFERENCE, k="", repeat=0), drop=("repeat",))),
        base_ref, run_ref, run_ref / base_ref))
    print("machine speed ratio (run/baseline) %.3f: %s; change = run/baseline/speed" % (
        speed, speed_from))
    print(hdr)
    for line in lines:
        print(line)
    if extra:
        print("%d configurations are not in the baseline (ignored), e.g. %s" % (
            len(extra), fmt_key(extra[0])))
    print("regress: %d configurations compared, %d regressions" % (len(base_g), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
