/* SPDX-License-Identifier: MIT */
#include "ref_sphere.h"

#include <math.h>
#include <mpfr.h>

enum { REF_SPHERE_BITS = 512 }; /* 154 digits: every sum and product of unit-scale inputs exact or far below */

#define RND MPFR_RNDN

typedef struct mball { mpfr_t v[2], w[3]; } mball;

static void mball_init(mball *o, const ref_ball *d)
{
    int i;
    for (i = 0; i < 2; i++) mpfr_init2(o->v[i], REF_SPHERE_BITS), mpfr_set_d(o->v[i], d->vel[i], RND);
    for (i = 0; i < 3; i++) mpfr_init2(o->w[i], REF_SPHERE_BITS), mpfr_set_d(o->w[i], d->w[i], RND);
}

static void mball_clear(mball *o)
{
    int i;
    for (i = 0; i < 2; i++) mpfr_clear(o->v[i]);
    for (i = 0; i < 3; i++) mpfr_clear(o->w[i]);
}

/* 1/x, 0 for an infinite x. */
static void inv(mpfr_t out, double x)
{
    if (isinf(x)) mpfr_set_zero(out, 1);
    else mpfr_set_d(out, 1.0, RND), mpfr_div_d(out, out, x, RND);
}

static double ulp_of(double scale, int prec)
{
    int ex;
    if (scale == 0) return ldexp(1.0, prec == 24 ? -149 : -1074);
    frexp(scale, &ex);
    return ldexp(1.0, ex - prec);
}

static double scale_of(const ref_ball *d, const double *got, double s)
{
    int i;
    for (i = 0; i < 2; i++) s = fmax(s, fmax(fabs(d->vel[i]), fabs(got[i])));
    for (i = 0; i < 3; i++) s = fmax(s, d->r * fmax(fabs(d->w[i]), fabs(got[2 + i])));
    return s;
}

/* Worst |got - ref| in units of `ulp`, spins as spin x radius. */
static double ball_err(const mball *o, const double *got, double radius, double ulp)
{
    mpfr_t d;
    double worst = 0;
    int i;
    mpfr_init2(d, REF_SPHERE_BITS);
    for (i = 0; i < 5; i++) {
        mpfr_d_sub(d, got[i], i < 2 ? o->v[i] : o->w[i - 2], RND);
        if (i >= 2) mpfr_mul_d(d, d, radius, RND);
        worst = fmax(worst, fabs(mpfr_get_d(d, RND)) / ulp);
    }
    mpfr_clear(d);
    return worst;
}

/* out = x + k y */
static void add_mul(mpfr_t out, mpfr_t x, mpfr_t y, mpfr_t k, mpfr_t tmp)
{
    mpfr_mul(tmp, y, k, RND);
    mpfr_add(out, x, tmp, RND);
}

