"""results.py: reading wskel-bench result CSVs, shared by the other scripts.

fit.py, plot.py, report.py, regress.py and merge_shards.py all read the
harness's CSV through this module, so the format is understood in one place:

  - '#' lines are comments (the machine and build header), returned apart;
  - the configuration is CONFIG_COLS, the same columns, in the same order and
    spelling, as wskel-bench's resume and --dry-run key (config_text);
  - CSVs written before the holes axis (no `holes` column, e.g. the
    committed results/baseline/regress.csv) load with holes = 0 on every
    row, inserted after r_req as if the column had been there; config_key
    and config_text give a missing holes (a raw row or JSON line of such a
    file) the same default, so old and new files key alike;
  - the counter columns are the ones between `validated` and `message`.  They
    are the union of the variants' declared counters, and a counter that a
    row's variant does not have is an empty cell, loaded as None (absent).
    None is not 0: consumers skip it or compare it as a value of its own.
    Columns are found by name, so added or removed columns (stale_events is
    going away) need no change here.

Also the order of k (empty = no cache, integers, then max), k as a number
for the model, group-by helpers, the log-log slope and the qsort() reference
of the '#' block (qsort_ref, written by wskel-bench --qsort-ref).  Plain Python only.
"""
import csv
import math

CONFIG_COLS = ("variant", "family", "n", "r_req", "holes", "k", "weights", "seed", "repeat")
# Configuration columns a CSV may lack (older harness versions), with the
# value they had implicitly.
CONFIG_DEFAULTS = {"holes": 0}
INT_COLS = {"n", "r_req", "holes", "seed", "repeat", "r", "signal", "peak_rss_bytes",
            "peak_tracked_bytes", "nodes", "arcs", "crossings", "validated"}
FLOAT_COLS = {"wall_s", "cpu_s"}


def read_raw(path):
    """Return (comment_lines, header, rows) with the text exactly as in the
    file: comment lines with their '#' and newline, rows as lists of cells
    (merge_shards writes them back untouched, so nothing is converted)."""
    comments, body = [], []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line)
            elif line.strip():
                body.append(line)
    parsed = list(csv.reader(body))
    if not parsed:
        return comments, [], []
    return comments, parsed[0], parsed[1:]


def _counters(header):
    if not header:
        return []
    try:
        return header[header.index("validated") + 1:header.index("message")]
    except ValueError:
        raise ValueError("not a wskel-bench CSV: no 'validated' or 'message' column")


def counter_columns(path):
    """Names of the counter columns of a CSV, in file order."""
    return _counters(read_raw(path)[1])


def _convert(path, lineno, key, val, ints):
    if key in ints:
        if val == "":
            return None
        try:
            return int(val)
        except ValueError:
            raise ValueError("%s: row %d: %s = %r is not an integer" % (path, lineno, key, val))
    if key in FLOAT_COLS:
        return float(val) if val != "" else None
    return val


def load_csv(path):
    """Return (comments, rows): comment lines without '#' and surrounding
    blanks, rows as dicts in column order.  Integer and counter columns are
    ints, times floats; an empty number cell is None.  A short row (a line
    cut off by a killed writer) is padded with empty cells."""
    raw_comments, header, raw_rows = read_raw(path)
    comments = [c[1:].strip() for c in raw_comments]
    ints = INT_COLS | set(_counters(header))
    missing = [c for c in CONFIG_DEFAULTS if header and c not in header]
    rows = []
    for i, cells in enumerate(raw_rows, 1):
        cells = cells + [""] * (len(header) - len(cells))
        row = {key: _convert(path, i, key, val, ints) for key, val in zip(header, cells)}
        if missing:
            row = _with_defaults(row, missing)
        rows.append(row)
    return comments, rows


def _with_defaults(row, missing):
    """row with the missing configuration columns added at their place in
    CONFIG_COLS (after the column before them), holding their defaults."""
    out = {}
    for key, val in row.items():
        out[key] = val
        for c in missing:
            i = CONFIG_COLS.index(c)
            if i > 0 and CONFIG_COLS[i - 1] == key:
                out[c] = CONFIG_DEFAULTS[c]
    for c in missing:
        out.setdefault(c, CONFIG_DEFAULTS[c])
    return out


def cell(v):
    """A value as its CSV cell: None is the empty cell."""
    return "" if v is None else str(v)


def config_key(row, drop=()):
    """The configuration of a row (loaded, raw dict or JSON line) as a tuple
    of cell texts; drop leaves columns out (regress groups repeats: "repeat")."""
    return tuple(cell(row[c] if c in row else CONFIG_DEFAULTS[c])
                 for c in CONFIG_COLS if c not in drop)


def config_text(row):
    """The configuration as wskel-bench writes it in --dry-run and --resume."""
    return ",".join(config_key(row))


def group_by(rows, key):
    """{key: [rows]} in first-seen order; key is a function of a row or a
    tuple of column names."""
    if not callable(key):
        cols = tuple(key)
        key = lambda r: tuple(r[c] for c in cols)  # noqa: E731
    out = {}
    for r in rows:
        out.setdefault(key(r), []).append(r)
    return out


def k_order(k):
    """Sort key for k cells: empty (no cache) first, then integers by value,
    then max."""
    k = cell(k)
    if k == "":
        return (0, 0)
    if k == "max":
        return (2, 0)
    return (1, int(k))


def k_value(row):
    """k as a number for the model and the k axes: empty (no cache) counts as
    1, max as r (the cache then holds every crossing of a segment)."""
    k = cell(row.get("k"))
    if k == "":
        return 1.0
    if k == "max":
        return float(max(row["r"] or 1, 1))
    return float(k)


def qsort_ref(comments):
    """The machine's qsort() reference of a CSV (wskel-bench --qsort-ref, see
    bench/qsort_ref.h): the median of its `qsort_ref_s: SECONDS (...)`
    comment lines (comments as load_csv returns them), or None if it has
    none."""
    vals = []
    for c in comments:
        if c.startswith("qsort_ref_s:"):
            try:
                vals.append(float(c.split()[1]))
            except (IndexError, ValueError):
                raise ValueError("bad qsort reference line: %r" % c)
    if not vals:
        return None
    vals.sort()
    m = len(vals) // 2
    return vals[m] if len(vals) % 2 else 0.5 * (vals[m - 1] + vals[m])


def loglog_slope(xs, ys):
    """Least-squares slope of log y on log x over the points with x, y > 0;
    nan with fewer than two such points or a single x."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys)
           if x is not None and y is not None and x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    if sxx <= 0:
        return float("nan")
    return sum((x - mx) * (y - my) for x, y in pts) / sxx
