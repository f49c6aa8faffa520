#!/bin/sh
# SPDX-License-Identifier: MIT
# FIXEL_* variables at hostile values (issue #26). The variables are those
# of the one table, boards/env/env_table.c (fixel-info --env prints it);
# README.md's environment table lists the same names, every FIXEL_ name the
# code reads must be in it (a variable without an entry fails), and the
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
# OUTDIR is removed and made again: without it "$PWD/" would be removed
[ -n "$draw" ] && [ -n "$out" ] || { echo "usage: sh tests/corners/env-corners.sh DRAW OUTDIR [LIMIT]" >&2; exit 2; }
case $draw in /*) ;; *) draw=$PWD/$draw;; esac
case $out in /*) ;; *) out=$PWD/$out;; esac
P=0; F=0
rm -rf "$out"; mkdir -p "$out/dir"
. tests/corners/limits.sh
mkfifo "$out/fifo"
printf 'clear #102030\n' > "$out/s.fxs"

# The one table (boards/env/env_table.c), as fixel-info --env prints it;
# README.md's table lists the same names, and every FIXEL_ name that any
# file of the library or the tools reads (getenv or fx_env_get) is in it.
table=$(cd "$out" && "$(dirname "$draw")/fixel-info" --env | sed 1d | cut -f1 | sort -u)
[ -n "$table" ] || { echo "env-corners: fixel-info --env printed no table"; echo "env-corners: 0 passed, 1 failed"; exit 1; }
readme=$(sed -n 's/^| *\(`FIXEL_[^|]*\)|.*/\1/p' README.md | grep -o 'FIXEL_[A-Z_]*' | sort -u)
in_list() { case " $(echo $2) " in *" $1 "*) return 0;; esac; return 1; }
for v in $table; do
    if in_list "$v" "$readme"; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL $v: in the table, not in README.md's table"; fi
done
for v in $readme; do
    if in_list "$v" "$table"; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL $v: in README.md's table, not in boards/env/env_table.c"; fi
done
for v in $(grep -rhoE '(getenv|fx_env_get)[[:space:]]*\([[:space:]]*"FIXEL_[A-Z0-9_]*"' boards tools | grep -o 'FIXEL_[A-Z0-9_]*' | sort -u); do
    if in_list "$v" "$table"; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL $v: read by the code, not in boards/env/env_table.c"; fi
done
vars=$(echo "$readme" | grep -v '^FIXEL_GLUT_')

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
