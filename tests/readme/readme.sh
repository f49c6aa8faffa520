#!/bin/sh
# SPDX-License-Identifier: MIT
# Every code block of README.md works as pasted:
#   ```c   a whole program (int main) compiles against this build and runs;
#          a fragment (no main) is skipped, said so
#   ```    a fixel-draw script renders (fixel-draw -o), a replay file
#          (first statement "screen") drives examples/polyline to its end
#   ```sh  commands run from a scratch folder when they only run built
#          programs (FIXEL_... build/...); otherwise every `make ...` line is
#          a target make knows (make -n) and every repository path named exists
# usage: tests/readme/readme.sh BUILD_DIR       "readme: N passed, N failed"
B=${1:-build}
ROOT=$(pwd)
case $B in /*) ;; *) B=$ROOT/$B ;; esac
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "readme: FAIL: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# blocks into $tmp/block-N.LANG, with the README line each starts on
awk -v dir="$tmp" '
/^```/ && !inb { inb = 1; n++; lang = substr($0, 4); if (lang == "") lang = "txt"; f = dir "/block-" n "." lang; print NR > (dir "/block-" n ".line"); next }
/^```/ && inb { inb = 0; close(f); next }
inb { print > f }' README.md
LIBS=$(make --no-print-directory -s print-LDLIBS)
n=0
for f in $(ls "$tmp"/block-*.* | grep -v '\.line$' | sort -t- -k2 -n); do
    n=$((n + 1))
    base=${f%.*}; lang=${f##*.}; at="README.md:$(cat "$base.line")"
    case $lang in
    c)
        if ! grep -q 'int main' "$f"; then echo "readme: $at: a fragment (no main), not run"; continue; fi
        mkdir -p "$tmp/run$n"
        if cc -std=c11 -Wall -Wextra -Werror -I"$ROOT/kernel-free-src/include" -I"$ROOT/boards/include" "$f" \
              -o "$tmp/run$n/prog" "$B/libfixel.a" $LIBS 2> "$tmp/run$n/log" &&
           (cd "$tmp/run$n" && ./prog) >> "$tmp/run$n/log" 2>&1; then ok
        else bad "$at: the C program does not build or run: $(head -5 "$tmp/run$n/log")"; fi ;;
    txt)
        first=$(grep -v '^[[:space:]]*\(#\|$\)' "$f" | head -1 | awk '{print $1}')
        if [ "$first" = screen ]; then
            if [ ! -x "$B/examples/polyline" ]; then bad "$at: a replay file, but $B/examples/polyline is not built (make examples)"; continue; fi
            FIXEL_BACKEND=memory FIXEL_REPLAY="$f" FIXEL_OUT="$tmp/replay$n.png" timeout 60 "$B/examples/polyline" > "$tmp/log$n" 2>&1 &&
                [ -s "$tmp/replay$n.png" ] && ok || bad "$at: the replay file does not run: $(head -3 "$tmp/log$n")"
        else
            timeout 120 "$B/bin/fixel-draw" -o "$tmp/script$n.png" "$f" > "$tmp/log$n" 2>&1 && [ -s "$tmp/script$n.png" ] && ok ||
                bad "$at: the script does not render as pasted: $(grep -v '^$' "$tmp/log$n" | head -3)"
        fi ;;
    sh)
        if ! grep -v '^[[:space:]]*\(#\|$\)' "$f" | grep -qv '^\(FIXEL_\|build/\)'; then
            # only built programs: run them in a scratch folder
            mkdir -p "$tmp/sh$n" && ln -s "$ROOT/examples" "$tmp/sh$n/examples" && ln -s "$B" "$tmp/sh$n/build"
            (cd "$tmp/sh$n" && FIXEL_BACKEND=memory timeout 120 sh "$f") > "$tmp/log$n" 2>&1 && ok ||
                bad "$at: the commands fail: $(head -3 "$tmp/log$n")"
            continue
        fi
        bads=""
        sed 's/#.*//' "$f" | while read -r cmd rest; do
            case $cmd in
            make|sudo) [ "$cmd" = sudo ] && { set -- $rest; cmd=$1; shift; rest=$*; }
                [ "$cmd" = make ] || { echo "$cmd $rest"; continue; }
                make -n -s --no-print-directory $rest > /dev/null 2>&1 || echo "BAD make $rest" ;;
            *) echo "$cmd $rest" ;;
            esac
        done > "$tmp/cmds$n"
        # repository paths the commands name
        for w in $(grep -v '^BAD' "$tmp/cmds$n"); do
            case $w in tests/*|tools/*|examples/*|docs/*|boards/*) [ -e "$w" ] || bads="$bads missing:$w" ;; esac
        done
        bads="$bads$(grep '^BAD' "$tmp/cmds$n" | sed 's/^BAD/ unknown:/' | tr '\n' ' ')"
        [ -z "$(echo "$bads" | tr -d ' ')" ] && ok || bad "$at:$bads" ;;
    *) echo "readme: $at: a $lang block, not checked" ;;
    esac
done
[ $((pass + fail)) -ge 10 ] && ok || bad "only $((pass + fail)) blocks checked: is README.md's fence syntax still \`\`\`?"
echo "readme: $pass passed, $fail failed"
[ $fail -eq 0 ]
