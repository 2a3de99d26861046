#!/usr/bin/python3
"""test_scripts.py: tests of the benchmark scripts on small synthetic CSVs.

  - scripts/results.py: the loader (comments apart, empty counter cells as
    None, columns found by name), the configuration key, k order, slope;
  - fit.py recovers the exact coefficients of rows made from its own model;
  - plot.py writes its PNGs from a CSV and a fit.json, draws the model of
    the fit.json (not a refit) dashed beside its data in the data's colour,
    leaves absent counters out, puts at most MAX_LINES data series in a
    panel (splitting a family's panel when there are more), one panel per
    family, and every legend beside its panel, clear of the data;
  - report.py embeds the figures and, with --roof, the rendered roof;
  - regress.py passes identical runs and fails on a changed counter, where
    an empty cell equals only an empty cell;
  - plot_offsets.py writes a PNG from GeoJSON offsets and a skeleton;
  - compare_skeletons.py compares times weight-aware: a zero-length arc
    of a weighted skeleton whose ends are tol / 2 apart, with times
    (tol / 2) / w apart, is one node; times 3 tol / w apart are not;
  - large_report.py (scripts/perf_large.sh's report): the exponent, time /
    qsort and bytes per vertex at 10^6 of rows made with known values, and
    the verdicts against the targets, "not measured" below 10^6.
No binary is needed.  Prints a line per test and 'N passed, N failed'; exits
1 on any failure.  usage: /usr/bin/python3 tests/test_scripts.py
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import traceback

os.environ["MPLBACKEND"] = "Agg"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRIPTS = os.path.join(ROOT, "scripts")
sys.path.insert(0, SCRIPTS)
import results  # noqa: E402

PY = sys.executable
TMP = tempfile.mkdtemp(prefix="wskel-test-scripts.")
MID = ["r", "status", "signal", "wall_s", "cpu_s", "peak_rss_bytes", "peak_tracked_bytes",
       "nodes", "arcs", "crossings", "validated"]
# No stale_events (it is being removed) and a counter the scripts never heard of.
COUNTERS = ["edge_events", "split_events", "multi_split_events", "switch_events",
            "start_events", "cache_hits", "queue_pops", "brand_new_counter"]
ARR_ONLY = {"switch_events", "start_events", "cache_hits"}
COEF = [2e-8, 5e-10, 3e-9, 1e-3]   # c1 n^2, c2 r^3/k, c3 n r log n, c0


def model_time(n, r, k):
    row = {"k": k, "r": r}
    x = [n * n, r ** 3 / max(results.k_value(row), 1.0), n * max(r, 1) * math.log(max(n, 2)), 1]
    return sum(c * v for c, v in zip(COEF, x))


def make_row(variant, family, n, k="", seed=1, repeat=0, weights="unit", wall=None):
    r = n // 3
    row = {"variant": variant, "family": family, "n": n, "r_req": -1, "holes": 0, "k": k,
           "weights": weights, "seed": seed, "repeat": repeat, "r": r, "status": "ok",
           "signal": None, "wall_s": wall if wall is not None else model_time(n, r, k),
           "cpu_s": 0.001, "peak_rss_bytes": 1000 * n, "peak_tracked_bytes": 100 * n + 7,
           "nodes": 2 * n - 2, "arcs": 2 * n - 3, "crossings": r * (r - 1) // 2,
           "validated": 1, "message": ""}
    for i, c in enumerate(COUNTERS):
        absent = variant != "arrangement" and c in ARR_ONLY
        row[c] = None if absent else n * (i + 1) + seed
    return row


def write_csv(name, rows, counters=COUNTERS, comments=("date: 2026-01-01", "cores: 2")):
    path = os.path.join(TMP, name)
    cols = list(results.CONFIG_COLS) + MID + list(counters) + ["message"]
    with open(path, "w", newline="") as f:
        f.write("# wskel-bench results (synthetic)\n")
        for c in comments:
            f.write("# %s\n" % c)
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for r in rows:
            # repr keeps the times exact, so the fit sees the model's own numbers.
            w.writerow([repr(r[c]) if isinstance(r[c], float) else results.cell(r[c])
                        for c in cols])
    return path


def run(script, *args):
    p = subprocess.run([PY, os.path.join(SCRIPTS, script)] + list(args), capture_output=True,
                       text=True, cwd=ROOT, timeout=120)
    return p.returncode, p.stdout + p.stderr


def sweep_rows():
    """Two variants, two families; arrangement with a k sweep at n = 1000."""
    rows = []
    for fam in ("star", "crossing"):
        for n in (200, 500, 1000, 2000, 5000):
            rows.append(make_row("naive", fam, n, wall=1e-9 * n * n + 1e-4))
            for k in ("1", "max"):
                rows.append(make_row("arrangement", fam, n, k))
        for k in ("2", "4", "8"):
            rows.append(make_row("arrangement", fam, 1000, k))
    return rows


# ---------------------------------------------------------------- results.py

def test_loader_comments_and_types():
    path = write_csv("load.csv", [make_row("naive", "star", 100), make_row("arrangement", "star",
                                                                            100, "max")])
    comments, rows = results.load_csv(path)
    assert comments == ["wskel-bench results (synthetic)", "date: 2026-01-01", "cores: 2"], comments
    assert len(rows) == 2, rows
    n, a = rows
    assert n["n"] == 100 and n["r_req"] == -1 and n["k"] == "" and a["k"] == "max"
    assert isinstance(n["wall_s"], float) and n["signal"] is None and n["message"] == ""
    assert list(n)[:9] == list(results.CONFIG_COLS), list(n)


def test_qsort_reference_from_comments():
    path = write_csv("qsort.csv", [make_row("naive", "star", 100)],
                     comments=("date: 2026-01-01",
                               "qsort_ref_s: 0.08 (before the runs; qsort() of 1000000 doubles)",
                               "qsort_ref_s: 0.1 (after the runs; ...)"))
    comments, rows = results.load_csv(path)
    assert len(rows) == 1
    assert abs(results.qsort_ref(comments) - 0.09) < 1e-12, results.qsort_ref(comments)
    assert results.qsort_ref(comments + ["qsort_ref_s: 0.5 (resumed)"]) == 0.1
    assert results.qsort_ref(["date: 2026-01-01"]) is None
    try:
        results.qsort_ref(["qsort_ref_s: soon"])
        raise AssertionError("a malformed line was accepted")
    except ValueError:
        pass


def test_loader_empty_counters_are_none():
    path = write_csv("empty.csv", [make_row("naive", "star", 100), make_row("arrangement",
                                                                             "star", 100, "1")])
    assert results.counter_columns(path) == COUNTERS, results.counter_columns(path)
    _, (n, a) = results.load_csv(path)
    for c in ARR_ONLY:
        assert n[c] is None, (c, n[c])
        assert isinstance(a[c], int) and a[c] > 0, (c, a[c])
    assert n["edge_events"] == 101 and n["brand_new_counter"] == 801
    assert "stale_events" not in n


def test_loader_rejects_bad_integer_and_pads_short_rows():
    path = write_csv("bad.csv", [make_row("naive", "star", 100)])
    text = open(path).read().replace(",101,", ",1.5,")
    open(path, "w").write(text)
    try:
        results.load_csv(path)
        raise AssertionError("a counter of 1.5 was accepted")
    except ValueError as e:
        assert "edge_events" in str(e), e
    with open(path, "w") as f:
        f.write(",".join(list(results.CONFIG_COLS) + MID + ["message"]) + "\n")
        f.write("naive,star,100,-1,0,,unit,1,0,33\n")
    _, rows = results.load_csv(path)
    assert rows[0]["r"] == 33 and rows[0]["nodes"] is None and rows[0]["message"] == ""


def test_config_key_one_definition():
    row = make_row("arrangement", "star", 300, "8", seed=2, repeat=1)
    path = write_csv("key.csv", [row])
    _, (loaded,) = results.load_csv(path)
    _, header, (raw,) = results.read_raw(path)
    as_json = dict(loaded, k=8)
    keys = {results.config_key(loaded), results.config_key(dict(zip(header, raw))),
            results.config_key(as_json)}
    assert keys == {("arrangement", "star", "300", "-1", "0", "8", "unit", "2", "1")}, keys
    # wskel-bench's --dry-run / --resume key, with JSON's null k as the empty cell
    j = {"variant": "naive", "family": "comb", "n": 40, "r_req": -1, "holes": 2, "k": None,
         "weights": "unit", "seed": 3, "repeat": 0}
    assert results.config_text(j) == "naive,comb,40,-1,2,,unit,3,0", results.config_text(j)
    del j["holes"]  # a JSON line of a file written before the holes axis
    assert results.config_text(j) == "naive,comb,40,-1,0,,unit,3,0", results.config_text(j)
    assert results.config_key(loaded, drop=("repeat",))[-1] == "2"



def test_csv_without_holes_column_loads_as_holes_0():
    """A CSV of before the holes axis (the committed baselines): holes = 0 on
    every row, in its place after r_req, keyed like a new file's rows."""
    rows = regress_rows()
    new = write_csv("with_holes.csv", rows)
    old = os.path.join(TMP, "without_holes.csv")
    with open(new) as f, open(old, "w") as g:
        for line in f:
            if line.startswith("#"):
                g.write(line)
                continue
            cells = line.rstrip("\n").split(",")
            del cells[4]
            g.write(",".join(cells) + "\n")
    _, header, _ = results.read_raw(old)
    assert "holes" not in header and header[:4] == ["variant", "family", "n", "r_req"], header
    _, a = results.load_csv(new)
    _, b = results.load_csv(old)
    assert a == b, (a[0], b[0])
    assert list(b[0])[:9] == list(results.CONFIG_COLS) and b[0]["holes"] == 0
    raw = dict(zip(header, results.read_raw(old)[2][0]))
    assert results.config_key(raw) == results.config_key(a[0]), results.config_key(raw)
    # regress.py compares the new file with the old one as equal
    rc, out = run("regress.py", new, old)
    assert rc == 0 and "3 configurations compared, 0 regressions" in out, out

