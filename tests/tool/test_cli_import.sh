#!/bin/sh
# Users' own n,k files (gen/1_spectral/import.c): every format read from real
# or constructed files in tests/data/import/ (provenance: tests/data/import/README.md),
# each checked against the same data converted independently into the data
# pack's CSV (*.reference.csv); the four routes (--nk, a manifest's
# 'material ID = FILE', fresnel import, the data-pack CSV); and the hostile
# variants of each format, which must fail with file:line, exit status 2 and
# no output written.
F="$BUILD/fresnel"
I=tests/data/import
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

pass() { echo "PASS import: $1"; }
fail() { echo "FAIL import: $1"; }

f0() { "$F" params --nk "$1" 2>/dev/null | grep '^f0_unclamped,'; }

# Largest per-channel difference of two f0_unclamped rows, or "x" if one is missing.
f0_diff() {
    printf '%s\n%s\n' "$1" "$2" | awk -F, 'NF != 4 { bad = 1 } { for (i = 2; i <= 4; i++) v[NR, i] = $i }
        END { if (bad || NR != 2) { print "x"; exit } m = 0
              for (i = 2; i <= 4; i++) { d = v[1, i] - v[2, i]; if (d < 0) d = -d; if (d > m) m = d } print m }'
}

within() { awk -v d="$1" -v tol="$2" 'BEGIN { exit !(d != "x" && d + 0 <= tol) }'; }

