# SPDX-License-Identifier: MIT
"""The hard-disk equation of state from an event-driven gas on collide2d.World.

N equal disks (diameter sigma = 1, mass 1, k T = 1) in a periodic square
box at packing fraction eta = N pi sigma^2 / (4 A), started on a square
lattice with random velocities.  The world (collide2d_world.h, in C) does
the events: impacts at restitution 1, exactly in time order; this script
only advances it and reads its statistics.

The pressure comes from the collision virial the world sums, stats.virial =
sum over impacts of r_ij . dp_j (r_ij from i to j at contact, dp_j the
impulse on j; > 0 for repulsion).  In two dimensions
    P A = N k T + virial / (2 t),   so   Z = P A / (N k T) = 1 + virial / (2 t E)
over a time t, with E = N k T the kinetic energy.  The error bar is the
standard error of 10 block means (blocks of equal time, each about
impacts x N / 20 impacts at the collision rate of the melting run).

Reference: D. Henderson, "A simple equation of state for hard discs",
Mol. Phys. 30, 971-972 (1975), doi:10.1080/00268977500102511:
    Z = (1 + eta^2 / 8) / (1 - eta)^2,
within a few tenths of a percent of simulations up to eta = 0.5.  A point
agrees if |Z - Z_Henderson| <= 4 error bars + 1 % (the fit's own error and
the finite-N correction of a small box).

Usage: python3 hard_disk_eos.py [--eta 0.1,0.2,...] [--side N] [--impacts C]
                                [--seed S] [--plot FILE.png]
  --eta      packing fractions, each in [0.01, 0.5]      [0.1,0.2,0.3,0.4,0.5]
  --side     disks per side of the starting lattice      [12]
  --impacts  impacts per disk measured (after 20 to melt) [100]
  --plot     Z(eta) against Henderson's curve as a PNG: with matplotlib if it
             is installed, else gnuplot, else a message and no plot
Run from anywhere: the package is found beside this folder (../collide2d).
Exit status 1 if a point disagrees, 2 on bad arguments.
"""
import argparse
import math
import os
import random
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
import collide2d as c2d  # noqa: E402

SIGMA = 1.0
BLOCKS = 10
MELT = 20  # impacts per disk before measuring


def henderson(eta):
    return (1 + eta * eta / 8) / (1 - eta) ** 2


