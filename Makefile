# Fresnel reflectance library: runtime (src/, include/), host tools (gen/), tests.
#   make          build the library, the single-file runtimes, build/fresnel
#                 and the default scene's example, then say what is where;
#                 one job per core (JOBS=N or -jN to choose)
#   make test     installs missing tools (tests/deps.sh), unit and error-bound
#                 tests, again under ASan+UBSan, and again built by the other
#                 compiler (clang when CC is gcc, else gcc): each check in the
#                 passes its header names (tests/README.md), JOBS at a time
#   make check    the edit loop's subset: the first pass, without the checks
#                 of the external tools (browser, GPU drivers, qemu)
#   make install  PREFIX=/usr/local DESTDIR=   headers, libfresnel.a, fresnel.pc,
#                 CMake package, bin/fresnel, share/fresnel/ (ports/install.sh)
#   make uninstall PREFIX=... DESTDIR=...      removes what install put there

CC      ?= cc
AR      ?= ar
BUILD   ?= build
OPT     ?= -O2
SAN     ?=
PREFIX  ?= /usr/local
DESTDIR ?=

WARN       := -std=c99 -Wall -Wextra -Wpedantic -Werror
# The runtime never hands sqrtf a negative argument and sets no errno
# (fresnel.h), so errno-setting math need not be kept: with it dropped gcc
# inlines sqrtf (the batches use SIMD intrinsics, src/f32/simd.h).
MATH_FLAGS := -fno-math-errno -fno-trapping-math
CFLAGS_LIB := $(WARN) $(OPT) $(MATH_FLAGS) $(SAN) -Iinclude -MMD -MP
# Other renderers' algorithms (gen/bench/peers.h), measured against ours by
# `fresnel bench --targets`: compiled with the runtime's math flags.
$(BUILD)/obj/gen/bench/bench_compare.o: CFLAGS_GEN += $(MATH_FLAGS)
CFLAGS_GEN := $(WARN) $(OPT) $(SAN) -D_POSIX_C_SOURCE=200809L -DFRESNEL_DATA_DIR=\"$(CURDIR)/data\" \
              -DFRESNEL_CFLAGS='"$(CC) $(OPT) $(MATH_FLAGS) $(SAN), no LTO"' -Iinclude -Igen -MMD -MP
LDLIBS     := -lm

