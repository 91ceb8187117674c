#!/bin/sh
# passes: first (OSMesa runs the same shaders in every pass)
# make check: no (OSMesa)
# The GLSL port in a real GL pipeline: runs tests/shader_ports/glsl_port_osmesa.c, built by make
# test-bins against OSMesa and $BUILD/libfresnel.a into $BUILD/glsl/. Its
# own link line (pkg-config osmesa) is why it is not a test_*.c check.
# A missing OSMesa is a failure, not a skip: .ci/run installs it.
BUILD=${BUILD:-build}
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
if [ ! -x "$out/glsl_port_osmesa" ]; then
    echo "FAIL glsl: $out/glsl_port_osmesa not built (make test-bins builds it)"
    exit 1
fi
# Mesa's shader cache in build/ rather than the user's home; the second
# (sanitizer) pass then finds the shaders compiled.
MESA_SHADER_CACHE_DIR="${BUILD%%/*}/mesa-shader-cache" ASAN_OPTIONS=detect_leaks=0 \
    "$out/glsl_port_osmesa" ports/glsl
