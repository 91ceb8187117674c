#!/bin/sh
# passes: first (text against text)
# The single-file runtimes committed in ports/single/ (for users who vendor
# one file without building) are what ports/single.sh writes from the
# sources: the working copy (which make rewrites when the sources change)
# and, in a git checkout, the copy in git's index. (How they build and what
# they compute: tests/ports/test_single_file.sh.)
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
single=ports/single

for type in f32 q15 f16; do
    if sh ports/single.sh $type >"$t/fresnel_single_$type.h" 2>"$t/err"; then
        f=$single/fresnel_single_$type.h
        if [ ! -f "$f" ]; then
            echo "FAIL $f: missing (make writes it; commit it)"
        elif ! cmp -s "$f" "$t/fresnel_single_$type.h"; then
            echo "FAIL $f is not what ports/single.sh $type writes from the sources (run make, commit it)"
        elif ! command -v git >/dev/null || ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
            echo "PASS $f is what ports/single.sh $type writes (not a git checkout: no committed copy to compare)"
        elif ! git ls-files --error-unmatch "$f" >/dev/null 2>&1; then
            echo "FAIL $f is not committed (git add it)"
        elif ! git diff --quiet -- "$f"; then
            echo "FAIL $f: the committed copy is not what the sources give ($(git diff --stat -- "$f" | tail -1); commit it)"
        else
            echo "PASS $f, as committed, is what ports/single.sh $type writes from the sources"
        fi
    else
        echo "FAIL ports/single.sh $type: $(head -3 "$t/err")"
    fi
done

