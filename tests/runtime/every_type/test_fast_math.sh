#!/bin/sh
# passes: first (compile-time behaviour of gcc and clang, the same in every pass)
# -ffast-math (or -Ofast, -ffinite-math-only) as a user's global flag would
# silently break the NaN policy and the critical angles of the binary32 and
# binary16 runtime: every such source must fail to build and name the flags
# to drop; -fno-fast-math after it must build again. The same for the
# file that implements a single-file runtime (ports/single/), whose message
# must name that file's macro, not src/.
t=$(mktemp -d)
single=ports/single
trap 'rm -rf "$t"' EXIT
pat='fresnel: compile the runtime (its sources in src/, or the file that defines FRESNEL_IMPLEMENTATION'
for cc in gcc clang; do
    command -v $cc >/dev/null || continue
    for flags in "-ffast-math" "-Ofast" "-O2 -ffinite-math-only"; do
        bad=""
        n=0
        for f in src/f32/*.c src/f16/*.c; do
            # binary16 sources compile to nothing without _Float16 (clang 14)
            case $f in src/f16/*) $cc -std=c99 -Iinclude -c "$f" -o "$t/p.o" && nm "$t/p.o" |
                grep -q ' T fresnel_' || continue ;; esac
            n=$((n + 1))
            # shellcheck disable=SC2086
            if $cc -std=c99 -Iinclude $flags -c "$f" -o "$t/o.o" 2>"$t/err"; then
                bad="$bad $f:compiled"
            elif ! grep -q -e "$pat" "$t/err"; then
                bad="$bad $f:$(head -1 "$t/err")"
            fi
        done
        if [ -z "$bad" ] && [ $n -gt 0 ]; then
            echo "PASS $cc $flags: all $n binary32/binary16 sources fail, naming the flags"
        else
            echo "FAIL $cc $flags:$bad"
        fi
    done
    if $cc -std=c99 -Wall -Wextra -Wpedantic -Iinclude -ffast-math -fno-fast-math -c src/f32/exact.c \
        -o "$t/o.o" 2>"$t/err"; then
        echo "PASS $cc -ffast-math -fno-fast-math: builds"
    else
        echo "FAIL $cc -ffast-math -fno-fast-math: $(head -3 "$t/err")"
    fi
    for type in f32 f16; do
        [ -f $single/fresnel_single_$type.h ] || {
            echo "FAIL $single/fresnel_single_$type.h: missing"
            continue
        }
        printf '#define FRESNEL_IMPLEMENTATION\n#include "fresnel_single_%s.h"\n' $type >"$t/impl.c"
        $cc -std=c99 -I$single -c "$t/impl.c" -o "$t/p.o" 2>/dev/null && nm "$t/p.o" | grep -q ' T fresnel_' ||
            continue
        if $cc -std=c99 -I$single -ffast-math -c "$t/impl.c" -o "$t/o.o" 2>"$t/err"; then
            echo "FAIL $cc -ffast-math, fresnel_single_$type.h implemented: compiled"
        elif grep -q -e "$pat" "$t/err"; then
            echo "PASS $cc -ffast-math, fresnel_single_$type.h implemented: fails, naming FRESNEL_IMPLEMENTATION's file"
        else
            echo "FAIL $cc -ffast-math, fresnel_single_$type.h implemented: $(head -1 "$t/err")"
        fi
    done
done
