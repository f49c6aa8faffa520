#!/bin/sh
# SPDX-License-Identifier: MIT
# Rewrites the KEYS section of docs/man/fixel-kiosk.1 (between its
# BEGIN KEYS / END KEYS comments) from `fixel-kiosk --keys`, the key table:
# every directive, widget key and data value with its type and range
# (tests/corners/kiosk-corners.sh checks the page against the table).
# usage: tools/gen/man-kiosk.sh [FIXEL_KIOSK] [PAGE]
set -eu
KIOSK=${1:-build/bin/fixel-kiosk}
PAGE=${2:-docs/man/fixel-kiosk.1}
tmp=$PAGE.tmp
{
    sed '/^\.\\" BEGIN KEYS/q' "$PAGE"
    printf '.SH KEYS\nEvery directive, widget key and data value with its type and range, as\n.B fixel\\-kiosk \\-\\-keys\nprints them (values outside the range are refused, naming it):\n'
    "$KIOSK" --keys | while read -r scope name type range rest; do
        range=$(printf '%s' "$range" | sed -e 's/-/\\-/g')
        rest=$(printf '%s' "$rest" | sed -e 's/\\/\\e/g' -e 's/-/\\-/g' -e 's/^ *//')
        [ "$range" = "\\-" ] && range=""
        case "$range" in at) n=${rest#most }; n=${n%% *}; range="at most $n bytes"; rest=${rest#most "$n" bytes}; rest=${rest# }; rest=${rest# };; esac
        printf '.TP\n.BR "%s" " %s"\n%s%s%s\n' "$name" "($scope, $type)" "${range:+$range: }" "$rest" ""
    done
    sed -n '/^\.\\" END KEYS/,$p' "$PAGE"
} > "$tmp"
mv "$tmp" "$PAGE"
