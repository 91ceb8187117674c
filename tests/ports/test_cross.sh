#!/bin/sh
# passes: first (target code does not change under the host's sanitizers)
# make check: no (qemu and the cross compilers)
# start: early (three emulators at once)
# The fixed-point runtime on the Arm and RISC-V ISAs: `make
# cross-test` builds the conformance program for a Cortex-M0, a Cortex-M4F
# and an RV32IMC, runs it under qemu and compares every result with the
# host's bit for bit, and checks the symbols of the fixed-point-only
# Cortex-M0 build. Then the Cortex-M0 instruction counts, as NOTE lines.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if make --no-print-directory -s cross-test BUILD="$BUILD" >"$log" 2>&1; then
    grep -E '^(PASS|FAIL|NOTE) ' "$log"
    grep -qE '^(PASS|FAIL) ' "$log" || echo "FAIL make cross-test printed no result: $(tail -5 "$log")"
else
    grep -E '^(PASS|FAIL|NOTE) ' "$log"
    echo "FAIL make cross-test: $(grep -v -E '^(PASS|FAIL|NOTE) ' "$log" | tail -5 | tr '\n' ' ')"
    exit 1
fi
if BUILD="$BUILD" sh ports/cross.sh count m0 >"$log" 2>&1; then
    awk -F'\t' '{ printf "NOTE Cortex-M0 fixed point %-26s %5d instructions per call (min %d, max %d)\n", $1, $2, $3, $4 }' "$log"
    s=$(awk -F'\t' '$1 == "schlick" { print $2 }' "$log")
    [ -n "$s" ] && [ "$s" -lt 200 ] && echo "PASS Cortex-M0 fixed-point Schlick takes $s instructions per call (< 200)" ||
        echo "FAIL Cortex-M0 fixed-point Schlick: '$s' instructions per call"
else
    echo "FAIL Cortex-M0 instruction count: $(tail -3 "$log")"
fi
