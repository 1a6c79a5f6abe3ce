/* SPDX-License-Identifier: MIT */
/* ref_toi_accel.c - see ref_toi_accel.h. */
#include "ref_toi_accel.h"

#include <gmp.h>
#include <math.h>
#include <stdlib.h>

#define RDEG 8 /* degree of f g is at most 7 */
#define PREC 1024

/* ------------------------------------------------------------ polynomials over Q */

typedef struct rp {
    int deg; /* -1: zero polynomial */
    mpq_t c[RDEG + 1];
    int zok;             /* z holds a positive integer multiple of the polynomial */
    mpz_t z[RDEG + 1];
} rp;

static void rp_init(rp *p)
{
    int i;
    for (i = 0; i <= RDEG; i++) {
        mpq_init(p->c[i]);
        mpz_init(p->z[i]);
    }
    p->deg = -1;
    p->zok = 0;
}

static void rp_clear(rp *p)
{
    int i;
    for (i = 0; i <= RDEG; i++) {
        mpq_clear(p->c[i]);
        mpz_clear(p->z[i]);
    }
}

/* integer mirror: the coefficients times the lcm of their denominators,
 * divided by their content (a positive multiple: signs are unchanged) */
static void rp_finalize(rp *p)
{
    mpz_t l, g, t;
    int i;
    mpz_inits(l, g, t, NULL);
    mpz_set_ui(l, 1);
    for (i = 0; i <= p->deg; i++) mpz_lcm(l, l, mpq_denref(p->c[i]));
    mpz_set_ui(g, 0);
    for (i = 0; i <= p->deg; i++) {
        mpz_divexact(t, l, mpq_denref(p->c[i]));
        mpz_mul(p->z[i], mpq_numref(p->c[i]), t);
        mpz_gcd(g, g, p->z[i]);
    }
    if (mpz_sgn(g) != 0)
        for (i = 0; i <= p->deg; i++) mpz_divexact(p->z[i], p->z[i], g);
    p->zok = 1;
    mpz_clears(l, g, t, NULL);
}

static void rp_norm(rp *p)
{
    while (p->deg >= 0 && mpq_sgn(p->c[p->deg]) == 0) p->deg--;
}

static void rp_copy(rp *d, const rp *s)
{
    int i;
    for (i = 0; i <= RDEG; i++) {
        if (i <= s->deg) mpq_set(d->c[i], s->c[i]);
        else mpq_set_ui(d->c[i], 0, 1);
    }
    d->deg = s->deg;
    d->zok = 0;
}

static void rp_eval(mpq_t out, const rp *p, const mpq_t x)
{
    int i;
    mpq_set_ui(out, 0, 1);
    for (i = p->deg; i >= 0; i--) {
        mpq_mul(out, out, x);
        mpq_add(out, out, p->c[i]);
    }
}

/* sign of p at x; with the integer mirror and a dyadic x = m / 2^k, by
 * Horner over the integers: p(x) 2^(k deg) = sum z_i m^i 2^(k (deg - i)) */
static int rp_sign_at(const rp *p, const mpq_t x)
{
    mpq_t v;
    int s;
    if (p->deg < 0) return 0;
    if (p->zok && mpz_popcount(mpq_denref(x)) == 1) {
        mp_bitcnt_t k = mpz_scan1(mpq_denref(x), 0);
        mpz_t acc, t;
        int i;
        mpz_inits(acc, t, NULL);
        mpz_set(acc, p->z[p->deg]);
        for (i = p->deg - 1; i >= 0; i--) {
            mpz_mul(acc, acc, mpq_numref(x));
            mpz_mul_2exp(t, p->z[i], k * (mp_bitcnt_t)(p->deg - i));
            mpz_add(acc, acc, t);
        }
        s = mpz_sgn(acc);
        mpz_clears(acc, t, NULL);
        return s;
    }
    mpq_init(v);
    rp_eval(v, p, x);
    s = mpq_sgn(v);
    mpq_clear(v);
    return s;
}

static void rp_deriv(rp *d, const rp *s)
{
    int i;
    rp t;
    rp_init(&t);
    for (i = 1; i <= s->deg; i++) {
        mpq_set_ui(t.c[i - 1], (unsigned long)i, 1);
        mpq_mul(t.c[i - 1], t.c[i - 1], s->c[i]);
    }
    t.deg = s->deg - 1;
    if (t.deg < -1) t.deg = -1;
    rp_norm(&t);
    rp_copy(d, &t);
    rp_clear(&t);
}

