#!/bin/sh
# SPDX-License-Identifier: MIT
# The Debian packages the GLUT corpus needs on the Mesa side: Xvfb to give
# freeglut a display, freeglut and GLU headers to build the programs, Mesa's
# software drivers (llvmpipe, the reference, and softpipe), libpng for the
# shim and the comparison; on fixel's side, the X11 bitmap fonts freeglut's
# GLUT_BITMAP_* fonts are (xfonts-base, xfonts-75dpi) and FreeType, which
# reads them (headers at build time, libfreetype6 at run time). Installs the missing ones as root (tests/deps.sh),
# otherwise prints the apt-get command.
#   sh tests/glut/deps.sh          install what is missing
#   sh tests/glut/deps.sh --list   print the list
GLUT_DEB_PKGS="xvfb xauth freeglut3-dev libglu1-mesa-dev libgl1-mesa-dri libpng-dev pkg-config gcc xfonts-base xfonts-75dpi libfreetype-dev"
if [ "${1:-}" = "--list" ]; then echo $GLUT_DEB_PKGS; exit 0; fi
here=$(cd "$(dirname "$0")/.." && pwd)
exec sh "$here/deps.sh" $GLUT_DEB_PKGS
