# cvmesh - build, test, benchmark and install.
#   make              library (static + shared) and the CLI into build/
#   make demo         install missing packages, build, mesh the NACA 0012 of examples/data (.vtu + .svg + .png)
#   make check        install missing packages, build, run every test (see CHECK_STEPS below)
#   make fuzz         run each libFuzzer target for FUZZ_LONG_TIME seconds (clang)
#   make bench        benchmarks side by side with Triangle / TetGen / scipy (tests/bench)
#   make install PREFIX=/usr/local [DESTDIR=...]
#   make amalgamation one-file build/amalgamation/cvmesh.c + cvmesh.h
#   make clean
# Variables: CC=gcc|clang, OPENMP=1|0, BUILD=build, SAN=1 (ASan+UBSan), TETGEN=1|0
# (link TetGen 1.5, AGPL-3+, for 3D boundary recovery: 1 by default when
# /usr/include/tetgen.h exists; 0 builds a BSD-only library), FUZZ_TIME=10 (seconds
# per fuzz target in make check), JOBS=<cores>. Everything reads only files of this
# repository: the example domains are examples/data (examples/data/make_domains.py).

SHELL := /bin/bash

# The version is the header's (CVM_VERSION_*), read here so the two cannot disagree.
header_version = $(shell sed -n 's/^\#define CVM_VERSION_$(1) \([0-9][0-9]*\)$$/\1/p' include/cvmesh.h)
VERSION_MAJOR := $(call header_version,MAJOR)
VERSION_MINOR := $(call header_version,MINOR)
VERSION_PATCH := $(call header_version,PATCH)
VERSION := $(VERSION_MAJOR).$(VERSION_MINOR).$(VERSION_PATCH)

# GNU make's built-in default CC is "cc"; keep it unless the user chose one.
CC ?= cc
BUILD ?= build
OPENMP ?= 1
SAN ?= 0
FUZZ ?= 0
TETGEN ?= $(if $(wildcard /usr/include/tetgen.h),1,0)
PREFIX ?= /usr/local
DATA_DIR := $(CURDIR)/examples/data
# The interpreter that creates the venv; every Python a target runs is $(VENV_PY).
PYTHON ?= python3
VENV := $(abspath $(BUILD))/venv
VENV_PY := $(VENV)/bin/python
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
FUZZ_TIME ?= 10
FUZZ_LONG_TIME ?= 600
CLANG ?= clang

WARN := -Wall -Wextra -Wpedantic -Werror
OPT ?= -O3
CFLAGS_BASE := -std=c99 $(OPT) -g $(WARN) -fvisibility=hidden -fPIC -Iinclude -Ilib \
               -D_POSIX_C_SOURCE=200809L
ifeq ($(OPENMP),1)
  OMPFLAGS := -fopenmp
endif
ifeq ($(SAN),1)
  SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
ifeq ($(FUZZ),1)
  SANFLAGS += -fsanitize=fuzzer-no-link
endif
ALL_CFLAGS := $(CFLAGS_BASE) $(OMPFLAGS) $(SANFLAGS) $(CFLAGS)
LDLIBS_LIB := -llbfgs -lz -lm $(OMPFLAGS)

