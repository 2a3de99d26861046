#!/usr/bin/python3
"""stress.py: the stress sweep (`make stress`, quick version `make stress-quick`).

    tests/stress/stress.py [--cases N] [--jobs J] [--timeout S] [--seed S]
                           [--out DIR] [--classes A,B] [--variants V,W] [--quick]
                           [--update-known]

Case i of seed S is made by maker class i mod C (tests/stress/makers.py: every
family of `bin/wskel-gen --list` and the degenerate makers) from
random.Random("S:i"), so a case is reproducible from its name and the quick
cases are the first ones of the full sweep.  Each polygon is run through
every variant (bin/wskel --check, a time limit per run):

  naive                 must pass --check (exit 1: the maker made an invalid
                        polygon: dropped and counted, not a failure)
  arrangement --k 1, arrangement --k max, monotone, motorcycle (equal
  weights only: its refusal of other weights is n/a), deforming (positive
  weights here; an input it hands to the reference is 'fallback', counted,
  not a failure)
                        must pass --check and be naive's skeleton
                        (testlib.same_skeleton: 1e-7 of the diagonal, times
                        over the smallest weight); monotone's refusal "not
                        monotone in any direction" is a failure ('refused')
                        on a polygon
                        monotone by construction or exactly monotone in some
                        direction (makers.exact_monotone_direction), else not
                        applicable ('n/a')

Outcomes per variant: pass, exit2, exit3, differs (from naive), timeout,
crash (killed by a signal), refused, other (another exit code), n/a
(monotone on a polygon that is not monotone), unref (passed --check, but
naive failed, so not compared).  The failures (exit2, exit3, differs,
timeout, crash, refused, other) go to OUT/failures/NAME.wpoly, each with
its outcomes in '#' lines, and to OUT/failures.tsv; the cases a variant
handed to the reference ('fallback') to OUT/fallbacks/ and
OUT/fallbacks.tsv; invalid polygons to
OUT/invalid.tsv; the table of counts per class and variant to stdout and
OUT/summary.txt (and OUT/summary.json).  Exit 1 if any case failed.

--quick (make test): the first 300 cases (--cases to change), checked
against the committed known failures tests/data/stress/KNOWN (file,
variant, outcome, message; each file in tests/data/stress/): fails if no
case ran, if a class had no valid case, on a failure that is not known, on
a known one whose outcome changed and on a known one that now passes (so
the list stays true).  --update-known rewrites KNOWN and its files from
this run's failures (review the diff before committing it); rows whose
file is not one of this run's cases (the full sweep's) are kept.

The full sweep (make stress) is checked against KNOWN the same way (a
known row that is not one of its cases is run from its file), so it
passes when every failure is listed; it lists every failure in its
summary either way.  Full-sweep rows name the file where the case is kept
with its evidence, relative to tests/data/stress/ (e.g.
../degenerate/NAME.wpoly, a file of KNOWN_FILES in tests/test_degenerate.py).

--variants V,W runs only naive (the reference) and those variants, e.g. to
count one variant's reference fallbacks over many cases; KNOWN rows of the
other variants are not checked then.

The programs are copied to a private directory first, so rebuilding bin/
during a run changes nothing.  Environment: WSKEL_BIN, WSKEL_GEN_BIN.
"""

import argparse
import collections
import hashlib
import json
import multiprocessing
import os
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
import makers  # noqa: E402
import testlib as tl  # noqa: E402
from testlib import cs  # noqa: E402

ROOT = tl.ROOT
KNOWN_DIR = os.path.join(tl.DATA, "stress")
KNOWN_FILE = os.path.join(KNOWN_DIR, "KNOWN")
VARIANTS = [("naive", ["--variant", "naive"]),
            ("arrangement-k1", ["--variant", "arrangement", "--k", "1"]),
            ("arrangement-kmax", ["--variant", "arrangement", "--k", "max"]),
            ("monotone", ["--variant", "monotone"]),
            ("motorcycle", ["--variant", "motorcycle"]),
            ("deforming", ["--variant", "deforming"])]
