#!/usr/bin/python3
"""fit.py: fit the running-time model of the arrangement paper to a sweep.

    time ~ c1 n^2 + c2 r^3/k + c3 n r log n + c0,   all c >= 0

by non-negative least squares (scipy.optimize.nnls).  Each row is divided by
its measured time before the solve, so the fit minimises relative error: the
sweep spans several decades of time and an absolute fit would only see the
largest n.  Prints, per variant (all families together) and per variant,
family and weight mode: the coefficients, R^2 (of the raw times) and each
term's share of the predicted time at the largest n of the group.  --json
writes the same fits for plot.py (the dashed model curves) to read back.

usage: fit.py RESULTS.csv [--json OUT.json]
"""
import argparse
import json
import math
import os
import sys

import numpy as np
from scipy.optimize import nnls

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results import group_by, k_value  # noqa: E402
# tests/test_bench.sh reads CSVs through fit.load_csv: keep the name here.
from results import load_csv  # noqa: E402,F401

TERMS = ["n^2", "r^3/k", "n r log n", "1"]
SOLVER = "scipy.optimize.nnls"


def design_row(n, r, k):
    n, r, k = float(n), float(r), float(k)
    return [n * n, r ** 3 / max(k, 1.0), n * max(r, 1.0) * math.log(max(n, 2.0)), 1.0]


def fit_rows(rows):
    """Fit the model to rows (status ok, with wall_s).  Returns a dict or None."""
    pts = [r for r in rows if r["status"] == "ok" and r["wall_s"] and r["wall_s"] > 0]
    if len(pts) < 3:
        return None
    X = np.array([design_row(r["n"], r["r"], k_value(r)) for r in pts])
    t = np.array([r["wall_s"] for r in pts])
    # Relative least squares with columns scaled to unit size for conditioning.
    scale = X.max(axis=0)
    scale[scale == 0] = 1.0
    A = (X / scale) / t[:, None]
    coef = nnls(A, np.ones(len(t)))[0] / scale
    pred = X @ coef
    ss_res = float(((t - pred) ** 2).sum())
    ss_tot = float(((t - t.mean()) ** 2).sum())
    r2 = 1.0 - ss_res / ss_tot if ss_tot > 0 else float("nan")
    rel = float(np.median(np.abs(pred - t) / t))
    big = max(pts, key=lambda r: (r["n"], r["r"]))
    xb = np.array(design_row(big["n"], big["r"], k_value(big)))
    tot = float(xb @ coef)
    share = [float(c * x / tot) if tot > 0 else 0.0 for c, x in zip(coef, xb)]
    return {"coef": [float(c) for c in coef], "r2": r2, "median_rel_err": rel,
            "points": len(pts), "solver": SOLVER, "share_at": {"n": big["n"], "r": big["r"],
                                                               "k": big["k"]},
            "share": share}


def predict(fit, n, r, k):
    """The model time of a fit (a fit.json entry) at n, r and numeric k."""
    return float(np.array(design_row(n, r, k)) @ np.array(fit["coef"]))


def fit_groups(rows):
    """Fits per variant and per variant/family/weights: {label: fit}, in the
    order fit.txt lists them (each variant, then its families and weights)."""
    out = {}
    for v, vr in sorted(group_by(rows, ("variant",)).items()):
        f = fit_rows(vr)
        if f:
            out[v[0]] = f
        for (fam, w), gr in sorted(group_by(vr, ("family", "weights")).items()):
            f = fit_rows(gr)
            if f:
                out["/".join((v[0], fam, w))] = f
    return out


def format_fits(fits):
    lines = []
    if not fits:
        return "no group has 3 or more ok runs with a time: nothing to fit\n"
    lines.append("model: time = c1 n^2 + c2 r^3/k + c3 n r log n + c0  (NNLS, relative "
                 "error, %s)" % SOLVER)
    lines.append("%-32s %10s %10s %10s %10s %7s %7s %5s  %s" % (
        "group", "c1 n^2", "c2 r^3/k", "c3 nrlogn", "c0", "R^2", "relerr", "pts",
        "share n^2/r^3k/nrlogn/1 at largest n"))
    for label, f in fits.items():
        c = f["coef"]
        share = "/".join("%.0f%%" % (100 * s) for s in f["share"])
        lines.append("%-32s %10.3g %10.3g %10.3g %10.3g %7.4f %6.1f%% %5d  %s (n=%s r=%s)" % (
            label, c[0], c[1], c[2], c[3], f["r2"], 100 * f["median_rel_err"], f["points"],
            share, f["share_at"]["n"], f["share_at"]["r"]))
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--json", help="also write the fits as JSON (read by plot.py --fit)")
    args = ap.parse_args()
    _, rows = load_csv(args.csv)
    fits = fit_groups(rows)
    sys.stdout.write(format_fits(fits))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(fits, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
