#!/bin/sh
# Instructions and cycles per call from a qemu execution trace (-singlestep
# -d exec,nochain: one "Trace" line per instruction executed, guest PC in the
# second field of the bracket). tests/ports/cross/bench.c calls port_mark before
# each call of a row and after the last one (it prints the number of calls
# per row after BENCH; bench_float.c prints none: 33); the lines between
# two marks are one call plus the loop, and the last row named "(loop...)"
# before it (a function that returns its argument through the same loop) is
# subtracted call by call. (row starts at 0: an uninitialised awk variable is
# the empty string as an array subscript, which kept the loop row apart from
# row 0.) A name line may carry, after a tab, the number of evaluations one
# call of its row makes (the batches): that row is reported per
# evaluation, to one decimal.
#
# Cycles (with OBJDUMP, Arm targets): each executed instruction costs its
# Cortex-M0 time, from the Cortex-M0 Technical Reference Manual (Arm DDI
# 0432C, section 3.3 "Instruction set summary", Table 3-1; zero wait states):
#   data processing, shifts, compares, MOVS/ADDS ...       1
#   MULS                                                   1 or 32 (the
#       implementation's choice: both columns are printed)
#   LDR*, STR* (any addressing, literal included)          2
#   LDM, STM, PUSH, POP                                    1 + N registers
#   POP with PC                                            4 + N
#   B<cond>                                                3 taken, 1 not
#   B                                                      3
#   BL                                                     4
#   BX, BLX                                                3
#   MOV PC / ADD PC                                        3
# A conditional branch is taken when the next traced PC is not the next
# instruction's address. On the Cortex-M4F build these are still Cortex-M0
# timings (its own differ); the Makefile prints cycles for m0 only.
#
# usage: count.sh NM ELF TRACE BENCH_OUTPUT [OBJDUMP]
#   -> "name<TAB>mean<TAB>min<TAB>max" per row (instructions), and with
#      OBJDUMP six more columns: cycles mean, min, max with a 1-cycle
#      multiplier, then with a 32-cycle multiplier.
nm_tool=$1 elf=$2 trace=$3 out=$4 objdump=${5:-}
mark=$("$nm_tool" "$elf" | awk '$3 == "port_mark" { print $1 }')
[ -n "$mark" ] || { echo "count.sh: no port_mark in $elf" >&2; exit 1; }
per=$(sed -n 's/^BENCH \([0-9][0-9]*\)$/\1/p' "$out")
per=$((${per:-33} + 1))
sed -n '/^BENCH/,/^END$/p' "$out" | grep -v -e '^BENCH' -e '^END$' >"$trace.names"
: >"$trace.isa"
if [ -n "$objdump" ]; then
    # address<TAB>size<TAB>mnemonic<TAB>operands of every instruction
    "$objdump" -d --no-show-raw-insn "$elf" >/dev/null 2>&1 || { echo "count.sh: $objdump fails on $elf" >&2; exit 1; }
    "$objdump" -d "$elf" | awk -F'\t' '$1 ~ /^ *[0-9a-f]+:$/ && NF >= 3 {
        a = $1; gsub(/[ :]/, "", a); b = $2; gsub(/ /, "", b)
        printf "%s\t%d\t%s\t%s\n", a, length(b) / 2, $3, $4 }' >"$trace.isa"
fi
awk -v mark="/$mark/" -v names="$trace.names" -v isa="$trace.isa" -v per="$per" '
function hexval(s,    i, v) { v = 0; s = tolower(s); for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return v }
BEGIN {
    nrow = 0
    while ((getline line < names) > 0) {
        nf = split(line, parts, "\t"); name[nrow] = parts[1]; each[nrow] = nf > 1 ? parts[2] + 0 : 1; nrow++
    }
    ncyc = 0
    while ((getline line < isa) > 0) {
        split(line, f, "\t"); m = f[3]; sub(/\.[nw]$/, "", m); ops = f[4]
        a = sprintf("%08x", hexval(f[1])); fall[a] = sprintf("%08x", hexval(f[1]) + f[2])
        c = 1; mul[a] = 0; cond[a] = 0
        nreg = 0
        if (ops ~ /\{/) { r = ops; sub(/^[^{]*\{/, "", r); sub(/\}.*$/, "", r); nreg = split(r, rr, ",") }
        if (m == "muls" || m == "mul") { mul[a] = 1 }
        else if (m ~ /^(ldr|str)/) c = 2
        else if (m ~ /^(ldm|stm|push)/) c = 1 + nreg
        else if (m == "pop") c = (ops ~ /pc/ ? 4 : 1) + nreg
        else if (m == "bl") c = 4
        else if (m == "b" || m == "bx" || m == "blx") c = 3
        else if (m ~ /^b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)$/) cond[a] = 1
        else if ((m == "mov" || m == "add") && ops ~ /^pc,/) c = 3
        cyc[a] = c; ncyc++
    }
    row = 0
}
/^Trace/ {
    n++
    if (ncyc) {
        pc = $0; sub(/^[^[]*\[[0-9a-fA-F]*\//, "", pc); pc = tolower(substr(pc, 1, 8))
        if (prev != "") {
            if (mul[prev]) { c1 += 1; c32 += 32 }
            else { k = cyc[prev] + (cond[prev] && pc != fall[prev] ? 2 : 0); c1 += k; c32 += k }
        }
        prev = pc
    }
    if (index($0, mark)) {
        if (k_ > 0) { iv[row, k_] = n - last; i1[row, k_] = c1 - last1; i32[row, k_] = c32 - last32 }
        last = n; last1 = c1; last32 = c32; k_++
        if (k_ == per) { row++; k_ = 0 }
    }
}
END {
    if (row != nrow) { printf "count.sh: %d rows of marks for %d names\n", row, nrow > "/dev/stderr"; exit 1 }
    for (r = 0; r < nrow; r++) {
        if (name[r] ~ /^\(loop/) { base = r; continue }
        s = 0; lo = 1e9; hi = 0; s1 = 0; lo1 = 1e9; hi1 = 0; s32 = 0; lo32 = 1e9; hi32 = 0
        for (j = 1; j < per; j++) {
            v = iv[r, j] - iv[base, j]; s += v
            if (v < lo) lo = v
            if (v > hi) hi = v
            v = i1[r, j] - i1[base, j]; s1 += v
            if (v < lo1) lo1 = v
            if (v > hi1) hi1 = v
            v = i32[r, j] - i32[base, j]; s32 += v
            if (v < lo32) lo32 = v
            if (v > hi32) hi32 = v
        }
        if (ncyc && each[r] > 1)
            printf "%s\t%.1f\t%.1f\t%.1f\t%.1f\t%.1f\t%.1f\t%.1f\t%.1f\t%.1f\n", name[r], s / (per - 1) / each[r], lo / each[r], hi / each[r], s1 / (per - 1) / each[r], lo1 / each[r], hi1 / each[r], s32 / (per - 1) / each[r], lo32 / each[r], hi32 / each[r]
        else if (ncyc)
            printf "%s\t%.0f\t%d\t%d\t%.0f\t%d\t%d\t%.0f\t%d\t%d\n", name[r], s / (per - 1), lo, hi, s1 / (per - 1), lo1, hi1, s32 / (per - 1), lo32, hi32
        else if (each[r] > 1)
            printf "%s\t%.1f\t%.1f\t%.1f\n", name[r], s / (per - 1) / each[r], lo / each[r], hi / each[r]
        else
            printf "%s\t%.0f\t%d\t%d\n", name[r], s / (per - 1), lo, hi
    }
}' "$trace"
