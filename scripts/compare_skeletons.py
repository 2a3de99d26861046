#!/usr/bin/python3
"""compare_skeletons.py: are two wskel-1 skeletons of one polygon the same?

    compare_skeletons.py A.json B.json [--tol T] [--verbose]

Exit 0 if they agree within the tolerance, 1 if they differ, 2 on usage or
parse errors (unreadable file, not wskel-1, different polygons).

Two correct programs may describe one skeleton differently, so each side is
normalised before the comparison:

  * nodes whose positions coincide within tol are merged (union-find over a
    grid of cell size tol).  CGAL, for one, represents a vertex event where
    more than three arcs meet as several nodes joined by zero-length arcs;
    wskel writes one node;
  * arcs whose ends fall into one merged node (zero-length arcs) are dropped;
  * every other arc becomes the unordered pair of its merged ends plus its
    pair of faces.

Merged nodes of A are then matched to merged nodes of B by position (some
member of one within tol of some member of the other; the nearest
representative wins), and the arcs are compared as multisets.  Reported:
arcs only in A, arcs only in B, face-label mismatches (same ends, different
{left, right}, or the same faces on the wrong sides), time mismatches
(matched nodes whose t differ by more than their time tolerance, or a
merged node whose members disagree in t by more than it) and counts.

The default tolerance is 1e-7 times the diagonal of the bounding box of the
input vertices (the first n nodes), loose next to wskel's own 1e-9 policy
because CGAL's Exact_predicates_inexact_constructions_kernel constructs
event points in plain doubles.

Times are compared weight-aware: the offset line of edge e moves at speed
w(e), so a node whose position errs by tol has a time that errs by up to
tol / w over the weights w of its faces.  A node's time tolerance is tol
divided by the smallest weight of the faces at it (the left and right faces
of its arcs; nodes merged into one or matched with each other: the smallest
over all of them).  wskel-1 files carry no weights, so each face's weight is
read off the skeleton itself: the distance of its latest node (largest t)
from the face's input edge line, over that node's t (the smaller estimate
of A's and B's).  For unit weights that is 1, and the time tolerance tol,
as before.  compare(..., weights=[w per input edge]) gives them instead.

Import it to compare dicts: compare(a, b, tol=None, weights=None) ->
CompareResult.  Stdlib only.
"""

import argparse
import json
import math
import sys
from collections import defaultdict

__all__ = ["CompareResult", "SkeletonError", "compare", "default_tol", "face_weights", "load",
           "main"]


class SkeletonError(ValueError):
    """The input is not a usable wskel-1 skeleton (exit code 2)."""


class CompareResult:
    """What compare() found.  identical is the verdict; the lists hold the
    evidence, each entry a dict with positions, faces and times so that a
    message can name the place."""

    def __init__(self, tol):
        self.tol = tol
        self.only_a = []          # arcs of A with no counterpart in B
        self.only_b = []
        self.face_mismatches = [] # same merged ends, different faces
        self.time_mismatches = [] # matched nodes with different t, or a merged node with mixed t
        self.nodes_only_a = []    # merged nodes of A that match no node of B
        self.nodes_only_b = []
        self.counts = {}

    @property
    def identical(self):
        return not (self.only_a or self.only_b or self.face_mismatches or self.time_mismatches
                    or self.nodes_only_a or self.nodes_only_b)

    def summary(self):
        c = self.counts
        verdict = "identical" if self.identical else "DIFFERENT"
        return ("%s (tol %.3g): A %d nodes -> %d merged, %d arcs (%d zero-length); "
                "B %d nodes -> %d merged, %d arcs (%d zero-length); %d arcs matched; "
                "only in A %d, only in B %d, face mismatches %d, time mismatches %d, "
                "unmatched nodes A %d B %d"
                % (verdict, self.tol, c.get("nodes_a", 0), c.get("merged_a", 0),
                   c.get("arcs_a", 0), c.get("zero_arcs_a", 0), c.get("nodes_b", 0),
                   c.get("merged_b", 0), c.get("arcs_b", 0), c.get("zero_arcs_b", 0),
                   c.get("matched_arcs", 0), len(self.only_a), len(self.only_b),
                   len(self.face_mismatches), len(self.time_mismatches),
                   len(self.nodes_only_a), len(self.nodes_only_b)))

    def details(self, limit=None):
        """Human-readable lines, at most limit per category (None: all)."""
        out = []

        def section(title, items, fmt):
            if not items:
                return
            out.append("%s: %d" % (title, len(items)))
            for it in items[:limit] if limit is not None else items:
                out.append("  " + fmt(it))
            if limit is not None and len(items) > limit:
                out.append("  ... %d more" % (len(items) - limit))

        def arc(it):
            return "(%s) -- (%s) faces {%s}" % (_fmt_pt(it["p"]), _fmt_pt(it["q"]),
                                                ",".join(str(f) for f in it["faces"]))

        section("arcs only in A", self.only_a, arc)
        section("arcs only in B", self.only_b, arc)
        section("face-label mismatches", self.face_mismatches,
                lambda it: "(%s) -> (%s): A left/right %s, B left/right %s"
                % (_fmt_pt(it["p"]), _fmt_pt(it["q"]), it["a"], it["b"]))
        section("time mismatches", self.time_mismatches,
                lambda it: "(%s): %s" % (_fmt_pt(it["p"]), it["what"]))
        section("merged nodes only in A", self.nodes_only_a,
                lambda it: "(%s) t=%.17g" % (_fmt_pt(it["p"]), it["t"]))
        section("merged nodes only in B", self.nodes_only_b,
                lambda it: "(%s) t=%.17g" % (_fmt_pt(it["p"]), it["t"]))
        return out


