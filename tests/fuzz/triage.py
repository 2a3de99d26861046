#!/usr/bin/python3
"""triage.py: sort the variant target's findings (tests/fuzz/README.md).

    /usr/bin/python3 tests/fuzz/triage.py [--out DIR] [--timeout S] FILE|DIR...

Runs every input through bin/wskel --check --verbose with every variant
(--list-variants) and prints one line per input: each variant's outcome
(ok NODES/ARCS, mismatch, unsupported, ealgo, invalid, timeout, crash) and
whether it passes (every variant valid and naive's skeleton, or
unsupported).  "mismatch": a valid skeleton that is not naive's as the fuzz
target compares them (tests/same_skeleton.h, in Python testlib.same_skeleton):
nodes within WK_SAME_SKELETON_TOL_REL (engine/tolerance.h, 1e-6) of the
input's bounding-box diagonal, and in time within that over their faces'
weight (read off the skeletons, scripts/compare_skeletons.py's
face_weights), merged; node and arc counts may differ (zero-length arcs,
nodes merged within the tolerance).  Inputs with the same outcome and messages are one group; the
smallest of each group is named.  With --out, each group's smallest input is
written to DIR as a .wpoly (comment lines dropped, the polygon's lines kept
byte for byte; GraphML converted with Python's shortest round-trip repr)
with a one-line '#' comment naming its outcome: ready for tests/data/fuzz/.
"""
import argparse
import os
import re
import subprocess
import sys
import json
import math
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WSKEL = os.path.join(ROOT, "bin", "wskel")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
import compare_skeletons as cs  # noqa: E402
import testlib  # noqa: E402

# WK_SAME_SKELETON_TOL_REL of engine/tolerance.h (the fuzz target's oracle).
SAME_TOL_REL = 1e-6


def variants():
    out = subprocess.run([WSKEL, "--list-variants"], capture_output=True, text=True, check=True)
    return [line.split()[0] for line in out.stdout.splitlines() if line.strip()]


