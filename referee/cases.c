/* SPDX-License-Identifier: MIT */
#include "cases.h"

#include <math.h>

static double pick_restitution(c2d_rng *r)
{
    uint64_t k = c2d_rng_next(r) % 4;
    if (k == 0) return 1.0;
    if (k == 1) return 0.0;
    return c2d_rng_unit(r);
}

void gen_plain(c2d_rng *r, ref_case *c)
{
    double ang = c2d_rng_range(r, 0, 6.283185307179586);
    double dist = c2d_rng_range(r, 0.5, 2.0);
    int i;
    c->pa[0] = c2d_rng_range(r, -10, 10);
    c->pa[1] = c2d_rng_range(r, -10, 10);
    c->pb[0] = c->pa[0] + dist * cos(ang);
    c->pb[1] = c->pa[1] + dist * sin(ang);
    for (i = 0; i < 2; i++) {
        c->va[i] = c2d_rng_range(r, -10, 10);
        c->vb[i] = c2d_rng_range(r, -10, 10);
    }
    c->ma = exp(c2d_rng_range(r, log(0.1), log(10)));
    c->mb = exp(c2d_rng_range(r, log(0.1), log(10)));
    c->has_normal = (int)(c2d_rng_next(r) & 1);
    c->n[0] = c->pb[0] - c->pa[0];
    c->n[1] = c->pb[1] - c->pa[1];
    c->e = pick_restitution(r);
    /* Make it an impact more often than not: flip b's velocity if receding. */
    if ((c->vb[0] - c->va[0]) * c->n[0] + (c->vb[1] - c->va[1]) * c->n[1] > 0 && (c2d_rng_next(r) % 8) != 0) {
        c->vb[0] = -c->vb[0];
        c->vb[1] = -c->vb[1];
        c->va[0] = -c->va[0];
        c->va[1] = -c->va[1];
    }
}

double gen_magnitude(c2d_rng *r, int kmin, int kmax, int prec)
{
    int k = kmin + (int)(c2d_rng_next(r) % (uint64_t)(kmax - kmin + 1));
    double m = 1.0 + c2d_rng_unit(r);
    double v = ldexp(m, k);
    /* round to prec bits (also handles the subnormal range of the format) */
    if (prec < 53) v = (double)(float)v;
    return (c2d_rng_next(r) & 1) ? -v : v;
}

static double gen_field(c2d_rng *r, int prec, int emin, int emax)
{
    uint64_t k = c2d_rng_next(r) % 16;
    int sub = emin - prec + 1; /* smallest subnormal exponent */
    if (k == 0) return 0.0;
    if (k < 4) return gen_magnitude(r, -4, 4, prec);          /* moderate */
    if (k < 6) return gen_magnitude(r, sub, emin, prec);       /* subnormal/tiny */
    if (k < 8) return gen_magnitude(r, emax - 8, emax - 1, prec); /* near overflow */
    return gen_magnitude(r, sub, emax - 1, prec);              /* anywhere */
}

static double gen_mass(c2d_rng *r, int prec, int emin, int emax)
{
    uint64_t k = c2d_rng_next(r) % 10;
    if (k == 0) return INFINITY;
    return fabs(gen_field(r, prec, emin, emax)) + (k == 1 ? ldexp(1.0, emin - prec + 1) : 0.0);
}

