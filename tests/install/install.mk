# SPDX-License-Identifier: MIT
# make install/uninstall into staging directories, man pages, the kiosk unit
# (tests/install/install.sh).
TEST_DEB_PKGS += man-db systemd
TEST_SUITES += "sh tests/install/install.sh $(BUILD)"
.PHONY: test-install
test-install: all
	@sh tests/run-suites.sh "sh tests/install/install.sh $(BUILD)"
