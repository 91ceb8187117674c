#!/bin/sh
# `fresnel params --for TARGET`: the rows each renderer's metal takes, the
# table of every target, and bad input (exit 2, the valid targets named, no
# output); the `targets` scene key: the same parameters in the header's
# comments, in C, GLSL and HLSL.
# What the fit promises: its mean CIEDE2000 never above the naive
# conversion's (the table, on five metals and two dielectrics), and no more:
# every text that says so (README.md, tests/README.md, targets.h,
# target_fit.c, `params --help`, the gain line) names the mean, and README's
# example of a max above the naive one (chromium in MaterialX) is the tool's
# own output.
# The gamut: water and BK7 in linear Rec.2020 (white at grazing incidence a
# rounding above 1) are inside it, gold in sRGB outside.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
bad() { # name, expected stderr pattern, args...
    name=$1; pat=$2; shift 2
    "$F" params "$@" >"$t/out" 2>"$t/err"
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qE -e "$pat" "$t/err" && [ ! -s "$t/out" ]; then
        echo "PASS params --for: $name (exit 2: $(head -1 "$t/err"))"
    else
        echo "FAIL params --for: $name: exit $rc, stderr '$(cat "$t/err")', stdout '$(head -2 "$t/out")'"
    fi
}
all='openpbr, materialx, blender, unreal, gltf, filament, gulbrandsen, all'
bad "unknown target lists the valid ones" "unknown target 'renderman' for --for \(expected one of: $all\)" \
    --material cu --for renderman
bad "near miss suggests and lists" "unknown target 'openpr' for --for \(did you mean 'openpbr'\? expected one of: $all\)" \
    --material cu --for openpr
bad "missing value" "--for" --material cu --for
bad "unknown target checked before the material" "unknown target" --material nosuchmetal --for x

# One target: its rows, inside OpenPBR's ranges (specular_color <= 1), then the dE lines.
if "$F" params --material au --for openpbr >"$t/out" 2>"$t/err" &&
    awk -F, '/^#/ { next } { rows[++n] = $1 }
             $1 != "parameter" { for (i = 2; i <= 4; i++) if (!($i >= 0 && $i <= 1)) bad = 1 }
             END { exit bad || n != 3 || rows[1] != "parameter" || rows[2] != "base_color" || rows[3] != "specular_color" }' \
        "$t/out" &&
    grep -qE '^# fitted: mean dE2000 [0-9.]+, max [0-9.]+' "$t/out" &&
    grep -qE '^# naive base_color,' "$t/out" && grep -qE '^# gain of the fit: ' "$t/out" &&
    grep -q 'against the unclipped ground truth (outside the srgb gamut)' "$t/out"; then
    echo "PASS params --for openpbr: base_color, specular_color in [0, 1], fitted / naive dE2000, gold's unclipped cost"
else
    echo "FAIL params --for openpbr: $(cat "$t/err") $(tr '\n' '|' <"$t/out")"
fi
# A scalar row repeats in r, g, b.
if "$F" params --material ag --for materialx >"$t/out" 2>"$t/err" &&
    awk -F, '$1 == "exponent" { ok = $2 == $3 && $3 == $4 } END { exit !ok }' "$t/out" &&
    [ "$(grep -vc '^#' "$t/out")" -eq 5 ]; then
    echo "PASS params --for materialx: color0, color82, color90 and exponent (repeated in r, g, b)"
else
    echo "FAIL params --for materialx: $(cat "$t/err") $(tr '\n' '|' <"$t/out")"
fi
# glTF takes linear Rec.709 only: another space is flagged.
if "$F" params --material cu --space display-p3 --for gltf >"$t/out" 2>"$t/err" &&
    grep -q '^# this format takes linear Rec.709 (--space srgb); these values are in display-p3' "$t/out" &&
    grep -q '^baseColorFactor,' "$t/out"; then
    echo "PASS params --for gltf --space display-p3: baseColorFactor, flagged as not Rec.709"
else
    echo "FAIL params --for gltf --space display-p3: $(cat "$t/err") $(tr '\n' '|' <"$t/out")"
fi
# The table: every target, the fit's mean never above the naive mean.
if "$F" params --material cu --for all >"$t/out" 2>"$t/err" &&
    awk -F, '/^#/ { next } NR && $1 == "target" { head = $0; next }
             { n++; if (!($2 <= $4)) bad = 1 }
             END { exit bad || n != 7 || head != "target,fitted_mean,fitted_max,naive_mean,naive_max" }' "$t/out"; then
    echo "PASS params --for all: one row per target, fitted mean <= naive mean"
