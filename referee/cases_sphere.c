/* SPDX-License-Identifier: MIT */
#include "cases_sphere.h"
#include "cases.h"

#include <math.h>

enum { POOL_SPIN = 200 };
static const double pool_m = 0.17, pool_r = 0.028575;

static double log_uniform(c2d_rng *r, double lo, double hi) { return lo * pow(hi / lo, c2d_rng_unit(r)); }

static void random_spin(c2d_rng *r, ref_ball *d, double size)
{
    int i;
    for (i = 0; i < 3; i++) d->w[i] = c2d_rng_range(r, -size, size);
}

/* b touching a in a random direction; the velocities turned around if the
 * pair recedes (or is exactly tangent). */
static void place_and_approach(c2d_rng *r, ref_balls_case *c)
{
    double th = c2d_rng_range(r, 0, 6.283185307179586), d = c->a.r + c->b.r, gn;
    c->a.pos[0] = c2d_rng_range(r, -1, 1), c->a.pos[1] = c2d_rng_range(r, -1, 1);
    c->b.pos[0] = c->a.pos[0] + d * cos(th), c->b.pos[1] = c->a.pos[1] + d * sin(th);
    gn = (c->b.vel[0] - c->a.vel[0]) * (c->b.pos[0] - c->a.pos[0]) +
         (c->b.vel[1] - c->a.vel[1]) * (c->b.pos[1] - c->a.pos[1]);
    if (gn >= 0) {
        int i;
        for (i = 0; i < 2; i++) c->a.vel[i] = -c->a.vel[i], c->b.vel[i] = -c->b.vel[i];
        if (gn == 0) c->a.vel[0] += 0.5; /* never exactly tangent */
    }
}

static void pool_ball(c2d_rng *r, ref_ball *d)
{
    d->m = pool_m, d->r = pool_r, d->inertia = 0.4 * pool_m * pool_r * pool_r;
    d->vel[0] = c2d_rng_range(r, -3, 3), d->vel[1] = c2d_rng_range(r, -3, 3);
    random_spin(r, d, POOL_SPIN);
}

void gen_pool_balls(c2d_rng *r, ref_balls_case *c)
{
    pool_ball(r, &c->a), pool_ball(r, &c->b);
    c->e = c2d_rng_range(r, 0.9, 1);
    if (c2d_rng_unit(r) < 0.5) c->mu = c2d_rng_range(r, 0, 0.2), c->boost = 0, c->decay = 0;
    else c->mu = 9.951e-3, c->boost = 0.108, c->decay = 1.088;
    place_and_approach(r, c);
}

static void mixed_ball(c2d_rng *r, ref_ball *d)
{
    d->m = log_uniform(r, 0.01, 10), d->r = log_uniform(r, 0.01, 1);
    d->inertia = c2d_rng_range(r, 0.1, 1) * d->m * d->r * d->r;
    d->vel[0] = c2d_rng_range(r, -1, 1), d->vel[1] = c2d_rng_range(r, -1, 1);
    random_spin(r, d, 1 / d->r);
}

void gen_mixed_balls(c2d_rng *r, ref_balls_case *c)
{
    mixed_ball(r, &c->a), mixed_ball(r, &c->b);
    if (c2d_rng_unit(r) < 0.125) c->b.m = INFINITY;
    c->e = c2d_rng_unit(r);
    c->mu = c2d_rng_range(r, 0, 1);
    c->boost = c2d_rng_unit(r) < 0.5 ? 0 : c2d_rng_range(r, 0, 0.5);
    c->decay = c2d_rng_range(r, 0, 3);
    place_and_approach(r, c);
}

