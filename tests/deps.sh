#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the Debian packages fixel needs when they are missing: with apt-get
# when run as root, otherwise it stops (exit 1) with the exact commands to run.
#
# usage: deps.sh [--check] [--for WHAT] PACKAGE[:ARCH]...
#   PACKAGE:ARCH is a multiarch package (arm64 -dev libraries for the cross
#   tests); its architecture is added to dpkg first.
#   --for names the purpose in the message ("make run", "make test"...).
#   --check is accepted for old callers and means the same.
#   --no-install only names what is missing (exit 1), root or not: for a
#   make that has already evaluated pkg-config (a cross build's tools).
[ "$1" = "--check" ] && shift
noinstall=0
if [ "$1" = "--no-install" ]; then noinstall=1; shift; fi
what="fixel"
if [ "$1" = "--for" ]; then what="$2"; shift 2; fi
command -v dpkg-query >/dev/null 2>&1 || { echo "deps: not a Debian system; install the equivalents of: $*"; exit 0; }
missing=""
arches=""
foreign=$(dpkg --print-foreign-architectures 2>/dev/null)
for p in "$@"; do
    case $p in
    *:*) a=${p#*:}
         if ! echo "$foreign" | grep -qx "$a" && [ "$a" != "$(dpkg --print-architecture)" ]; then
             case " $arches " in *" $a "*) ;; *) arches="$arches $a" ;; esac
         fi ;;
    esac
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
APT="apt-get -o DPkg::Lock::Timeout=300"
if [ "$(id -u)" -eq 0 ] && [ $noinstall = 0 ]; then
    echo "deps: $what installs$missing"
    export DEBIAN_FRONTEND=noninteractive
    for a in $arches; do dpkg --add-architecture "$a"; done
    # a mirror mid-sync can fail one index; the others still serve
    $APT update -qq || $APT update -qq || true
    # Native packages first, then each foreign architecture's on their own:
    # apt resolving both at once on a fresh system reported "held broken
    # packages" where the two steps succeed, and one architecture's index out
    # of step with the others (a mirror mid-sync, seen for armhf) must not stop
    # the rest (tests/arm/test-arm.sh skips an architecture without them, saying so).
    native=$(for p in $missing; do case $p in *:*) ;; *) echo "$p" ;; esac; done)
    # A download that fails (a dropped connection, a mirror mid-sync) is
    # retried once after a fresh update; failing twice stops.
    [ -z "$native" ] || $APT install -y -qq --no-install-recommends $native >/dev/null ||
        { echo "deps: apt-get install failed; updating and retrying once"; sleep 10; $APT update -qq
          $APT install -y -qq --no-install-recommends $native >/dev/null; } ||
        { echo "deps: apt-get install failed for:" $native; exit 1; }
    for a in $(for p in $missing; do case $p in *:*) echo "${p#*:}" ;; esac; done | sort -u); do
        $APT install -y -qq --no-install-recommends $(for p in $missing; do case $p in *:$a) echo "$p" ;; esac; done) >/dev/null ||
            echo "deps: could not install the $a packages (mirror out of step?); going on without them"
    done
else
    sudo="sudo "; [ "$(id -u)" -eq 0 ] && sudo=""
    how="run"
    # a root without sudo (a fresh Debian, a container): say who runs it
    if [ -n "$sudo" ] && ! command -v sudo >/dev/null 2>&1; then sudo=""; how="run as root"; fi
    echo "$what needs Debian packages that are missing; $how:"
    for a in $arches; do echo "  ${sudo}dpkg --add-architecture $a"; done
    # the same two steps as above: native packages, then each architecture's
    native=$(for p in $missing; do case $p in *:*) ;; *) printf ' %s' "$p" ;; esac; done)
    foreign=$(for p in $missing; do case $p in *:*) echo "${p#*:}" ;; esac; done | sort -u)
    if [ -n "$native" ]; then
        echo "  ${sudo}apt-get update && ${sudo}apt-get install -y --no-install-recommends$native"
    else
        echo "  ${sudo}apt-get update"
    fi
    for a in $foreign; do
        echo "  ${sudo}apt-get install -y --no-install-recommends$(for p in $missing; do case $p in *:$a) printf ' %s' "$p" ;; esac; done)"
    done
    exit 1
fi
