#!/bin/sh
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
echo "kiosk: $P passed, $F failed"
[ "$F" -eq 0 ]
