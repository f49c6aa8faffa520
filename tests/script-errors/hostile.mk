# SPDX-License-Identifier: MIT
# The hostile inputs of issue #26 through fixel-draw and fixel-kiosk, plain
# and ASan+UBSan: tests/script-errors/hostile.sh.
test-hostile:
	@$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/bin/fixel-kiosk $(PLAIN_BUILD)/bin/fixel-shot $(PLAIN_BUILD)/bin/fixel-demo
	@$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/bin/fixel-kiosk $(ASAN_BUILD)/bin/fixel-shot $(ASAN_BUILD)/bin/fixel-demo
	@sh tests/script-errors/hostile.sh $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/bin/fixel-kiosk $(PLAIN_BUILD)/hostile 1
	@sh tests/script-errors/hostile.sh $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/bin/fixel-kiosk $(ASAN_BUILD)/hostile 3

TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-shot $(PLAIN_BUILD)/bin/fixel-demo && sh tests/script-errors/hostile.sh $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/bin/fixel-kiosk $(PLAIN_BUILD)/hostile 1" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-shot $(ASAN_BUILD)/bin/fixel-demo && sh tests/script-errors/hostile.sh $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/bin/fixel-kiosk $(ASAN_BUILD)/hostile 3"

# /usr/bin/time measures the sanitized runs' RSS (their memory cap)
TEST_DEB_PKGS += time

.PHONY: test-hostile
