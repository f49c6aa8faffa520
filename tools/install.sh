#!/bin/sh
# SPDX-License-Identifier: MIT
# make install / make uninstall (the Makefile passes every directory in the
# environment). One list of files serves both, so uninstall removes exactly
# what install wrote:
#   LIBDIR        libfixel.a, libfixel.so.VERSION, .so.SOMAJOR and .so links
#   INCLUDEDIR    fixel/*.h (the public headers)
#   PKGCONFIGDIR  fixel.pc, written here for this PREFIX/LIBDIR/INCLUDEDIR
#   BINDIR        the tools (TOOLS; fixel-bench is not among them)
#   MANDIR        man1/<tool>.1 and man5/fixel-script.5 from docs/man;
#                 man3/*.3, the API reference ($BUILD/man/man3, make install-build)
#   SYSTEMDUNITDIR fixel-kiosk.service (ExecStart in BINDIR, config in SYSCONFDIR)
#   DATADIR       fixel/examples/* (the example programs with a Makefile
#                 for them, kiosk configs and their picture);
#                 doc/fixel/api/*.html (the API reference, docs/api)
# ldconfig runs after installing or removing into the live system as root
# (DESTDIR empty). Directories: fixel's own are removed by uninstall; the
# shared ones (bin, lib, share/man/man1...) only inside a DESTDIR, and only
# when empty.
# usage: install.sh install|uninstall|list
set -eu
mode=$1
: "${DESTDIR=}" "${PREFIX:?}" "${BINDIR:?}" "${LIBDIR:?}" "${INCLUDEDIR:?}" "${DATADIR:?}" "${MANDIR:?}"
: "${PKGCONFIGDIR:?}" "${SYSCONFDIR:?}" "${SYSTEMDUNITDIR:?}" "${VERSION:?}" "${SOMAJOR:?}" "${BUILD:?}"
: "${TOOLS=}" "${LIBS_PRIVATE=}"
D=$DESTDIR
EXDIR=$DATADIR/fixel/examples
HEADERS=$(ls kernel-free-src/include/fixel/*.h boards/include/fixel/*.h)
# files only: examples/course/ holds the course scripts (tests/golden/course)
EXAMPLES=$(find examples -maxdepth 1 -type f 2>/dev/null | sort)

# "destination source mode" lines; source "-" is generated, "@link" a symlink
files() {
    echo "$LIBDIR/libfixel.a $BUILD/libfixel.a 644"
    echo "$LIBDIR/libfixel.so.$VERSION $BUILD/libfixel.so.$VERSION 755"
    echo "$LIBDIR/libfixel.so.$SOMAJOR @libfixel.so.$VERSION -"
    echo "$LIBDIR/libfixel.so @libfixel.so.$VERSION -"
    for h in $HEADERS; do echo "$INCLUDEDIR/fixel/${h##*/} $h 644"; done
    echo "$PKGCONFIGDIR/fixel.pc - 644"
    for t in $TOOLS; do
        echo "$BINDIR/$t $BUILD/bin/$t 755"
        [ -f "docs/man/$t.1" ] && echo "$MANDIR/man1/$t.1 docs/man/$t.1 644"
    done
    echo "$MANDIR/man5/fixel-script.5 docs/man/fixel-script.5 644"
    for m in "$BUILD"/man/man3/*.3; do
        [ -f "$m" ] && echo "$MANDIR/man3/${m##*/} $m 644"
    done
    for h in docs/api/*.html; do echo "$DATADIR/doc/fixel/api/${h##*/} $h 644"; done
    case " $TOOLS " in *" fixel-kiosk "*)
        echo "$SYSTEMDUNITDIR/fixel-kiosk.service - 644" ;; esac
    # examples.mk is the tree's own fragment; Makefile.installed is the
    # Makefile a user runs in a copy of the installed folder
    for e in $EXAMPLES; do
        case $e in
        examples/examples.mk) ;;
        examples/Makefile.installed) echo "$EXDIR/Makefile $e 644" ;;
        *) echo "$EXDIR/${e##*/} $e 644" ;;
        esac
    done
}

pc() {
    # Cflags: fixel's own include directory only (the public headers include
    # nothing from libpng, libdrm...); their libraries are Libs.private for
    # static links (pkg-config --static).
    cat <<EOF
prefix=$PREFIX
libdir=$LIBDIR
includedir=$INCLUDEDIR

Name: fixel
Description: integer-only fixed-point graphics on Linux framebuffers
Version: $VERSION
Libs: -L\${libdir} -lfixel
Libs.private: $LIBS_PRIVATE
Cflags: -I\${includedir}
EOF
}
unit() {
    sed -e "s|@BINDIR@|$BINDIR|g" -e "s|@SYSCONFDIR@|$SYSCONFDIR|g" tools/fixel-kiosk/fixel-kiosk.service.in
}

live_root() { [ -z "$D" ] && [ "$(id -u)" = 0 ]; }

case $mode in
list) files | cut -d' ' -f1 ;;
install)
    files | while read -r dst src m; do
        install -d "$D$(dirname "$dst")"
        case $src in
        @*) ln -sf "${src#@}" "$D$dst" ;;
        -)  case $dst in
            *.pc) pc > "$D$dst" ;;
            *.service) unit > "$D$dst" ;;
            esac
            chmod "$m" "$D$dst" ;;
        *)  install -m "$m" "$src" "$D$dst" ;;
        esac
        echo "  INSTALL $D$dst"
    done
    if live_root && command -v ldconfig >/dev/null 2>&1; then ldconfig; echo "  LDCONFIG"; fi ;;
uninstall)
    files | while read -r dst src m; do
        if [ -e "$D$dst" ] || [ -L "$D$dst" ]; then rm -f "$D$dst"; echo "  RM      $D$dst"; fi
    done
    for d in "$INCLUDEDIR/fixel" "$EXDIR" "$DATADIR/fixel" "$DATADIR/doc/fixel/api" "$DATADIR/doc/fixel"; do
        [ -d "$D$d" ] && rmdir "$D$d" 2>/dev/null && echo "  RMDIR   $D$d"
    done
    if [ -n "$D" ]; then
        # shared directories made for a staged install: only inside DESTDIR
        files | cut -d' ' -f1 | while read -r dst; do
            d=$(dirname "$dst")
            while [ "$d" != "/" ] && [ "$d" != "." ]; do
                if [ -d "$D$d" ]; then rmdir "$D$d" 2>/dev/null || break; echo "  RMDIR   $D$d"; fi
                d=$(dirname "$d")
            done
        done
    fi
    if live_root && command -v ldconfig >/dev/null 2>&1; then ldconfig; echo "  LDCONFIG"; fi ;;
*) echo "usage: $0 install|uninstall|list" >&2; exit 2 ;;
esac
exit 0
