#!/bin/sh
# SPDX-License-Identifier: MIT
# Kiosk corner tests generated from the key table (issue #26): every line
# of `fixel-kiosk --keys` (kiosk_keys in tools/fixel-kiosk/kiosk_parse.c).
#  - the directives and widget keys the parser's "unknown ..." messages
#    list must each have a table entry, and every table entry must be one
#    the parser lists: a directive without an entry fails here;
#  - fixel-kiosk(1) lists exactly the table (tools/gen/man-kiosk.sh);
#  - every numeric directive and widget key at min, max, 0, +-1, one past
#    each bound, near 2^15, 2^16, 2^24, 2^31, 2^63: inside the range the
#    kiosk draws (exit 0) or refuses with a message of its own, outside it
#    refuses naming the declared range;
#  - every widget type fed every data value corner, frame by frame, with
#    the widest scale allowed and narrow ones (heat maps: +-2000000).
# Each run has LIMIT s of CPU, 30 x LIMIT of wall time and 1 GiB of memory
# (address space plain, RSS sanitized); a sanitizer report fails it.
#   sh tests/corners/kiosk-corners.sh KIOSK OUTDIR [LIMIT]
kiosk=$1; out=$2; limit=${3:-1}
P=0; F=0
rm -rf "$out"; mkdir -p "$out"
. tests/corners/limits.sh
fail() { F=$((F + 1)); echo "FAIL $1: $2"; [ -f "$out/err" ] && head -c 400 "$out/err" | sed 's/^/    /'; }

# run CONFIG-TEXT [DATA-TEXT [FRAMES]]: sets rc; stderr in $out/err
run() {
    printf '%s\n' "$1" > "$out/c.conf"
    printf '%s\n' "${2:-a=1}" > "$out/d"
    limited "$kiosk" "$kiosk" --headless --frames "${3:-1}" --data "$out/d" "$out/c.conf"
    [ -z "$why" ] && [ $rc -gt 1 ] && why="exit $rc"
}

"$kiosk" --keys > "$out/keys" || { echo "kiosk-corners: --keys failed"; echo "kiosk-corners: 0 passed, 1 failed"; exit 1; }

# ---- the parser's lists against the table ----
run "grid 1x1
no-such-directive 1"
dirs=$(sed -n 's/.*unknown directive (\(.*\)).*/\1/p' "$out/err")
run "grid 1x1
widget number a no-such-key=1"
wkeys=$(sed -n 's/.*unknown widget key (\(.*\)).*/\1/p' "$out/err" | tr -d ';' | sed 's/[a-z]*://g')
[ -n "$dirs" ] && [ -n "$wkeys" ] || { fail lists "no list in the unknown-directive / unknown-key messages"; }
for d in $dirs; do
    if awk -v d="$d" '$1 == "directive" && $2 == d { f = 1 } END { exit !f }' "$out/keys"; then P=$((P + 1)); else fail "directive-$d" "the parser takes it, the table has no entry"; fi
done
for d in $wkeys; do
    if awk -v d="$d" '$1 == "widget" && $2 == d { f = 1 } END { exit !f }' "$out/keys"; then P=$((P + 1)); else fail "widget-key-$d" "the parser takes it, the table has no entry"; fi
done
for d in $(awk '$1 == "directive" { print $2 }' "$out/keys"); do
    case " $dirs " in *" $d "*) P=$((P + 1));; *) fail "directive-$d" "in the table, not in the parser's list";; esac
done
for d in $(awk '$1 == "widget" { print $2 }' "$out/keys"); do
    case " $wkeys " in *" $d "*) P=$((P + 1));; *) fail "widget-key-$d" "in the table, not in the parser's list";; esac
done

# ---- the manual page lists the table as it is ----
cp docs/man/fixel-kiosk.1 "$out/page.1"
if sh tools/gen/man-kiosk.sh "$kiosk" "$out/page.1" && cmp -s docs/man/fixel-kiosk.1 "$out/page.1"; then P=$((P + 1))
else fail man-page "docs/man/fixel-kiosk.1 differs from the table (run tools/gen/man-kiosk.sh)"; fi

# ---- numeric keys at their corners ----
# corners MIN MAX SCALE: "TEXT INSIDE" lines; SCALE 1000 for numbers
# (thousandths: the values are written with three decimals)
corners() {
    awk -v lo="$1" -v hi="$2" -v sc="$3" 'function emit(t, v) { print t, (v >= lo && v <= hi) ? 1 : 0 }
    function dec(v) { if (sc == 1) return sprintf("%d", v); s = v < 0 ? "-" : ""; a = v < 0 ? -v : v;
                      return sprintf("%s%d.%03d", s, int(a / 1000), a % 1000) }
    BEGIN {
        emit(dec(lo), lo); emit(dec(hi), hi); emit("0", 0); emit("1", sc); emit("-1", -sc)
        emit(dec(lo - 1), lo - 1); emit(dec(hi + 1), hi + 1)
        n = split("32767 32768 65535 65536 16777216 2147483647 2147483648", p, " ")
        for (i = 1; i <= n; i++) { emit(p[i], p[i] * sc); emit("-" p[i], -p[i] * sc) }
        # past every int64 (plain and in thousandths): refused whatever the range
        print "9223372036854775807", 0; print "-9223372036854775808", 0; print "9223372036854776", (sc == 1000 ? 0 : 0)
        print "-9223372036854775.999", 0; print "99999999999999999999", 0
    }'
}
# numbers of the table in thousandths (exact: awk has 53 bits, these have at most 19 digits, so split)
milli() { echo "$1" | tr -d '.'; }

