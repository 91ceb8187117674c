#!/bin/sh
# Hostile data for the generator: `fresnel gen --data DIR` on a
# copy of data/ with one bad n,k table added to materials.csv. Every error
# must name file:line (a missing file has no line: it names the file), exit
# with status 2 and leave no output or temp file; a table that only partly
# covers 360-830 nm proceeds with a file:line warning.
# Decisions (gen/1_spectral/load_nk.c, gen/1_spectral/resample.c): a table that misses 360-830 nm
# entirely is an error; lines longer than 4096 bytes and tables of more than
# 100000 rows are errors, so a 100 MB file is rejected after reading ~3 MB.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
cp -r data "$t/data" || exit 1
echo "hostile,Hostile table,hostile data test,metal" >>"$t/data/materials.csv"
echo "ghost,Listed but absent,hostile data test,metal" >>"$t/data/materials.csv"
printf 'materials = hostile\nmodels = schlick f82\n' >"$t/hostile.scene"
H='wavelength_nm,n,k'
csv="$t/data/hostile.csv"

leftovers() { ls "$t" | grep -c '^out\.h'; }

# name, expected stderr pattern (after the file path); the table is in $csv.
expect_error() {
    rm -f "$t"/out.h*
    "$F" gen "$t/hostile.scene" -o "$t/out.h" --data "$t/data" 2>"$t/err" >/dev/null
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qE -e "^$csv$2" "$t/err" && [ "$(leftovers)" -eq 0 ]; then
        echo "PASS hostile data: $1 ($(head -1 "$t/err" | sed "s|$t/data/||"))"
    else
        echo "FAIL hostile data: $1: exit $rc, files left $(leftovers), stderr '$(head -3 "$t/err")'"
    fi
}

: >"$csv"
expect_error "empty file" ':1: expected the header line .*empty file'
printf '%s\n' "$H" >"$csv"
expect_error "header only" ':2: expected at least two data rows'
printf '%s\n500,1.5,0\n' "$H" >"$csv"
expect_error "one row" ':3: expected at least two data rows'
printf '%s\n500,1.5,0\n510,1.5,0\n505,1.5,0\n' "$H" >"$csv"
expect_error "unsorted wavelengths" ':4: wavelength 505 not greater than previous 510'
printf '%s\n500,1.5,0\n500,1.6,0\n' "$H" >"$csv"
expect_error "duplicate wavelength" ':3: wavelength 500 not greater than previous 500'
printf '%s\n500,1.5,0\n510,-1.5,0\n' "$H" >"$csv"
expect_error "negative n" ':3: n = -1.5, expected n > 0'
printf '%s\n500,1.5,0\n510,1.5,-0.25\n' "$H" >"$csv"
expect_error "negative k" ':3: k = -0.25, expected k >= 0'
printf '%s\n500,1.5,0\n510,nan,0\n' "$H" >"$csv"
expect_error "NaN n" ':3: column n: expected a finite number'
printf '%s\n500,1.5,0\n510,1.5,NaN\n' "$H" >"$csv"
expect_error "NaN k" ':3: column k: expected a finite number'
printf '%s\n500,1.5,0\n510,1e39,0\n' "$H" >"$csv"
expect_error "n above FLT_MAX" ':3: n = 1e\+39, expected n in .*binary32'
printf '%s\n500,1.5,0\n510,1.5,3.5e38\n' "$H" >"$csv"
expect_error "k above FLT_MAX" ':3: k = 3.5e\+38, expected k <= .*binary32'
printf '%s\n500,1.5,0\n510,1e-39,0\n' "$H" >"$csv"
expect_error "n below FLT_MIN (a binary32 subnormal)" ':3: n = 1e-39, expected n in'
printf '%s\n500,1.5,0\n510,1.5,abc\n' "$H" >"$csv"
expect_error "text in a number column" ":3: column k: expected a number, got 'abc'"
printf '%s\n1000,1.5,0\n1500,1.45,0\n2000,1.4,0\n' "$H" >"$csv"
expect_error "a range above the visible spectrum (1000-2000 nm)" ':2: the table covers 1000-2000 nm, expected it to reach into 360-830 nm'
printf '%s\n200,1.5,0\n300,1.45,0\n350,1.4,0\n' "$H" >"$csv"
expect_error "a range below the visible spectrum (200-350 nm)" ':4: the table covers 200-350 nm'
awk 'BEGIN { printf "%s\n500,1.5,", "wavelength_nm,n,k"; for (i = 0; i < 65536; i++) printf "0"; print "" }' >"$csv"
expect_error "a 64 KB line" ':2: expected a line of at most 4096 bytes'
printf '%s\n500,1.5,0\n510,1.5\0,0\n' "$H" >"$csv"
expect_error "a NUL byte" ':3: expected text, found a NUL byte'

