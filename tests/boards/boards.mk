# SPDX-License-Identifier: MIT
# tests/boards/: programs on fx_app driven headless (FIXEL_REPLAY, FIXEL_OUT).
IMGCMP := $(BUILD)/tests/imgcmp
$(IMGCMP): $(BUILD)/obj/tests/boards/imgcmp.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

.PHONY: test-boards-bins
test-boards-bins: $(IMGCMP) examples
