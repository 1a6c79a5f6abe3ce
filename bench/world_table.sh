#!/bin/sh
# SPDX-License-Identifier: MIT
# bench/world_table.sh BIN OUT - the world section of the benchmark: runs
# BIN (build/bench/world) at N = 1,024, 10,000 and 100,489 and eta 0.5 and
# 0.2, ROUNDS times each interleaved (median of the CPU-time rates), counts
# instructions per collision at N = 1,024 with callgrind when valgrind is
# there, and writes the markdown table OUT (bench/RESULTS-world.md) beside
# the targets of issue 20 and the Smallenburg figures it quotes.
set -eu
bin=$1 out=$2 rounds=${ROUNDS:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
r=1
while [ "$r" -le "$rounds" ]; do
    for eta in 0.5 0.2; do
        for n in 1024 10000 100489; do
            "$bin" "$n" "$eta" | sed -n 's/.*: \([0-9.]*\) M collisions\/s.*/\1/p' >>"$tmp/$n-$eta"
        done
    done
    r=$((r + 1))
done
median() { sort -n "$1" | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
ir() {
    if ! command -v valgrind >/dev/null 2>&1; then echo "n/a"; return; fi
    rm -f "$tmp"/cg.*
    line=$(valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.%p" "$bin" 1024 "$1" 20 5 2>/dev/null)
    c=$(echo "$line" | sed -n 's/.*: \([0-9]*\) collisions.*/\1/p')
    i=$(sed -n 's/^summary: //p' "$tmp"/cg.*.1)
    echo $((i / c))
}
load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
{
    echo "## The event-driven world (\`make bench-world\`)"
    echo
    echo "Periodic hard-disk gas, e = 1, diameter 1, started on a lattice, melted for 5 collisions per disk and"
    echo "timed over 20 (bench/world.c). Millions of collisions per CPU second, the median of $rounds interleaved"
    echo "rounds; load average $load on $(nproc 2>/dev/null || echo '?') CPUs during the run, $(date -u +%Y-%m-%d)."
    echo "Targets from issue 20: 1.5x Smallenburg's 2-D EDMD at N = 10,000 and 100,489."
    echo
    echo "| N | eta 0.5 | Smallenburg 2-D | target | eta 0.2 | Smallenburg 2-D | target |"
    echo "|---:|---:|---:|---:|---:|---:|---:|"
    echo "| 1,024 | $(median "$tmp/1024-0.5") | 1.42 | - | $(median "$tmp/1024-0.2") | 0.62 | - |"
    echo "| 10,000 | $(median "$tmp/10000-0.5") | 0.74 | 1.11 | $(median "$tmp/10000-0.2") | 0.25 | 0.375 |"
    echo "| 100,489 | $(median "$tmp/100489-0.5") | 0.25 | 0.375 | $(median "$tmp/100489-0.2") | 0.125 | 0.19 |"
    echo
    echo "Instructions per collision (callgrind, N = 1,024, the timed part only): eta 0.5: $(ir 0.5)"
    echo "(target 1,300; Smallenburg 1,339 at -Ofast, 1,880 at -O2), eta 0.2: $(ir 0.2)."
} >"$out"
cat "$out"
