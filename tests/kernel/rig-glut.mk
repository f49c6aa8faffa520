# SPDX-License-Identifier: MIT
# (Named to sort after kernel.mk, whose variables it uses.)
# The GLUT layer in the rig (tests/kernel/guest/glut.c, issue #21): a course
# program built against boards/glut per architecture, linked statically
# with the library. An explicit rule, so it replaces kernel.mk's pattern
# rule for this one guest program; the layer's objects get a rule of their
# own (its headers, -D_GNU_SOURCE as the top Makefile gives boards/).
KT_GLUT_SRC := $(sort $(wildcard boards/glut/*.c))
define KT_GLUT_RULES
$(KT_BUILD)/$(1)/obj/boards/glut/%.o: boards/glut/%.c | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) -Iboards/glut/include -D_GNU_SOURCE $(KT_DEPFLAGS) -c $$< -o $$@
$(KT_BUILD)/$(1)/libfixel-glut.a: $(patsubst %.c,$(KT_BUILD)/$(1)/obj/%.o,$(KT_GLUT_SRC))
	@rm -f $$@
	$(if $(filter aarch64,$(1)),aarch64-linux-gnu-ar,ar) rcs $$@ $$^
$(KT_BUILD)/$(1)/tests/glut: $(KT_DIR)/guest/glut.c $(KT_BUILD)/$(1)/libfixel-glut.a $(KT_BUILD)/$(1)/libfixel.a $(wildcard $(KT_DIR)/guest/*.h) | $(KT_BUILD)/deps.stamp
	@mkdir -p $$(@D)
	$(KT_CC_$(1)) $(KT_CFLAGS) -Iboards/glut/include $(KT_DEPFLAGS) $$< -o $$@ \
	    $(KT_BUILD)/$(1)/libfixel-glut.a $(KT_BUILD)/$(1)/libfixel.a $(KT_LDLIBS)
endef
$(foreach a,$(KT_ARCHES),$(eval $(call KT_GLUT_RULES,$(a))))
