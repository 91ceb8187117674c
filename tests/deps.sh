#!/bin/sh
# The one list of what `make test` needs on a Debian machine, and the check
# that installs it.
#   sh tests/deps.sh [GROUP|ROW...]   GROUP: all (default, `make deps`, run
#                                     first by `make test`) or cross (`make
#                                     cross-deps`); or one target's toolchain
#                                     and emulator, m0 m4f m55 (Arm), rv32,
#                                     a64 (`make measure`), which says what
#                                     it found or installed; or the names of rows
# Each row's probe does what the tests do with the tool, in miniature: a
# compiler compiles, links (static where the tests link static) and its
# program runs, under the row's emulator for a cross compiler; OSMesa and the
# Vulkan loader link a program that runs, and lavapipe is listed as a device;
# Chromium takes a headless screenshot; the bare-metal compilers link the
# ports' start-up code (and newlib) and the program runs under qemu. A probe
# that fails names its row's Debian packages. As root the missing packages
# are installed with apt-get and every probe runs again: one that still
# fails is a deps failure naming the probe and its error, never a test FAIL.
# Otherwise the script prints the exact `apt-get install` line to run and
# exits 1 at once. Nothing missing: exit 0, silently (for a target: one line
# naming its rows).
#
# For tests/repo/test_deps.sh, without uninstalling anything:
#   DEPS_PATH      PATH the probes find their tools on (default: $PATH); the
#                  tools run with the real PATH
#   DEPS_ROOT      prefix for the files probed where a program cannot be
#                  built (lavapipe's ICD, newlib's directory; default: none)
#   DEPS_UID       user id to act as (default: id -u)
#   DEPS_APT       the apt-get command run as root (default: apt-get)
#
# To add a tool: one row below, "GROUP ROW PACKAGE...", and its probe in
# probe() further down. Packages a tool only recommends (the AArch64 C
# library of gcc-aarch64-linux-gnu, clang's sanitizer runtime) are named on
# its row: the install is --no-install-recommends. GROUP cross rows are also
# what `make cross-deps` checks.
table='
all   make            make
all   gcc             gcc libc6-dev
all   clang           clang
all   clang-rt        libclang-rt-dev
all   g++             g++
all   clang++         clang
all   pkg-config      pkg-config
all   binutils        binutils
all   xmllint         libxml2-utils
all   osmesa          libosmesa6-dev
all   cmake           cmake
all   glslang         glslang-tools
all   spirv-val       spirv-tools
all   spirv-cross     spirv-cross
all   vulkan          libvulkan-dev
all   lavapipe        mesa-vulkan-drivers
all   chromium        chromium
all   firefox         firefox-esr
cross arm-none-eabi   gcc-arm-none-eabi binutils-arm-none-eabi
cross newlib          libnewlib-arm-none-eabi
cross qemu-arm        qemu-system-arm
cross riscv64-elf     gcc-riscv64-unknown-elf binutils-riscv64-unknown-elf
cross qemu-riscv32    qemu-user-static
cross aarch64         gcc-aarch64-linux-gnu libc6-dev-arm64-cross
cross qemu-aarch64    qemu-user-static
'
probe_path=${DEPS_PATH-$PATH}
root=${DEPS_ROOT-}
uid=${DEPS_UID-$(id -u)}
all_rows=$(printf '%s\n' "$table" | awk 'NF >= 3 { print $2 }')
target=""
case ${1:-all} in
all) rows=$all_rows ;;
cross) rows=$(printf '%s\n' "$table" | awk '$1 == "cross" { print $2 }') ;;
m0 | m4f | m55) target=$1 rows="arm-none-eabi newlib qemu-arm" ;;
rv32) target=$1 rows="riscv64-elf qemu-riscv32" ;;
a64) target=$1 rows="aarch64 qemu-aarch64" ;;
*)
    rows="$*"
    for r in $rows; do
        printf '%s\n' "$all_rows" | grep -qxF -e "$r" && continue
        echo "tests/deps.sh: unknown group or row '$r' (expected all, cross, a target m0 m4f m55 rv32 a64, or a row: $(echo $all_rows))" >&2
        exit 2
    done
    ;;
