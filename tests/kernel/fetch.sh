#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetches Debian's kernel for amd64 and arm64 (image, headers, kbuild, the few
# source files gpio-sim needs) into the cache and builds the out-of-tree
# gpio-sim module for both. Nothing is installed: packages are downloaded and
# unpacked with dpkg -x. Each step leaves a stamp so a warm cache costs only
# the apt-cache query that resolves the version.
#
# usage: fetch.sh CACHE_DIR      prints the cache's per-ABI directory last
set -eu
CACHE=$(mkdir -p "$1" && cd "$1" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
log() { echo "fetch: $*" >&2; }

# The metapackage points at the current ABI; image, headers, kbuild and source
# must all come from the same upload, so the version is pinned explicitly.
ABI=$(apt-cache depends linux-image-amd64 2>/dev/null |
      sed -n 's/^ *Depends: linux-image-\(.*\)-amd64$/\1/p' | head -1)
if [ -z "$ABI" ]; then
    log "cannot resolve the kernel ABI from linux-image-amd64 (run apt-get update?)"
    exit 1
fi
VER=$(apt-cache show "linux-image-$ABI-amd64" | sed -n 's/^Version: //p' | head -1)
KSER=$(echo "$ABI" | cut -d. -f1,2)           # 6.1
D="$CACHE/$ABI"
mkdir -p "$D/debs"

dl() { # package[:arch] — apt-get download into debs/ unless already there
    name=${1%%:*}
    arch=amd64
    case $1 in *:*) arch=${1#*:} ;; esac
    set -- "$D"/debs/"${name}"_*_"$arch".deb "$D"/debs/"${name}"_*_all.deb
    for f; do [ -f "$f" ] && return 0; done
    log "apt-get download $name ($arch)"
    (cd "$D/debs" && apt-get -q -o APT::Sandbox::User=root download "$name:$arch=$VER" >/dev/null 2>&1) ||
        (cd "$D/debs" && apt-get -q -o APT::Sandbox::User=root download "$name:$arch" >/dev/null)
}
deb() { ls "$D"/debs/"$1"_*.deb | head -1; }

# --- images --------------------------------------------------------------
if [ ! -f "$D/amd64.stamp" ]; then
    dl "linux-image-$ABI-amd64"
    rm -rf "$D/amd64"; mkdir -p "$D/amd64"
    dpkg -x "$(deb "linux-image-$ABI-amd64")" "$D/amd64/root"
    depmod -b "$D/amd64/root" "$ABI-amd64"
    # PVH boot of the bare ELF skips SeaBIOS's and the guest's own xz
    # decompression, ~2 s of every TCG boot.
    python3 "$HERE/extract_vmlinux.py" "$D/amd64/root/boot/vmlinuz-$ABI-amd64" "$D/amd64/vmlinux"
    touch "$D/amd64.stamp"
fi
if [ ! -f "$D/arm64.stamp" ]; then
    dl "linux-image-$ABI-arm64:arm64"
    rm -rf "$D/arm64"; mkdir -p "$D/arm64"
    dpkg -x "$(deb "linux-image-$ABI-arm64")" "$D/arm64/root"
    depmod -b "$D/arm64/root" "$ABI-arm64"
    touch "$D/arm64.stamp"
fi
if [ ! -f "$D/busybox-arm64.stamp" ]; then
    dl busybox-static:arm64
    rm -rf "$D/bb-arm64"
    dpkg -x "$(deb busybox-static)" "$D/bb-arm64"
    cp "$D/bb-arm64/bin/busybox" "$D/arm64/busybox"
    rm -rf "$D/bb-arm64"
    touch "$D/busybox-arm64.stamp"
fi

# --- headers + kbuild ----------------------------------------------------
if [ ! -f "$D/headers.stamp" ]; then
    dl "linux-headers-$ABI-common"
    dl "linux-headers-$ABI-amd64"
    dl "linux-headers-$ABI-arm64:arm64"
    dl "linux-kbuild-$KSER"
    rm -rf "$D/kbuild"
    for p in "linux-headers-$ABI-common" "linux-headers-$ABI-amd64" \
             "linux-headers-$ABI-arm64" "linux-kbuild-$KSER"; do
        dpkg -x "$(deb "$p")" "$D/kbuild"
    done
    # The per-arch trees include the common tree by absolute path and point
    # their scripts/tools at /usr/lib/linux-kbuild-*; re-point both into the
    # cache.
    for a in amd64 arm64; do
        h="$D/kbuild/usr/src/linux-headers-$ABI-$a"
        sed -i "s#/usr/src/#$D/kbuild/usr/src/#g" "$h/Makefile"
    done
    for l in $(find "$D/kbuild/usr/src" -maxdepth 2 -type l); do
        t=$(readlink "$l")
        case $t in /*) ln -sfn "$D/kbuild$t" "$l" ;; esac
    done
    touch "$D/headers.stamp"
fi

# --- gpio-sim sources ----------------------------------------------------
if [ ! -f "$D/src.stamp" ]; then
    dl "linux-source-$KSER"
    rm -rf "$D/src"; mkdir -p "$D/src"
    tarball=$(dpkg-deb -c "$(deb "linux-source-$KSER")" | awk '{print $NF}' | grep 'linux-source-.*\.tar\.xz$' | head -1)
    dpkg-deb --fsys-tarfile "$(deb "linux-source-$KSER")" | tar -x -C "$D/src" "$tarball"
    top=$(basename "$tarball" .tar.xz)
    tar -xJf "$D/src/$tarball" -C "$D/src" "$top/drivers/gpio/gpio-sim.c" \
        "$top/drivers/gpio/gpiolib.h" "$top/kernel/irq/irq_sim.c"
    mkdir -p "$D/gpio-sim"
    cp "$D/src/$top/drivers/gpio/gpio-sim.c" "$D/src/$top/drivers/gpio/gpiolib.h" \
       "$D/src/$top/kernel/irq/irq_sim.c" "$D/gpio-sim/"
    rm -rf "$D/src" "$D"/debs/linux-source-*.deb
    # irq_to_desc() is not exported to modules; generic_handle_irq() does the
    # same dispatch through an exported symbol (CONFIG_IRQ_SIM is off, so
    # irq_sim.c must be built into the module).
    sed -i 's/handle_simple_irq(irq_to_desc(\([a-z_]*\)));/generic_handle_irq(\1);/' "$D/gpio-sim/irq_sim.c"
    grep -q 'generic_handle_irq(' "$D/gpio-sim/irq_sim.c" || { log "irq_sim.c patch did not apply"; exit 1; }
    printf 'obj-m := gpio-sim-oot.o\ngpio-sim-oot-y := gpio-sim.o irq_sim.o\n' > "$D/gpio-sim/Kbuild"
    touch "$D/src.stamp"
fi

# --- gpio-sim module, both arches ----------------------------------------
for a in amd64 arm64; do
    ko="$D/$a/gpio-sim-oot.ko"
    [ -f "$ko" ] && continue
    log "building gpio-sim for $a"
    rm -rf "$D/build-$a"; cp -r "$D/gpio-sim" "$D/build-$a"
    extra=""
    [ $a = arm64 ] && extra="ARCH=arm64 CROSS_COMPILE=aarch64-linux-gnu-"
    make -s -C "$D/kbuild/usr/src/linux-headers-$ABI-$a" M="$D/build-$a" $extra modules >"$D/build-$a.log" 2>&1 ||
        { cat "$D/build-$a.log" >&2; exit 1; }
    cp "$D/build-$a/gpio-sim-oot.ko" "$ko"
    rm -rf "$D/build-$a"
done

# --- vkms, both arches ---------------------------------------------------
# Debian 6.1 has CONFIG_DRM_VKMS off; the virtual KMS driver is built out of
# tree like gpio-sim. It offers RGB565 on its primary plane and computes CRCs
# of every composed frame (debugfs): the rig's proof of 16-bit scanout.
if [ ! -f "$D/vkms-src.stamp" ]; then
    dl "linux-source-$KSER"
    rm -rf "$D/src" "$D/vkms"; mkdir -p "$D/src" "$D/vkms"
    tarball=$(dpkg-deb -c "$(deb "linux-source-$KSER")" | awk '{print $NF}' | grep 'linux-source-.*\.tar\.xz$' | head -1)
    top=$(basename "$tarball" .tar.xz)
    dpkg-deb --fsys-tarfile "$(deb "linux-source-$KSER")" | tar -xO "$tarball" |
        tar -xJ -C "$D/src" "$top/drivers/gpu/drm/vkms"
    cp "$D/src/$top"/drivers/gpu/drm/vkms/*.[ch] "$D/vkms/"
    rm -rf "$D/src" "$D"/debs/linux-source-*.deb
    objs=$(cd "$D/vkms" && ls *.c | sed 's/\.c$/.o/' | tr '\n' ' ')
    printf 'obj-m := vkms.o\nvkms-y := %s\n' "$objs" > "$D/vkms/Kbuild"
    touch "$D/vkms-src.stamp"
fi
for a in amd64 arm64; do
    ko="$D/$a/vkms.ko"
    [ -f "$ko" ] && continue
    log "building vkms for $a"
    # A cache copied from another directory still names the old place in the
    # headers' one-line Makefile: point it here again.
    sed -i "s#^include .*/linux-headers-$ABI-common/Makefile\$#include $D/kbuild/usr/src/linux-headers-$ABI-common/Makefile#" \
        "$D/kbuild/usr/src/linux-headers-$ABI-$a/Makefile"
    rm -rf "$D/vkms-build-$a"; cp -r "$D/vkms" "$D/vkms-build-$a"
    extra=""
    [ $a = arm64 ] && extra="ARCH=arm64 CROSS_COMPILE=aarch64-linux-gnu-"
    make -s -C "$D/kbuild/usr/src/linux-headers-$ABI-$a" M="$D/vkms-build-$a" $extra modules >"$D/vkms-build-$a.log" 2>&1 ||
        { cat "$D/vkms-build-$a.log" >&2; exit 1; }
    cp "$D/vkms-build-$a/vkms.ko" "$ko"
    rm -rf "$D/vkms-build-$a"
done

echo "$D"
