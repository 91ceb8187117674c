# Fresnel reflectance library: runtime (src/, include/), host tools (gen/), tests.
#   make          build the library and build/fresnel, run the main job
#   make test     unit and error-bound tests, then again under ASan+UBSan
#   make install  PREFIX=/usr/local DESTDIR=   headers, libfresnel.a, fresnel.pc

CC      ?= cc
AR      ?= ar
BUILD   ?= build
OPT     ?= -O2
SAN     ?=
PREFIX  ?= /usr/local
DESTDIR ?=

WARN       := -std=c99 -Wall -Wextra -Wpedantic -Werror
CFLAGS_LIB := $(WARN) $(OPT) $(SAN) -Iinclude -MMD -MP
CFLAGS_GEN := $(WARN) $(OPT) $(SAN) -D_POSIX_C_SOURCE=200809L -DFRESNEL_DATA_DIR=\"$(CURDIR)/data\" -Iinclude -Isrc -Igen -MMD -MP
LDLIBS     := -lm

LIB_SRC  := $(wildcard src/*.c)
GEN_SRC  := $(filter-out gen/main.c,$(wildcard gen/*.c))
TEST_SRC := $(wildcard tests/test_*.c)
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
GEN_OBJ  := $(GEN_SRC:%.c=$(BUILD)/obj/%.o)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)

.PHONY: all main-job test test-bins install clean
.DELETE_ON_ERROR:

all: $(BUILD)/libfresnel.a $(BUILD)/fresnel
	@$(MAKE) --no-print-directory main-job

main-job: $(BUILD)/fresnel $(BUILD)/scene_example
	$(BUILD)/fresnel accuracy
	$(BUILD)/scene_example

# The default scene: its generated header and a program built against it.
SCENE := data/scenes/default.scene
$(BUILD)/scene_default.h: $(SCENE) $(BUILD)/fresnel $(wildcard data/*.csv)
	$(BUILD)/fresnel gen $(SCENE) -o $@

$(BUILD)/scene_example: tests/consumer/scene_example.c $(BUILD)/scene_default.h $(BUILD)/libfresnel.a
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

$(BUILD)/fresnel: $(BUILD)/obj/gen/main.o $(GEN_OBJ) $(BUILD)/libfresnel.a
	$(CC) $(SAN) -o $@ $^ $(LDLIBS)

$(BUILD)/tests/%: tests/%.c $(GEN_OBJ) $(BUILD)/libfresnel.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_GEN) -Itests -o $@ $< $(GEN_OBJ) $(BUILD)/libfresnel.a $(LDLIBS)

test-bins: $(TEST_BIN) $(BUILD)/fresnel $(BUILD)/libfresnel.a $(BUILD)/scene_example

# The second pass rebuilds everything with sanitizers in build/asan; the last
# line printed is "N passed, N failed".
test:
	@$(MAKE) --no-print-directory test-bins
	@$(MAKE) --no-print-directory BUILD=build/asan OPT="-O1 -g" \
	    SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" test-bins
	@sh tests/run.sh build build/asan

install: $(BUILD)/libfresnel.a
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/fresnel.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(BUILD)/libfresnel.a $(DESTDIR)$(PREFIX)/lib/
	v=`sed -n 's/^#define FRESNEL_VERSION "\(.*\)"/\1/p' include/fresnel.h`; \
	printf 'prefix=%s\nincludedir=$${prefix}/include\nlibdir=$${prefix}/lib\n\nName: fresnel\nDescription: Fresnel reflectance for small devices\nVersion: %s\nCflags: -I$${includedir}\nLibs: -L$${libdir} -lfresnel -lm\n' \
	    '$(PREFIX)' "$$v" > $(DESTDIR)$(PREFIX)/lib/pkgconfig/fresnel.pc

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# ---- GLSL ports and OSMesa (issue 6) ----
include ports/glsl/glsl.mk
