#!/bin/sh
# SPDX-License-Identifier: MIT
# links.sh PAGE... - the other names each manual page documents: every name
# in its NAME section (.Nm) but the page's own, printed as "PAGE NAME.3"
# pairs.  `make install` links each NAME.3 to its PAGE (man3/c2d_collidef.3
# -> c2d_collide.3), so `man 3 c2d_collidef` finds it.
set -eu
for page in "$@"; do
    own=$(basename "$page" .3)
    sed -n '/^\.Sh NAME/,/^\.Sh /s/^\.Nm \([A-Za-z0-9_]*\).*/\1/p' "$page" | while read -r name; do
        [ "$name" = "$own" ] || echo "$own.3 $name.3"
    done
done
