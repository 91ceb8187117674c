#!/bin/sh
# passes: first (these builds are independent of the pass's flags)
# make check: no (AArch64 under qemu)
# tests/runtime/f32/test_batch.c (fresnel_conductor_batch and _rgb_batch bit for bit
# against fresnel_conductor_prepared, lane by lane) on each SIMD kernel of
# src/f32/simd.h, built with the flags users build with: gcc and clang, in
# ISO C (-std=c99) and in the GNU modes (gnu99, gnu11, gnu17; gcc's default
# and CMake's), where gcc contracts a * b + c into a fused multiply-add
# wherever the target has one, unless src/f32/internal.h turns that off.
# Targets with FMA (AVX2+FMA, AVX-512 with FMA, AArch64 NEON, and the
# portable C loops on them) are built in every mode by both compilers;
# targets without it (the SSE2 baseline, which takes its AVX2 kernel at run
# time or, with FRESNEL_I_SIMD_DISPATCH=0, not; AVX without AVX2) have no
# instruction to contract into, so each is built once per compiler, the
# modes taken in turn. Also -O3 -march=native, and gcc with
# -ffp-contract=fast on its command line. AArch64 runs under
# qemu-aarch64-static (gcc, and clang --target=aarch64-linux-gnu).
# A kernel this CPU cannot run (AVX-512 without AVX-512F, qemu-user has
# none) is compiled, warning-free, and not run: a NOTE says so.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-Wall -Wextra -Wpedantic -Werror -D_POSIX_C_SOURCE=200809L -fno-math-errno -fno-trapping-math -Iinclude -Itests/common"
SRC="tests/runtime/f32/test_batch.c src/f32/exact.c src/f32/exact_avx.c"
MODES="c99 gnu99 gnu11 gnu17"
cpu=$(grep -m1 '^flags' /proc/cpuinfo 2>/dev/null)
has() { case " $cpu " in *" $1 "*) return 0 ;; esac; return 1; }
built=0 ran=0

# check LABEL RUNNER CC FLAGS...: build the test (RUNNER "compile" only
# compiles it; "host" runs it here; anything else is the command to run it
# with), then one PASS line for the build or its FAIL lines.
check() {
    label=$1 runner=$2 cc=$3
    shift 3
    if ! command -v "$cc" >/dev/null; then
        echo "FAIL batch [$label]: $cc missing (sh tests/deps.sh cross)"
        return
    fi
    if ! $cc $W "$@" $SRC -lm -o "$t/tb" 2>"$t/err"; then
        echo "FAIL batch [$label]: $cc $* does not build: $(head -3 "$t/err" | tr '\n' ' ')"
        return
    fi
    built=$((built + 1))
    [ "$runner" = compile ] && return
    if [ "$runner" = host ]; then
        "$t/tb" >"$t/out" 2>&1
    else
        $runner "$t/tb" >"$t/out" 2>&1
    fi
    status=$?
    npass=$(grep -c '^PASS ' "$t/out")
    if [ $status -eq 0 ] && [ "$npass" -gt 0 ] && ! grep -q '^FAIL ' "$t/out"; then
        echo "PASS batch [$label]: $cc $*: $npass checks"
        ran=$((ran + 1))
    else
        sed -n "s/^FAIL batch: /FAIL batch [$label]: /p" "$t/out"
        echo "FAIL batch [$label]: $cc $*: exit status $status, $npass checks passed"
    fi
}

# every mode, both compilers: LABEL RUNNER FLAGS...
every_mode() {
    kernel=$1 how=$2
    shift 2
    for compiler in gcc clang; do
        for m in $MODES; do
            check "$kernel" "$how" $compiler -std=$m "$@"
        done
    done
}

# one build per compiler, the modes in turn: LABEL RUNNER FLAGS...
next_mode=0
modes_in_turn() {
    kernel=$1 how=$2
    shift 2
    for compiler in gcc clang; do
        m=$(echo $MODES | cut -d' ' -f$((next_mode % 4 + 1)))
        next_mode=$((next_mode + 1))
        check "$kernel" "$how" $compiler -std=$m "$@"
    done
}

case $(uname -m) in
x86_64)
    modes_in_turn "x86-64 SSE2, no run-time choice" host -O2 -DFRESNEL_I_SIMD_DISPATCH=0
    modes_in_turn "x86-64 SSE2, AVX2 kernel at run time" host -O2
    if has avx; then
        modes_in_turn "x86-64 AVX without AVX2" host -O2 -mavx
    else
        echo "NOTE batch: this CPU has no AVX; that kernel was compiled, not run"
        modes_in_turn "x86-64 AVX without AVX2" compile -O2 -mavx
    fi
    if has avx2 && has fma; then
        every_mode "x86-64 AVX2+FMA" host -O2 -mavx2 -mfma
    else
        echo "NOTE batch: this CPU has no AVX2+FMA; that kernel was compiled, not run"
        every_mode "x86-64 AVX2+FMA" compile -O2 -mavx2 -mfma
    fi
    if has avx512f && has fma; then
        every_mode "x86-64 AVX-512" host -O2 -mavx512f -mfma
    else
        echo "NOTE batch: this CPU has no AVX-512F; the AVX-512 kernel was compiled, not run"
        every_mode "x86-64 AVX-512" compile -O2 -mavx512f -mfma
    fi
    check "x86-64 -march=native" host gcc -std=gnu17 -O3 -march=native
    check "x86-64 -march=native" host clang -std=gnu17 -O3 -march=native
    check "x86-64 -march=native" host gcc -std=gnu17 -O2 -march=native -ffp-contract=fast
    fma=-march=native
    ;;
*) fma= ;;
esac
every_mode "portable C" host -O3 $fma -DFRESNEL_CONFIG=FRESNEL_CFG_NO_SIMD
if command -v qemu-aarch64-static >/dev/null; then
    for m in $MODES; do
        check "AArch64 NEON, qemu" qemu-aarch64-static aarch64-linux-gnu-gcc -std=$m -O2 -static
        check "AArch64 NEON, qemu" qemu-aarch64-static clang --target=aarch64-linux-gnu -std=$m -O2 -static
    done
else
    echo "FAIL batch [AArch64 NEON]: qemu-aarch64-static missing (sh tests/deps.sh cross)"
fi
echo "NOTE batch: $built builds, $ran of them run and passed; each run: $(sed -n 's/^NOTE batch: //p' "$t/out")"
