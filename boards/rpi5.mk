# SPDX-License-Identifier: MIT
# Board profile: Raspberry Pi 5, 64-bit OS (vc4/v3d DRM; GPIO on the RP1 chip).
CROSS_COMPILE ?= aarch64-linux-gnu-
CPU_FLAGS ?= -mcpu=cortex-a76
BUILD ?= build/rpi5
PKG_CONFIG ?= PKG_CONFIG_LIBDIR=/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig pkg-config
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= auto
BOARD_GPIO_BUTTONS ?= :GPIO17=up/low,:GPIO27=down/low,:GPIO22=enter/low
