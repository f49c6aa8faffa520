#!/bin/sh
# SPDX-License-Identifier: MIT
# fixel-info on whatever machine runs the tests: every section is printed,
# missing hardware is reported rather than fatal, and it always says what
# fixel would open.
bin=$1
P=0; F=0
out=$("$bin" 2>/dev/null); rc=$?
[ $rc -eq 0 ] && P=$((P + 1)) || { F=$((F + 1)); echo "FAIL: exit $rc"; }
for s in "DRM cards" "fbdev devices" "input devices" "GPIO chips" "fixel's choice"; do
    case "$out" in *"$s"*) P=$((P + 1)) ;; *) F=$((F + 1)); echo "FAIL: no section $s" ;; esac
done
# every section has content: a device, "none found" or an explanation
for s in "DRM cards" "fbdev devices" "input devices" "GPIO chips"; do
    next=$(echo "$out" | sed -n "/^$s/{n;p;}")
    case "$next" in "  "?*) P=$((P + 1)) ;; *) F=$((F + 1)); echo "FAIL: section $s is empty" ;; esac
done
case "$out" in *"backend "*|*"nothing opened"*) P=$((P + 1)) ;; *) F=$((F + 1)); echo "FAIL: no choice reported" ;; esac
"$bin" --help | grep -q "usage: fixel-info" && P=$((P + 1)) || { F=$((F + 1)); echo "FAIL: --help"; }
"$bin" --bogus >/dev/null 2>&1 && { F=$((F + 1)); echo "FAIL: bad option accepted"; } || P=$((P + 1))
# the sibling tools: fixel-shot fails clearly without a device, fixel-draw
# streams to the display (memory backend here) and stops on a bad line
dir=$(dirname "$bin")
if [ ! -e /dev/fb0 ] && [ ! -e /dev/dri ]; then
    msg=$("$dir/fixel-shot" -o /tmp/fixel-shot-test.png 2>&1) && { F=$((F + 1)); echo "FAIL: fixel-shot succeeded without a device"; } ||
    case "$msg" in *"no display device"*) P=$((P + 1)) ;; *) F=$((F + 1)); echo "FAIL: fixel-shot said: $msg" ;; esac
fi
"$dir/fixel-shot" --help | grep -q "usage: fixel-shot" && P=$((P + 1)) || { F=$((F + 1)); echo "FAIL: fixel-shot --help"; }
printf 'size 64 48\nclear #ff0000\npresent\nclear #00ff00\npresent\n' | FIXEL_BACKEND=memory "$dir/fixel-draw" --display - 2>/dev/null &&
    P=$((P + 1)) || { F=$((F + 1)); echo "FAIL: fixel-draw --display - stream"; }
printf 'size 64 48\nbogus\n' | FIXEL_BACKEND=memory "$dir/fixel-draw" --display - 2>/dev/null &&
    { F=$((F + 1)); echo "FAIL: fixel-draw stream accepted a bad line"; } || P=$((P + 1))
echo "fixel-info: $P passed, $F failed"
[ "$F" -eq 0 ]
