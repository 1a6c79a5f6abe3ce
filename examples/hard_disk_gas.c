/* SPDX-License-Identifier: MIT */
/* hard_disk_gas.c - the equation of state of the hard-disk fluid from an
 * event-driven simulation on collide2d alone.
 *
 * N equal disks (diameter sigma = 1, mass 1) in a periodic square box at
 * packing fraction eta = N pi sigma^2 / (4 A).  Events are processed in time
 * order: a pair's next contact comes from c2d_time_of_impact (radius sum
 * sigma), the impact itself from c2d_collide with restitution 1; a cell list
 * (cells at least sigma wide, a particle's events sought in the 3 x 3 cells
 * around it, plus the time it leaves its cell) keeps each prediction local.
 *
 * The pressure comes from the collision virial: in two dimensions
 *     Z = P A / (N k T) = 1 + sum over impacts of (r_i - r_j) . J_i / (2 t E)
 * with J_i the impulse on disk i at contact, t the time measured and E the
 * kinetic energy (= N k T in 2-D, constant at e = 1).  The run is cut into
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

#include "collide2d.h"

#define SIGMA 1.0
#define PI 3.14159265358979323846
#define BLOCKS 10
#define EQUILIBRATION 50 /* impacts per disk before measuring */
#define NO_PARTNER (-1)
#define CELL_CROSSING (-2)

typedef struct disk {
    double x, y, vx, vy, t; /* position at time t, velocity */
    int cell, next;         /* cell index, next disk in the same cell */
    unsigned long count;    /* impacts so far (invalidates older predictions) */
    double event_time;      /* this disk's next event */
    int partner;            /* disk, NO_PARTNER or CELL_CROSSING */
    unsigned long partner_count;
} disk;

typedef struct gas {
    int n, m;          /* disks; cells per side */
    double box, cell;  /* box side, cell side */
    disk *d;
    int *head;         /* first disk of each cell */
    int *heap, *where; /* binary heap of disks by event_time, and each disk's slot */
    double now;
} gas;

/* ------------------------------------------------------------ event heap */

static void heap_swap(gas *g, int a, int b)
{
    int t = g->heap[a];
    g->heap[a] = g->heap[b];
    g->heap[b] = t;
    g->where[g->heap[a]] = a;
    g->where[g->heap[b]] = b;
}

static double key(const gas *g, int slot) { return g->d[g->heap[slot]].event_time; }

/* Restore the heap order around one disk whose event time changed. */
static void heap_fix(gas *g, int i)
{
    int s = g->where[i];
    while (s > 0 && key(g, (s - 1) / 2) > key(g, s)) {
        heap_swap(g, s, (s - 1) / 2);
        s = (s - 1) / 2;
    }
    for (;;) {
        int l = 2 * s + 1, r = l + 1, best = s;
        if (l < g->n && key(g, l) < key(g, best)) best = l;
        if (r < g->n && key(g, r) < key(g, best)) best = r;
        if (best == s) break;
        heap_swap(g, s, best);
        s = best;
    }
}

/* ------------------------------------------------------------ cells */

static int cell_of(const gas *g, double x, double y)
{
    int cx = (int)(x / g->cell), cy = (int)(y / g->cell);
    cx = cx < 0 ? 0 : cx >= g->m ? g->m - 1 : cx;
    cy = cy < 0 ? 0 : cy >= g->m ? g->m - 1 : cy;
    return cy * g->m + cx;
}

static void cell_insert(gas *g, int i)
{
    g->d[i].next = g->head[g->d[i].cell];
    g->head[g->d[i].cell] = i;
}

static void cell_remove(gas *g, int i)
{
    int *p = &g->head[g->d[i].cell];
    while (*p != i) p = &g->d[*p].next;
    *p = g->d[i].next;
}

/* Move disk i to time t along its straight line. */
static void advance(disk *p, double t)
{
    p->x += p->vx * (t - p->t);
    p->y += p->vy * (t - p->t);
    p->t = t;
}

/* The periodic image of b nearest to a (its displacement is below two cell
 * widths, under half the box since there are at least 5 cells a side). */
static double nearest(double delta, double box)
{
    if (delta > 0.5 * box) return delta - box;
    if (delta < -0.5 * box) return delta + box;
    return delta;
}

/* Bodies for collide2d: a at its own position, b at its nearest image. */
static void bodies(const gas *g, const disk *p, const disk *q, double t, c2d_body *a, c2d_body *b)
{
    double qx = q->x + q->vx * (t - q->t), qy = q->y + q->vy * (t - q->t);
    a->pos.x = p->x, a->pos.y = p->y, a->vel.x = p->vx, a->vel.y = p->vy, a->mass = 1.0;
    b->pos.x = p->x + nearest(qx - p->x, g->box), b->pos.y = p->y + nearest(qy - p->y, g->box);
    b->vel.x = q->vx, b->vel.y = q->vy, b->mass = 1.0;
}

