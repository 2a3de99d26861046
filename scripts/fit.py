#!/usr/bin/python3
"""fit.py: fit the running-time model of the arrangement paper to a sweep.

    time ~ c1 n^2 + c2 r^3/k + c3 n r log n + c0,   all c >= 0

by non-negative least squares (scipy.optimize.nnls when python3-scipy is
installed, else the Lawson-Hanson active-set method below, in numpy).  Each
row is divided by its measured time before the solve, so the fit minimises
relative error: the sweep spans several decades of time and an absolute fit
would only see the largest n.  Prints, per variant (all families together) and
per variant, family and weight mode: the coefficients, R^2 (of the raw times) and each
term's share of the predicted time at the largest n of the group.

Also the CSV loader the other scripts import (load_csv): wskel-bench CSVs
carry '#' comment lines, which are returned separately as the header.

usage: fit.py RESULTS.csv [--json OUT.json] [--status ok]
"""
import argparse
import csv
import json
import math
import sys

import numpy as np

TERMS = ["n^2", "r^3/k", "n r log n", "1"]
CONFIG_COLS = ["variant", "family", "n", "r_req", "k", "weights", "seed", "repeat"]
INT_COLS = {"n", "r_req", "seed", "repeat", "r", "signal", "peak_rss_bytes",
            "peak_tracked_bytes", "nodes", "arcs", "crossings", "validated"}
FLOAT_COLS = {"wall_s", "cpu_s"}


def load_csv(path):
    """Return (comments, rows): comment lines without '# ', rows as dicts.

    Numbers are converted (empty cells become None); counter columns are ints.
    """
    comments, lines = [], []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line[1:].strip())
            elif line.strip():
                lines.append(line)
    rows = []
    if not lines:
        return comments, rows
    reader = csv.DictReader(lines)
    fields = reader.fieldnames
    counter_cols = set(fields[fields.index("validated") + 1:fields.index("message")])
    for raw in reader:
        row = {}
        for key, val in raw.items():
            if key in INT_COLS or key in counter_cols:
                row[key] = int(val) if val not in ("", None) else None
            elif key in FLOAT_COLS:
                row[key] = float(val) if val not in ("", None) else None
            else:
                row[key] = val if val is not None else ""
        rows.append(row)
    return comments, rows


def counter_columns(path):
    """Names of the counter columns of a CSV, in order."""
    with open(path, newline="") as f:
        for line in f:
            if not line.startswith("#") and line.strip():
                fields = next(csv.reader([line]))
                return fields[fields.index("validated") + 1:fields.index("message")]
    return []


def row_key(row):
    return tuple(str(row[c]) for c in CONFIG_COLS)


def k_value(row):
    """k as a number for the model: empty (no cache) counts as 1, max as r."""
    k = row.get("k") or ""
    if k == "":
        return 1.0
    if k == "max":
        return float(max(row["r"] or 1, 1))
    return float(k)


def design_row(n, r, k):
    n, r, k = float(n), float(r), float(k)
    return [n * n, r ** 3 / max(k, 1.0), n * max(r, 1.0) * math.log(max(n, 2.0)), 1.0]


def nnls_numpy(A, b, max_iter=None):
    """Lawson-Hanson active-set NNLS: min ||Ax - b|| subject to x >= 0."""
    m, p = A.shape
    x = np.zeros(p)
    passive = np.zeros(p, dtype=bool)
    w = A.T @ (b - A @ x)
    tol = 10 * np.finfo(float).eps * np.linalg.norm(A, 1) * max(m, p)
    max_iter = max_iter or 3 * p
    it = 0
    while (~passive).any() and w[~passive].max() > tol and it < max_iter:
        it += 1
        j = np.argmax(np.where(passive, -np.inf, w))
        passive[j] = True
        while True:
            s = np.zeros(p)
            s[passive] = np.linalg.lstsq(A[:, passive], b, rcond=None)[0]
            if s[passive].min() > 0:
                break
            mask = passive & (s <= 0)
            alpha = np.min(x[mask] / (x[mask] - s[mask]))
            x = x + alpha * (s - x)
            passive &= x > tol
            x[~passive] = 0
        x = s
        w = A.T @ (b - A @ x)
    return x


def nnls(A, b):
    try:
        from scipy.optimize import nnls as sp_nnls
        return sp_nnls(A, b)[0], "scipy.optimize.nnls"
    except ImportError:
        return nnls_numpy(A, b), "numpy Lawson-Hanson"


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
    coef_scaled, solver = nnls(A, np.ones(len(t)))
    coef = coef_scaled / scale
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
            "points": len(pts), "solver": solver, "share_at": {"n": big["n"], "r": big["r"],
                                                               "k": big["k"]},
            "share": share}


def predict(fit, n, r, k):
    return float(np.array(design_row(n, r, k)) @ np.array(fit["coef"]))


def fit_groups(rows):
    """Fits per variant and per (variant, family, weights): {label: fit}."""
    out = {}
    variants = sorted({r["variant"] for r in rows})
    for v in variants:
        vr = [r for r in rows if r["variant"] == v]
        f = fit_rows(vr)
        if f:
            out[v] = f
        for fam in sorted({r["family"] for r in vr}):
            for w in sorted({r["weights"] for r in vr if r["family"] == fam}):
                f = fit_rows([r for r in vr if r["family"] == fam and r["weights"] == w])
                if f:
                    out[v + "/" + fam + "/" + w] = f
    return out


def format_fits(fits):
    lines = []
    if not fits:
        return "no group has 3 or more ok runs with a time: nothing to fit\n"
    solver = next(iter(fits.values()))["solver"]
    lines.append("model: time = c1 n^2 + c2 r^3/k + c3 n r log n + c0  (NNLS, relative "
                 "error, %s)" % solver)
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
    ap.add_argument("--json", help="also write the fits as JSON")
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
