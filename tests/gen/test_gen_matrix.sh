#!/bin/sh
# passes: first other (the runtime's own tests run under the sanitizers)
# make check: no (g++ and clang++; minutes)
# start: early (fifteen large scenes)
# Every material x every model x both number types x n1 in {1, 1.33, 1.5,
# 2.42, 4} x every LUT spacing (grazing-pl: q15 only, its lutN with N <= 64):
# `fresnel gen` succeeds; the header compiles warning-free as C99 under gcc
# and clang and as C++17 under g++ and clang++ (-Wall -Wextra -Wpedantic
# -Werror); tests/gen/gen_matrix_check.c reads it back (every value in its C type
# and documented range) and holds each Q1.15 LUT table, through the
# fixed-point runtime, to its binary32 twin within the documented bound.
# The LUT sizes are the grammar's ends and a middle one (4, 16, 256; 64 for
# grazing-pl). Also: a header of each number type alone compiles.
# Then the report against the header: for water (a dielectric with a
# total-reflection edge for n1 > 1.33), gold (outside the sRGB gamut) and
# diamond, every scene model (the thin film with grazing spacing: a film no
# less dense than n1, gold's its own, on the materials its domain admits in
# n1 (in a scene of its own where one leaves it), at thicknesses across the scene's
# range and the runtime's, 0, 5000 nm and beyond) x number type (f32, q15 and, where the build
# has _Float16, f16: `fresnel gen --help` lists them) x LUT size in {4, 8,
# 12, 16, 64, 128, 256} (grazing-pl: N <= 64, q15 only) x spacing x n1,
# gen_matrix_check's SCENE mode evaluates each model as `fresnel report`
# does and requires the header's numbers, and holds each Q15 LUT to its
# bound of its own double nodes, and each binary16 LUT to
# FRESNEL_DOMAIN_LUT_F16 (FRESNEL_DOMAIN_LUT_CUBIC_F16) of its own binary16
# nodes in double; at n1 1.5,
# `fresnel curve --type` of each material prints the header's numbers too
# (with --film N:D, the thin film's column at D).
B=${BUILD:-build}
F="$B/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-Wall -Wextra -Wpedantic -Werror"
if [ ! -x "$B/tests/gen_matrix_check" ]; then
    echo "FAIL gen matrix: $B/tests/gen_matrix_check not built (make test-bins builds it)"
    exit 1
fi
cp "$B/tests/gen_matrix_check" "$t/check"
mats=$(tail -n +2 data/materials.csv | cut -d, -f1 | tr '\n' ' ')
named="schlick lsk lsk-comp f82 gulbrandsen cook-torrance approx-conductor exact exact-gaussian exact-point"
all_types=$("$F" gen --help | sed -n 's/^ *types = f32 *number types: *//p')
case " $all_types " in *" f32 "*) case " $all_types " in *" q15 "*) ;; *) all_types="" ;; esac ;; *) all_types="" ;; esac
[ -n "$all_types" ] || echo "FAIL gen matrix: fresnel gen --help lists no number types f32 and q15"

# compile NAME HEADER: the four compilers, one line each
compile() {
    printf '#include "%s"\nint main(void) { return 0; }\n' "$(basename "$2")" >"$t/use.c"
    for c in "gcc -std=c99" "clang -std=c99" "g++ -std=c++17 -x c++" "clang++ -std=c++17 -x c++"; do
        # shellcheck disable=SC2086
        if $c $W -Iinclude -I"$t" -c "$t/use.c" -o "$t/use.o" >"$t/cc.log" 2>&1 && [ ! -s "$t/cc.log" ]; then
            echo "PASS gen matrix $1: compiles warning-free with $c"
        else
            echo "FAIL gen matrix $1: $c: $(head -5 "$t/cc.log")"
        fi
    done
}

# in_film_domain MATERIAL N1: the thin-film model represents the material
# under a film in n1 (include/fresnel_film.h, THE DOMAIN)
in_film_domain() {
    "$F" curve --material "$1" --n1 "$2" --film 4:0 --samples 2 >/dev/null 2>&1
}

