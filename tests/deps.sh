#!/bin/sh
# The one list of what `make test` needs on a Debian machine, and the check
# that installs it.
#   sh tests/deps.sh [GROUP]   GROUP: all (default, `make deps`, run first by
#                              `make test`) or cross (`make cross-deps`)
# Each missing probe names its Debian package. As root the missing packages
# are installed with apt-get; otherwise the script prints the exact
# `apt-get install` line to run and exits 1 at once. Nothing missing: exit 0,
# silently.
#
# For tests/test_deps.sh, without uninstalling anything:
#   DEPS_PATH      PATH the cmd probes search (default: $PATH)
#   DEPS_ROOT      prefix for the file and dir probes (default: none)
#   DEPS_UID       user id to act as (default: id -u)
#   DEPS_DRY_RUN=1 print the apt-get commands instead of running them
#
# To add a tool: one line below, "GROUP KIND PROBE PACKAGE". KIND is cmd (a
# command on PATH), file or dir (a path that must exist), or link
# (COMPILER:FLAGS links an empty program: clang's sanitizer runtime is only
# a recommended package of clang, and `make CC=clang test` needs it; so is
# the AArch64 C library of gcc-aarch64-linux-gnu, which
# tests/test_batch_simd.sh links with gcc and clang). GROUP
# cross rows are also what `make cross-deps` checks.
table='
all   cmd  make                     make
all   cmd  gcc                      gcc
all   cmd  clang                    clang
all   cmd  g++                      g++
all   cmd  clang++                  clang
all   link clang:-fsanitize=address,undefined libclang-rt-dev
all   cmd  pkg-config               pkg-config
all   cmd  nm                       binutils
all   cmd  xmllint                  libxml2-utils
all   file /usr/include/GL/osmesa.h libosmesa6-dev
all   cmd  cmake                    cmake
all   cmd  glslangValidator         glslang-tools
all   cmd  spirv-val                spirv-tools
all   file /usr/include/vulkan/vulkan.h libvulkan-dev
all   file /usr/share/vulkan/icd.d/lvp_icd.x86_64.json mesa-vulkan-drivers
all   cmd  chromium                 chromium
cross cmd  arm-none-eabi-gcc        gcc-arm-none-eabi
cross cmd  arm-none-eabi-nm         binutils-arm-none-eabi
cross cmd  arm-none-eabi-objdump    binutils-arm-none-eabi
cross dir  /usr/lib/arm-none-eabi/newlib libnewlib-arm-none-eabi
cross cmd  riscv64-unknown-elf-gcc  gcc-riscv64-unknown-elf
cross cmd  riscv64-unknown-elf-nm   binutils-riscv64-unknown-elf
cross cmd  qemu-system-arm          qemu-system-arm
cross cmd  qemu-riscv32-static      qemu-user-static
cross cmd  aarch64-linux-gnu-gcc    gcc-aarch64-linux-gnu
cross link aarch64-linux-gnu-gcc:-static libc6-dev-arm64-cross
'
group=${1:-all}
case $group in
all | cross) ;;
*)
    echo "tests/deps.sh: unknown group '$group' (expected all or cross)" >&2
    exit 2
    ;;
esac
probe_path=${DEPS_PATH-$PATH}
root=${DEPS_ROOT-}
uid=${DEPS_UID-$(id -u)}

missing=""
tmp=$(mktemp) || exit 1
trap 'rm -f "$tmp" "$tmp.c"' EXIT
# `all` covers every row; `cross` only the cross rows
rows=$(printf '%s\n' "$table" | awk -v g="$group" 'NF == 4 && (g == "all" || $1 == g)')
set -f # the probes are literal names, never globs
for row in $(printf '%s\n' "$rows" | awk '{ print $2 "|" $3 "|" $4 }'); do
    kind=${row%%|*}
    rest=${row#*|}
    probe=${rest%%|*}
    pkg=${rest#*|}
    case $kind in
    cmd) (PATH=$probe_path command -v "$probe") >/dev/null 2>&1 && continue ;;
    file) [ -f "$root$probe" ] && continue ;;
    dir) [ -d "$root$probe" ] && continue ;;
    link)
        printf 'int main(void) { return 0; }\n' >"$tmp.c"
        # the compiler as the cmd probes find it; its linker from the real PATH
        cc=$(PATH=$probe_path command -v "${probe%%:*}") &&
            "$cc" ${probe#*:} "$tmp.c" -o "$tmp" >/dev/null 2>&1 && continue
        ;;
    esac
    case " $missing " in
    *" $pkg "*) ;;
    *) missing="$missing $pkg" ;;
    esac
done
set +f
[ -z "$missing" ] && exit 0

apt="apt-get -o DPkg::Lock::Timeout=600"
install="DEBIAN_FRONTEND=noninteractive $apt install -y --no-install-recommends$missing"
if [ "$uid" -ne 0 ]; then
    echo "deps: missing$missing. Run as root, then make test again:" >&2
    echo "$apt update && $install" >&2
    exit 1
fi
echo "deps: installing$missing"
if [ "${DEPS_DRY_RUN-}" = 1 ]; then
    echo "$apt update -qq"
    echo "$install"
    exit 0
fi
$apt update -qq && eval "$install" >/dev/null || {
    echo "deps: could not install$missing; run: $apt update && $install" >&2
    exit 1
}
