#!/bin/sh
# passes: first (the examples do not change with the pass's flags)
# The README's examples run as printed: every code block of README.md, of
# gen/README.md and of ports/README.md's firmware and set-up sections, in order, in a
# scratch directory that holds the repository's top-level entries (build/
# is $BUILD) and what the blocks before wrote; HOME is a scratch directory.
# Each block is fenced, and its info string says how it is checked:
#   sh     run as a script (set -e); `make test` (this run), `make report`,
#          `make bench`, `make cross-count` (minutes of timing and
#          emulation) are checked to be targets of the Makefile instead
#   scene  a manifest, written to the file its first line names (# NAME)
#   c      compiled by gcc as C99 and by g++ as C++17, -Wall -Wextra
#          -Wpedantic -Werror, against include/, ports/single/ and the
#          headers the blocks before wrote
#   cmake  the lines of a game's CMakeLists.txt, with this repository in
#          fresnel/ and tests/ports/consumer/consumer.c as the game: configured,
#          built and run
#   glsl   compiled by glslangValidator after ports/glsl/prelude_es300.glsl,
#          ports/glsl/fresnel.glsl and the .glsl files the blocks before wrote
#   metal  compiled as C++ by g++ (-fsingle-precision-constant) through
#          tests/shader_ports/msl/metal_stdlib, with ports/msl/ and the
#          .metal files the blocks before wrote, in float and with
#          FRESNEL_MSL_HALF (Apple's compiler is macOS-only)
#   wgsl   compiled as one module after the .wgsl files the blocks before
#          wrote, in headless Chromium's WebGPU (tests/shader_ports/webgpu_page.sh)
#   text   not run: a listing or a program's output
# Any other block, and an indented code block, is a FAIL. In README.md's
# prose every `build/fresnel ...` command runs (exit 0) and every `make ...`
# names a target. The Cortex-M0 table beside the Q1.15 example gives, for
# each one-channel function the example calls, the bound its header states,
# the model's CIEDE2000 and the counts data/report/report.md records (its
# row found through tests/ports/cross/q15_models.h). README.md is at most
# 250 lines: detail lives in the documents it links.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
root=$(pwd)
case $BUILD in /*) build_abs=$BUILD ;; *) build_abs=$root/$BUILD ;; esac
run=$t/run
mkdir -p "$run" "$t/home" "$t/blocks"
for f in *; do
    [ "$f" = build ] || ln -s "$root/$f" "$run/$f"
done
ln -s "$build_abs" "$run/build"

# ---- the blocks, in order: $t/blocks/NNN.TAG, their origin in $t/blocks/NNN.where ----
# extract FILE [HEADING]: FILE's blocks (only under the ## HEADING if given)
n=0
extract() {
    awk -v file="$1" -v heading="$2" -v dir="$t/blocks" -v start="$n" '
        BEGIN { k = start; on = heading == "" }
        !fence && /^## / { if (heading != "") on = substr($0, 4) == heading }
        !on { next }
        /^```/ {
            if (!fence) { fence = 1; tag = substr($0, 4); sub(/[ \t].*/, "", tag); if (tag == "") tag = "none"
                          k++; out = sprintf("%s/%03d.%s", dir, k, tag)
                          printf "%s:%d", file, NR > sprintf("%s/%03d.where", dir, k); printf "" > out; next }
            fence = 0; close(out); next
        }
        fence { print >> out; next }
        /^(    |\t)/ && prev == "" { k++; printf "%s:%d", file, NR > sprintf("%s/%03d.where", dir, k)
                                   printf "%s\n", $0 > sprintf("%s/%03d.indented", dir, k) }
        { prev = $0 }
        END { print k > (dir "/count") }' "$1"
    n=$(cat "$t/blocks/count")
}
extract README.md
extract gen/README.md
extract ports/README.md "Firmware: a scene to a Cortex-M0 binary"
extract ports/README.md "Set-up, install, CMake and vendoring"

