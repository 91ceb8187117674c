#!/bin/sh
# passes: first (g++ and clang++ compile the same C++ in every pass)
# make check: no (glslangValidator, spirv-cross)
# The MSL port (ports/msl/) where Apple's compiler is not: for the default
# scene and the three scenes of the Vulkan test (every model, every LUT
# kind, the thin film on six substrates), `fresnel gen --msl` after
# ports/msl/fresnel.metal compiled as C++ by g++ and clang++ through
# tests/shader_ports/msl/metal_stdlib, in float and with FRESNEL_MP half,
# run on every cosine step of 1/1024 and compared with the C runtime by
# tests/shader_ports/msl_host_test.c (built by make check-bins); and the
# same functions reached through SPIRV-Cross (the scene's GLSL compiled by
# glslangValidator, spirv-opt, spirv-cross --msl, in float and with relaxed
# precision as half), compiled and run the same way. Then the one-file port
# (make msl) compiles the same way, and gen --msl refuses what the port
# lacks.
# The table of ports/README.md:
#   BUILD=build sh tests/shader_ports/test_msl.sh | sed -n 's/^NOTE table //p'
BUILD=${BUILD:-build}
out="$BUILD/msl/test"
for tool in g++ clang++ glslangValidator spirv-opt spirv-cross; do
    if ! command -v $tool >/dev/null 2>&1; then
        echo "FAIL msl: $tool not found: install Debian's g++, clang, glslang-tools, spirv-tools and spirv-cross (tests/deps.sh does)"
        exit 1
    fi
done
for built in "$BUILD/msl/msl_host_test" "$BUILD/msl/fresnel.metal"; do
    if [ ! -f "$built" ]; then
        echo "FAIL msl: $built not built (make check-bins builds it)"
        exit 1
    fi
done
mkdir -p "$out"
status=0
echo "NOTE table | scene | model | g++ float | g++ half | clang float | clang half | half bound | spirv-cross float | spirv-cross half | its bound |"
echo "NOTE table |---|---|---|---|---|---|---|---|---|---|"
for manifest in data/scenes/default.scene tests/data/scenes/vk_models.scene tests/data/scenes/vk_uniform.scene \
    tests/data/scenes/vk_film.scene; do
    ident=$(basename "$manifest" .scene | tr 'A-Z-' 'a-z_')
    if ! "$BUILD/fresnel" gen "$manifest" --msl -o "$out/$ident.metal" 2>"$out/gen.log" ||
        ! "$BUILD/fresnel" gen "$manifest" --glsl -o "$out/$ident.glsl" 2>"$out/gen.log"; then
        echo "FAIL msl: fresnel gen $manifest --msl / --glsl: $(cat "$out/gen.log")"
        status=1
        continue
    fi
    "$BUILD/msl/msl_host_test" "$out" "$manifest" "$ident" "$out/$ident.metal" "$out/$ident.glsl" || status=1
done

# The one file of `make msl` stands in for the two of ports/ (a user who
# vendors one file): the default scene after it, both compilers.
printf '#include "%s"\n#include "%s"\nint main() { return fresnel_default_au_f82_rgb(0.5).x > 0.0 ? 0 : 1; }\n' \
    "$BUILD/msl/fresnel.metal" "$out/default.metal" >"$out/one_file.cpp"
for cxx in "g++ -fsingle-precision-constant" clang++; do
    if $cxx -std=c++14 -Wall -Wextra -Werror -Itests/shader_ports/msl -I. "$out/one_file.cpp" -o "$out/one_file" \
        >"$out/one_file.log" 2>&1 && "$out/one_file"; then
        echo "PASS msl: make msl's one file and the default scene compile and run ($cxx)"
    else
        echo "FAIL msl: make msl's one file with the default scene ($cxx): $(head -5 "$out/one_file.log")"
        status=1
    fi
done

# What the port lacks is refused: grazing-pl tables, with exit 2 and no output.
printf 'materials = au\nmodels = lut16\ntypes = q15\nlut_spacing = grazing-pl\n' >"$out/pl.scene"
rm -f "$out/pl.metal"
"$BUILD/fresnel" gen "$out/pl.scene" --msl -o "$out/pl.metal" 2>"$out/pl.err"
rc=$?
if [ $rc -eq 2 ] && [ ! -e "$out/pl.metal" ] && grep -q "pl.scene" "$out/pl.err"; then
    echo "PASS msl: gen --msl refuses lut_spacing grazing-pl at the manifest, exit 2, no output"
else
    echo "FAIL msl: gen --msl on a grazing-pl scene: exit $rc, $(head -2 "$out/pl.err")"
    status=1
fi
exit $status
