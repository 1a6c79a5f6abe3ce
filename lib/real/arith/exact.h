/* SPDX-License-Identifier: MIT */
/* real/arith/exact.h - template: exact floating-point arithmetic.  Needs
 * real/arith/bits.h first.
 *
 * ERROR-FREE TRANSFORMS
 *   For floating a, b (no overflow), s = fl(a + b) and the rounding error
 *   err = (a + b) - s is itself a floating number, computed exactly by
 *   Knuth's TwoSum in six operations.  Likewise p = fl(a * b) and
 *   err = a * b - p (barring underflow) by Dekker's TwoProduct: split each
 *   factor into halves of at most ceil(p/2) bits (Veltkamp: c = (2^s + 1) a,
 *   hi = c - (c - a)), whose pairwise products are exact; with a fused
 *   multiply-add, err = fma(a, b, -p) gives the same bits in one step.
 *
 * EXPANSIONS (Shewchuk)
 *   A sum of floating numbers with nonoverlapping significands, kept in
 *   increasing magnitude, represents a number exactly; adding one more
 *   number with a chain of TwoSums keeps it exact (GROW-EXPANSION), and the
 *   largest component has the sign of the whole.  The collision's d is a
 *   sum of eight exact products (the velocity components times the exact
 *   normal, hi and lo parts), so its sign - OK versus SEPARATING - is
 *   decided exactly whatever the cancellation.
 *
 * WINDOWED EXACT SUM
 *   Terms are extended numbers (real/arith/bits.h) whose exponents may span far
 *   more than one format can hold.  Terms within C2D_R_WINDOW binades of the
 *   largest are scaled into one window and summed exactly; if that partial
 *   sum is at least 2^(C2D_R_MARGIN - C2D_R_WINDOW) of the window's top, the
 *   terms left below it (each < 2^-C2D_R_WINDOW of the top, at most
 *   C2D_ATOMS of them) cannot change it by a relative 2^-C2D_R_MARGIN, so
 *   it is returned rounded; otherwise the window's components rejoin the
 *   rest and the next window starts at the new largest term.
 */
#ifndef C2D_REAL_EXACT_H
#define C2D_REAL_EXACT_H

/* s + err == a + b exactly (Knuth's TwoSum; no overflow assumed). */
static c2d_real c2d_two_sum(c2d_real a, c2d_real b, c2d_real *err)
{
    c2d_real s = a + b;
    c2d_real bv = s - a;
    c2d_real av = s - bv;
    *err = (a - av) + (b - bv);
    return s;
}

/* p + err == a * b exactly, barring underflow of err (Dekker/Veltkamp, or a
 * fused multiply-add where the hardware has one: identical results). */
static c2d_real c2d_two_prod(c2d_real a, c2d_real b, c2d_real *err)
{
    c2d_real p = a * b;
#ifdef C2D_R_FMA
    *err = C2D_R_FMA(a, b, -p);
#else
    c2d_real ca = C2D_R_SPLIT * a, cb = C2D_R_SPLIT * b;
    c2d_real ah = ca - (ca - a), bh = cb - (cb - b);
    c2d_real al = a - ah, bl = b - bh;
    *err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
    return p;
}

/* TwoProduct for code dispatched at run time (real/collide/collide.h): with
 * fused != 0, the error from a fused multiply-add, which only a caller
 * compiled for a target with FMA and chosen because the CPU has it may ask
 * for (C2D_R_FUSED, defined under C2D_DISPATCH); otherwise c2d_two_prod.
 * The error term is a * b - p exactly either way: the same bits. */
C2D_HOT c2d_real c2d_two_prod_as(c2d_real a, c2d_real b, c2d_real *err, int fused)
{
#ifdef C2D_R_FUSED
    if (fused != 0) {
        c2d_real p = a * b;
        *err = C2D_R_FUSED(a, b, -p);
        return p;
    }
#else
    (void)fused;
#endif
    return c2d_two_prod(a, b, err);
}

/* Add b to the nonoverlapping expansion e[0..n) (increasing magnitude),
 * keeping it exact and nonoverlapping (GROW-EXPANSION with zero
 * elimination).  Returns the new length (<= n + 1). */
static int c2d_grow(c2d_real *e, int n, c2d_real b)
{
    c2d_real q = b, h;
    int i, k = 0;
    for (i = 0; i < n; i++) {
        q = c2d_two_sum(q, e[i], &h);
        if (h != 0) e[k++] = h;
    }
    if (q != 0) e[k++] = q;
    return k;
}

enum { C2D_ATOMS = 40 }; /* terms of an exact sum, at most */

/* Exact sum of up to C2D_ATOMS/2 extended numbers, returned rounded to an
 * extended number (error below 2^-C2D_R_MANT relative; the sign is exact). */
