#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk pages and touch (issue #24, docs/kiosk.md "Pages and touch"):
#  1. the carousel on the headless kiosk's virtual clock (--frames, "@frame
#     1000"): every frame must show the page the dwell times say, checked
#     against single-page kiosks drawn from the same data (the digits and
#     dials are the same pixels), plus one golden frame;
#  2. hostile page configs: refused with FILE:LINE:COL and the reason;
#  3. swipes, edge taps, buttons and the waking touch through the input
#     replay (FIXEL_REPLAY: raw evdev events of a virtual touchscreen) on
#     live kiosks drawing into memory (FIXEL_BACKEND=memory, --out DIR);
#  4. with a real mosquitto on 127.0.0.1: a button's message (QoS, retain)
#     seen by mosquitto_sub, PREFIX/set/page by name and index, the status'
#     page fields, and a fleet screen that comes up on the page a retained
#     set/page names.
# Every wait is bounded; only loopback is used.
# Usage: run.sh BIN OUTDIR [--update]
[ -n "$1" ] && [ -n "$2" ] || { echo "usage: run.sh BIN OUTDIR [--update]"; echo "pages: 0 passed, 1 failed"; exit 2; }
bin=$(readlink -f "$1"); out=$2; update=$3
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
img() { python3 "$root/tests/mqtt/img.py" "$@"; }
command -v python3 >/dev/null 2>&1 || { echo "pages: python3 missing (make deps)"; echo "pages: 0 passed, 1 failed"; exit 1; }
rm -rf "$out"; mkdir -p "$out"; out=$(cd "$out" && pwd)
pids=""
cleanup() { for p in $pids; do kill "$p" 2>/dev/null; done; }
trap cleanup EXIT
# a suite stopped by a signal stops: the EXIT trap alone would clean up and
# let the script go on, and a stray run then fights the next one for its files
trap 'exit 143' INT TERM
. "$(cd "$(dirname "$0")" && pwd)/../lib/patience.sh" # waitfor, scaled by the measured PATIENCE
# everything above the status line (the page indicator lives in it)
TOP="0 0 480 306"

# ---- 1. the carousel, frame by frame ----
head='title Plant room
size 480x320
grid 2x2'
temps='widget number temp col=0 row=0 decimals=1 unit=C
widget gauge temp col=1 row=0 min=0 max=40 unit=C
widget bar watts col=0 row=1 w=2 min=0 max=3000 unit=W'
power='widget number watts decimals=0 unit=W'
controls='widget button Next col=0 row=0 page=next
widget button Home col=1 row=0 page=temps
widget clock col=2 row=0
widget number watts col=0 row=1 w=3 unit=W'
printf '%s\ncarousel dwell=3\npage temps dwell=2\n%s\npage power grid=1x1\n%s\npage controls grid=3x2\n%s\n' \
    "$head" "$temps" "$power" "$controls" > "$out/multi.conf"
printf '%s\n%s\n' "$head" "$temps" > "$out/ref-temps.conf"
printf '%s\ngrid 1x1\n%s\n' "$head" "$power" > "$out/ref-power.conf"
# (the buttons name pages: a page of the same name, alone)
printf '%s\npage temps grid=3x2\n%s\n' "$head" "$controls" > "$out/ref-controls.conf"
{ printf 'temp=21.5\nwatts=1234\n'; i=0; while [ $i -lt 14 ]; do printf '@frame 1000\n'; i=$((i + 1)); done; } > "$out/stream"
draw() { "$bin" --headless --frames 14 --out "$out/$1" --data "$out/stream" "$out/$1.conf" >/dev/null 2>&1 || bad "$1 exited $?"; }
for c in multi ref-temps ref-power ref-controls; do draw $c; done
# temps 2 s (its own dwell), power 3 s and controls 3 s (the carousel's)
want="temps temps power power power controls controls controls temps temps power power power controls"
f=0
for p in $want; do
    n=$(printf '%04d' $f)
    if img same "$out/multi/frame-$n.png" "$out/ref-$p/frame-$n.png" $TOP; then ok; else bad "carousel frame $f: not page $p"; fi
    f=$((f + 1))
