# mvmpm - multi-velocity-field material point method
#   make deps      install the Debian packages it needs (apt-get)
#   make           build ./mvmpm
#   make test      C unit tests, the REPL in tmux, Lua verification; ends "N passed, M failed"
#   make test SAN=1  the same under AddressSanitizer/UndefinedBehaviorSanitizer
#   make test TSAN=1 the same under ThreadSanitizer (MVMPM_THREADS=2 for every run)
#   make bench     speed figures (rates and ratios), never part of the tests
#   make figures   the documentation's figures (docs/figures/*.png)
#   make pbx-scale the PBX grain bed's cost against its grain count (a few minutes)
#   make study     what accuracy costs in time: studies/*.lua, CSVs in out/study,
#                  plots in docs/figures/accuracy_*.png (docs/accuracy.md)
#   make check-paraview  ParaView's pvbatch opens a run's XDMF (needs Debian's paraview)

DEB_PACKAGES = build-essential pkg-config liblua5.4-dev libhdf5-dev hdf5-tools \
               libedit-dev zlib1g-dev python3-h5py python3-numpy tmux

PKGS   = lua5.4 hdf5 libedit zlib
CC    ?= cc
# the same warnings, as errors, in every build; -Wformat-truncation is
# gcc's alone (clang refuses to hear of it)
WARNCOM = -Wall -Wextra -Werror -Wshadow -Wno-unused-parameter
WARN   = $(WARNCOM) -Wno-format-truncation
OPT    = -O3 -march=native
# undefined behaviour stops the run at the first report: gcc's
# "undefined" leaves out float-cast-overflow (a NaN or 1e308 cast to an
# int), so it is named.  float-divide-by-zero stays out: make test never
# trips it, but a time step that underflows to 0 on an absurd velocity
# does, and the run then stops on its own check (det F <= 0)
UBSAN  = -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
export UBSAN_OPTIONS ?= halt_on_error=1:print_stacktrace=1
ifeq ($(FUZZ),1)
CC     = clang
WARN   = $(WARNCOM)
BUILD  = build-fuzz
OPT    = -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link $(UBSAN)
BIN    = $(BUILD)/mvmpm
else ifeq ($(SAN),1)
BUILD  = build-san
OPT    = -O1 -g -fno-omit-frame-pointer $(UBSAN)
BIN    = $(BUILD)/mvmpm
else ifeq ($(TSAN),1)
BUILD  = build-tsan
OPT    = -O1 -g -fno-omit-frame-pointer -fsanitize=thread
BIN    = $(BUILD)/mvmpm
else
BUILD  = build
BIN    = mvmpm
endif
CFLAGS  = -std=c11 -pthread -D_POSIX_C_SOURCE=200809L $(WARN) $(OPT) -MMD -MP \
          $(shell pkg-config --cflags $(PKGS) 2>/dev/null) $(EXTRA_CFLAGS)
LDLIBS  = $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lm -pthread

