#!/bin/sh
# SPDX-License-Identifier: MIT
# Drives one rig run: fetch/build the cached kernel pieces, pack one
# initramfs per architecture, boot both guests and judge them (run.py).
# usage: rig.sh CACHE_DIR BUILD_DIR     (BUILD_DIR holds <arch>/tests/*, host_render)
set -eu
CACHE=$1 B=$2
HERE=$(cd "$(dirname "$0")" && pwd)
D=$(sh "$HERE/fetch.sh" "$CACHE" | tail -1)
ABI=$(basename "$D")
mkdir -p "$B/work"
OPTIONAL_MODULES=drm_shmem_helper OPTIONAL_KO="$D/amd64/vkms.ko" CARD_MODULES=virtio-gpu \
sh "$HERE/mkinitramfs.sh" "$D/amd64/root" "$ABI-amd64" /bin/busybox "$D/amd64/gpio-sim-oot.ko" \
    "$B/x86_64/tests" "$B/work/initrd-x86_64.cpio.gz" \
    bochs virtio_pci virtio_input uinput evdev configfs
OPTIONAL_MODULES=drm_shmem_helper OPTIONAL_KO="$D/arm64/vkms.ko" CARD_MODULES=bochs \
sh "$HERE/mkinitramfs.sh" "$D/arm64/root" "$ABI-arm64" "$D/arm64/busybox" "$D/arm64/gpio-sim-oot.ko" \
    "$B/aarch64/tests" "$B/work/initrd-aarch64.cpio.gz" \
    virtio_pci virtio-gpu virtio_input uinput evdev configfs
exec python3 "$HERE/run.py" --render "$B/host_render" --work "$B/work" ${RIG_PARALLEL:+--parallel} \
    "arch=x86_64,kernel=$D/amd64/vmlinux,initrd=$B/work/initrd-x86_64.cpio.gz" \
    "arch=aarch64,kernel=$D/arm64/root/boot/vmlinuz-$ABI-arm64,initrd=$B/work/initrd-aarch64.cpio.gz"
