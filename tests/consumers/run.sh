#!/bin/sh
# SPDX-License-Identifier: MIT
# run.sh OUTDIR MAKE - build and run the consumer project (consumer.c) in each
# way a user picks collide2d up, from the repository root:
#   find_package      CMake install (shared) into a DESTDIR staging tree,
#                     then find_package(collide2d 1.1 CONFIG) against it
#   add_subdirectory  CMake, on the source tree
#   FetchContent      CMake, on the source tree
#   pkg-config        `make install DESTDIR=... PREFIX=/opt/c2d`, then the
#                     plain Makefile with --define-variable=prefix= (and
#                     --define-prefix must agree); `make uninstall` must then
#                     leave the staging tree empty
#   find_package (make install)  find_package(collide2d 1.1 CONFIG) against
#                     that same `make install` (its CMake package)
# Each path prints the consumer's pass line; the last line is
# "consumers: N passed, N failed".
set -u
[ $# -eq 2 ] || { echo "usage: run.sh OUTDIR MAKE" >&2; exit 2; }
out=$1 make=$2
src=$(pwd)
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
pass=0 fail=0

# step NAME COMMAND...: run quietly into OUTDIR/NAME.log; on failure show it.
step() {
    name=$1
    shift
    if "$@" >>"$out/$name.log" 2>&1; then
        return 0
    fi
    echo "consumers: FAILED $name: $*" >&2
    tail -n 30 "$out/$name.log" >&2
    return 1
}
# result NAME OK: count and print the consumer's own line.
result() {
    if [ "$2" -eq 0 ]; then
        pass=$((pass + 1))
        tail -n 1 "$out/$1.log"
    else
        fail=$((fail + 1))
    fi
}

cmake_consumer() { # NAME -DVAR=VALUE...
    name=$1
    shift
    step "$name" cmake -S tests/consumers -B "$out/$name" -DC2D_HOW="$name" "$@" &&
        step "$name" cmake --build "$out/$name" &&
        step "$name" "$out/$name/consumer"
}

stage=$out/cmake-stage
ok=0
{ step cmake-install cmake -S . -B "$out/cmake-lib" -DBUILD_SHARED_LIBS=ON &&
    step cmake-install cmake --build "$out/cmake-lib" &&
    step cmake-install env DESTDIR="$stage" cmake --install "$out/cmake-lib" --prefix /opt/c2d &&
    cmake_consumer find_package -DCMAKE_PREFIX_PATH="$stage/opt/c2d"; } || ok=1
result find_package $ok

ok=0
cmake_consumer add_subdirectory -DC2D_SOURCE_DIR="$src" || ok=1
result add_subdirectory $ok

ok=0
cmake_consumer FetchContent -DC2D_SOURCE_DIR="$src" || ok=1
result FetchContent $ok

# pkg-config on a staged `make install`; the staging directory exists first,
# so "uninstall leaves it empty" means exactly that.
stage=$out/make-stage
prefix=$stage/opt/c2d
pcdir=$prefix/lib/pkgconfig
mkdir -p "$stage"
ok=0
{ step pkg-config "$make" --no-print-directory install DESTDIR="$stage" PREFIX=/opt/c2d &&
    a=$(PKG_CONFIG_PATH=$pcdir pkg-config --define-variable=prefix="$prefix" --cflags --libs collide2d) &&
    b=$(PKG_CONFIG_PATH=$pcdir pkg-config --define-prefix --cflags --libs collide2d) &&
    a=$(echo $a) && b=$(echo $b) &&
    { [ "$a" = "$b" ] && [ "$a" = "-I$prefix/include -L$prefix/lib -lcollide2d" ] ||
        { echo "consumers: FAILED pkg-config: '$a' / '$b'" >&2; false; }; } &&
    step pkg-config "$make" --no-print-directory -C tests/consumers OUT="$out/consumer-pkgconfig" \
        PKG_CONFIG_PATH="$pcdir" C2D_PREFIX="$prefix" &&
    step pkg-config "$out/consumer-pkgconfig"; } || ok=1
result pkg-config $ok

# The CMake package `make install` writes, on the same staging tree.
ok=0
name=find_package-make
{ step $name cmake -S tests/consumers -B "$out/$name" -DC2D_HOW=find_package \
    -DC2D_LABEL="find_package (make install)" -DCMAKE_PREFIX_PATH="$prefix" &&
    step $name cmake --build "$out/$name" &&
    { grep -qF "collide2d 1.1" "$out/$name.log" && grep -qF "from $prefix/lib/cmake/collide2d" "$out/$name.log" ||
        { echo "consumers: FAILED $name: not found in $prefix/lib/cmake/collide2d" >&2; false; }; } &&
    step $name "$out/$name/consumer"; } || ok=1
result $name $ok

ok=0
step uninstall "$make" --no-print-directory uninstall DESTDIR="$stage" PREFIX=/opt/c2d || ok=1
left=$(cd "$stage" && find . -mindepth 1 | sort)
if [ $ok -eq 0 ] && [ -z "$left" ]; then
    echo "consumers: make uninstall left $stage empty: passed" >>"$out/uninstall.log"
else
    echo "consumers: FAILED make uninstall left:" $left >&2
    ok=1
fi
result uninstall $ok

echo "consumers: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
