# SPDX-License-Identifier: MIT
# fixel-draw's threaded ray tracing gives the one-thread goldens (tests/rt/draw-mt.sh).
TEST_SUITES += "sh tests/rt/draw-mt.sh $(BUILD)/bin/fixel-draw $(BUILD)/tests/golden $(BUILD)/tests/rt-draw-mt"