def _fmt_pt(p):
    return "%.17g, %.17g" % (p[0], p[1])


# ------------------------------------------------------------------ parsing

def _check(d, name):
    """Validate the parts of the contract the comparison relies on."""
    if not isinstance(d, dict):
        raise SkeletonError("%s: not a JSON object" % name)
    if d.get("format") != "wskel-1":
        raise SkeletonError("%s: format is %r, expected \"wskel-1\"" % (name, d.get("format")))
    n, nodes, arcs = d.get("n"), d.get("nodes"), d.get("arcs")
    if not isinstance(n, int) or n < 3:
        raise SkeletonError("%s: \"n\" must be an integer >= 3" % name)
    if not isinstance(nodes, list) or len(nodes) < n:
        raise SkeletonError("%s: \"nodes\" must be a list of at least n = %d nodes" % (name, n))
    if not isinstance(arcs, list):
        raise SkeletonError("%s: \"arcs\" must be a list" % name)
    pts = []
    for i, v in enumerate(nodes):
        if (not isinstance(v, list) or len(v) != 3
                or not all(isinstance(c, (int, float)) and math.isfinite(c) for c in v)):
            raise SkeletonError("%s: node %d must be [x, y, t] with finite numbers" % (name, i))
        pts.append((float(v[0]), float(v[1]), float(v[2])))
    out_arcs = []
    for i, e in enumerate(arcs):
        if (not isinstance(e, list) or len(e) != 4
                or not all(isinstance(c, int) and not isinstance(c, bool) for c in e)):
            raise SkeletonError("%s: arc %d must be [a, b, left, right] with integers" % (name, i))
        a, b, l, r = e
        if not (0 <= a < len(pts) and 0 <= b < len(pts)):
            raise SkeletonError("%s: arc %d refers to a missing node" % (name, i))
        # a PSLG's cap arcs (at its horizon) have the unswept side, -1
        lo = -1 if "pslg" in d else 0
        if not (lo <= l < n and lo <= r < n):
            raise SkeletonError("%s: arc %d has a face outside [%d, n)" % (name, i, lo))
        out_arcs.append((a, b, l, r))
    return n, pts, out_arcs


