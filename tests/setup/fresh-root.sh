#!/bin/sh
# SPDX-License-Identifier: MIT
# First-try set-up, the way a new user meets it (issue #20): a fresh Debian 12
# (bookworm) root made by mmdebstrap with only make, git and ca-certificates,
# a clone of this repository in it, entered with chroot.
#   user  a normal user's `make run` stops, exit non-zero and before compiling,
#         with the exact `sudo apt-get ...` line of the run set; root runs
#         that line; the same `make run` then renders out/*.png. The user's
#         `make test` then stops the same way with the lines of the test set
#         only (dpkg --add-architecture, apt-get); root runs them; the user's
#         `make test $SETUP_USER_TEST_ARGS` then passes.
#   root  in a second untouched root, root's first `make run` installs the
#         run set (and nothing of the test set) and renders; root's first
#         `make test $SETUP_TEST_ARGS` then installs the test set and passes.
#   debs  with --debs DIR (make deb's output): apt-get installs DIR/<arch>'s
#         libfixel0, libfixel-dev and fixel-tools into a third untouched root,
#         the README's example builds there with pkg-config and runs, and the
#         packaged fixel-draw renders.
#   deb-build with --deb-build: in another untouched root, root's first `make
#         deb DEB_ARCHES=<native>` in a copy of the tree without .git (what
#         a release tarball or a ZIP gives) installs its build set, builds
#         the packages and passes lintian; those packages are then the ones
#         the debs step installs (unless --debs names others).
# The suites' totals are added to this script's own. Every root is copied
# from one mmdebstrap run and removed on every exit path; packages come from
# the Debian mirror. Within one run the roots share one apt archive directory
# (bind-mounted /var/cache/apt/archives), so a package is downloaded once per
# run, not once per root; apt still resolves and installs everything in each.
#
# usage: fresh-root.sh [--no-test] [--no-run] [--deb-build] [--debs DIR] [WORKDIR]
#                        (root; default WORKDIR build/setup)
#   --no-test                skips both make test runs (make test-setup-run)
#   --no-run                 skips the user's and root's steps (make test-setup-deb)
#   SETUP_TEST_ARGS=...      variables for root's make test (make test-setup
#                            passes the CI subset: tests/README.md, "CI")
#   SETUP_USER_TEST_ARGS=... the same for the user's make test (default: as root's)
#   SETUP_MAKE="make -j2"    how make is called in the roots (default: make)
#   SETUP_KEEP=1             leaves the roots in WORKDIR (remove them by hand)
# Ends with "setup: N passed, N failed". Commits only: the copy is a clone of
# HEAD, uncommitted changes are not in it.
set -u
do_test=1; do_run=1; deb_build=0; debs=""
while :; do
    case ${1:-} in
    --test) do_test=1; shift ;;
    --no-test) do_test=0; shift ;;
    --debs) debs=$(cd "$2" && pwd); shift 2 ;;
    --no-run) do_run=0; shift ;;
    --deb-build) deb_build=1; shift ;;
    *) break ;;
    esac
