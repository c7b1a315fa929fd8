# mvmpm - multi-velocity-field material point method
#   make deps      install the Debian packages it needs (apt-get)
#   make           build ./mvmpm
#   make test      the layers' check, C unit tests, the REPL in tmux, Lua
#                  verification; ends "N passed, M failed"; the jobs run
#                  JOBS at a time (default: the machine's cores)
#   make layers    every include and every call between objects against the
#                  layers of src/ (docs/architecture.md)
#   make test SAN=1  the same under AddressSanitizer/UndefinedBehaviorSanitizer,
#                  less the long convergence files of tests/heavy (SAN_FULL=1
#                  runs them too; hours on two cores)
#   make test TSAN=1 the same under ThreadSanitizer (MVMPM_THREADS=2 for every run)
#   make bench     speed figures (rates and ratios), never part of the tests
#   make figures   the documentation's figures (docs/figures/*.png)
#   make pbx-scale the PBX grain bed's cost against its grain count (a few minutes)
#   make study     what accuracy costs in time: studies/*.lua, CSVs in out/study,
#                  plots in docs/figures/accuracy_*.png (docs/accuracy.md)
#   make check-paraview  ParaView's three XDMF readers open a 2-D and a 3-D run's XDMF (installs
#                  Debian's paraview first: make deps-paraview)
#   make install   PREFIX/bin/mvmpm, the Lua modules, mvmpm.so for a stock lua5.4,
#                  the manual mvmpm(1); PREFIX=/usr/local, DESTDIR for staging
#   make CC=clang  the same build with clang; PORTABLE=1 without -march=native

DEB_PACKAGES = build-essential pkg-config liblua5.4-dev libhdf5-dev hdf5-tools \
               libedit-dev zlib1g-dev python3-h5py python3-numpy tmux lua5.4 \
               groff-base

PKGS   = lua5.4 hdf5 libedit zlib
CC    ?= cc
PREFIX ?= /usr/local
# the same warnings, as errors, in every build, with gcc or clang
# (make CC=clang); -Wformat-truncation is gcc's alone
WARNCOM = -Wall -Wextra -Werror -Wshadow -Wno-unused-parameter
ifneq (,$(findstring clang,$(shell $(CC) --version 2>/dev/null)))
WARN   = $(WARNCOM)
else
WARN   = $(WARNCOM) -Wno-format-truncation
endif
# PORTABLE=1: code for any x86-64 (or the compiler's default target), for
# a binary that must run on every node of a cluster; otherwise tuned to
# this machine's processor
ifeq ($(PORTABLE),1)
ARCH   =
else
ARCH   = -march=native
endif
OPT    = -O3 $(ARCH)
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
# -O2: the sanitizers' checks stay, and the tests run in 0.6 of the time
# they take at -O1
BUILD  = build-san
OPT    = -O2 $(ARCH) -g -fno-omit-frame-pointer $(UBSAN)
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
          $(EXTRA_CFLAGS)
LDLIBS  = $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lm -pthread

# The layers (docs/architecture.md): each directory of src/ is compiled
# with the include paths of the layers it may use and no others, so an
# include that crosses a layer the wrong way does not compile.  The core
# sees no Lua, HDF5 or rendering header; only io sees HDF5's, only lua
# and app see Lua's.  make layers checks the same table by name.
PC_LUA  = $(shell pkg-config --cflags lua5.4 2>/dev/null)
PC_HDF5 = $(shell pkg-config --cflags hdf5 2>/dev/null)
PC_APP  = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
LAYERS  = core io render lua app
INC_core   = -Isrc/core
INC_io     = -Isrc/core -Isrc/io $(PC_HDF5)
INC_render = -Isrc/core -Isrc/io -Isrc/render
INC_lua    = -Isrc/core -Isrc/io -Isrc/render -Isrc/lua $(PC_LUA)
INC_app    = -Isrc/core -Isrc/io -Isrc/render -Isrc/lua -Isrc/app $(PC_APP)
# a source's layer: the directory under src/ of the object's stem
layer   = $(firstword $(subst /, ,$(1)))
empty   :=
space   := $(empty) $(empty)

