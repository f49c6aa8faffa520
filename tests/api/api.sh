#!/bin/sh
# SPDX-License-Identifier: MIT
# The API reference (tools/gen/apiref.sh) is complete and current:
#   - every public function and object (tools/gen/exports.sh --names, what
#     libfixel.so exports) and every static inline function of the public
#     headers has a man page with a description;
#   - fixel(3) lists every one of them;
#   - the committed HTML (docs/api/) is what the headers give now;
#   - a declaration without a comment is caught (a copy of the headers with
#     one added), so the first check cannot pass by missing them all;
#   - the documented aliases are there (fx_fill_circle...).
# usage: tests/api/api.sh [CC]
CC=${1:-gcc}
cd "$(dirname "$0")/../.."
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "api: FAIL: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

sh tools/gen/apiref.sh --man "$tmp/man" || bad "apiref.sh --man failed"
sh tools/gen/exports.sh --names "$CC" > "$tmp/exported" || bad "exports.sh failed"
sh tools/gen/apiref.sh --undocumented > "$tmp/undoc"
# static inline functions: declared in the headers, not exported
grep -hE '^static inline [^(]*[ *](fx|gl)[A-Za-z0-9_]*\(' kernel-free-src/include/fixel/*.h boards/include/fixel/*.h |
    sed -E 's/\(.*//; s/.*[ *]//' | sort -u > "$tmp/inline"
sort -u "$tmp/exported" "$tmp/inline" > "$tmp/public"
[ "$(wc -l < "$tmp/public")" -gt 500 ] && ok || bad "only $(wc -l < "$tmp/public") public names found"

# pages with a description: their names
grep -l '^\.SH DESCRIPTION' "$tmp"/man/man3/*.3 | sed 's|.*/||; s|\.3$||' | sort > "$tmp/paged"
missing=$(comm -23 "$tmp/public" "$tmp/paged" | tr '\n' ' ')
[ -z "$missing" ] && ok || bad "public names without a man page: $missing"
nocomment=$(comm -12 "$tmp/public" "$tmp/undoc" | tr '\n' ' ')
[ -z "$nocomment" ] && ok || bad "public names without a comment above them in their header: $nocomment"

sed -n 's/^\.B \(f[x_A-Za-z0-9]*\)$/\1/p; s/^\.B \(gl[A-Za-z0-9_]*\)$/\1/p' "$tmp/man/man3/fixel.3" | sort -u > "$tmp/listed"
notlisted=$(comm -23 "$tmp/public" "$tmp/listed" | tr '\n' ' ')
[ -z "$notlisted" ] && ok || bad "fixel(3) does not list: $notlisted"

# the pages render (man-db or groff present: both are in the test set)
if command -v man >/dev/null 2>&1; then
    out=$(MANWIDTH=80 man -l "$tmp/man/man3/fx_line.3" 2>&1)
    case $(echo "$out" | tr -s ' ') in *"fx_line - "*"#include <fixel/line.h>"*) ok ;; *) bad "man -l fx_line.3 renders: $out" ;; esac
    out=$(MANWIDTH=80 man -l "$tmp/man/man3/fixel.3" 2>&1 | grep -c '<fixel/')
    [ "$out" -ge 40 ] && ok || bad "man -l fixel.3 shows $out headers"
else
    echo "api: man is not installed: rendering not checked"
fi

for a in fx_fill_circle:fx_disc fx_fill_polygon:fx_fill_poly fx_fill_triangle:fx_fill_tri fx_put_pixel:fx_plot; do
    n=${a%%:*} to=${a#*:}
    grep -q "Alias of $to" "$tmp/man/man3/$n.3" 2>/dev/null && ok || bad "$n is not documented as the alias of $to"
done

sh tools/gen/apiref.sh --html "$tmp/html"
if diff -r "$tmp/html" docs/api > "$tmp/diff"; then ok
else bad "docs/api is not current: sh tools/gen/apiref.sh --html docs/api"; head -20 "$tmp/diff"; fi

# the check itself: a new function without a comment is reported
mkdir -p "$tmp/tree/kernel-free-src/include" "$tmp/tree/boards/include"
cp -r kernel-free-src/include/fixel "$tmp/tree/kernel-free-src/include/"
cp -r boards/include/fixel "$tmp/tree/boards/include/"
cp Makefile "$tmp/tree/"
printf '\nvoid fx_api_suite_probe(int x);\n' >> "$tmp/tree/kernel-free-src/include/fixel/line.h"
u=$(APIREF_ROOT="$tmp/tree" sh tools/gen/apiref.sh --undocumented)
[ "$u" = "fx_api_suite_probe" ] && ok || bad "an undocumented declaration is not caught (got: $u)"

echo "api: $pass passed, $fail failed"
[ $fail -eq 0 ]
