#!/bin/sh
# SPDX-License-Identifier: MIT
# Self-checking GLUT programs (tests/glut/self/*.c), each built against
# fixel's layer (run headless) and, when freeglut, Mesa and xvfb-run are
# installed (sh tests/glut/deps.sh), against freeglut + Mesa under Xvfb:
# both must print the expected lines, so the expectations are freeglut's.
# Also what a headless run tells the user (issue #39).
# usage: self.sh BUILD   (needs BUILD/libfixel-glut.a); "glut-self: N passed, N failed"
B=${1:-build}
out=$B/glut/self
mkdir -p "$out"
P=0 F=0
pass() { P=$((P + 1)); echo "PASS glut-self $1"; }
fail() { F=$((F + 1)); echo "FAIL glut-self $1"; [ -f "$2" ] && cat "$2"; }
if ! ${CC:-gcc} -std=gnu11 -O2 -Wall -Wextra -Werror -I boards/glut/include tests/glut/self/winlife.c \
        "$B/libfixel-glut.a" "$B/libfixel.a" ${GLUT_FIXEL_LIBS:-} -lm -o "$out/winlife" 2> "$out/build.log"; then
    cat "$out/build.log"; echo "glut-self: 0 passed, 1 failed"; exit 1
fi
for prog in glyphs lists; do
    ${CC:-gcc} -std=gnu11 -O2 -Wall -Wextra -Werror -I boards/glut/include tests/glut/self/$prog.c \
        "$B/libfixel-glut.a" "$B/libfixel.a" ${GLUT_FIXEL_LIBS:-} -lm -o "$out/$prog" 2>> "$out/build.log" ||
        { cat "$out/build.log"; echo "glut-self: 0 passed, 1 failed"; exit 1; }
done
# The Mesa side is built without the sanitizers CC may carry (SAN=1):
# Mesa and the X libraries are not ours to check, and leak at exit.
mcc=${CC:-gcc}; mcc=${mcc%% *}
mesa=
if command -v xvfb-run >/dev/null && $mcc -std=gnu11 -O2 -o "$out/winlife-mesa" \
        tests/glut/self/winlife.c -lglut -lGL 2> "$out/build-mesa.log" &&
        $mcc -std=gnu11 -O2 -o "$out/glyphs-mesa" tests/glut/self/glyphs.c -lglut -lGL 2>> "$out/build-mesa.log" &&
        $mcc -std=gnu11 -O2 -o "$out/lists-mesa" tests/glut/self/lists.c -lglut -lGL 2>> "$out/build-mesa.log"; then
    mesa=1
else
    echo "glut-self: freeglut/Mesa/xvfb-run absent: the Mesa half is skipped (sh tests/glut/deps.sh)"
fi
# mode, wanted exit status, wanted stdout (lines joined by spaces)
cases='size-before-init|0|ok window-width ok window-height ok init-width ok init-height ok init-x ok init-y ok viewport-width ok viewport-height close
destroy-outside|7|returned ok current-window close
destroy-exit|0|display destroyed close
destroy-return|7|display destroyed close returned
destroy-create|7|ok second-id ok second-width ok second-height ok second-pixel close returned'
echo "$cases" > "$out/cases"
while IFS='|' read -r mode rc want; do
    FIXEL_BACKEND=memory "$out/winlife" "$mode" > "$out/$mode.out" 2> "$out/$mode.err"
    got_rc=$?
    got=$(tr '\n' ' ' < "$out/$mode.out" | sed 's/ $//')
    if [ "$got_rc" = "$rc" ] && [ "$got" = "$want" ]; then pass "fixel $mode"
    else echo "  exit $got_rc, stdout: $got"; fail "fixel $mode" "$out/$mode.err"; fi
done < "$out/cases"
if [ -n "$mesa" ]; then
    cat > "$out/mesa.sh" <<M
while IFS='|' read -r mode rc want; do
    LIBGL_ALWAYS_SOFTWARE=1 timeout 60 "$out/winlife-mesa" "\$mode" > "$out/\$mode.mesa" 2>&1
    echo "\$mode \$?" >> "$out/mesa.rc"
