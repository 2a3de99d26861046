#!/usr/bin/python3
"""test_exact_nodes.py: nodes against the exact meeting of their offset lines.

Every node where exactly three faces meet must lie where the three faces'
offset lines meet (w_i t = signed distance to edge i), solved in 80-digit
decimal arithmetic (tests/exact_nodes.py), within 1e-9 of the diagonal
(eps_d).  The inputs are ones where a node was once far off its lines'
meeting while within tolerance of them: the weighted comb with a spike,
where the engine merged a stretch that shrinks slowly and ended the spike
141 units (2e-5 diagonals) from the exact node.  Naive, arrangement and
monotone (its fallback) are checked; deforming is not (tests/data/fuzz/KNOWN).
"""
import os
import sys
import tempfile
import unittest
from decimal import Decimal

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact_nodes  # noqa: E402
import testlib as tl  # noqa: E402

FILES = ["fuzz/mismatch_deforming_weighted_comb_spike.wpoly"]
VARIANTS = ["naive", "arrangement", "monotone"]


class ExactNodes(unittest.TestCase):
    def test_three_face_nodes_are_exact(self):
        tl.need(tl.WSKEL)
        checked = 0
        with tempfile.TemporaryDirectory(prefix="wskel-exact-") as work:
            for rel in FILES:
                poly = os.path.join(tl.DATA, rel)
                for v in VARIANTS:
                    with self.subTest(file=rel, variant=v):
                        out = os.path.join(work, v + ".json")
                        rc, _, err = tl.wskel(["--check", "-o", out, poly], variant=v)
                        self.assertEqual(rc, 0, err)
                        n, worst, bad = exact_nodes.check(poly, out, Decimal("1e-9"))
                        checked += n
                        self.assertGreater(n, 0)
                        self.assertEqual(bad, [], "%s %s: worst %.3g diagonals off" % (rel, v, worst))
        print("exact nodes: %d three-face nodes of %d files x %d variants within 1e-9 diagonals"
              % (checked, len(FILES), len(VARIANTS)), file=sys.stderr)


if __name__ == "__main__":
    unittest.main()
