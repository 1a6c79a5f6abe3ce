/* SPDX-License-Identifier: MIT */
#include "ref_sphere.h"

#include <math.h>
#include <mpfr.h>

/* The working precision of one case: the spread of its inputs' exponents
 * plus 512 bits (154 digits at unit scale, 2,700 bits over the whole double
 * range): every difference of two inputs exact, and every quantity the
 * model forms, a cancelling one included (its exact value is at least the
 * product of two input ulps), carried to 2^-400 of itself. */
static mpfr_prec_t ref_bits = 512;

static void spread_of(const double *x, int n, int *lo, int *hi)
{
    int i;
    for (i = 0; i < n; i++)
        if (x[i] != 0 && isfinite(x[i])) {
            int e = ilogb(x[i]);
            if (e < *lo) *lo = e;
            if (e > *hi) *hi = e;
        }
}

static void ball_spread(const ref_ball *d, int *lo, int *hi)
{
    const double x[10] = {d->pos[0], d->pos[1], d->vel[0], d->vel[1], d->w[0], d->w[1], d->w[2], d->m, d->r, d->inertia};
    spread_of(x, 10, lo, hi);
}

static void set_bits(int lo, int hi)
{
    ref_bits = hi >= lo ? (hi - lo) + 512 : 512;
}

#define RND MPFR_RNDN

typedef struct mball { mpfr_t v[2], w[3]; } mball;

