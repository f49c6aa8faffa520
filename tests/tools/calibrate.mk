# SPDX-License-Identifier: MIT
# fixel-calibrate headless (tests/tools/calibrate.sh; well under a second).
TEST_SUITES += "sh tests/tools/calibrate.sh $(BUILD)/bin $(BUILD)/tests/calibrate"
