#!/bin/sh
# `fresnel gen`, `curve`, `params` contracts: the emitted header
# compiles warning-free and holds only what the scene names, output is
# byte-identical for identical input, manifest errors give file:line, exit 2
# and leave no file behind.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"

"$F" gen data/scenes/default.scene -o "$t/a.h" && "$F" gen data/scenes/default.scene -o "$t/b.h"
if cmp -s "$t/a.h" "$t/b.h" && [ -s "$t/a.h" ]; then echo "PASS gen: byte-identical output for identical input"
else echo "FAIL gen: two runs differ or are empty"; fi
for cc in gcc clang; do
    printf '#include "a.h"\nint main(void) { return fresnel_default_au_f0.r > 0.5f ? 0 : 1; }\n' >"$t/use.c"
    if $cc $W -Iinclude -I"$t" "$t/use.c" -o "$t/use" 2>"$t/cc" && [ ! -s "$t/cc" ] && "$t/use"; then
        echo "PASS gen: default scene header compiles warning-free with $cc (-Werror) and is usable"
    else
        echo "FAIL gen: header with $cc: $(head -5 "$t/cc")"
    fi
done

printf 'materials = cu\nmodels = schlick\n' >"$t/only.scene"
"$F" gen "$t/only.scene" -o "$t/only.h" 2>"$t/err"
consts=$(grep -c '^static const' "$t/only.h")
if [ "$consts" -eq 1 ] && grep -q 'fresnel_only_cu_f0 ' "$t/only.h" && ! grep -qE 'fresnel_only_(au|cu_f82|cu_eta|cu_lut)' "$t/only.h"; then
    echo "PASS gen: a Schlick-only, copper-only scene emits exactly one constant (cu F0)"
else
    echo "FAIL gen: schlick-only scene emitted $consts constants: $(grep '^static const' "$t/only.h" | cut -c1-80)"
fi
# f_avg = yes adds each material's F_avg (binary32 and Q1.15), the value
# `fresnel params` prints; gamut = keep carries gold's red above 1 into the
# constants and the curve tables, which the runtimes return.
printf 'materials = au cu\nmodels = schlick lut16-cubic\ntypes = f32 q15\ngamut = keep\nf_avg = yes\n' >"$t/keep.scene"
"$F" gen "$t/keep.scene" -o "$t/keep.h" 2>"$t/err"
pavg=$("$F" params --material au --gamut keep | grep '^f_avg,' | cut -d, -f2)
havg=$(grep 'fresnel_keep_au_f_avg FRESNEL' "$t/keep.h" | sed 's/.*{\([0-9.]*\)f.*/\1/')
if grep -q 'fresnel_keep_au_f_avg_q15' "$t/keep.h" && awk -v a="$pavg" -v b="$havg" 'BEGIN { exit !(a > 1.02 && (a - b < 1e-6 && b - a < 1e-6)) }'; then
    echo "PASS gen: f_avg = yes emits F_avg (f32 and Q15); under keep gold's red is $havg, as fresnel params prints"
else
    echo "FAIL gen f_avg: params '$pavg', header '$havg', $(head -2 "$t/err")"
