#!/usr/bin/env bash
# tests/fuzz/run.sh TARGET SECONDS [libFuzzer options...]: run one libFuzzer
# target (build/fuzz/fuzz_TARGET, built by `make fuzz`) for SECONDS from the
# committed seeds tests/fuzz/corpus/TARGET/ plus the scratch corpus
# build/fuzz/corpus/TARGET/ (new entries go there, never into the
# repository).  Crashes, leaks, UB and timeouts are saved under
# build/fuzz/findings/TARGET/; the variant target's WK_EALGO inputs under
# build/fuzz/findings/ealgo/.  Prints the executions and exec/s; exits
# non-zero on a finding (with the command to reproduce it).
# Environment: FUZZ_DIR=DIR instead of build/fuzz (binaries, corpus,
# findings; make fuzz passes its own); FUZZ_JOBS=N runs N processes in
# parallel (-fork=N);
# FUZZ_SEED=S fixes libFuzzer's random seed (CI);
# WSKEL_FUZZ_COLLECT=DIR makes the variant target save invalid skeletons
# and count mismatches there instead of aborting (see fuzz_variants.c).
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.." || exit 2
t="${1:?usage: run.sh TARGET SECONDS [options]}"
secs="${2:?usage: run.sh TARGET SECONDS [options]}"
shift 2
BF="${FUZZ_DIR:-build/fuzz}"
bin="$BF/fuzz_$t"
[ -x "$bin" ] || { echo "fuzz: $bin is missing; run 'make fuzz' (or make $bin)" >&2; exit 2; }
seeds="tests/fuzz/corpus/$t"
scratch="$BF/corpus/$t"
found="$BF/findings/$t"
mkdir -p "$scratch" "$found" "$BF/findings/ealgo"
case "$t" in
  wpoly)    opts=(-max_len=4096 -dict=tests/fuzz/wpoly.dict -timeout=10) ;;
  graphml)  opts=(-max_len=16384 -dict=tests/fuzz/graphml.dict -timeout=10) ;;
  geojson)  opts=(-max_len=8192 -dict=tests/fuzz/geojson.dict -timeout=10) ;;
  wkt)      opts=(-max_len=4096 -dict=tests/fuzz/wkt.dict -timeout=10) ;;
  variants) opts=(-max_len=16384 -dict=tests/fuzz/wpoly.dict -timeout=20) ;;
  *) echo "fuzz: unknown target $t" >&2; exit 2 ;;
esac
[ -n "${FUZZ_JOBS:-}" ] && opts+=(-fork="$FUZZ_JOBS")
[ -n "${FUZZ_SEED:-}" ] && opts+=(-seed="$FUZZ_SEED")
[ -n "${WSKEL_FUZZ_COLLECT:-}" ] && mkdir -p "$WSKEL_FUZZ_COLLECT"
log="$BF/fuzz_$t.log"
echo "fuzz: $t for $secs s: $bin ${opts[*]} -max_total_time=$secs $* $scratch $seeds"
export WSKEL_FUZZ_EALGO_DIR="${WSKEL_FUZZ_EALGO_DIR:-$BF/findings/ealgo}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
rc=0
"$bin" "${opts[@]}" -max_total_time="$secs" -print_final_stats=1 \
  -artifact_prefix="$found/" "$@" "$scratch" "$seeds" >"$log" 2>&1 || rc=$?
runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | tail -1 | awk '{print $2 + 0}')
[ -z "$runs" ] || [ "$runs" = 0 ] && runs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#')
ealgo=$(ls "$BF/findings/ealgo" 2>/dev/null | wc -l)
echo "fuzz: $t: ${runs:-?} executions, ${rate:-?} exec/s, scratch corpus $(ls "$scratch" | wc -l) files; log $log"
if [ "$t" = variants ]; then
  echo "fuzz: $t: $ealgo WK_EALGO inputs in $BF/findings/ealgo/ (not crashes; see tests/fuzz/README.md)"
  [ -n "${WSKEL_FUZZ_COLLECT:-}" ] &&
    echo "fuzz: $t: $(ls "$WSKEL_FUZZ_COLLECT" | wc -l) invalid/mismatch inputs collected in $WSKEL_FUZZ_COLLECT/ (WSKEL_FUZZ_COLLECT: not aborted on)"
fi
[ "$rc" -eq 72 ] && { echo "fuzz: $t: interrupted"; exit 72; }
if [ "$rc" -ne 0 ]; then
  echo "fuzz: $t: FINDING (libFuzzer exit $rc):" >&2
  grep -E 'FINDING|ERROR: |SUMMARY: |runtime error|timeout after|Test unit written' "$log" | head -20 >&2
  for a in $(grep -o "Test unit written to [^ ]*" "$log" | awk '{print $5}'); do
    echo "fuzz: reproduce with: $bin $a" >&2
  done
  exit "$rc"
fi
