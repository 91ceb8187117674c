#!/bin/sh
# passes: first (the page is the same in every pass)
# The viewer's page as a user first sees it, in headless Chromium with a
# 1280 x 800 window: it opens on the scene's own material (the first
# `material ID = FILE` line) rather than the data pack's first, unless the
# address names one (#material=ID); the curves lie inside the window, beside
# the picture; each curve panel has a labelled tick every 15 degrees (5 in
# the 70-90 degree zoom) and at least three reflectance ticks. Read through
# the page's #layout hook.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if ! command -v chromium >/dev/null 2>&1; then
    echo "FAIL viewer layout: chromium not found (tests/deps.sh installs it)"
    exit 0
fi
cp tests/data/import/TiN-Pfluger.yml "$t/TiN.yml"
printf 'materials = au cu\nmaterial tin = TiN.yml\nmodels = schlick f82\n' >"$t/coat.scene"
printf 'materials = au cu\nmodels = schlick f82\n' >"$t/pack.scene"
# layout SCENE HASH: the #layout hook's lines for SCENE's page opened at #layout&HASH
layout() {
    "$F" viewer "$1" -o "$t/page" 2>"$t/err" || { echo "ERROR fresnel viewer: $(cat "$t/err")"; return; }
    HOME="$t/home" timeout 300 chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
        --no-first-run --disable-extensions --user-data-dir="$t/profile" --window-size=1280,800 \
        --virtual-time-budget=20000 --dump-dom "file://$t/page/index.html#layout$2" 2>/dev/null |
        sed -n '/<pre id="test-result">/,/<\/pre>/p' | sed 's/.*<pre id="test-result">//; s/<\/pre>.*//'
}
layout "$t/coat.scene" "" >"$t/coat"
if ! grep -q '^DONE$' "$t/coat"; then
    echo "FAIL viewer layout: the page's #layout hook did not finish: $(head -3 "$t/coat")"
    exit 0
fi
grep -q '^START tin$' "$t/coat" && echo "PASS viewer opens on the scene's own material (tin, after au and cu)" ||
    echo "FAIL viewer opens on $(sed -n 's/^START //p' "$t/coat"), not the scene's own material tin"
layout "$t/coat.scene" "&material=cu" >"$t/named"
grep -q '^START cu$' "$t/named" && echo "PASS viewer: #material=cu in the address comes first" ||
    echo "FAIL viewer with #material=cu opens on $(sed -n 's/^START //p' "$t/named")"
layout "$t/pack.scene" "" >"$t/pack"
grep -q '^START au$' "$t/pack" && echo "PASS viewer: a scene of data-pack materials opens on its first (au)" ||
    echo "FAIL viewer: a data-pack scene opens on $(sed -n 's/^START //p' "$t/pack")"
read -r _ top bottom _ width height <<EOT
$(grep '^PLOT ' "$t/coat")
EOT
if [ -n "$bottom" ] && [ "$bottom" -le "$height" ]; then
    echo "PASS viewer: the curves lie inside a 1280 x 800 window (plot at y $top-$bottom, window ${width}x$height)"
else
    echo "FAIL viewer: the curves end at y $bottom, below the ${width}x$height window of a 1280 x 800 screen"
fi
read -r _ x0 y0 x1 y1 <<EOT
$(grep '^TICKS ' "$t/coat")
EOT
if [ "${x0:-0}" -eq 7 ] && [ "${x1:-0}" -eq 5 ] && [ "${y0:-0}" -ge 3 ] && [ "${y1:-0}" -ge 3 ]; then
    echo "PASS viewer: curve ticks every 15 degrees (7) and every 5 in the zoom (5), $y0 and $y1 reflectance ticks"
else
    echo "FAIL viewer: curve ticks $x0 $y0 (0-90) and $x1 $y1 (70-90)"
fi
