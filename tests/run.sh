#!/bin/sh
# Runs every test binary in each build directory given (build, build/asan),
# and every tests/test_*.sh once per directory with BUILD set to it. Counts
# the PASS/FAIL lines; a test that exits non-zero without printing a FAIL
# line (a crash, a sanitizer report) counts as one failure. Ends with the line
# "N passed, N failed".
pass=0
fail=0
log=$(mktemp)
for dir in "$@"; do
    for t in "$dir"/tests/test_*; do
        [ -x "$t" ] || continue
        name="$dir/tests/$(basename "$t")"
        ( "$t" ) >"$log" 2>&1
        rc=$?
        sed -n 's/^\(PASS\|FAIL\|NOTE\) /\1 ['"$(basename "$dir")"'] /p' "$log"
        p=$(grep -c '^PASS ' "$log"); f=$(grep -c '^FAIL ' "$log")
        pass=$((pass + p)); fail=$((fail + f))
        if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
            echo "FAIL [$(basename "$dir")] $name exited $rc without a FAIL line:"; tail -20 "$log"
            fail=$((fail + 1))
        fi
    done
    for s in tests/test_*.sh; do
        [ -f "$s" ] || continue
        BUILD="$dir" sh "$s" >"$log" 2>&1
        rc=$?
        sed -n 's/^\(PASS\|FAIL\|NOTE\) /\1 ['"$(basename "$dir")"'] /p' "$log"
        p=$(grep -c '^PASS ' "$log"); f=$(grep -c '^FAIL ' "$log")
        pass=$((pass + p)); fail=$((fail + f))
        if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
            echo "FAIL [$(basename "$dir")] $s exited $rc without a FAIL line:"; tail -20 "$log"
            fail=$((fail + 1))
        fi
    done
done
rm -f "$log"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