done
SRC=$(cd "$(dirname "$0")/../.." && pwd)
W=${1:-build/setup}
mkdir -p "$W" && W=$(cd "$W" && pwd)
MIRROR=${SETUP_MIRROR:-http://deb.debian.org/debian}
MK=${SETUP_MAKE:-make}
TEST_ARGS=${SETUP_TEST_ARGS:-}
USER_TEST_ARGS=${SETUP_USER_TEST_ARGS-$TEST_ARGS}
P=0; F=0
pass() { echo "PASS $*"; P=$((P + 1)); }
fail() { echo "FAIL $*"; F=$((F + 1)); }
now() { date +%s; }
finish() { echo "setup: $P passed, $F failed"; [ "$F" -eq 0 ]; exit $?; }
T_ALL=$(now)

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

ROOTS="$W/pristine $W/user $W/root $W/debsrc $W/deb $W/debs-built $W/archives"
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
        rm -rf --one-file-system $ROOTS
    fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP

mount_in() { # root: /proc, /sys, /dev (qemu's /dev/kvm, ptys, /dev/shm), the shared apt archives
    mount -t proc proc "$1/proc" && MOUNTED="$1/proc $MOUNTED"
    mount --rbind /sys "$1/sys" && mount --make-rslave "$1/sys" && MOUNTED="$1/sys $MOUNTED"
    mount --rbind /dev "$1/dev" && mount --make-rslave "$1/dev" && MOUNTED="$1/dev $MOUNTED"
    mount --bind "$W/archives" "$1/var/cache/apt/archives" && MOUNTED="$1/var/cache/apt/archives $MOUNTED"
}
in_root() { # root, command: runs as root inside, with a plain environment
    r=$1; shift
    chroot "$r" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        LANG=C.UTF-8 TERM=dumb CI=${CI:-} sh -c "$*"
}
clone_into() { # root, dir
    git clone -q --no-hardlinks "$SRC" "$1$2" || return 1
}
installed() { # root, package: installed in that root?
    in_root "$1" "dpkg-query -W -f='\${Status}' $2 2>/dev/null | grep -q 'install ok installed'"
}
# make test's closing total, added to ours: suite_total LOG RC LABEL
suite_total() {
    total=$(grep -E '^total: [0-9]+ passed, [0-9]+ failed' "$1" | tail -n 1)
    tp=$(echo "$total" | sed -nE 's/^total: ([0-9]+) passed.*/\1/p')
    tf=$(echo "$total" | sed -nE 's/.* ([0-9]+) failed.*/\1/p')
    grep -E '^(FAIL|!!|SKIP|deps:)|passed, [0-9]+ failed' "$1" | sed 's/^/    /'
    if [ "$2" -eq 0 ] && [ -n "$tp" ] && [ "$tf" = 0 ]; then
        P=$((P + tp))
        pass "$3: $total ($(( $(now) - t0 )) s)"
    else
        tail -n 40 "$1"
        P=$((P + ${tp:-0})); F=$((F + ${tf:-0}))
        fail "$3: exit $2, ${total:-no total}"
    fi
}

# --- the fresh root -----------------------------------------------------------
t0=$(now)
rm -rf --one-file-system $ROOTS
mkdir -p "$W/archives/partial"
if ! command -v mmdebstrap >/dev/null 2>&1; then
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends mmdebstrap >/dev/null ||
        { apt-get -o DPkg::Lock::Timeout=300 update -qq; DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends mmdebstrap >/dev/null; }
fi
# Valid-Until off: a machine whose clock runs ahead must not refuse the
# security suite's Release file; Retries: a file whose download fails is
# fetched again (apt's own options, in the roots too; nothing of fixel's).
bootstrap() {
    rm -rf --one-file-system "$W/pristine"
    mmdebstrap --variant=apt --include=make,git,ca-certificates \
        --aptopt='Acquire::Check-Valid-Until "false"' --aptopt='Acquire::Retries "3"' \
        bookworm "$W/pristine" \
        "deb $MIRROR bookworm main" "deb $MIRROR bookworm-updates main" \
        "deb http://deb.debian.org/debian-security bookworm-security main" > "$W/mmdebstrap.log" 2>&1
}
# The download is retried once (a mirror mid-sync or a dropped connection);
# failing twice is a failure: nothing below can be checked without the root.
if bootstrap || { tail -n 5 "$W/mmdebstrap.log"; echo "fresh-root.sh: mmdebstrap failed; retrying once in 30 s"; sleep 30; bootstrap; }; then
    pass "mmdebstrap bookworm: make, git, ca-certificates ($(( $(now) - t0 )) s)"
else
    tail -n 20 "$W/mmdebstrap.log"; fail "mmdebstrap bookworm, twice (mirror unreachable?)"; finish
fi
for r in user root debsrc deb; do
    case $r in
    user|root) [ $do_run = 1 ] || continue ;;
    debsrc) [ $deb_build = 1 ] || continue ;;
    deb) [ -n "$debs" ] || [ $deb_build = 1 ] || continue ;;
    esac
    cp -a "$W/pristine" "$W/$r"
done

