#!/bin/bash
# test_bench.sh: the benchmark harness's own tests (bin/wskel-bench and the
# scripts).  Run from the repository root after `make`:  bash tests/test_bench.sh
#   1. a crashing, a hanging and an out-of-memory child (--self-test, applied
#      to one configuration) and a rejected input each get their status, and
#      the other configurations of the sweep still run;
#   2. --resume after an interrupted sweep (a truncated CSV with a partial last
#      line, and a parent killed mid-sweep) gives the same rows as an
#      uninterrupted sweep (configuration, status and counter columns);
#   3. shards 0/3, 1/3, 2/3 cover every configuration exactly once, and
#      merge_shards.py puts them back together;
#   4. regress.py passes on an honest baseline and fails on doctored ones;
#   5. the holes axis: holes > 0 left out for families without holes,
#      'unsupported' for monotone, the spec key; a CSV of before the holes
#      column resumes as holes = 0 and keeps its columns, and regress.py
#      compares a new run with such a baseline;
#   6. the qsort() reference (--qsort-ref): alone it prints one positive
#      number of seconds; in a sweep (flag or spec key) the CSV gets a
#      '# qsort_ref_s:' line before and after the runs, rows and columns as
#      without it, --resume adds one more, scripts/results.py reads them;
#   7. scripts/perf_large.sh on small n: one CSV for all variants with their
#      qsort lines, --max-n honoured, summary.csv and REPORT.md written;
#      an unknown variant or a bad option is a usage error (64).
set -u
PY=/usr/bin/python3
BENCH=bin/wskel-bench
T=$(mktemp -d "${TMPDIR:-/tmp}/wskel-test-bench.XXXXXX")
trap 'rm -rf "$T"' EXIT
fails=0
pass() { echo "ok   $1"; }
fail() { echo "FAIL $1"; fails=$((fails + 1)); }
check() { if eval "$2"; then pass "$1"; else fail "$1"; fi; }

# status of the row for seed S (column 8) in CSV
status_of() { grep -v '^#' "$1" | awk -F, -v s="$2" 'NR > 1 && $8 == s { print $11 }'; }
# configuration, r, status, nodes, arcs, crossings, validated and counters:
# everything but times and memory, which differ between runs
stable_cols() {
    $PY - "$1" <<'EOF'
import sys
sys.path.insert(0, "scripts")
import fit
_, rows = fit.load_csv(sys.argv[1])
skip = {"wall_s", "cpu_s", "peak_rss_bytes", "message"}
for r in rows:
    print(",".join(str(v) for k, v in r.items() if k not in skip))
EOF
}

[ -x "$BENCH" ] || { echo "test_bench.sh: $BENCH missing (run make)"; exit 1; }

# ---- 1. failure statuses; the sweep continues
base=(--family star --n 100 --seeds 1..3 --quiet --validate)
$BENCH "${base[@]}" --self-test crash:1 --out "$T/crash.csv"
check "crash: status crash, signal 11" \
    '[ "$(status_of $T/crash.csv 2)" = crash ] && grep -q "^naive,star,100,-1,0,,unit,2,0,[0-9]*,crash,11," $T/crash.csv'
check "crash: the sweep continues" \
    '[ "$(status_of $T/crash.csv 1)" = ok ] && [ "$(status_of $T/crash.csv 3)" = ok ]'
start=$(date +%s)
$BENCH "${base[@]}" --self-test hang:1 --time-limit 1 --out "$T/hang.csv"
check "hang: status timeout within the limit" \
    '[ "$(status_of $T/hang.csv 2)" = timeout ] && [ $(( $(date +%s) - start )) -lt 10 ]'
check "hang: the sweep continues" \
    '[ "$(status_of $T/hang.csv 1)" = ok ] && [ "$(status_of $T/hang.csv 3)" = ok ]'
$BENCH "${base[@]}" --self-test oom:1 --mem-limit 200 --out "$T/oom.csv"
check "oom: status out-of-memory" '[ "$(status_of $T/oom.csv 2)" = out-of-memory ]'
check "oom: the sweep continues" \
    '[ "$(status_of $T/oom.csv 1)" = ok ] && [ "$(status_of $T/oom.csv 3)" = ok ]'
