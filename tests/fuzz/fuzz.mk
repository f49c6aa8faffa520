# SPDX-License-Identifier: MIT
# Fuzzing with libFuzzer (clang, ASan + UBSan): tests/fuzz/README.md.
#   make fuzz                 each target for FUZZ_SECONDS (default 60) on its corpus
#   make test                 each target over its seed corpus plus FUZZ_RUNS new inputs
# The core sources (the top Makefile's CORE_SRC) are compiled once by clang
# with the same sanitizers into build/fuzz/libcore.a, linked into each
# target (the gcc-built libfixel.a is not instrumented for coverage).
TEST_DEB_PKGS += clang libclang-rt-14-dev
FUZZ_CC      ?= clang
FUZZ_BUILD   := build/fuzz
FUZZ_TARGETS := $(patsubst tests/fuzz/%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_CFLAGS  := -std=c11 -g -O1 -D_GNU_SOURCE -Ikernel-free-src/include -Iboards/include -Itests/fuzz
FUZZ_FLAGS   := $(FUZZ_CFLAGS) -fsanitize=fuzzer $(FUZZ_SAN)
FUZZ_OBJ     := $(CORE_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
FUZZ_SECONDS ?= 60
FUZZ_RUNS    ?= 3000

$(FUZZ_BUILD)/obj/%.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link $(FUZZ_SAN) -MMD -MP -c $< -o $@
-include $(FUZZ_OBJ:.o=.d)

$(FUZZ_BUILD)/libcore.a: $(FUZZ_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(FUZZ_BUILD)/%: tests/fuzz/%.c $(FUZZ_BUILD)/libcore.a tests/fuzz/guard.h tests/fuzz/scenehost.h tests/fuzz/choice.h tests/fuzz/fuzz_image.h \
                 tests/fuzz/fuzz_kiosk.c tests/fuzz/fuzz_obj.c tests/fuzz/fuzz_psf.c $(wildcard kernel-free-src/include/fixel/*.h)
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) $< $(FUZZ_EXTRA_$*) $(FUZZ_BUILD)/libcore.a -o $@

fuzz-build: $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/%)

fuzz: fuzz-build
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t; \
	  echo "== $$t ($(FUZZ_SECONDS) s)"; \
	  $(FUZZ_BUILD)/$$t -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/ \
	    $(FUZZ_BUILD)/corpus/$$t tests/fuzz/corpus/$${t#fuzz_} 2>&1 | grep -E 'stat::number_of_executed_units|ERROR|SUMMARY' ; \
	done

TEST_SUITES += "sh tests/fuzz/run-short.sh $(FUZZ_RUNS)"

.PHONY: fuzz fuzz-build
FUZZ_EXTRA_fuzz_gkiosk := tools/fixel-kiosk/kiosk_parse.c
FUZZ_EXTRA_fuzz_png := boards/memory/memfb.c boards/posix/files.c -lpng -lz
# fuzz_face: hostile fonts and any text through boards/text/face.c and the
# system's FreeType, HarfBuzz, FriBiDi, fontconfig and libunibreak (only
# when the build has them: HAVE_TEXT in the top Makefile).
FUZZ_EXTRA_fuzz_face := boards/text/face.c $(shell $(PKG_CONFIG) --cflags --libs $(TEXT_PKGS) 2>/dev/null) -lpthread
ifneq ($(HAVE_TEXT),1)
  FUZZ_TARGETS := $(filter-out fuzz_face,$(FUZZ_TARGETS))
endif
# boards/image/ (issue #41): each decoder's target links the whole folder
FUZZ_IMAGE := boards/image/image.c boards/image/jpeg.c boards/image/gif.c boards/image/webp.c boards/memory/memfb.c boards/posix/files.c \
              -ljpeg -lgif -lwebp -lpng -lz
FUZZ_EXTRA_fuzz_jpeg := $(FUZZ_IMAGE)
FUZZ_EXTRA_fuzz_gif := $(FUZZ_IMAGE)
FUZZ_EXTRA_fuzz_webp := $(FUZZ_IMAGE)

# The long campaign (docs/RELIABILITY.md records its results): one core,
# nice 15, each target for its share of FUZZ_CAMPAIGN (TARGET:SECONDS ...).
FUZZ_CAMPAIGN ?= fuzz_grammar:900 fuzz_gkiosk:900 fuzz_gobj:900 fuzz_gpsf:600 fuzz_png:600 fuzz_jpeg:300 fuzz_gif:300 fuzz_webp:300
fuzz-campaign: fuzz-build
	sh tests/fuzz/campaign.sh $(FUZZ_CAMPAIGN)
.PHONY: fuzz-campaign