def test_k_order_value_group_slope():
    ks = ["max", "16", "", "2", "1", 4]
    assert sorted(ks, key=results.k_order) == ["", "1", "2", 4, "16", "max"]
    assert results.k_value({"k": "", "r": 50}) == 1.0
    assert results.k_value({"k": "max", "r": 50}) == 50.0
    assert results.k_value({"k": "16", "r": 50}) == 16.0
    g = results.group_by([{"a": 1, "b": 2}, {"a": 1, "b": 3}, {"a": 2, "b": 2}], ("a",))
    assert list(g) == [(1,), (2,)] and len(g[(1,)]) == 2
    s = results.loglog_slope([1, 2, 4, 8, None], [3, 12, 48, 192, 5])
    assert abs(s - 2.0) < 1e-12, s
    assert math.isnan(results.loglog_slope([4, 4], [1, 2]))
    assert math.isnan(results.loglog_slope([1, 2], [0, 3]))


# ---------------------------------------------------------------- fit.py

def test_fit_recovers_coefficients():
    rows = [r for r in sweep_rows() if r["variant"] == "arrangement"]
    path = write_csv("fit.csv", rows)
    out = os.path.join(TMP, "fit.json")
    rc, text = run("fit.py", path, "--json", out)
    assert rc == 0, text
    fits = json.load(open(out))
    assert set(fits) == {"arrangement", "arrangement/crossing/unit", "arrangement/star/unit"}
    for label, f in fits.items():
        for got, want in zip(f["coef"], COEF):
            assert abs(got - want) <= 1e-6 * want, (label, f["coef"], COEF)
        assert abs(f["r2"] - 1.0) < 1e-9 and f["median_rel_err"] < 1e-9, (label, f)
        assert abs(sum(f["share"]) - 1.0) < 1e-9 and f["share_at"]["n"] == 5000
    assert fits["arrangement"]["points"] == len(rows)
    sys.path.insert(0, SCRIPTS)
    import fit
    # fit.txt and fit.json say the same: the table is the JSON printed.
    assert text == fit.format_fits(fits), text
    assert text.startswith("model: time = c1 n^2 + c2 r^3/k + c3 n r log n + c0  (NNLS, "
                           "relative error, scipy.optimize.nnls)\n"), text