static void mball_init(mball *o, const ref_ball *d)
{
    int i;
    for (i = 0; i < 2; i++) mpfr_init2(o->v[i], ref_bits), mpfr_set_d(o->v[i], d->vel[i], RND);
    for (i = 0; i < 3; i++) mpfr_init2(o->w[i], ref_bits), mpfr_set_d(o->w[i], d->w[i], RND);
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

static int ball_valid(const ref_ball *d)
{
    return isfinite(d->pos[0]) && isfinite(d->pos[1]) && isfinite(d->vel[0]) && isfinite(d->vel[1]) &&
           isfinite(d->w[0]) && isfinite(d->w[1]) && isfinite(d->w[2]) && isfinite(d->r) && d->r >= 0 && d->m > 0 &&
           d->inertia > 0;
}

/* s = max(s, |x|) */
static void max_abs(mpfr_t s, const mpfr_t x)
{
    if (mpfr_cmpabs(x, s) > 0) mpfr_abs(s, x, RND);
}

/* s = max(s, |vx|, |vy|, |R w| before and after (o)). */
static void scale_of(mpfr_t s, const ref_ball *d, const mball *o)
{
    mpfr_t x;
    int i;
    mpfr_init2(x, ref_bits);
    for (i = 0; i < 2; i++) mpfr_set_d(x, d->vel[i], RND), max_abs(s, x), max_abs(s, o->v[i]);
    for (i = 0; i < 3; i++) {
        mpfr_set_d(x, d->w[i], RND), mpfr_mul_d(x, x, d->r, RND), max_abs(s, x);
        mpfr_mul_d(x, o->w[i], d->r, RND), max_abs(s, x);
    }
    mpfr_clear(x);
}

/* ulp of the scale s at prec bits, at least 2^(emin - prec + 1). */
static void ulp_of(mpfr_t u, const mpfr_t s, int prec, int emin)
{
    long ex = emin + 1;
    if (!mpfr_zero_p(s)) (void)mpfr_get_d_2exp(&ex, s, MPFR_RNDZ); /* s = f 2^ex, f in [0.5, 1) */
    if (ex - 1 < emin) ex = emin + 1;
    mpfr_set_ui_2exp(u, 1, ex - 1 - (prec - 1), RND);
}

/* |got - exact| x weight / ulp; a subnormal exact spin (forgive) is
 * forgiven its own rounding |fl(exact) - exact|. */
static double err_in(double got, const mpfr_t exact, double weight, int forgive, const mpfr_t ulp, int prec,
                     int emin)
{
    mpfr_t d, f;
    double r, fl;
    if (!isfinite(got)) return INFINITY;
    mpfr_inits2(ref_bits, d, f, (mpfr_ptr)0);
    fl = prec < 53 ? (double)mpfr_get_flt(exact, RND) : mpfr_get_d(exact, RND);
    mpfr_set_d(d, got, RND), mpfr_sub(d, d, exact, RND), mpfr_abs(d, d, RND);
    if (forgive && fabs(fl) < ldexp(1.0, emin)) {
        mpfr_set_d(f, fl, RND), mpfr_sub(f, f, exact, RND), mpfr_abs(f, f, RND);
        mpfr_sub(d, d, f, RND);
        if (mpfr_sgn(d) < 0) mpfr_set_zero(d, 1);
    }
    mpfr_mul_d(d, d, weight, RND);
    mpfr_div(d, d, ulp, RND);
    r = mpfr_get_d(d, MPFR_RNDU);
    mpfr_clears(d, f, (mpfr_ptr)0);
    return r;
}

/* Worst error of one ball's outputs; with radius 0 the spins must be kept
 * bit for bit. */
static double ball_err(const ref_ball *d, const mball *o, const double *got, const mpfr_t ulp, int prec, int emin)
{
    double worst = 0;
    int i;
    for (i = 0; i < 2; i++) worst = fmax(worst, err_in(got[i], o->v[i], 1, 0, ulp, prec, emin));
    for (i = 0; i < 3; i++)
        worst = fmax(worst, d->r == 0 ? (got[2 + i] == d->w[i] ? 0 : INFINITY)
                                      : err_in(got[2 + i], o->w[i], d->r, 1, ulp, prec, emin));
    return worst;
}

/* The range flags from one ball's exact outputs. */
static void range_of(const mball *o, double limit, ref_sphere_verdict *v)
{
    int i;
    for (i = 0; i < 5; i++) {
        mpfr_srcptr x = i < 2 ? o->v[i] : o->w[i - 2];
        if (fabs(mpfr_get_d(x, RND)) >= limit / 8) v->range_allowed = 1;
        if (fabs(mpfr_get_d(x, RND)) > limit) v->range_required = 1;
    }
}

/* out = x + k y */
static void add_mul(mpfr_t out, mpfr_t x, mpfr_t y, mpfr_t k, mpfr_t tmp)
{
    mpfr_mul(tmp, y, k, RND);
    mpfr_add(out, x, tmp, RND);
}

void ref_balls(const ref_balls_case *c, const double got[10], int prec, int emin, double limit, ref_sphere_verdict *v)
{
    mpfr_t nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam, f, jt, jz, k, s, u;
    mball oa, ob;
    int i;
    v->status = C2D_INVALID, v->range_allowed = v->range_required = 0, v->err_ulp = 0;
    if (!ball_valid(&c->a) || !ball_valid(&c->b) || !(c->e >= 0 && c->e <= 1) || !(c->mu >= 0) ||
        !(isfinite(c->boost) && c->boost >= 0) || !(isfinite(c->decay) && c->decay >= 0))
        return;
    {
        const double x[4] = {c->e, c->mu, c->boost, c->decay};
        int lo = 0, hi = 0;
        ball_spread(&c->a, &lo, &hi), ball_spread(&c->b, &lo, &hi), spread_of(x, 4, &lo, &hi);
        set_bits(lo, hi);
    }
    v->status = C2D_DEGENERATE;
    if ((isinf(c->a.m) && isinf(c->b.m)) || (c->a.pos[0] == c->b.pos[0] && c->a.pos[1] == c->b.pos[1])) return;
    mpfr_inits2(ref_bits, nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam,
                f, jt, jz, k, s, u, (mpfr_ptr)0);
    mpfr_set_d(nx, c->b.pos[0], RND), mpfr_sub_d(nx, nx, c->a.pos[0], RND);
    mpfr_set_d(ny, c->b.pos[1], RND), mpfr_sub_d(ny, ny, c->a.pos[1], RND);
    mpfr_set_d(dvx, c->b.vel[0], RND), mpfr_sub_d(dvx, dvx, c->a.vel[0], RND);
    mpfr_set_d(dvy, c->b.vel[1], RND), mpfr_sub_d(dvy, dvy, c->a.vel[1], RND);
    /* the approach's sign from dv.(pb - pa), exact at this precision */
    mpfr_mul(gn, dvx, nx, RND), mpfr_mul(t1, dvy, ny, RND), mpfr_add(gn, gn, t1, RND);
    v->status = mpfr_sgn(gn) < 0 ? C2D_OK : C2D_SEPARATING;
    mball_init(&oa, &c->a), mball_init(&ob, &c->b);
    mpfr_hypot(len, nx, ny, RND);
    mpfr_div(nx, nx, len, RND), mpfr_div(ny, ny, len, RND);
    inv(ima, c->a.m), inv(imb, c->b.m);
    mpfr_add(imn, ima, imb, RND);
    mpfr_mul(gn, dvx, nx, RND), mpfr_mul(t1, dvy, ny, RND), mpfr_add(gn, gn, t1, RND);
    /* Jn = -(1 + e) gn / imn; the normal result (c2d_collide's) and its range */
    mpfr_set_d(t1, c->e, RND), mpfr_add_ui(t1, t1, 1, RND);
    mpfr_mul(jn, t1, gn, RND), mpfr_neg(jn, jn, RND), mpfr_div(jn, jn, imn, RND);
    if (v->status == C2D_OK) {
        mball *o[2] = {&oa, &ob};
        mpfr_ptr im[2] = {ima, imb}, nn[2] = {nx, ny};
        for (i = 0; i < 2; i++) {
            int j;
            for (j = 0; j < 2; j++) {
                mpfr_mul(k, jn, im[i], RND), mpfr_mul(k, k, nn[j], RND);
                if (i == 0) mpfr_neg(k, k, RND);
                if (fabs(mpfr_get_d(k, RND)) >= limit / 8) v->range_allowed = 1;
                mpfr_add(o[i]->v[j], o[i]->v[j], k, RND);
            }
        }
        range_of(&oa, limit, v), range_of(&ob, limit, v);
        if (v->range_required) v->status = C2D_RANGE;
    }
    if (v->status != C2D_OK) {
        mball_clear(&oa), mball_clear(&ob);
        mpfr_clears(nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam, f, jt, jz, k,
                    s, u, (mpfr_ptr)0);
        return;
    }
    if (c->mu != 0 || c->boost != 0) {
        /* gt = dv.t - (Ra wza + Rb wzb), gz = -(Ra (wxa ny - wya nx) + Rb (wxb ny - wyb nx)) */
        mpfr_mul(gt, dvy, nx, RND), mpfr_mul(t1, dvx, ny, RND), mpfr_sub(gt, gt, t1, RND);
        mpfr_set_d(t1, c->a.r, RND), mpfr_mul_d(t1, t1, c->a.w[2], RND), mpfr_sub(gt, gt, t1, RND);
        mpfr_set_d(t1, c->b.r, RND), mpfr_mul_d(t1, t1, c->b.w[2], RND), mpfr_sub(gt, gt, t1, RND);
        mpfr_mul_d(t1, ny, c->a.w[0], RND), mpfr_mul_d(t2, nx, c->a.w[1], RND), mpfr_sub(t1, t1, t2, RND);
        mpfr_mul_d(gz, t1, -c->a.r, RND);
        mpfr_mul_d(t1, ny, c->b.w[0], RND), mpfr_mul_d(t2, nx, c->b.w[1], RND), mpfr_sub(t1, t1, t2, RND);
        mpfr_mul_d(t1, t1, -c->b.r, RND), mpfr_add(gz, gz, t1, RND);
        mpfr_hypot(g, gt, gz, RND);
        inv(qa, c->a.inertia), mpfr_mul_d(qa, qa, c->a.r, RND);
        inv(qb, c->b.inertia), mpfr_mul_d(qb, qb, c->b.r, RND);
        mpfr_mul_d(t1, qa, c->a.r, RND), mpfr_add(imt, imn, t1, RND);
        mpfr_mul_d(t1, qb, c->b.r, RND), mpfr_add(imt, imt, t1, RND);
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
        {
            mball *o[2] = {&oa, &ob};
            mpfr_ptr im[2] = {ima, imb}, q[2] = {qa, qb};
            for (i = 0; i < 2; i++) {
                int sg = i == 0 ? -1 : 1;
                /* va -= Jt t / ma, vb += Jt t / mb, t = (-ny, nx), on top of the normal result */
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
    }
    range_of(&oa, limit, v), range_of(&ob, limit, v);
    mpfr_set_zero(s, 1);
    scale_of(s, &c->a, &oa), scale_of(s, &c->b, &ob);
    ulp_of(u, s, prec, emin);
    v->err_ulp = fmax(ball_err(&c->a, &oa, got, u, prec, emin), ball_err(&c->b, &ob, got + 5, u, prec, emin));
    if (v->range_required) v->status = C2D_RANGE;
    mball_clear(&oa), mball_clear(&ob);
    mpfr_clears(nx, ny, len, dvx, dvy, gn, gt, gz, g, t1, t2, ima, imb, qa, qb, imn, imt, jn, mu, lam, f, jt, jz, k, s,
                u, (mpfr_ptr)0);
}

void ref_cushion(const ref_cushion_case *c, const double got[5], int prec, int emin, double limit,
                 ref_sphere_verdict *v)
{
    mpfr_t nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn, dvt, dwn, dwt;
    mball o;
    const ref_ball *d = &c->a;
    v->status = C2D_INVALID, v->range_allowed = v->range_required = 0, v->err_ulp = 0;
    if (!ball_valid(d) || !isfinite(d->m) || !(d->r > 0) || !isfinite(c->n[0]) || !isfinite(c->n[1]) ||
        !(c->h >= d->r && c->h <= 2 * d->r) || !(c->e >= 0 && c->e <= 1) || !(c->mu >= 0))
        return;
    v->status = C2D_DEGENERATE;
    if (c->n[0] == 0 && c->n[1] == 0) return;
    {
        const double x[5] = {c->n[0], c->n[1], c->h, c->e, c->mu};
        int lo = 0, hi = 0;
        ball_spread(d, &lo, &hi), spread_of(x, 5, &lo, &hi);
        set_bits(lo, hi);
    }
    mpfr_inits2(ref_bits, nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn,
                dvt, dwn, dwt, (mpfr_ptr)0);
    mpfr_set_d(nx, c->n[0], RND), mpfr_set_d(ny, c->n[1], RND), mpfr_hypot(len, nx, ny, RND);
    mpfr_div(nx, nx, len, RND), mpfr_div(ny, ny, len, RND);
    mpfr_set_d(sn, c->h, RND), mpfr_sub_d(sn, sn, d->r, RND), mpfr_div_d(sn, sn, d->r, RND);
    mpfr_sqr(cs, sn, RND), mpfr_ui_sub(cs, 1, cs, RND), mpfr_sqrt(cs, cs, RND);
    /* the approach's sign from the exact v.n (no rounding of n^) */
    mpfr_set_d(t1, c->n[0], RND), mpfr_mul_d(t1, t1, d->vel[0], RND);
    mpfr_set_d(t2, c->n[1], RND), mpfr_mul_d(t2, t2, d->vel[1], RND), mpfr_add(t1, t1, t2, RND);
    if (mpfr_sgn(t1) <= 0 || c->h == 2 * d->r) {
        v->status = C2D_SEPARATING;
        mpfr_clears(nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn, dvt, dwn, dwt,
                    (mpfr_ptr)0);
        return;
    }
    v->status = C2D_OK;
    mpfr_mul_d(vn, nx, d->vel[0], RND), mpfr_mul_d(t1, ny, d->vel[1], RND), mpfr_add(vn, vn, t1, RND);
    mpfr_mul(t1, vn, cs, RND);
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
    range_of(&o, limit, v);
    mpfr_set_zero(t1, 1);
    scale_of(t1, d, &o);
    ulp_of(t2, t1, prec, emin);
    v->err_ulp = ball_err(d, &o, got, t2, prec, emin);
    if (v->range_required) v->status = C2D_RANGE;
    mball_clear(&o);
    mpfr_clears(nx, ny, len, sn, cs, vn, vt, wn, wt, pn, s1, s2, sl, a, lam, f, f1, f2, q, t1, t2, dvn, dvt, dwn, dwt,
                (mpfr_ptr)0);
}

double ref_exp_neg_err(double x, double got, int prec)
{
    mpfr_t r, d;
    double err;
    int ex;
    mpfr_inits2(512, r, d, (mpfr_ptr)0);
    mpfr_set_d(r, -x, RND), mpfr_exp(r, r, RND);
    mpfr_d_sub(d, got, r, RND);
    (void)frexp(mpfr_get_d(r, MPFR_RNDZ), &ex);
    err = fabs(mpfr_get_d(d, RND)) /
          (mpfr_get_d(r, MPFR_RNDZ) == 0 ? ldexp(1.0, prec == 24 ? -149 : -1074) : ldexp(1.0, ex - prec));
    mpfr_clears(r, d, (mpfr_ptr)0);
    return err;
}
