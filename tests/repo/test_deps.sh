#!/bin/sh
# passes: first (about the machine, not the build)
# make check: no (probes Chromium, qemu and the cross compilers)
# tests/deps.sh, the set-up `make test` runs first: which packages it asks
# for, what it does as root and as another user, and that each probe fails
# the way a machine without the package fails. The probes find their tools
# on a fake PATH (links to this machine's, some removed or replaced by
# broken ones) and files under an empty root, so nothing is installed or
# removed.
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
D=tests/deps.sh

# this machine: `make test` got past deps, so nothing may be missing now
if sh $D all >"$t/out" 2>&1 && [ ! -s "$t/out" ]; then
    echo "PASS deps.sh all (the cross rows included): every probe does its job here, silent, exit 0"
else
    echo "FAIL deps.sh on this machine: $(head -5 "$t/out")"
fi

# A fake PATH: a link to every command of this machine's PATH (the first of
# each name), then xmllint removed.
mkdir "$t/bin"
for dir in $(echo "$PATH" | tr ':' ' '); do
    [ -d "$dir" ] && ln -s "$dir"/* "$t/bin/" 2>/dev/null
done
rm "$t/bin/xmllint"
# deps ARGS...: deps.sh with the fake PATH as a user; exit status in $rc
deps() {
    DEPS_PATH="$t/bin" DEPS_UID=1000 sh $D "$@" >"$t/out" 2>"$t/err"
    rc=$?
}
apt_line() { # the line deps.sh prints for PACKAGES
    echo "apt-get -o DPkg::Lock::Timeout=600 update && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends $*"
}
# asks NAME PACKAGES ROWS...: deps.sh on ROWS asks for exactly PACKAGES
asks() {
    name=$1 want=$2
    shift 2
    deps "$@"
    if [ $rc -eq 1 ] && [ ! -s "$t/out" ] && grep -qxF "$(apt_line "$want")" "$t/err"; then
        echo "PASS $name: exit 1, asks for $want"
    else
        echo "FAIL $name: exit $rc, $(cat "$t/out" "$t/err" | head -4)"
    fi
}
asks "not root, xmllint missing, every other probe doing its job on the fake PATH" libxml2-utils all
deps cross
if [ $rc -eq 0 ] && [ ! -s "$t/out" ] && [ ! -s "$t/err" ]; then
    echo "PASS cross group: xmllint is not a cross row, nothing missing"
else
    echo "FAIL cross group asked for a non-cross package: exit $rc, $(head -2 "$t/err")"
fi
# one target (make measure): its toolchain and emulator rows only, named
# on one line; with its emulator gone, only that emulator's package
deps m55
if [ $rc -eq 0 ] && [ ! -s "$t/err" ] &&
    grep -qx 'deps: m55 needs the rows arm-none-eabi newlib qemu-arm: all present' "$t/out"; then
    echo "PASS target m55: its three rows, all present, said in one line"
else
    echo "FAIL target m55: exit $rc, $(cat "$t/out" "$t/err" | head -3)"
fi
mv "$t/bin/qemu-riscv32-static" "$t/qemu-riscv32-static.away" 2>/dev/null
mv "$t/bin/qemu-riscv32" "$t/qemu-riscv32.away" 2>/dev/null
asks "target rv32, its emulator missing" qemu-user-static rv32
mv "$t/qemu-riscv32-static.away" "$t/bin/qemu-riscv32-static" 2>/dev/null
mv "$t/qemu-riscv32.away" "$t/bin/qemu-riscv32" 2>/dev/null

# As root: apt-get update, the install of the missing packages alone (lock
# timeout, noninteractive), then every failed probe again. A stand-in for
# apt-get logs its arguments; the first installs nothing, the second puts
# xmllint back on the fake PATH.
printf '#!/bin/sh\necho "$*" >>"%s/apt.log"\n' "$t" >"$t/apt-noop"
printf '#!/bin/sh\necho "$*" >>"%s/apt.log"\ncase "$*" in *install*) ln -s "%s" "%s/bin/xmllint" ;; esac\n' \
    "$t" "$(command -v xmllint)" "$t" >"$t/apt-fix"
chmod +x "$t/apt-noop" "$t/apt-fix"
DEPS_PATH="$t/bin" DEPS_UID=0 DEPS_APT="$t/apt-noop" sh $D xmllint gcc >"$t/out" 2>"$t/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$t/apt.log")" = "-o DPkg::Lock::Timeout=600 update -qq
-o DPkg::Lock::Timeout=600 install -y --no-install-recommends libxml2-utils" ] &&
    grep -q '^deps: the xmllint probe still fails with libxml2-utils installed' "$t/err"; then
    echo "PASS root, xmllint missing, an install that does not bring it: apt-get update, install of libxml2-utils alone, then a deps failure naming the probe"
else
    echo "FAIL root, install without effect: exit $rc, apt: $(cat "$t/apt.log" | tr '\n' ';') $(head -3 "$t/err")"
fi
rm -f "$t/apt.log"
DEPS_PATH="$t/bin" DEPS_UID=0 DEPS_APT="$t/apt-fix" sh $D xmllint gcc >"$t/out" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && [ ! -s "$t/err" ] && grep -q '^deps: installing libxml2-utils' "$t/out" && [ -L "$t/bin/xmllint" ]; then
    echo "PASS root, xmllint missing, an install that brings it: the probes pass again, exit 0"
else
    echo "FAIL root, install with effect: exit $rc, $(cat "$t/out" "$t/err" | head -3)"
fi

# replace NAME SCRIPT: NAME on the fake PATH becomes SCRIPT (a sh body; $REAL
# is the real command)
replace() {
    real=$(command -v "$1")
    rm -f "$t/bin/$1"
    printf '#!/bin/sh\nREAL=%s\n%s\n' "$real" "$2" >"$t/bin/$1"
    chmod +x "$t/bin/$1"
}
restore() { rm -f "$t/bin/$1" && ln -s "$(command -v "$1")" "$t/bin/$1"; }

# What a machine without a package does: the compilers' libraries and
# headers, the runtimes, the emulators, the drivers.
replace aarch64-linux-gnu-gcc 'exec "$REAL" -nostdinc "$@"'
asks "aarch64-linux-gnu-gcc without its C library (only recommended by gcc-aarch64-linux-gnu)" \
    "gcc-aarch64-linux-gnu libc6-dev-arm64-cross" cross
restore aarch64-linux-gnu-gcc
replace qemu-aarch64-static 'exit 1'
asks "qemu-aarch64-static that runs nothing" qemu-user-static aarch64 qemu-aarch64
restore qemu-aarch64-static
replace arm-none-eabi-gcc 'case " $* " in *" -lc "*) echo "ld: cannot find -lc" >&2; exit 1 ;; esac; exec "$REAL" "$@"'
asks "arm-none-eabi-gcc without newlib" libnewlib-arm-none-eabi arm-none-eabi newlib qemu-arm
restore arm-none-eabi-gcc
replace qemu-system-arm 'exit 1'
asks "qemu-system-arm that runs nothing" qemu-system-arm arm-none-eabi newlib qemu-arm
restore qemu-system-arm
replace riscv64-unknown-elf-gcc 'case " $* " in *" -lgcc "*) echo "ld: cannot find -lgcc" >&2; exit 1 ;; esac; exec "$REAL" "$@"'
asks "riscv64-unknown-elf-gcc without its libgcc" "gcc-riscv64-unknown-elf binutils-riscv64-unknown-elf" riscv64-elf qemu-riscv32
restore riscv64-unknown-elf-gcc
replace clang 'case "$*" in *-fsanitize=*) exit 1 ;; esac; exec "$REAL" "$@"'
asks "clang without its sanitizer runtime (libFuzzer, ASan, UBSan)" libclang-rt-dev clang clang-rt clang++
rm "$t/bin/clang" "$t/bin/clang++"
asks "no clang: clang, and its sanitizer runtime, only recommended" "clang libclang-rt-dev" clang clang-rt clang++
restore clang
restore clang++
replace pkg-config 'case "$*" in *osmesa*) echo "Package osmesa was not found" >&2; exit 1 ;; esac; exec "$REAL" "$@"'
asks "no osmesa.pc" libosmesa6-dev pkg-config osmesa
restore pkg-config
replace chromium 'exit 0'
asks "a chromium that takes no screenshot" chromium chromium
restore chromium
mkdir "$t/root"
export DEPS_ROOT="$t/root"
asks "no lavapipe ICD file" mesa-vulkan-drivers vulkan lavapipe
unset DEPS_ROOT
rm "$t/bin/g++"
asks "no g++" g++ g++ clang++

# An empty PATH and an empty root: every probe fails, the line names every
# package of the table once.
mkdir "$t/nobin"
DEPS_PATH="$t/nobin" DEPS_ROOT="$t/root" DEPS_UID=1000 sh $D all >/dev/null 2>"$t/err"
rc=$?
got=$(sed -n 's/.* --no-install-recommends //p' "$t/err" | tr ' ' '\n' | sort | tr '\n' ' ')
table=$(sed -n "/^table='/,/^'/p" $D | awk 'NF >= 3 && $1 ~ /^(all|cross)$/ { for (i = 3; i <= NF; i++) print $i }' |
    sort -u | tr '\n' ' ')
if [ $rc -eq 1 ] && [ -n "$got" ] && [ "$got" = "$table" ]; then
    echo "PASS nothing present: the install line names every package of the table once ($(echo $got | wc -w))"
else
    echo "FAIL nothing present: exit $rc, asked for '$got', table '$table'"
fi
for want in libosmesa6-dev glslang-tools spirv-tools cmake g++ qemu-user-static gcc-riscv64-unknown-elf \
    libc6-dev-arm64-cross libclang-rt-dev; do
    case " $table " in
    *" $want "*) ;;
    *) echo "FAIL the table has no row for $want" ;;
    esac
done
sh $D bogus >/dev/null 2>"$t/err"
if [ $? -eq 2 ] && grep -q "unknown group or row 'bogus'" "$t/err"; then
    echo "PASS unknown group: exit 2, named"
else
    echo "FAIL unknown group: $(head -2 "$t/err")"
fi

# make test runs deps first; make cross-deps and .ci/run add no list of their own
first=$(make --no-print-directory -n test 2>/dev/null | head -1)
if [ "$first" = "sh tests/deps.sh all" ] && make --no-print-directory -n cross-deps 2>/dev/null | grep -qx 'sh tests/deps.sh cross' &&
    ! grep -q 'apt-get' .ci/run && ! grep -qE 'apt-get +(-[^ ]+ +)*(update|install)' Makefile; then
    echo "PASS make test starts with tests/deps.sh; cross-deps uses its cross rows; .ci/run and the Makefile hold no apt-get"
else
    echo "FAIL deps wiring: make -n test starts with '$first'"
fi
