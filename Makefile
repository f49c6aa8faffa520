# SPDX-License-Identifier: MIT
# fixel — the one entry point.
#   make                 library (static + shared), tools, fixel.pc
#   make run             the main job (headless on a machine without a display)
#   make check           the quick loop: unit, golden and script-error suites, plain and ASan
#   make test            every test suite, plain and under ASan+UBSan, with a total
#   make bench           the benchmark table (tools/fixel-bench)
#   make deps            install the Debian packages the build needs (root) or say how
#   make install PREFIX=/usr/local DESTDIR=   (also LIBDIR BINDIR INCLUDEDIR MANDIR DATADIR ...); make uninstall
#   make deb             Debian packages for amd64, arm64, armhf (build/deb/<arch>/)
#   make test-setup      first-try make run / make test in fresh bookworm roots (CI)
#   make golden-update   re-render every golden set (look at them before committing)
#   make help            every target, with a line each
#   make BOARD=rpi4 ...  cross-build with a board profile from boards/<name>.mk
# CC, CFLAGS, CPPFLAGS and LDFLAGS from the environment or the command line
# are honoured: CC replaces $(CROSS_COMPILE)gcc, the flags are appended after
# fixel's own (which a build cannot do without).

BOARD    ?= pc
-include boards/$(BOARD).mk

# Build on every core unless the user chose (-j, -jN, --jobs, or MAKEFLAGS
# from the environment). GNU make 4.3 shows -j to a makefile only through
# its own command line, hence /proc; sub-makes inherit the jobserver.
ifeq ($(filter -j% --jobs%,$(MAKEFLAGS) $(shell echo "$$MAKEFLAGS") $(shell tr '\0' ' ' < /proc/$$PPID/cmdline 2>/dev/null)),)
  MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 1)
endif

CROSS_COMPILE ?=
# make's built-in defaults (cc, ar) give way to the board's toolchain; a CC,
# AR or NM the user sets (environment or command line) wins over both.
ifeq ($(filter environment command line override,$(origin CC)),)
  CC     := $(CROSS_COMPILE)gcc
endif
ifeq ($(filter environment command line override,$(origin AR)),)
  AR     := $(CROSS_COMPILE)ar
endif
ifeq ($(filter environment command line override,$(origin NM)),)
  NM     := $(CROSS_COMPILE)nm
endif
CFLAGS   ?=
CPPFLAGS ?=
PKG_CONFIG ?= pkg-config
PREFIX   ?= /usr/local
DESTDIR  ?=
VERSION  := 0.1.0
SOMAJOR  := 0

BUILD    ?= build
OPT      ?= -O2
SAN      ?=
# The sanitized build lives inside the board's build directory (build/asan
# for the PC, build/rpi4/asan for BOARD=rpi4), so it never mixes with the
# plain objects, nor with another board's. PLAIN_BUILD and ASAN_BUILD name
# both whichever of them this make is building.
PLAIN_BUILD := $(BUILD)
ASAN_BUILD  := $(PLAIN_BUILD)/asan
ifeq ($(SAN),1)
  override BUILD := $(ASAN_BUILD)
  SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif

WARN     := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wvla
CSTD     := -std=c11
INCLUDES := -Ikernel-free-src/include -Iboards/include
CPU_FLAGS ?=
# Board defaults compiled in (boards/<name>.mk); environment variables override them at run time.
BOARD_DEFS := -DFX_BOARD_ROTATION=$(or $(BOARD_ROTATION),0) -DFX_BOARD_BACKEND='"$(or $(BOARD_BACKEND),auto)"' \
              -DFX_BOARD_GPIO_BUTTONS='"$(BOARD_GPIO_BUTTONS)"' \
              $(if $(filter RGB565,$(BOARD_DRM_FORMAT)),-DFX_BOARD_DRM_FORMAT_RGB565)
BASEFLAGS := $(CSTD) $(WARN) $(OPT) -g $(CPU_FLAGS) $(BOARD_DEFS) $(SANFLAGS) -fPIC -MMD -MP $(INCLUDES)

