#!/bin/sh
# Runs the checks of one or more passes and counts their PASS/FAIL lines:
#   sh tests/run.sh [--check] PASS=DIR[@COMPILER]...
# PASS is first, sanitize or other (make test: first=build
# sanitize=build/asan other=build/clang@clang); DIR is the pass's build
# directory; its scripts run with BUILD=DIR and CC=COMPILER (default $CC).
# The checks are every test_*.c under tests/ (its binary DIR/tests/test_*,
# the file's name without .c: names are unique) and every test_*.sh under
# tests/, in any of its folders. A check's opening comment names the passes where it
# can find something, one line, "passes: first sanitize" (all when there is
# none; tests/README.md has the rule), and "make check: no (why)" leaves it
# out of --check (make check). A check that exits non-zero without a FAIL
# line (a crash, a sanitizer report) counts as one failure.
# JOBS checks run at once (default: the number of CPUs), the slowest first
# (by DIR/test-times.tsv of the first pass, which each run writes; without it
# those whose header says "start: early", then those left out of make
# check, then the other scripts, then the binaries); each one's output is
# printed whole, in the order they start, so the log reads as if they ran
# one after another. At the end: the ten slowest checks and last the line
# "N passed, N failed".

# One check, run by the pool below: its output, then its exit status and
# times (the .rc file, written last, says it is done).
if [ "${1-}" = --job ]; then
    work=$2 idx=$3 dir=$5 cc=$6 kind=$7 src=$8
    [ "$cc" = - ] && cc=${CC:-cc}
    start=$(date +%s.%N)
    if [ "$kind" = bin ]; then
        ("$dir/tests/$(basename "$src" .c)") >"$work/$idx.log" 2>&1 </dev/null
    else
        BUILD="$dir" CC="$cc" sh "$src" >"$work/$idx.log" 2>&1 </dev/null
    fi
    rc=$?
    # the CPU time of the check's processes (user + system), from times
    times >"$work/$idx.cpu" # not in a pipeline: a subshell has no children
    cpu=$(awk 'NR == 2 { for (i = 1; i <= 2; i++) { split($i, t, "m"); s += t[1] * 60 + t[2] } print s }' "$work/$idx.cpu")
    echo "$rc $start $(date +%s.%N) ${cpu:-0}" >"$work/$idx.tmp" && mv "$work/$idx.tmp" "$work/$idx.rc"
    exit 0
fi

only_check=no
[ "${1-}" = --check ] && only_check=yes && shift
jobs=${JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
pass=0
fail=0

# header FILE KEY: the value of "KEY:" in FILE's opening comment
header() {
    sed -n "1,20{s/^\\(#\\|\\/\\*\\| \\*\\|\\/\\/\\) *$2: *//p}" "$1" | sed 's/ *\*\/$//' | head -1
}

# The list: one line per check and pass where it runs,
# "index label dir compiler kind source pass".
n=0
times_file=""
for arg in "$@"; do
    name=${arg%%=*}
    spec=${arg#*=}
    dir=${spec%@*}
    cc=${spec#"$dir"}
    cc=${cc#@}
    case $name in
    first | sanitize | other) ;;
    *)
        echo "tests/run.sh: '$arg': expected first=DIR, sanitize=DIR or other=DIR[@COMPILER]" >&2
        exit 2
        ;;
    esac
    first_arg=no
    [ -n "$times_file" ] || { first_arg=yes; times_file=$dir/test-times.tsv; }
    for src in $(find tests \( -name 'test_*.c' -o -name 'test_*.sh' \) -type f | sort); do
        passes=$(header "$src" passes | sed "s/(.*//")
        [ $first_arg = yes ] && for p in ${passes:-all}; do
            case $p in
            all | first | sanitize | other) ;;
            *) echo "FAIL $src: unknown pass '$p' on its passes: line (expected all, first, sanitize, other)"
               fail=$((fail + 1)) ;;
            esac
        done
        case " ${passes:-all} " in *" all "* | *" $name "*) ;; *) continue ;; esac
        [ $only_check = yes ] && case $(header "$src" "make check") in no*) continue ;; esac
        case $src in *.c) kind=bin ;; *) kind=script ;; esac
        n=$((n + 1))
        echo "$n $(basename "$dir") $dir ${cc:--} $kind $src $name" >>"$work/list"
    done
done
# a binary's name is its file's: two checks of one name would share it
dups=$(find tests -name 'test_*.c' -type f | sed 's|.*/||' | sort | uniq -d)
for d in $dups; do
    echo "FAIL tests/run.sh: two checks named $d: $(find tests -name "$d" -type f | tr '\n' ' ')"
    fail=$((fail + 1))
done
[ "$n" -gt 0 ] || { echo "0 passed, $((fail + 1)) failed (no check to run)"; exit 1; }

