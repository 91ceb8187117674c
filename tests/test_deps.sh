#!/bin/sh
# tests/deps.sh, the set-up `make test` runs first: which packages it asks
# for, what it does as root and as another user. Probes are pointed at a fake
# PATH and an empty file-system root, so nothing is installed or removed.
[ "$BUILD" = build ] || exit 0 # about the machine, not the build; once
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
D=tests/deps.sh

# this machine: `make test` got past deps, so nothing may be missing now
if sh $D all >"$t/out" 2>&1 && [ ! -s "$t/out" ] && sh $D cross >"$t/out" 2>&1 && [ ! -s "$t/out" ]; then
    echo "PASS deps.sh all and cross: every probe is present here, silent, exit 0"
else
    echo "FAIL deps.sh on this machine: $(head -3 "$t/out")"
fi

# A fake PATH holding every command of the table except xmllint: one
# package.
mkdir "$t/bin"
for c in $(awk '$2 == "cmd" { print $3 }' $D | sort -u); do
    [ "$c" = xmllint ] && continue
    p=$(command -v "$c") && ln -s "$p" "$t/bin/$c"
done
DEPS_PATH="$t/bin" DEPS_UID=1000 sh $D all >"$t/out" 2>"$t/err"
rc=$?
want="apt-get -o DPkg::Lock::Timeout=600 update && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends libxml2-utils"
if [ $rc -eq 1 ] && [ ! -s "$t/out" ] && grep -qxF "$want" "$t/err"; then
    echo "PASS not root, xmllint missing: exit 1 with the exact line: $want"
else
    echo "FAIL not root, xmllint missing: exit $rc, $(cat "$t/out" "$t/err" | head -3)"
fi
DEPS_PATH="$t/bin" DEPS_UID=0 DEPS_DRY_RUN=1 sh $D all >"$t/out" 2>"$t/err"
rc=$?
if [ $rc -eq 0 ] && grep -qx 'apt-get -o DPkg::Lock::Timeout=600 update -qq' "$t/out" &&
    grep -qx 'DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends libxml2-utils' "$t/out"; then
    echo "PASS root, xmllint missing: apt-get update, then install of libxml2-utils alone (lock timeout 600 s, noninteractive)"
else
    echo "FAIL root, xmllint missing: exit $rc, $(cat "$t/out" "$t/err" | head -3)"
fi
DEPS_PATH="$t/bin" DEPS_UID=1000 sh $D cross >"$t/out" 2>&1
if [ $? -eq 0 ] && [ ! -s "$t/out" ]; then
    echo "PASS cross group: xmllint is not a cross row, nothing missing"
else
    echo "FAIL cross group asked for a non-cross package: $(head -2 "$t/out")"
fi

# A clang that cannot link -fsanitize=address,undefined (no runtime library)
printf '#!/bin/sh\ncase "$*" in *-fsanitize=*) exit 1 ;; esac\nexec %s "$@"\n' "$(command -v clang)" >"$t/clang"
chmod +x "$t/clang"
rm "$t/bin/clang"
ln -s "$t/clang" "$t/bin/clang"
DEPS_PATH="$t/bin" DEPS_UID=1000 sh $D all >/dev/null 2>"$t/err"
if grep -q -- '--no-install-recommends libclang-rt-dev libxml2-utils$' "$t/err"; then
    echo "PASS clang without its sanitizer runtime: asks for libclang-rt-dev"
else
    echo "FAIL clang without its sanitizer runtime: $(tail -1 "$t/err")"
fi

# Without clang on PATH, clang and its sanitizer runtime (the link probe)
rm "$t/bin/clang" "$t/bin/clang++"
DEPS_PATH="$t/bin" DEPS_UID=1000 sh $D all >/dev/null 2>"$t/err"
if grep -q -- '--no-install-recommends clang libclang-rt-dev libxml2-utils$' "$t/err"; then
    echo "PASS clang and xmllint missing: asks for clang, libclang-rt-dev (sanitizer runtime), libxml2-utils"
else
    echo "FAIL clang missing: $(tail -1 "$t/err")"
fi

# An empty root: the file and dir probes (OSMesa, newlib) fail; an empty PATH:
# every command. All packages of the table, each once.
mkdir "$t/root" "$t/nobin"
DEPS_PATH="$t/nobin" DEPS_ROOT="$t/root" DEPS_UID=1000 sh $D all >/dev/null 2>"$t/err"
rc=$?
got=$(sed -n 's/.* --no-install-recommends //p' "$t/err" | tr ' ' '\n' | sort | tr '\n' ' ')
table=$(awk 'NF == 4 && $1 ~ /^(all|cross)$/ && $2 ~ /^(cmd|file|dir|link)$/ { print $4 }' $D | sort -u | tr '\n' ' ')
if [ $rc -eq 1 ] && [ -n "$got" ] && [ "$got" = "$table" ]; then
    echo "PASS nothing present: the install line names every package of the table once ($(echo $got | wc -w))"
else
    echo "FAIL nothing present: exit $rc, asked for '$got', table '$table'"
fi
DEPS_ROOT="$t/root" DEPS_UID=1000 sh $D cross >/dev/null 2>"$t/err"
if grep -q -- '--no-install-recommends libnewlib-arm-none-eabi$' "$t/err"; then
    echo "PASS cross group, newlib's directory missing: asks for libnewlib-arm-none-eabi alone"
else
    echo "FAIL cross group without newlib: $(head -3 "$t/err")"
fi
for want in libosmesa6-dev glslang-tools spirv-tools cmake g++ qemu-user-static gcc-riscv64-unknown-elf; do
    case " $table " in
    *" $want "*) ;;
    *) echo "FAIL the table has no row for $want" ;;
    esac
done
sh $D bogus >/dev/null 2>"$t/err"
if [ $? -eq 2 ] && grep -q "unknown group 'bogus'" "$t/err"; then
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
