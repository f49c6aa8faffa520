#!/bin/sh
# SPDX-License-Identifier: MIT
# make install / uninstall into staging directories (issue #20):
#   - a Debian-style install (PREFIX=/usr, multiarch LIBDIR) puts every file
#     where it belongs, fixel-bench not among them, and fixel.pc names exactly
#     these directories with Cflags of fixel's include path only;
#   - the README's 15-line example builds against it with pkg-config and runs;
#   - a second install with another PREFIX gets its own fixel.pc (never stale);
#   - the man pages render without warnings (man --warnings) and
#     fixel-script(5) names every command of fixel-draw --commands;
#   - systemd-analyze verify is clean on the installed kiosk unit;
#   - uninstall leaves each staging directory empty.
# usage: install.sh BUILD_DIR        "install: N passed, N failed"
B=$1
O=$(mkdir -p "$B/install-test" && cd "$B/install-test" && pwd)
P=0; F=0
ok() { echo "PASS $*"; P=$((P + 1)); }
no() { echo "FAIL $*"; F=$((F + 1)); }
MK="${MAKE:-make} --no-print-directory -s BUILD=$B"
ARCH=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
rm -rf "$O"; mkdir -p "$O"
S=$O/stage
V="PREFIX=/usr LIBDIR=/usr/lib/$ARCH"

if $MK install DESTDIR="$S" $V > "$O/install.log" 2>&1; then ok "make install DESTDIR=... $V"; else
    cat "$O/install.log"; no "make install failed"; echo "install: $P passed, $F failed"; exit 1; fi
miss=""
for f in usr/lib/$ARCH/libfixel.a usr/lib/$ARCH/libfixel.so usr/lib/$ARCH/libfixel.so.0 \
         usr/lib/$ARCH/pkgconfig/fixel.pc usr/include/fixel/draw.h usr/include/fixel/version.h \
         usr/bin/fixel-draw usr/bin/fixel-kiosk usr/share/man/man1/fixel-draw.1 \
         usr/share/man/man5/fixel-script.5 lib/systemd/system/fixel-kiosk.service \
         usr/share/fixel/examples/kiosk-basic.conf; do
    [ -e "$S/$f" ] || miss="$miss $f"
