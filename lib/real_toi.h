/* real_toi.h - template: c2d_time_of_impact, two disks moving with constant
 * velocities.  Needs real_bits.h and real_exact.h first.
 *
 * DERIVATION
 *   With d = pb - pa and v = vb - va, the disks touch when |d + v t| = R,
 *   i.e. a t^2 + 2 b t + c = 0 with a = v.v, b = d.v, c = d.d - R^2.  They
 *   approach only if b < 0; the first contact is the smaller root.
 *   The textbook discriminant b^2 - ac cancels catastrophically for disks
 *   far apart relative to their size.  Lagrange's identity
 *   (d.v)^2 + (d x v)^2 = |d|^2 |v|^2 turns it into
 *       b^2 - ac = a R^2 - (d x v)^2 = a (R - h)(R + h),
 *   h = |d x v| / |v| the miss distance, so the only cancellation left is
 *   the intrinsic one of a grazing miss (h ~ R).  They miss when h > R.
 *   The smaller root in the stable form (no subtraction of near-equal
 *   terms, since b < 0):
 *       t = c / (-b + sqrt(b^2 - ac)),   c = (|d| - R)(|d| + R),
 *   is accurate to a few ulp plus the time one rounding of |d| is worth at
 *   the approach speed at contact.  Overlapping (|d| <= R) and approaching
 *   gives t = 0.
 *
 * RANGE
 *   d and v are each taken exactly (TwoSum, as double-doubles) and scaled by
 *   a power of two so their largest component lies in [1, 4); R scales with
 *   d.  Then no square or product can overflow or underflow harmfully, and
 *   t scales back by 2^(kd - kv) with a single rounding.
 */
#ifndef C2D_REAL_TOI_H
#define C2D_REAL_TOI_H

/* The exact difference (x1 - x0, y1 - y0) as a double-double vector h + l
 * scaled by 2^-k, where k is chosen from the larger component so both lie
 * in [0, 4).  Returns k, or C2D_NO_EXP for a zero difference. */
static int c2d_scaled_diff2(c2d_real x1, c2d_real x0, c2d_real y1, c2d_real y0, c2d_real *h, c2d_real *l)
{
    c2d_xf hx, lx, hy, ly;
    int k;
    c2d_exact_diff(x1, x0, &hx, &lx);
    c2d_exact_diff(y1, y0, &hy, &ly);
    if (hx.m == 0 && hy.m == 0) return C2D_NO_EXP;
    k = hx.m == 0 ? hy.e : (hy.m == 0 ? hx.e : (hx.e > hy.e ? hx.e : hy.e));
    h[0] = c2d_scale2(hx.m, hx.e - k);
    l[0] = c2d_scale2(lx.m, lx.e - k);
    h[1] = c2d_scale2(hy.m, hy.e - k);
    l[1] = c2d_scale2(ly.m, ly.e - k);
    return k;
}

static c2d_status c2d_real_time_of_impact(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum,
                                          c2d_real *t)
{
    c2d_real dh[2], dl[2], vh[2], vl[2], crossh[2], crossl[2];
    c2d_real rad, dist, speed, dv, cross, h, c, disc, tt;
    int kd, kv;
    if (a == NULL || b == NULL || t == NULL) return C2D_INVALID;
    if (!c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y) || !c2d_finite4(a->vel.x, a->vel.y, b->vel.x, b->vel.y) ||
        !(radius_sum >= 0 && radius_sum <= C2D_R_MAX))
        return C2D_INVALID;
    kv = c2d_scaled_diff2(b->vel.x, a->vel.x, b->vel.y, a->vel.y, vh, vl);
    if (kv == C2D_NO_EXP) return C2D_SEPARATING; /* no relative motion */
    kd = c2d_scaled_diff2(b->pos.x, a->pos.x, b->pos.y, a->pos.y, dh, dl);
    if (kd == C2D_NO_EXP) return C2D_SEPARATING; /* coincident: not approaching */
    /* In units of 2^kd for lengths and 2^kv for speeds, both vectors have
     * their largest component in [1, 4): squares and products are safe. */
    dv = c2d_dot_dd(dh, dl, vh, vl);
    rad = c2d_scale2(radius_sum, -kd); /* Inf when far larger than |d|: overlapping */
    dist = C2D_R_SQRT(dh[0] * dh[0] + dh[1] * dh[1] + 2 * (dh[0] * dl[0] + dh[1] * dl[1]));
    if (dist <= rad) {
        if (dv >= 0) return C2D_SEPARATING;
        *t = 0;
        return C2D_OK;
    }
    if (dv >= 0) return C2D_SEPARATING;
    speed = C2D_R_SQRT(vh[0] * vh[0] + vh[1] * vh[1] + 2 * (vh[0] * vl[0] + vh[1] * vl[1]));
    /* d x v = dx vy - dy vx, as a dot product of (-dy, dx) with (vx, vy). */
    crossh[0] = -dh[1];
    crossh[1] = dh[0];
    crossl[0] = -dl[1];
    crossl[1] = dl[0];
    cross = c2d_abs(c2d_dot_dd(crossh, crossl, vh, vl));
    h = cross / speed;
    if (h > rad) return C2D_SEPARATING; /* misses */
    c = (dist - rad) * (dist + rad);
    disc = speed * C2D_R_SQRT((rad - h) * (rad + h));
    tt = c / (disc - dv);
    tt = c2d_scale2(tt, kd - kv);
    if (!(tt <= C2D_R_MAX)) return C2D_RANGE;
    *t = tt;
    return C2D_OK;
}

#endif /* C2D_REAL_TOI_H */
