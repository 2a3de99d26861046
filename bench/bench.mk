# bench.mk: the benchmark targets (included at the end of the Makefile).
#   make bench     default sweep -> results/latest/ (CSV, plots, fit, REPORT.md)
#   make curves    the larger sweeps (curves, curves_monotone, curves_k, curves_large)
#                  -> results/curves/
#   make regress   fixed sweep, compared with results/baseline/regress.csv
#   make regress-baseline   re-measure the baseline (commit the result)
#   make test-bench         the harness's own tests
#   make roof      re-render results/roof/roof_holes.png (the roof REPORT.md and
#                  README.md show; VTK under xvfb-run)
# BENCH_FLAGS adds wskel-bench options (e.g. BENCH_FLAGS=--resume).
BENCH      := bin/wskel-bench
BENCH_ENV  := WSKEL_CFLAGS='$(CFLAGS)'
BENCH_DEPS := $(BENCH) $(filter bin/wskel-cgal,$(PROGS))

.PHONY: bench curves regress regress-baseline test-bench roof

bench: $(BENCH_DEPS)
	@mkdir -p results/latest/plots
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/default.spec $(BENCH_FLAGS) --out results/latest/bench.csv
	$(PY) scripts/fit.py results/latest/bench.csv --json results/latest/fit.json > results/latest/fit.txt && cat results/latest/fit.txt
	$(PY) scripts/plot.py results/latest/bench.csv results/latest/plots --fit results/latest/fit.json
	$(PY) scripts/report.py results/latest/bench.csv results/latest/plots results/latest/REPORT.md --fit results/latest/fit.txt --roof $(ROOF_PNG)

curves: $(BENCH_DEPS)
	@mkdir -p results/curves/plots
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/curves.spec --resume $(BENCH_FLAGS) --out results/curves/curves.csv
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/curves_monotone.spec --resume $(BENCH_FLAGS) --out results/curves/curves.csv
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/curves_k.spec --resume $(BENCH_FLAGS) --out results/curves/curves.csv
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/curves_large.spec --resume $(BENCH_FLAGS) --out results/curves/curves.csv
	$(PY) scripts/fit.py results/curves/curves.csv --json results/curves/fit.json > results/curves/fit.txt && cat results/curves/fit.txt
	$(PY) scripts/plot.py results/curves/curves.csv results/curves/plots --fit results/curves/fit.json
	$(PY) scripts/report.py results/curves/curves.csv results/curves/plots results/curves/REPORT.md --fit results/curves/fit.txt --roof $(ROOF_PNG)

regress: $(BENCH)
	@mkdir -p results/latest
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/regress.spec $(BENCH_FLAGS) --out results/latest/regress.csv
	$(PY) scripts/regress.py results/latest/regress.csv results/baseline/regress.csv --confirm $(BENCH)

regress-baseline: $(BENCH)
	@mkdir -p results/baseline
	$(BENCH_ENV) $(BENCH) --spec bench/sweeps/regress.spec --out results/baseline/regress.csv

test-bench: $(BENCH)
	bash tests/test_bench.sh

# The rendered roof of one polygon with holes (wskel-gen holes, seed 3): the
# polygon is committed beside the picture, so the picture can be checked.
ROOF_PNG := results/roof/roof_holes.png
roof: bin/wskel bin/wskel-gen
	@mkdir -p results/roof $(B)
	bin/wskel-gen holes --n 60 --holes 4 --seed 3 -o results/roof/roof_holes.wpoly
	bin/wskel --format vtp -o $(B)/roof_holes.vtp results/roof/roof_holes.wpoly
	xvfb-run -a $(PY) scripts/render.py $(B)/roof_holes.vtp $(ROOF_PNG) --size 900x560 --zoom 1.7
