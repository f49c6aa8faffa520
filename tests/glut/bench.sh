#!/bin/sh
# SPDX-License-Identifier: MIT
# Frames per second of the rotating lit teapot (progs/teapot.c) and the
# million-point Mandelbrot (progs/mandelbrot.c), both 800x600, with Mesa's
# llvmpipe on one thread (LP_NUM_THREADS=0) and on all cores, softpipe, and
# fixel's GLUT layer headless when it is built.
#   sh tests/glut/bench.sh [--build DIR] [--out DIR]
# Both sides time themselves with FIXEL_GLUT_BENCH=1 (Mesa through the shim,
# fixel in its GLUT layer): wall clock from the end of frame 1 to the end of
# frame N, so start-up and the first frame are left out. The machine may be
# shared, so each renderer runs GLUT_BENCH_REPS times (default 5, at least
# 1), the renderers interleaved run by run, and the table gives the median
# frames per second, the range (slowest-fastest run) and fixel's median over
# the row's median (> 1: fixel is faster). GLUT_BENCH_TEAPOT /
# GLUT_BENCH_MANDEL set the frames after the first (default 100 and 3).
# The table is also written to OUT/glut-bench.txt.
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

row() { printf 'glut-bench: %-11s %-20s %6s %5s %10s %17s %11s\n' "$@"; }
reps=${GLUT_BENCH_REPS:-5}
[ "$reps" -ge 1 ] 2>/dev/null || reps=1
lib=$build/libfixel-glut.a
GLUT_FIXEL_LIBS=${GLUT_FIXEL_LIBS:-$(pkg-config --libs libpng zlib libdrm libevdev libgpiod 2>/dev/null) -lpthread -lm}
for p in teapot mandelbrot; do
    [ -f "$lib" ] && { $CC -std=gnu11 -O2 -I "$root/boards/glut/include" -o "$out/$p.fixel" "$here/progs/$p.c" \
        "$lib" "$build/libfixel.a" $GLUT_FIXEL_LIBS -lm || rm -f "$out/$p.fixel"; }
done
# One timed run: prints "SECONDS FPS" (empty when it failed).
run_mesa() {  # PROGRAM FRAMES env...
    p=$1 k=$2; shift 2
    env LIBGL_ALWAYS_SOFTWARE=1 FIXEL_GLUT_BENCH=1 FIXEL_GLUT_FRAMES=$((k + 1)) \
        LD_PRELOAD="$out/shim.so" "$@" "$out/bin/$p" 2>/dev/null | grep '^glut-shim: frames' |
        sed -n 's/.* in \([0-9.]*\) s = \([0-9.]*\) fps/\1 \2/p'
}
run_fixel() {  # PROGRAM FRAMES
    [ -x "$out/$1.fixel" ] || return 0
    FIXEL_BACKEND=memory FIXEL_GLUT_BENCH=1 FIXEL_GLUT_FRAMES=$(($2 + 1)) "$out/$1.fixel" 2>/dev/null |
        grep '^fixel-glut: frames' | sed -n 's/.* in \([0-9.]*\) s = \([0-9.]*\) fps/\1 \2/p'
}
# median and range of the fps column of a results file: "MEDIAN MIN MAX N"
stats() { awk 'NF == 2 { print $2 }' "$1" | sort -g | awk '{ v[NR] = $1 } END {
    if (!NR) exit; m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "%.2f %.2f %.2f %d\n", m, v[1], v[NR], NR }'; }
{
row program renderer frames runs "median fps" "range fps" "fixel/this"
for p in teapot mandelbrot; do
    k=$kt; [ $p = mandelbrot ] && k=$km
    : > "$out/$p.l1" ; : > "$out/$p.ln" ; : > "$out/$p.sp" ; : > "$out/$p.fx"
    i=0
    while [ $i -lt "$reps" ]; do
        run_mesa $p $k GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=0 >> "$out/$p.l1"
        run_mesa $p $k GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=$(nproc) >> "$out/$p.ln"
        run_mesa $p $k GALLIUM_DRIVER=softpipe >> "$out/$p.sp"
        run_fixel $p $k >> "$out/$p.fx"
        i=$((i + 1))
    done
    fx=$(stats "$out/$p.fx")
    for r in "l1:llvmpipe 1 thread" "ln:llvmpipe $(nproc) threads" "sp:softpipe" "fx:fixel 1 thread"; do
        if [ "${r%%:*}" = fx ] && [ ! -x "$out/$p.fixel" ]; then
            row "$p" "fixel" "$k" 0 - "not built" -; continue
        fi
        st=$(stats "$out/$p.${r%%:*}")
        [ -n "$st" ] || { row "$p" "${r#*:}" "$k" 0 - "failed" -; continue; }
        set -- $st
        ratio=-
        [ -n "$fx" ] && ratio=$(echo "${fx%% *} $1" | awk '{ printf "%.2f", $1 / $2 }')
        row "$p" "${r#*:}" "$k" "$4" "$1" "$2-$3" "$ratio"
    done
done
} | tee "$out/glut-bench.txt"