# ---------------------------------------------------------------- plot.py

def test_plot_writes_pngs():
    path = write_csv("plot.csv", sweep_rows())
    fitj = os.path.join(TMP, "plotfit.json")
    rc, text = run("fit.py", path, "--json", fitj)
    assert rc == 0, text
    outdir = os.path.join(TMP, "plots")
    rc, text = run("plot.py", path, outdir, "--fit", fitj)
    assert rc == 0, text
    for name in ("time_vs_n", "memory_vs_n", "k_effect", "k_tradeoff", "events_vs_bounds"):
        png = os.path.join(outdir, name + ".png")
        assert os.path.exists(png), (png, text)
        with open(png, "rb") as f:
            head = f.read(8)
        assert head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(png) > 1000, png


def capture_figures(fn, *args):
    """Run a plot function with plot.save replaced, return {name: figure}."""
    import plot
    figs, save = {}, plot.save
    plot.save = lambda fig, outdir, name, written: figs.__setitem__(name, fig)
    try:
        note = fn(*args)
    finally:
        plot.save = save
    return figs, note


def test_plot_draws_the_given_fit():
    import plot
    import matplotlib.pyplot as plt
    path = write_csv("plotfit.csv", sweep_rows())
    # A model no fit of these rows gives: time 7 s everywhere.  Seeing it
    # drawn shows the curve comes from --fit's file, not from a refit.
    fitj = os.path.join(TMP, "seven.json")
    json.dump({"arrangement/star/unit": {"coef": [0.0, 0.0, 0.0, 7.0]}}, open(fitj, "w"))
    argv, sys.argv = sys.argv, ["plot.py", path, os.path.join(TMP, "p2"), "--fit", fitj]
    try:
        figs, rc = capture_figures(plot.main)
    finally:
        sys.argv = argv
    assert rc == 0 and "time_vs_n" in figs, (rc, figs)
    dashed = [ln for ax in figs["time_vs_n"].axes for ln in ax.get_lines()
              if ln.get_linestyle() == "--"]
    assert len(dashed) == 1, len(dashed)
    assert all(abs(y - 7.0) < 1e-12 for y in dashed[0].get_ydata()), dashed[0].get_ydata()
    plt.close("all")


