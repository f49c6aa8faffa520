# SPDX-License-Identifier: MIT
# Bounded work counted in instructions (issue #14): each huge primitive of
# tests/core/bounded_cases.h runs under valgrind's lackey, and its count
# beyond an empty run must stay inside a fixed budget.
$(BUILD)/tests/bounded-count: $(BUILD)/obj/tests/bounded/count.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

test-bounded: $(BUILD)/tests/bounded-count
	@sh tests/bounded/count.sh $(BUILD)/tests/bounded-count

TEST_SUITES += "$(MAKE) --no-print-directory -s test-bounded"
.PHONY: test-bounded