void gen_extreme(c2d_rng *r, ref_case *c, int prec, int emin, int emax)
{
    int i;
    for (i = 0; i < 2; i++) {
        c->pa[i] = gen_field(r, prec, emin, emax);
        c->pb[i] = gen_field(r, prec, emin, emax);
        c->va[i] = gen_field(r, prec, emin, emax);
        c->vb[i] = gen_field(r, prec, emin, emax);
        c->n[i] = gen_field(r, prec, emin, emax);
    }
    do {
        c->ma = gen_mass(r, prec, emin, emax);
        c->mb = gen_mass(r, prec, emin, emax);
    } while (c->ma == 0 || c->mb == 0 || (isinf(c->ma) && isinf(c->mb)));
    c->has_normal = (int)(c2d_rng_next(r) & 1);
    c->e = pick_restitution(r);
    if (prec < 53) c->e = (double)(float)c->e;
    /* Approach more often than not (otherwise half the cases are trivial). */
    if ((c2d_rng_next(r) % 4) != 0) {
        double nx = c->has_normal ? c->n[0] : c->pb[0] - c->pa[0];
        double ny = c->has_normal ? c->n[1] : c->pb[1] - c->pa[1];
        double d = (c->vb[0] - c->va[0]) * nx + (c->vb[1] - c->va[1]) * ny;
        if (d > 0) {
            for (i = 0; i < 2; i++) {
                c->va[i] = -c->va[i];
                c->vb[i] = -c->vb[i];
            }
        }
    }
}

void case_to_bodies(const ref_case *c, c2d_body *a, c2d_body *b)
{
    a->pos.x = c->pa[0];
    a->pos.y = c->pa[1];
    a->vel.x = c->va[0];
    a->vel.y = c->va[1];
    a->mass = c->ma;
    b->pos.x = c->pb[0];
    b->pos.y = c->pb[1];
    b->vel.x = c->vb[0];
    b->vel.y = c->vb[1];
    b->mass = c->mb;
}

void case_to_bodiesf(const ref_case *c, c2d_bodyf *a, c2d_bodyf *b)
{
    a->pos.x = (float)c->pa[0];
    a->pos.y = (float)c->pa[1];
    a->vel.x = (float)c->va[0];
    a->vel.y = (float)c->va[1];
    a->mass = (float)c->ma;
    b->pos.x = (float)c->pb[0];
    b->pos.y = (float)c->pb[1];
    b->vel.x = (float)c->vb[0];
    b->vel.y = (float)c->vb[1];
    b->mass = (float)c->mb;
}

double ref_to_float(double x)
{
    volatile float f = (float)x;
    return f;
}

void case_to_float(ref_case *c)
{
    int i;
    for (i = 0; i < 2; i++) {
        c->pa[i] = (float)c->pa[i], c->pb[i] = (float)c->pb[i];
        c->va[i] = (float)c->va[i], c->vb[i] = (float)c->vb[i];
        c->n[i] = (float)c->n[i];
    }
    c->ma = (float)c->ma, c->mb = (float)c->mb, c->e = (float)c->e;
}

/* Every component with its own exponent anywhere in the format's range
 * (subnormals included): magnitudes that differ by more than the exponent
 * range, the audit's failure kind.  Approaching more often than not. */
void gen_toi_ratios(c2d_rng *r, ref_case *c, double *radius, int prec, int emin, int emax)
{
    int i, sub = emin - prec + 1;
    for (i = 0; i < 2; i++) {
        c->pa[i] = c2d_rng_next(r) % 4 == 0 ? 0.0 : gen_magnitude(r, sub, emax - 2, prec);
        c->pb[i] = gen_magnitude(r, sub, emax - 2, prec);
        c->va[i] = c2d_rng_next(r) % 4 == 0 ? 0.0 : gen_magnitude(r, sub, emax - 2, prec);
        c->vb[i] = c2d_rng_next(r) % 3 == 0 ? 0.0 : gen_magnitude(r, sub, emax - 2, prec);
    }
    *radius = fabs(gen_magnitude(r, sub, emax - 2, prec));
    if (c2d_rng_next(r) % 4 != 0 &&
        (c->pb[0] - c->pa[0]) * (c->vb[0] - c->va[0]) + (c->pb[1] - c->pa[1]) * (c->vb[1] - c->va[1]) > 0)
        for (i = 0; i < 2; i++) c->va[i] = -c->va[i], c->vb[i] = -c->vb[i];
    c->ma = c->mb = 1, c->n[0] = c->n[1] = 0, c->has_normal = 0, c->e = 0;
}
