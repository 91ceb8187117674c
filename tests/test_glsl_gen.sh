#!/bin/sh
# `fresnel gen --glsl` (issue 6): the default scene as GLSL compiles after the
# port and evaluates on the GPU to the C runtime's values from the C header
# of the same manifest. Needs OSMesa, like tests/test_glsl.sh.
BUILD=${BUILD:-build}
CC=${CC:-cc}
out="$BUILD/glsl"
if [ ! -f /usr/include/GL/osmesa.h ] || ! pkg-config --exists osmesa 2>/dev/null; then
    echo "FAIL glsl gen: OSMesa not found: install Debian's libosmesa6-dev (.ci/run does this)"
    exit 1
fi
mkdir -p "$out"
if ! "$BUILD/fresnel" gen data/scenes/default.scene --glsl -o "$out/scene_default.glsl" 2>"$out/gen.log"; then
    echo "FAIL glsl gen: fresnel gen --glsl: $(cat "$out/gen.log")"
    exit 1
fi
grep -q 'f[,)]' "$out/scene_default.glsl" && echo "FAIL glsl gen: a C float suffix in the GLSL output" ||
    echo "PASS glsl gen: no C float suffixes in the GLSL output"
san=
if nm "$BUILD/libfresnel.a" 2>/dev/null | grep -q '__asan_'; then
    san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
fi
# shellcheck disable=SC2086,SC2046
if ! $CC -std=c99 -Wall -Wextra -Wpedantic -Werror -O1 -g $san -Iinclude -Iports/glsl/host -Itests -I"$BUILD" \
    -o "$out/glsl_gen_test" tests/glsl_gen_test.c ports/glsl/host/glctx.c "$BUILD/libfresnel.a" \
    $(pkg-config --cflags --libs osmesa) -lm >"$out/gen_build.log" 2>&1; then
    echo "FAIL glsl gen: tests/glsl_gen_test.c does not build:"
    cat "$out/gen_build.log"
    exit 1
fi
MESA_SHADER_CACHE_DIR="${BUILD%%/*}/mesa-shader-cache" ASAN_OPTIONS=detect_leaks=0 \
    "$out/glsl_gen_test" ports/glsl "$out/scene_default.glsl"
