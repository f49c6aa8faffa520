#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk --threads (issue #27): a frame drawn in bands of rows on 2, 3
# and 4 threads (and, for one config, 0: every core) must be, byte for byte,
# the one-thread frame. Every examples/kiosk-*.conf, fed a stream that reaches every widget
# (pages turned by the carousel, stale sources, images good and bad), plus a
# config with two output sections, in XRGB8888 and RGB565, both redrawing
# everything (--full) and from damage only (where only the damage's rows
# are cut into bands).
# A widget drawing outside its band writes the same pixels as the band that
# owns them, so the comparison cannot see it; a ThreadSanitizer build can
# (it reports the two threads' writes): given TSAN_BIN, every config also
# runs on 3 threads under it and must draw without a report. Build it with
#   make BUILD=build/tsan SANFLAGS=-fsanitize=thread build/tsan/bin/fixel-kiosk
# (not part of make test; replacing a widget's clip instead of narrowing it
# to the band was caught this way, and passed the comparison).
# Usage: threads.sh BIN OUTDIR [TSAN_BIN]
bin=$1; out=$2; tsan=$3
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
rm -rf "$out"; mkdir -p "$out"

# the sources of the configs without a stream of their own (fleet, pages):
# values that change every frame, a text that changes, then silence (stale)
gen=$out/stream-gen.txt
i=0
while [ $i -lt 30 ]; do
    printf 'temp=%d.%d\nhum=%d\nbatt=%d\npower=%d\nwatts=%d\nstatus=run %d\n@frame 1000\n' \
        $((15 + i % 9)) $((i * 7 % 10)) $((30 + i * 3 % 50)) $((100 - i)) $((800 + i * 37 % 400)) \
        $((i * 97 % 3000)) $i >> "$gen"
    i=$((i + 1))
done
printf 'stale 20\noutput HDMI-A-1 size=320x240\ntitle Left\ngrid 2x1\nwidget number temp col=0 row=0 decimals=1 unit=C\n'\
'widget gauge hum col=1 row=0 min=0 max=100\noutput HDMI-A-2 size=240x320\ngrid 1x2\n'\
'widget bar batt col=0 row=0 min=0 max=100\nwidget spark power col=0 row=1\n' > "$out/two.conf"

run() { # NAME CONF STREAM FRAMES FORMAT MODE THREADS
    d=$out/$1-$5-$6-$7; mkdir -p "$d"
    m=; [ "$6" = full ] && m=--full
    "$bin" --headless $m --threads "$7" --frames "$4" --format "$5" --out "$d" --data "$3" "$2" > "$d.log" 2>&1 ||
        bad "$1 $5 $6 --threads $7 exited $?: $(cat "$d.log")"
}

for conf in examples/kiosk-*.conf "$out/two.conf"; do
    name=$(basename "$conf" .conf)
    case $name in
    kiosk-basic) stream=tests/kiosk/stream.txt; n=12 ;;
    kiosk-all) stream=tests/kiosk/stream-all.txt; n=12 ;;
    kiosk-pages) stream=$gen; n=45 ;; # its carousel shows all three pages by frame 40
    *) stream=$gen; n=40 ;;
    esac
    for fmt in XRGB8888 RGB565; do
        for mode in full damage; do
            run "$name" "$conf" "$stream" $n $fmt $mode 1
            ref=$out/$name-$fmt-$mode-1
            nref=$(ls "$ref" | wc -l)
            # screens of output sections write one file per screen a frame
            if [ "$nref" -ge "$n" ]; then ok; else bad "$name $fmt $mode: $nref frames written, expected $n"; fi
            # 0 (every core) once: on a two-core machine it is 2 again
            ts="2 3 4"; [ "$name-$fmt-$mode" = kiosk-all-XRGB8888-damage ] && ts="2 3 4 0"
            for t in $ts; do
                run "$name" "$conf" "$stream" $n $fmt $mode $t
                d=$out/$name-$fmt-$mode-$t
                diffs=0
                for f in "$ref"/*.png; do
                    cmp -s "$f" "$d/$(basename "$f")" || { diffs=$((diffs + 1)); [ $diffs -le 3 ] &&
                        echo "  $name $fmt $mode --threads $t: $(basename "$f") differs from one thread"; }
                done
                if [ $diffs -eq 0 ] && [ "$(ls "$d" | wc -l)" -eq "$nref" ]; then ok
                else bad "$name $fmt $mode --threads $t: $diffs of $nref frames differ from one thread"; fi
            done
        done
    done
    # the frames are not all one picture (the comparison above would be
    # weak if nothing moved): the first and the last frame differ
    first=$(ls "$out/$name-XRGB8888-damage-1"/*.png | head -1); last=$(ls "$out/$name-XRGB8888-damage-1"/*.png | tail -1)
    if cmp -s "$first" "$last"; then bad "$name: first and last frame are the same picture"; else ok; fi
done

if [ -n "$tsan" ]; then
    for conf in examples/kiosk-*.conf "$out/two.conf"; do
        name=$(basename "$conf" .conf)
        stream=$gen; case $name in kiosk-basic) stream=tests/kiosk/stream.txt ;; kiosk-all) stream=tests/kiosk/stream-all.txt ;; esac
        TSAN_OPTIONS="halt_on_error=1 exitcode=66" "$tsan" --headless --threads 3 --frames 12 --data "$stream" "$conf" \
            > "$out/tsan-$name.log" 2>&1
        rc=$?
        if [ $rc -eq 0 ] && ! grep -q ThreadSanitizer "$out/tsan-$name.log"; then ok
        else bad "$name under ThreadSanitizer (exit $rc): $(grep -m1 -A3 ThreadSanitizer "$out/tsan-$name.log")"; fi
    done
fi

# bad thread counts are refused with the range, exit 2
for v in -1 65 x 2x ""; do
    "$bin" --headless --threads "$v" --data /dev/null examples/kiosk-basic.conf > "$out/bad.log" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -q "0 (every core) to 64" "$out/bad.log"; then ok; else bad "--threads '$v': exit $rc, $(cat "$out/bad.log")"; fi
done
"$bin" --help | grep -q -- "--threads N" && ok || bad "--help does not name --threads"
# the other numeric options are whole strings in their ranges too
for a in "--size 100x100x" "--size 8x8" "--mem-report 3q" "--mem-report -1" "--frames 2x"; do
    # shellcheck disable=SC2086
    "$bin" --headless $a --data /dev/null examples/kiosk-basic.conf > "$out/bad.log" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -q "wants .* from .* to .*, not" "$out/bad.log"; then ok; else bad "$a: exit $rc, $(cat "$out/bad.log")"; fi
done
echo "kiosk-threads: $P passed, $F failed"
[ "$F" -eq 0 ]
