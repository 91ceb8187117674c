#!/bin/sh
# Cross builds of the fixed-point (and binary16, binary32) runtime for the
# targets of ports/, their runs under qemu, instruction counts and sizes.
# Called by the Makefile's cross section (make cross, cross-conform,
# cross-count, size); BUILD is the build directory, and $BUILD/cross/conform_data.c
# (the material set prepared on the host) must exist.
#
#   cross.sh check                     toolchains and emulators present?
#   cross.sh nm                        fixed-point-only Cortex-M0 build: symbol checks
#   cross.sh conform TARGET STRIDE [OFFSET]
#                                      conformance run vs the host, bit for
#                                      bit: every STRIDE-th cos code from
#                                      OFFSET, every code near 0 and one
#   cross.sh count TARGET              instructions per call (qemu trace); on
#                                      m0 also cycles (1- and 32-cycle MULS)
#   cross.sh count a64 gcc|clang OPT   the binary32 runtime on AArch64 Linux
#                                      (NEON batches), built by that compiler
#                                      at OPT, instructions per call
#   cross.sh size                      .text/.rodata per model, type and target
#
# TARGET is m0 (qemu -M microbit, Cortex-M0), m4f (qemu -M mps2-an386,
# Cortex-M4F), m55 (qemu -M mps3-an547, Cortex-M55 with Helium) or rv32
# (qemu-riscv32 user mode, RV32IMC); for count also a64
# (qemu-aarch64 user mode, AArch64 Linux, static glibc).
set -u
BUILD=${BUILD:-build}
OUT=$BUILD/cross
HOSTCC=${HOSTCC:-cc}
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"
# The fixed-point-only builds take all of src/ and let the configuration
# leave the binary32 and binary16 files empty (fresnel_config.h), as a
# firmware project that vendors all of src/ would.
ALL_SRC=$(ls src/*/*.c)
FIXED_SRC=$(ls src/q15/*.c)
F16_SRC=$(ls src/f16/*.c)
F32_SRC=$(ls src/f32/*.c)
FIXED_ONLY="-DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOAT|FRESNEL_CFG_NO_F16"
PORT_COMMON="ports/common/port_print.c ports/common/mem.c"
INC="-Iinclude -Iports/common -Itests/ports/cross"

target() { # sets CC CF LD PORT RUN NMT SZ AR for $1
    case $1 in
    m0 | m4f | m55)
        CC=arm-none-eabi-gcc NMT=arm-none-eabi-nm SZ=arm-none-eabi-size AR=arm-none-eabi-ar
        PORT="ports/cortex-m/startup.c"
        case $1 in
        m0) CF="-mcpu=cortex-m0 -mthumb -Os" MACHINE=microbit SCRIPT=ports/cortex-m0/microbit.ld ;;
        m4f)
            CF="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -O2" MACHINE=mps2-an386
            SCRIPT=ports/cortex-m4f/mps2-an386.ld
            ;;
        m55)
            CF="-mcpu=cortex-m55 -mthumb -mfloat-abi=hard -O2" MACHINE=mps3-an547
            SCRIPT=ports/cortex-m55/mps3-an547.ld
            ;;
        esac
        CF="$CF -mfp16-format=ieee"
        LD="-nostdlib -nostartfiles -Wl,--gc-sections -Lports/cortex-m -T$SCRIPT"
        RUN="qemu-system-arm -M $MACHINE -display none -monitor none -serial none -chardev stdio,id=sh -semihosting-config enable=on,target=native,chardev=sh -kernel"
        ;;
    rv32)
        CC=riscv64-unknown-elf-gcc NMT=riscv64-unknown-elf-nm SZ=riscv64-unknown-elf-size AR=riscv64-unknown-elf-ar
        CF="-march=rv32imc -mabi=ilp32 -Os"
        PORT="ports/rv32imc/port.c ports/rv32imc/start.S"
        LD="-nostdlib -nostartfiles -static -Wl,--gc-sections -Wl,--no-warn-rwx-segments"
        RUN=$(command -v qemu-riscv32 || command -v qemu-riscv32-static)
        ;;
    *) echo "cross.sh: unknown target '$1'" >&2; exit 2 ;;
    esac
    CF="$CF -ffreestanding -ffunction-sections -fdata-sections"
}

need() { command -v "$1" >/dev/null 2>&1 || { echo "cross.sh: $1 not found (see ports/README.md for the Debian packages)" >&2; exit 3; }; }

cmd_check() {
    for t in arm-none-eabi-gcc riscv64-unknown-elf-gcc qemu-system-arm; do need $t; done
    command -v qemu-riscv32 >/dev/null 2>&1 || need qemu-riscv32-static
}

# conform/bench ELF for target $1 with stride $3 from offset $4 -> $OUT/$1/<name>.elf
build_prog() { # target prog stride [offset]
    target "$1"
    mkdir -p "$OUT/$1"
    $CC $W $CF $FIXED_ONLY -DCONFORM_STRIDE="$3" -DCONFORM_OFFSET="${4:-0}" $INC $LD tests/ports/cross/$2.c \
        "$OUT/conform_data.c" $PORT_COMMON $PORT $ALL_SRC -lgcc -o "$OUT/$1/$2_$3.elf"
}

# the same program on the host, one per target (the targets run at once)
host_prog() { # target prog stride offset -> $OUT/host/<prog>_<target>
    mkdir -p "$OUT/host"
    $HOSTCC $W -O2 $FIXED_ONLY -DCONFORM_STRIDE="$3" -DCONFORM_OFFSET="$4" $INC tests/ports/cross/$2.c "$OUT/conform_data.c" \
        ports/common/port_print.c ports/host/port.c $ALL_SRC -o "$OUT/host/$2_$1"
}

cmd_conform() { # target stride [offset]: PASS/FAIL lines
    t=$1 s=$2 o=${3:-0}
    if ! build_prog "$t" conform "$s" "$o" 2>"$OUT/conform_$t.err" || ! host_prog "$t" conform "$s" "$o" 2>>"$OUT/conform_$t.err"; then
        echo "FAIL cross $t: conformance build: $(head -5 "$OUT/conform_$t.err")"
        return
    fi
    host="$OUT/host/conform_$t.txt"
    "$OUT/host/conform_$t" >"$host"
    $RUN "$OUT/$t/conform_$s.elf" >"$OUT/$t/conform_$s.txt" 2>"$OUT/$t/conform_$s.err"
    rc=$?
    if [ $rc -eq 0 ] && cmp -s "$host" "$OUT/$t/conform_$s.txt" && grep -q '^done$' "$OUT/$t/conform_$s.txt"; then
        if [ "$s" = 1 ]; then
            every="every cos code"
        else
            every="every ${s}th cos code from $o and every code within 64 of 0 and one"
        fi
        echo "PASS cross $t: fixed-point conformance under $(basename "${RUN%% *}"), $every x $(sed -n 's/^conformance: \([0-9]*\) materials.*/\1/p' "$OUT/$t/conform_$s.txt") materials x $(($(wc -l <"$OUT/$t/conform_$s.txt") - 2)) functions: bit-identical to the host"
    else
        echo "FAIL cross $t: conformance (exit $rc, stride $s from $o) differs from the host: $(diff "$host" "$OUT/$t/conform_$s.txt" | head -6 | tr '\n' ' ') $(head -3 "$OUT/$t/conform_$s.err")"
    fi
}

