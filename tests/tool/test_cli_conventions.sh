#!/bin/sh
# Command-line conventions of the fresnel tool: version, names and their
# suggestions, option values, input quirks (BOM, NUL, control characters,
# subnormals), help text, quiet materials listing.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1"; }
# expect NAME STATUS STDERR-PATTERN args... (stdin from $t/in)
expect() {
    name=$1; want=$2; pat=$3; shift 3
    "$F" "$@" <"$t/in" >"$t/out" 2>"$t/err"; rc=$?
    if [ $rc -eq "$want" ] && grep -qE -e "$pat" "$t/err"; then
        pass "$name (exit $want: $(head -1 "$t/err"))"
    else
        fail "$name: exit $rc, stderr '$(cat "$t/err")'"
    fi
}
: >"$t/in"
v=$(sed -n 's/^#define FRESNEL_VERSION "\(.*\)"$/\1/p' include/fresnel.h)
[ -n "$v" ] && [ "$("$F" --version)" = "fresnel $v" ] && [ "$("$F" version)" = "fresnel $v" ] &&
    pass "--version and version print fresnel $v" || fail "version: '$("$F" --version 2>&1)' want '$v'"

# Suggestions for every kind of name.
expect "model suggestion" 2 "unknown model 'schlik' \(did you mean 'schlick'\?\)" eval --model schlik --type f32
expect "type suggestion" 2 "unknown type 'f23' \(did you mean 'f32'\?\)" eval --model exact --type f23
expect "subcommand suggestion" 2 "unknown command 'evl' \(did you mean 'eval'\?\)" evl
expect "option suggestion" 2 "unknown option '--materail' \(did you mean '--material'\?\)" params --materail au
expect "material suggestion" 2 "unknown material 'cuu' \(did you mean 'cu'\?\)" params --material cuu
expect "colour space suggestion" 2 "unknown colour space 'srbg' \(did you mean 'srgb'\?\)" wavelengths --space srbg
expect "bench type suggestion" 2 "unknown type 'q16' \(did you mean 'q15'\?\)" bench --type q16
expect "curve spacing suggestion" 2 "did you mean 'uniform'" curve --material au --lut-spacing unifrom

# Colour-space names: any case, common aliases.
ref=$("$F" wavelengths --space srgb)
for s in sRGB SRGB rec709 bt709 BT709; do
    [ "$("$F" wavelengths --space "$s" 2>&1)" = "$ref" ] && pass "space '$s' is srgb" || fail "space '$s'"
