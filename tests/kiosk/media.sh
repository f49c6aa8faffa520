#!/bin/sh
# SPDX-License-Identifier: MIT
# The kiosk's qr widget read back by a real decoder (zbar-tools' zbarimg,
# issue #41): each frame drawn headless must decode to exactly the strings
# it shows (a data-driven code whose value changes between frames, a
# configured one), and the frames must match tests/golden/kiosk/qr-N.png.
# An unreadable code fails (zbarimg finds fewer symbols).
# Then an animated GIF (tests/kiosk/img/anim.gif: red 1 s, green 2 s, blue
# 0.5 s, looping forever) in an image widget, one frame every 500 ms: each
# frame shows the GIF frame its delays say.
# Usage: media.sh BIN OUTDIR [--update]
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
# the GIF: frames 0-1 red, 2-5 green, 6 blue, 7-8 red again (looped)
mkdir -p "$out/anim"
"$bin" --headless --frames 9 --out "$out/anim" --data tests/kiosk/qr/anim.txt tests/kiosk/qr/anim.conf >/dev/null 2>&1 \
    && ok || bad "gif run exited $?"
sum() { md5sum < "$out/anim/frame-000$1.png" | cut -c1-32; }
r=$(sum 0); g=$(sum 2); b=$(sum 6)
[ "$r" != "$g" ] && [ "$g" != "$b" ] && [ "$r" != "$b" ] && ok || bad "gif: red, green and blue frames not distinct"
for n in 1 7 8; do [ "$(sum $n)" = "$r" ] && ok || bad "gif: frame $n is not the red GIF frame"; done
for n in 3 4 5; do [ "$(sum $n)" = "$g" ] && ok || bad "gif: frame $n is not the green GIF frame"; done
for n in 0 2 6; do
    g=tests/golden/kiosk/gif-$n.png
    if [ "$update" = --update ]; then cp "$out/anim/frame-000$n.png" "$g"; fi
    if cmp -s "$g" "$out/anim/frame-000$n.png"; then ok; else bad "gif frame $n differs from $g"; fi
done
echo "media: $P passed, $F failed"
[ $F -eq 0 ]
