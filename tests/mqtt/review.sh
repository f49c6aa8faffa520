#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk and MQTT: the issue #24 review findings, each against a real
# mosquitto on 127.0.0.1 at a free port (run.sh is the full tour; this one
# is short and only checks what once went wrong):
#   1. a huge PUBLISH never reaches the kiosk's memory (MQTT v5 Maximum
#      Packet Size, 1 MiB): its peak resident set stays put, the broker says
#      it dropped the message; payloads between the kiosk's payload limit
#      (8 KiB) and its packet limit (12000 bytes, 256 KiB) arrive and count bad;
#   2. a partial line on stdin and an MQTT payload do not share a buffer;
#   3. a reload that changes the control prefix moves control, status,
#      online flag and last will to the new prefix;
#   4. a backlight found off (bl_power 4) is lit at start and left lit at exit.
# Usage: review.sh BIN OUTDIR
bin=$(readlink -f "$1"); out=$2
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
here=$(cd "$(dirname "$0")" && pwd)
img() { python3 "$here/img.py" "$@"; }
PATH=$PATH:/usr/sbin:/sbin
for t in mosquitto mosquitto_pub mosquitto_sub python3; do
    command -v $t >/dev/null 2>&1 || { echo "mqtt-review: $t missing (make deps)"; echo "mqtt-review: 0 passed, 1 failed"; exit 1; }
done
rm -rf "$out"; mkdir -p "$out"; out=$(cd "$out" && pwd)
pids=""
cleanup() { for p in $pids; do kill "$p" 2>/dev/null; done; }
trap cleanup EXIT
# a suite stopped by a signal stops: the EXIT trap alone would clean up and
# let the script go on, and a stray run then fights the next one for its files
trap 'exit 143' INT TERM
PA=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
# waitfor S CMD...: until CMD succeeds, at most S seconds (a broken kiosk
# fails in bounded time even when each try waits for a retained message)
. "$(cd "$(dirname "$0")" && pwd)/../lib/patience.sh"
# waitfor SECONDS COMMAND (seconds here, times the measured PATIENCE)
waitfor() { end=$(( $(date +%s) + $1 * PATIENCE )); shift; while :; do "$@" && return 0; [ $(date +%s) -ge $end ] && return 1; sleep 0.1; done; }
pub() { mosquitto_pub -h 127.0.0.1 -p $PA "$@"; }
retained() { mosquitto_sub -h 127.0.0.1 -p $PA -t "$1" -C 1 -W 1 2>/dev/null; }
field() { retained "$1/status" | sed -n "s/.*\"$2\":\"\{0,1\}\([^\",}]*\).*/\1/p"; }
is() { [ "$(field "$1" "$2")" = "$3" ]; }
kb() { awk -v k="$2:" '$1 == k { print $2 }' /proc/$1/status; }

cat > "$out/broker.conf" <<EOC
listener $PA 127.0.0.1
user $(id -un)
allow_anonymous true
log_dest file $out/broker.log
log_type all
EOC
mosquitto -c "$out/broker.conf" 2>"$out/broker.err" & pids="$pids $!"
waitfor 10 pub -t probe -m x 2>/dev/null && ok || bad "the broker did not come up: $(cat "$out/broker.err")"

start() { # start NAME [--data FILE]: a live kiosk drawing into memory
    n=$1; shift
    mkdir -p "$out/$n"
    FIXEL_BACKEND=memory "$bin" --out "$out/$n" "$@" "$out/$n.conf" </dev/null >>"$out/$n.log" 2>&1 &
    eval "K_$n=\$!"; pids="$pids $!"
}
online() { [ "$(retained "$1/online")" = online ]; }

