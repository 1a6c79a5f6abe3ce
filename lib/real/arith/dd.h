/* SPDX-License-Identifier: MIT */
/* real/arith/dd.h - template: double-length numbers with an extended exponent
 * ("dd"), for models whose results depend on differences that may cancel.
 * Needs real/arith/bits.h, real/arith/exact.h and real/arith/sign.h first.
 *
 * WHY
 *   The rough contact (real/rough.h) needs the slip speed at the contact,
 *   g_t = (vb - va).t^ - (wa ra + wb rb), which vanishes for rolling
 *   contact however fast the bodies move, and divides by |n| (a square
 *   root).  In working precision its error would be u times the bodies'
 *   speeds, ruinous for a light body whose own scale is small.  Carried as
 *   a double-length value (h + l) 2^e, every step keeps about 2p bits, so
 *   g_t is accurate to u |g_t| + O(u^2) of the speeds; the extended
 *   exponent means nothing over- or underflows until the final result is
 *   rounded to its body once.
 *
 * ARITHMETIC (u = 2^-(MANT+1); each operation's relative error is a small
 * multiple of u^2, the classical double-double bounds)
 *   add: TwoSum of the high parts and of the low parts, renormalised twice
 *        (an operand entirely below the other's low part is dropped).
 *   mul: TwoProduct of the high parts plus the cross terms.
 *   div: q1 = ah / bh, the remainder a - q1 b in double length, q2 = r / bh.
 *   sqrt: s = sqrt(h), one Newton correction (a - s^2) / 2s with s^2 exact.
 *   h is kept in [1, 2) (or 0) and |l| <= ulp(h) / 2.
 */
#ifndef C2D_REAL_DD_H
#define C2D_REAL_DD_H

/* Results are written through pointers and inputs read through const
 * pointers (which may alias the result): a struct passed or returned by
 * value becomes a memcpy call at -Os on small cores, and the library links
 * no C library. */
typedef struct c2d_dd { c2d_real h, l; int e; } c2d_dd;

/* r = (h + l) 2^e, renormalised. */
static void c2d_dd_set(c2d_dd *r, c2d_real h, c2d_real l, int e)
{
    c2d_real err, s = c2d_two_sum(h, l, &err);
    if (s == 0) {
        r->h = 0;
        r->l = 0;
        r->e = 0;
    } else {
        int k = c2d_ilogb(s);
        r->h = c2d_scale2(s, -k);
        r->l = c2d_scale2(err, -k);
        r->e = e + k;
    }
}

static void c2d_dd_of(c2d_dd *r, c2d_real x) { c2d_dd_set(r, x, 0, 0); }

/* *d = *s field by field (no memcpy call on small cores). */
static void c2d_dd_copy(c2d_dd *d, const c2d_dd *s)
{
    d->h = s->h;
    d->l = s->l;
    d->e = s->e;
}

static void c2d_dd_negate(c2d_dd *a)
{
    a->h = -a->h;
    a->l = -a->l;
}

static int c2d_dd_sign(const c2d_dd *a) { return (a->h > 0) - (a->h < 0); }

/* r = (ah + al) 2^ea + (bh + bl) 2^eb, both parts nonzero and their
 * exponents close enough that the smaller one's parts stay normal once
 * aligned to the larger: the classical double-double sum, each alignment an
 * exact power-of-two scaling. */
static void c2d_dd_sum_aligned(c2d_dd *r, const c2d_real a[2], int ea, const c2d_real b[2], int eb)
{
    const int k = ea - eb;
    c2d_real ah = a[0], al = a[1], bh = b[0], bl = b[1], s, t, e1, e2;
    int e = ea;
    if (k >= 0) {
        bh = c2d_scale2(bh, -k);
        bl = c2d_scale2(bl, -k);
    } else {
        ah = c2d_scale2(ah, k);
        al = c2d_scale2(al, k);
        e = eb;
    }
    s = c2d_two_sum(ah, bh, &e1);
    t = c2d_two_sum(al, bl, &e2);
    e1 += t;
    s = c2d_two_sum(s, e1, &e1);
    c2d_dd_set(r, s, e1 + e2, e);
}

