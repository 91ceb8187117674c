#!/bin/sh
# Replays the committed fuzz corpus without libFuzzer: each target
# tests/fuzz/fuzz_*.c is linked with tests/fuzz/replay_main.c against the
# objects `make test` built in $BUILD (so the asan pass replays under
# ASan+UBSan) and fed every file of tests/fuzz/corpus/<target>/. The oracle
# is the target's own; one PASS line per target, a FAIL line per failing
# file, build failure or crash.
B=${BUILD:-build}
CC=${CC:-cc}
case "$B" in
*asan*) SAN="-g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" ;;
*) SAN="" ;;
esac
out="$B/fuzz-replay"
mkdir -p "$out" || exit 1
gen_obj=$(ls "$B"/obj/gen/*/*.o 2>/dev/null | grep -v '/main\.o$')
if [ -z "$gen_obj" ] || [ ! -f "$B/libfresnel.a" ]; then
    echo "FAIL fuzz replay: $B has no generator objects or libfresnel.a (run make test-bins)"
    exit 1
fi
for src in tests/fuzz/fuzz_*.c; do
    name=$(basename "$src" .c)
    if [ ! -d "tests/fuzz/corpus/$name" ]; then
        echo "FAIL fuzz replay $name: no seed corpus tests/fuzz/corpus/$name/"
        continue
    fi
    # shellcheck disable=SC2086
    if ! $CC -std=c99 -Wall -Wextra -Wpedantic -Werror -O1 $SAN -DFUZZ_REPLAY -D_POSIX_C_SOURCE=200809L \
        -Iinclude -Isrc -Igen -Itests/fuzz "$src" tests/fuzz/replay_main.c $gen_obj "$B/libfresnel.a" -lm \
        -o "$out/$name" 2>"$out/$name.build.log"; then
        echo "FAIL fuzz replay $name: does not build: $(head -5 "$out/$name.build.log")"
        continue
    fi
    "$out/$name" "tests/fuzz/corpus/$name" >"$out/$name.log" 2>&1
    rc=$?
    grep -E '^(PASS|FAIL) ' "$out/$name.log"
    if [ "$rc" -ne 0 ] && ! grep -q '^FAIL ' "$out/$name.log"; then
        echo "FAIL fuzz replay $name exited $rc:"
        tail -20 "$out/$name.log"
    fi
done
