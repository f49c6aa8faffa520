#!/bin/bash
# SPDX-License-Identifier: MIT
# Runs test suites (each argument is one command) and adds up their closing
# "N passed, N failed" lines. A suite that exits non-zero without reporting a
# failure, or prints no such line, counts as one failure of its own.
#
# usage: run-suites.sh [--total] [-j N] COMMAND...
#   -j N      run up to N suites at once (default: FIXEL_TEST_JOBS, else 1).
#             Most suites use one core (qemu-user, the golden runner, shell
#             loops), so on CI's two cores two at a time nearly halves the
#             wall time. A command written "solo: COMMAND" runs with nothing
#             beside it: the suites that talk to a broker, boot a kernel or
#             time frames keep a machine as quiet as a serial run gave them.
#   Output: each suite's output is printed whole when it ends, under
#   "== [k/M] COMMAND", followed by its time; the order is the order of
#   ending. While suites run in parallel, every `make` they start takes a
#   lock first (a wrapper put first on PATH), so two suites never build
#   the same target at once.
# The whole script is one function, read before it runs: bash reads a
# script as it goes, and a suite run lasts long enough for a checkout or a
# merge to rewrite this file under it.
main() {
total=0
jobs=${FIXEL_TEST_JOBS:-1}
while [ $# -gt 0 ]; do
    case $1 in
    --total) total=1; shift ;;
    -j) jobs=$2; shift 2 ;;
    -j*) jobs=${1#-j}; shift ;;
    *) break ;;
    esac
done
case $jobs in ''|*[!0-9]*|0) echo "run-suites: -j wants a whole number >= 1, not '$jobs'"; exit 2 ;; esac
M=$#
P=0; F=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
t_all=$SECONDS

if [ "$jobs" -gt 1 ]; then
    # make through a lock: the lock is taken by the outermost make of a
    # suite only (FIXEL_MAKE_LOCKED marks its children), so recursive makes
    # do not wait on their own parent.
    real_make=$(command -v make)
    mkdir -p "$tmp/bin"
    cat > "$tmp/bin/make" <<EOF
#!/bin/sh
if [ -n "\$FIXEL_MAKE_LOCKED" ]; then exec "$real_make" "\$@"; fi
export FIXEL_MAKE_LOCKED=1
exec flock "$tmp/make.lock" "$real_make" "\$@"
EOF
    chmod +x "$tmp/bin/make"
    export PATH="$tmp/bin:$PATH"
fi

# collect I: prints suite I's output and adds its result to the totals
collect() {
    local i=$1 cmd=${cmds[$1]} rc line p f
    rc=$(cat "$tmp/$i.rc")
    echo "== [$i/$M] $cmd"
    cat "$tmp/$i.out"
    # CI has a time limit: each suite's share of it is worth seeing.
    echo "== [$i/$M] took $(cat "$tmp/$i.time") s"
    line=$(grep -E '^([A-Za-z0-9_-]+: )?[0-9]+ passed, [0-9]+ failed' "$tmp/$i.out" | tail -n 1)
    p=$(echo "$line" | sed -nE 's/^([A-Za-z0-9_-]+: )?([0-9]+) passed, ([0-9]+) failed.*/\2/p')
    f=$(echo "$line" | sed -nE 's/^([A-Za-z0-9_-]+: )?([0-9]+) passed, ([0-9]+) failed.*/\3/p')
    if [ -z "$p" ]; then
        echo "!! suite printed no result line (exit $rc): $cmd"
        F=$((F + 1)); failed="$failed [$i]"
        return
    fi
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "!! suite exited $rc: $cmd"
        f=1
    fi
    [ "$f" -eq 0 ] || failed="$failed [$i]"
    P=$((P + p)); F=$((F + f))
}

# launch I: starts suite I in the background
launch() {
    local i=$1
    (
        t0=$SECONDS
        sh -c "${cmds[$i]}" > "$tmp/$i.out" 2>&1 < /dev/null
        rc=$?
        echo $((SECONDS - t0)) > "$tmp/$i.time"
        echo $rc > "$tmp/$i.rc"
    ) &
    pid_of[$i]=$!
    running[$i]=1
    echo "== [$i/$M] started: ${cmds[$i]}"
}

# reap: waits until one running suite ends and collects it
reap() {
    local i
    while :; do
        for i in "${!running[@]}"; do
            if [ -s "$tmp/$i.rc" ]; then
                wait "${pid_of[$i]}" 2>/dev/null
                unset "running[$i]"
                collect "$i"
                return
            fi
        done
        wait -n 2>/dev/null || sleep 0.2
    done
}

declare -a cmds solo pid_of
declare -A running=()
failed=""
# FIXEL_TEST_ONLY="TEXT,TEXT...": only the suites whose command contains
# one of the comma-separated texts (the fresh roots' first-try make test
# runs the suites that depend on what a minimal system lacks; tests/README.md,
# "CI").
if [ -n "${FIXEL_TEST_ONLY:-}" ]; then
    kept=()
    IFS=, read -r -a words <<< "$FIXEL_TEST_ONLY"
    for c in "$@"; do
        for w in "${words[@]}"; do
            [ -n "$w" ] || continue
            case $c in *"$w"*) kept+=("$c"); break ;; esac
        done
    done
    echo "== FIXEL_TEST_ONLY=$FIXEL_TEST_ONLY: ${#kept[@]} of $# suites"
    set -- "${kept[@]}"
    M=$#
fi
i=0
for c in "$@"; do
    i=$((i + 1))
    case $c in
    solo:*) cmds[$i]=${c#solo:}; cmds[$i]=${cmds[$i]# }; solo[$i]=1 ;;
    *) cmds[$i]=$c; solo[$i]=0 ;;
    esac
done

next=1
while [ $next -le $M ] || [ ${#running[@]} -gt 0 ]; do
    if [ $next -le $M ]; then
        if [ "${solo[$next]}" = 1 ] || [ "$jobs" -eq 1 ]; then
            # alone: let the others end first
            while [ ${#running[@]} -gt 0 ]; do reap; done
            launch $next; next=$((next + 1))
            reap
            continue
        fi
        if [ ${#running[@]} -lt "$jobs" ]; then
            launch $next; next=$((next + 1))
            continue
        fi
    fi
    reap
done

echo "== $M suites in $((SECONDS - t_all)) s${failed:+; failed:$failed}"
if [ $total = 1 ]; then echo "total: $P passed, $F failed"; else echo "suites: $P passed, $F failed"; fi
[ "$F" -eq 0 ]
}
main "$@"
exit $?
