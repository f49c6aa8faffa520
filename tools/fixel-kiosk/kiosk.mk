# fixel-kiosk: the scripted end-to-end suite (golden frames in tests/golden/kiosk).
TEST_SUITES += "sh tests/kiosk/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk"
.PHONY: kiosk-golden-update
kiosk-golden-update: $(BUILD)/bin/fixel-kiosk
	mkdir -p tests/golden/kiosk
	sh tests/kiosk/run.sh $(BUILD)/bin/fixel-kiosk $(BUILD)/kiosk --update
# The fuzz target tests/fuzz/fuzz_kiosk.c needs the pure parser file.
FUZZ_EXTRA_kiosk := tools/fixel-kiosk/kiosk_parse.c
FUZZ_EXTRA_fuzz_kiosk := tools/fixel-kiosk/kiosk_parse.c
