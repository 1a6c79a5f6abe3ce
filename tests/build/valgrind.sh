#!/bin/sh
# SPDX-License-Identifier: MIT
# valgrind.sh BILLIARDS OUTDIR - short headless demo runs under memcheck:
# any memory error or a definitely lost block fails the run.  Prints
# "valgrind: N passed, N failed".
set -u
bin=$1
out=${2:-build/valgrind}
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=valgrind
vg() { # name expected-exit args...  (valgrind's own failure exit: 99)
    name=$1
    want=$2
    shift 2
    valgrind --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \
        --log-file="$out/$name.log" "$bin" "$@" >"$out/$name.out" 2>"$out/$name.err"
    rc=$?
    if [ "$rc" -eq "$want" ]; then
        c2d_passed
        echo "valgrind: $name: $(grep -h 'ERROR SUMMARY' "$out/$name.log" | sed 's/^==[0-9]*== //')"
    else
        c2d_failed "$name: exit $rc, want $want (log: $out/$name.log)"
        grep -h -A12 'Invalid\|uninitialised\|definitely lost\|ERROR SUMMARY' "$out/$name.log" | head -40 >&2
        cat "$out/$name.err" >&2
    fi
}
vg break 0 --headless --seconds 2 --json --screenshot "$out/break.png"
vg break-box2d 0 --headless --response box2d --seconds 2 --json
vg gas 0 --headless --scene gas --balls 200 --seconds 1 --json
# a refused flag: exit 2 with a message, and still nothing leaked or misread
vg bad-flag 2 --headless --seconds -1
c2d_summary
