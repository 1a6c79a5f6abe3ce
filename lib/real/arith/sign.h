/* SPDX-License-Identifier: MIT */
/* real/arith/sign.h - template: extended-number arithmetic and exact signs of sums
 * of products over the whole exponent range.  Needs real/arith/bits.h and
 * real/arith/exact.h first.
 *
 * EXTENDED ARITHMETIC
 *   An extended number m 2^e (real/arith/bits.h) never over- or underflows, so
 *   c2d_ext_mul/div/add/sqrt below round exactly once each, like the
 *   floating operation would in a format with an unbounded exponent:
 *   products and quotients round the product of the significands, a sum
 *   aligns the smaller operand (exactly, or not at all when it lies below
 *   half an ulp of the larger, where round-to-nearest returns the larger),
 *   a square root first makes the exponent even.  Code written with them
 *   has the error analysis of plain arithmetic with no range caveat.
 *
 * EXACT SIGNS
 *   A polynomial in the inputs (a discriminant, a dot product) is a sum of
 *   products of input values.  Each product of two extended numbers is
 *   exactly hi + lo (TwoProduct on the significands), so the polynomial is
 *   an exact sum of "atoms".  c2d_exact_sum (real/arith/exact.h) returns that sum
 *   correctly rounded, with its exact sign.  A product of two such sums is
 *   formed by first compressing each to its exact components
 *   (c2d_compress: the windowed GROW-EXPANSION of real/arith/exact.h, keeping
 *   every component instead of rounding) and multiplying component by
 *   component, so degree-4 quantities are exact too.
 */
#ifndef C2D_REAL_SIGN_H
#define C2D_REAL_SIGN_H

/* Results through pointers, inputs through const pointers that may alias
 * the result: a struct passed or returned by value becomes a memcpy call at
 * -Os on small cores. */
static void c2d_ext_set(c2d_ext *r, c2d_real m, int e)
{
    if (m == 0) {
        r->m = 0;
        r->e = 0;
    } else {
        int k = c2d_ilogb(m);
        r->m = c2d_scale2(m, -k);
        r->e = e + k;
    }
}

static void c2d_ext_mul(c2d_ext *r, const c2d_ext *a, const c2d_ext *b) { c2d_ext_set(r, a->m * b->m, a->e + b->e); }

/* r = a / b, b != 0. */
static void c2d_ext_div(c2d_ext *r, const c2d_ext *a, const c2d_ext *b) { c2d_ext_set(r, a->m / b->m, a->e - b->e); }

/* r = a + sign b (sign +1 or -1), one rounding. */
static void c2d_ext_add(c2d_ext *r, const c2d_ext *a, const c2d_ext *b, int sign)
{
    c2d_real am = a->m, bm = sign < 0 ? -b->m : b->m;
    int ae = a->e, be = b->e, k = a->e - b->e;
    /* |b| < 2^(b.e + 1) <= a quarter of an ulp of a when k >= MANT + 3, below
     * half the spacing even under a power of two: a + b rounds to a.  (At
     * MANT + 2 it need not: tests/unit/test_ext_add.c.) */
    if (bm == 0 || (am != 0 && k >= C2D_R_MANT + 3)) {
        c2d_ext_set(r, am, ae);
    } else if (am == 0 || k <= -(C2D_R_MANT + 3)) {
        c2d_ext_set(r, bm, be);
    } else if (k >= 0) {
        c2d_ext_set(r, am + c2d_scale2(bm, -k), ae);
    } else {
        c2d_ext_set(r, c2d_scale2(am, k) + bm, be);
    }
}

/* r = sqrt(a), a >= 0. */
static void c2d_ext_sqrt(c2d_ext *r, const c2d_ext *a)
{
    c2d_real m = a->m;
    int e = a->e;
    if (m <= 0) {
        c2d_ext_set(r, 0, 0);
        return;
    }
    if ((e & 1) != 0) {
        m *= 2;
        e -= 1;
    }
    c2d_ext_set(r, C2D_R_SQRT(m), e / 2);
}

static int c2d_ext_sign(const c2d_ext *a) { return (a->m > 0) - (a->m < 0); }

/* The exact sum of atom[0..n) rewritten in place as at most n components
 * (their sum is exact; each window's are nonoverlapping).  Returns the new
 * count.  Each window's components go to the back of the array while the
 * atoms still to be summed are kept at the front: a window of w atoms
 * yields at most w components, so the two never meet. */
static int c2d_compress(c2d_ext *atom, int n)
{
    c2d_real ex[C2D_ATOMS];
    const int end = n;
    int top = n, i;
    for (;;) {
        int k = 0, rest = 0, emax = C2D_NO_EXP;
        for (i = 0; i < n; i++)
            if (atom[i].m != 0 && atom[i].e > emax) emax = atom[i].e;
        if (emax == C2D_NO_EXP) break;
        for (i = 0; i < n; i++) {
            if (atom[i].m == 0) continue;
            if (atom[i].e >= emax - C2D_R_WINDOW) {
                k = c2d_grow(ex, k, c2d_scale2(atom[i].m, atom[i].e - emax));
            } else {
                c2d_ext_copy(&atom[rest++], &atom[i]);
            }
        }
        for (i = 0; i < k; i++) c2d_ext_set(&atom[--top], ex[i], emax);
        n = rest;
    }
    for (i = top; i < end; i++) c2d_ext_copy(&atom[i - top], &atom[i]);
    return end - top;
}

/* An exact sum being built from products, in a buffer of C2D_ATOMS
 * atoms that is compressed when it fills up. */
typedef struct c2d_acc {
    c2d_ext atom[C2D_ATOMS];
    int n;
    int full; /* set when even the compressed sum left no room */
} c2d_acc;

static void c2d_acc_clear(c2d_acc *acc)
{
    acc->n = 0;
    acc->full = 0;
}

/* acc += sign * x * y, exactly (sign is +1 or -1). */
static void c2d_acc_product(c2d_acc *acc, const c2d_ext *x, const c2d_ext *y, int sign)
{
    c2d_real lo, hi;
    if (acc->n + 2 > C2D_ATOMS) acc->n = c2d_compress(acc->atom, acc->n);
    if (acc->n + 2 > C2D_ATOMS) {
        acc->full = 1;
        return;
    }
    hi = c2d_two_prod(sign < 0 ? -x->m : x->m, y->m, &lo);
    c2d_ext_set(&acc->atom[acc->n++], hi, x->e + y->e);
    c2d_ext_set(&acc->atom[acc->n++], lo, x->e + y->e);
}

/* acc += sign * x * y for floating x, y (exactly). */
static void c2d_acc_product_of(c2d_acc *acc, c2d_real x, c2d_real y, int sign)
{
    c2d_ext xx, yy;
    c2d_ext_set(&xx, x, 0);
    c2d_ext_set(&yy, y, 0);
    c2d_acc_product(acc, &xx, &yy, sign);
}

/* acc += sign * x * y for two numbers given exactly as hi + lo. */
static void c2d_acc_pair_product(c2d_acc *acc, const c2d_ext x[2], const c2d_ext y[2], int sign)
{
    int i, j;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) c2d_acc_product(acc, &x[i], &y[j], sign);
}

/* r = the sum so far, correctly rounded, its sign exact (unless acc->full). */
static void c2d_acc_value(c2d_ext *r, c2d_acc *acc)
{
    c2d_ext s = c2d_exact_sum(acc->atom, acc->n);
    c2d_ext_copy(r, &s);
}

#endif /* C2D_REAL_SIGN_H */