done
# the comparison can fail: pages differ from each other where it matters
img same "$out/multi/frame-0000.png" "$out/ref-power/frame-0000.png" $TOP && bad "temps and power look alike" || ok
# and the frames show the values: the big number cell of page power
# differs from the same page with another value
printf 'temp=21.5\nwatts=1235\n' | "$bin" --headless --out "$out/other" --last "$out/ref-power.conf" >/dev/null 2>&1
img same "$out/other/last.png" "$out/ref-power/frame-0000.png" $TOP && bad "1234 W and 1235 W look alike" || ok
g="$root/tests/golden/kiosk/pages-0005.png"
[ "$update" = --update ] && cp "$out/multi/frame-0005.png" "$g"
cmp -s "$g" "$out/multi/frame-0005.png" && ok || bad "carousel frame 5 differs from $g (actual: $out/multi/frame-0005.png)"
# a single-page config has no page indicator: frames as before pages existed
cmp -s "$out/ref-temps/frame-0000.png" "$out/multi/frame-0000.png" && bad "the page indicator is missing" || ok
# damage-only frames equal full redraws across page turns
"$bin" --headless --frames 14 --full --out "$out/multi-full" --data "$out/stream" "$out/multi.conf" >/dev/null 2>&1
same=1; for x in "$out"/multi-full/*.png; do cmp -s "$x" "$out/multi/$(basename "$x")" || same=0; done
[ $same = 1 ] && ok || bad "damage-only frames differ from full redraws across page turns"

# the example config loads and turns its pages (temps 10 s, power 20 s)
{ printf 'temp=21.5\nwatts=1234\n'; i=0; while [ $i -lt 31 ]; do printf '@frame 1000\n'; i=$((i + 1)); done; } |
    "$bin" --headless --frames 31 --out "$out/example" "$root/examples/kiosk-pages.conf" > "$out/example.log" 2>&1 &&
    grep -q "31 frames, 2 lines, 0 bad" "$out/example.log" && ok || bad "examples/kiosk-pages.conf: $(cat "$out/example.log")"
img same "$out/example/frame-0009.png" "$out/example/frame-0010.png" 0 0 800 466 && bad "example: no page turn at 10 s" || ok
img same "$out/example/frame-0029.png" "$out/example/frame-0030.png" 0 0 800 466 && bad "example: no page turn at 30 s" || ok
img same "$out/example/frame-0010.png" "$out/example/frame-0029.png" 0 0 800 466 && ok || bad "example: page power changed between 10 and 29 s"

# ---- 2. hostile page configs ----
refuse() { # refuse "CONFIG" "FILE:LINE:COL: message part"
    printf '%s\n' "$1" > "$out/bad.conf"
    if "$bin" --headless --data /dev/null "$out/bad.conf" >/dev/null 2>"$out/bad.err"; then bad "accepted: $1"
    elif grep -qF "$out/bad.conf:$2" "$out/bad.err"; then ok
    else bad "'$1': wanted $2, got: $(cat "$out/bad.err")"; fi
}
refuse 'widget number a
widget button Lights topic=home/light/set payload=ON' "2:22: topic= needs an mqtt directive"
refuse 'page a
page b
widget number x' "1:6: a page without widgets"
refuse 'page a
widget button Go page=elsewhere' "2:18: page=: no page of that name"
refuse 'carousel dwell=100000' "1:10: dwell=100000: expected 0..86400"
refuse 'touch edge=80' "1:7: edge=80: expected 0..50"
refuse 'page a grid=0x2
widget clock' "1:8: grid=0x2: expected 1..16 each"
refuse 'page prev
widget clock' "1:6: page name"
refuse 'widget button B page=next qos=7' "1:27: qos=7: expected 0..2"
refuse "widget button B page=next payload=$(printf '%0130d' 0)" "1:27: payload="
refuse 'widget button B page=next topic=a/#
mqtt host=127.0.0.1' "1:27: topic=: a topic without wildcards"
refuse 'page a
widget clock
page a
widget clock' "3:6: a second page of that name"

# ---- 3. touch through the input replay (no broker) ----
# live kiosks without a carousel; the replay is a 480x320 touchscreen
printf '%s\npage temps\n%s\npage power grid=1x1\n%s\npage controls grid=3x2\n%s\n' \
    "$head" "$temps" "$power" "$(printf '%s\n' "$controls" | sed 's/widget clock col=2 row=0/widget button Stay col=2 row=0 page=controls/')" > "$out/live.conf"
printf '%s\npage controls grid=3x2\n%s\n' "$head" "$(printf '%s\n' "$controls" | sed 's/widget clock col=2 row=0/widget button Stay col=2 row=0 page=controls/; s/page=temps/page=controls/')" > "$out/ref-stay.conf"
printf 'temp=21.5\nwatts=1234\n' > "$out/values"
for c in ref-temps ref-power ref-stay; do
    "$bin" --headless --out "$out/$c-0" --last --data "$out/values" "$out/$c.conf" >/dev/null 2>&1
done
# replay building blocks: a press at X Y, moves, a release
down() { printf 'ev 0 ABS ABS_X %s\nev 0 ABS ABS_Y %s\nev 0 KEY BTN_TOUCH 1\nsyn 0\nframe\n' "$1" "$2"; }
move() { printf 'ev 0 ABS ABS_X %s\nev 0 ABS ABS_Y %s\nsyn 0\n' "$1" "$2"; }
up() { printf 'ev 0 KEY BTN_TOUCH 0\nsyn 0\nframe\n' ; }
tap() { down "$1" "$2"; up; }
swipe() { down "$1" 150; move $(( ($1 + $2) / 2 )) 152; move "$2" 155; up; }
# live NAME CONF: run the replay in $out/NAME.txt; the last frame is $out/NAME/live.ppm
live() {
    mkdir -p "$out/$1"
    { printf 'device 0 touch abs 0 479 0 319\nwait 300\nframe\n'; cat "$out/$1.txt"; printf 'wait 200\nframe\n'; } > "$out/$1.replay"
    FIXEL_BACKEND=memory FIXEL_REPLAY="$out/$1.replay" timeout 60 "$bin" --out "$out/$1" --data "$out/values" "$2" \
        </dev/null >"$out/$1.log" 2>&1 || bad "$1: exited $? $(tail -3 "$out/$1.log")"
}
shows() { img same "$out/$1/live.ppm" "$out/ref-$2-0/last.png" $TOP; }
check() { # check NAME PAGE WHY
    if shows "$1" "$2"; then ok; else bad "$1: not page $2 after $3"; fi
}
swipe 400 100 > "$out/swl.txt"; live swl "$out/live.conf"; check swl power "a swipe to the left"
swipe 100 400 > "$out/swr.txt"; live swr "$out/live.conf"; check swr stay "a swipe to the right (wraps to the last page)"
{ swipe 400 100; swipe 400 100; swipe 100 400; } > "$out/sw3.txt"; live sw3 "$out/live.conf"; check sw3 power "left, left, right"
swipe 300 265 > "$out/short.txt"; live short "$out/live.conf"; check short temps "a 35-pixel drag (a swipe is 40)"
{ down 400 40; move 380 200; move 330 300; up; } > "$out/down.txt"; live down "$out/live.conf"; check down temps "a drag mostly downwards"
tap 470 150 > "$out/edge.txt"; live edge "$out/live.conf"; check edge power "a tap at the right edge"
{ tap 470 150; tap 5 150; tap 5 150; } > "$out/edge3.txt"; live edge3 "$out/live.conf"; check edge3 stay "right, left, left edge taps"
tap 240 150 > "$out/mid.txt"; live mid "$out/live.conf"; check mid temps "a tap in the middle"
# buttons: Next on the controls page wraps to temps; Home goes to temps
{ swipe 100 400; tap 80 80; } > "$out/next.txt"; live next "$out/live.conf"; check next temps "the Next button"
{ swipe 100 400; tap 240 80; } > "$out/home.txt"; live home "$out/live.conf"; check home temps "the Home button"
# a press that slides off the button before the release does nothing
{ swipe 100 400; down 80 80; move 80 200; move 80 250; up; } > "$out/slide.txt"; live slide "$out/live.conf"
check slide stay "a press slid off Next"
# pressed look: while held (Stay is teal, #26a69a, all over), just after
# the release, and gone KIOSK_PRESS_MS (250 ms) later
STAY="324 26 478 162"
face() { img count "$out/$1/live.ppm" $STAY 26a69a; }
{ swipe 100 400; down 400 80; } > "$out/held.txt"; live held "$out/live.conf"
[ "$(face held)" -gt 12000 ] && ok || bad "a held button is not drawn pressed ($(face held) teal pixels)"
[ "$(face swr)" -lt 3000 ] && ok || bad "an untouched button looks pressed ($(face swr) teal pixels)"
# the release: drawn at once (the flash is still on), a frame 600 ms later
{ swipe 100 400; tap 400 80; } > "$out/flash.txt"
{ printf 'device 0 touch abs 0 479 0 319\nwait 300\nframe\n'; cat "$out/flash.txt"; } > "$out/flash.replay"
mkdir -p "$out/flash"
FIXEL_BACKEND=memory FIXEL_REPLAY="$out/flash.replay" timeout 60 "$bin" --out "$out/flash" --data "$out/values" \
    "$out/live.conf" </dev/null >"$out/flash.log" 2>&1
[ "$(face flash)" -gt 12000 ] && ok || bad "a button just released is not drawn pressed ($(face flash) teal pixels)"
{ swipe 100 400; tap 400 80; printf 'wait 600\nframe\n'; } > "$out/after.txt"; live after "$out/live.conf"
check after stay "a tap on Stay, 600 ms later"
# the waking touch: a screen dark by its schedule (on two hours from now)
# wakes on the first swipe, which does not turn the page; the second does
now=$(date +%H:%M); hh=${now%%:*}; mm=${now#*:}
on=$(printf '%02d:%s' $(( (${hh#0} + 2) % 24 )) "$mm"); off=$(printf '%02d:%s' $(( (${hh#0} + 3) % 24 )) "$mm")
{ cat "$out/live.conf"; printf 'schedule on=%s off=%s\n' "$on" "$off"; } > "$out/dark.conf"
swipe 400 100 > "$out/wake1.txt"; live wake1 "$out/dark.conf"; check wake1 temps "a swipe on a dark screen (it only wakes)"
{ swipe 400 100; swipe 400 100; } > "$out/wake2.txt"; live wake2 "$out/dark.conf"; check wake2 power "the swipe after the waking one"
# keys: right arrow, Page Down
printf 'device 1 keyboard\nev 1 KEY KEY_RIGHT 1\nev 1 KEY KEY_RIGHT 0\nsyn 1\nframe\n' > "$out/key.txt"
live key "$out/live.conf"; check key power "the right arrow key"

# ---- 4. with a broker: button messages, set/page, status, a fleet ----
PATH=$PATH:/usr/sbin:/sbin
if ! command -v mosquitto >/dev/null 2>&1 || ! command -v mosquitto_sub >/dev/null 2>&1; then
    bad "mosquitto or mosquitto_sub missing (make test installs mosquitto mosquitto-clients)"
else
    PA=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
    printf 'listener %s 127.0.0.1\nuser %s\nallow_anonymous true\nlog_dest file %s/broker.log\n' "$PA" "$(id -un)" "$out" > "$out/broker.conf"
    mosquitto -c "$out/broker.conf" 2>"$out/broker.err" & pids="$pids $!"
    pub() { mosquitto_pub -h 127.0.0.1 -p $PA "$@"; }
    sub() { mosquitto_sub -h 127.0.0.1 -p $PA "$@"; }
    waitfor 50 pub -t probe -m x 2>/dev/null && ok || bad "the broker did not come up: $(cat "$out/broker.err")"
    mqtt="mqtt host=127.0.0.1 port=$PA backoff=1 backoff_max=2 status=1"
    # the control panel: Lights publishes ON (QoS 1, retained), Off a JSON payload (QoS 0)
    cat > "$out/panel.conf" <<EOC
size 480x320
grid 2x1
$mqtt client=panel prefix=fleet/panel
widget button Lights col=0 row=0 topic=home/light/set payload=ON qos=1 retain=1
widget button Off col=1 row=0 topic=home/light/set payload={"state":"OFF"} qos=0
EOC
    sub -t home/light/set -q 2 -C 2 -W 20 -F '%q %r %p' > "$out/light.txt" 2>&1 & SUB=$!
    sleep 1 # mosquitto_sub subscribed
    # 4 s for the kiosk to connect to a broker on the same machine (a tap
    # while offline is not sent: checked below)
    { printf 'device 0 touch abs 0 479 0 319\n'
      printf 'wait 4000\n'; tap 120 150; printf 'wait 300\n'; tap 360 150; printf 'wait 1500\nframe\n'; } > "$out/panel.replay"
    mkdir -p "$out/panel"
    FIXEL_BACKEND=memory FIXEL_REPLAY="$out/panel.replay" timeout 60 "$bin" --out "$out/panel" "$out/panel.conf" \
        </dev/null >"$out/panel.log" 2>&1 || bad "panel exited $?: $(tail -3 "$out/panel.log")"
    wait $SUB
    [ "$(sed -n 1p "$out/light.txt")" = "1 0 ON" ] && ok || bad "Lights: wanted '1 0 ON' (QoS 1), mosquitto_sub saw: $(cat "$out/light.txt")"
    [ "$(sed -n 2p "$out/light.txt")" = '0 0 {"state":"OFF"}' ] && ok || bad "Off: wanted QoS 0 and the JSON payload, saw: $(cat "$out/light.txt")"
    # retain=1 left ON with the broker (the later QoS 0 OFF was not retained)
    [ "$(sub -t home/light/set -C 1 -W 3 -F '%r %p' 2>/dev/null)" = "1 ON" ] && ok || bad "Lights' retained message is not ON"
    st=$(sub -t fleet/panel/status -C 1 -W 3 2>/dev/null)
    case "$st" in *'"page":0,"pages":1,"page_name":"main","presses":2,"press_errors":0'*) ok ;;
        *) bad "panel status: $st" ;; esac

    # on a screen dark by its schedule the first tap only wakes it: one
    # message for two taps
    { sed 's|client=panel prefix=fleet/panel|client=dark prefix=fleet/dark|; s|home/light/set payload=ON qos=1 retain=1|home/dark/set payload=ON qos=1|' \
        "$out/panel.conf"; printf 'schedule on=%s off=%s\n' "$on" "$off"; } > "$out/darkpanel.conf"
    sub -t home/dark/set -q 1 -C 2 -W 12 -F '%p' > "$out/dark.txt" 2>/dev/null & SUB=$!
    sleep 1
    { printf 'device 0 touch abs 0 479 0 319\nwait 4000\n'; tap 120 150; printf 'wait 300\n'; tap 120 150; printf 'wait 1500\nframe\n'; } > "$out/darkpanel.replay"
    mkdir -p "$out/darkpanel"
    FIXEL_BACKEND=memory FIXEL_REPLAY="$out/darkpanel.replay" timeout 60 "$bin" --out "$out/darkpanel" "$out/darkpanel.conf" \
        </dev/null >"$out/darkpanel.log" 2>&1 || bad "darkpanel exited $?: $(tail -3 "$out/darkpanel.log")"
    wait $SUB
    [ "$(cat "$out/dark.txt")" = ON ] && ok || bad "two taps on a dark screen: wanted one ON (the first only wakes), saw: $(cat "$out/dark.txt")"
    case "$(sub -t fleet/dark/status -C 1 -W 3 2>/dev/null)" in *'"presses":1,'*'"screen":"on"'*) ok ;;
        *) bad "dark panel status: $(sub -t fleet/dark/status -C 1 -W 3)" ;; esac

    # a button tapped while the broker is away: not sent, counted, drawn red
    cat > "$out/away.conf" <<EOC
size 480x320
grid 1x1
mqtt host=127.0.0.1 port=1 backoff=1 backoff_max=2
widget button Lights topic=home/light/set payload=ON
EOC
    { printf 'device 0 touch abs 0 479 0 319\nwait 300\n'; down 240 150; up; } > "$out/away.replay"
    mkdir -p "$out/away"
    FIXEL_BACKEND=memory FIXEL_REPLAY="$out/away.replay" timeout 60 "$bin" --out "$out/away" "$out/away.conf" \
        </dev/null >"$out/away.log" 2>&1
    grep -q "button Lights: not sent, the broker is offline" "$out/away.log" && ok || bad "offline tap not reported: $(cat "$out/away.log")"
    [ "$(img count "$out/away/live.ppm" 4 4 478 304 ef5350)" -gt 50000 ] && ok || bad "offline tap not drawn red"

    # set/page by name, by index, next; bad names are bad lines; the frame follows
    sed "s|^carousel.*||" "$out/multi.conf" | sed "s|^size 480x320|size 480x320\n$mqtt client=wall prefix=fleet/wall|" > "$out/wall.conf"
    { printf 'device 0 touch abs 0 479 0 319\n'; printf 'wait 80000\n'; } > "$out/wall.replay"
    mkdir -p "$out/wall"
    FIXEL_BACKEND=memory FIXEL_REPLAY="$out/wall.replay" timeout 90 "$bin" --out "$out/wall" --data "$out/values" "$out/wall.conf" \
        </dev/null >"$out/wall.log" 2>&1 & WALL=$!; pids="$pids $WALL"
    field() { sub -t "fleet/$1/status" -C 1 -W 2 2>/dev/null | sed -n "s/.*\"$2\":\"\{0,1\}\([^\",}]*\).*/\1/p"; }
    isfield() { [ "$(field "$1" "$2")" = "$3" ]; }
    waitfor 50 isfield wall pages 3 && ok || bad "wall: status pages != 3: $(sub -t fleet/wall/status -C 1 -W 2)"
    pub -t fleet/wall/set/page -m power
    waitfor 50 isfield wall page_name power && ok || bad "set/page power: status says $(field wall page_name)"
    [ "$(field wall page)" = 1 ] && ok || bad "set/page power: status page $(field wall page), wanted 1"
    wshows() { img same "$out/wall/live.ppm" "$out/ref-$1-0/last.png" $TOP; }
    waitfor 30 wshows power && ok || bad "set/page power: the frame is not page power"
    pub -t fleet/wall/set/page -m 0
    waitfor 50 isfield wall page_name temps && ok || bad "set/page 0: status says $(field wall page_name)"
    waitfor 30 wshows temps && ok || bad "set/page 0: the frame is not page temps"
    pub -t fleet/wall/set/page -m prev
    waitfor 50 isfield wall page_name controls && ok || bad "set/page prev from temps: status says $(field wall page_name)"
    for v in 3 nowhere -1 ''; do pub -t fleet/wall/set/page -m "$v"; done
    waitfor 50 isfield wall bad 4 && ok || bad "set/page 3, nowhere, -1 and '' should be 4 bad lines: $(sub -t fleet/wall/status -C 1 -W 2)"
    [ "$(field wall page_name)" = controls ] && ok || bad "a bad set/page moved the page to $(field wall page_name)"
    # a fleet: a second screen with the same pages and its own prefix comes
    # up on the page a retained set/page names (one broker, several screens,
    # different pages of the same data)
    pub -r -t fleet/door/set/page -m power
    sed 's|client=wall prefix=fleet/wall|client=door prefix=fleet/door|' "$out/wall.conf" > "$out/door.conf"
    { printf 'device 0 touch abs 0 479 0 319\n'; printf 'wait 80000\n'; } > "$out/door.replay"
    mkdir -p "$out/door"
    FIXEL_BACKEND=memory FIXEL_REPLAY="$out/door.replay" timeout 90 "$bin" --out "$out/door" --data "$out/values" "$out/door.conf" \
        </dev/null >"$out/door.log" 2>&1 & DOOR=$!; pids="$pids $DOOR"
    waitfor 50 isfield door page_name power && ok || bad "door did not come up on the retained page: $(field door page_name)"
    dshows() { img same "$out/door/live.ppm" "$out/ref-$1-0/last.png" $TOP; }
    waitfor 30 dshows power && ok || bad "door's frame is not page power"
    [ "$(field wall page_name)" = controls ] && ok || bad "door's page moved wall's"
    pub -r -t fleet/door/set/page -n # clear the retained message
    kill $WALL $DOOR 2>/dev/null; wait $WALL $DOOR 2>/dev/null
fi

echo "pages: $P passed, $F failed"
[ "$F" -eq 0 ]
