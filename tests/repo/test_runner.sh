#!/bin/sh
# passes: first (tests/run.sh itself, the same in every pass)
# tests/run.sh, the runner of make test and make check, on a tree of made-up
# checks in folders of tests/: each runs in the passes its header names (all without one) with
# that pass's BUILD and CC; a misspelt pass is a FAIL, not a check dropped
# in silence; a check that exits non-zero without a FAIL line counts as one
# failure; two checks run at once under JOBS=2 and each one's output is
# printed whole; without recorded times "start: early" starts first; make
# check's subset leaves out "make check: no"; the final count, the
# slowest-ten table and build/test-times.tsv.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
g=group
T=tests/$g/          # the made-up scripts' folder, as run.sh names them
TC=tests/$g/deep/    # the made-up C check's, a level further down
mkdir -p "$t/$T" "$t/$TC" "$t/build/tests" "$t/build/asan/tests" "$t/build/clang/tests"
cp tests/run.sh "$t/tests/"
# check NAME BODY [HEADER...]: NAME.sh in the made-up $T, the header lines, then BODY
check() {
    f=$t/$T$1.sh
    shift
    body=$1
    shift
    { echo '#!/bin/sh'; for h in "$@"; do echo "# $h"; done; echo "$body"; } >"$f"
}
check test_everywhere 'echo "PASS everywhere $BUILD $CC"'
check test_two 'echo "PASS two $BUILD $CC"' 'passes: first other (a reason)' 'what it checks'
check test_typo 'echo "PASS typo"' 'passes: frist'
check test_crash 'echo "NOTE about to crash"; exit 3' 'passes: sanitize'
check test_slow 'echo "PASS slow"' 'passes: first' 'make check: no (an external tool)'
# two checks that each wait for the other: they pass only when run at once
check test_meet_a 'echo "PASS a1"; : >"$BUILD/a"; i=0; while [ ! -f "$BUILD/b" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done; [ -f "$BUILD/b" ] && echo "PASS a2 met b" || echo "FAIL a2: b never ran beside a"' 'passes: first'
check test_meet_b 'echo "PASS b1"; : >"$BUILD/b"; i=0; while [ ! -f "$BUILD/a" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done; [ -f "$BUILD/a" ] && echo "PASS b2 met a" || echo "FAIL b2: a never ran beside b"' 'passes: first'
check test_zz_early 'echo "PASS early"' 'passes: first' 'start: early (a long one)'
printf '/* a C check\n * passes: sanitize */\n' >"$t/${TC}test_c.c"
printf '#!/bin/sh\necho "PASS c binary $0"\n' >"$t/build/asan/tests/test_c"
chmod +x "$t/build/asan/tests/test_c"

(cd "$t" && CC=cc JOBS=2 sh tests/run.sh first=build sanitize=build/asan other=build/clang@clang) >"$t/out" 2>&1
rc=$?
expect() { # name, then the lines the output must have, in this order
    name=$1
    shift
    missing=""
    for l in "$@"; do grep -qxF -e "$l" "$t/out" || missing="$missing '$l'"; done
    [ -z "$missing" ] && echo "PASS run.sh: $name" || echo "FAIL run.sh: $name: missing$missing"
}
expect "a check without a passes: line runs in every pass with its BUILD and CC" \
    "PASS [build] everywhere build cc" "PASS [asan] everywhere build/asan cc" "PASS [clang] everywhere build/clang clang"
expect "'passes: first other' runs there only" "PASS [build] two build cc" "PASS [clang] two build/clang clang"
grep -q 'two build/asan' "$t/out" && echo "FAIL run.sh: a first other check ran in the sanitize pass" ||
    echo "PASS run.sh: a first other check does not run in the sanitize pass"
expect "a C check's binary runs in its pass, from the pass's build" "PASS [asan] c binary build/asan/tests/test_c"
n=$(grep -c "unknown pass 'frist'" "$t/out")
[ "$n" -eq 1 ] && grep -qxF "FAIL ${T}test_typo.sh: unknown pass 'frist' on its passes: line (expected all, first, sanitize, other)" "$t/out" &&
    echo "PASS run.sh: a misspelt pass is one FAIL line naming it" || echo "FAIL run.sh: misspelt pass: $n lines"
