#!/bin/sh
# passes: first (Chromium runs the same page in every pass; the tool that writes it:
# tests/tool/test_cli_viewer.sh)
# make check: no (headless Chromium)
# start: early (two browsers for minutes)
# The page of `fresnel viewer` (gen/viewer/) in a real browser engine:
# headless Chromium with software GL (SwiftShader), no display.
# - the page loads with no console message, requests nothing (its own count
#   of resource entries), and its test hook (#test) renders every material x
#   model of the viewer's scene (data/scenes/viewer.scene), and the spectral
#   reference, at the cosines of theta = 0, 0.5, ..., 90 degrees into a float
#   framebuffer and prints the pixels;
# - each pixel equals the C runtime's value (`fresnel curve`, binary32) within
#   1e-6 for the models (the GLSL port's functions on the constants `fresnel
#   gen --glsl` emits) and 2e-6 for the reference (the page's 1024-node table
#   of the unclipped truth, linear in sqrt(c));
# - lit pixels (camera, normal, lights, distribution and Fresnel) at 8 image
#   positions equal tests/shader_ports/viewer_lit.c's host shading with the C runtime's
#   Fresnel within 1e-3 relative (binary32 on the GPU against double: the
#   Blinn-Phong exponent 510 at roughness 0.25 magnifies n.h's rounding);
# - a screenshot per view (each material, both distributions, split,
#   difference, CIEDE2000 per pixel) goes to $BUILD/viewer/, made by the
#   page's test hook from its canvas in the same browser run.
# - the same page in WebGL 1 (#webgl1): the probes read back as floats where
#   the browser offers WEBGL_color_buffer_float (within 2.5e-5: the LUTs'
#   16-bit texture nodes), else as bytes (4e-3: WebGL 1 promises no float
#   render target).
# - a scene with a thin film (gold and copper under a 1.38 film, F82 beside
#   it), in WebGL 2 and in WebGL 1: the page's film at its starting thickness (the slider's) and the
#   film's reference (a 128-node table per slider step) against `fresnel
#   curve --film` (1e-5, the film's cos and sin the C runtime's polynomials;
#   2e-3: the reference table's interpolation), the lit probes against
#   tests/shader_ports/viewer_lit.c (WebGL 2), and a screenshot; the film's
#   two peers, shown in its place, against their binary32 C transcriptions
#   (5e-5: they take SwiftShader's sin, cos and exp). A page of its own: a
#   scene of its own.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
pass() { echo "PASS viewer: $1"; }
fail() { echo "FAIL viewer: $1"; }
out="$BUILD/viewer"
if ! "$F" viewer data/scenes/viewer.scene -o "$out" 2>"$t/err"; then
    fail "fresnel viewer on the viewer's scene: $(cat "$t/err")"
    exit 0
fi
page="$out/index.html"
if ! command -v chromium >/dev/null 2>&1; then
    fail "chromium not found (tests/deps.sh installs it)"
    exit 0
fi
rm -f "$out"/*.png
# browse LOG ARGS...: chromium with its own home and profile. The timeout
# only ends a hung browser: a loaded machine takes many minutes.
browse() {
    log=$1
    shift
    HOME="$log.home" timeout 1800 chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
        --no-first-run --disable-extensions --enable-logging=stderr --v=0 --user-data-dir="$log.profile" \
        --virtual-time-budget=30000 "$@" 2>"$log"
}
abs=$(cd "$out" && pwd)/index.html
# WebGL 2 and the WebGL 1 fallback (#webgl1, below) in two browsers at once
browse "$t/log" --dump-dom "file://$abs#test" >"$t/page" &
browse "$t/log1" --dump-dom "file://$abs#test&webgl1" >"$t/page1" &
wait
# the test hook's lines: the text of <pre id="test-result">
sed -n '/<pre id="test-result">/,/<\/pre>/p' "$t/page" | sed 's/.*<pre id="test-result">//; s/<\/pre>.*//' >"$t/dom"
if grep -q '^DONE$' "$t/dom" && ! grep -q '^ERROR' "$t/dom"; then
    pass "the page renders its probes in Chromium (WebGL 2 on SwiftShader)"
