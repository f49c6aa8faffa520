#!/bin/sh
# SPDX-License-Identifier: MIT
# The GLUT corpus against Mesa: renders every program of corpus.txt with Mesa
# (GALLIUM_DRIVER, default llvmpipe: the reference) and, when fixel's GLUT
# layer is built, with fixel headless, and compares the two frames.
#   sh tests/glut/run.sh [--build DIR] [--out DIR] [NAME...]
# --build: fixel's build directory (default build), holding libfixel-glut.a
#   and libfixel.a; GLUT_FIXEL_LIBS: the libraries they need (glut.mk passes
#   the Makefile's LDLIBS); GLUT_FIXEL_INCLUDE: fixel's GL headers (default
#   boards/glut/include). --out: where frames, logs and diffs go (default
#   BUILD/glut). --frames DIR: compare DIR/NAME.png (frames made some other
#   way, e.g. by mesa/run.sh with softpipe) instead of fixel's.
#   Ends with "glut-mesa: N passed, N failed[, N skipped]".
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=build
out=
frames=
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --frames) frames=$(cd "$2" && pwd); shift 2 ;;
        *) break ;;
    esac
done
case $build in /*) ;; *) build=$root/$build ;; esac
[ -n "$out" ] || out=$build/glut
mkdir -p "$out/mesa" "$out/fixel/bin" "$out/diff"
out=$(cd "$out" && pwd)
CC=${CC:-gcc}
export GLUT_TOOLS=${GLUT_TOOLS:-$out/tools}
names=$*
[ -n "$names" ] || names=$(awk '!/^#/ && NF {print $1}' "$here/corpus.txt")
total=$(echo $names | wc -w)

# ---- Mesa: the reference frames, regenerated every run, in the background
# while fixel's side builds and renders (the two halves share the cores) ----
sh "$here/mesa/run.sh" "$out/mesa" $names > "$out/mesa.log" 2>&1 &
mesa_pid=$!
mesa_done() { wait $mesa_pid; mesa_rc=$?; cat "$out/mesa.log"; }

# ---- fixel ----
lib=$build/libfixel-glut.a
inc=${GLUT_FIXEL_INCLUDE:-$root/boards/glut/include}
if [ -z "$frames" ] && { [ ! -f "$lib" ] || [ ! -d "$inc/GL" ]; }; then
    mesa_done
    echo "glut-mesa: fixel's GLUT layer is not built ($lib missing): only the Mesa half ran"
    echo "glut-mesa: 0 passed, 0 failed, $total skipped"
    exit $mesa_rc
fi
GLUT_FIXEL_LIBS=${GLUT_FIXEL_LIBS:-$(pkg-config --libs libpng zlib libdrm libevdev libgpiod 2>/dev/null) -lpthread -lm}
# Builds progs/NAME.c against fixel and renders its frame headless.
build_and_run() {
    n=$1 frame=$2 bin=$out/fixel/bin/$1
    if ! $CC -std=gnu11 -O2 -Wall -Wextra -I "$inc" -o "$bin" "$here/progs/$n.c" \
            "$lib" "$build/libfixel.a" $GLUT_FIXEL_LIBS -lm >"$out/fixel/$n.build.log" 2>&1; then
        echo "$n: FAIL does not build against fixel (see $out/fixel/$n.build.log)"
        return 1
    fi
    replay=
    [ -f "$here/replay/$n.txt" ] && replay=$here/replay/$n.txt
    rm -f "$out/fixel/$n.png"
    FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=$frame FIXEL_GLUT_OUT="$out/fixel/$n.png" \
        FIXEL_GLUT_REPLAY=$replay timeout "${GLUT_TIMEOUT:-120}" "$bin" >"$out/fixel/$n.log" 2>&1
    st=$?
    if [ $st -ne 0 ] || [ ! -f "$out/fixel/$n.png" ]; then
        echo "$n: FAIL fixel run (exit $st, see $out/fixel/$n.log)"
        return 1
    fi
}

fixel_failed=" "
if [ -z "$frames" ]; then
    for n in $names; do
        frame=$(awk -v n="$n" '$1 == n {print $3}' "$here/corpus.txt")
        build_and_run "$n" "$frame" || fixel_failed="$fixel_failed$n "
    done
fi
mesa_done

pass=0 fail=0
for n in $names; do
    row=$(awk -v n="$n" '$1 == n' "$here/corpus.txt")
    set -- $row
    class=$2 frame=$3 cov=$4 col=$5
    cand=$out/fixel/$n.png
    if [ -n "$frames" ]; then
        cand=$frames/$n.png
    else
        case $fixel_failed in *" $n "*) fail=$((fail + 1)); continue ;; esac
    fi
    if [ ! -f "$out/mesa/$n.png" ]; then
        echo "$n: FAIL no Mesa frame"
        fail=$((fail + 1)); continue
    fi
    if [ ! -f "$cand" ]; then
        echo "$n: FAIL no frame $cand"
        fail=$((fail + 1)); continue
    fi
    if [ "$class" = 3d ]; then
        sh "$here/compare" --name "$n" --diff "$out/diff/$n" "$cand" "$out/mesa/$n.png" 3d "$cov" "$col"
    else
        sh "$here/compare" --name "$n" --diff "$out/diff/$n" "$cand" "$out/mesa/$n.png" 2d
    fi
    if [ $? -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
done
echo "glut-mesa: $pass passed, $fail failed"
[ $fail -eq 0 ]