def axes_titled(fig, prefix):
    return [ax for ax in fig.axes if ax.get_visible() and ax.get_title().startswith(prefix)]


def test_plot_skips_absent_counters():
    import plot
    import matplotlib.pyplot as plt
    _, rows = results.load_csv(write_csv("events.csv", sweep_rows()))
    figs, note = capture_figures(plot.plot_events, rows, TMP, [])
    assert note is None, note
    fig = figs["events_vs_bounds"]
    labels = lambda ax: sorted(c.get_label() for c in ax.collections)  # noqa: E731
    # One column per variant, one colour per family.  naive has no
    # switch_events (empty cells): its panel has no points, not zeros.
    (switch,) = axes_titled(fig, "arrangement: switch_events")
    assert labels(switch) == ["crossing", "star"], labels(switch)
    (nswitch,) = axes_titled(fig, "naive: switch_events")
    assert labels(nswitch) == [], labels(nswitch)
    (every,) = axes_titled(fig, "naive: all events")
    assert "star" in labels(every), labels(every)
    naive = [c for c in every.collections if c.get_label() == "star"][0]
    want = sorted(r["edge_events"] + r["split_events"] + r["multi_split_events"]
                  for r in rows if r["variant"] == "naive" and r["family"] == "star")
    assert sorted(naive.get_offsets()[:, 1]) == want
    nocount = [dict(r, **{c: None for c in plot.EVENT_COLS}) for r in rows]
    figs, note = capture_figures(plot.plot_events, nocount, TMP, [])
    assert not figs and "skipped" in note, note
    plt.close("all")


def many_variant_rows():
    """Eight variants on one family: more than a panel may hold."""
    rows = []
    for i in range(8):
        for n in (200, 1000, 3000):
            rows.append(make_row("v%d" % i, "star", n, wall=(i + 1) * 1e-9 * n * n))
    return rows


def data_lines(ax):
    """The data series of a panel: solid or dotted lines (dashed ones are
    models or the bound)."""
    return [ln for ln in ax.get_lines() if ln.get_linestyle() in ("-", ":")]


