#!/bin/sh
# SPDX-License-Identifier: MIT
# rpi-zero's board libraries (armel: libdrm, libevdev, libgpiod, libpng,
# zlib) in a private sysroot, for a host where the multiarch packages
# (libpng-dev:armel ...) cannot be installed: bookworm's security suite has
# no armel, so once the host's zlib1g, libpng16-16 or linux-libc-dev has a
# security update the armel ones (bookworm main only, older) cannot match it,
# and multiarch needs equal versions. Downloading a package needs no match:
# `apt-get download` fetches the .debs from bookworm main and checks each
# against the hash of the index apt verified with the archive's signature
# (it refuses an unauthenticated one), and dpkg-deb -x unpacks them here
# without installing anything. boards/rpi-zero.mk uses the sysroot when the
# multiarch packages are absent.
#
# usage: sysroot-armel.sh [DIR]   (default build/sysroot-armel; make clean
#   removes it, tests/arm/deps.sh makes it again). Needs the armel index
#   (dpkg --add-architecture armel && apt-get update, which deps.sh does as
#   root); the download itself needs no root. Exits 1, saying why, when the
#   sysroot cannot be made; an existing complete one is kept.
set -u
say() { echo "tests/arm/sysroot-armel.sh: $*"; }
dir=${1:-build/sysroot-armel}
# The -dev packages and their runtime libraries (the .so symlinks point into
# them), nothing else: libc, libgcc and the kernel headers come with the
# cross toolchain (libc6-dev-armel-cross, linux-libc-dev-armel-cross); the
# rest of libdrm-dev's dependencies are the GPU drivers' libraries and
# libpciaccess, which libdrm.pc does not require; libgpiod2's libstdc++ is
# for its C++ bindings.
pkgs="zlib1g zlib1g-dev libpng16-16 libpng-dev libdrm2 libdrm-dev libevdev2 libevdev-dev libgpiod2 libgpiod-dev"
stamp=$dir/.fixel-sysroot
# The stamp names the packages it was made from: a list changed here remakes it.
if [ -f "$stamp" ] && [ "$(sed -n 's/^package //p' "$stamp" | cut -d' ' -f1 | sort | tr '\n' ' ')" = \
                         "$(printf '%s\n' $pkgs | sort | tr '\n' ' ')" ]; then
    exit 0
fi
for c in apt-get dpkg-deb pkg-config; do
    command -v $c >/dev/null 2>&1 || { say "no $c here (a Debian host is needed)"; exit 1; }
done
mkdir -p "$(dirname "$dir")" || exit 1
# Made beside DIR and renamed into place at the end: an interrupted or
# failed run never leaves a half sysroot that the Makefile would take.
tmp=$(mktemp -d "$(dirname "$dir")/.sysroot-armel.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' INT TERM HUP
mkdir "$tmp/debs" "$tmp/root"
# apt drops to the _apt user to download: let it write there.
# (mktemp -d is 0700: _apt must be able to pass through it too)
[ "$(id -u)" = 0 ] && id _apt >/dev/null 2>&1 && chmod 755 "$tmp" && chown _apt "$tmp/debs"
if ! (cd "$tmp/debs" && apt-get -q download $(printf '%s:armel ' $pkgs)) > "$tmp/download.log" 2>&1; then
    say "could not download the armel packages from the Debian archive:"
    grep -E '^E:' "$tmp/download.log" | head -n 2 | cut -c1-240 | sed 's/^/  /'
    grep -q 'armel' "$tmp/download.log" && ! dpkg --print-foreign-architectures | grep -qx armel &&
        say "(armel is not a dpkg architecture here: dpkg --add-architecture armel && apt-get update, as root)"
    exit 1
fi
for f in "$tmp"/debs/*.deb; do
    dpkg-deb -x "$f" "$tmp/root" || { say "could not unpack $f"; exit 1; }
    echo "package $(dpkg-deb -f "$f" Package) $(dpkg-deb -f "$f" Version)" >> "$tmp/root/.fixel-sysroot"
done
# An absolute link (zlib1g-dev's libz.so -> /lib/arm-linux-gnueabi/...)
# would point at the host's tree: made relative, it stays in the sysroot.
(cd "$tmp/root" && find . -type l) | while read -r l; do
    t=$(readlink "$tmp/root/$l")
    case $t in
    /*) d=$(dirname "${l#./}")
        if [ "$d" = . ]; then up=.; else up=$(echo "$d" | sed 's|[^/][^/]*|..|g'); fi
        ln -sfn "$up$t" "$tmp/root/$l" ;;
    esac
done
# The same query boards/rpi-zero.mk makes: every library must be found.
if ! PKG_CONFIG_SYSROOT_DIR="$tmp/root" \
     PKG_CONFIG_LIBDIR="$tmp/root/usr/lib/arm-linux-gnueabi/pkgconfig:$tmp/root/usr/share/pkgconfig" \
     pkg-config --exists libpng zlib libdrm libevdev libgpiod; then
    say "the unpacked packages lack a pkg-config file (libpng zlib libdrm libevdev libgpiod)"
    exit 1
fi
rm -rf "$dir" && mv "$tmp/root" "$dir" || exit 1
say "made $dir ($(grep -c '^package ' "$dir/.fixel-sysroot") packages: $(sed -n 's/^package //p' "$dir/.fixel-sysroot" | tr '\n' ' '| sed 's/ $//'))"