VARIANT_ARGS = dict(VARIANTS)
OUTCOMES = ["pass", "fallback", "exit2", "exit3", "differs", "timeout", "crash", "refused", "other",
            "n/a",
            "unref"]
FAILURES = {"exit2", "exit3", "differs", "timeout", "crash", "refused", "other"}
NOT_MONOTONE = "not monotone in any direction"
UNIT_ONLY = "supports equal weights only"

# Set in each worker by init_worker.
CFG = {}


# ---------------------------------------------------------------- running

def limit_memory():
    mb = CFG.get("mem_mb", 0)
    if mb > 0:
        resource.setrlimit(resource.RLIMIT_AS, (mb << 20, mb << 20))


def run_wskel(args, poly, out):
    """(exit code or None on timeout, first stderr line, seconds)."""
    cmd = [CFG["wskel"], "--check", "-o", out] + args + [poly]
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=CFG["timeout"],
                           preexec_fn=limit_memory, errors="replace")
        rc, err = p.returncode, p.stderr.strip()
    except subprocess.TimeoutExpired:
        rc, err = None, "timed out after %g s" % CFG["timeout"]
    dt = time.monotonic() - t0
    err = err.replace(poly, "INPUT")
    lines = err.splitlines()
    return rc, (lines[0] if lines else ""), dt


def fallbacks(path):
    """The reference_fallbacks counter of a wskel JSON output (0 if absent):
    the variant handed the input to the reference variant."""
    with open(path) as f:
        stats = tl.json.load(f).get("stats") or {}
    counters = stats.get("counters", stats)
    return int(counters.get("reference_fallbacks", 0) or 0)


def evaluate(poly, monotone, work):
    """Every variant on the polygon file poly.  Returns (None, message) if
    naive's reader rejects it, else ({variant: [outcome, message, exit,
    seconds]}, None)."""
    res = {}
    ref = None
    with open(poly) as f:
        pts, ws, _ = makers.parse_wpoly(f.read())
    # the tolerance of the C sweeps (1e-7 of the diagonal, at least 64 ulps
    # of the largest coordinate); times: t errors are position errors over
    # the weight, so tol / the smallest weight
    mag = max(max(abs(x), abs(y)) for x, y in pts)
    tol = max(1e-7 * makers.diagonal(pts), 64 * mag * 2.0 ** -52)
    tol_t = tol / min(ws)
    for name, args in VARIANTS:
        out = os.path.join(work, name + ".json")
        if os.path.exists(out):
            os.unlink(out)
        rc, msg, dt = run_wskel(args, poly, out)
        if name == "naive" and rc == 1:
            return None, msg
        if rc is None:
            oc = "timeout"
        elif rc < 0:
            oc, msg = "crash", "killed by signal %d; %s" % (-rc, msg)
        elif rc == 0:
            oc = "pass"
            if name == "naive":
                try:
                    ref = cs.load(out)
                except cs.SkeletonError as e:
                    oc, msg = "other", "exit 0 but unreadable output: %s" % e
            elif ref is None:
                oc, msg = "unref", "valid; naive failed, not compared"
            else:
                try:
                    sk = cs.load(out)
                    same, why = tl.same_skeleton(ref, sk, tol, tol_t)
                    if not same:
                        oc, msg = "differs", "differs from naive (A: naive, B: this): %s" % why
                    elif fallbacks(out):
                        # naive's own answer: not a comparison of this variant
                        oc, msg = "fallback", "handed to the reference variant"
                except (cs.SkeletonError, KeyError, IndexError, TypeError) as e:
                    oc, msg = "differs", "cannot compare with naive: %r" % e
        elif rc == 2 and name == "monotone" and NOT_MONOTONE in msg:
            oc = "refused" if monotone else "n/a"
        elif rc == 2 and name == "motorcycle" and UNIT_ONLY in msg:
            oc = "n/a"  # the motorcycle variant takes equal weights only
        elif rc == 2:
            oc = "exit2"
        elif rc == 3:
            oc = "exit3"
        else:
            oc, msg = "other", "exit %d: %s" % (rc, msg)
        res[name] = [oc, msg, rc, round(dt, 3)]
    if "monotone" in res and res["monotone"][0] in ("refused", "n/a"):
        # A polygon exactly monotone in some direction must not be refused,
        # monotone by construction or not.
        try:
            d = makers.exact_monotone_direction(pts)
        except Exception as e:  # a bug of the check: the note says so
            res["monotone"][1] += "; monotonicity check failed: %r" % e
            d = None
        if d:
            res["monotone"][0] = "refused"
            res["monotone"][1] += "; exactly monotone in direction (%d, %d)" % d
        elif res["monotone"][0] == "refused":
            res["monotone"][1] += "; not exactly monotone in doubles (only up to rounding)"
    return res, None


