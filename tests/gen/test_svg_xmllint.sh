#!/bin/sh
# make check: no (xmllint)
# The SVG writer's sample plot (build/tests/test_svg --write) is well-formed
# XML by a real parser, xmllint from Debian's libxml2-utils (.ci/run installs
# it). A missing xmllint is a failure, not a skip: this is the check that
# the report's plots open anywhere.
T="$BUILD/tests/test_svg"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if ! command -v xmllint >/dev/null 2>&1; then
    echo "FAIL svg: xmllint not found (apt-get install libxml2-utils)"
    exit 1
fi
if "$T" --write "$t/a.svg" && "$T" --write "$t/b.svg"; then
    echo "PASS svg: sample plot written twice"
else
    echo "FAIL svg: $T --write failed"
    exit 1
fi
if xmllint --noout "$t/a.svg" 2>"$t/err"; then
    echo "PASS svg: sample plot is well-formed XML (xmllint)"
else
    echo "FAIL svg: xmllint: $(head -3 "$t/err")"
fi
cmp -s "$t/a.svg" "$t/b.svg" && echo "PASS svg: two writes byte-identical (cmp)" ||
    echo "FAIL svg: two writes differ"
