# SPDX-License-Identifier: MIT
# The qemu real-kernel rig (tests/kernel/README.md). Included by the top
# Makefile; `make test-kernel` runs it. Guest programs are every
# tests/kernel/guest/*.c, linked statically for x86_64 and aarch64 against
# the library sources (LIB_SRC) compiled here per architecture.

KT_DIR   := tests/kernel
# FIXEL_KERNEL_CACHE lets several work trees share one download.
KT_CACHE ?= $(or $(FIXEL_KERNEL_CACHE),$(KT_DIR)/cache)
KT_BUILD := build/kernel
KT_ARCHES := x86_64 aarch64
KT_CC_x86_64  := gcc
KT_CC_aarch64 := aarch64-linux-gnu-gcc
# The library's sources with the real boards/linux backends, whatever this
# make found: the rig installs libdrm, libevdev and libgpiod itself
# (deps.stamp) and links them (KT_LDLIBS), while LIB_SRC was chosen when make
# read the Makefile, maybe before that install (the stand-ins of
# boards/linux/absent then made 42 rig checks fail: "this build has no
# libdrm"). memfb.c is in it: fx_app's replay writes frames (fx_write_image).
KT_LIBSRC := $(CORE_SRC) $(sort $(foreach d,$(BOARD_DIRS) $(BOARD_LIB_DIRS),$(wildcard boards/$(d)/*.c)))
KT_GUESTSRC := $(wildcard $(KT_DIR)/guest/*.c)
# No -Werror here: the main build enforces it, and a cross compiler's extra
# warning must not stop the rig.
# (the guests decode no JPEG, GIF or WebP and draw no QR code: boards/image
# builds without those libraries, which the targets' sysroots lack)
KT_CFLAGS := -std=c11 -O2 -g0 -Wall -Wextra -DFX_NO_JPEG -DFX_NO_GIF -DFX_NO_WEBP -DFX_NO_QR \
	-Ikernel-free-src/include -Iboards/include -Ikernel-free-src -I$(KT_DIR)/guest \
	-I/usr/include/libdrm -I/usr/include/libevdev-1.0
KT_LDLIBS := -static -ldrm -levdev -lgpiod -lpng16 -lz -lm
# Header dependencies: a struct that changes in a boards/ header must rebuild
# every object using it, or the guests link mismatched layouts.
KT_DEPFLAGS := -MMD -MP
-include $(shell find $(KT_BUILD) -name '*.d' 2>/dev/null)

# Installs qemu, cross compiler, arm64 -dev packages (root; no-op when present).
$(KT_BUILD)/deps.stamp: $(KT_DIR)/deps.sh
	@mkdir -p $(@D)
	sh $(KT_DIR)/deps.sh
	@touch $@

define KT_ARCH_RULES
$(KT_BUILD)/$(1)/obj/%.o: %.c | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) $(KT_DEPFLAGS) -c $$< -o $$@
$(KT_BUILD)/$(1)/libfixel.a: $(patsubst %.c,$(KT_BUILD)/$(1)/obj/%.o,$(KT_LIBSRC))
	@rm -f $$@
	$(if $(filter aarch64,$(1)),aarch64-linux-gnu-ar,ar) rcs $$@ $$^
$(KT_BUILD)/$(1)/tests/%: $(KT_DIR)/guest/%.c $(KT_BUILD)/$(1)/libfixel.a $(wildcard $(KT_DIR)/guest/*.h) | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) $(KT_DEPFLAGS) $$< -o $$@ $(KT_BUILD)/$(1)/libfixel.a $(KT_LDLIBS)
KT_GUESTS += $(patsubst $(KT_DIR)/guest/%.c,$(KT_BUILD)/$(1)/tests/%,$(KT_GUESTSRC))
endef
$(foreach a,$(KT_ARCHES),$(eval $(call KT_ARCH_RULES,$(a))))

$(KT_BUILD)/host_render: $(KT_DIR)/host_render.c $(KT_BUILD)/x86_64/libfixel.a $(KT_DIR)/guest/scenes.h
	gcc $(KT_CFLAGS) $< -o $@ $(KT_BUILD)/x86_64/libfixel.a $(KT_LDLIBS)

kernel-guests: $(KT_GUESTS) $(KT_BUILD)/host_render

# The package step, then a new make that reads what it installed.
test-kernel: $(KT_BUILD)/deps.stamp
	@$(MAKE) --no-print-directory test-kernel-nodeps
test-kernel-nodeps: kernel-guests
	@sh $(KT_DIR)/rig.sh $(KT_CACHE) $(KT_BUILD)

.PHONY: test-kernel test-kernel-nodeps kernel-guests

# The rig's packages (tests/kernel/deps.sh installs the same ones on its own).
TEST_DEB_PKGS += qemu-system-x86 qemu-system-arm busybox-static cpio kmod xz-utils python3 bc \
                 gcc-aarch64-linux-gnu libc6-dev-arm64-cross \
                 libdrm-dev:arm64 libevdev-dev:arm64 libgpiod-dev:arm64 libpng-dev:arm64 zlib1g-dev:arm64
deps-kernel:
	sh $(KT_DIR)/deps.sh

# Part of `make test`; FIXEL_SKIP_KERNEL=1 leaves it out (a machine without
# apt access or the time for a first download).
ifneq ($(FIXEL_SKIP_KERNEL),1)
TEST_SUITES += "solo: $(MAKE) --no-print-directory -s test-kernel"
endif
.PHONY: deps-kernel
