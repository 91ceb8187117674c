#!/bin/sh
# passes: first (the same in every build)
# Every public name of include/*.h follows the NAMING rule of
# include/fresnel.h, whose word lists ("slot = words;") this test reads: one
# source for the rule and its check. One FAIL line per name outside it.
#
# The names are those the headers define (outside comments): macros,
# typedef names, struct tags, functions (declared, or static inline) and
# constant tables; each is checked by its kind: a function as a function
# (or a _prepare, or a utility), a type as a type, a macro as a macro.
# Beyond the word order: a BOUND_ or DOMAIN_ macro names a function that
# exists (same model and forms, type and call); a _prepare returns its
# _prep type, and a _prep type without _fast has its _prepare; an ALIASES
# block #defines each second name to a name of the rule. With a built
# $BUILD/libfresnel.a, every function it defines (fresnel_i_* aside) is one
# the headers declare, so no name escapes the list.
lib=${BUILD:-build}/libfresnel.a
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
# The headers without comments, one line per line (strings kept).
for h in include/*.h; do
    awk -v H="$h" '
    { out = ""; s = $0
      while (s != "") {
          if (inc) { i = index(s, "*/"); if (!i) { s = ""; break } s = substr(s, i + 2); inc = 0; continue }
          if (match(s, /\/\*|\/\/|"/)) {
              tok = substr(s, RSTART, RLENGTH); out = out substr(s, 1, RSTART - 1); s = substr(s, RSTART + RLENGTH)
              if (tok == "/*") inc = 1
              else if (tok == "//") s = ""
              else { j = index(s, "\""); out = out "\"\""; s = j ? substr(s, j + 1) : "" }
          } else { out = out s; s = "" }
      }
      print H "\t" out }' "$h"
