#!/bin/sh
# passes: first (a shell script: once is enough)
# make uninstall (ports/install.sh uninstall) trusts nothing in
# install_manifest.txt: a line that leads outside DESTDIR/PREFIX ("f ../..",
# an absolute path, a directory reached through a symbolic link) is refused
# with a message and exit 1, the rest is still removed, and every manifest
# ends (a malformed up-level line such as "d .x" included).
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
pass() { echo "PASS uninstall: $1"; }
fail() { echo "FAIL uninstall: $1"; }
P=/opt/fresnel
# stage DIR LINE...: DESTDIR=DIR/root with PREFIX's share/fresnel/x.txt
# installed, a victim file beside DESTDIR, and a manifest of the given lines
# (then the file and the manifest themselves)
stage() {
    d=$1
    shift
    mkdir -p "$d/root$P/share/fresnel"
    echo victim >"$d/victim"
    echo installed >"$d/root$P/share/fresnel/x.txt"
    { printf '%s\n' "$@"; echo "f share/fresnel/x.txt"; echo "f share/fresnel/install_manifest.txt"; } \
        >"$d/root$P/share/fresnel/install_manifest.txt"
}
run() { # dir: uninstall with a time limit; sets rc
    timeout 20 sh ports/install.sh uninstall "$1/root" "$P" >"$1/out" 2>"$1/err"
    rc=$?
}

for line in "f ../../../victim" "f $t/a/victim" "f share/../../../../victim" "d ../../.."; do
    rm -rf "$t/a"
    stage "$t/a" "$line"
    run "$t/a"
    if [ "$rc" -eq 1 ] && [ -f "$t/a/victim" ] && [ ! -e "$t/a/root$P/share/fresnel/x.txt" ] &&
        grep -q "refusing manifest line" "$t/a/err"; then
        pass "'$(echo "$line" | sed "s|$t|\$t|")' refused, exit 1, the installed file removed, the file outside kept ($(head -1 "$t/a/err" | sed "s|$t/||g"))"
    else fail "'$line': exit $rc, victim $([ -f "$t/a/victim" ] && echo kept || echo REMOVED), $(cat "$t/a/err")"; fi
done

# a directory of the prefix replaced by a link to the outside
rm -rf "$t/b"
stage "$t/b"
mkdir "$t/b/outside"
echo victim >"$t/b/outside/y.txt"
ln -s "$t/b/outside" "$t/b/root$P/lib"
printf 'f lib/y.txt\n' >>"$t/b/root$P/share/fresnel/install_manifest.txt"
run "$t/b"
[ "$rc" -eq 1 ] && [ -f "$t/b/outside/y.txt" ] && grep -q "outside" "$t/b/err" &&
    pass "a file reached through a symbolic link out of the prefix is refused" ||
    fail "link out of the prefix: exit $rc, $(cat "$t/b/err")"

# malformed up-level lines end (the loop that walked up never did) and are refused
for line in "d .x" "d ./x" "d ./../../../../../../../../.."; do
    rm -rf "$t/c"
    stage "$t/c" "$line"
    run "$t/c"
    if [ "$rc" -eq 1 ] && grep -q "refusing manifest line '$line'" "$t/c/err"; then
        pass "'$line' ends and is refused ($(head -1 "$t/c/err" | sed "s|$t/||g"))"
    else fail "'$line': exit $rc (124: did not end), $(cat "$t/c/err")"; fi
done

# a clean manifest: everything removed, up to the DESTDIR the install made
rm -rf "$t/d"
stage "$t/d" "d ." "d ./.." "d ./../.." "d share" "d share/fresnel"
run "$t/d"
[ "$rc" -eq 0 ] && [ ! -e "$t/d/root" ] && [ -f "$t/d/victim" ] &&
    pass "a clean manifest: exit 0, DESTDIR/PREFIX and the levels the install made removed, nothing else" ||
    fail "clean manifest: exit $rc, left $(find "$t/d" | sed "s|$t/||g" | tr '\n' ' ') $(cat "$t/d/err")"