LIB_SRC  := $(wildcard src/*/*.c)
GEN_SRC  := $(wildcard gen/*/*.c)
# The checks: every test_*.c under tests/ (tests/README.md has the layout),
# each built to $(BUILD)/tests/<its name>; the names are unique.
TEST_SRC := $(sort $(shell find tests -name 'test_*.c' -type f))
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
GEN_OBJ  := $(GEN_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/embed/viewer_assets.o
TEST_BIN := $(addprefix $(BUILD)/tests/,$(notdir $(TEST_SRC:.c=)))
ifneq ($(words $(TEST_BIN)),$(words $(sort $(TEST_BIN))))
$(error two checks under tests/ share a name: $(sort $(foreach b,$(TEST_BIN),$(if $(filter-out 1,$(words $(filter $(b),$(TEST_BIN)))),$(notdir $(b))))))
endif

# As many jobs as the machine has cores, unless make was given -j (or is a
# sub-make sharing its parent's jobs).
JOBS ?= $(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
ifeq ($(findstring -j,$(MAKEFLAGS))$(findstring jobserver,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(JOBS)
endif

.PHONY: all single test test-bins check check-bins install uninstall deps clean report bench bench-run viewer \
        spirv-count
.DELETE_ON_ERROR:

# A first build ends with what it made and where (tests/repo/test_make_summary.sh).
SINGLE := ports/single/fresnel_single_f32.h ports/single/fresnel_single_q15.h ports/single/fresnel_single_f16.h
all: $(BUILD)/libfresnel.a $(BUILD)/fresnel $(SINGLE) $(BUILD)/scene_example
	@echo "built:"
	@echo "  $(BUILD)/libfresnel.a     the runtime, every number type (headers: include/)"
	@echo "  $(BUILD)/fresnel          the generator: constants and tables for a scene ($(BUILD)/fresnel help)"
	@echo "  $(BUILD)/scene_example    a program on $(SCENE)'s header, scene_default.h: gold by angle"
	@echo "  ports/single/          fresnel_single_f32.h, _q15.h, _f16.h: one type's runtime in one file"
	@echo "next: make test; make report for the error, time and instructions of every model"
	@echo "      ($(BUILD)/report/report.md; the last one made is data/report/report.md)"

# The single-file runtimes: one stb-style header per number type, made from
# include/ and src/<type>/ by ports/single.sh into ports/single/, where they
# are committed for users who vendor one file (tests/ports/test_single_file.sh
# fails when the committed copy is not what the sources give). Rewritten only
# when the text changes; builds running at once each write their own
# temporary file and move it into place.
single: $(SINGLE)
ports/single/fresnel_single_%.h: ports/single.sh $(wildcard include/*.h) $(wildcard src/*/*)
	@mkdir -p $(BUILD)/single $(@D)
	@sh ports/single.sh $* > $(BUILD)/single/$*.tmp && \
	    if cmp -s $(BUILD)/single/$*.tmp $@; then rm -f $(BUILD)/single/$*.tmp; touch $@; \
	    else mv $(BUILD)/single/$*.tmp $@ && echo "wrote $@"; fi

# The default scene: its generated header and a program built against it.
SCENE := data/scenes/default.scene
$(BUILD)/scene_default.h: $(SCENE) $(BUILD)/fresnel $(wildcard data/*.csv)
	$(BUILD)/fresnel gen $(SCENE) -o $@

$(BUILD)/scene_example: tests/ports/consumer/scene_example.c $(BUILD)/scene_default.h $(BUILD)/libfresnel.a
	$(CC) $(WARN) $(OPT) $(SAN) -Iinclude -I$(BUILD) $< $(BUILD)/libfresnel.a $(LDLIBS) -o $@

$(BUILD)/libfresnel.a: $(LIB_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

$(BUILD)/obj/src/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_LIB) -c $< -o $@

$(BUILD)/obj/gen/%.o: gen/%.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -c $< -o $@

# `fresnel viewer` carries its page template and the GLSL port inside the
# tool (gen/viewer/embed.sh), so it reads no file of the tree at run time.
$(BUILD)/embed/viewer_assets.c: ports/webgl/viewer.html ports/glsl/fresnel.glsl gen/viewer/embed.sh
	@mkdir -p $(@D)
	sh gen/viewer/embed.sh $@ viewer_page=ports/webgl/viewer.html viewer_glsl_port=ports/glsl/fresnel.glsl

$(BUILD)/obj/embed/viewer_assets.o: $(BUILD)/embed/viewer_assets.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -c $< -o $@

$(BUILD)/fresnel: $(BUILD)/obj/gen/main.o $(GEN_OBJ) $(BUILD)/libfresnel.a
	$(CC) $(SAN) -o $@ $^ $(LDLIBS)

# A program of tests/ (a check, or a helper a check runs): $(BUILD)/tests/NAME
# from NAME.c in whichever folder of tests/ holds it.
vpath test_%.c $(sort $(dir $(TEST_SRC)))
vpath gen_matrix_check.c tests/gen
vpath conform_gen.c tests/ports/cross
$(BUILD)/tests/%: %.c $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Isrc -Itests/common -o $@ $< $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)
# A test source that a dependency file names and the tree lacks is not an
# error: the program is rebuilt from its source in tests/.
tests/%.c: ;

# Programs the test scripts run, built here with the flags of this pass (so
# the sanitizer pass runs them sanitized): the fuzz targets linked with a
# replay driver (tests/fuzz/test_fuzz_replay.sh), the OSMesa GLSL test
# (tests/shader_ports/test_glsl_port_osmesa.sh), the generated-header checker (tests/gen/test_gen_matrix.sh), the
# Vulkan test (tests/shader_ports/test_vulkan.sh).
FUZZ_REPLAY := $(patsubst tests/fuzz/%.c,$(BUILD)/fuzz-replay/%,$(wildcard tests/fuzz/fuzz_*.c))
$(BUILD)/fuzz-replay/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/replay_main.c $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -DFUZZ_REPLAY -Isrc -Itests/common -Itests/fuzz -o $@ $< tests/fuzz/replay_main.c $(GEN_OBJ) \
	    $(BUILD)/libfresnel.a $(LDLIBS)
GLSL_TEST_SRC := tests/shader_ports/glsl_port_osmesa.c ports/glsl/host/glctx.c ports/glsl/host/png.c
$(BUILD)/glsl/glsl_port_osmesa: $(GLSL_TEST_SRC) $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Iports/glsl/host -Itests/common -o $@ $(GLSL_TEST_SRC) $(GEN_OBJ) $(BUILD)/libfresnel.a \
	    $$(pkg-config --cflags --libs osmesa) $(LDLIBS)
# The Vulkan test (tests/shader_ports/test_vulkan.sh): links the Vulkan loader (libvulkan-dev).
VULKAN_TEST_SRC := tests/shader_ports/vulkan_test.c ports/vulkan/vkrun.c
$(BUILD)/vulkan/vulkan_test: $(VULKAN_TEST_SRC) ports/vulkan/vkrun.h $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Iports/vulkan -Itests/common -o $@ $(VULKAN_TEST_SRC) $(GEN_OBJ) $(BUILD)/libfresnel.a -lvulkan $(LDLIBS)
# The MSL port on the host (tests/shader_ports/test_msl.sh): compiles C++ with g++ and clang++ at run time.
$(BUILD)/msl/msl_host_test: tests/shader_ports/msl_host_test.c tests/shader_ports/port_checks.h $(GEN_OBJ) \
                            $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Itests/common -o $@ $< $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)
# The shader ports' mediump contract (tests/shader_ports/test_mixed_precision.sh): C++ through the host's
# metal_stdlib map, every mediump operation binary16 or binary32 as a policy says.
MIXED_DEPS := tests/shader_ports/msl/metal_stdlib ports/msl/fresnel.metal ports/glsl/fresnel.glsl tests/common/materials.h
$(BUILD)/tests/mixed_precision: tests/shader_ports/mixed_precision.cpp $(MIXED_DEPS) $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CXX) -std=c++14 -O2 $(SAN) -Wall -Wextra -Werror -DFRESNEL_MSL_HALF -DFRESNEL_MSL_HOST_MIXED -Iports/msl \
	    -Itests/shader_ports/msl -Iinclude -Igen -Itests/common -o $@ $< $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)
# The WGSL port in a browser (tests/shader_ports/test_wgsl.sh): writes the page, then checks what it logged.
$(BUILD)/wgsl/wgsl_page_test: tests/shader_ports/wgsl_page_test.c tests/shader_ports/port_checks.h $(GEN_OBJ) \
                              $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Itests/common -o $@ $< $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)
$(BUILD)/tests/viewer_lit: tests/shader_ports/viewer_lit.c $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Itests/common -o $@ $< $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)

# make check's programs; make test's add the two that link OSMesa and Vulkan.
check-bins: $(TEST_BIN) $(BUILD)/fresnel $(BUILD)/libfresnel.a $(BUILD)/scene_example $(SINGLE) $(FUZZ_REPLAY) \
            $(BUILD)/tests/gen_matrix_check $(BUILD)/tests/viewer_lit $(BUILD)/hlsl/fresnel.hlsl \
            $(BUILD)/msl/msl_host_test $(BUILD)/msl/fresnel.metal $(BUILD)/tests/mixed_precision \
            $(BUILD)/wgsl/wgsl_page_test $(BUILD)/wgsl/fresnel.wgsl $(BUILD)/wgsl/fresnel_f16.wgsl
test-bins: check-bins $(BUILD)/glsl/glsl_port_osmesa $(BUILD)/vulkan/vulkan_test

# Every tool a test needs, from the one list in tests/deps.sh: installed with
# apt-get when run as root, else the exact apt-get line and a stop.
deps:
	@sh tests/deps.sh all

# The first pass builds in build/; the second rebuilds everything with
# sanitizers in build/asan; the third with the other compiler (-Werror, as
# always) in build/gcc or build/clang, whose tests run with CC set to it. The
# three builds share JOBS jobs; then tests/run.sh runs JOBS checks at a time
# and prints the ten slowest. The last line printed is "N passed, N failed".
OTHER_CC := $(if $(findstring clang,$(shell $(CC) --version 2>/dev/null)),gcc,clang)
# -jJOBS unless make was given its own -j (a jobserver the sub-makes share)
JFLAG     = $(if $(findstring jobserver,$(MAKEFLAGS)),,-j$(JOBS))
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
.PHONY: test-build-first test-build-sanitize test-build-other
test-build-first:
	@$(MAKE) --no-print-directory BUILD=build test-bins
test-build-sanitize:
	@$(MAKE) --no-print-directory BUILD=build/asan OPT="-O1 -g" SAN="$(SAN_FLAGS)" test-bins
test-build-other:
	@$(MAKE) --no-print-directory BUILD=build/$(OTHER_CC) CC=$(OTHER_CC) test-bins
test: deps
	@s=$$(date +%s); $(MAKE) --no-print-directory $(JFLAG) test-build-first test-build-sanitize test-build-other && \
	    echo "NOTE make test: the three builds took $$(($$(date +%s) - s)) s"
	@JOBS=$(JOBS) sh tests/run.sh first=build sanitize=build/asan other=build/$(OTHER_CC)@$(OTHER_CC)
check:
	@$(MAKE) --no-print-directory $(JFLAG) BUILD=build check-bins
	@JOBS=$(JOBS) sh tests/run.sh --check first=build

# Benchmarks, never tests: `make report` writes build/report/ (accuracy against
# the spectral ground truth, time and instructions per evaluation, plots, and
# the speed targets from `make bench` by gcc and clang at -O2 and -O3
# -march=native, saved as build/report/speed-COMPILER-*.txt), `make bench`
# prints time per evaluation against the peers' algorithms (below).
# `make spirv-count`: SPIR-V instructions per scene model (ports/vulkan/spirv_count.sh).
spirv-count: $(BUILD)/fresnel
	@sh ports/vulkan/spirv_count.sh $(BUILD)

report: $(BUILD)/fresnel
	@mkdir -p $(BUILD)/report
	$(MAKE) -s --no-print-directory BUILD=$(BUILD) cross-count > $(BUILD)/report/cross-count.txt
	$(MAKE) -s --no-print-directory BUILD=$(BUILD) size > $(BUILD)/report/size.txt
	sh ports/vulkan/spirv_count.sh $(BUILD) > $(BUILD)/report/spirv-count.txt
	for cc in $(BENCH_CCS); do \
	    $(MAKE) -s --no-print-directory BUILD=$(BUILD) CC=$$cc OPT=-O2 bench-run > $(BUILD)/report/speed-$$cc-O2.txt && \
	    $(MAKE) -s --no-print-directory BUILD=$(BUILD) CC=$$cc OPT='-O3 -march=native' bench-run \
	        > $(BUILD)/report/speed-$$cc-O3-native.txt || exit 1; \
	done
	$(BUILD)/fresnel report -o $(BUILD)/report --cross $(BUILD)/report/cross-count.txt --size $(BUILD)/report/size.txt \
	    --spirv $(BUILD)/report/spirv-count.txt \
	    $(foreach cc,$(BENCH_CCS),--speed $(BUILD)/report/speed-$(cc)-O2.txt --speed $(BUILD)/report/speed-$(cc)-O3-native.txt)
	@echo "make report: build/report/report.md (accuracy, speed, cross-target and SPIR-V counts, sizes), pareto.svg, sigma.svg, curves/;"
	@echo "             build/report/targets.md (for the developers: the project's goals, each measured and marked)"

# `make bench` times the library against the peers' algorithms and floor
# loops (tests/speed/speed.c; the file format is in gen/bench/speed_targets.h),
# built by gcc and by clang (or only by the CC given: `make bench CC=clang`)
# at -O2 and at -O3 -march=native, or only at the flag set given
# (`make bench OPT='-O3 -march=native'`). Each compiler and flag set builds
# the program, the runtime's sources and the peers in its own directory,
# with $(OPT) $(MATH_FLAGS), so no object of another flag set is reused.
# SPEED_ARGS='--rounds R' sets the number of interleaved rounds (default 41).
BENCH_CCS := $(if $(filter command line environment,$(origin CC)),$(CC),gcc clang)
SPEED_DIR := $(BUILD)/bench/$(notdir $(firstword $(CC)))$(subst =,-,$(subst $() ,,$(OPT)))
SPEED_SRC := tests/speed/speed.c tests/speed/kernels.c gen/bench/bench_compare.c gen/bench/speed_targets.c \
             $(wildcard src/f32/*.c src/q15/*.c)
SPEED_CFLAGS := $(WARN) $(OPT) $(MATH_FLAGS) -D_POSIX_C_SOURCE=200809L -Iinclude -Igen
# The thin film's table, as `fresnel gen` writes it (GEN_TOOL: the host tool
# that writes it, by default this build's).
GEN_TOOL ?= $(BUILD)/fresnel
$(SPEED_DIR)/speed_film.h: tests/speed/film.scene $(GEN_TOOL)
	@mkdir -p $(@D)
	$(GEN_TOOL) gen tests/speed/film.scene -o $@
$(SPEED_DIR)/speed: $(SPEED_SRC) $(SPEED_DIR)/speed_film.h $(wildcard tests/speed/*.h gen/bench/*.h include/*.h src/*/*.h)
	@mkdir -p $(@D)
	$(CC) $(SPEED_CFLAGS) -I$(SPEED_DIR) -DSPEED_OPT='"$(OPT)"' -DSPEED_CFLAGS='"$(CC) $(SPEED_CFLAGS)"' $(SPEED_SRC) $(LDLIBS) -o $@

bench-run: $(SPEED_DIR)/speed
	@$(SPEED_DIR)/speed $(SPEED_ARGS)

bench:
ifeq ($(origin OPT),file)
	@for cc in $(BENCH_CCS); do \
	    $(MAKE) --no-print-directory BUILD=$(BUILD) CC=$$cc OPT=-O2 bench-run && \
	    $(MAKE) --no-print-directory BUILD=$(BUILD) CC=$$cc OPT='-O3 -march=native' bench-run || exit 1; \
	done
else
	@for cc in $(BENCH_CCS); do $(MAKE) --no-print-directory BUILD=$(BUILD) CC=$$cc bench-run || exit 1; done
endif

# `make viewer`: the viewer's scene as one page, build/viewer/index.html
# (with the Cortex-M0 costs when `make report` has left its cross-count).
VIEWER_SCENE := data/scenes/viewer.scene
viewer: $(BUILD)/fresnel
	$(BUILD)/fresnel viewer $(VIEWER_SCENE) -o $(BUILD)/viewer \
	    $(if $(wildcard $(BUILD)/report/cross-count.txt),--cross $(BUILD)/report/cross-count.txt)

# DESTDIR and PREFIX reach ports/install.sh as written, any character but a
# newline kept, a $ too (make's value function: not expanded by make); each
# argument one single-quoted shell word ('it'\''s').
shell_word = '$(subst ','\'',$(1))'
install: $(BUILD)/libfresnel.a $(BUILD)/fresnel $(BUILD)/hlsl/fresnel.hlsl $(BUILD)/msl/fresnel.metal
	@sh ports/install.sh install $(call shell_word,$(value DESTDIR)) $(call shell_word,$(value PREFIX)) \
	    $(call shell_word,$(BUILD))

uninstall:
	@sh ports/install.sh uninstall $(call shell_word,$(value DESTDIR)) $(call shell_word,$(value PREFIX))

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
# The dependency files are written by the compiler, never remade by a rule.
%.d: ;

# ---- GLSL ports and OSMesa ----
include ports/glsl/glsl.mk
include ports/hlsl/hlsl.mk
include ports/msl/msl.mk
include ports/wgsl/wgsl.mk

# ---- fuzzing ----
# `make fuzz` runs each libFuzzer target tests/fuzz/fuzz_*.c for FUZZ_SECONDS
# under ASan+UBSan, starting from the committed seed corpus
# tests/fuzz/corpus/<target>/; inputs it finds go to $(BUILD)/fuzz/corpus/<target>/,
# crashes to $(BUILD)/fuzz/artifacts/<target>/. `make test` replays the seed
# corpus without libFuzzer (tests/fuzz/test_fuzz_replay.sh).
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 60
FUZZ_FLAGS   := $(WARN) -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
                -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -Igen -Itests/fuzz
# Host code the targets exercise, linked into each with the whole runtime.
FUZZ_GEN     := gen/common/reference.c gen/common/reference_targets.c gen/common/cli.c gen/1_spectral/load_nk.c \
                gen/1_spectral/resample.c gen/scene/scene.c gen/2_derive/targets.c gen/1_spectral/colour_space.c \
                gen/1_spectral/colorimetry.c gen/model/registry.c gen/model/number_type.c gen/3_encode/q15_params.c \
                gen/model/eval_ref.c gen/model/eval_f32.c gen/model/eval_q15.c gen/model/eval_f16.c gen/3_encode/encoded_eta.c \
                gen/common/reference_film.c gen/catalog/catalog.c
FUZZ_TARGETS := $(patsubst tests/fuzz/%.c,%,$(wildcard tests/fuzz/fuzz_*.c))

.PHONY: fuzz fuzz-bins
fuzz-bins: $(FUZZ_TARGETS:%=$(BUILD)/fuzz/%)

# Each source compiled once with FUZZ_FLAGS, its objects shared by the targets.
fuzz_obj = $(patsubst %.c,$(BUILD)/fuzz/obj/%.o,$(1))
$(BUILD)/fuzz/obj/%.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) -MMD -MP -c $< -o $@
$(BUILD)/fuzz/fuzz_%: $(call fuzz_obj,tests/fuzz/fuzz_%.c $(LIB_SRC) $(FUZZ_GEN))
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) $^ -lm -o $@

# clang 14 on x86-64 has no _Float16: the binary16 target and src/f16/
# are compiled by gcc (ASan, UBSan, and comparison tracing that libFuzzer's
# value profile reads) and linked into the clang-built fuzzer; the other
# sources are clang's, with full coverage.
FUZZ_GCC       ?= gcc
FUZZ_GCC_FLAGS  = $(WARN) -g -O1 $(F16_CFLAGS) -fsanitize=address,undefined -fno-sanitize-recover=all \
                  -fsanitize-coverage=trace-cmp -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -Igen -Itests/fuzz
FUZZ_F16_SRC   := tests/fuzz/fuzz_f16_models.c $(wildcard src/f16/*.c)
FUZZ_F16_OBJ   := $(FUZZ_F16_SRC:%.c=$(BUILD)/fuzz/gcc/%.o)
$(BUILD)/fuzz/gcc/%.o: %.c $(wildcard tests/fuzz/*.h) $(wildcard src/*/*.h) $(wildcard include/*.h)
	@mkdir -p $(@D)
	$(FUZZ_GCC) $(FUZZ_GCC_FLAGS) -c $< -o $@
$(BUILD)/fuzz/fuzz_f16_models: $(FUZZ_F16_OBJ) $(call fuzz_obj,tests/fuzz/gcc_cov_stubs.c \
                                $(filter-out src/f16/%,$(LIB_SRC)) $(FUZZ_GEN))
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) $^ -lm -o $@

# The end-to-end generator target links `fresnel gen` and what it calls
# (the embedded GLSL port: the WGSL back end translates it).
FUZZ_GEN_HEADER := gen/cli/cmd_gen.c $(filter-out gen/cli/cmd_%.c gen/bench/% gen/report/% gen/viewer/%,$(GEN_SRC)) \
                   $(BUILD)/embed/viewer_assets.c
$(BUILD)/fuzz/fuzz_gen_header: $(call fuzz_obj,tests/fuzz/fuzz_gen_header.c $(LIB_SRC) $(FUZZ_GEN_HEADER))
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) $^ -lm -o $@

fuzz: fuzz-bins
	@for t in $(FUZZ_TARGETS); do \
	    mkdir -p $(BUILD)/fuzz/corpus/$$t $(BUILD)/fuzz/artifacts/$$t || exit 1; \
	    echo "== $$t: $(FUZZ_SECONDS) s"; \
	    $(BUILD)/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 -use_value_profile=1 \
	        -artifact_prefix=$(BUILD)/fuzz/artifacts/$$t/ \
	        $(BUILD)/fuzz/corpus/$$t tests/fuzz/corpus/$$t 2>$(BUILD)/fuzz/$$t.log; \
	    rc=$$?; grep -E '^(stat::number_of_executed_units|stat::new_units_added|==[0-9]+==|SUMMARY|fuzz oracle|NOTE)' $(BUILD)/fuzz/$$t.log; \
	    [ $$rc -eq 0 ] || { echo "$$t: failing input in $(BUILD)/fuzz/artifacts/$$t/, log $(BUILD)/fuzz/$$t.log"; exit 1; }; \
	done

# The long pass of the worst-case searches behind the stated bounds
# (tests/common/search.h; make test runs their fast pass): each search with
# SEARCH_LONG=1, its best points rewritten into tests/data/worst_inputs/ (three
# per key, sixty per number type at most), which the fast pass replays. Minutes (the thin film's: about half an hour on two
# cores); fails when a search beats a bound, the corpus written all the same.
SEARCHES := film_search:film model_search:models q15_fast_search:fast
search: $(BUILD)/tests/test_film_search $(BUILD)/tests/test_model_search $(BUILD)/tests/test_q15_fast_search
	@status=0; for s in $(SEARCHES); do \
	    out=tests/data/worst_inputs/$${s#*:}.txt; rm -f $$out.new; \
	    echo "== test_$${s%%:*} (SEARCH_LONG=1)"; \
	    SEARCH_LONG=1 SEARCH_CORPUS_OUT=$$out.new $(BUILD)/tests/test_$${s%%:*} || status=1; \
	    sort -u $$out.new | sort -t'#' -k2 -gr | \
	        awk '{ split($$1, t, ":"); if (n[$$1]++ < 3 && m[t[1]]++ < 60) print }' | sort >$$out || status=1; \
	    rm -f $$out.new; \
	done; exit $$status
.PHONY: search

# ---- fixed point, fp16 and cross targets ----
# Everything below belongs to the fixed-point / binary16 runtime and its
# cross builds (include/fresnel_q15.h, include/fresnel_f16.h, ports/).

# _Float16 on x86-64 without F16C converts through libgcc (__extendhfsf2,
# __truncsfhf2): with -mf16c each conversion is one instruction, the values
# are the same, and the library still references only libm. (F16C: every
# x86-64 CPU since 2012.)
F16_CFLAGS := $(if $(findstring x86_64,$(shell $(CC) -dumpmachine 2>/dev/null)),-mf16c)
$(BUILD)/obj/src/f16/%.o: CFLAGS_LIB += $(F16_CFLAGS)

# The exhaustive fixed-point test links its own copy of the fixed-point
# sources built with FRESNEL_RANGE_CHECK, which turns the range analysis in
# the sources (FRESNEL_I_RANGE) into checks; linked before libfresnel.a, these
# objects provide every fixed-point symbol, so no archive member is pulled.
Q15_SRC := $(wildcard src/q15/*.c)
Q15_RC_OBJ := $(Q15_SRC:%.c=$(BUILD)/obj/rc/%.o)
$(BUILD)/obj/rc/src/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_LIB) -DFRESNEL_RANGE_CHECK -c $< -o $@
$(BUILD)/tests/test_q15_bounds: tests/runtime/q15/test_q15_bounds.c $(Q15_RC_OBJ) $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Isrc -Itests/common -o $@ $< $(Q15_RC_OBJ) $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)

# Cross builds (ports/, ports/cross.sh): the fixed-point conformance program
# run under qemu on a Cortex-M0, a Cortex-M4F and an RV32IMC, compared bit for
# bit with the host; symbol checks of the fixed-point-only Cortex-M0 build;
# instructions per call (and on AArch64 Linux, the mobile toolchains' target,
# the binary32 runtime's); code size per model, type and target.
#   make cross-test    what tests/ports/test_cross.sh runs (PASS/FAIL lines)
#   make cross-count   instructions per call (qemu -singlestep traces), Cortex-M0 cycles;
#                      AArch64 binary32 and its NEON batches, gcc and clang at -O2, -O3
#   make size          .text/.rodata per model and type, Cortex-M0/M4F, RV32IMC
# cross-deps installs the missing Debian packages of tests/deps.sh's cross rows.
.PHONY: cross-deps cross-data cross-test cross-count size
cross-deps:
	@sh tests/deps.sh cross

$(BUILD)/cross/conform_data.c: $(BUILD)/tests/conform_gen
	@mkdir -p $(@D)
	$< > $@.tmp && mv $@.tmp $@
cross-data: $(BUILD)/cross/conform_data.c

# Every cos code on the Cortex-M0; on the Cortex-M4F, the Cortex-M55 and
# the RV32IMC every code within 64 of 0 and one and every CROSS_STRIDE-th
# between, from CROSS_OFFSET: the day's number modulo the stride, so that
# CROSS_STRIDE days of runs cover every code there too (CROSS_STRIDE=1:
# every code). The four in parallel.
CROSS_STRIDE ?= 4
CROSS_OFFSET ?= $(shell echo $$(( $$(date +%s) / 86400 % $(CROSS_STRIDE) )))
cross-test: cross-deps cross-data
	@d=$(BUILD)/cross; \
	BUILD=$(BUILD) sh ports/cross.sh conform m0 1 >$$d/m0.log 2>&1 & \
	BUILD=$(BUILD) sh ports/cross.sh conform m4f $(CROSS_STRIDE) $(CROSS_OFFSET) >$$d/m4f.log 2>&1 & \
	BUILD=$(BUILD) sh ports/cross.sh conform m55 $(CROSS_STRIDE) $(CROSS_OFFSET) >$$d/m55.log 2>&1 & \
	BUILD=$(BUILD) sh ports/cross.sh conform rv32 $(CROSS_STRIDE) $(CROSS_OFFSET) >$$d/rv32.log 2>&1 & \
	wait; cat $$d/m0.log $$d/m4f.log $$d/m55.log $$d/rv32.log
	@BUILD=$(BUILD) sh ports/cross.sh nm

cross-count: cross-deps cross-data
	@for t in m0 m4f m55 rv32; do \
	    echo "== $$t fixed point: per call over 3 materials x 3 cosine sets x 17 cosines (tests/ports/cross/bench.c):" \
	        "instructions mean min max$$( [ $$t = m0 ] && echo '; Cortex-M0 cycles, 1-cycle MULS: mean min max; 32-cycle MULS: mean min max')"; \
	    BUILD=$(BUILD) sh ports/cross.sh count $$t | awk -F'\t' '{ printf "%-28s %6s %6s %6s", $$1, $$2, $$3, $$4; \
	        if (NF >= 10) printf "   %6s %6s %6s   %6s %6s %6s", $$5, $$6, $$7, $$8, $$9, $$10; printf "\n" }' || exit 1; \
	done
	@for t in m0 m4f; do \
	    echo "== $$t binary32 and binary16 (newlib libm$$( [ $$t = m0 ] && echo ', soft-float')), copper at 550 nm, 33 cosines: instructions mean min max$$( [ $$t = m0 ] && echo '; Cortex-M0 cycles, 1-cycle MULS: mean min max; 32-cycle MULS: mean min max')"; \
	    BUILD=$(BUILD) sh ports/cross.sh count $$t float | awk -F'\t' '{ printf "%-28s %6d %6d %6d", $$1, $$2, $$3, $$4; \
	        if (NF >= 10) printf "   %6d %6d %6d   %6d %6d %6d", $$5, $$6, $$7, $$8, $$9, $$10; printf "\n" }' || exit 1; \
	done
	@for cc in gcc clang; do for opt in -O2 -O3; do \
	    echo "== a64 binary32, AArch64 NEON, $$cc $$opt (qemu-aarch64 user mode, static glibc libm), copper at 550 nm, 33 cosines:" \
	        "instructions mean min max; the batches per cosine, in calls of 256 cosines"; \
	    BUILD=$(BUILD) sh ports/cross.sh count a64 $$cc $$opt | awk -F'\t' '{ printf "%-28s %6s %6s %6s\n", $$1, $$2, $$3, $$4 }' || exit 1; \
	done; done

# make measure FILE=prog.c [TARGET=m0|m4f|m55|rv32] [INCLUDE=dir]: a
# firmware's own program, built with the fixed-point runtime for TARGET
# (default m0) and run under qemu; the instructions between its first two
# port_mark calls (Cortex-M0: and cycles), and the library bytes it links
# (ports/README.md, "Firmware"). Builds only that program, and checks (as
# root: installs) only TARGET's toolchain and emulator (tests/deps.sh TARGET).
TARGET ?= m0
.PHONY: measure
measure:
	@test -n "$(FILE)" || { echo "make measure: FILE=prog.c is required" >&2; exit 2; }
	@sh tests/deps.sh $(TARGET)
	@BUILD=$(BUILD) sh ports/cross.sh measure $(TARGET) $(FILE) $(if $(INCLUDE),-I$(INCLUDE))

size: cross-deps cross-data
	@BUILD=$(BUILD) sh ports/cross.sh size
