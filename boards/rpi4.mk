# SPDX-License-Identifier: MIT
# Board profile: Raspberry Pi 4 / 400 / CM4, 64-bit OS (vc4-kms-v3d: DRM).
CROSS_COMPILE ?= aarch64-linux-gnu-
CPU_FLAGS ?= -mcpu=cortex-a72
BUILD ?= build/rpi4
PKG_CONFIG ?= PKG_CONFIG_LIBDIR=/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig pkg-config
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= auto
BOARD_GPIO_BUTTONS ?= :GPIO17=up/low,:GPIO27=down/low,:GPIO22=enter/low
