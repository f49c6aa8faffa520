# The hostile inputs of issue #26 through fixel-draw and fixel-kiosk, plain
# and ASan+UBSan: tests/script-errors/hostile.sh.
test-hostile:
	@$(MAKE) --no-print-directory -s build/bin/fixel-draw build/bin/fixel-kiosk
	@$(MAKE) --no-print-directory -s SAN=1 build/asan/bin/fixel-draw build/asan/bin/fixel-kiosk
	@sh tests/script-errors/hostile.sh build/bin/fixel-draw build/bin/fixel-kiosk build/hostile 1
	@sh tests/script-errors/hostile.sh build/asan/bin/fixel-draw build/asan/bin/fixel-kiosk build/asan/hostile 3

TEST_SUITES += "sh tests/script-errors/hostile.sh build/bin/fixel-draw build/bin/fixel-kiosk build/hostile 1" \
               "sh tests/script-errors/hostile.sh build/asan/bin/fixel-draw build/asan/bin/fixel-kiosk build/asan/hostile 3"

.PHONY: test-hostile
