# SPDX-License-Identifier: MIT
# fixel-demo on two outputs (--display OUTPUT=PAGE), headless on memory
# displays (tests/tools/demo-outputs.sh; about a second).
TEST_SUITES += "$(MAKE) --no-print-directory -s $(IMGCMP) && sh tests/tools/demo-outputs.sh $(BUILD)/bin $(BUILD)/tests $(BUILD)/tests/demo-outputs"
