#!/bin/sh
# SPDX-License-Identifier: MIT
# default_goal.sh OUTDIR - a plain `make` (no target, no variable, no
# MAKEFLAGS from a calling make) in a fresh copy of the source tree
# (OUTDIR/tree: the files git knows or would add, or everything but build/
# outside a git checkout) builds build/libcollide2d.a, the shared library
# and build/collide2d.pc (`make` once built nothing: a FORCE rule came first).  Then the
# header dependencies (-MMD -MP): a second `make` compiles
# nothing, touching a template header recompiles the objects that include
# it and only those, touching include/collide2d.h recompiles every object.
# The copy is left for tests/build/install.sh.  Prints
# "default-goal: N passed, N failed".
set -u
out=${1:-build/test-make}
. tests/harness/tally.sh
c2d_tally_name=default-goal
rm -rf "$out/tree"
mkdir -p "$out/tree"
tree=$(cd "$out/tree" && pwd)

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files -co --exclude-standard
else
    find . -path ./build -prune -o -type f -print
fi | while IFS= read -r f; do [ -e "$f" ] && printf '%s\n' "$f"; done | tar -cf - -T - | tar -xf - -C "$tree"

# plain_make LOG: `make` in the copy, as a user types it.
plain_make() {
    (cd "$tree" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL -u MAKEOVERRIDES make) >"$out/$1" 2>&1
}
show() { cat "$out/$1" >&2; }

version=$(sed -n 's/^#define C2D_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$/\2/p' include/collide2d.h | paste -sd.)
if plain_make make1.log; then c2d_passed; else c2d_failed "plain make exits 0"; show make1.log; fi
for f in build/libcollide2d.a build/libcollide2d.so "build/libcollide2d.so.$version" build/collide2d.pc; do
    c2d_check "plain make builds $f" test -s "$tree/$f"
done
c2d_check "plain make does not stop at FORCE" sh -c "! grep -q \"Nothing to be done for 'FORCE'\" '$out/make1.log'"

# compiled LOG: the lib/ sources a make run compiled, sorted, one line.
compiled() { sed -n 's/.* -c \(lib\/[a-z0-9_]*\.c\) -o .*/\1/p' "$out/$1" | sort | paste -sd' '; }
same() { # WHAT GOT WANT
    if [ "$2" = "$3" ]; then c2d_passed; else c2d_failed "$1: compiled '$2', want '$3'"; fi
}
plain_make make2.log
same "a second make" "$(compiled make2.log)" ""

# The objects that include a header are the ones whose .d names it; a
# template header no lib/*.c includes directly, and the public header.
for h in lib/real/arith/bits.h include/collide2d.h; do
    want=$(cd "$tree" && for d in build/obj/*.d; do
        grep -q "[ /]$(basename "$h")\( \|$\)" "$d" && printf '%s\n' "lib/$(basename "$d" .d | sed 's/\.pic$//').c"
    done | sort | paste -sd' ')
    [ -n "$want" ] || { c2d_failed "no object depends on $h"; continue; }
    touch "$tree/$h"
    plain_make "touch-$(basename "$h").log"
    same "make after touching $h" "$(compiled "touch-$(basename "$h").log")" "$want"
done
# Every variant's object (plain and -fPIC) includes the public header.
same "the objects including include/collide2d.h" \
    "$(cd "$tree" && grep -l 'collide2d\.h' build/obj/*.d | wc -l)" "$(($(ls "$tree"/lib/*.c | wc -l) * 2))"

c2d_summary
