#!/bin/sh
# SPDX-License-Identifier: MIT
# Builds the shim and the corpus the Mesa way: sh build.sh OUTDIR [NAME...]
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
out=$1; shift
CC=${CC:-gcc}
CFLAGS_GLUT=${CFLAGS_GLUT:--std=gnu11 -O2 -Wall -Wextra}
mkdir -p "$out/bin"
if [ ! -f "$out/shim.so" ] || [ "$here/mesa/shim.c" -nt "$out/shim.so" ]; then
    $CC -std=gnu11 -O2 -Wall -Wextra -fPIC -shared -o "$out/shim.so" "$here/mesa/shim.c" \
        $(pkg-config --cflags --libs libpng) -ldl || { echo "glut-mesa: shim failed to build"; exit 1; }
fi
names=$*
[ -n "$names" ] || names=$(awk '!/^#/ && NF {print $1}' "$here/corpus.txt")
for n in $names; do
    src="$here/progs/$n.c"
    [ -f "$src" ] || { echo "glut-mesa: no $src"; exit 1; }
    if [ ! -f "$out/bin/$n" ] || [ "$src" -nt "$out/bin/$n" ]; then
        $CC $CFLAGS_GLUT -o "$out/bin/$n" "$src" -lglut -lGLU -lGL -lm ||
            { echo "glut-mesa: $n failed to build"; exit 1; }
    fi
done