def load(path):
    """Read a wskel-1 JSON file into a dict; SkeletonError if that fails."""
    try:
        with open(path, "r", encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise SkeletonError("%s: cannot read: %s" % (path, e.strerror or e))
    except ValueError as e:
        raise SkeletonError("%s: not JSON: %s" % (path, e))


def default_tol(d):
    """1e-7 times the bounding-box diagonal of the input vertices of d, but at
    least 64 ulps of the largest coordinate magnitude."""
    n, pts, _ = _check(d, "skeleton")
    xs = [p[0] for p in pts[:n]]
    ys = [p[1] for p in pts[:n]]
    diag = math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    # Far from the origin the coordinates themselves carry absolute rounding
    # (ulp of the largest magnitude); every implementation's constructed
    # nodes inherit some tens of ulps of it, whatever its relative accuracy.
    mag = max(max(abs(v) for v in xs), max(abs(v) for v in ys))
    return max(1e-7 * diag, 64 * mag * 2.0 ** -52)


# ------------------------------------------------------------ weights

def _edge_ends(d, n):
    """(i, j) per input edge i: it runs from input vertex i to j, the next
    vertex of its ring ("rings" lists the ring sizes; one ring if absent)."""
    sizes = d.get("rings") or [n]
    if not (isinstance(sizes, list) and all(isinstance(k, int) and k >= 3 for k in sizes)
            and sum(sizes) == n):
        sizes = [n]
    ends, start = [], 0
    for k in sizes:
        ends += [(start + i, start + (i + 1) % k) for i in range(k)]
        start += k
    return ends


def face_weights(d):
    """The weight of each face (input edge) of skeleton dict d, estimated
    from its nodes: distance from the edge's line over t, at the face's node
    with the largest t > 0.  None where no node tells (or the estimate is not
    positive: a wall or overhang face)."""
    n, pts, arcs = _check(d, "skeleton")
    ends = _edge_ends(d, n)
    best = [None] * n   # (t, node) per face
    for a, b, l, r in arcs:
        for f in (l, r):
            if f < 0:
                continue
            for v in (a, b):
                t = pts[v][2]
                if t > 0 and (best[f] is None or t > best[f][0]):
                    best[f] = (t, v)
    out = []
    for f in range(n):
        if best[f] is None:
            out.append(None)
            continue
        t, v = best[f]
        (px, py, _), (qx, qy, _) = pts[ends[f][0]], pts[ends[f][1]]
        ln = math.hypot(qx - px, qy - py)
        if ln == 0:
            out.append(None)
            continue
        dist = ((qx - px) * (pts[v][1] - py) - (qy - py) * (pts[v][0] - px)) / ln
        w = abs(dist) / t
        out.append(w if w > 0 and math.isfinite(w) else None)
    return out


def _node_weights(n_nodes, arcs, weights):
    """Per node: the smallest known weight of the faces of its arcs; the
    smallest known weight overall for a node without one (1 if none)."""
    known = [w for w in weights if w is not None]
    fallback = min(known) if known else 1.0
    nw = [None] * n_nodes
    for a, b, l, r in arcs:
        for f in (l, r):
            w = weights[f] if f >= 0 else None
            if w is None:
                continue
            for v in (a, b):
                if nw[v] is None or w < nw[v]:
                    nw[v] = w
    return [fallback if w is None else w for w in nw]


# ------------------------------------------------------------ normalising

class _Grid:
    """Points hashed into square cells of side tol: every point within tol of
    a query lies in the query's cell or one of its eight neighbours."""

    def __init__(self, tol):
        self.tol = tol
        self.cells = defaultdict(list)

    def key(self, x, y):
        if self.tol > 0:
            return (math.floor(x / self.tol), math.floor(y / self.tol))
        return (x, y)

    def add(self, x, y, item):
        self.cells[self.key(x, y)].append(item)

    def near(self, x, y):
        kx, ky = self.key(x, y)
        if self.tol <= 0:
            yield from self.cells.get((kx, ky), ())
            return
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                yield from self.cells.get((kx + dx, ky + dy), ())


def _spread(ps):
    """The largest distance between two of the points ps (the diagonal of
    their bounding box for many points: an upper bound, cheap)."""
    if len(ps) <= 64:
        return max((math.hypot(p[0] - q[0], p[1] - q[1]) for i, p in enumerate(ps)
                    for q in ps[i + 1:]), default=0.0)
    xs = [p[0] for p in ps]
    ys = [p[1] for p in ps]
    return math.hypot(max(xs) - min(xs), max(ys) - min(ys))


def _close(p, q, tol):
    return math.hypot(p[0] - q[0], p[1] - q[1]) <= tol


class _Normal:
    """One skeleton after merging coincident nodes: cluster[i] is node i's
    merged node; members, rep (the lowest-numbered member's position) and
    the surviving arcs (ca, cb, left, right) over merged nodes."""

    def __init__(self, pts, arcs, tol):
        parent = list(range(len(pts)))

        def find(i):
            while parent[i] != i:
                parent[i] = parent[parent[i]]
                i = parent[i]
            return i

        grid = _Grid(tol)
        for i, p in enumerate(pts):
            for j in grid.near(p[0], p[1]):
                if _close(p, pts[j], tol):
                    ri, rj = find(i), find(j)
                    if ri != rj:
                        parent[max(ri, rj)] = min(ri, rj)
            grid.add(p[0], p[1], i)
        roots = {}
        self.cluster = []
        self.members = []
        for i in range(len(pts)):
            r = find(i)
            if r not in roots:
                roots[r] = len(self.members)
                self.members.append([])
            self.cluster.append(roots[r])
            self.members[roots[r]].append(i)
        self.rep = [pts[m[0]] for m in self.members]
        self.arcs = []
        self.zero = 0
        for a, b, l, r in arcs:
            ca, cb = self.cluster[a], self.cluster[b]
            if ca == cb:
                self.zero += 1
            else:
                self.arcs.append((ca, cb, l, r))


# ------------------------------------------------------------- comparing

def compare(a, b, tol=None, weights=None):
    """Compare two wskel-1 skeleton dicts of the same polygon.

    tol: absolute tolerance for positions; None selects default_tol(a).
    Times: tol over the smallest weight of a node's faces (weights: one per
    input edge; None reads them off the skeletons, see face_weights).
    Raises SkeletonError if either dict breaks the contract
    or the two do not share their n input vertices.  Returns a CompareResult
    whose .identical is the verdict."""
    na, pa, arcs_a = _check(a, "A")
    nb, pb, arcs_b = _check(b, "B")
    if na != nb:
        raise SkeletonError("A has n = %d input vertices, B has n = %d" % (na, nb))
    if tol is None:
        tol = default_tol(a)
    if not (tol >= 0 and math.isfinite(tol)):
        raise SkeletonError("tolerance must be finite and >= 0 (got %r)" % tol)
    n = na
    for i in range(n):
        if not _close(pa[i], pb[i], tol):
            raise SkeletonError("input vertex %d differs: A (%s), B (%s): not the same polygon"
                                % (i, _fmt_pt(pa[i]), _fmt_pt(pb[i])))

    res = CompareResult(tol)
    A = _Normal(pa, arcs_a, tol)
    B = _Normal(pb, arcs_b, tol)
    res.counts = {"n": n, "nodes_a": len(pa), "nodes_b": len(pb),
                  "merged_a": len(A.members), "merged_b": len(B.members),
                  "arcs_a": len(arcs_a), "arcs_b": len(arcs_b),
                  "zero_arcs_a": A.zero, "zero_arcs_b": B.zero}

    # Weight-aware time tolerances: tol / w per node (see the module doc).
    if weights is None:
        wa, wb = face_weights(a), face_weights(b)
        weights = [x if y is None else y if x is None else min(x, y) for x, y in zip(wa, wb)]
    elif len(weights) != n:
        raise SkeletonError("%d weights for %d input edges" % (len(weights), n))
    wn_a = _node_weights(len(pa), arcs_a, weights)
    wn_b = _node_weights(len(pb), arcs_b, weights)
    cw_a = [min(wn_a[i] for i in mem) for mem in A.members]
    cw_b = [min(wn_b[i] for i in mem) for mem in B.members]

    # All members of a merged node must share one time: within tol, or the
    # members' spread in position if that is larger, over its faces' weight.
    # Why the spread: t is the weighted distance to the boundary, Lipschitz
    # with constant 1 / (smallest weight), so two nodes of a correct skeleton
    # d apart differ in t by up to d / w; merging is transitive (a chain of
    # nodes each within tol of the next), so a merged node can span far more
    # than tol.  Without it a skeleton compared with itself was "DIFFERENT":
    # a radius-1000 16-gon with one vertex pulled to 4e9 (tol 400) merges
    # 17 nodes over 2000 units with t from 0 to 474 (audit of issue 11).
    for name, S, pts, cw in (("A", A, pa, cw_a), ("B", B, pb, cw_b)):
        for c, mem in enumerate(S.members):
            ts = [pts[i][2] for i in mem]
            allowed = max(tol, _spread([pts[i] for i in mem])) / cw[c]
            if max(ts) - min(ts) > allowed:
                res.time_mismatches.append({
                    "p": S.rep[c],
                    "what": "%s merges %d nodes with t from %.17g to %.17g (time tolerance %.3g)"
                            % (name, len(mem), min(ts), max(ts), allowed)})

    # Match merged nodes: A's cluster -> B's cluster, nearest representative
    # among the B clusters having a member within tol of a member of A's.
    grid_b = _Grid(tol)
    for i, p in enumerate(pb):
        grid_b.add(p[0], p[1], i)
    match = [None] * len(A.members)
    taken = {}
    for ca, mem in enumerate(A.members):
        cands = set()
        for i in mem:
            for j in grid_b.near(pa[i][0], pa[i][1]):
                if _close(pa[i], pb[j], tol):
                    cands.add(B.cluster[j])
        if not cands:
            continue
        ra = A.rep[ca]
        best = min(cands, key=lambda cb: (math.hypot(ra[0] - B.rep[cb][0],
                                                     ra[1] - B.rep[cb][1]), cb))
        # One-to-one: a B node claimed twice keeps the nearer A node.
        if best in taken:
            other = taken[best]
            ro = A.rep[other]
            if (math.hypot(ro[0] - B.rep[best][0], ro[1] - B.rep[best][1])
                    <= math.hypot(ra[0] - B.rep[best][0], ra[1] - B.rep[best][1])):
                continue
            match[other] = None
        match[ca] = best
        taken[best] = ca
    for ca, cb in enumerate(match):
        if cb is None:
            res.nodes_only_a.append({"p": A.rep[ca], "t": pa[A.members[ca][0]][2]})
    for cb in range(len(B.members)):
        if cb not in taken:
            res.nodes_only_b.append({"p": B.rep[cb], "t": pb[B.members[cb][0]][2]})
    for ca, cb in enumerate(match):
        if cb is None:
            continue
        ta, tb = pa[A.members[ca][0]][2], pb[B.members[cb][0]][2]
        tol_t = tol / min(cw_a[ca], cw_b[cb])
        if abs(ta - tb) > tol_t:
            res.time_mismatches.append({"p": A.rep[ca],
                                        "what": "A t=%.17g, B t=%.17g (time tolerance %.3g)"
                                                % (ta, tb, tol_t)})

    # Arcs in one label space: ("b", id) for B's merged nodes and A's matched
    # ones, ("a", id) for A's unmatched ones.  An arc is keyed by its ordered
    # label pair (lo, hi) and carries its faces as (left of lo->hi, right).
    def label_a(ca):
        return ("b", match[ca]) if match[ca] is not None else ("a", ca)

    def keyed(S, label, arcs):
        out = defaultdict(list)
        for ca, cb, l, r in arcs:
            la, lb = label(ca), label(cb)
            if la > lb:
                la, lb, l, r = lb, la, r, l
            out[(la, lb)].append((l, r))
        return out

    ka = keyed(A, label_a, A.arcs)
    kb = keyed(B, lambda cb: ("b", cb), B.arcs)

    def pos(lab):
        kind, i = lab
        return A.rep[i] if kind == "a" else B.rep[i]

    def item(key, faces):
        return {"p": pos(key[0]), "q": pos(key[1]), "faces": sorted(faces)}

    matched = 0
    for key in sorted(set(ka) | set(kb)):
        fa, fb = list(ka.get(key, ())), list(kb.get(key, ()))
        # Exact (oriented) agreement first, then unordered agreement (faces on
        # the wrong sides), then whatever is left over.
        for f in list(fa):
            if f in fb:
                fa.remove(f)
                fb.remove(f)
                matched += 1
        while fa and fb:
            # Pair a leftover of A with the leftover of B sharing most faces.
            f = fa.pop(0)
            g = max(fb, key=lambda g: len(set(f) & set(g)))
            fb.remove(g)
            res.face_mismatches.append({"p": pos(key[0]), "q": pos(key[1]),
                                        "a": list(f), "b": list(g)})
        for f in fa:
            res.only_a.append(item(key, f))
        for g in fb:
            res.only_b.append(item(key, g))
    res.counts["matched_arcs"] = matched
    res.counts["arcs_a_nonzero"] = len(A.arcs)
    res.counts["arcs_b_nonzero"] = len(B.arcs)
    return res


# ------------------------------------------------------------------- CLI

def main(argv=None):
    # `... | head` closes the pipe early: end quietly like other filters.
    import signal
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    ap = argparse.ArgumentParser(
        description="Compare two wskel-1 skeletons of one polygon, arc for arc.")
    ap.add_argument("a", metavar="A.json")
    ap.add_argument("b", metavar="B.json")
    ap.add_argument("--tol", type=float, default=None,
                    help="absolute tolerance for positions (default: 1e-7 * bbox diagonal of "
                         "the input); times: tol over the weight of a node's faces")
    ap.add_argument("--verbose", "-v", action="store_true",
                    help="list every difference (default: the first 10 of each kind)")
    args = ap.parse_args(argv)
    try:
        res = compare(load(args.a), load(args.b), args.tol)
    except SkeletonError as e:
        print("compare_skeletons: %s" % e, file=sys.stderr)
        return 2
    print("%s vs %s: %s" % (args.a, args.b, res.summary()))
    for line in res.details(limit=None if args.verbose else 10):
        print(line)
    return 0 if res.identical else 1


if __name__ == "__main__":
    sys.exit(main())
