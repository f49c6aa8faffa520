#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-calibrate headless (FIXEL_BACKEND=memory, --points instead of a
# touchscreen): the written pointercal is the inverse of a known wiring,
# also with the display turned; a check point off by more than the
# tolerance and touches on one line write nothing; argument ranges.
# The real touchscreen path is the rig's (tests/kernel/guest/outputs.c).
# usage: calibrate.sh BIN_DIR WORK_DIR
B=${1:-build/bin}; W=${2:-build/tests/calibrate}
T=$B/fixel-calibrate
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
rm -rf "$W"; mkdir -p "$W"
run() { # STATUS NAME ARGS...: exit status STATUS
    st=$1; n=$2; shift 2
    env FIXEL_BACKEND=memory FIXEL_LOG=none "$@" > "$W/$n.out" 2> "$W/$n.err" < /dev/null; rc=$?
    [ "$rc" = "$st" ] && { ok; return 0; }
    bad "$n: exit $rc, want $st"; cat "$W/$n.err"; return 1
}
same() { [ "$2" = "$3" ] && ok || bad "$1: got '$2', want '$3'"; }

# The memory display is 640x480. Wiring: raw = 6*px + 100, 4000 - 9*py
# (physical pixels). Targets: margin 30, the sixth at (W/4, 3H/4).
raw() { # ROTATION: the twelve raw numbers of the six targets
    awk -v r="$1" 'BEGIN {
        W = 640; H = 480; lw = (r == 90 || r == 270) ? H : W; lh = (r == 90 || r == 270) ? W : H; m = 30
        split(m " " lw-1-m " " lw-1-m " " m " " int(lw/2) " " int(lw/4), X, " ")
        split(m " " m " " lh-1-m " " lh-1-m " " int(lh/2) " " int(3*lh/4), Y, " ")
        s = ""
        for (i = 1; i <= 6; i++) {
            x = X[i]; y = Y[i]
            if (r == 90) { px = W-1-y; py = x } else if (r == 180) { px = W-1-x; py = H-1-y }
            else if (r == 270) { px = y; py = H-1-x } else { px = x; py = y }
            s = s (i > 1 ? "," : "") (6*px + 100) "," (4000 - 9*py)
        }
        print s }'
}
want="10923 0 -1092267 0 -7282 29127111 65536 640 480"
for r in 0 90 180 270; do
    run 0 "rot$r" env FIXEL_ROTATION=$r "$T" -o "$W/pc$r" --points "$(raw $r)" &&
        same "rotation $r pointercal" "$(cat "$W/pc$r")" "$want"
    grep -q "^fixel: FIXEL_POINTERCAL=$W/pc$r\$" "$W/rot$r.out" && ok || bad "rot$r: no config line"
done
# the sixth touch 20 raw units off in x (about 3 px): passes at 12, fails at 2
pts=$(raw 0 | awk -F, '{ $11 += 20; OFS = ","; print }' OFS=,)
run 0 near "$T" -o "$W/near" --points "$pts"
run 1 far "$T" -o "$W/far" --tolerance 2 --points "$pts"
[ -e "$W/far" ] && bad "far: a file was written" || ok
grep -q "check point is 3.[0-9] px off (more than 2)" "$W/far.err" && ok || { bad "far: no reason"; cat "$W/far.err"; }
run 1 line "$T" -o "$W/line" --points 100,100,200,200,300,300,400,400,500,500,600,600
[ -e "$W/line" ] && bad "line: a file was written" || ok
run 0 stdout "$T" -o - --points "$(raw 0)" && grep -q "^pointercal: $want\$" "$W/stdout.out" && ok ||
    bad "-o -: no pointercal line"
# -o naming a FIFO (its write hung) or a device: refused by name before
# any touch, the node left as it was (issue #40)
mkfifo "$W/fifo"
run 2 out-fifo timeout 10 "$T" -o "$W/fifo" --points "$(raw 0)" &&
    grep -q "fixel-calibrate: -o $W/fifo: is a FIFO, not a regular file" "$W/out-fifo.err" && [ -p "$W/fifo" ] && ok ||
    bad "out-fifo: no reason or the FIFO was replaced: $(cat "$W/out-fifo.err")"
run 2 out-dir "$T" -o "$W" --points "$(raw 0)" && grep -q "is a directory, not a regular file" "$W/out-dir.err" && ok ||
    bad "out-dir: no reason"
# argument ranges
run 2 margin-low "$T" --margin 3 --points "$(raw 0)"
run 2 margin-big "$T" --margin 300 --points "$(raw 0)" && grep -q "leaves no room on a 640x480" "$W/margin-big.err" && ok || bad "margin-big: no reason"
run 2 timeout-zero "$T" --timeout 0
run 2 tolerance-big "$T" --tolerance 1001
run 2 points-short "$T" --points 1,2,3 && grep -q "error at character 6" "$W/points-short.err" && ok || bad "points-short: no place"
run 2 unknown "$T" --bogus
run 0 help "$T" --help && [ ! -s "$W/help.err" ] && ok || bad "help: not on stdout only"
echo "calibrate: $P passed, $F failed"
[ "$F" = 0 ]