SRC     = $(wildcard src/*.c)
OBJ     = $(SRC:src/%.c=$(BUILD)/%.o)
LIBOBJ  = $(filter-out $(BUILD)/main.o,$(OBJ))
UNIT    = $(wildcard tests/unit/test_*.c)
UNITBIN = $(UNIT:tests/unit/%.c=$(BUILD)/unit/%)

all: $(BIN)

$(BIN): $(OBJ)
	$(CC) $(CFLAGS) -o $@ $(OBJ) $(LDLIBS)

$(BUILD)/%.o: src/%.c | $(BUILD)
	$(CC) $(CFLAGS) -c $< -o $@

$(BUILD)/unit/%: tests/unit/%.c $(LIBOBJ) tests/unit/unit.h | $(BUILD)/unit
	$(CC) $(CFLAGS) -Isrc -o $@ $< $(LIBOBJ) $(LDLIBS)

$(BUILD) $(BUILD)/unit:
	mkdir -p $@

deps:
	@if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	$$SUDO apt-get update && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y $(DEB_PACKAGES)

unit: $(UNITBIN)

test: $(BIN) $(UNITBIN)
	@bash tests/run.sh $(BIN) $(BUILD)/unit

bench: $(BIN)
	@bash bench/run.sh ./$(BIN)

# one process per bed, so that each peak resident size is the bed's own
PBX_SIDES ?= 0.65e-3 1.2e-3 1.7e-3 2.4e-3
pbx-scale: $(BIN)
	@for s in $(PBX_SIDES); do PBX_SIDE=$$s ./$(BIN) test bench/pbx_scale.lua | grep '^pbx'; done

# a reduced PBX bed (0.36 mm square, grains half the default size, 4
# cells across the smallest) sheared to 100 % strain at 1e6/s, with
# binder and dry, in the background (about 10-15 minutes each on a free
# core); figures into docs/figures/pbx_shear/<run>/ (docs/pbx.md)
PBX_SHEAR = --set size=0.36e-3 --set scale=0.5 --set cells=4 --set packing=0.7 --set rate=1e6 --set ramp=0.01 --set images=0.25 --quiet
pbx-shear: $(BIN)
	@mkdir -p out
	nohup sh -c 'for r in binder:true dry:false; do name=$${r%%:*}; \
	  ./$(BIN) run scenarios/pbx9501.lua $(PBX_SHEAR) --set binder=$${r#*:} --out out/pbx_shear_$$name || exit 1; \
	  mkdir -p docs/figures/pbx_shear/$$name; \
	  cp out/pbx_shear_$$name/pbx_*.png out/pbx_shear_$$name/pbx_summary.txt out/pbx_shear_$$name/pbx_locking.csv \
	     out/pbx_shear_$$name/pbx_stats.csv docs/figures/pbx_shear/$$name/; \
	done; echo pbx shear runs done' > out/pbx_shear.log 2>&1 &
	@echo "running in the background; progress in out/pbx_shear.log"

clean:
	rm -rf build build-san build-tsan build-fuzz mvmpm

# the scene loader and Lua API under libFuzzer (clang), ASan and UBSan,
# seeded with the scenes and tests/fuzz/seeds (the corpus in
# build-fuzz/corpus is kept between runs); FUZZ_SECONDS (default 120)
# of fuzzing.  A clean run prints libFuzzer's counts; a finding prints
# the sanitizer's report and the reproducer's path and fails
FUZZ_SECONDS ?= 120
fuzz:
	@$(MAKE) --no-print-directory FUZZ=1 build-fuzz/fuzz_scene
	@bash tests/fuzz/run.sh build-fuzz/fuzz_scene $(FUZZ_SECONDS)

build-fuzz/fuzz_scene: tests/fuzz/fuzz_scene.c $(LIBOBJ)
	$(CC) $(CFLAGS) -fsanitize=fuzzer -Isrc -o $@ $< $(LIBOBJ) $(LDLIBS)

# many random scenes under the sanitizers (make test runs 20 seeds)
RANDOM_SEEDS ?= 1-500
random:
	@$(MAKE) --no-print-directory SAN=1 build-san/mvmpm
	SEEDS=$(RANDOM_SEEDS) ./build-san/mvmpm test tests/random/gen.lua

# the hard-case suite alone (it is part of make test)
hard: $(BIN)
	./$(BIN) test tests/hard/*.lua

# the documentation's figures, made again from the scenes
figures: $(BIN)
	./$(BIN) test docs/figures/fig5.lua
	./$(BIN) test docs/figures/bounce.lua

# the accuracy-cost study (docs/accuracy.md): each case over its grid of
# settings, one after the other (timings are taken one run at a time);
# STUDY_QUICK=1 for a smoke run, STUDY_REPEATS=R for the repeats (default 3)
STUDIES = bar bar_ppc_cfl disc block concentric concentric_onset bounce_friction bounce
study: $(BIN)
	@mkdir -p out/study docs/figures
	@bash -o pipefail -c 'for s in $(STUDIES); do ./$(BIN) test studies/$$s.lua || exit 1; done 2>&1 | tee out/study/study.log'

.PHONY: all deps unit test bench clean check-paraview figures hard pbx-scale pbx-shear fuzz random study
-include $(OBJ:.o=.d) $(UNITBIN:=.d)

# ParaView (Debian's paraview, not a build dependency) opens a run's XDMF
# series and must see every particle and every array of every snapshot
check-paraview: $(BIN)
	@rm -rf build/check-paraview
	./$(BIN) run scenarios/cylinder_bounce.lua --set friction=0.1 --out build/check-paraview --quiet
	pvbatch tests/tools/check_xdmf.py build/check-paraview/particles.xmf \
	  $$(for f in build/check-paraview/particles_*.h5; do printf '208 '; done)

# the granular shear cell (docs/shear.md) at the report's resolution, both
# scenes and both bond strengths, in the background:
#   make shear; tail -f out/shear.log
SHEAR_RUNS = shear_dry:scenarios/shear_dry.lua: \
             shear_binder:scenarios/shear_binder.lua: \
             shear_binder_bond0:scenarios/shear_binder.lua:--set=bond=0
shear: $(BIN)
	@mkdir -p out
	nohup sh -c 'for r in $(SHEAR_RUNS); do \
	  name=$${r%%:*}; rest=$${r#*:}; scene=$${rest%%:*}; opt=$${rest#*:}; \
	  ./$(BIN) run $$scene $$opt --out out/$$name --quiet || exit 1; \
	  mkdir -p docs/figures/shear/$$name; \
	  cp out/$$name/*.png out/$$name/summary.txt out/$$name/locking.csv docs/figures/shear/$$name/; \
	done; echo shear runs done' > out/shear.log 2>&1 &
	@echo "running in the background; progress in out/shear.log"

.PHONY: shear
