# libmodesplit build.
#
#   make                 library (shared + static), plugins, tools
#   make check           build and run every test (README's test command)
#   make demo            run the default scene: HDF5 file + PNG frames in demo/
#                        (each time anew: --force replaces the last demo's run)
#   make bench           benchmarks: medians, spreads, machine; CSV in bench/
#   make install PREFIX=/usr/local
#   make SAN=asan check  the tests under AddressSanitizer + UBSan (build-asan/)
#   make SAN=tsan check  the tests under ThreadSanitizer (build-tsan/)
#   make NATIVE=1 bench  add -march=native (benchmarks only; results differ
#                        in the last bits from the portable build)
#
# Sources are found by wildcard: lib/<part>/*.c is the library, one
# plugins/shapes/<name>.c or plugins/shaders/<name>.c per plugin,
# tools/modesplit/*.c the tool, tools/bench/<name>.c one benchmark program
# each, tests/test_<part>.c one Check suite each.

# The version has one source, include/modesplit/core.h (MS_VERSION_STRING).
VERSION   := $(shell sed -n 's/^\#define MS_VERSION_STRING "\(.*\)"/\1/p' include/modesplit/core.h)
SOVERSION := 0
PREFIX    ?= /usr/local
DESTDIR   ?=
CC        ?= cc
CXX       ?= c++
SAN       ?=
NATIVE    ?= 0

ifeq ($(SAN),)
BUILD ?= build
else
BUILD ?= build-$(SAN)
endif

PKG_CONFIG ?= pkg-config
# Libraries the build needs (tools/deps.sh installs them). OSMesa is
# optional: without it the renderer returns MS_ERR_UNSUPPORTED.
LIB_PKGS  := jansson hdf5 libpng
HAVE_OSMESA := $(shell $(PKG_CONFIG) --exists osmesa 2>/dev/null && echo 1 || echo 0)
ifeq ($(HAVE_OSMESA),1)
LIB_PKGS  += osmesa
endif
# The renderer's second GL path: EGL (surfaceless Mesa or a
# GPU's EGL), beside or instead of OSMesa; `make HAVE_EGL=0` or
# `make HAVE_OSMESA=0` builds with one only. With OSMesa the gl* entry
# points come from libOSMesa (they dispatch through Mesa's shared glapi,
# which EGL contexts set too); without it from glvnd's libOpenGL.
HAVE_EGL := $(shell $(PKG_CONFIG) --exists egl opengl 2>/dev/null && echo 1 || echo 0)
ifeq ($(HAVE_EGL),1)
LIB_PKGS  += egl
ifeq ($(HAVE_OSMESA),0)
LIB_PKGS  += opengl
endif
endif
HAVE_GL := $(if $(filter 1,$(HAVE_OSMESA) $(HAVE_EGL)),1,0)
PKG_CFLAGS := $(shell $(PKG_CONFIG) --cflags $(LIB_PKGS) 2>/dev/null)
PKG_LIBS   := $(shell $(PKG_CONFIG) --libs $(LIB_PKGS) 2>/dev/null)
CHECK_CFLAGS := $(shell $(PKG_CONFIG) --cflags check 2>/dev/null)
CHECK_LIBS   := $(shell $(PKG_CONFIG) --libs check 2>/dev/null)

WARN      := -Wall -Wextra -Werror -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes
OPT       ?= -O2
CFLAGS    ?= $(OPT) -g
BASEFLAGS := -std=c11 $(WARN) -fopenmp-simd -fPIC -fvisibility=hidden -D_POSIX_C_SOURCE=200809L
CPPFLAGS  += -Iinclude -Ilib -MMD -MP -DMS_HAVE_OSMESA=$(HAVE_OSMESA) \
             -DMS_HAVE_EGL=$(HAVE_EGL) -DMS_HAVE_GL=$(HAVE_GL) \
             -DMS_BUILD_PLUGIN_DIR='"$(abspath $(BUILD))/plugins"'
ifeq ($(NATIVE),1)
BASEFLAGS += -march=native
endif
ifeq ($(SAN),asan)
BASEFLAGS += -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
LDSAN     := -fsanitize=address,undefined
else ifeq ($(SAN),tsan)
BASEFLAGS += -fsanitize=thread -fno-omit-frame-pointer
LDSAN     := -fsanitize=thread
endif
ALL_CFLAGS := $(BASEFLAGS) $(CFLAGS) $(PKG_CFLAGS)
# lib/volume: the SPH pair loops need sqrtf without errno to vectorise (the
# results are the same bytes: IEEE sqrt is exact either way), and no fused
# multiply-add anywhere (clang contracts a * b + c by default), so every
# instruction-set path gives the same bits.
$(BUILD)/obj/lib/volume/%.o: ALL_CFLAGS += -fno-math-errno -ffp-contract=off
# The lane passes once per instruction set (lib/volume/passes.h), each
# file with its own flags: every x86-64 path with gcc and clang alike.
# No -mfma: the paths must not differ by a rounding.
# (`make -s isa-flags SRC=lib/volume/passes_avx2.c` prints a file's, for
# builds outside this Makefile: .ci/fuzz.)
ISA_FLAGS_passes_avx2   := -mavx2
ISA_FLAGS_passes_avx512 := -mavx512f -mavx512dq -mbmi -mbmi2 -mpopcnt
ifneq ($(filter x86_64%,$(shell $(CC) -dumpmachine)),)
$(BUILD)/obj/lib/volume/passes_avx2.o: ALL_CFLAGS += $(ISA_FLAGS_passes_avx2)
$(BUILD)/obj/lib/volume/passes_avx512.o: ALL_CFLAGS += $(ISA_FLAGS_passes_avx512)
endif
.PHONY: isa-flags
isa-flags:
	@echo $(ISA_FLAGS_$(basename $(notdir $(SRC))))
SYS_LIBS   := $(PKG_LIBS) -ldl -lpthread -lm

