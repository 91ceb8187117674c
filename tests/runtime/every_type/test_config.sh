#!/bin/sh
# passes: first (compile-time behaviour of gcc and clang, the same in every pass)
# fresnel_config.h: a misspelled or unknown configuration fails the build
# instead of silently building something else (libfixmath's test matrix
# tested FIXMATH_NO_HARD_DIV, a name the library never read); the known
# flags strip what they name.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror -Iinclude"
cat >"$t/use.c" <<'C'
#include "fresnel_fixed.h"
#include "fresnel_f16.h"
int use(int c) { return fresnel_schlick_q15(1311, c); }
C
for cc in gcc clang; do
    command -v $cc >/dev/null || continue
    must_fail() { # name, pattern, flags...
        name=$1; pat=$2; shift 2
        if $cc $W "$@" -c "$t/use.c" -o "$t/o.o" 2>"$t/err"; then
            echo "FAIL $cc: $name compiled"
        elif grep -qE -e "$pat" "$t/err"; then
            echo "PASS $cc: $name fails the build ($(grep -m1 -oE -e "$pat" "$t/err"))"
        else
            echo "FAIL $cc: $name failed without naming the cause: $(head -3 "$t/err")"
        fi
    }
    # binary16 follows the compiler: FRESNEL_HAS_F16 is 1 exactly where it
    # accepts _Float16 (gcc on x86-64), 0 where not (clang 14 on x86-64),
    # and then fresnel_f16.h and src/f16/*.c still build, to nothing
    printf '__extension__ typedef _Float16 h;\nh half(h x) { return x; }\n' >"$t/probe.c"
    has=0
    $cc $W -c "$t/probe.c" -o "$t/o.o" 2>/dev/null && has=1
    printf '#include "fresnel_f16.h"\ntypedef char ok[FRESNEL_HAS_F16 == %d ? 1 : -1];\nint unused;\n' $has >"$t/has.c"
    syms=""
    for f in src/f16/*.c; do
        $cc $W -c "$f" -o "$t/s.o" 2>>"$t/err16" || syms="$syms $f:error"
        [ $has -eq 1 ] || syms="$syms$(nm --defined-only "$t/s.o" 2>/dev/null | awk '$2 ~ /[TtDdRrBb]/ {printf " %s", $3}')"
    done
    if $cc $W -c "$t/has.c" -o "$t/o.o" 2>"$t/err" && [ -z "$syms" ]; then
        echo "PASS $cc: FRESNEL_HAS_F16 = $has, as the compiler's _Float16; src/f16/*.c build warning-free$([ $has -eq 1 ] || echo ', to empty objects')"
    else
        echo "FAIL $cc: FRESNEL_HAS_F16 is not $has (the compiler's _Float16) or src/f16/*.c:$syms $(head -3 "$t/err" "$t/err16")"
    fi
    must_fail "misspelled flag FRESNEL_CFG_NO_FLOT" 'FRESNEL_CFG_NO_FLOT' "-DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOT"
    must_fail "unknown flag bit 0x100" 'fresnel_i_config_has_unknown_flags' "-DFRESNEL_CONFIG=0x100"
    must_fail "stb-style FRESNEL_NO_FLOAT" 'configure with -DFRESNEL_CONFIG' "-DFRESNEL_NO_FLOAT"
    must_fail "stb-style FRESNEL_NO_SIMD" 'configure with -DFRESNEL_CONFIG' "-DFRESNEL_NO_SIMD"
    must_fail "empty FRESNEL_CONFIG" 'error' "-DFRESNEL_CONFIG="
    if $cc $W "-DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOAT|FRESNEL_CFG_NO_F16" -c "$t/use.c" -o "$t/o.o" 2>"$t/err"; then
        echo "PASS $cc: known flags FRESNEL_CFG_NO_FLOAT|FRESNEL_CFG_NO_F16 compile"
    else
        echo "FAIL $cc: known flags: $(head -3 "$t/err")"
    fi
    # FRESNEL_CFG_NO_Q15 strips the fixed-point API and code; so does its
    # alias FRESNEL_CFG_NO_FIXED (fresnel_config.h ALIASES)
    must_fail "FRESNEL_CFG_NO_Q15 hides fresnel_schlick_q15" 'fresnel_schlick_q15' "-DFRESNEL_CONFIG=FRESNEL_CFG_NO_Q15"
    must_fail "FRESNEL_CFG_NO_FIXED hides fresnel_schlick_q15" 'fresnel_schlick_q15' "-DFRESNEL_CONFIG=FRESNEL_CFG_NO_FIXED"
    syms=""
    for f in src/q15/*.c src/f16/*.c; do
        $cc $W "-DFRESNEL_CONFIG=FRESNEL_CFG_NO_Q15|FRESNEL_CFG_NO_F16" -c "$f" -o "$t/s.o" 2>>"$t/err2" || syms="$syms $f:error"
        syms="$syms$(nm --defined-only "$t/s.o" 2>/dev/null | awk '$2 ~ /[TtDdRrBb]/ {printf " %s", $3}')"
    done
    if [ -z "$syms" ]; then
        echo "PASS $cc: FRESNEL_CFG_NO_Q15|FRESNEL_CFG_NO_F16 leave src/q15/*.c and src/f16/*.c empty"
    else
        echo "FAIL $cc: stripped files still define:$syms $(head -3 "$t/err2" 2>/dev/null)"
    fi
    # FRESNEL_CFG_NO_FLOAT strips the binary32 API and code: all of src/
    # builds (warning-free, no empty translation unit) and defines the
    # fixed-point and binary16 functions only
    cat >"$t/float.c" <<'C'
#include "fresnel.h"
float use(float c) { return fresnel_schlick(0.04f, c); }
C
    if $cc $W -DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOAT -c "$t/float.c" -o "$t/o.o" 2>"$t/err"; then
        echo "FAIL $cc: FRESNEL_CFG_NO_FLOAT leaves fresnel_schlick declared"
    elif grep -q 'fresnel_schlick' "$t/err"; then
        echo "PASS $cc: FRESNEL_CFG_NO_FLOAT hides fresnel_schlick (fresnel.h)"
    else
        echo "FAIL $cc: FRESNEL_CFG_NO_FLOAT failed without naming fresnel_schlick: $(head -3 "$t/err")"
    fi
    defs="" errs=""
    : >"$t/err3"
    for f in src/*/*.c; do
        if $cc $W -DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOAT -c "$f" -o "$t/s.o" 2>>"$t/err3"; then
            defs="$defs $(nm --defined-only "$t/s.o" | awk '$2 ~ /^[TDRB]$/ { print $3 }' | tr '\n' ' ')"
        else
            errs="$errs $f"
        fi
    done
    # binary32 symbols: public fresnel_* without _q15/_f16, and internal
    # helpers other than the fixed-point ones (fresnel_i_qf*, the log2/exp2
    # tables) and the binary16 ones (*_h)
    float_defs=$(printf '%s\n' $defs | grep '^fresnel_' | grep -v -e '_q15' -e '_f16$' -e '_f16_rgb$' -e '^fresnel_i_.*_h$' \
        -e '^fresnel_i_\(qf\|a_qf\|exp2_t$\|log2_r$\|log2_t$\|range_fail$\)' \
        -e '^fresnel_isqrt_u32$' -e '^fresnel_udiv_frac_u32$' -e '^fresnel_recip_q16$' | tr '\n' ' ')
    if [ -z "$errs" ] && [ -z "$float_defs" ] && printf '%s\n' $defs | grep -qx fresnel_schlick_q15 &&
        ! printf '%s\n' $defs | grep -qx fresnel_schlick; then
        echo "PASS $cc: FRESNEL_CFG_NO_FLOAT on all of src/: fresnel_schlick_q15 defined, no binary32 fresnel_* symbol"
    else
        echo "FAIL $cc: FRESNEL_CFG_NO_FLOAT on src/: errors in:${errs:- none}; binary32 symbols: ${float_defs:-none} $(head -3 "$t/err3")"
    fi
done