static void rp_mul(rp *d, const rp *a, const rp *b)
{
    int i, j;
    rp t;
    mpq_t x;
    rp_init(&t);
    mpq_init(x);
    if (a->deg < 0 || b->deg < 0) {
        t.deg = -1;
    } else {
        for (i = 0; i <= a->deg; i++)
            for (j = 0; j <= b->deg; j++) {
                mpq_mul(x, a->c[i], b->c[j]);
                mpq_add(t.c[i + j], t.c[i + j], x);
            }
        t.deg = a->deg + b->deg;
        rp_norm(&t);
    }
    rp_copy(d, &t);
    rp_clear(&t);
    mpq_clear(x);
}

/* a = q b + r; q and/or r may be NULL. */
static void rp_divmod(rp *q, rp *r, const rp *a, const rp *b)
{
    rp rr, qq;
    mpq_t x;
    int i;
    rp_init(&rr);
    rp_init(&qq);
    mpq_init(x);
    rp_copy(&rr, a);
    qq.deg = a->deg - b->deg;
    if (qq.deg < 0) qq.deg = -1;
    while (rr.deg >= b->deg && rr.deg >= 0) {
        int k = rr.deg - b->deg;
        mpq_div(x, rr.c[rr.deg], b->c[b->deg]);
        mpq_set(qq.c[k], x);
        for (i = 0; i <= b->deg; i++) {
            mpq_t y;
            mpq_init(y);
            mpq_mul(y, x, b->c[i]);
            mpq_sub(rr.c[i + k], rr.c[i + k], y);
            mpq_clear(y);
        }
        mpq_set_ui(rr.c[rr.deg], 0, 1);
        rp_norm(&rr);
    }
    rp_norm(&qq);
    if (q != NULL) rp_copy(q, &qq);
    if (r != NULL) rp_copy(r, &rr);
    rp_clear(&rr);
    rp_clear(&qq);
    mpq_clear(x);
}

static void rp_gcd(rp *g, const rp *a, const rp *b)
{
    rp x, y, r;
    int i;
    rp_init(&x);
    rp_init(&y);
    rp_init(&r);
    rp_copy(&x, a);
    rp_copy(&y, b);
    while (y.deg >= 0) {
        rp_divmod(NULL, &r, &x, &y);
        rp_copy(&x, &y);
        rp_copy(&y, &r);
    }
    if (x.deg >= 0) { /* monic */
        mpq_t lead;
        mpq_init(lead);
        mpq_set(lead, x.c[x.deg]);
        for (i = 0; i <= x.deg; i++) mpq_div(x.c[i], x.c[i], lead);
        mpq_clear(lead);
    }
    rp_copy(g, &x);
    rp_clear(&x);
    rp_clear(&y);
    rp_clear(&r);
}

/* square-free part p / gcd(p, p') */
static void rp_sqfree(rp *s, const rp *p)
{
    rp d, g;
    rp_init(&d);
    rp_init(&g);
    rp_deriv(&d, p);
    if (d.deg < 0) {
        rp_copy(s, p);
    } else {
        rp_gcd(&g, p, &d);
        rp_divmod(s, NULL, p, &g);
    }
    rp_clear(&d);
    rp_clear(&g);
}

/* ------------------------------------------------------------ Sturm sequences */

typedef struct sturm {
    int n;
    rp s[RDEG + 2];
} sturm;

static void sturm_build(sturm *st, const rp *p)
{
    int i;
    for (i = 0; i < RDEG + 2; i++) rp_init(&st->s[i]);
    rp_copy(&st->s[0], p);
    rp_deriv(&st->s[1], p);
    st->n = 2;
    if (st->s[1].deg < 0) {
        st->n = 1;
        return;
    }
    while (st->n < RDEG + 2) {
        rp *r = &st->s[st->n];
        rp_divmod(NULL, r, &st->s[st->n - 2], &st->s[st->n - 1]);
        if (r->deg < 0) break;
        for (i = 0; i <= r->deg; i++) mpq_neg(r->c[i], r->c[i]);
        st->n++;
    }
    for (i = 0; i < st->n; i++) rp_finalize(&st->s[i]);
}

static void sturm_free(sturm *st)
{
    int i;
    for (i = 0; i < RDEG + 2; i++) rp_clear(&st->s[i]);
}

static int sturm_var(const sturm *st, const mpq_t x)
{
    int i, last = 0, v = 0;
    for (i = 0; i < st->n; i++) {
        int s = rp_sign_at(&st->s[i], x);
        if (s == 0) continue;
        if (last != 0 && s != last) v++;
        last = s;
    }
    return v;
}

/* ------------------------------------------------------------ root isolation */

#define MAXROOTS 16

typedef struct rroot {
    mpq_t lo, hi; /* the root is in (lo, hi), or equals lo == hi when exact */
    int exact;
} rroot;

typedef struct rlist {
    int n;
    rroot r[MAXROOTS];
} rlist;

static void rlist_init(rlist *l)
{
    int i;
    l->n = 0;
    for (i = 0; i < MAXROOTS; i++) {
        mpq_init(l->r[i].lo);
        mpq_init(l->r[i].hi);
        l->r[i].exact = 0;
    }
}

