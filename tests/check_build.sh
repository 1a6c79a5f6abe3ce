#!/bin/sh
# Build-contract checks for lib/: warning-free under gcc and clang with the
# strict flags, every C2D_NO_* option, freestanding with only the compiler's
# own headers, `cc -std=c99 -c lib/*.c` with no other flag, and no outside
# symbols but sqrt/sqrtf.  Prints "N passed, N failed".
set -u
out=${1:-build/check-build}
mkdir -p "$out"
pass=0
fail=0
check() { # name command...
    name=$1
    shift
    if "$@" >"$out/log" 2>&1; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "check-build: FAILED $name" >&2
        cat "$out/log" >&2
    fi
}
strict="-std=c99 -pedantic -Wall -Wextra -Wconversion -Wshadow -Werror"
for cc in gcc clang; do
    for opt in "" -DC2D_NO_DOUBLE -DC2D_NO_FLOAT -DC2D_NO_FIXED "-DC2D_NO_DOUBLE -DC2D_NO_FLOAT" "-DC2D_NO_FLOAT -DC2D_NO_FIXED"; do
        # shellcheck disable=SC2086
        check "$cc strict $opt" $cc $strict -O2 $opt -c lib/collide2d.c -o "$out/lib.o"
    done
    fsinc=$($cc -print-file-name=include)
    check "$cc freestanding" $cc $strict -O2 -ffreestanding -nostdinc -isystem "$fsinc" -c lib/collide2d.c -o "$out/fs_$cc.o"
done
check "plain cc -std=c99 -c lib/*.c" sh -c "cd '$out' && cc -std=c99 -c '$PWD'/lib/*.c"
undefined_only_sqrt() {
    extra=$(nm -u "$out/fs_gcc.o" | awk '{print $2}' | grep -vx -e sqrt -e sqrtf)
    [ -z "$extra" ] || { echo "unexpected outside symbols: $extra"; return 1; }
}
check "outside symbols are only sqrt/sqrtf" undefined_only_sqrt
# The batch kernel must stay vectorised (a stray branch or a mask conversion
# silently turns it scalar): float at gcc -O2 on baseline x86-64, double
# too from x86-64-v2 (SSE4.2's 64-bit compares), both under clang -O2.
vectorised_loops() { # compiler flags... -> number of vectorised loops
    "$@" -O2 -std=c99 -ffp-contract=off -Iinclude -c lib/collide2d.c -o "$out/vec.o" 2>&1 |
        grep -c -e 'loop vectorized' -e 'vectorized loop'
}
if [ "$(uname -m)" = x86_64 ]; then
    check "gcc -O2 vectorises the float batch kernel" test "$(vectorised_loops gcc -fopt-info-vec)" -ge 1
    check "gcc -O2 -march=x86-64-v2 vectorises both batch kernels" \
        test "$(vectorised_loops gcc -march=x86-64-v2 -fopt-info-vec)" -ge 2
    check "clang -O2 vectorises both batch kernels" \
        test "$(vectorised_loops clang -Rpass=loop-vectorize)" -ge 2
fi
check "header compiles as C++ (g++ -std=c++11)" g++ -std=c++11 -pedantic -Wall -Wextra -Werror -fsyntax-only -x c++ include/collide2d.h
echo "check-build: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