c2d_status ref_balls(const ref_balls_case *c, const double got[10], int prec, double *err_ulp)
{
    mpfr_t nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam, f, jt, jz, k;
    mball oa, ob;
    double s;
    mpfr_inits2(REF_SPHERE_BITS, nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam,
                f, jt, jz, k, (mpfr_ptr)0);
    mpfr_set_d(nx, c->b.pos[0], RND), mpfr_sub_d(nx, nx, c->a.pos[0], RND);
    mpfr_set_d(ny, c->b.pos[1], RND), mpfr_sub_d(ny, ny, c->a.pos[1], RND);
    mpfr_hypot(len, nx, ny, RND);
    mpfr_div(nx, nx, len, RND), mpfr_div(ny, ny, len, RND);
    mpfr_set_d(dvx, c->b.vel[0], RND), mpfr_sub_d(dvx, dvx, c->a.vel[0], RND);
    mpfr_set_d(dvy, c->b.vel[1], RND), mpfr_sub_d(dvy, dvy, c->a.vel[1], RND);
    mpfr_mul(gn, dvx, nx, RND), mpfr_mul(t1, dvy, ny, RND), mpfr_add(gn, gn, t1, RND);
    if (mpfr_sgn(gn) >= 0) {
        mpfr_clears(nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam, f, jt, jz, k,
                    (mpfr_ptr)0);
        return C2D_SEPARATING;
    }
    /* gt = dv.t - (Ra wza + Rb wzb), gz = -(Ra (wxa ny - wya nx) + Rb (wxb ny - wyb nx)) */
    mpfr_mul(gt, dvy, nx, RND), mpfr_mul(t1, dvx, ny, RND), mpfr_sub(gt, gt, t1, RND);
    mpfr_set_d(t1, c->a.r, RND), mpfr_mul_d(t1, t1, c->a.w[2], RND), mpfr_sub(gt, gt, t1, RND);
    mpfr_set_d(t1, c->b.r, RND), mpfr_mul_d(t1, t1, c->b.w[2], RND), mpfr_sub(gt, gt, t1, RND);
    mpfr_mul_d(t1, ny, c->a.w[0], RND), mpfr_mul_d(t2, nx, c->a.w[1], RND), mpfr_sub(t1, t1, t2, RND);
    mpfr_mul_d(gz, t1, -c->a.r, RND);
    mpfr_mul_d(t1, ny, c->b.w[0], RND), mpfr_mul_d(t2, nx, c->b.w[1], RND), mpfr_sub(t1, t1, t2, RND);
    mpfr_mul_d(t1, t1, -c->b.r, RND), mpfr_add(gz, gz, t1, RND);
    mpfr_hypot(g, gt, gz, RND);
    inv(ima, c->a.m), inv(imb, c->b.m);
    inv(qa, c->a.inertia), mpfr_mul_d(qa, qa, c->a.r, RND);
    inv(qb, c->b.inertia), mpfr_mul_d(qb, qb, c->b.r, RND);
    mpfr_add(imn, ima, imb, RND);
    mpfr_mul_d(t1, qa, c->a.r, RND), mpfr_add(imt, imn, t1, RND);
    mpfr_mul_d(t1, qb, c->b.r, RND), mpfr_add(imt, imt, t1, RND);
    /* Jn = -(1 + e) gn / imn */
    mpfr_set_d(t1, c->e, RND), mpfr_add_ui(t1, t1, 1, RND);
    mpfr_mul(jn, t1, gn, RND), mpfr_neg(jn, jn, RND), mpfr_div(jn, jn, imn, RND);
    /* mu = a + b exp(-c g) */
    mpfr_mul_d(t1, g, -c->decay, RND), mpfr_exp(t1, t1, RND), mpfr_mul_d(t1, t1, c->boost, RND);
    mpfr_set_d(mu, c->mu, RND), mpfr_add(mu, mu, t1, RND);
    /* lam = min(mu Jn, g / imt); f = lam / g */
    mpfr_div(t2, g, imt, RND);
    if (isinf(c->mu)) mpfr_set(lam, t2, RND);
    else mpfr_mul(lam, mu, jn, RND), mpfr_min(lam, lam, t2, RND);
    if (mpfr_zero_p(g)) mpfr_set_zero(f, 1);
    else mpfr_div(f, lam, g, RND);
    mpfr_mul(jt, f, gt, RND), mpfr_neg(jt, jt, RND);
    mpfr_mul(jz, f, gz, RND), mpfr_neg(jz, jz, RND);
    mball_init(&oa, &c->a), mball_init(&ob, &c->b);
    /* va -= (Jn n + Jt t)/ma, vb += (Jn n + Jt t)/mb, t = (-ny, nx) */
    {
        mball *o[2] = {&oa, &ob};
        mpfr_ptr im[2] = {ima, imb}, q[2] = {qa, qb};
        int i;
        for (i = 0; i < 2; i++) {
            int sg = i == 0 ? -1 : 1;
            mpfr_mul(k, jn, im[i], RND), mpfr_mul_si(k, k, sg, RND);
            add_mul(o[i]->v[0], o[i]->v[0], nx, k, t1);
            add_mul(o[i]->v[1], o[i]->v[1], ny, k, t1);
            mpfr_mul(k, jt, im[i], RND), mpfr_mul_si(k, k, sg, RND);
            mpfr_neg(t2, ny, RND);
            add_mul(o[i]->v[0], o[i]->v[0], t2, k, t1);
            add_mul(o[i]->v[1], o[i]->v[1], nx, k, t1);
            /* w += R (Jz t - Jt z) / I */
            mpfr_mul(k, jz, q[i], RND);
            add_mul(o[i]->w[0], o[i]->w[0], t2, k, t1);
            add_mul(o[i]->w[1], o[i]->w[1], nx, k, t1);
            mpfr_mul(k, jt, q[i], RND);
            mpfr_sub(o[i]->w[2], o[i]->w[2], k, RND);
        }
    }
    s = scale_of(&c->a, got, 0);
    s = scale_of(&c->b, got + 5, s);
    *err_ulp = fmax(ball_err(&oa, got, c->a.r, ulp_of(s, prec)), ball_err(&ob, got + 5, c->b.r, ulp_of(s, prec)));
    mball_clear(&oa), mball_clear(&ob);
    mpfr_clears(nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam, f, jt, jz, k,
                (mpfr_ptr)0);
    return C2D_OK;
}