SRC     = $(wildcard $(LAYERS:%=src/%/*.c))
# One binary runs 2-D and 3-D scenes.  Every source that sees dim.h is
# compiled twice, for DIM = 2 into $(BUILD) and for DIM = 3 into
# $(BUILD)/d3; the 3-D objects are linked into one relocatable object
# whose every global name gets the suffix _3d (objcopy), so the two
# dimensions' functions live side by side.  The sources below never see
# dim.h and are built once: their state (the interrupt flag, the Lua
# registry helpers) must be one for both.  make checks this list against
# the compiler's dependency files.  entry.c's main runs the 2-D
# application, and the 3-D one when the command's scene, checkpoint or
# snapshot is 3-D (src/app/app.h).
DIMFREE = core/hash core/par core/shape io/h5sum io/ofile io/out_csv \
          lua/interrupt lua/lstate lua/version render/axis app/entry app/repl \
          render/canvas render/cmap render/font render/plot_png render/png \
          render/svg
# the names each dimension's code calls in the other (lmvmpm.h)
DIMKEEP = lmvmpm_enter3 lmvmpm_loaded3 app_main3
SRC3    = $(filter-out $(DIMFREE:%=src/%.c),$(SRC))
OBJ3    = $(SRC3:src/%.c=$(BUILD)/d3/%.o)
OBJ     = $(SRC:src/%.c=$(BUILD)/%.o)
DIM3OBJ = $(BUILD)/dim3.o
LIBOBJ  = $(filter-out $(BUILD)/app/entry.o,$(OBJ)) $(DIM3OBJ)
UNIT    = $(wildcard tests/unit/test_*.c)
UNITBIN = $(UNIT:tests/unit/%.c=$(BUILD)/unit/%)

all: $(BIN)

# the compiler and its flags, kept in the build directory: objects built
# with others (make CC=clang, PORTABLE=1 after a tuned build) are rebuilt
FLAGSTAMP = $(BUILD)/flags
FLAGTEXT = $(CC) $(CFLAGS) $(foreach l,$(LAYERS),$(l): $(INC_$(l)))
$(shell mkdir -p $(BUILD); echo '$(FLAGTEXT)' | cmp -s - $(FLAGSTAMP) 2>/dev/null || echo '$(FLAGTEXT)' > $(FLAGSTAMP))

$(BIN): $(OBJ) $(DIM3OBJ)
	$(CC) $(CFLAGS) -o $@ $(OBJ) $(DIM3OBJ) $(LDLIBS)

$(BUILD)/d3/%.o: src/%.c $(FLAGSTAMP) | $(BUILD)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -DDIM=3 $(INC_$(call layer,$*)) -c $< -o $@

$(BUILD)/%.o: src/%.c $(FLAGSTAMP) | $(BUILD)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(INC_$(call layer,$*)) -c $< -o $@

# the 3-D objects as one, every global name they define suffixed _3d but
# those of DIMKEEP; and a DIMFREE source that comes to see dim.h stops
# the build (its .d file names it)
$(BUILD)/dim3.o: $(OBJ3) $(OBJ)
	@for f in $(DIMFREE); do if grep -q 'dim\.h' $(BUILD)/$$f.d 2>/dev/null; then \
	  echo "src/$$f.c includes dim.h: take it out of DIMFREE in the Makefile" >&2; exit 1; fi; done
	$(CC) $(CFLAGS) -r -nostdlib -o $@.tmp $(OBJ3)
	nm -g --defined-only $@.tmp | awk 'NF == 3 { print $$3 " " $$3 "_3d" }' | \
	  grep -v -E '^($(subst $(space),|,$(DIMKEEP))) ' > $@.syms
	objcopy --redefine-syms=$@.syms $@.tmp $@
	rm -f $@.tmp

# the build's identity (src/lua/version.c): git describe of this tree, else
# the release number, and the compiler and flags.  The header is
# rewritten only when its text changes, so only version.o is rebuilt
$(BUILD)/lua/version.o $(BUILD)/pic/lua/version.o: $(BUILD)/version_gen.h
$(BUILD)/lua/version.o $(BUILD)/pic/lua/version.o: CFLAGS += -I$(BUILD)
$(BUILD)/version_gen.h: FORCE | $(BUILD)
	@v=$$(git describe --always --dirty 2>/dev/null) || v=; \
	cc=$$($(CC) --version 2>/dev/null | head -1); \
	esc() { printf '%s' "$$1" | sed 's/[\\"]/\\&/g'; }; \
	{ [ -n "$$v" ] && printf '#define MVMPM_GIT_VERSION "%s"\n' "$$(esc "$$v")"; \
	  printf '#define MVMPM_BUILD "%s"\n' "$$(esc "$(CC) ($$cc) $(strip $(CFLAGS))")"; } >$@.new; \
	if cmp -s $@.new $@; then rm -f $@.new; else mv $@.new $@; fi

# the unit tests see every layer, but test_ckpt.c core's and io's only:
# a checkpoint is written and read back with no Lua header in sight
INC_unit = $(INC_app)
$(BUILD)/unit/test_ckpt: INC_unit = $(INC_io)
$(BUILD)/unit/%: tests/unit/%.c $(LIBOBJ) tests/unit/unit.h | $(BUILD)/unit
	$(CC) $(CFLAGS) $(INC_unit) -o $@ $< $(LIBOBJ) $(LDLIBS)

# the unit tests written for either dimension, built again for 3-D: the
# object's calls are renamed as dim3.o's names were (its .syms map)
UNIT3    = test_diag_dim test_dimvec test_normals test_out_h5 test_particles \
           test_render_view test_walls
UNIT3BIN = $(UNIT3:%=$(BUILD)/unit/%_3d)
$(BUILD)/unit/%_3d: tests/unit/%.c $(LIBOBJ) tests/unit/unit.h | $(BUILD)/unit
	$(CC) $(CFLAGS) -DDIM=3 $(INC_unit) -c $< -o $@.o
	objcopy --redefine-syms=$(BUILD)/dim3.o.syms $@.o
	$(CC) $(CFLAGS) -o $@ $@.o $(LIBOBJ) $(LDLIBS)
	rm -f $@.o

$(BUILD) $(BUILD)/unit:
	mkdir -p $@

deps:
	@if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	$$SUDO apt-get update && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y $(DEB_PACKAGES)

unit: $(UNITBIN) $(UNIT3BIN)

# under the sanitizers the long convergence files (tests/heavy) run only
# with SAN_FULL=1
LIGHT = $(if $(filter 1,$(SAN)),$(if $(filter 1,$(SAN_FULL)),0,1),0)
test: $(BIN) $(UNITBIN) $(UNIT3BIN) layers
	@LIGHT=$(LIGHT) bash tests/run.sh $(BIN) $(BUILD)/unit

# every include and every call between objects against the layers'
# table (tests/tools/layers.py, docs/architecture.md); make test runs it
layers: $(OBJ)
	@python3 tests/tools/layers.py $(BUILD)

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
	  ./$(BIN) run scenarios/pbx9501.lua $(PBX_SHEAR) --set binder=$${r#*:} --out out/pbx_shear_$$name --overwrite || exit 1; \
	  mkdir -p docs/figures/pbx_shear/$$name; \
	  cp out/pbx_shear_$$name/pbx_*.png out/pbx_shear_$$name/pbx_summary.txt out/pbx_shear_$$name/pbx_locking.csv \
	     out/pbx_shear_$$name/pbx_stats.csv docs/figures/pbx_shear/$$name/; \
	done; echo pbx shear runs done' > out/pbx_shear.log 2>&1 &
	@echo "running in the background; progress in out/pbx_shear.log"

clean:
	rm -rf build build-san build-tsan build-fuzz mvmpm

# The Lua module for a stock interpreter: the engine's objects built again
# position-independent, linked without liblua (the interpreter has it;
# two copies of Lua in one process would corrupt its state)
PICOBJ = $(patsubst $(BUILD)/%.o,$(BUILD)/pic/%.o,$(filter-out $(DIM3OBJ),$(LIBOBJ)))
LUALIBS = $(shell pkg-config --libs hdf5 libedit zlib 2>/dev/null) -lm -pthread
$(BUILD)/pic/%.o: src/%.c $(FLAGSTAMP) | $(BUILD)/pic
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(INC_$(call layer,$*)) -fPIC -c $< -o $@
$(BUILD)/pic:
	mkdir -p $@
$(BUILD)/mvmpm.so: $(PICOBJ)
	$(CC) $(CFLAGS) -shared -o $@ $(PICOBJ) $(LUALIBS)
module: $(BUILD)/mvmpm.so

# bin/, share/lua/5.4/mvmpm/ and lib/lua/5.4/ are where Debian's lua5.4
# looks under /usr/local; the binary looks in ../share/lua/5.4 beside
# itself, so any PREFIX works
LUAMODS = $(wildcard lua/mvmpm/*.lua)
install: $(BIN) $(BUILD)/mvmpm.so
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/lua/5.4/mvmpm \
	  $(DESTDIR)$(PREFIX)/lib/lua/5.4 $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/mvmpm
	install -m 644 $(LUAMODS) $(DESTDIR)$(PREFIX)/share/lua/5.4/mvmpm/
	install -m 755 $(BUILD)/mvmpm.so $(DESTDIR)$(PREFIX)/lib/lua/5.4/mvmpm.so
	install -m 644 docs/mvmpm.1 $(DESTDIR)$(PREFIX)/share/man/man1/mvmpm.1

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/mvmpm $(DESTDIR)$(PREFIX)/lib/lua/5.4/mvmpm.so \
	  $(DESTDIR)$(PREFIX)/share/man/man1/mvmpm.1
	rm -rf $(DESTDIR)$(PREFIX)/share/lua/5.4/mvmpm

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
	$(CC) $(CFLAGS) -fsanitize=fuzzer $(INC_app) -o $@ $< $(LIBOBJ) $(LDLIBS)

# many random scenes under the sanitizers (make test runs 20 2-D seeds
# and 4 3-D ones)
RANDOM_SEEDS ?= 1-500
RANDOM_SEEDS3 ?= 1-100
random:
	@$(MAKE) --no-print-directory SAN=1 build-san/mvmpm
	SEEDS=$(RANDOM_SEEDS) SEEDS3=$(RANDOM_SEEDS3) ./build-san/mvmpm test tests/random/gen.lua

# the hard-case suite alone (it is part of make test)
hard: $(BIN)
	./$(BIN) test tests/hard/*.lua

# the documentation's figures, made again from the scenes
figures: $(BIN)
	./$(BIN) test docs/figures/fig5.lua
	./$(BIN) test docs/figures/bounce.lua
	./$(BIN) test docs/figures/contact.lua
	./$(BIN) test docs/figures/contact_cases.lua
	./$(BIN) test docs/figures/cohesive.lua
	./$(BIN) test docs/figures/bar_crossing.lua
	./$(BIN) test docs/figures/default_shape.lua
	./$(BIN) test docs/figures/penalty_bounce.lua
	./$(BIN) test docs/figures/wall_rules.lua
	./$(BIN) test docs/figures/driven_walls.lua

# the accuracy-cost study (docs/accuracy.md): each case over its grid of
# settings, one after the other (timings are taken one run at a time);
# STUDY_QUICK=1 for a smoke run, STUDY_REPEATS=R for the repeats (default 3)
STUDIES = bar bar_ppc_cfl disc block concentric concentric_onset debond_front cohesive bounce_friction bounce_arm bounce roll roll_slab friction_work body_patch \
          grain_budget piston_pack thermal_explosion d3_bounce ringing
study: $(BIN)
	@mkdir -p out/study docs/figures
	@bash -o pipefail -c 'for s in $(STUDIES); do ./$(BIN) test studies/$$s.lua || exit 1; done 2>&1 | tee out/study/study.log'

FORCE:

.PHONY: FORCE all deps deps-paraview unit test layers bench clean module install uninstall print-cflags check-paraview figures hard pbx-scale pbx-shear fuzz random study
-include $(OBJ:.o=.d) $(OBJ3:.o=.d) $(UNITBIN:=.d) $(PICOBJ:.o=.d)

# ParaView (Debian's paraview, installed by make deps-paraview; not a
# build dependency) opens a run's XDMF series with each of its three
# XDMF readers, and each must see every particle and every array of
# every snapshot, bit for bit: a 2-D series (the cylinder's bounce, 208
# particles) and a 3-D one (a ball of 2,148 particles, five snapshots),
# each with the arrays of its dimension named (check_xdmf.py --dim)
PV_READERS = XDMFReader Xdmf3ReaderS Xdmf3ReaderT
deps-paraview:
	@if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	command -v pvbatch >/dev/null || { $$SUDO apt-get update && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y paraview python3-h5py python3-numpy; }
check-paraview: $(BIN) deps-paraview
	@rm -rf build/check-paraview
	./$(BIN) run scenarios/cylinder_bounce.lua --set friction=0.1 --out build/check-paraview --quiet
	@for r in $(PV_READERS); do \
	  pvbatch tests/tools/check_xdmf.py build/check-paraview/particles.xmf \
	    $$(for f in build/check-paraview/particles_*.h5; do printf '208 '; done) --reader $$r --dim 2 || exit 1; \
	done
	./$(BIN) run scenarios/sphere_bounce.lua --set t_end=2 --out build/check-paraview/d3 --quiet
	@for r in $(PV_READERS); do \
	  pvbatch tests/tools/check_xdmf.py build/check-paraview/d3/particles.xmf \
	    $$(for f in build/check-paraview/d3/particles_*.h5; do printf '2148 '; done) --reader $$r --dim 3 || exit 1; \
	done

# the granular shear cell (docs/shear.md) at the report's resolution, both
# scenes and both bond strengths, on the scenes' linear hats and on the
# default shape (B-splines), in the background (a run's options: + for a
# space):
#   make shear; tail -f out/shear.log
SHEAR_RUNS = shear_dry:scenarios/shear_dry.lua: \
             shear_binder:scenarios/shear_binder.lua: \
             shear_binder_bond0:scenarios/shear_binder.lua:--set=bond=0 \
             bspline2/shear_dry:scenarios/shear_dry.lua:--set=shape=bspline2 \
             bspline2/shear_binder:scenarios/shear_binder.lua:--set=shape=bspline2 \
             bspline2/shear_binder_bond0:scenarios/shear_binder.lua:--set=shape=bspline2+--set=bond=0
# hot-spot figures (docs/hotspots.md): the sliding block, the shear cell
# with binder at 100 cells with heat, and a small PBX bed (0.24 mm,
# grains at 0.35 of the default sizes, 3 cells across the smallest)
# sheared to 50 % at 1e6/s with heat; figures into docs/figures/hotspots/
HOT_PBX = --set size=0.24e-3 --set scale=0.35 --set cells=3 --set packing=0.7 --set rate=1e6 \
	--set ramp=0.01 --set images=0.1 --set strain=0.5 --set heat=true --quiet
hotspots: $(BIN)
	@mkdir -p out docs/figures/hotspots
	nohup sh -c 'D=docs/figures/hotspots; \
	  ./$(BIN) run scenarios/hotspot_slide.lua --out out/hot_slide --overwrite --quiet || exit 1; \
	  for k in 000005 000010; do ./$(BIN) render out/hot_slide/particles_$$k.h5 --by temperature \
	    --range 300,450 --domain 0,2e-3,0.3e-3,0.8e-3 --out $$D/slide_temperature_$$k.png || exit 1; done; \
	  cp out/hot_slide/hotspots_000010.csv $$D/slide_hotspots_000010.csv; cp out/hot_slide/hotspots_critical.png $$D/slide_hotspots_critical.png; \
	  ./$(BIN) run scenarios/shear_binder.lua --set heat=true --set cells=100 --out out/hot_shear_binder --overwrite --quiet || exit 1; \
	  for f in temperature_000 temperature_025 temperature_050 temperature_075 temperature_100 body_100 \
	    hotspots_strain hotspot_area_strain heat_strain; do cp out/hot_shear_binder/$$f.png $$D/binder_$$f.png; done; \
	  cp out/hot_shear_binder/heat.csv $$D/binder_heat.csv; cp out/hot_shear_binder/summary.txt $$D/binder_summary.txt; \
	  ./$(BIN) run scenarios/pbx9501.lua $(HOT_PBX) --out out/hot_pbx --overwrite || exit 1; \
	  cp out/hot_pbx/pbx_temperature_*.png out/hot_pbx/pbx_hotspot*.png out/hot_pbx/pbx_hotspots.csv \
	    out/hot_pbx/pbx_summary.txt out/hot_pbx/pbx_body_050.png $$D/; \
	  echo hotspot runs done' > out/hotspots.log 2>&1 &
	@echo "running in the background; progress in out/hotspots.log"

.PHONY: hotspots

shear: $(BIN)
	@mkdir -p out
	nohup sh -c 'for r in $(SHEAR_RUNS); do \
	  name=$${r%%:*}; rest=$${r#*:}; scene=$${rest%%:*}; opt=$${rest#*:}; \
	  ./$(BIN) run $$scene $$(echo "$$opt" | tr + " ") --out out/$$name --overwrite --quiet || exit 1; \
	  mkdir -p docs/figures/shear/$$name; \
	  cp out/$$name/*.png out/$$name/summary.txt out/$$name/locking.csv docs/figures/shear/$$name/; \
	done; echo shear runs done' > out/shear.log 2>&1 &
	@echo "running in the background; progress in out/shear.log"

.PHONY: shear

# the compile flags without the dependency files (tests compile with
# them): LAYER=core|io|render|lua|app gives that layer's include paths,
# the default is app's (every layer)
LAYER ?= app
print-cflags:
	@echo $(filter-out -MMD -MP,$(CFLAGS)) $(INC_$(LAYER))
