#!/bin/sh
# SPDX-License-Identifier: MIT
# Bounded work, counted: each huge primitive of tests/core/bounded_cases.h
# (lines and circles reaching 2^31 pixels off a 16x16 surface, Koch and
# Hilbert curves of order 12-30...) may execute at most BUDGET instructions
# beyond an empty run of the same program. Walking the invisible part of any
# of them would take billions. A control run drawing a visible line N times
# must cost more as N grows, past the budget, so the counter is seen to
# count. Instructions are counted by valgrind's lackey (deterministic; no
# hardware counters are needed).
bin=$1
BUDGET=1000000
P=0; F=0
if ! command -v valgrind >/dev/null 2>&1; then
    echo "bounded: valgrind is missing (make deps installs it)"; echo "bounded: 0 passed, 1 failed"; exit 1
fi
count() {
    valgrind --tool=lackey --basic-counts=yes "$bin" "$@" 2>&1 >/dev/null |
        sed -n 's/.*guest instrs: *//p' | tr -d ,
}
base=$(count none)
if [ -z "$base" ]; then
    echo "FAIL bounded: lackey printed no count"; echo "bounded: 0 passed, 1 failed"; exit 1
fi
cases=$("$bin" cases)
k=0
while [ "$k" -lt "$cases" ]; do
    n=$(count $k)
    d=$((n - base))
    if [ "$d" -le "$BUDGET" ]; then
        P=$((P + 1)); echo "ok   case $k: $d instructions"
    else
        F=$((F + 1)); echo "FAIL case $k: $d instructions (budget $BUDGET)"
    fi
    k=$((k + 1))
done
c1=$(( $(count control 100) - base )); c2=$(( $(count control 10000) - base ))
if [ "$c1" -lt "$c2" ] && [ "$c2" -gt "$BUDGET" ]; then
    P=$((P + 1)); echo "ok   control: 100 lines $c1, 10000 lines $c2 instructions"
else
    F=$((F + 1)); echo "FAIL control: 100 lines $c1, 10000 lines $c2 instructions"
fi
echo "bounded: $P passed, $F failed"
[ $F -eq 0 ]
