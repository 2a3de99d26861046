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

KEY_COLS = 8  # variant family n r_req k weights seed repeat


def read(path):
    comments, header, rows = [], None, []
    with open(path, newline="") as f:
        data = [line for line in f]
    body = []
    for line in data:
        if line.startswith("#"):
            comments.append(line)
        elif line.strip():
            body.append(line)
    reader = csv.reader(body)
    for fields in reader:
        if header is None:
            header = fields
        elif len(fields) == len(header):
            rows.append(fields)
    return comments, header, rows


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
            key = ",".join(r[:KEY_COLS])
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
        rows.sort(key=lambda r: order.get(",".join(r[:KEY_COLS]), 1 << 62))
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
                k = d["k"] if d["k"] is not None else ""
                key = ",".join(str(x) for x in (d["variant"], d["family"], d["n"], d["r_req"], k,
                                                d["weights"], d["seed"], d["repeat"]))
                jrows.setdefault(key, line if line.endswith("\n") else line + "\n")
    if jrows:
        with open(jsonl_path(args.out), "w") as f:
            for r in rows:
                line = jrows.get(",".join(r[:KEY_COLS]))
                if line:
                    f.write(line)
    print("merge_shards: %d rows from %d shards -> %s" % (len(rows), len(args.shards), args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