# About 111 MB of valid-looking rows (3.7 million, 300 to 670 nm).
awk -v h="$H" 'BEGIN { print h; for (i = 0; i < 3700000; i++) printf "%.7f,1.500000,0.000000\n", 300 + i * 0.0001 }' >"$csv"
size=$(wc -c <"$csv")
rm -f "$t"/out.h*
start=$(date +%s)
if [ -x /usr/bin/time ]; then
    /usr/bin/time -f '%M' -o "$t/rss" "$F" gen "$t/hostile.scene" -o "$t/out.h" --data "$t/data" 2>"$t/err" >/dev/null
    rc=$?
else
    "$F" gen "$t/hostile.scene" -o "$t/out.h" --data "$t/data" 2>"$t/err" >/dev/null
    rc=$?
    echo 0 >"$t/rss"
fi
secs=$(($(date +%s) - start))
rss=$(tail -1 "$t/rss")
# ASan's shadow memory inflates the resident size; the limit is for the plain build.
case "$BUILD" in *asan*) rss_limit=1000000 ;; *) rss_limit=65536 ;; esac
if [ "$size" -gt 100000000 ] && [ "$rc" -eq 2 ] && grep -q "^$csv:100002: expected at most 100000 data rows" "$t/err" &&
    [ "$(leftovers)" -eq 0 ] && [ "$secs" -le 10 ] && [ "$rss" -le "$rss_limit" ]; then
    echo "PASS hostile data: a $((size / 1000000)) MB table is rejected at line 100002 in ${secs} s, ${rss} KB resident"
else
    echo "FAIL hostile data: $size-byte table: exit $rc, $secs s, $rss KB, stderr '$(head -3 "$t/err")'"
fi
rm -f "$csv"

# A listed material whose file is missing: no line to cite, so the message names the file.
printf 'materials = ghost\nmodels = schlick\n' >"$t/ghost.scene"
rm -f "$t"/out.h*
"$F" gen "$t/ghost.scene" -o "$t/out.h" --data "$t/data" 2>"$t/err" >/dev/null
rc=$?
if [ "$rc" -eq 2 ] && grep -q "^$t/data/ghost.csv: cannot open: No such file" "$t/err" && [ "$(leftovers)" -eq 0 ]; then
    echo "PASS hostile data: a manifest naming a material whose file is missing ($(head -1 "$t/err" | sed "s|$t/data/||"))"
else
    echo "FAIL hostile data: missing material file: exit $rc, files left $(leftovers), stderr '$(head -3 "$t/err")'"
fi

# Partial coverage proceeds, with a warning at the row that ends the measured range.
printf '%s\n400,0.2,3.0\n650,0.25,3.5\n900,0.3,4.0\n' "$H" >"$csv"
rm -f "$t"/out.h*
"$F" gen "$t/hostile.scene" -o "$t/out.h" --data "$t/data" 2>"$t/err" >/dev/null
rc=$?
if [ "$rc" -eq 0 ] && [ -s "$t/out.h" ] && grep -q "^$csv:2: warning: measured 400-900 nm" "$t/err" &&
    [ "$(wc -l <"$t/err")" -eq 1 ]; then
    echo "PASS hostile data: a table measured from 400 nm proceeds with a file:line warning"
else
    echo "FAIL hostile data: partial range: exit $rc, stderr '$(head -3 "$t/err")'"
fi
cp "$t/out.h" "$t/lf.h" 2>/dev/null

# CRLF line endings: accepted, and the output is byte-identical to the LF table's.
printf '%s\r\n400,0.2,3.0\r\n650,0.25,3.5\r\n900,0.3,4.0\r\n' "$H" >"$csv"
rm -f "$t"/out.h*
"$F" gen "$t/hostile.scene" -o "$t/out.h" --data "$t/data" 2>"$t/err" >/dev/null
rc=$?
if [ "$rc" -eq 0 ] && cmp -s "$t/out.h" "$t/lf.h"; then
    echo "PASS hostile data: CRLF line endings give the same header as LF"
else
    echo "FAIL hostile data: CRLF: exit $rc, $(cmp "$t/out.h" "$t/lf.h" 2>&1 | head -1), stderr '$(head -3 "$t/err")'"
fi