else
    fail "the page did not finish: $(grep ERROR "$t/dom" | head -3) $(grep CONSOLE "$t/log" | head -3)"
    exit 0
fi
if grep -q 'CONSOLE' "$t/log"; then
    fail "console messages: $(grep CONSOLE "$t/log" | head -3)"
else
    pass "no console message while loading and rendering"
fi
grep -q '^RESOURCES 0$' "$t/dom" && pass "no network request (the page's resource entries: 0)" ||
    fail "resources fetched: $(grep '^RESOURCES' "$t/dom")"

models=$(awk -F= '/^models/ { sub(/#.*/, "", $2); print $2 }' data/scenes/viewer.scene)
materials=$(awk -F= '/^materials/ { sub(/#.*/, "", $2); print $2 }' data/scenes/viewer.scene)
for m in $materials; do
    "$F" curve --material "$m" --models "$models" --samples 181 >"$t/$m.csv" || fail "fresnel curve --material $m"
done
# compare DOM MODEL_TOL REFERENCE_TOL CLAMP [FILM_TOL FILM_REF_TOL]: every
# PROBE line of DOM against the C runtime's curve (CLAMP 1: the C value held
# to [0, 1], as an 8-bit read-back holds it; with a film, its rows too);
# prints the worst per material and model, and "over" or "missing" on a
# failure.
compare() {
    rows=$(($(echo "$models" | wc -w) + 1))
    [ -n "${5:-}" ] && rows=$((rows + 1)) # the film's reference
    for m in $materials; do
        grep "^PROBE $m " "$1" >"$t/$m.probe"
        awk -F, -v mat="$m" -v tm="$2" -v tr="$3" -v cl="$4" -v tf="${5:-0}" -v tfr="${6:-0}" -v want="$rows" '
            NR == FNR { if (FNR == 1) { for (i = 1; i <= NF; i++) col[$i] = i; next } row[$1 + 0] = $0; next }
            { split($0, p, " "); model = p[3]; split(row[p[4] + 0], c, ","); base = model == "reference" ? "unclipped" : model
              n[model]++
              for (ch = 0; ch < 3; ch++) { k = col[base "_" substr("rgb", ch + 1, 1)]
                  if (!k) { print "missing column " base; exit }
                  v = c[k]; if (cl && v > 1) v = 1
                  d = p[5 + ch] - v; if (d < 0) d = -d; if (d > w[model]) w[model] = d } }
            END { rows = 0
                  for (model in w) { rows++
                      tol = model == "thin-film" ? tf : (model == "film-reference" ? tfr : (model == "reference" ? tr : tm))
                      printf "%s %s %.3g%s; ", mat, model, w[model], (w[model] <= tol && n[model] == 181) ? "" : " over" }
                  if (rows != want) printf "missing rows (%d of %d); ", rows, want }' "$t/$m.csv" "$t/$m.probe"
    done
}
worst=$(compare "$t/dom" 1e-6 2e-6 0)
echo "NOTE viewer: largest |page - C runtime| per material and model: $worst"
echo "$worst" | grep -q 'over\|missing' &&
    fail "page and C runtime differ: $(echo "$worst" | tr ';' '\n' | grep 'over\|missing' | head -5)" ||
    pass "every model of every material, and the reference, at 181 angles: the page's pixels equal the C runtime within 1e-6 (reference 2e-6)"