static void rlist_clear(rlist *l)
{
    int i;
    for (i = 0; i < MAXROOTS; i++) {
        mpq_clear(l->r[i].lo);
        mpq_clear(l->r[i].hi);
    }
}

/* a dyadic point strictly inside (a, b), 0 <= a < b: the arithmetic
 * midpoint, or a geometric one when the interval spans binades (so
 * isolation over 2^-1100 .. 2^3000 takes a few dozen steps, not thousands) */
static void midpoint(mpq_t m, const mpq_t a, const mpq_t b)
{
    if (mpq_sgn(a) > 0) {
        mpq_t q;
        mpq_init(q);
        mpq_div(q, b, a);
        if (mpq_cmp_ui(q, 16, 1) > 0) {
            long ea, eb, em;
            /* exponents via sizes of numerator and denominator */
            ea = (long)mpz_sizeinbase(mpq_numref(a), 2) - (long)mpz_sizeinbase(mpq_denref(a), 2);
            eb = (long)mpz_sizeinbase(mpq_numref(b), 2) - (long)mpz_sizeinbase(mpq_denref(b), 2);
            em = (ea + eb) / 2;
            mpq_set_ui(m, 1, 1);
            if (em >= 0) mpq_mul_2exp(m, m, (mp_bitcnt_t)em);
            else mpq_div_2exp(m, m, (mp_bitcnt_t)(-em));
            mpq_clear(q);
            if (mpq_cmp(m, a) > 0 && mpq_cmp(m, b) < 0) return;
        } else {
            mpq_clear(q);
        }
    } else if (mpq_sgn(a) == 0) {
        mpq_div_2exp(m, b, 64);
        return;
    }
    mpq_add(m, a, b);
    mpq_div_2exp(m, m, 1);
}

/* roots of the square-free p in (a, b], by Sturm */
static int count_roots(const sturm *st, const mpq_t a, const mpq_t b) { return sturm_var(st, a) - sturm_var(st, b); }

/* isolate the roots of square-free p in the open interval (a, b), in order */
static void isolate(const rp *p, const sturm *st, const mpq_t a, const mpq_t b, rlist *out)
{
    int n = count_roots(st, a, b) - (rp_sign_at(p, b) == 0 ? 1 : 0);
    mpq_t m;
    if (n <= 0) return;
    if (n == 1 && rp_sign_at(p, a) != 0 && rp_sign_at(p, b) != 0) {
        if (out->n < MAXROOTS) {
            mpq_set(out->r[out->n].lo, a);
            mpq_set(out->r[out->n].hi, b);
            out->r[out->n].exact = 0;
            out->n++;
        }
        return;
    }
    mpq_init(m);
    midpoint(m, a, b);
    isolate(p, st, a, m, out);
    if (rp_sign_at(p, m) == 0 && out->n < MAXROOTS) {
        mpq_set(out->r[out->n].lo, m);
        mpq_set(out->r[out->n].hi, m);
        out->r[out->n].exact = 1;
        out->n++;
    }
    isolate(p, st, m, b, out);
    mpq_clear(m);
}

/* one bisection step of an inexact root's interval (p square-free, its only
 * root there; endpoints non-roots) */
static void refine_step(const rp *p, rroot *r)
{
    mpq_t m;
    int sm, sl;
    if (r->exact) return;
    mpq_init(m);
    midpoint(m, r->lo, r->hi);
    sm = rp_sign_at(p, m);
    sl = rp_sign_at(p, r->lo);
    if (sm == 0) {
        mpq_set(r->lo, m);
        mpq_set(r->hi, m);
        r->exact = 1;
    } else if (sm == sl) {
        mpq_set(r->lo, m);
    } else {
        mpq_set(r->hi, m);
    }
    mpq_clear(m);
}

/* refine until the width is below 2^-bits relative to |hi| (or exact) */
static void refine(const rp *p, rroot *r, int bits)
{
    mpq_t w, s;
    mpq_init(w);
    mpq_init(s);
    while (!r->exact) {
        mpq_sub(w, r->hi, r->lo);
        mpq_abs(s, r->hi);
        mpq_div_2exp(s, s, (unsigned long)bits);
        if (mpq_cmp(w, s) <= 0) break;
        refine_step(p, r);
    }
    mpq_clear(w);
    mpq_clear(s);
}

/* ------------------------------------------------------------ the problem */

typedef struct prob {
    mpq_t p[2], v[2], a[2], r;
    rp f, g, h;
} prob;

