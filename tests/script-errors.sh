#!/bin/sh
# SPDX-License-Identifier: MIT
# Every script error path: fixel-draw must exit non-zero, print
# SCRIPT:LINE:COL: message on stderr, and leave no output file behind.
# Each tests/script-errors/*.fxs starts with "# expect: LINE:COL: message".
draw=$1; out=$2
mkdir -p "$out"
P=0; F=0
for s in tests/script-errors/*.fxs; do
    want=$(sed -n '1s/^# expect: //p' "$s")
    img="$out/$(basename "$s" .fxs).png"
    rm -f "$img"
    "$draw" -o "$img" "$s" 2> "$out/err.txt" > /dev/null
    rc=$?
    got=$(head -n 1 "$out/err.txt")
    if [ $rc -ne 0 ] && [ "$got" = "$s:$want" ] && [ ! -e "$img" ]; then
        P=$((P + 1))
    else
        echo "FAIL $s: exit $rc, stderr '$got', wanted '$s:$want'$( [ -e "$img" ] && echo ', output file was written')"
        F=$((F + 1))
    fi
done
# Command-line errors: each exits non-zero with a message.
check() { # description, expected exit code, args...
    d=$1; code=$2; shift 2
    rm -f "$out/cli.png"
    "$draw" "$@" > /dev/null 2> "$out/err.txt"; rc=$?
    if [ $rc -eq "$code" ] && [ -s "$out/err.txt" ] && [ ! -e "$out/cli.png" ]; then P=$((P + 1))
    else echo "FAIL $d: exit $rc (wanted $code), stderr: $(cat "$out/err.txt")"; F=$((F + 1)); fi
}
check "missing script" 1 -o "$out/cli.png" /nonexistent/script.fxs
check "script is a directory" 1 -o "$out/cli.png" tests
check "bad format" 2 -o "$out/cli.png" -f RGB999 tests/script-errors/unknown-command.fxs
check "bad size" 2 -o "$out/cli.png" -s 0x10 tests/script-errors/unknown-command.fxs
check "unknown option" 2 -o "$out/cli.png" --frobnicate
echo "clear #102030" > "$out/ok.fxs"
check "unwritable output" 3 -o /nonexistent/dir/x.png "$out/ok.fxs"
# And the good path writes a file.
rm -f "$out/ok.png"
if "$draw" -o "$out/ok.png" "$out/ok.fxs" && [ -s "$out/ok.png" ]; then P=$((P + 1)); else echo "FAIL good script wrote no file"; F=$((F + 1)); fi
echo "script-errors: $P passed, $F failed"
[ $F -eq 0 ]
