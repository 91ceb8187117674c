#!/bin/sh
# passes: first (the same in every build)
# The product speaks of the product as it is: its docs, comments, help and
# messages (tests/repo/text_files.sh lists them), and its file names, tell of no
# work history: no issues or findings and their labels (F7), nothing fixed,
# reported or renamed along the way, no older names, versions or code. Work
# history belongs in commit messages. One FAIL line per hit, as file:line.
#
# The wording caught (case-insensitive unless said):
#   issue(s), finding(s); a label F<number> other than the quantities F0,
#   F82, F90 and the number types F16, F32, F64 (case-sensitive); is/are/was fixed (in, by, now, here, or at
#   the end of a clause), "(fixed)", "(reported)", "once reported/found";
#   "the old ..." and "the older ..."; "previously", "used to be", "no
#   longer"; earlier, older, previous or former version(s), release(s),
#   name(s), code, form(s); before the change/commit/fix/rename; before,
#   after, since or in commit; the working tree; when this was written.
# tests/repo/product_text.allow lists the few lines where such a word means
# something else (SCHOTT's glass F5), each with its reason; an entry that
# matches nothing, or has no reason, is a failure too.
# --words prints the case-insensitive pattern of the wording, for the checks
# of what the tool prints (tests/tool/test_cli_conventions.sh).
words='\b(issues?|findings?|previously|used to be|no longer|working tree|when this was written)\b'
words="$words"'|\b(is|are|was|were|been) fixed([.,;:)]|$| (in|by|now|here)\b)|(^|[ \t])\((fixed|reported)\)|\bonce (reported|found)\b'
words="$words"'|\bthe old(er)? [a-z]|\b(earlier|older|previous|former) (versions?|releases?|names?|code|forms?)\b'
words="$words"'|\bbefore (the|this) (change|commit|fix|rename)|\b(before|after|since|in) commit\b'
[ "$1" = --words ] && { printf '%s\n' "$words"; exit 0; }
allow=tests/repo/product_text.allow
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
sh tests/repo/text_files.sh >"$t/files"
# shellcheck disable=SC2046 # one path per line, no spaces (git ls-files)
{
    grep -nHEi "$words" $(cat "$t/files")
    grep -nHE '\bF[0-9]+\b' $(cat "$t/files") |
        awk '{ s = $0; sub(/^[^:]*:[0-9]+:/, "", s); n = 0
               while (match(s, /(^|[^A-Za-z0-9_])F[0-9]+([^A-Za-z0-9_]|$)/)) {
                   w = substr(s, RSTART, RLENGTH); gsub(/[^F0-9]/, "", w)
                   if (w !~ /^F(0|82|90|16|32|64)$/) n++
                   s = substr(s, RSTART + RLENGTH - 1) }
               if (n) print }'
    sh tests/repo/text_files.sh -a | grep -Ei 'issue|finding' | sed 's/$/:0:(a file name)/'
} | sort -u >"$t/hits"
awk -v ALLOW="$allow" '
BEGIN {
    FS = "\n"
    while ((getline l < ALLOW) > 0) {
        nl++
        if (l ~ /^#/ || l ~ /^[ \t]*$/) continue
        n = split(l, f, "|")
        if (n < 3 || f[1] == "" || f[2] == "" || f[3] ~ /^[ \t]*$/) {
            printf "FAIL product text: %s:%d: an entry is path|regex|reason: %s\n", ALLOW, nl, l; bad++; continue
        }
        na++; path[na] = f[1]; re[na] = f[2]; line[na] = nl
    }
}
{
    file = $0; sub(/:.*/, "", file)
    text = $0; sub(/^[^:]*:[0-9]+:/, "", text)
    for (i = 1; i <= na; i++) if (path[i] == file && text ~ re[i]) { used[i] = 1; next }
    printf "FAIL product text: %s\n", $0; bad++
}
END {
    for (i = 1; i <= na; i++) if (!used[i]) { printf "FAIL product text: %s:%d: allows a line no text has: %s|%s\n", ALLOW, line[i], path[i], re[i]; bad++ }
    if (!bad) printf "PASS product text: no work history in the docs, comments, messages or file names (%d allowed lines, %s)\n", na, ALLOW
    exit bad > 0
}' "$t/hits"