static void prob_init(prob *P, const ref_toia_in *in)
{
    int i;
    mpq_t t, u;
    mpq_inits(t, u, NULL);
    for (i = 0; i < 2; i++) {
        mpq_inits(P->p[i], P->v[i], P->a[i], NULL);
        mpq_set_d(P->p[i], in->pb[i]);
        mpq_set_d(t, in->pa[i]);
        mpq_sub(P->p[i], P->p[i], t);
        mpq_set_d(P->v[i], in->vb[i]);
        mpq_set_d(t, in->va[i]);
        mpq_sub(P->v[i], P->v[i], t);
        mpq_set_d(P->a[i], in->ab[i]);
        mpq_set_d(t, in->aa[i]);
        mpq_sub(P->a[i], P->a[i], t);
    }
    mpq_init(P->r);
    mpq_set_d(P->r, in->r);
    rp_init(&P->f);
    rp_init(&P->g);
    rp_init(&P->h);
    /* f = |p|^2 - R^2 + 2 p.v t + (|v|^2 + p.a) t^2 + v.a t^3 + |a|^2/4 t^4 */
    for (i = 0; i < 2; i++) {
        mpq_mul(t, P->p[i], P->p[i]);
        mpq_add(P->f.c[0], P->f.c[0], t);
        mpq_mul(t, P->p[i], P->v[i]);
        mpq_mul_2exp(t, t, 1);
        mpq_add(P->f.c[1], P->f.c[1], t);
        mpq_mul(t, P->v[i], P->v[i]);
        mpq_mul(u, P->p[i], P->a[i]);
        mpq_add(t, t, u);
        mpq_add(P->f.c[2], P->f.c[2], t);
        mpq_mul(t, P->v[i], P->a[i]);
        mpq_add(P->f.c[3], P->f.c[3], t);
        mpq_mul(t, P->a[i], P->a[i]);
        mpq_div_2exp(t, t, 2);
        mpq_add(P->f.c[4], P->f.c[4], t);
    }
    mpq_mul(t, P->r, P->r);
    mpq_sub(P->f.c[0], P->f.c[0], t);
    P->f.deg = 4;
    rp_norm(&P->f);
    rp_deriv(&P->g, &P->f);
    for (i = 0; i <= P->g.deg; i++) mpq_div_2exp(P->g.c[i], P->g.c[i], 1);
    rp_deriv(&P->h, &P->g);
    rp_finalize(&P->f);
    rp_finalize(&P->g);
    rp_finalize(&P->h);
    mpq_clears(t, u, NULL);
}

static void prob_clear(prob *P)
{
    int i;
    for (i = 0; i < 2; i++) mpq_clears(P->p[i], P->v[i], P->a[i], NULL);
    mpq_clear(P->r);
    rp_clear(&P->f);
    rp_clear(&P->g);
    rp_clear(&P->h);
}

/* sign of polynomial q just after x: first nonzero derivative */
static int sign_after(const rp *q, const mpq_t x)
{
    rp d;
    int s = 0, k;
    rp_init(&d);
    rp_copy(&d, q);
    for (k = 0; k <= RDEG && d.deg >= 0; k++) {
        s = rp_sign_at(&d, x);
        if (s != 0) break;
        rp_deriv(&d, &d);
    }
    rp_clear(&d);
    return s;
}

/* MPFR: d(t), d'(t), |d|, |d'|, f, g, h at t */
typedef struct mstate {
    mpfr_t d[2], d1[2], nd, nd1, f, g, h, na;
} mstate;

static void ms_init(mstate *m)
{
    int i;
    for (i = 0; i < 2; i++) mpfr_inits2(PREC, m->d[i], m->d1[i], (mpfr_ptr)0);
    mpfr_inits2(PREC, m->nd, m->nd1, m->f, m->g, m->h, m->na, (mpfr_ptr)0);
}

static void ms_clear(mstate *m)
{
    int i;
    for (i = 0; i < 2; i++) mpfr_clears(m->d[i], m->d1[i], (mpfr_ptr)0);
    mpfr_clears(m->nd, m->nd1, m->f, m->g, m->h, m->na, (mpfr_ptr)0);
}

