#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk's message-to-pixels latency over MQTT (docs/BENCHMARK.md,
# section 8): a real mosquitto on 127.0.0.1 at a free port, live kiosks
# drawing into memory (FIXEL_BACKEND=memory) with FIXEL_KIOSK_TRACE on, and
# kbench (kbench.c) publishing sequence numbers and matching them with the
# frames the kiosks presented.
#   run.sh KIOSK KBENCH OUTDIR           the benchmark: one kiosk at 10, 100
#       and 1000 messages/s, then 20 kiosks of different configs at 100/s;
#       KBENCH_SECONDS (default 30) per run; the table is OUTDIR/kbench.txt
#   run.sh --smoke KIOSK KBENCH OUTDIR   make test's check: every value
#       published is presented (lockstep), and a short free run at 100/s and
#       one with three kiosks lose and mismatch nothing; no timing asserted
# Every wait is bounded; only loopback is used.
set -u
smoke=0
[ "${1:-}" = --smoke ] && { smoke=1; shift; }
[ $# -eq 3 ] || { echo "usage: run.sh [--smoke] KIOSK KBENCH OUTDIR"; exit 2; }
kiosk=$(readlink -f "$1"); kb=$(readlink -f "$2" 2>/dev/null || echo "$2"); out=$3
here=$(cd "$(dirname "$0")" && pwd)
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
PATH=$PATH:/usr/sbin:/sbin # Debian puts the broker in /usr/sbin
for t in mosquitto python3; do
    command -v $t >/dev/null 2>&1 || { echo "kbench: $t missing (make deps installs mosquitto python3)"; echo "kbench: 0 passed, 1 failed"; exit 1; }
done
[ -x "$kb" ] || { echo "kbench: $kb not built (it needs libmosquitto-dev: make deps)"; echo "kbench: 0 passed, 1 failed"; exit 1; }
[ -x "$kiosk" ] || { echo "kbench: no $kiosk"; echo "kbench: 0 passed, 1 failed"; exit 1; }
rm -rf "$out"; mkdir -p "$out"; out=$(cd "$out" && pwd)
pids=""
cleanup() { for p in $pids; do kill "$p" 2>/dev/null; done; }
trap cleanup EXIT
# a suite stopped by a signal stops: the EXIT trap alone would clean up and
# let the script go on, and a stray run then fights the next one for its files
trap 'exit 143' INT TERM
# wait up to $1 tenths of a second for the command after it to succeed
. "$(cd "$(dirname "$0")" && pwd)/../lib/patience.sh" # waitfor, scaled by the measured PATIENCE
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
listening() { python3 -c 'import socket,sys; socket.create_connection(("127.0.0.1",int(sys.argv[1])),1)' $port 2>/dev/null; }

# the broker as Debian ships it, on loopback: default queue limits
# (max_inflight_messages 20, max_queued_messages 1000 per client)
cat > "$out/broker.conf" <<EOC
listener $port 127.0.0.1
allow_anonymous true
log_dest file $out/broker.log
EOC
mosquitto -c "$out/broker.conf" 2>"$out/broker.err" & BROKER=$!; pids="$pids $BROKER"
waitfor 50 listening || { echo "kbench: mosquitto did not come up: $(cat "$out/broker.err")"; echo "kbench: 0 passed, 1 failed"; exit 1; }

# kconf NAME SIZE FILTER TYPE DECIMALS EXTRA: one kiosk's config; the
# widget under test shows source v, fed by the benchmark's topic
kconf() {
    w=$(echo "$2" | cut -dx -f1)
    cat > "$out/$1.conf" <<EOC
title kbench $1
grid 3x2
size $2
stale 60
history 120
mqtt host=127.0.0.1 port=$port client=$1 keepalive=30 $6
subscribe $3 source=v qos=1
widget $4 v col=0 row=0 w=2 decimals=$5 min=0 max=100000 label="sequence"
widget clock col=2 row=0
widget text note col=0 row=1 w=3
EOC
}
# kstart NAME: the live kiosk on the memory display, tracing its frames
kstart() {
    FIXEL_BACKEND=memory FIXEL_KIOSK_TRACE="$out/$1.trace" "$kiosk" "$out/$1.conf" </dev/null >"$out/$1.log" 2>&1 &
    eval "PID_$1=\$!"; pids="$pids $!"
}
kstop() { for n in "$@"; do eval "p=\$PID_$n"; kill "$p" 2>/dev/null; wait "$p" 2>/dev/null; done; }
# kbench ARGS... KIOSK-NAMES: one run; its output goes to the screen and OUT/runs.txt
run() {
    args=""; names=""
    while [ $# -gt 0 ]; do
        case $1 in --lockstep) args="$args $1"; shift ;; --*) args="$args $1 $2"; shift 2 ;; *) names="$names $1"; shift ;; esac
    done
    ks=""
    for n in $names; do eval "p=\$PID_$n"; ks="$ks $p:$out/$n.trace"; done
    # shellcheck disable=SC2086
    "$kb" --port $port --broker $BROKER $args $ks >"$out/run.out" 2>&1; rc=$?
    grep -v '^KBENCH' "$out/run.out"; cat "$out/run.out" >> "$out/runs.txt"
    grep '^KBENCH' "$out/run.out" >> "$out/rows.txt"
    return $rc
}