/* r = a + sign b (sign +1 or -1). */
static void c2d_dd_add(c2d_dd *r, const c2d_dd *a, const c2d_dd *b, int sign)
{
    const c2d_real pa[2] = {a->h, a->l};
    const c2d_real pb[2] = {sign < 0 ? -b->h : b->h, sign < 0 ? -b->l : b->l};
    const int k = a->e - b->e;
    if (pb[0] != 0 && (pa[0] == 0 || k < -(2 * C2D_R_MANT + 6))) { /* a is zero or below b's low part */
        c2d_dd_set(r, pb[0], pb[1], b->e);
    } else if (pb[0] == 0 || k > 2 * C2D_R_MANT + 6) { /* b is zero or below a's low part */
        c2d_dd_set(r, pa[0], pa[1], a->e);
    } else {
        c2d_dd_sum_aligned(r, pa, a->e, pb, b->e);
    }
}

/* (ah + al)(bh + bl) on bare parts (no exponent, no normalisation): the
 * high part returned, the low part in *l, renormalised by one TwoSum.  What
 * c2d_dd_mul does to the parts, for callers that keep their own scale
 * (real/toia/eval.h). */
static c2d_real c2d_dd_mul_parts(c2d_real ah, c2d_real al, c2d_real bh, c2d_real bl, c2d_real *l)
{
    c2d_real err, p = c2d_two_prod(ah, bh, &err);
    err += ah * bl + al * bh;
    return c2d_two_sum(p, err, l);
}

/* (The TwoSum in c2d_dd_set returns the renormalised parts unchanged.) */
static void c2d_dd_mul(c2d_dd *r, const c2d_dd *a, const c2d_dd *b)
{
    c2d_real l, h = c2d_dd_mul_parts(a->h, a->l, b->h, b->l, &l);
    c2d_dd_set(r, h, l, a->e + b->e);
}

/* r = a / b, b != 0. */
static void c2d_dd_div(c2d_dd *r, const c2d_dd *a, const c2d_dd *b)
{
    c2d_real q1 = a->h / b->h, err, p = c2d_two_prod(q1, b->h, &err);
    c2d_real rem = ((a->h - p) - err + a->l) - q1 * b->l; /* a->h - p is exact: p ~ a->h */
    c2d_dd_set(r, q1, rem / b->h, a->e - b->e);
}

/* r = sqrt(a), a >= 0. */
static void c2d_dd_sqrt(c2d_dd *r, const c2d_dd *a)
{
    c2d_real h = a->h, l = a->l, s, err, p;
    int e = a->e;
    if (!(h > 0)) { /* 0, or below: the square root of a rounded zero */
        c2d_dd_of(r, 0);
        return;
    }
    if ((e & 1) != 0) {
        h *= 2;
        l *= 2;
        e -= 1;
    }
    s = C2D_R_SQRT(h);
    p = c2d_two_prod(s, s, &err);
    c2d_dd_set(r, s, ((h - p) - err + l) / (2 * s), e / 2);
}

/* The value rounded to the working format (Inf beyond it). */
static c2d_real c2d_dd_value(const c2d_dd *a) { return c2d_scale2(a->h + a->l, a->e); }

/* |a| > |b| (to within the low parts: used only where either answer is
 * right at equality). */
static int c2d_dd_abs_greater(const c2d_dd *a, const c2d_dd *b)
{
    if (b->h == 0) return a->h != 0;
    if (a->h == 0) return 0;
    if (a->e != b->e) return a->e > b->e;
    return c2d_abs(a->h + a->l) > c2d_abs(b->h + b->l);
}

/* r = the exact sum in acc, as its rounded value plus the rounded value of
 * the remainder. */
static void c2d_dd_of_acc(c2d_dd *r, c2d_acc *acc)
{
    c2d_ext hi, lo, parts[C2D_ATOMS + 1];
    int i, n = c2d_compress(acc->atom, acc->n);
    for (i = 0; i < n; i++) c2d_ext_copy(&parts[i], &acc->atom[i]);
    hi = c2d_exact_sum(acc->atom, n);
    if (hi.m == 0) {
        c2d_dd_of(r, 0);
        return;
    }
    parts[n].m = -hi.m;
    parts[n].e = hi.e;
    lo = c2d_exact_sum(parts, n + 1);
    c2d_dd_set(r, hi.m, lo.m == 0 ? 0 : c2d_scale2(lo.m, lo.e - hi.e), hi.e);
}

#endif /* C2D_REAL_DD_H */
