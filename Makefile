# mcrash — top-level build. `make` builds bin/mcrash; `make test` runs every test;
# `make check-asan` runs them under AddressSanitizer + UBSan; `make demo` runs the default scenario.
# Everything depends on Debian packages only; `make deps` installs them (as root) when missing.

CC       ?= cc
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
BUILD    ?= build
BIN      ?= bin
PKGS      = ode hdf5-serial yaml-0.1
DEB_PKGS  = build-essential pkg-config libode-dev libsundials-dev libhdf5-dev libyaml-dev \
            liblapack-dev hdf5-tools zlib1g-dev libopenmpi-dev openmpi-bin
# wanted, not required: tests/test_report_page.c opens `mcrash report`'s page in headless
# Chromium and skips (saying so) without it
DEB_OPT   = chromium

PKG_CFLAGS := $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS   := $(shell pkg-config --libs $(PKGS) 2>/dev/null)

OPT      ?= -O2 -g
# OpenMP threads the FE element and node loops (OMP_NUM_THREADS; results do not depend on it);
# `make OMP=` builds without it
OMP      ?= -fopenmp
CFLAGS   += -std=c17 -Wall -Wextra -Werror -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE \
            $(OPT) $(OMP) $(if $(OMP),,-Wno-unknown-pragmas) -MMD -MP -I. $(PKG_CFLAGS) $(SAN)
LDFLAGS  += $(SAN) $(OMP)
# the FE kernel (fe/ and its subfolders) at -O3: its element loops vectorise further (hex -20 %, shells -2..5 % per
# element-cycle, bench/bench_fe.c; the results are the same to the bit, the FE tests check them;
# not under the sanitizers, where -O3 gives false stringop warnings)
FE_OPT   ?= -O3
LDLIBS   += $(PKG_LIBS) -lsundials_cvode -lsundials_nvecserial -llapack -lblas -lm

