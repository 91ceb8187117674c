#!/bin/sh
# passes: first (reads sources only; runs once)
# The shader ports have one source of the model functions,
# ports/glsl/fresnel.glsl; the HLSL and MSL ports are their language's
# spellings of its type and helper names, then an #include of it. So no run
# of 6 or more lines stands in both a GLSL file (ports/glsl/*.glsl) and an
# HLSL or MSL file (ports/hlsl/*.hlsl, ports/msl/*.metal), nor in both of
# those: lines compared with their spaces collapsed, blank
# lines passed over, a run within one file on each side. The controls show
# the detector finds a 6-line run (re-indented) and passes over a 5-line one.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

# shared_runs A_FILE... -- B_FILE...: prints "a.glsl:L ~ b.hlsl:M (N lines)"
# for each run of N >= $min lines that stands from line L of an A file and
# from line M of a B file.
min=6
shared_runs() {
    args=
    side=a
    for f in "$@"; do
        if [ "$f" = -- ]; then
            side=b
        else
            args="$args side=$side $f"
        fi
    done
    # shellcheck disable=SC2086
    awk -v min=$min '
        FNR == 1 { file++ }
        {
            s = $0
            gsub(/[ \t\r]+/, " ", s)
            sub(/^ /, "", s)
            sub(/ $/, "", s)
            if (s == "")
                next
            k = ++n[side]
            text[side, k] = s
            fid[side, k] = file
            at[side, k] = FILENAME ":" FNR
        }
        function run(sd, i,    key, j) {
            if (fid[sd, i] != fid[sd, i + min - 1])
                return ""
            key = text[sd, i]
            for (j = 1; j < min; j++)
                key = key "\n" text[sd, i + j]
            return key
        }
        function flush() {
            if (len)
                print at["a", sa] " ~ " at["b", sb] " (" len " lines)"
            len = 0
        }
        END {
            for (i = 1; i + min - 1 <= n["a"]; i++)
                if ((key = run("a", i)) != "" && !(key in first))
                    first[key] = i
            for (i = 1; i + min - 1 <= n["b"]; i++) {
                if ((key = run("b", i)) == "" || !(key in first))
                    continue
                ai = first[key]
                if (len && i == pb + 1 && ai == pa + 1) {
                    len++
                } else {
                    flush()
                    sa = ai
                    sb = i
                    len = min
                }
                pa = ai
                pb = i
            }
            flush()
        }' $args
}

# Controls: lines 2-7 of a.glsl stand again, re-indented, in six.hlsl; only
# lines 2-6 in five.hlsl.
printf 'one\ntwo\nthree\nfour\nfive\nsix\nseven\neight\n' >"$t/a.glsl"
printf 'other\n  two\n\nthree\n four\nfive\t\nsix\nseven\nend\n' >"$t/six.hlsl"
printf 'other\ntwo\nthree\nfour\nfive\nsix\nend\n' >"$t/five.hlsl"
found=$(shared_runs "$t/a.glsl" -- "$t/six.hlsl")
if [ "$found" = "$t/a.glsl:2 ~ $t/six.hlsl:2 ($min lines)" ]; then
    echo "PASS shader source: the control's re-indented run of $min lines is found"
else
    echo "FAIL shader source: the control's run of $min lines: expected a.glsl:2 ~ six.hlsl:2, got '$found'"
fi
found=$(shared_runs "$t/a.glsl" -- "$t/five.hlsl")
if [ -z "$found" ]; then
    echo "PASS shader source: the control's run of $((min - 1)) lines is not reported"
else
    echo "FAIL shader source: the control's run of $((min - 1)) lines is reported: $found"
fi

# The ports.
for other in hlsl msl; do
    ext=$([ $other = hlsl ] && echo hlsl || echo metal)
    found=$(shared_runs ports/glsl/*.glsl -- ports/$other/*.$ext)
    if [ -z "$found" ]; then
        echo "PASS shader source: no run of $min lines stands in both ports/glsl/*.glsl and ports/$other/*.$ext"
    else
        echo "FAIL shader source: runs of $min lines in both the GLSL and the $other port (one source:" \
            "ports/glsl/fresnel.glsl; the port defines spellings): $(printf '%s\n' "$found" | head -5 | tr '\n' ' ')"
    fi
done
found=$(shared_runs ports/hlsl/*.hlsl -- ports/msl/*.metal)
if [ -z "$found" ]; then
    echo "PASS shader source: no run of $min lines stands in both ports/hlsl/*.hlsl and ports/msl/*.metal"
else
    echo "FAIL shader source: runs of $min lines in both the HLSL and the MSL port: $(printf '%s\n' "$found" | head -5 | tr '\n' ' ')"
fi
