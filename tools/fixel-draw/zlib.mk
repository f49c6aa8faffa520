# SPDX-License-Identifier: MIT
# fixel-draw inflates .psf.gz fonts with zlib when the target links it (bare
# cross sysroots may not have it; gzip files are then refused with a message).
ifneq ($(filter -lz,$(PKG_LIBS)),)
$(BUILD)/obj/tools/fixel-draw/main.o: BASEFLAGS += -DFX_DRAW_ZLIB=1
endif