def case_name(seed, i, cls):
    return "s%d-c%05d-%s" % (seed, i, cls.replace(":", "-"))


def header(name, cls, case, i):
    return ["stress case %s (class %s; tests/stress/stress.py --seed %d --only %d)"
            % (name, cls, CFG["seed"], i),
            "made: %s" % case.desc,
            "monotone by construction: %s" % ("yes" if case.monotone else "no")]


def run_case(i):
    """Make case i and run it.  Returns a record dict."""
    seed = CFG["seed"]
    cls, maker = CFG["classes"][i % len(CFG["classes"])]
    name = case_name(seed, i, cls)
    rec = {"index": i, "name": name, "cls": cls}
    work = CFG["work"]
    try:
        case = maker(random.Random("%d:%d" % (seed, i)))
    except makers.MakerError as e:
        rec.update(state="notmade", msg=str(e))
        return rec
    except Exception:  # a bug of the maker: make test fails on it
        rec.update(state="makerbug", msg="maker raised: " + traceback.format_exc(limit=3))
        return rec
    body = makers.wpoly_body(case.pts, case.ws)
    text = "".join("# %s\n" % c for c in header(name, cls, case, i)) + body
    poly = os.path.join(work, "case.wpoly")
    with open(poly, "w") as f:
        f.write(text)
    res, why = evaluate(poly, case.monotone, work)
    rec.update(desc=case.desc, monotone=case.monotone, n=len(case.pts), text=text,
               hash=hashlib.sha256(body.encode()).hexdigest())
    if res is None:  # the reader's verdict; the input-domain bounds counted apart
        rec.update(state="domain" if "input domain" in why else "invalid", msg=why)
    else:
        rec.update(state="ran", res=res)
    return rec


def select_variants(names):
    """VARIANTS narrowed to naive (the reference every other is compared
    with) and the named ones (--variants; all when none are named)."""
    global VARIANTS
    unknown = [n for n in names if n not in VARIANT_ARGS]
    if unknown:
        raise SystemExit("stress.py: unknown variant %s (variants: %s)"
                         % (", ".join(unknown), ", ".join(v for v, _ in VARIANTS)))
    if names:
        VARIANTS = [(v, a) for v, a in VARIANTS if v == "naive" or v in names]


def init_worker(cfg):
    CFG.update(cfg)
    select_variants(cfg["variant_names"])
    CFG["classes"] = select_classes(cfg["class_names"])
    CFG["work"] = tempfile.mkdtemp(prefix="w-", dir=cfg["tmp"])


def select_classes(names):
    allc = makers.classes()
    if not names:
        return allc
    by = dict(allc)
    unknown = [n for n in names if n not in by]
    if unknown:
        raise SystemExit("stress.py: unknown class %s (classes: %s)"
                         % (", ".join(unknown), ", ".join(c for c, _ in allc)))
    return [(n, by[n]) for n in names]


# ---------------------------------------------------------------- report

