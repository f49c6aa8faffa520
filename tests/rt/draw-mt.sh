#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-draw ray traces on several threads ('raytrace' through the host's
# boards/posix/rt_mt.c, issue #22): every ray-tracing golden script,
# rendered with -j 3 in each of its formats, must give exactly the golden
# picture the core's one-thread render made (tests/golden/golden
# --compare-ppm); a tile ('raytrace X Y W H') over a drawn background must
# be the same on 1 and 3 threads and leave the pixels around it alone.
# usage: draw-mt.sh FIXEL_DRAW GOLDEN_BIN WORK_DIR
D=${1:-build/bin/fixel-draw}; G=${2:-build/tests/golden}; W=${3:-build/tests/rt-draw-mt}
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
rm -rf "$W"; mkdir -p "$W/set/scripts" "$W/ppm"
for s in tests/golden/scripts/rt-*.fxs; do
    n=$(basename "$s" .fxs)
    cp "$s" "$W/set/scripts/"
    for f in $(sed -n 's/^# formats: //p' "$s"); do
        mkdir -p "$W/set/$f" "$W/ppm/$f"
        cp "tests/golden/$f/$n.png" "$W/set/$f/"
        "$D" -j 3 -f "$f" -o "$W/ppm/$f/$n.ppm" "$s" > "$W/$n-$f.log" 2>&1 && ok ||
            { bad "fixel-draw -j 3 $s ($f)"; cat "$W/$n-$f.log"; }
    done
done
# the textures a script loads (none today) would need --textures-ppm
"$G" --dir "$W/set" --out "$W/out" --compare-ppm "$W/ppm" > "$W/compare.log" 2>&1
sed -n 's/^golden: //p' "$W/compare.log" | grep -q '^[1-9][0-9]* passed, 0 failed' && ok ||
    { bad "threaded renders differ from the goldens"; cat "$W/compare.log"; }

cat > "$W/tile.fxs" <<'FXS'
size 96 64
clear #204080
rtcamera 0 0 5 0 0 0 0 1 0 40
rtlight 3 4 5 #FFFFFF
rtmaterial #202020 #C08040 #FFFFFF 30 0.3 0 1
rtshape sphere
raytrace 13 9 57 41
FXS
for j in 1 3; do
    "$D" -j $j -o "$W/tile-$j.ppm" "$W/tile.fxs" && ok || bad "tile -j $j"
done
cmp -s "$W/tile-1.ppm" "$W/tile-3.ppm" && ok || bad "tile: -j 1 and -j 3 differ"
# the corner pixel (0, 0) outside the tile keeps the clear colour: PPM
# header "P6\n96 64\n255\n" is 13 bytes, then R G B
[ "$(od -An -tx1 -j13 -N3 "$W/tile-3.ppm" | tr -d ' \n')" = 204080 ] && ok || bad "tile: drew outside its rectangle"
"$D" -j 0 -o "$W/x.ppm" "$W/tile.fxs" 2> "$W/j0.err"; [ $? = 2 ] && grep -q "1..64" "$W/j0.err" && ok || bad "-j 0 accepted"
# on a display (the memory backend here) the rows are shown as bands
# finish: the run must succeed and still write nothing else
FIXEL_BACKEND=memory "$D" --display -j 3 tests/golden/scripts/rt-spheres.fxs > "$W/display.log" 2>&1 && ok ||
    { bad "fixel-draw --display -j 3"; cat "$W/display.log"; }
echo "rt-draw-mt: $P passed, $F failed"
[ $F = 0 ]