# --- a normal user: the exact line, then success --------------------------------
if [ $do_run = 1 ]; then
t0=$(now)
U=$W/user
echo 'fx:x:1000:1000:fixel user:/home/fx:/bin/sh' >> "$U/etc/passwd"
echo 'fx:x:1000:' >> "$U/etc/group"
echo 'fx:*:19000:0:99999:7:::' >> "$U/etc/shadow"
mkdir -p "$U/home/fx" && clone_into "$U" /home/fx/fixel && chown -R 1000:1000 "$U/home/fx"
mount_in "$U"
as_user() {
    chroot --userspec=1000:1000 "$U" /usr/bin/env -i HOME=/home/fx PATH=/usr/local/bin:/usr/bin:/bin \
        LANG=C.UTF-8 TERM=dumb CI=${CI:-} sh -c "cd /home/fx/fixel && $*"
}
root_runs() { # log, the lines printed for the user, label: root runs them, in order
    if [ -n "$2" ] && in_root "$U" "set -e; $(echo "$2" | sed 's/sudo //g; s/$/;/' | tr '\n' ' ')" > "$W/$1" 2>&1; then
        pass "$3 ($(( $(now) - t0 )) s since the step began)"
    else
        tail -n 20 "$W/$1"; fail "$3: failed as root"
    fi
}
sp() { case " $1 " in *" $2 "*) return 0 ;; esac; return 1; } # word $2 in list $1
# (a root without sudo, as these are, is told to run the lines "as root",
# without the sudo in front)
CMD='^  (sudo )?(apt-get|dpkg) '
APTLINE='^  (sudo )?apt-get update && (sudo )?apt-get install -y --no-install-recommends( [a-z0-9.+-]+)+$'
as_user $MK run > "$W/user-run-1.log" 2>&1; rc=$?
line=$(grep -E "$APTLINE" "$W/user-run-1.log")
pk=$(echo "$line" | sed 's/.*--no-install-recommends//')
if [ $rc -ne 0 ] && [ "$(echo "$line" | wc -l)" = 1 ] && [ -n "$line" ] &&
   [ "$(grep -cE "$CMD" "$W/user-run-1.log")" = 1 ] && [ ! -e "$U/home/fx/fixel/build" ] &&
   sp "$pk" gcc && sp "$pk" libpng-dev && sp "$pk" pkg-config && ! sp "$pk" clang && ! sp "$pk" valgrind && ! sp "$pk" libcairo2-dev; then
    pass "user make run stops (exit $rc, nothing built) with:$(echo "$line" | sed 's/^ */ /')"
else
    cat "$W/user-run-1.log"; fail "user make run: exit $rc, not one exact sudo apt-get line of the run set before any build"