lib_bytes() { # elf -> total size of the library's symbols (fresnel_*, internal helpers fresnel_i_* included),
    # each address once (identical helpers folded into one by the compiler carry both names)
    total=0
    for h in $($NMT -S "$1" | awk '$NF ~ /^fresnel_/ && NF == 4 && !seen[$1]++ { print $2 }'); do
        total=$((total + 0x$h))
    done
    echo $total
}

sym_size() { # elf symbol -> size in bytes (decimal)
    h=$($NMT -S "$1" | awk -v s="$2" '$NF == s { print $2 }')
    echo $((0x${h:-0}))
}

# The fixed-point-only Cortex-M0 build: the library (every file of src/,
# compiled with FIXED_ONLY), the conformance firmware and a firmware that
# uses Schlick for one material.
cmd_nm() {
    target m0
    d=$OUT/m0/fixed-only
    mkdir -p "$d"
    rm -f "$d"/*.o "$d/libfresnel_q15.a"
    for f in $ALL_SRC; do
        $CC $W $CF $FIXED_ONLY -Iinclude -c "$f" -o "$d/$(basename "$f" .c).o" || { echo "FAIL cross m0: $f does not build"; return; }
    done
    $AR rcs "$d/libfresnel_q15.a" "$d"/*.o
    # The configuration, not the file list, keeps binary32 and binary16 out:
    # every global the library defines is a fixed-point one.
    other=$($NMT --defined-only "$d/libfresnel_q15.a" | awk 'NF == 3 && $2 ~ /^[A-Z]$/ { print $3 }' |
        grep -v -e '_q15' -e '^fresnel_i_' -e '^fresnel_isqrt_u32$' -e '^fresnel_udiv_frac_u32$' -e '^fresnel_recip_q16$' | sort -u | tr '\n' ' ')
    q15=$($NMT --defined-only "$d/libfresnel_q15.a" | awk '$3 == "fresnel_schlick_q15" { print $3 }')
    if [ -z "$other" ] && [ -n "$q15" ]; then
        echo "PASS cross m0: all $(echo $ALL_SRC | wc -w) files of src/ with $FIXED_ONLY define only fixed-point symbols (fresnel_schlick_q15, no fresnel_schlick)"
    else
        echo "FAIL cross m0: the fixed-only build of src/ defines ${other:-no fresnel_schlick_q15}"
    fi
    $CC $W $CF $FIXED_ONLY $INC $LD tests/ports/cross/schlick_only.c $PORT_COMMON $PORT "$d/libfresnel_q15.a" -lgcc \
        -o "$d/schlick_only.elf" 2>"$d/err" || { echo "FAIL cross m0: schlick_only: $(head -3 "$d/err")"; return; }
    [ -f "$OUT/m0/conform_1.elf" ] || build_prog m0 conform 1 || { echo "FAIL cross m0: conformance firmware does not build"; return; }
    for f in "$d/libfresnel_q15.a" "$d/schlick_only.elf" "$OUT/m0/conform_1.elf"; do
        bad=$($NMT "$f" | awk '{ print $NF }' | grep -E '^(__aeabi_[fd]|__aeabi_[iu]?l|__aeabi_[iu]?div|__aeabi_[iu]idiv|__aeabi_ldiv|__aeabi_lmul|__aeabi_llsl|__aeabi_llsr|__aeabi_lasr|__clz|__(add|sub|mul|div|fix|float|extend|trunc|cmp|eq|ne|lt|le|gt|ge|un)[sdht]f|sqrtf?$|powf?$|expf?$|logf?$|log1pf?$)' | sort -u | tr '\n' ' ')
        if [ -z "$bad" ]; then
            echo "PASS cross m0: $(basename "$f") (-mcpu=cortex-m0 -mthumb -Os, --gc-sections): no soft-float, int64, division, clz or libm symbol"
        else
            echo "FAIL cross m0: $(basename "$f") references $bad"
        fi
    done
    ext=$($NMT -u "$d/libfresnel_q15.a" | awk 'NF == 2 { print $2 }' | sort -u)
    defined=$($NMT --defined-only "$d/libfresnel_q15.a" | awk 'NF == 3 { print $3 }' | sort -u)
    outside=$(printf '%s\n' "$ext" | grep -vxF "$defined" | grep -v '^$' | tr '\n' ' ')
    case "$outside" in
    "" | "memcpy " | "memset " | "memcpy memset ") echo "PASS cross m0: the fixed-point library needs nothing from outside but ${outside:-nothing}(struct copies)" ;;
    *) echo "FAIL cross m0: the fixed-point library references $outside" ;;
    esac
    # Global symbols of the library in the firmware: Schlick's entry point
    # only. Local ones are the static helpers of schlick_q15.c that -Os chose
    # not to inline (src/q15/math_q15.h), part of Schlick's own code.
    lib=$($NMT "$d/schlick_only.elf" | awk '$2 ~ /^[A-Z]$/ && $NF ~ /^fresnel_/ { print $NF }' | sort -u | tr '\n' ' ')
    helpers=$($NMT "$d/schlick_only.elf" | awk '$2 ~ /^[a-z]$/ && $NF ~ /^fresnel_i_/ { print $NF }' | sort -u | tr '\n' ' ')
    if [ "$lib" = "fresnel_schlick_q15 " ]; then
        echo "PASS cross m0: a firmware using Schlick for one material links only fresnel_schlick_q15 and its inline helpers ($helpers): $(lib_bytes "$d/schlick_only.elf") bytes of library code"
    else
        echo "FAIL cross m0: the Schlick-only firmware links $lib"
    fi
}

# The binary32 runtime (tests/ports/cross/bench_float.c with its batch rows, no
# binary16) on AArch64 Linux, built by gcc or clang at OPT with the
# runtime's math flags (the Makefile's MATH_FLAGS), counted under
# qemu-aarch64 user mode: the phones' and tablets' toolchains and NEON.
cmd_count_a64() { # gcc|clang OPT
    case $1 in
    gcc) cc="aarch64-linux-gnu-gcc" ;;
    clang) cc="clang --target=aarch64-linux-gnu" ;;
    *) echo "cross.sh: count a64 takes gcc or clang, not '$1'" >&2; exit 2 ;;
    esac
    need aarch64-linux-gnu-gcc
    need qemu-aarch64-static
    d=$OUT/a64/$1$(echo "$2" | tr -d ' =')
    mkdir -p "$d"
    $cc $W $2 -fno-math-errno -fno-trapping-math -static -DFRESNEL_CONFIG=FRESNEL_CFG_NO_F16 -DBENCH_BATCH_N=256 \
        $INC tests/ports/cross/bench_float.c "$OUT/conform_data.c" ports/common/port_print.c ports/host/port.c \
        $F32_SRC -lm -o "$d/bench.elf" || exit 1
    qemu-aarch64-static -singlestep -d exec,nochain -D "$d/trace.log" "$d/bench.elf" >"$d/bench.txt" || exit 1
    sh ports/count.sh aarch64-linux-gnu-nm "$d/bench.elf" "$d/trace.log" "$d/bench.txt"
    rm -f "$d/trace.log" "$d/trace.log.names" "$d/trace.log.isa"
}

cmd_count() { # target [float]: name<TAB>mean<TAB>min<TAB>max on stdout (m0: + cycles, ports/count.sh)
    t=$1
    if [ "$t" = a64 ]; then
        cmd_count_a64 "${2:-}" "${3:-}"
        return
    fi
    if [ "${2:-}" = float ]; then
        # binary32 and binary16 runtimes with newlib's libm (Cortex-M only)
        target "$t"
        mkdir -p "$OUT/$t"
        $CC $W $CF $INC $LD tests/ports/cross/bench_float.c "$OUT/conform_data.c" $PORT_COMMON $PORT $F32_SRC $F16_SRC \
            -lm -lc -lgcc -o "$OUT/$t/bench_1.elf" || exit 1
    else
        build_prog "$t" bench 1 || exit 1
    fi
    case $t in
    rv32) $RUN -singlestep -d exec,nochain -D "$OUT/$t/trace.log" "$OUT/$t/bench_1.elf" >"$OUT/$t/bench.txt" ;;
    *) $RUN "$OUT/$t/bench_1.elf" -singlestep -d exec,nochain -D "$OUT/$t/trace.log" >"$OUT/$t/bench.txt" ;;
    esac
    # cycles from the Cortex-M0's timings: on the m0 build only
    od=""
    [ "$t" = m0 ] && od=arm-none-eabi-objdump
    sh ports/count.sh "$NMT" "$OUT/$t/bench_1.elf" "$OUT/$t/trace.log" "$OUT/$t/bench.txt" $od
    rm -f "$OUT/$t/trace.log" "$OUT/$t/trace.log.names" "$OUT/$t/trace.log.isa"
}

# The runtime of one type compiled once per target into an archive, so
# that each probe only compiles tests/ports/cross/size_probe.c and links.
size_lib() { # target type -> $OUT/$1/size_<type>.a
    d=$OUT/$1/size_$2
    rm -rf "$d" && mkdir -p "$d"
    case $2 in fixed) src=$FIXED_SRC ;; f16) src=$F16_SRC ;; f32) src=$F32_SRC ;; esac
    inc=""
    [ "$1" = rv32 ] && [ "$2" = f32 ] && inc="-Iports/rv32imc/include"
    for f in $src; do
        $CC $W $CF $inc -Iinclude -c "$f" -o "$d/$(basename "$f" .c).o" || return 1
    done
    $AR rcs "$OUT/$1/size_$2.a" "$d"/*.o
}

# .text and .rodata of the probe for one model.
probe_size() { # target kind(PROBE|PROBE_F32|PROBE_F16) id type [-Dextra] -> "text ro" or "- -"
    t=$1 kind=$2 id=$3 ty=$4 def=${5:-}
    extra="" libs="-lgcc"
    [ "$t" = rv32 ] && [ "$kind" = PROBE_F32 ] && extra="-Iports/rv32imc/include -Wl,--unresolved-symbols=ignore-all"
    [ "$t" != rv32 ] && [ "$kind" != PROBE ] && libs="-lm -lc -lgcc"
    $CC $W $CF -D$kind="$id" $def -Iinclude -nostdlib -nostartfiles -Wl,--gc-sections -Wl,-e,probe $extra \
        tests/ports/cross/size_probe.c "$OUT/$t/size_$ty.a" ports/common/mem.c $libs -o "$OUT/probe.elf" 2>"$OUT/probe.err" ||
        { echo "- -"; return; }
    $SZ -A "$OUT/probe.elf" | awk '$1 == ".text" { t = $2 } $1 == ".rodata" { r = $2 } END { printf "%d %d\n", t, r }'
}

cmd_size() {
    models="schlick schlick-gen lsk lsk-comp f82 gulbrandsen approx-conductor cook-torrance exact-conductor exact-dielectric schlick-internal lut lut-residual"
    mkdir -p "$OUT"
    for t in m0 m4f rv32; do
        target $t
        mkdir -p "$OUT/$t"
        for ty in fixed f16 f32; do
            [ $t = rv32 ] && [ $ty = f16 ] && continue
            size_lib $t $ty || { echo "cross.sh: $ty runtime does not build for $t" >&2; exit 1; }
            case $ty in fixed) kind=PROBE ;; f16) kind=PROBE_F16 ;; f32) kind=PROBE_F32 ;; esac
            set -- $(probe_size $t $kind 0 $ty)
            eval "base_${t}_${ty}_t=$1 base_${t}_${ty}_r=$2"
        done
    done
    printf '| model | type | Cortex-M0 -Os .text / .rodata | Cortex-M4F -O2 .text / .rodata | RV32IMC -Os .text / .rodata |\n'
    printf '|---|---|---:|---:|---:|\n'
    i=0
    for m in $models; do
        i=$((i + 1))
        for ty in fixed f16 f32; do
            case $ty in fixed) kind=PROBE ;; f16) kind=PROBE_F16 ;; f32) kind=PROBE_F32 ;; esac
            row="| $m | $ty |"
            for t in m0 m4f rv32; do
                target $t
                if [ $ty = f16 ] && [ $t = rv32 ]; then
                    row="$row n/a |"
                    continue
                fi
                set -- $(probe_size $t $kind $i $ty)
                if [ "$1" = - ]; then
                    row="$row build failed |"
                    continue
                fi
                eval "bt=\$base_${t}_${ty}_t br=\$base_${t}_${ty}_r"
                note=""
                [ $t = rv32 ] && [ $ty = f32 ] && note=" + libm"
                row="$row $(($1 - bt)) / $(($2 - br))$note |"
            done
            echo "$row"
        done
    done
    # The inline fast paths of fresnel_q15_fast.h, the exact conductor's RGB
    # call beside its fast form, and the batches (a 64-cosine scanline),
    # fixed point only.
    for mj in schlick-fast:16 f82-fast:17 lut-u16-fast:18 lut-u16-pl-fast:21 exact-conductor-fast:22 \
        exact-conductor-rgb-fast:23 exact-conductor-rgb:24 schlick-batch:30 schlick-gen-batch:37 f82-batch:31 \
        lut-batch:32 lut-linear-batch:33 lut-cubic-batch:34 schlick-rgb-batch:35 f82-rgb-batch:36; do
        m=${mj%:*} j=${mj#*:}
        row="| $m | fixed |"
        for t in m0 m4f rv32; do
            target $t
            set -- $(probe_size $t PROBE $j fixed)
            eval "bt=\$base_${t}_fixed_t br=\$base_${t}_fixed_r"
            if [ "$1" = - ]; then row="$row build failed |"; else row="$row $(($1 - bt)) / $(($2 - br)) |"; fi
        done
        echo "$row"
    done
    echo
    echo "Bytes the call of one model adds to an otherwise empty program (tests/ports/cross/size_probe.c, --gc-sections), including the"
    echo "libgcc soft-float helpers and newlib libm functions it pulls in (f32 and f16 on Cortex-M0; f16 on Cortex-M4F converts"
    echo "in hardware); RV32 f32 excludes libm, which Debian's riscv64-unknown-elf toolchain does not ship; gcc 12 has no"
    echo "_Float16 for RISC-V. lut = fresnel_lut*_u16 / fresnel_lut / fresnel_lut_f16; lut-residual = the s8 residual table."
    target m0
    # A Schlick-only fixed scene on the fast path: one material, and the
    # increment per further material (2 -> 4 materials, halved).
    set -- $(probe_size m0 PROBE 19 fixed -DSCENE_N=1)
    s1t=$(($1 - base_m0_fixed_t)) s1r=$(($2 - base_m0_fixed_r))
    set -- $(probe_size m0 PROBE 19 fixed -DSCENE_N=2)
    s2t=$1 s2r=$2
    set -- $(probe_size m0 PROBE 19 fixed -DSCENE_N=4)
    echo
    echo "Cortex-M0 -Os, fresnel_schlick_q15_fast (tests/ports/cross/size_probe.c PROBE=19, SCENE_N materials' F0 in a const table):"
    echo "schlick-only fixed scene: .text $s1t B, .rodata $s1r B (one material); per further material: .text $((($1 - s2t) / 2)) B, .rodata $((($2 - s2r) / 2)) B"
    set -- $(probe_size m0 PROBE 20 fixed -DSCENE_N=1)
    s1t=$(($1 - base_m0_fixed_t)) s1r=$(($2 - base_m0_fixed_r))
    set -- $(probe_size m0 PROBE 20 fixed -DSCENE_N=2)
    s2t=$1 s2r=$2
    set -- $(probe_size m0 PROBE 20 fixed -DSCENE_N=4)
    echo "schlick-only fixed scene, RGB (fresnel_schlick_q15_rgb_fast, PROBE=20): .text $s1t B, .rodata $s1r B (one material); per further material: .text $((($1 - s2t) / 2)) B, .rodata $((($2 - s2r) / 2)) B"
    wt=$($SZ -t "$OUT/m0/size_fixed.a" | awk '$NF ~ /TOTALS/ { print $1 }')
    echo "whole fixed runtime (libfresnel fixed objects): .text $wt B (Cortex-M0 -Os, src/q15/*.c, before --gc-sections)"
    d=$OUT/m0/fixed-only
    [ -f "$d/schlick_only.elf" ] || cmd_nm >/dev/null
    echo
    echo "Schlick only, one material, fixed point, Cortex-M0 (tests/ports/cross/schlick_only.c linked with start-up and semihosting):"
    echo "library code linked: $(lib_bytes "$d/schlick_only.elf") bytes ($($NMT "$d/schlick_only.elf" | awk '$NF ~ /^fresnel_/ { print $NF }' | tr '\n' ' ')); the whole firmware:"
    $SZ -A "$d/schlick_only.elf" | awk '$1 ~ /^\.(text|rodata|data|bss)$/ { printf "  %-8s %6d\n", $1, $2 }'
}

# A firmware's own program (FILE.c, with the port interface of
# ports/common/port.h) on a target: built with the fixed-point runtime,
# run under qemu, and the instructions it executes between its first and
# second port_mark call counted from the trace (with the Cortex-M0's
# cycles), and the bytes of library code it links. Builds only that.
cmd_measure() { # target file.c [compiler flags...]
    t=$1 file=$2
    shift 2
    target "$t"
    d=$OUT/measure/$t
    mkdir -p "$d"
    $CC $W $CF $FIXED_ONLY -Iinclude -Iports/common "$@" $LD "$file" $PORT_COMMON $PORT $ALL_SRC -lgcc \
        -o "$d/prog.elf" || exit 1
    case $t in
    rv32) $RUN -singlestep -d exec,nochain -D "$d/trace.log" "$d/prog.elf" >"$d/out.txt" || exit 1 ;;
    *) $RUN "$d/prog.elf" -singlestep -d exec,nochain -D "$d/trace.log" >"$d/out.txt" || exit 1 ;;
    esac
    sed -n '/^BENCH/,/^END$/!p' "$d/out.txt"
    printf 'BENCH 1\n%s\nEND\n' "$(basename "$file" .c)" >"$d/names.txt"
    od=""
    [ "$t" = m0 ] && od=arm-none-eabi-objdump
    set -- $(sh ports/count.sh "$NMT" "$d/prog.elf" "$d/trace.log" "$d/names.txt" $od | cut -f2,5,8)
    rm -f "$d/trace.log" "$d/trace.log.names" "$d/trace.log.isa"
    [ -n "${1:-}" ] || { echo "cross.sh measure: $file calls port_mark fewer than twice" >&2; exit 1; }
    printf '%s on %s: %s instructions between the first two port_mark calls' "$(basename "$file")" "$t" "$1"
    [ "$t" = m0 ] && printf ' (Cortex-M0 cycles: %s with a 1-cycle multiplier, %s with a 32-cycle one)' "$2" "$3"
    printf '; library code linked: %s bytes\n' "$(lib_bytes "$d/prog.elf")"
}

case ${1:-} in
check) cmd_check ;;
nm) cmd_check && cmd_nm ;;
conform) cmd_check && cmd_conform "$2" "$3" "${4:-0}" ;;
count) [ "$2" = a64 ] || cmd_check; cmd_count "$2" "${3:-}" "${4:-}" ;;
size) cmd_check && cmd_size ;;
measure) cmd_check && shift && cmd_measure "$@" ;;
probe) # target id: .text and .rodata one size_probe.c probe adds to the empty program
    cmd_check
    target "$2"
    mkdir -p "$OUT/$2"
    size_lib "$2" fixed || exit 1
    set -- "$2" $(probe_size "$2" PROBE 0 fixed) "$3"
    b1=$2 b2=$3
    set -- $(probe_size "$1" PROBE "$4" fixed)
    echo ".text $(($1 - b1)) .rodata $(($2 - b2))"
    ;;
*) sed -n '2,22p' "$0"; exit 2 ;;
esac
