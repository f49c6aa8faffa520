#!/bin/sh
# SPDX-License-Identifier: MIT
# The library's face (issue #20, docs/ABI.md):
#   exports   nm -D --defined-only of libfixel.so equals, name for name, the
#             functions and objects the public headers declare (either way)
#   soname    libfixel.so.$SOMAJOR, and SOMAJOR is FX_VERSION_MAJOR
#   version   FX_VERSION_MAJOR/MINOR/PATCH/STRING agree with the Makefile's VERSION
#   spdx      every source file has its SPDX-License-Identifier line
#   guards    every public header has its extern "C" guard
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
