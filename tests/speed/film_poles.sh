#!/bin/sh
# The thin film's accuracy and cost by pole count (tests/README.md, "Thin
# film: poles"). For each FRESNEL_FILM_POLES in POLES (default 3 4 5 6), the files
# git tracks are copied to a scratch folder with that count, and it prints
# build/tests/test_film's CIEDE2000 lines against the spectral truth (the
# default sampling), `make bench`'s film-f32 and schlick-rgb-f32 rows and
# film-vs-schlick-rgb target (gcc -O2), and, where arm-none-eabi-gcc and
# qemu-system-arm are installed, the Cortex-M0 thin-film row of
# `ports/cross.sh count m0` (instructions per RGB call: mean min max).
# Run from the repository's root: sh tests/speed/film_poles.sh
set -eu
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
for n in ${POLES:-3 4 5 6}; do
    d=$t/p$n
    mkdir -p "$d"
    git ls-files | tar -cf - -T - | tar -xf - -C "$d"
    sed "s/^#define FRESNEL_FILM_POLES [0-9]*/#define FRESNEL_FILM_POLES $n/" include/fresnel_film.h >"$d/include/fresnel_film.h"
    echo "== FRESNEL_FILM_POLES $n"
    (
        cd "$d"
        make -s -j1 build/tests/test_film build/fresnel >/dev/null
        build/tests/test_film | grep 'vs spectral truth' || true
        make -s CC=gcc OPT=-O2 bench | grep -E '^(row (film|schlick-rgb)-f32 |target film-vs-schlick-rgb )'
        if command -v arm-none-eabi-gcc >/dev/null && command -v qemu-system-arm >/dev/null; then
            make -s build/cross/conform_data.c >/dev/null
            BUILD=build sh ports/cross.sh count m0 | grep '^thin-film'
        fi
    )
done