esac
packages() { printf '%s\n' "$table" | awk -v r="$1" '$2 == r { for (i = 3; i <= NF; i++) print $i }'; }

w=$(mktemp -d) || exit 1
trap 'rm -rf "$w"' EXIT

# tool NAME: NAME's path as the probes find it (on DEPS_PATH)
tool() { PATH=$probe_path command -v "$1"; }
# runs PROGRAM ARGS... (a timeout: a hung tool is a failure) and wants
# EXPECTED as its whole output: expect EXPECTED PROGRAM ARGS...
expect() {
    want=$1
    shift
    got=$(timeout 120 "$@" 2>&1) && [ "$got" = "$want" ] && return 0
    echo "$*: printed '$got', expected '$want'"
    return 1
}

# The programs the probes build: a C program that needs libm, the same in
# C++17, a libFuzzer entry point, an OSMesa context that clears a 4x4
# buffer, the Vulkan devices the loader finds, and a bare-metal program on
# the ports' start-up code (its square root from newlib with -DLIBM).
cat >"$w/hello.c" <<'C'
#include <math.h>
#include <stdio.h>
int main(int argc, char **argv)
{
    (void)argv;
    printf("%g\n", sqrt(argc + 3.0));
    return 0;
}
C
cat >"$w/hello.cc" <<'C'
#include <cmath>
#include <cstdio>
#include <string>
int main(int argc, char **)
{
    std::string s = std::to_string(static_cast<int>(std::sqrt(argc + 3.0)));
    std::puts(s.c_str());
}
C
cat >"$w/fuzz.c" <<'C'
#include <stddef.h>
#include <stdint.h>
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    (void)data;
    (void)size;
    return 0;
}
C
cat >"$w/osmesa.c" <<'C'
#include <GL/osmesa.h>
#include <stdio.h>
int main(void)
{
    static unsigned char px[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, px, GL_UNSIGNED_BYTE, 4, 4))
        return 1;
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    printf("%d\n", px[0]);
    OSMesaDestroyContext(ctx);
    return 0;
}
C
cat >"$w/vulkan.c" <<'C'
#include <stdio.h>
#include <vulkan/vulkan.h>
int main(void)
{
    VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO, NULL, "deps", 1, NULL, 0, VK_API_VERSION_1_0};
    VkInstanceCreateInfo info = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, NULL, 0, &app, 0, NULL, 0, NULL};
    VkInstance instance;
    VkPhysicalDevice dev[8];
    uint32_t n = 8, i;
    if (vkCreateInstance(&info, NULL, &instance) != VK_SUCCESS || vkEnumeratePhysicalDevices(instance, &n, dev) < 0)
        return 1;
    for (i = 0; i < n; i++) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(dev[i], &p);
        puts(p.deviceName);
    }
    vkDestroyInstance(instance, NULL);
    return 0;
}
C
cat >"$w/bare.c" <<'C'
#include "port.h"
#ifdef LIBM
#include <math.h>
static volatile float four = 4.0f;
#define OK (sqrtf(four) == 2.0f)
#else
#define OK 1
#endif
int main(void);
int main(void)
{
    port_puts(OK ? "ok\n" : "wrong\n");
    return 0;
}
C
printf '#version 450\nlayout(location = 0) out vec4 colour;\nvoid main() { colour = vec4(1.0); }\n' >"$w/f.frag"
printf 'cmake_minimum_required(VERSION 3.13)\nproject(probe C)\nadd_executable(hello hello.c)\ntarget_link_libraries(hello m)\n' \
    >"$w/CMakeLists.txt"

W="-std=c99 -Wall -Wextra -Wpedantic -Werror"
# cortex_m OUT CPU-FLAGS LINKER-SCRIPT EXTRA...: bare.c as ports/cross.sh builds a Cortex-M program
cortex_m() {
    out=$1 cf=$2 ld=$3
    shift 3
    # shellcheck disable=SC2086
    "$arm" $W $cf -mthumb -ffreestanding -Iports/common -nostdlib -nostartfiles -Wl,--gc-sections -Lports/cortex-m \
        -T"$ld" "$@" ports/cortex-m/startup.c ports/common/mem.c -lgcc -o "$out"
}
M0="-mcpu=cortex-m0 -Os"
M4F="-mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16 -O2"
M55="-mcpu=cortex-m55 -mfloat-abi=hard -O2"
qemu_arm() { # machine elf
    expect ok "$qemu" -M "$1" -display none -monitor none -serial none -chardev stdio,id=sh \
        -semihosting-config enable=on,target=native,chardev=sh -kernel "$2"
}