# Libraries the boards side and the tools use (installed by `make deps`).
# Without libpng (a board toolchain with no target libraries) images are PPM
# only; without libdrm/libevdev/libgpiod the DRM and input backends are left
# out (see BOARD_LIB_DIRS). The core never needs either.
SYS_PKGS := libpng zlib
OPT_PKGS := libdrm libevdev libgpiod
HAVE_PNG := $(shell $(PKG_CONFIG) --exists $(SYS_PKGS) 2>/dev/null && echo 1)
HAVE_OPT := $(shell $(PKG_CONFIG) --exists $(OPT_PKGS) 2>/dev/null && echo 1)
# Smooth text from real fonts (boards/text, fixel/face.h; issue #37). Without
# them boards/text/absent answers every call with -FX_ENOTSUP and a message
# naming the packages; a build says so in its summary (BUILT_WITHOUT), not
# on stdout at every read of this file, where make -s print-VAR is parsed.
TEXT_PKGS := freetype2 harfbuzz fribidi fontconfig libunibreak
HAVE_TEXT := $(shell $(PKG_CONFIG) --exists $(TEXT_PKGS) 2>/dev/null && echo 1)
PKGS     := $(if $(HAVE_PNG),$(SYS_PKGS)) $(if $(HAVE_OPT),$(OPT_PKGS)) $(if $(HAVE_TEXT),$(TEXT_PKGS))
# The image decoders (boards/image/), each optional: without its library a
# format is refused by name (FX_NO_JPEG, FX_NO_GIF, FX_NO_WEBP). giflib has
# no pkg-config file: its header is looked for. libqrencode (the tools' qr).
HAVE_JPEG := $(shell $(PKG_CONFIG) --exists libjpeg 2>/dev/null && echo 1)
HAVE_WEBP := $(shell $(PKG_CONFIG) --exists libwebp 2>/dev/null && echo 1)
# (linked, not only preprocessed: a cross compiler may see the host's header
# and have no target library)
# ('#' through a variable: inside $(shell) a \# stays "\#", which the
# preprocessor alone let through as a stray character)
HASH      := \#
HAVE_GIF  := $(shell printf '$(HASH)include <gif_lib.h>\nint main(void) { return GifErrorString(0) == 0; }\n' | \
               $(CC) -x c - -lgif -o /dev/null >/dev/null 2>&1 && echo 1)
HAVE_QR   := $(shell $(PKG_CONFIG) --exists libqrencode 2>/dev/null && echo 1)
# STATIC=1 needs each library's archive, which a -dev package may not ship
# (Debian's libqrencode-dev has only the .so): a library whose .pc is there
# but whose static link fails is left out, by name in the build summary,
# instead of failing the link of every tool (CI, stop 45: -lqrencode on rpi4).
ifeq ($(STATIC),1)
  static_links = $(shell echo 'int main(void) { return 0; }' | $(CC) -x c - -static -o /dev/null \
                   $$($(PKG_CONFIG) --static --libs $(1) 2>/dev/null) >/dev/null 2>&1 && echo 1)
  HAVE_TEXT := $(if $(HAVE_TEXT),$(call static_links,$(TEXT_PKGS)))
  HAVE_JPEG := $(if $(HAVE_JPEG),$(call static_links,libjpeg))
  HAVE_WEBP := $(if $(HAVE_WEBP),$(call static_links,libwebp))
  HAVE_QR   := $(if $(HAVE_QR),$(call static_links,libqrencode))
  HAVE_GIF  := $(if $(HAVE_GIF),$(shell echo 'int main(void) { return 0; }' | $(CC) -x c - -static -lgif -o /dev/null >/dev/null 2>&1 && echo 1))
  PKGS      := $(if $(HAVE_PNG),$(SYS_PKGS)) $(if $(HAVE_OPT),$(OPT_PKGS)) $(if $(HAVE_TEXT),$(TEXT_PKGS))
endif
PKGS     += $(if $(HAVE_JPEG),libjpeg) $(if $(HAVE_WEBP),libwebp) $(if $(HAVE_QR),libqrencode)
PKG_CFLAGS := $(shell $(PKG_CONFIG) --cflags $(PKGS) 2>/dev/null) $(if $(HAVE_PNG),,-DFX_NO_PNG -DFX_NO_ZLIB) \
              $(if $(HAVE_OPT),,-DFX_NO_BOARD_LIBS) $(if $(HAVE_TEXT),,-DFX_NO_TEXT) \
              $(if $(HAVE_JPEG),,-DFX_NO_JPEG) $(if $(HAVE_WEBP),,-DFX_NO_WEBP) $(if $(HAVE_GIF),,-DFX_NO_GIF) \
              $(if $(HAVE_QR),,-DFX_NO_QR)
PKG_LIBS   := $(shell $(PKG_CONFIG) --libs $(PKGS) 2>/dev/null) $(if $(HAVE_GIF),-lgif)
LDFLAGS  ?=
# STATIC=1: single static binaries to copy to a board (no shared library),
# in their own directory ($(BUILD)/static): a static build never re-links the
# dynamic build's binaries, nor the other way round.
ifeq ($(STATIC),1)
  BUILD    := $(BUILD)/static
  LDFLAGS += -static
  PKG_LIBS := $(shell $(PKG_CONFIG) --static --libs $(PKGS) 2>/dev/null) $(if $(HAVE_GIF),-lgif)
