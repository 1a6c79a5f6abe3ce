#!/bin/sh
# SPDX-License-Identifier: MIT
# install.sh TREE OUTDIR - `make install` and `make uninstall` with spaces
# in DESTDIR and PREFIX, run in TREE (a copy of the source tree,
# tests/build/default_goal.sh's, so the builds of a parallel `make test`
# are not disturbed); scratch directories under OUTDIR/"space dir":
#   - install into DESTDIR="OUTDIR/space dir/stage 3" PREFIX="/opt/my dir":
#     every file of the list below, and nothing else, lands under
#     DESTDIR/PREFIX; nothing changes in TREE (but build/) or in the
#     scratch directory outside DESTDIR
#   - the installed collide2d.pc and the CMake package name the prefix:
#     plain pkg-config --cflags/--libs (each path one word to a shell) and
#     with --define-prefix, and a CMake find_package(collide2d)
#     consumer built and run against the staged tree, when cmake is there
#   - uninstall leaves DESTDIR empty and the rest as before
#   - uninstall with DESTDIR=".../victim x" beside a file "victim" (in the
#     scratch directory, and in OUTDIR/victims) exits 0 and deletes nothing
# Logs and listings in OUTDIR.  Prints "install: N passed, N failed".
set -u
[ $# -eq 2 ] || { echo "usage: install.sh TREE OUTDIR" >&2; exit 2; }
src=$(pwd)
tree=$(cd "$1" && pwd)
. tests/harness/tally.sh
c2d_tally_name=install
rm -rf "$2/space dir"
mkdir -p "$2/space dir"
work=$(cd "$2/space dir" && pwd)
logs=$(cd "$2" && pwd)
stage="$work/stage 3"
prefix="/opt/my dir"
root=$stage$prefix
mkdir -p "$stage"
: >"$work/victim"
# And where the only space is DESTDIR's own (an unquoted rm in uninstall
# would remove "victim" beside it).
rm -rf "$logs/victims" && mkdir -p "$logs/victims" && : >"$logs/victims/victim"

# mk LOG ARGS...: make in TREE, no MAKEFLAGS from a calling make.
mk() {
    log=$1
    shift
    (cd "$tree" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u MAKEOVERRIDES make --no-print-directory "$@") \
        >>"$logs/$log" 2>&1 || { cat "$logs/$log" >&2; return 1; }
}
# listing DIR: every path under DIR (the tree's build/ left out), sorted.
listing() { (cd "$1" && find . -path ./build -prune -o -print | LC_ALL=C sort); }
unchanged() { # WHAT BEFORE-FILE DIR
    listing "$3" >"$2.after"
    if cmp -s "$2" "$2.after"; then c2d_passed; else
        c2d_failed "$1 changed:"
        diff "$2" "$2.after" >&2
    fi
}
listing "$tree" >"$logs/tree.before"
listing "$work" >"$logs/work.before"

version=$(sed -n 's/^#define C2D_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$/\2/p' include/collide2d.h | paste -sd.)
major=${version%%.*}
expected() {
    printf '%s\n' include/collide2d.h include/collide2d_world.h lib/libcollide2d.a "lib/libcollide2d.so.$version" "lib/libcollide2d.so.$major" \
        lib/libcollide2d.so lib/pkgconfig/collide2d.pc lib/cmake/collide2d/collide2dConfig.cmake \
        lib/cmake/collide2d/collide2dConfigVersion.cmake lib/cmake/collide2d/collide2dTargets.cmake
    for p in man/*.3; do printf 'share/man/man3/%s\n' "${p#man/}"; done
    sh man/links.sh man/*.3 | while read -r page name; do printf 'share/man/man3/%s\n' "$name"; done
}

c2d_check "make install DESTDIR='$stage' PREFIX='$prefix'" mk install.log install DESTDIR="$stage" PREFIX="$prefix"
expected | LC_ALL=C sort >"$logs/expected"
(cd "$stage" && find . ! -type d | sed 's|^\./||' | LC_ALL=C sort) >"$logs/found"
sed "s|^|${prefix#/}/|" "$logs/expected" | LC_ALL=C sort >"$logs/expected.full"
if cmp -s "$logs/expected.full" "$logs/found"; then c2d_passed; else
    c2d_failed "the files under DESTDIR are not exactly the expected ones:"
    diff "$logs/expected.full" "$logs/found" >&2
fi
unchanged "the tree (outside build/) after install" "$logs/tree.before" "$tree"
listing "$work" | grep -v '^\./stage 3/' >"$logs/work.after-install"
if grep -v '^\./stage 3/' "$logs/work.before" | cmp -s - "$logs/work.after-install"; then c2d_passed; else
    c2d_failed "the scratch directory outside DESTDIR changed:"
    grep -v '^\./stage 3/' "$logs/work.before" | diff - "$logs/work.after-install" >&2
fi

# pkg-config prints a space in a path as "\ ".
pc=$(PKG_CONFIG_PATH="$root/lib/pkgconfig" pkg-config --define-prefix --variable=includedir collide2d 2>&1 | sed 's/\\ / /g')
c2d_check "pkg-config --define-prefix: includedir '$pc'" test "$pc" = "$root/include"
# The flags as a shell reads them (as a Makefile recipe or a script's eval
# does): each path one word, spaces kept.  collide2d.pc writes the spaces of
# its paths as "\ "; unescaped, "-I/opt/my dir/include" would be two words.
# words "PKG-CONFIG OPTIONS" WORD...: pkg-config's output for collide2d, read
# by the shell, is exactly the words WORD...
words() {
    opts=$1
    shift
    want=$(printf '%s\n' "$@")
    out=$(PKG_CONFIG_PATH="$root/lib/pkgconfig" pkg-config $opts collide2d 2>&1) &&
        eval "set -- $out" && [ "$(printf '%s\n' "$@")" = "$want" ] ||
        { echo "install: pkg-config $opts printed: $out" >&2; return 1; }
}
c2d_check "pkg-config --cflags: -I'$prefix/include', one word" words --cflags "-I$prefix/include"
c2d_check "pkg-config --libs: -L'$prefix/lib' -lcollide2d" words --libs "-L$prefix/lib" -lcollide2d
c2d_check "pkg-config --define-prefix --cflags: -I'$root/include', one word" \
    words "--define-prefix --cflags" "-I$root/include"
c2d_check "pkg-config --define-prefix --libs: -L'$root/lib' -lcollide2d" \
    words "--define-prefix --libs" "-L$root/lib" -lcollide2d
if command -v cmake >/dev/null 2>&1; then
    if cmake -S "$src/tests/consumers" -B "$work/consumer" -DC2D_HOW=find_package \
        -DCMAKE_PREFIX_PATH="$root" >"$logs/cmake.log" 2>&1 &&
        cmake --build "$work/consumer" >>"$logs/cmake.log" 2>&1 &&
        "$work/consumer/consumer" >>"$logs/cmake.log" 2>&1 &&
        grep -qF "from $root/lib/cmake/collide2d" "$logs/cmake.log"; then
        c2d_passed
    else
        c2d_failed "CMake find_package(collide2d) against the staged make install"
        tail -n 30 "$logs/cmake.log" >&2
    fi
    rm -rf "$work/consumer"
else
    echo "install: cmake not found, find_package check skipped"
fi

c2d_check "make uninstall DESTDIR='$stage' PREFIX='$prefix'" mk uninstall.log uninstall DESTDIR="$stage" PREFIX="$prefix"
left=$(cd "$stage" && find . -mindepth 1)
c2d_check "uninstall leaves DESTDIR empty${left:+ (left: $left)}" test -z "$left"
unchanged "the scratch directory after uninstall" "$logs/work.before" "$work"

for v in "$work" "$logs/victims"; do
    listing "$v" >"$logs/victims.before"
    c2d_check "make uninstall DESTDIR='$v/victim x'" mk victim.log uninstall DESTDIR="$v/victim x"
    c2d_check "uninstall beside '$v/victim' keeps it" test -f "$v/victim"
    unchanged "$v after the victim uninstall" "$logs/victims.before" "$v"
done
unchanged "the tree (outside build/) after uninstall" "$logs/tree.before" "$tree"

c2d_summary