def test_plot_small_multiples_at_most_six_lines():
    import plot
    import matplotlib.pyplot as plt
    _, rows = results.load_csv(write_csv("many.csv", many_variant_rows() + sweep_rows()))
    for fn, name, args in ((plot.plot_time_vs_n, "time_vs_n", ({},)),
                           (plot.plot_memory_vs_n, "memory_vs_n", ())):
        figs, _ = capture_figures(fn, rows, TMP, [], *args)
        axes = [ax for ax in figs[name].axes if ax.get_visible()]
        counts = [len(data_lines(ax)) for ax in axes]
        assert max(counts) <= plot.MAX_LINES, (name, counts)
        star = [ax for ax in axes if ax.get_title().startswith("star")]
        # time: 10 series on star (8 + naive + arrangement) over 2 panels;
        # memory: 2 per variant (tracked and RSS), 20 over 4 panels.
        want = {"time_vs_n": 2, "memory_vs_n": 4}[name]
        assert len(star) == want, (name, [ax.get_title() for ax in star])
        assert sum(len(data_lines(ax)) for ax in star) == want * 5, (name, counts)
        # One panel per family and weight mode otherwise: crossing has one.
        assert len([ax for ax in axes if ax.get_title().startswith("crossing")]) == 1
    plt.close("all")


def test_plot_model_dashed_beside_its_data():
    import plot
    import matplotlib.pyplot as plt
    path = write_csv("plotmodel.csv", sweep_rows())
    _, rows = results.load_csv(path)
    fitj = os.path.join(TMP, "plotmodel.json")
    rc, text = run("fit.py", path, "--json", fitj)
    assert rc == 0, text
    fits = json.load(open(fitj))
    figs, _ = capture_figures(plot.plot_time_vs_n, rows, TMP, [], fits)
    for ax in figs["time_vs_n"].axes:
        data = data_lines(ax)
        dashed = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]
        # Every data line (naive and arrangement here) has its model, in its colour.
        assert len(data) == len(dashed) == 2, (ax.get_title(), len(data), len(dashed))
        assert sorted(str(d.get_color()) for d in data) == \
            sorted(str(d.get_color()) for d in dashed)
    plt.close("all")


def test_plot_legends_cover_no_data():
    import plot
    import matplotlib.pyplot as plt
    _, rows = results.load_csv(write_csv("legend.csv", sweep_rows()))
    figs = {}
    for fn, args in ((plot.plot_time_vs_n, ({},)), (plot.plot_memory_vs_n, ()),
                     (plot.plot_k, ()), (plot.plot_events, ())):
        f, _ = capture_figures(fn, rows, TMP, [], *args)
        figs.update(f)
    assert set(figs) == {"time_vs_n", "memory_vs_n", "k_effect", "k_tradeoff",
                         "events_vs_bounds"}, set(figs)
    for name, fig in figs.items():
        fig.canvas.draw()
        seen = 0
        for ax in fig.axes:
            leg = ax.get_legend()
            if leg is None:
                continue
            seen += 1
            a, b = ax.get_window_extent(), leg.get_window_extent()
            assert b.x0 >= a.x1 - 1, (name, ax.get_title(), a, b)
        assert seen >= 1, name
    # The k figures: one column per family (star, crossing).
    titles = sorted(ax.get_title() for ax in figs["k_effect"].axes if ax.get_visible())
    assert titles == ["crossing: peak memory against k", "crossing: time against k",
                      "star: peak memory against k", "star: time against k"], titles
    plt.close("all")


def test_report_embeds_the_roof():
    path = write_csv("report.csv", sweep_rows())
    plots = os.path.join(TMP, "report_plots")
    rc, text = run("plot.py", path, plots)
    assert rc == 0, text
    roof = os.path.join(TMP, "roofdir", "roof.png")
    os.makedirs(os.path.dirname(roof), exist_ok=True)
    shutil.copy(os.path.join(ROOT, "results", "roof", "roof_holes.png"), roof)
    out = os.path.join(TMP, "out", "REPORT.md")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    rc, text = run("report.py", path, plots, out, "--roof", roof)
    assert rc == 0, text
    md = open(out).read()
    assert "## A roof" in md and "](../roofdir/roof.png)" in md, md[-600:]
    assert "](../report_plots/k_effect.png)" in md
    # Without --roof (or with a missing file) no roof section.
    rc, text = run("report.py", path, plots, out, "--roof", roof + ".absent")
    assert rc == 0 and "## A roof" not in open(out).read(), text


