/* real_sign.h - template: extended-number arithmetic and exact signs of sums
 * of products over the whole exponent range.  Needs real_bits.h and
 * real_exact.h first.
 *
 * EXTENDED ARITHMETIC
 *   An extended number m 2^e (real_bits.h) never over- or underflows, so
 *   c2d_xf_mul/div/add/sqrt below round exactly once each, like the
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
 *   an exact sum of "atoms".  c2d_exact_sum (real_exact.h) returns that sum
 *   correctly rounded, with its exact sign.  A product of two such sums is
 *   formed by first compressing each to its exact components
 *   (c2d_compress: the windowed GROW-EXPANSION of real_exact.h, keeping
 *   every component instead of rounding) and multiplying component by
 *   component, so degree-4 quantities are exact too.
 */
#ifndef C2D_REAL_SIGN_H
#define C2D_REAL_SIGN_H

static c2d_xf c2d_xf_mul(c2d_xf a, c2d_xf b) { return c2d_xf_make(a.m * b.m, a.e + b.e); }

/* b != 0 */
static c2d_xf c2d_xf_div(c2d_xf a, c2d_xf b) { return c2d_xf_make(a.m / b.m, a.e - b.e); }

static c2d_xf c2d_xf_neg(c2d_xf a)
{
    a.m = -a.m;
    return a;
}

/* a + b, one rounding. */
static c2d_xf c2d_xf_add(c2d_xf a, c2d_xf b)
{
    int k = a.e - b.e;
    if (b.m == 0) return a;
    if (a.m == 0) return b;
    /* |b| < 2^(b.e + 1) <= half an ulp of a when k >= MANT + 3: a + b rounds to a. */
    if (k >= C2D_R_MANT + 3) return a;
    if (k <= -(C2D_R_MANT + 3)) return b;
    if (k >= 0) return c2d_xf_make(a.m + c2d_scale2(b.m, -k), a.e);
    return c2d_xf_make(c2d_scale2(a.m, k) + b.m, b.e);
}

/* sqrt(a) for a >= 0. */
static c2d_xf c2d_xf_sqrt(c2d_xf a)
{
    c2d_real m = a.m;
    int e = a.e;
    if (m <= 0) return c2d_xf_make(0, 0);
    if ((e & 1) != 0) {
        m *= 2;
        e -= 1;
    }
    return c2d_xf_make(C2D_R_SQRT(m), e / 2);
}

static int c2d_xf_sign(c2d_xf a) { return (a.m > 0) - (a.m < 0); }

/* The exact sum of atom[0..n) rewritten in place as at most n components
 * (their sum is exact; each window's are nonoverlapping).  Returns the new
 * count.  Each window's components go to the back of the array while the
 * atoms still to be summed are kept at the front: a window of w atoms
 * yields at most w components, so the two never meet. */
static int c2d_compress(c2d_xf *atom, int n)
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
                c2d_xf_copy(&atom[rest++], &atom[i]);
            }
        }
        for (i = 0; i < k; i++) atom[--top] = c2d_xf_make(ex[i], emax);
        n = rest;
    }
    for (i = top; i < end; i++) c2d_xf_copy(&atom[i - top], &atom[i]);
    return end - top;
}

/* An exact sum being built from products, in a buffer of C2D_ATOMS
 * atoms that is compressed when it fills up. */
typedef struct c2d_acc {
    c2d_xf atom[C2D_ATOMS];
    int n;
    int full; /* set when even the compressed sum left no room */
} c2d_acc;

static void c2d_acc_clear(c2d_acc *acc)
{
    acc->n = 0;
    acc->full = 0;
}

/* acc += sign * x * y, exactly (sign is +1 or -1). */
static void c2d_acc_product(c2d_acc *acc, c2d_xf x, c2d_xf y, int sign)
{
    if (acc->n + 2 > C2D_ATOMS) acc->n = c2d_compress(acc->atom, acc->n);
    if (acc->n + 2 > C2D_ATOMS) {
        acc->full = 1;
        return;
    }
    if (sign < 0) x.m = -x.m;
    acc->n = c2d_push_product(acc->atom, acc->n, x, y);
}

/* The sum so far, correctly rounded, its sign exact (unless acc->full). */
static c2d_xf c2d_acc_value(c2d_acc *acc) { return c2d_exact_sum(acc->atom, acc->n); }

#endif /* C2D_REAL_SIGN_H */
