/* SPDX-License-Identifier: MIT */
/* fixed.c - the Q16.16 API: the collision and the time of impact in integer
 * arithmetic only (int32/int64; on 32-bit cores the compiler's 64-bit
 * helpers), for cores without a floating-point unit.
 *
 * COLLISION
 *   The impulse form of docs/METHOD.md with a unit normal, so that every
 *   quantity has a fixed scale: u = n/|n| is formed with an integer square
 *   root in Q2.28 (n first normalised so max(|nx|, |ny|) is in [2^29, 2^30),
 *   so |n|^2 < 2^61), the normal speed vn = (vb - va).u, the impulse per
 *   unit of reduced mass (1 + e) vn, the weights wa = mb/(ma + mb) and
 *   wb = ma/(ma + mb) in Q0.28, and
 *       va' = va + (1 + e) vn wa u,    vb' = vb - (1 + e) vn wb u.
 *   Every product is formed in int64 and rounded to nearest once; a result
 *   outside int32 is C2D_RANGE, never a wrap-around.
 *
 * TIME OF IMPACT
 *   As in real/toi.h: with d = pb - pa, v = vb - va and the miss distance
 *   h = |d x v| / |v|, the earliest contact is t = c / (-d.v + |v| sqrt(R^2 - h^2))
 *   with c = (|d| - R)(|d| + R).  d (with R) and v are each scaled by a power
 *   of two so their largest component has 29 bits; t scales back by the
 *   difference of the two exponents in the final long division.
 */
#include "internal.h"

#ifndef C2D_NO_FIXED

enum {
    C2D_Q = 16,         /* fraction bits of c2d_fixed */
    C2D_UNIT_BITS = 28  /* unit normal and weights in Q2.28 / Q0.28 */
};

static int64_t c2d_abs64(int64_t x) { return x < 0 ? -x : x; }

/* Round x / 2^s to nearest, ties away from zero, symmetric in sign (a plain
 * arithmetic shift would round negative values differently). */
static int64_t c2d_round_shift(int64_t x, int s)
{
    int64_t half = (int64_t)1 << (s - 1);
    return x >= 0 ? (x + half) >> s : -((-x + half) >> s);
}

static int64_t c2d_round_div(int64_t num, int64_t den)
{
    int64_t q = c2d_abs64(num) / den;
    int64_t r = c2d_abs64(num) % den;
    if (2 * r >= den) q += 1;
    return num < 0 ? -q : q;
}

