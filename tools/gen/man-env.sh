#!/bin/sh
# SPDX-License-Identifier: MIT
# Rewrites the ENVIRONMENT section of each manual page given (between its
# BEGIN ENVIRONMENT / END ENVIRONMENT comments) from README.md's table of
# FIXEL_* variables, the one list of them (tests/corners/env-corners.sh
# checks env.c and the pages against it).
# usage: tools/gen/man-env.sh PAGE...
set -eu
for page in "$@"; do
    tmp=$page.tmp
    {
        sed '/^\.\\" BEGIN ENVIRONMENT/q' "$page"
        printf '.SH ENVIRONMENT\nThe display and input settings every fixel program reads (a value the\nprogram sets itself wins):\n'
        sed -n 's/^| *`\(FIXEL_[^|]*\)| *\([^|]*\)| *\([^|]*\)|$/\1|\2|\3/p' README.md | grep -v '^FIXEL_GLUT' |
        while IFS='|' read -r names vals what; do
            names=$(printf '%s' "$names" | tr -d '`' | sed -e 's/ *$//' -e 's/_/\\_/g' -e 's/, */ ", " /g')
            vals=$(printf '%s' "$vals" | tr -d '`' | sed -e 's/ *$//' -e 's/\\/\\e/g' -e 's/-/\\-/g')
            what=$(printf '%s' "$what" | tr -d '`' | sed -e 's/ *$//' -e 's/\\/\\e/g' -e 's/-/\\-/g')
            printf '.TP\n.BR %s\n%s: %s\n' "$names" "$vals" "$what"
        done
        sed -n '/^\.\\" END ENVIRONMENT/,$p' "$page"
    } > "$tmp"
    mv "$tmp" "$page"
done
