/* SPDX-License-Identifier: MIT */
/* world.c - collisions per CPU second of the event-driven world
 * (include/collide2d_world.h): equal disks (diameter 1, mass 1) in a
 * periodic square box at area fraction eta, e = 1, started on a square
 * lattice with random velocities, melted for `warm` collisions per disk and
 * then timed over `per` collisions per disk.
 *
 * Usage: world [N [ETA [PER [WARM]]]]   (defaults 10000 0.5 20 5); a bad
 * argument exits 2.  Built as build/bench/world by make; make bench-world runs
 * the table below, make test-bench a small gas.
 * Instructions: valgrind --tool=callgrind ./world 1024 0.5 writes the timed
 * part as its own dump (callgrind.out.PID.1, between CALLGRIND_ZERO_STATS
 * and the dump "world"); its total over the collisions printed.
 *
 * Measured (gcc 12 -O2, x86-64, the 2 cores shared, load ~2.5 to 3.7, so
 * +-15 %; medians of three runs alternating with the world before the
 * canonical rule and the calendar, commit 27d6d19, in brackets):
 *   N        eta 0.5              eta 0.2           (M collisions per CPU s)
 *   1,024    1.00  (0.92)         0.73  (0.62)
 *   10,000   0.64  (0.63)         0.44  (0.43)
 *   100,489  0.29  (0.31)         0.22  (0.20)
 *   After merging main (sensors, resolvers, rest rule), against main
 *   5bac685 in brackets, load 3.3 to 4.4: 1,024: 1.12 (1.00), 0.70 (0.60);
 *   10,000: 0.76 (0.62), 0.46 (0.43); 100,489: 0.29 (0.31), 0.22 (0.20).
 *   callgrind (make bench-world-ir), N = 1,024: 4,165 instructions per
 *   collision at eta 0.5 (3,922 before), 5,043 at eta 0.2 (5,317 before);
 *   after merging main's sensors, resolvers and rest rule (5bac685: 4,071
 *   and 5,482): 4,212 and 5,087.
 * The steps, instructions per collision at eta 0.5, N = 1,024:
 *   3,922  before (cells, a 4-ary heap, the image from the cell offset)
 *   5,609  the canonical frame (both disks at the later state time, lower
 *          index first, the nearest image there), the periodic rebase, the
 *          candidate test a call per candidate
 *   4,776  the straight candidate test inlined in the relative frame
 *          (q minus p, a at the origin: symmetric, so no branch on the
 *          order but a negation)
 *   4,532  the calendar queue instead of the 4-ary heap (the heap was 720
 *          per collision, the calendar about 450; at N = 100,489 it has 43 %
 *          fewer L1 misses, cachegrind, but the same CPU time)
 *   4,417  a crossing keeps the disk's best other event and scans the 3
 *          new cells only (eta 0.2: 5,421 then; crossings are 1.9 per
 *          collision there, 0.4 at eta 0.5)
 *   4,165  the scan over the non-empty cells only, its helpers inlined
 *   4,131  (from 4,216 after the merges; eta 0.2 5,092 -> 4,985) the
 *          straight candidate's no-relative-motion test moved below the
 *          filters' range, off the common path; the image's lower halves
 *          kept in the frame.  Of 126,008 candidates (27,029 predictions)
 *          52 % are rejected as receding, 20 % as a miss, 6 % as too late;
 *          27,187 reach c2d_time_of_impact
 *   tried and dropped: a square-root lower bound on the time of impact
 *   (3 % fewer calls, +1 % instructions); positions not extrapolated when a
 *   disk's age is 0 (no change).
 *   Tried and dropped (w-speed2): Smallenburg's neighbour lists instead of
 *   the cells' crossings: each disk a square shell of half-side h around
 *   where it was filed, a list of up to 26 disks whose shells come within
 *   r_i + r_j + 2 h (per axis, and + 2 sqrt(2) h in all), built from cells
 *   of that reach by shell centre, both ways; leaving the shell is the
 *   event (refile, relist, predict from the list), a full list falls back
 *   to the cells.  Same collisions, count for count.  Instructions per
 *   collision at N = 1,024 (eta 0.5 / 0.2): h = 0.35 diameter 5,220 /
 *   10,612, h = 0.75 6,556 / 8,834 (the cells: 4,216 / 5,092); CPU rates
 *   (load 6 to 8) 30 to 60 % below the cells' at every N.  In 2-D the
 *   3 x 3 cells of one diameter already hold only ~5.8 candidates at eta
 *   0.5: a list is as long (7.4 at h = 0.35) and shells are left about as
 *   often as cells are crossed unless h >= 0.5 diameter, when the lists
 *   grow past 10 and each refile (about 900 instructions) costs more than
 *   the crossing's 3-cell scan it replaces.  Also dropped: skipping the
 *   nearest image for cells far from the periodic sides (+79 per collision).
 * At N = 100,489 two thirds of the time were cache misses on the
 * neighbours' states and the cells' heads (perf), before the prefetch.
 * Branch w-world (issue 20's instruction target, the same events and hashes):
 *   4,169  main at 7ac35fa (eta 0.2: 5,008)
 *   3,961  a straight candidate's time of impact by c2d_time_of_impact's
 *          plain path inlined in the relative frame (the same operations:
 *          no call, checks, bodies or negation; the library's call where it
 *          would not decide)
 *   3,894  its window tested first as all inputs nonzero
 *   3,869  a candidate older than the predictor (nine in ten) takes the
 *          predictor's position at age +0 from the frame
 *   3,828  the cells' first disks gathered three to a row, no loop per cell
 *   3,740  the cell scan without gcc's SLP vectoriser (eta 0.2: 4,642)
 *   tried and dropped: c2d_w_self_of or c2d_w_body_at always inlined (+46,
 *   -2), an event staying in the window moved in place (+26), days of 1 or
 *   4 events (-2, +14), the queue's insert and remove inlined (-16 for more
 *   code), the SLP vectoriser off for the whole world (-33).
 *   Where it goes now: 84 % predictions (2.6 per collision: the two disks
 *   of the impact, stale events, crossings; 4.7 candidates each, about 60
 *   instructions per candidate test, 120 per inlined time of impact, 470 of
 *   fixed cost per prediction with its queue update).  Smallenburg's
 *   structure (neighbour lists with "left my shell" events) would change
 *   which events occur: the world hash mixes stats.events (crossings and
 *   stale events count) and c2d_world_bytes, so it cannot be had with the
 *   same hashes; the 1,300 target needs that decision. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "collide2d_world.h"
#include "callgrind.h"
#include "rng.h"

static c2d_rng rng = {1};
static double uniform(void) { return c2d_rng_range(&rng, -1.0, 1.0); } /* [-1, 1) */

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Advance until `target` collisions in total; returns the world time. */
static double run_to(c2d_world *w, unsigned long long target, double dt)
{
    c2d_world_stats s;
    c2d_world_get_stats(w, &s);
    while (s.collisions < target) {
        c2d_world_advance(w, s.time + dt);
        c2d_world_get_stats(w, &s);
    }
    return s.time;
}

