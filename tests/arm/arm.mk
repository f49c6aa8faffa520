# SPDX-License-Identifier: MIT
# `make test-arm`: the unit and golden suites of every Raspberry Pi
# architecture, cross-built statically and run under qemu's user emulators
# (called explicitly: this machine has no binfmt handler), plus the
# integer-only check of the core for each. The golden images are the same
# files as on x86: any pixel difference is a bug. tests/arm/README.md.
test-arm:
	@sh tests/arm/test-arm.sh

deps-arm:
	sh tests/arm/deps.sh

# What tests/arm/deps.sh installs, for `make test`'s package step. The armel
# libraries are left to tests/arm/deps.sh, which test-arm runs as root:
# bookworm's security suite has no armel, so once zlib1g, libpng16-16 or
# linux-libc-dev has a security update the armel packages cannot match the
# host's (multiarch needs equal versions); deps.sh then unpacks them into
# build/sysroot-armel (tests/arm/sysroot-armel.sh), which boards/rpi-zero.mk
# uses. Without either (no network), rpi-zero's suites run without them.
TEST_DEB_PKGS += gcc-aarch64-linux-gnu gcc-arm-linux-gnueabihf gcc-arm-linux-gnueabi \
                 libc6-dev-arm64-cross libc6-dev-armhf-cross libc6-dev-armel-cross qemu-user-static \
                 $(foreach a,arm64 armhf,$(foreach p,libdrm-dev libevdev-dev libgpiod-dev libpng-dev zlib1g-dev,$(p):$(a)))

# QUICK=1 leaves the cross-architecture run out of `make test` (for quick
# local iterations; CI always runs it).
# One suite per board: each is a cross build and then qemu-user on one core,
# so the three run beside the other suites (tests/run-suites.sh) instead of
# one after another. make test leaves out rpi-zero's unit run, which repeats
# rpi3-32's (the same 32-bit ARM code; armel emulates the tests' double
# references in software: 330 s of CPU, more than half of that board's
# suite); its golden run, which checks the pixels, stays. make test-arm
# runs every board whole.
ifneq ($(QUICK),1)
TEST_SUITES += "ARM_BOARDS=rpi4 sh tests/arm/test-arm.sh" "ARM_BOARDS=rpi3-32 sh tests/arm/test-arm.sh" \
               "ARM_BOARDS=rpi-zero ARM_NO_UNIT=rpi-zero sh tests/arm/test-arm.sh"
endif

.PHONY: test-arm deps-arm
