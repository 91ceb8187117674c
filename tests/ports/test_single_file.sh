#!/bin/sh
# passes: first (builds of its own, independent of the pass's flags)
# make check: no (four compilers build each single file, C99 and C++17; test_single_committed.sh is make check's)
# The single-file runtimes as ports/single.sh writes them from the sources,
# used as a vendoring project uses them: each header copied alone into an
# empty folder, built with gcc and clang as C99 -Werror, every type's alone and all
# three implemented in one file; as C++17 by g++ and clang++ in a unity build
# (the .c files included from one C++ file); each printing what the same
# program (tests/ports/consumer/single_file.c) prints against include/ and
# libfresnel.a, bit for bit. The thin film of each type likewise
# (tests/ports/consumer/single_film.c), C99 and C++17: used in a file without
# FRESNEL_IMPLEMENTATION, its table from the header `fresnel gen` writes for
# a thin-film scene, in a folder that holds that header and the single file
# only. The binary32 file also runs tests/runtime/f32/test_batch.c
# (every batch kernel, lane by lane). Its AVX2 kernel's target pragma reaches
# no other function: the combined file, compiled for plain x86-64 by gcc,
# clang and g++, has VEX-encoded instructions (v...) only in the kernel's
# functions (*_avx*), and those use 8 lanes (ymm).
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-Wall -Wextra -Wpedantic -Werror"
C=tests/ports/consumer

for type in f32 q15 f16; do
    if sh ports/single.sh $type >"$t/fresnel_single_$type.h" 2>"$t/err"; then
        mkdir "$t/$type" && cp "$t/fresnel_single_$type.h" "$t/$type/"
    else
        echo "FAIL ports/single.sh $type: $(head -3 "$t/err")"
    fi
done

# the reference: the same program against include/ and libfresnel.a
if cc -std=c99 $W -DWITH_F32 -DWITH_Q15 -DWITH_F16 -DFRESNEL_LIBRARY -Iinclude $C/single_file.c "$BUILD/libfresnel.a" -lm \
    -o "$t/library" 2>"$t/err" && "$t/library" >"$t/library.out"; then
    :
else
    echo "FAIL the consumer against libfresnel.a: $(head -3 "$t/err")"
fi

# binary16 where the compiler has _Float16 (FRESNEL_HAS_F16; not clang 14
# on x86-64, where fresnel_single_f16.h compiles to nothing)
printf '__extension__ typedef _Float16 h;\nh half(h x) { return x; }\n' >"$t/probe.c"
has_f16() { $1 -x c -c "$t/probe.c" -o "$t/probe.o" 2>/dev/null; }

# same LABEL OUTPUT COMPILER PREFIXES: OUTPUT's lines of the types in PREFIXES
# are the library's lines of those types
same() {
    label=$1 out=$2 compiler=$3
    shift 3
    for p in "$@"; do
        grep "^$p " "$t/library.out" >"$t/want"
        grep "^$p " "$out" >"$t/got"
        if [ "$p" = f16 ] && ! has_f16 "$compiler"; then
            label="$label (no _Float16 in $compiler: binary16 builds to nothing)"
            [ ! -s "$t/got" ] || { echo "FAIL $label: printed binary16 lines"; return 1; }
        elif [ ! -s "$t/want" ]; then
            echo "FAIL $label: the library printed no $p line"
            return 1
        elif ! cmp -s "$t/want" "$t/got"; then
            echo "FAIL $label: $p differs from libfresnel.a: $(diff "$t/want" "$t/got" | sed -n 2,3p | tr '\n' ' ')"
            return 1
        fi
    done
    n=$(wc -l <"$out")
    echo "PASS $label: $n lines, bit for bit those of libfresnel.a"
}

# ---- each type alone, and all three in one program, C99 ----
for cc in gcc clang; do
    for set in f32 q15 f16 "f32 q15 f16"; do
        defs="" inc=""
        for type in $set; do
            defs="$defs -DWITH_$(echo $type | tr a-z A-Z)"
            inc="$inc -I$t/$type"
        done
        label="$cc -std=c99, fresnel_single_{$(echo $set | tr ' ' ,)}.h alone"
        if $cc -std=c99 $W -O2 $defs $inc $C/single_file.c $C/single_file_impl.c -lm -o "$t/prog" 2>"$t/err" && [ ! -s "$t/err" ] &&
            "$t/prog" >"$t/prog.out"; then
            # shellcheck disable=SC2086
            same "$label" "$t/prog.out" $cc $set
        else
            echo "FAIL $label: $(head -5 "$t/err")"
        fi
    done