endif
LDLIBS   := $(PKG_LIBS) -lpthread -lm
# The libraries are chosen when make reads this file, so objects compiled
# without them (before tests/arm/deps.sh unpacked rpi-zero's armel sysroot or
# installed a board's -dev packages) must be rebuilt once they appear: the
# stamp holds the choice and is rewritten only when it changes (as
# tools/fixel-kiosk/kiosk.mk does). Only into an existing $(BUILD)/obj:
# reading the Makefile must not create build/.
# The text is taken here, once: the objects that add their own flags to
# PKG_CFLAGS (fixel-bench's, fixel-info's, fixel-shot's) would otherwise
# hand them to the stamp when one of them is the first built.
LIBS_STAMP := $(BUILD)/obj/libs
LIBS_STAMP_TEXT := $(PKG_CFLAGS)
$(shell if [ -d '$(BUILD)/obj' ] && [ "$$(cat '$(LIBS_STAMP)' 2>/dev/null)" != '$(LIBS_STAMP_TEXT)' ]; then \
	echo '$(LIBS_STAMP_TEXT)' > '$(LIBS_STAMP)'; fi)

CORE_SRC   := $(sort $(wildcard kernel-free-src/*/*.c))
# boards/: every .c of these folders; the folders that need libdrm, libevdev
# and libgpiod only when they are there (boards/linux/absent/ stands in for
# them otherwise, so the memory backend and fx_app still link).
BOARD_DIRS     := posix memory image display app env linux/display linux/console
BOARD_LIB_DIRS := linux/drm linux/input
BOARD_SRC  := $(sort $(foreach d,$(BOARD_DIRS) $(if $(HAVE_OPT),$(BOARD_LIB_DIRS),linux/absent) \
                                 $(if $(HAVE_TEXT),text,text/absent),\
                                 $(wildcard boards/$(d)/*.c)))
LIB_SRC    := $(CORE_SRC) $(BOARD_SRC)
LIB_OBJ    := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB_A      := $(BUILD)/libfixel.a
LIB_SO     := $(BUILD)/libfixel.so.$(VERSION)

TOOLS      := $(sort $(notdir $(patsubst %/,%,$(dir $(wildcard tools/*/main.c)))))
# The benchmark links the host's peer libraries (cairo, pixman, SDL2_gfx) and
# a -march=native reference: it is a host tool, not built for a board.
ifneq ($(CROSS_COMPILE),)
  TOOLS    := $(filter-out fixel-bench,$(TOOLS))
endif
TOOL_BINS  := $(TOOLS:%=$(BUILD)/bin/%)

# Test suites: each entry is a command that prints a final "N passed, N failed".
# The unit binary holds the tests of every layer (tests/README.md):
#   tests/core/    kernel-free-src        tests/boards/  boards/
#   tests/tools/   the tools' own code    tests/lib/     the framework and shared helpers
# test_display and test_pointer exercise boards/linux's backends, which need
# the board libraries.
TEST_DIRS  := tests/core tests/boards tests/tools
TEST_SRC   := $(sort $(filter-out $(if $(HAVE_OPT),,tests/boards/test_display.c tests/boards/test_pointer.c) \
                  $(if $(HAVE_TEXT),,tests/boards/test_face.c),\
                $(foreach d,$(TEST_DIRS),$(wildcard $(d)/test_*.c))))
