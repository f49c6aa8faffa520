# SPDX-License-Identifier: MIT
# Board profile: Raspberry Pi Zero / Zero W / Pi 1 (ARM1176, ARMv6, VFPv2).
# Debian's armhf targets ARMv7, so the soft-float armel toolchain
# (gcc-arm-linux-gnueabi + libc6-dev-armel-cross) is used; static builds run
# on Raspberry Pi OS too.
CROSS_COMPILE ?= arm-linux-gnueabi-
CPU_FLAGS ?= -march=armv6 -marm
BUILD ?= build/rpi-zero
PKG_CONFIG ?= PKG_CONFIG_LIBDIR=/usr/lib/arm-linux-gnueabi/pkgconfig:/usr/share/pkgconfig pkg-config
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= auto
BOARD_GPIO_BUTTONS ?= :GPIO17=up/low,:GPIO27=down/low,:GPIO22=enter/low