LIB_SRC := $(wildcard lib/*/*.c)
ifeq ($(HAVE_GL),0)
LIB_SRC := $(filter-out lib/render/gl_%.c,$(LIB_SRC))
endif
ifeq ($(HAVE_OSMESA),0)
LIB_SRC := $(filter-out lib/render/gl_context_osmesa.c,$(LIB_SRC))
endif
ifeq ($(HAVE_EGL),0)
LIB_SRC := $(filter-out lib/render/gl_context_egl.c,$(LIB_SRC))
endif
LIB_OBJ   := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
SHARED    := $(BUILD)/lib/libmodesplit.so.$(VERSION)
SONAME    := libmodesplit.so.$(SOVERSION)
STATIC    := $(BUILD)/lib/libmodesplit.a

SHAPE_SRC  := $(wildcard plugins/shapes/*.c)
SHADER_SRC := $(wildcard plugins/shaders/*.c)
PLUGINS    := $(SHAPE_SRC:plugins/shapes/%.c=$(BUILD)/plugins/shape_%.so) \
              $(SHADER_SRC:plugins/shaders/%.c=$(BUILD)/plugins/shader_%.so)
PLUGIN_LIBS ?= $(shell $(PKG_CONFIG) --libs jansson libpng 2>/dev/null) -lm

TOOL_SRC  := $(wildcard tools/modesplit/*.c)
TOOL      := $(if $(TOOL_SRC),$(BUILD)/bin/modesplit)
BENCH_SRC := $(wildcard tools/bench/*.c)
BENCHES   := $(BENCH_SRC:tools/bench/%.c=$(BUILD)/bin/%)
TEST_SRC  := $(wildcard tests/test_*.c)
TESTS     := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
# ThreadSanitizer runs the suites of the code that starts or shares threads
# (the rest is single-threaded and only gets 10-40x slower under TSan);
# `make check SAN=tsan` names them when it starts.
TSAN_SUITES ?= core plugin sim determinism api
# the volume's shared pool and its helper thread
TSAN_SUITES += pool
# the tool's PNG writer thread (run / render --png)
TSAN_SUITES += render_tool
# the library's own threads against the engine's tasks
TSAN_SUITES += threads
ifeq ($(SAN),tsan)
TESTS     := $(filter $(TSAN_SUITES:%=$(BUILD)/tests/test_%),$(TESTS))
endif
# Helpers shared by several test suites (tests/support_*.c).
TEST_SUPPORT := $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tests/support_*.c))
# The tool's ThreadSanitizer suppressions for Mesa (one list for tool and tests).
TEST_SUPPORT += $(BUILD)/obj/tools/modesplit/tsan_mesa.o

.SECONDARY:
# V=1 shows the full commands.
ifeq ($(V),1)
Q :=
else
Q := @
endif

# A compile that fails or is killed half-way leaves no truncated object
# that the next make would take as up to date.
.DELETE_ON_ERROR:

.PHONY: all lib plugins tools tests check check-headers check-exports check-readme check-paraview check-usd demo golden bench \
        install uninstall clean deps
.DEFAULT_GOAL := all

all: lib plugins tools

lib: $(SHARED) $(STATIC) $(BUILD)/lib/$(SONAME) $(BUILD)/lib/libmodesplit.so
plugins: $(PLUGINS)
tools: $(TOOL) $(BENCHES)
tests: $(TESTS)

# What the objects were compiled for (compiler, flags, the optional
# libraries found): a change rebuilds them all. Without it, installing
# libsdl2-dev (or OSMesa, EGL) after a first build left the old objects
# compiled without it beside new ones with it, and `modesplit` failed to
# link (view_gl_fn undefined).
CONFIG_STAMP := $(BUILD)/config.stamp

$(BUILD)/obj/%.o: %.c $(CONFIG_STAMP)
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -c $< -o $@

$(SHARED): $(LIB_OBJ)
	@mkdir -p $(@D)
	@echo "  LD      $@"
	$(Q)$(CC) -shared -Wl,-soname,$(SONAME) -Wl,--no-undefined $(LDSAN) -o $@ $^ $(SYS_LIBS)

$(BUILD)/lib/$(SONAME): $(SHARED)
	$(Q)ln -sf $(notdir $<) $@
$(BUILD)/lib/libmodesplit.so: $(BUILD)/lib/$(SONAME)
	$(Q)ln -sf $(notdir $<) $@

$(STATIC): $(LIB_OBJ)
	@mkdir -p $(@D)
	@echo "  AR      $@"
	$(Q)rm -f $@ && ar rcs $@ $^

# Plugins are self-contained: they use no libmodesplit symbols, so they
# load into any host (a statically linked test, an engine, the tool).
$(BUILD)/plugins/shape_%.so: plugins/shapes/%.c include/modesplit/plugin.h $(wildcard plugins/common/*.h) $(CONFIG_STAMP)
	@mkdir -p $(@D)
	@echo "  PLUGIN  $@"
	$(Q)$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -shared -Wl,--no-undefined $(LDSAN) -o $@ $< $(PLUGIN_LIBS)
$(BUILD)/plugins/shader_%.so: plugins/shaders/%.c include/modesplit/plugin.h $(wildcard plugins/common/*.h) $(CONFIG_STAMP)
	@mkdir -p $(@D)
	@echo "  PLUGIN  $@"
	$(Q)$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -shared -Wl,--no-undefined $(LDSAN) -o $@ $< $(PLUGIN_LIBS)

# The tool links the shared library, found next to it at run time.
$(BUILD)/bin/modesplit: $(TOOL_SRC:%.c=$(BUILD)/obj/%.o) $(SHARED) $(BUILD)/lib/libmodesplit.so
	@mkdir -p $(@D)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDSAN) -o $@ $(filter %.o,$^) -L$(BUILD)/lib -lmodesplit \
	    -Wl,-rpath,'$$ORIGIN/../lib' $(SYS_LIBS)

$(BUILD)/bin/%: $(BUILD)/obj/tools/bench/%.o $(STATIC)
	@mkdir -p $(@D)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDSAN) -o $@ $< $(STATIC) $(SYS_LIBS)

# modesplit view: the window is SDL2's, optional like OSMesa;
# without it `modesplit view` says so and exits 2. The tool links no
# OpenGL library (the viewer takes its few GL calls from the window's
# context). tests/test_view also links the viewer's SDL-free parts.
HAVE_SDL2   := $(shell $(PKG_CONFIG) --exists sdl2 2>/dev/null && echo 1 || echo 0)
ifeq ($(HAVE_SDL2),1)
SDL2_CFLAGS := $(shell $(PKG_CONFIG) --cflags sdl2 2>/dev/null)
SDL2_LIBS   := $(shell $(PKG_CONFIG) --libs sdl2 2>/dev/null)
endif
VIEW_TEST_OBJ := $(addprefix $(BUILD)/obj/tools/modesplit/,view_log.o view_camera.o view_stats.o \
                 view_input.o regular_file.o)
$(BUILD)/obj/tools/modesplit/%.o: CPPFLAGS += -DMS_HAVE_SDL2=$(HAVE_SDL2)
$(BUILD)/obj/tools/modesplit/%.o: ALL_CFLAGS += $(SDL2_CFLAGS)
$(BUILD)/bin/modesplit: SYS_LIBS += $(SDL2_LIBS)

CONFIG_LINE := cc=$(CC) cflags=$(CFLAGS) native=$(NATIVE) osmesa=$(HAVE_OSMESA) egl=$(HAVE_EGL) \
               sdl2=$(HAVE_SDL2)
# rewritten only when it differs, so an unchanged configuration rebuilds
# nothing
$(shell mkdir -p $(BUILD) && { [ "$$(cat $(CONFIG_STAMP) 2>/dev/null)" = '$(CONFIG_LINE)' ] || \
    printf '%s\n' '$(CONFIG_LINE)' > $(CONFIG_STAMP); })
$(BUILD)/tests/test_view: $(VIEW_TEST_OBJ)
$(BUILD)/tests/test_view: TEST_SUPPORT += $(VIEW_TEST_OBJ)

# Tests link the static library so they can also reach internal functions.
$(BUILD)/obj/tests/%.o: tests/%.c $(CONFIG_STAMP)
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CPPFLAGS) -Itests $(ALL_CFLAGS) $(CHECK_CFLAGS) -c $< -o $@
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TEST_SUPPORT) $(STATIC) | plugins tools
	@mkdir -p $(@D)
	@echo "  LD      $@"
	$(Q)$(CC) $(LDSAN) $(TEST_LDFLAGS) -o $@ $< $(TEST_SUPPORT) $(STATIC) $(CHECK_LIBS) $(SYS_LIBS)
# test_threads counts the library's pthread_create calls (its
# __wrap_pthread_create); a variable of its own, which the tools and
# plugins it depends on never read.
$(BUILD)/tests/test_threads: TEST_LDFLAGS := -Wl,--wrap=pthread_create
# test_alloc counts the library's direct calls to the C allocator
$(BUILD)/tests/test_alloc: TEST_LDFLAGS := $(foreach f,malloc calloc realloc free aligned_alloc \
    posix_memalign strdup strndup,-Wl,--wrap=$(f))

deps:
	@tools/deps.sh

# make check: the checks of the tree (headers, exports, the README's
# example, the docs, the ABI listing, the bench figures), then every suite,
# each a target of its own, so that `make -j2 check` runs two at a time.
# Every suite runs even if one fails; one summary at the end; the target
# fails if any suite did. `make check-suites` runs the suites alone (with
# the summary), building what they need.
CHECK_PRE := check-headers check-exports check-readme check-docs check-layers check-abi check-bench-figures
check: deps
	@$(MAKE) --no-print-directory all tests
	@$(MAKE) --no-print-directory --output-sync=target $(CHECK_PRE)
	@$(MAKE) --no-print-directory check-suites

# One run of a suite, $(CHECK_DIR)/<suite>[.<case>].result: its output in
# .log, the cases it could not run in .skipped (MS_TEST_SKIP_FILE), the
# paths this machine does not have in .na (MS_TEST_NA_FILE), and "passed
# SECONDS" or "failed SECONDS" in .result. The recipe succeeds either way,
# so the other suites still run; check-suites counts.
CHECK_DIR := $(BUILD)/check
# A suite listed in CHECK_SPLIT runs as one job per Check case (CK_RUN_CASE)
# instead of one for the whole suite: test_volume is the longest suite
# (~45 s of one core, where the others take 0-27 s; plain build), and would
# be the last job left running; test_sim's one-thread scene runs (the glass
# and the stir for 20 and 10 s) are most of its time.
# The cases are read from the suite's tcase_create("...") calls, so a new
# case runs without a change here; a suite whose cases are not all named
# by a literal there runs whole.
CHECK_SPLIT ?= volume sim
LP := (
split_cases = $(if $(filter $(words $(shell grep -o 'tcase_create$(LP)' tests/test_$(1).c)),\
    $(words $(shell grep -o 'tcase_create("[A-Za-z0-9_]*")' tests/test_$(1).c))),\
    $(shell sed -n 's/.*tcase_create("\([A-Za-z0-9_]*\)").*/\1/p' tests/test_$(1).c))
# AddressSanitizer + UBSan (SAN=asan) run every suite but the jobs named in
# ASAN_LEAVE_OUT (a suite, or <suite>.<case> of a suite split here):
#   view.window: the viewer in a window under Xvfb, whose time goes to
#   Xvfb and llvmpipe; .ci/valgrind runs the same scripted session (drag,
#   drop, rain, shader switch, orbit, resize, lost context, F12, Esc) under
#   memcheck. The viewer's own parts (input logs, camera, stats: view.parts)
#   run here.
#   view.view_long: registered only with MS_TEST_LONG=1 (make
#   check-long-view, the plain build); without it the job ran no test and
#   was listed as passed.
ASAN_LEAVE_OUT ?= view.window view.view_long
# ThreadSanitizer (SAN=tsan) runs the jobs of TSAN_SUITES but those named in
# TSAN_LEAVE_OUT:
#   determinism.golden: the golden hash of a one-thread run; TSan finds
#   nothing where no second thread runs. The plain and ASan builds check it.
#   sim.one_thread_scenes: the sim suite's long scene runs (the glass and
#   the stir for seconds, the drag, the paddle, a still pool's minute and
#   a splash with spray), each on one thread: over half of the suite's
#   time under TSan (the still pool alone hit the 300 s case limit), for
#   nothing it could find. The sim's threaded cases (the two-thread split,
#   the worker, spray on one and two threads) stay.
TSAN_LEAVE_OUT ?= determinism.golden sim.one_thread_scenes
SAN_LEAVE_OUT := $(if $(filter asan,$(SAN)),$(ASAN_LEAVE_OUT))$(if $(filter tsan,$(SAN)),$(TSAN_LEAVE_OUT))
CHECK_SPLIT += $(foreach j,$(SAN_LEAVE_OUT),$(if $(findstring .,$(j)),$(firstword $(subst ., ,$(j)))))
SUITE_NAMES := $(TESTS:$(BUILD)/tests/test_%=%)
SUITE_JOBS  := $(foreach n,$(SUITE_NAMES),$(or $(if $(filter $(n),$(CHECK_SPLIT)),\
    $(addprefix $(n).,$(call split_cases,$(n)))),$(n)))
SUITE_JOBS  := $(filter-out $(SAN_LEAVE_OUT),$(SUITE_JOBS))
# the suites with a job to run (all but one wholly left out)
SUITE_NAMES := $(foreach n,$(SUITE_NAMES),$(if $(filter $(n) $(n).%,$(SUITE_JOBS)),$(n)))
# The longest jobs start first, so that none of them starts last (each
# job's seconds are in `make check`'s output); the rest in name order. In
# this order under ASan (stability ~310 s, accuracy ~220 s, colliders,
# alloc, volume.hard and volume.model ~150 s, render and tool ~75 s on a
# loaded 2-core machine); the plain build's longest are the same ones, at
# 13-27 s.
# Under TSan the longest are sim and determinism (~210 s each) and pool (~95 s).
CHECK_FIRST ?= stability accuracy colliders alloc volume.hard volume.model sim.one_thread_scenes \
               tool render io sim.sim determinism determinism.determinism pool
SUITE_JOBS  := $(foreach j,$(CHECK_FIRST),$(filter $(j),$(SUITE_JOBS))) \
               $(filter-out $(CHECK_FIRST),$(SUITE_JOBS))
# Suites that must have the machine to themselves run after all the
# others, one at a time:
#   view: tests/view_x11.sh drags the water with real X events and takes
#   its screenshots after fixed sleeps (2 s after the drag), and a frame
#   of llvmpipe can take half a second on a loaded core; a suite on the
#   other core would push the drag's frames past the screenshot. When the
#   suite runs split by case (SAN=asan), that is view.window; view.parts
#   (in-process unit parts) shares the machine.
#   resume: kill_at polls a running tool's run file every millisecond and
#   SIGKILLs it once it holds frame k (k up to 20 of 24): the poll must win
#   the race against the tool's last frames. With a suite on the other
#   core, poller and tool share one; under load it lost once in four
#   `make -j2 check` runs (the tool ended on its own: test_resume.c:119).
# No other suite needs this: their temporary files are mkdtemp/mkstemp
# names (ms_test_tmp_dir), none listens on a port or writes into the tree
# (test_plugin's `make install` finds the build up to date),
# the full-disk cases mount their tmpfs in a private mount namespace, and
# the cases that signal a running tool wait for what they check (frames in
# the file, the process's exit) instead of a fixed time.
CHECK_ALONE ?= resume view view.window
CHECK_ALONE    := $(filter $(CHECK_ALONE),$(SUITE_JOBS))
CHECK_SHARED   := $(filter-out $(CHECK_ALONE),$(SUITE_JOBS))
SHARED_RESULTS := $(addprefix $(CHECK_DIR)/,$(addsuffix .result,$(CHECK_SHARED)))
CHECK_RESULTS  := $(SHARED_RESULTS) $(addprefix $(CHECK_DIR)/,$(addsuffix .result,$(CHECK_ALONE)))
define suite_job
$(CHECK_DIR)/$(1).result: $(BUILD)/tests/test_$(firstword $(subst ., ,$(1))) FORCE $(2)
endef
$(foreach j,$(CHECK_SHARED),$(eval $(call suite_job,$(j))))
# each suite of CHECK_ALONE after every shared job and every suite before it
ALONE_BEFORE := $(SHARED_RESULTS)
$(foreach j,$(CHECK_ALONE),$(eval $(call suite_job,$(j),$(ALONE_BEFORE)))\
    $(eval ALONE_BEFORE += $(CHECK_DIR)/$(j).result))

.PHONY: check-suites FORCE
FORCE:
# $* is <suite> or <suite>.<case>
$(CHECK_DIR)/%.result:
	@mkdir -p $(@D); rm -f $@ $(@:.result=.skipped) $(@:.result=.na)
	@suite=$(firstword $(subst ., ,$*)); case_=$(word 2,$(subst ., ,$*)); t0=$$(date +%s); \
	if env $${case_:+CK_RUN_CASE=$$case_} MS_TEST_BUILD=$(BUILD) MS_TEST_SAN=$(SAN) \
	    MS_TEST_SKIP_FILE=$(abspath $(@:.result=.skipped)) MS_TEST_NA_FILE=$(abspath $(@:.result=.na)) \
	    $(BUILD)/tests/test_$$suite > $(@:.result=.log) 2>&1; then r=passed; else r=failed; fi; \
	s=$$(($$(date +%s) - t0)); echo "$$r $$s" > $@; \
	echo "== $(BUILD)/tests/test_$$suite$${case_:+ (case $$case_)}: $$r in $$s s;" \
	    "$$(grep '^[0-9]*%: Checks' $(@:.result=.log) | tail -n 1)"

check-suites: $(CHECK_RESULTS)
	@$(if $(filter tsan,$(SAN)),echo "tsan: the threaded suites: $(notdir $(TESTS));" \
	    "left out (TSAN_LEAVE_OUT; the Makefile says why): $(TSAN_LEAVE_OUT)";) \
	$(if $(filter asan,$(SAN)),echo "asan: left out (ASAN_LEAVE_OUT; the Makefile says why): $(ASAN_LEAVE_OUT)";) \
	failed=""; for r in $(CHECK_RESULTS); do \
	    res=failed; [ -f "$$r" ] && read -r res sec < "$$r"; [ "$$res" = passed ] && continue; \
	    job=$${r##*/}; job=$${job%.result}; failed="$$failed $${job%%.*}"; \
	    echo "== $(BUILD)/tests/test_$${job%%.*}$$(case $$job in *.*) echo " (case $${job#*.})";; esac): FAILED;" \
	        "its log ($${r%.result}.log):"; cat "$${r%.result}.log"; \
	done; \
	fail=$$(printf '%s\n' $$failed | sort -u | grep -c .); pass=$$(($(words $(SUITE_NAMES)) - fail)); \
	skips=$(abspath $(BUILD))/skipped.txt; nas=$(abspath $(BUILD))/not-applicable.txt; \
	: > $$skips; : > $$nas; for r in $(CHECK_RESULTS:.result=); do \
	    if [ -f $$r.skipped ]; then cat $$r.skipped >> $$skips; fi; \
	    if [ -f $$r.na ]; then cat $$r.na >> $$nas; fi; \
	done; \
	if [ -s $$nas ]; then echo "make check: $$(wc -l < $$nas) cases checked only the paths this machine has;" \
	    "not applicable here (not a skip):"; sed 's/^/  /' $$nas; fi; \
	nskip=0; if [ -s $$skips ]; then nskip=$$(wc -l < $$skips); \
	    echo "make check: $$nskip cases could not run here and were skipped:"; sed 's/^/  /' $$skips; fi; \
	echo "suites: $$pass passed, $$fail failed, $$nskip skipped"; \
	if [ $$fail -ne 0 ]; then echo "make check: FAILED"; exit 1; fi; \
	echo "make check: all $(words $(SUITE_NAMES)) suites passed ($(BUILD))"

# The public headers compile as C11 (pedantic) and as C++11.
check-headers:
	@mkdir -p $(BUILD)/compile
	$(Q)$(CC) -std=c11 $(WARN) -Iinclude -fsyntax-only tests/compile/headers.c
	$(Q)$(CXX) -std=c++11 -Wall -Wextra -Werror -Wpedantic -Iinclude -fsyntax-only \
	    -x c++ tests/compile/headers.c
	@echo "headers: C11 and C++11 OK"

# The shared library exports ms_* symbols only.
check-exports: $(SHARED)
	@tests/check_exports.sh $(SHARED)

# The README's C example compiles and runs.
check-readme: $(STATIC)
	@CC="$(CC) $(LDSAN)" MS_LIBS="$(SYS_LIBS)" tests/check_readme.sh $(BUILD)

# README.md, CHANGELOG.md, docs/ and the sources' comments cite no work
# round, branch or issue number, and the README stays a guide (<= 400
# lines); the self-test plants such lines and expects the check to fail.
.PHONY: check-docs check-layers
check-docs:
	@tests/check_docs.sh --self-test
	@tests/check_docs.sh

# dependencies point down: core includes no part, volume and surface not
# each other
check-layers:
	@tests/check_layers.sh

# The renderer's golden pictures: tests/data/golden/<scene>.png,
# compared with a tolerance by test_render; written afresh only here, on
# purpose, so a change of the look is a visible diff in review.
# And the golden hash of a fixed scene's fields (tests/data/golden_hash.txt,
# test_determinism) and of the volume's dam break (golden_volume_hash.txt,
# test_volume), refreshed when a change is meant to change results.
golden: $(BUILD)/tests/test_render $(BUILD)/tests/test_determinism $(BUILD)/tests/test_volume plugins
	MS_GOLDEN_WRITE=1 CK_RUN_CASE=render $(BUILD)/tests/test_render
	@echo "golden: wrote tests/data/golden/*.png; look at them before committing"
	@CK_RUN_CASE=golden MS_GOLDEN_WRITE=1 MS_TEST_BUILD=$(BUILD) $(BUILD)/tests/test_determinism
	@echo "golden: wrote tests/data/golden_hash.txt"
	@CK_RUN_CASE=golden MS_GOLDEN_WRITE=1 MS_TEST_BUILD=$(BUILD) $(BUILD)/tests/test_volume
	@echo "golden: wrote tests/data/golden_volume_hash.txt"


# ---- the ABI listing and the Python package ----------------------------------
# tools/abi/abi.json lists every public function (C signature, exported or
# not), struct (size, field offsets) and enum value, from the headers, the
# compiler and `nm -D` of the library; the Python package builds its ctypes
# layouts from its copy (tools/python/modesplit/abi.json). `make check` fails
# with a diff when either differs from what the headers and the library give;
# after a deliberate ABI change run `make abi` and commit both.
PYTHON ?= python3
ABI_LISTINGS := tools/abi/abi.json tools/python/modesplit/abi.json
.PHONY: abi check-abi check-python
abi: $(SHARED) $(BUILD)/lib/libmodesplit.so
	$(Q)$(PYTHON) tools/abi/abi_listing.py --lib $(BUILD)/lib/libmodesplit.so --out $(ABI_LISTINGS)
check-abi: $(SHARED) $(BUILD)/lib/libmodesplit.so
	$(Q)$(PYTHON) tools/abi/abi_listing.py --lib $(BUILD)/lib/libmodesplit.so --check $(ABI_LISTINGS)
# The Python package's tests against this build's library, with the python3
# on PATH (numpy, pytest, matplotlib, h5py); .ci/run does the same in a venv
# with the package pip-installed. MS_PYTEST_ARGS adds pytest options.
# SAN=asan loads the ASan+UBSan library into Python (ASan preloaded) and runs
# every test but those marked no_asan (matplotlib's C++ aborts under ASan's
# interceptors; RSS means nothing with ASan's quarantine).
ifeq ($(SAN),asan)
PY_SAN := LD_PRELOAD=$$($(CC) -print-file-name=libasan.so) ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 \
          UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
PY_SAN_ARGS := -m "not no_asan"
endif
check-python: all
	$(Q)PYTHONPATH=$(abspath tools/python) MODESPLIT_LIB=$(abspath $(BUILD))/lib/libmodesplit.so MODESPLIT_BUILD=$(abspath $(BUILD)) \
	    $(PY_SAN) $(PYTHON) -m pytest -q -rs tools/python/tests $(PY_SAN_ARGS) $(MS_PYTEST_ARGS)

# ParaView (pvpython, Debian's 5.11) opens the runs the tool
# writes, with its default reader and the legacy one (tests/paraview/).
# Needs pvpython + xvfb-run; skipped (exit 77) without them, failed in CI.
check-paraview: all
	@tests/paraview/check.sh $(BUILD)

# `modesplit export --usd` read back with pxr (tools/usd_tests/).
# USD_VENV=1 (CI) pip-installs usd-core, h5py, numpy, pytest into $(BUILD)/venv-usd.
check-usd: all
	@tools/usd_tests/check.sh $(BUILD) $(if $(filter 1,$(USD_VENV)),--venv)

demo: deps
	@$(MAKE) --no-print-directory all
	@mkdir -p demo
	$(BUILD)/bin/modesplit run data/scenes/default.json --out demo/default.h5 --force --png demo/frames
	@echo "demo: wrote demo/default.h5 (HDF5), demo/default.xmf (ParaView) and demo/frames/*.png"

bench: deps
	@$(MAKE) --no-print-directory all
	@mkdir -p bench
	@for b in $(BENCHES); do echo "== $$b"; $$b --csv-dir bench || exit 1; done

install: all
	install -d $(DESTDIR)$(PREFIX)/include/modesplit $(DESTDIR)$(PREFIX)/lib/pkgconfig \
	    $(DESTDIR)$(PREFIX)/lib/modesplit/plugins $(DESTDIR)$(PREFIX)/bin
	install -m 644 include/modesplit/*.h $(DESTDIR)$(PREFIX)/include/modesplit/
	install -m 755 $(SHARED) $(DESTDIR)$(PREFIX)/lib/
	ln -sf $(notdir $(SHARED)) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libmodesplit.so
	install -m 644 $(STATIC) $(DESTDIR)$(PREFIX)/lib/
	$(if $(PLUGINS),install -m 755 $(PLUGINS) $(DESTDIR)$(PREFIX)/lib/modesplit/plugins/)
	$(if $(TOOL),install -m 755 $(TOOL) $(DESTDIR)$(PREFIX)/bin/)
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' \
	    -e 's|@REQUIRES@|$(LIB_PKGS)|g' tools/modesplit.pc.in \
	    > $(DESTDIR)$(PREFIX)/lib/pkgconfig/modesplit.pc
	# the scenes, the man page and the USD exporter under share/
	install -d $(DESTDIR)$(PREFIX)/share/modesplit/scenes $(DESTDIR)$(PREFIX)/share/man/man1 \
	    $(DESTDIR)$(PREFIX)/share/modesplit/python/modesplit
	install -m 644 data/scenes/*.json data/scenes/README.md $(DESTDIR)$(PREFIX)/share/modesplit/scenes/
	install -m 644 tools/modesplit/modesplit.1 $(DESTDIR)$(PREFIX)/share/man/man1/
	install -m 644 tools/python/modesplit/usd_export.py \
	    $(DESTDIR)$(PREFIX)/share/modesplit/python/modesplit/

uninstall:
	rm -rf $(DESTDIR)$(PREFIX)/include/modesplit $(DESTDIR)$(PREFIX)/lib/modesplit
	rm -f $(DESTDIR)$(PREFIX)/lib/libmodesplit.* $(DESTDIR)$(PREFIX)/lib/pkgconfig/modesplit.pc
	rm -f $(DESTDIR)$(PREFIX)/bin/modesplit
	rm -rf $(DESTDIR)$(PREFIX)/share/modesplit
	rm -f $(DESTDIR)$(PREFIX)/share/man/man1/modesplit.1

clean:
	rm -rf build build-asan build-tsan demo

# ---- the accuracy study and the long stability runs ----
# make accuracy     the full study of `modesplit accuracy` (both cores, one
#                   case per job), committed in data/accuracy/; then the
#                   accuracy figures of README.md and docs/accuracy.md are
#                   rewritten from its CSV (tools/bench/figures.py)
# make check-long   the coupled long runs of tests/test_stability.c (fig1 and
#                   fig10 at the top coupling gains for 10 simulated minutes,
#                   every shipped scene at 1 and 2 threads, a pool at rest for
#                   each pressure law) and the viewer left open for 10 minutes;
#                   .ci/run runs them (check-long-physics, check-long-view)
ACCURACY_DIR ?= data/accuracy
.PHONY: accuracy check-long
accuracy: all
	@rm -rf $(ACCURACY_DIR)/parts $(ACCURACY_DIR)/*.dat $(ACCURACY_DIR)/*.png
	$(BUILD)/bin/modesplit accuracy --jobs --out $(ACCURACY_DIR) | xargs -P $$(nproc) -I{} sh -c '{}'
	$(BUILD)/bin/modesplit accuracy --merge $(ACCURACY_DIR)/parts --out $(ACCURACY_DIR)
	$(PYTHON) tools/bench/figures.py --write README.md docs/accuracy.md

# make accuracy-rerun  the study's cases again but the three largest dam
#                   breaks, into data/accuracy/rerun.csv: docs/accuracy.md's
#                   table of how well two runs agree (errors, CPU costs)
RERUN_DIR ?= $(BUILD)/accuracy-rerun
.PHONY: accuracy-rerun
accuracy-rerun: all
	@rm -rf $(RERUN_DIR)
	$(BUILD)/bin/modesplit accuracy --jobs --out $(RERUN_DIR) | grep -v -e 'sph-particles-[0-9]' | \
	    xargs -P $$(nproc) -I{} sh -c '{}'
	$(BUILD)/bin/modesplit accuracy --merge $(RERUN_DIR)/parts --out $(RERUN_DIR)
	cp $(RERUN_DIR)/accuracy.csv $(ACCURACY_DIR)/rerun.csv
	$(PYTHON) tools/bench/figures.py --write README.md docs/accuracy.md

# check-accuracy (in make check): the quick study's rows against the
# committed study's same cases (tools/modesplit/check_accuracy.py); a
# change that moves them regenerates data/accuracy/ with `make accuracy`.
# Not under a sanitizer (SAN=...): test_accuracy runs the quick study there.
.PHONY: check-accuracy
check-accuracy: all
	$(Q)$(PYTHON) tools/modesplit/check_accuracy.py $(BUILD)/bin/modesplit
CHECK_PRE += $(if $(SAN),,check-accuracy)

# The long cases run side by side, each its own process; all must pass.
# <suite>:<case> each: the stability suite's long physics runs (all CPU),
# and the viewer left open on a still pool (test_view's view_long: 12
# minutes of wall clock, paced in real time, which uses under a core).
# check-long runs them all; .ci/run runs check-long-physics as a stage and
# check-long-view beside the stages after it, which leave a core to it.
LONG_PHYSICS := stability:coupled_top_gains stability:coupled_every_scene stability:still_pool \
                stability:spray_stir
LONG_VIEW    := view:view_long
.PHONY: check-long-physics check-long-view
# $(1): the jobs, $(2): the target's name
define run_long
	@skips=$(abspath $(BUILD))/skipped-$(2).txt; rm -f $$skips; pids=; \
	for j in $(1); do \
	    MS_TEST_LONG=1 CK_RUN_CASE=$${j#*:} MS_TEST_BUILD=$(BUILD) MS_TEST_SAN=$(SAN) \
	        MS_TEST_SKIP_FILE=$$skips $(BUILD)/tests/test_$${j%%:*} & pids="$$pids $$!"; \
	done; \
	fail=0; for p in $$pids; do wait $$p || fail=1; done; \
	if [ -s $$skips ]; then echo "make $(2): skipped:"; cat $$skips; fi; \
	if [ $$fail -ne 0 ]; then echo "make $(2): FAILED"; exit 1; fi; \
	echo "make $(2): passed ($(BUILD))"
endef
check-long: all $(BUILD)/tests/test_stability $(BUILD)/tests/test_view
	$(call run_long,$(LONG_PHYSICS) $(LONG_VIEW),check-long)
check-long-physics: all $(BUILD)/tests/test_stability
	$(call run_long,$(LONG_PHYSICS),check-long-physics)
check-long-view: all $(BUILD)/tests/test_view
	$(call run_long,$(LONG_VIEW),check-long-view)

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
# Plugins include plugins/common/*.h: their dependency files too.
-include $(wildcard $(BUILD)/plugins/*.d)

# ---- the clang build (CI) ----
# check-clang: the library, plugins, tools and tests compile with clang and
# the same -Werror warnings (build-clang/); .ci/run runs it, so a warning
# only clang gives fails CI. It needs a CI-only tool (clang: tools/deps.sh
# --ci), so it is not part of `make check`.
.PHONY: check-clang
check-clang:
	@command -v clang > /dev/null || { echo "check-clang: clang not found (tools/deps.sh --ci)"; exit 1; }
	@$(MAKE) --no-print-directory CC=clang BUILD=build-clang all tests
	@echo "check-clang: library, plugins, tools and tests build with clang -Werror (build-clang/)"

# ---- the speed figures of README.md and docs/performance.md ----
# data/bench/*.csv: one `make bench` on a quiet machine (data/bench/README.md
# names it). README.md and docs/performance.md link each figure they quote
# to its CSV row, or generate a table from them; check-bench-figures (in
# `make check`) fails when one differs. After a deliberate `make bench` on a quiet machine:
# `make bench-commit` copies bench/*.csv there and rewrites the figures.
.PHONY: check-bench-figures bench-commit
check-bench-figures:
	$(Q)$(PYTHON) tools/bench/test_figures.py
	$(Q)$(PYTHON) tools/bench/figures.py --check README.md docs/performance.md docs/accuracy.md
bench-commit:
	$(Q)$(PYTHON) tools/bench/figures.py --commit bench

# ---- the layout of the C files (CI) ----
# format-check: every C file under lib/ include/ tools/ tests/ plugins/
# follows .clang-format, whole files (tools/format_check.sh; --fix lays them
# out). It needs a CI-only tool (clang-format: tools/deps.sh --ci), so it is
# not part of `make check`; .ci/run runs it.
.PHONY: format-check
format-check:
	@tools/format_check.sh

# ---- a one-process A/B of two library builds ----
# build/bin/volume_ab A.so B.so dam N REPS | scene FILE REPS | peer FRAMES
# REPS (peer: bench_dfsph --peer's DFSPH scene, whole runs in turn): both builds dlmopen'ed, sub-steps, frames or runs in turn
# (tools/ab/volume_ab.c). Not part
# of `all` or `bench`: `make volume-ab`.
.PHONY: volume-ab
volume-ab: $(BUILD)/bin/volume_ab
$(BUILD)/bin/volume_ab: tools/ab/volume_ab.c include/modesplit/volume.h
	@mkdir -p $(@D)
	@echo "  CC      $@"
	$(Q)$(CC) -Iinclude $(BASEFLAGS) -D_GNU_SOURCE $(CFLAGS) -o $@ $< $(LDSAN) $(SYS_LIBS)

# ---- aarch64: the NEON path, cross-built and run under qemu-user ----
# check-aarch64: Debian's cross gcc builds the library (all but lib/io,
# whose HDF5 has no arm64 build here, and the GL files), the shape plugins
# and the volume and determinism suites into build-aarch64/; qemu-user runs
# the suites, each case a job as in `make check`. They hold the every-path
# same-bytes cases (on aarch64: C and NEON) and the golden hash, so a pass
# is the same bytes as x86. The cross compiler and qemu-user come from
# tools/deps.sh --aarch64; the arm64 libraries linked (jansson, Check,
# libpng, zlib) are Debian's arm64 packages, unpacked into
# build-aarch64/sysroot/ (apt-get download): installing them through
# multiarch would upgrade the amd64 ones of the same names.
A64        := build-aarch64
A64_CC     ?= aarch64-linux-gnu-gcc
A64_AR     ?= aarch64-linux-gnu-ar
A64_RUN    ?= qemu-aarch64 -L /usr/aarch64-linux-gnu
A64_ROOT   := $(abspath $(A64))/sysroot
A64_DEBS   := libjansson4 libjansson-dev check libsubunit0 libsubunit-dev libpng16-16 libpng-dev \
              zlib1g zlib1g-dev
A64_STAMP  := $(A64)/sysroot/.unpacked
A64_PKG    := PKG_CONFIG_SYSROOT_DIR=$(A64_ROOT) \
              PKG_CONFIG_LIBDIR=$(A64_ROOT)/usr/lib/aarch64-linux-gnu/pkgconfig $(PKG_CONFIG)
A64_LIB_SRC := $(filter-out lib/io/% lib/render/gl_%,$(wildcard lib/*/*.c))
A64_OBJ    := $(A64_LIB_SRC:%.c=$(A64)/obj/%.o)
A64_LIB    := $(A64)/lib/libmodesplit.a
A64_SUITES ?= volume determinism
A64_PLUGINS := $(SHAPE_SRC:plugins/shapes/%.c=$(A64)/plugins/shape_%.so)
A64_CPPFLAGS := -Iinclude -Ilib -Itests -MMD -MP -DMS_HAVE_OSMESA=0 -DMS_HAVE_EGL=0 -DMS_HAVE_GL=0 \
                -DMS_BUILD_PLUGIN_DIR='"$(abspath $(A64))/plugins"'
# (=, not :=: pkg-config reads the sysroot once it is unpacked)
A64_CFLAGS  = $(BASEFLAGS) $(CFLAGS) $(shell $(A64_PKG) --cflags jansson libpng check)
A64_LIBS    = $(shell $(A64_PKG) --libs jansson libpng check) -ldl -lpthread -lm \
              -Wl,--disable-new-dtags \
              -Wl,-rpath,$(A64_ROOT)/usr/lib/aarch64-linux-gnu -Wl,-rpath,$(A64_ROOT)/lib/aarch64-linux-gnu
A64_TEST_SUPPORT := $(patsubst %.c,$(A64)/obj/%.o,$(wildcard tests/support_*.c))
.PHONY: aarch64 check-aarch64
$(A64_STAMP):
	@command -v $(A64_CC) > /dev/null || { echo "aarch64: $(A64_CC) not found (tools/deps.sh --aarch64)"; exit 1; }
	@rm -rf $(@D) && mkdir -p $(@D)/debs
	$(Q)cd $(@D)/debs && apt-get download -q -o APT::Sandbox::User="$$(id -un)" $(A64_DEBS:%=%:arm64) > /dev/null || \
	    { echo "aarch64: apt-get download failed (tools/deps.sh --aarch64 adds the arm64 package lists)"; exit 1; }
	$(Q)for d in $(@D)/debs/*.deb; do dpkg-deb -x $$d $(@D) || exit 1; done
	@touch $@
$(A64)/obj/lib/volume/%.o: A64_CFLAGS += -fno-math-errno -ffp-contract=off
$(A64)/obj/%.o: %.c | $(A64_STAMP)
	@mkdir -p $(@D)
	@echo "  CC64    $<"
	$(Q)$(A64_CC) $(A64_CPPFLAGS) $(A64_CFLAGS) -c $< -o $@
$(A64_LIB): $(A64_OBJ)
	@mkdir -p $(@D)
	$(Q)rm -f $@ && $(A64_AR) rcs $@ $^
$(A64)/plugins/shape_%.so: plugins/shapes/%.c include/modesplit/plugin.h $(wildcard plugins/common/*.h) | $(A64_STAMP)
	@mkdir -p $(@D)
	@echo "  PLUG64  $@"
	$(Q)$(A64_CC) $(A64_CPPFLAGS) $(A64_CFLAGS) -shared -Wl,--no-undefined -o $@ $< $(A64_LIBS)
$(A64)/tests/test_%: $(A64)/obj/tests/test_%.o $(A64_TEST_SUPPORT) $(A64_LIB)
	@mkdir -p $(@D)
	@echo "  LD64    $@"
	$(Q)$(A64_CC) -o $@ $< $(A64_TEST_SUPPORT) $(A64_LIB) $(A64_LIBS)
aarch64: $(A64_SUITES:%=$(A64)/tests/test_%) $(A64_PLUGINS)
.PHONY: clean-aarch64
clean: clean-aarch64
clean-aarch64:
	rm -rf $(A64)
-include $(shell find $(A64)/obj -name '*.d' 2>/dev/null)
# Each suite's cases as jobs (split_cases, as CHECK_SPLIT); a job's
# result, log and records as in $(CHECK_DIR) (run_job, below).
A64_CHECK  := $(A64)/check
A64_JOBS   := $(foreach n,$(A64_SUITES),$(or $(addprefix $(n).,$(call split_cases,$(n))),$(n)))
# A64_LEAVE_OUT: the jobs not run here, each with its reason:
#   volume.tool: runs the `modesplit` tool, which links lib/io (HDF5):
#   not built for aarch64 (above). The in-process ms_get_build_info it
#   prints is checked by volume.hard (modesplit_isa_forces_a_path...).
A64_LEAVE_OUT ?= volume.tool
# CK_TIMEOUT_MULTIPLIER under qemu-user: each case's time limit
# (tcase_set_timeout, set for the host's widest path) is scaled by it, as
# the cases do the same work, emulated. qemu-user runs the NEON path ~20x
# slower than the host runs SSE2 and ~80x slower than AVX-512 (CPU time of
# volume.golden: 19 s, 0.93 s, 0.24 s).
A64_SLOWER ?= 80
A64_JOBS   := $(filter-out $(A64_LEAVE_OUT),$(A64_JOBS))
# A64_ONLY: run these jobs alone (.ci/run: the golden hashes, below)
A64_JOBS   := $(or $(A64_ONLY),$(A64_JOBS))
# check-aarch64-golden (.ci/run): the golden hashes alone, on NEON: the
# volume's dam break under both pressure laws and the every-effect scene
# give the bytes committed from x86-64. The whole check-aarch64 is ~50x
# the CPU time of `make check`'s volume and determinism suites (qemu-user),
# too long for CI's budget.
A64_GOLDEN := volume.golden determinism.golden
.PHONY: check-aarch64-golden
check-aarch64-golden:
	@$(MAKE) --no-print-directory check-aarch64 A64_ONLY="$(A64_GOLDEN)"
$(A64_CHECK)/%.result: FORCE aarch64
	$(call run_job,$(A64),$(A64_RUN),CK_TIMEOUT_MULTIPLIER=$(A64_SLOWER))
check-aarch64: $(A64_JOBS:%=$(A64_CHECK)/%.result)
	$(call sum_jobs,$(A64_CHECK),$(A64_JOBS),check-aarch64)
	@echo "make check-aarch64: passed on aarch64 (NEON, under qemu-user; left out: $(A64_LEAVE_OUT))"

# run_job: the recipe of one job, $@ = <dir>/<suite>[.<case>].result, in
# $(1)'s build; $(2) a command before the suite (an emulator), $(3) more
# environment. Its output in .log, its skips in .skipped, its paths not
# applicable in .na, "passed SECONDS" or "failed SECONDS" in .result; the
# recipe succeeds either way, so the other jobs still run.
define run_job
	@mkdir -p $(@D); rm -f $@ $(@:.result=.skipped) $(@:.result=.na)
	@j=$(basename $(notdir $@)); suite=$${j%%.*}; case_=$$(case $$j in *.*) echo "$${j#*.}";; esac); \
	t0=$$(date +%s); \
	if env $${case_:+CK_RUN_CASE=$$case_} MS_TEST_BUILD=$(1) $(3) \
	    MS_TEST_SKIP_FILE=$(abspath $(@:.result=.skipped)) MS_TEST_NA_FILE=$(abspath $(@:.result=.na)) \
	    $(2) $(1)/tests/test_$$suite > $(@:.result=.log) 2>&1; then r=passed; else r=failed; fi; \
	s=$$(($$(date +%s) - t0)); echo "$$r $$s" > $@; \
	echo "== $(@:.result=): $$r in $$s s; $$(grep '^[0-9]*%: Checks' $(@:.result=.log) | tail -n 1)"
endef
# sum_jobs: $(2), the jobs run under $(1), as `make check` sums its suites:
# each failed job's log, the paths not applicable, the skips; fails when a
# job did. $(3) names the target.
define sum_jobs
	@failed=0; for j in $(2); do r=$(1)/$$j.result; res=failed; \
	    [ -f $$r ] && read -r res sec < $$r; [ "$$res" = passed ] && continue; failed=$$((failed + 1)); \
	    echo "== $(1)/$$j: FAILED; its log:"; cat $(1)/$$j.log; \
	done; \
	for j in $(2); do \
	    if [ -f $(1)/$$j.na ]; then sed "s|^|  $$j: not applicable here: |" $(1)/$$j.na; fi; \
	    if [ -f $(1)/$$j.skipped ]; then sed "s|^|  $$j: skipped: |" $(1)/$$j.skipped; fi; \
	done; \
	echo "$(3): $(words $(2)) jobs, $$failed failed, $$(cat $(addprefix $(1)/,$(addsuffix .skipped,$(2))) 2>/dev/null | wc -l) skipped"; \
	[ $$failed -eq 0 ] || { echo "make $(3): FAILED"; exit 1; }
endef

# ---- the portable paths, forced ----
# check-paths: the suites that drive the volume (volume, each case a job,
# and determinism) again with MODESPLIT_ISA forcing each path of
# PATHS_ISAS (c and sse2: the plain C every target has, and the path of
# every x86-64 CPU), so the paths a CPU without AVX-512 takes pass the same
# physics, golden hashes and same-bytes cases as the picked one, which
# `make check` ran. The cases' time limits scale with the path's measured
# speed (tests/support_run.c). .ci/run runs it.
PATHS_ISAS   ?= c sse2
PATHS_SUITES ?= volume determinism
PATHS_CHECK  := $(BUILD)/check-paths
PATHS_JOBS   := $(foreach n,$(PATHS_SUITES),$(or $(addprefix $(n).,$(call split_cases,$(n))),$(n)))
# the longest first (as CHECK_FIRST), so that none of them starts last
PATHS_FIRST  ?= volume.hard volume.model determinism.determinism
PATHS_JOBS   := $(filter $(PATHS_FIRST),$(PATHS_JOBS)) $(filter-out $(PATHS_FIRST),$(PATHS_JOBS))
PATHS_JOBS   := $(foreach i,$(PATHS_ISAS),$(addprefix $(i)/,$(PATHS_JOBS)))
.PHONY: check-paths
$(PATHS_CHECK)/%.result: FORCE $(PATHS_SUITES:%=$(BUILD)/tests/test_%)
	$(call run_job,$(BUILD),,MODESPLIT_ISA=$(patsubst %/,%,$(dir $*)))
check-paths: $(PATHS_JOBS:%=$(PATHS_CHECK)/%.result)
	$(call sum_jobs,$(PATHS_CHECK),$(PATHS_JOBS),check-paths)
	@echo "make check-paths: $(PATHS_SUITES) passed on the paths $(PATHS_ISAS) ($(BUILD))"
