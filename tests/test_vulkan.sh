#!/bin/sh
# The shader ports in a real Vulkan pipeline (ports/vulkan/): for the default
# scene, two scenes with every model and every LUT kind and one with the thin film, `fresnel gen
# --glsl` (GLSL 4.50) and `fresnel gen --hlsl` after their ports, compiled to
# SPIR-V by glslangValidator, checked by spirv-val and run on Mesa's
# lavapipe by tests/vulkan_test.c (built by make test-bins), against the C
# runtime on every cosine step of 1/1024. Then the bad inputs of --hlsl.
# Missing tools are a FAIL, not a skip (make test installs them: tests/deps.sh).
#
# The table of ports/README.md:
#   BUILD=build sh tests/test_vulkan.sh | sed -n 's/^NOTE table //p'
BUILD=${BUILD:-build}
out="$BUILD/vulkan/test"
icd=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -1)
for tool in glslangValidator spirv-val; do
    if ! command -v $tool >/dev/null 2>&1; then
        echo "FAIL vulkan: $tool not found: install Debian's glslang-tools and spirv-tools"
        exit 1
    fi
done
if [ -z "$icd" ] || [ ! -f /usr/include/vulkan/vulkan.h ]; then
    echo "FAIL vulkan: lavapipe or the Vulkan headers not found: install Debian's mesa-vulkan-drivers and libvulkan-dev"
    exit 1
fi
for built in "$BUILD/vulkan/vulkan_test" "$BUILD/hlsl/fresnel.hlsl"; do
    if [ ! -f "$built" ]; then
        echo "FAIL vulkan: $built not built (make test-bins builds it)"
        exit 1
    fi
