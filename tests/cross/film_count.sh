#!/bin/sh
# Thin-film runtime measurements (not part of make test):
#   sh tests/cross/film_count.sh        BUILD=build by default
# 1. host: ns per RGB evaluation of fresnel_film_rgb against
#    fresnel_schlick_rgb (tests/cross/film_bench.c speed);
# 2. Cortex-M0 (arm-none-eabi-gcc -Os, qemu-system-arm -M microbit):
#    fresnel_film_q15_rgb's instructions per call (ports/count.sh:
#    mean min max; cycles with a 1-cycle and a 32-cycle multiplier), the
#    fixed-point-only build's symbols checked for division and soft-float
#    helpers, and its code and table sizes.
set -eu
BUILD=${BUILD:-build}
OUT=$BUILD/film-count
mkdir -p "$OUT"
make -s --no-print-directory BUILD="$BUILD" "$BUILD/libfresnel.a" "$BUILD/fresnel" >/dev/null
GEN_OBJ=$(ls "$BUILD"/obj/gen/*/*.o | grep -v '/main\.o$')
${CC:-cc} -std=c99 -O2 -D_POSIX_C_SOURCE=200809L -Iinclude -Igen tests/cross/film_bench.c $GEN_OBJ \
    "$BUILD/obj/embed/viewer_assets.o" "$BUILD/libfresnel.a" -lm -o "$OUT/film_bench"
"$OUT/film_bench" speed
"$OUT/film_bench" table >"$OUT/film_table.c"
arm-none-eabi-gcc -std=c99 -Wall -Wextra -Werror -mcpu=cortex-m0 -mthumb -Os -ffreestanding \
    -ffunction-sections -fdata-sections '-DFRESNEL_CONFIG=FRESNEL_CFG_NO_FLOAT|FRESNEL_CFG_NO_F16' \
    -Iinclude -Iports/common -nostdlib -nostartfiles -Wl,--gc-sections -Lports/cortex-m \
    -Tports/cortex-m0/microbit.ld tests/cross/film_m0.c "$OUT/film_table.c" ports/common/port_print.c \
    ports/common/mem.c ports/cortex-m/startup.c $(ls src/*/*.c) -lgcc -o "$OUT/film_m0.elf"
if arm-none-eabi-nm "$OUT/film_m0.elf" | grep -E '__aeabi_(i|u)?div|__aeabi_f|__aeabi_d|__(div|mod)si3|__addsf3|__mulsf3'; then
    echo "film_count: division or soft-float helpers linked into the Cortex-M0 build" >&2
    exit 1
fi
echo "Cortex-M0 build: no division or soft-float helper linked"
arm-none-eabi-nm -S --size-sort "$OUT/film_m0.elf" | awk '$4 ~ /film/ { printf "  %s %d bytes\n", $4, ("0x" $2) + 0 }'
qemu-system-arm -M microbit -display none -monitor none -serial none -chardev stdio,id=sh \
    -semihosting-config enable=on,target=native,chardev=sh -kernel "$OUT/film_m0.elf" \
    -singlestep -d exec,nochain -D "$OUT/trace.log" >"$OUT/bench.txt"
echo "Cortex-M0 instructions per call (mean min max; cycles 1-cycle MULS mean min max; 32-cycle MULS mean min max):"
sh ports/count.sh arm-none-eabi-nm "$OUT/film_m0.elf" "$OUT/trace.log" "$OUT/bench.txt" arm-none-eabi-objdump
rm -f "$OUT/trace.log"
