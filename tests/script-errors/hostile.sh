#!/bin/sh
# SPDX-License-Identifier: MIT
# Every hostile input listed in issue #26, run through the tools: each must
# finish within LIMIT seconds of CPU (default 1; the sanitized build gets 3;
# CPU, as the machine may be shared; 30x LIMIT of wall time catches a run
# that blocks), under
# a memory cap (1 GiB of address space for plain builds, 1 GiB of RSS
# measured for sanitized ones), with no sanitizer report, and with the
# expected exit status and message.
#   sh tests/script-errors/hostile.sh DRAW KIOSK OUTDIR [LIMIT]
draw=$1; kiosk=$2; out=$3; limit=${4:-1}; wall=$((limit * 30))
P=0; F=0
rm -rf "$out"; mkdir -p "$out"
export UBSAN_OPTIONS=halt_on_error=1:exitcode=99:print_stacktrace=1
export ASAN_OPTIONS=exitcode=98:detect_leaks=0
san=0; case "$draw" in *asan*) san=1;; esac
have_time=0; [ -x /usr/bin/time ] && have_time=1
# A sanitized build reserves terabytes of address space for its shadow, so
# it can never run under the plain builds' ulimit -v; its cap is the RSS
# that /usr/bin/time measures (the `time` package, in make test's set).
# Without it the sanitized runs go uncapped and say so once, instead of
# every one failing on the address-space limit (issue #39's fresh root).
[ $san = 1 ] && [ $have_time = 0 ] && echo "hostile: no /usr/bin/time (package time): the sanitized runs' RSS is not measured"

# check NAME WANT_RC MESSAGE-SUBSTRING(or '') COMMAND...
check() {
    name=$1; want=$2; msg=$3; shift 3
    if [ $san = 1 ] && [ $have_time = 1 ]; then
        ( ulimit -t "$limit"; timeout -k 1 "$wall" /usr/bin/time -f '%M' -o "$out/rss" "$@" ) > "$out/stdout" 2> "$out/stderr"; rc=$?
    elif [ $san = 1 ]; then
        ( ulimit -t "$limit"; timeout -k 1 "$wall" "$@" ) > "$out/stdout" 2> "$out/stderr"; rc=$?
        echo 0 > "$out/rss"
    else
        ( ulimit -v 1048576; ulimit -t "$limit"; timeout -k 1 "$wall" "$@" ) > "$out/stdout" 2> "$out/stderr"; rc=$?
        echo 0 > "$out/rss"
    fi
    rss=$(tail -n 1 "$out/rss" 2>/dev/null | tr -dc 0-9); [ -n "$rss" ] || rss=0
    why=""
    [ $rc -eq 124 ] || [ $rc -eq 137 ] && why="over the wall-time limit ($wall s): blocked?"
    [ $rc -eq 152 ] || grep -q 'Command terminated by signal 24' "$out/rss" 2>/dev/null && why="over the CPU limit ($limit s)"
    [ -z "$why" ] && grep -qE 'runtime error|AddressSanitizer|LeakSanitizer' "$out/stderr" && why="sanitizer report"
    [ -z "$why" ] && [ "$rss" -gt 1048576 ] && why="RSS $rss KiB over 1 GiB"
    [ -z "$why" ] && [ $rc -ne "$want" ] && why="exit $rc, wanted $want"
    [ -z "$why" ] && [ -n "$msg" ] && ! grep -qF -- "$msg" "$out/stderr" && why="no '$msg' in the message"
    if [ -z "$why" ]; then P=$((P + 1)); else
        F=$((F + 1)); echo "FAIL $name: $why"; head -c 600 "$out/stderr" | sed 's/^/    /'
    fi
}
# script LINES...: writes $out/s.fxs
script() { printf '%s\n' "$@" > "$out/s.fxs"; }
png=$out/o.png