/* A command-line number, whole and in [lo, hi], or a message and exit 2. */
static double number_arg(const char *what, const char *text, double lo, double hi)
{
    char *end;
    double x = strtod(text, &end);
    if (end == text || *end != '\0' || !(x >= lo && x <= hi)) {
        fprintf(stderr, "world: %s '%s' is not a number in [%g, %g]\n", what, text, lo, hi);
        exit(2);
    }
    return x;
}

int main(int argc, char **argv)
{
    size_t n, side, i;
    double eta, per, warm;
    if (argc > 5) {
        fprintf(stderr, "usage: world [N [ETA [PER [WARM]]]]\n");
        return 2;
    }
    n = argc > 1 ? (size_t)number_arg("N", argv[1], 2, 1e8) : 10000;
    eta = argc > 2 ? number_arg("ETA", argv[2], 1e-6, 0.78) : 0.5;
    per = argc > 3 ? number_arg("PER", argv[3], 0, 1e6) : 20;
    warm = argc > 4 ? number_arg("WARM", argv[4], 0, 1e6) : 5;
    side = (size_t)ceil(sqrt((double)n));
    double box = sqrt((double)n * 3.14159265358979323846 / (4 * eta)), t0, t1, dt;
    c2d_world_desc d = {0};
    c2d_world_stats s0, s1;
    c2d_world *w;
    void *mem;
    d.capacity = n, d.width = d.height = box, d.boundary = C2D_PERIODIC, d.restitution = 1, d.wall_restitution = 1;
    mem = malloc(c2d_world_bytes(&d));
    if (mem == NULL || c2d_world_init(&w, mem, c2d_world_bytes(&d), &d) != C2D_OK) return 2;
    for (i = 0; i < n; i++) {
        c2d_body b = {{((double)(i % side) + 0.5) * box / (double)side, ((double)(i / side) + 0.5) * box / (double)side},
                      {uniform(), uniform()}, 1};
        if (c2d_world_add(w, &b, 0.5, NULL) != C2D_OK) {
            fprintf(stderr, "world: the lattice does not fit (eta too high for N = %zu)\n", n);
            return 2;
        }
    }
    dt = 1.0; /* about one collision per disk per unit time at these speeds */
    run_to(w, (unsigned long long)(warm * (double)n / 2), dt);
    c2d_world_get_stats(w, &s0);
    CALLGRIND_ZERO_STATS;
    t0 = cpu_seconds();
    run_to(w, s0.collisions + (unsigned long long)(per * (double)n / 2), dt);
    t1 = cpu_seconds();
    CALLGRIND_DUMP_STATS_AT("world");
    c2d_world_get_stats(w, &s1);
    printf("world: N = %zu eta = %.2f periodic e = 1: %llu collisions (%llu events) in %.3f s CPU: %.3f M collisions/s, "
           "%.1f events per collision\n",
           n, eta, s1.collisions - s0.collisions, s1.events - s0.events, t1 - t0,
           (double)(s1.collisions - s0.collisions) / (t1 - t0) * 1e-6,
           (double)(s1.events - s0.events) / (double)(s1.collisions - s0.collisions));
    free(mem);
    return 0;
}
