#!/bin/sh
# make install / make uninstall.
#   sh ports/install.sh install   DESTDIR PREFIX BUILD
#   sh ports/install.sh uninstall DESTDIR PREFIX
# Installs, under DESTDIR/PREFIX:
#   include/*.h and the single-file runtimes (ports/single/*.h),
#   lib/libfresnel.a, lib/pkgconfig/fresnel.pc,
#   lib/cmake/fresnel/fresnelConfig.cmake + fresnelConfigVersion.cmake
#   (imported target fresnel::fresnel), bin/fresnel, share/fresnel/data/ (the
#   data pack, which the installed bin/fresnel finds without --data),
#   share/fresnel/glsl/ (the GLSL port), share/fresnel/hlsl/fresnel.hlsl and
#   share/fresnel/msl/fresnel.metal (the HLSL and MSL ports as one file each,
#   BUILD/hlsl/fresnel.hlsl, BUILD/msl/fresnel.metal), share/fresnel/LICENSE,
# and share/fresnel/install_manifest.txt: one line per installed file
# ("f PATH") and per directory the install created ("d PATH"), relative to
# DESTDIR/PREFIX. uninstall removes exactly those files, then those
# directories if they are empty, and nothing else.
set -u
action=${1:-}
destdir=${2-}
prefix=${3:-/usr/local}
build=${4:-build}
case $prefix in
/*) ;;
*)
    echo "install: PREFIX must be an absolute path, got '$prefix'" >&2
    exit 2
    ;;
esac
root=$destdir$prefix
manifest_rel=share/fresnel/install_manifest.txt
manifest=$root/$manifest_rel

# inside REL: REL is a relative path that stays inside DESTDIR/PREFIX (no
# empty, "." or ".." part), so "f ../../x" or "d /etc" in a tampered
# manifest is refused
inside() {
    case $1 in
    "" | /* | . | ./* | .. | ../* | */. | */.. | *//* | */./* | */../*) return 1 ;;
    esac
    return 0
}

