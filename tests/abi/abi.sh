#!/bin/sh
# SPDX-License-Identifier: MIT
# The library's face (issue #20, docs/ABI.md):
#   exports   nm -D --defined-only of libfixel.so equals, name for name, the
#             functions and objects the public headers declare (either way)
#   soname    libfixel.so.$SOMAJOR, and SOMAJOR is FX_VERSION_MAJOR
#   version   FX_VERSION_MAJOR/MINOR/PATCH/STRING agree with the Makefile's VERSION
#   spdx      every source file has its SPDX-License-Identifier line
#   guards    every public header has its extern "C" guard
#   prefixes  every global symbol of libfixel.a / libfixel-glut.a is fx_-named
# usage: abi.sh BUILD_DIR VERSION SOMAJOR [NM]
B=$1; VERSION=$2; SOMAJOR=$3; NM=${4:-nm}
P=0; F=0
ok() { echo "PASS $*"; P=$((P + 1)); }
no() { echo "FAIL $*"; F=$((F + 1)); }
so=$B/libfixel.so.$VERSION
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# exports
SOMAJOR=$SOMAJOR sh tools/gen/exports.sh --names > "$tmp/declared"
$NM -D --defined-only "$so" | awk '$2 ~ /^[TDRBVWiu]$/ { print $3 }' | sed 's/@.*//' | grep -v '^FIXEL_' | sort -u > "$tmp/exported"
extra=$(comm -13 "$tmp/declared" "$tmp/exported")
missing=$(comm -23 "$tmp/declared" "$tmp/exported")
[ -z "$extra" ] && ok "exports: nothing beyond the public headers ($(wc -l < "$tmp/exported") symbols)" ||
    no "exports: libfixel.so exports what no public header declares:" $extra
[ -z "$missing" ] && ok "exports: every declared function and object is exported ($(wc -l < "$tmp/declared"))" ||
    no "exports: declared in a public header but not exported (not defined?):" $missing
# symbol version node
$NM -D --defined-only "$so" | grep -q "FIXEL_$SOMAJOR" && ok "exports: versioned as FIXEL_$SOMAJOR" ||
    no "exports: no FIXEL_$SOMAJOR version node"

# prefixes: a static link puts every global symbol of the archives into the
# user's program, so internal cross-file functions are named like public ones
# (fx_, or the fx16_/fx32_/fx56_/fx3d_ families); the GLUT layer adds the
# GL/GLU/GLUT names it implements (issue #42: vsd_*, rt_* and fxg_* were not)
pfx() { # ARCHIVE ALLOWED-ERE
    [ -f "$1" ] || { no "prefixes: $1 was not built"; return; }
    bad=$($NM -g --defined-only "$1" | awk '$2 ~ /^[A-TV-Z]$/ { print $3 }' | grep -vE "$2" | sort -u)
    [ -z "$bad" ] && ok "prefixes: every global symbol of $1 is fx_-named$3" ||
        no "prefixes: $1 defines global symbols outside fx_$3:" $bad
}
pfx "$B/libfixel.a" '^fx(_|[0-9]+[a-z]*_)'
pfx "$B/libfixel-glut.a" '^(fx(_|[0-9]+[a-z]*_)|glu?t?[A-Z])' " (or a GL/GLU/GLUT name)"

# soname
sn=$(objdump -p "$so" 2>/dev/null | sed -n 's/^ *SONAME *//p')
[ "$sn" = "libfixel.so.$SOMAJOR" ] && ok "soname $sn" || no "soname is '$sn', wanted libfixel.so.$SOMAJOR"

# version
H=kernel-free-src/include/fixel/version.h
get() { sed -n "s/^#define $1 //p" $H | tr -d '"'; }
mj=$(get FX_VERSION_MAJOR); mn=$(get FX_VERSION_MINOR); pt=$(get FX_VERSION_PATCH); st=$(get FX_VERSION_STRING)
[ "$mj.$mn.$pt" = "$VERSION" ] && ok "version.h $mj.$mn.$pt = Makefile VERSION" ||
    no "version.h says $mj.$mn.$pt, the Makefile's VERSION is $VERSION"
[ "$st" = "$VERSION" ] && ok "FX_VERSION_STRING $st" || no "FX_VERSION_STRING is $st, wanted $VERSION"
[ "$mj" = "$SOMAJOR" ] && ok "soname major = FX_VERSION_MAJOR" || no "SOMAJOR $SOMAJOR differs from FX_VERSION_MAJOR $mj"

# spdx, guards: one line each in this total, their own lists above it
if sh tools/gen/spdx.sh --check > "$tmp/spdx"; then ok "$(tail -n 1 "$tmp/spdx")"; else grep FAIL "$tmp/spdx"; no "spdx lines missing (run tools/gen/spdx.sh)"; fi
if sh tools/gen/cxx-guards.sh --check > "$tmp/g"; then ok "$(tail -n 1 "$tmp/g")"; else grep FAIL "$tmp/g"; no "extern \"C\" guards missing (run tools/gen/cxx-guards.sh)"; fi
echo "abi: $P passed, $F failed"
[ $F -eq 0 ]
