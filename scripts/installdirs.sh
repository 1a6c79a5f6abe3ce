# SPDX-License-Identifier: MIT
# installdirs.sh - the directories `make install` creates, so that
# `make uninstall` removes those (when empty) and no directory that was
# there before.
#   installdirs.sh create MANIFEST DIR...   create each DIR with its missing
#                                           parents; append every directory
#                                           created to MANIFEST
#   installdirs.sh remove MANIFEST DIR...   for each DIR and its parents,
#                                           deepest first: remove it if it is
#                                           listed in MANIFEST and empty, and
#                                           drop it from MANIFEST
# MANIFEST lives in the build tree (build/install-dirs.txt): after
# `make clean`, uninstall still removes the files but leaves directories.
set -eu
[ $# -ge 2 ] || { echo "usage: installdirs.sh create|remove MANIFEST DIR..." >&2; exit 2; }
mode=$1 manifest=$2
shift 2
case $mode in
create)
    mkdir -p "$(dirname "$manifest")"
    for dir in "$@"; do
        missing=""
        d=$dir
        while [ -n "$d" ] && [ "$d" != / ] && [ "$d" != . ] && [ ! -d "$d" ]; do
            missing="$d
$missing"
            d=$(dirname "$d")
        done
        mkdir -p "$dir"
        printf '%s' "$missing" >>"$manifest"
    done
    ;;
remove)
    [ -f "$manifest" ] || exit 0
    # Every DIR and parent, longest path first: children before parents.
    for dir in "$@"; do
        d=$dir
        while [ -n "$d" ] && [ "$d" != / ] && [ "$d" != . ]; do
            printf '%s\n' "$d"
            d=$(dirname "$d")
        done
    done | awk '{ print length($0) "\t" $0 }' | sort -rn | cut -f2- | while IFS= read -r d; do
        if grep -qxF "$d" "$manifest" && [ -d "$d" ] && [ -z "$(ls -A "$d")" ]; then
            rmdir "$d"
            grep -vxF "$d" "$manifest" >"$manifest.tmp" || true
            mv "$manifest.tmp" "$manifest"
        fi
    done
    ;;
*)
    echo "installdirs.sh: unknown mode '$mode' (create or remove)" >&2
    exit 2
    ;;
esac
