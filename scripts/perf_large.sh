#!/bin/bash
# perf_large.sh: large-n runs of the given variants on the star and coastline
# families (bin/wskel-gen), n = 10^3, 10^4, 10^5, 10^6, one seed, with the
# qsort() reference of the same run (wskel-bench --qsort-ref), then
# scripts/large_report.py: per variant and family the time per n, peak
# tracked bytes per vertex, time / qsort at 10^6, the log-log exponent of
# time in n over 10^3..10^6, each set against the large-n targets (time at
# 10^6 <= 50 qsorts, <= 1 KiB per vertex, exponent <= 1.15).
#
# usage: scripts/perf_large.sh [options] VARIANT...
#   --max-n V=N       skip n > N for variant V (repeatable); defaults:
#                     naive=100000, arrangement=100000 (quadratic); others none
#   --n LIST          vertex counts (default 1000,10000,100000,1000000)
#   --families LIST   (default star,coastline)
#   --seed S          (default 1)
#   --time-limit SEC  per run (default 3600; a run over it is a 'timeout' row)
#   --mem-limit MB    per run (default 16384)
#   --out DIR         (default results/large): DIR/large.csv (+ .jsonl), the
#                     raw sweep; DIR/summary.csv; DIR/REPORT.md
# VARIANT: any name `bin/wskel --list-variants` shows.  Runs are timed by
# wskel-bench: the construction alone, no validation, one child per run,
# one job at a time.  Heavy at 10^6: run on a quiet machine.
set -u
cd "$(dirname "$0")/.."
PY=/usr/bin/python3
usage() { sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 64; }
die() { echo "perf_large.sh: $*" >&2; exit 64; }

orig_args="$*"
declare -A cap=([naive]=100000 [arrangement]=100000)
ns=1000,10000,100000,1000000
families=star,coastline
seed=1
tlimit=3600
mlimit=16384
out=results/large
variants=()
while [ $# -gt 0 ]; do
    case "$1" in
    --max-n)
        [ $# -ge 2 ] || die "--max-n needs V=N"
        [[ "$2" =~ ^([A-Za-z0-9_-]+)=([0-9]+)$ ]] || die "--max-n: '$2' is not VARIANT=N"
        cap[${BASH_REMATCH[1]}]=${BASH_REMATCH[2]}
        shift 2 ;;
    --n) [ $# -ge 2 ] || die "--n needs a list"; ns=$2; shift 2 ;;
    --families) [ $# -ge 2 ] || die "--families needs a list"; families=$2; shift 2 ;;
    --seed) [ $# -ge 2 ] || die "--seed needs a value"; seed=$2; shift 2 ;;
    --time-limit) [ $# -ge 2 ] || die "--time-limit needs seconds"; tlimit=$2; shift 2 ;;
    --mem-limit) [ $# -ge 2 ] || die "--mem-limit needs MB"; mlimit=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || die "--out needs a directory"; out=$2; shift 2 ;;
    -h | --help) usage ;;
    -*) die "unknown option '$1' (see --help)" ;;
    *) variants+=("$1"); shift ;;
    esac
done
[ ${#variants[@]} -gt 0 ] || die "no variant given (see --help; bin/wskel --list-variants)"
for b in bin/wskel bin/wskel-bench; do [ -x $b ] || die "$b missing (run make)"; done
[[ "$ns" =~ ^[0-9]+(,[0-9]+)*$ ]] || die "--n: '$ns' is not a comma-separated list of integers"
known=$(bin/wskel --list-variants | awk 'NF {print $1}')
for v in "${variants[@]}"; do
    grep -qxF -- "$v" <<<"$known" || die "unknown variant '$v' (bin/wskel --list-variants: $(echo $known))"
done

# the build's flags, for the CSV's '# cflags:' line (as make bench does)
cflags=$(make -s --no-print-directory --eval='print-cflags: ; @echo $(CFLAGS)' print-cflags 2>/dev/null)
mkdir -p "$out" || exit 1
csv=$out/large.csv
rm -f "$csv" "${csv%.csv}.jsonl"
for v in "${variants[@]}"; do
    max=${cap[$v]:-}
    vns=$(tr , '\n' <<<"$ns" | awk -v m="$max" 'm == "" || $1 <= m' | paste -sd, -)
    if [ -z "$vns" ]; then
        echo "perf_large.sh: $v: no n within --max-n $v=$max, skipped" >&2
        continue
    fi
    echo "perf_large.sh: $v: n = $vns on $families${max:+ (max n $max)}" >&2
    # --resume: every variant appends to the one CSV (a missing CSV starts
    # fresh); each invocation writes its own qsort_ref_s lines.
    WSKEL_CFLAGS="$cflags" bin/wskel-bench --family "$families" --n "$vns" --variant "$v" --seeds "$seed" \
        --qsort-ref --time-limit "$tlimit" --mem-limit "$mlimit" --resume --out "$csv" ||
        { echo "perf_large.sh: wskel-bench failed for $v" >&2; exit 1; }
done
[ -s "$csv" ] || die "nothing ran"
$PY scripts/large_report.py "$csv" "$out" --command "scripts/perf_large.sh $orig_args" \
    --caps "$(for v in "${variants[@]}"; do [ -n "${cap[$v]:-}" ] && printf '%s=%s ' "$v" "${cap[$v]}"; done)"
