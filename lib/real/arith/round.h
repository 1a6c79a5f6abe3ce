/* SPDX-License-Identifier: MIT */
/* real/arith/round.h - template: correctly rounded quotients of exact sums, and
 * the cheap filter in front of them.
 * Needs real/arith/bits.h, real/arith/exact.h and real/arith/sign.h first.
 *
 * THE PROBLEM
 *   Where an exact answer is representable, or its nearest representable
 *   value is what the user should get (an axis-aligned impact: a swap, a
 *   sign flip against a wall), the result must be N / D rounded once, with N
 *   and D polynomials in the inputs.  Both are exact sums of products of
 *   extended numbers (real/arith/sign.h), so the question is only which of two
 *   adjacent representable values is nearer.
 *
 * THE FILTER (Ziv's strategy)
 *   The exact method below costs thousands of operations, but N / D is
 *   almost never near a rounding boundary (a midpoint between adjacent
 *   representable values).  So first y is computed in double length,
 *   yh + yl with yh = fl(yh + yl), together with a bound B on its error.
 *   The midpoints next to yh lie at least h = half the gap from |yh| down
 *   to its predecessor away from it (the gap above is never smaller), so
 *   when |yl| + B < h the exact y lies strictly between them and rounds to
 *   yh: that is the answer, bit for bit the one the exact method gives (the
 *   correctly rounded value is unique).  Otherwise - an exact tie, a value
 *   within B of a midpoint, a tiny or subnormal result, an input outside
 *   the window below - the exact method decides.  The test itself is
 *   rounded: t = fl(|yl| + B) <= h (1 - 4u) gives |yl| + B <= t / (1 - u)
 *   < h, with u = 2^-(MANT+1) (h is a power of two, h (1 - 4u) exact).
 *
 *   Error bounds (u as above; TwoSum always exact, TwoProduct exact when
 *   |fl(x y)| >= 2^(EMIN + MANT + 3): then ulp(x) ulp(y) >= 2^-(2 MANT + 2)
 *   |x y| >= 2^(EMIN - MANT), the smallest subnormal, so the error term is
 *   representable - Boldo 2006 for Dekker's product, and trivially for
 *   FMA).  The window: velocities and masses at most 2^(EMAX/2 - 1) (no
 *   sum, product or Veltkamp split overflows), and every TwoProduct's
 *   product and the quotient's leading part at least
 *   tiny = 2^(EMIN + 2 MANT + 4), else the filter declines.  Then a plain
 *   product that underflows errs by at most half the smallest subnormal,
 *   under u^3 / 4 of its step's leading part: negligible beside the u^2
 *   terms below (each |low| <= u |high| from a TwoSum).
 *   - A wall: y = v + e w, w = v - u = wh + wl exactly; ph + pe = e wh
 *     exactly; pe + e wl two roundings (<= 3u^2 |ph|, with e wl dropped to
 *     nothing below); s1 + s2 = v + ph exactly, s2 + pe one rounding
 *     (<= u (u |s1| + 2u |ph|)); yh + yl = TwoSum.  |y - yh - yl| <=
 *     5 u^2 (|ph| + |s1|).
 *   - A pair: J = (1 + e) w / (ma + mb), then ua' = u + mb J, ub' = v - ma J.
 *     f = 1 + e = fh + fl and s = ma + mb = sh + sl exactly.  F = f w:
 *     ph + pe = fh wh exactly, pe + (fh wl + fl wh) four roundings and fl wl
 *     dropped: |F - f w| <= 8.1 u^2 |ph|.  J = F / s: q1 = fl(Fh / sh),
 *     a + b = q1 sh exactly (Fh - a exact by Sterbenz), the remainder
 *     r = ((Fh - a) - b + Fl) - q1 sl with <= 7 u^2 |Fh| of rounding, its
 *     true value R = F - q1 s has |R| <= 3u |Fh|, and J = q1 + fl(r / sh)
 *     differs from F / s = q1 + R / s by <= 7u^2 + 3u^2 (sl in s) + 3u^2
 *     (the last division), so |J - f w / s| <= 23 u^2 |q1| with F's error.
 *     X = t J (t = mb, or -ma): xh + xe = t Jh exactly, xe + t Jl two
 *     roundings: |X - t f w / s| <= 26.1 u^2 |xh|.  s1 + s2 = u + xh
 *     exactly, s2 + xe one rounding (<= u^2 |s1| + 2 u^2 |xh|): in all
 *     |y - yh - yl| <= 29 u^2 |xh| + u^2 |s1|.
 *   Both are covered eightfold by B = 256 u^2 (|xh| + |s1|) (|ph| for the
 *   wall), computed with one rounding of the sum (relative u) and an exact
 *   power-of-two scaling (|xh| >= tiny keeps B normal).  The filter thus
 *   declines about one result in 2^(MANT+1) / 512 at random (1 in 2^44 for
 *   double, 1 in 2^15 for float) besides the window.
 *
 * THE EXACT METHOD
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
static void c2d_acc_add(c2d_acc *acc, const c2d_ext *x, int sign)
{
    c2d_ext one;
    c2d_ext_set(&one, 1, 0);
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
static void c2d_remainder(c2d_acc *acc, const c2d_ext *num, int nn, const c2d_ext *den, int nd, c2d_real q)
{
    c2d_ext xq;
    int i;
    c2d_acc_clear(acc);
    c2d_ext_set(&xq, q, 0);
    for (i = 0; i < nn; i++) c2d_acc_add(acc, &num[i], 1);
    for (i = 0; i < nd; i++) c2d_acc_product(acc, &xq, &den[i], -1);
}

/* The sign of R = N - q D. */
static int c2d_remainder_sign(const c2d_ext *num, int nn, const c2d_ext *den, int nd, c2d_real q)
{
    c2d_acc acc;
    c2d_ext r;
    c2d_remainder(&acc, num, nn, den, nd, q);
    c2d_acc_value(&r, &acc);
    return c2d_ext_sign(&r);
}

