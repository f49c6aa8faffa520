# Corner tests generated from the scene-script argument table (issue #26):
# tests/corners/corners.c. `make test-corners` runs the plain and the
# ASan+UBSan build; both are suites of `make test`.
$(BUILD)/tests/corners: $(BUILD)/obj/tests/corners/corners.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

test-corners:
	@$(MAKE) --no-print-directory -s build/tests/corners
	@$(MAKE) --no-print-directory -s SAN=1 build/asan/tests/corners
	@build/tests/corners && build/asan/tests/corners

TEST_SUITES += "$(MAKE) --no-print-directory -s build/tests/corners && build/tests/corners" \
               "$(MAKE) --no-print-directory -s SAN=1 build/asan/tests/corners && build/asan/tests/corners"

.PHONY: test-corners
