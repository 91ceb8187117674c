#!/bin/sh
# `fresnel report` runs on a tiny scene and writes every part;
# every dE number in the summary is finite and >= 0. Timing and instruction
# counts are benchmarks (make report), not tests.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
printf 'materials = cu water\nmodels = schlick exact lut16\n' >"$t/tiny.scene"
if "$F" report --scene "$t/tiny.scene" -o "$t/out" --no-timing --no-instructions >"$t/log" 2>&1 &&
    [ -s "$t/out/report.md" ] && [ -s "$t/out/pareto.svg" ] && [ -s "$t/out/sigma.svg" ] &&
    [ -s "$t/out/curves/cu.svg" ] && [ -s "$t/out/curves/water.svg" ]; then
    echo "PASS report: report.md, pareto.svg, sigma.svg and curves/*.svg written for a tiny scene"
else
    echo "FAIL report on a tiny scene: $(tail -3 "$t/log")"
fi
bad=$(sed -n '/^## Summary/,/^## Every/p' "$t/out/report.md" | grep '^| [a-z]' | awk -F'|' '{ if (!($4 + 0 >= 0) || !($5 + 0 >= 0) || $4 ~ /nan|inf/ || $5 ~ /nan|inf/) print }')
rows=$(sed -n '/^## Summary/,/^## Every/p' "$t/out/report.md" | grep -c '^| [a-z]')
[ -z "$bad" ] && [ "$rows" -ge 3 ] && echo "PASS report: $rows summary rows, every dE finite and >= 0" ||
    echo "FAIL report summary: rows $rows, bad: $bad"
grep -q '## Reproducing Hoffman' "$t/out/report.md" && grep -q '## Which model for which budget' "$t/out/report.md" &&
    grep -q '## Gaussian window width' "$t/out/report.md" && grep -q '## Colours outside the gamut' "$t/out/report.md" &&
    grep -q '## Hemispherical average F_avg' "$t/out/report.md" && echo "PASS report: every section present" ||
    echo "FAIL report: a section is missing"
# The renderers' table: the metal only, every target and the project's own columns.
sec=$(sed -n '/^## How well each renderer shows each metal/,/^## Reproducing/p' "$t/out/report.md")
if printf '%s\n' "$sec" | grep -q '^| metal | openpbr | materialx | blender | unreal | gltf | filament | gulbrandsen | ours: f82 | ours: exact | ours: best of the scene |$' &&
    printf '%s\n' "$sec" | grep -qE '^\| cu( \| [0-9.]+ / [0-9.]+){7} \| - \| [0-9.]+ / [0-9.]+ \| [0-9.]+ / [0-9.]+ \([a-z0-9-]+\) \|$' &&
    ! printf '%s\n' "$sec" | grep -q '^| water'; then
    echo "PASS report: the renderers' table, cu's row (no f82 in the scene: '-'), no dielectric"
else
    echo "FAIL report: renderers' table: $(printf '%s\n' "$sec" | grep '^| ' | head -4 | tr '\n' '|')"
fi
"$F" report --scene "$t/missing.scene" -o "$t/out2" --no-timing >/dev/null 2>"$t/err"
[ $? -eq 2 ] && [ ! -e "$t/out2/report.md" ] && echo "PASS report: a missing scene is an error (exit 2), nothing written" ||
    echo "FAIL report missing scene"

# The host speed targets (targets.md, the developers' file): one row per
# target with its ratio for each compiler at both flag sets of `make bench`
# and a mark; a miss by either compiler is a miss and says what it is.
# report.md holds the measurements only: the bench output without its
# target lines, no goal, mark or what was tried. Synthetic --speed files
# (the format of gen/bench/speed_targets.h), not a timing.
speed_file() { # OPT RATIO [COMPILER]: every target's ratio RATIO
    printf '# opt: %s\n# compiler: %s\n' "$1" "${3:-test}"
    for r in schlick-f32 schlick-q15 conductor-call conductor-batch conductor-rgb-batch mitsuba-call mitsuba-inline \
        mitsuba-inline-rgb lut16-cubic-f32 \
        lut32-q15 lut16-cubic-q15 lut16-linear-q15; do
        printf 'row %s call 1 1 1 1 1 1 1 1\n' "$r"
    done
    for id in batch-vs-mitsuba-inline rgb-batch-vs-mitsuba-inline conductor-vs-mitsuba-call lut16-cubic-vs-schlick lut32-q15-vs-schlick-q15 \
        lut16-cubic-q15-vs-schlick-q15 lut16-linear-q15-vs-schlick-q15; do
        printf 'target %s %s %s %s goal text\n' "$id" "$2" "$2" "$2"
    done
}
speed_file -O2 0.25 cc-a >"$t/o2.txt"
speed_file '-O3  -march=native' 0.75 cc-a >"$t/o3.txt"
speed_file -O2 0.25 cc-b >"$t/o2b.txt"
speed_file '-O3 -march=native' 0.9 cc-b >"$t/o3b.txt"
printf 'materials = cu\nmodels = schlick\n' >"$t/one.scene"
if "$F" report --scene "$t/one.scene" -o "$t/sp" --no-timing --no-instructions --speed "$t/o2.txt" --speed "$t/o3.txt" \
    --speed "$t/o2b.txt" --speed "$t/o3b.txt" >"$t/log" 2>&1; then
    rows=$(grep '^| Host speed: ' "$t/sp/targets.md")
    n=$(echo "$rows" | grep -c 'MISS\|pass')
    all=$(echo "$rows" | grep -c -- 'cc-a -O2: [0-9.]*x (quartiles [0-9.]*-[0-9.]*) \(pass\|MISS\).*; cc-a -O3 -march=native: [0-9.]*x.*; cc-b -O2: [0-9.]*x.*; cc-b -O3 -march=native: [0-9.]*x')
    miss=$(echo "$rows" | grep -c 'conductor-batch / mitsuba-inline.*cc-a -O3 -march=native: 0.75x (quartiles 0.75-0.75) pass.*cc-b -O3 -march=native: 0.90x (quartiles 0.90-0.90) MISS: conductor-batch takes 0.90x the time of mitsuba-inline, goal 0.8x.*| \*\*MISS\*\* |$')
    pass=$(echo "$rows" | grep 'lut16-linear-q15 / schlick-q15' | grep -c '| \*\*pass\*\* |$')
    heads=$(grep -c "^\`make bench OPT='[^']*'\`, cc-[ab]:$" "$t/sp/report.md")
    [ "$n" -eq 7 ] && [ "$all" -eq 7 ] && [ "$miss" -eq 1 ] && [ "$pass" -eq 1 ] && [ "$heads" -eq 4 ] &&
        grep -q "^## Host speed against other renderers' algorithms" "$t/sp/report.md" &&
        echo "PASS report: 7 host speed targets, each with its ratio for two compilers at -O2 and -O3 -march=native and a pass/MISS mark; a miss by one compiler is a miss and says what it is" ||
        echo "FAIL report speed rows: $n rows, $all with both compilers and flag sets, miss $miss, pass $pass, $heads file headings: $(echo "$rows" | head -2)"
    facts=$(grep -n -i -E 'goal|pass\*\*|MISS|tried|^target |^# target' "$t/sp/report.md" | head -3)
    [ -z "$facts" ] && [ "$(grep -c '^row conductor-batch ' "$t/sp/report.md")" -eq 4 ] && grep -q '^# Targets' "$t/sp/targets.md" &&
        echo "PASS report: report.md states measurements (the bench rows; no target line, goal, mark or what was tried), targets.md the targets" ||
        echo "FAIL report.md speaks of goals: $facts"
