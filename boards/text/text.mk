# SPDX-License-Identifier: MIT
# Smooth text (boards/text, fixel/face.h; issue #37). The library's own
# packages are in the top Makefile's DEB_PKGS and TEXT_PKGS; the tests read
# these fonts by path: DejaVu Sans (Latin, Greek, Cyrillic, Arabic, Hebrew)
# and GNU FreeFont's FreeSerif (Devanagari, Thai; fontconfig's fallback for
# them in test_face.c).
TEST_DEB_PKGS += fonts-dejavu-core fonts-freefont-ttf