static c2d_ext c2d_exact_sum(c2d_ext *atom, int n)
{
    c2d_real ex[C2D_ATOMS];
    for (;;) {
        int i, k = 0, rest = 0, emax = C2D_NO_EXP;
        c2d_real approx = 0;
        for (i = 0; i < n; i++)
            if (atom[i].m != 0 && atom[i].e > emax) emax = atom[i].e;
        if (emax == C2D_NO_EXP) return c2d_ext_make(0, 0);
        for (i = 0; i < n; i++) {
            if (atom[i].m == 0) continue;
            if (atom[i].e >= emax - C2D_R_WINDOW) {
                k = c2d_grow(ex, k, c2d_scale2(atom[i].m, atom[i].e - emax));
            } else {
                c2d_ext_copy(&atom[rest++], &atom[i]);
            }
        }
        for (i = 0; i < k; i++) approx += ex[i];
        if (rest == 0 || (approx != 0 && c2d_ilogb(approx) > C2D_R_MARGIN - C2D_R_WINDOW))
            return c2d_ext_make(approx, emax);
        for (i = 0; i < k; i++) atom[rest++] = c2d_ext_make(ex[i], emax);
        n = rest;
    }
}

/* Append the exact product x * y of two extended numbers as two atoms. */
static int c2d_push_product(c2d_ext *atom, int n, c2d_ext x, c2d_ext y)
{
    c2d_real lo, hi = c2d_two_prod(x.m, y.m, &lo);
    atom[n++] = c2d_ext_make(hi, x.e + y.e);
    atom[n++] = c2d_ext_make(lo, x.e + y.e);
    return n;
}

/* The exact difference x1 - x0 as (hi + lo) * 2^e, hi and lo as extended
 * numbers: halving first when the difference could overflow (exact for the
 * large operand, and what the small one loses is far below hi). */
static void c2d_exact_diff(c2d_real x1, c2d_real x0, c2d_ext *hi, c2d_ext *lo)
{
    int e = 0;
    c2d_real h, l;
    if (c2d_abs(x1) >= c2d_pow2(C2D_R_EMAX - 1) || c2d_abs(x0) >= c2d_pow2(C2D_R_EMAX - 1)) {
        x1 *= (c2d_real)0.5;
        x0 *= (c2d_real)0.5;
        e = 1;
    }
    h = c2d_two_sum(x1, -x0, &l);
    *hi = c2d_ext_make(h, e);
    *lo = c2d_ext_make(l, e);
}

/* r.(nh + nl) for r = vb - va as a double-double: exact differences and
 * exact products, so the error is ~1 ulp of the result plus ~u^2 of the
 * terms.  `fused` as for c2d_two_prod_as. */
C2D_HOT c2d_real c2d_dot2_as(const c2d_real_vec *nh, const c2d_real_vec *nl, const c2d_real_vec *va,
                             const c2d_real_vec *vb, int fused)
{
    c2d_real rlx, rly, ex, ey, t;
    c2d_real rhx = c2d_two_sum(vb->x, -va->x, &rlx);
    c2d_real rhy = c2d_two_sum(vb->y, -va->y, &rly);
    c2d_real px = c2d_two_prod_as(rhx, nh->x, &ex, fused);
    c2d_real py = c2d_two_prod_as(rhy, nh->y, &ey, fused);
    c2d_real s = c2d_two_sum(px, py, &t);
    c2d_real small = ((rhx * nl->x + rlx * nh->x) + (rhy * nl->y + rly * nh->y)) + (rlx * nl->x + rly * nl->y);
    return s + (t + ((ex + ey) + small));
}

static c2d_real c2d_dot2(const c2d_real_vec *nh, const c2d_real_vec *nl, const c2d_real_vec *va,
                         const c2d_real_vec *vb)
{
    return c2d_dot2_as(nh, nl, va, vb, 0);
}

/* x.y for double-double vectors (xh + xl, yh + yl), to about 2 ulp even
 * under cancellation. */
static c2d_real c2d_dot_dd(const c2d_real *xh, const c2d_real *xl, const c2d_real *yh, const c2d_real *yl)
{
    c2d_real e0, e1, t;
    c2d_real p0 = c2d_two_prod(xh[0], yh[0], &e0);
    c2d_real p1 = c2d_two_prod(xh[1], yh[1], &e1);
    c2d_real s = c2d_two_sum(p0, p1, &t);
    return s + (t + (e0 + e1) + ((xh[0] * yl[0] + xl[0] * yh[0]) + (xh[1] * yl[1] + xl[1] * yh[1])));
}

#endif /* C2D_REAL_EXACT_H */