else
    echo "FAIL params --for all: $(cat "$t/err") $(tr '\n' '|' <"$t/out")"
fi
bad="" rows=0
for m in ag cu au al fe water bk7; do
    if "$F" params --material "$m" --for all >"$t/out" 2>"$t/err"; then
        rows=$((rows + $(grep -c '^[a-z]*,[0-9]' "$t/out")))
        bad="$bad$(awk -F, -v m="$m" '/^#/ || $1 == "target" { next } !($2 <= $4) { printf " [%s %s: %s > %s]", m, $1, $2, $4 }' "$t/out")"
    else
        bad="$bad [$m: $(cat "$t/err")]"
    fi
done
if [ "$rows" -eq 49 ] && [ -z "$bad" ]; then
    echo "PASS params --for all: the fitted mean <= the naive mean for every target on ag cu au al fe water bk7 ($rows fits)"
else
    echo "FAIL params --for all: fitted mean above the naive one ($rows rows):$bad"
fi

# The claim, as strong as the fit: wherever a text says the fit is never
# worse (or above) than the naive conversion, the same clause names the mean.
# claims NAME FILE: the clauses (split at , . ; : and brackets, each paragraph
# joined, comment marks dropped) that say "never worse/above" of the fit or
# the naive conversion without "mean".
claims() {
    awk -v name="$1" '
        { l = $0; sub(/^[ \t]*(\/\*|\*\/|\*|\/\/|#)?[ \t]*/, "", l) }
        l == "" { flush(); next }
        { para = para " " l }
        END { flush() }
        function flush(   n, i, c) {
            n = split(para, c, /[,.;:()]/)
            for (i = 1; i <= n; i++)
                if (c[i] ~ /never (worse|above)/ && c[i] ~ /(naive|fit)/ && c[i] !~ /mean/)
                    printf " [%s:%s]", name, c[i]
            para = ""
        }' "$2"
}
"$F" params --help >"$t/help" 2>&1
"$F" params --material cr --for materialx >"$t/cr" 2>"$t/err"
bad=""
for f in README.md tests/README.md gen/2_derive/targets.h gen/2_derive/target_fit.c; do
    bad="$bad$(claims "$f" "$f")"
done
bad="$bad$(claims "params --help" "$t/help")$(claims "params --for" "$t/cr")"
if [ -z "$bad" ] && grep -q 'fitted mean is never above the naive' "$t/help"; then
    echo "PASS the fit's promise names the mean wherever it is stated (README.md, tests/README.md, targets.h, target_fit.c, params --help and --for)"
else
    echo "FAIL a text promises more than the fitted mean:$bad"
fi
# README's example of a max above the naive one: chromium in MaterialX, as the tool prints it.
fit_max=$(sed -n 's/^# fitted: mean dE2000 [0-9.]*, max \([0-9.]*\) .*/\1/p' "$t/cr")
naive_max=$(sed -n 's/^# naive (.*): mean dE2000 [0-9.]*, max \([0-9.]*\)$/\1/p' "$t/cr")
para=$(awk '/^\*\*The same metal in another renderer\*\*/ { on = 1 } on && /^$/ { exit } on { printf "%s ", $0 }' README.md)
if [ -n "$fit_max" ] && [ -n "$naive_max" ] &&
    awk -v a="$fit_max" -v b="$naive_max" 'BEGIN { exit !(a + 0 > b + 0) }' &&
    echo "$para" | grep -q "chromium in MaterialX, $fit_max against the naive $naive_max" &&
    echo "$para" | grep -q 'maximum is not minimised' &&
    grep -q "^# gain of the fit: .*, max [0-9.]* higher (the fitted mean is never above the naive conversion's; the max is not minimised)" "$t/cr"; then
    echo "PASS README: the fit's max can be above the naive one: chromium in MaterialX $fit_max against $naive_max, as params prints it, and its gain line says higher"
else
    echo "FAIL README's example of the max: tool $fit_max against $naive_max; README: '$para'; $(grep '^# gain' "$t/cr")"
fi

# The gamut's boundary: rounding is not a colour outside it.
bad=""
for m in water bk7; do
    "$F" params --material "$m" --space rec2020 --for openpbr >"$t/out" 2>"$t/err" || bad="$bad [$m: $(cat "$t/err")]"
    ! grep -q 'outside the rec2020 gamut' "$t/out" || bad="$bad [$m --for openpbr: $(grep outside "$t/out")]"
    "$F" params --material "$m" --space rec2020 --for all >"$t/out" 2>"$t/err" || bad="$bad [$m: $(cat "$t/err")]"
    grep -qx 'target,fitted_mean,fitted_max,naive_mean,naive_max' "$t/out" || bad="$bad [$m --for all: $(grep '^target' "$t/out")]"
done
"$F" params --material au --for all >"$t/out" 2>"$t/err"
if [ -z "$bad" ] && grep -qx 'target,fitted_mean,fitted_max,naive_mean,naive_max,fitted_mean_unclipped,fitted_max_unclipped' "$t/out" &&
    "$F" params --material au --for openpbr | grep -q '^# against the unclipped ground truth (outside the srgb gamut)'; then
    echo "PASS params --for: water and bk7 inside the rec2020 gamut, gold outside srgb's"
else
    echo "FAIL params --for gamut:$bad $(grep '^target' "$t/out")"
fi

# The scene key: each material's comment holds what params --for prints.
printf 'materials = cu\nmodels = schlick\ntargets = blender gltf\ntypes = q15\n' >"$t/t.scene"
"$F" params --material cu --for blender >"$t/blender" 2>&1
if "$F" gen "$t/t.scene" -o "$t/t.h" 2>"$t/err" && "$F" gen "$t/t.scene" --glsl -o "$t/t.glsl" 2>>"$t/err" &&
    "$F" gen "$t/t.scene" --hlsl -o "$t/t.hlsl" 2>>"$t/err" &&
    h=$(awk '$2 == "blender" && $3 == "base_color" { print $4, $5, $6 }' "$t/t.h") &&
    p=$(awk -F, '$1 == "base_color" { printf "%.6f %.6f %.6f", $2, $3, $4 }' "$t/blender") &&
    [ -n "$h" ] && [ "$h" = "$p" ] && grep -q '^ \*   gltf         baseColorFactor ' "$t/t.h" &&
    grep -q '^ \*   blender      base_color ' "$t/t.glsl" && grep -q '^ \*   blender      base_color ' "$t/t.hlsl" &&
    printf '#include "t.h"\nint main(void) { return 0; }\n' >"$t/main.c" &&
    ${CC:-cc} -std=c99 -Wall -Wextra -Werror -Iinclude -I"$t" -c "$t/main.c" -o "$t/main.o" 2>>"$t/err"; then
    echo "PASS gen targets key: the header's comment holds params --for's values ($h), in C, GLSL and HLSL; compiles"
else
    echo "FAIL gen targets key: header '$h', params '$p': $(cat "$t/err")"
fi

# A thin film over the metal: each renderer's film inputs in its names and
# units (OpenPBR micrometres, the others nanometres), those without one
# refused by name, and in a film scene's header the same rows (glTF's
# minimum and maximum the scene's thickness range).
"$F" params --material au --for openpbr --film 1.38:300 >"$t/fo" 2>"$t/err" &&
    "$F" params --material au --for gltf --film 1.38:300 >"$t/fg" 2>>"$t/err" &&
    "$F" params --material au --for blender --film 1.38:300 >"$t/fb" 2>>"$t/err" &&
    "$F" params --material au --for materialx --film 1.38:300 >"$t/fm" 2>>"$t/err"
got=$(cat "$t/fo" "$t/fg" "$t/fb" "$t/fm" | grep -E '^(thin_film|iridescence|Thin Film|thickness|ior)' | cut -d, -f1,2 | tr '\n' ' ')
want='thin_film_weight,1 thin_film_thickness,0.3 thin_film_ior,1.38 iridescenceFactor,1 iridescenceThicknessMaximum,300 iridescenceThicknessMinimum,300 iridescenceIor,1.38 Thin Film Thickness,300 Thin Film IOR,1.38 thickness,300 ior,1.38 '
bare=$("$F" params --material au --for openpbr | grep '^base_color')
if [ "$got" = "$want" ] && grep -q '^base_color' "$t/fo" && [ "$(grep '^base_color' "$t/fo")" = "$bare" ]; then
    echo "PASS params --for --film: openpbr (micrometres), gltf, blender, materialx (nanometres) film inputs; the metal's rows the bare metal's"
else
    echo "FAIL params --for --film: got '$got' $(cat "$t/err")"
fi
# under the film, each renderer's metal refitted through the renderer's own
# film formula: the fitted mean never above the naive one, the max beside it
for r in fo:openpbr:base_color fg:gltf:baseColorFactor fb:blender:base_color fm:materialx:color0; do
    file=${r%%:*}
    rest=${r#*:}
    target=${rest%%:*}
    first=${rest#*:}
    fit=$(sed -n 's/^# under the film, fitted: mean dE2000 \([0-9.]*\), max \([0-9.]*\); naive (.*): mean \([0-9.]*\), max \([0-9.]*\)$/\1 \3 \2 \4/p' "$t/$file")
    if [ -n "$fit" ] && echo "$fit" | awk '{ exit !($1 <= $2) }' &&
        grep -Eq "^# under the film, through $target.s own film formula .*: $first [0-9.]+,[0-9.]+,[0-9.]+( |\$)" "$t/$file"; then
        echo "PASS params --for $target --film: $first refitted under the film through $target's own film formula (fitted, naive mean dE2000; fitted, naive max: $fit)"
    else
        echo "FAIL params --for $target --film: refit '$fit' $(tail -2 "$t/$file")"
    fi
done
bad "--film for a target without a film input names those with one" \
    "target unreal has no thin-film input this tool knows \(those that have: openpbr materialx blender gltf\)" \
    --material au --for unreal --film 1.38:300
bad "--film without --for" "--film needs --for TARGET" --material au --film 1.38:300
bad "--film with --for all" "--film needs --for TARGET" --material au --for all --film 1.38:300
bad "--film out of range" "--film expects N:D" --material au --for openpbr --film 5:300
printf 'materials = au\nmodels = f82 thin-film\nfilm = 1.38\nfilm_thickness = 100 400\ntargets = openpbr gltf unreal\n' >"$t/f.scene"
if "$F" gen "$t/f.scene" -o "$t/f.h" 2>"$t/err" &&
    grep -q '^ \*  *thin_film_thickness 0.4 (the scene.s range 0.1-0.4: set per use)$' "$t/f.h" &&
    grep -q '^ \*  *iridescenceThicknessMinimum 100$' "$t/f.h" && grep -q '^ \*  *iridescenceThicknessMaximum 400$' "$t/f.h" &&
    grep -q '^ \*  *iridescenceIor   1.38$' "$t/f.h" && grep -q 'no thin-film input known: the film is not carried' "$t/f.h"; then
    echo "PASS gen targets key, film scene: each renderer's film inputs under its metal, the thickness range in its units"
else
    echo "FAIL gen targets key, film scene: $(grep -A3 'thin film over' "$t/f.h" | head -8) $(cat "$t/err")"
fi
# under the film, the header's refit over the scene's range: one per
# renderer with a film input, the fitted mean never above the naive one;
# for a range of one thickness, the values params --for --film prints
fits=$(sed -n "s/^ \*  *dE2000 \([0-9.]*\) \/ [0-9.]* against the film's truth over the thickness range (naive conversion \([0-9.]*\) \/ [0-9.]*)$/\1 \2/p" "$t/f.h")
printf 'materials = au\nmodels = thin-film\nfilm = 1.38\nfilm_thickness = 300 300\ntargets = blender\n' >"$t/f1.scene"
one=$("$F" gen "$t/f1.scene" -o "$t/f1.h" 2>>"$t/err" && awk '/under that film/ { on = 1; next } on && $2 == "base_color" { print $3, $4, $5; exit }' "$t/f1.h")
want=$(sed -n 's/^# under the film, through .*: base_color \([0-9.]*\),\([0-9.]*\),\([0-9.]*\) .*/\1 \2 \3/p' "$t/fb" | awk '{ printf "%.6f %.6f %.6f", $1, $2, $3 }')
if [ "$(echo "$fits" | grep -c .)" = 2 ] && echo "$fits" | awk '{ if (!($1 <= $2)) bad = 1 } END { exit bad }' &&
    [ -n "$one" ] && [ "$one" = "$want" ]; then
    echo "PASS gen targets key, film scene: the metal refitted under the film over the thickness range for openpbr and gltf (fitted, naive mean: $(echo "$fits" | tr '\n' ';')); one thickness: params --film's values ($one)"
else
    echo "FAIL gen targets key, film scene: refits '$fits', one thickness '$one' against params '$want' $(cat "$t/err")"
fi