done
mkdir -p "$out"
cat >"$out/vk_models.scene" <<'SCENE'
# every scene model and LUT kind (small tables), the default scene's materials
materials = au cu ag al cr
models = schlick lsk lsk-comp f82 gulbrandsen cook-torrance approx-conductor exact exact-gaussian exact-point lut4 lut4-residual lut4-cubic
SCENE
cat >"$out/vk_film.scene" <<'SCENE'
# the thin film, on one material: each material's film is a 1744-float const
# array, and lavapipe takes minutes per pipeline over several
materials = cu
models = thin-film
film = 2.2
SCENE
cat >"$out/vk_uniform.scene" <<'SCENE'
# the LUT kinds with nodes uniform in cos theta
materials = au cu ag al cr
models = lut4 lut4-residual
lut_spacing = uniform
SCENE
status=0
# Only lavapipe (the loader sees no other driver); its LLVM optimisation off
# (GALLIVM_PERF=nopt): the generated const-array tables take seconds per
# pipeline to optimise, and the arithmetic is the same IEEE binary32. The
# shader cache in build/ lets the later passes of make test reuse the code.
# Leak detection is off as in tests/test_glsl.sh: in the sanitizer pass the
# one leak LeakSanitizer reports is 128 bytes allocated inside libubsan
# itself (a realloc in libubsan.so) while the driver runs, not by the host.
for manifest in data/scenes/default.scene "$out/vk_models.scene" "$out/vk_uniform.scene" "$out/vk_film.scene"; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    if ! "$BUILD/fresnel" gen "$manifest" --glsl -o "$out/$ident.glsl" 2>"$out/gen.log" ||
        ! "$BUILD/fresnel" gen "$manifest" --hlsl -o "$out/$ident.hlsl" 2>>"$out/gen.log"; then
        echo "FAIL vulkan: fresnel gen $manifest --glsl/--hlsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    VK_ICD_FILENAMES="$icd" VK_DRIVER_FILES="$icd" GALLIVM_PERF=nopt \
        MESA_SHADER_CACHE_DIR="${BUILD%%/*}/mesa-shader-cache" ASAN_OPTIONS=detect_leaks=0 \
        "$BUILD/vulkan/vulkan_test" "$out" "$manifest" "$ident" "$out/$ident.glsl" "$out/$ident.hlsl" || status=1
done

# Every committed scene's --hlsl output compiles (glslangValidator's HLSL
# front end) and validates after the single-file HLSL port of `make hlsl`
# (vulkan_test includes ports/hlsl/fresnel.hlsl instead), one compute shader
# calling every function, with FRESNEL_MP min16float (the default) and float.
for manifest in data/scenes/*.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    if ! "$BUILD/fresnel" gen "$manifest" --hlsl -o "$out/scene_$ident.hlsl" 2>"$out/gen.log"; then
        echo "FAIL vulkan: fresnel gen $manifest --hlsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    all=$(sed -n -e "s/^float3 \(fresnel_${ident}_[a-z0-9_]*_rgb\)(float c)$/\1(c)/p" \
        -e "s/^float3 \(fresnel_${ident}_[a-z0-9_]*_rgb\)(float c, float d_nm)$/\1(c, 300.0)/p" "$out/scene_$ident.hlsl" | paste -sd+)
    for mp in min16float float; do
        f="$out/scene_${ident}_$mp.hlsl"
        { echo "#define FRESNEL_MP $mp"
          cat "$BUILD/hlsl/fresnel.hlsl" "$out/scene_$ident.hlsl"
          printf '[[vk::binding(0, 0)]] RWStructuredBuffer<float> fr_out;\n'
          printf '[numthreads(64, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID)\n{\n'
          printf '    float c = (float)id.x / 64.0;\n    float3 r = %s;\n    fr_out[id.x] = r.x + r.y + r.z;\n}\n' "$all"
        } >"$f"
        n=$(printf '%s' "$all" | tr '+' '\n' | grep -c .)
        if [ "$n" -gt 0 ] && glslangValidator -V -D -e main -S comp -o "$f.spv" "$f" >"$f.log" 2>&1 &&
            spirv-val --target-env vulkan1.0 "$f.spv" >>"$f.log" 2>&1; then
            echo "PASS vulkan: $manifest --hlsl, $n functions, FRESNEL_MP $mp: compiles and validates after the single-file port"
        else
            echo "FAIL vulkan: $manifest --hlsl, FRESNEL_MP $mp ($n functions): $(grep -m 3 -i 'error' "$f.log" | tr '\n' ' ')"
            status=1
        fi
    done
done

# Bad input for --hlsl: a clear error, exit 2, the existing output untouched.
expect_bad() {
    name=$1
    want=$2
    shift 3
    echo keep >"$out/bad.hlsl"
    "$BUILD/fresnel" gen "$@" >"$out/bad.out" 2>"$out/bad.err"
    st=$?
    if [ $st -eq 2 ] && grep -q -- "$want" "$out/bad.err" && [ "$(cat "$out/bad.hlsl")" = keep ] &&
        [ -z "$(ls "$out" | grep '\.tmp\.')" ]; then
        echo "PASS vulkan: $name: exit 2, $(head -1 "$out/bad.err" | cut -c1-120)"
    else
        echo "FAIL vulkan: $name: exit $st, stderr: $(cat "$out/bad.err"), output: $(cat "$out/bad.hlsl")"
        status=1
    fi
}
printf 'materials = au\nmodels = lut16\ntypes = q15\nlut_spacing = grazing-pl\n' >"$out/pl.scene"
expect_bad "a LUT spacing the shader ports lack, --hlsl" "pl.scene:4: expected lut_spacing grazing or uniform with --hlsl" -- \
    "$out/pl.scene" --hlsl -o "$out/bad.hlsl"
printf 'name = a__b\nmaterials = au\nmodels = schlick\n' >"$out/a__b.scene"
expect_bad "scene name with __, --hlsl" "no '__'\|double '_'" -- "$out/a__b.scene" --hlsl -o "$out/bad.hlsl"
expect_bad "an unknown back end (--msl)" "--msl" -- data/scenes/default.scene --msl -o "$out/bad.hlsl"
expect_bad "--glsl and --hlsl together" "one back end per run" -- data/scenes/default.scene --glsl --hlsl -o "$out/bad.hlsl"
expect_bad "--glsl-texture with --hlsl" "needs --glsl" -- \
    data/scenes/default.scene --hlsl -o "$out/bad.hlsl" --glsl-texture "$out/bad_tex.h"
printf 'materials = au\nmodels = schlick nosuch\n' >"$out/unknown.scene"
expect_bad "an unknown model, --hlsl" "unknown.scene:2" -- "$out/unknown.scene" --hlsl -o "$out/bad.hlsl"
exit $status
