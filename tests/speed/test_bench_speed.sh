#!/bin/sh
# passes: first other (the program is built here with CC, not by the pass)
# `make bench`'s program (tests/speed/speed.c) builds with the flag set given and
# prints the format gen/bench/speed_targets.h describes: its header, every
# row, every target; `fresnel report --speed` reads what it prints. Nothing
# about speed is checked: the numbers are benchmarks (make bench).
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if make -s --no-print-directory BUILD="$t/b" GEN_TOOL="$F" CC="${CC:-cc}" OPT=-O1 SPEED_ARGS='--rounds 3' bench-run \
    >"$t/speed.txt" 2>"$t/err"; then
    echo "PASS bench speed: builds in its own directory per compiler and flag set and runs (OPT=-O1, 3 rounds)"
else
    echo "FAIL bench speed: $(head -3 "$t/err")"
    exit 0
fi
ls -d "$t/b/bench/"*-O1 >/dev/null 2>&1 && echo "PASS bench speed: built in $(basename "$(ls -d "$t/b/bench/"*-O1)")/" ||
    echo "FAIL bench speed: no build directory named after the flag set: $(ls "$t/b/bench" 2>&1)"
missing=""
for k in opt cflags compiler cpu vector workload peers; do
    grep -q "^# $k: " "$t/speed.txt" || missing="$missing $k"
done
grep -q '^# opt: -O1$' "$t/speed.txt" && grep -q '^# cflags: .* -O1 -fno-math-errno -fno-trapping-math' "$t/speed.txt" ||
    missing="$missing (opt/cflags value)"
[ -z "$missing" ] && echo "PASS bench speed: header names flags, compiler, CPU, vector extension, workload and peers" ||
    echo "FAIL bench speed: header lacks:$missing"
missing=""
for r in copy schlick-inline sqrt2-div1 sqrt2-div2 schlick-f32 schlick-q15 conductor-call conductor-prepared conductor-batch \
    conductor-rgb-batch mitsuba-call mitsuba-inline mitsuba-inline-rgb pbrt-call pbrt-inline lut16-cubic-f32 lut32-q15 lut16-cubic-q15 lut16-linear-q15 \
    schlick-rgb-f32 film-f32; do
    awk -v r="$r" '$1 == "row" && $2 == r && NF == 11 { f = 1 } END { exit !f }' "$t/speed.txt" || missing="$missing $r"
done
[ -z "$missing" ] && echo "PASS bench speed: every row (floors, library calls and batch, peers as call and inlined, LUTs, RGB Schlick, the thin film), 11 fields" ||
    echo "FAIL bench speed: rows missing or malformed:$missing"
n=$(grep -c '^target ' "$t/speed.txt")
[ "$n" -ge 7 ] && grep -q '^target batch-vs-mitsuba-inline .*goal -O2 <= 0.5, -O3 -march=native <= 0.8' "$t/speed.txt" &&
    echo "PASS bench speed: $n target lines; a flag set without goals names both goals" ||
    echo "FAIL bench speed: $n target lines: $(grep '^target' "$t/speed.txt" | head -2)"
printf 'materials = cu\nmodels = schlick\n' >"$t/tiny.scene"
if "$F" report --scene "$t/tiny.scene" -o "$t/out" --no-timing --no-instructions --speed "$t/speed.txt" >"$t/log" 2>&1 &&
    [ "$(grep -c '^| Host speed: ' "$t/out/targets.md")" -ge 6 ] && grep -q '; [^;|]* -O1: [0-9.]*x (no goal at this flag set)' "$t/out/targets.md"; then
    echo "PASS bench speed: fresnel report --speed reads the program's output"
else
    echo "FAIL bench speed: report --speed: $(head -3 "$t/log")"
fi
