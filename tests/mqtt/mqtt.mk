# SPDX-License-Identifier: MIT
# fixel-kiosk over MQTT against real mosquitto brokers (tests/mqtt/run.sh).
TEST_SUITES += "solo: sh tests/mqtt/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/mqtt"
TEST_DEB_PKGS += mosquitto mosquitto-clients openssl python3 libmosquitto-dev libcjson-dev
# the issue #24 review findings (packet limit, line buffers, prefix reload, backlight)
TEST_SUITES += "solo: sh tests/mqtt/review.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/mqtt-review"