# ---- every file F0 within 1e-4 of its independent conversion
for pair in Au-Johnson.yml:Au-Johnson TiN-Pfluger.yml:TiN-Pfluger N-BK7.yml:N-BK7 BOROFLOAT33.yml:BOROFLOAT33 \
    E-LLF2.yml:E-LLF2 TiO2-Devore-o.yml:TiO2-Devore-o PMMA-495-specs.yml:PMMA-495-specs Ar-Peck-15C.yml:Ar-Peck-15C \
    herzberger-constructed.yml:herzberger-constructed TlCl-Schroter.yml:TlCl-Schroter urea-Rosker-e.yml:urea-Rosker-e \
    Au-Johnson.export.csv:Au-Johnson.export N-BK7.export.csv:N-BK7.export Au-eV.nk:Au-eV Au-nm.nk:Au-nm \
    Au.eta.spd:Au.spd Au.k.spd:Au.spd; do
    file=${pair%%:*}
    ref=${pair##*:}.reference.csv
    d=$(f0_diff "$(f0 "$I/$file")" "$(f0 "$I/$ref")")
    if within "$d" 1e-4; then pass "$file: F0 within 1e-4 of $ref (max diff $d)"
    else fail "$file: F0 differs from $ref by $d ($(f0 "$I/$file" 2>&1 | head -1))"; fi
done

# ---- the format each file is told to be
for pair in Au-Johnson.yml:rii-yaml Au-Johnson.export.csv:rii-csv Au-eV.nk:sopra Au.eta.spd:spd \
    Au-Johnson.reference.csv:csv; do
    file=${pair%%:*}
    want=${pair##*:}
    if "$F" params --nk "$I/$file" 2>/dev/null | head -1 | grep -q "; $want file,"; then pass "$file is read as $want"
    else fail "$file: not read as $want: $("$F" params --nk "$I/$file" 2>&1 | head -1)"; fi
done

# ---- a user's file gives the same rows as the data pack's table of the same data
"$F" params --material au | grep -v '^#' >"$t/pack.csv"
"$F" params --nk "$I/Au-Johnson.yml" | grep -v '^#' >"$t/file.csv"
if [ -s "$t/pack.csv" ] && cmp -s "$t/pack.csv" "$t/file.csv"; then
    pass "params --nk Au-Johnson.yml prints the same rows as --material au (same Johnson & Christy data), f0_unclamped included"
else fail "params --nk Au-Johnson.yml differs from --material au: $(diff "$t/pack.csv" "$t/file.csv" | head -3)"; fi
if "$F" params --nk "$I/TiN-Pfluger.yml" --name tin --space rec2020 --sigma 10 --n1 1.33 | head -1 | grep -q '^# material tin (TiN-Pfluger.yml;'; then
    pass "params --nk takes --name and every other material option"
else fail "params --nk --name: $("$F" params --nk "$I/TiN-Pfluger.yml" --name tin 2>&1 | head -1)"; fi
n=$("$F" curve --nk "$I/N-BK7.yml" --samples 10 2>/dev/null | grep -c '^[0-9]')
[ "$n" -eq 10 ] && pass "curve --nk: 10 rows" || fail "curve --nk: $n rows"
if "$F" bench --nk "$I/TiN-Pfluger.yml" --runs 0 --count 64 >/dev/null 2>"$t/err"; then pass "bench --nk runs"
else fail "bench --nk: $(head -1 "$t/err")"; fi

# ---- fresnel import: the file's rows in nm, read back identically
for file in Au-Johnson.yml N-BK7.yml Au-Johnson.export.csv Au-eV.nk Au.k.spd herzberger-constructed.yml; do
    if "$F" import "$I/$file" -o "$t/imported.csv" 2>"$t/err"; then
        d=$(f0_diff "$(f0 "$I/$file")" "$(f0 "$t/imported.csv")")
        if within "$d" 1e-9 && head -1 "$t/imported.csv" | grep -qx 'wavelength_nm,n,k'; then
            pass "import $file: a wavelength_nm,n,k CSV giving the same F0 (diff $d)"
        else fail "import $file: F0 diff $d"; fi
    else fail "import $file: $(head -1 "$t/err")"; fi
done
rows=$("$F" import "$I/Au-Johnson.yml" -o - 2>/dev/null | tail -n +2 | wc -l)
yaml_rows=$(awk '/^        [0-9]/' "$I/Au-Johnson.yml" | wc -l)
[ "$rows" -eq "$yaml_rows" ] && pass "import keeps the file's own $rows rows (nothing resampled)" || fail "import: $rows rows for $yaml_rows in the file"
first=$("$F" import "$I/Au-Johnson.yml" -o - 2>/dev/null | sed -n 2p)
[ "$first" = "187.9,1.28,1.188" ] && pass "import writes wavelengths in nm (0.1879 um -> 187.9)" || fail "import first row '$first'"
# the imported CSV is a data-pack table: added to a copy of data/ it is a material like any other
cp -r data "$t/data"
"$F" import "$I/TiN-Pfluger.yml" -o "$t/data/tin.csv" 2>/dev/null
echo "tin,Titanium nitride TiN,Pfluger 1984 (refractiveindex.info),metal" >>"$t/data/materials.csv"
d=$(f0_diff "$("$F" params --material tin --data "$t/data" 2>/dev/null | grep '^f0_unclamped,')" "$(f0 "$I/TiN-Pfluger.yml")")
within "$d" 0 && pass "an imported file added to materials.csv is a data-pack material with the same F0" || fail "imported material: diff $d"
"$F" materials --data "$t/data" | grep -q '^tin,Titanium nitride TiN,Pfluger 1984 (refractiveindex.info),metal,' &&
    pass "fresnel materials lists it in materials.csv's column order" || fail "materials listing of tin"

# ---- a manifest names a user's file, relative to the manifest
mkdir -p "$t/project/nk"
cp "$I/TiN-Pfluger.yml" "$t/project/nk/TiN.yml"
printf 'materials = cu\nmaterial tin = nk/TiN.yml\nmodels = schlick f82 lut16\ntypes = f32 q15\n' >"$t/project/coat.scene"
if (cd "$t" && "$OLDPWD/$F" gen project/coat.scene -o "$t/coat.h" 2>"$t/err"); then
    hash=$(sha256sum "$t/project/nk/TiN.yml" | cut -d' ' -f1)
    bytes=$(wc -c <"$t/project/nk/TiN.yml" | tr -d ' ')
    if grep -q "^ \*   tin  *TiN.yml (supplied by the user: rii-yaml, $bytes bytes)" "$t/coat.h" && grep -q "sha256 $hash" "$t/coat.h" &&
        grep -q 'fresnel_coat_tin_f0' "$t/coat.h" && grep -q 'fresnel_coat_cu_f0' "$t/coat.h"; then
        pass "gen: 'material tin = nk/TiN.yml' beside 'materials = cu'; the header records name, format, size and sha256"
    else fail "gen with a user's file: header comment $(grep -n 'tin' "$t/coat.h" | head -3)"; fi
    # the data's terms as they are: the pack's licence for cu, none claimed for tin
    sed -n '1,/^ \*\/$/p' "$t/coat.h" | tr '\n' ' ' >"$t/opening"
    if grep -q "the data pack's materials are facts derived from refractiveindex.info data (CC0 1.0;" "$t/opening" &&
        grep -q " \* tin: derived from a file supplied by the user (named with its SHA-256 in the  \* material list), under whatever terms it came with" "$t/opening" &&
        ! grep -q "numbers below are facts derived from refractiveindex.info" "$t/opening"; then
        pass "gen: the header gives the data pack's licence for its materials and, for the user's file, no licence it cannot know"
    else fail "gen with a user's file: the opening comment's data terms: $(sed -n 2,5p "$t/coat.h")"; fi
    printf 'material tin = nk/TiN.yml\nmodels = schlick\n' >"$t/project/own.scene"
    if "$F" gen "$t/project/own.scene" -o "$t/own.h" 2>"$t/err" && ! grep -q "CC0" "$t/own.h" &&
        grep -q "tin: derived from a file supplied by the user" "$t/own.h"; then
        pass "gen: a scene of the user's files alone claims no licence for their data"
    else fail "gen with only a user's file: $(sed -n 2,4p "$t/own.h" 2>/dev/null) $(head -1 "$t/err")"; fi
    if ${CC:-cc} -std=c99 -Wall -Wextra -Werror -fsyntax-only -Iinclude -include "$t/coat.h" -x c /dev/null 2>"$t/err"; then
        pass "the header with a user's material compiles warning-free"
    else fail "header with a user's material: $(head -2 "$t/err")"; fi
else fail "gen with a user's file: $(head -2 "$t/err")"; fi
cp "$t/coat.h" "$t/coat1.h"
echo "# edited" >>"$t/project/nk/TiN.yml"
"$F" gen "$t/project/coat.scene" -o "$t/coat.h" 2>/dev/null
if ! cmp -s "$t/coat.h" "$t/coat1.h" && grep -q "sha256 $(sha256sum "$t/project/nk/TiN.yml" | cut -d' ' -f1)" "$t/coat.h"; then
    pass "a changed file changes the recorded hash"
else fail "a changed file left the header's hash unchanged"; fi
printf 'material x = nk/missing.yml\nmodels = schlick\n' >"$t/project/missing.scene"
"$F" gen "$t/project/missing.scene" -o "$t/m.h" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && grep -q "project/nk/missing.yml: cannot open" "$t/err" && [ ! -e "$t/m.h" ] &&
    pass "gen: a missing material file is named as resolved, exit 2, no output" || fail "missing material file: rc $rc $(head -1 "$t/err")"
printf 'materials = nk/TiN.yml\nmodels = schlick\n' >"$t/project/path.scene"
"$F" gen "$t/project/path.scene" -o "$t/m.h" 2>"$t/err"
grep -q ":1: expected material ids .*'material ID = FILE'" "$t/err" && pass "a path in 'materials =' points to 'material ID = FILE'" ||
    fail "path in materials: $(head -1 "$t/err")"
"$F" params --material "$I/TiN-Pfluger.yml" 2>"$t/err" >/dev/null
grep -q "use\|--nk FILE" "$t/err" && pass "--material with a path points to --nk" || fail "--material path: $(head -1 "$t/err")"

# ---- hostile variants: exit 2, file:line, the expected words, no output
# expect NAME FILE PATTERN [extra options]: PATTERN follows "FILE:" in the message.
expect() {
    name=$1 file=$2 pattern=$3
    shift 3
    rm -f "$t/out.csv"
    echo keep >"$t/kept.csv"
    "$F" import "$file" -o "$t/kept.csv" "$@" 2>"$t/err" >/dev/null
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qE -e "^$file$pattern" "$t/err" && [ "$(cat "$t/kept.csv")" = keep ] &&
        [ "$(ls "$t" | grep -c '^kept\.csv.')" -eq 0 ]; then
        pass "rejects $name ($(head -1 "$t/err" | sed "s|$t/||" | cut -c1-150))"
    else fail "$name: exit $rc, stderr '$(head -2 "$t/err")'"; fi
}
# accept NAME FILE REFERENCE: read without error and the same F0 as REFERENCE.
accept() {
    d=$(f0_diff "$(f0 "$2")" "$(f0 "$3")")
    within "$d" 1e-12 && pass "accepts $1 (same F0)" || fail "$1: F0 diff $d ($("$F" params --nk "$2" 2>&1 | head -1))"
}

y=$t/h.yml
au="$I/Au-Johnson.yml"
head -13 "$au" >"$y"; echo "        0.1879 1.28" >>"$y"
expect "YAML: a truncated row" "$y" ':14: expected 3 numbers \(um n k\)'
head -13 "$au" >"$y"
expect "YAML: a truncated block (data: | and no rows)" "$y" ":13: expected rows after 'data: \|'"
sed 's/^        \([0-9.]*\) /        \1e3 /' "$au" >"$y"
expect "YAML: wavelengths in nm (wrong unit)" "$y" ':[0-9]+: the table covers .* \(wavelengths read as um; were the numbers meant as nm'
sed 's/tabulated nk/formula 12/' "$au" >"$y"
expect "YAML: an unknown formula type" "$y" ":12: expected type .*got 'formula 12'"
printf 'DATA:\n  - type: formula A\n    wavelength_range: 0.4 0.8\n    coefficients: 1 2\n' >"$y"
expect "YAML: an n2 file (formula A)" "$y" ':2: .*nonlinear index n2'
grep -v coefficients "$I/N-BK7.yml" >"$y"
expect "YAML: coefficients missing" "$y" ':12: formula 2: coefficients missing'
sed 's/coefficients: .*/coefficients:/' "$I/N-BK7.yml" >"$y"
expect "YAML: an empty coefficient list" "$y" ':14: expected coefficients: C1 C2 ..., got none'
sed 's/coefficients: .*/coefficients: 1 2 3 4 5 6 7/' "$I/herzberger-constructed.yml" >"$y"
expect "YAML: more coefficients than the formula reads" "$y" ':9: formula 7 reads at most 6 coefficients, got 7'
grep -v wavelength_range "$I/N-BK7.yml" >"$y"
expect "YAML: wavelength_range missing" "$y" ':12: formula 2: wavelength_range missing'
sed 's/wavelength_range: .*/wavelength_range: 2.5 0.3/' "$I/N-BK7.yml" >"$y"
expect "YAML: a reversed wavelength_range" "$y" ':13: expected wavelength_range: lo hi'
sed 's/wavelength_range: .*/wavelength_range: 1.0 2.5/' "$I/N-BK7.yml" >"$y"
expect "YAML: a formula range outside the visible" "$y" ":13: the formula's wavelength_range 1-2.5 um .*fewer than two points in 360-830 nm"
sed 's/coefficients: .*/coefficients: -5 0.1 0.1/' "$I/N-BK7.yml" >"$y"
expect "YAML: a formula with no real n" "$y" ':14: formula 2 gives no real, positive n'
sed 's/^    data: |/\tdata: |/' "$au" >"$y"
expect "YAML: a tab in the indentation" "$y" ':13: expected spaces for indentation, got a tab'
sed '15s/.*/        # a comment inside the block/' "$au" >"$y"
expect "YAML: a comment inside a data block" "$y" ':15: expected a row of numbers inside the data block, got a comment'
sed 's/^COMMENTS:/NOTES:/' "$au" >"$y"
expect "YAML: a key outside the schema" "$y" ":9: expected a top-level key .*got 'NOTES'"
sed 's/^    data: |/    values: |/' "$au" >"$y"
expect "YAML: an entry key outside the schema" "$y" ":13: expected a key of a DATA entry .*got 'values'"
sed '15s/.*/        0.1879 1.30 1.2/' "$au" >"$y"
expect "YAML: a repeated wavelength" "$y" ':15: wavelength 187.9 nm not greater than the previous row'
sed '16s/.*/        0.1800 1.30 1.2/' "$au" >"$y"
expect "YAML: a wavelength going backwards" "$y" ':16: wavelength 180 nm not greater than the previous row'
sed '20s/ \([0-9.]*\)$/ -\1/' "$au" >"$y"
expect "YAML: a negative k" "$y" ':20: k = -[0-9.]*, expected k >= 0'
sed '20s/^\(        [0-9.]*\) /\1 -/' "$au" >"$y"
expect "YAML: a negative n" "$y" ':20: n = -[0-9.]*, expected n > 0'
sed '20s/ \([0-9.]*\)$/ 1e39/' "$au" >"$y"
expect "YAML: a k no binary32 holds" "$y" ':20: k = 1e\+39, expected k <= .*binary32'
{ cat "$au"; printf '  - type: formula 1\n    wavelength_range: 0.3 0.9\n    coefficients: 0 1 0.1\n'; } >"$y"
expect "YAML: n given twice" "$y" ':[0-9]+: n is given twice: by the entry at line 12'
printf 'DATA:\n  - type: tabulated k\n    data: |\n        0.4 0.1\n        0.8 0.2\n' >"$y"
expect "YAML: k without n" "$y" ":1: expected an entry giving n"
sed 's/$/\r/' "$au" >"$t/crlf.yml"
accept "YAML with CRLF line ends" "$t/crlf.yml" "$au"
printf '\357\273\277' >"$t/bom.yml"; cat "$au" >>"$t/bom.yml"
accept "YAML with a byte-order mark" "$t/bom.yml" "$au"
{ echo "# a comment of my own"; sed 's/^COMMENTS: |/COMMENTS: |  # trailing/; s/^DATA:/# between keys\nDATA:/' "$au"; } >"$t/comments.yml"
accept "YAML with comment lines" "$t/comments.yml" "$au"
sed 's/^        \([0-9.]*\) \([0-9.]*\) /        \1\t\2\t/' "$au" >"$t/tabs.yml"
accept "YAML rows separated by tabs" "$t/tabs.yml" "$au"

c=$t/h.csv
ex="$I/Au-Johnson.export.csv"
sed '2s/$/,1.5/' "$ex" >"$c"
expect "CSV export: a row with three fields under wl,n" "$c" ':2: expected 2 comma-separated numbers under .wl,n., got 3'
awk '/^wl,k/ { print; exit } { print }' "$ex" >"$c"
expect "CSV export: a wl,k header without rows (truncated)" "$c" ':[0-9]+: expected rows after this header, got none'
awk -F, '/^[0-9]/ { printf "%g,%s\n", $1 * 1000, $2; next } { print }' "$ex" >"$c"
expect "CSV export: wavelengths in nm (wrong unit)" "$c" ':[0-9]+: the table covers .* \(wavelengths read as um; were the numbers meant as nm'
sed 's/^wl,k/wl,n/' "$ex" >"$c"
expect "CSV export: n given twice" "$c" ':[0-9]+: expected each of n and k once'
sed '1s/.*/wl,n,x/' "$ex" >"$c"
expect "CSV export: an unknown header" "$c" ":1: expected a header 'wl,n', 'wl,k' or 'wl,n,k'"
sed 's/$/\r/' "$ex" >"$t/crlf.csv"
accept "CSV export with CRLF line ends" "$t/crlf.csv" "$ex"
printf '\357\273\277' >"$t/bom.csv"; cat "$ex" >>"$t/bom.csv"
accept "CSV export with a byte-order mark" "$t/bom.csv" "$ex"

s=$t/h.nk
nk="$I/Au-eV.nk"
sed '1s/^1/3/' "$nk" >"$s"
expect "SOPRA: unit code 3 (ambiguous)" "$s" ':1: unit code 3 is read as cm\^-1 by some programs'
sed '1s/^1/7/' "$nk" >"$s"
expect "SOPRA: an unknown unit code" "$s" ':1: expected unit code 1 \(eV\), 2 \(um\) or 4 \(nm\), got 7'
sed '$d' "$nk" >"$s"
expect "SOPRA: a missing row (truncated)" "$s" ':45: expected 45 n,k pairs .*got 44'
sed '$s/\t[0-9.]*$//' "$nk" >"$s"
expect "SOPRA: a row without its k" "$s" ':46: expected 45 n,k pairs .*got 44 and an n without its k'
sed '1s/.*/1\t350\t850\t44/' "$nk" >"$s"
expect "SOPRA: nm values under the eV code (wrong unit)" "$s" ':[0-9]+: the table covers .* \(wavelengths read as eV\)'
sed '1s/.*/1\t1.4\t3.6/' "$nk" >"$s"
expect "SOPRA: a header of three numbers (with --format sopra)" "$s" ':1: expected the SOPRA header .*got 3 numbers' --format sopra
sed '3s/.*/0.16\tabc/' "$nk" >"$s"
expect "SOPRA: text for a number" "$s" ":3: expected a finite number, got 'abc'"
sed 's/\t/;/g' "$nk" >"$t/semi.nk"
accept "SOPRA with ';' separators" "$t/semi.nk" "$nk"
sed 's/$/\r/' "$nk" >"$t/crlf.nk"
accept "SOPRA with CRLF line ends" "$t/crlf.nk" "$nk"

mkdir -p "$t/spd"
cp "$I/Au.eta.spd" "$I/Au.k.spd" "$t/spd/"
sed '$s/ [0-9.]*$//' "$I/Au.k.spd" >"$t/spd/Au.k.spd"
expect "spd: a wavelength without its value (in the k file)" "$t/spd/Au.k.spd" ':[0-9]+: expected a value after wavelength'
rm "$t/spd/Au.eta.spd"
cp "$I/Au.k.spd" "$t/spd/Au.k.spd"
expect "spd: a k file without its eta file" "$t/spd/Au.k.spd" ': a k file needs its n beside it'
awk '/^[0-9]/ { printf "%g %s\n", $1 / 1000, $2; next } { print }' "$I/Au.eta.spd" >"$t/spd/um.spd"
expect "spd: wavelengths in um (wrong unit)" "$t/spd/um.spd" ':[0-9]+: the table covers .*look like micrometres'
cp "$I/Au.eta.spd" "$t/spd/Au.eta.spd"
rm "$t/spd/Au.k.spd"
"$F" params --nk "$t/spd/Au.eta.spd" 2>"$t/err" >/dev/null && grep -q "warning: no Au.k.spd beside it; k = 0" "$t/err" &&
    pass "spd: an eta file alone is read with k = 0 and a warning" || fail "spd eta alone: $(head -1 "$t/err")"

e=$t/empty.yml
: >"$e"
expect "an empty file" "$e" ':1: expected n,k data, the file is empty'
printf 'what is this\n' >"$e"
expect "a file of no known format" "$e" ":1: cannot tell the format from 'what is this'"
printf 'DATA:\n\0\n' >"$e"
expect "a NUL byte" "$e" ':2: expected text, found a NUL byte'
expect "a format that does not match the file (--format sopra on YAML)" "$au" ':1: expected the SOPRA header' --format sopra
"$F" import "$t/none.yml" -o "$t/out.csv" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && grep -q "none.yml: cannot open" "$t/err" && pass "a missing file: exit 2, named" || fail "missing file: rc $rc"
"$F" import "$au" -o "$au" 2>"$t/err"
[ $? -eq 2 ] && grep -q "is an input of this command" "$t/err" && pass "import refuses to overwrite its input" || fail "import over its input"
"$F" import "$au" --format yaml -o "$t/x.csv" 2>"$t/err"
grep -q "unknown format 'yaml'" "$t/err" && pass "an unknown --format is named ($(head -1 "$t/err" | cut -c1-80))" || fail "unknown --format: $(head -1 "$t/err")"

# ---- converted values: a finite number in the file can overflow in nm
printf 'wl,n\n0.4,1.5\n1e306,1.6\n' >"$t/huge.csv"
expect "CSV export: a wavelength of 1e306 um (inf nm)" "$t/huge.csv" ':3: the wavelength converts to inf nm, expected a finite number of nm'
printf '1 1e-320 3 2\n1.5 0\n1.5 0\n1.5 0\n' >"$t/tiny.nk"
expect "SOPRA: an energy of 1e-320 eV (inf nm)" "$t/tiny.nk" ':2: the wavelength converts to inf nm'
printf 'DATA:\n  - type: tabulated nk\n    data: |\n        0.4 1.5 0\n        1e306 1.6 0\n' >"$t/huge.yml"
expect "YAML: a wavelength of 1e306 um (inf nm)" "$t/huge.yml" ':5: the wavelength converts to inf nm'
for route in "params --nk $t/huge.csv" "curve --nk $t/huge.csv --samples 3"; do
    "$F" $route >/dev/null 2>"$t/err"
    rc=$?
    [ "$rc" -eq 2 ] && grep -q 'huge.csv:3: the wavelength converts to inf nm' "$t/err" &&
        pass "${route%% *} --nk refuses the file import refuses" || fail "${route%% *} --nk huge.csv: exit $rc $(head -1 "$t/err")"
done
printf 'material h = huge.csv\nmodels = schlick\n' >"$t/huge.scene"
"$F" gen "$t/huge.scene" -o "$t/huge.h" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$t/huge.h" ] && grep -q 'huge.csv:3: the wavelength converts to inf nm' "$t/err" &&
    pass "gen refuses a manifest's file with an infinite wavelength" || fail "gen huge.csv: exit $rc $(head -1 "$t/err")"
# SOPRA's unit and intervals are range-checked as numbers (an int conversion
# of 1e300 is undefined behaviour, which the sanitizer pass would report)
printf '1e300 1.4 3.6 2\n1 0\n1 0\n1 0\n' >"$s"
expect "SOPRA: a unit code of 1e300" "$s" ':1: expected unit code 1 \(eV\), 2 \(um\) or 4 \(nm\), got 1e\+300' --format sopra
printf '1 1.4 3.6 1e300\n1 0\n1 0\n1 0\n' >"$s"
expect "SOPRA: 1e300 intervals" "$s" ':1: expected a whole number of intervals in 1..100000, got 1e\+300'
printf '1 1.4 3.6 -1e300\n1 0\n' >"$s"
expect "SOPRA: -1e300 intervals" "$s" ':1: expected a whole number of intervals in 1..100000, got -1e\+300' --format sopra

# ---- .spd: several pairs to a line, a comment after the first pair
awk '/^[0-9]/ { printf "%s %s ", $1, $2; if (++n % 3 == 0) print ""; next } { print }' "$I/Au.eta.spd" >"$t/spd/multi.eta.spd"
awk '/^[0-9]/ { printf "%s %s ", $1, $2; if (++n % 2 == 0) print ""; next } { print }' "$I/Au.k.spd" >"$t/spd/multi.k.spd"
accept ".spd with three pairs to a line (told as spd)" "$t/spd/multi.eta.spd" "$I/Au.eta.spd"
grep -v '^#' "$I/Au.eta.spd" | sed '1s/$/ # first pair/' >"$t/spd/c.eta.spd"
cp "$I/Au.k.spd" "$t/spd/c.k.spd"
accept ".spd whose first line ends in a comment" "$t/spd/c.eta.spd" "$I/Au.eta.spd"
printf '400,1.5,0.1\n500,1.5,0.1\n' >"$e"
expect "data rows without their header (not taken for .spd)" "$e" ":1: cannot tell the format from '400,1.5,0.1'"

# ---- classic Mac OS line ends (CR alone): named, at the first one
tr '\n' '\r' <"$I/Au.eta.spd" >"$t/spd/cr.eta.spd"
expect ".spd with CR-only line ends" "$t/spd/cr.eta.spd" ':1: expected lines ending in LF or CR LF, found a CR alone'
tr '\n' '\r' <"$I/Au-Johnson.reference.csv" >"$t/cr.csv"
expect "the data pack's CSV with CR-only line ends" "$t/cr.csv" ':1: expected lines ending in LF or CR LF, found a CR alone' --format csv
tr '\n' '\r' <"$au" >"$t/cr.yml"
expect "YAML with CR-only line ends" "$t/cr.yml" ':1: expected lines ending in LF or CR LF, found a CR alone'

# ---- no output replaces a file the command reads, the implicit half of a .spd pair included
cp "$I/Au.eta.spd" "$I/Au.k.spd" "$t/spd/"
for pair in Au.k.spd:Au.eta.spd Au.eta.spd:Au.k.spd Au.k.spd:Au.k.spd; do
    in=${pair%%:*} out=${pair##*:}
    "$F" import "$t/spd/$in" -o "$t/spd/$out" 2>"$t/err"
    rc=$?
    if [ "$rc" -eq 2 ] && cmp -s "$t/spd/$out" "$I/$out" && grep -q "spd/$out: is .*an input of this command" "$t/err"; then
        pass "import $in -o $out: refused, exit 2, $out untouched"
    else fail "import $in -o $out: exit $rc, $(cmp "$t/spd/$out" "$I/$out" 2>&1) $(head -1 "$t/err")"; fi
done
printf 'material tin = nk/TiN.yml\nmodels = schlick\n' >"$t/project/self.scene"
cp "$t/project/nk/TiN.yml" "$t/tin.keep"
"$F" gen "$t/project/self.scene" -o "$t/project/nk/TiN.yml" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && cmp -s "$t/project/nk/TiN.yml" "$t/tin.keep" && grep -q 'an input of this command' "$t/err" &&
    pass "gen -o a material file of its manifest: refused, exit 2, untouched" || fail "gen -o material file: exit $rc $(head -1 "$t/err")"
cp data/materials.csv "$t/data/materials.keep" 2>/dev/null
cp "$t/data/materials.csv" "$t/data/materials.keep"
"$F" gen "$t/project/coat.scene" --data "$t/data" -o "$t/data/materials.csv" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && cmp -s "$t/data/materials.csv" "$t/data/materials.keep" &&
    pass "gen -o a data-pack file it read: refused, exit 2, untouched" || fail "gen -o materials.csv: exit $rc $(head -1 "$t/err")"

# ---- a directory or an I/O error as the input is a read failure (exit 1),
# the same for every route; a FIFO never blocks; a device is refused
mkdir -p "$t/project/dir.yml"
printf 'material d = dir.yml\nmodels = schlick\n' >"$t/project/dir.scene"
printf 'material d = /proc/self/mem\nmodels = schlick\n' >"$t/project/mem.scene"
for route in "import $t/project/dir.yml -o $t/o.csv" "params --nk $t/project/dir.yml" "gen $t/project/dir.scene -o $t/o.h" \
    "gen $t/project -o $t/o.h" "import /proc/self/mem -o $t/o.csv" "params --nk /proc/self/mem" "gen $t/project/mem.scene -o $t/o.h"; do
    "$F" $route >/dev/null 2>"$t/err"
    rc=$?
    [ "$rc" -eq 1 ] && grep -q 'cannot read: \(Is a directory\|Input/output error\)' "$t/err" && [ ! -e "$t/o.csv" ] && [ ! -e "$t/o.h" ] &&
        pass "fresnel $(echo "$route" | sed "s|$t/||g"): exit 1 ($(head -1 "$t/err" | sed "s|$t/||"))" ||
        fail "fresnel $(echo "$route" | sed "s|$t/||g"): exit $rc $(head -1 "$t/err")"
done
mkfifo "$t/project/fifo.yml"
printf 'material f = fifo.yml\nmodels = schlick\n' >"$t/project/fifo.scene"
for route in "gen $t/project/fifo.scene -o $t/o.h" "import $t/project/fifo.yml -o $t/o.csv" "gen $t/project/fifo.yml -o $t/o.h"; do
    timeout 20 "$F" $route >/dev/null 2>"$t/err"
    rc=$?
    [ "$rc" -eq 2 ] && grep -q 'fifo.yml' "$t/err" && [ ! -e "$t/o.h" ] &&
        pass "a FIFO with no writer does not block: fresnel ${route%% *} exits 2 ($(head -1 "$t/err" | sed "s|$t/||"))" ||
        fail "FIFO: fresnel $(echo "$route" | sed "s|$t/||g"): exit $rc (124: blocked) $(head -1 "$t/err")"
done
if cat "$au" | "$F" import /dev/stdin -o "$t/o.csv" 2>"$t/err" && [ -s "$t/o.csv" ]; then pass "import /dev/stdin reads a pipe"
else fail "import /dev/stdin from a pipe: $(head -1 "$t/err")"; fi
rm -f "$t/o.csv"
"$F" import /dev/zero -o "$t/o.csv" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && grep -q 'expected a regular file or a pipe, got a character device' "$t/err" &&
    pass "a device as input: exit 2 ($(head -1 "$t/err"))" || fail "import /dev/zero: exit $rc $(head -1 "$t/err")"

# ---- out of memory is exit 3 on every route: a 15 MB file (read whole)
# under a 25 MB address-space limit
# (a sanitizer build reserves more address space than that at startup: skipped)
if ! (ulimit -v 25000; "$F" --version) >/dev/null 2>&1; then
    echo "NOTE this build does not start under ulimit -v 25000 (sanitizers?): out-of-memory status not tested"
else
    { cat "$au"; head -c 15000000 /dev/zero | tr '\0' '#' | fold -w 1000 | sed 's/^/# /'; } >"$t/project/big.yml"
    printf 'material b = big.yml\nmodels = schlick\n' >"$t/project/big.scene"
    for route in "import $t/project/big.yml -o $t/o.csv" "params --nk $t/project/big.yml" "gen $t/project/big.scene -o $t/o.h"; do
        (ulimit -v 25000; "$F" $route) >/dev/null 2>"$t/err"
        rc=$?
        [ "$rc" -eq 3 ] && grep -q 'out of memory' "$t/err" && [ ! -e "$t/o.h" ] && [ ! -e "$t/o.csv" ] &&
            pass "out of memory: fresnel ${route%% *} exits 3 ($(head -1 "$t/err" | sed "s|$t/||"))" ||
            fail "out of memory: fresnel $(echo "$route" | sed "s|$t/||g"): exit $rc $(head -1 "$t/err")"
    done
fi
