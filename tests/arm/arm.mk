# `make test-arm`: the unit and golden suites of every Raspberry Pi
# architecture, cross-built statically and run under qemu's user emulators
# (called explicitly: this machine has no binfmt handler), plus the
# integer-only check of the core for each. The golden images are the same
# files as on x86: any pixel difference is a bug. tests/arm/README.md.
test-arm:
	@sh tests/arm/test-arm.sh

deps-arm:
	sh tests/arm/deps.sh

TEST_SUITES += "sh tests/arm/test-arm.sh"

.PHONY: test-arm deps-arm
