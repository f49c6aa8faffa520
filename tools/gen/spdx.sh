#!/bin/sh
# SPDX-License-Identifier: MIT
# Puts an "SPDX-License-Identifier: MIT" line into every source file that has
# none (idempotent: a file that has one in its first 5 lines is left alone).
# Source files: C (.c .h .cc .cpp), shell (.sh, .ci/run, executables starting
# "#!"), python (.py), make (Makefile, .mk, debian/rules).
#   C:            /* SPDX-License-Identifier: MIT */ as the first line
#   others:       # SPDX-License-Identifier: MIT, after a "#!" line if any
#
# usage: tools/gen/spdx.sh            add where missing (run from anywhere)
#        tools/gen/spdx.sh --check    list files without it; "spdx: N passed, N failed"
#        tools/gen/spdx.sh --list     the files it covers
set -eu
cd "$(dirname "$0")/../.."
mode=${1:-add}
TAG="SPDX-License-Identifier: MIT"

files() {
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        git ls-files -co --exclude-standard
    else
        find . -path ./build -prune -o -path ./out -prune -o -path ./.git -prune -o -type f -print | sed 's|^\./||'
    fi | while IFS= read -r f; do
        [ -f "$f" ] || continue
        case $f in
        build/*|out/*|debian/.debhelper/*|debian/tmp/*) continue ;;
        *.c|*.h|*.cc|*.cpp|*.sh|*.py|*.mk|Makefile|*/Makefile|debian/rules|.ci/run) echo "$f" ;;
        tests/fuzz/corpus/*|tests/golden/*|tests/data/*|tests/input/*) ;;
        *) [ -x "$f" ] && head -c 2 "$f" | grep -q '^#!' && echo "$f" ;;
        esac
    done
}

has_tag() { head -n 5 "$1" | grep -q 'SPDX-License-Identifier:'; }

case $mode in
--list) files ;;
--check)
    p=0; f=0
    for x in $(files); do
        if has_tag "$x"; then p=$((p + 1)); else echo "FAIL $x: no $TAG line"; f=$((f + 1)); fi
    done
    echo "spdx: $p passed, $f failed"
    [ $f -eq 0 ] ;;
add)
    n=0
    for x in $(files); do
        has_tag "$x" && continue
        tmp="$x.spdx.$$"
        case $x in
        *.c|*.h|*.cc|*.cpp) { echo "/* $TAG */"; cat "$x"; } > "$tmp" ;;
        *)  if head -n 1 "$x" | grep -q '^#!'; then
                { head -n 1 "$x"; echo "# $TAG"; tail -n +2 "$x"; } > "$tmp"
            else
                { echo "# $TAG"; cat "$x"; } > "$tmp"
            fi ;;
        esac
        chmod --reference="$x" "$tmp" && mv "$tmp" "$x"
        echo "spdx: $x"; n=$((n + 1))
    done
    echo "spdx: added the line to $n file(s)" ;;
*) echo "usage: $0 [--check|--list]" >&2; exit 2 ;;
esac