# 1. a 64 MiB PUBLISH: libmosquitto used to take it whole before the kiosk
# could say "oversize"; now the broker keeps it from the kiosk.
cat > "$out/big.conf" <<EOC
grid 1x1
size 160x120
mqtt host=127.0.0.1 port=$PA prefix=rv/big status=1 backoff=1 backoff_max=2
subscribe big/lines
widget text msg col=0 row=0
EOC
start big
waitfor 10 online rv/big && ok || bad "big never said online: $(cat "$out/big.log")"
hwm0=$(kb $K_big VmHWM)
head -c 67108864 /dev/zero | tr '\0' 7 > "$out/huge"
pub -t big/lines -f "$out/huge"
rm -f "$out/huge"
# over the payload limit, under the packet limit: they arrive and count bad
head -c 12000 /dev/zero | tr '\0' 7 > "$out/mid"
pub -t big/lines -f "$out/mid"
head -c 262144 /dev/zero | tr '\0' 7 > "$out/mid"
pub -t big/lines -f "$out/mid"
pub -t big/lines -m 'msg=after'
waitfor 10 is rv/big lines 3 && ok || bad "big: the 12000-byte and 256 KiB payloads and msg=after should be 3 lines: $(retained rv/big/status)"
is rv/big bad 2 && ok || bad "big: the 12000-byte and 256 KiB payloads should be 2 bad lines: $(retained rv/big/status)"
is rv/big connects 1 && ok || bad "big: the huge message cost a reconnect: $(retained rv/big/status)"
hwm1=$(kb $K_big VmHWM)
echo "mqtt-review: big peak resident set $hwm0 -> $hwm1 KiB over a 64 MiB publish"
# 1 MiB packet limit: at most that in libmosquitto's buffer, plus slack
[ -n "$hwm0" ] && [ -n "$hwm1" ] && [ $((hwm1 - hwm0)) -lt 4096 ] && ok || bad "big: peak resident set grew from $hwm0 to $hwm1 KiB: the 64 MiB message reached the kiosk"
grep -qi "too large\|oversize\|maximum packet" "$out/broker.log" && ok || bad "the broker log does not say it dropped the oversized message for the kiosk"

# 2. stdin (a FIFO here) holds "temp=2" without its newline while an MQTT
# payload of data lines arrives; the rest of the stdin line comes after.
cat > "$out/mix.conf" <<EOC
grid 2x1
size 480x320
stale 600
mqtt host=127.0.0.1 port=$PA prefix=rv/mix status=1 backoff=1 backoff_max=2
subscribe mix/lines
widget number temp col=0 row=0 decimals=1
widget number hum col=1 row=0 decimals=2
EOC
mkfifo "$out/mix.fifo"
start mix --data "$out/mix.fifo"
exec 3>"$out/mix.fifo"
waitfor 10 online rv/mix && ok || bad "mix never said online: $(cat "$out/mix.log")"
printf 'temp=2' >&3
sleep 0.5 # the kiosk reads the FIFO every 100 ms
pub -t mix/lines -m 'hum=45.25'
waitfor 10 is rv/mix lines 1 && ok || bad "mix: the MQTT line was not counted alone: $(retained rv/mix/status)"
printf '1.5\n' >&3
waitfor 10 is rv/mix lines 2 && ok || bad "mix: the stdin line was not counted: $(retained rv/mix/status)"
is rv/mix bad 0 && ok || bad "mix: a stdin line and an MQTT payload ran into each other: $(retained rv/mix/status)"
exec 3>&-
printf 'temp=21.5\nhum=45.25\n' | "$bin" --headless --out "$out/exp-mix" --last "$out/mix.conf" >/dev/null 2>&1
img ppm "$out/exp-mix/last.png" "$out/exp-mix/last.ppm"
waitfor 10 img same "$out/mix/live.ppm" "$out/exp-mix/last.ppm" 0 0 480 300 && ok || bad "mix does not show temp 21.5 and hum 45.25"