$BENCH --family notched --n 100 --r 90,10 --quiet --out "$T/rej.csv"
check "rejected: impossible generator parameters" \
    'grep -q "^naive,notched,100,90,0,,unit,1,0,0,rejected,.*r=90 > n/2=50" $T/rej.csv'
check "rejected: the sweep continues" 'grep -q "^naive,notched,100,10,0,,unit,1,0,10,ok," $T/rej.csv'
$BENCH --family star,monotone --n 100 --variant monotone --quiet --out "$T/uns.csv"
check "unsupported: monotone on a star polygon" \
    'grep -q "^monotone,star,100,.*,unsupported,.*not monotone in any direction" $T/uns.csv'
check "unsupported: a monotone polygon is ok" 'grep -q "^monotone,monotone,100,.*,ok," $T/uns.csv'
check "jsonl twin has every row" \
    '[ $(wc -l < $T/crash.jsonl) = 3 ] && grep -q "\"status\":\"crash\",\"signal\":11" $T/crash.jsonl'

# ---- 2. resume
sweep=(--family star,comb,spiral --n 100,300 --seeds 1,2 --weights unit,uniform --quiet --validate)
$BENCH "${sweep[@]}" --out "$T/full.csv"
stable_cols "$T/full.csv" > "$T/full.stable"
check "full sweep has 24 rows" '[ $(wc -l < $T/full.stable) = 24 ]'
# interrupted: keep the header and 7 rows, plus half of the 8th row
$BENCH "${sweep[@]}" --out "$T/cut.csv"
n_hdr=$(grep -c '^#' "$T/cut.csv")
head -n $((n_hdr + 1 + 7)) "$T/cut.csv" > "$T/cut2.csv"
sed -n "$((n_hdr + 9))p" "$T/cut.csv" | head -c 30 >> "$T/cut2.csv"
mv "$T/cut2.csv" "$T/cut.csv"
$BENCH "${sweep[@]}" --resume --out "$T/cut.csv"
stable_cols "$T/cut.csv" > "$T/cut.stable"
check "resume after truncation: same rows" 'cmp -s $T/full.stable $T/cut.stable'
# a parent killed mid-sweep
$BENCH "${sweep[@]}" --n 100,300,3000 --out "$T/kill.csv" &
pid=$!
sleep 0.4
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
$BENCH "${sweep[@]}" --n 100,300,3000 --resume --out "$T/kill.csv"
$BENCH "${sweep[@]}" --n 100,300,3000 --out "$T/kill_ref.csv"
check "resume after kill -9: same rows (and the kill did interrupt)" \
    'grep -q "^# resumed [1-9]" $T/kill.csv && cmp -s <(stable_cols $T/kill.csv) <(stable_cols $T/kill_ref.csv)'
check "resume of a finished sweep runs nothing" \
    '$BENCH "${sweep[@]}" --resume --dry-run --out $T/full.csv | wc -l | grep -qx 0'
sed 's/^# generator version: [0-9]*/# generator version: 0/' "$T/full.csv" > "$T/oldgen.csv"
check "resume refuses a CSV of another generator version" \
    '! $BENCH "${sweep[@]}" --resume --out $T/oldgen.csv 2>$T/oldgen.err && grep -q "generator version 0" $T/oldgen.err'

# ---- 3. shards
$BENCH "${sweep[@]}" --dry-run > "$T/all.list"
for i in 0 1 2; do $BENCH "${sweep[@]}" --shard $i/3 --dry-run; done | sort -n > "$T/shards.list"
check "shards 0/3 1/3 2/3 cover every configuration exactly once" \
    'cmp -s <(sort -n $T/all.list) $T/shards.list'
