#!/bin/sh
# The thin film through the tool: `fresnel curve --film N:D` (its columns,
# the identities of its spectral truth, the thin-film model's closeness to
# it, --nk, every number type, bad values) and `fresnel gen` of a scene with
# a film (each type's table, the refusals a film outside the model's domain
# gets, no output then).
case "$BUILD" in *asan*) exit 0 ;; esac # the runtime's own tests run under the sanitizers
F="${BUILD:-build}/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

# columns: theta, cos, the film's truth (clipped, unclipped), thin-film
if "$F" curve --material au --film 1.5:300 --samples 19 >"$t/c.csv" 2>"$t/err" &&
    [ "$(head -1 "$t/c.csv")" = "theta_deg,cos,gt_r,gt_g,gt_b,unclipped_r,unclipped_g,unclipped_b,thin-film_r,thin-film_g,thin-film_b" ] &&
    [ "$(wc -l <"$t/c.csv")" -eq 20 ]; then
    echo "PASS curve --film: the film's truth and the thin-film model, 19 rows"
else
    echo "FAIL curve --film: $(head -2 "$t/c.csv") $(cat "$t/err")"
fi
# the model within 0.03 of the truth on gold under a 1.5 film at 300 nm (a
# reflectance difference; CIEDE2000 is the report's measure), the truth's
# clipped columns the unclipped ones held to [0, 1]
awk -F, 'NR > 1 { for (i = 0; i < 3; i++) { d = $(9 + i) - $(3 + i); if (d < 0) d = -d; if (d > m) m = d
                                            u = $(6 + i); if (u > 1) u = 1; if (u < 0) u = 0; if (u != $(3 + i)) bad++ } }
     END { printf "%g %d\n", m, bad; exit !(m < 0.03 && bad == 0) }' "$t/c.csv" >"$t/m" &&
    echo "PASS curve --film: thin-film within 0.03 of the film's truth, gt the truth clipped ($(cat "$t/m"))" ||
    echo "FAIL curve --film: thin-film against the truth, gt against unclipped: $(cat "$t/m")"

# identities of the truth: d = 0 and a film of the ambient's index are the bare
# material (curve's unclipped columns without --film)
"$F" curve --material cu --samples 31 --models schlick | cut -d, -f1-2,6-8 >"$t/bare"
for film in 2.2:0 1:640; do
    "$F" curve --material cu --samples 31 --film "$film" | cut -d, -f1-2,6-8 >"$t/film"
    if awk -F, 'NR == FNR { a[FNR] = $0; next } FNR > 1 { split(a[FNR], b, ","); for (i = 3; i <= 5; i++) { d = $i - b[i]; if (d < 0) d = -d; if (d > 1e-9) exit 1 } }' \
        "$t/bare" "$t/film"; then
        echo "PASS curve --film $film: the truth is the bare material's (to 1e-9)"
    else
        echo "FAIL curve --film $film: the truth differs from the bare material's"
    fi
done

# a user's n,k file and every number type
for ty in $("$F" gen --help | sed -n 's/^ *types = f32 *number types: *//p'); do
    if "$F" curve --nk data/ti.csv --film 2.4:180 --type "$ty" --samples 10 >"$t/o" 2>"$t/err" &&
        [ "$(wc -l <"$t/o")" -eq 11 ] && ! grep -qiE 'nan|inf' "$t/o"; then
        echo "PASS curve --nk FILE --film --type $ty"
    else
        echo "FAIL curve --nk --film --type $ty: $(cat "$t/err") $(head -3 "$t/o")"
    fi
done

expect_error() { # name, stderr pattern, args...
    name=$1
    pat=$2
    shift 2
    "$F" "$@" >"$t/out" 2>"$t/err"
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qE -e "$pat" "$t/err" && [ ! -s "$t/out" ]; then
        echo "PASS $name (exit 2: $(head -1 "$t/err"))"
    else
        echo "FAIL $name: exit $rc, stderr '$(cat "$t/err")', stdout '$(head -2 "$t/out")'"
    fi
}
for bad in 1.5 1.5: :300 1.5:300x 0.9:300 4.5:300 1.5:-1 1.5:5001 1.5:nan nan:300 1.5:inf; do
    expect_error "curve --film $bad refused" "--film expects N:D" curve --material au --film "$bad"
done
expect_error "curve --film less dense than --n1 refused" "total reflection inside the film" \
    curve --material au --n1 1.5 --film 1.33:100
expect_error "curve thin-film without --film refused" "thin-film needs a film" curve --material au --models thin-film
# substrates outside the model's domain (include/fresnel_film.h THE DOMAIN):
# less dense than the ambient (glass / film / air: total reflection in the
# substrate), an index below the ambient's in air, one of about the
# ambient's index (BK7 under 1.5, water under water)
printf 'wavelength_nm,n,k\n300,1.0,0\n900,1.0,0\n' >"$t/air.csv"
printf 'wavelength_nm,n,k\n300,0.5,0\n900,0.5,0\n' >"$t/half.csv"
expect_error "curve --film on a substrate less dense than n1 refused" \
    "less dense than the incident medium's 1.5: it reflects totally" curve --nk "$t/air.csv" --n1 1.5 --film 2.0:150
