#!/bin/sh
# SPDX-License-Identifier: MIT
# No store-forwarding stall on the hot path of c2d_collide_normal (issue 22)
# at any optimisation level the documentation names (-O0, -O2, -O3 and
# -O3 -march=native: docs/DETERMINISM.md; -Os: docs/MCU.md), with gcc and
# with clang.  A deterministic property of the machine code, not a time:
# lib/double.c and lib/float.c are compiled with the library's own flags,
# disassembled, and tests/build/stall_scan.awk follows c2d_collide_normal,
# c2d_collide and their float twins into whatever they call that is not
# C2D_COLD, reporting every stack load that overlaps an earlier store
# without lying inside it (gcc 12 -O3 stored the by-value normal as two
# 8-byte halves and read it back as one 16-byte vector; docs/SPEED.md).
# x86-64 hosts only (the widths are x86's); skips a missing compiler.
# Usage: normal_stall.sh OUTDIR.  Prints "check-normal-stall: N passed, N failed".
set -u
out=${1:-build/check-normal-stall}
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=check-normal-stall
if [ "$(uname -m)" != x86_64 ] || ! command -v objdump >/dev/null 2>&1; then
    echo "check-normal-stall: SKIPPED: needs an x86-64 host with objdump"
    c2d_passed
    c2d_summary
    exit
fi
# The functions the library keeps out of line (lib/internal.h, C2D_COLD):
# the rare tiers, where the scan stops.
cold=$(grep -rh 'C2D_COLD' lib | sed -n 's/.*C2D_COLD[^(]* \**\(c2d_[a-z0-9_]*\)(.*/\1/p' | sort -u | tr '\n' ' ')
clean() { # CC FLAGS SOURCE ROOTS: the hot path of ROOTS, compiled so, has no unforwardable load
    # shellcheck disable=SC2086
    "$1" $2 -std=c99 -ffp-contract=off -fno-math-errno -Iinclude -c "lib/$3.c" -o "$out/$3.o" \
        >"$out/log" 2>&1 || { cat "$out/log"; return 1; }
    objdump -d -M intel --no-show-raw-insn "$out/$3.o" >"$out/$3.dis" || return 1
    awk -v roots="$4" -v cold="$cold" -f tests/build/stall_scan.awk "$out/$3.dis" >"$out/found"
    [ -s "$out/found" ] || return 0
    sed "s/^/    /" "$out/found"
    return 1
}
for cc in gcc clang; do
    if ! command -v "$cc" >/dev/null 2>&1; then
        echo "check-normal-stall: SKIPPED $cc: not installed"
        c2d_passed
        continue
    fi
    for flags in -O0 -O2 -O3 "-O3 -march=native" -Os; do
        c2d_check "$cc $flags c2d_collide_normal, c2d_collide" clean "$cc" "$flags" double \
            "c2d_collide_normal c2d_collide"
        c2d_check "$cc $flags c2d_collide_normalf, c2d_collidef" clean "$cc" "$flags" float \
            "c2d_collide_normalf c2d_collidef"
    done
done
c2d_summary
