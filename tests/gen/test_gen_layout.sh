#!/bin/sh
# passes: first other (the layout is the same in the sanitized build)
# The generator's architecture, checked on its object files (gen/README.md):
# - floors: gen/'s folders in the order of `floors` below, the ground floor
#   first; a file includes (#include "folder/...") and calls (uses a symbol
#   defined in) only files of its own folder and of the folders before it,
#   and every folder of gen/ has its place in the order;
# - no dependency cycle between gen/ sources: file A depends on file B when
#   A's object uses a symbol B's defines; tsort finds any loop;
# - a subcommand (gen/cli/cmd_<name>.c) only parses and calls: it defines no
#   global but cmd_<name>;
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
# Floors, from the ground up (gen/main.c is "main").
floors="common catalog 1_spectral scene 2_derive 3_encode model 4_emit bench report viewer cli main"
for f in $(find gen -name '*.[ch]' | sort); do
    d=${f#gen/}
    case $d in */*) d=${d%%/*} ;; *) d=main ;; esac
    sed -n 's|^#include "\([a-z0-9_]*\)/.*|\1|p' "$f" | sort -u | sed "s|^|include $f $d |"
done >"$t/includes"
awk -v floors="$floors" '
    function folder(f) { sub(/^gen\//, "", f); return f ~ /\// ? substr(f, 1, index(f, "/") - 1) : "main" }
    BEGIN { n = split(floors, fl, " "); for (i = 1; i <= n; i++) rank[fl[i]] = i }
    FILENAME ~ /includes$/ { from = $3; to = $4; how = "includes"; file = $2 }
    FILENAME ~ /edges$/ { from = folder($1); to = folder($2); how = "calls"; file = $1 " -> " $2 }
    from != to {
        if (!(from in rank)) unknown[from] = 1
        if (!(to in rank)) unknown[to] = 1
        if ((from in rank) && (to in rank) && rank[to] > rank[from]) {
            key = from " " how " " to
            if (!(key in up)) { up[key] = file; nup++ }
        }
    }
    END {
        for (u in unknown) print "UNKNOWN " u
        for (k in up) print "UP " k " (" up[k] ")"
    }' "$t/includes" "$t/edges" | sort >"$t/floors"
nfolders=$(find gen -mindepth 1 -maxdepth 1 -type d | wc -l)
if [ ! -s "$t/floors" ]; then
    echo "PASS gen layout: the $nfolders folders of gen/ lie in floors ($floors); no include or call runs up one"
else
    echo "FAIL gen layout: $(grep -c '^UP' "$t/floors") arrows run up a floor or a folder has no floor ($floors):" \
        "$(head -12 "$t/floors" | tr '\n' ';')"
fi

bad=$(awk '$1 == "def" && $2 ~ /^gen\/cli\/cmd_/ { n = $2; sub(/^gen\/cli\//, "", n); sub(/\.c$/, "", n); if ($3 != n) print $2 ":" $3 }' "$t/syms")
if [ -z "$bad" ]; then
    echo "PASS gen layout: each gen/cli/cmd_<name>.c defines only cmd_<name>"
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

# One model catalog (gen/catalog/models.h) and registry
# (gen/model/registry.c): no other gen/ source chooses or lists models by
# name. The names are what the tool offers (fresnel eval
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
    bad=$(find gen -name '*.[ch]' ! -path gen/model/registry.c ! -path gen/catalog/models.h | sort | while read -r f; do
        awk -v names="$(echo "$names" | tr '\n' ' ')" -v f="$f" '
            BEGIN { n = split(names, nm, " ") }
            { k = 0; for (i = 1; i <= n; i++) if (index($0, "\"" nm[i] "\"")) k++
              if (k >= 2 || (k == 1 && $0 ~ /strn?cmp|model_find|scene_has_model/)) print f ":" FNR ": " $0 }' "$f"
    done)
    if [ -z "$bad" ]; then
        echo "PASS gen layout: the $(echo "$names" | wc -l) model names are chosen and listed only in gen/catalog/models.h and gen/model/registry.c"
    else
        echo "FAIL gen layout: model names chosen or listed outside the catalog and the registry: $(echo "$bad" | head -5)"
    fi
fi
