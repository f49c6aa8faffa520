#!/bin/sh
# SPDX-License-Identifier: MIT
# The long fuzzing campaign (issue #26; not part of make test): each
# TARGET:SECONDS in turn on one core at low priority, ASan + UBSan with
# -fno-sanitize-recover=all (fuzz.mk), continuing from its own corpus in
# build/fuzz-campaign/ and the seeds. Each binary is copied just before it
# runs, so a rebuild does not disturb the run. A line per target goes to
# build/fuzz-campaign/summary.txt: executions, seconds, rate, result.
#   sh tests/fuzz/campaign.sh fuzz_gkiosk:900 fuzz_grammar:600 ...
dir=build/fuzz-campaign
mkdir -p "$dir/bin" "$dir/artifacts"
for spec in "$@"; do
    t=${spec%%:*}; secs=${spec#*:}
    name=${t#fuzz_}
    cp "build/fuzz/$t" "$dir/bin/$t" || exit 1
    mkdir -p "$dir/corpus/$name"
    set -- "$dir/corpus/$name"
    [ -d "tests/fuzz/corpus/$name" ] && set -- "$@" "tests/fuzz/corpus/$name"
    start=$(date +%s)
    nice -n 15 "$dir/bin/$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$dir/artifacts/$name-" "$@" > "$dir/$name.log" 2>&1
    rc=$?
    end=$(date +%s)
    n=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$dir/$name.log" | tail -1 | grep -o '[0-9]*$')
    [ -n "$n" ] || n=$(grep -o '^#[0-9]*' "$dir/$name.log" | tail -1 | tr -d '#')
    if [ $rc -eq 0 ]; then res=clean; else res="FAILED (exit $rc): $(grep -m1 -E 'ERROR|runtime error' "$dir/$name.log")"; fi
    echo "$t $n executions $((end - start)) s $((n / (end - start + 1))) exec/s $(date -u +%FT%TZ) $res" >> "$dir/summary.txt"
done
