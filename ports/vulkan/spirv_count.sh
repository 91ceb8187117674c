#!/bin/sh
# SPIR-V instructions per model, the GPU's counterpart of `make cross-count`:
#   sh ports/vulkan/spirv_count.sh [BUILD]      (make spirv-count)
# For each model of ports/vulkan/spirv_count.scene (gold; LUTs of 32 nodes;
# the thin film under a film of index 1.38), a GLSL 4.50 compute shader
# whose main() reads a cosine from a storage buffer, calls the scene's
# function (`fresnel gen --glsl`) and writes its three channels, is compiled
# by glslangValidator -V and optimised by spirv-opt -O (which inlines every
# call into main); the count is the instructions of the optimised module's
# functions (OpFunction to OpFunctionEnd, OpLabel included) less those of
# the same main returning its cosine (the harness). Columns:
#   highp         precision highp float (binary32 throughout)
#   mediump       precision mediump float, then spirv-opt
#                 --convert-relaxed-to-half -O: the RelaxedPrecision
#                 operations in explicit 16-bit floats, with the conversions
#                 that takes (what a driver that honours mediump runs)
# The thin film reads its tables from a storage buffer (the generated
# GLSL's route in Vulkan), at binding 2. Its two peers follow, rows
# khr-iridescence-peer and polarised-film-peer: the GLSL of
# ports/webgl/viewer.html (KHR_materials_iridescence as the glTF Sample
# Viewer evaluates it, given gold's F0; the polarised form of the same
# family, given gold's eta, kappa), their inputs (film index, F0 or eta,
# kappa) read from the input buffer as the film's table is, the cosine held
# to [0, 1] and the result too, as the film's own function does.
# Instruction counts, not cycles: a GPU's cost per instruction varies with
# the instruction and the chip.
B=${1:-build}
F=$B/fresnel
t=$(mktemp -d) || exit 1
trap 'rm -rf "$t"' EXIT
for tool in glslangValidator spirv-opt spirv-dis spirv-val; do
    command -v $tool >/dev/null 2>&1 || {
        echo "spirv-count: $tool not found: install Debian's glslang-tools and spirv-tools" >&2
        exit 1
    }
done
[ -x "$F" ] || {
    echo "spirv-count: $F not built (make builds it)" >&2
    exit 1
}
"$F" gen ports/vulkan/spirv_count.scene --glsl -o "$t/scene.glsl" || exit 1

# shader PRECISION CALL: the module's source for one call (CALL: an
# expression of c, or "film")
shader() {
    cat ports/glsl/prelude_450.glsl
    echo "precision $1 float;"
    echo "#define FRESNEL_FILM_BINDING 2"
    cat ports/glsl/fresnel.glsl "$t/scene.glsl"
    case $2 in khr | polarised) cat "$t/peers.glsl" ;; esac
    printf 'layout(local_size_x = 64) in;\n'
    printf 'layout(std430, set = 0, binding = 0) readonly buffer FrIn { highp float fr_in[]; };\n'
    printf 'layout(std430, set = 0, binding = 1) writeonly buffer FrOut { highp float fr_out[]; };\n'
    printf 'void main()\n{\n    int i = int(gl_GlobalInvocationID.x);\n'
    printf '    highp float c = fr_in[FRESNEL_FILM_FLOATS + 2 * i], d = fr_in[FRESNEL_FILM_FLOATS + 2 * i + 1];\n'
    case $2 in
    film) printf '    vec3 r = fresnel_spirv_count_au_thin_film_rgb(c, d);\n' ;;
    khr) printf '    vec3 r = clamp(peer_khr(fr_in[0], d, clamp(c, 0.0, 1.0), vec3(fr_in[1], fr_in[2], fr_in[3])), 0.0, 1.0);\n' ;;
    polarised) printf '    vec3 r = clamp(peer_polarised(fr_in[0], d, clamp(c, 0.0, 1.0), vec3(fr_in[1], fr_in[2], fr_in[3]), vec3(fr_in[4], fr_in[5], fr_in[6])), 0.0, 1.0);\n' ;;
    harness) printf '    vec3 r = vec3(c, c, c);\n' ;;
    *) printf '    vec3 r = %s;\n' "$2" ;;
    esac
    printf '    fr_out[3 * i] = r.x;\n    fr_out[3 * i + 1] = r.y;\n    fr_out[3 * i + 2] = r.z;\n}\n'
}

# count PRECISION CALL: instructions of the optimised module's functions
count() {
    shader "$1" "$2" >"$t/m.comp"
    glslangValidator -V --target-env vulkan1.0 -S comp -o "$t/m.spv" "$t/m.comp" >"$t/log" 2>&1 || {
        echo "spirv-count: glslangValidator failed on $2 ($1): $(grep -m3 ERROR "$t/log" | tr '\n' ' ')" >&2
        return 1
    }
    if [ "$1" = mediump ]; then
        spirv-opt --convert-relaxed-to-half -O "$t/m.spv" -o "$t/o.spv" || return 1
    else
        spirv-opt -O "$t/m.spv" -o "$t/o.spv" || return 1
    fi
    spirv-val --target-env vulkan1.0 "$t/o.spv" || return 1
    spirv-dis --no-header "$t/o.spv" | awk '/ OpFunction / || /^ *OpFunction / { f = 1 } f { n++ } /OpFunctionEnd/ { f = 0 } END { print n + 0 }'
}

# the peers' GLSL: the page's, from its constants to its film_peer()
sed -n '/^const highp mat3 PEER_XYZ_TO_709/,/^vec3 film_peer(/p' ports/webgl/viewer.html | sed '$d' >"$t/peers.glsl"
grep -q '^highp vec3 peer_polarised(' "$t/peers.glsl" || {
    echo "spirv-count: the film's peers not found in ports/webgl/viewer.html" >&2
    exit 1
}

hp0=$(count highp harness) && mp0=$(count mediump harness) || exit 1
echo "| model | highp | mediump (16-bit) |"
echo "|---|---:|---:|"
for model in $(sed -n 's/^models *= *//p' ports/vulkan/spirv_count.scene); do
    ident=$(echo "$model" | tr '-' '_')
    if [ "$model" = thin-film ]; then
        call=film
    elif grep -q "^vec3 fresnel_spirv_count_au_${ident}_rgb(FRESNEL_HIGHP float c, FRESNEL_HIGHP float d_nm)" "$t/scene.glsl"; then
        call="fresnel_spirv_count_au_${ident}_rgb(c, d)"
    else
        call="fresnel_spirv_count_au_${ident}_rgb(c)"
    fi
    hp=$(count highp "$call") && mp=$(count mediump "$call") || exit 1
    echo "| $model | $((hp - hp0)) | $((mp - mp0)) |"
done
for peer in khr polarised; do
    hp=$(count highp $peer) && mp=$(count mediump $peer) || exit 1
    [ $peer = khr ] && row=khr-iridescence-peer || row=polarised-film-peer
    echo "| $row | $((hp - hp0)) | $((mp - mp0)) |"
done
echo
echo "Harness (main reading the cosine and writing it three times): $hp0 instructions highp, $mp0 mediump; subtracted above."
echo "Tools: $(glslangValidator --version | head -1 | sed "s/^Glslang Version: */glslang /"), $(spirv-opt --version 2>&1 | head -1 | cut -d" " -f1-2)."