/* The sign of |R| - h D, with R = N - q D of sign r_sign and h half the gap
 * |q - q_other| between q and a neighbour (a power of two: exact). */
static int c2d_beyond_half(const c2d_ext *num, int nn, const c2d_ext *den, int nd, c2d_real q, c2d_real q_other,
                           int r_sign)
{
    c2d_acc acc;
    c2d_ext h, s;
    int i;
    c2d_ext_set(&h, q_other, 0);
    c2d_ext_set(&s, q, 0);
    c2d_ext_add(&h, &h, &s, -1);
    h.m = c2d_abs(h.m);
    h.e -= 1;
    c2d_remainder(&acc, num, nn, den, nd, q);
    if (r_sign < 0)
        for (i = 0; i < acc.n; i++) acc.atom[i].m = -acc.atom[i].m;
    for (i = 0; i < nd; i++) c2d_acc_product(&acc, &h, &den[i], -1);
    c2d_acc_value(&s, &acc);
    return c2d_ext_sign(&s);
}

/* *r = (sum of num[0..nn)) / (sum of den[0..nd)), den's sum > 0, correctly
 * rounded, ties to even, Inf beyond the largest finite value. */
static void c2d_round_quotient(c2d_real *r, const c2d_ext *num, int nn, const c2d_ext *den, int nd)
{
    c2d_acc acc;
    c2d_ext nv, dv, qx;
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
    c2d_ext_div(&qx, &nv, &dv);
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

/* ------------------------------------------------------------ the filter */

/* The window's edges: a velocity or mass at most big, a TwoProduct's
 * product or the quotient's leading part at least tiny (derivation above). */
static inline c2d_real c2d_filter_big(void) { return c2d_pow2(C2D_R_EMAX / 2 - 1); }
static inline c2d_real c2d_filter_tiny(void) { return c2d_pow2(C2D_R_EMIN + 2 * C2D_R_MANT + 4); }

/* B = 256 u^2 (|x| + |y|), rounded up enough (derivation above). */
static inline c2d_real c2d_filter_bound(c2d_real x, c2d_real y)
{
    return c2d_pow2(6 - 2 * C2D_R_MANT) * (c2d_abs(x) + c2d_abs(y));
}

/* 1 when yh (= fl(yh + yl)) is the correctly rounded value of every y with
 * |y - yh - yl| <= bound: |yl| + bound below half the gap under |yh|.
 * Declines subnormal, tiny and non-finite yh. */
static int c2d_ziv_accept(c2d_real yh, c2d_real yl, c2d_real bound)
{
    const c2d_real ay = c2d_abs(yh);
    c2d_real h;
    if (!(ay >= c2d_pow2(C2D_R_EMIN + C2D_R_MANT + 2) && ay <= C2D_R_MAX)) return 0;
    h = (ay - c2d_from_bits(c2d_bits(ay) - (c2d_real_bits)1)) * (c2d_real)0.5; /* Sterbenz: exact */
    return c2d_abs(yl) + bound <= h * ((c2d_real)1 - c2d_pow2(1 - C2D_R_MANT)) ? 1 : 0;
}

/* *y = the correctly rounded v + e (v - u), when the filter can tell
 * (returns 1); 0 leaves it to the exact method. */
static int c2d_filter_wall(c2d_real *y, c2d_real u, c2d_real v, c2d_real e)
{
    c2d_real wh, wl, ph, pe, s1, s2, yh, yl;
    if (!(c2d_abs(u) <= c2d_filter_big() && c2d_abs(v) <= c2d_filter_big())) return 0;
    wh = c2d_two_sum(v, -u, &wl);
    ph = c2d_two_prod(e, wh, &pe);
    if (!(c2d_abs(ph) >= c2d_filter_tiny())) return 0;
    pe += e * wl;
    s1 = c2d_two_sum(v, ph, &s2);
    s2 += pe;
    yh = c2d_two_sum(s1, s2, &yl);
    if (c2d_ziv_accept(yh, yl, c2d_filter_bound(ph, s1)) == 0) return 0;
    *y = yh;
    return 1;
}

/* J = (1 + e)(v - u) / (mine + theirs) as *jh + *jl (error under
 * 23 u^2 |jh|), or 0 outside the window. */
static int c2d_filter_impulse(c2d_real *jh, c2d_real *jl, const c2d_real uv[2], c2d_real mine, c2d_real theirs,
                              c2d_real e)
{
    const c2d_real big = c2d_filter_big();
    c2d_real wh, wl, fh, fl, sh, sl, ph, pe, q1, a, b, r;
    if (!(c2d_abs(uv[0]) <= big && c2d_abs(uv[1]) <= big && mine <= big && theirs <= big)) return 0;
    wh = c2d_two_sum(uv[1], -uv[0], &wl);
    fh = c2d_two_sum(1, e, &fl);
    sh = c2d_two_sum(mine, theirs, &sl);
    ph = c2d_two_prod(fh, wh, &pe);
    if (!(c2d_abs(ph) >= c2d_filter_tiny())) return 0;
    pe += fh * wl + fl * wh;
    fh = c2d_two_sum(ph, pe, &fl); /* F = (1 + e) w */
    q1 = fh / sh;
    if (!(c2d_abs(q1) >= c2d_filter_tiny() && c2d_abs(q1) <= big)) return 0;
    a = c2d_two_prod(q1, sh, &b);
    r = (((fh - a) - b) + fl) - q1 * sl; /* F - q1 s */
    *jh = c2d_two_sum(q1, r / sh, jl);
    return 1;
}

/* *y = the correctly rounded u + t J (J = jh + jl from
 * c2d_filter_impulse), when the filter can tell (returns 1). */
static int c2d_filter_apply(c2d_real *y, c2d_real u, c2d_real t, c2d_real jh, c2d_real jl)
{
    c2d_real xh, xe, s1, s2, yh, yl;
    xh = c2d_two_prod(t, jh, &xe);
    if (!(c2d_abs(xh) >= c2d_filter_tiny())) return 0;
    xe += t * jl;
    s1 = c2d_two_sum(u, xh, &s2);
    s2 += xe;
    yh = c2d_two_sum(s1, s2, &yl);
    if (c2d_ziv_accept(yh, yl, c2d_filter_bound(xh, s1)) == 0) return 0;
    *y = yh;
    return 1;
}

#endif /* C2D_REAL_ROUND_H */
