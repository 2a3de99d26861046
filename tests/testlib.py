"""testlib.py: what the Python tests share (tests/test_outputs.py,
tests/test_degenerate.py, tests/test_cgal_agreement.py).

  ROOT, DATA                    the repository and tests/data
  WSKEL, WSKEL_GEN, WSKEL_CGAL  bin/wskel, bin/wskel-gen, bin/wskel-cgal, or
                                what WSKEL_BIN, WSKEL_GEN_BIN, WSKEL_CGAL_BIN say
  have(), need()                a program is built; skip the test unless (fail
                                unless, when CI=true: in CI nothing is skipped)
  run()                         a command with a time limit: (exit, stdout, stderr)
  wskel(), wskel_json()         bin/wskel with arguments; its JSON output parsed
  list_counters()               what `bin/wskel --list-counters --variant V` prints
  parse_wpoly(), read_wpoly(), write_wpoly()   .wpoly text and files
  cs                            scripts/compare_skeletons.py
  same_skeleton()               two wskel-1 skeletons of one polygon compared as
                                tests/helpers.h's same_skeleton (merging)
  Tally                         pass/fail counts of a test's cases: one summary
                                line on stderr, one failure naming them all

Import it from a test with
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import testlib
"""

import collections
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data")
WSKEL = os.environ.get("WSKEL_BIN", os.path.join(ROOT, "bin", "wskel"))
WSKEL_GEN = os.environ.get("WSKEL_GEN_BIN", os.path.join(ROOT, "bin", "wskel-gen"))
WSKEL_CGAL = os.environ.get("WSKEL_CGAL_BIN", os.path.join(ROOT, "bin", "wskel-cgal"))
TIMEOUT = 120  # seconds for one program run: a hang is a failure, not a wait

__all__ = ["ROOT", "DATA", "WSKEL", "WSKEL_GEN", "WSKEL_CGAL", "TIMEOUT", "have", "in_ci", "need",
           "run", "wskel", "wskel_json", "list_counters", "parse_wpoly", "read_wpoly",
           "write_wpoly", "cs",
           "same_skeleton", "Tally"]

sys.path.insert(0, os.path.join(ROOT, "scripts"))
import compare_skeletons as cs  # noqa: E402,F401


# ------------------------------------------------------------ programs

def have(path):
    """The program at path is built (a file we may execute)."""
    return os.path.isfile(path) and os.access(path, os.X_OK)


def in_ci():
    """CI=true in the environment (.ci/run exports it; so do GitHub Actions)."""
    return os.environ.get("CI", "").lower() == "true"


def need(*paths):
    """Skip the calling test (or class, from setUpClass) unless every program
    exists; the message names the missing ones.  With CI=true a missing
    program fails the test instead: a CI run that skips its checks passes on
    nothing."""
    missing = [os.path.relpath(p, ROOT) for p in paths if not have(p)]
    if missing:
        if in_ci():
            raise AssertionError("not built: %s (CI=true: a missing program is a failure, "
                                 "not a skip; .ci/install-deps installs what it needs, then make)"
                                 % ", ".join(missing))
        raise unittest.SkipTest("not built yet: %s (run make)" % ", ".join(missing))