TEST_LIB_SRC := $(sort $(wildcard tests/lib/*.c))
# 32-bit targets have no __int128: test files whose reference arithmetic
# needs it unguarded run on 64-bit hosts only (tests/arm/test-arm.sh says so).
ifeq ($(shell echo '__int128 x;' | $(CC) -x c -c -o /dev/null - 2>/dev/null && echo y),)
  TEST_NEEDS_128 := $(shell grep -l '__int128' $(TEST_SRC) | xargs -r grep -L '__SIZEOF_INT128__')
  TEST_SRC := $(filter-out $(TEST_NEEDS_128),$(TEST_SRC))
endif
TEST_OBJ   := $(TEST_SRC:%.c=$(BUILD)/obj/%.o) $(TEST_LIB_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/tests/registry.o
TEST_BIN   := $(BUILD)/tests/unit
GOLDEN_BIN := $(BUILD)/tests/golden
TEST_SUITES :=
TEST_DEB_PKGS :=
BENCH_DEB_PKGS :=


.PHONY: all lib tools run run-nodeps test test-nodeps test-bins test-plain test-asan check-freestanding check-layers deps deps-check cross-deps-check test-setup test-setup-run test-setup-deb install-build install uninstall \
        golden-update clean help
all: lib tools $(BUILD)/fixel.pc
	$(built_without_summary)

# Fragments from modules (kernel rig, bench, fuzz, board layers...) add
# targets and suites. boards/<name>.mk at the top of boards/ are the board
# profiles (read above); fragments live one or two folders down.
-include $(sort $(wildcard tests/*/*.mk tools/*/*.mk boards/*/*.mk boards/*/*/*.mk examples/*.mk))

lib: $(LIB_A) $(if $(filter 1,$(STATIC)),,$(LIB_SO))
tools: $(TOOL_BINS)

# V=1 shows the full commands.
ifeq ($(V),1)
  Q :=
else
  Q := @
endif

$(BUILD)/obj/kernel-free-src/%.o: kernel-free-src/%.c
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(BASEFLAGS) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: %.c $(LIBS_STAMP)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(BASEFLAGS) -D_GNU_SOURCE -D_FILE_OFFSET_BITS=64 $(PKG_CFLAGS) -Itests -Itests/lib $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(LIBS_STAMP):
	@mkdir -p $(@D)
	@echo '$(LIBS_STAMP_TEXT)' > $@

$(LIB_A): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  AR      $@")
	$(Q)rm -f $@
	$(Q)$(AR) rcs $@ $^

# Only the public API leaves libfixel.so: a version script naming every
# function and object the public headers declare (docs/ABI.md).
PUBLIC_HEADERS := $(sort $(wildcard kernel-free-src/include/fixel/*.h boards/include/fixel/*.h))
$(BUILD)/libfixel.map: $(PUBLIC_HEADERS) tools/gen/exports.sh
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  GEN     $@")
	$(Q)SOMAJOR=$(SOMAJOR) sh tools/gen/exports.sh --map "$(CC)" > $@.tmp && mv $@.tmp $@

$(LIB_SO): $(LIB_OBJ) $(BUILD)/libfixel.map
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) -shared -Wl,-soname,libfixel.so.$(SOMAJOR) -Wl,--version-script=$(BUILD)/libfixel.map \
	  $(SANFLAGS) $(LDFLAGS) -o $@ $(LIB_OBJ) $(LDLIBS)
	$(Q)ln -sf libfixel.so.$(VERSION) $(BUILD)/libfixel.so.$(SOMAJOR)
	$(Q)ln -sf libfixel.so.$(VERSION) $(BUILD)/libfixel.so

# Each tools/<name>/ with a main.c becomes $(BUILD)/bin/<name>; a fragment may
# add TOOL_LIBS_<name> (extra libraries) and TOOL_SRC_<name> (extra sources).
.SECONDEXPANSION:
tool_objs = $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tools/$1/*.c) $(TOOL_SRC_$1))
$(BUILD)/bin/%: $$(call tool_objs,$$*) $(LIB_A)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(filter %.o,$^) $(LIB_A) $(TOOL_LIBS_$*) $(LDLIBS)
# A tool's objects are reached only through that chained pattern rule, so
# make would delete them as intermediates and relink every tool on the next
# run: keep them.
.SECONDARY: $(foreach t,$(TOOLS),$(call tool_objs,$t))

# The build tree's own fixel.pc, for programs built against an uninstalled
# fixel (PKG_CONFIG_PATH=$(BUILD)); make install writes the installed one.
$(BUILD)/fixel.pc: Makefile
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  GEN     $@")
	$(Q)printf 'libdir=%s\n\nName: fixel\nDescription: integer-only fixed-point graphics on Linux framebuffers (build tree)\nVersion: %s\nLibs: -L$${libdir} -lfixel\nLibs.private: %s\nCflags: -I%s -I%s\n' \
	  '$(abspath $(BUILD))' '$(VERSION)' '$(strip $(PKG_LIBS) -lpthread -lm)' '$(abspath kernel-free-src/include)' '$(abspath boards/include)' > $@

# ---- tests ----
$(BUILD)/tests/registry.c: $(TEST_SRC) tests/lib/gen-registry.sh $(LIBS_STAMP)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  GEN     $@")
	$(Q)sh tests/lib/gen-registry.sh $(TEST_SRC) > $@

$(BUILD)/obj/tests/registry.o: $(BUILD)/tests/registry.c
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(BASEFLAGS) -Itests/lib $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(TEST_BIN): $(TEST_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(TEST_OBJ) $(LIB_A) $(LDLIBS) -lm

$(GOLDEN_BIN): $(BUILD)/obj/tests/golden/golden.o $(LIB_A)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(LIB_A) $(LDLIBS)

# The suites of one build directory (plain or sanitized); each prints its
# own total.
build_suites = "$(1)/tests/unit" \
	"$(1)/tests/golden --dir tests/golden --out $(1)/golden" \
	"$(1)/tests/golden --dir tests/golden/course --scripts examples/course --out $(1)/golden-course" \
	"sh tests/script-errors.sh $(1)/bin/fixel-draw $(1)/script-errors" \
	"sh tests/boards/bands.sh $(1)"
BUILD_SUITES = $(call build_suites,$(BUILD))

test-plain: all $(TEST_BIN) $(GOLDEN_BIN)
	@bash tests/run-suites.sh $(BUILD_SUITES)

test-asan:
	@$(MAKE) --no-print-directory SAN=1 test-plain

check-freestanding:
	@sh tests/check-freestanding.sh "$(CC)" "$(NM)" "$(BUILD)/freestanding" $(CORE_SRC)

# The include and getenv rules of the layers (docs/ARCHITECTURE.md).
check-layers:
	@sh tests/check-layers.sh

# Without the board libraries (a cross toolchain lacking the target's libdrm,
# libevdev, libgpiod) the tools cannot link; the test binaries still can.
test-bins: $(if $(HAVE_OPT),all,lib) $(TEST_BIN) $(GOLDEN_BIN)

test:
	@sh tests/deps.sh --for "make test" $(sort $(DEB_PKGS) $(TEST_DEB_PKGS))
	@$(MAKE) --no-print-directory test-nodeps

# Suites run TEST_JOBS at a time (tests/run-suites.sh; the ones marked
# "solo:" alone): most use one core, and CI's machine has two.
TEST_JOBS ?= $(shell n=$$(nproc 2>/dev/null || echo 1); [ $$n -gt 4 ] && n=4; echo $$n)
test-nodeps:
	@$(MAKE) --no-print-directory test-bins
	@$(MAKE) --no-print-directory SAN=1 test-bins
	@bash tests/run-suites.sh --total -j $(TEST_JOBS) \
	  $(call build_suites,$(PLAIN_BUILD)) \
	  $(call build_suites,$(ASAN_BUILD)) \
	  "sh tests/check-freestanding.sh '$(CC)' '$(NM)' build/freestanding $(CORE_SRC)" \
	  "sh tests/check-layers.sh" \
	  "sh tests/check-docs.sh" \
	  $(TEST_SUITES)

# The edit-compile-test loop: the build set only (unit, golden, course
# golden and script-error suites, plain and under ASan+UBSan, and the layer
# rules), a few minutes on two cores; `make test` is everything.
check_suites = "$(1)/tests/unit" \
	"$(1)/tests/golden --dir tests/golden --out $(1)/golden" \
	"$(1)/tests/golden --dir tests/golden/course --scripts examples/course --out $(1)/golden-course" \
	"sh tests/script-errors.sh $(1)/bin/fixel-draw $(1)/script-errors"
check:
	@sh tests/deps.sh --for "make check" $(sort $(DEB_PKGS))
	@$(MAKE) --no-print-directory check-nodeps
check-nodeps:
	@$(MAKE) --no-print-directory test-bins
	@$(MAKE) --no-print-directory SAN=1 test-bins
	@bash tests/run-suites.sh --total -j $(TEST_JOBS) \
	  $(call check_suites,$(PLAIN_BUILD)) $(call check_suites,$(ASAN_BUILD)) "sh tests/check-layers.sh" "sh tests/check-docs.sh"
.PHONY: check check-nodeps

# Every golden set, in one go (`git status` then shows what changed; look at
# the pictures before committing):
#   tests/golden/<FORMAT>/  scene scripts per pixel format (tests/golden/golden.c)
#   tests/golden/course/    the course examples, examples/course/*.fxs (same runner)
#   tests/golden/demo/      fixel-demo's gallery pages     (tools/fixel-demo)
#   tests/golden/kiosk/     fixel-kiosk's chosen frames    (tests/kiosk/run.sh)
#   tests/input/pointer/    pointer replay frames          (tests/boards/test_pointer.c)
GOLDEN_UPDATES := golden-update-scenes demo-golden-update kiosk-golden-update pointer-golden-update
golden-update: $(GOLDEN_UPDATES)
golden-update-scenes: all $(GOLDEN_BIN)
	$(GOLDEN_BIN) --dir tests/golden --out $(BUILD)/golden --update
	$(GOLDEN_BIN) --dir tests/golden/course --scripts examples/course --out $(BUILD)/golden-course --update
pointer-golden-update: $(TEST_BIN)
	FIXEL_POINTER_GOLDEN_UPDATE=1 $(TEST_BIN) pointer_
.PHONY: $(GOLDEN_UPDATES)

# ---- the main job ----
# make run / make test first install (root) or name (user) the packages of
# their purpose, then build in a new make, whose pkg-config sees them.
run:
	@sh tests/deps.sh --for "make run" $(sort $(DEB_PKGS))
	@$(MAKE) --no-print-directory run-nodeps

# The same without the package step (a packager's build, a machine without apt).
run-nodeps: all
	@mkdir -p out
	@if [ -x $(BUILD)/bin/fixel-demo ]; then $(BUILD)/bin/fixel-demo; else \
	  $(BUILD)/bin/fixel-draw -o out/showcase.png tools/fixel-draw/showcase.fxs && \
	  echo "fixel: no display here; rendered the showcase headless into out/showcase.png"; fi

# ---- dependencies ----
# A cross build (BOARD=rpi4 ...) whose target libraries pkg-config cannot
# find stops before compiling the tools, naming the missing packages and the
# command that installs them (the library alone still builds: the core needs
# nothing, and tests/arm runs its suites without them).
CROSS_TRIPLET := $(patsubst %-,%,$(CROSS_COMPILE))
DEB_ARCH_aarch64-linux-gnu   := arm64
DEB_ARCH_arm-linux-gnueabihf := armhf
DEB_ARCH_arm-linux-gnueabi   := armel
DEB_ARCH_x86_64-linux-gnu    := amd64
CROSS_DEB_ARCH := $(DEB_ARCH_$(CROSS_TRIPLET))
CROSS_DEB_PKGS := gcc-$(CROSS_TRIPLET) libc6-dev-$(CROSS_DEB_ARCH)-cross \
  $(foreach p,libpng-dev zlib1g-dev libdrm-dev libevdev-dev libgpiod-dev,$(p):$(CROSS_DEB_ARCH))
# armel's multiarch packages no longer install beside an updated bookworm
# host (no armel in bookworm-security): boards/rpi-zero.mk takes them from
# the sysroot tests/arm/sysroot-armel.sh unpacks instead.
cross-deps-check:
	@sh tests/deps.sh --no-install --for "make BOARD=$(BOARD) (target $(or $(CROSS_DEB_ARCH),$(CROSS_TRIPLET)))" $(CROSS_DEB_PKGS) || \
	  { $(if $(filter armel,$(CROSS_DEB_ARCH)),echo "(when apt cannot install the :armel packages: sh tests/arm/sysroot-armel.sh unpacks them into build/sysroot-armel, which make BOARD=$(BOARD) then uses)";) \
	    echo "(or build the library alone: make BOARD=$(BOARD) lib)"; exit 1; }
	@echo "make BOARD=$(BOARD): the target packages are installed, but PKG_CONFIG ($(PKG_CONFIG))"; \
	 echo "  finds$(if $(HAVE_PNG),, no libpng/zlib)$(if $(HAVE_OPT),, no libdrm/libevdev/libgpiod) for $(CROSS_DEB_ARCH)"; exit 1
ifneq ($(CROSS_DEB_ARCH),)
ifneq ($(HAVE_PNG)$(HAVE_OPT),11)
# (workloads.o and rtref.o are core-only benchmark code the unit tests link: not guarded)
$(filter-out %/workloads.o %/rtref.o,$(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tools/*/*.c))) $(TOOL_BINS): | cross-deps-check
# A goal that builds the tools (make BOARD=..., the default) stops before
# compiling anything, the library's objects included.
ifneq ($(if $(MAKECMDGOALS),$(filter all tools run-nodeps install-build,$(MAKECMDGOALS)),all),)
$(LIB_OBJ) $(GLUT_OBJ): | cross-deps-check
endif
endif
endif

