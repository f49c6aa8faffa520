# SPDX-License-Identifier: MIT
# examples/: small programs built against the library as a user would
# (<fixel/...> includes); `make examples` builds build/examples/<name>.
EXAMPLES     := $(basename $(notdir $(wildcard examples/*.c)))
EXAMPLE_BINS := $(EXAMPLES:%=$(BUILD)/examples/%)

.PHONY: examples
examples: $(EXAMPLE_BINS)
	$(built_without_summary)

$(BUILD)/examples/%: $(BUILD)/obj/examples/%.o $(LIB_A)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

# The interactive example driven headless by a replay file, its last frame
# compared with a golden PNG, hello under valgrind (tests/boards/examples.sh).
TEST_SUITES += "$(MAKE) --no-print-directory -s test-boards-bins && sh tests/boards/examples.sh $(BUILD) $(BUILD)/tests/examples"
