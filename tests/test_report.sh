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
"$F" report --scene "$t/missing.scene" -o "$t/out2" --no-timing >/dev/null 2>"$t/err"
[ $? -eq 2 ] && [ ! -e "$t/out2/report.md" ] && echo "PASS report: a missing scene is an error (exit 2), nothing written" ||
    echo "FAIL report missing scene"