uninstall() {
    if [ ! -f "$manifest" ]; then
        echo "uninstall: no $manifest (nothing installed by make install under this DESTDIR and PREFIX)" >&2
        exit 1
    fi
    entries=$(cat "$manifest") || exit 1
    # the physical DESTDIR/PREFIX: a listed file whose directory resolves
    # elsewhere (through a symbolic link) is refused too
    root_real=$(cd "$root" && pwd -P) || exit 1
    # levels above PREFIX that an install may have created: up to DESTDIR
    # itself, and never / (without DESTDIR)
    depth=$(printf '%s\n' "$prefix" | tr -s / '\n' | grep -c .)
    [ -n "$destdir" ] || depth=$((depth - 1))
    refused=$(mktemp) || exit 1
    trap 'rm -f "$refused"' EXIT
    refuse() {
        echo "uninstall: refusing manifest line '$1': $2" >&2
        echo x >>"$refused"
    }
    # files first; then the directories inside PREFIX, deepest first; then
    # PREFIX itself (".") and the levels above it ("./..", "./../..") that
    # the install created, innermost first; each directory only if empty
    printf '%s\n' "$entries" | while IFS= read -r line; do
        case $line in
        "f "* | "d "*) ;;
        "") ;;
        *) refuse "$line" "expected 'f PATH' or 'd PATH'" ;;
        esac
    done
    printf '%s\n' "$entries" | sed -n 's/^f //p' | while IFS= read -r f; do
        if ! inside "$f"; then
            refuse "f $f" "not a path inside $root"
            continue
        fi
        dir=$(cd "$root/$(dirname "$f")" 2>/dev/null && pwd -P) || continue # already gone
        case $dir/ in
        "$root_real"/*) rm -f "$dir/$(basename "$f")" ;;
        *) refuse "f $f" "its directory is $dir, outside $root" ;;
        esac
    done
    {
        printf '%s\n' "$entries" | sed -n 's/^d //p' | grep -v '^\.' | while IFS= read -r d; do
            if inside "$d"; then
                printf '%s\t%s\n' "${#d}" "$d"
            else
                refuse "d $d" "not a path inside $root"
            fi
        done | sort -rn | cut -f2- | while IFS= read -r d; do
            dir=$(cd "$root/$d" 2>/dev/null && pwd -P) || continue
            case $dir/ in
            "$root_real"/?*) echo "$dir" ;;
            *) refuse "d $d" "it is $dir, outside $root" ;;
            esac
        done
        printf '%s\n' "$entries" | sed -n 's/^d //p' | grep '^\.' | sort | while IFS= read -r up; do
            # "." then "/.." any number of times, nothing else; each step
            # shortens rest, so this ends
            rest=${up#.}
            while :; do
                case $rest in
                /..*) rest=${rest#/..} ;;
                *) break ;;
                esac
            done
            if [ -n "$rest" ]; then
                refuse "d $up" "expected '.' or './..' repeated (PREFIX and the levels above it)"
                continue
            fi
            levels=$(printf '%s' "$up" | tr -cd / | wc -c)
            if [ "$levels" -gt "$depth" ]; then
                refuse "d $up" "above ${destdir:-/}"
                continue
            fi
            d=$root
            i=0
            while [ "$i" -lt "$levels" ]; do
                d=$(dirname "$d")
                i=$((i + 1))
            done
            echo "$d"
        done
    } | while IFS= read -r d; do
        rmdir "$d" 2>/dev/null || [ ! -d "$d" ] || echo "uninstall: kept $d (not empty)"
    done
    if [ -s "$refused" ]; then
        echo "uninstall: $(wc -l <"$refused" | tr -d ' ') manifest line(s) refused; nothing outside $root was removed" >&2
        exit 1
    fi
    return 0
}

if [ "$action" = uninstall ]; then
    uninstall
    echo "uninstalled fresnel from $root: every file and directory its install_manifest.txt listed"
    exit 0
fi
if [ "$action" != install ]; then
    echo "usage: sh ports/install.sh install DESTDIR PREFIX BUILD | uninstall DESTDIR PREFIX" >&2
    exit 2
fi
for f in "$build/libfresnel.a" "$build/fresnel" "$build/hlsl/fresnel.hlsl" "$build/msl/fresnel.metal"; do
    [ -f "$f" ] || {
        echo "install: $f missing (make install builds it)" >&2
        exit 1
    }
done

list=$(mktemp) || exit 1
trap 'rm -f "$list" "$list.old"' EXIT
# directories a previous install created stay recorded as created
[ -f "$manifest" ] && grep '^d ' "$manifest" >"$list.old"

# mkdirs REL: creates DESTDIR/PREFIX/REL and records each level it creates
mkdirs() {
    rel=$1
    path=""
    IFS_save=$IFS
    IFS=/
    for part in $rel; do
        path=${path:+$path/}$part
        if [ ! -d "$root/$path" ]; then
            mkdir -p "$root/$path" || exit 1
            echo "d $path" >>"$list"
        fi
    done
    IFS=$IFS_save
}
# put MODE SRC RELDIR: installs SRC as RELDIR/basename(SRC)
put() {
    mkdirs "$2"
    install -m "$1" "$3" "$root/$2/" || exit 1
    echo "f $2/$(basename "$3")" >>"$list"
}
# PREFIX under DESTDIR and the levels above it that are missing count as
# created: "." is DESTDIR/PREFIX, ".." its parent, and so on
up=.
d=$root
while [ ! -d "$d" ]; do
    echo "d $up" >>"$list"
    up=$up/..
    d=$(dirname "$d")
done
mkdir -p "$root" || exit 1

version=$(sed -n 's/^#define FRESNEL_VERSION "\(.*\)"/\1/p' include/fresnel.h)
for h in include/*.h ports/single/*.h; do put 644 include "$h"; done
put 644 lib "$build/libfresnel.a"
put 755 bin "$build/fresnel"
mkdirs lib/pkgconfig
# The prefix may hold any character but a newline. In fresnel.pc it is
# escaped as pkg-config reads a variable that its flags use: a backslash
# before each byte outside [A-Za-z0-9/._+,:=@%^~-] (pkg-config's shell-style
# splitting of the flags takes it away; \$ and \{ keep ${ from being a
# variable), and "\#" for # (the backslash keeps the line reader from
# taking a comment, the quotes keep GLib's splitting in freedesktop
# pkg-config from taking one after an escaped space). Then what sed's
# replacement gives a meaning to (\, & and the | delimiter) is escaped.
prefix_pc=$(printf '%s\n' "$prefix" | LC_ALL=C sed -e 's/[^A-Za-z0-9/._+,:=@%^~#-]/\\&/g' -e 's/#/"\\#"/g')
prefix_sed=$(printf '%s' "$prefix_pc" | sed 's/[\\&|]/\\&/g')
sed -e "s|@PREFIX@|$prefix_sed|" -e "s|@FRESNEL_VERSION@|$version|" ports/fresnel.pc.in \
    >"$root/lib/pkgconfig/fresnel.pc" || exit 1
echo "f lib/pkgconfig/fresnel.pc" >>"$list"
put 644 lib/cmake/fresnel ports/cmake/fresnelConfig.cmake
sed "s/@FRESNEL_VERSION@/$version/" ports/cmake/fresnelConfigVersion.cmake.in >"$root/lib/cmake/fresnel/fresnelConfigVersion.cmake" || exit 1
echo "f lib/cmake/fresnel/fresnelConfigVersion.cmake" >>"$list"
for f in $(cd data && find . -type f | sed 's|^\./||' | sort); do
    put 644 "share/fresnel/data/$(dirname "$f" | sed 's|^\.$||;s|^\./||')" "data/$f"
done
for f in ports/glsl/*.glsl ports/glsl/README.md; do put 644 share/fresnel/glsl "$f"; done
put 644 share/fresnel/hlsl "$build/hlsl/fresnel.hlsl"
put 644 share/fresnel/hlsl ports/hlsl/README.md
put 644 share/fresnel/msl "$build/msl/fresnel.metal"
put 644 share/fresnel/msl ports/msl/README.md
put 644 share/fresnel LICENSE
echo "f $manifest_rel" >>"$list"
{
    [ -f "$list.old" ] && cat "$list.old"
    cat "$list"
} | sed 's|/$||;s|//*|/|g' | awk '!seen[$0]++' >"$manifest.tmp" && mv "$manifest.tmp" "$manifest"

# what went where, and how a build finds it
cat <<EOF
installed fresnel $version in $root ($(grep -c '^f ' "$manifest") files, listed in $manifest_rel):
  include/            $(cd include && ls *.h | tr '\n' ' ')
                      $(cd ports/single && ls *.h | tr '\n' ' ')(one file each)
  lib/                libfresnel.a; pkgconfig/fresnel.pc; the CMake package in lib/cmake/fresnel (target fresnel::fresnel)
  bin/fresnel         the generator, which reads share/fresnel/data/
  share/fresnel/      data/ (the data pack), glsl/, hlsl/ and msl/ (the shader ports), LICENSE
use it: pkg-config --cflags --libs fresnel   (PKG_CONFIG_PATH=$prefix/lib/pkgconfig)
        find_package(fresnel)                (CMAKE_PREFIX_PATH=$prefix)
undo:   make uninstall PREFIX=$prefix${destdir:+ DESTDIR=$destdir}
EOF
