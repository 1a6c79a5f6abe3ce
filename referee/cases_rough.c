/* SPDX-License-Identifier: MIT */
/* cases_rough.c - see cases_rough.h. */
#include "cases_rough.h"

#include "cases.h"

#include <math.h>

static const double kMu[] = {0.05, 0.2, 1.0, 1e6, INFINITY};

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
        d[i]->inertia = c2d_rng_next(r) % 8 == 0 ? INFINITY : c2d_rng_range(r, 0.1, 1) * d[i]->mass * d[i]->radius * d[i]->radius;
    }
    if (c2d_rng_next(r) % 10 == 0) c->b.mass = INFINITY;
    c->has_normal = (int)(c2d_rng_next(r) & 1);
    c->e = base.e;
    c->mu = kMu[c2d_rng_next(r) % 5];
    c->beta = c2d_rng_next(r) % 4 == 0 ? 1.0 : c2d_rng_range(r, -1, 1);
    /* approach more often than not */
    if ((c->b.vel[0] - c->a.vel[0]) * c->n[0] + (c->b.vel[1] - c->a.vel[1]) * c->n[1] > 0)
        for (i = 0; i < 2; i++) c->a.vel[i] = -c->a.vel[i], c->b.vel[i] = -c->b.vel[i];
}

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
    c->beta = c2d_rng_next(r) % 3 == 0 ? 1.0 : (prec < 53 ? (double)(float)c2d_rng_range(r, -1, 1) : c2d_rng_range(r, -1, 1));
}

void rough_case_to_float(ref_rough_case *c)
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

void rough_disk_of(c2d_disk *d, const ref_disk *r)
{
    d->pos.x = r->pos[0], d->pos.y = r->pos[1], d->vel.x = r->vel[0], d->vel.y = r->vel[1];
    d->spin = r->spin, d->mass = r->mass, d->radius = r->radius, d->inertia = r->inertia;
}

void rough_diskf_of(c2d_diskf *d, const ref_disk *r)
{
    d->pos.x = (float)r->pos[0], d->pos.y = (float)r->pos[1], d->vel.x = (float)r->vel[0];
    d->vel.y = (float)r->vel[1], d->spin = (float)r->spin, d->mass = (float)r->mass;
    d->radius = (float)r->radius, d->inertia = (float)r->inertia;
}

c2d_surface rough_surface_of(const ref_rough_case *c)
{
    c2d_surface s;
    s.restitution = c->e, s.friction = c->mu, s.tangential_restitution = c->beta;
    return s;
}

c2d_status rough_call(const ref_rough_case *c, double out[6])
{
    c2d_disk a, b;
    c2d_surface s = rough_surface_of(c);
    c2d_vec2 n;
    c2d_status st;
    rough_disk_of(&a, &c->a), rough_disk_of(&b, &c->b);
    n.x = c->n[0], n.y = c->n[1];
    st = c->has_normal ? c2d_collide_rough_normal(&a, &b, n, s) : c2d_collide_rough(&a, &b, s);
    out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y, out[4] = a.spin, out[5] = b.spin;
    return st;
}

c2d_status rough_callf(const ref_rough_case *c, double out[6])
{
    c2d_diskf a, b;
    c2d_surfacef s;
    c2d_vec2f n;
    c2d_status st;
    rough_diskf_of(&a, &c->a), rough_diskf_of(&b, &c->b);
    s.restitution = (float)c->e, s.friction = (float)c->mu, s.tangential_restitution = (float)c->beta;
    n.x = (float)c->n[0], n.y = (float)c->n[1];
    st = c->has_normal ? c2d_collide_rough_normalf(&a, &b, n, s) : c2d_collide_roughf(&a, &b, s);
    out[0] = a.vel.x, out[1] = a.vel.y, out[2] = b.vel.x, out[3] = b.vel.y, out[4] = a.spin, out[5] = b.spin;
    return st;
}
