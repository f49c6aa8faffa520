#!/bin/sh
# SPDX-License-Identifier: MIT
# The architecture docs name real files: every `path` in backticks in
# docs/ARCHITECTURE.md, docs/RECIPES.md, boards/README.md and tests/README.md
# that looks like a file or folder of this tree (has a / or a source/doc
# suffix) must exist, read from the top of the tree or, for the short forms
# the docs use in tables ("raster/line.c", "test_line.c"), under the folders
# they abbreviate.
# Names of the API in backticks (fx_..., FX_...) must be in the sources.
# Placeholders (<name>, NAME, *, ...) and commands are skipped.
#   sh tests/check-docs.sh [DOC...]
cd "$(dirname "$0")/.." || exit 1
[ $# -gt 0 ] || set -- docs/ARCHITECTURE.md docs/RECIPES.md boards/README.md tests/README.md
P=0; F=0
for doc in "$@"; do
    # backticked spans, one a line; a span with a space is a command or code
    grep -o '`[^`]*`' "$doc" | tr -d '`' | grep -v ' ' | sort -u > /tmp/check-docs.$$
    while IFS= read -r t; do
        case $t in
        .*|*'<'*|*'*'*|*'...'*|*'…'*|*'$'*|*'{'*|*'|'*|*'='*|*'('*|http*|-*|*'%'*|*:*|*'@'*) continue ;;
        esac
        # a function or type of the API: declared in the sources
        case $t in
        *.h|*.c) ;;
        fx_*|fx3d_*|FX_*)
            s=${t%()}
            if grep -rqw -- "$s" kernel-free-src boards tools; then P=$((P + 1)); else
                F=$((F + 1)); echo "FAIL $doc: \`$t\` is not a symbol of the sources"; fi
            continue ;;
        esac
        case $t in
        */*|*.c|*.h|*.sh|*.md|*.mk|*.fxs|*.png|*.py) ;;
        *) continue ;;
        esac
        # a placeholder in capitals (tests/golden/FORMAT/) names no one file
        echo "$t" | grep -q '[A-Z][A-Z][A-Z]' && ! [ -e "$t" ] && continue
        # what a build writes (build/man/man3 ...) is not in the tree
        case $t in build/*|out/*) continue ;; esac
        # a path of the system (/etc/hosts, /dev/dri), not of the tree
        case $t in /*) continue ;; esac
        p=${t%/}; p=${p#./}
        found=""
        for base in "" kernel-free-src/ kernel-free-src/include/ boards/ boards/include/ tools/ tests/ tests/core/ tests/boards/ tests/tools/ docs/ "$(dirname "$doc")/"; do
            if [ -e "$base$p" ]; then found=1; break; fi
        done
        # bare file names of a table (test_line.c) anywhere in the tree
        if [ -z "$found" ] && [ "${p#*/}" = "$p" ] && [ -n "$(git ls-files "*/$p" "$p" 2>/dev/null | head -n 1)" ]; then found=1; fi
        if [ -n "$found" ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL $doc: \`$t\` names no file or folder of the tree"; fi
    done < /tmp/check-docs.$$
    rm -f /tmp/check-docs.$$
done
echo "docs: $P passed, $F failed"
[ $F -eq 0 ]
