#!/bin/sh
# SPDX-License-Identifier: MIT
# A gzip-compressed PSF font renders exactly like the plain one, and a
# corrupt or non-font gzip stream fails with a message and no picture.
draw=$1; out=$2
mkdir -p "$out"
P=0; F=0
ok() { P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
gzip -9 -c tests/data/fixel-12x14.psf > "$out/f.psf.gz"
gzip -9 -c tests/data/fixel-8x10.psf > "$out/g.psf.gz"
for f in fixel-12x14 fixel-8x10; do
    z=$out/f.psf.gz; [ $f = fixel-8x10 ] && z=$out/g.psf.gz
    printf 'size 120 40\nclear #000000\nfont %s\ntext 2 2 "gz 5\342\202\254 caf\303\251"\n' "tests/data/$f.psf" > "$out/plain.fxs"
    printf 'size 120 40\nclear #000000\nfont %s\ntext 2 2 "gz 5\342\202\254 caf\303\251"\n' "$z" > "$out/gz.fxs"
    if "$draw" -o "$out/plain.ppm" "$out/plain.fxs" && "$draw" -o "$out/gz.ppm" "$out/gz.fxs" &&
        cmp -s "$out/plain.ppm" "$out/gz.ppm"; then ok; else bad "$f: .psf.gz renders differently"; fi
    # the text really is drawn (not two blank pictures)
    if [ "$(tail -c +20 "$out/gz.ppm" | tr -d '\000' | wc -c)" -gt 50 ]; then ok; else bad "$f: nothing drawn"; fi
done
head -c 300 "$out/f.psf.gz" > "$out/cut.psf.gz"
printf 'font %s\n' "$out/cut.psf.gz" > "$out/cut.fxs"
rm -f "$out/cut.ppm"
if ! "$draw" -o "$out/cut.ppm" "$out/cut.fxs" 2> "$out/err.txt" && [ -s "$out/err.txt" ] && [ ! -e "$out/cut.ppm" ]; then ok; else bad "truncated gzip accepted"; fi
printf 'not a font' | gzip -c > "$out/text.gz"
printf 'font %s\n' "$out/text.gz" > "$out/text.fxs"
if ! "$draw" -o "$out/text.ppm" "$out/text.fxs" 2> "$out/err.txt" && grep -q "not a usable PSF font" "$out/err.txt"; then ok; else bad "gzip of a non-font accepted"; fi
echo "text-gz: $P passed, $F failed"
[ $F -eq 0 ]