# ---- a build never fails or half-builds silently ----
# Without the compiler (a bare system) a make that would compile stops
# before anything starts, with the package line `make run` gives, instead
# of make's "gcc: No such file or directory" from whichever job ran first.
# The goals that install the packages themselves (run, test, deps, deb...)
# go on: their own step names or installs the compiler.
NO_CC_GOALS := run test deps deps-check clean help uninstall test-setup test-setup-run test-setup-deb deb bench-peers glut-deps deps-glut print-%
ifeq ($(shell command -v $(firstword $(CC)) 2>/dev/null),)
ifneq ($(if $(MAKECMDGOALS),$(filter-out $(NO_CC_GOALS),$(MAKECMDGOALS)),all),)
  $(shell sh tests/deps.sh --no-install --for "make" $(if $(CROSS_COMPILE),$(CROSS_DEB_PKGS),$(sort $(DEB_PKGS))) >&2)
  $(error the compiler $(firstword $(CC)) is not installed (the line above installs it; or set CC=...))
endif
endif

# Without libdrm/libevdev/libgpiod or libpng the build still succeeds, with
# stand-ins (boards/linux/absent: no DRM/KMS, no input devices, no GPIO) and
# PPM-only images; every build entry (all, install, examples, glut) ends by
# saying so and naming the packages that bring them (tests/deps.sh).
BUILT_WITHOUT := $(subst $(eval) ,/,$(strip $(if $(HAVE_OPT),,libdrm/libevdev/libgpiod) $(if $(HAVE_PNG),,libpng) \
                   $(if $(HAVE_TEXT),,FreeType/HarfBuzz/FriBiDi/fontconfig/libunibreak) \
                   $(if $(HAVE_JPEG),,libjpeg) $(if $(HAVE_GIF),,giflib) $(if $(HAVE_WEBP),,libwebp)))
