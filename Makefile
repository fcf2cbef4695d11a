# refray - a plain GNU Makefile.  `make` builds build/refray and the
# library a host links (build/lib: librefray.a, librefray.so, refray.pc);
# `make check` installs missing packages, builds and runs every test;
# `make demo` installs, builds and renders scenes/demo.scene.
#
# Knobs (command line or config.mk):
#   PNG=0 EXR=0     build without libpng / OpenEXR (PFM and PPM output only)
#   JSON=0          build without jansson (no JSON scenes, kit manifests)
#   SANITIZE=1      -fsanitize=address,undefined (own build directory)
#   LONG_DOUBLE=1   the tracer's `real` is long double (own build directory;
#                   `make` copies that refray to $(BUILD)/refray-ld for
#                   `refray stability`, spec/numerics.md, and `make install`
#                   installs it as $(PREFIX)/libexec/refray/refray-ld)
#   M32=1           a 32-bit build (gcc -m32 and Debian's i386 packages, which
#                   make deps installs); implies EXR=0 (see below)
#   CC=clang        clang instead of gcc (make deps installs it)
#   LTO=0           no link-time optimisation of build/refray (on by default
#                   with gcc outside SANITIZE=1; see below)
#   make pgo        an opt-in profile-guided build in build/variant-pgo*
#   VALGRIND=1      run the test suite under valgrind memcheck
#   V=1             show full commands
#   PREFIX, DESTDIR for `make install`

-include config.mk

PREFIX    ?= /usr/local
PNG       ?= 1
EXR       ?= 1
JSON      ?= 1
SANITIZE  ?= 0
LONG_DOUBLE ?= 0
M32       ?= 0
VALGRIND  ?= 0
V         ?= 0

# The 32-bit build.  Debian's i386 OpenEXR development package cannot be
# installed next to the amd64 one (installing it removes the other), so a
# 32-bit build goes without EXR; libpng, jansson and Check have i386
# packages that coexist.  pkg-config then reads the i386 modules only.
ifeq ($(M32),1)
override EXR := 0
export PKG_CONFIG_LIBDIR := /usr/lib/i386-linux-gnu/pkgconfig:/usr/share/pkgconfig
endif

# Each non-default configuration builds into its own directory so objects of
# different flag sets never mix.
VARIANT := $(if $(filter 1,$(PGO)),-pgo)$(if $(filter 1,$(M32)),-m32)$(if $(findstring clang,$(CC)),-clang)$(if $(filter 1,$(SANITIZE)),-san)$(if $(filter 1,$(LONG_DOUBLE)),-ld)$(if $(filter 0,$(PNG)),-nopng)$(if $(filter 0,$(EXR)),-noexr)$(if $(filter 0,$(JSON)),-nojson)
BUILD   ?= build$(if $(VARIANT),/variant$(VARIANT))
GEN     := $(BUILD)/gen

CC      ?= cc
CFLAGS  ?= -O2 -g
# Doubles in SSE2 registers, not in the x87's 80-bit ones, so that double
# arithmetic rounds as it does on x86-64 (the tests compare bits).
ifeq ($(M32),1)
override CFLAGS += -m32 -msse2 -mfpmath=sse
override LDFLAGS += -m32
endif
# a*b + c rounds twice, as the source reads it and as the proofs (spec/proofs.md)
# and the bit-exact tests assume: no fused multiply-add whatever the compiler's
# default (clang fuses within an expression where the target has FMA).
override CFLAGS += -ffp-contract=off
# The tests read the floating-point flags (no overflow, no invalid operation
# on the far and stiff cases): gcc keeps them by default (-ftrapping-math),
# clang speculates both arms of a select and pushes a product through it
# unless told the flags matter.
ifneq ($(findstring clang,$(CC)),)
override CFLAGS += -ffp-exception-behavior=maytrap
endif
WARN    := -std=c99 -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
           -Wmissing-prototypes -Wwrite-strings -Werror
# flex and bison output is not ours: it gets C99 without -pedantic/-Werror
# and with the warnings their skeletons are known to trip switched off.
GEN_WARN := -std=c99 -Wall -Wno-unused-function -Wno-unused-parameter \
            -Wno-sign-compare -Wno-unused-but-set-variable
CPPFLAGS += -D_POSIX_C_SOURCE=200809L -Isrc -Iinclude -I$(GEN) -MMD -MP
LDLIBS  += -lm

# The long double build (src/base/vec.h): -Wno-error=format until every printf of
# a vec3 component casts it to double (src/scene/validate.c, src/export/export_pov.c).
ifeq ($(LONG_DOUBLE),1)
CPPFLAGS += -DREFRAY_LONG_DOUBLE
CFLAGS  += -Wno-error=format
endif

ifeq ($(SANITIZE),1)
CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
endif

# Link-time optimisation of the refray program (spec/performance.md, sixth
# round: the hot path crosses trace.c, shade.c, intersect.c, bvh*.c, whose
# calls LTO inlines).  gcc only: the library's and the program's objects are
# fat (LTO bytecode and ordinary code), refray is linked with -flto and
# CFLAGS (so -ffp-contract=off and M32's -mfpmath=sse hold when the code is
# generated at link time), and every other link, the public libraries' too,
# takes the ordinary code (-fno-lto; the static library's bytecode sections
# are removed).  Off for clang (clang 14 has no fat objects) and under the
# sanitizers; LTO=0 turns it off.
ifeq ($(if $(findstring clang,$(CC)),1,$(SANITIZE)),0)
LTO ?= 1
else
LTO ?= 0
endif
ifeq ($(LTO),1)
LTO_CFLAGS := -flto -ffat-lto-objects
LTO_LINK   := -flto=auto
override LDFLAGS += -fno-lto
endif

