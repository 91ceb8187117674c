#!/bin/sh
# passes: first other (the fixed-point runtime's own tests run under the sanitizers)
# A q15-only scene header as a firmware uses it: it includes the fixed-point
# header only (not the binary32 fresnel.h), so it builds with include/'s
# fresnel_fixed*.h and fresnel_config.h alone, or after fresnel_single_q15.h
# with no include/ at all; and the three-channel fast paths
# (fresnel_f82_q15_rgb_fast, fresnel_conductor_q15_rgb_fast) take its F0,
# F82 a and fast conductor constants as emitted (tests/ports/consumer/scene_fast_rgb.c).
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"
printf 'materials = au cu\nmodels = schlick f82 exact\ntypes = q15\n' >"$t/metals.scene"
if ! "$F" gen "$t/metals.scene" -o "$t/metals.h" 2>"$t/err"; then
    echo "FAIL gen q15 scene: $(head -3 "$t/err")"
    exit 1
fi
includes=$(grep '^#include' "$t/metals.h" | tr '\n' ' ')
if [ "$includes" = '#include "fresnel_q15.h" ' ]; then
    echo "PASS a q15-only scene header includes fresnel_q15.h only"
else
    echo "FAIL a q15-only scene header includes: $includes"
fi
# include/ without the binary32 header
mkdir "$t/fixed"
cp include/fresnel_q15.h include/fresnel_q15_fast.h include/fresnel_config.h "$t/fixed/"
if ${CC:-cc} $W -O2 -I"$t/fixed" -I"$t" tests/ports/consumer/scene_fast_rgb.c "$BUILD/libfresnel.a" -lm -o "$t/check" 2>"$t/cc" &&
    [ ! -s "$t/cc" ]; then
    echo "PASS the q15 scene header builds with fresnel_q15.h, fresnel_q15_fast.h and fresnel_config.h alone"
    "$t/check"
else
    echo "FAIL the q15 scene header without fresnel.h: $(head -5 "$t/cc")"
fi
# the single-file runtime, no include/
mkdir "$t/single"
sh ports/single.sh q15 >"$t/single/fresnel_single_q15.h"
if ${CC:-cc} $W -O2 -DFRESNEL_SINGLE -I"$t/single" -I"$t" tests/ports/consumer/scene_fast_rgb.c -lm -o "$t/check1" 2>"$t/cc" &&
    [ ! -s "$t/cc" ]; then
    echo "PASS the q15 scene header builds after fresnel_single_q15.h, without include/"
    "$t/check1" | sed 's/^\(PASS\|FAIL\) /\1 fresnel_single_q15.h: /'
else
    echo "FAIL the q15 scene header with fresnel_single_q15.h: $(head -5 "$t/cc")"
fi
