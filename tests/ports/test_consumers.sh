#!/bin/sh
# passes: first (installs and builds with CMake, pkg-config, C++ compilers: not a sanitizer
# question)
# make check: no (CMake, C++ and install routes)
# Consumers, one per route a user takes: `make install` + pkg-config, + CMake
# find_package, the source tree through CMake add_subdirectory and
# FetchContent (ports/cmake), vendored include/ + src/f32/ compiled with plain cc,
# and C++17 (g++ and clang++) against the installed libfresnel.a. Every build
# is warning-free with -Werror and prints the same numbers. Then the installed
# tool finds its data pack, and `make uninstall` leaves nothing behind.
# Last, installs to prefixes with a space, an apostrophe and # & $ " in
# them, each consumed through pkg-config and CMake and uninstalled.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
W="-std=c99 -Wall -Wextra -Wpedantic -Werror"
P=/opt/fresnel
R=$t/root$P
version=$(sed -n 's/^#define FRESNEL_VERSION "\(.*\)"/\1/p' include/fresnel.h)

# ---- install ----
missing=""
if make --no-print-directory -s install PREFIX=$P DESTDIR="$t/root" >"$t/log" 2>&1; then
    for f in include/fresnel.h include/fresnel_q15.h include/fresnel_q15_fast.h include/fresnel_fixed.h \
        include/fresnel_fixed_fast.h include/fresnel_f16.h include/fresnel_config.h \
        lib/libfresnel.a lib/pkgconfig/fresnel.pc lib/cmake/fresnel/fresnelConfig.cmake \
        lib/cmake/fresnel/fresnelConfigVersion.cmake bin/fresnel share/fresnel/data/materials.csv \
        share/fresnel/data/SOURCES.md share/fresnel/glsl/fresnel.glsl share/fresnel/hlsl/fresnel.hlsl share/fresnel/msl/fresnel.metal \
        share/fresnel/LICENSE \
        share/fresnel/install_manifest.txt; do
        [ -f "$R/$f" ] || missing="$missing $f"
    done
    if [ -z "$missing" ]; then
        echo "PASS make install PREFIX DESTDIR puts headers, libfresnel.a, fresnel.pc, CMake package, bin/fresnel, data, GLSL, HLSL, MSL, LICENSE in place"
    else
        echo "FAIL make install: missing$missing"
    fi
else
    echo "FAIL make install: $(tail -5 "$t/log")"
fi
(cd "$R" && find . -type f | sed 's|^\./||' | sort) >"$t/present"
sed -n 's/^f //p' "$R/share/fresnel/install_manifest.txt" 2>/dev/null | sort >"$t/listed"
if [ -s "$t/listed" ] && cmp -s "$t/present" "$t/listed"; then
    echo "PASS install manifest lists exactly the $(wc -l <"$t/listed") installed files"
else
    echo "FAIL install manifest differs from the installed files: $(diff "$t/present" "$t/listed" | head -5)"
fi

# ---- the installed tool's data pack: --data, $FRESNEL_DATA, BINDIR/../share/fresnel/data, build tree ----
# A copy of the installed tree in another place, its data pack damaged: the
# tool must read that pack (and report it), wherever the tree is.
cp -R "$R" "$t/moved"
echo garbage >"$t/moved/share/fresnel/data/materials.csv"
(cd / && env -u FRESNEL_DATA "$t/moved/bin/fresnel" materials) >/dev/null 2>"$t/err"
if grep -q "$t/moved/bin/../share/fresnel/data/materials.csv:1" "$t/err"; then
    echo "PASS installed fresnel reads BINDIR/../share/fresnel/data without --data, after the tree is moved"
else
    echo "FAIL installed fresnel does not read its own data pack: $(head -3 "$t/err")"
fi
if (cd / && env -u FRESNEL_DATA "$R/bin/fresnel" materials) >"$t/m1" 2>"$t/err" &&
    ./build/fresnel materials --data data >"$t/m2" 2>/dev/null && cmp -s "$t/m1" "$t/m2"; then
    echo "PASS installed fresnel materials, run from /, lists the same materials as the source tree"
