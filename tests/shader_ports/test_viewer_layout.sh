#!/bin/sh
# passes: first (the page is the same in every pass)
# make check: no (headless Chromium)
# The viewer's page as a user first sees it, in headless Chromium. With a
# 1280 x 800 window: it opens on the scene's own material (the first
# `material ID = FILE` line) rather than the data pack's first, unless the
# address names one (#material=ID), and on the thin film when the scene has
# one; the curves lie inside the window, beside the picture; each curve
# panel has a labelled tick every 15 degrees (5 in the 70-90 degree zoom)
# and at least three reflectance ticks. At a phone's 360 x 740 with a touch
# screen's coarse pointer (in a frame: headless Chromium's window is at
# least 500 px wide), a laptop's 1280 x 800 and a desktop's 2560 x 1440: no
# element reaches past the window's width (a box that scrolls sideways on
# its own counts as its box), the page does not scroll sideways, a drag on
# the picture is the page's (touch-action none); on the phone every control
# is at least 44 px tall. Read through the page's #layout hook; each size's
# screenshot is written to $BUILD/viewer-screens/ (ports/webgl/README.md,
# "Screenshots", is this recipe).
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
printf 'materials = au cu\nmodels = schlick f82 thin-film\nfilm = 1.38\nfilm_thickness = 100 600\n' >"$t/film.scene"
CHROMIUM="chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --no-first-run
    --disable-extensions --virtual-time-budget=20000"
# layout SCENE HASH: the #layout hook's lines for SCENE's page opened at #layout&HASH
layout() {
    "$F" viewer "$1" -o "$t/page" 2>"$t/err" || { echo "ERROR fresnel viewer: $(cat "$t/err")"; return; }
    # shellcheck disable=SC2086
    HOME="$t/home" timeout 300 $CHROMIUM --user-data-dir="$(mktemp -d "$t/profile.XXXXXX")" --window-size=${3:-1280,800} $4 \
        --dump-dom "file://$t/page/index.html#layout$2" 2>/dev/null |
        sed -n '/<pre id="test-result">/,/<\/pre>/p' | sed 's/.*<pre id="test-result">//; s/<\/pre>.*//'
}
layout "$t/coat.scene" "" >"$t/coat"
if ! grep -q '^DONE$' "$t/coat"; then
    echo "FAIL viewer layout: the page's #layout hook did not finish: $(head -3 "$t/coat")"
    exit 0
fi
grep -q '^START tin ' "$t/coat" && echo "PASS viewer opens on the scene's own material (tin, after au and cu)" ||
    echo "FAIL viewer opens on $(sed -n 's/^START //p' "$t/coat"), not the scene's own material tin"
layout "$t/coat.scene" "&material=cu" >"$t/named"
grep -q '^START cu ' "$t/named" && echo "PASS viewer: #material=cu in the address comes first" ||
    echo "FAIL viewer with #material=cu opens on $(sed -n 's/^START //p' "$t/named")"
layout "$t/pack.scene" "" >"$t/pack"
grep -q '^START au schlick$' "$t/pack" && echo "PASS viewer: a scene of data-pack materials opens on its first (au), with its first model" ||
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

# ---- the film scene opens on the film; three window sizes ----
layout "$t/film.scene" "" >"$t/film"
grep -q '^START au thin-film$' "$t/film" && echo "PASS viewer: a thin-film scene opens on the film (au, thin-film)" ||
    echo "FAIL viewer: a thin-film scene opens on $(sed -n 's/^START //p' "$t/film"), not the thin film"
mkdir -p "$BUILD/viewer-screens"
# the phone: the page in a 360 x 740 frame, its hook's lines posted to the frame's page
cat >"$t/page/phone.html" <<'EOT'
<!DOCTYPE html><html><body style="margin:0;background:#202124">
<iframe src="index.html#layout" style="width:360px;height:740px;border:0;display:block"></iframe>
<pre id="test-result"></pre>
<script>addEventListener("message", (e) => { document.getElementById("test-result").textContent = e.data; });</script>
</body></html>
EOT
coarse="--blink-settings=primaryPointerType=2,availablePointerTypes=2"
for size in phone laptop desktop; do
    case $size in
    phone) page=phone.html win=500,740 want=360 flags=$coarse ;;
    laptop) page="index.html#layout" win=1280,800 want=1280 flags= ;;
    desktop) page="index.html#layout" win=2560,1440 want=2560 flags= ;;
    esac
    # shellcheck disable=SC2086
    HOME="$t/home" timeout 300 $CHROMIUM --user-data-dir="$(mktemp -d "$t/profile.XXXXXX")" --window-size=$win $flags \
        --dump-dom "file://$t/page/$page" 2>/dev/null | sed -n '/<pre id="test-result">/,/<\/pre>/p' |
        sed 's/.*<pre id="test-result">//; s/<\/pre>.*//' >"$t/$size"
    read -r _ _ _ _ width _ <<EOT
$(grep '^PLOT ' "$t/$size")
EOT
    read -r _ scroll client <<EOT
$(grep '^PAGE ' "$t/$size")
EOT
    read -r _ over what <<EOT
$(grep '^OVERFLOW ' "$t/$size")
EOT
    read -r _ is_coarse small which <<EOT
$(grep '^COARSE ' "$t/$size")
EOT
    touch_action=$(sed -n 's/^TOUCH //p' "$t/$size")
    if ! grep -q '^DONE$' "$t/$size"; then
        echo "FAIL viewer at $size size: the #layout hook did not finish: $(head -3 "$t/$size")"
    elif [ "$width" != "$want" ] || [ "$over" != 0 ] || [ "$scroll" -gt "$client" ] || [ "$touch_action" != none ]; then
        echo "FAIL viewer at $size size (window $width, wanted $want): $over elements past the window's width ($what), page $scroll px wide in $client, touch-action $touch_action"
    elif [ $size = phone ] && { [ "$is_coarse" != 1 ] || [ "$small" != 0 ]; }; then
        echo "FAIL viewer on a phone: coarse pointer $is_coarse, $small controls under 44 px ($which)"
    else
        echo "PASS viewer at $size size (${width} px wide$([ $size = phone ] && echo ', a coarse pointer: every control at least 44 px tall')): nothing past the window's width, no sideways scrolling, a drag on the picture is the page's"
    fi
    # shellcheck disable=SC2086
    HOME="$t/home" timeout 300 $CHROMIUM --user-data-dir="$(mktemp -d "$t/profile.XXXXXX")" --window-size=$win $flags \
        --screenshot="$BUILD/viewer-screens/$size.png" "file://$t/page/$(echo "$page" | sed 's/#layout//')" >/dev/null 2>&1
    if [ -s "$BUILD/viewer-screens/$size.png" ] && [ "$(wc -c <"$BUILD/viewer-screens/$size.png")" -gt 20000 ]; then
        echo "PASS viewer screenshot at $size size: $BUILD/viewer-screens/$size.png ($(wc -c <"$BUILD/viewer-screens/$size.png") bytes)"
    else
        echo "FAIL viewer screenshot at $size size: $BUILD/viewer-screens/$size.png missing or blank"
    fi
done
