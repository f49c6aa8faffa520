# SPDX-License-Identifier: MIT
# make deb's package set, libfixel-dev's Depends and the source copy of a
# tree without .git, checked without building packages (tests/deb/control.sh;
# make deb itself: tests/install/install.mk).
TEST_DEB_PKGS += dpkg-dev
TEST_SUITES += "sh tests/deb/control.sh $(BUILD)"
.PHONY: test-deb-control
test-deb-control: $(BUILD)/fixel.pc
	@sh tests/run-suites.sh "sh tests/deb/control.sh $(BUILD)"