# The slowest first, so that no long check starts last.
awk -v tf="$times_file" '
    BEGIN { while ((getline line < tf) > 0) { split(line, f, "\t"); t[f[1] " " f[2]] = f[3] } }
    { key = $2 " " $6
      if (key in t) cost = t[key]
      else cost = ($5 == "script") ? 1 : 0.5
      print cost "\t" $0 }' "$work/list" | sort -t "$(printf '\t')" -k1,1gr -s | cut -f2- >"$work/queue"
if [ ! -f "$times_file" ]; then
    : >"$work/early"
    : >"$work/heavy"
    while read -r line; do
        set -- $line
        case $(header "$6" start)/$(header "$6" "make check") in
        early*) echo "$line" >>"$work/early" ;;
        */no*) echo "$line" >>"$work/heavy" ;;
        esac
    done <"$work/queue"
    cat "$work/early" "$work/heavy" | grep -vxF -f - "$work/queue" >"$work/rest"
    cat "$work/early" "$work/heavy" "$work/rest" >"$work/queue"
fi
xargs -P "$jobs" -L 1 sh "$0" --job "$work" <"$work/queue" &
pool=$!

# tally LABEL NAME EXIT_STATUS LOG: prints and counts one check's lines
tally() {
    sed -n 's/^\(PASS\|FAIL\|NOTE\) /\1 ['"$1"'] /p' "$4"
    p=$(grep -c '^PASS ' "$4")
    f=$(grep -c '^FAIL ' "$4")
    pass=$((pass + p))
    fail=$((fail + f))
    if [ "$3" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL [$1] $2 exited $3 without a FAIL line:"
        tail -20 "$4"
        fail=$((fail + 1))
    fi
}

start=$(date +%s.%N)
: >"$work/times"
while read -r idx label dir cc kind src name; do
    while [ ! -f "$work/$idx.rc" ] && kill -0 "$pool" 2>/dev/null; do
        sleep 0.2
    done
    [ "$kind" = bin ] && what="$dir/tests/$(basename "$src" .c)" || what=$src
    if [ ! -f "$work/$idx.rc" ]; then
        echo "FAIL [$label] $what did not run"
        fail=$((fail + 1))
        continue
    fi
    read -r rc t0 t1 cpu <"$work/$idx.rc"
    before=$fail
    before_pass=$pass
    tally "$label" "$what" "$rc" "$work/$idx.log"
    printf '%s\t%s\t%.1f\t%d\t%d\t%s\t%.1f\n' "$label" "$src" "$(echo "$t0 $t1" | awk '{ print $2 - $1 }')" \
        $((pass - before_pass)) $((fail - before)) "$what" "$cpu" >>"$work/times"
done <"$work/queue"
wait "$pool"

total=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.0f", e - s }')
cpu=$(awk -F'\t' '{ s += $7 } END { printf "%.0f", s }' "$work/times")
echo "NOTE the ten slowest checks (of $n, $jobs at a time, $total s in all, $cpu CPU s): seconds, CPU seconds of its processes"
sort -t "$(printf '\t')" -k3,3gr "$work/times" | head -10 |
    awk -F'\t' '{ printf "NOTE %7.1f %7.1f  [%s] %s\n", $3, $7, $1, $6 }'
awk '!($2 in n) { order[++k] = $2 } { n[$2]++ }
    END { printf "NOTE checks per pass:"; for (i = 1; i <= k; i++) printf "%s %s %d", (i > 1 ? "," : ""), order[i], n[order[i]]; printf "\n" }' \
    "$work/list"
if [ -n "$times_file" ] && [ -d "$(dirname "$times_file")" ]; then
    if [ $only_check = yes ] && [ -f "$times_file" ]; then
        # make check keeps the times of the passes it did not run
        awk -F'\t' 'NR == FNR { seen[$1 "\t" $2] = 1; print; next } !(($1 "\t" $2) in seen)' \
            "$work/times" "$times_file" >"$work/merged" && cp "$work/merged" "$times_file"
    else
        cp "$work/times" "$times_file"
    fi
fi
if [ $only_check = yes ]; then
    # what make check ran, what it left to make test, and how to run one alone
    left=$(for src in $(find tests \( -name 'test_*.c' -o -name 'test_*.sh' \) -type f | sort); do
        case $(header "$src" "make check") in no*) basename "$src" ;; esac
    done | tr '\n' ' ')
    echo "NOTE make check ran $n checks: $(awk '{ n = $6; sub(/.*\//, "", n); sub(/\.(c|sh)$/, "", n); printf "%s ", n }' "$work/list")"
    echo "NOTE left to make test (external tools, other passes): $left"
    echo "NOTE one alone: build/tests/test_NAME (a .c check; make build/tests/test_NAME first), or BUILD=build sh with the script's path under tests/"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
