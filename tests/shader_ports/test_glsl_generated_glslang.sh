#!/bin/sh
# passes: first (glslangValidator does the same work in every pass; the emitters under the
# sanitizers: tests/shader_ports/test_gen_shaders.sh)
# make check: no (glslangValidator)
# `fresnel gen --glsl` output compiles in every dialect the GLSL port claims:
# glslangValidator (Debian glslang-tools) on each prelude x scene x model,
# a fragment shader calling the model's function for every material. The
# scenes: every committed data/scenes/*.scene and two written here with
# every LUT kind (lutN, lutN-residual, lutN-cubic; N = 4 and 256 at the
# ends of the range) in both spacings the port reads (grazing, uniform).
# GLSL ES 1.00 runs under the ES 2.0 minimum limits and Appendix A's
# indexing rules (fragment arrays: constant-index-expressions only), which
# glslangValidator enforces when its configuration says so; ES 3.00 and 3.30
# also compile with FRESNEL_LUT_ARRAYS 0 (the texture path there). Then the
# bad inputs of --glsl. A missing glslangValidator is a FAIL, not a skip.
BUILD=${BUILD:-build}
out="$BUILD/glsl/glslang"
port=ports/glsl
if ! command -v glslangValidator >/dev/null 2>&1; then
    echo "FAIL glslang: glslangValidator not found: install Debian's glslang-tools"
    exit 1
fi
mkdir -p "$out"
# ES 2.0 minimums and Appendix A: no general indexing, no while/do loops.
glslangValidator -c | sed \
    -e 's/^\(nonInductiveForLoops\|whileLoops\|doWhileLoops\|generalUniformIndexing\|generalAttributeMatrixVectorIndexing\|generalVaryingIndexing\|generalSamplerIndexing\|generalVariableIndexing\|generalConstantMatrixVectorIndexing\) 1$/\1 0/' \
    -e 's/^MaxFragmentUniformVectors .*/MaxFragmentUniformVectors 16/' \
    -e 's/^MaxVertexUniformVectors .*/MaxVertexUniformVectors 128/' \
    -e 's/^MaxVaryingVectors .*/MaxVaryingVectors 8/' \
    -e 's/^MaxTextureImageUnits .*/MaxTextureImageUnits 8/' \
    -e 's/^MaxVertexTextureImageUnits .*/MaxVertexTextureImageUnits 0/' >"$out/es100.conf"

# validate NAME FILE [CONF]: one PASS/FAIL line.
validate() {
    if glslangValidator $3 "$2" >"$2.log" 2>&1; then
        echo "PASS $1"
    else
        echo "FAIL $1: glslangValidator $3 $2:"
        grep -m 5 'ERROR' "$2.log"
    fi
}
# main_of DIALECT EXPR: a fragment main writing EXPR (a vec3).
main_of() {
    case $1 in
    es100) printf 'varying highp float fr_c;\nvoid main() { gl_FragColor = vec4(%s, 1.0); }\n' "$2" ;;
    110 | 120) printf 'varying float fr_c;\nvoid main() { gl_FragColor = vec4(%s, 1.0); }\n' "$2" ;;
    *) printf 'in highp float fr_c;\nout vec4 fr_out;\nvoid main() { fr_out = vec4(%s, 1.0); }\n' "$2" ;;
    esac
}
# prelude_of DIALECT: the port's prelude file, or for the other versions
# fresnel.glsl supports (tests/shader_ports/glsl_port_osmesa.c compiles it in all of them) the
# #version line and an ES default precision.
prelude_of() {
    case $1 in
    es100 | es300 | 330) cat "$port/prelude_$1.glsl" ;;
    es*) printf '#version %s es\nprecision mediump float;\n' "${1#es}" ;;
    *) printf '#version %s\n' "$1" ;;
    esac
}

# The controls: the checks can fail. Array constructors (the const-array
# path of the tables) and a variable index into a uniform array are rejected
# for ES 1.00 under this configuration.
{ cat $port/prelude_es100.glsl
  printf 'const float t[2] = float[2](0.5, 1.0);\nuniform float u[4];\n'
  main_of es100 'vec3(t[0])'; } >"$out/control_array.frag"
{ cat $port/prelude_es100.glsl
  printf 'uniform float u[4];\n'
  main_of es100 'vec3(u[int(fr_c * 3.0)])'; } >"$out/control_index.frag"
for c in array index; do
    if glslangValidator "$out/es100.conf" "$out/control_$c.frag" >"$out/control_$c.log" 2>&1; then
        echo "FAIL glslang: the ES 1.00 $c control compiles: the validation cannot catch that class"
    else
        echo "PASS glslang: the ES 1.00 $c control is rejected ($(grep -m1 ERROR "$out/control_$c.log" | cut -c1-70))"
    fi
