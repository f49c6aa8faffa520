#!/bin/sh
# SPDX-License-Identifier: MIT
# First-try set-up, the way a new user meets it (issue #20): a fresh Debian 12
# (bookworm) root made by mmdebstrap with only make, git and ca-certificates,
# a clone of this repository copied in, and chroot:
#   user  a normal user's `make run` stops with the exact sudo apt-get line
#         (exit non-zero); after root runs that line, the same `make run` works
#   run   root's first `make run` in a second untouched root succeeds (out/*.png)
#   test  root's first `make test` in a third untouched root: the whole suite
#         (--test; its total is added to this script's own)
# Nothing is kept between runs: every root is bootstrapped anew and removed on
# every exit path; the packages come from the Debian mirror each time.
#
#   debs  with --debs DIR (make deb's output): apt-get installs DIR/<arch>'s
#         libfixel0, libfixel-dev and fixel-tools into a fourth untouched root,
#         and the README's example builds there with pkg-config and runs
# usage: fresh-root.sh [--test] [--debs DIR] [WORKDIR]   (root; default WORKDIR build/setup)
#   SETUP_TEST_ARGS="QUICK=1 FIXEL_SKIP_KERNEL=1" runs a subset in the test root.
#   SETUP_KEEP=1 leaves the roots in WORKDIR (for a look; remove them by hand).
# Ends with "setup: N passed, N failed". Commits only: the copy is a clone of
# HEAD, uncommitted changes are not in it.
set -u
do_test=0; debs=""
while :; do
    case ${1:-} in
    --test) do_test=1; shift ;;
    --debs) debs=$(cd "$2" && pwd); shift 2 ;;
    *) break ;;
    esac
