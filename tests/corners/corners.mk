# SPDX-License-Identifier: MIT
# Corner tests generated from the scene-script argument table (issue #26):
# tests/corners/corners.c. `make test-corners` runs the plain and the
# ASan+UBSan build; both are suites of `make test`.
$(BUILD)/tests/corners: $(BUILD)/obj/tests/corners/corners.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

test-corners:
	@$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/tests/corners
	@$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/tests/corners
	@$(PLAIN_BUILD)/tests/corners && $(ASAN_BUILD)/tests/corners
	@$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-kiosk && sh tests/corners/kiosk-corners.sh $(PLAIN_BUILD)/bin/fixel-kiosk $(PLAIN_BUILD)/kiosk-corners 1
	@$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-kiosk && sh tests/corners/kiosk-corners.sh $(ASAN_BUILD)/bin/fixel-kiosk $(ASAN_BUILD)/kiosk-corners 3

TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/tests/corners && $(PLAIN_BUILD)/tests/corners" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/tests/corners && $(ASAN_BUILD)/tests/corners"

.PHONY: test-corners

# The API corner test (tests/corners/api.c): public functions with NULL and
# extreme values on surfaces between guard pages.
$(BUILD)/obj/tests/corners/api.o: BASEFLAGS += -Itests/fuzz
$(BUILD)/tests/api-corners: $(BUILD)/obj/tests/corners/api.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/tests/api-corners && $(PLAIN_BUILD)/tests/api-corners" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/tests/api-corners && $(ASAN_BUILD)/tests/api-corners"

# Kiosk corner tests generated from fixel-kiosk --keys (issue #26):
# tests/corners/kiosk-corners.sh, plain and ASan+UBSan.
TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-kiosk && sh tests/corners/kiosk-corners.sh $(PLAIN_BUILD)/bin/fixel-kiosk $(PLAIN_BUILD)/kiosk-corners 1" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-kiosk && sh tests/corners/kiosk-corners.sh $(ASAN_BUILD)/bin/fixel-kiosk $(ASAN_BUILD)/kiosk-corners 3"

# FIXEL_* variables at hostile values (tests/corners/env-corners.sh).
TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-draw && sh tests/corners/env-corners.sh $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/env-corners 1" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-draw && sh tests/corners/env-corners.sh $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/env-corners 3"
