#!/bin/sh
# The scene's part of the generated identifiers: the manifest's `name` key
# (a C identifier part, else a file:line error, exit 2, no output), or the
# manifest's file name mapped to a valid identifier part (gen/scene/scene.h,
# FORMAT). Headers of two manifests with different names compile in one
# translation unit, as C99 and as C++17; each opening comment states the
# licence of the constants.
F="${BUILD:-build}/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
body='materials = au\nmodels = schlick lut8-residual\ntypes = f32 q15\n'

# derived FILE EXPECTED
derived() {
    printf "$body" >"$t/$1"
    if "$F" gen "$t/$1" -o "$t/d.h" 2>"$t/err" && grep -q "fresnel_$2_au_f0 " "$t/d.h" &&
        grep -q "^#define FRESNEL_SCENE_$(echo "$2" | tr a-z A-Z)_H" "$t/d.h"; then
        echo "PASS gen name: file '$1' gives identifiers fresnel_$2_..."
    else
        echo "FAIL gen name: file '$1': expected fresnel_$2_au_f0, got $(grep -o 'fresnel_[A-Za-z0-9_]*_au_f0 ' "$t/d.h" 2>/dev/null) $(head -2 "$t/err")"
    fi
}
derived 2metals.scene 2metals
derived x.v1 x_v1
derived x.v2 x_v2
derived 'A b--c.d.scene' a_b_c_d
derived _lead_.scene lead
derived '--.scene' scene
derived "$(printf 'caf\303\251.scene')" caf

# rejected VALUE
rejected() {
    printf "# scene\nname = %s\n$body" "$1" >"$t/n.scene"
    rm -f "$t/n.h"
    "$F" gen "$t/n.scene" -o "$t/n.h" 2>"$t/err"
    rc=$?
    if [ "$rc" -eq 2 ] && grep -q "^$t/n.scene:2: expected name as a C identifier part" "$t/err" && [ ! -e "$t/n.h" ]; then
        echo "PASS gen name: name = '$1' is rejected at file:line"
    else
        echo "FAIL gen name: name = '$1': exit $rc, $(head -2 "$t/err")"
    fi
}
rejected 'a__b'
rejected '_a'
rejected 'a_'
rejected 'a-b'
rejected 'a b'
rejected 'caf\303\251'
rejected 'abcdefghijabcdefghijabcdefghijabcdefghijk'

printf "name = One\n$body" >"$t/x.v1"
printf "name = two_2\n$body" >"$t/x.v2"
printf '#include "one.h"\n#include "two.h"\nint main(void) { return (int)(fresnel_One_au_f0.r + fresnel_two_2_au_f0.r); }\n' >"$t/use.c"
if "$F" gen "$t/x.v1" -o "$t/one.h" 2>"$t/err" && "$F" gen "$t/x.v2" -o "$t/two.h" 2>>"$t/err" &&
    cc -std=c99 -Wall -Wextra -Wpedantic -Werror -Iinclude -I"$t" -c "$t/use.c" -o "$t/use.o" 2>>"$t/err" &&
    c++ -std=c++17 -x c++ -Wall -Wextra -Wpedantic -Werror -Iinclude -I"$t" -c "$t/use.c" -o "$t/use.o" 2>>"$t/err"; then
    echo "PASS gen name: two scenes named by the key compile in one translation unit (C99, C++17)"
else
    echo "FAIL gen name: two named scenes together: $(head -5 "$t/err")"
fi
if grep -q "Data: the numbers below are facts derived from refractiveindex.info data (CC0 1.0;" "$t/one.h" &&
    grep -q "CC BY-SA 4.0" "$t/one.h" && grep -q "under the project's MIT licence" "$t/one.h" &&
    "$F" gen --glsl "$t/x.v1" -o "$t/one.glsl" 2>/dev/null && grep -q "MIT licence" "$t/one.glsl"; then
    echo "PASS gen name: the opening comment states the constants' licence (C and GLSL)"
else
    echo "FAIL gen name: no licence statement in the opening comment"
fi
