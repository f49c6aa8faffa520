# SPDX-License-Identifier: MIT
# Sourced by the shell suites that wait on live processes (a kiosk, a
# broker): how long to wait comes from the machine's measured state, not a
# guess of a quiet machine's speed. PATIENCE is the ratio of wall time to
# CPU time of a short CPU-bound loop, rounded up: 1 on an idle machine, N
# when N runnable processes share each core. Every bound of a suite is its
# quiet-machine value times PATIENCE, so a loaded machine (CI beside other
# suites, a fresh root under apt) waits longer instead of failing, and an
# idle one fails as fast as before. FIXEL_TEST_PATIENCE=N sets it by hand.
# Needs python3 (the suites that source this already do).
patience_measure() {
    python3 - <<'PY' 2>/dev/null || echo 1
import time, math
best = None
for _ in range(3):
    w0 = time.perf_counter(); c0 = time.process_time()
    x = 0
    for i in range(400000):
        x += i
    w = time.perf_counter() - w0; c = max(time.process_time() - c0, 1e-6)
    r = w / c
    best = r if best is None else min(best, r)
print(min(16, max(1, math.ceil(best - 0.15))))
PY
}
PATIENCE=${FIXEL_TEST_PATIENCE:-$(patience_measure)}
case $PATIENCE in ''|*[!0-9]*|0) PATIENCE=1 ;; esac
# waitfor N COMMAND...: up to N tenths of a second (times PATIENCE) of wall
# time for COMMAND to succeed, tried every 0.1 s; returns as soon as it does.
# A deadline, not a count of tries: a slow COMMAND (a python image check on
# a loaded machine) must not stretch the wait by its own length.
waitfor() {
    _end=$(( $(date +%s%N) / 1000000 + $1 * 100 * PATIENCE )); shift
    while :; do
        "$@" && return 0
        [ $(( $(date +%s%N) / 1000000 )) -ge $_end ] && return 1
        sleep 0.1
    done
}
# bound N: N (a quiet machine's bound, in any unit) scaled by PATIENCE
bound() { echo $(($1 * PATIENCE)); }
