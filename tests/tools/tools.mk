# SPDX-License-Identifier: MIT
# tests/tools/: the tools' promises to users (tests/tools/behaviour.sh).
TEST_SUITES += "sh tests/tools/behaviour.sh $(BUILD)/bin $(BUILD)/tests/behaviour"