def gas(side, eta, rng):
    """The world: side^2 disks on a lattice, velocities of zero sum and k T = 1."""
    n = side * side
    box = math.sqrt(n * math.pi * SIGMA ** 2 / (4 * eta))
    if box < 3 * SIGMA * (1 + 2 ** -20):
        raise ValueError("a periodic box needs at least 3 diameters a side: more disks or a lower eta")
    world = c2d.World(box, box, capacity=n, boundary="periodic", restitution=1.0)
    g, k = box / side, range(n)
    v = [(rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in k]
    mx, my = sum(a for a, _ in v) / n, sum(b for _, b in v) / n
    s = math.sqrt(n / (sum((a - mx) ** 2 + (b - my) ** 2 for a, b in v) / 2))  # kinetic energy N
    world.add_many([((i % side + 0.5) * g, (i // side + 0.5) * g) for i in k],
                   [((a - mx) * s, (b - my) * s) for a, b in v], 1.0, SIGMA / 2)
    return world


def measure(eta, side, impacts, seed):
    """(Z, error bar) at packing fraction eta."""
    world = gas(side, eta, random.Random(seed))
    n = world.count
    while world.stats.collisions < MELT * n // 2:  # melt the lattice; the collision rate on the way
        world.advance(world.time + 1.0)
    block = impacts * n / 2 / BLOCKS * world.time / world.stats.collisions  # the time of a block
    energy = 0.5 * float((world.velocities() ** 2).sum())  # E = N k T, kept by every impact
    z = []
    for _ in range(BLOCKS):
        before = world.stats
        world.advance(before.time + block)
        z.append(1 + (world.stats.virial - before.virial) / (2 * block * energy))
    mean = sum(z) / BLOCKS
    err = math.sqrt(sum((x - mean) ** 2 for x in z) / (BLOCKS - 1) / BLOCKS)
    return mean, err


def plot(path, rows):
    """Z(eta) against Henderson's curve; returns what drew it, or None."""
    curve = [(e / 100, henderson(e / 100)) for e in range(0, 56)]
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        plt = None
    if plt is not None:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        ax.plot(*zip(*curve), label="Henderson (1975)")
        ax.errorbar([r[0] for r in rows], [r[1] for r in rows], yerr=[r[2] for r in rows], fmt="o",
                    label="event-driven gas on collide2d")
        ax.set_xlabel("packing fraction eta")
        ax.set_ylabel("Z = PA / NkT")
        ax.legend()
        fig.savefig(path, dpi=100)
        return "matplotlib"
    if shutil.which("gnuplot") is None:
        return None
    data = "\n".join(f"{e} {z} {err}" for e, z, err, _ in rows) + "\ne\n"
    script = (f"set terminal pngcairo size 600,450\nset output '{path}'\n"
              "set xlabel 'packing fraction eta'\nset ylabel 'Z = PA/NkT'\nset key top left\n"
              "plot [0:0.55] (1 + x*x/8)/(1-x)**2 title 'Henderson (1975)', "
              "'-' using 1:2:3 with yerrorbars pointtype 7 title 'event-driven gas on collide2d'\n" + data)
    r = subprocess.run(["gnuplot"], input=script, text=True, capture_output=True)
    if r.returncode != 0:
        # pngcairo may be missing from a minimal gnuplot: the plain png terminal
        r = subprocess.run(["gnuplot"], input=script.replace("pngcairo", "png"), text=True, capture_output=True)
    return "gnuplot" if r.returncode == 0 else None


def etas(text):
    try:
        values = [float(x) for x in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a comma-separated list of numbers: {text!r}")
    if not values or not all(0.01 <= v <= 0.5 for v in values):
        raise argparse.ArgumentTypeError("each packing fraction must be in [0.01, 0.5]")
    return values


def bounded(lo, hi):
    def parse(text):
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not an integer: {text!r}")
        if not lo <= v <= hi:
            raise argparse.ArgumentTypeError(f"must be in [{lo}, {hi}]")
        return v
    return parse


def main(argv=None):
    p = argparse.ArgumentParser(description="Hard-disk equation of state from an event-driven gas on collide2d.")
    p.add_argument("--eta", type=etas, default=[0.1, 0.2, 0.3, 0.4, 0.5])
    p.add_argument("--side", type=bounded(5, 200), default=12)
    p.add_argument("--impacts", type=bounded(10, 100000), default=100)
    p.add_argument("--seed", type=bounded(0, 2 ** 62), default=1)
    p.add_argument("--plot", metavar="FILE.png")
    args = p.parse_args(argv)  # bad arguments: message on stderr, exit status 2
    print(f"hard_disk_eos: N = {args.side ** 2} disks, {args.impacts} impacts per disk measured, "
          f"collide2d {c2d.__version__}")
    print(f"{'eta':>6} {'Z':>8} {'+-':>7} {'Henderson':>10} {'diff':>8} {'error bars':>10}")
    rows, ok = [], True
    for eta in args.eta:
        try:
            z, err = measure(eta, args.side, args.impacts, args.seed)
        except ValueError as e:
            p.error(f"eta = {eta}: {e}")
        ref = henderson(eta)
        good = abs(z - ref) <= 4 * err + 0.01 * ref
        ok &= good
        rows.append((eta, z, err, ref))
        print(f"{eta:6.3f} {z:8.4f} {err:7.4f} {ref:10.4f} {100 * (z - ref) / ref:+7.2f}% "
              f"{(z - ref) / err if err > 0 else 0:+10.1f}{'' if good else '  <- disagrees'}")
    if args.plot:
        how = plot(args.plot, rows)
        if how:
            print(f"hard_disk_eos: plot written to {args.plot} ({how})")
        else:
            print("hard_disk_eos: no plot (neither matplotlib nor gnuplot is installed)", file=sys.stderr)
    print(f"hard_disk_eos: {'passed' if ok else 'FAILED'} (Henderson, Mol. Phys. 30, 971 (1975))")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