def run(cmd, timeout=TIMEOUT, stdin=None):
    """(exit code, stdout, stderr) of cmd; exit code None if it ran out of time."""
    try:
        p = subprocess.run(cmd, input=stdin, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return None, "", "timed out after %d s" % timeout


def wskel(args, variant=None, timeout=TIMEOUT):
    """bin/wskel [--variant V] ARGS: (exit code, stdout, stderr)."""
    return run([WSKEL] + (["--variant", variant] if variant else []) + list(args), timeout)


def wskel_json(args, variant=None, timeout=TIMEOUT):
    """bin/wskel's JSON skeleton on stdout: (exit code, document or None,
    stderr).  args name the input and any options but -o and --format."""
    rc, out, err = wskel(["--format", "json"] + list(args), variant, timeout)
    return rc, (json.loads(out) if rc == 0 else None), err


def list_counters(variant=None):
    """[(name, meaning)] of `bin/wskel --list-counters [--variant V]`: the
    counters a run of V reports (the keys of the JSON stats, with time_s and
    peak_bytes).  Raises AssertionError on a failure or a malformed line."""
    rc, out, err = wskel(["--list-counters"], variant)
    if rc != 0:
        raise AssertionError("wskel --list-counters --variant %s: exit %s: %s"
                             % (variant, rc, err.strip()))
    rows = []
    for line in out.splitlines():
        m = re.fullmatch(r"([a-z][a-z0-9_]*)\t(\S.*)", line)
        if not m:
            raise AssertionError("--list-counters --variant %s: line %r is not name<TAB>meaning"
                                 % (variant, line))
        rows.append((m.group(1), m.group(2)))
    return rows


# ------------------------------------------------------------ polygons

def parse_wpoly(text, name="<text>"):
    """(points, weights, comment lines) of .wpoly text in input order.  '#'
    lines (kept as comments) and blank lines are ignored, the first other
    line is n, then n lines 'x y [w]' (w, default 1, weights the edge to the
    next vertex).  ValueError, naming `name`, if malformed."""
    pts, ws, comments, n = [], [], [], None
    for line in text.splitlines():
        s = line.strip()
        if not s:
            continue
        if s.startswith("#"):
            comments.append(s[1:].strip())
            continue
        if n is None:
            n = int(s)
            continue
        v = [float(c) for c in s.split()]
        if len(v) not in (2, 3):
            raise ValueError("%s: line %r is not 'x y [w]'" % (name, s))
        pts.append((v[0], v[1]))
        ws.append(v[2] if len(v) > 2 else 1.0)
    if n is None or n != len(pts):
        raise ValueError("%s: header says %s vertices, found %d" % (name, n, len(pts)))
    return pts, ws, comments


def read_wpoly(path):
    """(points, weights) of the .wpoly file at path (parse_wpoly)."""
    with open(path) as f:
        pts, ws, _ = parse_wpoly(f.read(), path)
    return pts, ws


def write_wpoly(path, pts, ws=None, comment=None):
    """Write pts (and the weights ws, if any) as .wpoly, every number with 17
    significant digits (integers stay integers), after a '# comment' line."""
    with open(path, "w") as f:
        if comment:
            f.write("# %s\n" % comment)
        f.write("%d\n" % len(pts))
        for i, (x, y) in enumerate(pts):
            if ws:
                f.write("%.17g %.17g %.17g\n" % (x, y, ws[i]))
            else:
                f.write("%.17g %.17g\n" % (x, y))
    return path


# ---------------------------------------------------------- sweeps

def variant_outcome(wskel_bin, variant, path, naive_out, refused=None, timeout=60):
    """One sweep case: run `wskel --variant VARIANT --check --stats PATH` and
    classify it against naive's output naive_out (its JSON text): "timeout",
    "unsupported" (exit 2 with the text refused in the message), "fail (exit
    N)", "fallback" (the reference answered: not compared), "ok" or "mismatch"
    (same_skeleton).  The far-vertex sweeps' shared step."""
    rc, out, err = run([wskel_bin, "--variant", variant, "--check", "--stats", path],
                       timeout=timeout)
    if rc is None:
        return "timeout"
    if rc == 2 and refused and refused in err:
        return "unsupported"
    if rc != 0:
        return "fail (exit %d)" % rc
    got = json.loads(out)
    if int((got.get("stats") or {}).get("reference_fallbacks", 0)):
        return "fallback"
    ok, _ = same_skeleton(json.loads(naive_out), got)
    return "ok" if ok else "mismatch"


def sweep_report(header, groups, counts, width, bad, list_bad):
    """Print a sweep's summary (the far-vertex sweeps'): the header line, one
    line per group of its outcome counts (counts[group][outcome]), then with
    list_bad the failing cases (name, outcome)."""
    print(header)
    for g in groups:
        print("%-*s %s" % (width, g, ", ".join("%s %d" % kv
                                                for kv in sorted(counts.get(g, {}).items()))))
    if list_bad:
        for name, key in bad:
            print("  %s: %s" % (name, key))


# ---------------------------------------------------------- comparison

def same_skeleton(a, b, tol=None, tol_t=None, weights=None):
    """Are the wskel-1 skeleton dicts a and b (of one polygon) the same
    skeleton?  Returns (True, "") or (False, the first difference).

    As same_skeleton of tests/helpers.h with merge = true (the C sweeps'
    oracle): the input vertices (the first n nodes) must coincide within tol
    with t = 0 on both sides; any two nodes, of either skeleton, within tol
    in x and in y and within tol_t in t are one node, transitively; arcs whose
    ends fall into one node are dropped; the others, as (node, node, left
    face, right face) with the ends in a fixed order, must be equal
    multisets.  Unlike scripts/compare_skeletons.py, nodes at one place but
    at different times stay apart (a nearly regular polygon has many nodes
    within tol of its centre whose times differ by more than tol).
    Defaults: tol = 1e-7 * the input's bounding-box diagonal, but at least
    64 ulps of the largest coordinate; tol_t = tol (the JSON has no weights:
    times err by position errors over the weight, so pass tol / the smallest
    weight when weights go below 1).  weights (one per input edge, as
    sk_match.P of tests/same_skeleton.h): two nodes' time tolerance is
    tol_t over the smallest weight of the faces at either node."""
    na, nb = a["n"], b["n"]
    if na != nb:
        return False, "%d vs %d input vertices" % (na, nb)
    n = na
    A, B = a["nodes"], b["nodes"]
    if tol is None:
        xs = [p[0] for p in A[:n]]
        ys = [p[1] for p in A[:n]]
        mag = max(max(abs(v) for v in xs), max(abs(v) for v in ys))
        tol = max(1e-7 * math.hypot(max(xs) - min(xs), max(ys) - min(ys)), 64 * mag * 2.0 ** -52)
    if tol_t is None:
        tol_t = tol
    for j in range(n):
        p, q = A[j], B[j]
        if not (abs(p[0] - q[0]) <= tol and abs(p[1] - q[1]) <= tol and p[2] == q[2] == 0):
            return False, "input vertex %d: (%.17g, %.17g, t %g) vs (%.17g, %.17g, t %g)" % (
                j, p[0], p[1], p[2], q[0], q[1], q[2])
    nodes = list(A) + list(B)
    off = len(A)
    par = list(range(len(nodes)))
    nw = [1.0] * len(nodes)
    if weights is not None:
        pos = [w for w in weights if w > 0]
        wmin = min(pos) if pos else 1.0
        nw = [math.inf] * len(nodes)
        for S, o in ((a, 0), (b, off)):
            for u, v, left, right in S["arcs"]:
                w = min([weights[f] for f in (left, right) if 0 <= f < len(weights)
                         and weights[f] > 0] or [math.inf])
                nw[u + o] = min(nw[u + o], w)
                nw[v + o] = min(nw[v + o], w)
        nw = [wmin if math.isinf(w) else w for w in nw]

    def find(x):
        while par[x] != x:
            par[x] = par[par[x]]
            x = par[x]
        return x
    for j in range(n):
        par[off + j] = j
    cells = {}
    for i, (x, y, t) in enumerate(nodes):
        kx, ky = (math.floor(x / tol), math.floor(y / tol)) if tol > 0 else (x, y)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for k in cells.get((kx + dx, ky + dy), ()):
                    q = nodes[k]
                    if (abs(q[0] - x) <= tol and abs(q[1] - y) <= tol
                            and abs(q[2] - t) <= tol_t / min(nw[i], nw[k])):
                        ri, rk = find(i), find(k)
                        if ri != rk:
                            par[max(ri, rk)] = min(ri, rk)
        cells.setdefault((kx, ky), []).append(i)

    def arcs(S, o):
        out = []
        for u, v, left, right in S["arcs"]:
            cu, cv = find(u + o), find(v + o)
            if cu == cv:
                continue
            out.append((cu, cv, left, right) if cu <= cv else (cv, cu, right, left))
        return sorted(out)
    xa, xb = arcs(a, 0), arcs(b, off)
    if xa == xb:
        return True, ""
    ca, cb = collections.Counter(xa), collections.Counter(xb)
    only_a, only_b = list((ca - cb).elements()), list((cb - ca).elements())

    def show(arc):
        u, v, left, right = arc
        p, q = nodes[u], nodes[v]
        return "(%.9g, %.9g, t %.9g) - (%.9g, %.9g, t %.9g) faces %d | %d" % (
            p[0], p[1], p[2], q[0], q[1], q[2], left, right)
    why = "%d arcs only in A, %d only in B (tol %.3g, tol_t %.3g; %d vs %d arcs after merging)" % (
        len(only_a), len(only_b), tol, tol_t, len(xa), len(xb))
    if only_a:
        why += "; first only in A: " + show(only_a[0])
    if only_b:
        why += "; first only in B: " + show(only_b[0])
    return False, why


# ------------------------------------------------------------- verdicts

class Tally:
    """The cases of one test: how many passed, the failure lines of the others
    (their inputs copied aside for replay), and those not compared and why.

        t = Tally("degenerate files")
        for ...:
            t.case(fails, path)        # fails: [] if the case passed
        t.report(self)                 # summary on stderr; fails the test
    """

    def __init__(self, what):
        self.what = what
        self.cases = 0
        self.passed = 0
        self.failures = []
        self.skipped = {}  # kind -> [why]
        self.keep = None  # directory of the failing inputs, made on the first

    def case(self, failures=(), path=None):
        """One case with its failure lines (none: it passed); a failing case's
        input at path is copied to self.keep at once (later cases may reuse
        the file)."""
        self.cases += 1
        if not failures:
            self.passed += 1
            return
        self.failures.extend(failures)
        if path and os.path.exists(path):
            if self.keep is None:
                self.keep = tempfile.mkdtemp(prefix="wskel-fail-")
            shutil.copy(path, os.path.join(self.keep, "%03d-%s" % (self.cases,
                                                                    os.path.basename(path))))

    def skip(self, why, kind="skipped"):
        """A case not compared, for a reason that is no failure (kind groups
        them in the summary)."""
        self.skipped.setdefault(kind, []).append(why)

    def summary(self, detail=""):
        notes = ["%d %s: %s" % (len(w), kind, w[0]) for kind, w in self.skipped.items()]
        return "%s: %d/%d passed%s%s" % (self.what, self.passed, self.cases,
                                         " (%s)" % detail if detail else "",
                                         "; " + "; ".join(notes) if notes else "")

    def report(self, test, detail="", limit=20, hint=None, list_skipped=()):
        """Print the summary to stderr, and every entry of the skip kinds in
        list_skipped (e.g. the skipped inputs, so none is skipped silently);
        fail `test` with the first `limit` failure lines if there are any
        (and where their inputs are kept)."""
        print(self.summary(detail), file=sys.stderr)
        for kind in list_skipped:
            if self.skipped.get(kind):
                print("  %s: %d: %s" % (kind, len(self.skipped[kind]),
                                        "; ".join(self.skipped[kind])), file=sys.stderr)
        if not self.failures:
            return
        lines = ["%s: %d of %d cases failed%s" % (
            self.what, self.cases - self.passed, self.cases,
            "; inputs kept in %s" % self.keep if self.keep else "")]
        lines += ["  " + f for f in self.failures[:limit]]
        if len(self.failures) > limit:
            lines.append("  ... %d more" % (len(self.failures) - limit))
        if hint:
            lines.append(hint)
        test.fail("\n".join(lines))