# Profile-guided optimisation, opt-in (spec/performance.md, sixth round):
# `make pgo` builds an instrumented refray in $(BUILD) (PGO=1 gives the
# directory its own name), renders PGO_TRAIN with it, then builds everything
# again there with the profile.  Trained on scenes outside make bench-pov's
# set.  Both stages share the directory: gcc names a profile after its object.
PGO ?= 0
ifeq ($(PGO),1)
PGO_PROFILE = $(abspath $(BUILD))/pgo-profile
ifeq ($(PGO_STAGE),gen)
override CFLAGS += -fprofile-generate=$(PGO_PROFILE) -fprofile-update=single
override LDFLAGS += -fprofile-generate=$(PGO_PROFILE)
else
override CFLAGS += -fprofile-use=$(PGO_PROFILE) -Wno-missing-profile
endif
endif
PGO_TRAIN ?= $(wildcard scenes/stress/*.scene scenes/analytic/*.scene)

# pkg-config is read lazily (=, not :=): on a fresh machine the packages are
# installed by `deps` in the same command, after this file was parsed.
ifeq ($(PNG),1)
CPPFLAGS += -DREFRAY_HAVE_PNG=1
PNG_CFLAGS = $(shell pkg-config --cflags libpng)
PNG_LIBS   = $(shell pkg-config --libs libpng)
endif
ifeq ($(EXR),1)
CPPFLAGS += -DREFRAY_HAVE_EXR=1
# OpenEXR's headers do not pass -pedantic -Werror: include them as system headers.
EXR_CFLAGS = $(patsubst -I%,-isystem %,$(shell pkg-config --cflags OpenEXR))
EXR_LIBS   = -lOpenEXRCore
endif
ifeq ($(JSON),1)
CPPFLAGS += -DREFRAY_HAVE_JSON=1
JSON_CFLAGS = $(shell pkg-config --cflags jansson)
JSON_LIBS   = $(shell pkg-config --libs jansson)
endif
CHECK_CFLAGS = $(shell pkg-config --cflags check)
# The tests compute some references in __float128 (libquadmath, part of gcc).
# clang has the type but not gcc's quadmath.h: it is found after clang's
# own headers in gcc's.
CHECK_LIBS   = $(shell pkg-config --libs check) -lquadmath
ifneq ($(findstring clang,$(CC)),)
CHECK_CFLAGS += -idirafter $(shell gcc -print-file-name=include)
endif

ifeq ($(V),1)
Q :=
else
Q := @
endif

DRIVER_SRCS := $(wildcard src/cli/*.c)
JSON_SRCS   := src/scene/json_read.c src/scene/load_json.c src/scene/load_json_mesh.c src/scene/load_json_derived.c \
               src/export/export_json_doc.c src/export/export_json_conv.c src/export/export_json_mesh.c \
               src/export/export_json_print.c src/export/export_json_build.c
OPTIONAL_SRCS := $(if $(filter 1,$(PNG)),,src/image/image_png.c) $(if $(filter 1,$(EXR)),,src/image/image_exr.c) \
                 $(if $(filter 1,$(JSON)),,$(JSON_SRCS))
LIB_SRCS    := $(filter-out $(DRIVER_SRCS) $(OPTIONAL_SRCS),$(wildcard src/*/*.c))
TEST_SRCS   := $(wildcard tests/*.c)
GEN_SRCS    := $(GEN)/scene.tab.c $(GEN)/scene.lex.c
GEN_HDRS    := $(GEN)/scene.tab.h $(GEN)/scene.lex.h

LIB_OBJS    := $(LIB_SRCS:%.c=$(BUILD)/obj/%.o) $(GEN_SRCS:$(GEN)/%.c=$(BUILD)/obj/gen/%.o)
DRIVER_OBJS := $(DRIVER_SRCS:%.c=$(BUILD)/obj/%.o)
TEST_OBJS   := $(TEST_SRCS:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/tests/difftest/gen.o

REFRAY   := $(BUILD)/refray
REFRAY_LD := $(BUILD)/refray-ld
# The program and the tests link the internal archive (every symbol); a
# host links the public library, which exports rf_ symbols only.
LIBRARY  := $(BUILD)/librefray-internal.a
TESTBIN  := $(BUILD)/check_refray
# The fixture generators (tests/gen/; their rule is below): defined before
# the test rule, whose prerequisites are expanded where it is read.
GEN_TOOLS := gen_sphere_meshes gen_ply_corpus gen_stress gen_big_mesh
GEN_BINS  := $(GEN_TOOLS:%=$(BUILD)/%)

# The public library (see its rules below).
RF_VERSION  := $(shell sed -n 's/^\#define RF_VERSION_STRING "\(.*\)"/\1/p' include/refray.h)
RF_ABI      := $(shell sed -n 's/^\#define RF_ABI_VERSION \([0-9]*\)/\1/p' include/refray.h)
LIB_CFLAGS  := -fPIC -fvisibility=hidden -DRF_BUILDING_LIBRARY
PUBLIC_LAYERS := base image lang scene render io api
# The io layer's process runner, worker pool, file writer and tile files
# serve the program only (kit, conform, render --jobs, merge): a host's
# library neither starts processes nor removes directories.
PUBLIC_OMIT := $(BUILD)/obj/src/io/proc.o $(BUILD)/obj/src/io/filewrite.o $(BUILD)/obj/src/io/pool.o \
               $(BUILD)/obj/src/io/tile_file.o
PUBLIC_OBJS := $(filter-out $(PUBLIC_OMIT),$(filter $(addprefix $(BUILD)/obj/src/,$(addsuffix /%,$(PUBLIC_LAYERS)))                  $(BUILD)/obj/gen/%,$(LIB_OBJS)))
PUBLIC_A    := $(BUILD)/lib/librefray.a
PUBLIC_SO   := $(BUILD)/lib/librefray.so.$(RF_VERSION)
PUBLIC_LIBS := $(PUBLIC_A) $(PUBLIC_SO)
$(LIB_OBJS): OBJ_CFLAGS += $(LIB_CFLAGS)
$(LIB_OBJS) $(DRIVER_OBJS): OBJ_CFLAGS += $(LTO_CFLAGS)

# Objects depend on the flags they are compiled with: a build directory
# made with other flags (say, before the library's -fPIC) is rebuilt.
FLAGS_STAMP := $(BUILD)/obj/flags
FLAGS_NOW   := $(CC) $(CPPFLAGS) $(CFLAGS) $(LIB_CFLAGS) $(LTO_CFLAGS)
ALL_LIBS  = $(JSON_LIBS) $(EXR_LIBS) $(PNG_LIBS) $(LDLIBS)
# The public library reads JSON scenes with jansson (src/scene/load_json*.c).
PUBLIC_LINK_LIBS = $(JSON_LIBS) $(EXR_LIBS) $(PNG_LIBS) $(LDLIBS)

# python3-jsonschema: the schema test of the JSON scene format (tests/json_schema.sh).
# parallel: GNU parallel, for the test of the recipe in spec/scaling.md.
# locales: the sources localedef makes a comma-decimal locale from
# (tests/embed/run.sh, [EMBED-LOCALE-1]).
DEBS := flex bison check pkg-config parallel locales $(if $(filter 1,$(PNG)),libpng-dev) \
        $(if $(filter 1,$(EXR)),libopenexr-dev) $(if $(filter 1,$(JSON)),libjansson-dev python3-jsonschema) \
        $(if $(findstring clang,$(CC)),clang)
ifeq ($(M32),1)
DEBS += gcc-multilib check:i386 $(if $(filter 1,$(PNG)),libpng-dev:i386) $(if $(filter 1,$(JSON)),libjansson-dev:i386)
endif

.PHONY: all deps check pgo check-ssh check-slurm scaling-figures test embed memory arena-min demo bench bench-pov precision terminator fixtures refray-ld report kit crosscheck mitsuba-venv difftest fuzz fuzz-run clean install uninstall solo
.DEFAULT_GOAL := all

all: $(REFRAY) $(REFRAY_LD) $(LIBRARY) $(PUBLIC_LIBS) $(BUILD)/refray.pc

# Installs only what is missing; as root with apt-get, otherwise with sudo.
deps:
	$(Q)if [ "$(M32)" = 1 ] && ! dpkg --print-foreign-architectures | grep -qx i386; then \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; $$SUDO dpkg --add-architecture i386; fi
	$(Q)missing=""; for p in $(DEBS); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' \
	    || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  echo "deps: installing$$missing"; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null; \
	fi

# `make check` and `make demo` each work alone on a fresh machine: packages
# first, then a recursive make that reads pkg-config afresh.
check: deps
	$(Q)$(MAKE) --no-print-directory test

demo: deps
	$(Q)$(MAKE) --no-print-directory all
	$(REFRAY) render scenes/demo.scene -o demo.png

# The recipes of spec/scaling.md tried for real on this machine, each in a
# temporary directory of its own (tests/scaling/): GNU parallel through a
# private sshd on 127.0.0.1, and a one-node Slurm with its own MUNGE daemon
# (root only).  Not part of `make check`: they install servers.
SCALING_DEBS_ssh := openssh-server openssh-client rsync parallel
SCALING_DEBS_slurm := slurm-wlm munge
check-ssh check-slurm: deps
	$(Q)missing=""; for p in $(SCALING_DEBS_ssh) $(if $(filter check-slurm,$@),$(SCALING_DEBS_slurm)); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  echo "$@: installing$$missing"; $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null; fi
	$(Q)$(MAKE) --no-print-directory $(REFRAY)
	$(Q)sh tests/scaling/$(if $(filter check-ssh,$@),ssh_localhost,slurm_local).sh $(REFRAY)

# Figures, not tests (spec/scaling.md): --jobs 1 against --jobs N, GNU
# parallel over tiles, the merge alone, a checkpointed render killed and
# resumed, each output compared with --jobs 1's bytes.  SCALING_SIZE=WxH,
# SCALING_JOBS="2 4", SCALING_OPTS="--samples 1" for other runs.  Times
# come from GNU time (Debian's time, installed if missing).
SCALING_SIZE ?= 1920x1080
SCALING_JOBS ?= 2 4
SCALING_OPTS ?=
scaling-figures: deps
	$(Q)[ -x /usr/bin/time ] || { if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  echo "scaling-figures: installing time"; $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq time >/dev/null; }
	$(Q)$(MAKE) --no-print-directory $(REFRAY)
	$(Q)SIZE=$(SCALING_SIZE) JOBS="$(SCALING_JOBS)" sh tests/scaling/figures.sh $(REFRAY) $(SCALING_OPTS)

# Leak kinds are listed in a variable: a literal comma would split $(if ...).
LEAK_KINDS := definite,indirect,possible
BENCH := $(BUILD)/bench
BENCH_SCENES ?= scenes/bench/grid1k.scene scenes/bench/grid10k.scene scenes/bench/grid100k.scene scenes/demo.scene
BENCH_RUNS ?= 5
BENCH_WIDTH ?= 320

# `make pgo` (above): the directory PGO=1 builds in, or BUILD when given.
PGO_BUILD = $(if $(filter command line,$(origin BUILD))$(filter 1,$(PGO)),$(BUILD),build/variant-pgo$(VARIANT))
pgo:
	$(Q)rm -rf $(PGO_BUILD)/pgo-profile
	$(Q)$(MAKE) --no-print-directory PGO=1 PGO_STAGE=gen BUILD=$(PGO_BUILD) $(PGO_BUILD)/refray
	$(Q)for s in $(PGO_TRAIN); do $(PGO_BUILD)/refray render $$s -o $(PGO_BUILD)/pgo-train.pfm -q \
	  --width 64 --height 48 2>/dev/null; done; true
	$(Q)$(MAKE) --no-print-directory PGO=1 BUILD=$(PGO_BUILD) all

# Figures, not tests: rays per second and how they fall with scene size.
bench: $(BENCH)
	$(BENCH) -r $(BENCH_RUNS) -w $(BENCH_WIDTH) $(BENCH_SCENES)

# Figures, not tests: error against light samples and run time over the
# analytic suite (tests/report.sh, spec/verify.md): PNG and SVG plots, TSVs
# and summary.md under build/report/.  Installs gnuplot-nox if missing.
REPORT_DIR := build/report
# $(call need_program,PROGRAM,DEBIAN_PACKAGE): installs the package when
# PROGRAM is missing (as root with apt-get, otherwise with sudo).
need_program = command -v $(1) >/dev/null 2>&1 || { if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  echo "installing $(2)"; $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $(2) >/dev/null; }
report: deps
	$(Q)$(call need_program,gnuplot,gnuplot-nox)
	$(Q)$(MAKE) --no-print-directory $(REFRAY)
	$(Q)sh tests/report.sh $(REFRAY) $(REPORT_DIR) scenes/analytic/*.scene

# Figures, not tests (spec/embedding.md): the bytes the library allocates
# per sphere, mesh triangle and light sample, and for MEMORY_SCENES, counted
# through the allocator hook; and the smallest fixed arena that renders
# ARENA_SCENE (tests/embed/render_string.c's arena, found by bisection).
MEMORY := $(BUILD)/memory
MEMORY_SCENES ?= scenes/demo.scene scenes/bench/grid100k.scene
ARENA_SCENE ?= scenes/demo.scene
memory: $(MEMORY)
	$(MEMORY) $(MEMORY_SCENES)

$(MEMORY): $(BUILD)/obj/tests/bench/memory.o $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $< $(LIBRARY) $(ALL_LIBS)

arena-min: embed
	$(Q)sh tests/bench/arena_min.sh $(BUILD)/embed/render_string-static $(ARENA_SCENE)

# Figures, not tests (spec/performance.md): CPU time of refray against
# POV-Ray 3.7 (+WT1 -A) on the same scenes through `refray export --to pov`,
# median of BENCH_POV_RUNS paired runs, and the two images compared by make
# difftest's rule.  SCENE@WxHxK overrides the size and pixel grid.
# Installs povray when missing; files of the run in build/bench-pov/.
BENCH_POV := $(BUILD)/benchpov
BENCH_POV_RUNS ?= 3
# The 100 000-triangle torus is written by gen_big_mesh into build/bench-pov/.
BENCH_POV_SCENES ?= scenes/bench/grid1k.scene@1600x1200x1 scenes/bench/grid100k.scene@1600x1200x1 \
  scenes/demo.scene@240x150x2 scenes/cornell.scene@160x160x2 scenes/bench/room.scene@160x160x2 \
  scenes/mesh.scene@240x160x2 build/bench-pov/torus/torus.scene@640x480x1 scenes/nested_glass.scene@240x160x2

bench-pov: deps
	$(if $(filter 0,$(PNG)),$(error make bench-pov reads POV-Ray's pictures as PNG: it needs PNG=1))
	$(Q)$(call need_program,povray,povray)
	$(Q)$(MAKE) --no-print-directory $(BENCH_POV) $(REFRAY) $(BUILD)/gen_big_mesh
	$(Q)mkdir -p build/bench-pov && $(BUILD)/gen_big_mesh build/bench-pov/torus --u 250 --v 200
	$(BENCH_POV) -r $(BENCH_POV_RUNS) -o build/bench-pov --refray $(REFRAY) $(BENCH_POV_SCENES)

$(BENCH_POV): $(BUILD)/obj/tests/bench/benchpov.o $(BUILD)/obj/tests/difftest/run.o $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $(BUILD)/obj/tests/bench/benchpov.o $(BUILD)/obj/tests/difftest/run.o \
	  $(LIBRARY) $(ALL_LIBS)

$(BENCH): $(BUILD)/obj/tests/bench/bench.o $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $< $(LIBRARY) $(ALL_LIBS)

# Figures, not tests: the worst error of every shading formula and hit test
# against __float128 (gcc's libquadmath), and the robust methods against the
# naive ones on scenes/stress (spec/numerics.md).  PRECISION_ARGS="-n 10000"
# for a quick run.
PRECISION := $(BUILD)/precision
precision: $(PRECISION)
	$(PRECISION) $(PRECISION_ARGS)

$(PRECISION): $(BUILD)/obj/tests/precision/precision.o $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $< $(LIBRARY) $(ALL_LIBS) -lquadmath

# Figures, not tests: the shadow terminator of smooth sphere meshes against
# the exact Lambert image, before and after the lifted shadow-ray start
# (spec/shading.md).  TERMINATOR_ARGS="-o DIR" also writes the renders.
TERMINATOR := $(BUILD)/terminator
terminator: $(TERMINATOR)
	$(TERMINATOR) $(TERMINATOR_ARGS)

$(TERMINATOR): $(BUILD)/obj/tests/terminator/terminator.o $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $< $(LIBRARY) $(ALL_LIBS)

# The long double twin of refray for `refray stability` (spec/numerics.md),
# built by a recursive make in its own directory and copied next to refray;
# part of `all` and of `make install`, so `refray verify --stability`
# works after a plain `make` and after an install.  Without LTO: the twin is
# not the one timed, and its LTO link would cost make check another 15 s of CPU.
refray-ld: $(REFRAY_LD)
$(REFRAY_LD): FORCE
	$(Q)$(MAKE) --no-print-directory LONG_DOUBLE=1 LTO=0 BUILD=$(BUILD)/ld $(BUILD)/ld/refray
	$(Q)cp $(BUILD)/ld/refray $@

# The conformance kit (spec/conformance.md): every analytic scene with its
# exact image, mask, .scene and .pov (and .json), one manifest.json and a
# README.md, in build/kit/ and as build/refray-kit-VERSION.tar.gz (its top
# directory refray-kit-VERSION/; the archive is the same bytes for the same
# kit).  KIT_SCENES=... for fewer scenes.
KIT_DIR     := build/kit
KIT_TARBALL  = build/refray-kit-$(RF_VERSION).tar.gz
KIT_SCENES  ?= $(sort $(wildcard scenes/analytic/*.scene))

kit: $(REFRAY)
	$(Q)$(REFRAY) kit -q -o $(KIT_DIR) $(KIT_SCENES)
	$(Q)cp tests/conform/kit_check.c $(KIT_DIR)/kit_check.c
	$(Q)tar -C $(dir $(KIT_DIR)) --sort=name --mtime=@0 --owner=0 --group=0 --numeric-owner \
	  --transform 's,^kit,refray-kit-$(RF_VERSION),' -cf - kit | gzip -n -9 > $(KIT_TARBALL).tmp && \
	  mv $(KIT_TARBALL).tmp $(KIT_TARBALL)
	@echo "kit: $(KIT_DIR)/ and $(KIT_TARBALL)"

# Other renderers measured by the oracle through the kit (spec/crosscheck.md,
# tests/crosscheck.sh): installs POV-Ray (Debian povray) and Mitsuba 3 (the
# venv below) when missing, builds the kit, runs `refray conform` with each
# renderer's command line, prints
# the tables and writes them into spec/crosscheck.md (CROSSCHECK_UPDATE=0:
# print only); every file of the run is kept in build/crosscheck/.
# CROSSCHECK_ONLY="NAME ..." runs only those scenes.
CROSSCHECK_UPDATE ?= 1
CROSSCHECK_ONLY ?=

crosscheck: kit mitsuba-venv
	$(Q)REFRAY=$(REFRAY) KIT=$(KIT_DIR) OUT=build/crosscheck UPDATE_SPEC=$(CROSSCHECK_UPDATE) \
	  ONLY="$(CROSSCHECK_ONLY)" MITSUBA_PYTHON=$(MITSUBA_VENV)/bin/python sh tests/crosscheck.sh

# Mitsuba 3 for `make crosscheck` (tests/conform/mitsuba3.py, spec/crosscheck.md
# section 5): a virtual environment under build/ with the versions of the
# recorded table, from PyPI, made only when missing (`make check` never needs
# it).  Debian's python3 makes one only with python3-venv, installed here
# when that is what fails.
MITSUBA_VENV    := build/mitsuba-venv
MITSUBA_PYTHON3 ?= /usr/bin/python3
MITSUBA_PIP     := mitsuba==3.9.1 drjit==1.5.0 numpy==2.4.6

mitsuba-venv: $(MITSUBA_VENV)/installed
$(MITSUBA_VENV)/installed:
	$(Q)rm -rf $(MITSUBA_VENV); $(MITSUBA_PYTHON3) -m venv $(MITSUBA_VENV) >/dev/null 2>&1 || { \
	  rm -rf $(MITSUBA_VENV); echo "mitsuba-venv: installing python3-venv"; \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq python3-venv >/dev/null && \
	  $(MITSUBA_PYTHON3) -m venv $(MITSUBA_VENV); }
	@echo "mitsuba-venv: pip install $(MITSUBA_PIP)"
	$(Q)$(MITSUBA_VENV)/bin/pip install -q $(MITSUBA_PIP)
	$(Q)echo "$(MITSUBA_PIP)" > $@

# Differential testing against POV-Ray 3.7 (spec/crosscheck.md, section 6):
# the minimal scenes of past findings (tests/difftest/regress/), then N
# random scenes of seed SEED (tests/difftest/gen.c, only what the export
# maps exactly), rendered by refray and by POV-Ray and compared pixel by
# pixel; each scene with an interior disagreement is shrunk and written to
# $(DIFFTEST_OUT), and the run fails.  Installs povray when missing.
# `make difftest N=1000` is a long campaign; .ci/run runs a short one.
DIFFTEST := $(BUILD)/refray-difftest
DIFFTEST_OBJS := $(addprefix $(BUILD)/obj/tests/difftest/,difftest.o run.o shrink.o gen.o)
DIFFTEST_OUT ?= build/difftest
N ?= 40
SEED ?= 1

difftest: deps
	$(if $(filter 0,$(PNG)),$(error make difftest reads POV-Ray's pictures as PNG: it needs PNG=1))
	$(Q)$(call need_program,povray,povray)
	$(Q)$(MAKE) --no-print-directory $(DIFFTEST)
	$(DIFFTEST) -n $(N) --seed $(SEED) -o $(DIFFTEST_OUT) --obj-dir tests/obj --regress tests/difftest/regress

$(DIFFTEST): $(DIFFTEST_OBJS) $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $(DIFFTEST_OBJS) $(LIBRARY) $(ALL_LIBS)

# Fuzzing with libFuzzer (clang, Debian clang + libclang-rt-14-dev): the
# front end (fuzz_scene), the OBJ reader (fuzz_obj), the PLY reader
# (fuzz_ply) and the image readers (fuzz_image).  `make fuzz
# FUZZ_SECONDS=600 [FUZZ_TARGETS="obj ply"]`: builds
# everything with clang and the fuzzer's instrumentation in build/fuzz,
# seeds each target's corpus (build/fuzz/corpus-TARGET) from the test files
# of its kind, and runs each in turn for FUZZ_SECONDS.  Crashes are written
# to build/fuzz/ as crash-*; each one becomes a file under
# tests/fuzz-regressions/ (a mesh file with a .scene that reads it).  The
# image target is seeded with tiny images refray renders in each format.
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 1
FUZZ_TARGETS ?= scene obj ply image
FUZZ_DIR := build/fuzz
FUZZ_DEBS := clang libclang-rt-14-dev
FUZZ_SEEDS_scene = scenes/*.scene scenes/*/*.scene tests/bad/*.scene tests/bad/*.json tests/fuzz-regressions/*.scene
FUZZ_SEEDS_obj = tests/obj/*.obj tests/ply/*.obj scenes/*/*.obj tests/bad/inc/*.obj
FUZZ_SEEDS_ply = tests/ply/*.ply tests/bad/inc/*.ply

fuzz:
	$(Q)$(MAKE) --no-print-directory deps
	$(Q)missing=""; for p in $(FUZZ_DEBS); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | \
	  grep -q '^install ok installed' || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then apt-get install -y -qq $$missing >/dev/null; fi
ifneq ($(filter image,$(FUZZ_TARGETS)),)
	$(Q)$(MAKE) --no-print-directory $(REFRAY) && mkdir -p $(FUZZ_DIR)/corpus-image
	$(Q)n=0; for f in png exr pfm ppm; do \
	  $(REFRAY) render scenes/analytic/ambient_only.scene --width 4 --height 3 -q -o $(FUZZ_DIR)/seed.$$f \
	    2>/dev/null && { printf "\\00$$n"; cat $(FUZZ_DIR)/seed.$$f; } > $(FUZZ_DIR)/corpus-image/seed-$$f; \
	  n=$$((n + 1)); done
endif
	$(Q)$(MAKE) --no-print-directory BUILD=$(FUZZ_DIR) CC=clang SANITIZE=0 \
	  CFLAGS="-g -O1 -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" fuzz-run

fuzz-run: $(LIBRARY) $(FUZZ_TARGETS:%=$(BUILD)/obj/tests/fuzz/fuzz_%.o) $(FUZZ_TARGETS:%=$(BUILD)/%.dict)
	$(Q)for t in $(FUZZ_TARGETS); do \
	  $(CC) $(CFLAGS) -fsanitize=fuzzer -o $(BUILD)/fuzz_$$t $(BUILD)/obj/tests/fuzz/fuzz_$$t.o $(LIBRARY) $(ALL_LIBS) || exit 1; \
	done
	$(Q)mkdir -p $(FUZZ_TARGETS:%=$(BUILD)/corpus-%)
	$(Q)$(foreach t,$(FUZZ_TARGETS),cp -n $(FUZZ_SEEDS_$(t)) $(BUILD)/corpus-$(t)/ 2>/dev/null;) true
	$(Q)for t in $(FUZZ_TARGETS); do echo "fuzz: $$t for $(FUZZ_SECONDS) s"; \
	  (cd $(BUILD) && ./fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -jobs=$(FUZZ_JOBS) -workers=$(FUZZ_JOBS) \
	    -dict=$$t.dict -max_len=8192 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 corpus-$$t) || exit 1; \
	done

$(BUILD)/scene.dict: src/lang/keywords.c
	$(Q){ sed -n 's/^ *{"\([A-Za-z_0-9]*\)", KWC.*/"\1"/p' src/lang/keywords.c; \
	  printf '%s\n' '"{"' '"}"' '"["' '"]"' '"("' '")"' '","' '"="' '".."' '"#"' '"\\""' \
	    '"1e400"' '"-0"' '"pi"' '"linear"' '"inverse_square"' '"none"'; } > $@
$(BUILD)/%.dict: tests/fuzz/%.dict
	$(Q)cp $< $@

VALGRIND_CMD := $(if $(filter 1,$(VALGRIND)),valgrind -q --error-exitcode=99 --leak-check=full \
                --show-leak-kinds=$(LEAK_KINDS) --errors-for-leak-kinds=$(LEAK_KINDS) \
                --trace-children=yes)
# The 32-bit build runs the heaviest cases about 2.5 times slower.
TEST_TIMEOUT := $(if $(filter 1,$(VALGRIND)),40,$(if $(filter 1,$(SANITIZE)),8,$(if $(filter 1,$(M32)),4,1)))

# The kit's stand-alone checker (tests/conform/kit_check.c): one C99 file that
# needs no library, built here only to be tested against `refray compare`.
KIT_CHECK := $(BUILD)/kit_check
# With JSON, the exports are checked against spec/scene.schema.json by a
# validator in Python (tests/json_schema.sh) and the Mitsuba adapter's
# decisions by its --dry-run, without Mitsuba (tests/mitsuba_adapter.sh).
# The bench-pov driver is built (not run) in the default configuration, so
# a change of the difftest code it shares cannot break `make bench-pov` unseen.
#
# Each suite runs in a check_refray process of its own, one make job each,
# so `make -j2 check` keeps two cores busy (make checks one suite at a time
# without -j); -k runs every suite whatever fails, -Otarget prints each
# suite's report whole.  The suites are those of the runner (suites.h, the
# same sed), the slowest first (SUITES_FIRST, measured by their time under
# SANITIZE=1) so that none starts last and runs alone; a name there that is
# no suite fails the run (check_refray refuses it).
SUITE_SED    := s/^Suite \*suite_\([a-z0-9_]*\)(void).*/\1/p
SUITES       := $(shell sed -n '$(SUITE_SED)' $(TEST_SRCS) | LC_ALL=C sort)
SUITES_FIRST := json scaling reliability stability faults oracle_area json_memory shortcuts verify badscenes random_scenes kit
# The suites of the JSON front end alone have no test in a build without
# it (JSON=0: check_refray refuses a suite where no test ran); the json
# suite checks there that its absence is reported.
JSON_ONLY_SUITES := json_memory json_derived json_samples
RUN_SUITES   := $(if $(filter 1,$(JSON)),$(SUITES),$(filter-out $(JSON_ONLY_SUITES),$(SUITES)))
RUN_FIRST    := $(if $(filter 1,$(JSON)),$(SUITES_FIRST),$(filter-out $(JSON_ONLY_SUITES),$(SUITES_FIRST)))
SUITE_RUNS   := $(addprefix test-suite-,$(RUN_FIRST) $(filter-out $(RUN_FIRST),$(RUN_SUITES)))
TEST_ENV = REFRAY_BIN=$(REFRAY) KIT_CHECK_BIN=$(KIT_CHECK) GEN_BIN_DIR=$(BUILD) REFRAY_TEST_VALGRIND=$(VALGRIND) \
           CK_TIMEOUT_MULTIPLIER=$(TEST_TIMEOUT)
.PHONY: test-run test-schema $(SUITE_RUNS)

test: $(TESTBIN) $(REFRAY) $(REFRAY_LD) $(KIT_CHECK) $(GEN_BINS) $(if $(VARIANT),,$(BENCH_POV))
	$(Q)$(MAKE) --no-print-directory -k -Otarget test-run
	$(Q)$(MAKE) --no-print-directory embed

test-run: $(if $(filter 1,$(JSON)),test-schema) $(SUITE_RUNS)

$(SUITE_RUNS): test-suite-%:
	$(Q)$(TEST_ENV) $(VALGRIND_CMD) $(TESTBIN) $*

test-schema:
	$(Q)sh tests/json_schema.sh $(REFRAY) $(BUILD)/json-schema && sh tests/mitsuba_adapter.sh $(REFRAY) $(BUILD)/mitsuba-dry

# The library as a host sees it: installed into $(STAGE), the two examples
# of tests/embed built with pkg-config against it and run, and the symbols
# of the installed libraries and of the core's objects checked.
STAGE        := $(BUILD)/stage
STAGE_PREFIX := $(abspath $(STAGE))$(PREFIX)
EMBED_FLAGS  := $(filter -m32 -fsanitize=%,$(CFLAGS) $(LDFLAGS))
CORE_OBJS    := $(filter $(BUILD)/obj/src/base/% $(BUILD)/obj/src/lang/% $(BUILD)/obj/src/scene/% \
                  $(BUILD)/obj/src/render/% $(BUILD)/obj/gen/%,$(LIB_OBJS))
embed: all
	$(Q)rm -rf $(STAGE) && $(MAKE) --no-print-directory install DESTDIR=$(abspath $(STAGE)) >/dev/null
	$(Q)CC="$(CC)" EXTRA="$(EMBED_FLAGS)" PKG_CONFIG_PATH="$(STAGE_PREFIX)/lib/pkgconfig$(if $(PKG_CONFIG_PATH),:$(PKG_CONFIG_PATH))" \
	  LIBDIR=$(STAGE_PREFIX)/lib OUT=$(BUILD)/embed IMAGE_EXT=$(if $(filter 1,$(PNG)),png,pfm) sh tests/embed/run.sh
	$(Q)CC="$(CC) $(EMBED_FLAGS)" DATA_CHECK=$(if $(filter 1,$(SANITIZE)),0,1) sh tests/check_symbols.sh $(STAGE_PREFIX)/lib $(RF_ABI) $(CORE_OBJS)

$(KIT_CHECK): tests/conform/kit_check.c
	@mkdir -p $(dir $@)
	@echo "  CC      $<"
	$(Q)$(CC) $(WARN) $(CFLAGS) $(LDFLAGS) -o $@ $< -lm

# The generators of committed fixtures (tests/gen/, C, no library): `make
# fixtures` writes the PLY corpus, the terminator's sphere meshes and the
# computed stress scenes again in place; tests/check_fixtures.c checks that
# they give the committed bytes.  gen_big_mesh writes the million-triangle
# torus of spec/numerics.md 2.16 where it is told.  -ffp-contract=off: every
# product rounded on its own, as in the committed files (clang would fuse
# a*b+c and change the last digit of a stress scene).
$(GEN_BINS): $(BUILD)/%: tests/gen/%.c tests/gen/gen.c tests/gen/gen.h
	@mkdir -p $(dir $@)
	@echo "  CC      $<"
	$(Q)$(CC) -D_POSIX_C_SOURCE=200809L -ffp-contract=off $(WARN) $(CFLAGS) $(LDFLAGS) -o $@ $< tests/gen/gen.c -lm

fixtures: $(GEN_BINS)
	$(Q)for g in gen_sphere_meshes gen_ply_corpus gen_stress; do $(BUILD)/$$g . || exit 1; done

$(REFRAY): $(DRIVER_OBJS) $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(if $(LTO_LINK),$(filter-out -fno-lto,$(LDFLAGS)) $(CFLAGS) $(LTO_LINK),$(LDFLAGS)) \
	  -o $@ $(DRIVER_OBJS) $(LIBRARY) $(ALL_LIBS)

$(FLAGS_STAMP): FORCE
	@mkdir -p $(dir $@)
	@echo '$(FLAGS_NOW)' | cmp -s - $@ || echo '$(FLAGS_NOW)' > $@
$(LIB_OBJS) $(DRIVER_OBJS) $(TEST_OBJS) $(DIFFTEST_OBJS): $(FLAGS_STAMP)

$(LIBRARY): $(LIB_OBJS)
	@echo "  AR      $@"
	$(Q)rm -f $@ && ar rcs $@ $^

# The public library.  Library objects are compiled position-independent
# with every symbol hidden but those marked RF_API (include/refray.h).  The
# shared library exports those alone (and says so again in its version
# script); the static one is the public layers' objects linked into one
# relocatable object whose hidden symbols are then made local, so that it
# too defines no global symbol but rf_ ones (tests/check_symbols.sh).  The
# exception: i386 code finds its own address through the compiler's
# __x86.get_pc_thunk.* functions, hidden and in COMDAT groups that every
# object of a program shares; made local, the linker would discard them.

$(PUBLIC_A): $(PUBLIC_OBJS)
	@mkdir -p $(dir $@)
	@echo "  AR      $@"
	$(Q)$(CC) $(CFLAGS) $(LDFLAGS) -r -nostdlib -o $(BUILD)/lib/refray.o $^
	$(Q)objcopy --localize-hidden --remove-section='.gnu.lto_*' --remove-section='.gnu.debuglto_*' $(BUILD)/lib/refray.o
	$(Q)objcopy $$(nm $(BUILD)/lib/refray.o | awk '$$3 ~ /^__x86\.get_pc_thunk\./ { print "--globalize-symbol=" $$3 }' | \
	  sort -u) $(BUILD)/lib/refray.o
	$(Q)rm -f $@ && ar rcs $@ $(BUILD)/lib/refray.o

$(PUBLIC_SO): $(PUBLIC_OBJS) src/api/librefray.map
	@mkdir -p $(dir $@)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS) $(LDFLAGS) -shared -Wl,-soname,librefray.so.$(RF_ABI) \
	  -Wl,--version-script=src/api/librefray.map -o $@ $(PUBLIC_OBJS) $(PUBLIC_LINK_LIBS)
	$(Q)ln -sf librefray.so.$(RF_VERSION) $(BUILD)/lib/librefray.so.$(RF_ABI)
	$(Q)ln -sf librefray.so.$(RF_ABI) $(BUILD)/lib/librefray.so

