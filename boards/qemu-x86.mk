# SPDX-License-Identifier: MIT
# Board profile: the rig's x86-64 guest (qemu -M pc, bochs-drm, 800x480).
CROSS_COMPILE ?=
CPU_FLAGS ?=
BUILD ?= build/qemu-x86
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= drm
BOARD_GPIO_BUTTONS ?=