done


for manifest in data/scenes/*.scene tests/data/scenes/glsl_luts.scene tests/data/scenes/glsl_luts_uniform.scene; do
    scene=$(basename "$manifest" .scene)
    ident=$(printf '%s' "$scene" | tr 'A-Z-' 'a-z_')
    glsl="$out/$ident.glsl"
    if ! "$BUILD/fresnel" gen "$manifest" --glsl -o "$glsl" --tables "$out/${ident}_tex.h" 2>"$out/gen.log"; then
        echo "FAIL glslang: fresnel gen $manifest --glsl: $(cat "$out/gen.log")"
        continue
    fi
    models=$(sed -n 's/^ \* Models: \(.*\)\.$/\1/p' "$glsl")
    nmat=$(grep -c '^/\* ---- ' "$glsl")
    for model in $models; do
        id=$(printf '%s' "$model" | tr '-' '_')
        # the thin film takes the thickness too, needs integers and texelFetch
        # (not GLSL ES 1.00), and reads its tables by three routes: the
        # texture (default), the uniform block (ES 3.00, 16 KiB at most: an
        # #error beyond) and the storage buffer (ES 3.10)
        params='FRESNEL_HIGHP float c' args='(fr_c)' variants="es100 es300 330"
        case $model in
        lut*) variants="$variants es300-texture" ;;
        thin-film)
            params='FRESNEL_HIGHP float c, FRESNEL_HIGHP float d_nm' args='(fr_c, 700.0 * fr_c)'
            variants="es300 330 es300-uniform es310-storage"
            ;;
        esac
        funcs=$(sed -n "s/^vec3 \(fresnel_${ident}_[a-z0-9_]*_${id}_rgb\)($params)$/\1/p" "$glsl")
        n=$(printf '%s\n' "$funcs" | grep -c .)
        if [ "$n" -ne "$nmat" ]; then
            echo "FAIL glslang: $scene $model: $n functions for $nmat materials"
            continue
        fi
        expr=$(printf '%s\n' "$funcs" | sed "s/\$/$args/" | paste -sd+)
        for v in $variants; do
            p=${v%-*}
            conf=
            [ "$p" = es100 ] && conf="$out/es100.conf"
            f="$out/${ident}_${id}_$v.frag"
            { prelude_of "$p"
              case $v in
              *-texture) echo '#define FRESNEL_LUT_ARRAYS 0' ;;
              *-uniform) echo '#define FRESNEL_FILM_UNIFORM 1' ;;
              *-storage) echo '#define FRESNEL_FILM_STORAGE 1' ;;
              esac
              cat "$port/fresnel.glsl" "$glsl"
              main_of "$p" "$expr"; } >"$f"
            if [ "$v" = es300-uniform ] && [ $((nmat * 6976)) -gt 16384 ]; then
                # the tables do not fit the block GLES 3.0 guarantees: refused
                if ! glslangValidator "$f" >"$f.log" 2>&1 && grep -q 'use the texture or storage route' "$f.log"; then
                    echo "PASS glslang: $scene $model, $nmat materials, $v: refused at compile time ($((nmat * 6976)) bytes of tables)"
                else
                    echo "FAIL glslang: $scene $model, $nmat materials, $v: $((nmat * 6976)) bytes compiled without the #error"
                fi
                continue
            fi
            validate "glslang: $scene $model, $nmat materials, $v" "$f" "$conf"
        done
    done
    # The scene with every model also in the other versions fresnel.glsl
    # supports, one shader calling every function.
    if [ "$ident" = glsl_luts ]; then
        all=$(sed -n "s/^vec3 \(fresnel_${ident}_[a-z0-9_]*_rgb\)(FRESNEL_HIGHP float c)$/\1(fr_c)/p" "$glsl" | paste -sd+)
        film=$(sed -n "s/^vec3 \(fresnel_${ident}_[a-z0-9_]*_rgb\)(FRESNEL_HIGHP float c, FRESNEL_HIGHP float d_nm)$/\1(fr_c, 300.0)/p" "$glsl" | paste -sd+)
        for v in 110 120 130 150 450 es310 es320; do
            f="$out/${ident}_all_$v.frag"
            case $v in 110 | 120) e=$all ;; *) e="$all+$film" ;; esac # const arrays from 1.30
            { prelude_of "$v"; cat "$port/fresnel.glsl" "$glsl"; main_of "$v" "$e"; } >"$f"
            validate "glslang: $scene, every model and material, GLSL $v" "$f"
        done
    fi
done

exit 0
