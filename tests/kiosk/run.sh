#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk end to end: a scripted stream (garbage lines, a source that
# stalls) drawn headless; chosen frames must match tests/golden/kiosk, frames
# drawn from damage only must equal full redraws, and garbage is never fatal.
# Usage: run.sh BIN OUTDIR [--update]
bin=$1; out=$2; update=$3
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
rm -rf "$out"; mkdir -p "$out/damage" "$out/full"
conf=examples/kiosk-basic.conf
stream=tests/kiosk/stream.txt
log=$("$bin" --headless --frames 12 --out "$out/damage" --data "$stream" $conf 2>/dev/null) || bad "damage run exited $?"
"$bin" --headless --frames 12 --full --out "$out/full" --data "$stream" $conf >/dev/null 2>&1 || bad "full run exited $?"
# the stream holds 6 malformed lines: counted, not fatal
case "$log" in *"6 bad"*) ok ;; *) bad "expected 6 bad lines, got: $log" ;; esac
for f in "$out"/full/*.png; do
    n=$(basename "$f")
    if cmp -s "$f" "$out/damage/$n"; then ok; else bad "damage-only frame $n differs from a full redraw"; fi
done
# golden frames: first data, after the garbage, hum stale at the end
for n in 0000 0004 0011; do
    g=tests/golden/kiosk/frame-$n.png
    if [ "$update" = "--update" ]; then cp "$out/damage/frame-$n.png" "$g"; fi
    if cmp -s "$g" "$out/damage/frame-$n.png"; then ok; else bad "frame-$n.png differs from $g"; fi
done
# a stream of nothing but garbage and a config error both behave
head -c 20000 /dev/urandom 2>/dev/null | "$bin" --headless --frames 2 --data - $conf >/dev/null 2>&1 && ok || bad "random bytes were fatal"
printf 'grid 2x2\nwidget gauge a col=5\n' > "$out/bad.conf"
if "$bin" --headless --data /dev/null "$out/bad.conf" 2>"$out/err.txt"; then bad "bad config accepted"
elif grep -q "outside the grid" "$out/err.txt"; then ok; else bad "bad config message: $(cat "$out/err.txt")"; fi
"$bin" --help | grep -q -- "--headless" && ok || bad "--help"

# every widget type (examples/kiosk-all.conf): heat map rows and whole maps,
# CSV with a header, an image that turns corrupt, missing, PPM, absurdly
# large and back, garbage of each new kind, a heat map that goes stale
mkdir -p "$out/all-damage" "$out/all-full"
conf=examples/kiosk-all.conf
stream=tests/kiosk/stream-all.txt
log=$("$bin" --headless --frames 12 --out "$out/all-damage" --data "$stream" $conf 2>/dev/null) || bad "all: damage run exited $?"
"$bin" --headless --frames 12 --full --out "$out/all-full" --data "$stream" $conf >/dev/null 2>&1 || bad "all: full run exited $?"
# 7 malformed lines (heat count, heat row, heat value, row on a scalar, CSV
# field, garbage, overlong); corrupt + missing + huge images
case "$log" in *"40 lines, 7 bad, 0 ignored, 3 image errors"*) ok ;; *) bad "all: expected 40 lines, 7 bad, 3 image errors, got: $log" ;; esac
for f in "$out"/all-full/*.png; do
    n=$(basename "$f")
    if cmp -s "$f" "$out/all-damage/$n"; then ok; else bad "all: damage-only frame $n differs from a full redraw"; fi
done
# golden: partial map + PNG; garbage + corrupt image; PPM scaled; stale map
for n in 0000 0002 0004 0011; do
    g=tests/golden/kiosk/all-$n.png
    if [ "$update" = "--update" ]; then cp "$out/all-damage/frame-$n.png" "$g"; fi
    if cmp -s "$g" "$out/all-damage/frame-$n.png"; then ok; else bad "all: frame-$n.png differs from $g"; fi
done
# the placeholders differ from each other and from a loaded image
if cmp -s "$out/all-damage/frame-0002.png" "$out/all-damage/frame-0003.png"; then bad "corrupt and missing look alike"; else ok; fi
# frames 0 and 6 show the same PNG (named again by a data line): the camera
# cell must be identical in both, so compare against a run that stops there
"$bin" --headless --frames 7 --last --out "$out" --data "$stream" $conf >/dev/null 2>&1 || bad "frame 6 run"
if cmp -s "$out/last.png" "$out/all-damage/frame-0006.png"; then ok; else bad "--last differs from frame 6"; fi

# image files that change under a running kiosk are reloaded (device, inode,
# size, mtime): replaced by rename, then rewritten in place with garbage
d="$out/live"; mkdir -p "$d/f"
cp examples/kiosk-logo.png "$d/img"
printf 'size 160x120\ngrid 1x1\nwidget image cam path=%s filter=nearest\n' "$d/img" > "$d/conf"
mkfifo "$d/fifo"
"$bin" --headless --frames 3 --out "$d/f" --data "$d/fifo" "$d/conf" > "$d/log" 2>&1 &
kpid=$!
exec 3>"$d/fifo"
wait_frame() { i=0; while [ ! -f "$d/f/frame-$1.png" ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i + 1)); done; }
printf 'x=1\n@frame 1000\n' >&3; wait_frame 0000
cp tests/kiosk/img/checker.ppm "$d/img.new"; mv "$d/img.new" "$d/img"
printf '@frame 1000\n' >&3; wait_frame 0001
printf 'garbage\n' > "$d/img"
printf '@frame 1000\n' >&3
exec 3>&-
wait $kpid || bad "live image run exited $?"
case "$(cat "$d/log")" in *"1 image errors"*) ok ;; *) bad "live: expected 1 image error: $(cat "$d/log")" ;; esac
# the replaced file shows exactly what a kiosk started on it shows
cp tests/kiosk/img/checker.ppm "$d/img"
printf 'x=1\n' | "$bin" --headless --frames 1 --last --out "$d" --data - "$d/conf" >/dev/null 2>&1
if cmp -s "$d/last.png" "$d/f/frame-0001.png"; then ok; else bad "live: reloaded image differs from a fresh start"; fi
if cmp -s "$d/f/frame-0000.png" "$d/f/frame-0001.png"; then bad "live: image not reloaded"; else ok; fi
if cmp -s "$d/f/frame-0001.png" "$d/f/frame-0002.png"; then bad "live: corrupt rewrite not noticed"; else ok; fi
# hostile image files: a PPM whose header claims 9999999 x 9999999 pixels,
# one cut short, a FIFO and a directory: each a counted error, none fatal,
# none blocking (the FIFO has no writer)
mkfifo "$d/pipe.png"
for img in tests/kiosk/img/huge.ppm tests/kiosk/img/short.ppm "$d/pipe.png" tests/kiosk; do
    printf 'size 160x120\ngrid 1x1\nwidget image cam path=%s\n' "$img" > "$d/h.conf"
    r=$(timeout 60 "$bin" --headless --frames 2 --data /dev/null "$d/h.conf" 2>/dev/null)
    case "$r" in *"0 bad, 0 ignored, 1 image errors"*) ok ;; *) bad "image $img: $r" ;; esac
done
echo "kiosk: $P passed, $F failed"
[ "$F" -eq 0 ]
