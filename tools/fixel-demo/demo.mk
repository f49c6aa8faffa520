# SPDX-License-Identifier: MIT
# fixel-demo: every gallery page rendered headless and compared with its
# committed picture (in the plain and the sanitized build).
TEST_SUITES += "$(PLAIN_BUILD)/bin/fixel-demo --golden tests/golden/demo" \
               "$(ASAN_BUILD)/bin/fixel-demo --golden tests/golden/demo"

.PHONY: demo-golden-update
demo-golden-update: $(BUILD)/bin/fixel-demo
	@mkdir -p tests/golden/demo
	$(BUILD)/bin/fixel-demo --golden tests/golden/demo --update

# The GLUT page (glutpage.c) runs a course program through the GLUT layer:
# its sources are linked in (boards/glut/glut.mk's objects, built with the
# layer's headers) and the page sees the GL headers.
TOOL_SRC_fixel-demo := $(GLUT_SRC)
$(BUILD)/obj/tools/fixel-demo/glutpage.o: BASEFLAGS += -Iboards/glut/include
