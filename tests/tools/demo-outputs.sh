#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-demo --display OUTPUT=PAGE on two memory displays (FIXEL_BACKEND=
# memory, FIXEL_REPLAY, FIXEL_OUT): each output's picture is its page as
# the headless renderer draws it; a touchscreen bound to the second output
# (FIXEL_INPUT_BIND) turns that output's page and an unbound one the
# first's; bad --display arguments are refused. The real-output case is
# the rig's (tests/kernel/guest/bind.c).
# usage: demo-outputs.sh BIN_DIR TESTS_DIR WORK_DIR
B=${1:-build/bin}; T=${2:-build/tests}; W=${3:-build/tests/demo-outputs}
D=$B/fixel-demo
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
rm -rf "$W"; mkdir -p "$W"
same_pic() { # NAME A B
    if r=$("$T/imgcmp" "$2" "$3"); then ok; else bad "$1: $r"; fi
}
run() { # STATUS NAME ARGS...
    st=$1; n=$2; shift 2
    env FIXEL_BACKEND=memory FIXEL_LOG=error "$@" > "$W/$n.out" 2> "$W/$n.err" < /dev/null; rc=$?
    [ "$rc" = "$st" ] && { ok; return 0; }
    bad "$n: exit $rc, want $st"; cat "$W/$n.err"; return 1
}

for p in lines colour circles textures; do
    "$D" --headless --page $p --out "$W/want" > /dev/null || bad "headless $p"
done

# Two outputs, two pages, each picture checked.
printf 'frame\n' > "$W/one.txt"
run 0 two FIXEL_REPLAY="$W/one.txt" FIXEL_OUT="$W/two.png" "$D" --display =lines --display =colour &&
    { same_pic "output 0 shows lines" "$W/two.png" "$W/want/lines.png"
      same_pic "output 1 shows colour" "$W/two.d1.png" "$W/want/colour.png"; }

# Device 0 is bound to output 1 and taps its Textures tab; device 1 is not
# bound and taps the Circles tab of output 0 (at 800 px, Circles spans x
# 50..111 and Textures 230..297: demo_tab_span; the range is the screen's,
# so raw units are pixels).
cat > "$W/taps.txt" <<'X'
device 0 touch abs 0 799 0 479 name Panel Touch
device 1 touch abs 0 799 0 479
ev 0 ABS ABS_X 256
ev 0 ABS ABS_Y 10
ev 0 KEY BTN_TOUCH 1
syn 0
ev 0 KEY BTN_TOUCH 0
syn 0
ev 1 ABS ABS_X 100
ev 1 ABS ABS_Y 10
ev 1 KEY BTN_TOUCH 1
syn 1
ev 1 KEY BTN_TOUCH 0
syn 1
frame
X
run 0 bound FIXEL_INPUT_BIND="Panel Touch=1" FIXEL_REPLAY="$W/taps.txt" FIXEL_OUT="$W/bound.png" \
    "$D" --display =lines --display =colour &&
    { same_pic "bound: output 0 turned to circles" "$W/bound.png" "$W/want/circles.png"
      same_pic "bound: output 1 turned to textures" "$W/bound.d1.png" "$W/want/textures.png"; }
# Unbound, both taps are output 0's (the last wins); output 1 keeps colour.
run 0 unbound FIXEL_REPLAY="$W/taps.txt" FIXEL_OUT="$W/unbound.png" "$D" --display =lines --display =colour &&
    { same_pic "unbound: output 0 took both taps" "$W/unbound.png" "$W/want/circles.png"
      same_pic "unbound: output 1 untouched" "$W/unbound.d1.png" "$W/want/colour.png"; }
# A binding that cannot be parsed stops the program.
run 1 badbind FIXEL_INPUT_BIND="no equals sign" FIXEL_REPLAY="$W/one.txt" "$D" --display =lines &&
    { grep -q "FIXEL_INPUT_BIND\|DEVICE=DISPLAY" "$W/badbind.err" && ok || bad "badbind: $(cat "$W/badbind.err")"; }

# A replay on an animated page: the Animation page redraws every tick, and
# on a loaded machine a frame is always due; the replay must still advance
# (it used to wait for an idle moment that never came, and the run hung).
# 'k' records the camera as a flight key, 'f' moves it forward, 'k' again:
# the flight file gets two different keys and the end of the file ends the run.
# (tests/boards/test_replay_anim.c makes the always-due case certain.)
cat > "$W/flight.txt" <<'X'
device 0 keyboard
frame
ev 0 KEY KEY_K 1
syn 0
ev 0 KEY KEY_K 0
syn 0
frame
ev 0 KEY KEY_F 1
syn 0
ev 0 KEY KEY_F 0
syn 0
frame
ev 0 KEY KEY_K 1
syn 0
ev 0 KEY KEY_K 0
syn 0
frame
frame
X
rm -f "$W/keys.txt"
run 0 animreplay FIXEL_REPLAY="$W/flight.txt" FIXEL_OUT="$W/anim.png" timeout -k 5 120 "$D" --display =anim --flight "$W/keys.txt" &&
    { [ "$(wc -l < "$W/keys.txt")" = 2 ] && [ "$(sed -n 1p "$W/keys.txt" | cut -d' ' -f2-)" != "$(sed -n 2p "$W/keys.txt" | cut -d' ' -f2-)" ] &&
          ok || bad "animreplay: flight keys: $(cat "$W/keys.txt")"; }

# Refused arguments.
run 2 noeq "$D" --display lines
grep -q "OUTPUT=PAGE" "$W/noeq.err" && ok || bad "noeq message: $(cat "$W/noeq.err")"
run 2 nopage "$D" --display HDMI-A-1=nosuch
grep -q "no page 'nosuch'" "$W/nopage.err" && ok || bad "nopage message: $(cat "$W/nopage.err")"
run 2 toomany "$D" --display =lines --display =lines --display =lines --display =lines --display =lines
grep -q "at most 4 outputs" "$W/toomany.err" && ok || bad "toomany message: $(cat "$W/toomany.err")"
run 2 withheadless "$D" --headless --display =lines
grep -q "does not go with --headless" "$W/withheadless.err" && ok || bad "withheadless: $(cat "$W/withheadless.err")"

echo "demo-outputs: $P passed, $F failed"
[ "$F" = 0 ]
