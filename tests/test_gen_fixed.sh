#!/bin/sh
# passes: first other (the fixed-point runtime's own tests run under the sanitizers)
# `fresnel gen` for `types = f32 q15`: the header compiles
# warning-free with the fixed-point header, a q15-only scene emits no float
# constants, and every Q1.15 constant evaluates like its f32 twin.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"
printf 'materials = cu au al\nmodels = schlick f82 lsk lsk-comp gulbrandsen cook-torrance exact exact-gaussian approx-conductor lut32 lut16-residual lut16-cubic\ntypes = f32 q15\n' >"$t/fx.scene"
if "$F" gen "$t/fx.scene" -o "$t/scene_fx.h" 2>"$t/err" &&
    cc $W -O2 -Iinclude -I"$t" tests/consumer/scene_fixed_check.c "$BUILD/libfresnel.a" -lm -o "$t/check" 2>"$t/cc" &&
    [ ! -s "$t/cc" ]; then
    echo "PASS gen q15: a types = f32 q15 header compiles warning-free against fresnel_fixed.h"
    "$t/check"
else
    echo "FAIL gen q15: $(cat "$t/err" "$t/cc" | head -8)"
fi
printf 'materials = cu\nmodels = schlick lut16\ntypes = q15\n' >"$t/q.scene"
"$F" gen "$t/q.scene" -o "$t/q.h" 2>"$t/err"
if grep -q 'fresnel_q_cu_f0_q15' "$t/q.h" && grep -q 'fresnel_q_cu_lut16_q15' "$t/q.h" &&
    ! grep -qE 'static const (fresnel_rgb|float) ' "$t/q.h"; then
    echo "PASS gen q15: a q15-only scene holds only Q1.15 constants (no float)"
else
    echo "FAIL gen q15: q15-only scene: $(grep 'static const' "$t/q.h" | cut -c1-80)"
fi