static void ms_eval(mstate *m, const prob *P, const mpfr_t t)
{
    int i;
    mpfr_t x, y;
    mpfr_inits2(PREC, x, y, (mpfr_ptr)0);
    mpfr_set_ui(m->nd, 0, MPFR_RNDN);
    mpfr_set_ui(m->nd1, 0, MPFR_RNDN);
    mpfr_set_ui(m->g, 0, MPFR_RNDN);
    mpfr_set_ui(m->h, 0, MPFR_RNDN);
    mpfr_set_ui(m->na, 0, MPFR_RNDN);
    for (i = 0; i < 2; i++) {
        /* d = p + t (v + a t / 2), d' = v + a t */
        mpfr_set_q(x, P->a[i], MPFR_RNDN);
        mpfr_mul(y, x, t, MPFR_RNDN);
        mpfr_set_q(x, P->v[i], MPFR_RNDN);
        mpfr_add(m->d1[i], x, y, MPFR_RNDN);
        mpfr_div_2ui(y, y, 1, MPFR_RNDN);
        mpfr_add(y, y, x, MPFR_RNDN);
        mpfr_mul(y, y, t, MPFR_RNDN);
        mpfr_set_q(x, P->p[i], MPFR_RNDN);
        mpfr_add(m->d[i], x, y, MPFR_RNDN);
        mpfr_sqr(x, m->d[i], MPFR_RNDN);
        mpfr_add(m->nd, m->nd, x, MPFR_RNDN);
        mpfr_sqr(x, m->d1[i], MPFR_RNDN);
        mpfr_add(m->nd1, m->nd1, x, MPFR_RNDN);
        mpfr_mul(x, m->d[i], m->d1[i], MPFR_RNDN);
        mpfr_add(m->g, m->g, x, MPFR_RNDN);
        mpfr_set_q(y, P->a[i], MPFR_RNDN);
        mpfr_mul(x, m->d[i], y, MPFR_RNDN);
        mpfr_add(m->h, m->h, x, MPFR_RNDN);
        mpfr_sqr(y, y, MPFR_RNDN);
        mpfr_add(m->na, m->na, y, MPFR_RNDN);
    }
    mpfr_add(m->h, m->h, m->nd1, MPFR_RNDN); /* h = |d'|^2 + d.a */
    mpfr_set_q(x, P->r, MPFR_RNDN);
    mpfr_sqr(x, x, MPFR_RNDN);
    mpfr_sub(m->f, m->nd, x, MPFR_RNDN);
    mpfr_sqrt(m->nd, m->nd, MPFR_RNDN);
    mpfr_sqrt(m->nd1, m->nd1, MPFR_RNDN);
    mpfr_sqrt(m->na, m->na, MPFR_RNDN);
    mpfr_clears(x, y, (mpfr_ptr)0);
}

static double ulp_of(double x, int prec, int emin)
{
    int ex;
    x = fabs(x);
    if (!(x > 0) || x < ldexp(1.0, emin)) return ldexp(1.0, emin - prec + 1);
    (void)frexp(x, &ex);
    return ldexp(1.0, ex - 1 - (prec - 1));
}

static void root_to_mpfr(mpfr_t out, const rp *p, rroot *r)
{
    refine(p, r, 420);
    if (r->exact) {
        mpfr_set_q(out, r->lo, MPFR_RNDN);
    } else {
        mpq_t m;
        mpq_init(m);
        mpq_add(m, r->lo, r->hi);
        mpq_div_2exp(m, m, 1);
        mpfr_set_q(out, m, MPFR_RNDN);
        mpq_clear(m);
    }
}

/* make a rational strictly between roots x (left; NULL = the point left0)
 * and y (right; NULL = right0 or +inf when right0 is NULL) */
static void sample_between(mpq_t s, const rp *p, rroot *x, rroot *y, const mpq_t left0, const mpq_t right0)
{
    mpq_t L, U;
    mpq_inits(L, U, NULL);
    for (;;) {
        if (x != NULL) mpq_set(L, x->hi);
        else mpq_set(L, left0);
        if (y != NULL) {
            mpq_set(U, y->lo);
        } else if (right0 != NULL) {
            mpq_set(U, right0);
        } else {
            mpq_set_ui(s, 1, 1);
            mpq_add(s, s, L);
            break;
        }
        if (mpq_cmp(L, U) < 0) {
            mpq_add(s, L, U);
            mpq_div_2exp(s, s, 1);
            break;
        }
        /* L == U */
        if (x != NULL && y != NULL && !x->exact && !y->exact) { /* a shared non-root endpoint */
            mpq_set(s, L);
            break;
        }
        if (y != NULL && !y->exact) {
            refine_step(p, y);
        } else if (x != NULL && !x->exact) {
            refine_step(p, x);
        } else {
            mpq_set(s, L);
            break;
        }
    }
    mpq_clears(L, U, NULL);
}

void ref_toia_init(ref_toia_out *o)
{
    mpfr_init2(o->t, PREC);
    o->status = C2D_INVALID;
}

void ref_toia_clear(ref_toia_out *o) { mpfr_clear(o->t); }

static int finite_in(const ref_toia_in *in)
{
    int i;
    for (i = 0; i < 2; i++)
        if (!isfinite(in->pa[i]) || !isfinite(in->pb[i]) || !isfinite(in->va[i]) || !isfinite(in->vb[i]) ||
            !isfinite(in->aa[i]) || !isfinite(in->ab[i]))
            return 0;
    return 1;
}