BUILT_WITHOUT_PKGS := $(if $(HAVE_OPT),,libdrm-dev libevdev-dev libgpiod-dev) $(if $(HAVE_PNG),,libpng-dev zlib1g-dev) \
                      $(if $(HAVE_TEXT),,libfreetype-dev libharfbuzz-dev libfribidi-dev libfontconfig-dev libunibreak-dev) \
                      $(if $(HAVE_JPEG),,libjpeg62-turbo-dev) $(if $(HAVE_GIF),,libgif-dev) $(if $(HAVE_WEBP),,libwebp-dev) pkg-config
define built_without_summary
@$(if $(BUILT_WITHOUT),\
  echo; echo "*** fixel: built WITHOUT $(BUILT_WITHOUT) ($(PKG_CONFIG) did not find them) ***"; \
  $(if $(HAVE_OPT),,echo "  no libdrm/libevdev/libgpiod: no DRM/KMS display (fbdev and the memory display only),"; \
    echo "    no input devices (touch, keyboard, mouse) and no GPIO buttons";) \
  $(if $(HAVE_PNG),,echo "  no libpng: pictures are PPM only (writing or reading .png fails)";) \
  $(if $(HAVE_TEXT),,echo "  no FreeType/HarfBuzz/FriBiDi/fontconfig/libunibreak: no smooth text (PSF fonts only)";) \
  $(if $(HAVE_JPEG),,echo "  no libjpeg: JPEG pictures are refused";) \
  $(if $(HAVE_GIF),,echo "  no giflib: GIF pictures and animations are refused";) \
  $(if $(HAVE_WEBP),,echo "  no libwebp: WebP pictures are refused";) \
  if sh tests/deps.sh --no-install --for "a full fixel build" $(BUILT_WITHOUT_PKGS); then \
    echo "  (the packages are installed, but $(PKG_CONFIG) does not find them: PKG_CONFIG_PATH?)"; \
  else echo "  then run make again (what changed is rebuilt)"; fi; echo,:)
