#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk with output sections (issue #25: one screen section per
# display, docs/kiosk.md "Several screens"): one process, two memory
# displays. Each screen's frame must be, pixel for pixel, what a kiosk with
# only that screen's section draws from the same data (so each shows its own
# widgets, title, grid and size, and nothing of the other's), headless and
# live; bad sections are refused as FILE:LINE:COL; the keys have ranges in
# --keys. A config without sections is the rest of tests/kiosk.
# Usage: screens.sh BIN OUTDIR
bin=$(readlink -f "$1"); out=$2
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
here=$(cd "$(dirname "$0")" && pwd)
img() { python3 "$here/../mqtt/img.py" "$@"; }
command -v python3 >/dev/null 2>&1 || { echo "kiosk-screens: python3 missing (make deps)"; echo "kiosk-screens: 0 passed, 1 failed"; exit 1; }
rm -rf "$out"; mkdir -p "$out"; out=$(cd "$out" && pwd)

# the two screens' sections, and each alone as a one-screen config
left='title Left
grid 2x1
widget number temp col=0 row=0 decimals=1 unit=C
widget text state col=1 row=0'
right='title Right
grid 1x2
widget bar temp col=0 row=0 min=0 max=40
widget number hum col=0 row=1 decimals=2'
printf 'stale 600\noutput HDMI-A-1 size=320x240\n%s\noutput HDMI-A-2 size=240x320 rotation=90\n%s\n' "$left" "$right" > "$out/two.conf"
printf 'stale 600\nsize 320x240\n%s\n' "$left" > "$out/left.conf"
printf 'stale 600\nsize 320x240\n%s\n' "$right" > "$out/right.conf"
data='temp=21.5
state=ok
hum=45.25'

# headless: both frames from one run
printf '%s\n' "$data" | "$bin" --headless --out "$out/two" --last "$out/two.conf" > "$out/two.txt" 2>&1 && ok || bad "two screens refused: $(cat "$out/two.txt")"
grep -q "3 lines, 0 bad, 0 ignored" "$out/two.txt" && ok || bad "every line has a widget on one of the screens: $(cat "$out/two.txt")"
for s in left right; do
    printf '%s\n' "$data" | "$bin" --headless --out "$out/$s" --last "$out/$s.conf" >/dev/null 2>&1
done
# hum has no widget on the left screen alone: "ignored 1" is not on its
# status line, so the pictures agree
[ -s "$out/two/last-HDMI-A-1.png" ] && [ -s "$out/two/last-HDMI-A-2.png" ] && ok || bad "not one file per screen: $(ls "$out/two")"
img same "$out/two/last-HDMI-A-1.png" "$out/left/last.png" 0 0 320 240 && ok || bad "HDMI-A-1 differs from its section drawn alone"
img same "$out/two/last-HDMI-A-2.png" "$out/right/last.png" 0 0 320 240 && ok || bad "HDMI-A-2 (rotation 90: 320x240 logical) differs from its section drawn alone"
img same "$out/left/last.png" "$out/right/last.png" 0 0 320 240 && bad "the two sections look the same: the comparisons prove nothing" || ok
# the value reaches both screens: temp on the left as digits, on the right as a bar
printf 'temp=30\n' | "$bin" --headless --out "$out/two30" --last "$out/two.conf" >/dev/null 2>&1
img same "$out/two30/last-HDMI-A-2.png" "$out/two/last-HDMI-A-2.png" 0 0 320 240 && bad "HDMI-A-2's bar did not move with temp" || ok

