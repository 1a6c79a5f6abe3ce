#!/bin/sh
# SPDX-License-Identifier: MIT
# Compile sources with emcc/em++ into a static library (make web's SDL2 and
# Box2D, built once and kept under build/web; EMLIB_CC, EMLIB_CXX, EMLIB_AR
# name other compilers and archiver: Box2D for aarch64).
# Usage: scripts/emlib.sh OUT.a SRCDIR "FLAGS" FILE...   (FILE relative to SRCDIR)
# JOBS (default 2) compiles run at once, under nice.  The library is written
# only when every file compiled, so a failed or interrupted build leaves no
# half library for the next make to take as done.
set -eu
out=$1 srcdir=$2 flags=$3
shift 3
objdir="${out%.a}.obj"
mkdir -p "$objdir"
for f in "$@"; do
    [ -f "$srcdir/$f" ] || { echo "emlib: $srcdir/$f: no such source" >&2; exit 1; }
done
# one compile per line: the compiler by the file's suffix, the object named
# after the path (a/b.c -> a__b.o, so equal basenames do not collide)
for f in "$@"; do
    case $f in *.c) cc=${EMLIB_CC:-emcc} ;; *) cc=${EMLIB_CXX:-em++} ;; esac
    o=$(printf '%s' "$f" | sed 's|/|__|g; s|\.[a-z]*$|.o|')
    printf '%s %s %s\n' "$cc" "$srcdir/$f" "$objdir/$o"
done | xargs -P "${JOBS:-2}" -L 1 sh -c 'nice "$0" '"$flags"' -c "$1" -o "$2" || exit 255'
rm -f "$out.tmp"
${EMLIB_AR:-emar} rcs "$out.tmp" "$objdir"/*.o
mv "$out.tmp" "$out"
