# tests/glut: the course's GLUT programs, rendered by fixel's GLUT layer and by
# Mesa (llvmpipe, the reference) and compared (issue #21; README.md here).
#   make test-glut-mesa        corpus both ways, "glut-mesa: N passed, N failed"
#   make bench-glut-mesa       teapot and Mandelbrot fps: fixel, llvmpipe, softpipe
#   make glut-softpipe-report  how far softpipe is from llvmpipe (informational)
#   make glut-deps             the Debian packages of the Mesa side
# The fixel half links $(GLUT_LIB) and $(LIB_A) with -I boards/glut/include; while
# the layer is not built, test-glut-mesa runs the Mesa half and says so.
GLUT_LIB ?= $(BUILD)/libfixel-glut.a
GLUT_LIB_DEP := $(if $(wildcard boards/glut/*.c),$(GLUT_LIB))

.PHONY: test-glut-mesa bench-glut-mesa glut-softpipe-report glut-deps
glut-deps:
	@sh tests/glut/deps.sh

test-glut-mesa: glut-deps $(LIB_A) $(GLUT_LIB_DEP)
	@CC="$(CC)" GLUT_FIXEL_LIBS="$(LDLIBS)" sh tests/glut/run.sh --build $(BUILD)

bench-glut-mesa: glut-deps $(LIB_A) $(GLUT_LIB_DEP)
	@CC="$(CC)" GLUT_FIXEL_LIBS="$(LDLIBS)" sh tests/glut/bench.sh --build $(BUILD)

glut-softpipe-report: glut-deps
	@GALLIUM_DRIVER=softpipe sh tests/glut/mesa/run.sh $(BUILD)/glut/softpipe || true
	@sh tests/glut/run.sh --build $(BUILD) --out $(BUILD)/glut/vs-softpipe --frames $(BUILD)/glut/softpipe || true