endef

# By purpose (README, "Packages"): DEB_PKGS builds the library and tools and
# runs `make run`; TEST_DEB_PKGS (added to by the tests/*/*.mk fragments) is
# what `make test` needs on top; BENCH_DEB_PKGS the peers of `make bench-peers`.
# PACKAGE:ARCH entries are multiarch libraries of the cross tests.
# man-db: make install installs man pages (tools, fixel-script(5), the API).
DEB_PKGS := gcc libc6-dev make pkg-config libpng-dev zlib1g-dev libdrm-dev libevdev-dev libgpiod-dev man-db \
            libfreetype-dev libharfbuzz-dev libfribidi-dev libfontconfig-dev libunibreak-dev \
            libjpeg62-turbo-dev libgif-dev libwebp-dev libqrencode-dev
# `make deps`: every set; `make deps-check`: the same, named "make deps".
deps deps-check:
	@sh tests/deps.sh --for "make deps" $(sort $(DEB_PKGS) $(TEST_DEB_PKGS) $(BENCH_DEB_PKGS))

# First-try set-up in fresh bookworm roots (tests/setup/fresh-root.sh; root,
# needs the Debian mirror): a user's and root's first make run and make test.
# CI runs this after the host's make test, so within CI's time the roots'
# make test runs its core suites (TEST_SUITES= : unit, golden and script
# errors, plain and ASan, freestanding, layers) after installing the whole
# test set; tests/README.md, "CI", says why and how
# long. SETUP_TEST_ARGS= SETUP_USER_TEST_ARGS= runs every suite in the roots.
# DEBS=build/deb (make deb's output) adds the package install test.
# Root's first try (which installs the whole test set and builds plain and
# ASan, as the user's does) runs the suites that met a minimal root's gaps
# before (issue #39: no /usr/bin/time for the hostile suite's sanitized
# runs, no /etc/hosts for the brokers); the core suites are the user's run's
# already, and running them twice cost CI about 150 s.
SETUP_TEST_ARGS ?= FIXEL_TEST_ONLY='hostile.sh,mqtt/'
SETUP_USER_TEST_ARGS ?= TEST_SUITES=
SETUP_MAKE ?= make -j2
test-setup:
	@SETUP_TEST_ARGS="$(SETUP_TEST_ARGS)" SETUP_USER_TEST_ARGS="$(SETUP_USER_TEST_ARGS)" SETUP_MAKE='$(SETUP_MAKE)' \
	  sh tests/setup/fresh-root.sh $(if $(DEBS),--debs $(DEBS)) build/setup
test-setup-run:
	@SETUP_MAKE='$(SETUP_MAKE)' sh tests/setup/fresh-root.sh --no-test $(if $(DEBS),--debs $(DEBS)) build/setup
# make deb as a new user meets it: a fresh root, a tree without .git, root's
# first try; then those packages installed in another fresh root.
test-setup-deb:
	@SETUP_MAKE='$(SETUP_MAKE)' sh tests/setup/fresh-root.sh --no-run --deb-build build/setup-deb

