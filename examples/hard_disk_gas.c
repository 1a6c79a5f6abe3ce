/* SPDX-License-Identifier: MIT */
/* hard_disk_gas.c - the equation of state of the hard-disk fluid from an
 * event-driven simulation: the world of collide2d_world.h.
 *
 * N equal disks (diameter sigma = 1, mass 1) in a periodic square box at
 * packing fraction eta = N pi sigma^2 / (4 A), restitution 1.  The world
 * processes the events in time order (impacts predicted by
 * c2d_time_of_impact and resolved by c2d_collide, in its own cell list) and
 * sums the collision virial for us.
 *
 * The pressure comes from the collision virial: in two dimensions
 *     Z = P A / (N k T) = 1 + sum over impacts of r_ij . J_j / (2 t E)
 * with r_ij from disk i to disk j and J_j the impulse on j at contact (the
 * world's stats.virial), t the time measured and E the kinetic energy
 * (= N k T in 2-D, constant at e = 1).  The run is cut into
 * blocks; the error bar is the standard error of the block means.
 *
 * Reference: D. Henderson, "A simple equation of state for hard discs",
 * Mol. Phys. 30, 971-972 (1975), doi:10.1080/00268977500102511:
 *     Z = (1 + eta^2 / 8) / (1 - eta)^2,
 * within a few tenths of a percent of simulations up to eta = 0.5 (it
 * overestimates Z by about 1 % at 0.6, towards the fluid's end near 0.7).  The run passes if |Z - Z_Henderson| <= 4 error bars + 0.5 %
 * (the fit's own error and the finite-N correction).
 *
 * Usage: hard_disk_gas [-n SIDE] [-e ETA] [-c COLLISIONS] [-s SEED]
 *   SIDE        disks per side of the starting lattice, N = SIDE^2 [32]
 *   ETA         packing fraction, 0.001 <= ETA <= 0.5 [0.4]
 *   COLLISIONS  impacts per disk measured (after 50 per disk to melt the
 *               lattice), cut into 10 blocks [200]
 *   SEED        random seed of the starting velocities [1]
 * Prints Z with its error bar against Henderson's; exit status 1 if they
 * disagree, 2 on bad arguments. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "collide2d_world.h"

#define SIGMA 1.0
#define PI 3.14159265358979323846
#define BLOCKS 10
#define EQUILIBRATION 50 /* impacts per disk before measuring */

static uint64_t rng = 1;

