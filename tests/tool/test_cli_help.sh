#!/bin/sh
# passes: first (text of the tool, not a sanitizer question)
# The tool's help says what it does: every command listed by `fresnel --help`
# answers COMMAND --help with its usage and exit status 0; `fresnel --help`
# says gen writes C, GLSL and HLSL; `fresnel gen --help` shows every key a
# scene manifest takes (gen/scene/scene.c's key_names, and the
# `material ID = FILE` line) with its values.
F=$BUILD/fresnel
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

"$F" --help >"$t/top"
commands=$(sed -n '/^commands:/,/^$/s/^  \([a-z]*\) .*/\1/p' "$t/top")
bad=""
for c in $commands; do
    "$F" "$c" --help >"$t/out" 2>&1 && head -1 "$t/out" | grep -q "^usage: fresnel $c" || bad="$bad $c"
done
if [ -n "$commands" ] && [ -z "$bad" ]; then
    echo "PASS every command's --help prints its usage, exit 0: $(echo $commands | wc -w) commands"
else
    echo "FAIL COMMAND --help without usage or with a non-zero exit:$bad"
fi

if grep -q '^  gen .*C, GLSL or HLSL' "$t/top"; then
    echo "PASS fresnel --help: gen writes C, GLSL or HLSL"
else
    echo "FAIL fresnel --help describes gen as: $(grep '^  gen ' "$t/top")"
fi

"$F" gen --help >"$t/gen"
keys=$(sed -n '/key_names\[\] = {/,/};/p' gen/scene/scene.c | grep -o '"[a-z_0-9]*"' | tr -d '"')
missing=""
for k in $keys; do
    grep -q "^  $k = " "$t/gen" || missing="$missing $k"
done
grep -q '^  material [a-z_0-9]* = ' "$t/gen" || missing="$missing material-ID=FILE"
grep -q 'map clip keep' "$t/gen" || missing="$missing gamut-values"
if [ -n "$keys" ] && [ -z "$missing" ]; then
    echo "PASS fresnel gen --help shows every manifest key ($(echo $keys | wc -w) and material ID = FILE) with its values"
else
    echo "FAIL fresnel gen --help lacks the manifest keys:$missing"
fi