# probe ROW: 0 when the row's tools do their job here; its errors on stdout.
# An emulator or driver row whose test program cannot be built (its
# compiler's row fails too) probes the emulator's command or the driver's
# file instead: both rows then name their packages at once.
probe() {
    d=$w/$1
    mkdir -p "$d"
    case $1 in
    make) m=$(tool make) && "$m" --version >/dev/null ;;
    gcc)
        cc=$(tool gcc) && "$cc" $W -O2 "$w/hello.c" -lm -o "$d/hello" && expect 2 "$d/hello" &&
            "$cc" -O1 -g -fsanitize=address,undefined "$w/hello.c" -lm -o "$d/asan" && expect 2 "$d/asan"
        ;;
    clang) cc=$(tool clang) && "$cc" $W -O2 "$w/hello.c" -lm -o "$d/hello" && expect 2 "$d/hello" ;;
    clang-rt)
        cc=$(tool clang) && "$cc" -O1 -g -fsanitize=address,undefined "$w/hello.c" -lm -o "$d/asan" &&
            expect 2 "$d/asan" && "$cc" -g -O1 -fsanitize=fuzzer,address,undefined "$w/fuzz.c" -o "$d/fuzz"
        ;;
    g++) cxx=$(tool g++) && "$cxx" -std=c++17 -Wall -Werror "$w/hello.cc" -o "$d/hello" && expect 2 "$d/hello" ;;
    clang++) cxx=$(tool clang++) && "$cxx" -std=c++17 -Wall -Werror "$w/hello.cc" -o "$d/hello" && expect 2 "$d/hello" ;;
    pkg-config) p=$(tool pkg-config) && "$p" --version >/dev/null ;;
    binutils)
        nm=$(tool nm) && sz=$(tool size) && cc=$(tool cc) && "$cc" -c "$w/hello.c" -o "$d/hello.o" &&
            "$nm" "$d/hello.o" | grep -q ' T main$' && "$sz" -A "$d/hello.o" | grep -q '^\.text'
        ;;
    xmllint) x=$(tool xmllint) && printf '<svg/>\n' >"$d/a.svg" && "$x" --noout "$d/a.svg" ;;
    osmesa)
        cc=$(tool cc) && p=$(tool pkg-config) && flags=$("$p" --cflags --libs osmesa) &&
            "$cc" $W "$w/osmesa.c" $flags -o "$d/osmesa" && expect 255 "$d/osmesa"
        ;;
    cmake)
        c=$(tool cmake) && cp "$w/hello.c" "$w/CMakeLists.txt" "$d/" && "$c" -S "$d" -B "$d/b" >"$d/log" 2>&1 &&
            "$c" --build "$d/b" >>"$d/log" 2>&1 && expect 2 "$d/b/hello" || { tail -5 "$d/log"; false; }
        ;;
    glslang) g=$(tool glslangValidator) && "$g" -V "$w/f.frag" -o "$d/f.spv" >/dev/null ;;
    spirv-val)
        v=$(tool spirv-val) || return 1
        g=$(tool glslangValidator) && "$g" -V "$w/f.frag" -o "$d/f.spv" >/dev/null || return 0
        "$v" --target-env vulkan1.0 "$d/f.spv"
        ;;
    spirv-cross)
        # GLSL to SPIR-V to MSL, as tests/shader_ports/test_msl.sh translates it
        x=$(tool spirv-cross) || return 1
        g=$(tool glslangValidator) && "$g" -V "$w/f.frag" -o "$d/f.spv" >/dev/null || return 0
        "$x" --msl "$d/f.spv" --output "$d/f.metal" && grep -q 'fragment' "$d/f.metal"
        ;;
    vulkan) cc=$(tool cc) && "$cc" $W "$w/vulkan.c" -lvulkan -o "$d/vulkan" ;;
    lavapipe)
        icd=$(ls "$root"/usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -1)
        [ -n "$icd" ] || { echo "no lavapipe ICD in $root/usr/share/vulkan/icd.d"; return 1; }
        cc=$(tool cc) && "$cc" $W "$w/vulkan.c" -lvulkan -o "$d/vulkan" 2>/dev/null || return 0
        devices=$(VK_ICD_FILENAMES="$icd" VK_DRIVER_FILES="$icd" timeout 120 "$d/vulkan" 2>&1)
        printf '%s\n' "$devices" | grep -q llvmpipe || { echo "no lavapipe (llvmpipe) device: $devices"; false; }
        ;;
    chromium)
        c=$(tool chromium) && HOME="$d" timeout 120 "$c" --headless=new --no-sandbox --use-angle=swiftshader \
            --enable-unsafe-swiftshader --no-first-run --disable-extensions --user-data-dir="$d/profile" \
            --window-size=64,64 --screenshot="$d/blank.png" about:blank >"$d/log" 2>&1 &&
            [ "$(head -c 4 "$d/blank.png" 2>/dev/null | od -An -tx1 | tr -d ' ')" = 89504e47 ] ||
            { echo "no screenshot of about:blank: $(tail -3 "$d/log")"; false; }
        ;;
    firefox)
        # WebGPU in headless Firefox ESR, as tests/shader_ports/test_wgsl.sh
        # runs it: the prefs, a page asking for an adapter with the
        # shader-f16 feature (the --wgsl-f16 modules), a marker on stdout
        f=$(tool firefox-esr) || return 1
        mkdir -p "$d/profile"
        printf 'user_pref("%s", true);\n' dom.webgpu.enabled gfx.webgpu.force-enabled gfx.webgpu.ignore-blocklist \
            browser.dom.window.dump.enabled >"$d/profile/user.js"
        {
            printf '<script>navigator.gpu.requestAdapter().then((a) => dump(!a ? "WEBGPU_NONE\\n" :\n'
            printf '  a.features.has("shader-f16") ? "WEBGPU_OK\\n" : "WEBGPU_NO_SHADER_F16\\n"),\n'
            printf '  (e) => dump("WEBGPU_ERROR " + e + "\\n"));</script>\n'
        } >"$d/gpu.html"
        HOME="$d" "$f" --headless --no-remote --profile "$d/profile" "file://$d/gpu.html" >"$d/log" 2>&1 &
        pid=$!
        n=0
        while ! grep -q WEBGPU_ "$d/log" && kill -0 $pid 2>/dev/null && [ $n -lt 120 ]; do
            sleep 1
            n=$((n + 1))
        done
        kill $pid 2>/dev/null
        wait $pid 2>/dev/null
        grep -q WEBGPU_OK "$d/log" || { echo "no WebGPU adapter with shader-f16 in headless Firefox: $(grep -a WEBGPU_ "$d/log" || tail -3 "$d/log")"; false; }
        ;;
    arm-none-eabi)
        arm=$(tool arm-none-eabi-gcc) && cortex_m "$d/m0.elf" "$M0" ports/cortex-m0/microbit.ld "$w/bare.c" &&
            nm=$(tool arm-none-eabi-nm) && "$nm" "$d/m0.elf" | grep -q ' T main$' &&
            od=$(tool arm-none-eabi-objdump) && "$od" -d "$d/m0.elf" | grep -q '<main>:'
        ;;
    newlib)
        if ! arm=$(tool arm-none-eabi-gcc) || ! cortex_m "$d/probe.elf" "$M0" ports/cortex-m0/microbit.ld "$w/bare.c" \
            >/dev/null 2>&1; then
            [ -d "$root/usr/lib/arm-none-eabi/newlib" ]
            return
        fi
        for t in m0 m4f; do
            if [ $t = m0 ]; then cf=$M0 ld=ports/cortex-m0/microbit.ld; else cf=$M4F ld=ports/cortex-m4f/mps2-an386.ld; fi
            cortex_m "$d/$t.elf" "$cf" "$ld" -DLIBM "$w/bare.c" -lm -lc || return 1
        done
        ;;
    qemu-arm)
        qemu=$(tool qemu-system-arm) || return 1
        arm=$(tool arm-none-eabi-gcc) && cortex_m "$d/m0.elf" "$M0" ports/cortex-m0/microbit.ld "$w/bare.c" >/dev/null 2>&1 &&
            cortex_m "$d/m4f.elf" "$M4F" ports/cortex-m4f/mps2-an386.ld "$w/bare.c" >/dev/null 2>&1 &&
            cortex_m "$d/m55.elf" "$M55" ports/cortex-m55/mps3-an547.ld "$w/bare.c" >/dev/null 2>&1 || return 0
        qemu_arm microbit "$d/m0.elf" && qemu_arm mps2-an386 "$d/m4f.elf" && qemu_arm mps3-an547 "$d/m55.elf"
        ;;
    riscv64-elf | qemu-riscv32)
        if [ "$1" = qemu-riscv32 ]; then
            qemu=$(tool qemu-riscv32 || tool qemu-riscv32-static) || return 1
        fi
        rv=$(tool riscv64-unknown-elf-gcc) &&
            "$rv" $W -march=rv32imc -mabi=ilp32 -Os -ffreestanding -Iports/common -nostdlib -nostartfiles -static \
                -Wl,--gc-sections -Wl,--no-warn-rwx-segments "$w/bare.c" ports/rv32imc/port.c ports/rv32imc/start.S \
                ports/common/mem.c -lgcc -o "$d/rv32.elf" && nm=$(tool riscv64-unknown-elf-nm) &&
            "$nm" "$d/rv32.elf" | grep -q ' T main$' || { [ "$1" = qemu-riscv32 ] && return 0; return 1; }
        [ "$1" = riscv64-elf ] || expect ok "$qemu" "$d/rv32.elf"
        ;;
    aarch64 | qemu-aarch64)
        if [ "$1" = qemu-aarch64 ]; then
            qemu=$(tool qemu-aarch64-static) || return 1
        fi
        cc=$(tool aarch64-linux-gnu-gcc) && "$cc" $W -O2 -static "$w/hello.c" -lm -o "$d/hello" ||
            { [ "$1" = qemu-aarch64 ] && return 0; return 1; }
        [ "$1" = aarch64 ] || expect 2 "$qemu" "$d/hello"
        ;;
    esac
}

