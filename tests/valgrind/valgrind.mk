# SPDX-License-Identifier: MIT
# `make valgrind`: the unit, golden and tool suites again with every process
# under memcheck (tests/valgrind/run.sh). Slow (tens of minutes on 2 cores),
# so `make test` runs only the quick tool part of it.
TEST_DEB_PKGS += valgrind

valgrind: all $(TEST_BIN) $(GOLDEN_BIN)
	@sh tests/valgrind/run.sh $(BUILD) $(BUILD)/valgrind

TEST_SUITES += "sh tests/valgrind/run.sh $(BUILD) $(BUILD)/valgrind-quick quick"

.PHONY: valgrind