lit=$(grep '^LIT ' "$t/dom" | "$BUILD/tests/viewer_lit" data/scenes/viewer.scene)
expect=$(($(echo "$materials" | wc -w) * ($(echo "$models" | wc -w) + 1) * 8 * 2 * 3))
echo "NOTE viewer: lit probes, largest |page - host| / max(|host|, 0.01), values compared, unknown rows: $lit"
echo "$lit" | awk -v n="$expect" '{ exit !($1 <= 1e-3 && $2 == n && $3 == 0) }' &&
    pass "lit pixels (8 positions on the sphere, the plate and the sky x every row x GGX and Blinn-Phong) equal the host's shading with the C runtime's Fresnel within 1e-3 relative" ||
    fail "lit probes: $lit"

shots=0
grep '^SHOT ' "$t/dom" | while read -r tag name data; do
    printf '%s' "${data#data:image/png;base64,}" | base64 -d >"$out/$name.png" 2>/dev/null
done
for png in "$out"/*.png; do
    [ -f "$png" ] && [ "$(wc -c <"$png")" -gt 20000 ] && [ "$(head -c 4 "$png" | od -An -tx1 | tr -d ' ')" = 89504e47 ] &&
        shots=$((shots + 1))
done
[ "$shots" -ge 7 ] && pass "$shots screenshots in $out/ (one per view, PNG from the page's canvas)" ||
    fail "$shots of 7 screenshots written"

# webgl1_page PAGE LOG WHAT [film]: a page run with #webgl1 (the port's GLSL
# ES 1.00 dialect, the LUTs from their packed texture, the film's table by
# texture2D at texel centres, one program per material): it finishes with
# no console message, and its probes equal the C runtime. Its read-back is
# float where the browser offers WEBGL_color_buffer_float (the models within
# 2.5e-5: the LUTs' 16-bit texture nodes, 1.25 * 2^-16; the reference 2e-6;
# the film 1e-5 and its reference 2e-3, as in WebGL 2), else 8-bit (4e-3,
# its 1/255, the C values held to [0, 1]).
webgl1_page() {
    dom=$1.dom
    sed -n '/<pre id="test-result">/,/<\/pre>/p' "$1" | sed 's/.*<pre id="test-result">//; s/<\/pre>.*//' >"$dom"
    if grep -q '^CONTEXT webgl1$' "$dom" && grep -q '^DONE$' "$dom" && ! grep -q '^ERROR' "$dom" && ! grep -q CONSOLE "$2"; then
        pass "$3 in WebGL 1 renders its probes with no console message"
    else
        fail "$3 in WebGL 1: $(grep -E '^(CONTEXT|ERROR)' "$dom" | head -2) $(grep CONSOLE "$2" | head -2)"
    fi
    if grep -q '^READBACK float$' "$dom"; then
        tol="2.5e-5 2e-6 0${4:+ 1e-5 2e-3}" how="float read-back: models within 2.5e-5, the reference 2e-6${4:+, the film 1e-5, its reference 2e-3}"
    else
        tol="4e-3 4e-3 1${4:+ 4e-3 4e-3}" how="8-bit read-back: within 4e-3"
    fi
    worst1=$(compare "$dom" $tol)
    echo "NOTE viewer: $3 in WebGL 1, largest |page - C runtime| ($how): $worst1"
    echo "$worst1" | grep -q 'over\|missing' &&
        fail "$3 in WebGL 1 and the C runtime differ: $(echo "$worst1" | tr ';' '\n' | grep 'over\|missing' | head -5)" ||
        pass "$3 in WebGL 1: every model of every material and the reference equal the C runtime at 181 angles ($how)"
}
webgl1_page "$t/page1" "$t/log1" "the viewer's page"

# The thin film's page: its own scene, the slider's starting thickness (the
# page's FILM line), curve --film for the film's columns.
printf 'materials = au cu\nmodels = f82 thin-film\nfilm = 1.38\nfilm_thickness = 0 1000\n' >"$t/film.scene"
if ! "$F" viewer "$t/film.scene" -o "$out/film" 2>"$t/err"; then
    fail "fresnel viewer on a scene with a thin film: $(cat "$t/err")"
    exit 0
