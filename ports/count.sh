#!/bin/sh
# Instructions per call from a qemu execution trace (-singlestep -d exec,nochain:
# one "Trace" line per instruction executed, guest PC in the second field of
# the bracket). tests/cross/bench.c calls port_mark before each of the 33
# calls of a row and after the last; the lines between two marks are one call
# plus the loop, and the last row named "(loop...)" before it (a function that
# returns its argument through the same loop) is subtracted call by call.
# (row starts at 0: an uninitialised awk variable is the empty string as an
# array subscript, which kept the loop row apart from row 0 and left the
# loop's 15 instructions on the Cortex-M0 in every count before.)
# usage: count.sh NM ELF TRACE BENCH_OUTPUT  -> "name<TAB>mean<TAB>min<TAB>max" per row
nm_tool=$1 elf=$2 trace=$3 out=$4
mark=$("$nm_tool" "$elf" | awk '$3 == "port_mark" { print $1 }')
[ -n "$mark" ] || { echo "count.sh: no port_mark in $elf" >&2; exit 1; }
sed -n '/^BENCH$/,/^END$/p' "$out" | grep -v -e '^BENCH$' -e '^END$' >"$trace.names"
awk -v mark="/$mark/" -v names="$trace.names" '
BEGIN { while ((getline line < names) > 0) name[nrow++] = line; per = 34; row = 0 }
/^Trace/ {
    n++
    if (index($0, mark)) {
        if (k > 0) iv[row, k] = n - last
        last = n; k++
        if (k == per) { row++; k = 0 }
    }
}
END {
    if (row != nrow) { printf "count.sh: %d rows of marks for %d names\n", row, nrow > "/dev/stderr"; exit 1 }
    for (r = 0; r < nrow; r++) {
        if (name[r] ~ /^\(loop/) { base = r; continue }
        s = 0; lo = 1e9; hi = 0
        for (j = 1; j < per; j++) {
            v = iv[r, j] - iv[base, j]; s += v
            if (v < lo) lo = v
            if (v > hi) hi = v
        }
        printf "%s\t%.0f\t%d\t%d\n", name[r], s / (per - 1), lo, hi
    }
}' "$trace"
