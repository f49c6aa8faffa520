#!/bin/sh
# SPDX-License-Identifier: MIT
# The packaging's logic, without building packages (make deb takes too long
# for every run; CI runs it whole):
#   - make deb's package set (DEB_PKGS + DEB_BUILD_DEB_PKGS) holds
#     build-essential and every Build-Depends of debian/control, so
#     dpkg-checkbuilddeps passes on a fresh machine after its install step;
#   - libfixel-dev depends on the package of every library that
#     pkg-config --static --libs fixel names (a static link works after
#     installing the .debs);
#   - a tree without .git (a release tarball) gives deb.sh a source copy with
#     debian/changelog that dpkg-parsechangelog reads.
# usage: control.sh BUILD_DIR       "deb-control: N passed, N failed"
B=${1:-build}
P=0; F=0
ok() { echo "PASS $*"; P=$((P + 1)); }
no() { echo "FAIL $*"; F=$((F + 1)); }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
MK="${MAKE:-make} --no-print-directory -s"

set_pkgs=" $($MK print-DEB_PKGS) $($MK print-DEB_BUILD_DEB_PKGS) "
case $set_pkgs in *" build-essential "*) ok "make deb installs build-essential" ;; *) no "make deb's set lacks build-essential" ;; esac
# Build-Depends: names without versions, :native or arch qualifiers;
# debhelper-compat is provided by debhelper
bd=$(sed -n '/^Build-Depends:/,/^[A-Z][A-Za-z-]*:/p' debian/control | sed '$d' | sed 's/^Build-Depends://' |
     tr ',' '\n' | sed -E 's/\(.*\)//; s/\[.*\]//; s/:native//; s/^[[:space:]]+//; s/[[:space:]]+$//' | grep -v '^$')
miss=""
for p in $bd; do
    [ "$p" = debhelper-compat ] && p=debhelper
    case $set_pkgs in *" $p "*) ;; *) miss="$miss $p" ;; esac
done
[ -n "$bd" ] && [ -z "$miss" ] && ok "make deb installs every Build-Depends ($(echo $bd | tr '\n' ' '))" ||
    no "Build-Depends not in make deb's set:$miss"

# libfixel-dev's Depends against the static link line
deps=$(awk '/^Package: libfixel-dev/{p=1} p && /^Depends:/{d=1} p && d{print} p && d && !/,$/{exit}' debian/control |
       sed 's/^Depends://' | tr ',' '\n' | sed -E 's/\(.*\)//; s/^[[:space:]]+//; s/[[:space:]]+$//' | grep -v '^\$' | grep -v '^$')
# ${fixel:TextDev} (debian/rules): the text libraries' -dev packages,
# where the build has them, as this host's does when make print-HAVE_TEXT says 1
if grep -q '\${fixel:TextDev}' debian/control && [ -n "$($MK print-HAVE_TEXT 2>/dev/null | tail -n 1)" ]; then
    deps="$deps
libfreetype-dev
libharfbuzz-dev
libfribidi-dev
libfontconfig-dev
libunibreak-dev"
fi
[ -f "$B/fixel.pc" ] || $MK "$B/fixel.pc" BUILD="$B" >/dev/null
libs=$(PKG_CONFIG_PATH="$B" pkg-config --static --libs fixel) || no "pkg-config --static --libs fixel"
miss=""; seen=""
for l in $libs; do
    case $l in -l*) ;; *) continue ;; esac
    n=${l#-l}
    case $n in fixel|m|pthread|c|dl|rt) continue ;; esac   # fixel itself; libc6-dev's
    f=$(gcc -print-file-name="lib$n.so"); [ "$f" = "lib$n.so" ] && f=$(gcc -print-file-name="lib$n.a")
    f=$(readlink -f "$f" 2>/dev/null || echo "$f")
    # the -dev package holds the link-time name (lib$n.so or .a), not the runtime file
    pkg=$(dpkg -S "$(dirname "$f")/lib$n.so" "$(dirname "$f")/lib$n.a" 2>/dev/null | head -1 | cut -d: -f1)
    [ -z "$pkg" ] && pkg=$(dpkg -S "*/lib$n.so" 2>/dev/null | grep -- '-dev' | head -1 | cut -d: -f1)
    if [ -z "$pkg" ]; then miss="$miss -l$n(no package found)"; continue; fi
    seen="$seen $pkg"
    echo "$deps" | grep -qx "$pkg" || miss="$miss $pkg(-l$n)"
done
[ -n "$seen" ] && [ -z "$miss" ] && ok "libfixel-dev depends on the packages of pkg-config --static --libs fixel:$seen" ||
    no "libfixel-dev lacks:$miss (static libs: $libs)"

# a tree without .git
mkdir -p "$tmp/tree"
git ls-files -z 2>/dev/null | tar --null -T - -c 2>/dev/null | tar -x -C "$tmp/tree" 2>/dev/null ||
    tar -c --exclude=./build --exclude=./.git . | tar -x -C "$tmp/tree"
[ -d "$tmp/tree/.git" ] && no "the copy has .git"
if (cd "$tmp/tree" && GIT_CEILING_DIRECTORIES="$tmp" sh tests/deb/deb.sh --source-only "$tmp/src") > "$tmp/log" 2>&1 &&
   [ "$(dpkg-parsechangelog -l "$tmp/src/debian/changelog" -S Source)" = fixel ] && [ -f "$tmp/src/Makefile" ] &&
   [ ! -d "$tmp/src/build" ]; then
    ok "a tree without .git gives deb.sh a source with debian/changelog"
else
    cat "$tmp/log"; no "deb.sh's source copy from a tree without .git"
fi
echo "deb-control: $P passed, $F failed"
[ $F -eq 0 ]