# refray.pc: relocatable (prefix found from the file's own place), with the
# build's optional libraries as private dependencies.  An optional library
# with a pkg-config module adds it to PC_REQUIRES_PRIVATE, one without
# adds its flags to PC_LIBS_PRIVATE.
PC_REQUIRES_PRIVATE := $(if $(filter 1,$(PNG)),libpng) $(if $(filter 1,$(JSON)),jansson)
PC_LIBS_PRIVATE     := $(EXR_LIBS) $(LDLIBS)
$(BUILD)/refray.pc: src/api/refray.pc.in include/refray.h Makefile
	@mkdir -p $(dir $@)
	$(Q)sed -e 's|@VERSION@|$(RF_VERSION)|' -e 's|@REQUIRES_PRIVATE@|$(strip $(PC_REQUIRES_PRIVATE))|' \
	  -e 's|@LIBS_PRIVATE@|$(strip $(PC_LIBS_PRIVATE))|' $< > $@

$(TESTBIN): $(TEST_OBJS) $(LIBRARY)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDFLAGS) -o $@ $(TEST_OBJS) $(LIBRARY) $(ALL_LIBS) $(CHECK_LIBS)

# Grouped targets (&:, GNU make 4.3): one run of bison (of flex) writes both
# files; as two plain targets, make -j2 ran it twice at once on the same files.
$(GEN)/scene.tab.c $(GEN)/scene.tab.h &: grammar/scene.y
	@mkdir -p $(GEN)
	@echo "  BISON   $<"
	$(Q)bison -Werror --defines=$(GEN)/scene.tab.h -o $(GEN)/scene.tab.c $<