c2d_status ref_cushion(const ref_cushion_case *c, const double got[5], int prec, double *err_ulp)
{
    mpfr_t nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn, dvt, dwn, dwt;
    mball o;
    const ref_ball *d = &c->a;
    mpfr_inits2(REF_SPHERE_BITS, nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn,
                dvt, dwn, dwt, (mpfr_ptr)0);
    mpfr_set_d(nx, c->n[0], RND), mpfr_set_d(ny, c->n[1], RND), mpfr_hypot(len, nx, ny, RND);
    mpfr_div(nx, nx, len, RND), mpfr_div(ny, ny, len, RND);
    mpfr_set_d(sn, c->h, RND), mpfr_sub_d(sn, sn, d->r, RND), mpfr_div_d(sn, sn, d->r, RND);
    mpfr_sqr(cs, sn, RND), mpfr_ui_sub(cs, 1, cs, RND), mpfr_sqrt(cs, cs, RND);
    mpfr_mul_d(vn, nx, d->vel[0], RND), mpfr_mul_d(t1, ny, d->vel[1], RND), mpfr_add(vn, vn, t1, RND);
    mpfr_mul(t1, vn, cs, RND);
    if (mpfr_sgn(t1) <= 0) {
        mpfr_clears(nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn, dvt, dwn, dwt,
                    (mpfr_ptr)0);
        return C2D_SEPARATING;
    }
    mpfr_mul_d(vt, nx, d->vel[1], RND), mpfr_mul_d(t2, ny, d->vel[0], RND), mpfr_sub(vt, vt, t2, RND);
    mpfr_mul_d(wn, nx, d->w[0], RND), mpfr_mul_d(t2, ny, d->w[1], RND), mpfr_add(wn, wn, t2, RND);
    mpfr_mul_d(wt, nx, d->w[1], RND), mpfr_mul_d(t2, ny, d->w[0], RND), mpfr_sub(wt, wt, t2, RND);
    /* Pn = (1 + e) m cos(th) vn */
    mpfr_set_d(pn, c->e, RND), mpfr_add_ui(pn, pn, 1, RND), mpfr_mul_d(pn, pn, d->m, RND), mpfr_mul(pn, pn, t1, RND);
    /* s1 = vt + R (cs wz - sn wn), s2 = -sn vn - R wt */
    mpfr_mul_d(s1, cs, d->w[2], RND), mpfr_mul(t2, sn, wn, RND), mpfr_sub(s1, s1, t2, RND);
    mpfr_mul_d(s1, s1, d->r, RND), mpfr_add(s1, s1, vt, RND);
    mpfr_mul(s2, sn, vn, RND), mpfr_mul_d(t2, wt, d->r, RND), mpfr_add(s2, s2, t2, RND), mpfr_neg(s2, s2, RND);
    mpfr_hypot(sl, s1, s2, RND);
    inv(q, d->inertia), mpfr_mul_d(q, q, d->r, RND);
    mpfr_mul_d(a, q, d->r, RND), mpfr_set_d(t2, 1.0, RND), mpfr_div_d(t2, t2, d->m, RND), mpfr_add(a, a, t2, RND);
    mpfr_div(t2, sl, a, RND);
    if (isinf(c->mu)) mpfr_set(lam, t2, RND);
    else mpfr_mul_d(lam, pn, c->mu, RND), mpfr_min(lam, lam, t2, RND);
    if (mpfr_zero_p(sl)) mpfr_set_zero(f, 1);
    else mpfr_div(f, lam, sl, RND);
    mpfr_mul(f1, f, s1, RND), mpfr_neg(f1, f1, RND);
    mpfr_mul(f2, f, s2, RND), mpfr_neg(f2, f2, RND);
    /* dvn = -(pn cs + f2 sn)/m, dvt = f1/m, dwn = -q f1 sn, dwt = -q f2, dwz = q f1 cs */
    mpfr_mul(dvn, pn, cs, RND), mpfr_mul(t2, f2, sn, RND), mpfr_add(dvn, dvn, t2, RND);
    mpfr_div_d(dvn, dvn, -d->m, RND);
    mpfr_div_d(dvt, f1, d->m, RND);
    mpfr_mul(dwn, q, f1, RND), mpfr_mul(dwn, dwn, sn, RND), mpfr_neg(dwn, dwn, RND);
    mpfr_mul(dwt, q, f2, RND), mpfr_neg(dwt, dwt, RND);
    mball_init(&o, d);
    mpfr_mul(t1, dvn, nx, RND), mpfr_mul(t2, dvt, ny, RND), mpfr_sub(t1, t1, t2, RND), mpfr_add(o.v[0], o.v[0], t1, RND);
    mpfr_mul(t1, dvn, ny, RND), mpfr_mul(t2, dvt, nx, RND), mpfr_add(t1, t1, t2, RND), mpfr_add(o.v[1], o.v[1], t1, RND);
    mpfr_mul(t1, dwn, nx, RND), mpfr_mul(t2, dwt, ny, RND), mpfr_sub(t1, t1, t2, RND), mpfr_add(o.w[0], o.w[0], t1, RND);
    mpfr_mul(t1, dwn, ny, RND), mpfr_mul(t2, dwt, nx, RND), mpfr_add(t1, t1, t2, RND), mpfr_add(o.w[1], o.w[1], t1, RND);
    mpfr_mul(t1, q, f1, RND), mpfr_mul(t1, t1, cs, RND), mpfr_add(o.w[2], o.w[2], t1, RND);
    *err_ulp = ball_err(&o, got, d->r, ulp_of(scale_of(d, got, 0), prec));
    mball_clear(&o);
    mpfr_clears(nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn, dvt, dwn, dwt,
                (mpfr_ptr)0);
    return C2D_OK;
}

double ref_exp_neg_err(double x, double got, int prec)
{
    mpfr_t r, d;
    double err;
    mpfr_inits2(REF_SPHERE_BITS, r, d, (mpfr_ptr)0);
    mpfr_set_d(r, -x, RND), mpfr_exp(r, r, RND);
    mpfr_d_sub(d, got, r, RND);
    err = fabs(mpfr_get_d(d, RND)) / ulp_of(mpfr_get_d(r, MPFR_RNDZ), prec);
    mpfr_clears(r, d, (mpfr_ptr)0);
    return err;
}