done < "$out/cases"
LIBGL_ALWAYS_SOFTWARE=1 timeout 120 "$out/glyphs-mesa" > "$out/glyphs.mesa" 2>&1
LIBGL_ALWAYS_SOFTWARE=1 timeout 60 "$out/lists-mesa" > "$out/lists.mesa" 2> "$out/lists.mesa.err"
M
    rm -f "$out/mesa.rc"
    xvfb-run -a -s "-screen 0 1024x768x24 -nolisten tcp" sh "$out/mesa.sh"
    while IFS='|' read -r mode rc want; do
        got_rc=$(awk -v m="$mode" '$1 == m {print $2}' "$out/mesa.rc" 2>/dev/null)
        got=$(tr '\n' ' ' < "$out/$mode.mesa" | sed 's/ $//')
        if [ "$got_rc" = "$rc" ] && [ "$got" = "$want" ]; then pass "mesa $mode"
        else echo "  exit $got_rc, output: $got"; fail "mesa $mode"; fi
    done < "$out/cases"
fi
# Issue #38: what glNewList(GL_COMPILE) holds (self/lists.c): every line
# "ok", and, with Mesa, the same lines Mesa prints.
FIXEL_BACKEND=memory "$out/lists" > "$out/lists.fixel" 2> "$out/lists.err"
st=$?
if [ $st = 0 ] && [ "$(grep -c '^ok ' "$out/lists.fixel")" -ge 28 ] && ! grep -qv '^ok ' "$out/lists.fixel"
then pass "fixel lists: $(wc -l < "$out/lists.fixel") checks"; else echo "  exit $st"; grep -v '^ok' "$out/lists.fixel"; fail "fixel lists" "$out/lists.err"; fi
if [ -n "$mesa" ]; then
    if cmp -s "$out/lists.mesa" "$out/lists.fixel"; then pass "mesa lists: the same lines"
    else diff "$out/lists.mesa" "$out/lists.fixel" | head -10; fail "mesa lists" "$out/lists.mesa.err"; fi
fi
# Issue #37: every glyph of every bitmap font as freeglut draws it, from the
# X11 fonts of xfonts-base/xfonts-75dpi. The glyphs freeglut's data hold in
# an older drawing than today's fonts (tests/glut/README.md, "Bitmap fonts")
# are listed: the differing set must be exactly that, so a regression and
# a fix both show. Heights, widths, raster moves, glutBitmapLength and the
# newline of glutBitmapString must all agree.
if [ -n "$mesa" ]; then
    FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=0 "$out/glyphs" > "$out/glyphs.fixel" 2> "$out/glyphs.err"
    if grep -q "instead of freeglut's" "$out/glyphs.err"; then
        fail "glyphs: the X11 fonts did not load (apt-get install xfonts-base xfonts-75dpi)" "$out/glyphs.err"
    else
        known='8x13: 39 42 45 66 68 96 168 207 214 217 224 225 226 227 228 232 233 234 235 236 237 238 239 241 242 243 244 245 246 249 250 251 252 253 255
9x15: 36 39 42 55 66 68 69 70 96 208
times10: 96
times24: 39 47 96
helv10: 96
helv12:
helv18:'
        echo "$known" | while IFS=: read -r font want; do
            got=$(diff "$out/glyphs.mesa" "$out/glyphs.fixel" | awk -v f="$font" '$1 == "<" && $2 == f && $3 == "c" {printf " %s", $4}')
            other=$(diff "$out/glyphs.mesa" "$out/glyphs.fixel" | awk -v f="$font" '$1 == "<" && ($2 == f || $3 == f) && $3 != "c"' | head -3)
            n=$(echo $got | wc -w)
            if [ "$got" = "$want" ] && [ -z "$other" ] && [ "$(grep -c "^$font c " "$out/glyphs.fixel")" = 256 ]; then
                echo "PASS glut-self glyphs $font: $((256 - n)) of 256 identical to freeglut, the $n known ones differ"
            else
                echo "FAIL glut-self glyphs $font: differing:$got (known:$want) $other"
            fi
        done > "$out/glyphs.judged"
        grep '^stroke' "$out/glyphs.mesa" > "$out/stroke.mesa"
        grep '^stroke' "$out/glyphs.fixel" > "$out/stroke.fixel"
        if cmp -s "$out/stroke.mesa" "$out/stroke.fixel" && [ "$(wc -l < "$out/stroke.fixel")" = 53 ]; then
            echo "PASS glut-self stroke metrics: glutStrokeHeight, MONO_ROMAN widths, glutStrokeLength's widest line"
        else
            echo "FAIL glut-self stroke metrics"; diff "$out/stroke.mesa" "$out/stroke.fixel" | head -5
        fi >> "$out/glyphs.judged"
        cat "$out/glyphs.judged"
        P=$((P + $(grep -c '^PASS' "$out/glyphs.judged"))) F=$((F + $(grep -c '^FAIL' "$out/glyphs.judged")))
    fi