fi
root_runs user-run-apt.log "$line" "root ran that line"
as_user $MK run > "$W/user-run-2.log" 2>&1; rc=$?
n=$(ls "$U"/home/fx/fixel/out/*.png 2>/dev/null | wc -l)
if [ $rc -eq 0 ] && [ "$n" -gt 0 ] && ! grep -qE "$CMD" "$W/user-run-2.log"; then
    pass "user make run after it: $n pictures in out/ ($(( $(now) - t0 )) s for the user's make run)"
else
    tail -n 30 "$W/user-run-2.log"; fail "user make run after the install: exit $rc, $n pictures"
fi
# A cross build without the target's toolchain and libraries stops before
# compiling anything, naming them and the commands that install them.
as_user $MK BOARD=rpi4 > "$W/user-cross.log" 2>&1; rc=$?
if [ $rc -ne 0 ] && grep -qxE '  (sudo )?dpkg --add-architecture arm64' "$W/user-cross.log" &&
   grep -E "$APTLINE" "$W/user-cross.log" | grep -q ' gcc-aarch64-linux-gnu' &&
   grep -E '^  (sudo )?apt-get install -y --no-install-recommends ' "$W/user-cross.log" | grep -q ' libpng-dev:arm64' &&
   [ -z "$(find "$U/home/fx/fixel/build/rpi4" -name '*.o' 2>/dev/null)" ]; then
    pass "user make BOARD=rpi4 stops before compiling (exit $rc, no object) with the arm64 packages and their commands"
else
    cat "$W/user-cross.log"; fail "user make BOARD=rpi4 without the arm64 packages: exit $rc"
fi

if [ $do_test = 1 ]; then
    t0=$(now)
    as_user $MK test > "$W/user-test-1.log" 2>&1; rc=$?
    lines=$(grep -E "$CMD" "$W/user-test-1.log")
    bad=$(echo "$lines" | grep -vE "$APTLINE" | grep -vE '^  (sudo )?dpkg --add-architecture [a-z0-9]+$' |
          grep -vE '^  (sudo )?apt-get install -y --no-install-recommends( [a-z0-9.+-]+:[a-z0-9]+)+$')
    native=$(echo "$lines" | grep -E "$APTLINE" | sed 's/.*--no-install-recommends//')
    allp=$(echo "$lines" | sed -n 's/.*--no-install-recommends//p' | tr '\n' ' ')
    if [ $rc -ne 0 ] && [ -n "$lines" ] && [ -z "$bad" ] && [ ! -e "$U/home/fx/fixel/build/asan" ] &&
       echo "$lines" | grep -qxE '  (sudo )?dpkg --add-architecture arm64' && echo "$lines" | grep -qxE '  (sudo )?dpkg --add-architecture armhf' &&
       sp "$native" clang && sp "$native" valgrind && sp "$native" xvfb && sp "$native" libcairo2-dev && sp "$allp" libpng-dev:arm64 &&
       ! sp "$native" gcc && ! sp "$native" libpng-dev; then
        pass "user make test stops (exit $rc, nothing built) with the test set only: $(echo "$lines" | wc -l) lines, $(echo "$allp" | wc -w) packages"
    else
        cat "$W/user-test-1.log"; fail "user make test: exit $rc, not the exact lines of the test set before any build"
    fi
    root_runs user-test-apt.log "$lines" "root ran those lines"
    t0=$(now)
    as_user $MK test $USER_TEST_ARGS > "$W/user-test-2.log" 2>&1; rc=$?
    grep -qE "$CMD" "$W/user-test-2.log" && { grep -B2 -E "$CMD" "$W/user-test-2.log"; fail "user make test asked for packages again"; }
    suite_total "$W/user-test-2.log" $rc "user make test $USER_TEST_ARGS after it"
fi
umount_all

# --- root: make run, then make test, each on its first try ----------------------------
t0=$(now)
R=$W/root
clone_into "$R" /root/fixel
mount_in "$R"
in_root "$R" "cd /root/fixel && $MK run" > "$W/root-run.log" 2>&1; rc=$?
n=$(ls "$R"/root/fixel/out/*.png 2>/dev/null | wc -l)
if [ $rc -eq 0 ] && [ "$n" -gt 0 ] && grep -q '^deps: make run installs' "$W/root-run.log"; then
    pass "root make run, first try: installed the run set, $n pictures in out/ ($(( $(now) - t0 )) s)"
else
    tail -n 30 "$W/root-run.log"; fail "root make run, first try: exit $rc, $n pictures"
fi
# what the run set leaves out
for p in clang valgrind libcairo2-dev qemu-user-static xvfb; do
    installed "$R" $p && fail "make run installed $p (a test or bench package)"
done
if [ $do_test = 1 ]; then
    t0=$(now)
    in_root "$R" "cd /root/fixel && $MK test $TEST_ARGS" > "$W/root-test.log" 2>&1; rc=$?
    grep -q '^deps: make test installs' "$W/root-test.log" || fail "root make test installed nothing (the test set was there?)"
    suite_total "$W/root-test.log" $rc "root make test $TEST_ARGS, first try"
    # make run built fixel-kiosk before the test set brought libmosquitto-dev:
    # make test must have rebuilt it with MQTT (tools/fixel-kiosk/kiosk.mk's
    # feature stamp), or the mqtt suite fails until make clean.
    if in_root "$R" "ldd /root/fixel/build/bin/fixel-kiosk" 2>&1 | grep -q libmosquitto; then
        pass "root make test rebuilt fixel-kiosk with the MQTT libraries make run had not installed"
    else
        fail "root make test left fixel-kiosk built without libmosquitto (make run's build, not rebuilt)"
    fi
fi
umount_all
fi # do_run

# --- make deb in a fresh root, from a tree without .git -------------------------
if [ $deb_build = 1 ]; then
    t0=$(now)
    S=$W/debsrc
    arch=$(dpkg --print-architecture)
    mkdir -p "$S/root/fixel-src"
    # git archive: a release tarball of HEAD (no .git, no build/)
    git -C "$SRC" archive --format=tar HEAD | tar -x -C "$S/root/fixel-src"
    mount_in "$S"
    in_root "$S" "cd /root/fixel-src && $MK deb DEB_ARCHES=$arch" > "$W/debsrc.log" 2>&1; rc=$?
    built=$(ls "$S/root/fixel-src/build/deb/$arch"/*.deb 2>/dev/null | wc -l)
    if [ $rc -eq 0 ] && [ "$built" -ge 3 ] && grep -q '^deps: make deb installs' "$W/debsrc.log" &&
       grep -qE '^deb: [0-9]+ passed, 0 failed' "$W/debsrc.log"; then
        pass "root make deb DEB_ARCHES=$arch, first try, no .git: installed its build set, $built packages, lintian clean ($(( $(now) - t0 )) s)"
        if [ -z "$debs" ]; then
            mkdir -p "$W/debs-built/$arch" && cp "$S/root/fixel-src/build/deb/$arch"/*.deb "$W/debs-built/$arch/"
            debs=$W/debs-built
        fi
    else
        tail -n 40 "$W/debsrc.log"; fail "root make deb DEB_ARCHES=$arch in a fresh root without .git: exit $rc, $built packages"
    fi
    umount_all
fi

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
echo "fresh-root.sh: $(( $(now) - T_ALL )) s in all"
finish
