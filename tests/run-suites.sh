#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs test suites (each argument is one command) and adds up their closing
# "N passed, N failed" lines. A suite that exits non-zero without reporting a
# failure, or prints no such line, counts as one failure of its own.
total=0
if [ "$1" = "--total" ]; then total=1; shift; fi
P=0; F=0
tmp=$(mktemp)
for cmd in "$@"; do
    echo "== $cmd"
    t0=$(date +%s)
    sh -c "$cmd" > "$tmp" 2>&1
    rc=$?
    cat "$tmp"
    # CI has a time limit: each suite's share of it is worth seeing.
    echo "== took $(( $(date +%s) - t0 )) s"
    line=$(grep -E '^([A-Za-z0-9_-]+: )?[0-9]+ passed, [0-9]+ failed' "$tmp" | tail -n 1)
    p=$(echo "$line" | sed -nE 's/^([A-Za-z0-9_-]+: )?([0-9]+) passed, ([0-9]+) failed.*/\2/p')
    f=$(echo "$line" | sed -nE 's/^([A-Za-z0-9_-]+: )?([0-9]+) passed, ([0-9]+) failed.*/\3/p')
    if [ -z "$p" ]; then
        echo "!! suite printed no result line (exit $rc): $cmd"
        F=$((F + 1))
        continue
    fi
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "!! suite exited $rc: $cmd"
        f=1
    fi
    P=$((P + p)); F=$((F + f))
done
rm -f "$tmp"
if [ $total = 1 ]; then echo "total: $P passed, $F failed"; else echo "suites: $P passed, $F failed"; fi
[ "$F" -eq 0 ]
