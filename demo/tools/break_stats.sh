#!/bin/sh
# SPDX-License-Identifier: MIT
# demo/tools/break_stats.sh - the break's statistics over many racks.
#   sh demo/tools/break_stats.sh [BIN] [SPEED] [SEEDS]
# Runs `BIN --headless --seed S --shot 0,SPEED --json` for seeds 1..SEEDS
# (default build/billiards, 8 m/s, 50 seeds) to rest and prints, per seed,
# the ball-ball collisions, cushion hits (cushions, jaws), object balls
# pocketed, scratches and the balls left touching another ball at rest
# (centres closer than a diameter + 1 um) and the largest group of balls
# touching each other (directly or through others; 0: none), then the mean, minimum and
# maximum of each and the number of racks with a ball pocketed.
bin=${1:-build/billiards}
speed=${2:-8}
seeds=${3:-50}
s=1
while [ "$s" -le "$seeds" ]; do
    "$bin" --headless --seed "$s" --shot "0,$speed" --json || exit 1
    s=$((s + 1))
done | python3 -c '
import json, sys, math
rows = []
D = 2 * 0.028575
for line in sys.stdin:
    j = json.loads(line)
    on = [b for b in j["balls"] if b["on_table"]]
    touching = set()
    group = list(range(len(on)))
    def root(a):
        while group[a] != a:
            a = group[a]
        return a
    for a in range(len(on)):
        for b in range(a + 1, len(on)):
            if math.hypot(on[a]["x"] - on[b]["x"], on[a]["y"] - on[b]["y"]) < D + 1e-6:
                touching.add(a); touching.add(b)
                group[root(a)] = root(b)
    sizes = [sum(1 for k in range(len(on)) if root(k) == r) for r in set(root(k) for k in range(len(on)))]
    rows.append((j["ball_ball_collisions"], j["cushion_collisions"], j["pocketed"], j["scratches"], len(touching),
                 max(sizes) if touching else 0))
names = ["collisions", "cushion", "pocketed", "scratches", "touching", "group"]
print("seed " + " ".join("%10s" % n for n in names))
for i, r in enumerate(rows):
    print("%4d " % (i + 1) + " ".join("%10d" % v for v in r))
for f, name in ((lambda c: sum(c) / len(c), "mean"), (min, "min"), (max, "max")):
    print("%4s " % name + " ".join("%10.1f" % f([r[k] for r in rows]) for k in range(len(names))))
print("racks with a ball pocketed: %d of %d; balls pocketed in all: %d" %
      (sum(1 for r in rows if r[2] > 0), len(rows), sum(r[2] for r in rows)))
'
