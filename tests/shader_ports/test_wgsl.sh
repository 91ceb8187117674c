#!/bin/sh
# passes: first (headless Chromium runs the same pages in every pass)
# make check: no (headless browsers)
# The WGSL port: for the default scene and the three scenes of the Vulkan
# test (every model, every LUT kind, the thin film from its storage
# buffer), `fresnel gen --wgsl` (the port translated from
# ports/glsl/fresnel.glsl, then the scene) runs as a WebGPU compute shader
# in two implementations, headless Chromium (Tint on SwiftShader, binary32)
# and headless Firefox ESR (naga on lavapipe), on every cosine step of
# 1/1024, and
# tests/shader_ports/wgsl_page_test.c compares every material and model with
# the C runtime (max |WGSL - C| <= 1e-5, every result in [0, 1]); compile
# errors come back with line numbers from getCompilationInfo(). The same
# scenes from `fresnel gen --wgsl-f16` run in Firefox with shader-f16, each
# model within its binary16 bound (port_half_bound). Then the
# port alone (make wgsl) compiles in both, and gen --wgsl refuses what the
# port lacks. The table:
#   BUILD=build sh tests/shader_ports/test_wgsl.sh | sed -n 's/^NOTE table //p'
BUILD=${BUILD:-build}
out="$BUILD/wgsl/test"
browser=${CHROMIUM:-chromium}
for b in "$browser" firefox-esr; do
    if ! command -v "$b" >/dev/null 2>&1; then
        echo "FAIL wgsl: $b not found: install Debian's chromium and firefox-esr (tests/deps.sh does)"
        exit 1
    fi
done
for built in "$BUILD/wgsl/wgsl_page_test" "$BUILD/wgsl/fresnel.wgsl" "$BUILD/fresnel"; do
    if [ ! -f "$built" ]; then
        echo "FAIL wgsl: $built not built (make check-bins builds it)"
        exit 1
    fi
done
mkdir -p "$out"
status=0

# tests/shader_ports/webgpu_page.sh opens a page in either browser and
# waits for its WGSL_DONE line.
run_page() { # page log [firefox]
    sh tests/shader_ports/webgpu_page.sh run "$1" "$2" "${3:-chromium}"
}

echo "NOTE table | scene | model | browser | max \|WGSL − C\| | bound |"
echo "NOTE table |---|---|---|---|---|"
for manifest in data/scenes/default.scene tests/data/scenes/vk_models.scene tests/data/scenes/vk_uniform.scene \
    tests/data/scenes/vk_film.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    if ! "$BUILD/fresnel" gen "$manifest" --wgsl -o "$out/$ident.wgsl" 2>"$out/gen.log"; then
        echo "FAIL wgsl: fresnel gen $manifest --wgsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    if ! "$BUILD/wgsl/wgsl_page_test" page "$out/$ident.html" "$manifest" "$ident" "$out/$ident.wgsl"; then
        status=1
        continue
    fi
    for b in chromium firefox; do
        run_page "$out/$ident.html" "$out/${ident}_$b.log" $b ||
            echo "NOTE wgsl: $ident: no WGSL_DONE from $b within ${WGSL_TIMEOUT:-240} s; its log ends: $(tail -c 300 "$out/${ident}_$b.log" | tr '\n' ' ')"
        "$BUILD/wgsl/wgsl_page_test" check "$manifest" "$ident" "$out/${ident}_$b.log" $b || status=1
    done
    # f16 (gen --wgsl-f16) where WebGPU has shader-f16: Firefox's (naga,
    # lavapipe's shaderFloat16); Chromium's SwiftShader adapter has none
    if ! "$BUILD/fresnel" gen "$manifest" --wgsl-f16 -o "$out/${ident}_f16.wgsl" 2>"$out/gen.log"; then
        echo "FAIL wgsl: fresnel gen $manifest --wgsl-f16: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    if ! "$BUILD/wgsl/wgsl_page_test" page "$out/${ident}_f16.html" "$manifest" "$ident" "$out/${ident}_f16.wgsl" f16; then
        status=1
        continue
    fi
    run_page "$out/${ident}_f16.html" "$out/${ident}_f16.log" firefox ||
        echo "NOTE wgsl: $ident f16: no WGSL_DONE from firefox within ${WGSL_TIMEOUT:-240} s; its log ends: $(tail -c 300 "$out/${ident}_f16.log" | tr '\n' ' ')"
    "$BUILD/wgsl/wgsl_page_test" check "$manifest" "$ident" "$out/${ident}_f16.log" firefox f16 || status=1
done

# The port alone compiles, and with f16 in Firefox.
for port in "fresnel.wgsl chromium" "fresnel.wgsl firefox" "fresnel_f16.wgsl firefox"; do
    set -- $port
    if msg=$(sh tests/shader_ports/webgpu_page.sh compile "$BUILD/wgsl/$1" "$out" $2); then
        echo "PASS wgsl: make wgsl's build/wgsl/$1 compiles in $2"
    else
        echo "FAIL wgsl: make wgsl's build/wgsl/$1 compiles in $2: $msg"
        status=1
    fi
done

# What the port lacks is refused as by --msl: grazing-pl tables, with exit 2 and no output.
printf 'materials = au\nmodels = lut16\ntypes = q15\nlut_spacing = grazing-pl\n' >"$out/pl.scene"
rm -f "$out/pl.wgsl"
"$BUILD/fresnel" gen "$out/pl.scene" --wgsl -o "$out/pl.wgsl" 2>"$out/pl.err"
rc=$?
if [ $rc -eq 2 ] && [ ! -e "$out/pl.wgsl" ] && grep -q "pl.scene" "$out/pl.err"; then
    echo "PASS wgsl: gen --wgsl refuses lut_spacing grazing-pl at the manifest, exit 2, no output"
else
    echo "FAIL wgsl: gen --wgsl on a grazing-pl scene: exit $rc, $(head -2 "$out/pl.err")"
    status=1
fi
exit $status
