# wskel: weighted straight skeletons.  `make` builds the library and the
# programs, `make test` runs every test (also under ASan/UBSan), `make bench`
# runs the default sweep.  See README.md.
# Fresh machine: `make bench` and `make test` first run the idempotent
# dependency install (.ci/install-deps: a no-op when every package is there),
# here, before the flags below are read from pkg-config and the CGAL headers
# looked for, so that one command works on a bare Debian 12.
ifneq ($(filter bench test,$(MAKECMDGOALS)),)
ifneq ($(shell bash .ci/install-deps >&2 && echo ok),ok)
$(error bash .ci/install-deps failed (see above); install the packages it names, then run make again)
endif
endif
CC      ?= cc
CXX     ?= g++
PY      := /usr/bin/python3
WARN    := -Wall -Wextra -Werror
CSTD    := -std=c11 -ffp-contract=off -fno-fast-math
OPT     ?= -O2 -g
CFLAGS  := $(CSTD) $(WARN) $(OPT) -fopenmp -Iengine -Ivariants -Ibench/gen
LDLIBS  := -lm -lgmp -fopenmp
XML_CFLAGS := $(shell pkg-config --cflags libxml-2.0 2>/dev/null)
XML_LIBS   := $(shell pkg-config --libs libxml-2.0 2>/dev/null)
CFLAGS  += $(XML_CFLAGS)
LDLIBS  += $(XML_LIBS)
# GeoJSON reader (engine/polygon_read_gis.c)
JSON_CFLAGS := $(shell pkg-config --cflags jansson 2>/dev/null)
JSON_LIBS   := $(shell pkg-config --libs jansson 2>/dev/null)
CFLAGS  += $(JSON_CFLAGS)
LDLIBS  += $(JSON_LIBS)