# scene NAME SPACING N1 TYPES MODELS [MATERIALS [MORE_LINES]]
scene() {
    printf 'name = %s\nmaterials = %s\nmodels = %s\ntypes = %s\nn1 = %s\nlut_spacing = %s\n%s' \
        "$1" "${6:-$mats}" "$5" "$4" "$3" "$2" "${7:-}" >"$t/$1.scene"
    if ! "$F" gen "$t/$1.scene" -o "$t/$1.h" 2>"$t/gen.log" >/dev/null; then
        echo "FAIL gen matrix $1: fresnel gen: $(grep -v warning "$t/gen.log" | head -3)"
        return 1
    fi
}

for spacing in grazing uniform grazing-pl; do
    case $spacing in
    grazing) luts="lut4 lut16 lut256 lut4-residual lut16-residual lut256-residual lut4-cubic lut16-cubic lut256-cubic"
        types="f32 q15" ;;
    uniform) luts="lut4 lut16 lut256 lut4-residual lut16-residual lut256-residual"; types="f32 q15" ;;
    *) luts="lut4 lut16 lut64"; types="q15" ;;
    esac
    for n1 in 1 1.33 1.5 2.42 4; do
        name=m_$(echo "$spacing" | tr -c 'a-z0-9\n' _)_$(echo "$n1" | tr . _)
        scene "$name" "$spacing" "$n1" "$types" "$named $luts" || continue
        compile "$name" "$t/$name.h"
        "$t/check" "$t/$name.h" "$spacing" "$name (${spacing}, n1 $n1)"
        rm -f "$t/$name.h"
    done
done
for types in $all_types; do
    scene "m_only_$types" grazing 1.5 "$types" "$named lut4 lut16-residual lut16-cubic" &&
        compile "m_only_$types (types = $types alone)" "$t/m_only_$types.h"
    scene "f_only_$types" grazing 1.5 "$types" "thin-film" "au diamond" 'film = 1.5
film au = 2.2
' && compile "f_only_$types (thin-film, types = $types alone)" "$t/f_only_$types.h"
done

for spacing in grazing uniform grazing-pl; do
    luts=""
    types=$all_types
    for n in 4 8 12 16 64 128 256; do
        case $spacing in
        grazing) luts="$luts lut$n lut$n-residual lut$n-cubic" ;;
        uniform) luts="$luts lut$n lut$n-residual" ;;
        *) [ "$n" -le 64 ] && luts="$luts lut$n"; types="q15" ;;
        esac
    done
    for n1 in 1 1.33 1.5 2.42 4; do
        name=r_$(echo "$spacing" | tr -c 'a-z0-9\n' _)_$(echo "$n1" | tr . _)
        # the thin film (independent of the spacing: grazing only): a film no
        # less dense than n1 on each material, gold's its own, over a range
        # (the materials the film's domain admits in n1: every one in air; in
        # denser media water and then diamond leave it, and their film is a
        # scene of its own, rf_*, on the others)
        film="" film_lines="" film_mats="" film_scene=""
        if [ "$spacing" = grazing ]; then
            film_lines="film = $(awk -v n="$n1" 'BEGIN { print (n > 2.42 ? n : 2.42) }')
