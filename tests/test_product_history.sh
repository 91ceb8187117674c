#!/bin/sh
# The product speaks of the product: no tracked source, test or document
# tells the work's history (an issue or finding number, "the old version",
# "when this was written", "before commit"); that belongs in commit messages.
[ "$BUILD" = build ] || exit 0 # text of the tree; once is enough
pattern='issue[- ]?[0-9]|fixed-point issue|when this was written|in the working tree|the old (version|code|nodes|scheme|format)|before commit|finding F[0-9]'
if ! command -v git >/dev/null 2>&1 || ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(find . -path ./build -prune -o -type f \( -name '*.[ch]' -o -name '*.md' -o -name '*.sh' -o -name '*.glsl' -o -name '*.hlsl' -o -name '*.html' -o -name Makefile -o -name '*.mk' \) -print)
else
    files=$(git ls-files '*.[ch]' '*.md' '*.sh' '*.glsl' '*.hlsl' '*.html' Makefile '*.mk')
fi
hits=$(echo "$files" | grep -v '^\(\./\)\?tests/test_product_history.sh$' | xargs grep -nIiE "$pattern" 2>/dev/null)
if [ -z "$hits" ]; then
    echo "PASS no source, test or document tells the work's history ($(echo "$files" | wc -l) files)"
else
    echo "FAIL work history in the tree: $(echo "$hits" | head -5 | cut -c1-160)"
fi