# ---- install (tools/install.sh: one file list for install and uninstall) ----
# Every directory can be set on the command line; LIBDIR may be multiarch
# (LIBDIR=/usr/lib/x86_64-linux-gnu). fixel.pc is written at install time for
# the directories installed into. ldconfig runs for a live install as root.
BINDIR       ?= $(PREFIX)/bin
LIBDIR       ?= $(PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
DATADIR      ?= $(PREFIX)/share
MANDIR       ?= $(DATADIR)/man
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
SYSCONFDIR   ?= $(if $(filter /usr,$(PREFIX)),/etc,$(PREFIX)/etc)
SYSTEMDUNITDIR ?= $(if $(filter /usr,$(PREFIX)),/lib/systemd/system,$(PREFIX)/lib/systemd/system)
INSTALL_TOOLS := $(filter-out fixel-bench,$(TOOLS))
INSTALL_ENV = DESTDIR='$(DESTDIR)' PREFIX='$(PREFIX)' BINDIR='$(BINDIR)' LIBDIR='$(LIBDIR)' \
  INCLUDEDIR='$(INCLUDEDIR)' DATADIR='$(DATADIR)' MANDIR='$(MANDIR)' PKGCONFIGDIR='$(PKGCONFIGDIR)' \
  SYSCONFDIR='$(SYSCONFDIR)' SYSTEMDUNITDIR='$(SYSTEMDUNITDIR)' VERSION='$(VERSION)' SOMAJOR='$(SOMAJOR)' \
  BUILD='$(BUILD)' TOOLS='$(INSTALL_TOOLS)' LIBS_PRIVATE='$(strip $(PKG_LIBS) -lpthread -lm)'

# The API reference as section-3 man pages (man fx_line, man 3 fixel), from
# the public headers' comments (tools/gen/apiref.sh; docs/api/ is its HTML).
API_MAN := $(BUILD)/man/man3/fixel.3
$(API_MAN): $(PUBLIC_HEADERS) tools/gen/apiref.sh
	@$(if $(Q),echo "  GEN     $(@D) (API reference)")
	$(Q)sh tools/gen/apiref.sh --man $(BUILD)/man

# What install installs, built (debian/rules builds this, not fixel-bench).
install-build: lib $(INSTALL_TOOLS:%=$(BUILD)/bin/%) $(API_MAN)

install: install-build
	@$(INSTALL_ENV) sh tools/install.sh install
	$(built_without_summary)

uninstall:
	@$(INSTALL_ENV) sh tools/install.sh uninstall

clean:
	rm -rf build out

help:
	@echo 'fixel targets (BOARD=<name> picks boards/<name>.mk; SAN=1 builds in $$BUILD/asan):'
	@echo '  all (default)        library (static + shared), tools, fixel.pc'
	@echo '  lib                  libfixel.a and libfixel.so only'
	@echo '  tools                every tools/<name>/ program into $(BUILD)/bin/'
	@echo '  run                  the main job (fixel-demo, or the showcase rendered headless)'
	@echo '  check                the quick loop: unit, golden, script errors, plain and ASan'
	@echo '  test                 every suite, plain and under ASan+UBSan, with a total'
	@echo '                         (QUICK=1 skips test-arm, FIXEL_SKIP_KERNEL=1 the kernel rig)'
	@echo '  test-plain           the suites of one build (SAN=1 for the sanitized one)'
	@echo '  test-asan            test-plain under ASan+UBSan'
	@echo '  test-bins            the test programs, without running them'
	@echo '  test-kernel          the qemu real-kernel rig (tests/kernel/README.md)'
	@echo '  test-arm             unit and golden suites under qemu-user for the ARM ABIs'
	@echo '  test-bounded         instruction budgets of the huge primitives (valgrind)'
	@echo '  check-freestanding   the core compiled freestanding and integer-only'
	@echo '  check-layers         the include/getenv rules of docs/ARCHITECTURE.md'
	@echo '  test-api             the API reference is complete and docs/api current (api-html rewrites it)'
	@echo '  test-readme          every README.md code block as pasted'
	@echo '  test-deb-control     make deb'"'"'s packages and libfixel-dev'"'"'s Depends, without building'
	@echo '  deb                  Debian packages (DEB_ARCHES=amd64 arm64 armhf), lintian, arm renders'
	@echo '  test-setup           fresh bookworm roots: first make run / make test, user and root (CI)'
	@echo '  test-setup-run       the same without the make test runs'
	@echo '  test-setup-deb       make deb from a tree without .git in a fresh root, then those packages installed'
	@echo '  valgrind             unit, golden and tool suites under memcheck (slow)'
	@echo '  fuzz                 each libFuzzer target for FUZZ_SECONDS'
	@echo '  bench, bench-peers   the benchmark table (docs/BENCHMARK.md)'
	@echo '  bench-insn           instructions per primitive, x86-64 and aarch64 (docs/PERFORMANCE.md)'
	@echo '  golden-update        re-render every golden set (then look at git status)'
	@echo '  kiosk-soak           the long constant-memory run of fixel-kiosk'
	@echo '  deps                 install the Debian packages the build needs (root)'
	@echo '  install              PREFIX=/usr/local DESTDIR='
	@echo '  clean                remove build/ and out/'
	@echo '  print-VAR            show a variable (e.g. make print-LIB_SRC)'
	@echo 'Variables: CC CFLAGS CPPFLAGS LDFLAGS (appended to fixel'"'"'s flags), OPT, CPU_FLAGS,'
	@echo '  CROSS_COMPILE, STATIC=1, V=1 (full commands), PREFIX, DESTDIR.'

# make print-VAR shows a variable's value (used by test scripts).
print-%:
	@echo $($*)

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
