#!/bin/sh
# SPDX-License-Identifier: MIT
# make test's fuzz pass: build every target, run it over its seed corpus and
# then N more generated inputs. One check per target.
runs=${1:-3000}
P=0; F=0
if ! command -v clang >/dev/null 2>&1; then
    echo "fuzz: clang is missing (make deps installs it)"; echo "fuzz: 0 passed, 1 failed"; exit 1
fi
make --no-print-directory -s fuzz-build > build/fuzz-build.log 2>&1 || {
    cat build/fuzz-build.log | tail -20; echo "fuzz: 0 passed, 1 failed"; exit 1; }
for t in build/fuzz/fuzz_*; do
    [ -x "$t" ] || continue
    name=${t##*/fuzz_}
    corpus=tests/fuzz/corpus/$name
    log=build/fuzz/$name.log
    # new inputs go to the first directory: keep them out of the repository
    mkdir -p "build/fuzz/corpus-$name"
    if [ -d "$corpus" ]; then set -- "build/fuzz/corpus-$name" "$corpus"; else set -- "build/fuzz/corpus-$name"; fi
    if "$t" -runs="$runs" -seed=1 -max_len=4096 -artifact_prefix=build/fuzz/ "$@" > "$log" 2>&1; then
        echo "ok   fuzz $name ($(grep -c . "$log") log lines, $runs runs)"; P=$((P + 1))
    else
        echo "FAIL fuzz $name:"; grep -E 'ERROR|SUMMARY|runtime error|==ERROR' "$log" | head -n 10; F=$((F + 1))
    fi
done
echo "fuzz: $P passed, $F failed"
[ $F -eq 0 ]