W="-Wall -Wextra -Wpedantic -Werror"
for b in "$t"/blocks/[0-9]*; do
    case $b in *.where) continue ;; esac
    where=$(cat "${b%.*}.where")
    tag=${b##*.}
    case $tag in
    text) echo "PASS $where: text, not run" ;;
    scene)
        name=$(sed -n '1s/^# \([A-Za-z0-9_.-]*\.scene\).*/\1/p' "$b")
        if [ -n "$name" ]; then
            cp "$b" "$run/$name"
            echo "PASS $where: scene $name written"
        else
            echo "FAIL $where: a scene block must name its file on its first line (# NAME.scene)"
        fi
        ;;
    sh)
        # the long runs checked as targets, the rest run as printed
        sed -E 's/^make (test|report|bench|cross-count)( .*)?$/readme_target \1/' "$b" >"$t/block.sh"
        if (cd "$run" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL HOME="$t/home" sh -e -c \
            'readme_target() { grep -q "^$1:" Makefile || { echo "make $1: no such target" >&2; exit 1; }; }
             . "$0"' "$t/block.sh") >"$t/log" 2>&1; then
            ran=$(grep -vc -e '^readme_target ' -e '^\s*#' -e '^\s*$' "$t/block.sh")
            checked=$(grep -c '^readme_target ' "$t/block.sh")
            echo "PASS $where: sh, $ran command(s) ran$([ "$checked" -eq 0 ] || echo ", $checked make target(s) checked")"
        else
            echo "FAIL $where: sh: $(tail -5 "$t/log" | tr '\n' ' ')"
        fi
        ;;
    c)
        cp "$b" "$t/block.c"
        if (cd "$run" && gcc -std=c99 $W -Iinclude -I. -Iports/single -c "$t/block.c" -o "$t/block.o") >"$t/log" 2>&1 &&
            (cd "$run" && g++ -x c++ -std=c++17 $W -Iinclude -I. -Iports/single -c "$t/block.c" -o "$t/block.o") >>"$t/log" 2>&1 &&
            [ ! -s "$t/log" ]; then
            echo "PASS $where: c, compiles warning-free as C99 (gcc) and C++17 (g++)"
        else
            echo "FAIL $where: c: $(head -5 "$t/log" | tr '\n' ' ')"
        fi
        ;;
    cmake)
        rm -rf "$t/cm"
        mkdir -p "$t/cm/game"
        ln -s "$root" "$t/cm/game/fresnel"
        cp tests/ports/consumer/consumer.c "$t/cm/game/main.c"
        { printf 'cmake_minimum_required(VERSION 3.16)\nproject(game C)\nadd_executable(game main.c)\n'; cat "$b"; } \
            >"$t/cm/game/CMakeLists.txt"
        if cmake -S "$t/cm/game" -B "$t/cm/build" >"$t/log" 2>&1 &&
            env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build "$t/cm/build" >>"$t/log" 2>&1 &&
            "$t/cm/build/game" >"$t/game.out" && [ -s "$t/game.out" ]; then
            echo "PASS $where: cmake, a game built and run with these lines"
        else
            echo "FAIL $where: cmake: $(grep -i -m5 -e error -e 'not found' "$t/log" | tr '\n' ' ')"
        fi
        ;;
    glsl)
        { cat ports/glsl/prelude_es300.glsl ports/glsl/fresnel.glsl
          for g in "$run"/*.glsl; do [ -f "$g" ] && [ ! -L "$g" ] && cat "$g"; done
          cat "$b"; } >"$t/block.frag"
        if ! command -v glslangValidator >/dev/null 2>&1; then
            echo "FAIL $where: glslangValidator not found (Debian's glslang-tools)"
        elif glslangValidator "$t/block.frag" >"$t/log" 2>&1; then
            echo "PASS $where: glsl, compiles (GLSL ES 3.00 fragment shader)"
        else
            echo "FAIL $where: glsl: $(grep -m5 -i error "$t/log" | tr '\n' ' ')"
        fi
        ;;
    metal)
        cp "$b" "$run/block.metal.cpp"
        if (cd "$run" && for half in "" -DFRESNEL_MSL_HALF=1; do
            g++ -std=c++14 -fsingle-precision-constant -Wall -Wextra -Werror $half -I"$root/ports/msl" \
                -I"$root/tests/shader_ports/msl" -I. -c block.metal.cpp -o "$t/block.o" || exit 1
        done) >"$t/log" 2>&1; then
            echo "PASS $where: metal, compiles as C++ through the host's metal_stdlib map, float and half"
        else
            echo "FAIL $where: metal: $(grep -m5 -i error "$t/log" | tr '\n' ' ')"
        fi
        rm -f "$run/block.metal.cpp"
        ;;
    wgsl)
        { for g in "$run"/*.wgsl; do [ -f "$g" ] && [ ! -L "$g" ] && cat "$g"; done; cat "$b"; } >"$t/block.wgsl"
        if ! command -v "${CHROMIUM:-chromium}" >/dev/null 2>&1; then
            echo "FAIL $where: chromium not found (Debian's chromium; tests/deps.sh installs it)"
        elif msg=$(sh tests/shader_ports/webgpu_page.sh compile "$t/block.wgsl" "$t"); then
            echo "PASS $where: wgsl, compiles in Chromium's WebGPU after the module the blocks before wrote"
        else
            echo "FAIL $where: wgsl: $msg"
        fi
        ;;
    indented) echo "FAIL $where: an indented code block: fence it and tag it (sh, c, text, ...)" ;;
    *) echo "FAIL $where: a code block tagged '$tag', which this test cannot check (tests/repo/test_readme.sh)" ;;
    esac
done

# ---- commands in README.md's prose ----
awk '/^```/ { fence = !fence; next } !fence { printf "%s ", $0 } /^$/ { print "" }' README.md |
    grep -o '`[^`]*`' | tr -d '`' | sort -u >"$t/spans"
bad="" ran=0
while IFS= read -r span; do
    case $span in
    "build/fresnel "*)
        (cd "$run" && HOME="$t/home" sh -c "$span" >/dev/null 2>"$t/err") || bad="$bad [$span: $(head -1 "$t/err")]"
        ran=$((ran + 1))
        ;;
    "make "*)
        target=$(echo "$span" | awk '{ print $2 }')
        grep -q "^$target:" Makefile || bad="$bad [$span: no such target]"
        ran=$((ran + 1))
        ;;
    esac
done <"$t/spans"
[ -z "$bad" ] && echo "PASS README.md's prose: $ran commands run or make targets found" ||
    echo "FAIL README.md's prose:$bad"

# ---- the Q1.15 example's costs and bounds ----
# q15_models.h: "{"ROW", e_NAME" and "e_NAME(...) { return FUNCTION(" give FUNCTION's row
awk '/^static fresnel_q15 e_[a-z0-9_]*\(/ { e = $3; sub(/\(.*/, "", e) }
     e && /return fresnel_[a-z0-9_]*\(/ { f = $0; sub(/.*return /, "", f); sub(/\(.*/, "", f); fn[e] = f; e = "" }
     /^    \{"[^"]*", e_[a-z0-9_]*,/ { split($0, p, "\""); r = $0; sub(/.*", /, "", r); sub(/,.*/, "", r); row[r] = p[2] }
     END { for (r in row) if (r in fn) print fn[r] "\t" row[r] }' tests/ports/cross/q15_models.h >"$t/rows"
sed -n '/^== m0 fixed point/,/^== /p' data/report/report.md >"$t/m0"
sed -n '/^## Summary over the metals/,/^## /p' data/report/report.md >"$t/summary"
bad="" rows=0
for f in $(sed -n 's/^| `\(fresnel_[a-z0-9_]*_q15\(_fast\)\{0,1\}\)` | .*/\1/p' README.md); do
    line=$(grep "^| \`$f\` |" README.md)
    row=$(awk -F'\t' -v f="$f" '$1 == f { print $2 }' "$t/rows")
    macro=$(echo "$f" | sed 's/^fresnel_//; s/_q15/_Q15/' | tr a-z A-Z | sed 's/^/FRESNEL_BOUND_/')
    bound=$(sed -n "s/^#define $macro \([0-9.]*\).*/\1/p" include/fresnel_q15.h include/fresnel_q15_fast.h)
    counts=$(awk -v r="$row" 'index($0, r) == 1 { rest = substr($0, length(r) + 1); split(rest, v, " ")
                 if (v[1] ~ /^[0-9]+$/) { print v[1] " / " v[3] " | " v[4] " / " v[7]; exit } }' "$t/m0")
    # the model's CIEDE2000 (the report's summary row of the scene model, q15); a
    # fast path "as above": within its own bound of the same model
    case $f in *_fast) de="as above" ;; *)
        model=$(echo "$row" | sed 's/^exact-conductor$/exact/')
        de=$(awk -F'|' -v m="$model" '{ gsub(/ /, "", $2); gsub(/ /, "", $3) } $2 == m && $3 == "q15" {
            gsub(/ /, "", $4); gsub(/ /, "", $5); print $4 " / " $5; exit }' "$t/summary") ;;
    esac
    want="| \`$f\` | $bound | $de | $counts |"
    rows=$((rows + 1))
    [ -n "$row" ] && [ -n "$bound" ] && [ "$line" = "$want" ] || bad="$bad [$line, expected $want]"
