#!/bin/sh
# SPDX-License-Identifier: MIT
# determinism.sh OUTDIR [COUNT [AMALGAMATION]] - the library's output bits over a fixed case
# set (tests/build/hash_vectors.c: COUNT cases of the variants, the world's
# scenes and 20,000 cases of the models) must hash the same under gcc and
# clang at -O0, -O2 and -O3,
# all with -ffp-contract=off.  The harness is always compiled
# the same way (gcc -O2 -ffp-contract=off) so only the library varies.
# Then, for information only, one build without -ffp-contract=off (gcc -O3
# -march=native -std=gnu99, where gcc's default contraction is "fast") shows
# what FMA contraction would change.  Prints "determinism: N passed, N failed".
set -u
out=${1:-build/determinism}
count=${2:-100000}
all=${3:-build/collide2d_all.c}
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=determinism
std="-std=c99 -ffp-contract=off -Iinclude"
# The harness (hash_vectors.c and the shared helper it uses) is built once.
harness() {
    mkdir -p "$out/harness" &&
        for f in tests/build/hash_vectors.c tests/build/hash_cases.c tests/harness/*.c; do
            gcc -O2 $std -Ireferee -Itests/harness -c "$f" -o "$out/harness/$(basename "$f" .c).o" || return 1
        done
}
if ! harness; then
    c2d_failed "hash_vectors.c does not build"
    c2d_summary
    exit 1
fi
# The variants' hash, the world's and the models' (hash_vectors prints
# them in that order), "V/W/M": a build must agree on all three.
hashes() {
    sed -n -e 's/.* [0-9]* cases, hash \([0-9a-f]*\)$/\1/p' \
        -e 's/.*: world hash \([0-9a-f]*\)$/\1/p' \
        -e 's/.* [0-9]* model cases, models hash \([0-9a-f]*\)$/\1/p' "$1" | paste -sd/ -
}
hash_of() { # name cc flags...
    name=$1
    cc=$2
    shift 2
    # shellcheck disable=SC2068
    mkdir -p "$out/lib_$name" &&
        for f in lib/*.c; do $cc $@ -Iinclude -c "$f" -o "$out/lib_$name/$(basename "$f" .c).o" || return 1; done &&
        gcc "$out"/harness/*.o "$out/lib_$name"/*.o -lm -o "$out/hv_$name" &&
        "$out/hv_$name" "$count" $(case $name in gcc-O2 | *-contract) echo "$out/$name.bin" ;; esac) >"$out/$name.txt" &&
        hashes "$out/$name.txt"
}
# agrees WHAT HASH: one more build's hash against the reference.
agrees() {
    if [ -n "$ref" ] && [ "$2" = "$ref" ]; then
        c2d_passed
        echo "determinism: $1: $2 same"
    else
        c2d_failed "$1: ${2:-build/run failed}, reference $ref"
    fi
}
ref=$(hash_of gcc-O2 gcc -O2 "$std")
echo "determinism: reference gcc -O2: $ref ($count cases)"
[ -n "$ref" ] || c2d_failed "reference gcc -O2: build/run failed"
for cc in gcc clang; do
    for opt in -O0 -O2 -O3; do
        [ "$cc$opt" = gcc-O2 ] && continue
        agrees "$cc $opt" "$(hash_of "$cc$opt" "$cc" "$opt $std")"
    done
done
# The amalgamated single file (scripts/amalgamate.sh) is the same library.
if [ -f "$all" ]; then
    agrees "amalgamation gcc -O2" "$(gcc -O2 $std -c "$all" -o "$out/all.o" &&
        gcc "$out"/harness/*.o "$out/all.o" -lm -o "$out/hv_all" &&
        "$out/hv_all" "$count" >"$out/all.txt" && hashes "$out/all.txt")"
fi
# The library's own FMA use (__FP_FAST_FMA: TwoProduct through fma()) must
# not change a bit either: -march=native with contraction still off.
agrees "gcc -O3 -march=native" "$(hash_of gcc-native-nocontract gcc "-O3 -march=native $std")"
h=$(hash_of gcc-native-contract gcc "-O3 -march=native -std=gnu99")
if [ -n "$h" ] && [ "$h" != "$ref" ]; then
    bytes=$(cmp -l "$out/gcc-O2.bin" "$out/gcc-native-contract.bin" | wc -l)
    echo "determinism: (info) gcc -O3 -march=native -std=gnu99 WITHOUT -ffp-contract=off: $h differs;" \
        "$bytes of $(wc -c <"$out/gcc-O2.bin") output bytes changed (FMA contraction)"
else
    echo "determinism: (info) gcc -O3 -march=native without -ffp-contract=off: ${h:-failed}, same as reference"
fi
rm -f "$out"/*.bin
c2d_summary
