#!/bin/sh
# SPDX-License-Identifier: MIT
# Builds the corpus against freeglut + Mesa and renders each program's
# compared frame with the LD_PRELOAD shim, under one Xvfb.
#   sh tests/glut/mesa/run.sh OUTDIR [NAME...]
# Environment: GALLIUM_DRIVER (llvmpipe, the reference, or softpipe),
# LP_NUM_THREADS, CC, GLUT_TIMEOUT (seconds a program may take, default 120).
# Writes OUTDIR/NAME.png and OUTDIR/NAME.log; prints one line per program.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:?usage: run.sh OUTDIR [NAME...]}
shift
mkdir -p "$out/bin"
out=$(cd "$out" && pwd)
CC=${CC:-gcc}
sh "$here/mesa/build.sh" "$out" "$@" || exit 1
if [ -z "${DISPLAY_READY:-}" ]; then
    command -v xvfb-run >/dev/null || { echo "glut-mesa: xvfb-run missing (sh tests/glut/deps.sh)"; exit 1; }
    DISPLAY_READY=1 exec xvfb-run -a -s "-screen 0 1600x1200x24 -nolisten tcp" sh "$0" "$out" "$@"
fi
export LIBGL_ALWAYS_SOFTWARE=1
export GALLIUM_DRIVER=${GALLIUM_DRIVER:-llvmpipe}
# llvmpipe's linear rasterizer (an 8-bit fast path for scenes without a clear,
# i.e. the second and later scenes of a frame too big for one) truncates
# colours where its general path rounds: the million-point Mandelbrot changes
# from 48 to 47 red after its 255000th point. The reference is the general
# path, the same in every scene; nothing else in the corpus changes with it.
export LP_PERF=${LP_PERF:-no_rast_linear}
names=$*
[ -n "$names" ] || names=$(awk '!/^#/ && NF {print $1}' "$here/corpus.txt")
rc=0
for n in $names; do
    frame=$(awk -v n="$n" '$1 == n {print $3}' "$here/corpus.txt")
    [ -n "$frame" ] || { echo "glut-mesa: $n is not in corpus.txt"; rc=1; continue; }
    replay=
    [ -f "$here/replay/$n.txt" ] && replay="$here/replay/$n.txt"
    rm -f "$out/$n.png"
    FIXEL_GLUT_FRAMES=$frame FIXEL_GLUT_OUT="$out/$n.png" FIXEL_GLUT_REPLAY=$replay \
        LD_PRELOAD="$out/shim.so" timeout "${GLUT_TIMEOUT:-120}" "$out/bin/$n" >"$out/$n.log" 2>&1
    st=$?
    if [ $st -ne 0 ] || [ ! -f "$out/$n.png" ]; then
        echo "glut-mesa: $n FAILED to render (exit $st, see $out/$n.log)"; rc=1
    else
        echo "glut-mesa: $n rendered frame $frame with $GALLIUM_DRIVER"
    fi
done
exit $rc