if [ $smoke = 1 ]; then
    kconf s1 480x320 kbench/seq number 0 ""
    kconf s2 320x240 'kbench/+' text 0 "prefix=kbench-status/s2 status=1"
    kconf s3 800x480 'kbench/#' gauge 1 ""
    for n in s1 s2 s3; do kstart $n; done
    # each value on screen by itself, in every kiosk
    run --label lockstep --lockstep --count 15 s1 s2 s3 && ok || bad "lockstep: a value was not presented, or was lost or mismatched"
    # free running: coalesced values are fine, lost or mismatched ones not
    run --label free --rate 100 --count 150 --drain-ms 20000 s1 s2 s3 && ok || bad "100/s: lost, mismatched or not presented"
    # the trace holds what the widgets drew: s3 shows one decimal
    grep -q "	v=15.0" "$out/s3.trace" && ok || bad "s3 (decimals=1) did not trace v=15.0: $(tail -2 "$out/s3.trace")"
    kstop s1 s2 s3
    # and the checks can fail: a false kiosk (tracer.py) that never counts
    # the value 9 and draws 7 as 70
    if command -v mosquitto_sub >/dev/null 2>&1; then
        : > "$out/liar.trace"
        python3 "$here/tracer.py" --lie $port kbench/seq "$out/liar.trace" & PID_liar=$!; pids="$pids $!"
        if run --label liar --rate 50 --count 12 --drain-ms 3000 liar; then bad "kbench passed a kiosk that lost 9 and drew 7 as 70"
        else
            grep -q "lost 1, mismatched 1," "$out/run.out" && ok || bad "kbench did not find exactly 1 lost and 1 mismatched: $(grep 'kiosk  1' "$out/run.out")"
            grep -q "first mismatch: presented unpublished 70" "$out/run.out" && ok || bad "kbench did not name the value 70"
        fi
        kstop liar
    else bad "mosquitto_sub missing (make deps installs mosquitto-clients)"; fi
    grep -q "ERROR: AddressSanitizer\|runtime error" "$out"/*.log && bad "sanitizer reports: $(grep -h -A3 'ERROR\|runtime error' "$out"/*.log | head -8)" || ok
    cleanup; trap - EXIT INT TERM
    echo "kbench: $P passed, $F failed"
    [ $F -eq 0 ]
    exit
fi

secs=${KBENCH_SECONDS:-30}
load0=$(cut -d' ' -f1-3 /proc/loadavg)
{
    echo "fixel-kiosk message-to-pixels benchmark (make bench-kiosk, docs/BENCHMARK.md section 8)"
    echo "date     $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "machine  $(uname -m), $(nproc) cores, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), $(uname -r)"
    echo "broker   $(mosquitto -h 2>/dev/null | sed -n 1p), QoS 1, 127.0.0.1"
    echo "load     $load0 (1, 5, 15 min) at the start"
} > "$out/head.txt"
cat "$out/head.txt"
# 1. one kiosk, three rates, a fresh kiosk for each
for rate in 10 100 1000; do
    kconf one$rate 480x320 kbench/seq number 0 ""
    kstart one$rate
    run --label one-kiosk --rate $rate --count $((rate * secs)) one$rate || bad "1 kiosk at $rate/s: lost, mismatched or not presented"
    kstop one$rate
done
# the floor: the same path with no kiosk (mosquitto_sub, one trace line per
# message, nothing drawn), at the highest rate
if command -v mosquitto_sub >/dev/null 2>&1; then
    : > "$out/floor.trace"
    python3 "$here/tracer.py" $port kbench/seq "$out/floor.trace" & PID_floor=$!; pids="$pids $!"
    run --label floor --rate 1000 --count $((1000 * secs)) floor || bad "the floor run lost or mismatched values"
    kstop floor
fi
# 2. the broker and 20 kiosks of different configs on one topic tree
sizes="320x240 480x320 800x480 1024x600"
types="number text gauge bar spark"
filters="kbench/seq kbench/+ kbench/#"
fleet=""
i=1; while [ $i -le 20 ]; do
    sz=$(echo $sizes | cut -d' ' -f$(( (i - 1) % 4 + 1 )))
    ty=$(echo $types | cut -d' ' -f$(( (i - 1) % 5 + 1 )))
    fl=$(echo $filters | cut -d' ' -f$(( (i - 1) % 3 + 1 )))
    ex=""; [ $((i % 2)) = 0 ] && ex="prefix=kbench-status/f$i status=5"
    kconf f$i $sz "$fl" $ty $((i % 3 == 0)) "$ex"
    kstart f$i; fleet="$fleet f$i"
    i=$((i + 1))
done
# shellcheck disable=SC2086
run --label 20-kiosks --rate 100 --count $((100 * secs)) $fleet || bad "20 kiosks: lost, mismatched or not presented"
# shellcheck disable=SC2086
kstop $fleet
load1=$(cut -d' ' -f1-3 /proc/loadavg)
{
    cat "$out/head.txt"
    echo "load     $load1 at the end"
    echo
    printf '%-10s %6s %6s %8s %8s %9s %9s %9s %10s %9s %10s %5s %5s\n' run msg/s msgs p50_ms p99_ms worst_p50 worst_p99 cpu_%core rss_KiB broker_% broker_KiB lost mism
    awk -F'\t' '{ printf "%-10s %6s %6s %8s %8s %9s %9s %9s %10s %9s %10s %5s %5s\n", $2, $3, $4, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15 }' "$out/rows.txt"
    echo
    echo "p50/p99: publish (CLOCK_MONOTONIC before mosquitto_publish) to the first presented frame showing that value"
    echo "or a newer one; cpu: utime+stime of the kiosks (all of them) over the run, % of one core; rss: VmRSS at the end."
} > "$out/kbench.txt"
echo; cat "$out/kbench.txt"
cleanup; trap - EXIT INT TERM
[ $F -eq 0 ]
