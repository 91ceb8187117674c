#!/bin/sh
# The GLSL port in a real GL pipeline: builds tests/glsl_test.c
# against OSMesa and $BUILD/libfresnel.a into $BUILD/glsl/ and runs it. Its
# own link line (pkg-config osmesa) is why it is not a tests/test_*.c.
# A missing OSMesa is a failure, not a skip: .ci/run installs it.
BUILD=${BUILD:-build}
CC=${CC:-cc}
out="$BUILD/glsl"
if [ ! -f /usr/include/GL/osmesa.h ] || ! pkg-config --exists osmesa 2>/dev/null; then
    echo "FAIL glsl: OSMesa not found (GL/osmesa.h, osmesa.pc): install Debian's libosmesa6-dev" \
        "(apt-get install libosmesa6-dev; .ci/run does this)"
    exit 1
fi
if [ ! -f "$BUILD/libfresnel.a" ]; then
    echo "FAIL glsl: $BUILD/libfresnel.a missing (make test builds it first)"
    exit 1
fi
# The sanitizer pass's library needs the sanitizer runtime at link time.
san=
if nm "$BUILD/libfresnel.a" 2>/dev/null | grep -q '__asan_'; then
    san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
fi
mkdir -p "$out"
# shellcheck disable=SC2086,SC2046
if ! $CC -std=c99 -Wall -Wextra -Wpedantic -Werror -O1 -g $san -Iinclude -Igen -Iports/glsl/host -Itests \
    -o "$out/glsl_test" tests/glsl_test.c ports/glsl/host/glctx.c ports/glsl/host/png.c gen/model/reference.c "$BUILD/libfresnel.a" \
    $(pkg-config --cflags --libs osmesa) -lm >"$out/build.log" 2>&1; then
    echo "FAIL glsl: tests/glsl_test.c does not build:"
    cat "$out/build.log"
    exit 1
fi
# Mesa's shader cache in build/ rather than the user's home; the second
# (sanitizer) pass then finds the shaders compiled.
MESA_SHADER_CACHE_DIR="${BUILD%%/*}/mesa-shader-cache" ASAN_OPTIONS=detect_leaks=0 \
    "$out/glsl_test" ports/glsl
