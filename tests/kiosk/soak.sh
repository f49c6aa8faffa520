#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-kiosk long run, constant memory (issue #14): LINES scripted data
# lines (every widget type, CSV, garbage, image reloads including corrupt,
# missing and oversized files) through the headless kiosk on the memory
# backend. Resident set and heap in use after warm-up and at the end must
# agree within fixed bounds; with VGLINES > 0 a shorter stream also runs
# under valgrind and must show no error and no leak.
# Usage: soak.sh BIN OUTDIR LINES [VGLINES]
bin=$1; out=$2; lines=${3:-200000}; vglines=${4:-0}
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL: $*"; }
HEAP_BOUND=4096 # bytes
RSS_BOUND=256   # KiB
rm -rf "$out"; mkdir -p "$out"
conf=examples/kiosk-all.conf

# 10 lines a frame; the camera changes every 20 frames through 5 files, so
# the picture (and the decoded image held) repeats every 100 frames
gen() {
    awk -v n="$1" 'BEGIN {
        split("examples/kiosk-logo.png tests/kiosk/img/checker.ppm tests/kiosk/img/corrupt.png tests/kiosk/img/nothere.png tests/kiosk/img/huge.png", img, " ");
        split("this is garbage|temp=abc|=5|field=1,2,3|field[9]=1,2,3,4,5,6,7,8|hum=12=3|temp[1]=4|12:00,x,1,on|\001\002\003", junk, "|");
        long = sprintf("%1100s", ""); gsub(/ /, "x", long); junk[10] = long;
        i = 0; f = 0; j = 0;
        while (i < n) {
            if (f % 20 == 0) { print "cam=" img[int(f / 20) % 5 + 1]; i++ }
            if (f % 100 == 0) { print "time,temp,hum,state"; i++ }
            for (k = 0; k < 8 && i < n; k++) {
                i++; s = (f * 8 + k) % 16;
                if (s == 0) printf "temp=%d.%02d\n", 15 + f % 10, (f * 7) % 100;
                else if (s == 1) printf "hum=%d\n", 30 + f % 50;
                else if (s == 2) printf "tank,%d\n", 200 - f % 200;
                else if (s == 3) printf "state=%s\n", (f % 3 ? "running" : "stopped (low)");
                else if (s == 4) { printf "field="; for (c = 0; c < 48; c++) printf "%s%d.%d", (c ? "," : ""), 15 + (c + f) % 15, c % 10; printf "\n" }
                else if (s == 5) { printf "field[%d]=", f % 6; for (c = 0; c < 8; c++) printf "%s%d", (c ? "," : ""), 15 + (c * f) % 16; printf "\n" }
                else if (s == 6 || s == 7) printf "12:%02d:%02d,%d.5,%d,%s\n", f / 60 % 60, f % 60, 10 + f % 20, 40 + f % 30, (f % 2 ? "running" : "");
                else if (s == 8 || s == 12) print junk[j++ % 10 + 1];
                else if (s == 9) print "# a comment";
                else if (s == 10) print "unknown=3";
                else printf "temp,%d\n", 18 + (f + k) % 7;
            }
            print "@frame 1000"; f++;
        }
    }'
}

gen "$lines" > "$out/stream.txt"
frames=$(grep -c '^@frame' "$out/stream.txt")
# warm up for a tenth of the run, ending on the same phase of the 100-frame
# cycle as the last frame so the same image is held at both measurements
warm=$(( (frames / 10 + 99) / 100 * 100 + (frames - 1) % 100 ))
[ "$warm" -lt "$frames" ] || warm=$((frames - 1))
t0=$(date +%s)
log=$("$bin" --headless --frames "$frames" --mem-report "$warm" --data "$out/stream.txt" $conf 2>/dev/null) ||
    bad "soak run exited $?"
t1=$(date +%s)
echo "$log" | sed 's/^/  /'
w=$(echo "$log" | sed -n 's/.*mem warm frame \([0-9]*\) rss_kb \([0-9]*\) heap_bytes \([0-9]*\).*/\2 \3/p')
e=$(echo "$log" | sed -n 's/.*mem end frame \([0-9]*\) rss_kb \([0-9]*\) heap_bytes \([0-9]*\).*/\2 \3/p')
if [ -z "$w" ] || [ -z "$e" ]; then bad "no memory report"; else
    set -- $w $e
    drss=$(( $3 - $1 )); dheap=$(( $4 - $2 ))
    echo "kiosk-soak: $lines lines, $frames frames in $((t1 - t0)) s; warm-up (frame $warm) rss ${1} KiB heap $2 B; end rss $3 KiB heap $4 B; growth rss $drss KiB heap $dheap B"
    [ "${drss#-}" -le $RSS_BOUND ] && ok || bad "RSS grew by $drss KiB (bound $RSS_BOUND)"
    [ "${dheap#-}" -le $HEAP_BOUND ] && ok || bad "heap grew by $dheap B (bound $HEAP_BOUND)"
    [ "$4" -gt 0 ] && ok || bad "heap in use reads 0: mallinfo2 missing?"
fi
# every garbage line was counted: the stream is bad at a fixed rate
nbad=$(echo "$log" | sed -n 's/.* \([0-9]*\) bad.*/\1/p')
[ -n "$nbad" ] && [ "$nbad" -gt $((frames / 2)) ] && ok || bad "expected garbage counted, got: $log"

if [ "$vglines" -gt 0 ]; then
    if ! command -v valgrind >/dev/null 2>&1; then bad "valgrind is missing (make deps)"; else
        gen "$vglines" > "$out/short.txt"
        vf=$(grep -c '^@frame' "$out/short.txt")
        valgrind --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all --error-exitcode=99 \
            "$bin" --headless --frames "$vf" --size 320x200 --data "$out/short.txt" $conf > "$out/vg.log" 2>&1
        rc=$?
        [ $rc -eq 0 ] && ok || bad "valgrind exit $rc: $(grep -E 'ERROR SUMMARY|lost:|still reachable' "$out/vg.log" | head -5)"
        grep -q "ERROR SUMMARY: 0 errors" "$out/vg.log" && ok || bad "valgrind reports errors"
        grep -q "All heap blocks were freed" "$out/vg.log" && ok || bad "valgrind: blocks left at exit: $(grep -E 'in use at exit' "$out/vg.log")"
        echo "kiosk-soak: valgrind, $vglines lines / $vf frames: $(grep -E 'ERROR SUMMARY' "$out/vg.log" | sed 's/==[0-9]*== //'); $(grep -E 'total heap usage' "$out/vg.log" | sed 's/==[0-9]*== *//')"
    fi
fi
echo "kiosk-soak: $P passed, $F failed"
[ "$F" -eq 0 ]