static uint64_t c2d_isqrt64(uint64_t x)
{
    uint64_t root = 0, bit = (uint64_t)1 << 62;
    while (bit > x) bit >>= 2;
    while (bit != 0) {
        if (x >= root + bit) {
            x -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return root;
}

/* Scale (x, y) by a power of two so max(|x|, |y|) lies in [2^(bits-1), 2^bits);
 * returns the exponent applied (positive: shifted left). */
static int c2d_normalize64(int64_t *x, int64_t *y, int bits)
{
    int shift = 0;
    int64_t big = c2d_abs64(*x) > c2d_abs64(*y) ? c2d_abs64(*x) : c2d_abs64(*y);
    const int64_t lo = (int64_t)1 << (bits - 1), hi = (int64_t)1 << bits;
    while (big < lo) { big *= 2; shift++; }
    while (big >= hi) { big /= 2; shift--; }
    if (shift > 0) {
        *x *= (int64_t)1 << shift;
        *y *= (int64_t)1 << shift;
    } else if (shift < 0) {
        *x = c2d_round_shift(*x, -shift);
        *y = c2d_round_shift(*y, -shift);
    }
    return shift;
}

static int c2d_mass_validx(c2d_fixed m) { return m > 0; }

static c2d_status c2d_validatex(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed e)
{
    if (a == NULL || b == NULL) return C2D_INVALID;
    if (!c2d_mass_validx(a->mass) || !c2d_mass_validx(b->mass)) return C2D_INVALID;
    if (e < 0 || e > C2D_FIXED_ONE) return C2D_INVALID;
    if (a->mass == C2D_FIXED_INFINITE_MASS && b->mass == C2D_FIXED_INFINITE_MASS)
        return C2D_DEGENERATE;
    return C2D_OK;
}

static int c2d_fits32(int64_t v) { return v >= INT32_MIN && v <= INT32_MAX; }

static c2d_status c2d_resolvex(c2d_bodyx *a, c2d_bodyx *b, int64_t nx, int64_t ny, c2d_fixed e)
{
    const int64_t one28 = (int64_t)1 << C2D_UNIT_BITS;
    int64_t len, ux, uy, vn, imp, wa, wb, dva, dvb, ax, ay, bx, by;
    if (nx == 0 && ny == 0) return C2D_DEGENERATE;
    (void)c2d_normalize64(&nx, &ny, 30);
    len = (int64_t)c2d_isqrt64((uint64_t)(nx * nx + ny * ny));
    ux = c2d_round_div(nx * one28, len);
    uy = c2d_round_div(ny * one28, len);
    /* |vb - va| < 2^33 and |u| <= 2^28: each product < 2^61, no overflow. */
    vn = ((int64_t)b->vel.x - a->vel.x) * ux + ((int64_t)b->vel.y - a->vel.y) * uy;
    vn = c2d_round_shift(vn, C2D_UNIT_BITS);
    if (vn >= 0) return C2D_SEPARATING;
    imp = c2d_round_shift((C2D_FIXED_ONE + (int64_t)e) * vn, C2D_Q); /* |imp| < 2^34 */
    if (a->mass == C2D_FIXED_INFINITE_MASS) {
        wa = 0;
        wb = one28;
    } else if (b->mass == C2D_FIXED_INFINITE_MASS) {
        wa = one28;
        wb = 0;
    } else {
        int64_t sum = (int64_t)a->mass + b->mass;
        wa = c2d_round_div((int64_t)b->mass * one28, sum);
        wb = c2d_round_div((int64_t)a->mass * one28, sum);
    }
    dva = c2d_round_shift(imp * wa, C2D_UNIT_BITS);
    dvb = c2d_round_shift(imp * wb, C2D_UNIT_BITS);
    ax = a->vel.x + c2d_round_shift(dva * ux, C2D_UNIT_BITS);
    ay = a->vel.y + c2d_round_shift(dva * uy, C2D_UNIT_BITS);
    bx = b->vel.x - c2d_round_shift(dvb * ux, C2D_UNIT_BITS);
    by = b->vel.y - c2d_round_shift(dvb * uy, C2D_UNIT_BITS);
    if (!c2d_fits32(ax) || !c2d_fits32(ay) || !c2d_fits32(bx) || !c2d_fits32(by))
        return C2D_RANGE;
    a->vel.x = (c2d_fixed)ax;
    a->vel.y = (c2d_fixed)ay;
    b->vel.x = (c2d_fixed)bx;
    b->vel.y = (c2d_fixed)by;
    return C2D_OK;
}

c2d_status c2d_collidex(c2d_bodyx *a, c2d_bodyx *b, c2d_fixed restitution)
{
    c2d_status s = c2d_validatex(a, b, restitution);
    if (s != C2D_OK) return s;
    return c2d_resolvex(a, b, (int64_t)b->pos.x - a->pos.x, (int64_t)b->pos.y - a->pos.y,
                        restitution);
}

c2d_status c2d_collide_normalx(c2d_bodyx *a, c2d_bodyx *b, c2d_vec2x normal, c2d_fixed restitution)
{
    c2d_status s = c2d_validatex(a, b, restitution);
    if (s != C2D_OK) return s;
    return c2d_resolvex(a, b, normal.x, normal.y, restitution);
}

/* floor(num * 2^shift / den) for num, den > 0, saturated at INT64_MAX;
 * shift may be negative.  Long division, so num * 2^shift never overflows. */
static int64_t c2d_div_shifted(uint64_t num, uint64_t den, int shift)
{
    uint64_t q = num / den, r = num % den;
    if (shift < 0) return (int64_t)(shift <= -63 ? 0 : q >> -shift);
    while (shift-- > 0) {
        if (q > ((uint64_t)INT64_MAX >> 1)) return INT64_MAX;
        q <<= 1;
        r <<= 1; /* r < den < 2^63, so no overflow */
        if (r >= den) {
            r -= den;
            q |= 1;
        }
    }
    return (int64_t)q;
}

c2d_status c2d_time_of_impactx(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed radius_sum, c2d_fixed *t)
{
    int64_t dx, dy, vx, vy, rad, dist, speed, dv, cross, h, c, root, den, tq;
    int sd, sv;
    if (a == NULL || b == NULL || t == NULL || radius_sum < 0) return C2D_INVALID;
    dx = (int64_t)b->pos.x - a->pos.x;
    dy = (int64_t)b->pos.y - a->pos.y;
    vx = (int64_t)b->vel.x - a->vel.x;
    vy = (int64_t)b->vel.y - a->vel.y;
    if (vx == 0 && vy == 0) return C2D_SEPARATING;
    if (dx == 0 && dy == 0) return C2D_SEPARATING; /* coincident: not approaching */
    /* Positions and the radius scale together (t is invariant); velocities
     * separately (t scales by 2^(sv - sd)). */
    rad = radius_sum;
    sd = c2d_normalize64(&dx, &dy, 29);
    if (sd >= 0) {
        if (rad > ((int64_t)1 << 31) >> sd) { /* radius_sum >> |d|: deeply overlapping */
            rad = (int64_t)1 << 31;
        } else {
            rad <<= sd;
        }
    } else {
        rad = c2d_round_shift(rad, -sd);
    }
    sv = c2d_normalize64(&vx, &vy, 29);
    dist = (int64_t)c2d_isqrt64((uint64_t)(dx * dx + dy * dy));
    dv = dx * vx + dy * vy;
    if (dist <= rad) {
        if (dv >= 0) return C2D_SEPARATING;
        *t = 0;
        return C2D_OK;
    }
    if (dv >= 0) return C2D_SEPARATING;
    speed = (int64_t)c2d_isqrt64((uint64_t)(vx * vx + vy * vy));
    cross = c2d_abs64(dx * vy - dy * vx);
    h = cross / speed;
    if (h > rad) return C2D_SEPARATING;
    c = (dist - rad) * (dist + rad);
    root = speed * (int64_t)c2d_isqrt64((uint64_t)((rad - h) * (rad + h)));
    den = -dv + root;
    tq = c2d_div_shifted((uint64_t)c, (uint64_t)den, C2D_Q + sv - sd);
    if (tq > INT32_MAX) return C2D_RANGE;
    *t = (c2d_fixed)tq;
    return C2D_OK;
}
#endif /* C2D_NO_FIXED */
