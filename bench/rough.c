/* Rough disks (c2d_collide_rough, Walton's model) against the MPFR referee
 * (referee/ref_rough.c): the library in double and float and the model
 * transcribed plainly (bench_walton).  The generators are the unit test's
 * (tests/unit/test_rough.c), so the benchmark measures the same families. */
#include "bench.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "approaches.h"

static const double kMu[] = {0.05, 0.2, 1.0, 1e6, INFINITY};

/* A unit-scale contact: radii 0.1..1 touching (to rounding) along a random
 * line, speeds and spin x radius up to 10, inertia k m r^2 with k in
 * [0.1, 1] or INFINITY, restitution, friction and beta over their range. */
void gen_rough(c2d_rng *r, ref_rough_case *c)
{
    ref_case base;
    double ang = c2d_rng_range(r, 0, 6.283185307179586);
    int i;
    ref_disk *d[2];
    gen_plain(r, &base);
    d[0] = &c->a, d[1] = &c->b;
    c->a.radius = c2d_rng_range(r, 0.1, 1), c->b.radius = c2d_rng_range(r, 0.1, 1);
    c->a.pos[0] = base.pa[0], c->a.pos[1] = base.pa[1];
    c->b.pos[0] = base.pa[0] + (c->a.radius + c->b.radius) * cos(ang);
    c->b.pos[1] = base.pa[1] + (c->a.radius + c->b.radius) * sin(ang);
    for (i = 0; i < 2; i++) {
        c->a.vel[i] = base.va[i], c->b.vel[i] = base.vb[i];
        c->n[i] = c->b.pos[i] - c->a.pos[i];
    }
    c->a.mass = base.ma, c->b.mass = base.mb;
    for (i = 0; i < 2; i++) {
        d[i]->spin = c2d_rng_range(r, -10, 10) / d[i]->radius;
        d[i]->inertia = c2d_rng_next(r) % 8 == 0 ? INFINITY
                                                 : c2d_rng_range(r, 0.1, 1) * d[i]->mass * d[i]->radius * d[i]->radius;
    }
    if (c2d_rng_next(r) % 10 == 0) c->b.mass = INFINITY;
    c->has_normal = (int)(c2d_rng_next(r) & 1);
    c->e = base.e;
    c->mu = kMu[c2d_rng_next(r) % 5];
    c->beta = c2d_rng_next(r) % 4 == 0 ? 1.0 : c2d_rng_range(r, -1, 1);
    if ((c->b.vel[0] - c->a.vel[0]) * c->n[0] + (c->b.vel[1] - c->a.vel[1]) * c->n[1] > 0)
        for (i = 0; i < 2; i++) c->a.vel[i] = -c->a.vel[i], c->b.vel[i] = -c->b.vel[i];
}

/* The normal part anywhere in the range (gen_extreme), spins and radii too. */
void gen_rough_extreme(c2d_rng *r, ref_rough_case *c, int prec, int emin, int emax)
{
    ref_case base;
    int i;
    gen_extreme(r, &base, prec, emin, emax);
    for (i = 0; i < 2; i++) {
        c->a.pos[i] = base.pa[i], c->b.pos[i] = base.pb[i], c->a.vel[i] = base.va[i], c->b.vel[i] = base.vb[i];
        c->n[i] = base.n[i];
    }
    c->a.mass = base.ma, c->b.mass = base.mb, c->has_normal = base.has_normal, c->e = base.e;
    c->a.spin = gen_magnitude(r, emin - prec + 1, emax - 4, prec);
    c->b.spin = gen_magnitude(r, emin - prec + 1, emax - 4, prec);
    c->a.radius = fabs(gen_magnitude(r, emin, emax - 4, prec)) * (c2d_rng_next(r) % 8 != 0);
    c->b.radius = fabs(gen_magnitude(r, emin, emax - 4, prec)) * (c2d_rng_next(r) % 8 != 0);
    c->a.inertia = c2d_rng_next(r) % 6 == 0 ? INFINITY : fabs(gen_magnitude(r, emin, emax - 1, prec));
    c->b.inertia = c2d_rng_next(r) % 6 == 0 ? INFINITY : fabs(gen_magnitude(r, emin, emax - 1, prec));
    c->mu = kMu[c2d_rng_next(r) % 5];
    c->beta = c2d_rng_next(r) % 3 == 0 ? 1.0
                                       : (prec < 53 ? (double)(float)c2d_rng_range(r, -1, 1) : c2d_rng_range(r, -1, 1));
}

static void round_to_float(ref_rough_case *c)
{
    ref_disk *d[2];
    int i, k;
    d[0] = &c->a, d[1] = &c->b;
    for (i = 0; i < 2; i++) {
        for (k = 0; k < 2; k++) d[i]->pos[k] = (float)d[i]->pos[k], d[i]->vel[k] = (float)d[i]->vel[k];
        d[i]->spin = (float)d[i]->spin, d[i]->mass = (float)d[i]->mass;
        d[i]->radius = (float)d[i]->radius, d[i]->inertia = (float)d[i]->inertia;
        c->n[i] = (float)c->n[i];
    }
    c->e = (float)c->e, c->mu = (float)c->mu, c->beta = (float)c->beta;
}

