# SPDX-License-Identifier: MIT
# make install/uninstall into staging directories, man pages, the kiosk unit
# (tests/install/install.sh).
TEST_DEB_PKGS += man-db systemd
TEST_SUITES += "sh tests/install/install.sh $(BUILD)"
.PHONY: test-install
test-install: all
	@bash tests/run-suites.sh "sh tests/install/install.sh $(BUILD)"

# `make deb`: Debian packages for amd64, arm64 and armhf (tests/deb/deb.sh);
# DEB_ARCHES= to choose. Installs what it needs first (root) or names it.
DEB_ARCHES ?= amd64 arm64 armhf
# build-essential: dpkg-checkbuilddeps requires it of every package build
# (its absence stopped a fresh machine's make deb after the installs);
# tests/deb/control.sh checks this set covers debian/control's Build-Depends.
# The cross packages only for the foreign arches asked for: make deb
# DEB_ARCHES=amd64 on a fresh amd64 machine needs no arm64 toolchain.
DEB_NATIVE_ARCH := $(shell dpkg --print-architecture 2>/dev/null)
DEB_CROSS_ARCHES := $(filter-out $(DEB_NATIVE_ARCH),$(DEB_ARCHES))
DEB_BUILD_DEB_PKGS := build-essential dpkg-dev debhelper lintian fakeroot \
  $(if $(DEB_CROSS_ARCHES),qemu-user-static) $(foreach a,$(DEB_CROSS_ARCHES),crossbuild-essential-$(a)) \
  $(foreach a,$(DEB_CROSS_ARCHES),$(foreach p,libdrm-dev libevdev-dev libgpiod-dev libpng-dev zlib1g-dev \
                                                libjpeg62-turbo-dev libgif-dev libwebp-dev libqrencode-dev,$(p):$(a)))
.PHONY: deb
deb:
	@sh tests/deps.sh --for "make deb" $(sort $(DEB_PKGS) $(DEB_BUILD_DEB_PKGS))
	@bash tests/run-suites.sh "sh tests/deb/deb.sh build/deb $(DEB_ARCHES)"
