#!/bin/sh
# passes: all (the tool, sanitized in the sanitize pass, on bad input and the viewer's scene)
# `fresnel viewer` (gen/viewer/) without a browser: bad input (a missing
# manifest, a scene the GLSL port cannot express) exits 2 with a message
# and writes no page, leaving an existing page as it was; the page of the
# viewer's scene is one file naming no network resource. The page in
# Chromium: tests/test_viewer.sh.
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
    pass "a scene the GLSL port cannot express: exit 2 at its line, the old page untouched, no temporary ($(head -1 "$t/err" | sed "s|$t/||"))" ||
    fail "grazing-pl scene: exit $rc, $(cat "$t/err")"

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
