#!/bin/sh
# Frames per second of the rotating lit teapot (progs/teapot.c) and the
# million-point Mandelbrot (progs/mandelbrot.c), both 800x600, with Mesa's
# llvmpipe on one thread (LP_NUM_THREADS=0) and on all cores, softpipe, and
# fixel's GLUT layer headless when it is built.
#   sh tests/glut/bench.sh [--build DIR] [--out DIR]
# Both sides time themselves with FIXEL_GLUT_BENCH=1 (Mesa through the shim,
# fixel in its GLUT layer): wall clock from the end of frame 1 to the end of
# frame N, so start-up and the first frame are left out. GLUT_BENCH_TEAPOT / GLUT_BENCH_MANDEL set the frames after the
# first (default 100 and 3).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=build out=
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        *) echo "usage: bench.sh [--build DIR] [--out DIR]"; exit 2 ;;
    esac
done
case $build in /*) ;; *) build=$root/$build ;; esac
[ -n "$out" ] || out=$build/glut-bench
mkdir -p "$out"
out=$(cd "$out" && pwd)
CC=${CC:-gcc}
kt=${GLUT_BENCH_TEAPOT:-100}
km=${GLUT_BENCH_MANDEL:-3}

if [ -z "${DISPLAY_READY:-}" ]; then
    sh "$here/mesa/build.sh" "$out" teapot mandelbrot || exit 1
    DISPLAY_READY=1 exec xvfb-run -a -s "-screen 0 1600x1200x24 -nolisten tcp" sh "$0" --build "$build" --out "$out"
fi

row() { printf 'glut-bench: %-11s %-22s %6s %9s %9s\n' "$@"; }
row program renderer frames seconds fps
mesa() {  # PROGRAM FRAMES LABEL env...
    p=$1 k=$2 label=$3; shift 3
    line=$(env LIBGL_ALWAYS_SOFTWARE=1 FIXEL_GLUT_BENCH=1 FIXEL_GLUT_FRAMES=$((k + 1)) \
        LD_PRELOAD="$out/shim.so" "$@" "$out/bin/$p" 2>/dev/null | grep '^glut-shim: frames')
    t=$(echo "$line" | sed -n 's/.* in \([0-9.]*\) s = .*/\1/p')
    f=$(echo "$line" | sed -n 's/.* = \([0-9.]*\) fps/\1/p')
    row "$p" "$label" "$k" "${t:-?}" "${f:-failed}"
}
for p in teapot mandelbrot; do
    k=$kt; [ $p = mandelbrot ] && k=$km
    mesa $p $k "llvmpipe 1 thread" GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=0
    mesa $p $k "llvmpipe $(nproc) threads" GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=$(nproc)
    mesa $p $k "softpipe" GALLIUM_DRIVER=softpipe
done

lib=$build/libfixel-glut.a
if [ ! -f "$lib" ]; then
    echo "glut-bench: fixel's GLUT layer is not built ($lib missing): Mesa only"
    exit 0
fi
GLUT_FIXEL_LIBS=${GLUT_FIXEL_LIBS:-$(pkg-config --libs libpng zlib libdrm libevdev libgpiod 2>/dev/null) -lpthread -lm}
for p in teapot mandelbrot; do
    k=$kt; [ $p = mandelbrot ] && k=$km
    $CC -std=gnu11 -O2 -I "$root/boards/glut/include" -o "$out/$p.fixel" "$here/progs/$p.c" \
        "$lib" "$build/libfixel.a" $GLUT_FIXEL_LIBS -lm || { row $p fixel "$k" - "no build"; continue; }
    # the layer times itself like the shim (FIXEL_GLUT_BENCH=1: frame 1 to frame N)
    line=$(FIXEL_BACKEND=memory FIXEL_GLUT_BENCH=1 FIXEL_GLUT_FRAMES=$((k + 1)) "$out/$p.fixel" 2>/dev/null |
           grep '^fixel-glut: frames')
    t=$(echo "$line" | sed -n 's/.* in \([0-9.]*\) s = .*/\1/p')
    f=$(echo "$line" | sed -n 's/.* = \([0-9.]*\) fps/\1/p')
    row $p "fixel 1 thread" "$k" "${t:-?}" "${f:-failed}"
done