/* When disk p (at time p->t) leaves its cell, moving in a straight line. */
static double leave_time(const gas *g, const disk *p)
{
    int cx = p->cell % g->m, cy = p->cell / g->m;
    double tx = p->vx > 0 ? ((cx + 1) * g->cell - p->x) / p->vx : p->vx < 0 ? (cx * g->cell - p->x) / p->vx : INFINITY;
    double ty = p->vy > 0 ? ((cy + 1) * g->cell - p->y) / p->vy : p->vy < 0 ? (cy * g->cell - p->y) / p->vy : INFINITY;
    double dt = tx < ty ? tx : ty;
    return dt > 0 ? dt : 0;
}

/* Disk i's next event from time g->now: the earliest impact with a disk in
 * the 3 x 3 cells around it, or leaving its cell. */
static void predict(gas *g, int i)
{
    disk *p = &g->d[i];
    int cx, cy, dx, dy;
    advance(p, g->now);
    p->event_time = g->now + leave_time(g, p);
    p->partner = CELL_CROSSING;
    cx = p->cell % g->m, cy = p->cell / g->m;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int c = ((cy + dy + g->m) % g->m) * g->m + (cx + dx + g->m) % g->m, j;
            for (j = g->head[c]; j >= 0; j = g->d[j].next) {
                c2d_body a, b;
                double t;
                if (j == i) continue;
                bodies(g, p, &g->d[j], g->now, &a, &b);
                if (c2d_time_of_impact(&a, &b, SIGMA, &t) == C2D_OK && g->now + t < p->event_time) {
                    p->event_time = g->now + t;
                    p->partner = j;
                    p->partner_count = g->d[j].count;
                }
            }
        }
    heap_fix(g, i);
}

/* ------------------------------------------------------------ set-up */

static uint64_t rng = 1;