class Summary:
    def __init__(self, classes):
        self.classes = classes
        self.counts = collections.defaultdict(collections.Counter)  # (cls, variant) -> outcome
        self.state = collections.defaultdict(collections.Counter)   # cls -> state
        self.invalid_msgs = collections.defaultdict(collections.Counter)
        self.records = []

    def add(self, rec):
        self.state[rec["cls"]][rec["state"]] += 1
        if rec["state"] == "ran":
            for v, r in rec["res"].items():
                self.counts[(rec["cls"], v)][r[0]] += 1
        elif rec["state"] in ("invalid", "domain", "notmade", "makerbug"):
            # grouped with the numbers left out (vertex ids, lines)
            self.invalid_msgs[rec["cls"]][short(re.sub(r"\d+(\.\d+)?(e-?\d+)?", "#",
                                                    rec["msg"]))] += 1

    def failing(self, rec):
        return rec["state"] == "ran" and any(r[0] in FAILURES for r in rec["res"].values())

    def table(self):
        cols = ["cases", "invalid", "domain"] + OUTCOMES
        lines = []
        w = max(len(c) for c in self.classes + ["TOTAL"]) + 2
        for v, _ in VARIANTS:
            lines.append("")
            lines.append("variant %s" % v)
            lines.append("%-*s" % (w, "class") + "".join("%9s" % c for c in cols))
            tot = collections.Counter()
            for c in self.classes:
                cnt = self.counts[(c, v)]
                row = {"cases": sum(cnt.values()), "domain": self.state[c]["domain"],
                       "invalid": (self.state[c]["invalid"] + self.state[c]["notmade"]
                                   + self.state[c]["makerbug"])}
                row.update(cnt)
                tot.update(row)
                lines.append("%-*s" % (w, c) + "".join("%9d" % row.get(k, 0) for k in cols))
            lines.append("%-*s" % (w, "TOTAL") + "".join("%9d" % tot.get(k, 0) for k in cols))
        return "\n".join(lines)

    def totals(self):
        out = {}
        for v, _ in VARIANTS:
            t = collections.Counter()
            for c in self.classes:
                t.update(self.counts[(c, v)])
            out[v] = dict(t)
        return out


def short(msg, width=160):
    msg = " ".join(msg.split())
    return msg if len(msg) <= width else msg[:width - 3] + "..."


def failure_kinds(records, summary, faildir):
    """The failures grouped by outcome and message (numbers left out): how
    many (case, variant) pairs, which variants and classes, three examples."""
    kinds = collections.defaultdict(list)
    for rec in records:
        if not summary.failing(rec):
            continue
        for v, r in rec["res"].items():
            if r[0] in FAILURES:
                key = (r[0], short(re.sub(r"-?\d+(\.\d+)?(e[-+]?\d+)?", "#", r[1]), 150))
                kinds[key].append((rec, v, r))
    if not kinds:
        return ""
    out = ["", "failures by kind (outcome: message, numbers as #): (case, variant) pairs, "
           "variants, classes, examples"]
    for (oc, msg), items in sorted(kinds.items(), key=lambda kv: -len(kv[1])):
        vs = collections.Counter(v for _, v, _ in items)
        cl = collections.Counter(rec["cls"] for rec, _, _ in items)
        out.append("%5d  %s: %s" % (len(items), oc, msg))
        out.append("       variants: %s" % ", ".join("%s %d" % kv for kv in sorted(vs.items())))
        out.append("       classes: %s" % ", ".join("%s %d" % kv for kv in cl.most_common()))
        seen = []
        for rec, v, r in items:
            if rec["name"] not in seen and len(seen) < 3:
                seen.append(rec["name"])
                out.append("       e.g. %s.wpoly (%s): %s" % (
                    os.path.join(faildir, rec["name"]), v, short(r[1], 200)))
    return "\n".join(out) + "\n"


