#!/bin/sh
# Consumers: `make install` + pkg-config, and vendoring include/ and src/.
# Both builds must be warning-free and print the same numbers.
[ "$BUILD" = build ] || exit 0 # not a sanitizer question; runs once
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"

if make --no-print-directory -s install PREFIX=/opt/fresnel DESTDIR="$t/root" >"$t/log" 2>&1 &&
    [ -f "$t/root/opt/fresnel/include/fresnel.h" ] && [ -f "$t/root/opt/fresnel/lib/libfresnel.a" ] &&
    [ -f "$t/root/opt/fresnel/lib/pkgconfig/fresnel.pc" ]; then
    echo "PASS make install PREFIX DESTDIR puts header, library and fresnel.pc in place"
else
    echo "FAIL make install: $(tail -5 "$t/log")"
fi

# pkg-config reads the installed .pc; DESTDIR is redirected with the sysroot variable.
flags=$(PKG_CONFIG_PATH="$t/root/opt/fresnel/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$t/root" \
    pkg-config --cflags --libs fresnel 2>"$t/pcerr")
if [ -n "$flags" ] && cc $W tests/consumer/consumer.c $flags -o "$t/installed" 2>"$t/cc1" && [ ! -s "$t/cc1" ]; then
    echo "PASS consumer builds warning-free with pkg-config --cflags --libs fresnel ($flags)"
else
    echo "FAIL consumer via pkg-config: flags '$flags' $(cat "$t/pcerr" "$t/cc1" 2>/dev/null | head -5)"
fi

mkdir -p "$t/vendor/fresnel"
cp include/*.h src/*.c src/*.h "$t/vendor/fresnel/"
if cc $W -I"$t/vendor/fresnel" tests/consumer/consumer.c "$t"/vendor/fresnel/*.c -lm -o "$t/vendored" 2>"$t/cc2" &&
    [ ! -s "$t/cc2" ]; then
    echo "PASS consumer builds warning-free from vendored include/ and src/ files"
else
    echo "FAIL vendored build: $(head -5 "$t/cc2")"
fi
for compiler in gcc clang; do
    if $compiler $W -O2 -I"$t/vendor/fresnel" -c "$t"/vendor/fresnel/exact.c -o "$t/x.o" 2>"$t/cc3" && [ ! -s "$t/cc3" ]; then
        echo "PASS runtime compiles warning-free with $compiler"
    else
        echo "FAIL runtime with $compiler: $(head -5 "$t/cc3")"
    fi
done
if [ -x "$t/installed" ] && [ -x "$t/vendored" ] && "$t/installed" >"$t/o1" && "$t/vendored" >"$t/o2" && cmp -s "$t/o1" "$t/o2"; then
    echo "PASS installed and vendored consumers agree"
else
    echo "FAIL installed and vendored consumers differ or did not run"
fi