expect_error "curve --film on a substrate of index 0.5 in air refused" "less dense than the incident medium's 1:" \
    curve --nk "$t/half.csv" --film 2.0:150
expect_error "curve --film on BK7 under n1 1.5 refused" "too close to the incident medium's index 1.5" \
    curve --material bk7 --n1 1.5 --film 2.5:150
expect_error "curve --film on water under n1 1.33 refused" "water.*(too close to|less dense than) the incident medium" \
    curve --material water --n1 1.33 --film 4:150
# the same stacks in a scene: gen and report refuse them at the material's line, nothing written
printf 'materials = bk7\nmodels = thin-film\nn1 = 1.5\nfilm = 2.5\n' >"$t/matched.scene"
echo keep >"$t/matched.h"
if ! "$F" gen "$t/matched.scene" -o "$t/matched.h" 2>"$t/err" &&
    grep -q 'matched.scene:1: bk7 under a 2.5 film in n1 1.5: .*too close to the incident medium' "$t/err" &&
    [ "$(cat "$t/matched.h")" = keep ]; then
    echo "PASS gen refuses a substrate of about the ambient's index at its line, the output untouched"
else
    echo "FAIL gen matched-index substrate: $(cat "$t/err")"
fi
printf 'materials = au bk7\nmodels = schlick thin-film\nn1 = 1.5\nfilm = 2.5\n' >"$t/matched-r.scene"
if ! "$F" report --scene "$t/matched-r.scene" -o "$t/matched-rep" --no-timing --no-instructions >/dev/null 2>"$t/err" &&
    grep -q 'too close to the incident medium' "$t/err" && [ ! -e "$t/matched-rep" ]; then
    echo "PASS report refuses a substrate of about the ambient's index, nothing written"
else
    echo "FAIL report matched-index substrate: $(cat "$t/err")"
fi
# inside the domain: BK7 under water (1.33), gold in glass under a 2.0 film
expect_ok() { # name, args...
    name=$1
    shift
    if "$F" "$@" >"$t/out" 2>"$t/err" && [ -s "$t/out" ]; then
        echo "PASS $name"
    else
        echo "FAIL $name: $(cat "$t/err")"
    fi
}
expect_ok "curve --film on BK7 under water (1.33) is in the domain" curve --material bk7 --n1 1.33 --film 2.0:150
expect_ok "curve --film on gold in glass (1.5) is in the domain" curve --material au --n1 1.5 --film 2.0:150

# gen: each type's table, named as the model's identifier
printf 'name = f\nmaterials = au bk7\nmodels = thin-film\ntypes = %s\nfilm = 1.38\nfilm bk7 = 2.1\nfilm_thickness = 100 400\n' \
    "$("$F" gen --help | sed -n 's/^ *types = f32 *number types: *//p')" >"$t/f.scene"
if "$F" gen "$t/f.scene" -o "$t/f.h" 2>"$t/err" && grep -q 'static const fresnel_film fresnel_f_au_thin_film ' "$t/f.h" &&
    grep -q 'static const fresnel_film_q15 fresnel_f_bk7_thin_film_q15 ' "$t/f.h" && grep -q '#include "fresnel_film.h"' "$t/f.h" &&
    grep -q 'a film of index 2.1 on bk7 in n1 1, thickness 100-400 nm' "$t/f.h"; then
    echo "PASS gen: thin-film tables per material and type, the film and its range in the comment"
else
    echo "FAIL gen thin-film: $(cat "$t/err") $(grep -c thin_film "$t/f.h" 2>/dev/null)"
fi
# a film less dense than n1 (total reflection inside it): refused at its line, nothing written
printf 'materials = au\nmodels = thin-film\nn1 = 1.5\nfilm = 1.2\n' >"$t/tir.scene"
echo keep >"$t/tir.h"
if ! "$F" gen "$t/tir.scene" -o "$t/tir.h" 2>"$t/err" && grep -q 'tir.scene:4: .*at least n1 1.5' "$t/err" &&
    [ "$(cat "$t/tir.h")" = keep ]; then
    echo "PASS gen refuses a film less dense than n1 at its line, the output untouched"
else
    echo "FAIL gen film below n1: $(cat "$t/err")"
fi

