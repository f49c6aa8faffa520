#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs what the qemu kernel rig needs on a Debian 12 host (run as root;
# CI runs it through `make deps-kernel`). Each step is skipped when already done
# so a warm machine pays only the dpkg queries.
set -eu
APT="apt-get -o DPkg::Lock::Timeout=300 -y -q --no-install-recommends"
export DEBIAN_FRONTEND=noninteractive

need=""
for p in qemu-system-x86 qemu-system-arm busybox-static cpio kmod xz-utils make gcc \
         libdrm-dev libevdev-dev libgpiod-dev gcc-aarch64-linux-gnu libc6-dev-arm64-cross \
         python3 bc; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed' || need="$need $p"
done

as_root() {
    if [ "$(id -u)" != 0 ]; then
        echo "deps.sh: missing packages or the arm64 architecture; run as root: sh $0" >&2
        exit 1
    fi
}

# arm64 guest programs link the arm64 static libdrm/libevdev/libgpiod; libpng
# and zlib make `make BOARD=qemu-arm64` (or rpi4/rpi5) build the whole library.
if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    as_root
    dpkg --add-architecture arm64
    updated=no
else
    updated=yes
fi
for p in libdrm-dev:arm64 libevdev-dev:arm64 libgpiod-dev:arm64 libpng-dev:arm64 zlib1g-dev:arm64; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed' || need="$need $p"
done

if [ -n "$need" ] || [ "$updated" = no ]; then
    as_root
    $APT update >/dev/null 2>&1 || $APT update >/dev/null 2>&1 || echo "deps.sh: apt-get update reported errors (mirror mid-sync?); trying anyway"
    if [ -n "$need" ]; then
        echo "deps.sh: installing$need"
        $APT install $need >/dev/null
    fi
fi
