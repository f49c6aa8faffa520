# SPDX-License-Identifier: MIT
# The GLUT layer's suite (issue #21): unit tests of tests/glut/test_*.c run
# through tests/lib/runner.c, and headless course-style programs (tests/glut/progs.sh).
GLUT_TEST_SRC := $(sort $(wildcard tests/glut/test_*.c))
GLUT_TEST_BIN := $(BUILD)/tests/glut-unit
$(GLUT_TEST_SRC:%.c=$(BUILD)/obj/%.o): BASEFLAGS += -Iboards/glut/include

$(BUILD)/tests/glut-registry.c: $(GLUT_TEST_SRC) tests/lib/gen-registry.sh
	@mkdir -p $(dir $@)
	sh tests/lib/gen-registry.sh $(GLUT_TEST_SRC) > $@
$(BUILD)/obj/tests/glut-registry.o: $(BUILD)/tests/glut-registry.c
	@mkdir -p $(dir $@)
	$(CC) $(BASEFLAGS) -Itests/lib -c $< -o $@
$(GLUT_TEST_BIN): $(GLUT_TEST_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/tests/lib/runner.o \
                  $(BUILD)/obj/tests/glut-registry.o $(GLUT_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(filter %.o,$^) $(GLUT_LIBS)

.PHONY: test-glut
test-glut: $(GLUT_TEST_BIN) $(GLUT_A) $(LIB_A)
	@bash tests/run-suites.sh "$(GLUT_TEST_BIN)" "sh tests/glut/progs.sh $(BUILD)"
TEST_SUITES += "$(GLUT_TEST_BIN)" "sh tests/glut/progs.sh $(BUILD)"
test-bins: $(GLUT_TEST_BIN)
