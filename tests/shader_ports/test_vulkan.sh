#!/bin/sh
# passes: first (glslangValidator, spirv-val and lavapipe do the same work in every pass; the
# emitters under the sanitizers: tests/shader_ports/test_gen_shaders.sh)
# make check: no (Vulkan, lavapipe)
# start: early (lavapipe compiles every table)
# The shader ports in a real Vulkan pipeline (ports/vulkan/): for the default
# scene, two scenes with every model and every LUT kind and the thin film on
# six substrates, `fresnel gen --glsl` (GLSL 4.50) and `fresnel gen --hlsl`
# after their ports, compiled to SPIR-V by glslangValidator, checked by
# spirv-val and run on Mesa's lavapipe by tests/shader_ports/vulkan_test.c (built by make
# test-bins), against the C runtime on every cosine step of 1/1024. The thin
# film runs from its table in a storage buffer, as on a GPU (a scene's const
# array is copied into every invocation by SPIR-V: over 25 minutes for one
# material's four pipelines); the scenes' film functions run in OSMesa
# (tests/shader_ports/test_glsl_generated_osmesa.sh) and Chromium (tests/shader_ports/test_viewer.sh) and compile
# and validate here in every committed scene's HLSL. Then the bad inputs of
# --hlsl.
# Missing tools are a FAIL, not a skip (make test installs them: tests/deps.sh).
#
# VULKAN_DEVICE picks the device (vulkan_test --device): cpu, lavapipe, by
# default (the loader then sees lavapipe's driver alone); gpu, the first GPU
# (every installed driver visible); or an index into the loader's list.
#
# The table of ports/README.md, after the device it was measured on:
#   BUILD=build sh tests/shader_ports/test_vulkan.sh | sed -n 's/^NOTE table //p'
#   VULKAN_DEVICE=gpu BUILD=build sh tests/shader_ports/test_vulkan.sh | sed -n 's/^NOTE table //p'
BUILD=${BUILD:-build}
out="$BUILD/vulkan/test"
device=${VULKAN_DEVICE:-cpu}
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
status=0
# vulkan_test's environment: for the CPU device, lavapipe alone
if [ "$device" = cpu ]; then
    vk() { VK_ICD_FILENAMES="$icd" VK_DRIVER_FILES="$icd" "$@"; }
else
    vk() { "$@"; }
fi
# Only lavapipe (the loader sees no other driver) unless VULKAN_DEVICE says otherwise; its LLVM optimisation off
# (GALLIVM_PERF=nopt): the generated const-array tables take seconds per
# pipeline to optimise, and the arithmetic is the same IEEE binary32. The
# shader cache in build/ lets the later passes of make test reuse the code.
# Leak detection is off as in tests/shader_ports/test_glsl_port_osmesa.sh: in the sanitizer pass the
# one leak LeakSanitizer reports is 128 bytes allocated inside libubsan
# itself (a realloc in libubsan.so) while the driver runs, not by the host.
for manifest in data/scenes/default.scene tests/data/scenes/vk_models.scene tests/data/scenes/vk_uniform.scene \
    tests/data/scenes/vk_film.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    if ! "$BUILD/fresnel" gen "$manifest" --glsl -o "$out/$ident.glsl" 2>"$out/gen.log" ||
        ! "$BUILD/fresnel" gen "$manifest" --hlsl -o "$out/$ident.hlsl" 2>>"$out/gen.log"; then
        echo "FAIL vulkan: fresnel gen $manifest --glsl/--hlsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    vk env GALLIVM_PERF=nopt MESA_SHADER_CACHE_DIR="${BUILD%%/*}/mesa-shader-cache" ASAN_OPTIONS=detect_leaks=0 \
        "$BUILD/vulkan/vulkan_test" --device "$device" "$out" "$manifest" "$ident" "$out/$ident.glsl" \
        "$out/$ident.hlsl" || status=1
done

# The device choice: a malformed one is a usage error; one the loader does
# not list (a GPU where lavapipe is the only driver, an index past the end)
# fails, naming the devices there are.
m=data/scenes/default.scene
if "$BUILD/vulkan/vulkan_test" --device fast "$out" $m default "$out/default.glsl" "$out/default.hlsl" >"$out/dev.out" 2>&1; then
    echo "FAIL vulkan: vulkan_test --device fast accepted"
    status=1
elif [ $? -eq 2 ] && grep -q "cpu, gpu or a device index" "$out/dev.out"; then
    echo "PASS vulkan: vulkan_test --device fast: exit 2, $(head -1 "$out/dev.out")"
else
    echo "FAIL vulkan: vulkan_test --device fast: $(head -2 "$out/dev.out")"
    status=1
fi
for absent in gpu 9; do
    VK_ICD_FILENAMES="$icd" VK_DRIVER_FILES="$icd" ASAN_OPTIONS=detect_leaks=0 "$BUILD/vulkan/vulkan_test" \
        --device $absent "$out" $m default "$out/default.glsl" "$out/default.hlsl" >"$out/dev.out" 2>&1
    st=$?
    if [ $st -ne 0 ] && grep -q "no Vulkan device '$absent' among the 1 the loader lists: 0 = .*(cpu)" "$out/dev.out"; then
        echo "PASS vulkan: --device $absent with lavapipe alone fails, naming the one device there is"
    else
        echo "FAIL vulkan: --device $absent with lavapipe alone: exit $st, $(grep -m2 -e FAIL -e device "$out/dev.out")"
        status=1
    fi
done

# Every committed scene's --hlsl output compiles (glslangValidator's HLSL
# front end) and validates after the single-file HLSL port of `make hlsl`
# (vulkan_test includes ports/hlsl/fresnel.hlsl instead), one compute shader
# calling every function, with FRESNEL_MP min16float (the default) and float.
# Of the thin film's functions (one body, one table each) the shader calls
# the first: glslangValidator's HLSL front end takes time in the square of
# their calls (4 calls 11 s, 20 calls over 6 minutes); every table is parsed.
for manifest in data/scenes/*.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    if ! "$BUILD/fresnel" gen "$manifest" --hlsl -o "$out/scene_$ident.hlsl" 2>"$out/gen.log"; then
        echo "FAIL vulkan: fresnel gen $manifest --hlsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    all=$(awk -v p="fresnel_${ident}_" '
        /^float3 fresnel_[a-z0-9_]*_rgb\(float c\)$/ && index($2, p) == 1 { sub(/\(.*/, "", $2); print $2 "(c)" }
        /^float3 fresnel_[a-z0-9_]*_rgb\(float c, float d_nm\)$/ && index($2, p) == 1 && !film++ { sub(/\(.*/, "", $2); print $2 "(c, 300.0)" }' \
        "$out/scene_$ident.hlsl" | paste -sd+)
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

exit $status
