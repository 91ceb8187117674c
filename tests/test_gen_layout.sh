#!/bin/sh
# passes: first other (the layout is the same in the sanitized build)
# The generator's architecture, checked on its object files (gen/README.md):
# - no dependency cycle between gen/ sources: file A depends on file B when
#   A's object uses a symbol B's defines; tsort finds any loop;
# - a subcommand (gen/cli/cmd_X.c) only parses and calls: it defines no
#   global but cmd_X;
# - the host tool reads the runtime through include/ only: no gen/ source
#   includes a header of src/.
B=${BUILD:-build}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
srcs=$(find gen -name '*.c' | sort)
for f in $srcs; do
    if [ ! -f "$B/obj/${f%.c}.o" ]; then
        echo "FAIL gen layout: $B/obj/${f%.c}.o missing (build first)"
        exit 1
    fi
done
for f in $srcs; do
    nm "$B/obj/${f%.c}.o" | awk -v f="$f" '$2 ~ /^[TDRBC]$/ { print "def", f, $3 } $1 == "U" { print "use", f, $2 }'
done >"$t/syms"
awk '$1 == "def" { d[$3] = $2 } $1 == "use" { u[++n] = $2 " " $3 }
     END { for (i = 1; i <= n; i++) { split(u[i], a, " "); if ((a[2] in d) && d[a[2]] != a[1]) print a[1], d[a[2]] } }' \
    "$t/syms" | sort -u >"$t/edges"
if tsort "$t/edges" >"$t/order" 2>"$t/loop"; then
    echo "PASS gen layout: no dependency cycle between the $(echo "$srcs" | wc -l) gen/ sources ($(wc -l <"$t/edges") edges)"
else
    echo "FAIL gen layout: dependency cycle between gen/ sources: $(grep -v 'input contains a loop' "$t/loop" | sed 's/^tsort: //' | tr '\n' ' ')"
fi
bad=$(awk '$1 == "def" && $2 ~ /^gen\/cli\/cmd_/ { n = $2; sub(/^gen\/cli\//, "", n); sub(/\.c$/, "", n); if ($3 != n) print $2 ":" $3 }' "$t/syms")
if [ -z "$bad" ]; then
    echo "PASS gen layout: each gen/cli/cmd_X.c defines only cmd_X"
else
    echo "FAIL gen layout: subcommand files export library code: $(echo "$bad" | tr '\n' ' ')"
fi
srch=$(find src -name '*.h' -exec basename {} \; | sort -u | tr '\n' ' ')
hits=""
for h in $srch; do
    hits="$hits$(grep -rln "#include \"\(.*/\)\?$h\"" gen 2>/dev/null | sed "s|\$| ($h)|")"
done
if [ -z "$hits" ]; then
    echo "PASS gen layout: gen/ includes no header of src/"
else
    echo "FAIL gen layout: gen/ includes runtime internals: $hits"
fi

# One model registry (gen/model/registry.c): no other gen/ file chooses or
# lists models by name. The names are what the tool offers (fresnel eval
# --help, fresnel gen --help); a line outside the registry fails when it
# compares or looks up a model name (strcmp, model_find, scene_has_model) or
# lists two or more of them. A name alone as a label (a parameter called f82,
# a bench row) is not a choice of model.
F="$B/fresnel"
names=$({ "$F" eval --help; "$F" gen --help; } 2>/dev/null |
    sed -n -e 's/^  \([a-z][a-z0-9-]*\)  .*/\1/p' -e 's/.*one or more of: \(.*\) lutN .*/\1/p' | tr ' ' '\n' | sort -u)
if [ "$(echo "$names" | wc -l)" -lt 10 ]; then
    echo "FAIL gen layout: could not read the model names from $F eval --help and gen --help"
else
    bad=$(find gen -name '*.c' ! -path gen/model/registry.c | sort | while read -r f; do
        awk -v names="$(echo "$names" | tr '\n' ' ')" -v f="$f" '
            BEGIN { n = split(names, nm, " ") }
            { k = 0; for (i = 1; i <= n; i++) if (index($0, "\"" nm[i] "\"")) k++
              if (k >= 2 || (k == 1 && $0 ~ /strn?cmp|model_find|scene_has_model/)) print f ":" FNR ": " $0 }' "$f"
    done)
    if [ -z "$bad" ]; then
        echo "PASS gen layout: the $(echo "$names" | wc -l) model names are chosen and listed only in gen/model/registry.c"
    else
        echo "FAIL gen layout: model names chosen or listed outside the registry: $(echo "$bad" | head -5)"
    fi
fi
