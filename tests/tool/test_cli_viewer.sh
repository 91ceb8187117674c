#!/bin/sh
# passes: all (the tool, sanitized in the sanitize pass, on bad input and the viewer's scene)
# `fresnel viewer` (gen/viewer/) without a browser: bad input (a missing
# manifest, a scene the GLSL port cannot express) exits 2 with a message
# and writes no page, leaving an existing page as it was; the page of the
# viewer's scene is one file naming no network resource. The page in
# Chromium: tests/shader_ports/test_viewer.sh.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
pass() { echo "PASS viewer: $1"; }
fail() { echo "FAIL viewer: $1"; }

"$F" viewer "$t/missing.scene" -o "$t/out" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$t/out/index.html" ] && grep -q 'missing.scene' "$t/err" &&
    pass "a missing manifest: exit 2, no page ($(head -1 "$t/err" | sed "s|$t/||"))" ||
    fail "missing manifest: exit $rc, $(cat "$t/err")"
printf 'materials = au\nmodels = lut16\ntypes = q15\nlut_spacing = grazing-pl\n' >"$t/pl.scene"
mkdir -p "$t/keep"
echo old >"$t/keep/index.html"
"$F" viewer "$t/pl.scene" -o "$t/keep" 2>"$t/err"
rc=$?
[ "$rc" -eq 2 ] && [ "$(cat "$t/keep/index.html")" = old ] && grep -q 'pl.scene:4' "$t/err" &&
    [ -z "$(ls "$t/keep" | grep -v '^index.html$')" ] &&
    pass "a scene the GLSL port cannot express: exit 2 at its line, the page already there untouched, no temporary ($(head -1 "$t/err" | sed "s|$t/||"))" ||
    fail "grazing-pl scene: exit $rc, $(cat "$t/err")"

# A failed page leaves no directory behind; -o - is the page on stdout.
printf 'materials = au\nmodels = schlick\n' >"$t/au.scene"
(ulimit -f 100; "$F" viewer "$t/au.scene" -o "$t/new") 2>"$t/err"
rc=$?
[ "$rc" -eq 1 ] && [ ! -e "$t/new" ] && pass "a page over ulimit -f: exit 1, no new directory left" ||
    fail "a page over ulimit -f: exit $rc, $(ls -a "$t/new" 2>&1 | tr '\n' ' ')"
abs=$(cd "$(dirname "$F")" && pwd)/fresnel
(cd "$t" && "$abs" viewer au.scene -o - >page.html 2>err)
rc=$?
[ "$rc" -eq 0 ] && [ ! -e "$t/-" ] && head -1 "$t/page.html" | grep -qi '<!doctype html' &&
    pass "viewer -o - writes the page to stdout, no directory '-'" || fail "viewer -o -: exit $rc, $(ls -d "$t/-" 2>&1) $(cat "$t/err")"

# Names enter the page escaped for where they land: a file name that opens
# an HTML comment and a script, a control character, U+2028, and a
# materials.csv name that closes the script element.
cp tests/data/import/Au-Johnson.yml "$t/<!--<script>.yml"
cp tests/data/import/Au-Johnson.yml "$t/$(printf 'c\001x\342\200\250.yml')"
printf 'material sc = <!--<script>.yml\nmaterial cx = c\001x\342\200\250.yml\nmaterials = au\nmodels = schlick lut16\n' >"$t/names.scene"
cp -r data "$t/data"
sed -i 's|^au,Gold Au,|au,Gold </script><script>alert(1)</script> \& "q",|' "$t/data/materials.csv"
if "$F" viewer "$t/names.scene" --data "$t/data" -o "$t/names" 2>"$t/err"; then
    tag_counts() { grep -oi '<script\|</script\|<!--' "$1" | tr A-Z a-z | sort | uniq -c | tr -s ' \n' ' '; }
    want='"materials":[{"id":"sc","name":"\u003c!--\u003cscript\u003e.yml"},{"id":"cx","name":"c\u0001x\u2028.yml"},{"id":"au","name":"Gold \u003c/script\u003e\u003cscript\u003ealert(1)\u003c/script\u003e \u0026 \"q\""}],'
    if [ "$(tag_counts "$t/names/index.html")" = "$(tag_counts ports/webgl/viewer.html)" ] &&
        grep -qxF -e "$want" "$t/names/index.html"; then
        pass "hostile names are escaped: the page's script and comment tags are the template's, the names JSON-escaped"
    else
        fail "hostile names: tags $(tag_counts "$t/names/index.html") (template $(tag_counts ports/webgl/viewer.html)); $(grep -a '"materials":' "$t/names/index.html" | head -c 300)"
    fi
else fail "viewer with hostile names: $(cat "$t/err")"; fi

out="$t/page"
if ! "$F" viewer data/scenes/viewer.scene -o "$out" 2>"$t/err"; then
    fail "fresnel viewer on the viewer's scene: $(cat "$t/err")"
    exit 0
fi
page="$out/index.html"
if grep -qiE '(src|href)=["'"'"']?(https?:|//)|https?://' "$page"; then
    fail "the page names a network resource: $(grep -oiE '(src|href)=.{0,40}|https?://[^ ]{0,40}' "$page" | head -3)"
else
    pass "the page is one self-contained file ($(wc -c <"$page") bytes) naming no network resource"
fi