else
    echo "FAIL installed fresnel materials: $(head -3 "$t/err")"
fi
mkdir "$t/empty"
(cd / && FRESNEL_DATA="$t/empty" "$t/moved/bin/fresnel" materials) >/dev/null 2>"$t/err"
if grep -q "$t/empty/materials.csv" "$t/err"; then
    echo "PASS \$FRESNEL_DATA comes before the installed data pack"
else
    echo "FAIL \$FRESNEL_DATA ignored by the installed tool: $(head -3 "$t/err")"
fi
(cd / && FRESNEL_DATA="$t/moved/share/fresnel/data" "$t/moved/bin/fresnel" materials --data "$t/empty") >/dev/null 2>"$t/err"
if grep -q "$t/empty/materials.csv" "$t/err"; then
    echo "PASS --data comes before \$FRESNEL_DATA"
else
    echo "FAIL --data does not come first: $(head -3 "$t/err")"
fi
rm "$t/moved/share/fresnel/data/materials.csv"
if (cd / && env -u FRESNEL_DATA "$t/moved/bin/fresnel" materials) >"$t/m3" 2>"$t/err" && cmp -s "$t/m3" "$t/m2"; then
    echo "PASS without an installed materials.csv the tool falls back to the source tree's data/"
else
    echo "FAIL no fallback to the source tree's data/: $(head -3 "$t/err")"
fi

# ---- pkg-config (DESTDIR is redirected with the sysroot variable) ----
flags=$(PKG_CONFIG_PATH="$R/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$t/root" \
    pkg-config --cflags --libs fresnel 2>"$t/pcerr")
if [ -n "$flags" ] && cc $W tests/ports/consumer/consumer.c $flags -o "$t/installed" 2>"$t/cc1" && [ ! -s "$t/cc1" ]; then
    echo "PASS consumer builds warning-free with pkg-config --cflags --libs fresnel ($flags)"
else
    echo "FAIL consumer via pkg-config: flags '$flags' $(cat "$t/pcerr" "$t/cc1" 2>/dev/null | head -5)"
fi