static double rel_tie_f(const mstate *m, const prob *P)
{
    mpfr_t x, y;
    double r;
    mpfr_inits2(PREC, x, y, (mpfr_ptr)0);
    mpfr_set_q(y, P->r, MPFR_RNDN);
    mpfr_sqr(y, y, MPFR_RNDN);
    mpfr_sqr(x, m->nd, MPFR_RNDN);
    mpfr_add(x, x, y, MPFR_RNDN);
    mpfr_abs(y, m->f, MPFR_RNDN);
    mpfr_div(x, y, x, MPFR_RNDN);
    r = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clears(x, y, (mpfr_ptr)0);
    return r;
}

static double rel_tie_g(const mstate *m)
{
    mpfr_t x;
    double r;
    mpfr_init2(x, PREC);
    mpfr_mul(x, m->nd, m->nd1, MPFR_RNDN);
    if (mpfr_zero_p(x)) {
        mpfr_clear(x);
        return 0;
    }
    mpfr_div(x, m->g, x, MPFR_RNDN);
    mpfr_abs(x, x, MPFR_RNDN);
    r = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    return r;
}

/* |f| / ((|d'|^2 + |d||a|) (2^-2p t)^2) (which 0) or |g| / (3|d'.a| (2^-2p t)^2) (1) */
static double res_tie(const mstate *m, const mpfr_t t, int prec, int which)
{
    mpfr_t x, y;
    double r;
    mpfr_inits2(PREC, x, y, (mpfr_ptr)0);
    mpfr_mul_2si(y, t, -2 * prec, MPFR_RNDN);
    mpfr_sqr(y, y, MPFR_RNDN);
    if (which == 0) {
        mpfr_sqr(x, m->nd1, MPFR_RNDN);
        mpfr_fma(x, m->nd, m->na, x, MPFR_RNDN);
        mpfr_mul(x, x, y, MPFR_RNDN);
        mpfr_abs(y, m->f, MPFR_RNDN);
    } else {
        mpfr_mul(x, m->nd1, m->na, MPFR_RNDN); /* |h'| <= 3 |d'||a| */
        mpfr_mul_ui(x, x, 3, MPFR_RNDN);
        mpfr_mul(x, x, y, MPFR_RNDN);
        mpfr_abs(y, m->g, MPFR_RNDN);
    }
    if (mpfr_zero_p(x)) {
        mpfr_clears(x, y, (mpfr_ptr)0);
        return INFINITY;
    }
    mpfr_div(x, y, x, MPFR_RNDN);
    r = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clears(x, y, (mpfr_ptr)0);
    return r;
}

/* |h| <= 2^-60 (|d'|^2 + |d||a|): h has a near-double root here */
static int rel_h_small(const mstate *m)
{
    mpfr_t x, y;
    int r;
    mpfr_inits2(PREC, x, y, (mpfr_ptr)0);
    mpfr_sqr(x, m->nd1, MPFR_RNDN);
    mpfr_mul(y, m->nd, m->na, MPFR_RNDN);
    mpfr_add(x, x, y, MPFR_RNDN);
    mpfr_mul_2si(x, x, -60, MPFR_RNDN);
    mpfr_abs(y, m->h, MPFR_RNDN);
    r = mpfr_cmp(y, x) <= 0;
    mpfr_clears(x, y, (mpfr_ptr)0);
    return r;
}

/* Is f near zero or negative here (overlapping or nearly: g ties matter)? */
static int near_overlap(const mstate *m, const prob *P)
{
    return mpfr_sgn(m->f) <= 0 || rel_tie_f(m, P) < 1e-6;
}

