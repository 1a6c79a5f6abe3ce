/* SPDX-License-Identifier: MIT */
/* real/collide/general.h - template: the general path of a collision, for any finite
 * inputs.  Needs real/arith/bits.h and real/arith/exact.h first.
 *
 * WHY IT EXISTS
 *   The fast path and tier 2 work in plain floating arithmetic and decline
 *   whatever could overflow, underflow or cancel.  This path takes the
 *   rest: normals from subnormal to DBL_MAX, mass ratios of 1e600,
 *   velocities near the top of the range, a d that cancels to nothing.
 *
 * HOW
 *   1. The normal arrives exactly as nh + nl per component (for
 *      c2d_collide, the TwoSum of the position difference), as extended
 *      numbers; only its direction matters, so its exponents are shifted to
 *      put the largest component in [1, 2).
 *   2. d = sum over the two bodies and two components of v_i (nh_i + nl_i):
 *      eight exact products (TwoProduct), summed exactly by the windowed
 *      expansion sum of real/arith/exact.h.  The sign of d is exact, its value
 *      correctly rounded to an extended number.
 *   3. Weights as quotients, never as 1 - w (which would lose the heavy
 *      body's tiny weight): with r = m_light / m_heavy <= 1 as an extended
 *      number, w_heavy = r / (1 + r), w_light = 1 / (1 + r).
 *   4. lambda_j = (1 + e) w_j d / |n|^2 as mantissa times 2^exponent, and
 *      each velocity change lambda_j n is scaled to its body once, so the
 *      only rounding that depends on the range is the last one.
 *   A change or result that overflows is C2D_RANGE; nothing is written.
 */
#ifndef C2D_REAL_GENERAL_H
#define C2D_REAL_GENERAL_H

/* Weights as extended numbers (step 3); an immovable body weighs 0. */
static void c2d_weights_ext(c2d_real ma, c2d_real mb, c2d_ext *wa, c2d_ext *wb)
{
    c2d_ext xa, xb, r, w_heavy, w_light;
    c2d_real onep;
    int a_heavy;
    if (ma > C2D_R_MAX || mb > C2D_R_MAX) {
        *wa = c2d_ext_make(ma > C2D_R_MAX ? (c2d_real)0.0 : (c2d_real)1.0, 0);
        *wb = c2d_ext_make(mb > C2D_R_MAX ? (c2d_real)0.0 : (c2d_real)1.0, 0);
        return;
    }
    xa = c2d_ext_make(ma, 0);
    xb = c2d_ext_make(mb, 0);
    a_heavy = xa.e > xb.e || (xa.e == xb.e && xa.m >= xb.m);
    r = a_heavy ? c2d_ext_make(xb.m / xa.m, xb.e - xa.e) : c2d_ext_make(xa.m / xb.m, xa.e - xb.e);
    onep = 1 + c2d_ext_value(r);
    w_heavy = c2d_ext_make(r.m / onep, r.e);
    w_light = c2d_ext_make(1 / onep, 0);
    c2d_ext_copy(wa, a_heavy ? &w_heavy : &w_light);
    c2d_ext_copy(wb, a_heavy ? &w_light : &w_heavy);
}

/* Step 1: shift the normal's exponents so its largest component is in [1, 2). */
static void c2d_normal_unit_exponent(c2d_ext nh[2], c2d_ext nl[2])
{
    int i;
    int top = nh[0].m == 0 ? nh[1].e : (nh[1].m == 0 ? nh[0].e : (nh[0].e > nh[1].e ? nh[0].e : nh[1].e));
    for (i = 0; i < 2; i++) {
        nh[i].e -= top;
        nl[i].e -= top;
    }
}

/* Step 2: d = (vb - va).(nh + nl), exact in sign. */
static c2d_ext c2d_exact_d(const c2d_real_body *a, const c2d_real_body *b, const c2d_ext nh[2], const c2d_ext nl[2])
{
    c2d_ext atom[C2D_ATOMS], v[4];
    int j, n = 0;
    v[0] = c2d_ext_make(-a->vel.x, 0);
    v[1] = c2d_ext_make(-a->vel.y, 0);
    v[2] = c2d_ext_make(b->vel.x, 0);
    v[3] = c2d_ext_make(b->vel.y, 0);
    for (j = 0; j < 4; j++) {
        n = c2d_push_product(atom, n, v[j], nh[j & 1]);
        n = c2d_push_product(atom, n, v[j], nl[j & 1]);
    }
    return c2d_exact_sum(atom, n);
}

/* The general path: any finite inputs, the normal exact as nh + nl. */
static c2d_status c2d_general(c2d_real_body *a, c2d_real_body *b, c2d_ext nh[2], c2d_ext nl[2], c2d_real e)
{
    c2d_ext d, w[2];
    c2d_real nval[2], lval[2], nn, out[4];
    int i, j;
    c2d_real_body *body[2];
    body[0] = a;
    body[1] = b;
    c2d_normal_unit_exponent(nh, nl);
    for (i = 0; i < 2; i++) {
        nval[i] = c2d_ext_value(nh[i]);
        lval[i] = c2d_ext_value(nl[i]);
    }
    d = c2d_exact_d(a, b, nh, nl);
    if (d.m >= 0) return C2D_SEPARATING;
    nn = (nval[0] * nval[0] + nval[1] * nval[1]) + 2 * (nval[0] * lval[0] + nval[1] * lval[1]);
    c2d_weights_ext(a->mass, b->mass, &w[0], &w[1]);
    for (j = 0; j < 2; j++) {
        /* Step 4: lambda = (1 + e) w d / |n|^2; dv = +-lambda n, scaled once. */
        c2d_real lm = ((1 + e) * d.m / nn) * w[j].m;
        int le = d.e + w[j].e;
        c2d_real sign = j == 0 ? (c2d_real)1.0 : (c2d_real)-1.0;
        c2d_real vel[2];
        vel[0] = body[j]->vel.x;
        vel[1] = body[j]->vel.y;
        for (i = 0; i < 2; i++) {
            c2d_real dv = w[j].m == 0 ? (c2d_real)0.0 : c2d_scale2(lm * nh[i].m, le + nh[i].e);
            /* weight 0: the immovable body, its velocity as given (-0 too) */
            out[2 * j + i] = w[j].m == 0 ? vel[i] : vel[i] + sign * dv;
            if (!c2d_finite4(dv, out[2 * j + i], 0, 0)) return C2D_RANGE;
        }
    }
    a->vel.x = out[0];
    a->vel.y = out[1];
    b->vel.x = out[2];
    b->vel.y = out[3];
    return C2D_OK;
}

/* The general path with the normal exact as the floating pair nh + nl. */
static c2d_status c2d_general_pair(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *nh, const c2d_real_vec *nl,
                                   c2d_real e)
{
    c2d_ext xh[2], xl[2];
    xh[0] = c2d_ext_make(nh->x, 0);
    xh[1] = c2d_ext_make(nh->y, 0);
    xl[0] = c2d_ext_make(nl->x, 0);
    xl[1] = c2d_ext_make(nl->y, 0);
    return c2d_general(a, b, xh, xl, e);
}

#endif /* C2D_REAL_GENERAL_H */
