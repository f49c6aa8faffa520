#!/bin/sh
# SPDX-License-Identifier: MIT
# The test suites again, every process under valgrind (memcheck): the unit
# and golden runners directly, the tool suites through wrappers that stand
# in for build/bin/<tool>. Valgrind writes one log per process; -q keeps a
# log empty unless memcheck found an invalid access, a use of uninitialised
# memory or a leak (definite or indirect), so each non-empty log is a failure,
# whatever the exit status the suite itself expected.
# usage: run.sh BUILD OUT [quick]
build=$1; out=$2; quick=$3
if ! command -v valgrind >/dev/null 2>&1; then
    echo "valgrind: not installed (make deps installs it)"; echo "valgrind: 0 passed, 1 failed"; exit 1
fi
rm -rf "$out"; mkdir -p "$out/logs" "$out/bin"
logs=$(cd "$out/logs" && pwd)
VG="valgrind -q --error-exitcode=0 --leak-check=full --show-leak-kinds=definite,indirect --errors-for-leak-kinds=definite,indirect --track-fds=no --trace-children=no"
for t in "$build"/bin/*; do
    name=${t##*/}
    real=$(cd "$(dirname "$t")" && pwd)/$name
    printf '#!/bin/sh\nexec %s --log-file=%s/%s.%%p.log %s "$@"\n' "$VG" "$logs" "$name" "$real" > "$out/bin/$name"
    chmod +x "$out/bin/$name"
done
vb=$out/bin
if [ -n "$quick" ]; then
    set -- "sh tests/script-errors.sh $vb/fixel-draw $out/script-errors" \
           "sh tests/kiosk/run.sh $vb/fixel-kiosk $out/kiosk"
else
    set -- "$VG --log-file=$logs/unit.%p.log $build/tests/unit" \
           "$VG --log-file=$logs/golden.%p.log $build/tests/golden --dir tests/golden --out $out/golden" \
           "sh tests/script-errors.sh $vb/fixel-draw $out/script-errors" \
           "sh tests/text/gz.sh $vb/fixel-draw $out/text-gz" \
           "sh tests/kiosk/run.sh $vb/fixel-kiosk $out/kiosk" \
           "sh tests/kiosk/info.sh $vb/fixel-info" \
           "$vb/fixel-demo --golden tests/golden/demo"
fi
bash tests/run-suites.sh "$@" > "$out/suites.log" 2>&1
src=$?
tail -n 1 "$out/suites.log"
P=0; F=0
for l in "$logs"/*.log; do
    [ -e "$l" ] || continue
    if [ -s "$l" ]; then
        F=$((F + 1)); echo "FAIL valgrind: $(basename "$l")"; head -n 30 "$l"
    else
        P=$((P + 1))
    fi
done
if [ $src -ne 0 ]; then
    echo "FAIL the suites themselves failed under valgrind (see $out/suites.log):"
    grep -E '^(FAIL|!!)' "$out/suites.log" | head -n 20
    F=$((F + 1))
fi
echo "valgrind: $P passed, $F failed ($P clean process logs)"
[ $F -eq 0 ]
