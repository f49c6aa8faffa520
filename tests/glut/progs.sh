#!/bin/sh
# SPDX-License-Identifier: MIT
# Headless course-style programs through the GLUT layer (the glut-progs
# suite; tests/glut/layer.sh is the layer-API suite): builds
# tests/glut/progs/*.c against build/libfixel-glut.a, runs them with
# FIXEL_BACKEND=memory, FIXEL_GLUT_FRAMES, FIXEL_GLUT_OUT and
# FIXEL_GLUT_REPLAY (layer/bres.in), and checks what they printed, wrote and
# the exit status of bad replays and stalls.
B=${1:-build}
out=$B/glut-progs
mkdir -p "$out"
P=0; F=0
pass() { P=$((P + 1)); echo "ok   $1"; }
fail() { F=$((F + 1)); echo "FAIL $1"; }
LIBS="$B/libfixel-glut.a $B/libfixel.a $(make -s --no-print-directory print-LDLIBS 2>/dev/null) -lm"
# the ASan build's libraries need the sanitizer runtimes at link time
SANF=
nm "$B/libfixel.a" 2>/dev/null | grep -q __asan_ && SANF="-fsanitize=address,undefined"
for lang in c c++; do
    cc="gcc $SANF"; [ $lang = c++ ] && cc="g++ $SANF -x c++"
    if $cc -Wall -Wextra -Werror -Iboards/glut/include tests/glut/layer/bres.c -x none -o "$out/bres-$lang" $LIBS 2>"$out/bres-$lang.log"; then
        pass "bres builds as $lang"
    else
        fail "bres builds as $lang"; cat "$out/bres-$lang.log"
    fi
done
bin=$out/bres-c
rm -f "$out/bres1.png"
FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_OUT="$out/bres1.png" "$bin" >/dev/null 2>&1
[ -s "$out/bres1.png" ] && pass "FIXEL_GLUT_FRAMES=1 writes FIXEL_GLUT_OUT" || fail "FIXEL_GLUT_FRAMES=1 writes FIXEL_GLUT_OUT"
log=$(FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=3 FIXEL_GLUT_OUT="$out/bres6.ppm" FIXEL_GLUT_REPLAY=tests/glut/layer/bres.in "$bin" 2>&1)
echo "$log" | grep -q '^key 113$' && pass "replayed key reaches glutKeyboardFunc" || fail "replayed key ($log)"
echo "$log" | grep -q '^key 65$' && pass "raw evdev shift+a gives 'A'" || fail "raw evdev shift+a ($log)"
echo "$log" | grep -q '^menu 2$' && pass "menu entry chosen by mouse" || fail "menu entry ($log)"
echo "$log" | grep -q 'key 3[0-9]' && fail "menu click leaked to keyboard" || pass "nothing leaked"
# the picture: the Bresenham line's first point and the polyline in cyan-ish (0,1,1)
if [ -s "$out/bres6.ppm" ]; then
    px=$(python3 -c "
d=open('$out/bres6.ppm','rb').read(); p=d.split(b'\n',3); w,h=map(int,p[1].split()); b=p[3]
def at(x,y): i=(y*w+x)*3; return tuple(b[i:i+3])
print(at(10,149-12), at(60,25))" 2>/dev/null)
    case "$px" in "(0, 255, 255) (0, 255, 255)") pass "frame after the menu: cyan line and polyline";;
                  *) fail "frame after the menu: $px";; esac
else
    fail "FIXEL_GLUT_FRAMES=3 wrote no frame"
