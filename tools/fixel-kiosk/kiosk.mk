# SPDX-License-Identifier: MIT
# fixel-kiosk: the scripted end-to-end suite (golden frames in tests/golden/kiosk).
TEST_SUITES += "sh tests/kiosk/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk"
# the qr widget decoded by zbarimg, an animated GIF's timing (issue #41)
TEST_SUITES += "sh tests/kiosk/media.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-media"
TEST_DEB_PKGS += zbar-tools
# constant memory over a run (issue #14): a short soak and valgrind pass in
# make test; make kiosk-soak is the long one whose numbers docs/kiosk.md quotes
TEST_SUITES += "solo: sh tests/kiosk/soak.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-soak 20000 1000"
KIOSK_SOAK_LINES ?= 200000
KIOSK_SOAK_VG    ?= 5000
.PHONY: kiosk-golden-update kiosk-soak
kiosk-golden-update: $(BUILD)/bin/fixel-kiosk
	mkdir -p tests/golden/kiosk
	sh tests/kiosk/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk --update
	sh tests/kiosk/media.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-media --update
kiosk-soak: $(BUILD)/bin/fixel-kiosk
	nice -n 5 sh tests/kiosk/soak.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-soak $(KIOSK_SOAK_LINES) $(KIOSK_SOAK_VG)
# The fuzz target tests/fuzz/fuzz_kiosk.c needs the pure parser file.
FUZZ_EXTRA_kiosk := tools/fixel-kiosk/kiosk_parse.c
FUZZ_EXTRA_fuzz_kiosk := tools/fixel-kiosk/kiosk_parse.c
# MQTT (docs/kiosk.md, "MQTT"): libmosquitto and cJSON when pkg-config finds
# them; without, fixel-kiosk builds and refuses a config with "mqtt" saying why.
KIOSK_MQTT_PKGS := libmosquitto libcjson
# Debian ships them shared only: a STATIC=1 kiosk goes without.
HAVE_KIOSK_MQTT := $(if $(filter 1,$(STATIC)),,$(shell $(PKG_CONFIG) --exists $(KIOSK_MQTT_PKGS) 2>/dev/null && echo 1))
ifeq ($(HAVE_KIOSK_MQTT),1)
$(BUILD)/obj/tools/fixel-kiosk/%.o: CPPFLAGS += -DKIOSK_HAVE_MQTT $(shell $(PKG_CONFIG) --cflags $(KIOSK_MQTT_PKGS))
TOOL_LIBS_fixel-kiosk += $(shell $(PKG_CONFIG) --libs $(KIOSK_MQTT_PKGS))
endif
# systemd (Type=notify, WatchdogSec=): READY=1 after the first frame,
# WATCHDOG=1 from the main loop; without libsystemd the kiosk tells nobody.
HAVE_KIOSK_SYSTEMD := $(if $(filter 1,$(STATIC)),,$(shell $(PKG_CONFIG) --exists libsystemd 2>/dev/null && echo 1))
ifeq ($(HAVE_KIOSK_SYSTEMD),1)
$(BUILD)/obj/tools/fixel-kiosk/%.o: CPPFLAGS += -DKIOSK_HAVE_SYSTEMD
TOOL_LIBS_fixel-kiosk += $(shell $(PKG_CONFIG) --libs libsystemd)
endif
# The optional parts are chosen when make reads this file, so objects built
# without them (a first `make run` before `make test` installed
# libmosquitto-dev) must be rebuilt once they appear: the stamp holds the
# choice and is rewritten only when it changes. Only into an existing
# $(BUILD)/obj: reading the Makefile must not create build/ (a user's first
# make stops before building anything; tests/setup/fresh-root.sh checks).
KIOSK_FEATURES := mqtt=$(HAVE_KIOSK_MQTT) systemd=$(HAVE_KIOSK_SYSTEMD)
KIOSK_STAMP := $(BUILD)/obj/tools/fixel-kiosk/features
$(shell if [ -d '$(BUILD)/obj' ] && [ "$$(cat '$(KIOSK_STAMP)' 2>/dev/null)" != '$(KIOSK_FEATURES)' ]; then \
	mkdir -p '$(dir $(KIOSK_STAMP))' && echo '$(KIOSK_FEATURES)' > '$(KIOSK_STAMP)'; fi)
$(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tools/fixel-kiosk/*.c)): $(KIOSK_STAMP)
$(KIOSK_STAMP):
	@mkdir -p $(@D)
	@echo '$(KIOSK_FEATURES)' > $@
TEST_SUITES += "solo: sh tests/kiosk/notify.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-notify"
TEST_DEB_PKGS += libsystemd-dev python3
# output sections: one process, one screen per section (issue #25)
TEST_SUITES += "solo: sh tests/kiosk/screens.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-screens"
# --threads: frames drawn in bands on 2, 3, 4 threads equal one thread's (issue #27)
TEST_SUITES += "sh tests/kiosk/threads.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk-threads"
