#!/bin/sh
# SPDX-License-Identifier: MIT
# Build-contract checks for lib/: warning-free under gcc and clang with the
# strict flags, every C2D_NO_* option, freestanding with only the compiler's
# own headers, `cc -std=c99 -c lib/*.c` with no other flag, no outside
# symbols but sqrt/sqrtf, no file that includes itself or a .c file, and the
# amalgamated single file (scripts/amalgamate.sh) held to the same contract.
# Usage: check_build.sh OUTDIR AMALGAMATION.  Prints "check-build: N passed,
# N failed".
set -u
out=${1:-build/check-build}
all=${2:-build/collide2d_all.c}
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=check-build
check() { # name command...: the command's output is shown when it fails
    name=$1
    shift
    if "$@" >"$out/log" 2>&1; then
        c2d_passed
    else
        c2d_failed "$name"
        cat "$out/log" >&2
    fi
}
strict="-std=c99 -pedantic -Wall -Wextra -Wconversion -Wshadow -Werror"
# compile_lib DIR CC FLAGS...: every translation unit of lib/ into DIR
compile_lib() {
    dir=$1
    cc=$2
    shift 2
    mkdir -p "$dir"
    for f in lib/*.c; do
        "$cc" "$@" -c "$f" -o "$dir/$(basename "$f" .c).o" || return 1
    done
}
for cc in gcc clang; do
    for opt in "" -DC2D_NO_DOUBLE -DC2D_NO_FLOAT -DC2D_NO_FIXED "-DC2D_NO_DOUBLE -DC2D_NO_FLOAT" "-DC2D_NO_FLOAT -DC2D_NO_FIXED"; do
        # shellcheck disable=SC2086
        check "$cc strict $opt" compile_lib "$out/lib" $cc $strict -O2 $opt
        # shellcheck disable=SC2086
        check "$cc strict $opt (amalgamation)" $cc $strict -O2 $opt -Iinclude -c "$all" -o "$out/all.o"
    done
    fsinc=$($cc -print-file-name=include)
    check "$cc freestanding" compile_lib "$out/fs_$cc" $cc $strict -O2 -ffreestanding -nostdinc -isystem "$fsinc"
    check "$cc freestanding (amalgamation)" $cc $strict -O2 -ffreestanding -nostdinc -isystem "$fsinc" -Iinclude \
        -c "$all" -o "$out/fs_all_$cc.o"
done
check "plain cc -std=c99 -c lib/*.c" sh -c "cd '$out' && cc -std=c99 -c '$PWD'/lib/*.c"
# What the objects need and none of them defines (the world, world.c, calls
# the impact of double.c: that is inside the library, not outside it).
undefined_only_sqrt() { # object files...
    nm -g --defined-only "$@" | awk 'NF == 3 {print $3}' | sort -u >"$out/syms_defined"
    extra=$(nm -u "$@" | awk 'NF == 2 {print $2}' | sort -u | comm -23 - "$out/syms_defined" |
        grep -vx -e sqrt -e sqrtf)
    [ -z "$extra" ] || { echo "unexpected outside symbols: $extra"; return 1; }
}
check "outside symbols are only sqrt/sqrtf" undefined_only_sqrt "$out"/fs_gcc/*.o
check "outside symbols are only sqrt/sqrtf (amalgamation)" undefined_only_sqrt "$out/fs_all_gcc.o"
same_public_symbols() {
    nm -g --defined-only "$out"/fs_gcc/*.o | awk 'NF == 3 {print $3}' | sort >"$out/syms_lib"
    nm -g --defined-only "$out/fs_all_gcc.o" | awk 'NF == 3 {print $3}' | sort >"$out/syms_all"
    cmp "$out/syms_lib" "$out/syms_all"
}
check "amalgamation defines the same public symbols as lib/" same_public_symbols
no_self_or_c_include() {
    bad=$(grep -rn --include='*.[ch]' --include='*.cpp' '#include *"[^"]*\.c"' lib include referee tests bench)
    for f in $(find lib -type f -name "*.[ch]"); do
        grep -q "#include *\"$(basename "$f")\"" "$f" && bad="$bad $f includes itself"
    done
    [ -z "$bad" ] || { echo "$bad"; return 1; }
}
check "no file includes itself or a .c file" no_self_or_c_include
# The batch kernel must stay vectorised (a stray branch or a mask conversion
# silently turns it scalar): float at gcc -O2 on baseline x86-64, double
# too from x86-64-v2 (SSE4.2's 64-bit compares), both under clang -O2.
vectorised_loops() { # compiler flags... -> number of vectorised loops
    for f in lib/double.c lib/float.c; do
        "$@" -O2 -std=c99 -ffp-contract=off -Iinclude -c "$f" -o "$out/vec.o" 2>&1
    done | grep -c -e 'loop vectorized' -e 'vectorized loop'
}
if [ "$(uname -m)" = x86_64 ]; then
    check "gcc -O2 vectorises the float batch kernel" test "$(vectorised_loops gcc -fopt-info-vec)" -ge 1
    check "gcc -O2 -march=x86-64-v2 vectorises both batch kernels" \
        test "$(vectorised_loops gcc -march=x86-64-v2 -fopt-info-vec)" -ge 2
    check "clang -O2 vectorises both batch kernels" \
        test "$(vectorised_loops clang -Rpass=loop-vectorize)" -ge 2
fi
# The opt-in inline front ends (C2D_INLINE): warning-free in a translation
# unit under gcc, clang and g++, on where the header can tell the compiler
# evaluates as written and off (plain calls) where it cannot.
inline_tu() {
    printf '#define C2D_INLINE\n#include "collide2d.h"\nint c2d_as_written(void);\nint c2d_as_written(void) { return C2D_INLINE_AS_WRITTEN; }\n' >"$out/inline.c"
}
inline_flag() { # compiler flags... -> C2D_INLINE_AS_WRITTEN
    printf '#define C2D_INLINE\n#include "collide2d.h"\nC2D_INLINE_AS_WRITTEN\n' | "$@" -Iinclude -E -x c - | tail -n 1
}
inline_tu
for cc in gcc clang; do
    check "$cc compiles the C2D_INLINE front ends" $cc $strict -O2 -Iinclude -c "$out/inline.c" -o "$out/inline.o"
done
check "g++ compiles the C2D_INLINE front ends" g++ -std=c++11 -pedantic -Wall -Wextra -Werror -O2 -Iinclude -x c++ -c \
    "$out/inline.c" -o "$out/inline.o"
check "C2D_INLINE is on in ISO C (gcc)" test "$(inline_flag gcc -std=c99)" = 1
check "C2D_INLINE is off under -ffast-math" test "$(inline_flag gcc -std=c99 -ffast-math)" = 0
if [ "$(uname -m)" = x86_64 ]; then
    check "C2D_INLINE is off for gnu99 on an FMA target (gcc contracts)" \
        test "$(inline_flag gcc -std=gnu99 -march=x86-64-v3)" = 0
fi
inline_required() { # compiler flags... -> does C2D_INLINE_REQUIRED compile?
    printf '#define C2D_INLINE\n#define C2D_INLINE_REQUIRED\n#include "collide2d.h"\nint c2d_ok;\n' |
        "$@" -Iinclude -fsyntax-only -x c - 2>/dev/null
}
inline_refused() { ! inline_required "$@"; }
check "C2D_INLINE_REQUIRED compiles where the front ends are inline" inline_required gcc -std=c99 -O2
check "C2D_INLINE_REQUIRED stops a build where they would be calls (fast math)" inline_refused gcc -std=c99 -ffast-math
if [ "$(uname -m)" = x86_64 ]; then
    check "C2D_INLINE_REQUIRED stops gnu99 on an FMA target" inline_refused gcc -std=gnu99 -march=x86-64-v3
fi
check "header compiles as C++ (g++ -std=c++11)" g++ -std=c++11 -pedantic -Wall -Wextra -Werror -fsyntax-only -x c++ include/collide2d.h
c2d_summary
