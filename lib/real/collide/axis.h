/* SPDX-License-Identifier: MIT */
/* real/collide/axis.h - template: impacts whose normal lies on an axis, every
 * output correctly rounded.  Needs real/collide/collide.h, real/arith/sign.h and
 * real/arith/round.h first.
 *
 * WHY
 *   Walls and rails are axis-aligned far more often than not, and a row of
 *   touching disks (Newton's cradle) collides along one axis.  There the
 *   exact answer is often representable - equal masses at e = 1 swap their
 *   normal velocities, a disk off an immovable wall at e = 1 has its normal
 *   velocity negated - and the general formula's |n|^2 and quotient would
 *   round it, leaving residual velocities of ~1e-16 that cause spurious
 *   micro-impacts.  So when one component of the normal is exactly zero,
 *   the library returns the correctly rounded result instead.
 *
 * THE FORMULA
 *   With the normal along axis i (sign s), only the i components u change:
 *       ua' = [ua (ma - e mb) + (1 + e) mb ub] / (ma + mb)
 *           = (ua ma + ub mb + e mb (ub - ua)) / (ma + mb),
 *       ub' = (ub mb + ua ma + e ma (ua - ub)) / (ma + mb),
 *   and against an immovable b (mb = INFINITY) ua' = ub + e (ub - ua), ub'
 *   = ub.  They approach when s (ub - ua) < 0, a comparison of two inputs:
 *   exact.  The other component is returned as it was, bit for bit.
 *
 * CHEAP WHEN IT CAN BE
 *   Equal masses at e = 1: a swap.  A wall at e = 1: 2 ub - ua, one
 *   rounding.  A wall at rest: -e ua, one rounding; at e = 0, ub itself.
 *   Otherwise the filter of real/arith/round.h first: the result in double
 *   length, ua' = ua + mb J and ub' = ub - ma J with the impulse per unit
 *   mass J = (1 + e)(ub - ua) / (ma + mb) computed once for both, kept when
 *   its error bound keeps it clear of every rounding boundary.  Only where it
 *   is not are numerator and denominator formed as exact sums of products
 *   (real/arith/sign.h) and the quotient rounded once (real/arith/round.h).
 */
#ifndef C2D_REAL_AXIS_H
#define C2D_REAL_AXIS_H

/* atom[n..] += sign x y z exactly: x y as two extended parts (TwoProduct on
 * the significands, so nothing over- or underflows), each times z. */
static int c2d_push_triple(c2d_ext *atom, int n, c2d_real x, c2d_real y, c2d_real z, int sign)
{
    c2d_ext xx, yy, zz, hi, lo;
    c2d_real l, h;
    c2d_ext_set(&xx, sign < 0 ? -x : x, 0);
    c2d_ext_set(&yy, y, 0);
    c2d_ext_set(&zz, z, 0);
    h = c2d_two_prod(xx.m, yy.m, &l);
    c2d_ext_set(&hi, h, xx.e + yy.e);
    c2d_ext_set(&lo, l, xx.e + yy.e);
    n = c2d_push_product(atom, n, hi, zz);
    return c2d_push_product(atom, n, lo, zz);
}

/* *u2 = the correctly rounded (u mine + v theirs + e theirs (v - u)) /
 * (mine + theirs): one body's normal velocity after the impact, both masses
 * finite. */
static void c2d_axis_pair(c2d_real *u2, c2d_real u, c2d_real v, c2d_real mine, c2d_real theirs, c2d_real e)
{
    c2d_ext num[16], den[2]; /* four triple products, four atoms each */
    int n = 0;
    n = c2d_push_triple(num, n, u, mine, 1, 1);
    n = c2d_push_triple(num, n, v, theirs, 1, 1);
    n = c2d_push_triple(num, n, e, theirs, v, 1);
    n = c2d_push_triple(num, n, e, theirs, u, -1);
    c2d_ext_set(&den[0], mine, 0);
    c2d_ext_set(&den[1], theirs, 0);
    c2d_round_quotient(u2, num, n, den, 2);
}

/* *u2 = the correctly rounded v + e (v - u): off an immovable body moving
 * at v. */
static void c2d_axis_wall(c2d_real *u2, c2d_real u, c2d_real v, c2d_real e)
{
    c2d_ext num[12], den[1];
    int n = 0;
    if (e == 1 && c2d_abs(v) <= C2D_R_MAX / 2) {
        *u2 = 2 * v - u; /* 2v exact: one rounding */
        return;
    }
    if (v == 0) {
        *u2 = -e * u; /* one rounding */
        return;
    }
    if (e == 0) {
        *u2 = v; /* exact */
        return;
    }
    if (c2d_filter_wall(u2, u, v, e) != 0) return;
    n = c2d_push_triple(num, n, v, 1, 1, 1);
    n = c2d_push_triple(num, n, e, v, 1, 1);
    n = c2d_push_triple(num, n, e, u, 1, -1);
    c2d_ext_set(&den[0], 1, 0);
    c2d_round_quotient(u2, num, n, den, 1);
}

/* The normal velocities (ua, ub) after the impact, correctly rounded. */
static void c2d_axis_velocities(c2d_real *ua, c2d_real *ub, c2d_real ma, c2d_real mb, c2d_real e)
{
    const c2d_real u = *ua, v = *ub;
    if (mb > C2D_R_MAX) {
        c2d_axis_wall(ua, u, v, e);
    } else if (ma > C2D_R_MAX) {
        c2d_axis_wall(ub, v, u, e);
    } else if (ma == mb && e == 1) {
        *ua = v; /* a swap */
        *ub = u;
    } else {
        const c2d_real uv[2] = {u, v};
        c2d_real jh, jl;
        const int quick = c2d_filter_impulse(&jh, &jl, uv, ma, mb, e);
        if (quick == 0 || c2d_filter_apply(ua, u, mb, jh, jl) == 0) c2d_axis_pair(ua, u, v, ma, mb, e);
        if (quick == 0 || c2d_filter_apply(ub, v, -ma, jh, jl) == 0) c2d_axis_pair(ub, v, u, mb, ma, e);
    }
}

/* An impact whose normal has one zero component (both zero: degenerate):
 * `axis` the other component's index, `sign` its sign.  `given` is
 * c2d_collide_normal's normal (it must be finite), NULL for c2d_collide,
 * whose sign comes from comparing the positions: exact even where their
 * difference overflows.  Validation in status priority first. */
C2D_COLD c2d_status c2d_axis_impact(c2d_real_body *a, c2d_real_body *b, const c2d_real_vec *given, int axis, int sign,
                                    c2d_real restitution)
{
    c2d_status s = c2d_validate(a, b, restitution);
    c2d_real *va, *vb, ua, ub;
    if (s == C2D_INVALID || (given != NULL && !c2d_finite4(given->x, given->y, 0, 0))) return C2D_INVALID;
    if (s != C2D_OK || a == b || sign == 0) return C2D_DEGENERATE;
    va = axis == 0 ? &a->vel.x : &a->vel.y;
    vb = axis == 0 ? &b->vel.x : &b->vel.y;
    ua = *va;
    ub = *vb;
    if (!(sign > 0 ? ub < ua : ub > ua)) return C2D_SEPARATING;
    c2d_axis_velocities(&ua, &ub, a->mass, b->mass, restitution);
    if (!c2d_finite4(ua, ub, 0, 0)) return C2D_RANGE;
    *va = ua;
    *vb = ub;
    return C2D_OK;
}

#endif /* C2D_REAL_AXIS_H */
