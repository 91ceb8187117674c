#!/bin/sh
# The runtime of one number type as one stb-style header, made from the
# sources (include/ and src/<type>/, which stay the one place to edit):
#   sh ports/single.sh TYPE > fresnel_single_TYPE.h      TYPE: f32, q15, f16
# `make` writes all three to ports/single/ (committed, for users who vendor
# one file); tests/ports/test_single_file.sh checks the committed copies and builds
# each as a consumer would (C99 alone, C++17 as a unity build) and checks that
# the AVX2 kernel's target reaches no other function.
#
# The header holds the type's public headers and fresnel_film.h (the thin
# film's tables and functions, which includes the three types' headers), so
# a file without FRESNEL_IMPLEMENTATION and a generated scene header (which
# includes a public header only where its guard is not yet defined) need
# nothing else; then, under FRESNEL_IMPLEMENTATION, every source of
# src/<type>/ in name order. Each #include "..." of include/ or src/<type>/
# is replaced by that file: a header that lies wholly inside its include
# guard the first time only (the rest would be empty), any other each time,
# as the preprocessor reads it; system headers stay.
# The implementation's pragmas that would last to the end of the including
# file (src/f32/internal.h's no-contraction) are closed after it.
set -eu
type=${1:-}
case $type in
f32) public="fresnel.h fresnel_film.h" ;;
q15) public="fresnel_q15.h fresnel_q15_fast.h fresnel_film.h" ;;
f16) public="fresnel_f16.h fresnel_film.h" ;;
*)
    echo "usage: sh ports/single.sh f32|q15|f16 > fresnel_single_TYPE.h" >&2
    exit 2
    ;;
esac
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
[ -d "src/$type" ] || {
    echo "single.sh: no src/$type/" >&2
    exit 1
}
version=$(sed -n 's/^#define FRESNEL_VERSION "\(.*\)"/\1/p' include/fresnel.h)
upper=$(echo "$type" | tr a-z A-Z)
sources=$(ls src/$type/*.c | LC_ALL=C sort)
contract=$(cat src/$type/*.h src/$type/*.c | grep -c '^#pragma STDC FP_CONTRACT' || true)

# inline FILE...: the files with their quoted includes expanded, the guarded
# ones once across all the files of one call and of the calls before it
# (the list of those already emitted is kept in $seen).
seen=$(mktemp)
trap 'rm -f "$seen"' EXIT
inline() {
    awk -v dirs="include src/$type" -v seen="$seen" '
    function find(name,    n, d, i, p) {
        n = split(dirs, d, " ")
        for (i = 1; i <= n; i++) {
            p = d[i] "/" name
            if ((getline line < p) > 0) { close(p); return p }
            close(p)
        }
        return ""
    }
    # 1 when the header is all inside its include guard: the first directive
    # is #ifndef G then #define G, and the #endif that closes it is the last
    function guarded(path,    line, depth, first, g, closed) {
        depth = 0; first = 1; closed = 0
        while ((getline line < path) > 0) {
            if (line !~ /^[ \t]*#/) continue
            if (closed) { close(path); return 0 }
            if (first) {
                if (line !~ /^#ifndef /) { close(path); return 0 }
                g = line; sub(/^#ifndef[ \t]+/, "", g)
                first = 0; depth = 1; expect_define = 1
                continue
            }
            if (expect_define) {
                expect_define = 0
                if (line !~ "^#define[ \t]+" g "[ \t]*$") { close(path); return 0 }
                continue
            }
            if (line ~ /^[ \t]*#[ \t]*if/) depth++
            else if (line ~ /^[ \t]*#[ \t]*endif/ && --depth == 0) closed = 1
        }
        close(path)
        return closed
    }
    function emit(path,    line, name, p) {
        if (path in done) return
        if (guarded(path)) {
            done[path] = 1
            print path >> seen
        }
        print "/* ---- file " path " ---- */"
        while ((getline line < path) > 0) {
            if (line ~ /^#include "[^"]*"/) {
                name = line
                sub(/^#include "/, "", name)
                sub(/".*/, "", name)
                p = find(name)
                if (p == "") { print "single.sh: " path ": cannot find " name > "/dev/stderr"; exit 1 }
                emit(p)
                continue
            }
            print line
        }
        close(path)
    }
    BEGIN {
        while ((getline line < seen) > 0) done[line] = 1
        close(seen)
    }
    { emit($0) }'
}

never=' *   Never -ffast-math, -Ofast or -ffinite-math-only for that file (the NaN
 *   policy and the exact forms need IEEE arithmetic): the file stops with
 *   #error under them; add -fno-fast-math to that one file, or move the
 *   implementation to a file built without them. Nor clang'"'"'s
 *   -ffp-contract=fast (THREAD SAFETY in fresnel.h).'
case $type in
f32)
    flags='-O2 -fno-math-errno -fno-trapping-math   (sqrtf inlined; link -lm)'
    config='FRESNEL_CFG_NO_SIMD (portable C batches, same results)'
    ;;
q15)
    flags='-O2 or -Os; no libm, no float, no division: Cortex-M0 and up'
    config='none needed (it holds only the Q1.15 runtime)'
    never=' *   Integer arithmetic only: the floating-point flags do not matter.'
    ;;
f16)
    flags='-O2 -fno-math-errno -fno-trapping-math; a compiler with _Float16
 *     (gcc 12 and later, clang on AArch64); without one the file is empty;
 *     link -lm'
    config='none needed (it holds only the binary16 runtime)'
    ;;
esac
cat <<EOF
/* fresnel_single_$type.h -- fresnel $version, the $(case $type in f32) echo binary32 ;; q15) echo Q1.15 fixed-point ;; f16) echo binary16 ;; esac) runtime in one file.
 *
 * Generated by \`sh ports/single.sh $type\` from include/ and src/$type/ of
 * the fresnel repository (edit those; \`make\` writes this file to
 * ports/single/, and \`make test\` fails when the committed copy is not
 * what the sources give).
 *
 * USE
 *   In exactly one C or C++ file of the program:
 *       #define FRESNEL_IMPLEMENTATION
 *       #include "fresnel_single_$type.h"
 *   Everywhere else include it without the macro: the declarations only.
 *   C99 or C++17. The other types' single files may be implemented in the
 *   same file.
 * FLAGS for the file that defines FRESNEL_IMPLEMENTATION
 *   $flags
$never
 * CONFIG
 *   -DFRESNEL_CONFIG='...' (fresnel_config.h), the same value in every file
 *   that includes this one: $config.
 *
 * The manual is the comment at the top of each public header below.
 * MIT licence (LICENSE in the fresnel repository).
 */
EOF
echo "$public" | tr ' ' '\n' | sed 's|^|include/|' | inline
cat <<EOF

/* ==== implementation ==== */
#if defined(FRESNEL_IMPLEMENTATION) && !defined(FRESNEL_SINGLE_${upper}_IMPLEMENTED)
#define FRESNEL_SINGLE_${upper}_IMPLEMENTED
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#endif
EOF
echo "$sources" | inline
cat <<EOF
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
EOF
[ "$contract" -eq 0 ] || printf '#else\n#pragma STDC FP_CONTRACT DEFAULT\n'
cat <<EOF
#endif
#endif /* FRESNEL_IMPLEMENTATION */
EOF
