/* SPDX-License-Identifier: MIT */
#include "ref_rough.h"

#include <math.h>
#include <mpfr.h>

enum { REF_ROUGH_BITS = 4400 }; /* > 2 x (2^11 exponents + 53 bits): differences and products exact */

void ref_rough_init(ref_rough_answer *r)
{
    int i;
    for (i = 0; i < 6; i++) mpfr_init2(r->out[i], REF_ROUGH_BITS);
    r->status = C2D_INVALID;
    r->range_allowed = r->range_required = 0;
}

void ref_rough_clear(ref_rough_answer *r)
{
    int i;
    for (i = 0; i < 6; i++) mpfr_clear(r->out[i]);
}

static int disk_valid(const ref_disk *d)
{
    return isfinite(d->pos[0]) && isfinite(d->pos[1]) && isfinite(d->vel[0]) && isfinite(d->vel[1]) &&
           isfinite(d->spin) && isfinite(d->radius) && d->radius >= 0 && d->mass > 0 && d->inertia > 0;
}

static void to_case(const ref_rough_case *c, ref_case *n)
{
    int i;
    for (i = 0; i < 2; i++) {
        n->pa[i] = c->a.pos[i];
        n->pb[i] = c->b.pos[i];
        n->va[i] = c->a.vel[i];
        n->vb[i] = c->b.vel[i];
        n->n[i] = c->n[i];
    }
    n->ma = c->a.mass;
    n->mb = c->b.mass;
    n->has_normal = c->has_normal;
    n->e = c->e;
}

/* 1/x, or 0 for x = INFINITY. */
static void inverse(mpfr_t out, double x)
{
    if (isinf(x)) mpfr_set_zero(out, 1);
    else mpfr_set_d(out, 1.0 / x, MPFR_RNDN), mpfr_set_d(out, 1.0, MPFR_RNDN), mpfr_div_d(out, out, x, MPFR_RNDN);
}