# ---- vendored sources, plain cc ----
# A binary32-only consumer copies the headers and the one folder of its type.
mkdir -p "$t/vendor/fresnel/include"
cp include/*.h "$t/vendor/fresnel/include/"
cp -R src/f32 "$t/vendor/fresnel/"
if cc $W -I"$t/vendor/fresnel/include" tests/ports/consumer/consumer.c "$t"/vendor/fresnel/f32/*.c -lm -o "$t/vendored" 2>"$t/cc2" &&
    [ ! -s "$t/cc2" ]; then
    echo "PASS consumer builds warning-free from vendored include/ and src/f32/ alone"
else
    echo "FAIL vendored build: $(head -5 "$t/cc2")"
fi
# Every type's folder builds from a copy of itself and include/ only.
for type in f32 q15 f16; do
    mkdir -p "$t/alone/$type/include" "$t/alone/$type/obj"
    cp include/*.h "$t/alone/$type/include/"
    cp -R "src/$type" "$t/alone/$type/"
    ok=1
    for f in "$t/alone/$type/$type"/*.c; do
        cc $W -O2 -I"$t/alone/$type/include" -c "$f" -o "$t/alone/$type/obj/$(basename "$f" .c).o" 2>>"$t/cc4" || ok=0
    done
    if [ $ok -eq 1 ] && [ ! -s "$t/cc4" ]; then
        echo "PASS src/$type/ compiles warning-free vendored alone (with include/)"
    else
        echo "FAIL src/$type/ vendored alone: $(head -5 "$t/cc4")"
    fi
done
for compiler in gcc clang; do
    if $compiler $W -O2 -I"$t/vendor/fresnel/include" -c "$t"/vendor/fresnel/f32/exact.c -o "$t/x.o" 2>"$t/cc3" && [ ! -s "$t/cc3" ]; then
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

# ---- CMake: find_package on the installed tree; the source tree by
# add_subdirectory and by FetchContent (from a tarball of the tree, as a
# release download would be) ----
mkdir "$t/tree"
tar cf - --exclude=./build --exclude=./.git . | (cd "$t/tree" && tar xf -)
(cd "$t" && tar czf fresnel-src.tar.gz tree)
cmake_route() { # name, cmake -D arguments...
    name=$1
    shift
    rm -rf "$t/cm"
    if cmake -S tests/ports/consumer/cmake -B "$t/cm" -DCMAKE_C_FLAGS="$W" "$@" >"$t/cm.log" 2>&1 &&
        env -u MAKEFLAGS -u MFLAGS cmake --build "$t/cm" >>"$t/cm.log" 2>&1 && "$t/cm/consumer" >"$t/o3" && cmp -s "$t/o1" "$t/o3"; then
        if grep -qi 'warning' "$t/cm.log"; then
            echo "FAIL CMake $name: warnings: $(grep -i -m3 warning "$t/cm.log")"
        else
            echo "PASS CMake $name: consumer builds warning-free, links fresnel::fresnel, agrees with pkg-config's"
        fi
    else
        echo "FAIL CMake $name: $(grep -i -m5 -e error -e differ "$t/cm.log")"
    fi
}
cmake_route "find_package(fresnel ${version%.*})" -DROUTE=find_package -DCMAKE_PREFIX_PATH="$R" -DWANT="${version%.*}"
cmake_route "add_subdirectory(ports/cmake)" -DROUTE=subdirectory -DFRESNEL_SOURCE="$t/tree"
cmake_route "FetchContent (URL tarball, SOURCE_SUBDIR ports/cmake)" -DROUTE=fetchcontent \
    -DFRESNEL_SOURCE="$t/fresnel-src.tar.gz"
rm -rf "$t/cm"
if cmake -S tests/ports/consumer/cmake -B "$t/cm" -DROUTE=find_package -DCMAKE_PREFIX_PATH="$R" -DWANT=99 >"$t/cm.log" 2>&1; then
    echo "FAIL find_package(fresnel 99) accepted version $version"
elif grep -q "$version" "$t/cm.log"; then
    echo "PASS find_package(fresnel 99) is refused, naming the installed $version"
else
    echo "FAIL find_package(fresnel 99) refused without naming the version: $(grep -m3 -i error "$t/cm.log")"
fi

# ---- C++17: every public header, one function of each type ----
# A library built without binary16 (clang 14 has no _Float16 on x86-64) is
# consumed with the configuration it was built with, as fresnel_config.h says.
cfg=
nm "$R/lib/libfresnel.a" 2>/dev/null | grep -q ' T fresnel_schlick_f16$' || cfg=-DFRESNEL_CONFIG=FRESNEL_CFG_NO_F16
for cxx in g++ clang++; do
    if $cxx -std=c++17 -Wall -Wextra -Wpedantic -Werror $cfg -I"$R/include" tests/ports/consumer/cxx_consumer.cpp \
        "$R/lib/libfresnel.a" -lm -o "$t/cxx_$cxx" 2>"$t/cxx.err" && [ ! -s "$t/cxx.err" ] &&
        "$t/cxx_$cxx" >"$t/o4" && head -5 "$t/o4" | cmp -s - "$t/o1" && grep -qx 'q15 [0-9]*' "$t/o4"; then
        echo "PASS C++17 ($cxx -Wall -Wextra -Wpedantic -Werror) includes every header, links libfresnel.a, agrees ($(grep -e q15 -e f16 "$t/o4" | tr '\n' ' '))"
    else
        echo "FAIL C++17 with $cxx: $(head -5 "$t/cxx.err" "$t/o4" 2>/dev/null)"
    fi
done

# ---- uninstall: exactly what install put there ----
if make --no-print-directory -s uninstall PREFIX=$P DESTDIR="$t/root" >"$t/log" 2>&1 && [ ! -e "$t/root" ]; then
    echo "PASS make uninstall removes every installed file and every directory install created"
else
    echo "FAIL make uninstall left: $(find "$t/root" 2>/dev/null | head -5) $(tail -3 "$t/log")"
fi
# into a prefix that already holds other files: those and their directories stay
mkdir -p "$t/pre$P/lib" "$t/pre$P/share/fresnel"
echo keep >"$t/pre$P/lib/other.a"
echo keep >"$t/pre$P/share/fresnel/notes.txt"
if make --no-print-directory -s install PREFIX=$P DESTDIR="$t/pre" >"$t/log" 2>&1 &&
    make --no-print-directory -s install PREFIX=$P DESTDIR="$t/pre" >>"$t/log" 2>&1 &&
    make --no-print-directory -s uninstall PREFIX=$P DESTDIR="$t/pre" >>"$t/log" 2>&1 &&
    [ "$(cd "$t/pre" && find . | sort | tr '\n' ' ')" = ". ./opt ./opt/fresnel ./opt/fresnel/lib ./opt/fresnel/lib/other.a ./opt/fresnel/share ./opt/fresnel/share/fresnel ./opt/fresnel/share/fresnel/notes.txt " ]; then
    echo "PASS install twice then uninstall into a used prefix keeps its other files and directories, removes the rest"
else
    echo "FAIL uninstall in a used prefix: $(cd "$t/pre" && find . | sort | tr '\n' ' ') $(tail -3 "$t/log")"
fi
if make --no-print-directory -s uninstall PREFIX=$P DESTDIR="$t/none" >"$t/log" 2>&1; then
    echo "FAIL make uninstall without an install succeeded"
elif grep -q 'install_manifest.txt' "$t/log"; then
    echo "PASS make uninstall without an install fails, naming the missing manifest"
else
    echo "FAIL make uninstall without an install: $(tail -3 "$t/log")"
fi

# ---- prefixes with odd characters: a space, an apostrophe, # & $ " ----
# make install takes PREFIX as written; fresnel.pc holds it escaped as
# pkg-config reads it, and pkg-config prints the flags as shell text, which
# a shell (here eval) or a Makefile recipe reads back into the paths; CMake
# finds the package relative to itself; make uninstall leaves nothing.
# (pkg-config prints a $ unescaped: one followed by a name would be a
# variable to the shell that reads the flags, hence US$ before a slash.
# CMake writes the path of the package's files unescaped into its own
# CMakeFiles/Makefile.cmake, which a " breaks, so that prefix skips CMake.)
for name in "a b" "it's" 'odd #&US$' 'q"q'; do
    p=$t/odd/$name
    label="PREFIX ending in '$name'"
    if ! make --no-print-directory -s install PREFIX="$p" >"$t/log" 2>&1 || [ ! -f "$p/include/fresnel.h" ]; then
        echo "FAIL make install $label: $(tail -3 "$t/log")"
        continue
    fi
    flags=$(PKG_CONFIG_PATH="$p/lib/pkgconfig" pkg-config --cflags --libs fresnel 2>"$t/pcerr")
    rm -f "$t/odd.bin"
    if [ -n "$flags" ] && eval "cc \$W tests/ports/consumer/consumer.c $flags -o \"\$t/odd.bin\"" 2>"$t/cc5" &&
        [ ! -s "$t/cc5" ] && "$t/odd.bin" >"$t/o5" && cmp -s "$t/o1" "$t/o5"; then
        echo "PASS $label: the consumer builds warning-free from pkg-config --cflags --libs fresnel ($flags) and agrees"
    else
        echo "FAIL $label, pkg-config: flags '$flags' $(cat "$t/pcerr" "$t/cc5" 2>/dev/null | head -5)"
    fi
    case $name in
    *'"'*) echo "NOTE CMake find_package, $label: not tried (a \" in the path breaks CMake's own build files)" ;;
    *) cmake_route "find_package(fresnel), $label" -DROUTE=find_package -DCMAKE_PREFIX_PATH="$p" ;;
    esac
    if make --no-print-directory -s uninstall PREFIX="$p" >"$t/log" 2>&1 && [ ! -e "$t/odd" ]; then
        echo "PASS make uninstall $label removes everything install put there"
    else
        echo "FAIL make uninstall $label left: $(find "$t/odd" 2>/dev/null | head -5) $(tail -3 "$t/log")"
    fi
done
