# SPDX-License-Identifier: MIT
# fixel-draw's threaded ray tracing gives the one-thread goldens
# (tests/rt/draw-mt.sh), in the plain and the sanitized build.
TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/tests/golden && sh tests/rt/draw-mt.sh $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/tests/golden $(PLAIN_BUILD)/tests/rt-draw-mt" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/tests/golden && sh tests/rt/draw-mt.sh $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/tests/golden $(ASAN_BUILD)/tests/rt-draw-mt"
# fixel-draw on the textbook's SDL files (tests/rt/sdl-draw.sh)
TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/bin/fixel-draw && sh tests/rt/sdl-draw.sh $(PLAIN_BUILD)/bin/fixel-draw $(PLAIN_BUILD)/tests/sdl-draw" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/bin/fixel-draw && sh tests/rt/sdl-draw.sh $(ASAN_BUILD)/bin/fixel-draw $(ASAN_BUILD)/tests/sdl-draw"