# 3. a reload moves the kiosk from prefix rv/c1 to rv/c2
cat > "$out/c.conf" <<EOC
grid 1x1
size 160x120
mqtt host=127.0.0.1 port=$PA prefix=rv/c1 status=1 backoff=1 backoff_max=2
widget text msg col=0 row=0
EOC
start c
waitfor 10 online rv/c1 && ok || bad "c never said online on rv/c1: $(cat "$out/c.log")"
sed 's|prefix=rv/c1|prefix=rv/c2|' "$out/c.conf" > "$out/c.new" && mv "$out/c.new" "$out/c.conf"
pub -q 1 -t rv/c1/set/reload -m 1
waitfor 10 is rv/c2 reloads 1 && ok || bad "c: no status on the new prefix rv/c2 after the reload: $(cat "$out/c.log")"
waitfor 10 online rv/c2 && ok || bad "c: rv/c2/online is not online"
[ "$(retained rv/c1/online)" = offline ] && ok || bad "c: the old prefix still says $(retained rv/c1/online)"
pub -q 1 -t rv/c2/set/brightness -m 40
waitfor 10 is rv/c2 brightness 40 && ok || bad "c: control on the new prefix does nothing: $(retained rv/c2/status)"
pub -q 1 -t rv/c1/set/brightness -m 70
pub -q 1 -t rv/c2/set/identify -m 1 # a marker: once it is counted, the 70 was seen or never will be
waitfor 10 is rv/c2 lines 2 && ok || bad "c: lines on rv/c2 $(field rv/c2 lines), wanted 2 (brightness 40, identify)"
is rv/c2 brightness 40 && ok || bad "c: the old prefix still controls the kiosk: $(retained rv/c2/status)"
# the last will moved too: a kiosk killed outright is offline under rv/c2
kill -9 $K_c; wait $K_c 2>/dev/null
waitfor 10 sh -c "[ \"\$(mosquitto_sub -h 127.0.0.1 -p $PA -t rv/c2/online -C 1 -W 1 2>/dev/null)\" = offline ]" && ok || bad "c: the last will did not move to rv/c2 (rv/c2/online is $(retained rv/c2/online))"

# 4. a backlight found off (a kiosk that crashed with its screen dark)
mkdir -p "$out/bl/panel"
echo 255 > "$out/bl/panel/max_brightness"; echo 100 > "$out/bl/panel/brightness"; echo 4 > "$out/bl/panel/bl_power"
printf 'grid 1x1\nsize 160x120\nscreen sysfs=%s\nmqtt host=127.0.0.1 port=%s prefix=rv/bl status=1 backoff=1 backoff_max=2\nwidget text msg col=0 row=0\n' \
    "$out/bl" $PA > "$out/bl.conf"
start bl
waitfor 10 online rv/bl && ok || bad "bl never said online: $(cat "$out/bl.log")"
[ "$(cat "$out/bl/panel/bl_power")" = 0 ] && is rv/bl screen on && ok || bad "bl: the kiosk says screen on but left bl_power at $(cat "$out/bl/panel/bl_power")"
pub -q 1 -t rv/bl/set/screen -m off
waitfor 10 sh -c "[ \"\$(cat $out/bl/panel/bl_power)\" = 4 ]" && ok || bad "bl: screen off did not reach bl_power"
kill -TERM $K_bl; wait $K_bl
[ "$(cat "$out/bl/panel/bl_power")" = 0 ] && [ "$(cat "$out/bl/panel/brightness")" = 100 ] && ok ||
    bad "bl: after exit bl_power $(cat "$out/bl/panel/bl_power") brightness $(cat "$out/bl/panel/brightness"), wanted 0 (lit) and 100 (as found)"

grep -q "ERROR: AddressSanitizer\|runtime error" "$out"/*.log && bad "sanitizer reports: $(grep -h -A3 'ERROR\|runtime error' "$out"/*.log | head -8)" || ok
cleanup; trap - EXIT INT TERM
echo "mqtt-review: $P passed, $F failed"
[ $F -eq 0 ]
