#!/bin/sh
# SPDX-License-Identifier: MIT
# The dependency rules of docs/ARCHITECTURE.md, checked on the sources:
# every #include of kernel-free-src/, boards/ and tools/ is resolved the way
# the compiler resolves it (the including file's folder, then
# -Ikernel-free-src/include, then -Iboards/include) and must land where its
# layer may look; and the library proper never reads the environment.
#
#   core    kernel-free-src/  its own headers (public and private) and the
#                             freestanding C headers in CORE_SYS; never boards/
#                             or tools/
#   boards  boards/           any system header, the core's public headers
#                             (kernel-free-src/include), its own headers; never
#                             a core private header (kernel-free-src/<sub>/),
#                             never tools/; boards/memory/ and boards/image/
#                             never boards/linux/
#   tools   tools/<name>/     any system header, the public headers of both
#                             layers, the tool's own files; never a private
#                             header of the core or of boards/
#   public  */include/fixel/  public headers include public headers only
#   getenv  kernel-free-src/ and boards/ call getenv only in ENV_FILES
#
# Usage: check-layers.sh [ROOT]   Prints each violation and, last,
# "layers: N passed, N failed" (one check per include line and per file for
# getenv); exits non-zero on any failure.
cd "${1:-.}" || exit 2

# Freestanding headers the core may include (C11 4p6; stdarg.h for the
# trace callbacks' formatting). Compiler intrinsics headers would join here;
# the core uses none today.
CORE_SYS="stdint.h stddef.h stdbool.h limits.h stdarg.h"
# The one place of the library allowed to read the environment: the
# documented fx_*_options_from_env() functions (issue #19). A file named
# env.c anywhere under boards/.
ENV_FILES='^boards/(.*/)?env\.c$'

P=0; F=0
pass() { P=$((P + 1)); }
fail() { F=$((F + 1)); echo "FAIL: $*"; }

# resolve FILE NAME: the path (relative to ROOT) a quoted #include "NAME" in
# FILE opens, or nothing when no candidate exists.
resolve() {
    for c in "$(dirname "$1")/$2" "kernel-free-src/include/$2" "boards/include/$2"; do
        if [ -f "$c" ]; then realpath -m --relative-to=. "$c"; return; fi
    done
}

# includes FILE: "LINE<TAB>KIND<TAB>NAME" per #include (KIND q or a).
includes() {
    grep -n '^[[:space:]]*#[[:space:]]*include' "$1" |
        sed -n 's/^\([0-9]*\):[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1	q	\2/p
                s/^\([0-9]*\):[[:space:]]*#[[:space:]]*include[[:space:]]*<\([^>]*\)>.*/\1	a	\2/p'
}

is_public() { case "$1" in kernel-free-src/include/* | boards/include/*) return 0 ;; esac; return 1; }

check_file() { # FILE LAYER
    f=$1; layer=$2
    tab=$(printf '\t')
    includes "$f" > "$tmp"
    while IFS="$tab" read -r line kind name; do
        [ "$kind" = q ] && where="$f:$line: #include \"$name\"" || where="$f:$line: #include <$name>"
        r=""
        if [ "$kind" = q ]; then
            r=$(resolve "$f" "$name")
            if [ -z "$r" ]; then fail "$where: no such file from $(dirname "$f") or the include path"; continue; fi
        else
            case "$name" in fixel/*) r=$(resolve /nonexistent/x "$name") ;; esac
        fi
        # a public header only ever includes public headers (or system ones)
        if is_public "$f" && [ -n "$r" ] && ! is_public "$r"; then
            fail "$where: a public header includes the private $r"; continue
        fi
        case $layer in
        core)
            if [ -z "$r" ]; then
                case " $CORE_SYS " in *" $name "*) pass ;; *) fail "$where: the core includes only $CORE_SYS from the system" ;; esac
            else
                case $r in kernel-free-src/*) pass ;; *) fail "$where: the core may not include $r (boards/ and tools/ are above it)" ;; esac
            fi ;;
        boards)
            case $r in
            "") pass ;;
            kernel-free-src/include/*) pass ;;
            kernel-free-src/*) fail "$where: boards/ may not include the core's private $r (public headers only)" ;;
            boards/linux/*)
                case $f in boards/memory/* | boards/image/*) fail "$where: ${f%/*}/ may not include $r (memory and image never depend on linux/)" ;;
                *) pass ;; esac ;;
            boards/*) pass ;;
            *) fail "$where: boards/ may not include $r" ;;
            esac ;;
        tools)
            tool=$(echo "$f" | cut -d/ -f1-2)
            case $r in
            "") pass ;;
            kernel-free-src/include/* | boards/include/*) pass ;;
            "$tool"/*) pass ;;
            *) fail "$where: tools include public headers only, not $r" ;;
            esac ;;
        esac
    done < "$tmp"
}

tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT

for f in $(find kernel-free-src -name '*.[ch]' | sort); do check_file "$f" core; done
for f in $(find boards -name '*.[ch]' | sort); do check_file "$f" boards; done
for f in $(find tools -name '*.[ch]' | sort); do check_file "$f" tools; done

# getenv: one check per library file; comment lines are not calls.
for f in $(find kernel-free-src boards -name '*.[ch]' | sort); do
    hits=$(grep -nE '(^|[^A-Za-z0-9_])(secure_)?getenv[[:space:]]*\(' "$f" |
        grep -vE '^[0-9]+:[[:space:]]*(\*|/\*|//)')
    if [ -z "$hits" ] || echo "$f" | grep -qE "$ENV_FILES"; then
        pass
    else
        n=$(echo "$hits" | wc -l)
        fail "$f: $n getenv call(s) in the library proper (only $ENV_FILES may read the environment): lines $(echo "$hits" | cut -d: -f1 | tr '\n' ' ')"
    fi
done

echo "layers: $P passed, $F failed"
[ "$F" -eq 0 ]