# ---------------------------------------------------------------- regress.py

def regress_rows():
    rows = []
    for rep in range(2):
        rows.append(make_row("naive", "star", 3000, repeat=rep, wall=0.5))
        rows.append(make_row("naive", "comb", 300, repeat=rep, wall=0.02))
        rows.append(make_row("arrangement", "star", 300, "1", repeat=rep, wall=0.03))
    return rows


def regress(base_rows, run_rows, base_counters=COUNTERS, run_counters=COUNTERS):
    base = write_csv("base.csv", base_rows, base_counters)
    runf = write_csv("run.csv", run_rows, run_counters)
    return run("regress.py", runf, base)


def test_regress_identical_passes():
    rows = regress_rows()
    assert any(r["switch_events"] is None for r in rows)   # empty in both
    rc, text = regress(rows, rows)
    assert rc == 0, text
    assert "3 configurations compared, 0 regressions" in text, text


def test_regress_changed_counter_fails():
    rows = regress_rows()
    changed = [dict(r) for r in rows]
    changed[2]["queue_pops"] += 1
    rc, text = regress(rows, changed)
    assert rc == 1 and "REGRESSION" in text and "queue_pops" in text, text


def test_regress_empty_versus_zero_fails():
    rows = regress_rows()
    changed = [dict(r) for r in rows]
    for r in changed:
        if r["family"] == "comb":
            r["switch_events"] = 0
    rc, text = regress(rows, changed)
    assert rc == 1 and "switch_events empty->0" in text, text


def test_regress_counter_columns_by_name():
    rows = regress_rows()
    rc, text = regress(rows, rows, run_counters=list(reversed(COUNTERS)))
    assert rc == 0, text
    old = [dict(r, stale_events=0) for r in rows]
    rc, text = regress(old, rows, base_counters=COUNTERS + ["stale_events"])
    assert rc == 1 and "only in the baseline: stale_events" in text, text


# ---------------------------------------------------------------- large_report.py

def test_large_report_exponent_ratio_and_verdicts():
    q = 0.1
    rows = []
    for n in (1000, 10000, 100000, 1000000):
        # fast: time 20 qsorts at 10^6, exponent 1.1, 500 bytes per vertex
        r = make_row("fast", "coastline", n, wall=20 * q * (n / 1e6) ** 1.1)
        r["peak_tracked_bytes"] = 500 * n
        rows.append(r)
        if n <= 100000:  # slow: quadratic, capped at 10^5
            rows.append(make_row("slow", "coastline", n, wall=1e-7 * n * n))
    rows.append(dict(make_row("slow", "star", 1000), status="timeout", wall_s=None,
                     message="time limit 5s exceeded during construction"))
    path = write_csv("large.csv", rows, comments=(
        "date: 2026-01-01", "cpu: test", "qsort_ref_s: %r (before the runs; ...)" % q,
        "qsort_ref_s: %r (after the runs; ...)" % q))
    out = os.path.join(TMP, "large")
    rc, text = run("large_report.py", path, out, "--command", "perf_large.sh fast slow")
    assert rc == 0, text
    with open(os.path.join(out, "summary.csv")) as f:
        summ = {(r["variant"], r["family"]): r for r in csv.DictReader(f)}
    fast = summ[("fast", "coastline")]
    assert abs(float(fast["exponent"]) - 1.1) < 1e-3, fast
    assert abs(float(fast["time_over_qsort_1e6"]) - 20) < 1e-3, fast
    assert float(fast["bytes_per_vertex_1e6"]) == 500.0, fast
    assert (fast["meets_time"], fast["meets_memory"], fast["meets_exponent"]) == (
        "meets", "meets", "meets"), fast
    slow = summ[("slow", "coastline")]
    assert abs(float(slow["exponent"]) - 2) < 1e-3 and slow["max_n_ok"] == "100000", slow
    assert slow["meets_time"] == "not measured" and slow["meets_memory"] == "not measured"
    assert slow["meets_exponent"] == "misses (fit below 10^6 only)", slow
    star = summ[("slow", "star")]
    assert star["status_n1000"] == "timeout" and star["exponent"] == "", star
    assert star["meets_exponent"] == "not measured" and star["max_n_ok"] == "", star
    report = open(os.path.join(out, "REPORT.md")).read()
    assert "median **0.1 s**" in report and "| fast | coastline | 1000000 |" in report, report
    assert "timeout (time limit 5s exceeded" in report, report


