# SPDX-License-Identifier: MIT
# GL corner test and GL fuzz target (issue #40; tests/glut/gl-corners.c,
# tests/fuzz/fuzz_gl.c). The table of entry points is generated from the
# layer's headers by tests/glut/gen-gl-table.sh.
#   make test-gl-corners   gcc plain, gcc SAN=1 and clang with
#                          -fsanitize=float-cast-overflow,undefined,address
#   make fuzz-gl-long      fuzz_gl for FUZZ_GL_SECONDS (default 600) on one core
GL_TABLE := $(PLAIN_BUILD)/gen/gl_table.h
$(GL_TABLE): tests/glut/gen-gl-table.sh $(wildcard boards/glut/include/GL/*.h)
	@mkdir -p $(dir $@)
	sh tests/glut/gen-gl-table.sh boards/glut/include/GL/gl.h boards/glut/include/GL/glu.h \
	  boards/glut/include/GL/freeglut_std.h boards/glut/include/GL/freeglut_ext.h > $@.tmp && mv $@.tmp $@

GL_CORNERS_DEPS := tests/glut/gl-corners.c tests/glut/gl-hostile.h $(GL_TABLE)
$(BUILD)/tests/gl-corners: $(GL_CORNERS_DEPS) $(GLUT_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -g $(SANFLAGS) $(INCLUDES) -Iboards/glut/include -I$(dir $(GL_TABLE)) \
	  tests/glut/gl-corners.c -o $@ $(GLUT_LIBS)

# clang: the GL layer, the boards and the core compiled with clang's
# sanitizers (float-cast-overflow is in clang's "undefined"; gcc has no
# such check), as the fuzz targets are (tests/fuzz/fuzz.mk's FUZZ_BUILD).
GL_SAN_SRC := $(BOARD_SRC) $(GLUT_SRC)
GL_SAN_OBJ := $(GL_SAN_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
$(GL_SAN_OBJ): FUZZ_CFLAGS += $(BOARD_DEFS) $(PKG_CFLAGS) -Iboards/glut/include
-include $(GL_SAN_OBJ:.o=.d)
$(FUZZ_BUILD)/libglut-san.a: $(GL_SAN_OBJ)
	@rm -f $@
	ar rcs $@ $^
GL_CLANG_SAN := -fsanitize=float-cast-overflow,undefined,address -fno-sanitize-recover=all
$(FUZZ_BUILD)/gl-corners-clang: $(GL_CORNERS_DEPS) $(FUZZ_BUILD)/libglut-san.a $(FUZZ_BUILD)/libcore.a
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(GL_CLANG_SAN) -Iboards/glut/include -I$(dir $(GL_TABLE)) \
	  tests/glut/gl-corners.c -o $@ $(FUZZ_BUILD)/libglut-san.a $(FUZZ_BUILD)/libcore.a $(LDLIBS)

# the fuzz target: fuzz.mk's rule with the GL layer and the table
FUZZ_EXTRA_fuzz_gl := -Iboards/glut/include -Itests/glut -I$(dir $(GL_TABLE)) $(GL_CLANG_SAN) \
  $(FUZZ_BUILD)/libglut-san.a $(LDLIBS)
$(FUZZ_BUILD)/fuzz_gl: $(FUZZ_BUILD)/libglut-san.a $(GL_TABLE) tests/glut/gl-hostile.h

test-gl-corners:
	@$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/tests/gl-corners
	@$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/tests/gl-corners
	@$(MAKE) --no-print-directory -s $(FUZZ_BUILD)/gl-corners-clang
	@$(PLAIN_BUILD)/tests/gl-corners && $(ASAN_BUILD)/tests/gl-corners && $(FUZZ_BUILD)/gl-corners-clang

TEST_SUITES += "$(MAKE) --no-print-directory -s $(PLAIN_BUILD)/tests/gl-corners && $(PLAIN_BUILD)/tests/gl-corners" \
               "$(MAKE) --no-print-directory -s SAN=1 $(ASAN_BUILD)/tests/gl-corners && $(ASAN_BUILD)/tests/gl-corners" \
               "$(MAKE) --no-print-directory -s $(FUZZ_BUILD)/gl-corners-clang && $(FUZZ_BUILD)/gl-corners-clang"

FUZZ_GL_SECONDS ?= 600
fuzz-gl-long: $(FUZZ_BUILD)/fuzz_gl
	@mkdir -p $(FUZZ_BUILD)/corpus/fuzz_gl
	nice -n 15 $(FUZZ_BUILD)/fuzz_gl -max_total_time=$(FUZZ_GL_SECONDS) -print_final_stats=1 -max_len=4096 \
	  -artifact_prefix=$(FUZZ_BUILD)/ $(FUZZ_BUILD)/corpus/fuzz_gl tests/fuzz/corpus/gl 2>&1 | \
	  grep -E 'stat::number_of_executed_units|stat::average_exec_per_sec|ERROR|SUMMARY|runtime error|Done'
.PHONY: test-gl-corners fuzz-gl-long
