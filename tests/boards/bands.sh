#!/bin/sh
# SPDX-License-Identifier: MIT
# Whole frames in bands (fixel/par.h, boards/posix/par.c): every golden scene
# script on 2, 3, 4 and 7 threads (fx_scene_run_mt) gives exactly its golden,
# the one-thread picture; each band of 3 drawn alone equals the picture
# inside the band and writes nothing outside it (a script that could draw
# there would race with the other bands), and so does every single row as a
# band (any cut the balancer can choose); the demo pages on 2, 3, 4 and 7
# threads equal their goldens.
# usage: bands.sh BUILD_DIR
B=${1:-build}
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
mkdir -p "$B/bands"
for j in 2 3 4 7; do
    "$B/tests/golden" --dir tests/golden --out "$B/bands/j$j" --threads $j > "$B/bands/j$j.log" 2>&1 &&
        grep -q "^golden: [1-9][0-9]* of [0-9]* renders drawn in bands" "$B/bands/j$j.log" && ok ||
        { bad "golden scripts on $j threads"; grep -v '^PASS' "$B/bands/j$j.log" | tail -20; }
done
"$B/tests/golden" --dir tests/golden --out "$B/bands/check3" --band-check 3 > "$B/bands/check3.log" 2>&1 && ok ||
    { bad "bands of 3 drawn alone"; grep -v '^PASS' "$B/bands/check3.log" | tail -20; }
# fx_scene_run_mt cuts where the last frame's cost says, so a cut can fall
# on any row: each row drawn alone as its band (XRGB8888; the plain build
# only: a run per row, about half a minute)
case "$B" in
*asan*) ;;
*)  "$B/tests/golden" --dir tests/golden --out "$B/bands/rows" --band-check rows > "$B/bands/rows.log" 2>&1 && ok ||
        { bad "every row drawn alone as a band"; grep -v '^PASS' "$B/bands/rows.log" | tail -20; } ;;
esac
for j in 2 3 4 7; do
    "$B/bin/fixel-demo" --golden tests/golden/demo -j $j > "$B/bands/demo-j$j.log" 2>&1 && ok ||
        { bad "demo pages on $j threads"; cat "$B/bands/demo-j$j.log"; }
done
echo "bands: $P passed, $F failed"
[ $F = 0 ]
