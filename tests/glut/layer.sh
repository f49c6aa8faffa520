#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel's GLUT layer alone (layer.c): glutGet, modifiers, stroke and bitmap
# text metrics, glGet round trips, and how glutMainLoop ends after
# glutLeaveMainLoop (freeglut's documented behaviour). Headless.
# usage: layer.sh BUILD   (needs BUILD/libfixel-glut.a); "glut-layer: N passed, N failed"
B=${1:-build}
out=$B/glut/layer
mkdir -p "$out"
P=0 F=0
if ! ${CC:-gcc} -std=gnu11 -O2 -Wall -Wextra -Werror -I boards/glut/include tests/glut/layer.c \
        "$B/libfixel-glut.a" "$B/libfixel.a" ${GLUT_FIXEL_LIBS:-} -lm -o "$out/layer" 2> "$out/build.log"; then
    cat "$out/build.log"; echo "glut-layer: 0 passed, 1 failed"; exit 1
fi
run() { FIXEL_BACKEND=memory "$@" > "$out/run.log" 2>&1; echo $? > "$out/rc"; }
judge() { # name, condition
    if eval "$2"; then P=$((P + 1)); echo "PASS glut-layer $1"; else F=$((F + 1)); echo "FAIL glut-layer $1"; cat "$out/run.log"; fi
}
run env FIXEL_GLUT_FRAMES=1 "$out/layer" api
n_ok=$(grep -c '^ok ' "$out/run.log"); n_fail=$(grep -c '^FAIL ' "$out/run.log")
grep '^FAIL ' "$out/run.log"
judge "api ($n_ok checks)" '[ "$(cat $out/rc)" = 0 ] && [ "$n_fail" = 0 ] && [ "$n_ok" -ge 12 ]'
# FIXEL_GLUT_* through the one table (boards/env/env_table.c): a frame count
# past its range stops the program (status 2) naming the range instead of
# running a scripted test forever; a bad switch is said and ignored.
run env FIXEL_GLUT_FRAMES=9223372036854775808 "$out/layer" api
judge "frames-out-of-range" '[ "$(cat $out/rc)" = 2 ] && grep -q "FIXEL_GLUT_FRAMES=9223372036854775808 ignored (a whole number from 0 to 1000000000)" "$out/run.log"'
run env FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_FULLSCREEN=yes "$out/layer" api
judge "switch-bad-word" '[ "$(cat $out/rc)" = 0 ] && grep -q "FIXEL_GLUT_FULLSCREEN=yes ignored (0 or 1)" "$out/run.log"'
run "$out/layer" leave-return
judge "leave-returns" '[ "$(cat $out/rc)" = 7 ] && grep -qx "returned frames=3 action=2" "$out/run.log"'
run "$out/layer" leave-exit
judge "leave-exits" '[ "$(cat $out/rc)" = 0 ] && ! grep -q returned "$out/run.log"'
# Keys alone (raw evdev: 127 is the Menu key, 108 Down, 106 Right, 28
# Enter): Menu, Down, Down, Enter picks Green; Menu, Down x3, Right, Down,
# Down, Enter picks Large in the submenu; Menu twice opens and closes, and
# F5 then reaches the program (the Menu key itself never does).
cat > "$out/menu-keys.txt" <<'R'
frame 1: evdev keyboard 1 127 1
frame 1: evdev keyboard 1 127 0
frame 1: evdev keyboard 1 108 1
frame 1: evdev keyboard 1 108 1
frame 1: evdev keyboard 1 28 1
frame 2: evdev keyboard 1 127 1
frame 2: evdev keyboard 1 108 1
frame 2: evdev keyboard 1 108 1
frame 2: evdev keyboard 1 108 1
frame 2: evdev keyboard 1 106 1
frame 2: evdev keyboard 1 108 1
frame 2: evdev keyboard 1 108 1
frame 2: evdev keyboard 1 28 1
frame 3: evdev keyboard 1 127 1
frame 3: evdev keyboard 1 127 1
frame 3: evdev keyboard 1 63 1
R
run env FIXEL_GLUT_FRAMES=4 FIXEL_GLUT_REPLAY="$out/menu-keys.txt" "$out/layer" menu-keys
judge "menu-keys" '[ "$(cat $out/rc)" = 0 ] && [ "$(grep -E "^(menu|special)" "$out/run.log" | tr "\n" " ")" = "menu 2 menu 11 special 5 0 0 " ]'
echo "glut-layer: $P passed, $F failed"
[ $F -eq 0 ]
