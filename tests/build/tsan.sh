#!/bin/sh
# SPDX-License-Identifier: MIT
# The library under ThreadSanitizer, with gcc and with clang: lib/*.c and
# tests/build/tsan_main.c built with -fsanitize=thread must run to the end
# with no report (issue 19: gcc's instrumented ifunc resolver of the batch
# kernel segfaulted in the loader, before main; internal.h turns the
# dispatch off under TSan).  A compiler without TSan (or a host where its
# run time cannot start) is skipped with a message and counted as passed.
# Usage: tsan.sh OUTDIR.  Prints "check-tsan: N passed, N failed".
set -u
out=${1:-build/check-tsan}
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=check-tsan
flags="-std=c99 -O1 -g -ffp-contract=off -fno-math-errno -fsanitize=thread -Iinclude"
has_tsan() { # CC: a trivial TSan program builds and runs
    printf 'int main(void) { return 0; }\n' >"$out/probe.c"
    "$1" -fsanitize=thread "$out/probe.c" -o "$out/probe_$1" >/dev/null 2>&1 && "$out/probe_$1" >/dev/null 2>&1
}
build_and_run() { # CC
    dir=$out/$1
    mkdir -p "$dir"
    for f in lib/*.c; do
        # shellcheck disable=SC2086
        "$1" $flags -c "$f" -o "$dir/$(basename "$f" .c).o" || return 1
    done
    # shellcheck disable=SC2086
    "$1" $flags tests/build/tsan_main.c "$dir"/*.o -o "$dir/tsan_main" -lpthread -lm || return 1
    TSAN_OPTIONS="halt_on_error=1 exitcode=66" "$dir/tsan_main" || { echo "tsan_main under $1: exit status $?"; return 1; }
}
for cc in gcc clang; do
    if ! command -v "$cc" >/dev/null 2>&1; then
        echo "check-tsan: SKIPPED $cc: not installed"
        c2d_passed
    elif ! has_tsan "$cc"; then
        echo "check-tsan: SKIPPED $cc: no working -fsanitize=thread (ThreadSanitizer)"
        c2d_passed
    else
        c2d_check "$cc -fsanitize=thread: a program linking the library runs" build_and_run "$cc"
    fi
done
c2d_summary