# ---- scripts: undefined behaviour ----
script "fillpolyf evenodd 32767.99999 0 0 0 0 1"
check fillpolyf-max 1 "X 32767.99999 out of range, expected -32768..32767" "$draw" -o "$png" "$out/s.fxs"
script "fillpolyf evenodd 32767 0 0 0 0 1"
check fillpolyf-in-range 0 "" "$draw" -o "$png" "$out/s.fxs"
script "mandelbrot -128 0 3 10"
check mandelbrot-centre 1 "CRE -128 out of range, expected -16..16" "$draw" -o "$png" "$out/s.fxs"
script "julia 0 0 -128 0 3 10"
check julia-c 1 "C_RE -128 out of range, expected -16..16" "$draw" -o "$png" "$out/s.fxs"
script "colorbar -2147483648 0 10 10"
check colorbar-xmin 0 "" "$draw" -o "$png" "$out/s.fxs"
script "colorbar 0 2147483640 100 10 5"
check colorbar-ticks 0 "" "$draw" -o "$png" "$out/s.fxs"
script "fractline 0 0 100 0 0 1 1"
check fractline-beta0 0 "" "$draw" -o "$png" "$out/s.fxs"
script "coastline 0 1 1 0 0 100 0 50 50"
check coastline-beta0 0 "" "$draw" -o "$png" "$out/s.fxs"
script "light 0 point 0 6 0 #FFFFFF" "shadowplane 0 1 0 1 0 #000000" "scale3d 32767 -32768 32767" "cube 2"
check shadow-scale3d 1 "SX 32767 out of range, expected -1024..1024" "$draw" -o "$png" "$out/s.fxs"
script "light 0 point 0 6 0 #FFFFFF" "shadowplane 0 1 0 1 0 #000000" "scale3d 1024 -1024 1024" "cube 2"
check shadow-scale3d-max 0 "" "$draw" -o "$png" "$out/s.fxs"
script "viewport3d 2147483647 0 1 1" "cube 2" "viewport3d 2147483600 2147483600 16384 16384" "sphere 2 8 8"
check viewport3d-x 0 "" "$draw" -o "$png" "$out/s.fxs"
script "texture checker 8 8 2 #000000 #FFFFFF" "texstyle 40000 0 1" "fillrect 0 0 10 10"
check texstyle-x0 0 "" "$draw" -o "$png" "$out/s.fxs"
awk 'BEGIN { print "v 0 0 0"; print "v 1 0 0"; print "v 0 1 0"; for (i = 0; i < 524289; i++) print "f 1 2 3" }' > "$out/valence.obj"
script "size 8 8" "obj \"$out/valence.obj\""
check obj-valence-2^19 1 "524289 triangles, more than the 262144 one command may draw" "$draw" -o "$png" "$out/s.fxs"
script "sphere 2 1024 8"
check sphere-slices 1 "SLICES 1024 out of range, expected 0..256" "$draw" -o "$png" "$out/s.fxs"
script "size 8 8" "sphere 2 256 256" "torus 2 1 256 256" "teapot 2 64"
check mesh-max 0 "" "$draw" -o "$png" "$out/s.fxs"

# ---- scripts: unbounded work ----
script "colorbar 0 0 10 2000000000"
check colorbar-tall 0 "" "$draw" -o "$png" "$out/s.fxs"
script "colorbar 0 0 2147483647 2147483647 100"
check colorbar-huge 0 "" "$draw" -o "$png" "$out/s.fxs"
mkfifo "$out/fifo"
script "obj \"$out/fifo\""
check obj-fifo 1 "not a regular file (a FIFO, socket or device)" "$draw" -o "$png" "$out/s.fxs"
script "font \"$out/fifo\""
check font-fifo 1 "not a regular file (a FIFO, socket or device)" "$draw" -o "$png" "$out/s.fxs"

