#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-bench --w3-classes runs and prints what docs/PERFORMANCE.md reads
# off it: per format, the three classes of W3's lines (all 100000 of them,
# their pixel shares adding up to the whole), ns per pixel for each peer,
# the store floor on the steep and mid rows only, and the whole-W3 line. Timings are
# not judged (make bench measures them).
# Usage: w3classes-check.sh BINDIR OUTDIR
bin=$1/fixel-bench; out=$2
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
mkdir -p "$out"
if "$bin" --w3-classes -p fixel -t 3 > "$out/all.txt" 2>&1; then ok; else bad "--w3-classes exited $?: $(tail -3 "$out/all.txt")"; fi
for f in xrgb8888 rgb565; do
    # the rows of format f: from its name to the blank line after it
    awk -v f="$f" '$0 == f { on = 1; next } on && /^$/ { exit } on' "$out/all.txt" > "$out/$f.txt"
    [ "$(grep -c '^steep \|^mid \|^shallow ' "$out/$f.txt")" -eq 3 ] && ok || bad "$f: not 3 class rows: $(cat "$out/$f.txt")"
    # class rows: name (1-4 words), lines, px%, then cells; sum the lines and shares
    sums=$(grep '^steep \|^mid \|^shallow ' "$out/$f.txt" | awk '{
        for (i = 1; i <= NF; i++) if ($i ~ /^[0-9.]+%$/) { n += $(i - 1); p += $i + 0; break } }
        END { printf "%d %.1f", n, p }')
    [ "${sums% *}" = 100000 ] && ok || bad "$f: the classes hold ${sums% *} lines, not 100000"
    awk -v p="${sums#* }" 'BEGIN { exit !(p >= 99.8 && p <= 100.2) }' && ok || bad "$f: shares add up to ${sums#* }%"
    # fixel's cell and the floor: "m [lo-hi]" numbers; the floor on the steep and mid rows
    [ "$(grep '^steep \|^mid ' "$out/$f.txt" | grep -Ec '%( +[0-9]+\.[0-9]+ \[ *[0-9.]+- *[0-9.]+\]){2}')" -eq 2 ] && ok ||
        bad "$f: steep and mid rows lack fixel's and the floor's cells: $(grep '^steep\|^mid' "$out/$f.txt")"
    [ "$(grep '^shallow ' "$out/$f.txt" | grep -Ec '\] +- *$')" -eq 1 ] && ok ||
        bad "$f: the shallow row should show no floor: $(grep '^shallow' "$out/$f.txt")"
    grep -q '^all of W3 .*100000 100.0%' "$out/$f.txt" && ok || bad "$f: no whole-W3 line"
    # the floor stores fixel's very pixels (a 45-degree line drawn flat once made it cheaper)
    [ "$(grep -c '^floor of the \(steep\|mid\) lines: the same pixels as fixel.s$' "$out/$f.txt")" -eq 2 ] && ok ||
        bad "$f: the floor's pixels are not fixel's: $(grep '^floor of' "$out/$f.txt")"
done
"$bin" --w3-classes -p fixel -t 3 -f rgb565 > "$out/565.txt" 2>&1
grep -qx xrgb8888 "$out/565.txt" && bad "-f rgb565 printed xrgb8888" || ok
grep -qx rgb565 "$out/565.txt" && ok || bad "-f rgb565: no rgb565 table"
# With the peer libraries built in, the best peer's ratio is named.
if "$bin" --peers --check -w W3 2>&1 | grep -q "built without"; then
    echo "w3classes-check: built without the peer libraries; the ratio column is not checked"
else
    "$bin" --w3-classes -p fixel,sdlgfx -t 3 -f xrgb8888 > "$out/gfx.txt" 2>&1
    [ "$(grep -c '^steep .* x sdlgfx$\|^mid .* x sdlgfx$\|^shallow .* x sdlgfx$' "$out/gfx.txt")" -eq 3 ] && ok ||
        bad "-p fixel,sdlgfx: rows without the ratio to sdlgfx: $(cat "$out/gfx.txt")"
    grep -q "the sum of the classes: [0-9.]* x the best peer" "$out/gfx.txt" && ok || bad "no whole-W3 ratio"
fi
echo "w3classes-check: $P passed, $F failed"
[ "$F" -eq 0 ]
