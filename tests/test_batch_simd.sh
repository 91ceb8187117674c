#!/bin/sh
# passes: first (these builds are independent of the pass's flags)
# make check: no (AArch64 under qemu)
# tests/test_batch.c (fresnel_conductor_batch and _rgb_batch bit for bit
# against fresnel_conductor_prepared) on each SIMD kernel of src/f32/simd.h
# the main build does not select (an x86-64 -O2 build takes its AVX2 kernel
# at run time on an AVX2 CPU): SSE2 without that choice
# (FRESNEL_I_SIMD_DISPATCH=0), AVX2 + FMA (x86-64-v3), AVX without AVX2
# (its own RGB row shuffles) and AVX-512 where this CPU runs them, AArch64
# NEON under qemu-aarch64-static, and the portable C of FRESNEL_CFG_NO_SIMD. The AVX-512 kernel is compiled
# warning-free by gcc and clang everywhere; it runs only on a CPU that has
# AVX-512F (qemu-user has none).
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror -D_POSIX_C_SOURCE=200809L -fno-math-errno -fno-trapping-math -Iinclude -Itests"
SRC="tests/test_batch.c $(ls src/f32/*.c | tr '\n' ' ')"
run() { # label, command...
    label=$1
    shift
    if "$@" >"$t/out" 2>&1; then
        sed -n "s/^\(PASS\|NOTE\) batch: /\1 batch [$label]: /p" "$t/out"
    else
        sed -n "s/^\(PASS\|FAIL\|NOTE\) batch: /\1 batch [$label]: /p" "$t/out"
        echo "FAIL batch [$label]: exit status non-zero: $(grep -v '^PASS\|^NOTE' "$t/out" | head -3 | tr '\n' ' ')"
    fi
}
build() { # label, compiler, flags...
    label=$1 cc=$2
    shift 2
    if $cc $W "$@" $SRC -lm -o "$t/tb" 2>"$t/err"; then
        return 0
    fi
    echo "FAIL batch [$label]: $cc $* does not build: $(head -3 "$t/err" | tr '\n' ' ')"
    return 1
}
cpu=$(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null)
has() { case " $cpu " in *" $1 "*) return 0 ;; esac; return 1; }
case $(uname -m) in
x86_64)
    build "x86-64 SSE2, no run-time choice" gcc -O2 -DFRESNEL_I_SIMD_DISPATCH=0 && run "x86-64 SSE2" "$t/tb"
    if has avx2 && has fma; then
        build "x86-64 AVX2+FMA" gcc -O2 -mavx2 -mfma && run "x86-64 AVX2+FMA" "$t/tb"
    else
        echo "NOTE batch: this CPU has no AVX2+FMA; that kernel was not run"
    fi
    if has avx; then
        build "x86-64 AVX without AVX2" gcc -O2 -mavx && run "x86-64 AVX without AVX2" "$t/tb"
    else
        echo "NOTE batch: this CPU has no AVX; that kernel was not run"
    fi
    for cc in gcc clang; do
        if $cc $W -O2 -mavx512f -mfma -c src/f32/exact.c -o "$t/x.o" 2>"$t/err"; then
            echo "PASS batch [x86-64 AVX-512]: $cc -mavx512f compiles src/f32/exact.c warning-free"
        else
            echo "FAIL batch [x86-64 AVX-512]: $cc -mavx512f: $(head -3 "$t/err" | tr '\n' ' ')"
        fi
    done
    if has avx512f; then
        build "x86-64 AVX-512" gcc -O2 -mavx512f -mfma && run "x86-64 AVX-512" "$t/tb"
    else
        echo "NOTE batch: this CPU has no AVX-512F; the AVX-512 kernel was compiled, not run"
    fi
    ;;
esac
build "portable C" gcc -O2 -DFRESNEL_CONFIG=FRESNEL_CFG_NO_SIMD && run "portable C" "$t/tb"
if command -v aarch64-linux-gnu-gcc >/dev/null && command -v qemu-aarch64-static >/dev/null; then
    build "AArch64 NEON, qemu" aarch64-linux-gnu-gcc -O2 -static && run "AArch64 NEON, qemu" qemu-aarch64-static "$t/tb"
else
    echo "FAIL batch [AArch64 NEON]: aarch64-linux-gnu-gcc or qemu-aarch64-static missing (sh tests/deps.sh cross)"
fi