done
for pair in p3:display-p3 P3:display-p3 bt2020:rec2020 BT2020:rec2020 ACEScg:acescg Display-P3:display-p3; do
    a=${pair%%:*}; b=${pair#*:}
    [ "$("$F" wavelengths --space "$a" 2>&1)" = "$("$F" wavelengths --space "$b")" ] && pass "space '$a' is $b" ||
        fail "space '$a'"
done
"$F" params --material au --space ACEScg | grep -q '^# space acescg,' && pass "params names the canonical space" ||
    fail "params --space ACEScg header"

# q15 everywhere, fixed still accepted.
a=$(printf '1.5,0,1\n' | "$F" eval --model exact --type q15); b=$(printf '1.5,0,1\n' | "$F" eval --model exact --type fixed)
[ -n "$a" ] && [ "$a" = "$b" ] && pass "eval --type q15 = --type fixed ($a)" || fail "q15 '$a' fixed '$b'"
"$F" eval --help | grep -q 'f32|f64|q15|f16' && pass "eval --help names q15" || fail "eval --help type names"
"$F" eval --model exact 2>&1 | grep -q 'f32, q15.*f64' && pass "eval --type required names q15" ||
    fail "eval missing --type message"
mkdir "$t/a" "$t/b"
printf 'materials = au\nmodels = schlick\ntypes = fixed\n' >"$t/a/s.scene"
printf 'materials = au\nmodels = schlick\ntypes = q15\n' >"$t/b/s.scene"
"$F" gen "$t/a/s.scene" -o "$t/a/s.h" && "$F" gen "$t/b/s.scene" -o "$t/b/s.h" && cmp -s "$t/a/s.h" "$t/b/s.h" &&
    pass "a scene's types = fixed means q15 (identical header)" || fail "scene types = fixed"

# No option is taken for a value; a stray word is named as such.
expect "stray positional (params)" 2 "unexpected argument 'au'" params au
expect "stray positional (eval)" 2 "unexpected argument 'au'" eval au
expect "stray positional (curve)" 2 "unexpected argument 'au'" curve au
expect "stray positional (materials)" 2 "unexpected argument 'x'" materials x
expect "stray positional (extremes)" 2 "unexpected argument 'x'" extremes x
expect "option as value (params)" 2 "option '--material' needs a value" params --material --space srgb
expect "option as value (eval)" 2 "option '--model' needs a value" eval --model --type f32
expect "option as value (gen)" 2 "option '-o' needs a value" gen s.scene -o --glsl
expect "option as value (bench)" 2 "option '--scene' needs a value" bench --scene --count 5
expect "option as value (report)" 2 "option '-o' needs a value" report -o --no-timing
expect "option as value (accuracy)" 2 "option '--materials' needs a value" accuracy --materials --steps 5
expect "option as value (wavelengths)" 2 "option '--space' needs a value" wavelengths --space --data x
printf '1.5,0,1\n' >"$t/in"
"$F" eval --model exact --type f64 --f90 -1 <"$t/in" >/dev/null 2>&1 && pass "a negative number is a value (--f90 -1)" ||
    fail "--f90 -1 rejected"
: >"$t/in"

# Input quirks.
printf '\357\273\277eta,kappa,cos\n1.5,0,1\n' >"$t/in"
"$F" eval --model exact --type f64 <"$t/in" >"$t/out" 2>"$t/err" && [ "$(cat "$t/out")" = "$(printf '1.5,0,1\n' | "$F" eval --model exact --type f64)" ] &&
    pass "eval skips a UTF-8 BOM before the header" || fail "eval BOM: $(cat "$t/err")"
printf '\357\273\2771.5,0,1\n' >"$t/in"
"$F" eval --model exact --type f64 <"$t/in" >"$t/out" 2>"$t/err" && [ -s "$t/out" ] &&
    pass "eval skips a UTF-8 BOM before data" || fail "eval BOM before data: $(cat "$t/err")"
printf '\357\273\277materials = au\nmodels = schlick\n' >"$t/bom.scene"
"$F" gen "$t/bom.scene" -o "$t/bom.h" 2>"$t/err" && pass "gen skips a UTF-8 BOM in a manifest" || fail "manifest BOM: $(cat "$t/err")"
printf '1.5,0,1\n1.5,0\0001,0.5\n' >"$t/in"
expect "NUL inside an eval line is rejected with its line" 2 '^<stdin>:2: .*NUL' eval --model exact --type f32
[ ! -s "$t/out" ] && pass "NUL: nothing written" || fail "NUL: output '$(cat "$t/out")'"
printf '1.5,\033[2J\007,1\n' >"$t/in"
"$F" eval --model exact --type f32 <"$t/in" >/dev/null 2>"$t/err"
if grep -q "$(printf '\033')" "$t/err" || grep -q "$(printf '\007')" "$t/err"; then
    fail "control characters echoed raw: $(od -c "$t/err" | head -3)"
else
    grep -q '\\x1b\[2J\\x07' "$t/err" && pass "control characters in quoted input are escaped ($(cat "$t/err"))" ||
        fail "escaping: $(cat "$t/err")"
fi
printf 'materials = a\033]0;x\007u\nmodels = schlick\n' >"$t/esc.scene"
"$F" gen "$t/esc.scene" -o "$t/esc.h" 2>"$t/err"
! grep -q "$(printf '\033')" "$t/err" && grep -q '\\x1b' "$t/err" && pass "manifest errors escape control characters" ||
    fail "manifest escaping: $(od -c "$t/err" | head -3)"
: >"$t/in"
"$F" params --material "$(printf 'a\033[31mu')" 2>"$t/err"
! grep -q "$(printf '\033')" "$t/err" && pass "argument errors escape control characters" || fail "argv escaping"
"$F" eval --model "$(printf 'x\302\233[2Jy')" --type f32 2>"$t/err"
! grep -q "$(printf '\302\233')" "$t/err" && grep -q 'x\\u009b\[2Jy' "$t/err" &&
    pass "a C1 control (U+009B) is escaped too ($(cat "$t/err"))" || fail "C1 escaping: $(od -c "$t/err" | head -3)"
for x in 1e-310 -4.9e-324 2.2e-308; do
    printf '1.5,0,%s\n' "$x" >"$t/in"
    "$F" eval --model exact --type f64 <"$t/in" >"$t/out" 2>"$t/err" && pass "subnormal cos $x accepted ($(cat "$t/out"))" ||
        fail "subnormal $x: $(cat "$t/err")"
done
printf '1.5,0,1e999\n' >"$t/in"
expect "overflowing number still rejected" 2 'expected a finite number' eval --model exact --type f64
: >"$t/in"

# A manifest with several bad entries: every one reported at its line.
printf 'materials = au\nmodels = schlik\ntypes = f33\nspace = srbg\nsigam = 3\n' >"$t/bad.scene"
"$F" gen "$t/bad.scene" -o "$t/bad.h" 2>"$t/err"; rc=$?
[ $rc -eq 2 ] && grep -q "bad.scene:2: .*'schlik' (did you mean 'schlick'?)" "$t/err" &&
    grep -q "bad.scene:3: .*'f33' (did you mean 'f32'?)" "$t/err" && grep -q "bad.scene:4: .*'srbg'" "$t/err" &&
    grep -q "bad.scene:5: .*'sigam' (did you mean 'sigma'?)" "$t/err" && [ ! -e "$t/bad.h" ] &&
    pass "manifest: all 4 bad lines reported, each at its line" || fail "manifest errors: exit $rc $(cat "$t/err")"
printf 'materials = gld cuu au\nmodels = schlick\n' >"$t/mats.scene"
"$F" gen "$t/mats.scene" -o "$t/mats.h" 2>"$t/err"; rc=$?
[ $rc -eq 2 ] && grep -q "'gld'" "$t/err" && grep -q "'cuu' (did you mean 'cu'?)" "$t/err" &&
    pass "manifest: every unknown material reported" || fail "unknown materials: $(cat "$t/err")"
printf 'materials = au\nmodels = schlick\nspace = BT2020\n' >"$t/alias.scene"
printf 'materials = au\nmodels = schlick\nspace = rec2020\n' >"$t/canon.scene"
"$F" gen "$t/alias.scene" -o - | grep -v 'alias' >"$t/a.h"; "$F" gen "$t/canon.scene" -o - | grep -v canon >"$t/c.h"
grep -q rec2020 "$t/a.h" && pass "manifest: space = BT2020 is rec2020" || fail "manifest space alias"

# Help and user-facing text speak of the product (the wording of
# tests/repo/test_product_text.sh, which reads the sources).
history=$(sh tests/repo/test_product_text.sh --words)
for c in eval wavelengths materials gen params curve bench report extremes accuracy viewer import; do
    if "$F" "$c" --help 2>&1 | grep -qiE "$history"; then fail "$c --help tells of work history: $("$F" "$c" --help 2>&1 | grep -iE "$history" | head -1)"; else pass "$c --help: no work history"; fi
done
"$F" extremes | grep -qiE "$history" && fail "extremes output tells of work history" || pass "extremes output: no work history"

# Materials: the coverage warnings only with --verbose.
n=$("$F" materials 2>&1 >/dev/null | wc -l)
nv=$("$F" materials --verbose 2>&1 >/dev/null | grep -c warning)
[ "$n" -eq 0 ] && [ "$nv" -gt 0 ] && pass "materials: quiet by default, $nv coverage warnings with --verbose" ||
    fail "materials: $n lines on stderr by default, $nv with --verbose"

# Exit statuses documented.
"$F" --help | grep -q '3 out of memory' && pass "--help documents exit status 3 for out of memory" || fail "--help exit statuses"

# A report on a scene without metals never prints nan.
printf 'materials = bk7 water\nmodels = schlick\n' >"$t/dielectric.scene"
"$F" report --scene "$t/dielectric.scene" -o "$t/rep" --no-timing --no-instructions >/dev/null 2>"$t/err" &&
    ! grep -qiw nan "$t/rep/report.md" && grep -q 'no metals' "$t/rep/report.md" &&
    pass "report without metals: 'no metals', no nan" || fail "report without metals: $(grep -iw nan "$t/rep/report.md" | head -2) $(cat "$t/err")"