done >"$t/code"
# The ALIASES blocks are in comments, which the code copy lost: mark them.
for h in include/*.h; do
    awk -v H="$h" '/^\/\* ALIASES/ { a = 1 } /^\/\* end of ALIASES/ { a = 0 }
        a && /^#define/ { print "alias", $2, H, $3 }' "$h"
done >"$t/aliases"
# Definitions: kind name header
awk -F '\t' '
{ h = $1; l = $2 }
l ~ /^[ \t]*#[ \t]*define[ \t]+[A-Za-z_]/ {
    n = l; sub(/^[ \t]*#[ \t]*define[ \t]+/, "", n); sub(/[^A-Za-z0-9_].*/, "", n); print "macro", n, h; next }
{ s = l; while (match(s, /struct[ \t]+(fresnel|FRESNEL)_[A-Za-z0-9_]*[ \t]*\{/)) {
      n = substr(s, RSTART, RLENGTH); sub(/^struct[ \t]+/, "", n); sub(/[ \t]*\{$/, "", n); print "type", n, h
      s = substr(s, RSTART + RLENGTH) } }
l ~ /^\}[ \t]*(fresnel|FRESNEL)_[A-Za-z0-9_]*[ \t]*;/ { n = l; sub(/^\}[ \t]*/, "", n); sub(/[ \t;].*/, "", n); print "type", n, h }
l ~ /^(__extension__[ \t]+)?typedef[^{]*[ \t*](fresnel|FRESNEL)_[A-Za-z0-9_]*[ \t]*[;\[]/ {
    n = l; sub(/[ \t]*[;\[].*/, "", n); sub(/.*[ \t*]/, "", n); print "type", n, h }
l ~ /^static[ \t]+const[ \t]+[A-Za-z0-9_]+[ \t]+(fresnel|FRESNEL)_[A-Za-z0-9_]*[ \t]*\[/ {
    n = l; sub(/[ \t]*\[.*/, "", n); sub(/.*[ \t]/, "", n); print "table", n, h }
l ~ /^[A-Za-z_][A-Za-z0-9_ \t*]*[ \t*](fresnel|FRESNEL)_[A-Za-z0-9_]*\(/ && l !~ /^(return|typedef|#)/ {
    n = l; sub(/\(.*/, "", n); sub(/.*[ \t*]/, "", n); print "function", n, h }
' "$t/code" | sort -u >"$t/defs"
# Every fresnel_/FRESNEL_ word of the code is defined in the headers (or only
# tested with defined(), the spellings fresnel_config.h turns away): the
# list above misses nothing.
awk -F '\t' '{ s = $2; gsub(/defined[ \t]*\([ \t]*[A-Za-z0-9_]+[ \t]*\)/, "", s)
    while (match(s, /(^|[^A-Za-z0-9_])(fresnel|FRESNEL)_[A-Za-z0-9_]*/)) {
        w = substr(s, RSTART, RLENGTH); sub(/^[^A-Za-z_]/, "", w); print w; s = substr(s, RSTART + RLENGTH) } }' "$t/code" |
    sort -u >"$t/used"
awk '{ print $2 }' "$t/defs" "$t/aliases" | sort -u >"$t/defined"
undefined=$(comm -23 "$t/used" "$t/defined" | tr '\n' ' ')
[ -z "$undefined" ] || echo "FAIL public names: used in include/*.h but defined by no line the test reads: $undefined"
if [ -f "$lib" ]; then
    nm -g --defined-only "$lib" | awk 'NF == 3 && $2 ~ /[TDR]/ { print $3 }' | grep -v '^fresnel_i_' | sort -u >"$t/exported"
    awk '$1 == "function" { print $2 }' "$t/defs" | sort -u >"$t/declared"
    hidden=$(comm -23 "$t/exported" "$t/declared" | tr '\n' ' ')
    [ -z "$hidden" ] && echo "PASS public names: every function $lib defines is one include/*.h declares" ||
        echo "FAIL public names: $lib defines functions no header declares: $hidden"
fi
# The rule's words, from fresnel.h's NAMING section.
awk '/^ \* NAMING/ { on = 1 } /^ \* CONVENTIONS/ { on = 0 } on { sub(/^ \*/, ""); printf "%s ", $0 }' include/fresnel.h |
    grep -oE '[A-Za-z_]+ = [A-Za-z0-9_ ]+;' | sed 's/ = /=/; s/;$//; s/  */ /g' >"$t/words"
ls include/fresnel*.h | sed 's|.*/fresnel||; s|\.h$||; s|^_||' | tr 'a-z' 'A-Z' | tr '\n' ' ' >"$t/headers"
awk -v WORDS="$t/words" -v HEADERS="$t/headers" -v ALIASES="$t/aliases" '
function alt(list,   a) { a = list; gsub(/ /, "|", a); return "(" a ")" }
function opt(list,   n, i, w, r) { n = split(list, w, " "); r = ""; for (i = 1; i <= n; i++) r = r "(_" w[i] ")?"; return r }
function bad(kind, n, h, why) { printf "FAIL public names: %s %s (%s) %s\n", kind, n, h, why; nbad++ }
BEGIN {
    while ((getline l < WORDS) > 0) { k = l; sub(/=.*/, "", k); v = l; sub(/^[^=]*=/, "", v); W[k] = v }
    need = "model form storage type call quantity number table operation integer TYPE QUALIFIER QUANTITY LIMIT SIZE FLAG FEATURE"
    nn = split(need, nw, " ")
    for (i = 1; i <= nn; i++) if (!(nw[i] in W)) { printf "FAIL public names: fresnel.h NAMING has no word list \"%s = ...;\"\n", nw[i]; nbad++ }
    MODEL = alt(W["model"]); FORMS = opt(W["form"]); TY = alt(W["type"])
    core = MODEL FORMS "(_avg)?"
    fn_re = "^fresnel_" core "(_" alt(W["storage"]) ")?(_" TY ")?(_rgb)?(_" alt(W["call"]) ")?$"
    what = "(" substr(MODEL, 2, length(MODEL) - 2) "|" substr(alt(W["quantity"]), 2)
    prepare_re = "^fresnel_" what "_prepare(_" TY ")?$"
    prep_re = "^fresnel_" what "_prep(_" TY ")?(_fast)?$"
    type_re = "^fresnel_" what "(_node)?(_" TY ")?$"
    number_re = "^fresnel_" alt(W["number"]) "$"
    table_re = "^fresnel_" MODEL FORMS "_" alt(W["table"]) "_" TY "$"
    util_re = "^fresnel_" alt(W["operation"]) "_" alt(W["integer"]) "$"
    UM = toupper(MODEL); UF = toupper(FORMS)
    tail = "(_" alt(W["TYPE"]) ")?(_FAST)?(_" alt(W["QUALIFIER"]) ")?$"
    bound_re = "^FRESNEL_(BOUND|DOMAIN)(_" UM UF "(_AVG)?)?" tail
    limit_re = "^FRESNEL_(" UM "_)?" alt(W["QUANTITY"]) "_" alt(W["LIMIT"]) tail
    const_re = "^FRESNEL_(ONE|VERSION|" UM "_" alt(W["SIZE"]) ")" tail
    config_re = "^FRESNEL_(CONFIG|CFG_" alt(W["FLAG"]) "|HAS_" alt(W["FEATURE"]) ")$"
    getline hl < HEADERS; gsub(/ +$/, "", hl); gsub(/ +/, "|", hl); gsub(/\|\|/, "|", hl)
    guard_re = "^FRESNEL(_(" hl "))?_H$"
    while ((getline l < ALIASES) > 0) { split(l, f, " "); alias_of[f[2]] = f[4]; alias_h[f[2]] = f[3] }
}
{ kind[$2] = $1; hdr[$2] = $3; names[++nn2] = $2 }
END {
    # what each function provides to the BOUND_/DOMAIN_ check: core|type|fast
    for (i = 1; i <= nn2; i++) {
        n = names[i]; if (kind[n] != "function" || n !~ fn_re) continue
        c = substr(n, 9); ty = ""; fast = ""
        if (c ~ /_(fast|batch)$/) { fast = (c ~ /_fast$/) ? "_FAST" : ""; sub(/_(fast|batch)$/, "", c) }
        sub(/_rgb$/, "", c)
        if (match(c, "_" TY "$")) { ty = toupper(substr(c, RSTART)); c = substr(c, 1, RSTART - 1) }
        c = toupper(c); gsub("_" toupper(alt(W["storage"])) "$", "", c)
        provides[c "|" ty "|" fast] = 1; provides["|" ty "|" fast] = 1
        m = c; sub(/_.*/, "", m); provides[m "|" ty "|" fast] = 1
    }
    for (i = 1; i <= nn2; i++) {
        n = names[i]; k = kind[n]; h = hdr[n]
        if (n ~ /^(fresnel_i_|FRESNEL_I_)/) continue
        if (n in alias_of) {
            if (!(alias_of[n] in kind)) bad("alias", n, h, "stands for " alias_of[n] ", which no header defines")
            continue
        }
        if (k == "function") {
            if (n ~ prepare_re) { p = n; sub(/_prepare/, "_prep", p); if (kind[p] != "type") bad(k, n, h, "returns no " p) }
            else if (n !~ fn_re && n !~ util_re)
                bad(k, n, h, "is not fresnel_<model>[_<form>...][_avg][_<storage>][_<type>][_rgb][_<call>], a _prepare or a utility")
        } else if (k == "type") {
            if (n ~ prep_re) { p = n; sub(/_prep/, "_prepare", p); if (n !~ /_fast$/ && kind[p] != "function") bad(k, n, h, "has no " p) }
            else if (n !~ type_re && n !~ number_re) bad(k, n, h, "is not fresnel_<model or quantity>[_node][_<type>] or a number type")
        } else if (k == "table") {
            if (n !~ table_re) bad(k, n, h, "is not fresnel_<model>[_<form>...]_<table>_<type>")
        } else if (k == "macro") {
            if (n ~ /^FRESNEL_(BOUND|DOMAIN)(_|$)/) {
                if (n !~ bound_re) { bad(k, n, h, "is not FRESNEL_BOUND_<F>[_<TYPE>][_FAST][_<QUALIFIER>]"); continue }
                c = n; sub(/^FRESNEL_(BOUND|DOMAIN)_?/, "", c); sub("(_" alt(W["QUALIFIER"]) ")$", "", c)
                fast = ""; if (c ~ /(^|_)FAST$/) { fast = "_FAST"; sub(/_?FAST$/, "", c) }
                ty = ""; if (match(c, "(^|_)" alt(W["TYPE"]) "$")) { ty = substr(c, RSTART); if (ty !~ /^_/) ty = "_" ty; c = substr(c, 1, RSTART - 1) }
                if (!((c "|" ty "|" fast) in provides))
                    bad(k, n, h, "bounds no function (" (c == "" ? "every model" : "fresnel_" tolower(c)) tolower(ty) tolower(fast) ")")
            } else if (n !~ limit_re && n !~ const_re && n !~ config_re && n !~ guard_re)
                bad(k, n, h, "is not FRESNEL_<NAME>[_<TYPE>][_FAST][_<QUALIFIER>] with a NAME of the rule")
        }
        checked++
    }
    if (!nbad) printf "PASS public names: the %d public names of include/*.h follow fresnel.h NAMING\n", checked
    exit nbad > 0
}' "$t/defs"
