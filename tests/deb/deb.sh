#!/bin/sh
# SPDX-License-Identifier: MIT
# `make deb`: the Debian packages libfixel0, libfixel-dev and fixel-tools,
# built with dpkg-buildpackage for amd64 (native) and cross-built for arm64
# and armhf, each checked by lintian (no errors). The arm packages' fixel-draw
# then renders golden scripts under qemu-user, and the pictures must equal
# the native renders pixel for pixel. The .debs stay in OUT/<arch>/ (the
# fresh-root test installs the native ones: make test-setup).
# usage: deb.sh OUT_DIR [ARCH...]       "deb: N passed, N failed"
#        deb.sh --source-only DIR        only the source copy into DIR (tests/deb/control.sh)

# The source to build: the tracked files of a git work tree (what a clone
# has), or, in a tree without .git (a release tarball, a ZIP), every file
# but the build output. (git ls-files there printed nothing, and
# dpkg-buildpackage then failed with "cannot open debian/changelog".)
copy_source() {
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1 && [ -n "$(git ls-files debian/changelog)" ]; then
        git ls-files -z | tar --null -T - -c | tar -x -C "$1"
    else
        tar -c --exclude=./build --exclude=./out --exclude=./.git . | tar -x -C "$1"
    fi
    [ -f "$1/debian/changelog" ] || { echo "deb: the source copy in $1 has no debian/changelog"; return 1; }
}
if [ "$1" = "--source-only" ]; then
    mkdir -p "$2" && copy_source "$2"; exit
fi
OUT=${1:-build/deb}; shift
ARCHES=${*:-amd64 arm64 armhf}
SRC=$(pwd)
mkdir -p "$OUT" && OUT=$(cd "$OUT" && pwd)
P=0; F=0
ok() { echo "PASS $*"; P=$((P + 1)); }
no() { echo "FAIL $*"; F=$((F + 1)); }
now() { date +%s; }
NATIVE=$(dpkg --print-architecture)
VERSION=$(dpkg-parsechangelog -l debian/changelog -S Version)
GOLDEN="core-lines conic-circles fill-polygons fill-textures 3d-teapot-gouraud fractal-mandel text-builtin"

for arch in $ARCHES; do
    t0=$(now)
    W=$OUT/$arch; rm -rf "$W"; mkdir -p "$W/src"
    # built out of tree, from a copy of the source
    copy_source "$W/src" || { no "$arch: source copy"; continue; }
    a=""; [ "$arch" != "$NATIVE" ] && a="-a$arch"
    if (cd "$W/src" && DEB_BUILD_OPTIONS="parallel=${DEB_JOBS:-2} ${DEB_BUILD_OPTIONS:-}" dpkg-buildpackage -us -uc -b $a) > "$W/build.log" 2>&1; then
        ok "dpkg-buildpackage $arch ($(( $(now) - t0 )) s): $(cd "$W" && ls *.deb | tr '\n' ' ')"
    else
        tail -n 30 "$W/build.log"; no "dpkg-buildpackage $arch"; continue
    fi
    for p in libfixel0 libfixel-dev fixel-tools; do
        [ -f "$W/${p}_${VERSION}_$arch.deb" ] || no "$arch: no $p package"
    done
    if lintian --fail-on error "$W"/*.changes > "$W/lintian.log" 2>&1; then
        ok "lintian $arch: no errors ($(grep -c '^W:' "$W/lintian.log") warnings, $(grep -c '^I:' "$W/lintian.log") info)"
    else
        cat "$W/lintian.log"; no "lintian $arch"
    fi
    dpkg-deb -c "$W/fixel-tools_${VERSION}_$arch.deb" | grep -q 'usr/bin/fixel-bench' && no "$arch: fixel-bench packaged"
    # the packaged fixel-draw renders golden scripts; cross ones under qemu-user
    rm -rf "$W/x"; mkdir -p "$W/x" "$W/render"
    for d in "$W"/libfixel0_*.deb "$W"/fixel-tools_*.deb; do dpkg -x "$d" "$W/x"; done
    run=""
    case $arch in
    "$NATIVE") run="" ;;
    arm64) run=qemu-aarch64-static ;;
    armhf) run=qemu-arm-static ;;
    *) no "$arch: no qemu named"; continue ;;
    esac
    for g in $GOLDEN; do
        s=tests/golden/scripts/$g.fxs
        [ -f "$s" ] || continue
        if [ ! -f "$OUT/ref/$g.ppm" ]; then
            mkdir -p "$OUT/ref"
            # reference: the native package if built, else this tree's build
            ref=$OUT/$NATIVE/x/usr/bin/fixel-draw; [ -x "$ref" ] || ref=build/bin/fixel-draw
            "$ref" -o "$OUT/ref/$g.ppm" "$s" >/dev/null 2>&1
        fi
        if $run "$W/x/usr/bin/fixel-draw" -o "$W/render/$g.ppm" "$s" > "$W/render/$g.log" 2>&1 &&
           cmp -s "$W/render/$g.ppm" "$OUT/ref/$g.ppm"; then
            ok "$arch fixel-draw ${run:+under $run }renders $g as the native build"
        else
            cat "$W/render/$g.log"; no "$arch fixel-draw $g differs from the native render"
        fi
    done
done
echo "deb: $P passed, $F failed"
[ $F -eq 0 ]