void gen_cushion(c2d_rng *r, ref_cushion_case *c)
{
    double th = c2d_rng_range(r, 0, 6.283185307179586);
    pool_ball(r, &c->a);
    c->a.pos[0] = c2d_rng_range(r, -1, 1), c->a.pos[1] = c2d_rng_range(r, -1, 1);
    c->n[0] = cos(th) * c2d_rng_range(r, 0.5, 2), c->n[1] = sin(th) * c2d_rng_range(r, 0.5, 2);
    c->h = c2d_rng_unit(r) < 0.5 ? 0.635 * 2 * pool_r : c2d_rng_range(r, pool_r, 2 * pool_r);
    c->e = c2d_rng_range(r, 0.5, 1), c->mu = c2d_rng_range(r, 0, 0.4);
    if (c->a.vel[0] * c->n[0] + c->a.vel[1] * c->n[1] <= 0) c->a.vel[0] = -c->a.vel[0], c->a.vel[1] = -c->a.vel[1];
    if (c->a.vel[0] * c->n[0] + c->a.vel[1] * c->n[1] <= 0) c->a.vel[0] = c->n[0], c->a.vel[1] = c->n[1];
}

/* 2^k (1 + u), k uniform in [-span, span], a random sign: a magnitude over
 * 2 span binades, exact in float for span < 126. */
static double wide(c2d_rng *r, int span)
{
    int k = (int)(c2d_rng_next(r) % (uint64_t)(2 * span + 1)) - span;
    double v = ldexp((double)(float)(1 + c2d_rng_unit(r)), k);
    return c2d_rng_next(r) & 1 ? -v : v;
}

/* One component of a speed or of spin x radius: 0 in one case in 8. */
static double wide_speed(c2d_rng *r, int span) { return c2d_rng_next(r) % 8 == 0 ? 0 : wide(r, span); }

/* kMu's regimes: no friction, sliding, either, sticking (1e6 and INFINITY:
 * mu Jn always beyond the slip's stopping impulse). */
static const double kWideMu[6] = {0, 0.05, 0.2, 1, 1e6, INFINITY};

/* Mass and radius anywhere in the span, inertia k m R^2 with k in [0.1, 1]
 * (one in 8 INFINITY); each velocity component and each spin x radius at
 * its own exponent.  The inertia and every product stay within the format. */
static void wide_ball(c2d_rng *r, ref_ball *d, int span)
{
    int i;
    d->m = fabs(wide(r, span)), d->r = fabs(wide(r, span));
    d->inertia = c2d_rng_next(r) % 8 == 0 ? INFINITY : (double)(float)c2d_rng_range(r, 0.1, 1) * d->m * d->r * d->r;
    for (i = 0; i < 2; i++) d->vel[i] = wide_speed(r, span);
    for (i = 0; i < 3; i++) d->w[i] = wide_speed(r, span) / d->r;
}

void gen_wide_balls(c2d_rng *r, ref_balls_case *c, int span)
{
    double th, d, gn;
    wide_ball(r, &c->a, span), wide_ball(r, &c->b, span);
    if (c2d_rng_next(r) % 8 == 0) c->b.m = INFINITY;
    c->e = c2d_rng_next(r) % 4 == 0 ? 1 : (double)(float)c2d_rng_unit(r);
    c->mu = kWideMu[c2d_rng_next(r) % 6];
    c->boost = c2d_rng_next(r) % 2 ? 0 : (double)(float)c2d_rng_range(r, 0, 0.5);
    c->decay = (double)(float)fabs(wide(r, span / 4));
    d = c->a.r + c->b.r, th = c2d_rng_range(r, 0, 6.283185307179586);
    c->a.pos[0] = c2d_rng_range(r, -10, 10) * d, c->a.pos[1] = c2d_rng_range(r, -10, 10) * d;
    c->b.pos[0] = c->a.pos[0] + d * cos(th), c->b.pos[1] = c->a.pos[1] + d * sin(th);
    gn = (c->b.vel[0] - c->a.vel[0]) * cos(th) + (c->b.vel[1] - c->a.vel[1]) * sin(th);
    if (gn > 0) {
        int i;
        for (i = 0; i < 2; i++) c->a.vel[i] = -c->a.vel[i], c->b.vel[i] = -c->b.vel[i];
    } else if (gn == 0) { /* both still along the line of centres */
        double s = fabs(wide(r, span));
        c->b.vel[0] = -s * cos(th), c->b.vel[1] = -s * sin(th);
    }
}

