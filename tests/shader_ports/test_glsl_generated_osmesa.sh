#!/bin/sh
# passes: first (OSMesa runs the same shaders in every pass; the emitters under the sanitizers and
# the texture header under each compiler: tests/shader_ports/test_gen_shaders.sh)
# make check: no (OSMesa)
# `fresnel gen --glsl` on the GPU: for the default scene and two scenes with
# every LUT kind and every analytic model (and the thin film), the generated GLSL (and, for
# GLSL ES 1.00, the packed LUT texture of --tables) evaluates in
# OSMesa to what the C runtime computes from the same manifest, in GLSL 3.30,
# ES 3.00 and ES 1.00 (tests/shader_ports/glsl_generated_osmesa.c, built once per scene because it
# includes the scene's texture header). Needs OSMesa, like tests/shader_ports/test_glsl_port_osmesa.sh.
BUILD=${BUILD:-build}
CC=${CC:-cc}
out="$BUILD/glsl/gen"
if [ ! -f /usr/include/GL/osmesa.h ] || ! pkg-config --exists osmesa 2>/dev/null; then
    echo "FAIL glsl gen: OSMesa not found: install Debian's libosmesa6-dev (.ci/run does this)"
    exit 1
fi
mkdir -p "$out"
san=
if nm "$BUILD/libfresnel.a" 2>/dev/null | grep -q '__asan_'; then
    san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
fi
# the objects of today's sources (a stale object of a removed file is not
# linked), and the viewer's embedded page (Makefile, viewer_assets)
gen_obj="$(for f in gen/*/*.c; do echo "$BUILD/obj/${f%.c}.o"; done) $BUILD/obj/embed/viewer_assets.o"
status=0
for manifest in data/scenes/default.scene tests/data/scenes/glsl_all_models.scene tests/data/scenes/glsl_uniform.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    IDENT=$(printf '%s' "$ident" | tr 'a-z' 'A-Z')
    if ! "$BUILD/fresnel" gen "$manifest" --glsl -o "$out/$ident.glsl" --tables "$out/${ident}_tex.h" \
        2>"$out/gen.log"; then
        echo "FAIL glsl gen: fresnel gen $manifest --glsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    if grep -q '[0-9]f[,)]' "$out/$ident.glsl"; then
        echo "FAIL glsl gen: $ident: a C float suffix in the GLSL output"
    else
        echo "PASS glsl gen: $ident: no C float suffixes in the GLSL output"
    fi
    # shellcheck disable=SC2086,SC2046
    if ! $CC -std=c99 -Wall -Wextra -Wpedantic -Werror -O1 -g $san -D_POSIX_C_SOURCE=200809L \
        -Iinclude -Igen -Iports/glsl/host -Itests/common \
        -I"$out" -DFR_TEX_HEADER="\"${ident}_tex.h\"" -DFR_TEX="fresnel_${ident}_lut_texture" \
        -DFR_TEX_WIDTH="FRESNEL_${IDENT}_LUT_TEXTURE_WIDTH" -DFR_TEX_HEIGHT="FRESNEL_${IDENT}_LUT_TEXTURE_HEIGHT" \
        -o "$out/glsl_gen_test_$ident" tests/shader_ports/glsl_generated_osmesa.c ports/glsl/host/glctx.c $gen_obj "$BUILD/libfresnel.a" \
        $(pkg-config --cflags --libs osmesa) -lm >"$out/build_$ident.log" 2>&1; then
        echo "FAIL glsl gen: tests/shader_ports/glsl_generated_osmesa.c does not build with $ident: $(grep -m 3 -iE 'error|undefined' "$out/build_$ident.log" | tr '\n' ' ')"
        status=1
        continue
    fi
    MESA_SHADER_CACHE_DIR="${BUILD%%/*}/mesa-shader-cache" ASAN_OPTIONS=detect_leaks=0 \
        "$out/glsl_gen_test_$ident" ports/glsl "$manifest" "$ident" "$out/$ident.glsl" || status=1
done
exit $status