# live: one process, its main loop drawing both displays (FIXEL_BACKEND=memory)
printf '%s\n' "$data" > "$out/live.data"
mkdir -p "$out/live"
FIXEL_BACKEND=memory "$bin" --data "$out/live.data" --out "$out/live" "$out/two.conf" </dev/null >"$out/live.log" 2>&1 &
kp=$!
for s in left right; do img ppm "$out/$s/last.png" "$out/$s/last.ppm"; done
shows() { [ -s "$out/live/live-$1.ppm" ] && img same "$out/live/live-$1.ppm" "$out/$2/last.ppm" 0 0 320 226; }
i=0; while [ $i -lt 100 ] && ! { shows HDMI-A-1 left && shows HDMI-A-2 right; }; do sleep 0.1; i=$((i + 1)); done
# the widgets only: live status lines count differently ("ignored" is not shown, but lines are read as they come)
shows HDMI-A-1 left && ok || bad "live HDMI-A-1 does not show its section: $(cat "$out/live.log")"
shows HDMI-A-2 right && ok || bad "live HDMI-A-2 does not show its section: $(cat "$out/live.log")"
kill -TERM $kp; wait $kp; rc=$?
[ $rc = 0 ] && ok || bad "the live kiosk with two screens exited $rc on SIGTERM"

# errors: FILE:LINE:COL and the reason
cfgerr() { # cfgerr NAME CONFIG-TEXT EXPECTED
    printf "$2" > "$out/$1.conf"
    if "$bin" --headless "$out/$1.conf" </dev/null >/dev/null 2>"$out/$1.txt"; then bad "$1: config accepted"
    elif grep -q "$1.conf:$3" "$out/$1.txt"; then ok; else bad "$1: wanted $1.conf:$3, got: $(cat "$out/$1.txt")"; fi
}
cfgerr dup 'output HDMI-A-1\nwidget clock col=0 row=0\noutput DSI-1\noutput HDMI-A-1\n' "4:8: output named twice (first on line 1)"
cfgerr key 'output HDMI-A-1 rotation=90 colour=red\n' "1:29: unknown output key (rotation size)"
cfgerr rot 'output HDMI-A-1 rotation=45\n' "1:17: rotation: 0, 90, 180 or 270"
cfgerr rot2 'output HDMI-A-1 rotation=360\n' "1:17: rotation: 0, 90, 180 or 270"
cfgerr size 'output HDMI-A-1 size=8x8\n' "1:17: size=8x8: expected 16..8192 each"
cfgerr name 'output HDMI/A\n' "1:8: output: a connector name"
cfgerr noname 'output\n' "1:1: output needs a connector name"
cfgerr five 'output A\noutput B\noutput C\noutput D\noutput E\n' "5:8: more than 4 outputs"
cfgerr after 'widget clock col=0 row=0\noutput HDMI-A-1\n' "2:1: output after widgets"
cfgerr wide 'output HDMI-A-1\nmqtt host=h\n' "2:1: this directive is for the whole kiosk"
cfgerr pages 'page one\noutput HDMI-A-1\n' "2:1: output sections and pages (page, carousel, touch) do not go together yet"
cfgerr pages2 'output HDMI-A-1\ncarousel dwell=5\n' "2:1: output sections and pages"
cfgerr button 'output A\nwidget clock col=0 row=0\noutput B\nwidget button go page=next\n' "4:1: button widgets go on the first output"
# a widget inside its own section's grid (2x1 here), not the other's (1x2)
printf 'output A\ngrid 2x1\nwidget clock col=1 row=0\noutput B\ngrid 1x2\nwidget clock col=1 row=0\n' > "$out/grid.conf"
"$bin" --headless "$out/grid.conf" </dev/null >/dev/null 2>"$out/grid.txt" && bad "a widget outside its section's grid was accepted" ||
    { grep -q "grid.conf:6:1: a widget lies outside the grid" "$out/grid.txt" && ok || bad "grid: $(cat "$out/grid.txt")"; }
"$bin" --keys | grep -q "^output *rotation *word .*0|90|180|270" && ok || bad "--keys lacks output rotation"
"$bin" --keys | grep -q "^output *size *AxB *16..8192" && ok || bad "--keys lacks output size"
echo "kiosk-screens: $P passed, $F failed"
[ $F -eq 0 ]
