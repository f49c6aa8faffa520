#!/bin/sh
# SPDX-License-Identifier: MIT
# Wraps the declarations of every public header (kernel-free-src/include/fixel,
# boards/include/fixel) in extern "C" for C++ users. Idempotent: a header that
# already says extern "C" is left alone. The opening goes after the include
# guard and the #include block that follows it (system headers stay outside),
# the closing before the guard's final #endif.
#
# usage: tools/gen/cxx-guards.sh           add where missing
#        tools/gen/cxx-guards.sh --check   "cxx-guards: N passed, N failed"
#        tools/gen/cxx-guards.sh --list    the public headers
set -eu
cd "$(dirname "$0")/../.."
mode=${1:-add}
headers() { ls kernel-free-src/include/fixel/*.h boards/include/fixel/*.h; }

case $mode in
--list) headers ;;
--check)
    p=0; f=0
    for h in $(headers); do
        if grep -q '^extern "C" {' "$h" && grep -q '^}  */\* extern "C" \*/' "$h"; then p=$((p + 1))
        else echo "FAIL $h: no extern \"C\" guard"; f=$((f + 1)); fi
    done
    echo "cxx-guards: $p passed, $f failed"
    [ $f -eq 0 ] ;;
add)
    for h in $(headers); do
        grep -q 'extern "C"' "$h" && continue
        awk '
            { line[NR] = $0 }
            END {
                for (i = 1; i <= NR; i++) if (line[i] ~ /^#endif/) last = i
                guard = 0
                for (i = 2; i <= NR; i++)
                    if (line[i] ~ /^#define / && line[i-1] ~ /^#ifndef /) { guard = i; break }
                if (!guard || !last) { print "cxx-guards: no include guard in " FILENAME > "/dev/stderr"; exit 1 }
                # first line after the guard that is not blank, an #include or a comment
                open = 0; incomment = 0
                for (i = guard + 1; i < last; i++) {
                    s = line[i]
                    if (incomment) { if (s ~ /\*\//) incomment = 0; continue }
                    if (s ~ /^[ \t]*$/ || s ~ /^#include/ || s ~ /^[ \t]*\/\/.*/) continue
                    if (s ~ /^[ \t]*\/\*/) { if (s !~ /\*\//) incomment = 1; continue }
                    open = i; break
                }
                if (!open) open = last
                # back up over the comment block directly above the first declaration
                while (open - 1 > guard && line[open-1] !~ /^[ \t]*$/ && line[open-1] !~ /^#include/) open--
                for (i = 1; i <= NR; i++) {
                    if (i == open)
                        print "#ifdef __cplusplus\nextern \"C\" {\n#endif\n"
                    if (i == last)
                        print "#ifdef __cplusplus\n}  /* extern \"C\" */\n#endif\n"
                    print line[i]
                }
            }' "$h" > "$h.cxx.$$"
        mv "$h.cxx.$$" "$h"
        echo "cxx-guards: $h"
    done ;;
*) echo "usage: $0 [--check|--list]" >&2; exit 2 ;;
esac