MODULES  = core analysis fe rom stage1_mb stage2_fe stage3_fe translators
# fe/ groups its sources in subfolders (docs/contracts.md "Layout of fe/"); a file in fe/ itself
# still builds
LIB_SRC  = $(foreach d,$(MODULES),$(wildcard $(d)/*.c)) $(wildcard fe/*/*.c)
CLI_SRC  = $(wildcard cli/*.c)
TEST_SRC = $(wildcard tests/test_*.c)
BENCH_SRC= $(wildcard bench/bench_*.c)

LIB_OBJ  = $(LIB_SRC:%.c=$(BUILD)/%.o)
CLI_OBJ  = $(CLI_SRC:%.c=$(BUILD)/%.o)
TEST_BIN = $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCH_BIN= $(BENCH_SRC:bench/%.c=$(BUILD)/bench/%)
LIB      = $(BUILD)/libmcrash.a
MCRASH   = $(BIN)/mcrash
# `mcrash study` under mpirun runs bin/mcrash-mpi (cli/study_mpi.c built by mpicc with MCS_MPI),
# built only where mpicc exists
MPICC   ?= $(shell command -v mpicc 2>/dev/null)
MCRASH_MPI = $(if $(MPICC),$(BIN)/mcrash-mpi)

.SECONDARY:
.PHONY: all deps test check-asan demo bench verify figures clean format fuzz fuzz-bins

all: $(MCRASH) $(MCRASH_MPI)

# install the Debian packages that are missing; nothing when all are present
deps:
	@missing=""; for p in $(DEB_PKGS); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -z "$$missing" ]; then echo "deps: all Debian packages present"; \
	elif [ "$$(id -u)" = 0 ]; then echo "deps: installing$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	else echo "deps: missing$$missing; run: sudo apt-get install -y$$missing"; exit 1; fi
	@for p in $(DEB_OPT); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' && continue; \
	  if [ "$$(id -u)" = 0 ]; then echo "deps: installing $$p"; \
	    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$p; } \
	      || echo "deps: $$p could not be installed; the tests that need it skip"; \
	  else echo "deps: $$p missing (sudo apt-get install -y $$p); the tests that need it skip"; fi; \
	done

$(BUILD)/fe/%.o: CFLAGS += $(if $(SAN),,$(FE_OPT))

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(MCRASH): $(CLI_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $(CLI_OBJ) $(LIB) $(LDLIBS)

$(BUILD)/mpi/study_mpi.o: cli/study_mpi.c
	@mkdir -p $(dir $@)
	$(MPICC) $(CFLAGS) -DMCS_MPI -c $< -o $@

$(BIN)/mcrash-mpi: $(filter-out $(BUILD)/cli/study_mpi.o,$(CLI_OBJ)) $(BUILD)/mpi/study_mpi.o $(LIB)
	@mkdir -p $(dir $@)
	$(MPICC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# the report page's test reads Chromium's PNG screenshot (zlib)
$(BUILD)/tests/test_report_page: LDLIBS += -lz

$(BUILD)/tests/%: $(BUILD)/tests/%.o $(LIB)
	$(CC) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

$(BUILD)/bench/%: $(BUILD)/bench/%.o $(LIB)
	$(CC) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# every test binary, then one closing line `N passed, N failed`
test: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(MCRASH) $(MCRASH_MPI) $(TEST_BIN)
	@MCRASH_BIN=$(MCRASH) MCRASH_BUILD=$(BUILD) sh tests/run_tests.sh $(TEST_BIN)

# the same tests under AddressSanitizer and UBSan, in their own build tree
check-asan: deps
	@$(MAKE) --no-print-directory test BUILD=build-asan BIN=build-asan/bin OPT="-O1 -g" \
	  SAN="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"

# longer verification runs (not part of `make test`)
verify: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(MCRASH) $(MCRASH_MPI) $(TEST_BIN)
	@MCRASH_VERIFY=1 MCRASH_BIN=$(MCRASH) MCRASH_BUILD=$(BUILD) sh tests/run_tests.sh $(TEST_BIN)

# the figures README.md and docs/*.md state, rewritten in place from the tests' own runs
# (tests/figures.h): every test as `make test` runs it, then as `make verify` does; a figure both
# state must read the same in both. Fails when a test fails, a doc's figure has no test or a
# figure depends on the mode, and leaves the docs untouched then
figures: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(MCRASH) $(MCRASH_MPI) $(TEST_BIN)
	@rm -f $(BUILD)/figures.tsv
	@MCRASH_FIGURES_OUT=$(CURDIR)/$(BUILD)/figures.tsv MCRASH_BIN=$(MCRASH) \
	  MCRASH_BUILD=$(BUILD) sh tests/run_tests.sh $(TEST_BIN)
	@MCRASH_FIGURES_OUT=$(CURDIR)/$(BUILD)/figures.tsv MCRASH_VERIFY=1 MCRASH_BIN=$(MCRASH) \
	  MCRASH_BUILD=$(BUILD) sh tests/run_tests.sh $(TEST_BIN)
	@perl scripts/figures.pl $(BUILD)/figures.tsv

# libFuzzer harnesses of the file readers (tests/fuzz/, docs/reliability.md "Fuzzing"), built by
# clang under ASan/UBSan in build-fuzz/; each runs FUZZ_SECONDS and a summary line per harness
# ends the output. clang is needed for this target only (make deps installs it here);
# -Wno-pass-failed: clang 14 warns where an `omp simd` loop is not vectorised at -O1
FUZZ_SECONDS ?= 60
FUZZ_HARNESS  = scenario keyword csv mme obj results
FUZZ_BUILD    = build-fuzz
FUZZ_SAN      = -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
fuzz:
	@$(MAKE) --no-print-directory deps DEB_PKGS="$(DEB_PKGS) clang"
	@$(MAKE) --no-print-directory -j$(JOBS) fuzz-bins CC=clang BUILD=$(FUZZ_BUILD) OPT="-O1 -g" \
	  FE_OPT= SAN="$(FUZZ_SAN) -fsanitize=fuzzer-no-link -Wno-pass-failed"
	@sh tests/fuzz/run_fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_HARNESS)

fuzz-bins: $(FUZZ_HARNESS:%=$(BUILD)/fuzz/fuzz_%)

$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fsanitize=fuzzer -o $@ $< $(LIB) $(LDFLAGS) $(LDLIBS)

bench: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(MCRASH) $(BENCH_BIN)
	@for b in $(BENCH_BIN); do $$b || exit 1; done

demo: deps
	@$(MAKE) --no-print-directory -j$(JOBS) $(MCRASH)
	@sh scripts/demo.sh $(MCRASH)

# open an exported sample results file in ParaView's XDMF readers (optional: needs pvpython,
# Debian package python3-paraview); prints points, cells, time steps as ParaView reads them
.PHONY: check-paraview
check-paraview: $(MCRASH) $(BUILD)/tests/test_export
	@command -v pvpython >/dev/null || { echo "check-paraview: pvpython not found (apt-get install python3-paraview)"; exit 1; }
	@$(BUILD)/tests/test_export --write-sample $(BUILD)/paraview >/dev/null
	@$(MCRASH) export $(BUILD)/paraview/sample.h5 --xdmf
	@$(MCRASH) export $(BUILD)/paraview/sample.h5 --xdmf2 $(BUILD)/paraview/sample_xdmf2.xmf
	@for v in "" --xdmf2; do f=$(BUILD)/paraview/sample.xmf; [ -n "$$v" ] && f=$(BUILD)/paraview/sample_xdmf2.xmf; \
	  pvpython --force-offscreen-rendering scripts/check_xdmf_paraview.py $$v --time 0.02 $$f > $(BUILD)/paraview/pv.log 2>&1 \
	    || { cat $(BUILD)/paraview/pv.log; exit 1; }; \
	  echo "$$f: $$(grep '^xdmf:' $(BUILD)/paraview/pv.log)"; done

format:
	clang-format -i $(LIB_SRC) $(CLI_SRC) $(TEST_SRC) $(BENCH_SRC) $(wildcard */*.h fe/*/*.h)

clean:
	rm -rf build build-asan build-fuzz bin out

-include $(LIB_OBJ:.o=.d) $(CLI_OBJ:.o=.d) $(BUILD)/mpi/study_mpi.d $(TEST_SRC:tests/%.c=$(BUILD)/tests/%.d)
