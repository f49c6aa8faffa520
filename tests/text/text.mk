# SPDX-License-Identifier: MIT
# fixel-draw reads .psf.gz fonts by inflating them on the tool side.
TEST_SUITES += "sh tests/text/gz.sh $(BUILD)/bin/fixel-draw $(BUILD)/text-gz"