$(GEN)/scene.lex.c $(GEN)/scene.lex.h &: grammar/scene.l
	@mkdir -p $(GEN)
	@echo "  FLEX    $<"
	$(Q)flex --header-file=$(GEN)/scene.lex.h -o $(GEN)/scene.lex.c $<

# The test runner lists every `Suite *suite_NAME(void)` of tests/*.c, so a
# new test file needs no edit anywhere else.
$(GEN)/suites.h: $(TEST_SRCS)
	@mkdir -p $(GEN)
	$(Q)printf 'SUITE(%s)\n' $(SUITES) > $@.tmp && mv $@.tmp $@

$(BUILD)/obj/gen/%.o: $(GEN)/%.c $(GEN_HDRS)
	@mkdir -p $(dir $@)
	@echo "  CC      $<"
	$(Q)$(CC) $(CPPFLAGS) $(GEN_WARN) $(CFLAGS) $(OBJ_CFLAGS) -c -o $@ $<

# Per-object flags go to OBJ_CFLAGS, not CFLAGS, so that a CFLAGS given on
# the command line (the fuzz build) does not drop them.
$(BUILD)/obj/src/image/image_png.o: OBJ_CFLAGS += $(PNG_CFLAGS)
$(BUILD)/obj/src/image/image_exr.o: OBJ_CFLAGS += $(EXR_CFLAGS)
$(JSON_SRCS:%.c=$(BUILD)/obj/%.o): OBJ_CFLAGS += $(JSON_CFLAGS)
$(BUILD)/obj/src/verify/manifest.o $(BUILD)/obj/src/verify/conform_report.o: OBJ_CFLAGS += $(JSON_CFLAGS)
# A suite file exports only suite_NAME(), declared by the runner itself.
$(BUILD)/obj/tests/%.o: OBJ_CFLAGS += $(CHECK_CFLAGS) -Wno-missing-prototypes
$(BUILD)/obj/tests/main.o: $(GEN)/suites.h

