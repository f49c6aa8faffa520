# SPDX-License-Identifier: MIT
# Board profile: a PC (x86-64), native build. Profiles are plain variables
# read by the top Makefile:
#   CROSS_COMPILE  toolchain prefix          CPU_FLAGS   code-generation flags
#   BUILD          output directory (cross builds keep theirs apart)
#   PKG_CONFIG     pkg-config finding the target's libdrm/libevdev/libgpiod
#   BOARD_ROTATION default display rotation (0/90/180/270; FIXEL_ROTATION wins)
#   BOARD_BACKEND  default display backend (auto/drm/fbdev/memory; FIXEL_BACKEND wins)
#   BOARD_DRM_FORMAT RGB565 for a 16-bit panel (FIXEL_DRM_FORMAT wins), else XRGB8888
#   BOARD_GPIO_BUTTONS default GPIO button map (syntax: fixel/input docs), "" = none
CROSS_COMPILE ?=
CPU_FLAGS ?=
BOARD_ROTATION ?= 0
BOARD_BACKEND ?= auto
BOARD_GPIO_BUTTONS ?=