static double uniform(void) /* splitmix64 -> [-1, 1) */
{
    uint64_t z = (rng += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-52 - 1.0;
}

static double kinetic(const c2d_world *w)
{
    size_t i, n = c2d_world_count(w);
    double e = 0;
    for (i = 0; i < n; i++) {
        c2d_body b;
        c2d_world_get(w, i, &b);
        e += 0.5 * b.mass * (b.vel.x * b.vel.x + b.vel.y * b.vel.y);
    }
    return e;
}

/* Smallest centre distance over all pairs now, in units of sigma (nearest
 * image), for N up to a few thousand; 0 when skipped. */
static double closest_pair(const c2d_world *w, double box)
{
    size_t i, j, n = c2d_world_count(w);
    double best = INFINITY;
    if (n > 4096) return 0;
    for (i = 0; i < n; i++) {
        c2d_body a;
        c2d_world_get(w, i, &a);
        for (j = i + 1; j < n; j++) {
            c2d_body b;
            double dx, dy;
            c2d_world_get(w, j, &b);
            dx = b.pos.x - a.pos.x, dy = b.pos.y - a.pos.y;
            dx -= box * round(dx / box), dy -= box * round(dy / box);
            if (dx * dx + dy * dy < best) best = dx * dx + dy * dy;
        }
    }
    return sqrt(best) / SIGMA;
}

/* Advance until `impacts` more impacts have happened (in steps of about
 * one impact per disk). */
static void run(c2d_world *w, unsigned long long impacts, double step)
{
    c2d_world_stats s;
    unsigned long long goal;
    c2d_world_get_stats(w, &s);
    goal = s.collisions + impacts;
    while (s.collisions < goal) {
        c2d_world_advance(w, s.time + step);
        c2d_world_get_stats(w, &s);
    }
}

static int option(int argc, char **argv, int *k, const char *name, double lo, double hi, double *out)
{
    char *end;
    double v;
    if (strcmp(argv[*k], name) != 0) return 0;
    if (*k + 1 >= argc) return -1;
    v = strtod(argv[*k + 1], &end);
    if (end == argv[*k + 1] || *end != '\0' || !(v >= lo && v <= hi)) return -1;
    *out = v;
    *k += 2;
    return 1;
}

int main(int argc, char **argv)
{
    double side = 32, eta = 0.4, per_disk = 200, seed = 1, e0, z[BLOCKS], mean = 0, var = 0, ref, err, closest = INFINITY,
           drift, box, px = 0, py = 0, scale;
    c2d_world_desc d;
    c2d_world *w;
    c2d_body *disk;
    void *mem;
    int k = 1, b, r = 0;
    size_t i, n;
    unsigned long long block;
    while (k < argc) {
        r = option(argc, argv, &k, "-n", 5, 1000, &side);
        if (r == 0) r = option(argc, argv, &k, "-e", 1e-3, 0.5, &eta);
        if (r == 0) r = option(argc, argv, &k, "-c", 1, 1e6, &per_disk);
        if (r == 0) r = option(argc, argv, &k, "-s", 0, 1e15, &seed);
        if (r <= 0) {
            fprintf(stderr, "usage: hard_disk_gas [-n SIDE (5..1000)] [-e ETA (0.001..0.5)] "
                            "[-c COLLISIONS (1..1e6)] [-s SEED]\n");
            return 2;
        }
    }
    n = (size_t)side * (size_t)side;
    rng = (uint64_t)seed;
    box = sqrt((double)n * PI * SIGMA * SIGMA / (4.0 * eta));
    memset(&d, 0, sizeof d);
    d.capacity = n, d.width = d.height = box, d.boundary = C2D_PERIODIC, d.restitution = 1;
    mem = malloc(c2d_world_bytes(&d));
    disk = malloc(n * sizeof *disk);
    if (mem == NULL || disk == NULL || c2d_world_init(&w, mem, c2d_world_bytes(&d), &d) != C2D_OK) {
        fprintf(stderr, "hard_disk_gas: out of memory\n");
        return 2;
    }
    /* Square lattice, random velocities with zero total momentum and
     * kinetic energy N (k T = 1). */
    for (i = 0; i < n; i++) {
        disk[i].pos.x = ((double)(i % (size_t)side) + 0.5) * box / side;
        disk[i].pos.y = ((double)(i / (size_t)side) + 0.5) * box / side;
        disk[i].vel.x = uniform(), disk[i].vel.y = uniform(), disk[i].mass = 1;
        px += disk[i].vel.x, py += disk[i].vel.y;
    }
    for (i = 0, e0 = 0; i < n; i++) {
        disk[i].vel.x -= px / (double)n, disk[i].vel.y -= py / (double)n;
        e0 += 0.5 * (disk[i].vel.x * disk[i].vel.x + disk[i].vel.y * disk[i].vel.y);
    }
    scale = sqrt((double)n / e0);
    for (i = 0; i < n; i++) {
        disk[i].vel.x *= scale, disk[i].vel.y *= scale;
        if (c2d_world_add(w, &disk[i], SIGMA / 2, NULL) != C2D_OK) {
            fprintf(stderr, "hard_disk_gas: the box needs at least 3 diameters a side (more disks or a lower eta)\n");
            return 2;
        }
    }
    e0 = kinetic(w);
    run(w, (unsigned long long)EQUILIBRATION * n / 2, 0.5);
    block = (unsigned long long)(per_disk * (double)n / 2 / BLOCKS);
    if (block < 1) block = 1;
    for (b = 0; b < BLOCKS; b++) {
        c2d_world_stats s0, s1;
        double c;
        c2d_world_get_stats(w, &s0);
        run(w, block, 0.5);
        c2d_world_get_stats(w, &s1);
        z[b] = 1.0 + (s1.virial - s0.virial) / (2.0 * (s1.time - s0.time) * kinetic(w));
        mean += z[b] / BLOCKS;
        c = closest_pair(w, box);
        if (c < closest) closest = c;
    }
    for (b = 0; b < BLOCKS; b++) var += (z[b] - mean) * (z[b] - mean) / (BLOCKS - 1);
    err = sqrt(var / BLOCKS);
    ref = (1 + eta * eta / 8) / ((1 - eta) * (1 - eta));
    drift = kinetic(w) / e0 - 1;
    printf("hard_disk_gas: N = %zu disks, eta = %.3f, %llu impacts per disk measured in %d blocks\n", n, eta,
           2 * block * BLOCKS / n, BLOCKS);
    printf("hard_disk_gas: closest pair at the block ends %.15f sigma, kinetic energy drift %.1e\n", closest, drift);
    printf("hard_disk_gas: Z = PA/NkT = %.4f +- %.4f; Henderson (1975) %.4f; difference %+.2f%% (%+.1f error bars)\n",
           mean, err, ref, 100 * (mean - ref) / ref, (mean - ref) / err);
    r = fabs(mean - ref) <= 4 * err + 0.005 * ref && fabs(drift) < 1e-9 && closest > 1 - 1e-9;
    printf("hard_disk_gas: %s\n", r ? "passed" : "FAILED");
    free(mem);
    free(disk);
    return r ? 0 : 1;
}
