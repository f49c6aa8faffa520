#!/bin/sh
# SPDX-License-Identifier: MIT
# The GLUT layer on a Pi architecture (issue #21): course programs of the
# corpus (tests/glut/progs), built against BUILD's libfixel-glut.a with the
# board's cross compiler, run headless under qemu-user, must write exactly
# the frame the same programs write on this x86-64 host (the integer core
# makes them bit-identical; Mesa is not involved: tests/glut compares the
# host frames with llvmpipe).
# usage: glut-frames.sh BOARD CROSS QEMU... (run by tests/arm/test-arm.sh
# after `make BOARD=... STATIC=1 test-bins`); ends "N passed, N failed".
set -u
board=$1 cross=$2; shift 2
# Lit 3D programs (normals, specular through the fixed-point pow, depth), a 2D one
# driven by a mouse replay, the texture-mapped quad, two-sided lighting and the
# local viewer.
progs="solids teapot polyline texquad twoside material"
P=0 F=0
out=build/$board/glut-frames
rm -rf "$out"; mkdir -p "$out/host" "$out/target"
fail() { echo "FAIL glut-frames $board $1: $2"; F=$((F + 1)); }
if ! make --no-print-directory -j2 glut build/libfixel.a > "$out/host-build.log" 2>&1 ||
   ! make --no-print-directory -j2 BOARD="$board" STATIC=1 glut "build/$board/static/libfixel.a" > "$out/build.log" 2>&1; then
    fail build "the layer does not build; see $out/*build.log"
    echo "glut-frames: $P passed, $F failed"; exit 1
fi
host_libs=$(make --no-print-directory -s print-LDLIBS)
tlibs=$(make --no-print-directory -s BOARD="$board" STATIC=1 print-LDLIBS)
tcflags=$(make --no-print-directory -s BOARD="$board" STATIC=1 print-CPU_FLAGS)
for n in $progs; do
    frame=$(awk -v n="$n" '$1 == n { print $3 }' tests/glut/corpus.txt)
    replay=tests/glut/replay/$n.txt; [ -f "$replay" ] || replay=
    if ! gcc -std=gnu11 -O2 -I boards/glut/include tests/glut/progs/$n.c build/libfixel-glut.a build/libfixel.a \
            $host_libs -lm -o "$out/host/$n" 2>> "$out/host-build.log" ||
       ! ${cross}gcc -std=gnu11 -O2 $tcflags -static -I boards/glut/include tests/glut/progs/$n.c \
            build/$board/static/libfixel-glut.a build/$board/static/libfixel.a $tlibs -lm \
            -o "$out/target/$n" 2>> "$out/build.log"; then
        fail "$n" "does not build; see $out/*build.log"; continue
    fi
    for side in host target; do
        run=; [ $side = target ] && run="$*"
        FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=$frame FIXEL_GLUT_OUT=$out/$side/$n.ppm FIXEL_GLUT_REPLAY=$replay \
            $run "$out/$side/$n" > "$out/$side/$n.log" 2>&1 || echo "exit $?" >> "$out/$side/$n.log"
    done
    if [ ! -s "$out/host/$n.ppm" ] || [ ! -s "$out/target/$n.ppm" ]; then
        fail "$n" "no frame written (logs in $out/host, $out/target)"
    elif cmp -s "$out/host/$n.ppm" "$out/target/$n.ppm"; then
        echo "PASS glut-frames $board $n: frame $frame equals x86-64's ($(wc -c < "$out/host/$n.ppm") bytes)"
        P=$((P + 1))
    else
        fail "$n" "frame $frame differs from x86-64's: $out/host/$n.ppm $out/target/$n.ppm"
    fi
done
echo "glut-frames: $P passed, $F failed"
[ $F -eq 0 ]