done

# ---- C++17 unity build: one .cpp that includes the program's .c files ----
printf '#include "single_file_impl.c"\n#include "single_file.c"\n' >"$t/unity.cpp"
for cxx in g++ clang++; do
    label="$cxx -std=c++17 unity build of all three"
    if $cxx -std=c++17 $W -O2 -DWITH_F32 -DWITH_Q15 -DWITH_F16 -I$C -I"$t/f32" -I"$t/q15" -I"$t/f16" "$t/unity.cpp" \
        -o "$t/prog" 2>"$t/err" && [ ! -s "$t/err" ] && "$t/prog" >"$t/prog.out"; then
        same "$label" "$t/prog.out" $cxx f32 q15 f16
    else
        echo "FAIL $label: $(head -5 "$t/err")"
    fi
done

# ---- the thin film: declared without FRESNEL_IMPLEMENTATION, its table from a generated scene header ----
# Per type a folder holding only fresnel_single_TYPE.h and the header
# `fresnel gen` writes for a thin-film scene of that type; the program's
# file that uses the film (single_film.c) does not define
# FRESNEL_IMPLEMENTATION, the one linked with it (single_film_main.c) does.
# At -O0: the declarations and the link are the question here (the builds
# above compile the code at -O2), and the results are the same bits.
for type in f32 q15 f16; do
    T=$(echo $type | tr a-z A-Z)
    case $type in f32) table=fresnel_film ;; *) table=fresnel_film_$type ;; esac
    d=$t/film_$type
    mkdir "$d" && cp "$t/$type/fresnel_single_$type.h" "$d/" || continue
    printf 'name = film\nmaterials = cu\nmodels = thin-film\ntypes = %s\nfilm = 1.8\n' $type >"$t/film_$type.scene"
    if ! "$BUILD/fresnel" gen "$t/film_$type.scene" -o "$d/scene_film.h" 2>"$t/err"; then
        echo "FAIL fresnel gen of a $type thin-film scene: $(head -3 "$t/err")"
        continue
    fi
    if ! cc -std=c99 $W -DWITH_$T -DFRESNEL_LIBRARY -Iinclude -I"$d" $C/single_film.c $C/single_film_main.c \
        "$BUILD/libfresnel.a" -lm -o "$t/film_lib" 2>"$t/err" || ! "$t/film_lib" >"$t/film_lib.out" ||
        [ ! -s "$t/film_lib.out" ]; then
        echo "FAIL the $type thin-film program against libfresnel.a: $(head -3 "$t/err")"
        continue
    fi
    for cc in gcc clang "g++ -x c++ -std=c++17" "clang++ -x c++ -std=c++17"; do
        case $cc in *++*) std="" lang=C++17 ;; *) std=-std=c99 lang=C99 ;; esac
        label="${cc%% *} $lang, $table in a file without FRESNEL_IMPLEMENTATION, a $type thin-film scene header beside fresnel_single_$type.h alone"
        # shellcheck disable=SC2086
        if $cc $std $W -O0 -DWITH_$T -I"$d" $C/single_film.c $C/single_film_main.c -lm -o "$t/film" 2>"$t/err" &&
            [ ! -s "$t/err" ] && "$t/film" >"$t/film.out"; then
            if [ $type = f16 ] && ! has_f16 "${cc%% *}"; then
                [ ! -s "$t/film.out" ] && echo "PASS $label (no _Float16 in ${cc%% *}: the binary16 film builds to nothing)" ||
                    echo "FAIL $label: printed binary16 lines without _Float16"
            elif cmp -s "$t/film_lib.out" "$t/film.out"; then
                echo "PASS $label: $(wc -l <"$t/film.out") colours, bit for bit those of libfresnel.a"
            else
                echo "FAIL $label: differs from libfresnel.a: $(diff "$t/film_lib.out" "$t/film.out" | sed -n 2,3p | tr '\n' ' ')"
            fi
        else
            echo "FAIL $label: $(head -5 "$t/err")"
        fi
    done
done