static double uniform(void) /* splitmix64 -> [-1, 1) */
{
    uint64_t z = (rng += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-52 - 1.0;
}

/* Square lattice, random velocities with zero total momentum and kinetic
 * energy N (k T = 1).  Returns the kinetic energy. */
static double setup(gas *g, int side, double eta)
{
    double px = 0, py = 0, e = 0, scale;
    int i;
    g->box = sqrt(g->n * PI * SIGMA * SIGMA / (4.0 * eta));
    g->m = (int)(g->box / SIGMA);
    g->cell = g->box / g->m;
    g->head = malloc((size_t)g->m * (size_t)g->m * sizeof *g->head);
    for (i = 0; i < g->m * g->m; i++) g->head[i] = -1;
    for (i = 0; i < g->n; i++) {
        disk *p = &g->d[i];
        memset(p, 0, sizeof *p);
        p->x = (i % side + 0.5) * g->box / side;
        p->y = (i / side + 0.5) * g->box / side;
        p->vx = uniform(), p->vy = uniform();
        px += p->vx, py += p->vy;
        p->cell = cell_of(g, p->x, p->y);
        cell_insert(g, i);
        g->heap[i] = i, g->where[i] = i;
    }
    for (i = 0; i < g->n; i++) {
        g->d[i].vx -= px / g->n, g->d[i].vy -= py / g->n;
        e += 0.5 * (g->d[i].vx * g->d[i].vx + g->d[i].vy * g->d[i].vy);
    }
    scale = sqrt(g->n / e);
    for (i = 0; i < g->n; i++) g->d[i].vx *= scale, g->d[i].vy *= scale;
    for (i = 0; i < g->n; i++) g->d[i].event_time = 0;
    for (i = 0; i < g->n; i++) predict(g, i);
    return g->n;
}

/* ------------------------------------------------------------ events */

/* Process events until `impacts` impacts have happened; returns the virial
 * sum (r_i - r_j) . J_i over them.  *closest: the smallest centre distance
 * seen at an impact, in units of sigma. */
static double run(gas *g, long impacts, double *closest)
{
    double virial = 0;
    while (impacts > 0) {
        int i = g->heap[0], j;
        disk *p = &g->d[i];
        g->now = p->event_time;
        j = p->partner;
        if (j == CELL_CROSSING) {
            int cx = p->cell % g->m, cy = p->cell / g->m;
            advance(p, g->now);
            /* Step into the neighbouring cell it is leaving towards,
             * wrapping around the box. */
            double tx = fabs(p->x - (p->vx > 0 ? (cx + 1) * g->cell : cx * g->cell));
            double ty = fabs(p->y - (p->vy > 0 ? (cy + 1) * g->cell : cy * g->cell));
            cell_remove(g, i);
            if (tx <= ty) cx += p->vx > 0 ? 1 : -1;
            else cy += p->vy > 0 ? 1 : -1;
            if (cx < 0) cx += g->m, p->x += g->box;
            if (cx >= g->m) cx -= g->m, p->x -= g->box;
            if (cy < 0) cy += g->m, p->y += g->box;
            if (cy >= g->m) cy -= g->m, p->y -= g->box;
            p->cell = cy * g->m + cx;
            cell_insert(g, i);
            predict(g, i);
        } else if (j >= 0 && g->d[j].count == p->partner_count) {
            disk *q = &g->d[j];
            c2d_body a, b;
            double dvx, dvy, dist;
            advance(p, g->now);
            advance(q, g->now);
            bodies(g, p, q, g->now, &a, &b);
            if (c2d_collide(&a, &b, 1.0) == C2D_OK) {
                dvx = a.vel.x - p->vx, dvy = a.vel.y - p->vy;
                virial += (a.pos.x - b.pos.x) * dvx + (a.pos.y - b.pos.y) * dvy;
                dist = hypot(a.pos.x - b.pos.x, a.pos.y - b.pos.y) / SIGMA;
                if (dist < *closest) *closest = dist;
                p->vx = a.vel.x, p->vy = a.vel.y, q->vx = b.vel.x, q->vy = b.vel.y;
                p->count++, q->count++;
                impacts--;
            }
            predict(g, i);
            predict(g, j);
        } else {
            predict(g, i); /* the partner has changed course since */
        }
    }
    return virial;
}

static double kinetic(const gas *g)
{
    double e = 0;
    int i;
    for (i = 0; i < g->n; i++) e += 0.5 * (g->d[i].vx * g->d[i].vx + g->d[i].vy * g->d[i].vy);
    return e;
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
    double side = 32, eta = 0.4, per_disk = 200, seed = 1, e0, z[BLOCKS], mean = 0, var = 0, ref, err,
           closest = INFINITY, drift;
    gas g;
    int k = 1, b, r = 0;
    long block;
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
    memset(&g, 0, sizeof g);
    g.n = (int)side * (int)side;
    rng = (uint64_t)seed;
    g.d = malloc((size_t)g.n * sizeof *g.d);
    g.heap = malloc((size_t)g.n * sizeof *g.heap);
    g.where = malloc((size_t)g.n * sizeof *g.where);
    if (g.d == NULL || g.heap == NULL || g.where == NULL) {
        fprintf(stderr, "hard_disk_gas: out of memory\n");
        return 2;
    }
    e0 = setup(&g, (int)side, eta);
    if (g.head == NULL || g.m < 5) {
        fprintf(stderr, "hard_disk_gas: the box needs at least 5 cells a side (more disks or a lower eta)\n");
        return 2;
    }
    (void)run(&g, (long)EQUILIBRATION * g.n / 2, &closest);
    block = (long)(per_disk * g.n / 2 / BLOCKS);
    if (block < 1) block = 1;
    closest = INFINITY;
    for (b = 0; b < BLOCKS; b++) {
        double t0 = g.now, v = run(&g, block, &closest);
        z[b] = 1.0 + v / (2.0 * (g.now - t0) * kinetic(&g));
        mean += z[b] / BLOCKS;
    }
    for (b = 0; b < BLOCKS; b++) var += (z[b] - mean) * (z[b] - mean) / (BLOCKS - 1);
    err = sqrt(var / BLOCKS);
    ref = (1 + eta * eta / 8) / ((1 - eta) * (1 - eta));
    drift = kinetic(&g) / e0 - 1;
    printf("hard_disk_gas: N = %d disks, eta = %.3f, %ld impacts per disk measured in %d blocks\n", g.n, eta,
           2 * block * BLOCKS / g.n, BLOCKS);
    printf("hard_disk_gas: closest approach at impact %.15f sigma, kinetic energy drift %.1e\n", closest, drift);
    printf("hard_disk_gas: Z = PA/NkT = %.4f +- %.4f; Henderson (1975) %.4f; difference %+.2f%% (%+.1f error bars)\n",
           mean, err, ref, 100 * (mean - ref) / ref, (mean - ref) / err);
    r = fabs(mean - ref) <= 4 * err + 0.005 * ref && fabs(drift) < 1e-9 && closest > 1 - 1e-9;
    printf("hard_disk_gas: %s\n", r ? "passed" : "FAILED");
    free(g.d), free(g.heap), free(g.where), free(g.head);
    return r ? 0 : 1;
}