void ref_rough(const ref_rough_case *c, double range_limit, ref_rough_answer *r)
{
    ref_case nc;
    ref_answer na;
    mpfr_t n[2], len, t[2], gn, gt, tmp, tmp2, ia, ib, ka, kb, mn, mt, jt, cone;
    int i;
    r->range_allowed = r->range_required = 0;
    if (!disk_valid(&c->a) || !disk_valid(&c->b) || !(c->mu >= 0) || !(c->beta >= -1 && c->beta <= 1)) {
        r->status = C2D_INVALID;
        return;
    }
    to_case(c, &nc);
    ref_answer_init(&na);
    ref_collide(&nc, range_limit, &na);
    r->status = na.status;
    r->range_allowed = na.range_allowed;
    r->range_required = na.range_required;
    if (na.status != C2D_OK) {
        ref_answer_clear(&na);
        return;
    }
    for (i = 0; i < 4; i++) mpfr_set_q(r->out[i], na.v[i], MPFR_RNDN);
    mpfr_set_d(r->out[4], c->a.spin, MPFR_RNDN);
    mpfr_set_d(r->out[5], c->b.spin, MPFR_RNDN);
    ref_answer_clear(&na);
    if (c->mu == 0 || c->beta == -1) return;
    mpfr_inits2(REF_ROUGH_BITS, n[0], n[1], len, t[0], t[1], gn, gt, tmp, tmp2, ia, ib, ka, kb, mn, mt, jt, cone,
                (mpfr_ptr)0);
    for (i = 0; i < 2; i++) {
        if (c->has_normal) {
            mpfr_set_d(n[i], c->n[i], MPFR_RNDN);
        } else {
            mpfr_set_d(n[i], c->b.pos[i], MPFR_RNDN);
            mpfr_sub_d(n[i], n[i], c->a.pos[i], MPFR_RNDN);
        }
    }
    mpfr_hypot(len, n[0], n[1], MPFR_RNDN);
    mpfr_neg(t[0], n[1], MPFR_RNDN);
    mpfr_div(t[0], t[0], len, MPFR_RNDN);
    mpfr_div(t[1], n[0], len, MPFR_RNDN);
    mpfr_set_zero(gn, 1);
    mpfr_set_zero(gt, 1);
    for (i = 0; i < 2; i++) {
        mpfr_set_d(tmp, c->b.vel[i], MPFR_RNDN);
        mpfr_sub_d(tmp, tmp, c->a.vel[i], MPFR_RNDN);
        mpfr_mul(tmp2, tmp, n[i], MPFR_RNDN);
        mpfr_div(tmp2, tmp2, len, MPFR_RNDN);
        mpfr_add(gn, gn, tmp2, MPFR_RNDN);
        mpfr_mul(tmp2, tmp, t[i], MPFR_RNDN);
        mpfr_add(gt, gt, tmp2, MPFR_RNDN);
    }
    mpfr_set_d(tmp, c->a.spin, MPFR_RNDN);
    mpfr_mul_d(tmp, tmp, c->a.radius, MPFR_RNDN);
    mpfr_sub(gt, gt, tmp, MPFR_RNDN);
    mpfr_set_d(tmp, c->b.spin, MPFR_RNDN);
    mpfr_mul_d(tmp, tmp, c->b.radius, MPFR_RNDN);
    mpfr_sub(gt, gt, tmp, MPFR_RNDN);
    inverse(ia, c->a.mass);
    inverse(ib, c->b.mass);
    inverse(ka, c->a.inertia);
    mpfr_mul_d(ka, ka, c->a.radius, MPFR_RNDN);
    mpfr_mul_d(ka, ka, c->a.radius, MPFR_RNDN);
    inverse(kb, c->b.inertia);
    mpfr_mul_d(kb, kb, c->b.radius, MPFR_RNDN);
    mpfr_mul_d(kb, kb, c->b.radius, MPFR_RNDN);
    mpfr_add(mn, ia, ib, MPFR_RNDN);                          /* 1 / mn */
    mpfr_add(mt, mn, ka, MPFR_RNDN);
    mpfr_add(mt, mt, kb, MPFR_RNDN);                          /* 1 / mt */
    mpfr_set_d(tmp, 1.0, MPFR_RNDN);
    mpfr_add_d(tmp, tmp, c->beta, MPFR_RNDN);
    mpfr_mul(jt, tmp, gt, MPFR_RNDN);
    mpfr_div(jt, jt, mt, MPFR_RNDN);
    mpfr_neg(jt, jt, MPFR_RNDN);                              /* sticking */
    if (!isinf(c->mu)) {
        mpfr_set_d(tmp, 1.0, MPFR_RNDN);
        mpfr_add_d(tmp, tmp, c->e, MPFR_RNDN);
        mpfr_mul(cone, tmp, gn, MPFR_RNDN);
        mpfr_neg(cone, cone, MPFR_RNDN);
        mpfr_div(cone, cone, mn, MPFR_RNDN);
        mpfr_mul_d(cone, cone, c->mu, MPFR_RNDN);             /* mu Jn > 0 */
        if (mpfr_cmpabs(jt, cone) > 0) {
            if (mpfr_sgn(gt) > 0) mpfr_neg(jt, cone, MPFR_RNDN);
            else mpfr_set(jt, cone, MPFR_RNDN);
        }
    }
    for (i = 0; i < 2; i++) {
        mpfr_mul(tmp, jt, t[i], MPFR_RNDN);
        mpfr_mul(tmp2, tmp, ia, MPFR_RNDN);
        mpfr_sub(r->out[i], r->out[i], tmp2, MPFR_RNDN);
        mpfr_mul(tmp2, tmp, ib, MPFR_RNDN);
        mpfr_add(r->out[2 + i], r->out[2 + i], tmp2, MPFR_RNDN);
    }
    inverse(tmp, c->a.inertia);
    mpfr_mul(tmp, tmp, jt, MPFR_RNDN);
    mpfr_mul_d(tmp, tmp, c->a.radius, MPFR_RNDN);
    mpfr_sub(r->out[4], r->out[4], tmp, MPFR_RNDN);
    inverse(tmp, c->b.inertia);
    mpfr_mul(tmp, tmp, jt, MPFR_RNDN);
    mpfr_mul_d(tmp, tmp, c->b.radius, MPFR_RNDN);
    mpfr_sub(r->out[5], r->out[5], tmp, MPFR_RNDN);
    for (i = 0; i < 6; i++) {
        double m = fabs(mpfr_get_d(r->out[i], MPFR_RNDN));
        if (m >= range_limit * 0.5) r->range_allowed = 1;
        if (m > range_limit * 1.0001) r->range_required = 1;
    }
    mpfr_clears(n[0], n[1], len, t[0], t[1], gn, gt, tmp, tmp2, ia, ib, ka, kb, mn, mt, jt, cone, (mpfr_ptr)0);
}

