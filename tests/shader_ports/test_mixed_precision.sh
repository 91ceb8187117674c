#!/bin/sh
# passes: first (the emulation is the same C++ in every pass; a sanitized run takes minutes)
# The shader ports' mediump contract: the mediump-safe functions of
# ports/glsl/fresnel.glsl with every operation done in binary16 or binary32
# as a policy says (all binary16, all binary32, random, adversarial; with and
# without flushing binary16 subnormals), on every binary16 cosine and the
# binary16 material set, within their FRESNEL_MP_BOUND_* (the program:
# tests/shader_ports/mixed_precision.cpp, built by make check-bins).
# The table of ports/glsl/README.md:
#   BUILD=build sh tests/shader_ports/test_mixed_precision.sh | sed -n 's/^NOTE table //p'
BUILD=${BUILD:-build}
if [ ! -x "$BUILD/tests/mixed_precision" ]; then
    echo "FAIL mixed precision: $BUILD/tests/mixed_precision not built (make check-bins builds it)"
    exit 1
fi
exec "$BUILD/tests/mixed_precision"
