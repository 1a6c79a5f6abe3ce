#!/bin/sh
# SPDX-License-Identifier: MIT
# Run one MCU test binary under QEMU with semihosting and judge it: QEMU's
# exit status (the harness's, through semihosting) must be 0 and the last
# line must read "NAME: N passed, 0 failed" with N > 0.  A hung target is
# killed by the timeout and fails.  On success that line of the harness's
# is the last; on failure the reason follows ("NAME: FAILED ..." on stderr)
# and then a closing line of the same form (tests/harness/tally.sh): the
# harness's counts when it printed them (at least 1 failed), else 0 passed,
# 1 failed.
# Usage: run.sh NAME ELF QEMU-COMMAND...
set -u
name=$1 elf=$2
shift 2
. tests/harness/tally.sh
c2d_tally_name=$name
out=$(timeout -k 5 "${C2D_MCU_TIMEOUT:-60}" "$@" -nographic -monitor none \
    -semihosting-config enable=on,target=native -kernel "$elf" 2>&1)
rc=$?
printf '%s\n' "$out"
last=$(printf '%s\n' "$out" | tail -n 1)
# fail REASON: the reason, then the closing line with the harness's counts
fail() {
    p=$(printf '%s\n' "$last" | sed -n "s/^$name: \([0-9]*\) passed, \([0-9]*\) failed\$/\1/p")
    f=$(printf '%s\n' "$last" | sed -n "s/^$name: \([0-9]*\) passed, \([0-9]*\) failed\$/\2/p")
    c2d_pass=${p:-0}
    c2d_fail=${f:-0}
    [ "$c2d_fail" -gt 0 ] && c2d_fail=$((c2d_fail - 1)) # the harness's failures, or this one
    c2d_failed "$1"
    c2d_summary
    exit 1
}
if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    fail "(timed out)"
fi
if [ $rc -ne 0 ]; then
    fail "(exit status $rc)"
fi
if ! printf '%s\n' "$last" | grep -Eq "^$name: [1-9][0-9]* passed, 0 failed\$"; then
    fail "(no closing \"N passed, 0 failed\" line)"
fi