ENGINE_SRC  := $(sort $(wildcard engine/*.c))
VARIANT_SRC := variants/registry.c $(sort $(wildcard variants/*/*.c))
# The polygon generators (build/libwskel-gen.a) and the parts of the bench
# harness other than its main (linked into bin/wskel-bench only).
GEN_SRC   := $(sort $(wildcard bench/gen/*.c))
BENCH_SRC := $(filter-out bench/wskel_%.c,$(sort $(wildcard bench/*.c)))
LIB_SRC := $(ENGINE_SRC) $(VARIANT_SRC)
TEST_SRC := $(sort $(wildcard tests/test_*.c))

B  := build
BA := build-asan
LIB     := $(B)/libwskel.a
LIBASAN := $(BA)/libwskel.a
GENLIB     := $(B)/libwskel-gen.a
GENLIBASAN := $(BA)/libwskel-gen.a
HDRS := $(wildcard engine/*.h variants/*.h variants/*/*.h bench/*.h bench/gen/*.h tests/*.h)

PROGS := bin/wskel bin/wskel-gen
HAVE_CGAL := $(wildcard /usr/include/CGAL/create_straight_skeleton_2.h)
ifneq ($(HAVE_CGAL),)
PROGS += bin/wskel-cgal
endif
HAVE_BENCH := $(wildcard bench/wskel_bench.c)
ifneq ($(HAVE_BENCH),)
PROGS += bin/wskel-bench
endif

.PHONY: all test test-unit test-asan test-cli test-py bench curves regress clean setup stress stress-quick python

all: $(LIB) $(GENLIB) $(PROGS)

$(B)/%.o: %.c $(HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@
$(BA)/%.o: %.c $(HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all -c $< -o $@
# Every run a unit test opens is a checked one (debug allocator backend,
# strict close; see wk_run_init_checked in engine/wskel.h).  The library is
# built without it.
$(B)/tests/%.o $(BA)/tests/%.o: CFLAGS += -DWK_CHECKED_RUNS

$(LIB): $(LIB_SRC:%.c=$(B)/%.o)
	@rm -f $@; ar rcs $@ $^
$(LIBASAN): $(LIB_SRC:%.c=$(BA)/%.o)
	@rm -f $@; ar rcs $@ $^
$(GENLIB): $(GEN_SRC:%.c=$(B)/%.o)
	@rm -f $@; ar rcs $@ $^
$(GENLIBASAN): $(GEN_SRC:%.c=$(BA)/%.o)
	@rm -f $@; ar rcs $@ $^

bin/wskel: $(B)/cli/main.o $(LIB)
	@mkdir -p bin
	$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
bin/wskel-gen: $(B)/bench/wskel_gen.o $(GENLIB) $(LIB)
	@mkdir -p bin
	$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
bin/wskel-bench: $(B)/bench/wskel_bench.o $(BENCH_SRC:%.c=$(B)/%.o) $(GENLIB) $(LIB)
	@mkdir -p bin
	$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
bin/wskel-cgal: tests/cgal/wskel_cgal.cpp
	@mkdir -p bin
	$(CXX) -std=c++17 -O2 -Wall -Wextra -Werror $< -o $@ -lgmp -lmpfr

$(B)/tests/run_tests: $(TEST_SRC:%.c=$(B)/%.o) $(GENLIB) $(LIB)
	$(CC) $(CFLAGS) $^ -o $@ -lcriterion $(LDLIBS)
$(BA)/tests/run_tests: $(TEST_SRC:%.c=$(BA)/%.o) $(GENLIBASAN) $(LIBASAN)
	$(CC) $(CFLAGS) -fsanitize=address,undefined $^ -o $@ -lcriterion $(LDLIBS)
$(BA)/wskel: $(BA)/cli/main.o $(LIBASAN)
	$(CC) $(CFLAGS) -fsanitize=address,undefined $^ -o $@ $(LDLIBS)

# The Python module (python/wskel/, README "Python"): the library compiled
# again with -fPIC into build-pic/, with the ctypes shim, into one shared
# object next to the binding.
BP := build-pic
PYSO := python/wskel/_libwskel.so
PY_SRC := $(LIB_SRC) python/wskel/shim.c
$(BP)/%.o: %.c $(HDRS) $(wildcard python/wskel/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC -c $< -o $@
$(PYSO): $(PY_SRC:%.c=$(BP)/%.o)
	$(CC) $(CFLAGS) -shared -Wl,--no-undefined $^ -o $@ $(LDLIBS)
python: $(PYSO)

# Unit and property tests, then the same under ASan/UBSan, then the
# command-line and Python-side tests (exit codes, messages, VTK read-back,
# CGAL agreement).
test: all test-unit test-asan test-cli test-py test-bench
test-unit: $(B)/tests/run_tests
	$(B)/tests/run_tests --jobs 2
test-asan: $(BA)/tests/run_tests $(BA)/wskel
	WSKEL_TEST_QUICK=1 ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp UBSAN_OPTIONS=print_stacktrace=1 $(BA)/tests/run_tests --jobs 2
	WSKEL_BIN=$(BA)/wskel WSKEL_DEGENERATE_CASES=400 WSKEL_MONO_CASES=150 WSKEL_REAL_CASES=8 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 $(PY) tests/test_degenerate.py
	WSKEL_BIN=$(BA)/wskel WSKEL_HOLES_CASES=60 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 $(PY) tests/test_holes.py
	WSKEL_BIN=$(BA)/wskel WSKEL_MOTORCYCLE_MAX_N=256 WSKEL_MOTORCYCLE_SEEDS=2 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 $(PY) tests/test_motorcycle.py
	WSKEL_BIN=$(BA)/wskel WSKEL_DEFORMING_MAX_N=16 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 $(PY) tests/test_deforming.py
test-cli: all
	bash tests/cli_tests.sh
	bash tests/test_layering.sh
test-py: all python
	$(PY) tests/test_python.py
	WSKEL_CHECKED_RUNS=1 $(PY) tests/test_python.py
	$(PY) tests/test_outputs.py
	$(PY) tests/test_degenerate.py
	$(PY) tests/test_holes.py
	$(PY) tests/test_near_touch.py
	$(PY) tests/test_exact_nodes.py
	$(PY) tests/test_motorcycle.py
	WSKEL_GLYPH_CASES=all $(PY) tests/test_glyphs.py
	WSKEL_DEFORMING_MAX_N=256 $(PY) tests/test_deforming.py
	$(PY) tests/test_cgal_agreement.py
	$(PY) tests/test_offset_cgal.py
	$(PY) tests/test_scripts.py
	$(MAKE) --no-print-directory stress-quick

# The stress sweep (tests/stress/stress.py): 10^4 polygons of every generator
# family and the degenerate makers through every variant, 2 jobs, 20 s per
# run; failing inputs and the summary in results/stress/.  Fails while any
# case fails.  stress-quick (part of make test): the first 300 cases, which
# must fail exactly as tests/data/stress/KNOWN says.
STRESS_FLAGS ?=
stress: all
	$(PY) tests/stress/stress.py --cases 10000 --jobs 2 --timeout 20 --out results/stress $(STRESS_FLAGS)
stress-quick: all
	$(PY) tests/stress/stress.py --quick --jobs 2 --timeout 20

setup:
	bash .ci/install-deps

clean:
	rm -rf $(B) $(BA) $(BP) bin $(PYSO)

# Fuzzing (tests/fuzz/README.md): libFuzzer targets built by clang with
# ASan/UBSan against the library sources compiled the same way into
# build/fuzz/ (not the gcc-built library).  `make fuzz` runs each
# target for FUZZ_SECONDS from its committed seeds tests/fuzz/corpus/T/; new
# corpus entries go to build/fuzz/corpus/T/, findings to build/fuzz/findings/
# (FUZZ_DIR=DIR puts all of it elsewhere, e.g. out of reach of make clean).
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := wpoly graphml geojson wkt variants
FUZZ_DIR     ?= $(B)/fuzz
BF := $(FUZZ_DIR)
# The library sources keep -Wall -Wextra without -Werror here: the gcc build
# (make) is the one whose warnings are errors; the targets themselves have it.
FUZZ_CFLAGS := $(CSTD) -Wall -Wextra -O1 -g -fno-omit-frame-pointer -fopenmp \
               -fsanitize=address,undefined -fno-sanitize-recover=all -Iengine -Ivariants $(XML_CFLAGS) $(JSON_CFLAGS)
.PHONY: fuzz fuzz-build
# Objects made by the pattern rules below are kept (not intermediate files).
.SECONDARY: $(LIB_SRC:%.c=$(BF)/%.o) $(FUZZ_TARGETS:%=$(BF)/tests/fuzz/fuzz_%.o)
fuzz-build: $(FUZZ_TARGETS:%=$(BF)/fuzz_%)
fuzz: fuzz-build
	@for t in $(FUZZ_TARGETS); do FUZZ_DIR=$(BF) bash tests/fuzz/run.sh $$t $(FUZZ_SECONDS) || exit 1; done
# Comparison tracing (-fsanitize-coverage=trace-cmp, which feeds libFuzzer
# the operands of integer comparisons to splice into inputs) is kept for
# the readers and the polygon checks, where input bytes meet integer
# compares, and left out of the geometry (engine and variants): there the
# input arrives as doubles, which are not traced, and the integer compares
# are of indices and counts.  It took 45% of the variant target's time
# (the corpus replay ran 2.6 times faster without it; tests/fuzz/README.md).
FUZZ_GEOM_SRC := $(filter-out engine/polygon%.c,$(LIB_SRC))
$(FUZZ_GEOM_SRC:%.c=$(BF)/%.o): FUZZ_COV := -fno-sanitize-coverage=trace-cmp
$(BF)/%.o: %.c $(HDRS)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link $(FUZZ_COV) -c $< -o $@
$(BF)/tests/fuzz/%.o: tests/fuzz/%.c $(HDRS) $(wildcard tests/fuzz/*.h)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Werror -fsanitize=fuzzer-no-link -c $< -o $@
$(BF)/fuzz_%: $(BF)/tests/fuzz/fuzz_%.o $(LIB_SRC:%.c=$(BF)/%.o)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer $^ -o $@ -lm -lgmp $(XML_LIBS) $(JSON_LIBS)

# Benchmark targets (bench, curves, regress) live with the harness.
-include bench/bench.mk
