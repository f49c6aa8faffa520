# SPDX-License-Identifier: MIT
# Board profile: Raspberry Pi Zero / Zero W / Pi 1 (ARM1176, ARMv6, VFPv2).
# Debian's armhf targets ARMv7, so the soft-float armel toolchain
# (gcc-arm-linux-gnueabi + libc6-dev-armel-cross) is used; static builds run
# on Raspberry Pi OS too.
CROSS_COMPILE ?= arm-linux-gnueabi-
CPU_FLAGS ?= -march=armv6 -marm
BUILD ?= build/rpi-zero
# Board libraries: Debian's multiarch packages (libpng-dev:armel ...) when
# they are installed, else the private sysroot tests/arm/sysroot-armel.sh
# unpacks (bookworm's security suite has no armel, so the multiarch ones stop
# installing once the host's zlib or libpng has a security update). With
# PKG_CONFIG_SYSROOT_DIR, pkg-config puts the sysroot before every -I and -L.
ARMEL_SYSROOT ?= $(CURDIR)/build/sysroot-armel
ARMEL_MULTIARCH_PKG_CONFIG := PKG_CONFIG_LIBDIR=/usr/lib/arm-linux-gnueabi/pkgconfig:/usr/share/pkgconfig pkg-config
ifndef PKG_CONFIG
  ifneq ($(wildcard $(ARMEL_SYSROOT)/.fixel-sysroot),)
    ifeq ($(shell $(ARMEL_MULTIARCH_PKG_CONFIG) --exists libpng zlib libdrm libevdev libgpiod 2>/dev/null && echo y),)
      PKG_CONFIG := PKG_CONFIG_SYSROOT_DIR=$(ARMEL_SYSROOT) \
        PKG_CONFIG_LIBDIR=$(ARMEL_SYSROOT)/usr/lib/arm-linux-gnueabi/pkgconfig:$(ARMEL_SYSROOT)/usr/share/pkgconfig pkg-config
    endif
  endif
endif
PKG_CONFIG ?= $(ARMEL_MULTIARCH_PKG_CONFIG)
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= auto
BOARD_GPIO_BUTTONS ?= :GPIO17=up/low,:GPIO27=down/low,:GPIO22=enter/low
