# SPDX-License-Identifier: MIT
# tests/glut: the course's GLUT programs, rendered by fixel's GLUT layer and by
# Mesa (llvmpipe, the reference) and compared (issue #21; README.md here).
#   make test-glut-mesa        corpus both ways, "glut-mesa: N passed, N failed"
#   make bench-glut-mesa       teapot and Mandelbrot fps: fixel, llvmpipe, softpipe
#   make glut-softpipe-report  how far softpipe is from llvmpipe (informational)
#   make glut-deps             the Debian packages of the Mesa side (also part of make deps)
#   make test                  runs test-glut-mesa (FIXEL_SKIP_GLUT_MESA=1: not)
# The fixel half links $(GLUT_LIB) and $(LIB_A) with -I boards/glut/include; while
# the layer is not built, test-glut-mesa runs the Mesa half and says so.
GLUT_LIB ?= $(BUILD)/libfixel-glut.a
GLUT_LIB_DEP := $(if $(wildcard boards/glut/*.c),$(GLUT_LIB))

.PHONY: test-glut-mesa bench-glut-mesa bench-glut glut-softpipe-report glut-deps deps-glut
# The Mesa side's packages (root installs them; otherwise the apt-get line is
# printed and the suite fails): once per build directory, like the kernel rig.
GLUT_DEPS_STAMP := $(BUILD)/glut/deps.stamp
$(GLUT_DEPS_STAMP): tests/glut/deps.sh
	@mkdir -p $(@D)
	@sh tests/glut/deps.sh
	@touch $@
glut-deps deps-glut:
	@sh tests/glut/deps.sh
# ...and `make test`'s package step names them with the rest, so that a
# normal user's first make test stops once, with one line for everything.
TEST_DEB_PKGS += $(shell sh tests/glut/deps.sh --list)
# `make deps` (CI's first step) installs them too.
deps: deps-glut

# The package step, then a new make: one that read pkg-config before the
# install would build the library without what it brought (as make test does).
test-glut-mesa: $(GLUT_DEPS_STAMP)
	@$(MAKE) --no-print-directory test-glut-mesa-nodeps
test-glut-mesa-nodeps: $(LIB_A) $(GLUT_LIB_DEP)
	@CC="$(CC)" GLUT_FIXEL_LIBS="$(LDLIBS)" sh tests/glut/run.sh --build $(BUILD)

bench-glut-mesa: $(GLUT_DEPS_STAMP)
	@$(MAKE) --no-print-directory bench-glut-mesa-nodeps
bench-glut-mesa-nodeps: $(LIB_A) $(GLUT_LIB_DEP)
	@CC="$(CC)" GLUT_FIXEL_LIBS="$(LDLIBS)" sh tests/glut/bench.sh --build $(BUILD)
.PHONY: test-glut-mesa-nodeps bench-glut-mesa-nodeps
# `make bench` runs it first: a prerequisite added here, tools/fixel-bench's
# recipe untouched (run make bench without -j, the two would share cores).
bench-glut: bench-glut-mesa
bench: bench-glut

# fixel's layer alone (tests/glut/layer.sh): glutGet, text metrics, glGet,
# how glutMainLoop ends after glutLeaveMainLoop. About 2 s; part of make test.
# With SAN=1 the program is built with the sanitizers too.
test-glut-layer: $(LIB_A) $(GLUT_LIB)
	@CC="$(CC) $(SANFLAGS)" GLUT_FIXEL_LIBS="$(LDLIBS)" sh tests/glut/layer.sh $(BUILD)
.PHONY: test-glut-layer
TEST_SUITES += "$(MAKE) --no-print-directory -s test-glut-layer"

# Self-checking programs (tests/glut/self.sh): a window's life (glutDestroyWindow,
# GLUT_ACTION_ON_WINDOW_CLOSE, glutInitWindowSize before glutInit), run on
# fixel and on freeglut + Mesa when they are installed; what a headless run
# says. A few seconds; part of make test.
test-glut-self: $(LIB_A) $(GLUT_LIB)
	@CC="$(CC) $(SANFLAGS)" GLUT_FIXEL_LIBS="$(LDLIBS)" sh tests/glut/self.sh $(BUILD)
.PHONY: test-glut-self
TEST_SUITES += "$(MAKE) --no-print-directory -s test-glut-self"

# Part of `make test` (about 45 s on 2 cores, most of it Mesa's million-point
# Mandelbrot); FIXEL_SKIP_GLUT_MESA=1 leaves it out.
ifneq ($(FIXEL_SKIP_GLUT_MESA),1)
TEST_SUITES += "$(MAKE) --no-print-directory -s test-glut-mesa"
endif

glut-softpipe-report: glut-deps
	@GALLIUM_DRIVER=softpipe sh tests/glut/mesa/run.sh $(BUILD)/glut/softpipe || true
	@sh tests/glut/run.sh --build $(BUILD) --out $(BUILD)/glut/vs-softpipe --frames $(BUILD)/glut/softpipe || true
