#!/bin/sh
# SPDX-License-Identifier: MIT
# `make bench-insn`: instructions per primitive of the workloads of
# docs/BENCHMARK.md, x86-64 (callgrind, counting only insn_region) next to
# aarch64 (the rpi4 build under qemu-aarch64-static; tools/fixel-bench/insn/
# qemu-count.c sums the exec trace between the markers). Counts do not
# depend on the machine's load, so they show a change where a shared box's
# timings cannot.
#
# qemu's trace is written a line per executed block, so the aarch64 counts
# take the first N primitives given below (the same prefix on both
# architectures: per-primitive averages of the same primitives); W9 (1.7 G
# instructions, a trace of ~10^8 lines) is counted on x86-64 only unless
# INSN_W9_ARM=1.
#   sh tools/fixel-bench/insn/bench-insn.sh HOSTBIN ARMBIN COUNTER [OUT]
host=$1; arm=$2; counter=$3; out=${4:-/dev/stdout}
prefix() { # workload -> primitives counted
    case $1 in
    W1_clear | W9_mandel | W10_blit) echo 1 ;;
    W2_rects) echo 2000 ;;
    W3_lines) echo 1000 ;;
    W4_aalines | W5_circles | W8_tris | W8g_tris_gouraud) echo 500 ;;
    W6_discs) echo 100 ;;
    W7_polys) echo 50 ;;
    esac
}
cg() { # args -> instructions in insn_region under callgrind
    valgrind --tool=callgrind --callgrind-out-file=/dev/null --collect-atstart=no \
        --toggle-collect=insn_region "$@" 2>&1 | sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'
}
qc() { # args -> instructions between the markers under qemu-aarch64
    qemu-aarch64-static -d in_asm,exec,nochain -D /dev/stdout "$@" | "$counter"
}
have_cg=1; command -v valgrind >/dev/null 2>&1 || have_cg=0
have_q=1
{ [ -x "$arm" ] && [ -x "$counter" ] && command -v qemu-aarch64-static >/dev/null 2>&1; } || have_q=0
{
echo "INSTRUCTIONS per primitive (x86-64: callgrind; aarch64: qemu-user exec trace; rpi4 build, -mcpu=cortex-a72)"
printf '%-27s %6s %14s %14s %10s\n' workload.fmt n x86-64 aarch64 arm/x86
"$host" --list | while read -r w nfull fmts; do
    n=$(prefix "$w")
    for f in $(echo "$fmts" | tr , ' '); do
        x=-; a=-
        [ $have_cg = 1 ] && x=$(cg "$host" -w "$w" -f "$f" -n "$n")
        if [ $have_q = 1 ] && { [ "$w" != W9_mandel ] || [ "${INSN_W9_ARM:-0}" = 1 ]; }; then
            a=$(qc "$arm" -w "$w" -f "$f" -n "$n")
        fi
        awk -v w="$w.$f" -v n="$n" -v x="$x" -v a="$a" 'BEGIN {
            xs = x == "-" || x == "" ? "-" : sprintf("%.1f", x / n)
            as = a == "-" || a == "" ? "-" : sprintf("%.1f", a / n)
            r = (xs != "-" && as != "-" && x > 0) ? sprintf("%.2f", a / x) : "-"
            printf "%-27s %6d %14s %14s %10s\n", w, n, xs, as, r }'
    done
done
[ $have_cg = 1 ] || echo "(no valgrind: x86-64 column empty)"
[ $have_q = 1 ] || echo "(no aarch64 build or qemu-aarch64-static: aarch64 column empty)"
} | tee "$out"