void ref_toia(const ref_toia_in *in, int prec, int emin, ref_toia_out *o)
{
    prob P;
    rp fg, psf, gsf;
    sturm st;
    rlist roots;
    mpq_t zero, H, s, U, x;
    mpfr_t tm;
    mstate ms;
    int i, found = -1, hfin = isfinite(in->h), sf0, sg0;
    double fmax = prec == 24 ? 3.4028234663852886e38 : 1.7976931348623157e308;
    o->tie_f = INFINITY;
    o->tie_g = INFINITY;
    o->tie_fs = INFINITY;
    o->tie_gs = INFINITY;
    o->unit = 0;
    o->td = 0;
    mpfr_set_ui(o->t, 0, MPFR_RNDN);
    if (!finite_in(in) || !(in->r >= 0) || isinf(in->r) || !(in->h >= 0)) {
        o->status = C2D_INVALID;
        return;
    }
    prob_init(&P, in);
    mpq_inits(zero, H, s, U, x, NULL);
    mpfr_init2(tm, PREC);
    ms_init(&ms);
    rp_init(&fg);
    rp_init(&psf);
    rp_init(&gsf);
    rlist_init(&roots);
    if (P.g.deg < 0) { /* v = a = 0 */
        o->status = C2D_SEPARATING;
        goto done;
    }
    sf0 = rp_sign_at(&P.f, zero);
    sg0 = sign_after(&P.g, zero);
    if (sf0 <= 0 && sg0 < 0) {
        o->status = C2D_OK;
        o->kind = REF_TOIA_AT0;
        o->td = 0;
        o->unit = ulp_of(0, prec, emin);
        goto done;
    }
    if (in->h == 0) {
        o->status = C2D_SEPARATING;
        goto done;
    }
    /* the search interval (0, H) or (0, U), U a Cauchy bound of f g */
    rp_mul(&fg, &P.f, &P.g);
    rp_sqfree(&psf, &fg);
    rp_finalize(&psf);
    if (hfin) {
        mpq_set_d(H, in->h);
    } else {
        mpq_t m;
        mpq_init(m);
        mpq_set_ui(U, 0, 1);
        for (i = 0; i < psf.deg; i++) {
            mpq_div(m, psf.c[i], psf.c[psf.deg]);
            mpq_abs(m, m);
            if (mpq_cmp(m, U) > 0) mpq_set(U, m);
        }
        mpq_set_ui(m, 1, 1);
        mpq_add(U, U, m);
        /* round up to a power of two, so every bisection point is dyadic */
        {
            mpz_t q;
            size_t bits;
            mpz_init(q);
            mpz_cdiv_q(q, mpq_numref(U), mpq_denref(U));
            bits = mpz_sizeinbase(q, 2);
            mpz_set_ui(q, 1);
            mpz_mul_2exp(q, q, (mp_bitcnt_t)bits);
            mpq_set_z(U, q);
            mpz_clear(q);
        }
        mpq_set(H, U);
        mpq_clear(m);
    }
    sturm_build(&st, &psf);
    isolate(&psf, &st, zero, H, &roots);
    sturm_free(&st);
    /* intervals (0, r1), (r1, r2), ..., (rk, H): first with f < 0, g < 0 */
    for (i = 0; i <= roots.n; i++) {
        rroot *lft = i == 0 ? NULL : &roots.r[i - 1], *rgt = i == roots.n ? NULL : &roots.r[i];
        sample_between(s, &psf, lft, rgt, zero, hfin ? H : NULL);
        if (rp_sign_at(&P.f, s) < 0 && rp_sign_at(&P.g, s) < 0) {
            found = i;
            break;
        }
    }
    if (found == 0) { /* cannot happen: handled at t = 0 */
        o->status = C2D_OK;
        o->kind = REF_TOIA_AT0;
        o->unit = ulp_of(0, prec, emin);
        goto done;
    }
    if (found > 0) {
        rroot *r = &roots.r[found - 1];
        mpq_t sl;
        int fl;
        mpq_init(sl);
        root_to_mpfr(o->t, &psf, r);
        /* f's sign just before the root: from the previous interval */
        sample_between(sl, &psf, found >= 2 ? &roots.r[found - 2] : NULL, r, zero, NULL);
        fl = rp_sign_at(&P.f, sl);
        mpq_clear(sl);
        o->kind = fl > 0 ? REF_TOIA_CROSS : REF_TOIA_TURN;
        o->status = C2D_OK;
    } else if (hfin && rp_sign_at(&P.f, H) <= 0 && sign_after(&P.g, H) < 0) {
        mpfr_set_q(o->t, H, MPFR_RNDN);
        o->kind = REF_TOIA_AT_H;
        o->status = C2D_OK;
    } else {
        o->status = C2D_SEPARATING;
    }
    if (o->status == C2D_OK) {
        double t = mpfr_get_d(o->t, MPFR_RNDN);
        o->td = t;
        if (mpfr_cmp_d(o->t, fmax) > 0) o->status = C2D_RANGE;
        ms_eval(&ms, &P, o->t);
        if (o->kind == REF_TOIA_AT_H) {
            o->unit = ulp_of(t, prec, emin);
        } else {
            mpfr_t sp, y;
            mpfr_inits2(PREC, sp, y, (mpfr_ptr)0);
            /* approach speed s = -g / |d| */
            mpfr_div(sp, ms.g, ms.nd, MPFR_RNDN);
            mpfr_neg(sp, sp, MPFR_RNDN);
            mpfr_mul(y, ms.nd1, ms.nd, MPFR_RNDN);
            mpfr_mul_2si(y, y, -200, MPFR_RNDN);
            if (o->kind == REF_TOIA_CROSS && mpfr_cmp_abs(ms.g, y) > 0) {
                double sd = mpfr_get_d(sp, MPFR_RNDN), dd = mpfr_get_d(ms.nd, MPFR_RNDN);
                o->unit = ulp_of(t, prec, emin) + ulp_of(dd, prec, emin) / sd;
            } else {
                double dd = mpfr_get_d(ms.nd, MPFR_RNDN) * mpfr_get_d(ms.nd1, MPFR_RNDN);
                double hh = fabs(mpfr_get_d(ms.h, MPFR_RNDN));
                o->unit = ulp_of(t, prec, emin) + (hh > 0 ? ulp_of(dd, prec, emin) / hh : INFINITY);
            }
            mpfr_clears(sp, y, (mpfr_ptr)0);
        }
    }
    /* band diagnostics: minima of f (roots of g from - to +) and extrema of g
     * (roots of h) in (0, H), up to the end of the decreasing stretch that
     * holds the contact (its first minimum of f after t, or H) */
    {
        rlist gr;
        mpq_t lim;
        int k, hit = o->status == C2D_OK || o->status == C2D_RANGE;
        mpq_init(lim);
        mpq_set(lim, H);
        for (k = 0; k < 2; k++) {
            const rp *q = k == 0 ? &P.g : &P.h;
            rlist_init(&gr);
            if (q->deg >= 1) {
                rp_sqfree(&gsf, q);
                rp_finalize(&gsf);
                sturm_build(&st, &gsf);
                if (mpq_sgn(lim) > 0) isolate(&gsf, &st, zero, lim, &gr);
                sturm_free(&st);
            }
            for (i = 0; i < gr.n; i++) {
                int left, right;
                if (!gr.r[i].exact) {
                    left = rp_sign_at(q, gr.r[i].lo);
                    right = rp_sign_at(q, gr.r[i].hi);
                } else {
                    left = right = 0;
                }
                root_to_mpfr(tm, &gsf, &gr.r[i]);
                if (k == 1 && mpq_cmp(gr.r[i].lo, lim) >= 0) break;
                ms_eval(&ms, &P, tm);
                if (k == 0) {
                    /* minimum of f: g from - to + (or a multiple root) */
                    if (!(left > 0 && right < 0)) {
                        double tf = rel_tie_f(&ms, &P), ts = res_tie(&ms, tm, prec, 0);
                        if (tf < o->tie_f) o->tie_f = tf;
                        if (ts < o->tie_fs) o->tie_fs = ts;
                        if (hit && mpfr_cmp(tm, o->t) > 0) { /* the stretch's end */
                            mpq_set(lim, gr.r[i].hi);
                            break;
                        }
                    }
                } else if (near_overlap(&ms, &P)) {
                    double tg = rel_tie_g(&ms), ts = res_tie(&ms, tm, prec, 1);
                    if (tg < o->tie_g) o->tie_g = tg;
                    if (ts < o->tie_gs) o->tie_gs = ts;
                }
            }
            rlist_clear(&gr);
        }
        /* inflection of g (root of h' = 3 d'.a): a near-double root of h */
        if (P.h.deg == 2) {
            rp hp;
            rp_init(&hp);
            rp_deriv(&hp, &P.h);
            if (hp.deg == 1) {
                mpq_div(x, hp.c[0], hp.c[1]);
                mpq_neg(x, x);
                if (mpq_sgn(x) > 0 && mpq_cmp(x, lim) < 0) {
                    mpfr_set_q(tm, x, MPFR_RNDN);
                    ms_eval(&ms, &P, tm);
                    if (near_overlap(&ms, &P) && rel_h_small(&ms)) {
                        double tg = rel_tie_g(&ms);
                        if (tg < o->tie_g) o->tie_g = tg;
                    }
                }
            }
            rp_clear(&hp);
        }
        if (hfin && mpq_cmp(H, lim) <= 0) {
            mpfr_set_q(tm, H, MPFR_RNDN);
            ms_eval(&ms, &P, tm);
            if (mpfr_sgn(ms.g) <= 0 || rel_tie_g(&ms) < 1e-20) {
                double tf = rel_tie_f(&ms, &P);
                if (tf < o->tie_f) o->tie_f = tf;
            }
            if (near_overlap(&ms, &P)) {
                double tg = rel_tie_g(&ms);
                if (tg < o->tie_g) o->tie_g = tg;
            }
        }
        mpq_clear(lim);
    }
done:
    rlist_clear(&roots);
    rp_clear(&fg);
    rp_clear(&psf);
    rp_clear(&gsf);
    ms_clear(&ms);
    mpfr_clear(tm);
    mpq_clears(zero, H, s, U, x, NULL);
    prob_clear(&P);
}

double ref_toia_err(const ref_toia_out *o, double got)
{
    mpfr_t x;
    double r;
    if (!isfinite(got)) return INFINITY;
    mpfr_init2(x, PREC);
    mpfr_set_d(x, got, MPFR_RNDN);
    mpfr_sub(x, x, o->t, MPFR_RNDN);
    mpfr_abs(x, x, MPFR_RNDN);
    r = mpfr_get_d(x, MPFR_RNDN) / o->unit;
    mpfr_clear(x);
    return r;
}