def failure_text(rec):
    """The case's .wpoly with its failing outcomes as comments."""
    lines = rec["text"].splitlines(True)
    k = next(j for j, s in enumerate(lines) if not s.startswith("#"))
    notes = ["# %s: %s: %s\n" % (v, r[0], short(r[1], 400)) for v, r in rec["res"].items()
             if r[0] in FAILURES or r[0] == "unref"]
    notes.append("# replay: bin/wskel --check --variant V FILE; compare with naive's skeleton "
                 "(testlib.same_skeleton)\n")
    return "".join(lines[:k] + notes + lines[k:])


def write_failure(outdir, rec):
    """OUT/failures/NAME.wpoly with the outcomes as comments."""
    with open(os.path.join(outdir, "failures", rec["name"] + ".wpoly"), "w") as f:
        f.write(failure_text(rec))


# ----------------------------------------------------------------- known

def read_known():
    """[(file, variant, outcome, message)] of tests/data/stress/KNOWN."""
    rows = []
    if not os.path.exists(KNOWN_FILE):
        return rows
    with open(KNOWN_FILE) as f:
        for ln, line in enumerate(f, 1):
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.rstrip("\n").split("\t")
            if len(parts) != 4 or parts[1] not in VARIANT_ARGS or parts[2] not in FAILURES:
                raise SystemExit("%s:%d: expected file<TAB>variant<TAB>outcome<TAB>message"
                                 % (KNOWN_FILE, ln))
            rows.append(tuple(parts))
    return rows


def file_hash(path):
    with open(path) as f:
        pts, ws, comments = makers.parse_wpoly(f.read())
    mono = any(c.startswith("monotone by construction: yes") for c in comments)
    return hashlib.sha256(makers.wpoly_body(pts, ws).encode()).hexdigest(), mono


def check_known(summary, records, log):
    """Problems (lines) of the quick run against KNOWN; [] if it holds."""
    known = read_known()
    problems = []
    by_hash = {}
    for rec in records:
        if rec["state"] == "ran":
            by_hash[rec["hash"]] = rec
    known_keys = {}
    ran_variants = set(v for v, _ in VARIANTS)
    for fname, var, oc, msg in known:
        if var not in ran_variants:  # --variants left it out
            continue
        path = os.path.join(KNOWN_DIR, fname)
        if not os.path.exists(path):
            problems.append("KNOWN lists %s, which is not in tests/data/stress/" % fname)
            continue
        h, mono = file_hash(path)
        known_keys[(h, var)] = (fname, oc)
        rec = by_hash.get(h)
        if rec is None:  # not among this run's cases: run the file itself
            res, why = evaluate(path, mono, CFG["work"])
            if res is None:
                problems.append("%s: known %s %s, but the reader rejects it now: %s"
                                % (fname, var, oc, why))
                continue
            got = res[var]
            log("known %s (not generated in this run, run from the file): %s %s"
                % (fname, var, got[0]))
        else:
            got = rec["res"][var]
        if got[0] == oc:
            continue
        if got[0] in FAILURES:
            problems.append("%s: known failure of %s changed from %s to %s: %s"
                            % (fname, var, oc, got[0], short(got[1])))
        else:
            problems.append("%s: %s now gives %s (known as %s): remove it from "
                            "tests/data/stress/KNOWN" % (fname, var, got[0], oc))
    for rec in records:
        if not summary.failing(rec):
            continue
        for var, r in rec["res"].items():
            if r[0] in FAILURES and (rec["hash"], var) not in known_keys:
                problems.append("%s: %s %s (new failure; the input is in the failures "
                                "directory): %s" % (rec["name"], var, r[0], short(r[1])))
    return problems


