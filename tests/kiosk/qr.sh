#!/bin/sh
# SPDX-License-Identifier: MIT
# The kiosk's qr widget read back by a real decoder (zbar-tools' zbarimg,
# issue #41): each frame drawn headless must decode to exactly the strings
# it shows (a data-driven code whose value changes between frames, a
# configured one), and the frames must match tests/golden/kiosk/qr-N.png.
# An unreadable code fails (zbarimg finds fewer symbols).
# Usage: qr.sh BIN OUTDIR [--update]
bin=$1; out=$2; update=$3
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
rm -rf "$out"; mkdir -p "$out"
if ! command -v zbarimg >/dev/null 2>&1; then
    echo "qr: zbarimg is missing (apt-get install zbar-tools)"; echo "qr: 0 passed, 1 failed"; exit 1
fi
"$bin" --headless --frames 2 --out "$out" --data tests/kiosk/qr/stream.txt tests/kiosk/qr/qr.conf >/dev/null 2>&1 \
    && ok || bad "kiosk run exited $?"
check() { # FRAME EXPECTED-LINES
    got=$(zbarimg -q --raw "$out/frame-000$1.png" 2>/dev/null | sort)
    want=$(printf '%s\n' "$2" | sort)
    if [ "$got" = "$want" ]; then ok; else bad "frame $1 decodes to '$got', not '$want'"; fi
}
check 0 "https://example.org/fault?id=42
fixel kiosk 7"
check 1 "https://example.org/fault?id=43&site=north
fixel kiosk 7"
for n in 0 1; do
    g=tests/golden/kiosk/qr-$n.png
    if [ "$update" = --update ]; then cp "$out/frame-000$n.png" "$g"; fi
    if cmp -s "$g" "$out/frame-000$n.png"; then ok; else bad "frame-000$n.png differs from $g"; fi
done
echo "qr: $P passed, $F failed"
[ $F -eq 0 ]