fi
# a replay line that does not parse: exit 5 naming the line; waiting for a
# frame that never comes: exit 3
printf 'frame 1: key a\nframe 1: jump 3 4\n' > "$out/bad.txt"
msg=$(FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=2 FIXEL_GLUT_REPLAY="$out/bad.txt" "$bin" 2>&1); st=$?
[ $st -eq 5 ] && echo "$msg" | grep -q 'line 2' && pass "bad replay line exits 5 naming it" || fail "bad replay line (exit $st: $msg)"
printf 'frame 2: key a\nframe 1: key b\n' > "$out/bad.txt"
FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=2 FIXEL_GLUT_REPLAY="$out/bad.txt" "$bin" >/dev/null 2>&1
st=$?; [ $st -eq 5 ] && pass "decreasing frame numbers exit 5" || fail "decreasing frame numbers (exit $st)"
printf 'frame 9: key a\n' > "$out/late.txt"
FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=10 FIXEL_GLUT_REPLAY="$out/late.txt" "$bin" >/dev/null 2>&1
st=$?; [ $st -eq 3 ] && pass "a replay waiting for a frame that never comes exits 3" || fail "stall (exit $st)"
# user-named paths that are not regular files (issue #40): a FIFO named by
# FIXEL_GLUT_REPLAY used to block in open() for ever, a directory was taken
# as an empty replay; a FIXEL_GLUT_OUT that cannot be written exited 0
rm -f "$out/fifo"; mkfifo "$out/fifo"; mkdir -p "$out/adir"
msg=$(FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_REPLAY="$out/fifo" timeout 10 "$bin" 2>&1); st=$?
[ $st -eq 5 ] && echo "$msg" | grep -q "FIXEL_GLUT_REPLAY=$out/fifo: is a FIFO, not a regular file" &&
    pass "FIXEL_GLUT_REPLAY naming a FIFO exits 5 at once, naming it" || fail "FIXEL_GLUT_REPLAY FIFO (exit $st: $msg)"
msg=$(FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_REPLAY="$out/adir" timeout 10 "$bin" 2>&1); st=$?
[ $st -eq 5 ] && echo "$msg" | grep -q "FIXEL_GLUT_REPLAY=$out/adir: is a directory, not a regular file" &&
    pass "FIXEL_GLUT_REPLAY naming a directory exits 5 naming it" || fail "FIXEL_GLUT_REPLAY directory (exit $st: $msg)"
msg=$(FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_OUT="$out/fifo" timeout 10 "$bin" 2>&1); st=$?
[ $st -eq 6 ] && echo "$msg" | grep -q "FIXEL_GLUT_OUT=$out/fifo: is a FIFO, not a regular file" &&
    pass "FIXEL_GLUT_OUT naming a FIFO exits 6 naming it" || fail "FIXEL_GLUT_OUT FIFO (exit $st: $msg)"
msg=$(FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_OUT="$out/no/such/dir/x.png" timeout 10 "$bin" 2>&1); st=$?
[ $st -eq 6 ] && echo "$msg" | grep -q "FIXEL_GLUT_OUT=$out/no/such/dir/x.png: cannot write" &&
    pass "a FIXEL_GLUT_OUT that cannot be written exits 6 naming it" || fail "unwritable FIXEL_GLUT_OUT (exit $st: $msg)"
rm -f "$out/fifo"
# a display asked for by name that cannot open ends the program (issue #20);
# only the automatic choice falls back to a memory window
if [ ! -e /dev/dri ] && [ ! -e /dev/fb0 ]; then
    msg=$(FIXEL_BACKEND=drm FIXEL_GLUT_FRAMES=1 "$bin" 2>&1); st=$?
    [ $st -eq 1 ] && echo "$msg" | grep -q 'no drm display' && pass "FIXEL_BACKEND=drm without DRM exits 1 with the reason" ||
        fail "FIXEL_BACKEND=drm without DRM (exit $st: $msg)"
    rm -f "$out/auto.png"
    env -u FIXEL_BACKEND FIXEL_GLUT_FRAMES=1 FIXEL_GLUT_OUT="$out/auto.png" "$bin" >/dev/null 2>&1; st=$?
    [ $st -eq 0 ] && [ -s "$out/auto.png" ] && pass "automatic display choice falls back to memory" ||
        fail "automatic fallback (exit $st)"
fi
echo "glut-progs: $P passed, $F failed"
[ $F -eq 0 ]
