#!/bin/sh
# SPDX-License-Identifier: MIT
# The fast-math guard (lib/internal.h, issue 19): lib/double.c compiled with
# -ffast-math or -ffinite-math-only must stop with the library's #error,
# and compile with -DC2D_ALLOW_FAST_MATH; with gcc and with clang.
# Usage: fast_math.sh OUTDIR.  Prints "check-fast-math: N passed, N failed".
set -u
out=${1:-build/check-fast-math}
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=check-fast-math
base="-std=c99 -O2 -ffp-contract=off -Iinclude -c lib/double.c -o $out/double.o"
refused() { # CC FLAG: the build fails, naming the guard
    # shellcheck disable=SC2086
    if "$1" $base "$2" >"$out/log" 2>&1; then echo "$1 $2: compiled"; return 1; fi
    grep -q 'collide2d: lib/ must not be built with -ffast-math or -ffinite-math-only' "$out/log" ||
        { cat "$out/log"; return 1; }
}
allowed() { # CC FLAG: the build succeeds with the opt-out
    # shellcheck disable=SC2086
    "$1" $base "$2" -DC2D_ALLOW_FAST_MATH >"$out/log" 2>&1 || { cat "$out/log"; return 1; }
}
for cc in gcc clang; do
    if ! command -v "$cc" >/dev/null 2>&1; then
        echo "check-fast-math: SKIPPED $cc: not installed"
        c2d_passed
        continue
    fi
    for flag in -ffast-math -ffinite-math-only; do
        c2d_check "$cc $flag is refused" refused "$cc" "$flag"
        c2d_check "$cc $flag -DC2D_ALLOW_FAST_MATH compiles" allowed "$cc" "$flag"
    done
    c2d_check "$cc without them compiles" "$cc" $base
done
c2d_summary
