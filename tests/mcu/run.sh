#!/bin/sh
# SPDX-License-Identifier: MIT
# Run one MCU test binary under QEMU with semihosting and judge it: QEMU's
# exit status (the harness's, through semihosting) must be 0 and the last
# line must read "NAME: N passed, 0 failed" with N > 0.  A hung target is
# killed by the timeout and fails.
# Usage: run.sh NAME ELF QEMU-COMMAND...
set -u
name=$1 elf=$2
shift 2
out=$(timeout -k 5 "${C2D_MCU_TIMEOUT:-60}" "$@" -nographic -monitor none \
    -semihosting-config enable=on,target=native -kernel "$elf" 2>&1)
rc=$?
printf '%s\n' "$out"
last=$(printf '%s\n' "$out" | tail -n 1)
if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    echo "$name: FAILED (timed out)"
    exit 1
fi
if [ $rc -ne 0 ]; then
    echo "$name: FAILED (exit status $rc)"
    exit 1
fi
if ! printf '%s\n' "$last" | grep -Eq "^$name: [1-9][0-9]* passed, 0 failed\$"; then
    echo "$name: FAILED (no closing \"N passed, 0 failed\" line)"
    exit 1
fi