void gen_wide_cushion(c2d_rng *r, ref_cushion_case *c, int span)
{
    double th = c2d_rng_range(r, 0, 6.283185307179586), nl = fabs(wide(r, span));
    uint64_t k = c2d_rng_next(r) % 4;
    wide_ball(r, &c->a, span);
    if (isinf(c->a.inertia)) c->a.inertia = 0.4 * c->a.m * c->a.r * c->a.r;
    c->a.pos[0] = c2d_rng_range(r, -10, 10) * c->a.r, c->a.pos[1] = c2d_rng_range(r, -10, 10) * c->a.r;
    c->n[0] = cos(th) * nl, c->n[1] = sin(th) * nl;
    /* the centre's height, the table's 0.635 D, or anywhere up to 2R */
    c->h = k == 0 ? c->a.r : k == 1 ? 0.635 * 2 * c->a.r : c->a.r * (1 + c2d_rng_unit(r));
    c->e = c2d_rng_next(r) % 4 == 0 ? 1 : (double)(float)c2d_rng_unit(r);
    c->mu = kWideMu[c2d_rng_next(r) % 6];
    if (c->a.vel[0] * c->n[0] + c->a.vel[1] * c->n[1] <= 0) c->a.vel[0] = -c->a.vel[0], c->a.vel[1] = -c->a.vel[1];
    if (c->a.vel[0] * c->n[0] + c->a.vel[1] * c->n[1] <= 0) c->a.vel[0] += cos(th) * fabs(wide(r, span));
}

/* Over the whole range: a magnitude 2^k (1 + u) at prec bits, k uniform
 * from the smallest subnormal's exponent to emax - 1, a random sign. */
static double whole(c2d_rng *r, int prec, int emin, int emax)
{
    int k = emin - prec + 1 + (int)(c2d_rng_next(r) % (uint64_t)(emax - emin + prec - 1));
    double v = ldexp(1 + c2d_rng_unit(r), k);
    if (prec < 53) v = ref_to_float(v);
    return c2d_rng_next(r) & 1 ? -v : v;
}

/* 0 in one case in 8, else anywhere. */
static double whole_or_zero(c2d_rng *r, int prec, int emin, int emax)
{
    return c2d_rng_next(r) % 8 == 0 ? 0 : whole(r, prec, emin, emax);
}

/* Every field at its own exponent: mass (one in 8 INFINITY), radius (one
 * in 8 zero), inertia (one in 8 INFINITY), each velocity and spin
 * component (one in 8 zero), the position. */
static void whole_ball(c2d_rng *r, ref_ball *d, int prec, int emin, int emax)
{
    int i;
    d->m = c2d_rng_next(r) % 8 == 0 ? INFINITY : fabs(whole(r, prec, emin, emax));
    d->r = c2d_rng_next(r) % 8 == 0 ? 0 : fabs(whole(r, prec, emin, emax));
    d->inertia = c2d_rng_next(r) % 8 == 0 ? INFINITY : fabs(whole(r, prec, emin, emax));
    for (i = 0; i < 2; i++) d->vel[i] = whole_or_zero(r, prec, emin, emax);
    for (i = 0; i < 3; i++) d->w[i] = whole_or_zero(r, prec, emin, emax);
    for (i = 0; i < 2; i++) d->pos[i] = whole_or_zero(r, prec, emin, emax);
}

static double to_prec(double x, int prec) { return prec < 53 ? ref_to_float(x) : x; }

/* (x, y) . (u, v) > 0, its sign from scaled terms (no overflow). */
static int dot_positive(double x, double y, double u, double v)
{
    double m1 = fmax(fabs(x), fabs(y)), m2 = fmax(fabs(u), fabs(v));
    if (m1 == 0 || m2 == 0 || !isfinite(m1) || !isfinite(m2)) return 0;
    return (x / m1) * (u / m2) + (y / m1) * (v / m2) > 0;
}

