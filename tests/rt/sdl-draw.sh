#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-draw on the textbook's SDL files: a .sdl renders as the script
# 'sdl "FILE"' + 'raytrace' would (the same pixels), --camera as a later
# rtcamera, --preview as rtpreview; errors print the SDL file's own
# FILE:LINE:COL and exit 1; --camera and --preview without a .sdl, and a bad
# --camera, exit 2.
# usage: sdl-draw.sh FIXEL_DRAW WORK_DIR
D=${1:-build/bin/fixel-draw}; W=${2:-build/tests/sdl-draw}
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
rm -rf "$W"; mkdir -p "$W"
same() { cmp -s "$1" "$2" && ok || bad "$3: $1 and $2 differ"; }

S=examples/sdl/csg.sdl
printf 'size 64 48\nsdl "%s"\nraytrace\n' "$S" > "$W/t.fxs"
"$D" -s 64x48 -o "$W/a.ppm" "$S" && "$D" -o "$W/b.ppm" "$W/t.fxs" && same "$W/a.ppm" "$W/b.ppm" "sdl = script" || bad "render $S"
printf 'size 64 48\nsdl "%s"\nrtcamera 0 2 8 0 0 0 0 1 0 40\nraytrace\n' "$S" > "$W/c.fxs"
"$D" -s 64x48 --camera 0,2,8 0,0,0 0,1,0 40 -o "$W/c1.ppm" "$S" && "$D" -o "$W/c2.ppm" "$W/c.fxs" &&
    same "$W/c1.ppm" "$W/c2.ppm" "--camera = rtcamera" || bad "render --camera"
cmp -s "$W/a.ppm" "$W/c1.ppm" && bad "--camera changed nothing" || ok
printf 'size 64 48\nsdl "%s"\nrtpreview\n' "$S" > "$W/p.fxs"
"$D" -s 64x48 --preview -o "$W/p1.ppm" "$S" && "$D" -o "$W/p2.ppm" "$W/p.fxs" &&
    same "$W/p1.ppm" "$W/p2.ppm" "--preview = rtpreview" || bad "render --preview"
# the default size
"$D" -o "$W/d.ppm" "$S" && [ "$(head -c 15 "$W/d.ppm" | tr '\n' ' ')" = "P6 640 480 255 " ] && ok || bad "default size not 640x480"

# errors: the SDL file's place, exit 1
printf 'sphere\n\n  push translate 1 2 x\n' > "$W/bad.sdl"
"$D" -o "$W/x.png" "$W/bad.sdl" 2> "$W/bad.err"; rc=$?
[ $rc = 1 ] && grep -q "^fixel-draw: $W/bad.sdl:3:22: translate: expected a number, found 'x'$" "$W/bad.err" && ok ||
    { bad "bad number: exit $rc"; cat "$W/bad.err"; }
printf 'def a { use a }\nuse a\n' > "$W/rec.sdl"
"$D" -o "$W/x.png" "$W/rec.sdl" 2> "$W/rec.err"; rc=$?
[ $rc = 1 ] && grep -q "rec.sdl:1:13: use a: recursive" "$W/rec.err" && ok || { bad "recursive use: exit $rc"; cat "$W/rec.err"; }
printf 'mesh none.3vn\n' > "$W/nomesh.sdl"
"$D" -o "$W/x.png" "$W/nomesh.sdl" 2> "$W/nomesh.err"; rc=$?
[ $rc = 1 ] && grep -q "nomesh.sdl:1:6: mesh: cannot read '$W/none.3vn'" "$W/nomesh.err" && ok ||
    { bad "missing mesh: exit $rc"; cat "$W/nomesh.err"; }
"$D" -o "$W/x.png" "$W/missing.sdl" 2> "$W/miss.err"; rc=$?
[ $rc = 1 ] && grep -q "missing.sdl" "$W/miss.err" && ok || { bad "missing file: exit $rc"; cat "$W/miss.err"; }
"$D" --camera 0,0,0 0,0,0 0,1,0 40 -o "$W/x.png" "$S" 2> "$W/cam.err"; rc=$?
[ $rc = 1 ] && grep -q "^fixel-draw: --camera: rtcamera" "$W/cam.err" && ok || { bad "eye = look: exit $rc"; cat "$W/cam.err"; }
# an error that is neither the reader's nor --camera's names the scene file
# (it said "--camera:" for every such error before the review)
# (the plain build: a sanitized one cannot run under an address-space cap)
case $D in *asan*) ;; *)
( ulimit -v 400000; "$D" -s 16384x16384 --preview -o "$W/y.png" "$S" ) 2> "$W/big.err"; rc=$?
[ $rc = 1 ] && grep -q "^fixel-draw: $S: " "$W/big.err" && ! grep -q -- "--camera" "$W/big.err" && ok ||
    { bad "a surface error on a .sdl scene: exit $rc"; cat "$W/big.err"; } ;;
esac
# arguments: exit 2
"$D" --camera 0,0,5 0,0,0 0,1,0 40 -o "$W/x.png" "$W/t.fxs" 2> /dev/null; [ $? = 2 ] && ok || bad "--camera with a script"
"$D" --preview -o "$W/x.png" "$W/t.fxs" 2> /dev/null; [ $? = 2 ] && ok || bad "--preview with a script"
"$D" --camera '0,0,5#' 0,0,0 0,1,0 40 -o "$W/x.png" "$S" 2> /dev/null; [ $? = 2 ] && ok || bad "--camera with a #"

echo "sdl-draw: $P passed, $F failed"
[ $F -eq 0 ]