def update_known(records, summary):
    """Rewrite tests/data/stress/ from this run's failures; the rows (and
    files) of cases that this run did not make (the full sweep's) stay."""
    os.makedirs(KNOWN_DIR, exist_ok=True)
    made = set(rec["hash"] for rec in records if rec["state"] == "ran")
    rows, keep = [], set()
    for fname, var, oc, msg in read_known():
        path = os.path.join(KNOWN_DIR, fname)
        if os.path.exists(path) and file_hash(path)[0] not in made:
            rows.append("%s\t%s\t%s\t%s" % (fname, var, oc, msg))
            keep.add(os.path.normpath(path))
    for f in os.listdir(KNOWN_DIR):
        if f.endswith(".wpoly") and os.path.normpath(os.path.join(KNOWN_DIR, f)) not in keep:
            os.unlink(os.path.join(KNOWN_DIR, f))
    for rec in sorted(records, key=lambda r: r["index"]):
        if not summary.failing(rec):
            continue
        fname = rec["name"] + ".wpoly"
        with open(os.path.join(KNOWN_DIR, fname), "w") as f:
            f.write(failure_text(rec))
        for var, _ in VARIANTS:
            r = rec["res"][var]
            if r[0] in FAILURES:
                rows.append("%s\t%s\t%s\t%s" % (fname, var, r[0], short(r[1], 300)))
    with open(KNOWN_FILE, "w") as f:
        f.write("# Known failures of the stress sweep (make stress-quick, run by make test,\n"
                "# and make stress): file<TAB>variant<TAB>outcome<TAB>message.  A file is\n"
                "# a case of tests/stress/stress.py --quick, committed here, or a case of\n"
                "# the full sweep, named relative to this directory where it is kept with\n"
                "# its evidence.  Both sweeps fail on a failure not listed, on a listed one\n"
                "# whose outcome changed and on a listed one that passes (remove its line,\n"
                "# and its file when no line is left).  Rewritten by tests/stress/stress.py\n"
                "# --quick --update-known, which keeps the full sweep's rows.\n")
        for r in rows:
            f.write(r + "\n")
    return len(rows)


# ------------------------------------------------------------------ main

