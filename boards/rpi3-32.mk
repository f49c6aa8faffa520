# SPDX-License-Identifier: MIT
# Board profile: Raspberry Pi 2 v1.2 / 3 / Zero 2 running a 32-bit (armhf) OS.
CROSS_COMPILE ?= arm-linux-gnueabihf-
CPU_FLAGS ?= -mcpu=cortex-a53 -mfpu=neon-fp-armv8 -mfloat-abi=hard
BUILD ?= build/rpi3-32
PKG_CONFIG ?= PKG_CONFIG_LIBDIR=/usr/lib/arm-linux-gnueabihf/pkgconfig:/usr/share/pkgconfig pkg-config
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= auto
BOARD_GPIO_BUTTONS ?= :GPIO17=up/low,:GPIO27=down/low,:GPIO22=enter/low
