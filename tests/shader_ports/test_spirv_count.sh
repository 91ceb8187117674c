#!/bin/sh
# passes: first (glslangValidator and spirv-opt do the same work in every pass)
# make check: no (glslangValidator, spirv-opt)
# `make spirv-count` (ports/vulkan/spirv_count.sh): a row for every model of
# ports/vulkan/spirv_count.scene and for the thin film's two peers with a positive instruction count in each
# column (the harness subtracted), every optimised module valid SPIR-V
# (the script runs spirv-val and stops on a failure), the harness and the
# tools named; and `fresnel report --spirv FILE` carries the table into the
# report's GPU section as printed.
BUILD=${BUILD:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if ! sh ports/vulkan/spirv_count.sh "$BUILD" >"$t/count.txt" 2>"$t/err"; then
    echo "FAIL spirv-count: $(head -3 "$t/err")"
    exit 1
fi
missing=""
for model in $(sed -n 's/^models *= *//p' ports/vulkan/spirv_count.scene) khr-iridescence-peer polarised-film-peer; do
    grep -Eq "^\| $model \| [1-9][0-9]* \| [1-9][0-9]* \|$" "$t/count.txt" || missing="$missing $model"
done
n=$(sed -n 's/^models *= *//p' ports/vulkan/spirv_count.scene | wc -w)
if [ -z "$missing" ] && grep -q '^Harness (main reading the cosine' "$t/count.txt" && grep -q '^Tools: glslang .*SPIRV-Tools' "$t/count.txt"; then
    echo "PASS spirv-count: $n models and the film's two peers, each a positive count highp and mediump (16-bit), harness and tools named"
else
    echo "FAIL spirv-count: rows missing or malformed:$missing ($(head -4 "$t/count.txt" | tr '\n' ' '))"
fi
printf 'materials = au\nmodels = schlick\n' >"$t/one.scene"
if "$BUILD/fresnel" report --scene "$t/one.scene" -o "$t/rep" --no-timing --no-instructions --spirv "$t/count.txt" \
    >"$t/log" 2>&1 && grep -q '^## GPU: SPIR-V instructions per call$' "$t/rep/report.md" &&
    [ "$(grep -c -F -x -f "$t/count.txt" "$t/rep/report.md")" -ge "$(grep -c . "$t/count.txt")" ]; then
    echo "PASS spirv-count: fresnel report --spirv carries the table into report.md's GPU section"
else
    echo "FAIL report --spirv: $(tail -3 "$t/log")"
fi
