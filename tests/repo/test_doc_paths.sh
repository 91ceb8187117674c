#!/bin/sh
# passes: first (the same in every build)
# Every path a text of the repository names is in the tree: docs, comments,
# help and messages (tests/repo/text_files.sh lists the files) may name a file or
# folder only as it is. One FAIL line per path that is not, as file:line.
#
# A path is a word with a slash whose first part is one of the tree's
# top-level folders (src/f32/lut.c), from the root; or, from the naming
# file's folder, one of its parents or a top-level folder, a word whose
# first part is a deeper folder's name (common/reference.c in gen/); or a
# ../ path from the naming file's folder (not in shell scripts, whose paths
# are the working directory's). Globs need one match: *, and a <placeholder>
# as *, make's % as any run of characters, {a,b} as either, a trailing ... as *. A document in
# capitals (README.md) needs to exist beside the naming file, in a folder
# above it, or at the root, and a bare glob (load_*.c) to match a file.
# Not paths of the tree: build/... (what the build makes), URLs, words
# after / $ ~ @ (absolute paths, $(BUILD)/...), other projects' sources that
# begin with one of our folder names (pbrt's src/pbrt/, Mitsuba's
# include/mitsuba/: `foreign` below).
foreign='^(src/pbrt|include/mitsuba)(/|$)'
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sh tests/repo/text_files.sh -a >"$t/tree"
sh tests/repo/text_files.sh >"$t/files"
[ -s "$t/files" ] || { echo "FAIL doc paths: no text files listed (tests/repo/text_files.sh)"; exit 1; }
# shellcheck disable=SC2046 # one path per line, no spaces (git ls-files)
awk -v TREE="$t/tree" -v FOREIGN="$foreign" '
BEGIN {
    while ((getline p < TREE) > 0) {
        all[++na] = p
        have[p] = 1
        if (p ~ /\/$/) {
            d = substr(p, 1, length(p) - 1)
            if (d !~ /\//) top[d] = 1
            else { n = split(d, part, "/"); deeper[part[n]] = 1 }
        } else {
            n = split(p, part, "/"); base[part[n]] = 1
        }
    }
}
function globre(p,   re, alt) {
    re = p
    gsub(/[.+^$()|]/, "\\\\&", re)
    gsub(/\*/, "[^/]*", re)
    gsub(/%/, ".*", re)
    while (match(re, /\{[^}]*\}/)) {
        alt = substr(re, RSTART + 1, RLENGTH - 2)
        gsub(/,/, "|", alt)
        re = substr(re, 1, RSTART - 1) "(" alt ")" substr(re, RSTART + RLENGTH)
    }
    return "^" re "$"
}
function exists(p,   re, i) {
    if (p in have) return 1
    if (p !~ /[*{%]/) return (p "/") in have
    re = globre(p)
    for (i = 1; i <= na; i++) if (all[i] ~ re || all[i] ~ substr(re, 1, length(re) - 1) "/$") return 1
    return 0
}
function parent(d) { if (d ~ /\//) { sub(/\/[^\/]*$/, "", d); return d } return "" }
# exists from the folder d or one above it
function from_above(d, p) {
    while (1) {
        if (exists((d == "" ? "" : d "/") p)) return 1
        if (d == "") return 0
        d = parent(d)
    }
}
function stale(p) { printf "FAIL doc paths: %s:%d: %s is not in the tree\n", FILENAME, FNR, p; bad++ }
FNR == 1 { dir = parent(FILENAME); shell = FILENAME ~ /\.sh$/; carry = "" }
{
    line = $0
    # a path broken at the end of the line above (gen/common/ | reference.c;
    # not src/f16/ | are)
    if (carry != "" && match(line, /^[ \t]*([*#]|\/\/|--)?[ \t]*[A-Za-z0-9_.*{}-]+/)) {
        w = substr(line, RSTART, RLENGTH); sub(/^[ \t]*([*#]|\/\/|--)?[ \t]*/, "", w)
        if (w ~ /[._*]/) line = carry w substr(line, RSTART + RLENGTH)
    }
    carry = ""
    if (match($0, /[A-Za-z0-9_.-]+\/[A-Za-z0-9_.\/-]*\/$/) && substr($0, RSTART - 1, 1) !~ /[\/$~@]/) carry = substr($0, RSTART, RLENGTH)
    gsub(/[A-Za-z][A-Za-z0-9+.-]*:\/\/[^ \t)>"'\''`]*/, " ", line)
    rest = line
    while (match(rest, /[A-Za-z0-9_.*%<>{},\\-]*[A-Za-z0-9_.*%<>{}\\]\/[A-Za-z0-9_.*%<>{},\\\/-]*/)) {
        tok = substr(rest, RSTART, RLENGTH)
        pre = RSTART > 1 ? substr(rest, RSTART - 1, 1) : ""
        rest = substr(rest, RSTART + RLENGTH)
        if (pre ~ /[\/$~@]/) continue
        sub(/\\n.*/, "", tok); sub(/<\/.*/, "", tok); sub(/^-[IL]/, "", tok)
        gsub(/\\\*/, "*", tok); gsub(/<[^<>\/]*>/, "*", tok)
        if (tok !~ /\{/) { sub(/,.*/, "", tok); sub(/\}.*/, "", tok) }
        sub(/\.\.\.$/, "*", tok)
        sub(/[.,:;\\]+$/, "", tok)
        first = tok; sub(/\/.*/, "", first)
        checked++
        if (first in top) {
            if (tok !~ FOREIGN && !exists(tok)) stale(tok)
        } else if (first == ".." && !shell) {
            p = tok; d = dir
            while (p ~ /^\.\.\//) { if (d == "") break; d = parent(d); p = substr(p, 4) }
            if (p !~ /^\.\.\// && !exists((d == "" ? "" : d "/") p)) stale(tok)
        } else if (first in deeper) {
            ok = from_above(dir, tok)
            for (f in top) if (!ok && exists(f "/" tok)) ok = 1
            if (!ok) stale(tok)
        } else checked--
    }
    rest = line
    while (match(rest, /(^|[^A-Za-z0-9_.\/<-])([A-Z][A-Z0-9_]*\.md|[A-Za-z0-9_]*(\*|<[a-z_]+>)[A-Za-z0-9_*]*\.[ch])([^A-Za-z0-9_\/]|$)/)) {
        tok = substr(rest, RSTART, RLENGTH)
        rest = substr(rest, RSTART + RLENGTH - 1)
        sub(/^[^A-Za-z0-9_*<]/, "", tok); sub(/[^A-Za-z0-9_*>]$/, "", tok)
        checked++
        if (tok ~ /\.md$/) { if (!from_above(dir, tok)) stale(tok); continue }
        gsub(/<[a-z_]+>/, "*", tok)
        re = globre(tok); ok = 0
        for (b in base) if (b ~ re) { ok = 1; break }
        if (!ok) stale(tok)
    }
}
END {
    if (!bad) printf "PASS doc paths: the %d paths named in %d text files are in the tree\n", checked, files
    exit bad > 0
}
FNR == 1 { files++ }
' $(cat "$t/files")