/* Each body's scale in MPFR (spin x radius may exceed the format). */
static void scale_of(mpfr_t s, const ref_disk *d, const mpfr_t vx, const mpfr_t vy, const mpfr_t spin)
{
    mpfr_t x;
    mpfr_init2(x, REF_ROUGH_BITS);
    mpfr_set_d(s, fmax(fabs(d->vel[0]), fabs(d->vel[1])), MPFR_RNDN);
    mpfr_set_d(x, d->spin, MPFR_RNDN);
    mpfr_mul_d(x, x, d->radius, MPFR_RNDN);
    mpfr_abs(x, x, MPFR_RNDN);
    mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_abs(x, vx, MPFR_RNDN);
    mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_abs(x, vy, MPFR_RNDN);
    mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_mul_d(x, spin, d->radius, MPFR_RNDN);
    mpfr_abs(x, x, MPFR_RNDN);
    mpfr_max(s, s, x, MPFR_RNDN);
    mpfr_clear(x);
}

/* ulp of a scale in a format of `prec` bits, smallest normal 2^emin, with
 * no upper limit (a spin x radius may exceed the format's range). */
static void ulp_of(mpfr_t u, const mpfr_t s, int prec, int emin)
{
    long ex = 0;
    if (mpfr_zero_p(s)) ex = emin;
    else (void)mpfr_get_d_2exp(&ex, s, MPFR_RNDZ); /* s = f 2^ex, f in [0.5, 1) */
    if (ex - 1 < emin) ex = emin + 1;
    mpfr_set_ui_2exp(u, 1, ex - 1 - (prec - 1), MPFR_RNDN);
}

/* |got - exact| x weight / ulp, less the part no value of the format could
 * avoid (a spin that is subnormal while spin x radius is not: its own
 * rounding, |fl(exact) - exact|, is forgiven). */
static double err_in(double got, const mpfr_t exact, double weight, int forgive_own_rounding, const mpfr_t ulp, int prec)
{
    mpfr_t d, f;
    double r, fl;
    if (!isfinite(got)) return INFINITY;
    mpfr_inits2(REF_ROUGH_BITS, d, f, (mpfr_ptr)0);
    fl = prec < 53 ? (double)mpfr_get_flt(exact, MPFR_RNDN) : mpfr_get_d(exact, MPFR_RNDN);
    mpfr_set_d(d, got, MPFR_RNDN);
    mpfr_sub(d, d, exact, MPFR_RNDN);
    mpfr_abs(d, d, MPFR_RNDN);
    mpfr_set_d(f, fl, MPFR_RNDN);
    mpfr_sub(f, f, exact, MPFR_RNDN);
    mpfr_abs(f, f, MPFR_RNDN);
    if (forgive_own_rounding) mpfr_sub(d, d, f, MPFR_RNDN);
    if (mpfr_sgn(d) < 0) mpfr_set_zero(d, 1);
    mpfr_mul_d(d, d, weight, MPFR_RNDN);
    mpfr_div(d, d, ulp, MPFR_RNDN);
    r = mpfr_get_d(d, MPFR_RNDU);
    mpfr_clears(d, f, (mpfr_ptr)0);
    return r;
}

