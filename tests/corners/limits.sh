# SPDX-License-Identifier: MIT
# Sourced by the generated corner suites (kiosk-corners.sh, env-corners.sh):
# limited PROGRAM CMD... runs CMD with $limit s of CPU, 30 x that of wall
# time and 1 GiB of address space (sanitized builds, whose shadow memory
# needs more address space, only the time limits), stderr to $out/err, and
# sets rc and why (empty, or what went wrong: a limit, a sanitizer report).
export UBSAN_OPTIONS=halt_on_error=1:exitcode=99:print_stacktrace=1
export ASAN_OPTIONS=exitcode=98:detect_leaks=0
wall=$((limit * 30))
limited() {
    case "$1" in *asan*) vm=unlimited;; *) vm=1048576;; esac
    shift
    ( ulimit -v $vm; ulimit -t "$limit"; timeout -k 1 "$wall" "$@" ) > /dev/null 2> "$out/err"; rc=$?
    why=""
    [ $rc -eq 124 ] && why="over the wall-time limit ($wall s): blocked?"
    [ $rc -eq 137 ] || [ $rc -eq 152 ] && why="killed: over the CPU limit ($limit s) or the wall-time limit ($wall s)"
    [ -z "$why" ] && grep -qE 'runtime error|AddressSanitizer' "$out/err" && why="sanitizer report"
}
