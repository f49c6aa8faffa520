# SPDX-License-Identifier: MIT
# fixel-shot reads DRM scanout buffers only when built with libdrm.
$(BUILD)/obj/tools/fixel-shot/main.o: PKG_CFLAGS += $(if $(HAVE_OPT),-DFX_SHOT_HAVE_DRM)