def test_plot_offsets_writes_png():
    """plot_offsets.py draws GeoJSON offsets (a square with a hole, two
    times, one empty) and a skeleton into a PNG."""
    sq = [[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]]
    hole = [[1, 1], [1, 2], [2, 2], [2, 1], [1, 1]]
    offs = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"t": t},
         "geometry": {"type": "MultiPolygon", "coordinates": c}}
        for t, c in ((0, [[sq, hole]]), (0.5, [[[[0.5, 0.5], [3.5, 0.5], [3.5, 3.5], [0.5, 3.5],
                                                  [0.5, 0.5]]]]), (2, []))]}
    skel = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"a": 0, "b": 4, "left": 3, "right": 0},
         "geometry": {"type": "LineString", "coordinates": [[0, 0, 0], [2, 2, 2]]}}]}
    po, ps, png = (os.path.join(TMP, n) for n in ("o.geojson", "s.geojson", "o.png"))
    for path, doc in ((po, offs), (ps, skel)):
        with open(path, "w") as f:
            json.dump(doc, f)
    r = subprocess.run([PY, os.path.join(SCRIPTS, "plot_offsets.py"), po, "--skeleton", ps,
                        "-o", png, "--title", "test"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(png, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"


# ------------------------------------------------------- compare_skeletons.py

def _square(w, centre):
    """The unit square, weight w on every edge, as a wskel-1 dict whose
    interior nodes are `centre` (a list of [x, y, t]); arcs to fill in."""
    return {"format": "wskel-1", "n": 4, "r": 0, "rings": [4],
            "nodes": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]] + centre, "arcs": []}


def test_compare_skeletons_time_tolerance_is_weight_aware():
    import compare_skeletons as cs
    w = 0.01
    a = _square(w, [[0.5, 0.5, 0.5 / w]])
    a["arcs"] = [[0, 4, 3, 0], [1, 4, 0, 1], [2, 4, 1, 2], [3, 4, 2, 3]]
    tol = cs.default_tol(a)

    def split(dt):
        """The centre as two nodes tol / 2 apart joined by a zero-length arc,
        the second one dt later."""
        d = tol / 2
        b = _square(w, [[0.5, 0.5, 0.5 / w], [0.5 + d, 0.5, 0.5 / w + dt]])
        b["arcs"] = [[0, 4, 3, 0], [1, 5, 0, 1], [2, 5, 1, 2], [3, 4, 2, 3], [4, 5, 0, 2]]
        return b
    # tol / 2 along the arc is (tol / 2) / w in time: 50 tol, far above tol
    same = cs.compare(a, split((tol / 2) / w))
    assert same.identical, same.summary() + "\n" + "\n".join(same.details())
    assert same.counts["zero_arcs_b"] == 1, same.summary()
    assert [round(x, 12) for x in cs.face_weights(a)] == [w] * 4, cs.face_weights(a)
    # 3 tol / w is more than any position within tol explains
    off = cs.compare(a, split(3 * tol / w))
    assert not off.identical and off.time_mismatches, off.summary()
    # the same with given weights; unit weights make 50 tol a mismatch
    assert cs.compare(a, split((tol / 2) / w), weights=[w] * 4).identical
    assert not cs.compare(a, split((tol / 2) / w), weights=[1.0] * 4).identical


def test_compare_skeletons_chained_merge_is_not_a_time_mismatch():
    """A merged node may chain nodes far more than tol apart (each within tol
    of the next); its members' times then differ by up to their spread over
    the weight, and a skeleton compared with itself must be identical.  The
    case (audit of issue 11): a radius-1000 16-gon with vertex 1 pulled out
    to x = 4e9, naive's skeleton: tol 400 merges 17 nodes over 2000 units,
    t from 0 to 474; before, compare(a, a) said DIFFERENT."""
    import compare_skeletons as cs
    a = {"format": "wskel-1", "n": 16, "r": 2, "rings": [16],
         "nodes": [[1000, 0, 0], [4000000000, 382.6834323650898, 0], [707.1067811865476, 707.1067811865474, 0], [382.68343236508986, 923.8795325112867, 0], [6.123233995736766e-14, 1000, 0], [-382.68343236508974, 923.8795325112867, 0], [-707.1067811865474, 707.1067811865476, 0], [-923.8795325112867, 382.6834323650899, 0], [-1000, 1.2246467991473532e-13, 0], [-923.8795325112868, -382.6834323650897, 0], [-707.1067811865477, -707.1067811865474, 0], [-382.6834323650903, -923.8795325112865, 0], [-1.8369701987210297e-13, -1000, 0], [382.68343236509, -923.8795325112866, 0], [707.1067811865473, -707.1067811865477, 0], [923.8795325112865, -382.68343236509037, 0], [709.846214056015, 353.5533766025476, 353.5534043618146], [563.3995974063873, 233.367754325643, 473.739038516197], [0, 1.333736175840638e-09, 980.7852804015932]],
         "arcs": [[0, 16, 15, 0], [1, 16, 0, 1], [16, 17, 15, 1], [2, 17, 1, 2], [7, 18, 6, 7], [6, 18, 5, 6], [8, 18, 7, 8], [5, 18, 4, 5], [9, 18, 8, 9], [4, 18, 3, 4], [10, 18, 9, 10], [3, 18, 2, 3], [15, 18, 14, 15], [14, 18, 13, 14], [17, 18, 15, 2], [13, 18, 12, 13], [12, 18, 11, 12], [11, 18, 10, 11]]}
    same = cs.compare(a, a)
    assert same.identical, same.summary() + "\n" + "\n".join(same.details())
    assert same.counts["merged_a"] < 19, same.summary()  # the chain did merge
    # a time off by more than the spread explains (2000 units at weight 1) is
    # still a mismatch; the weights are given, since read off the skeleton a
    # wrong t makes its face look slow and the tolerance grow with it
    b = json.loads(json.dumps(a))
    b["nodes"][17][2] += 5000.0
    off = cs.compare(a, b, weights=[1.0] * 16)
    assert not off.identical and off.time_mismatches, off.summary()


def test_gen_pslg_deterministic_and_non_crossing():
    """scripts/gen_pslg.py: the same N and seed give the same segments, a
    new seed others; no two segments cross or come within the clearance
    (tested here by brute force over all pairs, not by the grid it uses)."""
    sys.path.insert(0, SCRIPTS)
    import gen_pslg
    a, b, c = gen_pslg.segments(60, 5), gen_pslg.segments(60, 5), gen_pslg.segments(60, 6)
    assert a == b and a != c
    assert len(a) == 60, len(a)
    for i in range(len(a)):
        for j in range(i):
            (p, q), (r, t) = a[i], a[j]
            crosses = (gen_pslg._orient(p, q, r) * gen_pslg._orient(p, q, t) < 0
                       and gen_pslg._orient(r, t, p) * gen_pslg._orient(r, t, q) < 0)
            near = min(gen_pslg._dist(p, r, t), gen_pslg._dist(q, r, t),
                       gen_pslg._dist(r, p, q), gen_pslg._dist(t, p, q))
            assert not crosses and near >= 0.5, (i, j, near)
    text = gen_pslg.graphml(a)
    assert text.count("<edge ") == 60 and text.count("<node ") == 120


def main():
    tests = [(k, v) for k, v in globals().items() if k.startswith("test_") and callable(v)]
    failed = 0
    for name, fn in tests:
        try:
            fn()
            print("ok   " + name)
        except Exception:
            failed += 1
            print("FAIL " + name)
            traceback.print_exc()
    shutil.rmtree(TMP, ignore_errors=True)
    print("test_scripts.py: %d passed, %d failed" % (len(tests) - failed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
