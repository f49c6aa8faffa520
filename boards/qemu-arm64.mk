# SPDX-License-Identifier: MIT
# Board profile: the rig's arm64 guest (qemu -M virt -cpu cortex-a72, virtio-gpu).
CROSS_COMPILE ?= aarch64-linux-gnu-
CPU_FLAGS ?= -mcpu=cortex-a72
BUILD ?= build/qemu-arm64
PKG_CONFIG ?= PKG_CONFIG_LIBDIR=/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig pkg-config
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= drm
BOARD_GPIO_BUTTONS ?=