static void disk_from(c2d_disk *d, const ref_disk *r)
{
    d->pos.x = r->pos[0], d->pos.y = r->pos[1], d->vel.x = r->vel[0], d->vel.y = r->vel[1];
    d->spin = r->spin, d->mass = r->mass, d->radius = r->radius, d->inertia = r->inertia;
}

static void diskf_from(c2d_diskf *d, const ref_disk *r)
{
    d->pos.x = (float)r->pos[0], d->pos.y = (float)r->pos[1], d->vel.x = (float)r->vel[0];
    d->vel.y = (float)r->vel[1], d->spin = (float)r->spin, d->mass = (float)r->mass;
    d->radius = (float)r->radius, d->inertia = (float)r->inertia;
}

/* The contender on one case: status and {va, vb, spin a, spin b} (inputs
 * where nothing was written).  The transcription has no given normal: its
 * cases always use b.pos - a.pos. */
static c2d_status run(int which, const ref_rough_case *c, double out[6])
{
    c2d_status st;
    if (which == RK_LIBF) {
        c2d_diskf a, b;
        c2d_surfacef s;
        c2d_vec2f n;
        diskf_from(&a, &c->a), diskf_from(&b, &c->b);
        s.restitution = (float)c->e, s.friction = (float)c->mu, s.tangential_restitution = (float)c->beta;
        n.x = (float)c->n[0], n.y = (float)c->n[1];
        st = c->has_normal ? c2d_collide_rough_normalf(&a, &b, n, s) : c2d_collide_roughf(&a, &b, s);
        out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y, out[4] = a.spin, out[5] = b.spin;
    } else {
        c2d_disk a, b;
        c2d_surface s;
        c2d_vec2 n;
        disk_from(&a, &c->a), disk_from(&b, &c->b);
        s.restitution = c->e, s.friction = c->mu, s.tangential_restitution = c->beta;
        n.x = c->n[0], n.y = c->n[1];
        if (which == RK_WALTON) st = bench_walton(&a, &b, s);
        else st = c->has_normal ? c2d_collide_rough_normal(&a, &b, n, s) : c2d_collide_rough(&a, &b, s);
        out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y, out[4] = a.spin, out[5] = b.spin;
    }
    return st;
}

static int status_right(const ref_rough_answer *r, c2d_status s)
{
    if (r->status != C2D_OK) return s == r->status;
    if (r->range_required) return s == C2D_RANGE;
    if (s == C2D_RANGE) return r->range_allowed;
    return s == C2D_OK;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

void rough_evaluate(int which, int extreme, int n, unsigned long long seed, rough_stats *o)
{
    const int is_float = which == RK_LIBF, prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022;
    double *ulps = malloc((size_t)n * sizeof *ulps);
    ref_rough_answer ans;
    c2d_rng r;
    int i, m = 0;
    memset(o, 0, sizeof *o);
    o->n = n;
    r.s = seed;
    ref_rough_init(&ans);
    for (i = 0; i < n; i++) {
        ref_rough_case c;
        double got[6];
        c2d_status st;
        int k, nan = 0, inf = 0;
        if (!extreme) gen_rough(&r, &c);
        else if (is_float) gen_rough_extreme(&r, &c, 24, -126, 127);
        else gen_rough_extreme(&r, &c, 53, -1022, 1023);
        if (which == RK_WALTON) c.has_normal = 0; /* its normal is b.pos - a.pos */
        if (is_float) round_to_float(&c);
        st = run(which, &c, got);
        ref_rough(&c, is_float ? FLT_MAX : DBL_MAX, &ans);
        o->wrong_status += !status_right(&ans, st);
        for (k = 0; k < 6; k++) nan |= isnan(got[k]), inf |= isinf(got[k]) != 0;
        o->nan += nan, o->inf += inf;
        if (ans.status != C2D_OK || ans.range_allowed) continue;
        ulps[m] = ref_rough_err(&c, &ans, got, prec, emin);
        if (!(ulps[m] <= o->max_ulp)) o->max_ulp = ulps[m];
        m++;
        /* Energy can only be judged between bodies of finite mass and inertia:
         * an immovable moving wall or a spinning flywheel of infinite inertia
         * may give energy to the other body. */
        if (!extreme && st == C2D_OK && !nan && !inf && isfinite(c.a.mass) && isfinite(c.b.mass) &&
            isfinite(c.a.inertia) && isfinite(c.b.inertia)) {
            double before[4], after[4];
            ref_rough_invariants(&c, NULL, before);
            ref_rough_invariants(&c, got, after);
            if (before[0] > 0 && (after[0] - before[0]) / before[0] > o->max_energy_gain)
                o->max_energy_gain = (after[0] - before[0]) / before[0];
        }
    }
    ref_rough_clear(&ans);
    o->evaluated = m;
    if (m > 0) {
        qsort(ulps, (size_t)m, sizeof *ulps, cmp_double);
        o->med_ulp = m % 2 ? ulps[m / 2] : 0.5 * (ulps[m / 2 - 1] + ulps[m / 2]);
    } else {
        o->med_ulp = NAN;
    }
    free(ulps);
}
