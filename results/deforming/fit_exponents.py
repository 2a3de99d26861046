#!/usr/bin/python3
"""fit_exponents.py: the exponents of results/deforming/README.md from a
wskel-bench CSV: per variant and family, the least-squares slope of log
cpu_s and of log peak_tracked_bytes on log n (scripts/results.py,
loglog_slope) over the ok runs with n >= 1000 (n = 100 rounds to 0 s of
CPU), also over 10^3 .. 3*10^4 alone, and each run's reference_fallbacks.

usage: fit_exponents.py CSV..."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from results import load_csv, loglog_slope  # noqa: E402

for path in sys.argv[1:]:
    comments, rows = load_csv(path)
    for c in comments:
        if c.startswith("qsort_ref_s"):
            print(path, c)
    keys = []
    for r in rows:
        if (r["variant"], r["family"]) not in keys:
            keys.append((r["variant"], r["family"]))
    for k in keys:
        rs = [r for r in rows if (r["variant"], r["family"]) == k]
        ok = [r for r in rs if r["status"] == "ok" and r["n"] >= 1000]
        print("%-10s %-8s" % k, " ".join(
            "n=%d %s cpu %.3gs %d B/vertex fallbacks %s" % (
                r["n"], r["status"], r["cpu_s"] or 0, (r["peak_tracked_bytes"] or 0) // r["n"],
                r.get("reference_fallbacks")) for r in rs))
        for lo, hi in ((1000, 10 ** 9), (1000, 30000)):
            sel = [r for r in ok if lo <= r["n"] <= hi]
            print("    n %d..%s: cpu exponent %.2f, memory exponent %.2f" % (
                lo, "top" if hi > 10 ** 8 else hi,
                loglog_slope([r["n"] for r in sel], [r["cpu_s"] for r in sel]),
                loglog_slope([r["n"] for r in sel], [r["peak_tracked_bytes"] for r in sel])))
