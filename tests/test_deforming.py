#!/usr/bin/python3
"""test_deforming.py: the deforming-polygon variant (paper 004) against naive.

Every generator family (bin/wskel-gen --list, holes and coastline included),
n from 16 to WSKEL_DEFORMING_MAX_N (default 1,000; the full sweep of the
issue sets 2,000), unit and random (uniform 0.5..2, integer 1..4) weights,
WSKEL_DEFORMING_SEEDS seeds: bin/wskel --variant deforming --check must pass
and give naive's skeleton (testlib.same_skeleton).  An input the variant
hands to the reference (reference_fallbacks) is counted as not compared, and
the sweep fails if more than one in 20 is.  The step: the skeleton must not
depend on the predictor's increment, so the first increment halved and
doubled (--step 0.5, --step 2), and made 1000 times smaller and larger, must
give the same skeleton, and the small one must take more steps (so the
option reached the variant; a large first increment is cut back to the
event spacing at the first event, so its count may not change).
"""

import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import testlib as tl  # noqa: E402

MAX_N = int(os.environ.get("WSKEL_DEFORMING_MAX_N", "1000"))
SEEDS = int(os.environ.get("WSKEL_DEFORMING_SEEDS", "1"))
NS = [n for n in (16, 64, 256, 1000, 2000) if n <= MAX_N]
WEIGHTS = ("unit", "uniform", "int")


def families():
    rc, out, _ = tl.run([tl.WSKEL_GEN, "--list"])
    assert rc == 0
    return [line.split()[0] for line in out.splitlines() if line.strip()]


def stat(got, name):
    return int((got.get("stats") or {}).get(name, 0) or 0)


class Deforming(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        tl.need(tl.WSKEL)
        tl.need(tl.WSKEL_GEN)
        cls.tmp = tempfile.mkdtemp(prefix="wskel-deforming-")

    def gen(self, fam, n, seed, weights, extra=()):
        path = os.path.join(self.tmp, "%s-%d-%d-%s.wpoly" % (fam, n, seed, weights))
        rc, _, _ = tl.run([tl.WSKEL_GEN, fam, "--n", str(n), "--seed", str(seed),
                           "--weights", weights, "-o", path] + list(extra))
        return path if rc == 0 else None

    def deforming(self, path, *extra):
        rc, out, err = tl.run([tl.WSKEL, "--variant", "deforming", "--check", "--stats"]
                              + list(extra) + [path])
        return rc, (tl.json.loads(out) if rc == 0 else None), err

    def compare(self, t, name, path, weighted):
        rc, out_n, err_n = tl.run([tl.WSKEL, "--check", path])
        if rc != 0:
            t.case(["%s: naive exit %s: %s" % (name, rc, err_n.strip()[:200])], path)
            return
        rc, got, err = self.deforming(path)
        if rc != 0:
            t.case(["%s: deforming exit %s: %s" % (name, rc, err.strip()[:200])], path)
            return
        if stat(got, "reference_fallbacks"):
            t.skip(name, "handed to the reference variant (not compared)")
            return
        ref = tl.json.loads(out_n)
        # times err by position errors over the weight: weights go down to 0.5
        ok, why = tl.same_skeleton(ref, got) if not weighted else self.same_weighted(ref, got)
        t.case([] if ok else ["%s: differs from naive: %s" % (name, why[:200])], path)

    @staticmethod
    def same_weighted(a, b):
        ok, why = tl.same_skeleton(a, b)
        if ok:
            return ok, why
        xs = [p[0] for p in a["nodes"][:a["n"]]]
        ys = [p[1] for p in a["nodes"][:a["n"]]]
        tol = 1e-7 * tl.math.hypot(max(xs) - min(xs), max(ys) - min(ys))
        return tl.same_skeleton(a, b, tol=tol, tol_t=2 * tol)

    def test_families(self):
        t = tl.Tally("deforming vs naive, every family")
        for fam in families():
            for n in NS:
                for w in WEIGHTS:
                    for seed in range(1, SEEDS + 1):
                        extra = ["--holes", str(max(1, n // 60))] if fam == "holes" else []
                        path = self.gen(fam, n, seed, w, extra)
                        if path is None:
                            t.skip("%s n=%d" % (fam, n), "impossible parameters")
                            continue
                        self.compare(t, "%s n=%d %s seed %d" % (fam, n, w, seed), path, w != "unit")
        t.report(self, list_skipped=["handed to the reference variant (not compared)"])
        fallbacks = len(t.skipped.get("handed to the reference variant (not compared)", []))
        self.assertGreaterEqual(t.cases, len(NS) * SEEDS * len(WEIGHTS) * 8, t.summary())
        self.assertLessEqual(20 * fallbacks, t.cases + fallbacks, t.summary())

    def test_step_does_not_matter(self):
        t = tl.Tally("deforming: --step 0.5 and 2 against 1")
        for fam, n, w in (("star", 200, "unit"), ("random", 200, "uniform"), ("comb", 120, "int"),
                          ("rectilinear", 120, "unit"), ("holes", 150, "unit"),
                          ("coastline", 200, "uniform"), ("crossing", 100, "unit")):
            extra = ["--holes", "3"] if fam == "holes" else []
            path = self.gen(fam, n, 1, w, extra)
            self.assertIsNotNone(path)
            rc, base, err = self.deforming(path)
            self.assertEqual(rc, 0, err)
            for step in ("0.5", "2", "0.001", "1000"):
                rc, got, err = self.deforming(path, "--step", step)
                name = "%s n=%d %s --step %s" % (fam, n, w, step)
                if rc != 0:
                    t.case(["%s: exit %s: %s" % (name, rc, err.strip()[:200])], path)
                    continue
                fails = []
                if stat(got, "reference_fallbacks") != stat(base, "reference_fallbacks"):
                    fails.append("%s: a reference fallback with one step only" % name)
                if stat(got, "steps") == stat(base, "steps") and step == "0.001":
                    fails.append("%s: the same number of steps (%d): --step had no effect"
                                 % (name, stat(got, "steps")))
                ok, why = self.same_weighted(base, got)
                if not ok:
                    fails.append("%s: differs from --step 1: %s" % (name, why[:200]))
                t.case(fails, path)
        t.report(self)
        self.assertEqual(t.cases, 7 * 4)

    def test_weighted_rectangle_is_answered_by_the_variant(self):
        path = os.path.join(self.tmp, "rect.wpoly")
        tl.write_wpoly(path, [(0, 0), (4, 0), (4, 2), (0, 2)], [1, 0.5, 1, 2])
        rc, got, err = self.deforming(path)
        self.assertEqual(rc, 0, err)
        self.assertEqual(stat(got, "reference_fallbacks"), 0)


if __name__ == "__main__":
    unittest.main()