for i in 0 1 2; do $BENCH "${sweep[@]}" --shard $i/3 --out "$T/shard$i.csv"; done
spec="$T/sweep.spec"
printf 'family = star,comb,spiral\nn = 100,300\nseeds = 1,2\nweights = unit,uniform\nvalidate\n' > "$spec"
$PY scripts/merge_shards.py "$T/merged.csv" "$T"/shard{0,1,2}.csv --spec "$spec" --bench $BENCH > /dev/null
check "merge_shards gives the uninterrupted sweep" \
    'cmp -s <(stable_cols $T/merged.csv) $T/full.stable && [ $(wc -l < $T/merged.jsonl) = 24 ]'

# ---- 4. regress
rsweep=(--family star,comb --n 300,3000 --repeats 3 --quiet)
$BENCH "${rsweep[@]}" --out "$T/base.csv"
$BENCH "${rsweep[@]}" --out "$T/run.csv"
check "regress passes on an honest baseline" \
    '$PY scripts/regress.py $T/run.csv $T/base.csv --time-tol 3 > $T/r1.txt'
# doctor one counter (queue_pops of the first naive row) in the baseline
$PY - "$T/base.csv" "$T/doc1.csv" <<'EOF'
import sys
lines = open(sys.argv[1]).read().splitlines(True)
hdr = [l for l in lines if not l.startswith("#")][0].rstrip("\n").split(",")
i = hdr.index("queue_pops")
out, seen = [], False
for l in lines:
    if not l.startswith("#") and l.startswith("naive,") and not seen:
        f = l.split(",")
        f[i] = str(int(f[i]) + 1)
        l, seen = ",".join(f), True
    out.append(l)
open(sys.argv[2], "w").writelines(out)
EOF
check "regress fails on a doctored counter" \
    '! $PY scripts/regress.py $T/run.csv $T/doc1.csv --time-tol 3 > $T/r2.txt && grep -q "REGRESSION" $T/r2.txt'
$PY - "$T/base.csv" "$T/doc2.csv" <<'EOF'
import sys
lines = open(sys.argv[1]).read().splitlines(True)
hdr = [l for l in lines if not l.startswith("#")][0].rstrip("\n").split(",")
i = hdr.index("peak_tracked_bytes")
out, seen = [], False
for l in lines:
    if not l.startswith("#") and l.startswith("naive,") and not seen:
        f = l.split(",")
        f[i] = str(int(int(f[i]) / 1.05))   # the run now uses 5% more
        l, seen = ",".join(f), True
    out.append(l)
open(sys.argv[2], "w").writelines(out)
EOF
check "regress fails on peak tracked bytes +5%" \
    '! $PY scripts/regress.py $T/run.csv $T/doc2.csv --time-tol 3 > $T/r3.txt && grep -q "peak tracked" $T/r3.txt'
# scale_wall IN OUT FACTOR: IN with the wall times of naive comb n=3000 multiplied
scale_wall() {
    $PY - "$1" "$2" "$3" <<'EOF'
import sys
lines = open(sys.argv[1]).read().splitlines(True)
hdr = [l for l in lines if not l.startswith("#")][0].rstrip("\n").split(",")
i = hdr.index("wall_s")
out = []
for l in lines:
    if not l.startswith("#") and l.startswith("naive,comb,3000,"):
        f = l.split(",")
        f[i] = repr(float(f[i]) * float(sys.argv[3]))
        l = ",".join(f)
    out.append(l)
open(sys.argv[2], "w").writelines(out)
EOF
}
# doctored time: the baseline claims everything but the reference was 3x faster
scale_wall "$T/base.csv" "$T/doc3.csv" 0.3333333333333333
check "regress fails on a 3x slower configuration" \
    '! $PY scripts/regress.py $T/run.csv $T/doc3.csv --min-time 0.005 > $T/r4.txt && grep -q "REGRESSION: time x" $T/r4.txt'
check "a 3x slower configuration still fails after re-measuring (--confirm)" \
    '! $PY scripts/regress.py $T/run.csv $T/doc3.csv --min-time 0.005 --confirm $BENCH --confirm-rounds 1 > $T/r5.txt && grep -q "re-measured" $T/r5.txt'
