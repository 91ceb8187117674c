#!/bin/sh
# passes: first (the libFuzzer builds have their own flags, the same in every pass)
# make check: no (clang links six libFuzzer targets from source)
# `make fuzz` links each libFuzzer target against its own list of host
# sources (FUZZ_GEN in the Makefile): linking them all here keeps that list
# whole. The corpus replay: tests/fuzz/test_fuzz_replay.sh.
out=${BUILD:-build}/fuzz-link
mkdir -p "$out"
if make -s --no-print-directory BUILD="$out" fuzz-bins >"$out/fuzz-link.log" 2>&1; then
    echo "PASS fuzz: make fuzz-bins links every libFuzzer target"
else
    echo "FAIL fuzz: make fuzz-bins: $(grep -m3 'undefined reference\|error' "$out/fuzz-link.log")"
fi