done
[ -z "$miss" ] && ok "installed files in place" || no "not installed:$miss"
[ -e "$S/usr/bin/fixel-bench" ] && no "fixel-bench installed" || ok "fixel-bench not installed"
nh=$(ls kernel-free-src/include/fixel/*.h boards/include/fixel/*.h | wc -l)
[ "$(ls "$S/usr/include/fixel" | wc -l)" = "$nh" ] && ok "$nh public headers" || no "headers: $(ls "$S/usr/include/fixel" | wc -l) of $nh"
for t in $(ls "$S/usr/bin"); do [ -f "$S/usr/share/man/man1/$t.1" ] || no "no man page for $t"; done
pc=$S/usr/lib/$ARCH/pkgconfig/fixel.pc
grep -qx "libdir=/usr/lib/$ARCH" "$pc" && grep -qx 'includedir=/usr/include' "$pc" && grep -qx 'Cflags: -I${includedir}' "$pc" &&
    ! grep -q Requires "$pc" && ok "fixel.pc: libdir, includedir, Cflags of fixel only" || { cat "$pc"; no "fixel.pc"; }
cf=$(PKG_CONFIG_PATH= PKG_CONFIG_LIBDIR="$S/usr/lib/$ARCH/pkgconfig" pkg-config --cflags fixel)
[ -z "$(echo "$cf" | tr ' ' '\n' | grep -v '^$' | grep -v '^-I/usr/include$')" ] && ok "pkg-config --cflags fixel: '$cf'" ||
    no "pkg-config --cflags has more than fixel's path: $cf"

# the README example against the staged install
sed -n '/^## A 15-line example/,/^## /p' README.md | sed -n '/^```c$/,/^```$/p' | sed '1d;$d' > "$O/hello.c"
PC="env PKG_CONFIG_PATH= PKG_CONFIG_LIBDIR=$S/usr/lib/$ARCH/pkgconfig PKG_CONFIG_SYSROOT_DIR=$S pkg-config"
if [ -s "$O/hello.c" ] && cc -std=c11 -Wall -Wextra -Werror "$O/hello.c" -o "$O/hello" $($PC --cflags --libs fixel) 2> "$O/hello.log" &&
   (cd "$O" && LD_LIBRARY_PATH="$S/usr/lib/$ARCH" ./hello) && [ -s "$O/hello.png" ] &&
   LD_LIBRARY_PATH="$S/usr/lib/$ARCH" ldd "$O/hello" | grep -q "libfixel.so.0 => $S"; then
    ok "README example builds with pkg-config against the install, runs on its libfixel.so.0"
else
    cat "$O/hello.log"; no "README example against the install"
fi

# the installed examples build with their own Makefile in a copy (not the
# tree's examples.mk fragment) and hello runs
EXI=$S/usr/share/fixel/examples
if [ -f "$EXI/Makefile" ] && [ ! -e "$EXI/examples.mk" ] && rm -rf "$O/ex" && cp -r "$EXI" "$O/ex" &&
   (cd "$O/ex" && make PKG_CONFIG="$PC" > make.log 2>&1 && LD_LIBRARY_PATH="$S/usr/lib/$ARCH" ./hello) && [ -s "$O/ex/hello.png" ]; then
    ok "the installed examples build with their Makefile and hello runs"
else
    cat "$O/ex/make.log" 2>/dev/null; no "the installed examples' Makefile"
fi

# another PREFIX: its own fixel.pc
S2=$O/stage2
$MK install DESTDIR="$S2" PREFIX=/opt/fixel > "$O/install2.log" 2>&1 &&
    grep -qx 'prefix=/opt/fixel' "$S2/opt/fixel/lib/pkgconfig/fixel.pc" && grep -qx 'libdir=/opt/fixel/lib' "$S2/opt/fixel/lib/pkgconfig/fixel.pc" &&
    grep -q 'ExecStart=/opt/fixel/bin/fixel-kiosk .*/opt/fixel/etc/fixel/kiosk.conf' "$S2/opt/fixel/lib/systemd/system/fixel-kiosk.service" &&
    ok "PREFIX=/opt/fixel: fixel.pc and the unit name /opt/fixel" || { cat "$O/install2.log"; no "PREFIX=/opt/fixel install"; }

# man pages
if command -v man >/dev/null 2>&1; then
    for m in "$S"/usr/share/man/man1/*.1 "$S"/usr/share/man/man5/*.5; do
        w=$(LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -E UTF-8 -l "$m" 2>&1 >/dev/null)
        [ -z "$w" ] && ok "man ${m##*/}" || no "man --warnings ${m##*/}: $w"
    done
else no "no man (make test installs man-db)"; fi
left=""
for c in $("$B/bin/fixel-draw" --commands | cut -d' ' -f1); do
    grep -qx ".B $c" docs/man/fixel-script.5 || left="$left $c"
done
[ -z "$left" ] && ok "fixel-script(5) names every command" || no "fixel-script(5) lacks:$left (run tools/gen/man-script.sh)"

# the kiosk unit
if command -v systemd-analyze >/dev/null 2>&1; then
    u=$O/unit/fixel-kiosk.service; mkdir -p "$O/unit"
    # verify checks that ExecStart exists: point it at the staged binary
    sed "s|ExecStart=/usr/bin/fixel-kiosk|ExecStart=$S/usr/bin/fixel-kiosk|" "$S/lib/systemd/system/fixel-kiosk.service" > "$u"
    # Documentation=man:fixel-kiosk(1) is looked up with man: the staged page
    w=$(MANPATH="$S/usr/share/man" SYSTEMD_LOG_LEVEL=notice systemd-analyze verify "$u" 2>&1); rc=$?
    [ $rc -eq 0 ] && [ -z "$w" ] && ok "systemd-analyze verify fixel-kiosk.service" || no "systemd-analyze verify (exit $rc): $w"
else no "no systemd-analyze (make test installs systemd)"; fi

# uninstall: nothing left
$MK uninstall DESTDIR="$S" $V > "$O/uninstall.log" 2>&1
$MK uninstall DESTDIR="$S2" PREFIX=/opt/fixel >> "$O/uninstall.log" 2>&1
for s in "$S" "$S2"; do
    left=$(find "$s" -mindepth 1 2>/dev/null)
    [ -z "$left" ] && ok "uninstall left ${s##*/} empty" || no "uninstall left in ${s##*/}: $left"
done
echo "install: $P passed, $F failed"
[ $F -eq 0 ]