done
used=$(awk '/^```c/ { c = 1; next } /^```/ { c = 0 } c' README.md | grep -o 'fresnel_[a-z0-9_]*_q15[a-z0-9_]*(' |
    tr -d '(' | sed 's/_rgb//' | sort -u)
for f in $used; do
    grep -q "^| \`$f\` |" README.md || bad="$bad [$f: called by an example, no cost row]"
done
if [ "$rows" -gt 0 ] && [ -z "$bad" ]; then
    echo "PASS README.md's Cortex-M0 table: $rows functions (every one the Q1.15 example calls), the headers' bounds, data/report/report.md's CIEDE2000 and counts"
else
    echo "FAIL README.md's Cortex-M0 table:$bad"
fi

# ---- the thin film's row: its errors and its peers' against the report ----
# The row's "mean / max" pairs, in order: binary32, Q1.15, binary16, then
# KHR_materials_iridescence and the polarised form; the report's "all" rows
# of the film's two tables ("Thin film"). Each README number equals the
# report's within half a unit of its own last digit.
film_row=$(grep '^| a thin film' README.md)
readme_pairs=$(echo "$film_row" | grep -o '[0-9][0-9.]* / [0-9][0-9.]*' | sed 's| / | |' | tr '\n' ' ')
report_pairs=$(sed -n '/^## Thin film/,/^## /p' data/report/report.md | awk -F'|' '
    /^\| all \| \| / { a = $4 " " $5 " " $6 " " $7 " " $8 " " $9 }
    /^\| all \| [0-9]/ { b = $5 " " $6 " " $7 " " $8 }
    END { print a " " b }')
verdict=$(echo "$readme_pairs | $report_pairs" | awk -F'|' '{
    n = split($1, r, " "); m = split($2, q, " ")
    if (n != 10 || m != 10) { print "README has " n " numbers, the report " m " (10 expected)"; exit }
    for (i = 1; i <= n; i++) { d = index(r[i], ".") ? length(r[i]) - index(r[i], ".") : 0
        half = 0.5 * 10 ^ -d; diff = r[i] - q[i]; if (diff < 0) diff = -diff
        if (diff > half + 1e-12) printf "%s against the report'"'"'s %s; ", r[i], q[i] } }')
if [ -n "$film_row" ] && [ -z "$verdict" ]; then
    echo "PASS README.md's thin-film row: its CIEDE2000 (binary32, Q1.15, binary16) and its peers' (KHR_materials_iridescence, polarised) are data/report/report.md's"
else
    echo "FAIL README.md's thin-film row: ${verdict:-no row starting '| a thin film'}"
fi

# ---- README's length ----
lines=$(wc -l <README.md)
[ "$lines" -le 250 ] && echo "PASS README.md is $lines lines (at most 250)" ||
    echo "FAIL README.md is $lines lines, above 250: move detail to the documents it links"

# ---- the batches' sentence: what it claims is targets.md's ----
# "under half the scalar call's on a Cortex-M4F and a quarter on a
# Cortex-M55" for Schlick, F82 and the LUTs: those eight rows of
# data/report/targets.md are marked pass.
if grep -q "Schlick's, F82's and the u16 LUTs' instructions per cosine under half the scalar call's on a Cortex-M4F and a quarter on a Cortex-M55" README.md; then
    missing=""
    for core in "Cortex-M4F (long multiply)" "Cortex-M55 (Helium)"; do
        for m in Schlick F82 "LUT (u16, 64 nodes uniform in sqrt(c))" "LUT (u16, 64 nodes uniform in c)"; do
            grep -F "| $core, $m batch: instructions per cosine" data/report/targets.md | grep -q '\*\*pass\*\* |$' ||
                missing="$missing [$core $m]"
        done
    done
    if [ -z "$missing" ]; then
        echo "PASS README.md's batch sentence: Schlick's, F82's and the LUTs' batch rows on the Cortex-M4F and M55 are targets.md's passes"
    else
        echo "FAIL README.md's batch sentence: not a pass in data/report/targets.md:$missing"
    fi
else
    echo "FAIL README.md's batch sentence: not found"
fi