# The oracle registry lists every `const oracle_family oracle_NAME =` of
# src/oracle/*.c, so a new family needs no edit anywhere else.
ORACLE_SRCS := $(wildcard src/oracle/*.c)
$(GEN)/oracle_list.h: $(ORACLE_SRCS)
	@mkdir -p $(GEN)
	$(Q)sed -n 's/^const oracle_family oracle_\([a-z0-9_]*\) =.*/ORACLE_FAMILY(\1)/p' $(ORACLE_SRCS) | LC_ALL=C sort > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/src/oracle/oracle.o: $(GEN)/oracle_list.h

$(BUILD)/obj/%.o: %.c | $(if $(wildcard grammar/scene.y),$(GEN_HDRS))
	@mkdir -p $(dir $@)
	@echo "  CC      $<"
	$(Q)$(CC) $(CPPFLAGS) $(WARN) $(CFLAGS) $(OBJ_CFLAGS) -c -o $@ $<

# Development aid: a runner built from a subset of the sources, so one module
# can be tested while others are half written.  Use a BUILD of your own:
#   make solo BUILD=build/dev-shade SOLO_SRCS="src/render/shade.c" SOLO_TESTS="tests/check_shade.c"
# (add SOLO_PARSER=1 to link the generated scanner and parser)
SOLO_OBJS = $(SOLO_SRCS:%.c=$(BUILD)/obj/%.o) $(SOLO_TESTS:%.c=$(BUILD)/obj/%.o) \
            $(if $(SOLO_PARSER),$(GEN_SRCS:$(GEN)/%.c=$(BUILD)/obj/gen/%.o))
solo: $(SOLO_OBJS) $(BUILD)/obj/solo_main.o
	$(Q)$(CC) $(LDFLAGS) -o $(BUILD)/solo $^ $(ALL_LIBS) $(CHECK_LIBS)
	$(Q)CK_TIMEOUT_MULTIPLIER=$(TEST_TIMEOUT) $(VALGRIND_CMD) $(BUILD)/solo

$(BUILD)/obj/solo_main.o: tests/main.c FORCE
	@mkdir -p $(GEN)
	$(Q)sed -n 's/^Suite \*suite_\([a-z0-9_]*\)(void).*/SUITE(\1)/p' $(SOLO_TESTS) > $(GEN)/solo_suites.h
	$(Q)$(CC) $(CPPFLAGS) -DSUITES_HEADER='"solo_suites.h"' $(WARN) $(CFLAGS) $(CHECK_CFLAGS) -c -o $@ $<

# make prove: Frama-C's Eva and WP on the contracts of the shading formulas,
# the hit tests, the ray spawn functions, the camera ray and the light
# samples, and Gappa's rounding bounds (spec/proofs.md, tests/prove/prove.sh);
# make prove-mutants: one deliberate bug per ensures clause
# (tests/prove/mutants.txt) makes its goal fail.  They install what they need.
PROVE_DEBS := frama-c-base why3 z3 cvc4 gappa
# WP also proves the absence of run-time errors (-wp-rte: overflow of int
# arithmetic, out-of-bounds and invalid accesses, division by zero) in the
# functions it proves; PROVE_RTE= leaves those goals out.
PROVE_RTE ?= -wp-rte
.PHONY: prove prove-mutants prove-quick prove-deps
prove-deps:
	$(Q)missing=""; for p in $(PROVE_DEBS); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | \
	  grep -q '^install ok installed' || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  echo "prove: installing$$missing"; $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null; fi

prove: prove-deps
	$(Q)PROVE_OUT=$(BUILD)/prove PROVE_RTE='$(PROVE_RTE)' bash tests/prove/prove.sh

prove-mutants: prove-deps
	$(Q)PROVE_OUT=$(BUILD)/prove PROVE_RTE='$(PROVE_RTE)' bash tests/prove/mutants.sh

# What CI runs (seconds): Gappa's bounds, Eva on the shading formulas, four
# helpers taken by their contracts, and on the rays and light samples but
# light_concentric's 11,449 boxes; make prove checks those too, and runs WP.
prove-quick: prove-deps
	$(Q)PROVE_OUT=$(BUILD)/prove bash tests/prove/prove.sh quick

.PHONY: FORCE
FORCE:

# The public header alone, both libraries and refray.pc (in lib/pkgconfig).
install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include \
	  $(DESTDIR)$(PREFIX)/libexec/refray
	install -m 755 $(REFRAY) $(DESTDIR)$(PREFIX)/bin/refray
	install -m 755 $(REFRAY_LD) $(DESTDIR)$(PREFIX)/libexec/refray/refray-ld
	install -m 644 include/refray.h $(DESTDIR)$(PREFIX)/include/refray.h
	install -m 644 $(PUBLIC_A) $(DESTDIR)$(PREFIX)/lib/librefray.a
	install -m 755 $(PUBLIC_SO) $(DESTDIR)$(PREFIX)/lib/librefray.so.$(RF_VERSION)
	ln -sf librefray.so.$(RF_VERSION) $(DESTDIR)$(PREFIX)/lib/librefray.so.$(RF_ABI)
	ln -sf librefray.so.$(RF_ABI) $(DESTDIR)$(PREFIX)/lib/librefray.so
	install -m 644 $(BUILD)/refray.pc $(DESTDIR)$(PREFIX)/lib/pkgconfig/refray.pc

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/refray $(DESTDIR)$(PREFIX)/libexec/refray/refray-ld $(DESTDIR)$(PREFIX)/include/refray.h \
	  $(DESTDIR)$(PREFIX)/lib/librefray.a $(DESTDIR)$(PREFIX)/lib/librefray.so* \
	  $(DESTDIR)$(PREFIX)/lib/pkgconfig/refray.pc

clean:
	rm -rf build demo.png

-include $(wildcard $(BUILD)/obj/*/*.d $(BUILD)/obj/*/*/*.d)
