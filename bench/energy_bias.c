/* SPDX-License-Identifier: MIT */
/* energy_bias.c - is c2d_collide's energy error at e = 1 a bias?
 *
 * An elastic impact keeps the kinetic energy exactly; the library's result
 * is within a few ulp, so the relative change dE/E of one impact is a
 * rounding error of order 1e-16.  Summed over many impacts (a gas, a long
 * game), a zero-mean error random-walks, a systematic one drifts.  This
 * program measures the mean of dE/E over N random oblique impacts (unit-scale
 * scenes: centres 0.5-2 apart in any direction, speeds to 10, masses
 * 0.1-10, equal masses a quarter of the time), with E and E' in double-double
 * (TwoProduct, TwoSum: error ~1e-32, far below what is measured), and its
 * standard error; then the same for the impacts whose |n|^2 lies within 1%
 * of a power of two (where an outside measurement saw +2.2e-17) and the
 * rest, and for a separate sample placed within 2^-20 of |n|^2 = 1.  A mean more than 5 standard errors from zero is reported as a bias.
 * Usage: energy_bias [N]   (N impacts, default 100,000,000; prints one line
 * per class). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "collide2d.h"
#include "rng.h"

typedef struct stats { double n, mean, m2; } stats;

static void stats_add(stats *s, double x)
{
    const double d = x - s->mean;
    s->n += 1;
    s->mean += d / s->n;
    s->m2 += d * (x - s->mean);
}

static double stats_se(const stats *s) { return s->n > 1 ? sqrt(s->m2 / (s->n - 1) / s->n) : 0; }

/* hi + lo = a + b exactly. */
static double two_sum(double a, double b, double *lo)
{
    const double s = a + b, bv = s - a, av = s - bv;
    *lo = (a - av) + (b - bv);
    return s;
}

/* hi + lo = a * b exactly (fma: this file is not part of the library). */
static double two_prod(double a, double b, double *lo)
{
    const double p = a * b;
    *lo = fma(a, b, -p);
    return p;
}

/* *hi + *lo += a * b, in double-double. */
static void dd_add_product(double *hi, double *lo, double a, double b)
{
    double pl, sl;
    const double ph = two_prod(a, b, &pl);
    *hi = two_sum(*hi, ph, &sl);
    *lo += sl + pl;
}

/* Twice the kinetic energy of two bodies, double-double. */
static void energy2(const c2d_body *a, const c2d_body *b, double *hi, double *lo)
{
    *hi = *lo = 0;
    dd_add_product(hi, lo, a->mass * a->vel.x, a->vel.x);
    dd_add_product(hi, lo, a->mass * a->vel.y, a->vel.y);
    dd_add_product(hi, lo, b->mass * b->vel.x, b->vel.x);
    dd_add_product(hi, lo, b->mass * b->vel.y, b->vel.y);
}

static void report(const char *name, const stats *s)
{
    const double se = stats_se(s), z = se > 0 ? s->mean / se : 0;
    printf("energy_bias: %-26s %12.0f impacts: mean dE/E %+.3e, standard error %.2e (%+.1f sigma): %s\n", name, s->n,
           s->mean, se, z, fabs(z) > 5 ? "a bias" : "no bias detected");
}

int main(int argc, char **argv)
{
    const double total = argc > 1 ? atof(argv[1]) : 1e8;
    stats all = {0, 0, 0}, near = {0, 0, 0}, far = {0, 0, 0}, at = {0, 0, 0};
    c2d_rng r = {20261126};
    if (!(total >= 1)) {
        fprintf(stderr, "usage: energy_bias [N >= 1]\n");
        return 2;
    }
    while (all.n < total || at.n < total / 10) {
        /* Every other case at |n|^2 within 2^-20 of 1 (a power of two). */
        const int at_power = c2d_rng_next(&r) & 1;
        const double ang = c2d_rng_range(&r, 0, 6.283185307179586);
        const double dist = at_power ? sqrt(1 + c2d_rng_range(&r, -0x1p-20, 0x1p-20)) : c2d_rng_range(&r, 0.5, 2);
        c2d_body a, b;
        double e0h, e0l, e1h, e1l, nn, frac, lo, rel;
        a.pos.x = c2d_rng_range(&r, -10, 10), a.pos.y = c2d_rng_range(&r, -10, 10);
        b.pos.x = a.pos.x + dist * cos(ang), b.pos.y = a.pos.y + dist * sin(ang);
        a.vel.x = c2d_rng_range(&r, -10, 10), a.vel.y = c2d_rng_range(&r, -10, 10);
        b.vel.x = c2d_rng_range(&r, -10, 10), b.vel.y = c2d_rng_range(&r, -10, 10);
        a.mass = exp(c2d_rng_range(&r, log(0.1), log(10)));
        b.mass = c2d_rng_next(&r) % 4 == 0 ? a.mass : exp(c2d_rng_range(&r, log(0.1), log(10)));
        energy2(&a, &b, &e0h, &e0l);
        nn = (b.pos.x - a.pos.x) * (b.pos.x - a.pos.x) + (b.pos.y - a.pos.y) * (b.pos.y - a.pos.y);
        if (c2d_collide(&a, &b, 1.0) != C2D_OK) continue;
        energy2(&a, &b, &e1h, &e1l);
        rel = (two_sum(e1h, -e0h, &lo) + (lo + (e1l - e0l))) / e0h;
        frac = log2(nn) - floor(log2(nn));
        if (at_power) {
            stats_add(&at, rel);
            continue;
        }
        stats_add(&all, rel);
        stats_add(frac < 0.0144 || frac > 0.9856 ? &near : &far, rel); /* within 1% of 2^k */
    }
    report("all e = 1 impacts", &all);
    report("|n|^2 within 1% of 2^k", &near);
    report("|n|^2 elsewhere", &far);
    report("|n|^2 within 2^-20 of 1", &at);
    return 0;
}
