#!/bin/sh
# Output files and streams of the fresnel tool: `gen -o` never clobbers what
# it should not, never follows a planted name, never leaves a partial file
# or a temporary; every command reports a failed write or read with exit 1.
F="$BUILD/fresnel"
case $F in /*) ;; *) F="$PWD/$F" ;; esac
t=$(mktemp -d)
trap 'chmod -R u+w "$t" 2>/dev/null; rm -rf "$t"' EXIT
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1"; }
printf 'materials = au cu\nmodels = schlick f82\n' >"$t/s.scene"
"$F" gen "$t/s.scene" -o "$t/ref.h" 2>"$t/err" || fail "gen reference header: $(cat "$t/err")"
no_temps() { # dir: no .NAME.XXXXXX temporaries left
    [ -z "$(find "$1" -name '.*.??????' 2>/dev/null)" ]
}

# A regular file is replaced and keeps its mode.
printf 'old\n' >"$t/reg.h"; chmod 600 "$t/reg.h"
"$F" gen "$t/s.scene" -o "$t/reg.h" 2>"$t/err" && cmp -s "$t/reg.h" "$t/ref.h" &&
    [ "$(stat -c %a "$t/reg.h")" = 600 ] && no_temps "$t" &&
    pass "gen -o regular file: replaced, mode 0600 kept" || fail "gen -o regular file: mode $(stat -c %a "$t/reg.h") $(cat "$t/err")"
# A new file gets 0666 minus the umask.
(umask 027; "$F" gen "$t/s.scene" -o "$t/new.h") && [ "$(stat -c %a "$t/new.h")" = 640 ] &&
    pass "gen -o new file: mode from the umask (640 under 027)" || fail "gen -o new file: mode $(stat -c %a "$t/new.h")"

# A symlink: the target is written, the link stays a link.
mkdir "$t/real"; printf 'old\n' >"$t/real/target.h"; chmod 640 "$t/real/target.h"
ln -s real/target.h "$t/link.h"
"$F" gen "$t/s.scene" -o "$t/link.h" 2>"$t/err" && [ -L "$t/link.h" ] && cmp -s "$t/real/target.h" "$t/ref.h" &&
    [ "$(stat -c %a "$t/real/target.h")" = 640 ] && no_temps "$t" &&
    pass "gen -o symlink: target replaced (mode kept), link kept" || fail "gen -o symlink: $(ls -l "$t/link.h") $(cat "$t/err")"
# A dangling symlink: its target is created.
ln -s real/dangling.h "$t/dangle.h"
"$F" gen "$t/s.scene" -o "$t/dangle.h" 2>"$t/err" && [ -L "$t/dangle.h" ] && cmp -s "$t/real/dangling.h" "$t/ref.h" &&
    pass "gen -o dangling symlink: target created, link kept" || fail "gen -o dangling symlink: $(cat "$t/err")"

# Devices are written in place, never replaced. Private nodes of the same
# devices (root can make them) keep a regression from replacing the
# system's /dev/null; without them this part is skipped.
if mknod -m 666 "$t/null" c 1 3 2>/dev/null && mknod -m 666 "$t/full" c 1 7 2>/dev/null; then
    "$F" gen "$t/s.scene" -o "$t/null" 2>"$t/err" && [ -c "$t/null" ] &&
        pass "gen -o a null device: exit 0, still a device" || fail "gen -o null device: $(cat "$t/err"); $(ls -l "$t/null")"
    "$F" gen "$t/s.scene" -o "$t/full" 2>"$t/err"; rc=$?
    [ $rc -eq 1 ] && grep -q "$t/full" "$t/err" && [ -c "$t/full" ] &&
        pass "gen -o a full device: exit 1 naming it ($(cat "$t/err"))" || fail "gen -o full device: exit $rc $(cat "$t/err")"
else
    echo "NOTE device nodes cannot be made here (not root): gen -o DEVICE not tested"
fi
# A FIFO is written in place.
mkfifo "$t/fifo"
timeout 20 cat "$t/fifo" >"$t/fifo.out" &
reader=$!
timeout 20 "$F" gen "$t/s.scene" -o "$t/fifo" 2>"$t/err"; rc=$?
[ -p "$t/fifo" ] || kill $reader 2>/dev/null
wait $reader
[ $rc -eq 0 ] && [ -p "$t/fifo" ] && cmp -s "$t/fifo.out" "$t/ref.h" &&
    pass "gen -o FIFO: written through, still a FIFO" || fail "gen -o FIFO: exit $rc $(cat "$t/err")"
# -o - is stdout.
(cd "$t" && "$F" gen s.scene -o - >stdout.h 2>err) && cmp -s "$t/stdout.h" "$t/ref.h" && [ ! -e "$t/-" ] &&
    pass "gen -o - writes to stdout" || fail "gen -o -: $(cat "$t/err")"
"$F" gen "$t/s.scene" -o - >/dev/full 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && grep -q '<stdout>' "$t/err" && pass "gen -o - >/dev/full: exit 1 naming <stdout>" ||
    fail "gen -o - >/dev/full: exit $rc $(cat "$t/err")"

# /dev/stdout: a pipe (no path behind it) and a file opened for appending.
"$F" gen "$t/s.scene" -o /dev/stdout 2>"$t/err" | cat >"$t/pipe.h" && cmp -s "$t/pipe.h" "$t/ref.h" &&
    pass "gen -o /dev/stdout into a pipe" || fail "gen -o /dev/stdout | cat: $(cat "$t/err")"
printf 'first\n' >"$t/log"
"$F" gen "$t/s.scene" -o /dev/stdout >>"$t/log" 2>"$t/err" && [ "$(head -1 "$t/log")" = first ] &&
    [ "$(($(wc -l <"$t/ref.h") + 1))" -eq "$(wc -l <"$t/log")" ] &&
    pass "gen -o /dev/stdout >>LOG appends" || fail "gen -o /dev/stdout >>LOG: $(head -2 "$t/log") $(cat "$t/err")"

# A read-only file is an error and stays as it was.
printf 'keep\n' >"$t/ro.h"; chmod 444 "$t/ro.h"
"$F" gen "$t/s.scene" -o "$t/ro.h" 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$t/ro.h")" = keep ] && [ "$(stat -c %a "$t/ro.h")" = 444 ] && no_temps "$t" &&
    pass "gen -o read-only file: exit 1, untouched ($(cat "$t/err"))" || fail "gen -o read-only: exit $rc, $(cat "$t/ro.h")"
# The manifest itself, directly or through a link, is refused.
cp "$t/s.scene" "$t/keep.scene"
"$F" gen "$t/s.scene" -o "$t/s.scene" 2>"$t/err"; rc=$?
[ $rc -eq 2 ] && cmp -s "$t/s.scene" "$t/keep.scene" && grep -q 'an input of this command' "$t/err" &&
    pass "gen -o MANIFEST: exit 2, manifest untouched" || fail "gen -o MANIFEST: exit $rc $(cat "$t/err")"
ln -s s.scene "$t/scene-link"
"$F" gen "$t/s.scene" -o "$t/scene-link" 2>"$t/err"; rc=$?
[ $rc -eq 2 ] && cmp -s "$t/s.scene" "$t/keep.scene" &&
    pass "gen -o link-to-MANIFEST: exit 2, manifest untouched" || fail "gen -o link-to-MANIFEST: exit $rc"
# A directory is an error.
"$F" gen "$t/s.scene" -o "$t/real" 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && [ -d "$t/real" ] && pass "gen -o DIR: exit 1" || fail "gen -o DIR: exit $rc $(cat "$t/err")"

# Names a temporary could be predicted at (OUT.tmp.PID for the next few
# pids) planted as symlinks to a victim: none is followed.
printf 'victim\n' >"$t/victim"
mkdir "$t/plant"
pid=$$
i=0
while [ $i -lt 200 ]; do ln -s ../victim "$t/plant/out.h.tmp.$((pid + i))"; i=$((i + 1)); done
"$F" gen "$t/s.scene" -o "$t/plant/out.h" 2>"$t/err" && [ "$(cat "$t/victim")" = victim ] &&
    cmp -s "$t/plant/out.h" "$t/ref.h" && [ "$(find "$t/plant" -type l | wc -l)" -eq 200 ] &&
    pass "planted symlinks at OUT.tmp.PID are not followed" || fail "planted symlinks: victim '$(head -c 40 "$t/victim")'"

# A file size limit mid-write: no partial output, no temporary.
printf 'old\n' >"$t/lim.h"
(ulimit -f 2; "$F" gen "$t/s.scene" -o "$t/lim.h") 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$t/lim.h")" = old ] && no_temps "$t" && grep -q 'lim.h' "$t/err" &&
    pass "ulimit -f: exit 1, output as it was, no temporary ($(head -1 "$t/err"))" ||
    fail "ulimit -f: exit $rc, $(head -c 40 "$t/lim.h"), temps: $(find "$t" -name '.*.??????') $(cat "$t/err")"

# Several outputs of one command commit together or not at all: gen's -o and
# --tables (the header over a size limit the texture fits, or a full
# device), report -o DIR's report.md and plots (one plot unwritable).
printf 'materials = au cu al ag\nmodels = schlick f82 lsk gulbrandsen lut8\n' >"$t/tex.scene"
echo keep >"$t/g.glsl"; echo keep >"$t/t.h"
# 8 blocks: 4096 bytes (POSIX's 512-byte blocks) or 8192 (bash's 1024)
(ulimit -f 8; "$F" gen "$t/tex.scene" --glsl -o "$t/g.glsl" --tables "$t/t.h") 2>"$t/err"; rc=$?
"$F" gen "$t/tex.scene" --glsl -o "$t/g0.glsl" --tables "$t/t0.h" 2>/dev/null
[ $rc -eq 1 ] && [ "$(cat "$t/g.glsl")" = keep ] && [ "$(cat "$t/t.h")" = keep ] && no_temps "$t" &&
    [ "$(wc -c <"$t/g0.glsl")" -gt 8192 ] && [ "$(wc -c <"$t/t0.h")" -lt 4096 ] &&
    pass "gen --glsl -o OUT --tables TEX, OUT over ulimit -f: exit 1, both as they were ($(head -1 "$t/err" | sed "s|$t/||"))" ||
    fail "gen --tables under ulimit -f: exit $rc, OUT '$(head -c 20 "$t/g.glsl")', TEX '$(head -c 20 "$t/t.h")' $(cat "$t/err")"
"$F" gen "$t/tex.scene" --glsl -o /dev/full --tables "$t/t2.h" 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && [ ! -e "$t/t2.h" ] && no_temps "$t" &&
    pass "gen --glsl -o /dev/full --tables TEX: exit 1, TEX not created" || fail "gen -o /dev/full --tables: exit $rc, $(ls "$t/t2.h" 2>&1) $(cat "$t/err")"
"$F" report --scene "$t/s.scene" -o "$t/rep3" --no-timing --no-instructions >/dev/null 2>"$t/err" && cp "$t/rep3/report.md" "$t/rep3.md"
rm "$t/rep3/curves/cu.svg"; mkdir "$t/rep3/curves/cu.svg"; echo old >"$t/rep3/report.md"
"$F" report --scene "$t/s.scene" -o "$t/rep3" --no-timing --no-instructions >/dev/null 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$t/rep3/report.md")" = old ] && no_temps "$t/rep3" &&
    pass "report -o DIR with one plot unwritable: exit 1, report.md as it was, no temporary" ||
    fail "report -o DIR, one plot unwritable: exit $rc, report.md '$(head -c 30 "$t/rep3/report.md")' $(cat "$t/err")"
"$F" report --scene "$t/s.scene" -o "$t/new/rep" --no-timing --no-instructions >/dev/null 2>"$t/err"; rc=$?
[ $rc -ne 0 ] && [ ! -e "$t/new" ] && pass "report -o DIR under a missing directory: exit $rc, nothing created" ||
    fail "report -o missing/DIR: exit $rc"
"$F" report --scene "$t/s.scene" -o "$t/rep5" --no-timing --no-instructions --cross "$t/missing" >/dev/null 2>"$t/err"; rc=$?
[ $rc -eq 2 ] && [ ! -e "$t/rep5" ] && pass "report -o DIR with a missing --cross file: exit 2, DIR not left behind" ||
    fail "report with a missing --cross: exit $rc, $(ls -R "$t/rep5" 2>&1 | head -3) $(cat "$t/err")"
(cd "$t" && "$F" report --scene s.scene -o - --no-timing --no-instructions >/dev/null 2>err); rc=$?
[ $rc -eq 2 ] && [ ! -e "$t/-" ] && grep -q 'expected a directory' "$t/err" &&
    pass "report -o -: exit 2, no directory named '-' ($(cat "$t/err"))" || fail "report -o -: exit $rc, $(ls -d "$t/-" 2>&1) $(cat "$t/err")"
# report reads --cross after opening report.md: that file is still not replaced
"$F" report --scene "$t/s.scene" -o "$t/rep6" --no-timing --no-instructions >/dev/null 2>&1
echo "== m0 fixed point" >"$t/rep6/report.md"; cp "$t/rep6/report.md" "$t/cross.keep"
"$F" report --scene "$t/s.scene" -o "$t/rep6" --no-timing --no-instructions --cross "$t/rep6/report.md" >/dev/null 2>"$t/err"; rc=$?
[ $rc -eq 2 ] && cmp -s "$t/rep6/report.md" "$t/cross.keep" && no_temps "$t/rep6" &&
    pass "report -o DIR --cross DIR/report.md: exit 2, the input untouched" || fail "report over its --cross file: exit $rc $(cat "$t/err")"

# Every command checks its stdout.
full() { # name, args...
    name=$1; shift
    "$F" "$@" </dev/null >/dev/full 2>"$t/err"; rc=$?
    [ $rc -eq 1 ] && grep -q '<stdout>' "$t/err" && pass "$name >/dev/full: exit 1 naming <stdout>" ||
        fail "$name >/dev/full: exit $rc $(cat "$t/err")"
}
printf '1.5,0,0.5\n' >"$t/one"
"$F" eval --model exact --type f32 <"$t/one" >/dev/full 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && grep -q '<stdout>' "$t/err" && pass "eval >/dev/full: exit 1 naming <stdout>" ||
    fail "eval >/dev/full: exit $rc $(cat "$t/err")"
full params params --material au
full curve curve --material au --samples 5
full extremes extremes
full accuracy accuracy --materials au --steps 10
full materials materials
full wavelengths wavelengths --space srgb
full version --version
full help --help
full "eval --help" eval --help
full "report" report --scene "$t/s.scene" -o "$t/rep" --no-timing --no-instructions
# report -o DIR goes through the same safe output: a full disk is not faked
# here, but an unwritable file in DIR is an error with nothing left behind.
mkdir -p "$t/rep2"; mkdir "$t/rep2/report.md"
"$F" report --scene "$t/s.scene" -o "$t/rep2" --no-timing --no-instructions >/dev/null 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && no_temps "$t/rep2" && pass "report -o DIR with report.md a directory: exit 1, no temporary" ||
    fail "report -o DIR: exit $rc $(cat "$t/err")"

# Read errors: a directory on stdin.
"$F" eval --model exact --type f32 <"$t" >"$t/out" 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && grep -q '<stdin>' "$t/err" && pass "eval </dir: exit 1 naming <stdin> ($(cat "$t/err"))" ||
    fail "eval </dir: exit $rc $(cat "$t/err")"
for opt in --speed --cross --size; do
    "$F" report --scene "$t/s.scene" -o "$t/rd" --no-timing --no-instructions $opt "$t" >/dev/null 2>"$t/err"; rc=$?
    [ $rc -eq 1 ] && grep -q "$t: cannot read: Is a directory" "$t/err" && [ ! -e "$t/rd" ] &&
        pass "report $opt DIR (a directory as input, a read error): exit 1, nothing written" ||
        fail "report $opt DIR: exit $rc $(cat "$t/err")"
done
"$F" gen "$t" -o "$t/x.h" 2>"$t/err"; rc=$?
[ $rc -eq 1 ] && grep -q "$t" "$t/err" && [ ! -e "$t/x.h" ] && pass "gen DIR (a directory as manifest, a read error): exit 1, no output" ||
    fail "gen DIR: exit $rc $(cat "$t/err")"

# Out of memory has its own exit status (3), apart from bad input (2): an
# 80 MB line under a 60 MB address-space limit.
# (A sanitizer build reserves more address space than that at startup: skipped.)
if ! (ulimit -v 60000; "$F" --version) >/dev/null 2>&1; then
    echo "NOTE this build does not start under ulimit -v 60000 (sanitizers?): out-of-memory status not tested"
else
(ulimit -v 60000; head -c 80000000 /dev/zero | tr '\0' '1' | "$F" eval --model exact --type f32 >"$t/out") 2>"$t/err"; rc=$?
[ $rc -eq 3 ] && grep -q 'out of memory' "$t/err" && [ ! -s "$t/out" ] &&
    pass "out of memory: exit 3 ($(cat "$t/err"))" || fail "out of memory: exit $rc $(cat "$t/err")"
fi
