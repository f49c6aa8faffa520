#!/bin/sh
# SPDX-License-Identifier: MIT
# examples/ as a user runs them, and the headless driving of fixel/app.h
# (FIXEL_REPLAY, FIXEL_FRAMES, FIXEL_OUT) through examples/polyline.
# usage: [NO_VALGRIND=1] examples.sh BUILD_DIR WORK_DIR   (BUILD_DIR holds examples/ and
# tests/imgcmp; NO_VALGRIND for a sanitized build, which valgrind cannot run)
B=${1:-build}; W=${2:-$B/tests/examples}
case $B in /*) ;; *) B=$(pwd)/$B ;; esac
POLY=$B/examples/polyline; HELLO=$B/examples/hello; CMP=$B/tests/imgcmp
REPLAY=$(pwd)/examples/polyline.replay; GOLD=$(pwd)/tests/boards/polyline.png
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
rm -rf "$W"; mkdir -p "$W"
run() { # run NAME ENV... : polyline headless; stdout+stderr in $W/NAME.log, status in $rc
    n=$1; shift
    env FIXEL_BACKEND=memory "$@" "$POLY" > "$W/$n.log" 2>&1; rc=$?
}

# hello: writes hello.png and frees everything (valgrind clean when valgrind is there)
if (cd "$W" && "$HELLO") && [ -s "$W/hello.png" ]; then ok; else bad "hello: no hello.png"; fi
if [ -z "$NO_VALGRIND" ] && command -v valgrind > /dev/null 2>&1; then
    if (cd "$W" && valgrind -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=all \
            "$HELLO") > "$W/valgrind.log" 2>&1; then ok; else bad "hello under valgrind:"; cat "$W/valgrind.log"; fi
else
    echo "skip: hello under valgrind (no valgrind)"
fi

# the replay's last frame is the golden picture
run golden FIXEL_REPLAY="$REPLAY" FIXEL_OUT="$W/last.png"
if [ $rc = 0 ] && "$CMP" "$W/last.png" "$GOLD"; then ok; else bad "polyline replay: exit $rc, last frame vs $GOLD"; cat "$W/golden.log"; fi
# PPM output, numbered frames: the first of six, the sixth equal to the golden one
run numbered FIXEL_REPLAY="$REPLAY" FIXEL_OUT="$W/f-%03d.ppm"
if [ $rc = 0 ] && [ "$(ls "$W"/f-*.ppm | wc -l)" = 6 ] && "$CMP" "$W/f-006.ppm" "$GOLD"; then ok
else bad "numbered frames: exit $rc, $(ls "$W"/f-*.ppm 2>/dev/null | wc -l) files"; fi
# FIXEL_FRAMES stops the run (with the replay, and without one)
run limit FIXEL_REPLAY="$REPLAY" FIXEL_FRAMES=2 FIXEL_OUT="$W/l-%d.png"
if [ $rc = 0 ] && [ -f "$W/l-2.png" ] && [ ! -f "$W/l-3.png" ]; then ok; else bad "FIXEL_FRAMES=2: exit $rc"; fi
run one FIXEL_FRAMES=1 FIXEL_OUT="$W/one.png"
if [ $rc = 0 ] && [ -f "$W/one.png" ]; then ok; else bad "FIXEL_FRAMES=1 without a replay: exit $rc"; fi
# q in the replay quits before the rest of it
printf 'device 0 keyboard\nframe\nev 0 KEY KEY_Q 1\nframe\nevent mouse left down 10 10\nframe\n' > "$W/quit.replay"
run quit FIXEL_REPLAY="$W/quit.replay" FIXEL_OUT="$W/q-%d.png"
if [ $rc = 0 ] && [ -f "$W/q-1.png" ] && [ ! -f "$W/q-2.png" ]; then ok; else bad "q in the replay: exit $rc"; fi

# mistakes are reported and fail the run
expect_fail() { # NAME MESSAGE-PATTERN ENV...
    n=$1; pat=$2; shift 2
    run "$n" "$@"
    if [ $rc != 0 ] && grep -q -- "$pat" "$W/$n.log"; then ok
    else bad "$n: exit $rc, want non-zero and '$pat' in:"; cat "$W/$n.log"; fi
}
printf 'device 0 mouse\nev 0 REL REL_X 5\nsyn 0\nfrobnicate 3\n' > "$W/bad.replay"
expect_fail bad-line "bad.replay:4: cannot use 'frobnicate 3'" FIXEL_REPLAY="$W/bad.replay"
printf 'ev 2 KEY KEY_A 1\n' > "$W/nodev.replay"
expect_fail undeclared "nodev.replay:1" FIXEL_REPLAY="$W/nodev.replay"
printf 'screen 800 480\n' > "$W/screen.replay"
expect_fail screen "the display is 640x480" FIXEL_REPLAY="$W/screen.replay"
expect_fail missing "cannot open $W/none.replay" FIXEL_REPLAY="$W/none.replay"
expect_fail frames-word "FIXEL_FRAMES=abc" FIXEL_FRAMES=abc
expect_fail frames-zero "FIXEL_FRAMES=0" FIXEL_FRAMES=0
expect_fail pattern "at most one %d" FIXEL_OUT="$W/%s-%d.png" FIXEL_FRAMES=1
expect_fail unwritable "cannot write $W/no/such/dir/x.png" FIXEL_OUT="$W/no/such/dir/x.png" FIXEL_FRAMES=1

# the environment's other mistakes and non-events (fixel/env.h)
run log-level FIXEL_LOG=verbose FIXEL_FRAMES=1
if [ $rc = 0 ] && grep -q "FIXEL_LOG=verbose ignored" "$W/log-level.log"; then ok
else bad "unknown FIXEL_LOG level not reported: exit $rc"; cat "$W/log-level.log"; fi
# a missing input directory is no news: no line at the default level (the
# app reads /dev/input; FIXEL_REPLAY would skip it, so none here)
if [ -d /dev/input ]; then echo "skip: /dev/input exists here"
elif run noinput FIXEL_FRAMES=1; [ $rc = 0 ] && ! grep -q "/dev/input" "$W/noinput.log"; then ok
else bad "missing /dev/input logged at info level:"; cat "$W/noinput.log"; fi

echo "examples: $P passed, $F failed"
[ $F = 0 ]