# report: the thin film's section, one row per material with every type's
# mean and max, its table sizes; the other models' tables without it
printf 'materials = au bk7\nmodels = schlick thin-film\nfilm = 1.5\nfilm bk7 = 2.2\nfilm_thickness = 0 400\n' >"$t/r.scene"
if "$F" report --scene "$t/r.scene" -o "$t/rep" --no-timing --no-instructions >/dev/null 2>"$t/err" &&
    grep -q '^## Thin film' "$t/rep/report.md" &&
    grep -q 'x 201 thicknesses 0-400 nm (18291 samples per material)' "$t/rep/report.md" &&
    [ "$(grep -cE '^\| (au \| 1.5|bk7 \| 2.2|all \|) \|( [0-9.]+ \|){4,6}' "$t/rep/report.md")" -eq 3 ] &&
    ! grep -qi 'goal' "$t/rep/report.md" && grep -q '^| Thin film (thin-film) in f32 against its spectral truth' "$t/rep/targets.md" &&
    grep -q '^| f32 | 6976 | not timed' "$t/rep/report.md" && ! grep -q '^| au | thin-film' "$t/rep/report.md"; then
    echo "PASS report: the thin film's section (per material and type over angle x thickness, sizes), kept out of the other tables"
else
    echo "FAIL report thin film: $(cat "$t/err") $(sed -n '/## Thin film/,+12p' "$t/rep/report.md" 2>/dev/null | head -12)"
fi
# beside it the KHR_materials_iridescence peer and the polarised one on the
# same samples: a row per material and the whole, each mean <= max; the
# polarised form's input set named, and its mean with each set
peer=$(sed -n '/^Beside the real-time standard, /,/^| all/p' "$t/rep/report.md" |
    grep -E '^\| (au|bk7|all) \|( [0-9.]+ \|){6}$')
if [ "$(printf '%s\n' "$peer" | grep -c .)" -eq 3 ] &&
    printf '%s\n' "$peer" | awk -F'|' '{ if (!($3 + 0 <= $4 + 0 && $5 + 0 <= $6 + 0 && $7 + 0 <= $8 + 0)) exit 1 }' &&
    grep -q '^Beside the real-time standard, .*KHR_materials_iridescence.*polarised.*given the best of three sets on this scene (mean over its materials): .*eta' "$t/rep/report.md" &&
    grep -Eq "^The polarised form's mean CIEDE2000 over the materials with each input set: fitted [0-9.]+; Gaussian window [0-9.]+; point-sampled [0-9.]+\.$" "$t/rep/report.md"; then
    echo "PASS report: the film beside KHR_materials_iridescence and the polarised form, per material and all ($(printf '%s' "$peer" | tail -1))"
else
    echo "FAIL report: no KHR_materials_iridescence and polarised rows: '$peer'"
fi
# the goal beside the peers in targets.md: on the goal substrates the scene
# has (au, bk7), the film's mean over the better peer's, each within 1/20 or
# named with the film's mean in every type; the verdict from the worst ratio
goal=$(grep '^| Thin film (thin-film) in f32 beside its peers' "$t/rep/targets.md")
worst=$(printf '%s' "$goal" | sed -n 's/.* | worst \([0-9.]*\) (\(au\|bk7\)).*/\1/p')
if [ -n "$worst" ] && printf '%s' "$goal" | grep -q 'Au, Cu, Al, Ti, Fe, BK7 in the scene (2) | <= 0.05, each substrate |' &&
    { { awk -v w="$worst" 'BEGIN { exit !(w <= 0.05) }' && printf '%s' "$goal" | grep -q '| \*\*pass\*\* |$'; } ||
        { awk -v w="$worst" 'BEGIN { exit !(w > 0.05) }' &&
            printf '%s' "$goal" | grep -Eq '; over the goal: (au|bk7) [0-9.]+ \(film mean f32 [0-9.]+, q15 [0-9.]+' &&
            printf '%s' "$goal" | grep -q '| \*\*MISS\*\* |$'; }; }; then
    echo "PASS report: targets.md's goal for the film beside its peers on the goal substrates (worst $worst)"
else
    echo "FAIL report: targets.md's film-beside-peers goal: '$goal'"
fi
# and where they differ: a row per quarter of 0-400 nm, a cell per angle
# band, each "film / KHR / polarised"
bands=$(sed -n '/^Where they differ: mean CIEDE2000 over the materials by thickness and angle/,+7p' "$t/rep/report.md" |
    grep -cE '^\| (0-100|100-200|200-300|300-400) nm \|( [0-9.]+ / [0-9.]+ / [0-9.]+ \|){4}$')
[ "$bands" -eq 4 ] && pass_band=1 || pass_band=0
if [ $pass_band = 1 ] && grep -q '^| thickness \\ theta | 0-29 deg | 30-59 deg | 60-79 deg | 80-90 deg |$' "$t/rep/report.md"; then
    echo "PASS report: the film and its peers by thickness band (4) and angle band (4)"
else
    echo "FAIL report: the film and its peers by thickness and angle: $bands rows"
fi
# a scene whose only model is the film: refused (the report's tables compare models of angle)
printf 'materials = au\nmodels = thin-film\nfilm = 1.5\n' >"$t/only.scene"
"$F" report --scene "$t/only.scene" -o "$t/only" --no-timing --no-instructions >/dev/null 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && grep -q 'only.scene:2: expected a model besides thin-film' "$t/err" && [ ! -e "$t/only/report.md" ] &&
    echo "PASS report: a scene with the film alone is refused at its models line, no report written" ||
    echo "FAIL report with the film alone: exit $rc, $(cat "$t/err")"