else
    echo "FAIL report --speed: $(tail -3 "$t/log")"
fi
# The Cortex-M0 targets read their rows by name from `make cross-count`'s
# m0 section: a row whose name begins another's ("lut u16", "lut u16 fast")
# is itself, and a miss says where its instructions go.
{
    echo "== m0 fixed point: per call (synthetic)"
    echo "schlick                          92     86     92      154    150    155      433    429    434"
    echo "lut u16                         187     90    201      276    172    294      604    296    635"
    echo "schlick fast                     20     20     20       27     27     27      151    151    151"
    echo "f82 fast                         35     35     35       51     51     51      268    268    268"
    echo "lut u16 fast                     58      7     76       83     22    114      229     22    269"
    echo "lut u16 pl fast                  29     29     33       37     37     39      130    130    132"
    echo "== m4f fixed point: per call (synthetic)"
    echo "lut u16                          99     64    145"
} >"$t/cross.txt"
if "$F" report --scene "$t/one.scene" -o "$t/cr" --no-timing --no-instructions --cross "$t/cross.txt" >"$t/log" 2>&1; then
    lut=$(grep '^| Cortex-M0 fixed point, LUT (u16, 64 nodes, nodes uniform in sqrt(c))' "$t/cr/targets.md")
    case "$lut" in
    *"| 58 inline fast path (library function 187); the square root of the position"*"| **MISS** |")
        echo "PASS report: the Cortex-M0 LUT row reads 'lut u16' itself, not the longer 'lut u16 fast', and its miss says where the instructions go" ;;
    *) echo "FAIL report Cortex-M0 LUT row: $lut" ;;
    esac
else
    echo "FAIL report --cross: $(tail -3 "$t/log")"
fi
"$F" report --scene "$t/one.scene" -o "$t/sp0" --no-timing --no-instructions >/dev/null 2>&1
grep -q '^| Host speed against .* | not measured |$' "$t/sp0/targets.md" &&
    echo "PASS report: without --speed the host speed targets are 'not measured'" ||
    echo "FAIL report without --speed: $(grep 'Host speed' "$t/sp0/targets.md" | head -2)"
{ speed_file -O2 0.25 | head -4; echo 'row conductor-batch call 1 2'; } >"$t/bad.txt"
"$F" report --scene "$t/one.scene" -o "$t/sp2" --no-timing --speed "$t/bad.txt" >/dev/null 2>"$t/err"
[ $? -eq 2 ] && [ ! -e "$t/sp2/report.md" ] && grep -q "bad.txt:5: expected row NAME FORM then 8 finite numbers" "$t/err" &&
    echo "PASS report: a malformed --speed file is an error at file:line (exit 2), nothing written" ||
    echo "FAIL report bad --speed: $(cat "$t/err")"
# sscanf reads "inf" and "nan" as numbers: they are refused like any other malformed value
for bad in 'row conductor-batch call 1 2 3 4 inf 1 1 1' 'row conductor-batch call 1 2 3 4 5 1 nan 1' 'target conductor-batch inf 1 1'; do
    { speed_file -O2 0.25 | head -4; echo "$bad"; } >"$t/inf.txt"
    "$F" report --scene "$t/one.scene" -o "$t/sp3" --no-timing --no-instructions --speed "$t/inf.txt" >/dev/null 2>"$t/err"
    rc=$?
    [ $rc -eq 2 ] && [ ! -e "$t/sp3/report.md" ] && grep -q "inf.txt:5: expected .*finite" "$t/err" &&
        echo "PASS report: --speed line '$bad' is refused at file:line (exit 2)" ||
        echo "FAIL report --speed '$bad': exit $rc $(cat "$t/err")"
done
