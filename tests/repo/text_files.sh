#!/bin/sh
# Prints the repository's own text files, one path per line, for the checks
# that read what the product says (tests/repo/test_doc_paths.sh,
# tests/repo/test_product_text.sh): the files git tracks or would add (every
# file below the working directory outside build/ where there is no git),
# less the inputs
# that are data rather than text: the fuzzers' seed corpus, measured spectra
# and users' sample files (csv, yml, nk, spd), images, the licence.
# With -a it prints every path of the tree instead (files and folders, a
# folder with a trailing /), which is what "exists" means for a path a text
# names.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    list() { git ls-files --cached --others --exclude-standard | sort -u; }
else
    list() { find . -path ./build -prune -o -path ./.git -prune -o -type f -print | sed 's|^\./||'; }
fi
if [ "$1" = -a ]; then
    list | awk '{ print; p = $0; while (sub(/\/[^\/]*$/, "", p)) d[p "/"] = 1 } END { for (p in d) print p }' | sort
else
    list | grep -vE '^tests/fuzz/corpus/|\.(csv|yml|nk|spd|png|svg)$|^LICENSE$|(^|/)\.gitignore$' | sort
fi
