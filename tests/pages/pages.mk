# SPDX-License-Identifier: MIT
# fixel-kiosk pages and touch (tests/pages/run.sh): the carousel on the
# headless clock, swipes, taps and buttons through the input replay, button
# messages and set/page against a real mosquitto on 127.0.0.1.
TEST_SUITES += "solo: sh tests/pages/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/pages"
TEST_DEB_PKGS += mosquitto mosquitto-clients python3
.PHONY: kiosk-pages-golden-update
kiosk-pages-golden-update: $(BUILD)/bin/fixel-kiosk
	sh tests/pages/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/pages --update
