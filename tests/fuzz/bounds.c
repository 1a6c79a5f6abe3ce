/* SPDX-License-Identifier: MIT */
/* bounds.c - the bounds the documented accuracy implies, shared by the
 * checks of the three variants. */
#include "fuzz.h"

#include <float.h>
#include <math.h>

/* Why these bounds.  The header promises each output component within
 * 16 ulp of its body's velocity scale S (largest |component| before or
 * after).  The exact response changes each velocity along the normal only,
 * conserves momentum exactly (both masses finite: an immovable body absorbs
 * momentum) and kinetic energy (e = 1) or loses it (e < 1).  So with
 * delta = 16 ulp(S) per component:
 *   direction: the part of v' - v across the unit normal is the output error
 *             projected, <= sqrt(2) delta (we allow 1.5 delta);
 *   momentum: |sum m v - sum m v'| <= sum of m delta;
 *   energy:   m v'^2 - m v_exact^2 = m (v' - v_exact)(v' + v_exact)
 *             <= m delta (2 S + delta) per component, so with the 1/2 and two
 *             components, KE' - KE <= sum of m delta (2 S + delta).
 * The sums are formed in long double (64-bit significand, exponent range to
 * 1e4932: m v^2 neither overflows nor underflows for any double input); each
 * of its few roundings is <= LDBL_EPSILON of the magnitudes involved, hence
 * the extra 8 LDBL_EPSILON x (sum of |terms|).  For Q16.16 the documented
 * error is delta = 3 steps + 2^-24 S (in raw units).  Nothing here is tuned:
 * the only constants are the header's. */
const c2d_fuzz_fmt c2d_fuzz_fmt_double = {53, -1022};

long double c2d_fuzz_ulp(long double s, c2d_fuzz_fmt f)
{
    int ex;
    if (!(s >= ldexpl(1.0L, f.emin))) return ldexpl(1.0L, f.emin - f.prec + 1);
    (void)frexpl(s, &ex); /* s = g 2^ex, g in [0.5, 1) */
    return ldexpl(1.0L, ex - f.prec);
}

long double c2d_fuzz_maxabs4(long double a, long double b, long double c, long double d)
{
    long double m = fabsl(a);
    if (fabsl(b) > m) m = fabsl(b);
    if (fabsl(c) > m) m = fabsl(c);
    if (fabsl(d) > m) m = fabsl(d);
    return m;
}

void c2d_fuzz_check_conservation(const c2d_fuzz_response *x)
{
    long double ke0 = 0, ke1 = 0, ke_bound = 0, ke_mag = 0, frame[2];
    long double big = fabsl(x->n[0]) > fabsl(x->n[1]) ? fabsl(x->n[0]) : fabsl(x->n[1]);
    long double ux = x->n[0] / big, uy = x->n[1] / big, len = sqrtl(ux * ux + uy * uy);
    int i, j;
    for (j = 0; j < 2; j++) {
        long double dx = x->w[2 * j] - x->v[2 * j], dy = x->w[2 * j + 1] - x->v[2 * j + 1];
        long double across = fabsl(dx * uy - dy * ux) / len;
        long double bound = 1.5L * x->delta[j] + 8 * LDBL_EPSILON * (fabsl(dx) + fabsl(dy));
        if (!(across <= bound))
            c2d_fuzz_fail("body %c: velocity change has %.3Lg across the normal > bound %.3Lg", "ab"[j], across,
                          bound);
    }
    for (i = 0; i < 2 && !x->immovable[0] && !x->immovable[1]; i++) {
        long double p0 = 0, p1 = 0, bound = 0, mag = 0;
        for (j = 0; j < 2; j++) {
            p0 += x->m[j] * x->v[2 * j + i];
            p1 += x->m[j] * x->w[2 * j + i];
            bound += x->m[j] * x->delta[j];
            mag += fabsl(x->m[j] * x->v[2 * j + i]) + fabsl(x->m[j] * x->w[2 * j + i]);
        }
        bound += 8 * LDBL_EPSILON * mag;
        if (!(fabsl(p1 - p0) <= bound))
            c2d_fuzz_fail("momentum %c: before %.21Lg after %.21Lg, |diff| %.3Lg > bound %.3Lg", "xy"[i], p0, p1,
                          fabsl(p1 - p0), bound);
    }
    /* Energy in the frame of an immovable body, if any: a moving wall does
     * work on what it hits, but the response is Galilean invariant. */
    frame[0] = frame[1] = 0;
    for (j = 0; j < 2; j++) {
        if (!x->immovable[j]) continue;
        if (x->w[2 * j] != x->v[2 * j] || x->w[2 * j + 1] != x->v[2 * j + 1])
            c2d_fuzz_fail("immovable body %c moved", "ab"[j]);
        frame[0] = x->v[2 * j], frame[1] = x->v[2 * j + 1];
    }
    for (j = 0; j < 2; j++) {
        long double scale = 0;
        if (x->immovable[j]) continue;
        for (i = 0; i < 2; i++) {
            long double v = x->v[2 * j + i] - frame[i], w = x->w[2 * j + i] - frame[i];
            ke0 += x->m[j] * v * v;
            ke1 += x->m[j] * w * w;
            if (fabsl(v) > scale) scale = fabsl(v);
            if (fabsl(w) > scale) scale = fabsl(w);
        }
        ke_bound += 2 * x->m[j] * x->delta[j] * (2 * scale + x->delta[j]);
    }
    ke_mag = ke0 + ke1;
    ke_bound += 8 * LDBL_EPSILON * ke_mag;
    /* ke0, ke1 are 2 KE: compare doubled energies against the doubled bound. */
    if (!(ke1 - ke0 <= ke_bound))
        c2d_fuzz_fail("energy gained: 2KE %.21Lg -> %.21Lg (+%.3Lg > bound %.3Lg)", ke0, ke1, ke1 - ke0, ke_bound);
}

void c2d_fuzz_fill_scales(c2d_fuzz_response *x, c2d_fuzz_fmt f)
{
    int j;
    for (j = 0; j < 2; j++) {
        x->scale[j] = c2d_fuzz_maxabs4(x->v[2 * j], x->v[2 * j + 1], x->w[2 * j], x->w[2 * j + 1]);
        x->delta[j] = 16 * c2d_fuzz_ulp(x->scale[j], f);
    }
}
