#!/bin/sh
# Runs every test binary in each build directory given (build, build/asan),
# and every tests/test_*.sh once per directory with BUILD set to it. Counts
# the PASS/FAIL lines; a test that exits non-zero without printing a FAIL
# line (a crash, a sanitizer report) counts as one failure. Ends with the line
# "N passed, N failed".
pass=0
fail=0
log=$(mktemp)

# tally FLAVOUR NAME EXIT_STATUS: counts $log's lines for one test
tally() {
    sed -n 's/^\(PASS\|FAIL\|NOTE\) /\1 ['"$1"'] /p' "$log"
    p=$(grep -c '^PASS ' "$log")
    f=$(grep -c '^FAIL ' "$log")
    pass=$((pass + p))
    fail=$((fail + f))
    if [ "$3" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL [$1] $2 exited $3 without a FAIL line:"
        tail -20 "$log"
        fail=$((fail + 1))
    fi
}

# An argument DIR@COMPILER runs DIR's scripts with CC=COMPILER (the
# other-compiler pass of make test); a plain DIR keeps $CC.
for arg in "$@"; do
    dir=${arg%@*}
    cc=${arg#"$dir"}
    cc=${cc#@}
    flavour=$(basename "$dir")
    for t in "$dir"/tests/test_*; do
        [ -x "$t" ] || continue
        ("$t") >"$log" 2>&1
        tally "$flavour" "$t" $?
    done
    for s in tests/test_*.sh; do
        [ -f "$s" ] || continue
        BUILD="$dir" CC="${cc:-${CC:-cc}}" sh "$s" >"$log" 2>&1
        tally "$flavour" "$s" $?
    done
done
rm -f "$log"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
