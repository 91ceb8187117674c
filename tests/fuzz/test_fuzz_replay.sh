#!/bin/sh
# Replays the committed fuzz corpus without libFuzzer: each target
# tests/fuzz/fuzz_*.c, linked by make test-bins with tests/fuzz/replay_main.c
# against the objects of $BUILD (so the asan pass replays under ASan+UBSan)
# into $BUILD/fuzz-replay/, is fed every file of tests/fuzz/corpus/<target>/. The oracle
# is the target's own; one PASS line per target, a FAIL line per failing
# file, build failure or crash.
B=${BUILD:-build}
out="$B/fuzz-replay"
for src in tests/fuzz/fuzz_*.c; do
    name=$(basename "$src" .c)
    if [ ! -d "tests/fuzz/corpus/$name" ]; then
        echo "FAIL fuzz replay $name: no seed corpus tests/fuzz/corpus/$name/"
        continue
    fi
    if [ ! -x "$out/$name" ]; then
        echo "FAIL fuzz replay $name: $out/$name not built (make test-bins builds it)"
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
