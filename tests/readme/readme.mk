# SPDX-License-Identifier: MIT
# Every code block of README.md works as pasted (tests/readme/readme.sh):
# C programs build and run, scripts render, replay files replay, make lines
# name known targets.
TEST_SUITES += "$(MAKE) --no-print-directory -s examples && sh tests/readme/readme.sh $(BUILD)"
.PHONY: test-readme
test-readme: all examples
	@sh tests/run-suites.sh "sh tests/readme/readme.sh $(BUILD)"
