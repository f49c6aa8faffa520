# SPDX-License-Identifier: MIT
# fixel-draw --frames: numbered PNGs of an animated script (docs/ANIMATION.md).
TEST_SUITES += "sh tests/anim/frames.sh $(BUILD)/bin/fixel-draw $(BUILD)/anim-frames"