double ref_rough_err(const ref_rough_case *c, const ref_rough_answer *r, const double got[6], int prec, int emin)
{
    mpfr_t s, ua, ub;
    double worst = 0;
    int i;
    mpfr_inits2(REF_ROUGH_BITS, s, ua, ub, (mpfr_ptr)0);
    scale_of(s, &c->a, r->out[0], r->out[1], r->out[4]);
    ulp_of(ua, s, prec, emin);
    scale_of(s, &c->b, r->out[2], r->out[3], r->out[5]);
    ulp_of(ub, s, prec, emin);
    for (i = 0; i < 2; i++) {
        worst = fmax(worst, err_in(got[i], r->out[i], 1, 0, ua, prec));
        worst = fmax(worst, err_in(got[2 + i], r->out[2 + i], 1, 0, ub, prec));
    }
    worst = fmax(worst, c->a.radius == 0 ? (got[4] == c->a.spin ? 0 : INFINITY)
                                         : err_in(got[4], r->out[4], c->a.radius, 1, ua, prec));
    worst = fmax(worst, c->b.radius == 0 ? (got[5] == c->b.spin ? 0 : INFINITY)
                                         : err_in(got[5], r->out[5], c->b.radius, 1, ub, prec));
    mpfr_clears(s, ua, ub, (mpfr_ptr)0);
    return worst;
}

static void add_disk(mpfr_t *acc, const ref_disk *d, const double *vel, double spin, mpfr_t tmp)
{
    int i;
    if (!isinf(d->mass)) {
        for (i = 0; i < 2; i++) {
            mpfr_set_d(tmp, vel[i], MPFR_RNDN);
            mpfr_mul(tmp, tmp, tmp, MPFR_RNDN);
            mpfr_mul_d(tmp, tmp, 0.5 * d->mass, MPFR_RNDN);
            mpfr_add(acc[0], acc[0], tmp, MPFR_RNDN);
            mpfr_set_d(tmp, vel[i], MPFR_RNDN);
            mpfr_mul_d(tmp, tmp, d->mass, MPFR_RNDN);
            mpfr_add(acc[1 + i], acc[1 + i], tmp, MPFR_RNDN);
        }
        mpfr_set_d(tmp, d->pos[0], MPFR_RNDN); /* m (x vy - y vx) */
        mpfr_mul_d(tmp, tmp, vel[1], MPFR_RNDN);
        mpfr_mul_d(tmp, tmp, d->mass, MPFR_RNDN);
        mpfr_add(acc[3], acc[3], tmp, MPFR_RNDN);
        mpfr_set_d(tmp, d->pos[1], MPFR_RNDN);
        mpfr_mul_d(tmp, tmp, vel[0], MPFR_RNDN);
        mpfr_mul_d(tmp, tmp, d->mass, MPFR_RNDN);
        mpfr_sub(acc[3], acc[3], tmp, MPFR_RNDN);
    }
    if (!isinf(d->inertia)) {
        mpfr_set_d(tmp, spin, MPFR_RNDN);
        mpfr_mul(tmp, tmp, tmp, MPFR_RNDN);
        mpfr_mul_d(tmp, tmp, 0.5 * d->inertia, MPFR_RNDN);
        mpfr_add(acc[0], acc[0], tmp, MPFR_RNDN);
        mpfr_set_d(tmp, spin, MPFR_RNDN);
        mpfr_mul_d(tmp, tmp, d->inertia, MPFR_RNDN);
        mpfr_add(acc[3], acc[3], tmp, MPFR_RNDN);
    }
}

void ref_rough_invariants(const ref_rough_case *c, const double *got, double out[4])
{
    mpfr_t acc[4], tmp;
    int i;
    for (i = 0; i < 4; i++) mpfr_init2(acc[i], REF_ROUGH_BITS), mpfr_set_zero(acc[i], 1);
    mpfr_init2(tmp, REF_ROUGH_BITS);
    add_disk(acc, &c->a, got ? got : c->a.vel, got ? got[4] : c->a.spin, tmp);
    add_disk(acc, &c->b, got ? got + 2 : c->b.vel, got ? got[5] : c->b.spin, tmp);
    for (i = 0; i < 4; i++) out[i] = mpfr_get_d(acc[i], MPFR_RNDN), mpfr_clear(acc[i]);
    mpfr_clear(tmp);
}
