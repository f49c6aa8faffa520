# SPDX-License-Identifier: MIT
# fixel-info reports DRM/evdev/GPIO details only when those libraries are there.
$(BUILD)/obj/tools/fixel-info/main.o: PKG_CFLAGS += $(if $(HAVE_OPT),-DFX_INFO_HAVE_OPT)
TEST_SUITES += "sh tests/kiosk/info.sh $(BUILD)/bin/fixel-info"
