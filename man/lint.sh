#!/bin/sh
# SPDX-License-Identifier: MIT
# lint.sh HEADER PAGE... - the manual pages are clean and complete
# (C2D_MAN_INTERNAL: names of header functions that are not the API, such
# as the helpers of the inline front ends, separated by spaces):
#   - `mandoc -T lint` reports nothing, down to style messages, but that a
#     page refers (.Xr) to another page of this set, which is not installed
#     on the machine linting it;
#   - every .Xr to a c2d_/collide2d page names a page or a NAME of this set;
#   - every function the header declares is named by a page (links.sh).
# Prints "man: N passed, N failed" (one per page, plus the two checks).
set -u
header=$1
shift
dir=$(dirname "$1")
pass=0 fail=0
names=$(for p in "$@"; do basename "$p" .3; done; sh "$dir/links.sh" "$@" | sed 's/.* \(.*\)\.3$/\1/')
known() { printf '%s\n' $names | grep -qx "$1"; }
for page in "$@"; do
    out=$(mandoc -T lint -W style "$page" 2>&1 |
        grep -v -E "STYLE: referenced manual not found: Xr (c2d_[a-z0-9_]+|collide2d) 3( \([0-9]+ times\))?$")
    if [ -z "$out" ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        printf '%s\n' "$out"
    fi
done
bad=""
for x in $(sed -n 's/^\.Xr \(c2d_[a-z0-9_]*\|collide2d\) 3.*/\1/p' "$@" | sort -u); do
    known "$x" || bad="$bad $x"
done
if [ -z "$bad" ]; then pass=$((pass + 1)); else
    fail=$((fail + 1))
    echo "man: .Xr to pages that do not exist:$bad"
fi
missing=""
for f in $(sed -n 's/^[a-z0-9_ ]*[ *]\(c2d_[a-z0-9_]*\)(.*/\1/p' "$header" | sort -u); do
    case " ${C2D_MAN_INTERNAL:-} " in *" $f "*) continue ;; esac
    known "$f" || missing="$missing $f"
done
if [ -z "$missing" ]; then pass=$((pass + 1)); else
    fail=$((fail + 1))
    echo "man: functions in $header without a manual page:$missing"
    echo "man: (add each to the NAME section of the page that documents it, or write a page in $dir/)"
fi
echo "man: $pass passed, $fail failed ($# pages, $(sh "$dir/links.sh" "$@" | wc -l) more names linked to them)"
[ "$fail" -eq 0 ]