fi
grep -q 'id="film"' "$out/film/index.html" && pass "the film's page has the thickness slider" ||
    fail "no thickness slider in the film's page"
abs=$(cd "$out/film" && pwd)/index.html
browse "$t/logf" --dump-dom "file://$abs#test" >"$t/pagef" &
browse "$t/logf1" --dump-dom "file://$abs#test&webgl1" >"$t/pagef1" &
wait
sed -n '/<pre id="test-result">/,/<\/pre>/p' "$t/pagef" | sed 's/.*<pre id="test-result">//; s/<\/pre>.*//' >"$t/domf"
if grep -q '^DONE$' "$t/domf" && ! grep -q '^ERROR' "$t/domf" && ! grep -q CONSOLE "$t/logf"; then
    pass "the film's page renders its probes with no console message"
else
    fail "the film's page: $(grep ERROR "$t/domf" | head -2) $(grep CONSOLE "$t/logf" | head -2)"
    exit 0
fi
materials="au cu" models="f82 thin-film"
film_d=$(sed -n 's/^FILM //p' "$t/domf")
for m in $materials; do
    "$F" curve --material "$m" --models f82 --samples 181 >"$t/$m.bare.csv" &&
        "$F" curve --material "$m" --film "1.38:$film_d" --samples 181 >"$t/$m.film.csv" ||
        fail "fresnel curve --material $m (--film 1.38:$film_d)"
    sed '1s/unclipped_/film-reference_/g' "$t/$m.film.csv" | cut -d, -f6-11 | paste -d, "$t/$m.bare.csv" - >"$t/$m.csv"
done
worstf=$(compare "$t/domf" 1e-6 2e-6 0 1e-5 2e-3)
echo "NOTE viewer: thin film at $film_d nm, largest |page - C runtime| per material and model: $worstf"
echo "$worstf" | grep -q 'over\|missing' &&
    fail "the film's page and the C runtime differ: $(echo "$worstf" | tr ';' '\n' | grep 'over\|missing' | head -5)" ||
    pass "the thin film at $film_d nm and its reference, F82 and the reference, at 181 angles: within 1e-5, 2e-3, 1e-6 and 2e-6 of the C runtime"
lit=$(grep '^LIT ' "$t/domf" | "$BUILD/tests/viewer_lit" "$t/film.scene")
echo "NOTE viewer: thin film, lit probes: $lit"
echo "$lit" | awk -v n=$((2 * 4 * 8 * 2 * 3)) '{ exit !($1 <= 1e-3 && $2 == n && $3 == 0) }' &&
    pass "the film's lit pixels equal the host's shading within 1e-3 relative" || fail "the film's lit probes: $lit"
# the film's peers in its place (the page's GLSL of KHR_materials_iridescence
# and of the polarised form) against their binary32 C transcriptions
peers=$(grep '^PEER ' "$t/domf" | "$BUILD/tests/viewer_lit" --peers "$t/film.scene")
echo "NOTE viewer: the film's peers at $film_d nm, largest |page - C| over values: $peers"
echo "$peers" | awk -v n=$((2 * 2 * 181 * 3)) '{ exit !($1 <= 5e-5 && $2 == n && $3 == 0) }' &&
    pass "the film's peers (KHR_materials_iridescence, polarised) at 181 angles within 5e-5 of their C transcriptions" ||
    fail "the film's peers: $peers"
webgl1_page "$t/pagef1" "$t/logf1" "the thin film's page at $film_d nm" film
grep '^SHOT ' "$t/domf" | while read -r tag name data; do
    printf '%s' "${data#data:image/png;base64,}" | base64 -d >"$out/film-$name.png" 2>/dev/null
done
ls "$out"/film-*thin-film*.png >/dev/null 2>&1 && pass "a screenshot of the thin film in $out/" ||
    fail "no screenshot of the thin film"