# ---- scripts: results and messages ----
script "size 8 8" "polygon 5 5 5 5"
check polygon-point 0 "" "$draw" -o "$out/p.ppm" "$out/s.fxs"
px=$(od -An -j146 -N3 -tu1 "$out/p.ppm" 2>/dev/null | tr -s ' ')
if [ "$px" = " 255 255 255" ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL polygon-point: pixel (5,5) is '$px'"; fi
v=""; i=0; while [ $i -lt 65 ]; do v="$v $i 0 0 0"; i=$((i + 1)); done
script "texture checker 8 8 2 #000000 #FFFFFF" "texpoly$v"
check texpoly-65 1 "vertex 65 out of range, expected 3..64" "$draw" -o "$png" "$out/s.fxs"
printf 'fr\033[31mob\r 1\n' > "$out/s.fxs"
check unknown-escaped 1 'unknown command '"'"'fr\x1b[31mob'"'" "$draw" -o "$png" "$out/s.fxs"
if grep -q "$(printf '\033')" "$out/stderr"; then F=$((F + 1)); echo "FAIL unknown-escaped: raw ESC in the message"; else P=$((P + 1)); fi
: > "$out/empty.obj"
script "obj \"$out/empty.obj\""
check obj-empty 1 "no vertices in the file (it is empty)" "$draw" -o "$png" "$out/s.fxs"

# ---- output paths ----
script "clear #102030"
if [ -c /dev/full ] && [ -w /dev/full ]; then
    check out-dev-full 3 "No space left on device" "$draw" -o /dev/full "$out/s.fxs"
    if [ -c /dev/full ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL /dev/full is no longer a device"; fi
fi
long=$out/$(head -c 5000 /dev/zero | tr '\0' a).png
check out-long-path 3 "File name too long" "$draw" -o "$long" "$out/s.fxs"
ln -sf target.png "$out/link.png"
check out-symlink 0 "" "$draw" -o "$out/link.png" "$out/s.fxs"
if [ -L "$out/link.png" ] && [ -s "$out/target.png" ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL the symlink was replaced"; fi

# ---- gzip inputs ----
if command -v gzip > /dev/null; then
    head -c 32 tests/data/fixel-8x10.psf | gzip > "$out/a.gz"
    tail -c +33 tests/data/fixel-8x10.psf | gzip > "$out/b.gz"
    cat "$out/a.gz" "$out/b.gz" > "$out/two.psf.gz"
    script "font \"$out/two.psf.gz\"" 'text 0 0 "ok"'
    check gzip-two-members 0 "" "$draw" -o "$png" "$out/s.fxs"
    head -c 67108864 /dev/zero | gzip -1 > "$out/64.gz"
    script "font \"$out/64.gz\""
    check gzip-64MiB-exact 1 "not a usable PSF font" "$draw" -o "$png" "$out/s.fxs"
    head -c 67108865 /dev/zero | gzip -1 > "$out/64+1.gz"
    script "font \"$out/64+1.gz\""
    check gzip-64MiB+1 1 "cannot read font" "$draw" -o "$png" "$out/s.fxs"
    rm -f "$out/64.gz" "$out/64+1.gz"
fi

# ---- a PSF2 font whose 48 MiB unicode table matches nothing (61 KB gzipped) ----
if command -v gzip > /dev/null; then
    # magic, version 0, header 32, flags 1 (table), 256 glyphs of 8 bytes, 8x8
    printf '\162\265\112\206\0\0\0\0\040\0\0\0\001\0\0\0\0\001\0\0\010\0\0\0\010\0\0\0\010\0\0\0' > "$out/big.psf"
    head -c 2048 /dev/zero | tr '\0' '\201' >> "$out/big.psf"
    printf '\344\270\201' > "$out/t"
    i=0; while [ $i -lt 24 ]; do cat "$out/t" "$out/t" > "$out/t2"; mv "$out/t2" "$out/t"; i=$((i + 1)); done
    cat "$out/t" >> "$out/big.psf"; rm -f "$out/t"
    gzip -9 < "$out/big.psf" > "$out/big.psf.gz"; rm -f "$out/big.psf"
    script "font \"$out/big.psf.gz\"" "text 0 0 \"h$(printf '\303\251')llo $(printf '\344\270\200\344\270\200') w$(printf '\303\266')rld\""
    check psf-huge-unicode-table 0 "" "$draw" -o "$png" "$out/s.fxs"
    rm -f "$out/big.psf.gz"
fi

# ---- kiosk ----
conf=$out/k.conf
printf 'grid 2x2\nsize 160x120\nhistory 8\nwidget number t col=0 row=0\nwidget spark t col=1 row=0\nwidget bar t col=0 row=1 min=0 max=100\n' > "$conf"
printf 't=9223372036854776\n@frame 1000\nt=-9223372036854775.999\n@frame 1000\n' > "$out/d1"
check kiosk-number-bound 0 "" "$kiosk" --headless --frames 2 --data "$out/d1" "$conf"
printf 't=0\n@frame 1000\nt=80000000000000\n@frame 1000\nt=999999999999999\n@frame 1000\n' > "$out/d2"
check kiosk-spark-counter 0 "" "$kiosk" --headless --frames 3 --data "$out/d2" "$conf"
printf 'grid 1x1\nwidget bar t col=0 row=0 min=-9223372036854775 max=86400000\n' > "$out/k2.conf"
check kiosk-config-range 1 "min=-9223372036854775: expected -1000000000000000..1000000000000000" "$kiosk" --headless --data "$out/d1" "$out/k2.conf"
check kiosk-data-dir 1 "is a directory" "$kiosk" --headless --data "$out" "$conf"
check kiosk-config-dir 1 "is a directory" "$kiosk" --headless --data "$out/d1" "$out"
cp "$conf" "$out/k3.conf"
size=$(wc -c < "$out/k3.conf")
while [ "$size" -lt 65536 ]; do
    n=$((65536 - size)); [ $n -gt 80 ] && n=80
    if [ $n -ge 2 ]; then printf '#%s\n' "$(head -c $((n - 2)) /dev/zero | tr '\0' x)" >> "$out/k3.conf"; else printf '\n' >> "$out/k3.conf"; fi
    size=$(wc -c < "$out/k3.conf")
done
check kiosk-config-65536 0 "" "$kiosk" --headless --data "$out/d1" "$out/k3.conf"
# a PNG whose tEXt chunk declares 2 GiB (it took 2 GB of RSS per load), and a
# valid 2x2 RGBA one with alpha 0, through the kiosk's image widget
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\000\000\002\000\000\000\002\010\006\000\000\000\162\266\015\044\177\377\377\377\164\105\130\164\103\157\155\155\145\156\164\000' > "$out/text2g.png"
head -c 100 /dev/zero | tr '\0' x >> "$out/text2g.png"
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\000\000\002\000\000\000\002\010\006\000\000\000\162\266\015\044\000\000\000\021\111\104\101\124\170\234\143\370\317\300\300\000\302\014\060\006\000\051\350\003\375\001\072\143\176\000\000\000\000\111\105\116\104\256\102\140\202' > "$out/alpha0.png"
for img in text2g alpha0; do
    printf 'grid 1x1\nsize 64x48\nwidget image cam col=0 row=0 path=%s\n' "$out/$img.png" > "$out/img.conf"
    check kiosk-png-$img 0 "" "$kiosk" --headless --frames 2 --data "$out/d1" "$out/img.conf"
done
mkdir -p "$out/imgout"
printf "grid 1x1\nsize 64x48\nwidget image cam col=0 row=0 path=%s\n" "$out/fifo" > "$out/img.conf"
check kiosk-png-fifo 0 "" "$kiosk" --headless --frames 1 --data "$out/d1" --out "$out/imgout" "$out/img.conf"

# device and calibration paths naming a FIFO with no writer: refused, not
# waited on (fixel-shot -d, FIXEL_POINTERCAL)
shot=$(dirname "$draw")/fixel-shot
check shot-fifo 1 "not a device (a FIFO)" "$shot" -d "$out/fifo" -o "$png"
check shot-directory 1 "not a device (a directory)" "$shot" -d "$out" -o "$png"
printf 'grid 1x1\nsize 64x48\nwidget number a col=0 row=0\n' > "$out/pc.conf"
check pointercal-fifo 0 "calibration $out/fifo is not a regular file; ignored" \
    env FIXEL_BACKEND=memory FIXEL_FRAMES=2 FIXEL_POINTERCAL="$out/fifo" "$kiosk" --data "$out/d1" "$out/pc.conf"
check pointercal-directory 0 "calibration $out is not a regular file; ignored" \
    env FIXEL_BACKEND=memory FIXEL_FRAMES=2 FIXEL_POINTERCAL="$out" "$kiosk" --data "$out/d1" "$out/pc.conf"
# issue #40: the live kiosk's DIR/live.ppm must never replace a FIFO or a
# device node with a regular file: refused by name, the node left as it was
mkdir -p "$out/live"; mkfifo "$out/live/live.ppm"; ln -s /dev/null "$out/live/live-null.ppm"
check kiosk-live-fifo 0 "fixel-kiosk: --out $out/live/live.ppm: is a FIFO, not a regular file; live output stopped" \
    env FIXEL_BACKEND=memory FIXEL_FRAMES=2 "$kiosk" --data "$out/d1" --out "$out/live" "$out/pc.conf"
if [ -p "$out/live/live.ppm" ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL kiosk-live-fifo: live.ppm is no longer a FIFO"; fi
rm -f "$out/live/live.ppm"; mv "$out/live/live-null.ppm" "$out/live/live.ppm"
check kiosk-live-device 0 "fixel-kiosk: --out $out/live/live.ppm: is a character device, not a regular file" \
    env FIXEL_BACKEND=memory FIXEL_FRAMES=2 "$kiosk" --data "$out/d1" --out "$out/live" "$out/pc.conf"
if [ -c /dev/null ] && [ -L "$out/live/live.ppm" ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL kiosk-live-device: the link to /dev/null was replaced"; fi

# issue #40: fixel-demo --flight naming a FIFO hung reading it; a FIFO,
# device or directory is refused by name (the file is also written)
demo=$(dirname "$draw")/fixel-demo
check demo-flight-fifo 2 "fixel-demo: --flight $out/fifo: is a FIFO, not a regular file" \
    "$demo" --headless --flight "$out/fifo" --out "$out/demo"
check demo-flight-device 2 "fixel-demo: --flight /dev/null: is a character device, not a regular file" \
    "$demo" --headless --flight /dev/null --out "$out/demo"
check demo-flight-directory 2 "fixel-demo: --flight $out: is a directory, not a regular file" \
    "$demo" --headless --flight "$out" --out "$out/demo"

# ---- display environment and live input ----
script "clear #102030"
check display-stdin-1GB-line 1 "line longer than 1048576 bytes" \
    sh -c "head -c 1000000000 /dev/zero | tr '\\0' x | FIXEL_BACKEND=memory FIXEL_FRAMES=1 \"\$0\" --display -" "$draw"
long=$(head -c 10240 /dev/zero | tr '\0' a)
check drm-device-10KB 0 "drm: File name too long" env FIXEL_DRM_DEVICE="/dev/$long" FIXEL_FRAMES=1 "$draw" --display "$out/s.fxs"
check fb-device-null 0 "fbdev: Inappropriate ioctl for device" env FIXEL_FB_DEVICE=/dev/null FIXEL_FRAMES=1 "$draw" --display "$out/s.fxs"
for r in xyz 1x1 2147483648; do
    check rotation-$r 0 "FIXEL_ROTATION=$r ignored (0, 90, 180 or 270)" \
        env FIXEL_ROTATION=$r FIXEL_BACKEND=memory FIXEL_FRAMES=1 "$draw" --display "$out/s.fxs"
done

# Ctrl-C (SIGINT), timeout (SIGTERM) and a hang-up (SIGHUP) must stop a headless run on an endless source
for sig in INT TERM HUP; do
    timeout -k 2 -s $sig 0.5 "$kiosk" --headless --frames 100000000 --data /dev/zero "$conf" > /dev/null 2>&1; rc=$?
    if [ $rc -eq 124 ]; then P=$((P + 1)); else F=$((F + 1)); echo "FAIL kiosk-headless-SIG$sig: exit $rc (137: only SIGKILL stopped it)"; fi
done

echo "hostile: $P passed, $F failed"
[ $F -eq 0 ]