done
SRC=$(cd "$(dirname "$0")/../.." && pwd)
W=${1:-build/setup}
mkdir -p "$W" && W=$(cd "$W" && pwd)
MIRROR=${SETUP_MIRROR:-http://deb.debian.org/debian}
P=0; F=0
pass() { echo "PASS $*"; P=$((P + 1)); }
fail() { echo "FAIL $*"; F=$((F + 1)); }
now() { date +%s; }
finish() { echo "setup: $P passed, $F failed"; [ "$F" -eq 0 ]; exit $?; }

if [ "$(id -u)" != 0 ]; then
    echo "fresh-root.sh: needs root (mmdebstrap, chroot, mount)"
    fail "not root"; finish
fi
[ -n "$(git -C "$SRC" status --porcelain --untracked-files=no 2>/dev/null)" ] &&
    echo "fresh-root.sh: note: uncommitted changes are not in the copy (a clone of HEAD)"

# One run at a time per WORKDIR: a second one would remove the first's roots.
exec 9> "$W/.lock"
if ! flock -n 9; then fail "another fresh-root.sh runs in $W"; exit 1; fi
if grep -q " $W/" /proc/mounts; then fail "mounts left under $W (umount -R them)"; exit 1; fi

MOUNTED=""
umount_all() {
    for m in $MOUNTED; do umount -R "$m" 2>/dev/null || umount -R -l "$m" 2>/dev/null; done
    MOUNTED=""
}
cleanup() {
    umount_all
    # Never remove a tree that still has something mounted under it.
    if grep -q " $W/" /proc/mounts; then
        echo "fresh-root.sh: mounts left under $W; not removing it"
    elif [ "${SETUP_KEEP:-0}" != 1 ]; then
        rm -rf --one-file-system "$W/pristine" "$W/user" "$W/run" "$W/test" "$W/deb"
    fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP

mount_in() { # root: /proc, /sys and /dev (qemu's /dev/kvm, ptys, /dev/shm)
    mount -t proc proc "$1/proc" && MOUNTED="$1/proc $MOUNTED"
    mount --rbind /sys "$1/sys" && mount --make-rslave "$1/sys" && MOUNTED="$1/sys $MOUNTED"
    mount --rbind /dev "$1/dev" && mount --make-rslave "$1/dev" && MOUNTED="$1/dev $MOUNTED"
}
in_root() { # root, command: runs as root inside, with a plain environment
    r=$1; shift
    chroot "$r" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        LANG=C.UTF-8 TERM=dumb sh -c "$*"
}
clone_into() { # root, dir
    git clone -q --no-hardlinks "$SRC" "$1$2" || return 1
}

# --- the fresh root ---------------------------------------------------------
t0=$(now)
rm -rf --one-file-system "$W/pristine" "$W/user" "$W/run" "$W/test" "$W/deb"
if ! command -v mmdebstrap >/dev/null 2>&1; then
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends mmdebstrap >/dev/null ||
        { apt-get -o DPkg::Lock::Timeout=300 update -qq; DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends mmdebstrap >/dev/null; }
fi
# Valid-Until off: a machine whose clock runs ahead must not refuse the
# security suite's Release file (apt's own option, nothing of fixel's).
if mmdebstrap --variant=apt --include=make,git,ca-certificates \
        --aptopt='Acquire::Check-Valid-Until "false"' \
        bookworm "$W/pristine" \
        "deb $MIRROR bookworm main" "deb $MIRROR bookworm-updates main" \
        "deb http://deb.debian.org/debian-security bookworm-security main" > "$W/mmdebstrap.log" 2>&1; then
    pass "mmdebstrap bookworm ($(( $(now) - t0 )) s)"
else
    tail -n 20 "$W/mmdebstrap.log"; fail "mmdebstrap bookworm"; finish
fi
for r in user run test deb; do
    [ $r = test ] && [ $do_test = 0 ] && continue
    [ $r = deb ] && [ -z "$debs" ] && continue
    cp -a "$W/pristine" "$W/$r"
done

# --- a normal user: the exact line, then success -----------------------------
t0=$(now)
U=$W/user
echo 'fx:x:1000:1000:fixel user:/home/fx:/bin/sh' >> "$U/etc/passwd"
echo 'fx:x:1000:' >> "$U/etc/group"
echo 'fx:*:19000:0:99999:7:::' >> "$U/etc/shadow"
mkdir -p "$U/home/fx" && clone_into "$U" /home/fx/fixel && chown -R 1000:1000 "$U/home/fx"
mount_in "$U"
as_user() {
    chroot --userspec=1000:1000 "$U" /usr/bin/env -i HOME=/home/fx PATH=/usr/local/bin:/usr/bin:/bin \
        LANG=C.UTF-8 TERM=dumb sh -c "cd /home/fx/fixel && $*"
}
as_user make run > "$W/user-1.log" 2>&1; rc=$?
line=$(grep -E '^  sudo apt-get update && sudo apt-get install -y --no-install-recommends( [a-z0-9.+:-]+)+$' "$W/user-1.log")
if [ $rc -ne 0 ] && [ -n "$line" ] && ! grep -q 'error\|No such file' "$W/user-1.log" &&
   echo "$line" | grep -qw gcc && echo "$line" | grep -qw libpng-dev && ! echo "$line" | grep -qw 'clang\|valgrind\|libcairo2-dev'; then
    pass "user make run stops (exit $rc) with:$(echo "$line" | sed 's/^ */ /')"
else
    cat "$W/user-1.log"; fail "user make run: exit $rc, no exact sudo apt-get line of the run set"
fi
if [ -n "$line" ] && in_root "$U" "$(echo "$line" | sed 's/sudo //g')" > "$W/user-apt.log" 2>&1; then
    pass "root ran that line"
else
    tail -n 20 "$W/user-apt.log"; fail "the printed line failed as root"
fi
as_user make run > "$W/user-2.log" 2>&1; rc=$?
n=$(ls "$U"/home/fx/fixel/out/*.png 2>/dev/null | wc -l)
if [ $rc -eq 0 ] && [ "$n" -gt 0 ]; then
    pass "user make run after it: $n pictures in out/ ($(( $(now) - t0 )) s for the user part)"
else
    tail -n 30 "$W/user-2.log"; fail "user make run after the install: exit $rc, $n pictures"
fi
umount_all

# --- root's first make run -----------------------------------------------------
t0=$(now)
R=$W/run
clone_into "$R" /root/fixel
mount_in "$R"
in_root "$R" "cd /root/fixel && make run" > "$W/run.log" 2>&1; rc=$?
n=$(ls "$R"/root/fixel/out/*.png 2>/dev/null | wc -l)
if [ $rc -eq 0 ] && [ "$n" -gt 0 ]; then
    pass "root make run, first try: $n pictures in out/ ($(( $(now) - t0 )) s)"
else
    tail -n 30 "$W/run.log"; fail "root make run, first try: exit $rc, $n pictures"
fi
# what the run set leaves out
for p in clang valgrind libcairo2-dev libsdl2-dev qemu-user-static; do
    if in_root "$R" "dpkg-query -W -f='\${Status}' $p 2>/dev/null | grep -q 'install ok installed'"; then
        fail "make run installed $p (a test or bench package)"
    fi
done
umount_all

# --- the Debian packages in a fresh root ----------------------------------------
if [ -n "$debs" ]; then
    t0=$(now)
    D=$W/deb
    arch=$(dpkg --print-architecture)
    mkdir -p "$D/tmp/debs"
    cp "$debs/$arch"/libfixel0_*.deb "$debs/$arch"/libfixel-dev_*.deb "$debs/$arch"/fixel-tools_*.deb "$D/tmp/debs/" 2>/dev/null
    sed -n '/^## A 15-line example/,/^## /p' "$SRC/README.md" | sed -n '/^```c$/,/^```$/p' | sed '1d;$d' > "$D/tmp/hello.c"
    cp "$SRC/tests/golden/scripts/core-lines.fxs" "$D/tmp/"
    mount_in "$D"
    if in_root "$D" "export DEBIAN_FRONTEND=noninteractive; apt-get update -qq && apt-get install -y -qq --no-install-recommends /tmp/debs/*.deb gcc libc6-dev pkg-config" > "$W/deb-apt.log" 2>&1; then
        pass "apt-get install ./libfixel0 ./libfixel-dev ./fixel-tools ($(ls "$D/tmp/debs" | wc -l) packages)"
    else
        tail -n 20 "$W/deb-apt.log"; fail "apt-get install of the packages"
    fi
    if in_root "$D" 'cd /tmp && cc -Wall -Wextra -Werror hello.c -o hello $(pkg-config --cflags --libs fixel) && ./hello && test -s hello.png && ldd ./hello && ldd ./hello | grep -Eq "libfixel.so.0 => (/usr)?/lib/$(gcc -print-multiarch)/libfixel.so.0"' > "$W/deb-hello.log" 2>&1; then
        pass "README example: cc hello.c \$(pkg-config --cflags --libs fixel) against libfixel-dev, runs on libfixel0"
    else
        cat "$W/deb-hello.log"; fail "README example against the installed packages"
    fi
    if in_root "$D" 'cd /tmp && fixel-draw -o lines.png core-lines.fxs && test -s lines.png && test -f /lib/systemd/system/fixel-kiosk.service && ! command -v fixel-bench' > "$W/deb-tools.log" 2>&1; then
        pass "fixel-tools: fixel-draw renders, the kiosk unit is there, no fixel-bench ($(( $(now) - t0 )) s for the packages)"
    else
        cat "$W/deb-tools.log"; fail "fixel-tools in the fresh root"
    fi
    umount_all
fi

# --- root's first make test (the whole suite) -----------------------------------
if [ $do_test = 1 ]; then
    t0=$(now)
    T=$W/test
    clone_into "$T" /root/fixel
    mount_in "$T"
    in_root "$T" "cd /root/fixel && CI=${CI:-} make test ${SETUP_TEST_ARGS:-}" > "$W/test.log" 2>&1; rc=$?
    total=$(grep -E '^total: [0-9]+ passed, [0-9]+ failed' "$W/test.log" | tail -n 1)
    tp=$(echo "$total" | sed -nE 's/^total: ([0-9]+) passed.*/\1/p')
    tf=$(echo "$total" | sed -nE 's/.* ([0-9]+) failed.*/\1/p')
    grep -E '^(== |FAIL|!!|SKIP|total:|deps:)|passed, [0-9]+ failed' "$W/test.log"
    if [ $rc -eq 0 ] && [ -n "$tp" ] && [ "$tf" = 0 ]; then
        P=$((P + tp))
        pass "root make test ${SETUP_TEST_ARGS:-}, first try: $total ($(( $(now) - t0 )) s)"
    else
        tail -n 40 "$W/test.log"
        P=$((P + ${tp:-0})); F=$((F + ${tf:-0}))
        fail "root make test, first try: exit $rc, ${total:-no total}"
    fi
    umount_all
fi
finish
