#!/bin/sh
# The runtime library: no allocation, no stdio, no errno, no global mutable
# state. Checked on the object code: the only undefined symbols are libm's
# float functions, and there is no writable data (.data, .bss) at all.
[ "$BUILD" = build ] || exit 0
lib=build/libfresnel.a
allowed='^(sqrtf|expf|log1pf|fmaf)$'
nm --defined-only "$lib" | awk 'NF==3 {print $3}' | sort -u >/tmp/fresnel_defined.$$
external=$(nm -u "$lib" | awk 'NF==2 {print $2}' | sort -u | comm -23 - /tmp/fresnel_defined.$$)
rm -f /tmp/fresnel_defined.$$
bad=$(printf '%s\n' "$external" | grep -Ev "$allowed" | grep -v '^$')
if [ -n "$external" ] && [ -z "$bad" ]; then
    echo "PASS runtime references only libm float functions ($(printf '%s' "$external" | tr '\n' ' '))"
else
    echo "FAIL runtime references: $bad"
fi
writable=$(size -A "$lib" 2>/dev/null | awk '$1 ~ /^\.(data|bss)/ && $2 > 0 {print FILENAME": "$1" "$2}')
if [ -z "$writable" ]; then
    echo "PASS runtime has no .data or .bss (no global mutable state)"
else
    echo "FAIL runtime has writable data: $writable"
fi
if grep -nE '#include <(stdio|stdlib|errno|string)\.h>' src/*.c src/*.h include/fresnel.h >/dev/null; then
    echo "FAIL runtime includes a hosted header: $(grep -nE '#include <(stdio|stdlib|errno|string)\.h>' src/*.c src/*.h include/fresnel.h)"
else
    echo "PASS runtime includes no stdio, stdlib, errno or string headers"
fi
