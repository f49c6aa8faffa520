# SPDX-License-Identifier: MIT
# fixel-info and fixel-shot for the rig's guests (tests/kernel/guest/tools.c
# runs them): the real tools, linked statically per architecture with the
# DRM/evdev/GPIO details and PNG output they have in a normal build.
# mkinitramfs.sh puts <arch>/bin/* into the guest's /bin.
KT_TOOLS := fixel-info fixel-shot
KT_TOOL_FLAGS := -D_GNU_SOURCE -DFX_INFO_HAVE_OPT -DFX_SHOT_HAVE_DRM
define KT_TOOL_RULES
$(KT_BUILD)/$(1)/bin/%: tools/%/main.c $(KT_BUILD)/$(1)/libfixel.a $(KT_BUILD)/$(1)/obj/boards/memory/memfb.o | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) $(KT_TOOL_FLAGS) $(KT_DEPFLAGS) $$< -o $$@ \
	    $(KT_BUILD)/$(1)/obj/boards/memory/memfb.o $(KT_BUILD)/$(1)/libfixel.a $(KT_LDLIBS) -lpng16 -lz -lm
kernel-guests: $(addprefix $(KT_BUILD)/$(1)/bin/,$(KT_TOOLS)) $(KT_BUILD)/$(1)/bin/fixel-calibrate
# fixel-calibrate has its fit in a second file (guest/outputs.c runs it)
$(KT_BUILD)/$(1)/bin/fixel-calibrate: tools/fixel-calibrate/main.c tools/fixel-calibrate/fit.c $(KT_BUILD)/$(1)/libfixel.a | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) -D_GNU_SOURCE $(KT_DEPFLAGS) tools/fixel-calibrate/main.c tools/fixel-calibrate/fit.c -o $$@ \
	    $(KT_BUILD)/$(1)/libfixel.a $(KT_LDLIBS)
# guest/tools.c reads the screenshots back (libpng) and sends them zlib'd:
# an explicit rule, so it replaces kernel.mk's pattern rule for this one.
$(KT_BUILD)/$(1)/tests/tools: $(KT_DIR)/guest/tools.c $(KT_BUILD)/$(1)/libfixel.a $(KT_BUILD)/$(1)/obj/boards/memory/memfb.o $(wildcard $(KT_DIR)/guest/*.h) | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) -Wno-format-truncation $(KT_DEPFLAGS) $$< -o $$@ \
	    $(KT_BUILD)/$(1)/obj/boards/memory/memfb.o $(KT_BUILD)/$(1)/libfixel.a $(KT_LDLIBS) -lpng16 -lz -lm
endef
$(foreach a,$(KT_ARCHES),$(eval $(call KT_TOOL_RULES,$(a))))
# kept: make would delete memfb.o as an intermediate and relink every run
.SECONDARY: $(foreach a,$(KT_ARCHES),$(KT_BUILD)/$(a)/obj/boards/memory/memfb.o)
