#!/usr/bin/python3
"""merge_shards.py: merge the CSVs of a sharded sweep (--shard I/N) into one.

usage: merge_shards.py OUT.csv SHARD.csv... [--spec SPEC --bench bin/wskel-bench]

Keeps the first shard's comment header (plus a line naming the shards), checks
that every shard has the same columns, drops exact duplicate configurations
(a shard re-run with --resume) and fails if two shards disagree on the status
of one configuration.  With --spec the rows are put in the sweep's
configuration order (from wskel-bench --dry-run) and missing configurations
are listed; otherwise shards are interleaved in file order.  The .jsonl twins
are merged the same way when present.
"""
import argparse
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results import config_text, read_raw  # noqa: E402


def read(path):
    """(comment lines, header, rows): rows as raw cells, so they are written
    back byte for byte; a row with the wrong number of cells (cut off by a
    killed shard) is dropped, its configuration then shows as missing."""
    comments, header, rows = read_raw(path)
    return comments, header or None, [r for r in rows if len(r) == len(header)]


def key_of(header, cells):
    return config_text(dict(zip(header, cells)))


def jsonl_path(path):
    return path[:-4] + ".jsonl" if path.endswith(".csv") else path + ".jsonl"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("shards", nargs="+")
    ap.add_argument("--spec")
    ap.add_argument("--bench", default="bin/wskel-bench")
    args = ap.parse_args()
    header0, comments0 = None, None
    rows, seen = [], {}
    for path in args.shards:
        comments, header, shard_rows = read(path)
        if header0 is None:
            header0, comments0 = header, comments
        elif header != header0:
            sys.exit("merge_shards: %s: columns differ from %s" % (path, args.shards[0]))
        for r in shard_rows:
            key = key_of(header, r)
            status = r[header.index("status")]
            if key in seen:
                if seen[key] != status:
                    sys.exit("merge_shards: %s: %s is %s here, %s elsewhere" % (
                        path, key, status, seen[key]))
                continue
            seen[key] = status
            rows.append(r)
    order = None
    if args.spec:
        out = subprocess.run([args.bench, "--spec", args.spec, "--dry-run"], check=True,
                             capture_output=True, text=True).stdout
        order = {line.split(" ", 1)[1]: int(line.split(" ", 1)[0])
                 for line in out.splitlines() if line.strip()}
        missing = [k for k in order if k not in seen]
        extra = [k for k in seen if k not in order]
        rows.sort(key=lambda r: order.get(key_of(header0, r), 1 << 62))
        if missing:
            print("merge_shards: %d configurations missing, e.g. %s" % (len(missing), missing[0]))
        if extra:
            print("merge_shards: %d rows not in the spec, e.g. %s" % (len(extra), extra[0]))
    with open(args.out, "w", newline="") as f:
        f.writelines(comments0 or [])
        f.write("# merged from: %s\n" % " ".join(args.shards))
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header0)
        w.writerows(rows)
    # JSON lines: same keys, same order.
    jrows = {}
    for path in args.shards:
        jp = jsonl_path(path)
        if os.path.exists(jp):
            for line in open(jp):
                try:
                    d = json.loads(line)
                except ValueError:
                    continue
                # JSON's null k is the CSV's empty cell, as config_text writes it.
                jrows.setdefault(config_text(d), line if line.endswith("\n") else line + "\n")
    if jrows:
        with open(jsonl_path(args.out), "w") as f:
            for r in rows:
                line = jrows.get(key_of(header0, r))
                if line:
                    f.write(line)
    print("merge_shards: %d rows from %d shards -> %s" % (len(rows), len(args.shards), args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