void gen_whole_balls(c2d_rng *r, ref_balls_case *c, int prec, int emin, int emax)
{
    double th = c2d_rng_range(r, 0, 6.283185307179586), len = fabs(whole(r, prec, emin, emax));
    int i;
    whole_ball(r, &c->a, prec, emin, emax), whole_ball(r, &c->b, prec, emin, emax);
    /* b at a random offset of any length from a, or anywhere (one in 4) */
    if (c2d_rng_next(r) % 4 != 0) {
        c->b.pos[0] = to_prec(c->a.pos[0] + len * cos(th), prec);
        c->b.pos[1] = to_prec(c->a.pos[1] + len * sin(th), prec);
        if (!isfinite(c->b.pos[0]) || !isfinite(c->b.pos[1])) c->b.pos[0] = c->a.pos[0], c->b.pos[1] = -c->a.pos[1];
    }
    c->e = c2d_rng_next(r) % 4 == 0 ? 1 : to_prec(c2d_rng_unit(r), prec);
    c->mu = kWideMu[c2d_rng_next(r) % 6];
    c->boost = c2d_rng_next(r) % 2 ? 0 : to_prec(c2d_rng_range(r, 0, 0.5), prec);
    c->decay = c2d_rng_next(r) % 4 == 0 ? to_prec(1.088, prec) : fabs(whole_or_zero(r, prec, emin, emax));
    /* approaching (to the sign's rounding: the referee decides) */
    if (dot_positive(c->b.vel[0] - c->a.vel[0], c->b.vel[1] - c->a.vel[1], c->b.pos[0] - c->a.pos[0],
                     c->b.pos[1] - c->a.pos[1]))
        for (i = 0; i < 2; i++) c->a.vel[i] = -c->a.vel[i], c->b.vel[i] = -c->b.vel[i];
}

void gen_whole_cushion(c2d_rng *r, ref_cushion_case *c, int prec, int emin, int emax)
{
    uint64_t k = c2d_rng_next(r) % 4;
    whole_ball(r, &c->a, prec, emin, emax);
    if (isinf(c->a.m)) c->a.m = fabs(whole(r, prec, emin, emax));
    if (c->a.r == 0) c->a.r = fabs(whole(r, prec, emin, emax));
    c->n[0] = whole_or_zero(r, prec, emin, emax), c->n[1] = whole_or_zero(r, prec, emin, emax);
    if (c->n[0] == 0 && c->n[1] == 0) c->n[0] = whole(r, prec, emin, emax);
    /* the centre's height, the table's 0.635 D, or anywhere up to 2R: each
     * rounding monotonic, so within [R, 2R] */
    c->h = k == 0 ? c->a.r : to_prec(k == 1 ? 1.27 * c->a.r : c->a.r * (1 + c2d_rng_unit(r)), prec);
    c->e = c2d_rng_next(r) % 4 == 0 ? 1 : to_prec(c2d_rng_unit(r), prec);
    c->mu = kWideMu[c2d_rng_next(r) % 6];
    if (!dot_positive(c->a.vel[0], c->a.vel[1], c->n[0], c->n[1])) c->a.vel[0] = -c->a.vel[0], c->a.vel[1] = -c->a.vel[1];
}

/* Field by field through a list of addresses: gcc 12.2's vectoriser at -O2
 * dropped the last two of ten straight-line conversions here (r, inertia). */
static void ball_to_float(ref_ball *d)
{
    double *f[10];
    int i;
    f[0] = &d->pos[0], f[1] = &d->pos[1], f[2] = &d->vel[0], f[3] = &d->vel[1], f[4] = &d->w[0];
    f[5] = &d->w[1], f[6] = &d->w[2], f[7] = &d->m, f[8] = &d->r, f[9] = &d->inertia;
    for (i = 0; i < 10; i++) *f[i] = (float)*f[i];
}

