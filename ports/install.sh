#!/bin/sh
# make install / make uninstall.
#   sh ports/install.sh install   DESTDIR PREFIX BUILD
#   sh ports/install.sh uninstall DESTDIR PREFIX
# Installs, under DESTDIR/PREFIX:
#   include/*.h, lib/libfresnel.a, lib/pkgconfig/fresnel.pc,
#   lib/cmake/fresnel/fresnelConfig.cmake + fresnelConfigVersion.cmake
#   (imported target fresnel::fresnel), bin/fresnel, share/fresnel/data/ (the
#   data pack, which the installed bin/fresnel finds without --data),
#   share/fresnel/glsl/ (the GLSL port), share/fresnel/hlsl/fresnel.hlsl (the
#   HLSL port as one file, BUILD/hlsl/fresnel.hlsl), share/fresnel/LICENSE,
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

uninstall() {
    if [ ! -f "$manifest" ]; then
        echo "uninstall: no $manifest (nothing installed by make install under this DESTDIR and PREFIX)" >&2
        exit 1
    fi
    entries=$(cat "$manifest") || exit 1
    # files first; then the directories inside PREFIX, deepest first; then
    # PREFIX itself (".") and the levels above it ("..", "../..") that the
    # install created, innermost first; each directory only if empty
    printf '%s\n' "$entries" | sed -n 's/^f //p' | while IFS= read -r f; do
        rm -f "$root/$f"
    done
    {
        printf '%s\n' "$entries" | sed -n 's/^d //p' | grep -v '^\.' | awk '{ print length($0) "\t" $0 }' |
            sort -rn | cut -f2- | awk -v r="$root" '{ print r "/" $0 }'
        printf '%s\n' "$entries" | sed -n 's/^d //p' | grep '^\.' | awk '{ print length($0) "\t" $0 }' |
            sort -n | cut -f2- | while IFS= read -r up; do
            d=$root
            up=${up#.}
            while [ -n "$up" ]; do
                d=$(dirname "$d")
                up=${up#/..}
            done
            echo "$d"
        done
    } | while IFS= read -r d; do
        rmdir "$d" 2>/dev/null || [ ! -d "$d" ] || echo "uninstall: kept $d (not empty)"
    done
    return 0
}

if [ "$action" = uninstall ]; then
    uninstall
    exit 0
fi
if [ "$action" != install ]; then
    echo "usage: sh ports/install.sh install DESTDIR PREFIX BUILD | uninstall DESTDIR PREFIX" >&2
    exit 2
fi
for f in "$build/libfresnel.a" "$build/fresnel" "$build/hlsl/fresnel.hlsl"; do
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
for h in include/*.h; do put 644 include "$h"; done
put 644 lib "$build/libfresnel.a"
put 755 bin "$build/fresnel"
mkdirs lib/pkgconfig
# The prefix may hold any character but a newline: escape what sed's
# replacement gives a meaning to (\, & and the | delimiter).
prefix_sed=$(printf '%s' "$prefix" | sed 's/[\\&|]/\\&/g')
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
put 644 share/fresnel LICENSE
echo "f $manifest_rel" >>"$list"
{
    [ -f "$list.old" ] && cat "$list.old"
    cat "$list"
} | sed 's|/$||;s|//*|/|g' | awk '!seen[$0]++' >"$manifest.tmp" && mv "$manifest.tmp" "$manifest"
