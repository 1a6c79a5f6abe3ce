/* real_round.h - template: correctly rounded quotients of exact sums.
 * Needs real_bits.h, real_exact.h and real_sign.h first.
 *
 * THE PROBLEM
 *   Where an exact answer is representable, or its nearest representable
 *   value is what the user should get (an axis-aligned impact: a swap, a
 *   sign flip against a wall), the result must be N / D rounded once, with N
 *   and D polynomials in the inputs.  Both are exact sums of products of
 *   extended numbers (real_sign.h), so the question is only which of two
 *   adjacent representable values is nearer.
 *
 * THE METHOD
 *   q0 = N~ / D~ from the correctly rounded sums, then rounded to the
 *   format (subnormals included): within a couple of ulp of N / D.  For a
 *   candidate q the remainder R = N - q D is exact (q D is a product of an
 *   extended number with D's exact parts), and with D > 0, N / D - q has R's
 *   sign.  Let h be half the gap from q to its neighbour q' in that
 *   direction: q is the nearest when |R| < h D, the neighbour when
 *   |R| > h D (then repeat from q'), and at |R| = h D the tie goes to the
 *   even significand.  Each comparison is the exact sign of a sum of atoms,
 *   so the result is the correctly rounded quotient; an exact quotient ends
 *   at once with R = 0.  Past the largest finite value the result is
 *   infinite (the caller reports C2D_RANGE).
 */
#ifndef C2D_REAL_ROUND_H
#define C2D_REAL_ROUND_H

/* acc += sign * x. */
static void c2d_acc_add(c2d_acc *acc, const c2d_xf *x, int sign)
{
    c2d_xf one;
    c2d_xf_set(&one, 1, 0);
    c2d_acc_product(acc, x, &one, sign);
}

/* The next representable value after x (finite) towards +Inf (dir > 0) or
 * -Inf (dir < 0): one more or one less in the magnitude's bits, Inf past
 * the largest finite value. */
static c2d_real c2d_next(c2d_real x, int dir)
{
    c2d_real_bits u = c2d_bits(x);
    if (x == 0) return dir > 0 ? c2d_from_bits(1) : -c2d_from_bits(1);
    if ((x > 0) == (dir > 0))
        u += 1;
    else
        u -= 1;
    return c2d_from_bits(u);
}

/* acc = R = N - q D, exactly. */
static void c2d_remainder(c2d_acc *acc, const c2d_xf *num, int nn, const c2d_xf *den, int nd, c2d_real q)
{
    c2d_xf xq;
    int i;
    c2d_acc_clear(acc);
    c2d_xf_set(&xq, q, 0);
    for (i = 0; i < nn; i++) c2d_acc_add(acc, &num[i], 1);
    for (i = 0; i < nd; i++) c2d_acc_product(acc, &xq, &den[i], -1);
}

/* The sign of R = N - q D. */
static int c2d_remainder_sign(const c2d_xf *num, int nn, const c2d_xf *den, int nd, c2d_real q)
{
    c2d_acc acc;
    c2d_xf r;
    c2d_remainder(&acc, num, nn, den, nd, q);
    c2d_acc_value(&r, &acc);
    return c2d_xf_sign(&r);
}

/* The sign of |R| - h D, with R = N - q D of sign r_sign and h half the gap
 * |q - q_other| between q and a neighbour (a power of two: exact). */
static int c2d_beyond_half(const c2d_xf *num, int nn, const c2d_xf *den, int nd, c2d_real q, c2d_real q_other,
                           int r_sign)
{
    c2d_acc acc;
    c2d_xf h, s;
    int i;
    c2d_xf_set(&h, q_other, 0);
    c2d_xf_set(&s, q, 0);
    c2d_xf_add(&h, &h, &s, -1);
    h.m = c2d_abs(h.m);
    h.e -= 1;
    c2d_remainder(&acc, num, nn, den, nd, q);
    if (r_sign < 0)
        for (i = 0; i < acc.n; i++) acc.atom[i].m = -acc.atom[i].m;
    for (i = 0; i < nd; i++) c2d_acc_product(&acc, &h, &den[i], -1);
    c2d_acc_value(&s, &acc);
    return c2d_xf_sign(&s);
}

/* *r = (sum of num[0..nn)) / (sum of den[0..nd)), den's sum > 0, correctly
 * rounded, ties to even, Inf beyond the largest finite value. */
static void c2d_round_quotient(c2d_real *r, const c2d_xf *num, int nn, const c2d_xf *den, int nd)
{
    c2d_acc acc;
    c2d_xf nv, dv, qx;
    c2d_real q;
    int i, step, decided = 0;
    c2d_acc_clear(&acc);
    for (i = 0; i < nn; i++) c2d_acc_add(&acc, &num[i], 1);
    c2d_acc_value(&nv, &acc);
    c2d_acc_clear(&acc);
    for (i = 0; i < nd; i++) c2d_acc_add(&acc, &den[i], 1);
    c2d_acc_value(&dv, &acc);
    if (nv.m == 0) {
        *r = 0;
        return;
    }
    c2d_xf_div(&qx, &nv, &dv);
    q = c2d_scale2(qx.m, qx.e);
    if (!(q - q == 0)) q = q > 0 ? C2D_R_MAX : -C2D_R_MAX; /* the steps decide overflow exactly */
    /* q starts within a few ulp; each step moves one ulp towards N / D. */
    for (step = 0; step < 8 && decided == 0; step++) {
        const int r_sign = c2d_remainder_sign(num, nn, den, nd, q);
        if (r_sign == 0) {
            decided = 1; /* exact */
        } else {
            const c2d_real q_next = c2d_next(q, r_sign);
            /* Past the largest finite value the gap is the one below it. */
            const int beyond =
                c2d_beyond_half(num, nn, den, nd, q, q_next - q_next == 0 ? q_next : c2d_next(q, -r_sign), r_sign);
            if (beyond < 0) {
                decided = 1;
            } else if (beyond == 0) {
                if ((c2d_bits(q) & 1u) != 0) q = q_next; /* the tie goes to the even significand */
                decided = 1;
            } else {
                q = q_next;
                if (!(q - q == 0)) decided = 1; /* Inf: past the largest finite value */
            }
        }
    }
    *r = q;
}

#endif /* C2D_REAL_ROUND_H */
