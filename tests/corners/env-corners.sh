#!/bin/sh
# SPDX-License-Identifier: MIT
# FIXEL_* variables at hostile values (issue #26). The variables are those
# of README.md's environment table; every FIXEL_ name that boards/env/env.c
# reads must be in it (a variable without an entry fails), and the
# ENVIRONMENT sections of fixel-draw(1), fixel-kiosk(1) and fixel-demo(1)
# must be generated from it. Each variable is
# set in turn to: empty, a word no variable takes, 0, -1, 1, 2147483648,
# 9223372036854775808, a 10 KB value, control characters, a directory and
# a FIFO with no writer, and fixel-draw --display runs one frame on the
# memory backend: it must finish within LIMIT s of CPU and 30 x LIMIT of
# wall time in 1 GiB, with no sanitizer report, exit 0 or refuse with a
# message naming the variable (FIXEL_REPLAY: "replay: " and the file), and never echo a raw control character.
#   sh tests/corners/env-corners.sh DRAW OUTDIR [LIMIT]
draw=$1; out=$2; limit=${3:-1}
case $draw in /*) ;; *) draw=$PWD/$draw;; esac
case $out in /*) ;; *) out=$PWD/$out;; esac
P=0; F=0
rm -rf "$out"; mkdir -p "$out/dir"
. tests/corners/limits.sh
mkfifo "$out/fifo"
printf 'clear #102030\n' > "$out/s.fxs"

vars=$(sed -n 's/^| *\(`FIXEL_[^|]*\)|.*/\1/p' README.md | grep -o 'FIXEL_[A-Z_]*' | grep -v '^FIXEL_GLUT_' | sort -u)
[ -n "$vars" ] || { echo "env-corners: no FIXEL_ table in README.md"; echo "env-corners: 0 passed, 1 failed"; exit 1; }
for v in $(grep -o '"FIXEL_[A-Z_]*"' boards/env/env.c | tr -d '"' | sort -u); do
    case " $(echo $vars) " in *" $v "*) P=$((P + 1));; *) F=$((F + 1)); echo "FAIL $v: read by env.c, not in README.md's table";; esac
done

# the manual pages list the table as it is (tools/gen/man-env.sh)
for page in fixel-draw.1 fixel-kiosk.1 fixel-demo.1; do
    cp "docs/man/$page" "$out/$page"
    if sh tools/gen/man-env.sh "$out/$page" && cmp -s "docs/man/$page" "$out/$page"; then P=$((P + 1))
    else F=$((F + 1)); echo "FAIL $page: its ENVIRONMENT section differs from README.md's table (run tools/gen/man-env.sh)"; fi
done

long=$(head -c 10240 /dev/zero | tr '\0' a)
esc=$(printf 'a\033[31mb\rc')
for v in $vars; do
    i=0
    for val in "" "no-such-value" 0 -1 1 2147483648 9223372036854775808 "$long" "$esc" "$out/dir" "$out/fifo"; do
        i=$((i + 1))
        case $v in
        FIXEL_BACKEND) set -- env FIXEL_FRAMES=1;;
        FIXEL_FRAMES) set -- env FIXEL_BACKEND=memory;;
        *) set -- env FIXEL_BACKEND=memory FIXEL_FRAMES=1;;
        esac
        limited "$draw" sh -c 'cd "$0" && exec "$@"' "$out" "$@" "$v=$val" "$draw" --display "$out/s.fxs"
        named=$v; [ $v = FIXEL_REPLAY ] && named="replay: "
        [ -z "$why" ] && [ $rc -ne 0 ] && ! grep -q "$named" "$out/err" && why="exit $rc without naming $v"
        [ -z "$why" ] && grep -q "$(printf '\033')" "$out/err" && why="raw ESC in the message"
        if [ -z "$why" ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL $v value $i: $why"; head -c 300 "$out/err" | sed 's/^/    /'; echo; fi
    done
done
echo "env-corners: $P passed, $F failed"
[ $F -eq 0 ]
