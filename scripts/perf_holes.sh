#!/bin/bash
# perf_holes.sh: back-to-back runs of naive, arrangement (k = 1, max) and the
# CGAL baseline on the holes family (bin/wskel-gen holes), each compared with
# naive; writes its table to stdout (results/holes/REPORT.md quotes one run).
# Heavy: about 4 minutes, CGAL takes 4-5 GB at n = 10^4.  Run on a quiet machine.
cd "$(dirname "$0")/.."
out=/tmp/perf_holes; mkdir -p $out
for spec in "10000 100 1" "10000 100 2" "3000 30 1"; do
  set -- $spec; n=$1; h=$2; s=$3
  f=$out/holes_n${n}_h${h}_s${s}.wpoly
  bin/wskel-gen holes --n $n --holes $h --seed $s > $f
  for v in naive "arrangement --k 1" "arrangement --k max" cgal; do
    if [ "$v" = cgal ]; then cmd="bin/wskel-cgal --stats $f"; else cmd="bin/wskel --variant $v --stats --no-check $f"; fi
    /usr/bin/time -f "wall %e s, max RSS %M KB" $cmd > $out/o.json 2> $out/err.txt; rc=$?
    echo "n=$n h=$h seed=$s | $v | rc=$rc | $(grep -o "time_s[= ][0-9.e-]*\|peak_bytes [0-9]*\|peak_rss_bytes=[0-9]*" $out/err.txt | tr "\n" " ") | $(tail -1 $out/err.txt)"
    if [ "$v" = naive ]; then cp $out/o.json $out/naive.json; else [ $rc = 0 ] && echo "   vs naive: $(/usr/bin/python3 scripts/compare_skeletons.py $out/naive.json $out/o.json | tail -1 | cut -c1-90)"; fi
  done
done
