#!/bin/sh
# passes: first (reads sources only; the same in every pass)
# Every public function is exercised by a test: each fresnel_* function that
# include/*.h declares (or defines static inline), less the runtime's
# internal helpers fresnel_i_* (include/fresnel.h, NAMING), is called by name in the
# code of at least one file under tests/ (C outside its comments, a script
# outside its comment lines). One FAIL line names every function that none
# calls; the PASS line gives how many there are.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
# strip_c FILE...: the files without their C comments and string contents
strip_c() {
    awk '
    FNR == 1 { inc = 0 }
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
      print out }' "$@"
}
# The public functions: a declaration or definition at the start of a line of
# a header's code, return type first (the rule of tests/repo/test_public_names.sh).
for h in include/*.h; do
    strip_c "$h" | awk -v H="$h" '
        /^[A-Za-z_][A-Za-z0-9_ \t*]*[ \t*]fresnel_[A-Za-z0-9_]*\(/ && !/^(return|typedef|#)/ {
            n = $0; sub(/\(.*/, "", n); sub(/.*[ \t*]/, "", n); if (n !~ /^fresnel_i_/) print n }'
done | sort -u >"$t/public"
n=$(wc -l <"$t/public")
[ "$n" -gt 0 ] || { echo "FAIL public functions tested: no function found in include/*.h"; exit 1; }
# The code of the tests: every C source or header under tests/, every script.
find tests -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) -not -path 'tests/fuzz/corpus/*' | sort >"$t/c"
find tests -type f -name '*.sh' | sort >"$t/sh"
{
    # shellcheck disable=SC2046 # paths without spaces (the tree's)
    strip_c $(cat "$t/c")
    # shellcheck disable=SC2046
    sed 's/^[ \t]*#.*//' $(cat "$t/sh")
} | grep -oE '(^|[^A-Za-z0-9_])fresnel_[A-Za-z0-9_]+' | sed 's/^[^f]//' | sort -u >"$t/named"
missing=$(comm -23 "$t/public" "$t/named" | tr '\n' ' ')
if [ -z "$missing" ]; then
    echo "PASS public functions tested: each of the $n fresnel_* functions of include/*.h is called in the code of a test under tests/"
else
    echo "FAIL public functions tested: $(comm -23 "$t/public" "$t/named" | wc -l) of $n functions of include/*.h are named by no test under tests/: $missing"
fi