film au = 4
film_thickness = 80 640
"
            for mat in water au diamond; do
                in_film_domain "$mat" "$n1" && film_mats="$film_mats $mat"
            done
            if [ "$film_mats" = " water au diamond" ]; then
                film=" thin-film"
            else
                film_scene=rf_$(echo "$n1" | tr . _)
                if [ -z "$film_mats" ] || [ "${film_mats#* au}" = "$film_mats" ]; then
                    echo "FAIL gen matrix $film_scene: gold under a film in n1 $n1 left the film's domain"
                    film_scene=""
                fi
            fi
        fi
        r_lines=""
        [ -n "$film" ] && r_lines=$film_lines
        scene "$name" "$spacing" "$n1" "$types" "$named$luts$film" "water au diamond" "$r_lines" || continue
        [ "$n1" = 1.5 ] && compile "$name" "$t/$name.h"
        "$t/check" "$t/$name.h" "$spacing" "$name (${spacing}, n1 $n1)" "$t/$name.scene" 2>"$t/check.err"
        if [ -n "$film_scene" ] && scene "$film_scene" grazing "$n1" "$types" "thin-film" "$film_mats" "$film_lines"; then
            "$t/check" "$t/$film_scene.h" grazing "$film_scene (thin-film on$film_mats, n1 $n1)" "$t/$film_scene.scene" \
                2>"$t/check.err"
        fi
        # fresnel curve --type evaluates the same values (grazing-pl has no curve)
        if [ "$spacing" != grazing-pl ] && [ "$n1" = 1.5 ]; then
            for mat in water au diamond; do
                # the scene's film on mat (gold's its own), at 480 nm
                film_opt="" film_d=""
                if [ -n "$film" ]; then
                    film_d=480
                    film_opt="--film $( [ "$mat" = au ] && echo 4 || echo 2.42 ):$film_d"
                fi
                for ty in $types; do
                    # shellcheck disable=SC2086
                    if "$F" curve --material "$mat" --n1 "$n1" --lut-spacing "$spacing" --type "$ty" --samples 181 \
                        --models "$named$luts$film" $film_opt >"$t/curve.csv" 2>"$t/curve.err"; then
                        # shellcheck disable=SC2086
                        "$t/check" "$t/$name.h" "$spacing" "$name curve" "$t/$name.scene" "$t/curve.csv" "$mat" "$ty" $film_d 2>"$t/check.err"
                    else
                        echo "FAIL gen matrix $name: fresnel curve --type $ty: $(head -2 "$t/curve.err")"
                    fi
                    # the film's own scene: its column alone, where the domain admits mat
                    case "$film_scene:$film_mats " in
                    rf_*" $mat "*)
                        if "$F" curve --material "$mat" --n1 "$n1" --type "$ty" --samples 181 --models thin-film \
                            --film "$( [ "$mat" = au ] && echo 4 || echo 2.42 ):480" >"$t/curve.csv" 2>"$t/curve.err"; then
                            "$t/check" "$t/$film_scene.h" grazing "$film_scene curve" "$t/$film_scene.scene" \
                                "$t/curve.csv" "$mat" "$ty" 480 2>"$t/check.err"
                        else
                            echo "FAIL gen matrix $film_scene: fresnel curve --type $ty: $(head -2 "$t/curve.err")"
                        fi
                        ;;
                    esac
                done
            done
        fi
        rm -f "$t/$name.h"
    done
done

# The checker itself must catch what a wrong header looks like: a residual
# node wrapped past int16_t, an infinite float, a C99 designated initialiser
# (no C++17), a Q15 code above one, a binary16 constant that no binary16 holds.
printf '/* x */\nenum { fresnel_b_w_lut8_residual_frac = 15 };\nstatic const int16_t fresnel_b_w_lut8_residual_q15[3] FRESNEL_GEN_UNUSED = {\n    -385, 34867, 304\n};\n' >"$t/bad1.h"
printf '/* x */\nstatic const float fresnel_b_w_ct_eta FRESNEL_GEN_UNUSED = inf.0f;\n' >"$t/bad2.h"
printf '/* x */\nstatic const fresnel_nk_prep_q15 fresnel_b_w_nk_q15[1] FRESNEL_GEN_UNUSED = {\n    {.n = {1073741824, -30}, .nk2 = {1073741824, -29}}\n};\n' >"$t/bad3.h"
printf '/* x */\nstatic const fresnel_rgb_q15 fresnel_b_w_f0_q15 FRESNEL_GEN_UNUSED = {32769, 0, 0};\n' >"$t/bad4.h"
printf '/* x */\nstatic const fresnel_f16 fresnel_b_w_f0_f16[3] FRESNEL_GEN_UNUSED = {0.5f, 0.1f, 0.25f};\n' >"$t/bad5.h"
for b in 1 2 3 4 5; do
    if "$t/check" "$t/bad$b.h" grazing "bad$b" | grep -q '^FAIL gen matrix bad'"$b"': header values'; then
        echo "PASS gen matrix: the checker rejects wrong header $b ($(head -3 "$t/bad$b.h" | tail -1 | cut -c1-50))"
    else
        echo "FAIL gen matrix: the checker accepts wrong header $b"
    fi
done
