#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel's GLUT layer alone (layer.c): glutGet, modifiers, stroke and bitmap
# text metrics, glGet round trips, and how glutMainLoop ends after
# glutLeaveMainLoop (freeglut's documented behaviour). Headless.
# usage: layer.sh BUILD   (needs BUILD/libfixel-glut.a); "glut-layer: N passed, N failed"
B=${1:-build}
out=$B/glut/layer
mkdir -p "$out"
P=0 F=0
if ! ${CC:-gcc} -std=gnu11 -O2 -Wall -Wextra -Werror -I boards/glut/include tests/glut/layer.c \
        "$B/libfixel-glut.a" "$B/libfixel.a" ${GLUT_FIXEL_LIBS:-} -lm -o "$out/layer" 2> "$out/build.log"; then
    cat "$out/build.log"; echo "glut-layer: 0 passed, 1 failed"; exit 1
fi
run() { FIXEL_BACKEND=memory "$@" > "$out/run.log" 2>&1; echo $? > "$out/rc"; }
judge() { # name, condition
    if eval "$2"; then P=$((P + 1)); echo "PASS glut-layer $1"; else F=$((F + 1)); echo "FAIL glut-layer $1"; cat "$out/run.log"; fi
}
run env FIXEL_GLUT_FRAMES=1 "$out/layer" api
n_ok=$(grep -c '^ok ' "$out/run.log"); n_fail=$(grep -c '^FAIL ' "$out/run.log")
grep '^FAIL ' "$out/run.log"
judge "api ($n_ok checks)" '[ "$(cat $out/rc)" = 0 ] && [ "$n_fail" = 0 ] && [ "$n_ok" -ge 12 ]'
run "$out/layer" leave-return
judge "leave-returns" '[ "$(cat $out/rc)" = 7 ] && grep -qx "returned frames=3 action=2" "$out/run.log"'
run "$out/layer" leave-exit
judge "leave-exits" '[ "$(cat $out/rc)" = 0 ] && ! grep -q returned "$out/run.log"'
echo "glut-layer: $P passed, $F failed"
[ $F -eq 0 ]