# doctored run: one configuration 3x slower in the sweep only (a burst of
# load); re-measuring must clear it, and without --confirm it must not
scale_wall "$T/run.csv" "$T/slow_run.csv" 3
check "a burst of load in the sweep fails without --confirm" \
    '! $PY scripts/regress.py $T/slow_run.csv $T/base.csv --min-time 0.005 > $T/r6.txt && grep -q "REGRESSION: time x" $T/r6.txt'
check "... and passes once re-measured (--confirm)" \
    '$PY scripts/regress.py $T/slow_run.csv $T/base.csv --min-time 0.005 --confirm $BENCH --confirm-rounds 2 > $T/r7.txt && grep -q "re-measured" $T/r7.txt'

# ---- 5. holes
# drop_holes IN OUT: the CSV as written before the holes column
drop_holes() {
    $PY - "$1" "$2" <<'EOF'
import csv, sys
lines = open(sys.argv[1]).read().splitlines(True)
rows = list(csv.reader([l for l in lines if not l.startswith("#")]))
i = rows[0].index("holes")
with open(sys.argv[2], "w", newline="") as f:
    f.writelines(l for l in lines if l.startswith("#"))
    w = csv.writer(f, lineterminator="\n")
    for r in rows:
        w.writerow(r[:i] + r[i + 1:])
EOF
}
$BENCH --family star,holes,convex --n 60 --holes 0,3 --variant naive,monotone --quiet --validate \
    --out "$T/holes.csv"
check "holes: 0 and 3 for holes and convex, 0 only for star (10 rows)" \
    '[ $(grep -vc "^#" $T/holes.csv) = 11 ] && ! grep -q "^[a-z]*,star,60,-1,3," $T/holes.csv'
check "holes: naive ok with 3 holes" \
    'grep -q "^naive,holes,60,-1,3,,unit,1,0,[0-9]*,ok," $T/holes.csv && grep -q "^naive,convex,60,-1,3,,unit,1,0,30,ok," $T/holes.csv'
check "holes: monotone refuses holes (unsupported)" \
    'grep -q "^monotone,holes,60,-1,3,.*,unsupported,.*hole" $T/holes.csv && grep -q "^monotone,convex,60,-1,0,,unit,1,0,0,ok," $T/holes.csv'
check "holes: the JSON twin has holes" \
    'grep -q "\"family\":\"convex\",\"n\":60,\"r_req\":-1,\"holes\":3," $T/holes.jsonl'
printf 'family = holes\nn = 40\nholes = 1, 2\n' > "$T/holes.spec"
check "holes: spec key" \
    '[ "$($BENCH --spec $T/holes.spec --dry-run | cut -d" " -f2 | tr "\n" " ")" = "naive,holes,40,-1,1,,unit,1,0 naive,holes,40,-1,2,,unit,1,0 " ]'
check "holes: the default is 0" \
    '$BENCH --family star --n 50 --dry-run | grep -qx "0 naive,star,50,-1,0,,unit,1,0"'
check "holes: a bad value is a usage error (64)" \
    '$BENCH --family holes --n 40 --holes x --dry-run 2>/dev/null; [ $? = 64 ]'
check "max-n: a variant named there is left out above its n, the others stay" \
    '[ "$($BENCH --family star --n 50,100 --variant naive,deforming --max-n deforming=60 --dry-run | cut -d" " -f2 | cut -d, -f1,3 | tr "\n" " ")" = "naive,50 deforming,50 naive,100 " ]'
check "max-n: a value without VARIANT=N is a usage error (64)" \
    '$BENCH --family star --n 50 --max-n deforming --dry-run 2>/dev/null; [ $? = 64 ]'
printf 'family = star\nn = 50, 100\nvariant = naive, deforming\nmax-n = deforming=60\n' > "$T/maxn.spec"
check "max-n: spec key" \
    '[ "$($BENCH --spec $T/maxn.spec --dry-run | wc -l)" = 3 ]'
drop_holes "$T/full.csv" "$T/legacy.csv"
check "legacy CSV (no holes column): resume of the finished sweep runs nothing" \
    '$BENCH "${sweep[@]}" --resume --dry-run --out $T/legacy.csv | wc -l | grep -qx 0'
