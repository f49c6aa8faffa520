#!/bin/sh
# SPDX-License-Identifier: MIT
# What a user can rely on from the tools (issue #20): explicit displays that
# cannot open fail, only the automatic choice goes headless, --out makes
# parents, --help is stdout + exit 0, bad --frames / -o names are exit 2.
# Needs a machine without DRM and fbdev (checked; skipped otherwise).
# usage: behaviour.sh BIN_DIR WORK_DIR
B=${1:-build/bin}; W=${2:-build/tests/behaviour}
P=0; F=0
ok() { P=$((P + 1)); }
bad() { F=$((F + 1)); echo "FAIL $*"; }
rm -rf "$W"; mkdir -p "$W"
# expect STATUS NAME CMD...: exit status STATUS; output in $W/NAME.out/.err
expect() {
    want=$1; n=$2; shift 2
    "$@" > "$W/$n.out" 2> "$W/$n.err" < /dev/null; rc=$?
    if [ "$rc" = "$want" ]; then ok; return 0; fi
    bad "$n: exit $rc, want $want: $*"; cat "$W/$n.err"; return 1
}
has() { grep -q -- "$2" "$W/$1" || { bad "$1 lacks '$2'"; cat "$W/$1"; }; }

for t in fixel-demo fixel-draw fixel-info fixel-kiosk fixel-shot fixel-bench; do
    [ -x "$B/$t" ] || continue
    if expect 0 "help-$t" "$B/$t" --help; then
        [ -s "$W/help-$t.out" ] && [ ! -s "$W/help-$t.err" ] && ok || bad "$t --help: not on stdout only"
    fi
done

if [ -e /dev/dri ] || [ -e /dev/fb0 ]; then
    echo "skip: the display checks (this machine has /dev/dri or /dev/fb0)"
else
    for b in drm fbdev; do
        expect 1 "demo-$b" env FIXEL_BACKEND=$b "$B/fixel-demo" --out "$W/demo-$b" && has "demo-$b.err" "no $b display found"
        [ -d "$W/demo-$b" ] && bad "demo-$b rendered headless anyway"
        expect 1 "info-$b" env FIXEL_BACKEND=$b "$B/fixel-info" && has "info-$b.out" "nothing opened"
        printf 'x=1\n' > "$W/data"
        expect 1 "kiosk-$b" env FIXEL_BACKEND=$b "$B/fixel-kiosk" --data "$W/data" examples/kiosk-basic.conf
    done
    # a named device that cannot open says why, even when its path is huge (issue #26)
    long=/$(head -c 10000 /dev/zero | tr '\0' a)
    expect 1 drm-longpath env FIXEL_BACKEND=drm FIXEL_DRM_DEVICE="$long" "$B/fixel-demo" --out "$W/lp" &&
        has drm-longpath.err "File name too long"
    expect 1 fb-null env FIXEL_BACKEND=fbdev FIXEL_FB_DEVICE=/dev/null "$B/fixel-demo" --out "$W/fbn" &&
        has fb-null.err "/dev/null: not a framebuffer"
    expect 1 demo-bogus env FIXEL_BACKEND=bogus "$B/fixel-demo" --out "$W/bogus" && has demo-bogus.err "FIXEL_BACKEND=bogus"
    # the automatic choice falls back, says so once, and renders
    expect 0 demo-auto env -u FIXEL_BACKEND "$B/fixel-demo" --page lines --out "$W/auto/a/b" &&
        has demo-auto.out "no display here" && [ -f "$W/auto/a/b/lines.png" ] && ok || bad "demo auto: no lines.png"
    [ "$(grep -c "no display here" "$W/demo-auto.out")" = 1 ] && ok || bad "demo auto: said it more than once"
    # kiosk: no display and no --headless is a failure systemd can see
    expect 1 kiosk-auto env -u FIXEL_BACKEND "$B/fixel-kiosk" --data "$W/data" examples/kiosk-basic.conf &&
        has kiosk-auto.err "--headless"
    expect 0 kiosk-headless "$B/fixel-kiosk" --headless --last --out "$W/kiosk/x/y" --data "$W/data" examples/kiosk-basic.conf &&
        { [ -f "$W/kiosk/x/y/last.png" ] && ok || bad "kiosk --out x/y: no last.png"; }
fi

# fixel-demo --golden never claims a file it did not write
expect 1 golden-nodir "$B/fixel-demo" --golden "$W/no/such/dir"
grep -q "(wrote" "$W/golden-nodir.out" && bad "--golden claims to have written into a missing directory" || ok
has golden-nodir.out "could not write"
# bad arguments: exit 2
expect 2 kiosk-frames0 "$B/fixel-kiosk" --headless --frames 0 examples/kiosk-basic.conf
expect 2 kiosk-framesx "$B/fixel-kiosk" --headless --frames 3x examples/kiosk-basic.conf
printf 'clear #102030\n' > "$W/s.fxs"
expect 2 draw-jpg "$B/fixel-draw" -o "$W/x.jpg" "$W/s.fxs" && has draw-jpg.err ".png or .ppm"
[ -e "$W/x.jpg" ] && bad "fixel-draw wrote x.jpg"
expect 0 draw-ppm "$B/fixel-draw" -o "$W/x.ppm" "$W/s.fxs"

echo "behaviour: $P passed, $F failed"
[ $F = 0 ]
