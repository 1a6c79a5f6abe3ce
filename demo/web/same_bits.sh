#!/bin/sh
# SPDX-License-Identifier: MIT
# The same bits on x86-64 and aarch64: for a few shots from a few racks, the
# balls at rest from the native game's headless run (billiards --headless
# --json), from the simulation alone natively (same_bits) and from the same
# driver cross-compiled for aarch64 under qemu-user, compared double for
# double (each printed with 17 significant digits, so equal text is equal
# bits).  The browser's side is demo/web/test_web.py's.
# Usage: same_bits.sh BILLIARDS SAME_BITS AARCH64_SAME_BITS
set -u
if [ $# != 3 ]; then
    echo "usage: same_bits.sh BILLIARDS SAME_BITS AARCH64_SAME_BITS" >&2
    exit 2
fi
BIN=$1 NATIVE=$2 A64=$3
QEMU=${QEMU:-qemu-aarch64}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0 passes=0
# the balls' number, x, y, on_table of a JSON object with "balls", one per line
balls() { /usr/bin/python3 -c 'import json, sys
for b in json.load(sys.stdin)["balls"]:
    print(b["number"], repr(b["x"]), repr(b["y"]), b["on_table"])'; }
# seed, then --shot's fields: the break, spin and a soft shot, cut shots
for case in "1 0 12 0 0" "2 -3 9 0.2 -0.3" "3 4.5 6 -0.35 0.25" "7 180 3 0 0.4" "11 -1.2 14 0.1 0.1"; do
    set -- $case
    seed=$1 shot="$2,$3,$4,$5"
    "$BIN" --headless --json --seed "$seed" --shot "$shot" | balls > "$TMP/game" &&
        "$NATIVE" "$seed" "$2" "$3" "$4" "$5" | balls > "$TMP/native" &&
        "$QEMU" "$A64" "$seed" "$2" "$3" "$4" "$5" | balls > "$TMP/aarch64"
    if [ $? = 0 ] && [ -s "$TMP/game" ] && cmp -s "$TMP/game" "$TMP/native" && cmp -s "$TMP/native" "$TMP/aarch64"; then
        echo "ok - seed $seed, shot $shot: the same $(wc -l < "$TMP/game") balls, bit for bit (game, driver, aarch64)"
        passes=$((passes + 1))
    else
        echo "FAIL - seed $seed, shot $shot: the positions differ"
        diff "$TMP/game" "$TMP/native" | head -n 4
        diff "$TMP/native" "$TMP/aarch64" | head -n 4
        fails=$((fails + 1))
    fi
done
echo "same_bits: $passes passed, $fails failed"
[ "$fails" = 0 ]
