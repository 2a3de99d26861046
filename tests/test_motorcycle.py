#!/usr/bin/python3
"""test_motorcycle.py: the motorcycle variant (paper 002) against naive.

Every generator family (bin/wskel-gen --list, the coastline and holes
families included), n from 16 to 2,000 (WSKEL_MOTORCYCLE_MAX_N), unit
weights, several seeds: bin/wskel --variant motorcycle --check must pass and
give naive's skeleton (testlib.same_skeleton).  Small cases run with
--check-invariants too (the finder's and the wavefront's invariants after
every group).  The variant takes equal weights only: a weighted polygon is
refused with exit 2 and a message naming the edge, never answered.  An input
the variant hands to the reference (reference_fallbacks) is counted as not
compared.  A sweep that compared too little fails (the minimum is asserted).
"""

import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import testlib as tl  # noqa: E402

MAX_N = int(os.environ.get("WSKEL_MOTORCYCLE_MAX_N", "2000"))
SEEDS = int(os.environ.get("WSKEL_MOTORCYCLE_SEEDS", "3"))
NS = [n for n in (16, 64, 256, 1000, 2000) if n <= MAX_N]
INVARIANTS_MAX_N = 256
# Files the variant handed to the reference before a fix (test_own_answer_files)
OWN_ANSWER_FILES = [
    # two reflex vertices 5e-11 apart: their motorcycles crashed at their
    # origin, each waiting for the other (motorcycle.c, extend_origin_crashes)
    "tests/data/degenerate/mc_origin_crash_tiny_edge.wpoly",
    # a ghost whose B met F at the notched family's hub left a trace waiting
    # at its end (motorcycle.c, mc_process_next, MC_DONE)
    "tests/data/degenerate/mc_hub_ghost_done.wpoly",
    # two needle valleys' motorcycles crossing 8.3e-10 apart (eps_t 1.1e-9) at
    # speed 9.5e4: one simultaneous group ended the first one's trace 120
    # units short of its reflex arc (motorcycle_graph.c, sequential; star
    # n = 10^6 seed 1 reduced)
    "tests/data/degenerate/mc_fast_valleys_near_simultaneous.wpoly",
    # a trace grazing a wall vertex 1.2e-6 away (eps_d 1.3e-6): the shot
    # placing F missed both of its pieces and put F beyond the trace's end
    # (motorcycle.c, wall_vertex_piece; star n = 10^6 seed 1 reduced)
    "tests/data/degenerate/mc_wall_vertex_grazed.wpoly",
]


def families():
    rc, out, _ = tl.run([tl.WSKEL_GEN, "--list"])
    assert rc == 0
    return [line.split()[0] for line in out.splitlines() if line.strip()]


class Motorcycle(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        tl.need(tl.WSKEL)
        tl.need(tl.WSKEL_GEN)
        cls.tmp = tempfile.mkdtemp(prefix="wskel-motorcycle-")

    def gen(self, fam, n, seed, extra=()):
        path = os.path.join(self.tmp, "%s-%d-%d.wpoly" % (fam, n, seed))
        rc, _, _ = tl.run([tl.WSKEL_GEN, fam, "--n", str(n), "--seed", str(seed), "-o", path]
                          + list(extra))
        return path if rc == 0 else None

    def compare(self, t, name, path, invariants):
        rc, out_n, err_n = tl.run([tl.WSKEL, "--check", path])
        if rc != 0:
            t.case(["%s: naive exit %s: %s" % (name, rc, err_n.strip()[:200])], path)
            return
        args = [tl.WSKEL, "--variant", "motorcycle", "--check", "--stats", path]
        if invariants:
            args.insert(1, "--check-invariants")
        rc, out, err = tl.run(args)
        if rc != 0:
            t.case(["%s: motorcycle exit %s: %s" % (name, rc, err.strip()[:200])], path)
            return
        got = tl.json.loads(out)
        if int((got.get("stats") or {}).get("reference_fallbacks", 0) or 0):
            # the trace finder gave up and naive answered: naive vs naive
            t.skip(name, "handed to the reference variant (not compared)")
            return
        ok, why = tl.same_skeleton(tl.json.loads(out_n), got)
        t.case([] if ok else ["%s: differs from naive: %s" % (name, why[:200])], path)

    def test_families(self):
        t = tl.Tally("motorcycle vs naive, every family")
        for fam in families():
            for n in NS:
                for seed in range(1, SEEDS + 1):
                    extra = ["--holes", str(max(1, n // 60))] if fam == "holes" else []
                    path = self.gen(fam, n, seed, extra)
                    if path is None:
                        t.skip("%s n=%d seed %d" % (fam, n, seed), "impossible parameters")
                        continue
                    self.compare(t, "%s n=%d seed %d" % (fam, n, seed), path,
                                 n <= INVARIANTS_MAX_N)
        t.report(self, list_skipped=["handed to the reference variant (not compared)"])
        self.assertGreaterEqual(t.cases, len(NS) * SEEDS * 8, t.summary())

    def test_convex_with_holes(self):
        t = tl.Tally("motorcycle vs naive, convex polygons with holes")
        for n, h in ((40, 3), (200, 12)):
            for seed in range(1, SEEDS + 1):
                path = self.gen("convex", n, seed, ["--holes", str(h)])
                self.assertIsNotNone(path)
                self.compare(t, "convex n=%d holes %d seed %d" % (n, h, seed), path, n <= 64)
        t.report(self)
        self.assertEqual(t.cases, 2 * SEEDS)

    def test_own_answer_files(self):
        """Inputs the variant once handed to the reference: it must answer
        them itself (reference_fallbacks 0), with naive's skeleton."""
        t = tl.Tally("motorcycle answers itself (no reference fallback)")
        for f in OWN_ANSWER_FILES:
            path = os.path.join(tl.ROOT, f)
            self.assertTrue(os.path.exists(path), path)
            rc, out, err = tl.run([tl.WSKEL, "--variant", "motorcycle", "--check", "--stats", path])
            if rc != 0:
                t.case(["%s: motorcycle exit %s: %s" % (f, rc, err.strip()[:200])], path)
                continue
            if int(tl.json.loads(out)["stats"]["reference_fallbacks"]):
                t.case(["%s: handed to the reference variant" % f], path)
                continue
            self.compare(t, f, path, True)
        t.report(self)
        self.assertEqual(t.cases, len(OWN_ANSWER_FILES), t.summary())

    def test_weighted_is_refused(self):
        path = self.gen("star", 50, 1, ["--weights", "int"])
        self.assertIsNotNone(path)
        rc, out, err = tl.run([tl.WSKEL, "--variant", "motorcycle", path])
        self.assertEqual(rc, 2, err)
        self.assertIn("equal weights only", err)
        self.assertEqual(out, "", "no skeleton for a refused input")


if __name__ == "__main__":
    unittest.main()