fi
cat >"$t/keep_use.c" <<'EOF2'
#include "keep.h"
int main(void)
{
    fresnel_rgb f = fresnel_lut_cubic_rgb(fresnel_keep_au_lut16_cubic, 16, 1.0f);
    fresnel_rgb_q15 q = fresnel_lut_cubic_u16_q15_rgb(fresnel_keep_au_lut16_cubic_q15, 16, FRESNEL_ONE_Q15);
    fresnel_rgb g = fresnel_lut_cubic_rgb(fresnel_keep_au_lut16_cubic, 16, 0.0f);
    /* red above 1 at normal incidence in both runtimes, white at grazing */
    return f.r > 1.03f && f.r < 1.045f && q.r > 33700 && q.r < 34300 && g.r > 0.9999f && g.r < 1.0001f && f.g < 1.0f ? 0 : 1;
}
EOF2
if cc $W -Iinclude -I"$t" "$t/keep_use.c" src/f32/*.c src/q15/*.c -lm -o "$t/keep_use" 2>"$t/cc" && "$t/keep_use"; then
    echo "PASS gen: gamut = keep tables return gold's red above 1 in binary32 and Q1.15"
else
    echo "FAIL gen keep tables: $(head -3 "$t/cc")"
fi
printf 'materials = ag al\nmodels = f82 lut16-residual lsk-comp gulbrandsen cook-torrance exact-gaussian approx-conductor lsk exact lut8\nlut_spacing = uniform\n' >"$t/all.scene"
if "$F" gen "$t/all.scene" -o "$t/all.h" 2>"$t/err" &&
    printf '#include "all.h"\nint main(void) { return 0; }\n' >"$t/all.c" &&
    gcc $W -Iinclude -I"$t" "$t/all.c" -o "$t/all" 2>"$t/cc" && [ ! -s "$t/cc" ] &&
    grep -q fresnel_all_al_lut16_residual "$t/all.h" && grep -q fresnel_all_ag_gulbrandsen_g "$t/all.h" &&
    grep -q 'fresnel_lut_linear_residual_rgb' "$t/all.h"; then
    echo "PASS gen: every model, uniform spacing, compiles warning-free"
else
    echo "FAIL gen: all-models scene: $(cat "$t/err" "$t/cc" | head -5)"
fi

expect_gen_error() { # name, manifest text, expected stderr pattern
    printf "$2" >"$t/bad.scene"
    rm -f "$t/out.h"
    "$F" gen "$t/bad.scene" -o "$t/out.h" 2>"$t/err"
    rc=$?
    left=$(ls "$t" | grep -c 'out.h')
    if [ "$rc" -eq 2 ] && grep -qE -e "$3" "$t/err" && [ "$left" -eq 0 ]; then
        echo "PASS gen rejects $1 ($(head -1 "$t/err" | sed "s|$t/||"))"
    else
        echo "FAIL gen $1: exit $rc, files left $left, stderr '$(cat "$t/err")'"
    fi
}
expect_gen_error "an unknown material" 'models = schlick\nmaterials = au unobtainium\n' 'bad.scene:2: unknown material .unobtainium'
expect_gen_error "an unknown model" 'materials = au\nmodels = schlick fresnel9\n' 'bad.scene:2: .*fresnel9'
expect_gen_error "an unknown space" 'materials = au\nmodels = schlick\nspace = cmyk\n' 'bad.scene:3: .*cmyk'
expect_gen_error "an unknown key" 'materials = au\nmodels = schlick\ncolour = red\n' 'bad.scene:3: .*colour'
expect_gen_error "a duplicate key" 'materials = au\nmodels = schlick\nmaterials = cu\n' 'bad.scene:3: .*materials.*line 1'
expect_gen_error "a malformed number" 'materials = au\nmodels = schlick\nsigma = 2x5\n' 'bad.scene:3: .*2x5'
expect_gen_error "an unknown gamut policy" 'materials = au\nmodels = schlick\ngamut = mapp\n' "bad.scene:3: expected a gamut policy .*did you mean 'map'"
expect_gen_error "a bad f_avg value" 'materials = au\nmodels = schlick\nf_avg = true\n' 'bad.scene:3: expected a f_avg value'
expect_gen_error "an unknown type" 'materials = au\nmodels = schlick\ntypes = f32 f128\n' 'bad.scene:3: .*f128'
"$F" gen "$t/missing.scene" -o "$t/out.h" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$t/out.h" ] && grep -q 'missing.scene' "$t/err" &&
    echo "PASS gen rejects a missing manifest ($(head -1 "$t/err" | sed "s|$t/||"))" || echo "FAIL gen missing manifest: exit $rc"
echo 'stale' >"$t/keep.h"
printf 'materials = au nope\nmodels = schlick\n' >"$t/bad.scene"
"$F" gen "$t/bad.scene" -o "$t/keep.h" 2>/dev/null
[ "$(cat "$t/keep.h")" = stale ] && [ -z "$(ls "$t" | grep 'keep.h.tmp')" ] &&
    echo "PASS gen: a failed run leaves an existing output untouched and no temp file" || echo "FAIL gen: output clobbered or temp left"

"$F" curve --material cu --space srgb --samples 7 >"$t/curve.csv"
head -1 "$t/curve.csv" | grep -q '^theta_deg,cos,gt_r,gt_g,gt_b,unclipped_r,unclipped_g,unclipped_b,schlick_r,schlick_g,schlick_b,' &&
    [ "$(wc -l <"$t/curve.csv")" -eq 8 ] && sed -n 2p "$t/curve.csv" | grep -q '^0,1,' && tail -1 "$t/curve.csv" | grep -q '^90,0,1,1,1,1,1,1' &&
    echo "PASS curve: header, N rows from 0 to 90 degrees, GT white at grazing" || echo "FAIL curve: $(head -2 "$t/curve.csv" | cut -c1-120)"
n=$(head -1 "$t/curve.csv" | tr ',' '\n' | wc -l)
[ "$n" -eq $((8 + 3 * 11)) ] && echo "PASS curve: 11 default models x 3 channels" || echo "FAIL curve: $n columns"
"$F" params --material au --space display-p3 --sigma 12 >"$t/p.csv"
for k in dominant_nm f0_unclamped f0 f82 eta_gaussian kappa_gaussian eta_fit kappa_fit lsk_a lsk_alpha gulbrandsen_r gulbrandsen_g cook_torrance_eta; do
    grep -q "^$k," "$t/p.csv" || missing="$missing $k"
done
[ -z "$missing" ] && echo "PASS params prints every derived parameter" || echo "FAIL params missing:$missing"
"$F" curve --material nope 2>"$t/err" >/dev/null; rc=$?
[ "$rc" -eq 2 ] && grep -q "unknown material 'nope'" "$t/err" && echo "PASS curve: unknown material, exit 2" || echo "FAIL curve unknown material: $rc"
"$F" params --material au --space nope 2>"$t/err" >/dev/null; rc=$?
[ "$rc" -eq 2 ] && grep -q "nope" "$t/err" && echo "PASS params: unknown space, exit 2" || echo "FAIL params unknown space: $rc $(cat "$t/err")"
