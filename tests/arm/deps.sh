#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs what `make test-arm` and `make BOARD=rpi*` need on a Debian 12 host
# (root): the cross compilers for arm64, armhf and armel (ARMv6), qemu's user
# emulators, and the target architectures' -dev packages (multiarch) for
# libdrm, libevdev, libgpiod, libpng and zlib; for armel, when the multiarch
# packages cannot be installed, a private sysroot instead
# (tests/arm/sysroot-armel.sh). Skips what is present.
set -eu
cd "$(dirname "$0")/../.."
APT="apt-get -o DPkg::Lock::Timeout=300 -y -q --no-install-recommends"
export DEBIAN_FRONTEND=noninteractive
if [ "$(id -u)" != 0 ]; then
    echo "tests/arm/deps.sh: must run as root (apt-get install); or install:" >&2
    echo "  gcc-aarch64-linux-gnu gcc-arm-linux-gnueabihf gcc-arm-linux-gnueabi libc6-dev-armel-cross qemu-user-static" >&2
    echo "  and lib{drm,evdev,gpiod,png}-dev zlib1g-dev for :arm64 :armhf (for armel: sh tests/arm/sysroot-armel.sh)" >&2
    exit 1
fi
added=no
for arch in arm64 armhf armel; do
    if ! dpkg --print-foreign-architectures | grep -qx $arch; then
        dpkg --add-architecture $arch
        added=yes
    fi
done
installed() { dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null | grep -q '^install ok installed'; }
need=""
for p in gcc-aarch64-linux-gnu gcc-arm-linux-gnueabihf gcc-arm-linux-gnueabi libc6-dev-armel-cross \
         libc6-dev-arm64-cross libc6-dev-armhf-cross qemu-user-static; do
    installed "$p" || need="$need $p"
done
# A mirror caught mid-sync fails one index; the others still serve.
if [ -n "$need" ] || [ $added = yes ]; then
    $APT update >/dev/null 2>&1 || $APT update >/dev/null 2>&1 ||
        echo "tests/arm/deps.sh: apt-get update reported errors; trying anyway"
fi
if [ -n "$need" ]; then
    echo "tests/arm/deps.sh: installing$need"
    $APT install $need >/dev/null || echo "tests/arm/deps.sh: could not install the cross toolchains"
fi
# Each architecture's libraries on their own: multiarch needs the same
# version as the host's package, and when a mirror is out of step for one
# architecture the others must still be tested (test-arm builds and runs an
# architecture whose libraries are missing without what needs them, and says
# so).
for arch in arm64 armhf armel; do
    need=""
    for p in libdrm-dev libevdev-dev libgpiod-dev libpng-dev zlib1g-dev; do
        installed "$p:$arch" || need="$need $p:$arch"
    done
    [ -z "$need" ] && continue
    if [ $arch = armel ]; then
        # bookworm-security has no armel: once the host's zlib1g, libpng16-16
        # or linux-libc-dev has a security update, the armel packages
        # (bookworm main, older) cannot be co-installed. apt's simulation
        # (no download) tells that case from a failed download; the sysroot
        # serves either way.
        if $APT -s install $need >/dev/null 2>&1; then
            if $APT install $need >/dev/null 2>&1; then
                echo "tests/arm/deps.sh: installed$need"; continue
            fi
            why="could not install the armel libraries (mirror out of step?)"
        else
            why="the armel libraries do not install beside the host's packages (bookworm-security has no armel; multiarch needs equal versions)"
        fi
        [ -f build/sysroot-armel/.fixel-sysroot ] || echo "tests/arm/deps.sh: $why; unpacking them into build/sysroot-armel"
        # the index may predate a point release that replaced the files:
        # one fresh apt-get update and a second try
        sh tests/arm/sysroot-armel.sh ||
            { $APT update >/dev/null 2>&1; sh tests/arm/sysroot-armel.sh; } ||
            echo "tests/arm/deps.sh: no armel libraries (multiarch or sysroot, see above); test-arm runs rpi-zero without them"
        continue
    fi
    echo "tests/arm/deps.sh: installing$need"
    $APT install $need >/dev/null 2>&1 ||
        echo "tests/arm/deps.sh: could not install the $arch libraries (mirror out of step?); test-arm runs $arch without them"
done
exit 0
