# SPDX-License-Identifier: MIT
# The GLUT + OpenGL 1.x layer (boards/glut, issue #21): libfixel-glut.a, its
# shared library and fixel-glut.pc. Programs build with
#   cc lab.c -Iboards/glut/include $(BUILD)/libfixel-glut.a $(BUILD)/libfixel.a $(PKG_LIBS) -lm -ldl
# or, installed, $(pkg-config --cflags --libs fixel-glut).
# Its integer core (kernel-free-src/gl) is part of libfixel: the top
# Makefile's CORE_SRC takes every kernel-free-src/*/*.c.

GLUT_SRC    := $(sort $(wildcard boards/glut/*.c))
GLUT_OBJ    := $(GLUT_SRC:%.c=$(BUILD)/obj/%.o)
GLUT_A      := $(BUILD)/libfixel-glut.a
GLUT_SO     := $(BUILD)/libfixel-glut.so.$(VERSION)
GLUT_PC     := $(BUILD)/fixel-glut.pc
# -ldl: text.c dlopens FreeType; glibc before 2.34 keeps dlopen in libdl
# (harmless on later ones, where libdl is an empty stub)
GLUT_LIBS   := $(GLUT_A) $(LIB_A) $(LDLIBS) -lm -ldl

$(GLUT_OBJ): BASEFLAGS += -Iboards/glut/include
# The X11 bitmap fonts are read with FreeType, opened at run time (text.c):
# only its headers are needed here, and nothing is added to the link.
GLUT_FT_CFLAGS := $(shell $(PKG_CONFIG) --cflags freetype2 2>/dev/null)
$(BUILD)/obj/boards/glut/text.o: BASEFLAGS += $(if $(GLUT_FT_CFLAGS),$(GLUT_FT_CFLAGS) -DFXG_HAVE_FREETYPE)

$(GLUT_A): $(GLUT_OBJ)
	@mkdir -p $(dir $@)
	$(Q)rm -f $@
	@$(if $(Q),echo "  AR      $@")
	$(Q)$(AR) rcs $@ $^

$(GLUT_SO): $(GLUT_OBJ) $(LIB_SO)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) -shared -Wl,-soname,libfixel-glut.so.$(SOMAJOR) $(SANFLAGS) $(LDFLAGS) -o $@ $(GLUT_OBJ) -L$(BUILD) -lfixel $(LDLIBS) -lm -ldl
	$(Q)ln -sf libfixel-glut.so.$(VERSION) $(BUILD)/libfixel-glut.so.$(SOMAJOR)
	$(Q)ln -sf libfixel-glut.so.$(VERSION) $(BUILD)/libfixel-glut.so

$(GLUT_PC): boards/glut/glut.mk
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  GEN     $@")
	$(Q)printf 'prefix=%s\nlibdir=$${prefix}/lib\nincludedir=$${prefix}/include\n\nName: fixel-glut\nDescription: GLUT and OpenGL 1.x immediate mode on fixel framebuffers\nVersion: %s\nRequires.private: fixel\nLibs: -L$${libdir} -lfixel-glut -lfixel\nLibs.private: -lm -lpthread -ldl\nCflags: -I$${includedir}/fixel-glut\n' \
	  '$(PREFIX)' '$(VERSION)' > $@

.PHONY: glut install-glut uninstall-glut
glut: $(GLUT_A) $(if $(filter 1,$(STATIC)),,$(GLUT_SO)) $(GLUT_PC)
	$(if $(filter glut,$(MAKECMDGOALS)),$(built_without_summary))
all: glut
lib: glut

# The directories are the top Makefile's (LIBDIR, INCLUDEDIR, PKGCONFIGDIR);
# fixel-glut.pc is written for them at install time, like fixel.pc.
GLUT_HEADERS := $(notdir $(wildcard boards/glut/include/GL/*.h))
install-glut: glut
	install -d $(DESTDIR)$(INCLUDEDIR)/fixel-glut/GL $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR)
	install -m 644 boards/glut/include/GL/*.h $(DESTDIR)$(INCLUDEDIR)/fixel-glut/GL/
	install -m 644 $(GLUT_A) $(DESTDIR)$(LIBDIR)/
	$(if $(filter 1,$(STATIC)),,install -m 755 $(GLUT_SO) $(DESTDIR)$(LIBDIR)/ && \
	  ln -sf libfixel-glut.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libfixel-glut.so.$(SOMAJOR) && \
	  ln -sf libfixel-glut.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libfixel-glut.so)
	@$(if $(Q),echo "  GEN     $@")
	$(Q)printf 'libdir=%s\nincludedir=%s\n\nName: fixel-glut\nDescription: GLUT and OpenGL 1.x immediate mode on fixel framebuffers\nVersion: %s\nRequires.private: fixel\nLibs: -L$${libdir} -lfixel-glut -lfixel\nLibs.private: -lm -lpthread -ldl\nCflags: -I$${includedir}/fixel-glut\n' \
	  '$(LIBDIR)' '$(INCLUDEDIR)' '$(VERSION)' > $(DESTDIR)$(PKGCONFIGDIR)/fixel-glut.pc
install: install-glut

# Runs before fixel's own uninstall, which then removes the emptied directories.
uninstall-glut:
	rm -f $(GLUT_HEADERS:%=$(DESTDIR)$(INCLUDEDIR)/fixel-glut/GL/%) \
	  $(DESTDIR)$(LIBDIR)/libfixel-glut.a $(DESTDIR)$(LIBDIR)/libfixel-glut.so \
	  $(DESTDIR)$(LIBDIR)/libfixel-glut.so.$(SOMAJOR) $(DESTDIR)$(LIBDIR)/libfixel-glut.so.$(VERSION) \
	  $(DESTDIR)$(PKGCONFIGDIR)/fixel-glut.pc
	-rmdir $(DESTDIR)$(INCLUDEDIR)/fixel-glut/GL $(DESTDIR)$(INCLUDEDIR)/fixel-glut 2>/dev/null
uninstall: uninstall-glut
