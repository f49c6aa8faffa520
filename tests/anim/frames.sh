#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-draw --frames: an animated script rendered to numbered PNGs, frame k
# at the clock k/FPS; each frame is the picture the script draws with
# 'time k/FPS' (the host's clock wins over the script's 'time'); the
# frames move; a bad -o pattern or option is refused before anything runs.
draw=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
P=0; F=0
ok() { P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
body='size 64 48
clear #000000
key m 0 4 4
key m 1 40 30
interp m linear
color #FFFFFF
tween m translate
fillrect 0 0 8 8
bounce 0 0 63 47 50 4 -10 0 200 0.7 3'
printf 'time 3\n%s\n' "$body" > "$out/anim.fxs"
if "$draw" --frames 6 --fps 5 -o "$out/frame-%04d.png" "$out/anim.fxs"; then ok; else bad "--frames failed"; fi
n=$(ls "$out" | grep -c '^frame-000[0-5]\.png$')
if [ "$n" = 6 ] && [ ! -e "$out/frame-0006.png" ]; then ok; else bad "expected frame-0000..0005.png, got $n"; fi
for k in 0 1 2 3 4 5; do
    printf 'time 0.%d\n%s\n' $((k * 2)) "$body" > "$out/one.fxs"
    [ $k = 5 ] && printf 'time 1\n%s\n' "$body" > "$out/one.fxs"
    if "$draw" -o "$out/one-$k.png" "$out/one.fxs" && cmp -s "$out/one-$k.png" "$out/frame-000$k.png"; then ok
    else bad "frame $k differs from the script drawn at time $k/5"; fi
done
if ! cmp -s "$out/frame-0000.png" "$out/frame-0001.png" && ! cmp -s "$out/frame-0004.png" "$out/frame-0005.png"
then ok; else bad "the frames do not move"; fi
for o in "$out/x.png" "$out/%s-%d.png" "$out/%d-%d.png" "$out/%x.png"; do
    if ! "$draw" --frames 2 -o "$o" "$out/anim.fxs" 2> "$out/err.txt" && grep -q 'needs -o with one %d' "$out/err.txt"
    then ok; else bad "-o $o accepted"; fi
done
for a in "--frames 0" "--frames 100001" "--fps 0" "--frames x"; do
    # shellcheck disable=SC2086
    if ! "$draw" $a -o "$out/f%d.png" "$out/anim.fxs" 2> "$out/err.txt" && grep -q "bad --f" "$out/err.txt"
    then ok; else bad "$a accepted"; fi
done
printf 'time 0\nkey m 0 1\ntween m translate\n' > "$out/broken.fxs"
if ! "$draw" --frames 2 -o "$out/b%d.png" "$out/broken.fxs" 2> "$out/err.txt" &&
    grep -q "broken.fxs:3:.*needs 2 (frame 0)" "$out/err.txt"; then ok; else bad "error not reported with its frame"; cat "$out/err.txt"; fi
echo "anim-frames: $P passed, $F failed"
[ $F -eq 0 ]