n_hdr=$(grep -c '^#' "$T/legacy.csv")
head -n $((n_hdr + 1 + 20)) "$T/legacy.csv" > "$T/legacy2.csv"
$BENCH "${sweep[@]}" --resume --out "$T/legacy2.csv"
check "legacy CSV: resume appends rows in its columns, the same rows as a fresh sweep" \
    '[ "$(grep -v "^#" $T/legacy2.csv | awk -F, "{print NF}" | sort -u | wc -l)" = 1 ] && cmp -s <(stable_cols $T/legacy2.csv) $T/full.stable'
check "legacy CSV: resume refuses holes > 0" \
    '! $BENCH --family star,comb,spiral,holes --n 100 --holes 0,2 --resume --out $T/legacy2.csv 2>$T/leg.err && grep -q "before the holes column" $T/leg.err'
drop_holes "$T/base.csv" "$T/base_legacy.csv"
check "legacy CSV: regress.py compares a new run with it (holes = 0)" \
    '$PY scripts/regress.py $T/run.csv $T/base_legacy.csv --time-tol 3 > $T/r8.txt && grep -q "0 regressions" $T/r8.txt'

# ---- 5b. the variant's timed phase (JSON lines only; the CSV keeps its columns)
$BENCH --family star --n 300 --variant motorcycle,naive --quiet --out "$T/phase.csv"
check "phase: a motorcycle row has M(P) and a positive phase_s below wall_s, naive has none" \
    '$PY - $T/phase.jsonl <<EOF
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
m = [r for r in rows if r["variant"] == "motorcycle"]
nv = [r for r in rows if r["variant"] == "naive"]
assert len(m) == 1 and len(nv) == 1, rows
assert m[0]["phase"] == "M(P)" and 0 < m[0]["phase_s"] <= m[0]["wall_s"], m[0]
assert nv[0]["phase"] is None and nv[0]["phase_s"] is None, nv[0]
EOF'
check "phase: the CSV has no phase column" '! grep -v "^#" $T/phase.csv | head -1 | grep -q phase'
$PY scripts/plot.py "$T/phase.csv" "$T/phase_plots" > "$T/phase_plot.out" 2>&1
check "phase: plot.py draws phase_share (the timed phase's share against n)" \
    '[ -s $T/phase_plots/phase_share.png ] && grep -q "wrote .*phase_share.svg" $T/phase_plot.out'
$PY scripts/report.py "$T/phase.csv" "$T/phase_plots" "$T/phase.md" > /dev/null 2>&1
check "phase: report.py tabulates M(P)'s time and share (phase_s / wall_s of the JSON line)" \
    '$PY - $T/phase.jsonl $T/phase.md <<EOF
import json, sys
m = [json.loads(l) for l in open(sys.argv[1]) if json.loads(l)["variant"] == "motorcycle"][0]
want = "| star | unit | 300 | %.4g | %.4g | %.0f%% |" % (m["phase_s"], m["wall_s"],
                                                     100 * m["phase_s"] / m["wall_s"])
text = open(sys.argv[2]).read()
assert "## Timed phases" in text and want in text.splitlines(), want
assert "plots/phase_share.png" in text or "phase_share.png" in text
EOF'

# ---- 6. the qsort() reference
positive() { $PY -c 'import sys; v = float(sys.argv[1]); sys.exit(0 if 0 < v < 100 else 1)' "$1" 2>/dev/null; }
qref=$($BENCH --qsort-ref); qrc=$?
check "qsort-ref alone: exit 0, one positive number of seconds" \
    '[ $qrc = 0 ] && [ $(echo "$qref" | wc -l) = 1 ] && positive "$qref"'
