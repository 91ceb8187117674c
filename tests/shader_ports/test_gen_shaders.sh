#!/bin/sh
# passes: all (the shader back ends of the tool, under ASan+UBSan in the sanitize pass)
# make check: no (its outputs are test_gen_identity.sh's, byte for byte, in make check; this one runs the back ends under ASan+UBSan and their bad input in make test)
# `fresnel gen --glsl` (with --tables), `--hlsl`, `--msl`, `--wgsl` and `--wgsl-f16` on every committed
# scene and every scene of the shader tests (tests/data/scenes/): exit 0, and a
# function per material and model. Bad input for either back end: a clear
# error, exit 2, existing outputs untouched, no temporary left. What the
# shaders compute is checked in the first pass, where the work of OSMesa,
# glslangValidator and lavapipe is the same in every pass
# (tests/shader_ports/test_glsl_generated_osmesa.sh, tests/shader_ports/test_glsl_generated_glslang.sh, tests/shader_ports/test_vulkan.sh).
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

for manifest in data/scenes/*.scene tests/data/scenes/*.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    models=$(awk -F= '/^models/ { sub(/#.*/, "", $2); print $2 }' "$manifest" | wc -w)
    for back in glsl hlsl msl wgsl wgsl-f16; do
        out=$back
        if [ $back = glsl ]; then
            set -- --glsl -o "$t/$ident.glsl"
            # the tables a program uploads (the LUT texture of GLSL ES 1.00, the
            # film's), where there are some
            grep -q '^models *=.*\(lut\|thin-film\)' "$manifest" && set -- "$@" --tables "$t/${ident}_tex.h"
            sig="^vec3 fresnel_${ident}_[a-z0-9_]*_rgb(FRESNEL_HIGHP float c\(, FRESNEL_HIGHP float d_nm\)\{0,1\})$"
        elif [ $back = wgsl ] || [ $back = wgsl-f16 ]; then
            set -- --$back -o "$t/$ident.$out"
            grep -q '^models *=.*thin-film' "$manifest" && set -- "$@" --tables "$t/${ident}_tex.h"
            sig="^fn fresnel_${ident}_[a-z0-9_]*_rgb(c: f32\(, d_nm: f32\)\{0,1\}) -> vec3f {$"
        else
            [ $back = msl ] && out=metal
            set -- --$back -o "$t/$ident.$out"
            sig="^float3 fresnel_${ident}_[a-z0-9_]*_rgb(float c\(, float d_nm\)\{0,1\})$"
        fi
        if ! "$F" gen "$manifest" "$@" 2>"$t/err"; then
            echo "FAIL gen shaders: $manifest --$back: $(grep -v warning "$t/err" | head -3)"
            continue
        fi
        n=$(grep -c "$sig" "$t/$ident.$out")
        mats=$(grep -c '^/\* ---- ' "$t/$ident.$out")
        what="$n functions ($mats materials x $models models)"
        if [ $back != hlsl ] && [ $back != msl ] && [ -e "$t/${ident}_tex.h" ]; then
            # the tables header, compiled by this pass's compiler
            printf '#include "%s_tex.h"\n' "$ident" >"$t/tex.c"
            # shellcheck disable=SC2086
            ${CC:-cc} -std=c99 -Wall -Wextra -Wpedantic -Werror -I"$t" -c "$t/tex.c" -o "$t/tex.o" >"$t/cc.log" 2>&1 &&
                [ ! -s "$t/cc.log" ] && what="$what; its tables header compiles warning-free with ${CC:-cc}" ||
                n="0 ($(head -3 "$t/cc.log" | tr '\n' ' '))"
        fi
        rm -f "$t/${ident}_tex.h"
        if [ "$n" -gt 0 ] 2>/dev/null && [ "$n" -eq $((mats * models)) ]; then
            echo "PASS gen shaders: $manifest --$back$(echo "$what" | grep -q 'tables header' && echo ' --tables'): $what"
        else
            echo "FAIL gen shaders: $manifest --$back: $n functions for $mats materials x $models models"
        fi
    done