# ---- every public function the library defines, the single files define ----
if gcc -std=c99 $W -O2 -DWITH_F32 -DWITH_Q15 -DWITH_F16 -I"$t/f32" -I"$t/q15" -I"$t/f16" -c $C/single_file_impl.c \
    -o "$t/impl.o" 2>"$t/err"; then
    nm --defined-only "$BUILD/libfresnel.a" | awk '$2 == "T" && $3 ~ /^fresnel_/ {print $3}' | sort -u >"$t/lib.syms"
    nm --defined-only "$t/impl.o" | awk '$2 == "T" && $3 ~ /^fresnel_/ {print $3}' | sort -u >"$t/one.syms"
    missing=$(comm -23 "$t/lib.syms" "$t/one.syms" | tr '\n' ' ')
    if [ -s "$t/lib.syms" ] && [ -z "$missing" ]; then
        echo "PASS the single files define all $(wc -l <"$t/lib.syms") functions libfresnel.a defines"
    else
        echo "FAIL the single files lack: $missing"
    fi
else
    echo "FAIL single_file_impl.c: $(head -3 "$t/err")"
fi

# ---- tests/runtime/f32/test_batch.c on the single file's batch kernels ----
if gcc -std=c99 $W -O2 -D_POSIX_C_SOURCE=200809L -Iinclude -Itests/common -I"$t/f32" -DWITH_F32 tests/runtime/f32/test_batch.c \
    $C/single_file_impl.c -lm -o "$t/batch" 2>"$t/err" && "$t/batch" >"$t/batch.out"; then
    if grep -q '^FAIL' "$t/batch.out" || ! grep -q '^PASS' "$t/batch.out"; then
        echo "FAIL tests/runtime/f32/test_batch.c on fresnel_single_f32.h: $(grep -m3 '^FAIL' "$t/batch.out")"
    else
        echo "PASS tests/runtime/f32/test_batch.c on fresnel_single_f32.h: $(grep -c '^PASS' "$t/batch.out") checks pass"
    fi
else
    echo "FAIL tests/runtime/f32/test_batch.c on fresnel_single_f32.h: $(head -3 "$t/err")"
fi

# ---- the AVX2 target stays in the AVX2 kernel ----
case $(gcc -dumpmachine) in
x86_64*)
    cat >"$t/vex.c" <<'C'
#define FRESNEL_IMPLEMENTATION
#include "fresnel_single_f32.h"
/* the program's own code after the runtime, as in a unity build */
float after_the_runtime(float a, float b) { return a > b ? a * b : a - b; }
C
    for cc in gcc clang "g++ -x c++ -std=c++17"; do
        if $cc $W -O2 -I"$t/f32" -c "$t/vex.c" -o "$t/vex.o" 2>"$t/err" && objdump -d -C --no-show-raw-insn "$t/vex.o" >"$t/vex.s"; then
            # per function: its count of VEX-encoded and of ymm instructions
            awk '/^[0-9a-f]+ <.*>:$/ { f = substr($0, index($0, "<") + 1); sub(/>:$/, "", f); seen[f] = 1; next }
                 NF >= 2 && $2 ~ /^v/ { v[f]++ } /ymm/ { y[f]++ }
                 END { for (f in seen) printf "%s\t%d\t%d\n", f, v[f], y[f] }' "$t/vex.s" >"$t/funcs"
            leak=$(awk -F'\t' '$2 > 0 && $1 !~ /_avx/ {print $1}' "$t/funcs" | tr '\n' ' ')
            kernel=$(awk -F'\t' '$1 ~ /_avx/ && $3 > 0' "$t/funcs" | wc -l)
            plain=$(awk -F'\t' '$1 ~ /^(fresnel_schlick|fresnel_f82_rgb|after_the_runtime)($|\()/ && $2 == 0' "$t/funcs" | wc -l)
            if [ -n "$leak" ]; then
                echo "FAIL $cc -O2, plain x86-64: VEX instructions outside the AVX2 kernel, in: $leak"
            elif [ "$kernel" -eq 0 ] || [ "$plain" -ne 3 ]; then
                echo "FAIL $cc -O2: expected the AVX2 kernel in ymm and fresnel_schlick, fresnel_f82_rgb, the program's code after it ($kernel kernel functions, $plain plain)"
            else
                echo "PASS $cc -O2, plain x86-64: VEX only in the $kernel AVX2 kernel functions (8 lanes, ymm); $(($(wc -l <"$t/funcs") - kernel)) others, the program's code after the runtime included, SSE only"
            fi
        else
            echo "FAIL $cc: fresnel_single_f32.h for the target check: $(head -3 "$t/err")"
        fi
    done
    ;;
*) echo "NOTE no x86-64 compiler: the AVX2 target check needs one" ;;
esac