# probe_all ROW...: every probe at once; sets $failed to the rows that fail
probe_all() {
    for r in "$@"; do
        (probe "$r" >"$w/$r.log" 2>&1 </dev/null && : >"$w/$r.ok") &
    done
    wait
    failed=""
    for r in "$@"; do
        [ -f "$w/$r.ok" ] || failed="$failed $r"
        rm -f "$w/$r.ok"
    done
}
# done_ok [WHAT]: exit 0; for a target, first say what it needed
done_ok() {
    [ -n "$target" ] && echo "deps: $target needs the rows $(echo $rows): ${1:-all present}"
    exit 0
}
# shellcheck disable=SC2086
probe_all $rows
[ -z "$failed" ] && done_ok
missing=""
for r in $failed; do
    for pkg in $(packages "$r"); do
        case " $missing " in
        *" $pkg "*) ;;
        *) missing="$missing $pkg" ;;
        esac
    done
done

apt="apt-get -o DPkg::Lock::Timeout=600"
install="DEBIAN_FRONTEND=noninteractive $apt install -y --no-install-recommends$missing"
if [ "$uid" -ne 0 ]; then
    echo "deps: missing$missing (probes that failed:$failed). Run as root, then make test again:" >&2
    echo "$apt update && $install" >&2
    exit 1
fi
echo "deps: installing$missing (probes that failed:$failed)"
run_apt="${DEPS_APT:-apt-get} -o DPkg::Lock::Timeout=600"
$run_apt update -qq && DEBIAN_FRONTEND=noninteractive $run_apt install -y --no-install-recommends$missing >/dev/null || {
    echo "deps: could not install$missing; run: $apt update && $install" >&2
    exit 1
}
# shellcheck disable=SC2086
probe_all $failed
[ -z "$failed" ] && done_ok "installed$missing"
for r in $failed; do
    echo "deps: the $r probe still fails with$(printf ' %s' $(packages "$r")) installed:" >&2
    sed "s/^/    /" "$w/$r.log" | head -8 >&2
done
exit 1
