#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A stand-in kiosk for kbench (tests/kbench/run.sh): mosquitto_sub takes the
# benchmark's topic and every message becomes a FIXEL_KIOSK_TRACE line at
# once, nothing drawn. In the benchmark it is the floor (publish, broker,
# a subscriber, a trace line: what any kiosk pays before it draws); with
# --lie it drops the value 9 without counting it and writes 7 as 70, so the
# smoke test can see kbench find a lost and a mismatched value.
#   tracer.py [--lie] PORT TOPIC TRACE
import signal, subprocess, sys, time

lie = sys.argv[1] == "--lie"
port, topic, trace = sys.argv[1 + lie:4 + lie]
sub = subprocess.Popen(["mosquitto_sub", "-h", "127.0.0.1", "-p", port, "-q", "1", "-t", topic],
                       stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
def stop(*_):
    sub.kill()
    sub.wait()
    sys.exit(0)
signal.signal(signal.SIGTERM, stop)
signal.signal(signal.SIGINT, stop)
n = 0
with open(trace, "a") as t:
    for line in sub.stdout:
        v = line.decode(errors="replace").strip()
        if lie and v == "9":
            continue
        n += 1
        t.write("%d\t%d\t%d\tv=%s\n" % (time.monotonic_ns(), n, n, "70" if lie and v == "7" else v))
        t.flush()
stop()
