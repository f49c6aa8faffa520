#!/bin/sh
# SPDX-License-Identifier: MIT
# Builds the guest's initramfs: static busybox, the kernel modules the tests
# need (in dependency order, resolved by modprobe against the unpacked
# image), the out-of-tree gpio-sim module, /init and the test programs.
#
# usage: mkinitramfs.sh KROOT KVER BUSYBOX GPIO_SIM_KO TESTBIN_DIR OUT.cpio.gz MODULE...
set -eu
KROOT=$1 KVER=$2 BUSYBOX=$3 GPIOSIM=$4 BINS=$5 OUT=$6
shift 6
HERE=$(cd "$(dirname "$0")" && pwd)
S=$(mktemp -d)
chmod 755 "$S" # becomes the guest's /: non-root tests must traverse it
trap 'rm -rf "$S"' EXIT

mkdir -p "$S/bin" "$S/dev" "$S/proc" "$S/sys" "$S/tmp" "$S/etc" "$S/tests" "$S/lib/modules"
cp "$BUSYBOX" "$S/bin/busybox"
cp "$HERE/init.sh" "$S/init"
chmod 755 "$S/init"
# udev is absent: devtmpfs nodes are root-only, so init gives the display
# and input nodes to these groups the way udev rules do on a real system.
printf 'root:x:0:\nvideo:x:44:\ninput:x:101:\nuser:x:1000:\n' > "$S/etc/group"
printf 'root:x:0:0:root:/:/bin/sh\nuser:x:1000:1000:user:/tmp:/bin/sh\n' > "$S/etc/passwd"

: > "$S/modules.load"
for m in "$@"; do
    modprobe -d "$KROOT" -S "$KVER" --show-depends "$m" | while read -r cmd path _; do
        [ "$cmd" = insmod ] || continue
        rel=${path#"$KROOT"/lib/modules/"$KVER"/}
        grep -qx "$rel" "$S/modules.load" && continue
        mkdir -p "$S/lib/modules/$(dirname "$rel")"
        cp "$path" "$S/lib/modules/$rel"
        echo "$rel" >> "$S/modules.load"
    done
done
cp "$GPIOSIM" "$S/lib/modules/gpio-sim-oot.ko"
echo gpio-sim-oot.ko >> "$S/modules.load"
# Optional modules: copied with their dependencies but not loaded at boot;
# the guest program needing them insmods /modules.optional in order.
# OPTIONAL_MODULES="name..." (from the image), OPTIONAL_KO="file.ko..."
: > "$S/modules.optional"
# add_list LIST MODULE...: the modules and their dependencies not loaded at
# boot, copied and appended to LIST in insmod order
add_list() {
    list=$1; shift
    for m in "$@"; do
        modprobe -d "$KROOT" -S "$KVER" --show-depends "$m" | while read -r cmd path _; do
            [ "$cmd" = insmod ] || continue
            rel=${path#"$KROOT"/lib/modules/"$KVER"/}
            grep -qx "$rel" "$S/modules.load" "$list" && continue
            mkdir -p "$S/lib/modules/$(dirname "$rel")"
            cp "$path" "$S/lib/modules/$rel"
            echo "$rel" >> "$list"
        done
    done
}
# shellcheck disable=SC2086 # word lists
add_list "$S/modules.optional" ${OPTIONAL_MODULES:-}
for k in ${OPTIONAL_KO:-}; do
    [ -f "$k" ] || continue
    cp "$k" "$S/lib/modules/"
    basename "$k" >> "$S/modules.optional"
done

# A second card's driver (guest/outputs.c): CARD_MODULES="name...", its
# dependencies not loaded at boot listed in /modules.cards in order.
: > "$S/modules.cards"
# shellcheck disable=SC2086
add_list "$S/modules.cards" ${CARD_MODULES:-}

# RIG_TESTS="outputs display" (or RIG_ONLY): only these guest programs (while
# developing; make test leaves both unset: all of them).
for t in "$BINS"/*; do
    [ -x "$t" ] || continue
    case " ${RIG_TESTS:-${RIG_ONLY:-${t##*/}}} " in *" ${t##*/} "*) cp "$t" "$S/tests/" ;; esac
done
# Tools the tests run as commands (tools.mk builds them into BINS/../bin).
for t in "$BINS"/../bin/*; do
    [ -f "$t" ] && [ -x "$t" ] && cp "$t" "$S/bin/"
done
(cd "$S" && find . | cpio -o -H newc --quiet) | gzip -1 > "$OUT"
