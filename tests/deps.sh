#!/bin/sh
# Installs the Debian packages fixel needs when they are missing: with apt-get
# when run as root, otherwise it stops with the exact command to run.
[ "$1" = "--check" ] && shift
command -v dpkg-query >/dev/null 2>&1 || { echo "deps: not a Debian system; install the equivalents of: $*"; exit 0; }
missing=""
for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" -eq 0 ]; then
    echo "deps: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    # a mirror mid-sync can fail one index; the others still serve
    apt-get -o DPkg::Lock::Timeout=300 update -qq || apt-get -o DPkg::Lock::Timeout=300 update -qq || true
    apt-get -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends $missing >/dev/null ||
        { echo "deps: apt-get failed"; exit 1; }
else
    echo "fixel needs these packages: run"
    echo "  sudo apt-get install$missing"
    exit 1
fi