expect "a check that exits non-zero without a FAIL line is a failure, its output shown" \
    "FAIL [asan] ${T}test_crash.sh exited 3 without a FAIL line:" "NOTE about to crash"
# each check's lines together, though the two ran at once
sed -n 's/^PASS \[build\] \([ab][12]\).*/\1/p' "$t/out" | tr '\n' ' ' >"$t/order"
case $(cat "$t/order") in
"a1 a2 b1 b2 " | "b1 b2 a1 a2 ") echo "PASS run.sh: JOBS=2 runs two checks at once, each one's output printed whole ($(cat "$t/order"))" ;;
*) echo "FAIL run.sh: two checks at once: $(grep -E 'a[12]|b[12]' "$t/out" | tr '\n' ' ')" ;;
esac
# with no build/test-times.tsv yet, "start: early" first, then "make check: no"
[ "$(grep -m2 '^PASS' "$t/out" | tr '\n' ' ')" = "PASS [build] early PASS [build] slow " ] &&
    echo "PASS run.sh: without recorded times, 'start: early' starts first, then 'make check: no'" ||
    echo "FAIL run.sh: the first checks: $(grep -m2 '^PASS' "$t/out" | tr '\n' ' ')"
# PASS: everywhere x3, two x2, c, slow, early, a1 a2 b1 b2 = 12; FAIL: typo, crash
tail -1 "$t/out" | grep -qxF "12 passed, 2 failed" && [ $rc -eq 1 ] &&
    echo "PASS run.sh: the count is the last line; exit 1 on a failure" || echo "FAIL run.sh: last line '$(tail -1 "$t/out")', exit $rc"
grep -q '^NOTE the ten slowest checks (of 11, 2 at a time' "$t/out" &&
    [ "$(sed -n '/^NOTE the ten slowest/,/^NOTE checks per pass/p' "$t/out" | grep -c '^NOTE  ')" -eq 10 ] &&
    expect "the ten slowest and the checks per pass" "NOTE checks per pass: build 6, asan 3, clang 2" ||
    echo "FAIL run.sh: slowest-ten table: $(grep '^NOTE' "$t/out" | head -3)"
[ "$(wc -l <"$t/build/test-times.tsv")" -eq 11 ] && awk -F'\t' -v T="$TC" '$1 == "asan" && $2 == T "test_c.c" && $4 == 1' \
    "$t/build/test-times.tsv" | grep -q . && echo "PASS run.sh: build/test-times.tsv has a row per check and pass" ||
    echo "FAIL run.sh: test-times.tsv: $(head -3 "$t/build/test-times.tsv")"

# make check's subset: the first pass without "make check: no"
rm -f "$t/build/a" "$t/build/b"
(cd "$t" && CC=cc JOBS=2 sh tests/run.sh --check first=build) >"$t/out" 2>&1
grep -q 'PASS \[build\] slow' "$t/out" && echo "FAIL run.sh: --check ran a 'make check: no' check" ||
    expect "--check leaves out 'make check: no'" "PASS [build] everywhere build cc" "NOTE checks per pass: build 5"
# and says which it ran, which it left to make test, and how to run one alone
grep -q '^NOTE make check ran 5 checks: .*test_everywhere' "$t/out" && grep -q '^NOTE left to make test.*test_slow' "$t/out" &&
    grep -q '^NOTE one alone: build/tests/test_NAME' "$t/out" &&
    echo "PASS run.sh: --check names the checks it ran, those left to make test, and how to run one alone" ||
    echo "FAIL run.sh: --check's closing notes: $(grep '^NOTE' "$t/out" | tail -3 | tr '\n' ' ')"

# two C checks of one name in two folders would share one binary: a FAIL line
cp "$t/${TC}test_c.c" "$t/${T}test_c.c"
(cd "$t" && CC=cc JOBS=2 sh tests/run.sh --check first=build) >"$t/out" 2>&1
grep -qxF "FAIL tests/run.sh: two checks named test_c.c: ${T}test_c.c ${TC}test_c.c " "$t/out" ||
    grep -qxF "FAIL tests/run.sh: two checks named test_c.c: ${TC}test_c.c ${T}test_c.c " "$t/out" &&
    echo "PASS run.sh: two C checks of one name are a FAIL line naming both" ||
    echo "FAIL run.sh: two C checks of one name: $(grep 'two checks' "$t/out")"
