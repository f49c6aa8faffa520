# SPDX-License-Identifier: MIT
# fixel-kiosk's message-to-pixels latency over MQTT (docs/BENCHMARK.md, section 8):
#   make bench-kiosk   one kiosk at 10, 100 and 1000 messages/s, then a broker
#                      and 20 kiosks at 100/s (part of make bench; ~3 minutes)
#   make test          the smoke run: a few values, each must be presented
# tests/kbench/kbench.c publishes and matches the kiosks' FIXEL_KIOSK_TRACE
# lines; tests/kbench/run.sh starts the broker and the kiosks.
KBENCH_BIN := $(BUILD)/tests/kbench
KBENCH_HAVE := $(if $(filter 1,$(STATIC)),,$(if $(CROSS_COMPILE),,$(shell $(PKG_CONFIG) --exists libmosquitto 2>/dev/null && echo 1)))
ifeq ($(KBENCH_HAVE),1)
$(BUILD)/obj/tests/kbench/kbench.o: CPPFLAGS += $(shell $(PKG_CONFIG) --cflags libmosquitto)
$(KBENCH_BIN): $(BUILD)/obj/tests/kbench/kbench.o
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(shell $(PKG_CONFIG) --libs libmosquitto) -lpthread
test-bins: $(KBENCH_BIN)
endif
TEST_DEB_PKGS += mosquitto mosquitto-clients libmosquitto-dev libcjson-dev python3
TEST_SUITES += "solo: sh tests/kbench/run.sh --smoke $(BUILD)/bin/fixel-kiosk $(KBENCH_BIN) $(BUILD)/kbench-smoke"
# make bench runs it before the drawing table (tools/fixel-bench/bench.mk's
# recipe untouched, as tests/glut/glut.mk does)
bench: bench-kiosk
bench-kiosk: $(BUILD)/bin/fixel-kiosk $(if $(KBENCH_HAVE),$(KBENCH_BIN))
	sh tests/kbench/run.sh $(BUILD)/bin/fixel-kiosk $(KBENCH_BIN) $(BUILD)/kbench
.PHONY: bench-kiosk