awk '$3 == "integer" || $3 == "number" || $3 == "AxB" { print $1, $2, $3, $4 }' "$out/keys" > "$out/numeric"
while read -r scope key type range; do
    lo=${range%%..*}; hi=${range#*..}; sc=1
    if [ "$type" = number ]; then lo=$(milli "$lo"); hi=$(milli "$hi"); sc=1000; fi
    # awk compares the bounds in doubles: these bounds (<= 10^18) and corners differ by far more than the rounding
    corners "$lo" "$hi" "$sc" > "$out/cases"
    while read -r v inside; do
        val=$v; [ "$type" = AxB ] && val="${v}x$lo"
        case "$scope" in
        data) continue;;
        directive)
            if [ "$key" = grid ]; then cfg="grid $val
widget number a col=0 row=0"; else cfg="grid 1x1
$key $val
widget number a col=0 row=0"; fi;;
        mqtt) # headless kiosks parse the broker settings but do not connect
            other="backoff_max=3600"; [ "$key" = backoff_max ] && other="backoff=1"
            cfg="grid 1x1
mqtt host=127.0.0.1 $other $key=$val
widget number a col=0 row=0";;
        mqtt_tls) cfg="grid 1x1
mqtt host=127.0.0.1
mqtt_tls ca=$out/c.conf $key=$val
widget number a col=0 row=0";;
        subscribe) cfg="grid 1x1
mqtt host=127.0.0.1
subscribe t/x $key=$val
widget number a col=0 row=0";;
        screen) cfg="grid 1x1
screen backlight=none $key=$val
widget number a col=0 row=0";;
        output) cfg="output HDMI-A-1 $key=$val
widget number a col=0 row=0";;
        widget)
            ty="number a"; pre=""
            case "$key" in cells) ty="heat a";; smooth) ty="heat a cells=2x2";; quiet) ty="qr a";;
            qos|retain) ty="button b topic=t/x"; pre="mqtt host=127.0.0.1";; esac
            cfg="grid 16x16
size 64x64
$pre
widget $ty $key=$val";;
        page) cfg="grid 1x1
page p $key=$val
widget number a col=0 row=0";;
        carousel|touch) cfg="grid 1x1
$scope $key=$val
page p
widget number a col=0 row=0
page q
widget number a col=0 row=0";;
        *) fail "$scope-$key" "no corner case for a numeric key of scope $scope (add one above)"; continue;;
        esac
        run "$cfg"
        name="$scope-$key=$val"
        if [ -n "$why" ]; then fail "$name" "$why"
        elif [ "$inside" = 1 ] && [ $rc -ne 0 ] && grep -q "$key=.*: expected" "$out/err"; then fail "$name" "inside the table's range, refused as out of range"
        elif [ "$inside" = 1 ] && [ $rc -ne 0 ] && ! grep -qE "outside the grid|min.*max|max.*min|larger than" "$out/err"; then fail "$name" "inside the range, refused: $(head -c 200 "$out/err")"
        elif [ "$inside" = 0 ] && { [ $rc -ne 1 ] || ! grep -q "expected " "$out/err"; }; then fail "$name" "outside the range: exit $rc, wanted 1 and the range"
        else P=$((P + 1)); fi
    done < "$out/cases"
done < "$out/numeric"

# ---- data values: every widget type, every corner, one frame each ----
range=$(awk '$1 == "data" && $2 == "VALUE" { print $4 }' "$out/keys")
corners "$(milli "${range%%..*}")" "$(milli "${range#*..}")" 1000 > "$out/cases"
n=0; : > "$out/data"
while read -r v inside; do
    printf 'a=%s\nb,%s\nh=%s,%s,%s,%s\nh[1]=%s,%s\n@frame 1000\n' "$v" "$v" "$v" "$v" "$v" "$v" "$v" "$v" >> "$out/data"
    n=$((n + 1))
done < "$out/cases"
for ty in number gauge bar spark text clock; do
    for mm in "" "min=-1000000000000 max=1000000000000" "min=0 max=0.001" "min=-9223372036854775 max=86400000"; do
        run "grid 2x1
size 64x32
widget $ty a col=0 row=0 $mm
widget heat h col=1 row=0 cells=2x2 ${mm:+min=-2000000 max=2000000}" "$(cat "$out/data")" "$n"
        name="data-$ty${mm:+-}$(echo "$mm" | tr ' ' ',')"
        if [ -n "$why" ]; then fail "$name" "$why"
        elif [ $rc -ne 0 ] && ! grep -q "expected " "$out/err"; then fail "$name" "exit $rc"
        else P=$((P + 1)); fi
    done
done

echo "kiosk-corners: $P passed, $F failed"
[ $F -eq 0 ]