LIB_SRC := $(sort $(filter-out lib/cli/%,$(wildcard lib/*/*.c)))
CLI_SRC := $(sort $(wildcard lib/cli/*.c))
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)

# TetGen (lib/tetgen): the C++ shim is the only C++ in the tree. The C sources
# see CVM_WITH_TETGEN (lib objects only: the amalgamation stays C-only and
# TetGen-free); a change of TETGEN rebuilds the files that read it.
ifeq ($(TETGEN),1)
  CXX := $(if $(findstring clang,$(CC)),clang++,g++)
  ALL_CXXFLAGS := -std=c++11 $(OPT) -g -Wall -Wextra -Werror -fvisibility=hidden -fPIC -Iinclude -Ilib \
                  $(SANFLAGS) $(CXXFLAGS)
  TETGEN_OBJ := $(BUILD)/obj/lib/tetgen/tetgen_shim.o
  LIB_OBJ += $(TETGEN_OBJ)
  LDLIBS_LIB += -ltet -lstdc++
  # Linking those libraries would also export _edata, _end and __bss_start.
  SHARED_LDFLAGS := -Wl,--version-script=lib/tetgen/exports.map
  $(LIB_OBJ): ALL_CFLAGS += -DCVM_WITH_TETGEN
else ifneq ($(TETGEN),0)
  $(error TETGEN=$(TETGEN): use TETGEN=1 (link TetGen) or TETGEN=0 (BSD-only))
endif
TETGEN_STAMP := $(BUILD)/tetgen.stamp
$(TETGEN_STAMP): FORCE
	@mkdir -p $(dir $@)
	@echo $(TETGEN) | cmp -s - $@ || echo $(TETGEN) > $@
$(BUILD)/obj/lib/tetgen/tet3_out.o: $(TETGEN_STAMP)
.PHONY: FORCE
FORCE:

$(BUILD)/obj/%.o: %.cxx
	@mkdir -p $(dir $@)
	$(CXX) $(ALL_CXXFLAGS) -MMD -MP -c $< -o $@
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/obj/%.o)

STATIC := $(BUILD)/lib/libcvmesh.a
SONAME := libcvmesh.so.$(VERSION_MAJOR)
SHARED := $(BUILD)/lib/libcvmesh.so.$(VERSION)
CLI := $(BUILD)/bin/cvmesh

TEST_SRC := $(sort $(wildcard tests/unit/*.c tests/unit/*/*.c))
TEST_OBJ := $(TEST_SRC:%.c=$(BUILD)/obj/%.o)
TEST_BIN := $(BUILD)/tests/unit_tests
CHECK_CFLAGS = $(shell pkg-config --cflags check 2>/dev/null)
CHECK_LIBS = $(shell pkg-config --libs check 2>/dev/null || echo -lcheck -lsubunit -lrt -lpthread)
TEST_ENV = CVM_DATA_DIR=$(DATA_DIR) CVM_TEST_DATA=$(CURDIR)/tests/data CVM_DATA3D_DIR=$(abspath $(DATA3D))
# The 3D example surfaces, written by examples/data3d/make_data3d.py (standard library only).
DATA3D := $(BUILD)/data3d

# Fuzz targets: tests/fuzz/fuzz_<name>.c, seeds in tests/fuzz/corpus/<name>/.
FUZZ_TARGETS := poly_read node_read cdt vtu_read vtk_read msh_read refine optimise off_read stl_read tetpoly_read delaunay3 generate3 quadmesh insert3 optimise3 ele_read
# The targets make check runs for FUZZ_TIME seconds with a fixed seed. A
# target leaves this list while its fixed-seed run reaches one of its open
# findings (tests/fuzz/open/<target>/): it would fail on those known inputs.
FUZZ_CHECK_TARGETS := poly_read node_read cdt vtu_read vtk_read msh_read refine optimise off_read stl_read tetpoly_read delaunay3 generate3 quadmesh insert3 optimise3 ele_read
FUZZ_BINS := $(FUZZ_TARGETS:%=$(BUILD)/fuzz/fuzz_%)
REPLAY_BINS := $(FUZZ_TARGETS:%=$(BUILD)/fuzz/replay_%)
FUZZ_SUPPORT_OBJ := $(BUILD)/obj/tests/fuzz/mesh_oracle.o $(BUILD)/obj/tests/fuzz/fuzz_input.o \
                    $(BUILD)/obj/tests/fuzz/fuzz_pslg.o $(BUILD)/obj/tests/fuzz/fuzz_run.o \
                    $(BUILD)/obj/tests/unit/support/failing_alloc.o

# Build steps of make check run with -j$(JOBS) unless make was given -j.
PAR = $(if $(findstring -j,$(MAKEFLAGS))$(findstring j,$(firstword $(MAKEFLAGS))),,-j$(JOBS))

STAGE := $(abspath $(BUILD))/stage
EXAMPLES_C := $(sort $(wildcard examples/c/*.c))

.PHONY: install-c python fortran install-python install-fortran
.PHONY: venv check-standalone check-golden
.PHONY: data3d
.PHONY: all lib cli tests deps demo check check-unit check-asan check-symbols check-layers check-cli \
        check-examples check-python check-fortran check-clang check-noomp check-fuzz \
        check-replay check-valgrind check-amalgamation fuzz fuzz-bins replay-bins bench \
        install clean python fortran amalgamation

all: lib cli

lib: $(STATIC) $(SHARED)
cli: $(CLI)
tests: $(TEST_BIN)

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -MMD -MP -c $< -o $@

$(STATIC): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(SHARED): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,--no-undefined $(SHARED_LDFLAGS) $(SANFLAGS) -o $@ $^ $(LDLIBS_LIB)
	ln -sf libcvmesh.so.$(VERSION) $(BUILD)/lib/$(SONAME)
	ln -sf $(SONAME) $(BUILD)/lib/libcvmesh.so

$(CLI): $(CLI_OBJ) $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) -o $@ $(CLI_OBJ) $(STATIC) $(LDLIBS_LIB)

$(BUILD)/obj/tests/%.o: tests/%.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) $(CHECK_CFLAGS) -pthread -Itests/unit -MMD -MP -c $< -o $@

$(TEST_BIN): $(TEST_OBJ) $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) -pthread -o $@ $(TEST_OBJ) $(STATIC) $(CHECK_LIBS) $(LDLIBS_LIB)

# ---- fuzzing ---------------------------------------------------------------
# The oracle is shared with the unit tests but built without Check here.
$(BUILD)/obj/tests/fuzz/mesh_oracle.o: tests/unit/support/mesh_oracle.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -DCVMTEST_NO_CHECK -Itests/unit -MMD -MP -c $< -o $@

# libFuzzer binaries (CC=clang FUZZ=1 SAN=1, see check-fuzz).
$(BUILD)/fuzz/fuzz_%: $(BUILD)/obj/tests/fuzz/fuzz_%.o $(FUZZ_SUPPORT_OBJ) $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) -fsanitize=fuzzer -o $@ $^ $(LDLIBS_LIB)

# The same targets driven by tests/fuzz/regression_driver.c (any compiler).
$(BUILD)/fuzz/replay_%: $(BUILD)/obj/tests/fuzz/fuzz_%.o $(BUILD)/obj/tests/fuzz/regression_driver.o \
                        $(FUZZ_SUPPORT_OBJ) $(STATIC)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) -o $@ $^ $(LDLIBS_LIB)

# Keep the objects of the fuzz programs (make would delete them as intermediates).
.SECONDARY: $(FUZZ_TARGETS:%=$(BUILD)/obj/tests/fuzz/fuzz_%.o) $(BUILD)/obj/tests/fuzz/regression_driver.o \
            $(BUILD)/obj/tests/fuzz/fuzz_input.o $(BUILD)/obj/tests/fuzz/fuzz_pslg.o \
            $(BUILD)/obj/tests/fuzz/fuzz_run.o

fuzz-bins: $(FUZZ_BINS)
replay-bins: $(REPLAY_BINS)

# Seed corpus of a target: committed seeds, plus the example domains and test data for the readers.
fuzz_seeds = $(wildcard tests/fuzz/corpus/$(1)/*) \
  $(if $(filter poly_read,$(1)),$(wildcard examples/data/*.poly tests/data/*.poly)) \
  $(if $(filter node_read,$(1)),$(wildcard tests/data/*.node)) \
  $(if $(filter off_read,$(1)),$(wildcard examples/data3d/*.off)) \
  $(if $(filter stl_read,$(1)),$(wildcard examples/data3d/*.stl)) \
  $(if $(filter tetpoly_read,$(1)),$(wildcard examples/data3d/*.poly examples/data3d/*.smesh))

FUZZ_BUILD := $(BUILD)/fuzzer
FUZZ_SEED ?= 1
# make check also caps each target's executions, so with the fixed seed a run
# explores a prefix of one fixed input sequence (below what 20 s reach here).
FUZZ_RUNS_poly_read ?= 500000
FUZZ_RUNS_node_read ?= 500000
FUZZ_RUNS_cdt ?= 15000
FUZZ_RUNS_vtu_read ?= 100000
FUZZ_RUNS_vtk_read ?= 100000
FUZZ_RUNS_refine ?= 2000
FUZZ_RUNS_optimise ?= 1000
FUZZ_RUNS_off_read ?= 200000
FUZZ_RUNS_stl_read ?= 200000
FUZZ_RUNS_tetpoly_read ?= 200000
FUZZ_RUNS_ele_read ?= 100000
FUZZ_RUNS_delaunay3 ?= 600
FUZZ_RUNS_generate3 ?= 2000
FUZZ_RUNS_quadmesh ?= 300
FUZZ_RUNS_insert3 ?= 2000
FUZZ_RUNS_optimise3 ?= 1000
FUZZ_MAKE = $(MAKE) $(PAR) --no-print-directory BUILD=$(FUZZ_BUILD) CC=$(CLANG) SAN=1 FUZZ=1 OPENMP=0 TETGEN=0

# run_fuzz(target, seconds, seed, runs): fresh work corpus seeded from the committed one;
# the log goes to a file and is shown only on failure. make check uses a fixed
# seed (FUZZ_SEED, 1) so its short runs explore the same inputs on every machine
# of the same speed; make fuzz draws a new seed (0) each time.
define run_fuzz
	@rm -rf $(FUZZ_BUILD)/corpus/$(1) && mkdir -p $(FUZZ_BUILD)/corpus/$(1) $(FUZZ_BUILD)/artifacts/$(1)
	@for f in $(call fuzz_seeds,$(1)); do cp "$$f" "$(FUZZ_BUILD)/corpus/$(1)/$$(echo "$$f" | tr / _)"; done
	@echo "fuzz: $(1) for $(2) s"
	@ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  $(FUZZ_BUILD)/fuzz/fuzz_$(1) -max_total_time=$(2) -seed=$(3) -runs=$(4) -timeout=20 -rss_limit_mb=2048 \
	  -max_len=4096 -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/artifacts/$(1)/ \
	  $(FUZZ_BUILD)/corpus/$(1) > $(FUZZ_BUILD)/fuzz_$(1).log 2>&1 \
	  || { tail -n 60 $(FUZZ_BUILD)/fuzz_$(1).log; \
	       echo "fuzz: $(1) FAILED; crashing input in $(FUZZ_BUILD)/artifacts/$(1)/"; exit 1; }
	@grep -E '^stat::number_of_executed_units' $(FUZZ_BUILD)/fuzz_$(1).log | sed 's/^/fuzz: $(1) /' || true

endef

check-fuzz:
	@mkdir -p $(FUZZ_BUILD)
	$(FUZZ_MAKE) fuzz-bins
	$(foreach t,$(FUZZ_CHECK_TARGETS),$(call run_fuzz,$(t),$(FUZZ_TIME),$(FUZZ_SEED),$(or $(FUZZ_RUNS_$(t)),-1)))

fuzz:
	@mkdir -p $(FUZZ_BUILD)
	$(FUZZ_MAKE) fuzz-bins
	$(foreach t,$(FUZZ_TARGETS),$(call run_fuzz,$(t),$(FUZZ_LONG_TIME),0,-1))

# Replay every seed (and the example domains) through the fuzz targets without libFuzzer.
check-replay: replay-bins
	@set -e; for t in $(FUZZ_TARGETS); do \
	  case $$t in \
	    poly_read) extra="$(wildcard examples/data/*.poly tests/data/*.poly)";; \
	    node_read) extra="$(wildcard tests/data/*.node)";; \
	    off_read) extra="$(wildcard examples/data3d/*.off)";; \
	    stl_read) extra="$(wildcard examples/data3d/*.stl)";; \
	    tetpoly_read) extra="$(wildcard examples/data3d/*.poly examples/data3d/*.smesh)";; \
	    *) extra="";; \
	  esac; \
	  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    $(BUILD)/fuzz/replay_$$t tests/fuzz/corpus/$$t $$extra; \
	done

# ---- packages, demo --------------------------------------------------------
# Install missing system packages (Debian 12) when root; otherwise print the line.
deps:
	@sh .ci/deps.sh

# The NACA 0012 of examples/data: its triangulation and the three refiners'
# meshes, each as .vtu and as an .svg (PNG beside it when rsvg-convert exists)
# framed on the airfoil.
DEMO_IN := examples/data/naca0012.poly
DEMO_WINDOW := --svg-window=-0.45,-0.6,1.55,0.6
demo: deps
	$(MAKE) $(PAR) --no-print-directory all
	@mkdir -p $(BUILD)/demo
	$(CLI) triangulate $(DEMO_IN) -o $(BUILD)/demo/naca0012.vtu --svg $(BUILD)/demo/naca0012.svg $(DEMO_WINDOW) --quality
	@set -e; for a in frontal delaunay aflr; do \
	  echo "$(CLI) refine $(DEMO_IN) --algo $$a --auto 4 --grading 3 -o $(BUILD)/demo/naca0012_$$a.vtu --svg $(BUILD)/demo/naca0012_$$a.svg $(DEMO_WINDOW)"; \
	  $(CLI) refine $(DEMO_IN) --algo $$a --auto 4 --grading 3 -o $(BUILD)/demo/naca0012_$$a.vtu \
	    --svg $(BUILD)/demo/naca0012_$$a.svg $(DEMO_WINDOW) $$([ $$a = frontal ] && echo --quality); \
	done
	@if command -v rsvg-convert >/dev/null 2>&1; then \
	  for f in $(BUILD)/demo/*.svg; do rsvg-convert "$$f" -o "$${f%.svg}.png"; done; \
	  echo "demo: wrote $(BUILD)/demo/naca0012{,_frontal,_delaunay,_aflr}.{vtu,svg,png}"; \
	else echo "demo: wrote $(BUILD)/demo/naca0012{,_frontal,_delaunay,_aflr}.{vtu,svg} (no rsvg-convert: no PNG copies)"; fi

# ---- make check ------------------------------------------------------------
# Each step prints "== step ==" and its time; the first failure stops the run.
CHECK_STEPS := build check-unit check-symbols check-layers check-cli check-golden check-standalone check-examples check-asan \
               check-amalgamation check-clang check-noomp check-fuzz check-python check-fortran

check: deps
	@start=$$(date +%s); set -e; \
	for step in $(CHECK_STEPS); do \
	  t0=$$(date +%s); echo "== $$step =="; \
	  if [ $$step = build ]; then $(MAKE) $(PAR) --no-print-directory all tests; \
	  else $(MAKE) --no-print-directory $$step; fi; \
	  echo "== $$step: ok ($$(( $$(date +%s) - t0 )) s)"; \
	done; \
	echo "check: all steps passed in $$(( $$(date +%s) - start )) s"; \
	grep -h '^100%: Checks:' $(BUILD)/unit.log | tail -n 1

data3d: $(DATA3D)/.stamp
$(DATA3D)/.stamp: examples/data3d/make_data3d.py
	@mkdir -p $(DATA3D)
	$(PYTHON) $< $(DATA3D)
	@touch $@

# Each suite runs in its own process, JOBS at a time (.ci/run_unit_tests.sh).
UNIT_RUN = sh .ci/run_unit_tests.sh

check-unit: $(TEST_BIN) data3d
	$(TEST_ENV) $(UNIT_RUN) $(TEST_BIN) $(BUILD)/unit.log $(JOBS)

check-asan: data3d
	$(MAKE) $(PAR) --no-print-directory BUILD=$(BUILD)/asan SAN=1 OPENMP=0 tests replay-bins
	$(TEST_ENV) ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 CK_TIMEOUT_MULTIPLIER=4 \
	  $(UNIT_RUN) $(BUILD)/asan/tests/unit_tests $(BUILD)/asan/unit.log $(JOBS)
	$(MAKE) --no-print-directory BUILD=$(BUILD)/asan SAN=1 OPENMP=0 check-replay

check-valgrind: data3d
	$(MAKE) $(PAR) --no-print-directory BUILD=$(BUILD)/valgrind OPENMP=0 tests
	$(TEST_ENV) CK_FORK=no CK_TIMEOUT_MULTIPLIER=20 valgrind -q --error-exitcode=1 --leak-check=full \
	  --errors-for-leak-kinds=definite,indirect $(BUILD)/valgrind/tests/unit_tests

check-clang: data3d
	$(MAKE) $(PAR) --no-print-directory BUILD=$(BUILD)/clang CC=$(CLANG) all tests
	$(TEST_ENV) $(UNIT_RUN) $(BUILD)/clang/tests/unit_tests $(BUILD)/clang/unit.log $(JOBS)

# The unit tests themselves run without OpenMP in check-asan (OPENMP=0); here the
# build, the link (no OpenMP runtime) and the CLI.
check-noomp: data3d
	$(MAKE) $(PAR) --no-print-directory BUILD=$(BUILD)/noomp OPENMP=0 all
	@if readelf -d $(BUILD)/noomp/lib/libcvmesh.so.$(VERSION) | grep -q -E 'gomp|omp\.so'; then \
	  echo "check-noomp: OPENMP=0 library still links an OpenMP runtime"; exit 1; fi
	$(BUILD)/noomp/bin/cvmesh triangulate $(DATA_DIR)/annulus.poly -o $(BUILD)/noomp/annulus.node

# Golden checksums of the CLI's meshes on the example domains (tests/golden/sums.md5):
# a change that alters a mesh updates them on purpose (sh tests/golden/run.sh CLI --update).
check-golden: $(CLI)
	sh tests/golden/run.sh $(CLI)

# No file reaches outside the repository; a clone of HEAD alone demos and tests.
check-standalone:
	sh .ci/check_standalone.sh

check-symbols: $(SHARED)
	sh .ci/check_symbols.sh $(SHARED) .ci/exported_symbols.txt

# lib/ keeps its layers (a lower folder never includes a higher one) and its
# files within 800 lines, bar the few in .ci/layers_allow.txt; no two of its
# files depend on each other in a circle (symbols of the objects, nm).
check-layers: $(LIB_OBJ)
	sh .ci/check_layers.sh
	python3 .ci/check_cycles.py $(BUILD)/obj/lib

# The venv of every Python that a target runs (the CLI tests' checker, the
# binding tests, the benchmarks), from tests/requirements.txt.
venv: $(VENV)/.requirements
$(VENV)/.requirements: tests/requirements.txt
	@test -x $(VENV_PY) || { echo "venv: creating $(VENV)"; $(PYTHON) -m venv $(VENV); }
	$(VENV_PY) -m pip install -q --disable-pip-version-check -r $<
	@touch $@

# The independent checker's own tests, then the CLI tests that use it.
check-cli: $(CLI) venv
	@if [ ! -f tests/cli/run.sh ]; then echo "check-cli: tests/cli/run.sh is missing"; exit 1; fi
	$(VENV_PY) -m pytest -q -p no:cacheprovider tests/tools
	sh tests/cli/run.sh $(CLI) $(DATA_DIR) $(VENV_PY)

# Build every example against an installed copy found through pkg-config, then run it.
check-examples:
	rm -rf $(STAGE)
	$(MAKE) --no-print-directory install-c PREFIX=$(STAGE)
	@mkdir -p $(BUILD)/examples
	@set -e; for src in $(EXAMPLES_C); do \
	  name=$$(basename $$src .c); \
	  flags=$$(PKG_CONFIG_PATH=$(STAGE)/lib/pkgconfig pkg-config --cflags --libs cvmesh); \
	  echo "cc $$src $$flags"; \
	  $(CC) -std=c99 $(WARN) $$src $$flags -Wl,-rpath,$(STAGE)/lib -o $(BUILD)/examples/$$name; \
	  (cd $(BUILD)/examples && ./$$name) || { echo "check-examples: $$name failed"; exit 1; }; \
	done
	@# The co-volume Laplacian on cvmesh's 3D dual (and TetGen's mesh beside it): needs
	@# boundary recovery, so a build without TetGen says so and skips it.
	@if $(CLI) --version | grep -q TetGen; then \
	  $(MAKE) --no-print-directory venv && \
	  echo "$(VENV_PY) examples/python/covolume_laplacian3d.py --cvmesh $(CLI) --tetgen --check" && \
	  $(VENV_PY) examples/python/covolume_laplacian3d.py --cvmesh $(CLI) --tetgen --check; \
	else echo "check-examples: covolume_laplacian3d.py skipped (this build has no TetGen recovery)"; fi

# Bindings: their engineers own these scripts; skipped until they exist.
check-python: venv
	@if [ -f bindings/python/check.sh ]; then \
	  CVM_BUILD=$(abspath $(BUILD)) CC=$(CC) PYTHON=$(PYTHON) bash bindings/python/check.sh; \
	else echo "check-python: skipped (bindings/python/check.sh not present yet)"; fi

check-fortran: venv
	@if [ -f bindings/fortran/check.sh ]; then \
	  CVM_BUILD=$(abspath $(BUILD)) CC=$(CC) PYTHON=$(VENV_PY) LIBS="$(strip $(LDLIBS_LIB))" \
	    bash bindings/fortran/check.sh; \
	else echo "check-fortran: skipped (bindings/fortran/check.sh not present yet)"; fi

bench: all data3d
	BENCH_LIBS='$(LDLIBS_LIB)' sh tests/bench/run.sh $(BUILD) $(DATA_DIR)

# ---- amalgamation ----------------------------------------------------------
# One cvmesh.c holding every library source with internal headers inlined
# (.ci/amalgamate.sh), plus a copy of the public header.
AMALG := $(BUILD)/amalgamation

amalgamation: $(AMALG)/cvmesh.c $(AMALG)/cvmesh.h

$(AMALG)/cvmesh.h: include/cvmesh.h
	@mkdir -p $(dir $@)
	cp $< $@

$(AMALG)/cvmesh.c: $(LIB_SRC) $(wildcard lib/*/*.h) .ci/amalgamate.sh
	@mkdir -p $(dir $@)
	bash .ci/amalgamate.sh $@ $(LIB_SRC)
	@echo "amalgamation: wrote $@ ($$(wc -l < $@) lines) and $(AMALG)/cvmesh.h"

# The amalgamation compiles alone, warning-free, exports the same symbols, and
# the unit tests pass against it.
check-amalgamation: amalgamation $(TEST_OBJ) data3d
	$(CC) $(ALL_CFLAGS) -I$(AMALG) -c $(AMALG)/cvmesh.c -o $(AMALG)/cvmesh.o
	$(CC) -shared $(SANFLAGS) -o $(AMALG)/libcvmesh_amalg.so $(AMALG)/cvmesh.o $(LDLIBS_LIB)
	sh .ci/check_symbols.sh $(AMALG)/libcvmesh_amalg.so .ci/exported_symbols.txt
	$(CC) $(SANFLAGS) -pthread -o $(AMALG)/unit_tests $(TEST_OBJ) $(AMALG)/cvmesh.o \
	  $(CHECK_LIBS) $(LDLIBS_LIB)
	$(TEST_ENV) $(UNIT_RUN) $(AMALG)/unit_tests $(AMALG)/unit.log $(JOBS)

# ---- install, clean --------------------------------------------------------
# make install: the C library, header, pkg-config file and CLI, then the Fortran
# module and the Python package (bindings/*/*.mk). install-c is the C part alone.
install: install-c install-fortran install-python

install-c: all
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 644 include/cvmesh.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 include/cvmesh_experimental.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(STATIC) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(SHARED) $(DESTDIR)$(PREFIX)/lib/
	ln -sf libcvmesh.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libcvmesh.so
	install -m 755 $(CLI) $(DESTDIR)$(PREFIX)/bin/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' -e 's|@LIBS@|$(strip $(LDLIBS_LIB))|' \
	  .ci/cvmesh.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/cvmesh.pc

clean:
	rm -rf $(BUILD)

include bindings/python/python.mk bindings/fortran/fortran.mk

-include $(LIB_OBJ:.o=.d) $(CLI_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(FUZZ_SUPPORT_OBJ:.o=.d) \
         $(wildcard $(BUILD)/obj/tests/fuzz/*.d)