def snapshot(tmp):
    """Private copies of bin/wskel and bin/wskel-gen."""
    out = {}
    for key, path in (("wskel", tl.WSKEL), ("gen", makers.WSKEL_GEN)):
        if not tl.have(path):
            raise SystemExit("stress.py: %s is not built (run make)" % path)
        dst = os.path.join(tmp, os.path.basename(path))
        shutil.copy2(path, dst)
        out[key] = dst
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description="the stress sweep (see the module docstring)")
    ap.add_argument("--cases", type=int, default=None,
                    help="cases (default 10000; --quick: 300)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per run (default 20)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default=None,
                    help="output directory (default results/stress; --quick: a temporary one)")
    ap.add_argument("--classes", default="", help="comma-separated maker classes (default all)")
    ap.add_argument("--variants", default="",
                    help="comma-separated variants to run besides naive, the reference "
                    "(default all); KNOWN rows of the others are not checked")
    ap.add_argument("--only", type=int, action="append", default=[],
                    help="run only case I (repeatable)")
    ap.add_argument("--mem-mb", type=int, default=4096,
                    help="address-space limit per run in MB (0: none)")
    ap.add_argument("--quick", action="store_true", help="the make test version (see above)")
    ap.add_argument("--update-known", action="store_true",
                    help="with --quick: rewrite tests/data/stress/KNOWN from this run")
    ap.add_argument("--list-classes", action="store_true")
    a = ap.parse_args(argv)
    if a.list_classes:
        for c, m in makers.classes():
            print(c)
        return 0
    if a.update_known and not a.quick:
        ap.error("--update-known needs --quick")
    if a.update_known and a.variants:
        ap.error("--update-known needs every variant (no --variants)")
    ncases = a.cases if a.cases is not None else (300 if a.quick else 10000)
    tmp = tempfile.mkdtemp(prefix="wskel-stress-")
    try:
        progs = snapshot(tmp)
        makers.WSKEL_GEN = progs["gen"]
        os.environ["WSKEL_GEN_BIN"] = progs["gen"]
        names = [c for c in a.classes.split(",") if c]
        classes = select_classes(names)
        # --quick: a directory of its own, removed when the run passes (kept, and
        # named, when it fails)
        out = a.out or (tempfile.mkdtemp(prefix="wskel-stress-quick-") if a.quick else
                        os.path.join(ROOT, "results", "stress"))
        if os.path.isdir(os.path.join(out, "failures")):
            shutil.rmtree(os.path.join(out, "failures"))
        os.makedirs(os.path.join(out, "failures"), exist_ok=True)
        if os.path.abspath(out).startswith(ROOT + os.sep) and not a.quick:
            # a run's output (results/stress/), never committed
            with open(os.path.join(out, ".gitignore"), "w") as f:
                f.write("# written by tests/stress/stress.py: not under version control\n*\n")
        cfg = {"wskel": progs["wskel"], "timeout": a.timeout, "seed": a.seed, "tmp": tmp,
               "mem_mb": a.mem_mb, "class_names": [c for c, _ in classes],
               "variant_names": [v for v in a.variants.split(",") if v]}
        init_worker(cfg)
        indices = a.only or list(range(ncases))
        what = "stress%s: %d cases, %d classes, %d variants, %d jobs, %g s per run" % (
            " (quick)" if a.quick else "", len(indices), len(classes), len(VARIANTS), a.jobs,
            a.timeout)
        print(what, file=sys.stderr, flush=True)
        t0 = time.monotonic()
        summary = Summary([c for c, _ in classes])
        records = []
        fails = open(os.path.join(out, "failures.tsv"), "w")
        invalid = open(os.path.join(out, "invalid.tsv"), "w")
        # the cases a variant handed to the reference (not failures: listed
        # to be looked into), each with its file in OUT/fallbacks/
        fbdir = os.path.join(out, "fallbacks")
        if os.path.isdir(fbdir):
            shutil.rmtree(fbdir)
        fb = open(os.path.join(out, "fallbacks.tsv"), "w")
        fb.write("case\tclass\tvariant\tseconds\tmade\n")
        fails.write("case\tclass\tvariant\toutcome\texit\tseconds\tmessage\tmade\n")
        invalid.write("case\tclass\tstate\tmessage\tmade\n")
        step = max(1, len(indices) // 20)
        with multiprocessing.Pool(a.jobs, initializer=init_worker, initargs=(cfg,)) as pool:
            for k, rec in enumerate(pool.imap_unordered(run_case, indices, chunksize=4), 1):
                summary.add(rec)
                records.append(rec)
                if rec["state"] in ("invalid", "domain", "notmade", "makerbug"):
                    invalid.write("%s\t%s\t%s\t%s\t%s\n" % (rec["name"], rec["cls"], rec["state"],
                                                          short(rec["msg"], 400),
                                                          rec.get("desc", "")))
                elif summary.failing(rec):
                    write_failure(out, rec)
                    for v, r in rec["res"].items():
                        if r[0] in FAILURES:
                            fails.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                                rec["name"], rec["cls"], v, r[0], r[2], r[3], short(r[1], 400),
                                rec["desc"]))
                    fails.flush()
                if rec["state"] == "ran":
                    fbv = [(v, r) for v, r in rec["res"].items() if r[0] == "fallback"]
                    for v, r in fbv:
                        fb.write("%s\t%s\t%s\t%s\t%s\n" % (rec["name"], rec["cls"], v, r[3],
                                                            rec["desc"]))
                    if fbv:
                        os.makedirs(fbdir, exist_ok=True)
                        with open(os.path.join(fbdir, rec["name"] + ".wpoly"), "w") as f:
                            f.write(rec["text"])
                        fb.flush()
                if not a.quick and (k % step == 0 or k == len(indices)):
                    print("  %d/%d cases, %.0f s" % (k, len(indices), time.monotonic() - t0),
                          file=sys.stderr, flush=True)
        fails.close()
        invalid.close()
        fb.close()
        wall = time.monotonic() - t0
        ran = sum(s["ran"] for s in summary.state.values())
        nfail = sum(1 for r in records if summary.failing(r))
        st = collections.Counter()
        for c in summary.state.values():
            st.update(c)
        text = ("%s\nwall time %.1f s; %d cases ran, %d invalid (dropped), %d outside the "
                "input domain (dropped), %d not made, %d maker bugs; %d cases with a failure\n"
                "(columns: cases = valid cases run; invalid = the reader rejected the maker's "
                "polygon or the maker could not make it; domain = rejected by the input-domain "
                "bounds)\n" % (what, wall, ran, st["invalid"], st["domain"], st["notmade"],
                                st["makerbug"], nfail))
        text += summary.table() + "\n"
        inv = ["%s: %d x %s" % (c, k2, m) for c in summary.classes
               for m, k2 in summary.invalid_msgs[c].most_common(3)]
        if inv:
            text += "\ndropped (invalid, domain, not made), the commonest reasons per class:\n  " + \
                "\n  ".join(inv) + "\n"
        text += failure_kinds(records, summary, os.path.join(out, "failures"))
        text += "\nfailing inputs: %s\n" % os.path.join(out, "failures")
        if a.quick:  # the whole table only when the verdict is a failure
            totals = summary.totals()
            print("wall time %.1f s; %d cases ran, %d dropped; %d cases with a failure" % (
                wall, ran, st["invalid"] + st["domain"] + st["notmade"], nfail))
            for v, _ in VARIANTS:
                print("  %-17s %s" % (v, ", ".join("%s %d" % (k, totals[v].get(k, 0))
                                                    for k in OUTCOMES if totals[v].get(k))))
        else:
            print(text)
        with open(os.path.join(out, "summary.txt"), "w") as f:
            f.write(text)
        with open(os.path.join(out, "summary.json"), "w") as f:
            json.dump({"cases": len(indices), "ran": ran, "wall_s": round(wall, 1),
                       "seed": a.seed, "timeout_s": a.timeout, "totals": summary.totals(),
                       "per_class": {"%s/%s" % k: dict(v) for k, v in summary.counts.items()},
                       "states": {c: dict(s) for c, s in summary.state.items()}}, f, indent=1)
        if not a.quick:
            # make stress: every failure must be a known one (KNOWN, as --quick)
            problems = check_known(summary, records, lambda s: print(s, file=sys.stderr))
            if problems:
                print("stress: FAILED:\n  " + "\n  ".join(problems), file=sys.stderr)
                return 1
            print("stress: ok: %d cases ran, %d with a failure, all known (%d rows of %s)"
                  % (ran, nfail, len(read_known()), KNOWN_FILE), file=sys.stderr)
            return 0
        # ---- quick: the make test verdict
        problems = []
        if ran == 0:
            problems.append("no case ran: the sweep tested nothing")
        problems += ["%s: %s" % (r["name"], r["msg"]) for r in records
                     if r["state"] == "makerbug"]
        for c in summary.classes:
            if summary.state[c]["ran"] == 0:
                problems.append("class %s: no valid case among %d (invalid: %s)"
                                % (c, sum(summary.state[c].values()),
                                   "; ".join(m for m, _ in summary.invalid_msgs[c].most_common(2))))
        if a.update_known:
            k = update_known(records, summary)
            print("stress: wrote %d known failures to %s" % (k, KNOWN_FILE), file=sys.stderr)
        problems += check_known(summary, records, lambda s: print(s, file=sys.stderr))
        if problems:
            print(text, file=sys.stderr)
            print("stress (quick): FAILED:\n  " + "\n  ".join(problems), file=sys.stderr)
            print("summary and failing inputs kept in %s" % out, file=sys.stderr)
            return 1
        print("stress (quick): ok: %d cases ran, %d known failures still fail as listed"
              % (ran, len(read_known())), file=sys.stderr)
        if not a.out:
            shutil.rmtree(out, ignore_errors=True)
        return 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
