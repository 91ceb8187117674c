#!/bin/sh
# passes: first (the generator's output does not depend on the compiler of the pass)
# start: early
# The generator's output, byte for byte: every back end of `fresnel gen` (the
# C header in the manifest's types and, where the manifest allows, in every
# type; GLSL with its texture; HLSL) for every scene of data/scenes,
# tests/data/scenes, tests/data/identity and tests/speed/film.scene, its SHA-256 (of
# the output and the messages, the checkout's path taken out) and exit
# status, against tests/data/identity/expected.txt. A change to the
# generator's structure keeps these equal; a change to what it writes
# updates the file on purpose (UPDATE=1 sh tests/gen/test_gen_identity.sh) and
# says why in its commit.
F="${BUILD:-build}/fresnel"
expected=tests/data/identity/expected.txt
# one LABEL SCENE ARGS...: the line of one run (each run in a folder of its own)
if [ "${1-}" = --one ]; then
    label=$2 scene=$3
    shift 3
    d=$(mktemp -d "$T/run.XXXXXX")
    for a; do
        shift
        [ "$a" = TEX ] && a=$d/tex
        set -- "$@" "$a"
    done
    "$F" gen "$scene" -o "$d/out" "$@" 2>"$d/err"
    rc=$?
    # messages name the data pack by its absolute path: the checkout's own
    sed "s|$ROOT/||g" "$d/err" >"$d/err.rel"
    sum=$(cat "$d/out" "$d/tex" "$d/err.rel" 2>/dev/null | sha256sum | cut -c1-64)
    echo "$label rc=$rc $sum"
    exit 0
fi
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

ROOT=$(pwd)
export F T="$t" ROOT

# The runs, one per line: LABEL SCENE ARGS ($T/tex: the texture)
for s in data/scenes/*.scene tests/data/scenes/*.scene tests/data/identity/*.scene tests/speed/film.scene; do
    echo "$s:c $s"
    if ! grep -q '^ *material \|grazing-pl' "$s"; then
        mkdir -p "$t/all"
        sed '/^ *types *=/d' "$s" >"$t/all/$(basename "$s")"
        echo 'types = f32 q15 f16' >>"$t/all/$(basename "$s")"
        echo "$s:c-every-type $t/all/$(basename "$s")"
    fi
    echo "$s:glsl $s --glsl"
    echo "$s:tables $s --glsl --tables TEX"
    echo "$s:hlsl $s --hlsl"
    echo "$s:msl $s --msl"
    echo "$s:wgsl $s --wgsl"
done >"$t/runs"
jobs=${JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
xargs -P "$jobs" -L 1 sh "$0" --one <"$t/runs" |
    sort >"$t/got"

if [ "${UPDATE:-0}" = 1 ]; then
    cp "$t/got" "$expected"
    echo "PASS gen identity: $expected rewritten ($(wc -l <"$t/got") outputs)"
    exit 0
fi
n=$(wc -l <"$t/got")
if diff "$expected" "$t/got" >"$t/diff"; then
    echo "PASS gen identity: $n outputs of fresnel gen byte-identical to $expected"
else
    echo "FAIL gen identity: outputs differ from $expected:"
    grep '^[<>]' "$t/diff" | head -20
fi