void balls_case_to_float(ref_balls_case *c)
{
    ball_to_float(&c->a), ball_to_float(&c->b);
    c->e = (float)c->e, c->mu = (float)c->mu, c->boost = (float)c->boost, c->decay = (float)c->decay;
}

void cushion_case_to_float(ref_cushion_case *c)
{
    ball_to_float(&c->a);
    c->n[0] = (float)c->n[0], c->n[1] = (float)c->n[1];
    c->h = (float)c->h, c->e = (float)c->e, c->mu = (float)c->mu;
}

void ball_of(c2d_ball *d, const ref_ball *s)
{
    int i;
    d->pos.x = s->pos[0], d->pos.y = s->pos[1], d->vel.x = s->vel[0], d->vel.y = s->vel[1];
    for (i = 0; i < 3; i++) d->spin[i] = s->w[i];
    d->mass = s->m, d->radius = s->r, d->inertia = s->inertia;
}

void ballf_of(c2d_ballf *d, const ref_ball *s)
{
    int i;
    d->pos.x = (float)s->pos[0], d->pos.y = (float)s->pos[1], d->vel.x = (float)s->vel[0], d->vel.y = (float)s->vel[1];
    for (i = 0; i < 3; i++) d->spin[i] = (float)s->w[i];
    d->mass = (float)s->m, d->radius = (float)s->r, d->inertia = (float)s->inertia;
}

c2d_ball_surface ball_surface_of(const ref_balls_case *c)
{
    c2d_ball_surface s;
    s.restitution = c->e, s.friction = c->mu, s.friction_boost = c->boost, s.friction_decay = c->decay;
    return s;
}

c2d_cushion cushion_of(const ref_cushion_case *c)
{
    c2d_cushion k;
    k.normal.x = c->n[0], k.normal.y = c->n[1], k.height = c->h, k.restitution = c->e, k.friction = c->mu;
    return k;
}

static void out_of(double *o, const c2d_ball *d)
{
    o[0] = d->vel.x, o[1] = d->vel.y, o[2] = d->spin[0], o[3] = d->spin[1], o[4] = d->spin[2];
}

static void out_off(double *o, const c2d_ballf *d)
{
    o[0] = d->vel.x, o[1] = d->vel.y, o[2] = d->spin[0], o[3] = d->spin[1], o[4] = d->spin[2];
}

c2d_status balls_call(const ref_balls_case *c, double out[10])
{
    c2d_ball a, b;
    c2d_status st;
    ball_of(&a, &c->a), ball_of(&b, &c->b);
    st = c2d_collide_balls(&a, &b, ball_surface_of(c));
    out_of(out, &a), out_of(out + 5, &b);
    return st;
}

c2d_status balls_callf(const ref_balls_case *c, double out[10])
{
    c2d_ballf a, b;
    c2d_ball_surfacef s;
    c2d_status st;
    ballf_of(&a, &c->a), ballf_of(&b, &c->b);
    s.restitution = (float)c->e, s.friction = (float)c->mu, s.friction_boost = (float)c->boost;
    s.friction_decay = (float)c->decay;
    st = c2d_collide_ballsf(&a, &b, s);
    out_off(out, &a), out_off(out + 5, &b);
    return st;
}

c2d_status cushion_call(const ref_cushion_case *c, double out[5])
{
    c2d_ball a;
    c2d_status st;
    ball_of(&a, &c->a);
    st = c2d_collide_cushion(&a, cushion_of(c));
    out_of(out, &a);
    return st;
}

c2d_status cushion_callf(const ref_cushion_case *c, double out[5])
{
    c2d_ballf a;
    c2d_cushionf k;
    c2d_status st;
    ballf_of(&a, &c->a);
    k.normal.x = (float)c->n[0], k.normal.y = (float)c->n[1], k.height = (float)c->h;
    k.restitution = (float)c->e, k.friction = (float)c->mu;
    st = c2d_collide_cushionf(&a, k);
    out_off(out, &a);
    return st;
}