fi
# Without FreeType (text.c built without its headers, as on a system
# without libfreetype-dev): one line per font says so, and the 6x10 glyphs
# are drawn with freeglut's heights.
cp "$B/libfixel-glut.a" "$out/noft.a"
if ${CC:-gcc} -std=c11 -Wall -Wextra -Werror -Ikernel-free-src/include -Iboards/include -Iboards/glut/include \
        -c boards/glut/text.c -o "$out/text.o" 2> "$out/noft.log" && ar d "$out/noft.a" text.o && ar q "$out/noft.a" "$out/text.o" &&
   ${CC:-gcc} -std=gnu11 -I boards/glut/include tests/glut/self/glyphs.c "$out/noft.a" "$B/libfixel.a" \
        ${GLUT_FIXEL_LIBS:-} -lm -o "$out/glyphs-noft" 2>> "$out/noft.log"; then
    FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=0 "$out/glyphs-noft" > "$out/noft.out" 2> "$out/noft.err"
    if [ "$(grep -c "built without FreeType headers; drawing fixel's built-in 6x10 glyphs instead of freeglut's" "$out/noft.err")" = 7 ] &&
       grep -q '^helv18 c 65 width 12 moved 12 0: 0,0' "$out/noft.out" && grep -q '^font times24 height 29' "$out/noft.out"
    then pass "fallback-without-freetype"; else fail "fallback-without-freetype" "$out/noft.err"; fi
else
    fail "fallback-without-freetype (build)" "$out/noft.log"
fi
# Issue #39: a run with nothing to show says so, with the window's size and
# the variables that write a frame; a stall with no replay left says "none".
FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=1 "$out/winlife" destroy-exit > /dev/null 2> "$out/quiet.err"
if grep -q "FIXEL_BACKEND=memory: the 64x48 window runs headless and nothing is shown or written; FIXEL_GLUT_OUT=FILE.png writes a frame (FIXEL_GLUT_FRAMES=N" "$out/quiet.err"
then pass "headless-without-out-says-so"; else fail "headless-without-out-says-so" "$out/quiet.err"; fi
FIXEL_BACKEND=memory FIXEL_GLUT_OUT="$out/x.png" FIXEL_GLUT_FRAMES=1 "$out/winlife" destroy-exit > /dev/null 2> "$out/out.err"
if [ -f "$out/x.png" ] && ! grep -q "nothing is shown" "$out/out.err"; then pass "headless-with-out-quiet"
else fail "headless-with-out-quiet" "$out/out.err"; fi
# With no display asked for and none there, the library's line names the
# memory surface: it must be the window's 64x48, not a 640x480 screen.
env -u FIXEL_BACKEND FIXEL_DRM_DEVICE=/nonexistent/card FIXEL_FB_DEVICE=/nonexistent/fb \
    "$out/winlife" destroy-exit > /dev/null 2> "$out/auto.err"
if grep -q "memory" "$out/auto.err"; then
    if grep -q "memory 64x48" "$out/auto.err" && grep -q "no display: the 64x48 window" "$out/auto.err"
    then pass "no-display-window-size"; else fail "no-display-window-size" "$out/auto.err"; fi
else
    echo "glut-self: a display opened here: no-display-window-size not checked"
fi
${CC:-gcc} -std=gnu11 -O2 -I boards/glut/include tests/glut/progs/bresenham.c "$B/libfixel-glut.a" \
    "$B/libfixel.a" ${GLUT_FIXEL_LIBS:-} -lm -o "$out/bresenham" 2> "$out/build.log" || cat "$out/build.log"
FIXEL_BACKEND=memory FIXEL_GLUT_FRAMES=3 "$out/bresenham" > /dev/null 2> "$out/stall.err"
st=$?
if [ $st = 3 ] && grep -q "stalled at frame 1 of 3 (no replay event left)" "$out/stall.err" && ! grep -q -- "-1" "$out/stall.err"
then pass "stall-none-left"; else echo "  exit $st"; fail "stall-none-left" "$out/stall.err"; fi
echo "glut-self: $P passed, $F failed"
[ $F -eq 0 ]
