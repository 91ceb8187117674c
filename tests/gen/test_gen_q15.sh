#!/bin/sh
# passes: first other (the fixed-point runtime's own tests run under the sanitizers)
# `fresnel gen` for `types = f32 q15`: the header compiles
# warning-free with the fixed-point header, a q15-only scene emits no float
# constants, every Q1.15 constant evaluates like its f32 twin, and the exact
# conductor's fast-path constants of two user files are the host's
# (tests/gen/gen_fast_check.c).
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"
printf 'materials = cu au al\nmodels = schlick f82 lsk lsk-comp gulbrandsen cook-torrance exact exact-gaussian approx-conductor lut32 lut16-residual lut16-cubic\ntypes = f32 q15\n' >"$t/fx.scene"
if "$F" gen "$t/fx.scene" -o "$t/scene_fx.h" 2>"$t/err" &&
    cc $W -O2 -Iinclude -I"$t" tests/ports/consumer/scene_q15_check.c "$BUILD/libfresnel.a" -lm -o "$t/check" 2>"$t/cc" &&
    [ ! -s "$t/cc" ]; then
    echo "PASS gen q15: a types = f32 q15 header compiles warning-free against fresnel_fixed.h"
    "$t/check"
else
    echo "FAIL gen q15: $(cat "$t/err" "$t/cc" | head -8)"
fi
# gamut = keep takes gold's red F0 above 1; the fast paths, which take f0
# only up to one, must still get an F0 they can take from the header:
# every cos code, results in [0, one] within their bounds, under UBSan with
# unsigned wrap-around trapped (clang; gcc has no such check).
printf 'materials = au cu\nmodels = schlick f82\ntypes = q15\ngamut = keep\n' >"$t/keep.scene"
san="-fsanitize=undefined -fno-sanitize-recover=all"
command -v clang >/dev/null && kcc=clang && san="-fsanitize=undefined,unsigned-integer-overflow -fno-sanitize-recover=all"
if "$F" gen "$t/keep.scene" -o "$t/scene_keep.h" 2>"$t/err" &&
    ${kcc:-cc} $W -O1 -g $san -Iinclude -I"$t" tests/ports/consumer/scene_keep_fast_check.c -lm -o "$t/keep" 2>"$t/cc" &&
    [ ! -s "$t/cc" ]; then
    if ! "$t/keep" 2>"$t/ub" || [ -s "$t/ub" ]; then
        echo "FAIL gen keep: the fast paths on the keep scene's constants: $(head -3 "$t/ub")"
    fi
else
    echo "FAIL gen keep: $(cat "$t/err" "$t/cc" | head -8)"
fi
printf 'materials = cu\nmodels = schlick lut16\ntypes = q15\n' >"$t/q.scene"
"$F" gen "$t/q.scene" -o "$t/q.h" 2>"$t/err"
if grep -q 'fresnel_q_cu_f0_q15' "$t/q.h" && grep -q 'fresnel_q_cu_lut16_q15' "$t/q.h" &&
    ! grep -qE 'static const (fresnel_rgb|float) ' "$t/q.h"; then
    echo "PASS gen q15: a q15-only scene holds only Q1.15 constants (no float)"
else
    echo "FAIL gen q15: q15-only scene: $(grep 'static const' "$t/q.h" | cut -c1-80)"
fi
# Two user materials of constant n, k whose fast-path constants take one word
# at every code while a0 + c^2 is -32767 at one code (c = 4815, 25616).
n1=1.7668102256209994 k1=1.4640124426721695 n2=6.552184082229366 k2=6.5225902857269098
printf 'wavelength_nm,n,k\n360,%s,%s\n830,%s,%s\n' $n1 $k1 $n1 $k1 >"$t/rep1.csv"
printf 'wavelength_nm,n,k\n360,%s,%s\n830,%s,%s\n' $n2 $k2 $n2 $k2 >"$t/rep2.csv"
printf 'material rep1 = rep1.csv\nmaterial rep2 = rep2.csv\nmodels = exact\ntypes = f32 q15\n' >"$t/rep.scene"
if "$F" gen "$t/rep.scene" -o "$t/scene_rep.h" 2>"$t/err" &&
    cc $W -O2 -Iinclude -Igen -I"$t" -DREP1_N=$n1 -DREP1_K=$k1 -DREP2_N=$n2 -DREP2_K=$k2 tests/gen/gen_fast_check.c \
        "$BUILD/obj/gen/3_encode/q15_params.o" "$BUILD/obj/gen/common/reference.o" "$BUILD/libfresnel.a" -lm \
        -o "$t/fast" 2>"$t/cc" && [ ! -s "$t/cc" ]; then
    "$t/fast"
else
    echo "FAIL gen q15: user materials for the exact fast path: $(cat "$t/err" "$t/cc" | head -8)"
fi
