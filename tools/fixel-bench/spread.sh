#!/bin/sh
# SPDX-License-Identifier: MIT
# The ratios of fixel-bench's TABLE 1 as a spread over several runs: each
# run is interleaved within itself (section 4); this runs the program RUNS
# times and prints, per workload and ratio column, the median and the range
# of the runs' ratios (docs/PERFORMANCE.md reports them so: a shared
# machine moves single runs by tens of percent).
#   sh tools/fixel-bench/spread.sh RUNS FIXEL-BENCH [fixel-bench options...]
# SPREAD_DIR=DIR: summarise the tables already in DIR/*.txt instead.
runs=$1; bin=$2; shift 2
if [ -n "$SPREAD_DIR" ]; then
    tmp=$SPREAD_DIR
    runs=$(ls "$tmp"/*.txt | wc -l)
else
    tmp=$(mktemp -d) || exit 2
    i=1
    while [ $i -le "$runs" ]; do
        "$bin" -q --no-extras -x "$@" -o "$tmp/run$i.txt" > /dev/null 2>&1
        i=$((i + 1))
    done
fi
cat "$tmp"/*.txt | awk -v runs="$runs" '
/^TABLE 1/ { t1 = 1; next }
/^TABLE 2/ { t1 = 0 }
t1 && /fixel\/best peer/ {
    ncol = 0
    split("fixel/best peer|fixel/ceiling|api/best peer|api/ceiling", names, "|")
    for (k = 1; k <= 4; k++) { pos[k] = index($0, names[k]); if (pos[k]) ncol = k }
    next
}
t1 && /^W[0-9]/ {
    row = $1
    if (!(row in seen)) { seen[row] = 1; order[++nrows] = row }
    for (k = 1; k <= ncol; k++) {
        cell = substr($0, pos[k], 20)
        if (match(cell, /[0-9.]+ x [A-Za-z0-9-]+/)) {
            split(substr(cell, RSTART, RLENGTH), p, " ")
            n = ++cnt[row, k]; val[row, k, n] = p[1]; who[row, k] = p[3]
        }
    }
}
END {
    printf "%-27s", "workload.fmt (" runs " runs)"
    for (k = 1; k <= ncol; k++) printf "  %-28s", names[k] " median [range]"
    printf "\n"
    for (r = 1; r <= nrows; r++) {
        row = order[r]; printf "%-27s", row
        for (k = 1; k <= ncol; k++) {
            n = cnt[row, k]
            if (!n) { printf "  %-28s", "-"; continue }
            for (a = 1; a <= n; a++) v[a] = val[row, k, a] + 0
            for (a = 1; a <= n; a++) for (b = a + 1; b <= n; b++) if (v[b] < v[a]) { t = v[a]; v[a] = v[b]; v[b] = t }
            med = n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
            printf "  %-28s", sprintf("%.2f [%.2f-%.2f] %s", med, v[1], v[n], who[row, k])
        }
        printf "\n"
    }
}'
[ -n "$SPREAD_DIR" ] || rm -rf "$tmp"
