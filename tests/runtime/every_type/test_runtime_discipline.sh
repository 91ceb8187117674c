#!/bin/sh
# passes: first (the object code of build/libfresnel.a)
# The runtime library: no allocation, no stdio, no errno, no global mutable
# state. Checked on the object code: the only undefined symbols are libm's
# float functions, and there is no writable data (.data, .bss) at all.
# memset and memcpy are allowed: gcc turns fill and copy loops into calls to
# them and requires even a freestanding environment to provide both (gcc
# manual, "C Language Standards"); fresnel_conductor_batch's matched-index
# loop becomes a memset.
lib=build/libfresnel.a
# __cpu_model, __cpu_indicator_init: the compiler runtime's CPU feature word
# (reached through the GOT, _GLOBAL_OFFSET_TABLE_ in PIC code),
# read by the x86-64 SSE2 build's batch to take its AVX2 kernel.
allowed='^(sqrtf|expf|log1pf|fmaf|fabsf|memset|memcpy|__cpu_model|__cpu_indicator_init|_GLOBAL_OFFSET_TABLE_)$'
nm --defined-only "$lib" | awk 'NF==3 {print $3}' | sort -u >/tmp/fresnel_defined.$$
external=$(nm -u "$lib" | awk 'NF==2 {print $2}' | sort -u | comm -23 - /tmp/fresnel_defined.$$)
rm -f /tmp/fresnel_defined.$$
bad=$(printf '%s\n' "$external" | grep -Ev "$allowed" | grep -v '^$')
if [ -n "$external" ] && [ -z "$bad" ]; then
    echo "PASS runtime references only libm float functions, memset/memcpy and the CPU feature word ($(printf '%s' "$external" | tr '\n' ' '))"
else
    echo "FAIL runtime references: $bad"
fi
writable=$(size -A "$lib" 2>/dev/null | awk '$1 ~ /^\.(data|bss)/ && $2 > 0 {print FILENAME": "$1" "$2}')
if [ -z "$writable" ]; then
    echo "PASS runtime has no .data or .bss (no global mutable state)"
else
    echo "FAIL runtime has writable data: $writable"
fi
if grep -nE '#include <(stdio|stdlib|errno|string)\.h>' src/*/*.c src/*/*.h include/fresnel.h >/dev/null; then
    echo "FAIL runtime includes a hosted header: $(grep -nE '#include <(stdio|stdlib|errno|string)\.h>' src/*/*.c src/*/*.h include/fresnel.h)"
else
    echo "PASS runtime includes no stdio, stdlib, errno or string headers"
fi
# Names: every global symbol of the archive carries the public prefix
# fresnel_ (internal helpers fresnel_i_*), and a shared library built from
# src/ exports no internal helper (FRESNEL_I_HIDDEN).
foreign=$(nm -g --defined-only "$lib" | awk 'NF==3 {print $3}' | grep -v '^fresnel_' | sort -u | tr '\n' ' ')
if [ -z "$foreign" ]; then
    echo "PASS every global symbol of the runtime starts with fresnel_"
else
    echo "FAIL global symbols outside the fresnel_ prefix: $foreign"
fi
so=$(mktemp -d)
if ${CC:-cc} -std=c99 -O1 -fPIC -shared -Iinclude -fno-math-errno src/*/*.c -o "$so/libfresnel.so" -lm 2>"$so/err"; then
    exported=$(nm -D --defined-only "$so/libfresnel.so" | awk 'NF==3 {print $3}')
    internal=$(printf '%s\n' "$exported" | grep '^fresnel_i_' | tr '\n' ' ')
    if [ -z "$internal" ] && printf '%s\n' "$exported" | grep -q '^fresnel_schlick$'; then
        echo "PASS a shared library from src/ exports no fresnel_i_* helper ($(printf '%s\n' "$exported" | grep -c '^fresnel_') fresnel_* symbols)"
    else
        echo "FAIL shared library exports internal helpers: $internal"
    fi
else
    echo "FAIL shared library from src/ does not build: $(head -3 "$so/err")"
fi
rm -rf "$so"
