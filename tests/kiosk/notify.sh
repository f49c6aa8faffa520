#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk under a pretend systemd: a datagram socket as NOTIFY_SOCKET
# must receive READY=1 once the first frame is drawn and WATCHDOG=1 at about
# half of WATCHDOG_USEC while the main loop runs; a kiosk whose main loop is
# stopped (SIGSTOP) must stop pinging. Usage: notify.sh BIN OUTDIR
bin=$(readlink -f "$1"); out=$2
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
rm -rf "$out"; mkdir -p "$out"; out=$(cd "$out" && pwd)
printf 'grid 1x1\nsize 160x120\nwidget number t col=0 row=0\n' > "$out/k.conf"
# the listener: every datagram for 4 s, then what it got, one per line
python3 - "$out/notify" > "$out/got.txt" <<'PY' &
import socket, sys, time
s = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
s.bind(sys.argv[1])
s.settimeout(0.2)
end = time.time() + 4
while time.time() < end:
    try:
        d = s.recv(4096).decode()
        print('%.2f %s' % (time.time(), d.replace('\n', ' ')), flush=True)
    except socket.timeout:
        pass
PY
lp=$!
i=0; while [ ! -S "$out/notify" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
# WATCHDOG_PID must be the kiosk's own pid: sh execs it keeping $$
NOTIFY_SOCKET=$out/notify WATCHDOG_USEC=600000 FIXEL_BACKEND=memory \
    sh -c 'export WATCHDOG_PID=$$; exec "$0" "$@"' "$bin" "$out/k.conf" </dev/null >"$out/k.log" 2>&1 &
kp=$!
sleep 2
kill -STOP $kp        # a hung main loop: the pings must stop
sleep 1.5
kill -CONT $kp; sleep 0.1; kill -TERM $kp; wait $kp; rc=$?
wait $lp
[ $rc = 0 ] && ok || bad "kiosk exit $rc: $(cat "$out/k.log")"
grep -q "READY=1" "$out/got.txt" && ok || bad "no READY=1: $(cat "$out/got.txt")"
n=$(grep -c "WATCHDOG=1" "$out/got.txt")
# 2 s running at a ping every 300 ms: about 6 (the 100 ms tick rounds it; start-up eats some)
[ "$n" -ge 3 ] && [ "$n" -le 9 ] && ok || bad "$n watchdog pings in 2 s (WATCHDOG_USEC=600000): $(cat "$out/got.txt")"
# none while stopped: no gap between pings shorter than the stop
gap=$(awk '/WATCHDOG=1/ { if (p) { d = $1 - p; if (d > m) m = d } p = $1 } END { print (m >= 1.2) ? "yes" : "no" }' "$out/got.txt")
[ "$gap" = yes ] && ok || bad "the pings did not stop while the main loop was stopped: $(cat "$out/got.txt")"
echo "notify: $P passed, $F failed"
[ $F -eq 0 ]