def run(path, variant, timeout):
    """(kind, detail, skeleton): kind ok/unsupported/ealgo/invalid/input/
    timeout/crash; skeleton the wskel-1 dict when ok, else None."""
    try:
        p = subprocess.run([WSKEL, "--variant", variant, "--check", "--verbose", "--format",
                            "json", path], capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", "more than %g s" % timeout, None
    err = p.stderr.decode("utf-8", "replace").strip().replace("\n", " | ")
    err = err.replace("wskel: " + path + ":", "").replace(path, "FILE").strip()
    if p.returncode == 0:
        d = json.loads(p.stdout.decode())
        return "ok", "%d/%d" % (len(d["nodes"]), len(d["arcs"])), d
    if p.returncode == 1:
        return "input", err, None
    if p.returncode == 2:
        return ("unsupported" if "(unsupported by this variant," in err else "ealgo"), err, None
    if p.returncode == 3:
        return "invalid", err, None
    return "crash", "exit %d: %s" % (p.returncode, err[:300]), None


def same(a, b):
    """(True, "") if b is a's skeleton in canonical form, else (False, why)."""
    n = a["n"]
    xs = [v[0] for v in a["nodes"][:n]]
    ys = [v[1] for v in a["nodes"][:n]]
    tol = SAME_TOL_REL * math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    wa, wb = cs.face_weights(a), cs.face_weights(b)
    w = [x if y is None else y if x is None else min(x, y) for x, y in zip(wa, wb)]
    return testlib.same_skeleton(a, b, tol, tol, [1.0 if x is None else x for x in w])


def polygon_lines(path):
    """The .wpoly text of the input without comment and blank lines."""
    data = open(path, "rb").read()
    s = data.lstrip(b"\xef\xbb\xbf \t\r\n")
    if s.startswith(b"<"):
        return graphml_to_wpoly(data)  # None: not one cycle (see there)
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    keep = [l for l in data.replace(b"\r\n", b"\n").split(b"\n")
            if l.strip(b" \t") and not l.strip(b" \t").startswith(b"#")]
    return b"\n".join(keep) + b"\n"


def graphml_to_wpoly(data):
    root = ET.fromstring(data)
    ns = root.tag[:root.tag.index("}") + 1] if root.tag.startswith("{") else ""
    keys = {}
    for k in root.findall(ns + "key"):
        name = k.get("attr.name")
        if name and name not in keys and k.get("for") in (None, "all",
                                                          "edge" if "edge" in name else "node"):
            d = k.find(ns + "default")
            keys[name] = (k.get("id"), d.text if d is not None else None)
    g = root.find(ns + "graph")
    nodes = g.findall(ns + "node")
    edges = g.findall(ns + "edge")

    def value(e, name):
        kid, dflt = keys.get(name, (None, None))
        for d in e.findall(ns + "data"):
            if d.get("key") == kid:
                return float(d.text)
        return float(dflt) if dflt is not None else None

    pos = {n.get("id"): (value(n, "vertex-coordinate-x"), value(n, "vertex-coordinate-y"))
           for n in nodes}
    inc = {n.get("id"): [] for n in nodes}
    for i, e in enumerate(edges):
        inc[e.get("source")].append(i)
        inc[e.get("target")].append(i)
    # Only a single cycle is a polygon a .wpoly can hold; a PSLG (terminals,
    # vertices of degree 3 or more, several components) stays GraphML.
    if not nodes or len(edges) != len(nodes) or any(len(v) != 2 for v in inc.values()):
        return None
    out, cur, e = [], nodes[0].get("id"), inc[nodes[0].get("id")][0]
    while True:
        w = value(edges[e], "edge-weight")
        out.append((pos[cur], 1.0 if w is None else w))
        nxt = edges[e].get("target") if edges[e].get("source") == cur else edges[e].get("source")
        if nxt == nodes[0].get("id"):
            break
        if len(out) > len(edges):
            return None
        e = inc[nxt][1] if inc[nxt][0] == e else inc[nxt][0]
        cur = nxt
    lines = ["%d" % len(out)] + ["%r %r %r" % (p[0], p[1], w) for p, w in out]
    return ("\n".join(lines) + "\n").encode()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("inputs", nargs="+")
    ap.add_argument("--out")
    ap.add_argument("--timeout", type=float, default=30)
    args = ap.parse_args()
    files = []
    for p in args.inputs:
        if os.path.isdir(p):
            files += sorted(os.path.join(p, f) for f in os.listdir(p) if not f.endswith(".txt"))
        else:
            files.append(p)
    vs = variants()
    groups = {}
    for f in files:
        full = [(v,) + run(f, v, args.timeout) for v in vs]
        ref = full[0][3] if full[0][1] == "ok" else None
        res = [(v, kind, detail) for v, kind, detail, _ in full]
        summary, ok = [], True
        for i, (v, kind, detail) in enumerate(res):
            if kind == "ok" and ref is not None and i > 0:
                agree, why = same(ref, full[i][3])
                if not agree:
                    kind = "mismatch"
                    res[i] = (v, kind, "nodes/arcs %s, %s's %s: %s"
                              % (detail, vs[0], full[0][2], why))
            if kind not in ("ok", "unsupported") or (kind == "unsupported" and v == vs[0]):
                ok = False
            summary.append("%s=%s" % (v, kind))
        line = " ".join(summary)
        print("%s  %s  %s" % ("pass" if ok else "FAIL", line, f))
        for v, kind, detail in res:
            if kind not in ("ok", "unsupported"):
                print("      %s: %s" % (v, detail[:400]))
        if ok:
            continue
        # Group by outcome and the messages without numbers.
        sig = (line,) + tuple(re.sub(r"[-+0-9.e]+", "#", d.split(" | ")[0])[:200]
                              for v, k, d in res if k not in ("ok", "unsupported"))
        groups.setdefault(sig, []).append((os.path.getsize(f), f, line, res))
    print("\n%d inputs, %d failing groups" % (len(files), len(groups)))
    for sig, members in sorted(groups.items()):
        members.sort()
        size, f, line, res = members[0]
        print("  %3d x %s  e.g. %s" % (len(members), line, f))
        if args.out:
            os.makedirs(args.out, exist_ok=True)
            base = os.path.splitext(os.path.basename(f))[0]
            detail = "; ".join("%s: %s" % (v, d.split(" | ")[0][:160]) for v, k, d in res
                               if k not in ("ok", "unsupported"))
            comment = ("fuzz_variants finding (%s): %s" % (line, detail)).replace("\n", " ").rstrip()
            text = polygon_lines(f)
            if text is None:
                # a PSLG: kept as GraphML, the comment after the XML declaration
                data = open(f, "rb").read()
                decl = data.find(b"?>") + 2 if data.lstrip().startswith(b"<?xml") else 0
                with open(os.path.join(args.out, base + ".graphml"), "wb") as o:
                    o.write(data[:decl] + b"\n<!-- " + comment.replace("--", "- -").encode()
                            + b" -->" + data[decl:])
                continue
            with open(os.path.join(args.out, base + ".wpoly"), "wb") as o:
                o.write(("# " + comment).encode() + b"\n")
                o.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
