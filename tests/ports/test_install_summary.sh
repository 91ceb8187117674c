#!/bin/sh
# passes: first (the install itself is tests/ports/test_consumers.sh's; runs once)
# `make install` says what it installed where and how a build finds it, and
# installs the shader ports (share/fresnel/glsl/, hlsl/ and msl/) and the
# single-file runtimes (in include/); `make uninstall`
# says what it removed. (tests/ports/test_consumers.sh builds through each route.)
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
P=/opt/fresnel
R=$t/root$P
if make --no-print-directory -s install PREFIX=$P DESTDIR="$t/root" >"$t/out" 2>"$t/err"; then
    n=$(find "$R" -type f | wc -l)
    missing=""
    for f in share/fresnel/hlsl/fresnel.hlsl share/fresnel/msl/fresnel.metal share/fresnel/glsl/fresnel.glsl; do
        [ -f "$R/$f" ] || missing="$missing $f"
    done
    for f in ports/single/*.h; do
        cmp -s "$f" "$R/include/$(basename "$f")" || missing="$missing include/$(basename "$f")"
    done
    [ -z "$missing" ] && echo "PASS make install puts the shader ports in share/fresnel/ (glsl/, hlsl/, msl/) and the single files in include/" ||
        echo "FAIL make install lacks:$missing"
    said=""
    grep -q "^installed fresnel .* in $R ($n files" "$t/out" || said="$said where-and-count"
    for d in include/ lib/ bin/fresnel share/fresnel/; do
        grep -q "^  $d " "$t/out" || said="$said $d"
    done
    for h in include/*.h ports/single/*.h; do
        grep -q "$(basename "$h")" "$t/out" || said="$said $h"
    done
    grep -q 'pkg-config --cflags --libs fresnel' "$t/out" && grep -q 'find_package(fresnel)' "$t/out" || said="$said how-to-use"
    if [ -z "$said" ] && [ "$(wc -l <"$t/out")" -le 10 ]; then
        echo "PASS make install prints where its $n files went and how pkg-config and CMake find them, in $(wc -l <"$t/out") lines"
    else
        echo "FAIL make install output lacks:$said ($(head -3 "$t/out"))"
    fi
else
    echo "FAIL make install: $(tail -3 "$t/err")"
fi
if make --no-print-directory -s uninstall PREFIX=$P DESTDIR="$t/root" >"$t/out" 2>&1 && grep -q "^uninstalled fresnel from $R" "$t/out"; then
    echo "PASS make uninstall says what it removed"
else
    echo "FAIL make uninstall output: $(head -3 "$t/out")"
fi
