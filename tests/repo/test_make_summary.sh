#!/bin/sh
# passes: first (the default build only)
# `make` ends with a few lines that say what it built and where, and how to
# see the report; not with the accuracy table (`build/fresnel accuracy`).
# Each file or folder the summary names exists.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if ! make --no-print-directory BUILD="$BUILD" >"$t/out" 2>&1; then
    echo "FAIL make: $(tail -5 "$t/out")"
    exit 1
fi
sed -n '/^built:$/,$p' "$t/out" >"$t/summary"
n=$(wc -l <"$t/summary")
names=$(sed -n 's/^  \([a-z_./]*[a-z_.]\/*\) .*/\1/p' "$t/summary")
missing=""
for name in $names; do
    [ -e "$name" ] || missing="$missing $name"
done
if [ "$n" -eq 0 ] || [ "$n" -gt 10 ]; then
    echo "FAIL make ends with $n summary lines: $(tail -3 "$t/out")"
elif grep -q '^|' "$t/out"; then
    echo "FAIL make prints a table: $(grep -m1 '^|' "$t/out")"
elif [ -n "$missing" ] || [ "$(echo $names | wc -w)" -lt 4 ]; then
    echo "FAIL make's summary names what is not there:$missing"
elif ! grep -q 'make report' "$t/summary" || ! grep -q 'report.md' "$t/summary"; then
    echo "FAIL make's summary does not say how to see the report"
else
    echo "PASS make ends with $n lines: $(echo $names | wc -w) things built ($(echo $names)), each there, and how to see the report"
fi
# `make` alone runs one job per core (JOBS, the CPU count), and a -j given
# on the command line wins
cores=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
plain=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -pnq all 2>/dev/null | sed -n 's/^MAKEFLAGS = //p' | grep -o -- '-j[0-9]*' | head -1)
given=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -j1 -pnq all 2>/dev/null | sed -n 's/^MAKEFLAGS = //p' | grep -o -- '-j[0-9]*' | sort -u | tr '\n' ' ')
if [ "$plain" = "-j$cores" ] && [ "$given" = "-j1 " ]; then
    echo "PASS make runs $cores jobs by default (one per core), -j1 when asked"
else
    echo "FAIL make's jobs: '$plain' by default (want -j$cores), '$given' with -j1 (want -j1 alone)"
fi