qsweep=(--family star,coastline --n 200 --seeds 1,2 --quiet)
$BENCH "${qsweep[@]}" --qsort-ref --out "$T/qs.csv"
$BENCH "${qsweep[@]}" --out "$T/noqs.csv"
qline=$(grep "^# qsort_ref_s: " "$T/qs.csv" | head -1)
check "qsort-ref sweep: a line before the header row and one after the runs" \
    '[ $(grep -c "^# qsort_ref_s: [0-9.e-]* (before the runs; qsort() of 1000000 doubles" $T/qs.csv) = 1 ] &&
     [ $(grep -c "^# qsort_ref_s: [0-9.e-]* (after the runs;" $T/qs.csv) = 1 ] &&
     [ "$(grep -v "^#" $T/qs.csv | head -1)" = "$(grep -v "^#" $T/noqs.csv | head -1)" ] &&
     [ "$(grep -n "^# qsort_ref_s" $T/qs.csv | head -1 | cut -d: -f1)" -lt "$(grep -vn "^#" $T/qs.csv | head -1 | cut -d: -f1)" ] &&
     positive "$(echo "$qline" | cut -d" " -f3)"'
check "qsort-ref sweep: the same rows as without it" \
    'cmp -s <(stable_cols $T/qs.csv) <(stable_cols $T/noqs.csv) && [ $(grep -vc "^#" $T/qs.csv) = 5 ]'
check "qsort-ref sweep: results.qsort_ref reads a positive median" \
    'positive "$($PY -c "import sys; sys.path.insert(0, \"scripts\"); import results; print(results.qsort_ref(results.load_csv(sys.argv[1])[0]))" $T/qs.csv)"'
printf 'family = coastline\nn = 100\nqsort-ref\n' > "$T/qs.spec"
$BENCH --spec "$T/qs.spec" --quiet --out "$T/qs2.csv"
check "qsort-ref: spec key" '[ $(grep -c "^# qsort_ref_s: " $T/qs2.csv) = 2 ]'
$BENCH --spec "$T/qs.spec" --n 100,150 --quiet --resume --out "$T/qs2.csv"
check "qsort-ref: --resume appends its own lines and the new row" \
    '[ $(grep -c "^# qsort_ref_s: " $T/qs2.csv) = 4 ] && [ $(grep -vc "^#" $T/qs2.csv) = 3 ]'
check "qsort-ref: off by default" '! grep -q qsort_ref $T/noqs.csv'

# ---- 7. scripts/perf_large.sh
bash scripts/perf_large.sh --n 100,200,400 --max-n arrangement=200 --out "$T/large" \
    naive arrangement > "$T/large.out" 2>&1
lrc=$?
check "perf_large: runs, one CSV with every variant and its qsort lines" \
    '[ $lrc = 0 ] && [ $(grep -vc "^#" $T/large/large.csv) = 11 ] && [ $(grep -c "^# qsort_ref_s: " $T/large/large.csv) = 4 ]'
check "perf_large: --max-n leaves arrangement at n <= 200" \
    '! grep -q "^arrangement,[a-z]*,400," $T/large/large.csv && grep -q "^naive,coastline,400," $T/large/large.csv'
check "perf_large: summary.csv (4 groups) and REPORT.md" \
    '[ $(wc -l < $T/large/summary.csv) = 5 ] && grep -q "^naive,coastline,400," $T/large/summary.csv &&
     grep -q "| arrangement | star | 200 |" $T/large/REPORT.md && grep -q "qsort reference" $T/large/REPORT.md'
bash scripts/perf_large.sh --out "$T/large2" nope 2> "$T/large2.err"; lrc=$?
check "perf_large: unknown variant is a usage error (64)" \
    '[ $lrc = 64 ] && grep -q "unknown variant .nope." $T/large2.err && [ ! -e $T/large2/large.csv ]'
bash scripts/perf_large.sh --max-n naive naive 2>/dev/null; lrc=$?
check "perf_large: a bad --max-n is a usage error (64)" '[ $lrc = 64 ]'

# ---- usage errors
check "unknown variant is a usage error (64)" \
    '$BENCH --family star --n 10 --variant nope --out $T/x.csv 2>/dev/null; [ $? = 64 ]'
check "bad shard is a usage error (64)" \
    '$BENCH --family star --n 10 --shard 3/3 --out $T/x.csv 2>/dev/null; [ $? = 64 ]'

if [ $fails -ne 0 ]; then
    echo "test_bench.sh: $fails failure(s)"
    exit 1
fi
echo "test_bench.sh: all passed"
