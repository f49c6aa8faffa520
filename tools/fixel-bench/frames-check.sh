#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-bench --frames (TABLE 8) runs and prints what docs/PERFORMANCE.md
# reads off it: with more than 2 threads, a "2 thr" column next to the
# N-thread one (scaling at 1, 2 and every core), filled for banded rows;
# with 2 threads none. Timings are not judged (make bench measures them).
# Usage: frames-check.sh BINDIR OUTDIR
bin=$1/fixel-bench; out=$2
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
mkdir -p "$out"
w="script rt-spheres,kiosk kiosk-basic,present"
if "$bin" --frames -j 3 -t 1 -w "$w" > "$out/j3.txt" 2>&1; then ok; else bad "--frames -j 3 exited $?: $(tail -3 "$out/j3.txt")"; fi
grep -q "^what .* 1 thr .* 2 thr .* x2 .* N thr" "$out/j3.txt" && ok || bad "-j 3: no 2 thr column: $(grep '^what' "$out/j3.txt")"
# every script and kiosk row: 1 thr, 2 thr, x2, N thr as numbers
n=$(grep -c "^script rt-spheres \|^kiosk kiosk-basic " "$out/j3.txt")
[ "$n" -eq 6 ] && ok || bad "-j 3: $n script/kiosk rows, expected 6"
m=$(grep "^script rt-spheres \|^kiosk kiosk-basic " "$out/j3.txt" |
    awk '$5 ~ /^[0-9.]+$/ && $6 ~ /^[0-9.]+$/ && ($7 ~ /^[0-9.]+x$/ || $7 == "-") && $8 ~ /^[0-9.]+$/' | wc -l)
[ "$m" -eq 6 ] && ok || bad "-j 3: $m of 6 rows with 1, 2 and 3-thread figures: $(grep '^script\|^kiosk' "$out/j3.txt")"
grep -q "^present" "$out/j3.txt" && ok || bad "-j 3: no present rows"
if "$bin" --frames -j 2 -t 1 -w "script rt-spheres" > "$out/j2.txt" 2>&1; then ok; else bad "--frames -j 2 exited $?"; fi
grep "^what" "$out/j2.txt" | grep -q "2 thr" && bad "-j 2 has a 2 thr column" || ok
"$bin" --frames -j 1 > "$out/j1.txt" 2>&1
[ $? -eq 2 ] && grep -q "wants 2\.\." "$out/j1.txt" && ok || bad "-j 1 not refused: $(cat "$out/j1.txt")"
echo "frames-check: $P passed, $F failed"
[ "$F" -eq 0 ]