done

# expect_bad NAME WANT -- ARGS: fresnel gen ARGS with -o/--tables at
# files that exist beforehand and must survive unchanged.
expect_bad() {
    name=$1
    want=$2
    shift 3
    for f in bad.glsl bad_tex.h bad.hlsl; do echo keep >"$t/$f"; done
    "$F" gen "$@" >"$t/bad.out" 2>"$t/bad.err"
    st=$?
    if [ $st -eq 2 ] && grep -q -- "$want" "$t/bad.err" && [ "$(cat "$t/bad.glsl" "$t/bad_tex.h" "$t/bad.hlsl")" = "keep
keep
keep" ] && [ -z "$(ls "$t" | grep '\.tmp\.')" ]; then
        echo "PASS gen shaders: $name: exit 2, $(head -1 "$t/bad.err" | sed "s|$t/||" | cut -c1-120)"
    else
        echo "FAIL gen shaders: $name: exit $st, stderr: $(cat "$t/bad.err"), outputs: $(cat "$t/bad.glsl" "$t/bad_tex.h" "$t/bad.hlsl" | tr '\n' ' ')"
    fi
}
printf 'materials = au\nmodels = lut16\ntypes = q15\nlut_spacing = grazing-pl\n' >"$t/pl.scene"
expect_bad "grazing-pl with --glsl" "pl.scene:4: expected lut_spacing grazing or uniform" -- \
    "$t/pl.scene" --glsl -o "$t/bad.glsl" --tables "$t/bad_tex.h"
printf 'name = a__b\nmaterials = au\nmodels = schlick\n' >"$t/a__b.scene"
expect_bad "scene name with __ (reserved in GLSL)" "no '__'" -- "$t/a__b.scene" --glsl -o "$t/bad.glsl"
printf 'materials = au\nmodels = schlick\n' >"$t/nolut.scene"
expect_bad "--tables for a scene without LUTs or a film" "no LUT model and no thin film" -- \
    "$t/nolut.scene" --glsl -o "$t/bad.glsl" --tables "$t/bad_tex.h"
expect_bad "--wgsl --tables for a scene without a film" "no thin film" -- \
    data/scenes/default.scene --wgsl -o "$t/bad.glsl" --tables "$t/bad_tex.h"
expect_bad "--tables without --glsl" "needs --glsl" -- \
    data/scenes/default.scene -o "$t/bad.glsl" --tables "$t/bad_tex.h"
expect_bad "a LUT spacing the shader ports lack, --hlsl" "pl.scene:4: expected lut_spacing grazing or uniform with --hlsl" -- \
    "$t/pl.scene" --hlsl -o "$t/bad.hlsl"
expect_bad "scene name with __, --hlsl" "no '__'\|double '_'" -- "$t/a__b.scene" --hlsl -o "$t/bad.hlsl"
expect_bad "a LUT spacing the shader ports lack, --msl" "pl.scene:4: expected lut_spacing grazing or uniform with --msl" -- \
    "$t/pl.scene" --msl -o "$t/bad.hlsl"
expect_bad "a LUT spacing the shader ports lack, --wgsl" "pl.scene:4: expected lut_spacing grazing or uniform with --wgsl" -- \
    "$t/pl.scene" --wgsl -o "$t/bad.hlsl"
expect_bad "an unknown back end (--spirv)" "--spirv" -- data/scenes/default.scene --spirv -o "$t/bad.hlsl"
expect_bad "--glsl and --hlsl together" "one back end per run" -- data/scenes/default.scene --glsl --hlsl -o "$t/bad.hlsl"
expect_bad "--tables with --hlsl" "needs --glsl" -- \
    data/scenes/default.scene --hlsl -o "$t/bad.hlsl" --tables "$t/bad_tex.h"
printf 'materials = au\nmodels = schlick nosuch\n' >"$t/unknown.scene"
expect_bad "an unknown model, --hlsl" "unknown.scene:2" -- "$t/unknown.scene" --hlsl -o "$t/bad.hlsl"
