#!/bin/sh
# SPDX-License-Identifier: MIT
# demo/tools/break_stats.sh - the break's statistics over many racks.
#   sh demo/tools/break_stats.sh [BIN] [SPEED] [SEEDS]
# Runs `BIN --headless --seed S --shot 0,SPEED --json` for seeds 1..SEEDS
# (default build/billiards, 8 m/s, 50 seeds) to rest and prints, per seed,
# the ball-ball collisions, cushion hits (cushions, jaws), object balls
# pocketed, scratches and the balls left touching another ball at rest
# (centres closer than a diameter + 1 um), then the mean, minimum and
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
    for a in range(len(on)):
        for b in range(a + 1, len(on)):
            if math.hypot(on[a]["x"] - on[b]["x"], on[a]["y"] - on[b]["y"]) < D + 1e-6:
                touching.add(a); touching.add(b)
    rows.append((j["ball_ball_collisions"], j["cushion_collisions"], j["pocketed"], j["scratches"], len(touching)))
names = ["collisions", "cushion", "pocketed", "scratches", "touching"]
print("seed " + " ".join("%10s" % n for n in names))
for i, r in enumerate(rows):
    print("%4d " % (i + 1) + " ".join("%10d" % v for v in r))
for f, name in ((lambda c: sum(c) / len(c), "mean"), (min, "min"), (max, "max")):
    print("%4s " % name + " ".join("%10.1f" % f([r[k] for r in rows]) for k in range(5)))
print("racks with a ball pocketed: %d of %d; balls pocketed in all: %d" %
      (sum(1 for r in rows if r[2] > 0), len(rows), sum(r[2] for r in rows)))
'
