/* collide2d.c - exact, robust 2-D collisions between disks.  See collide2d.h.
 *
 * THE PHYSICS
 *   Two disks a, b with velocities va, vb and masses ma, mb touch; n is any
 *   vector from a towards b (the line of centres).  The contact force acts
 *   along n only, so an impulse J along the unit normal n^ = n/|n| changes
 *       va' = va - (J/ma) n^,    vb' = vb + (J/mb) n^,
 *   which conserves momentum (ma va + mb vb) for any J and leaves both
 *   tangential components untouched.  Newton's law of restitution fixes J:
 *       (vb' - va').n^ = -e (vb - va).n^
 *   =>  J = -(1 + e) (vb - va).n^ / (1/ma + 1/mb).
 *   Writing d = (vb - va).n (note: n, not n^), |n|^2 = n.n and the weights
 *       wa = mb / (ma + mb),   wb = ma / (ma + mb)      (wa + wb = 1)
 *   gives the form implemented here, which needs no square root:
 *       va' = va + (1 + e) wa (d / n.n) n
 *       vb' = vb - (1 + e) wb (d / n.n) n
 *   An impact happens only if the bodies approach: d < 0.  An immovable body
 *   (mass INFINITY) has weight 0 and the other weight 1.  With e = 1 the kinetic
 *   energy is conserved; with ma = mb and e = 1 the normal components are
 *   swapped, which is the seed document's method.
 *
 * THE SEED'S ERRATUM
 *   The seed's final summary (equal masses, e = 1) writes, e.g.,
 *       v1fx = [v2x nx^2 + v2y nx ny - v1x nx ny + v1y nx^2] / |n|^2
 *   i.e. it multiplies the tangential speed v1t by ut_y instead of ut_x for the
 *   x component (and the mirror mistake for y).  For a = (0,0) moving (1,0)
 *   hitting b = (1,1) at rest it yields a' = (-0.5,-0.5), b' = (0.5,0.5):
 *   momentum (1,0) becomes (0,0).  The correct expansion (ut = (-ny, nx)/|n|) is
 *       v1fx = [v2x nx^2 + v2y nx ny + v1x ny^2 - v1y nx ny] / |n|^2
 *       v1fy = [v2x nx ny + v2y ny^2 - v1x nx ny + v1y nx^2] / |n|^2
 *       v2fx = [v1x nx^2 + v1y nx ny + v2x ny^2 - v2y nx ny] / |n|^2
 *       v2fy = [v1x nx ny + v1y ny^2 - v2x nx ny + v2y nx^2] / |n|^2
 *   which is exactly the formula above with ma = mb, e = 1 and gives
 *   a' = (0.5,-0.5), b' = (0.5,0.5).
 *
 * WHY EACH ROBUSTNESS STEP EXISTS
 *   The accuracy promise is relative to each body's OWN velocity scale, so a
 *   heavy body's tiny velocity change, or a light body at rest hit by a fast
 *   heavy one, must come out accurate on its own scale.  Three things break
 *   naive code, and each has a guard below:
 *   1. Cancellation in d = (vb - va).n.  In a grazing impact the two products
 *      (vb-va)_x n_x and (vb-va)_y n_y nearly cancel, so the rounding of
 *      vb - va, of n = pb - pa and of the products (each relative to the LARGE
 *      terms) swamps d.  The result the light body sees is d itself, so its
 *      relative error must be small.  The fast path measures the cancellation
 *      (kappa = (|p_x| + |p_y|) / |d|) and accepts only kappa <= 4.  Otherwise
 *      d is recomputed from the exact differences (TwoSum) and exact products
 *      (TwoProduct) as a double-double; if even that leaves fewer than ~40 good
 *      bits, the general path sums the exact product terms as an exact
 *      floating-point expansion (Shewchuk), so the sign of d - and thus
 *      OK versus SEPARATING - is always exact.
 *   2. Overflow and underflow of intermediates: |n|^2, (vb - va), products,
 *      ma + mb, the mass ratio (1e600 is not a double).  The fast path runs
 *      only when every intermediate is provably within a safe window; the
 *      general path carries each quantity as mantissa x 2^exponent with an
 *      int exponent, so nothing over- or underflows until the final velocity
 *      change is scaled to its body with one rounding.
 *   3. Cancellation between the mass factors: wa = 1 - wb loses the heavy
 *      body's tiny weight.  Both weights are computed as quotients, in the
 *      general path as r/(1+r) and 1/(1+r) with r = m_light/m_heavy <= 1.
 *   All three paths evaluate the same formula, so results are continuous
 *   across the path boundaries; the fast path (and the batch kernel, which is
 *   the same inline code) is branch-free.
 *
 * TIME OF IMPACT
 *   With d = pb - pa and v = vb - va, solve |d + v t| = R for the smaller
 *   root.  The textbook discriminant b^2 - ac (b = d.v, a = v.v,
 *   c = d.d - R^2) cancels catastrophically for far-apart disks.  By
 *   Lagrange's identity b^2 - ac = a R^2 - (d x v)^2 = a (R - h)(R + h) with
 *   h = |d x v| / |v| the miss distance, so no cancellation remains except the
 *   intrinsic one at a grazing miss (h ~ R).  The root is taken in the stable
 *   form t = c / (-b + sqrt(disc)) with c = (|d| - R)(|d| + R), so t is
 *   accurate to a few ulp plus the time to close one rounding of |d|.  d and
 *   v are scaled by powers of two first, so nothing overflows.
 *
 * Q16.16
 *   The same formula in integers: the unit normal is formed with an integer
 *   square root in Q2.28, weights in Q0.28, all products in int64 with
 *   explicit rounding; results outside int32 give C2D_RANGE, never wrap.
 *
 * The double and float variants are one source: this file includes itself
 * once per floating type with the type's parameters defined (C2D_TEMPLATE).
 */
#ifndef C2D_TEMPLATE

#ifdef C2D_HEADER
#include C2D_HEADER
#else
#include "../include/collide2d.h"
#endif
#include <float.h>

/* The only outside symbols (time of impact).  Declared here, not through
 * <math.h>, so the library builds freestanding. */
#ifndef C2D_NO_DOUBLE
double sqrt(double x);
#endif
#ifndef C2D_NO_FLOAT
float sqrtf(float x);
#endif

long c2d_version(void) { return C2D_VERSION; }

const char *c2d_status_string(c2d_status status)
{
    switch (status) {
    case C2D_OK: return "ok";
    case C2D_SEPARATING: return "separating";
    case C2D_DEGENERATE: return "degenerate";
    case C2D_INVALID: return "invalid";
    case C2D_RANGE: return "range";
    default: return "unknown";
    }
}

/* The fast path must inline into each caller: called, it passes 11
 * doubles, more than the registers hold, and costs a third of the work. */
#ifdef __GNUC__
#define C2D_HOT static inline __attribute__((always_inline))
#define C2D_COLD static __attribute__((noinline))
#else
#define C2D_HOT static inline
#define C2D_COLD static
#endif

/* Internal result of the fast path: its inputs are outside its safe window. */
#define C2D_NEED_GENERAL 99
/* Internal: inside the window, but d cancels; recompute d in double-double. */
#define C2D_NEED_ACCURATE 98
/* "No exponent": a zero vector (int is >= 16 bits; real exponents stay
 * within +-2300). */
#define C2D_NO_EXP (-32767)

#define C2D_TEMPLATE 1
#ifndef C2D_NO_DOUBLE
#define R double
#define U uint64_t
#define FN(name) name
#define RC(x) x
#define R_MANT 52
#define R_EBIAS 1023
#define R_EMAX 1023
#define R_EMIN (-1022)
#define R_MAX DBL_MAX
#define R_SPLIT 134217729.0 /* 2^27 + 1 */
#ifdef __GNUC__ /* -ffreestanding implies -fno-builtin: ask for the FPU instruction */
#define R_SQRT __builtin_sqrt
#else
#define R_SQRT sqrt
#endif
#define R_FABS __builtin_fabs
#define R_EXP_K 900  /* fast window: |products| summed in [2^-900, 2^900] */
#define R_EXP_KAPPA2 41 /* double-double d trusted if kappa <= 2^41 */
#define R_WINDOW 600 /* exact-sum window, binades */
#define R_MARGIN 70  /* window sum must dominate the rest by 2^70 */
#if defined(__FP_FAST_FMA) && defined(__GNUC__)
#define R_HAS_FMA 1
#else
#define R_HAS_FMA 0
#endif
#define R_FMA __builtin_fma
#define BODY c2d_body
#define VEC c2d_vec2
#define PAIRS c2d_pairs
#include "collide2d.c"
#undef R
#undef U
#undef FN
#undef RC
#undef R_MANT
#undef R_EBIAS
#undef R_EMAX
#undef R_EMIN
#undef R_MAX
#undef R_SPLIT
#undef R_SQRT
#undef R_FABS
#undef R_EXP_K
#undef R_EXP_KAPPA2
#undef R_WINDOW
#undef R_MARGIN
#undef R_HAS_FMA
#undef R_FMA
#undef BODY
#undef VEC
#undef PAIRS
#endif

#ifndef C2D_NO_FLOAT
#define R float
#define U uint32_t
#define FN(name) name##f
#define RC(x) x##f
#define R_MANT 23
#define R_EBIAS 127
#define R_EMAX 127
#define R_EMIN (-126)
#define R_MAX FLT_MAX
#define R_SPLIT 4097.0f /* 2^12 + 1 */
#ifdef __GNUC__
#define R_SQRT __builtin_sqrtf
#else
#define R_SQRT sqrtf
#endif
#define R_FABS __builtin_fabsf
#define R_EXP_K 90
#define R_EXP_KAPPA2 12
#define R_WINDOW 72
#define R_MARGIN 36
#if defined(__FP_FAST_FMAF) && defined(__GNUC__)
#define R_HAS_FMA 1
#else
#define R_HAS_FMA 0
#endif
#define R_FMA __builtin_fmaf
#define BODY c2d_bodyf
#define VEC c2d_vec2f
#define PAIRS c2d_pairsf
#include "collide2d.c"
#endif
#undef C2D_TEMPLATE

#ifndef C2D_NO_FIXED
/* ------------------------------------------------------------------ Q16.16 */

#define C2D_Q 16
#define C2D_UNIT_BITS 28 /* unit normal and weights in Q2.28 / Q0.28 */

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

#else /* C2D_TEMPLATE: the floating-point body, instantiated per type */

/* ----------------------------------------------------- bits and exponents */

typedef union FN(c2d_pun) { R f; U u; } FN(c2d_pun);

static inline U FN(c2d_bits)(R x)
{
    FN(c2d_pun) p;
    p.f = x;
    return p.u;
}

static inline R FN(c2d_from_bits)(U u)
{
    FN(c2d_pun) p;
    p.u = u;
    return p.f;
}

#ifdef __GNUC__
static inline R FN(c2d_abs)(R x) { return R_FABS(x); } /* andpd, not a branch */
#else
static inline R FN(c2d_abs)(R x) { return x < 0 ? -x : x; }
#endif

/* 2^k for R_EMIN <= k <= R_EMAX, exactly. */
static inline R FN(c2d_pow2)(int k) { return FN(c2d_from_bits)((U)(k + R_EBIAS) << R_MANT); }

/* x * 2^k with a single rounding (only the last multiply can be inexact). */
static R FN(c2d_scale2)(R x, int k)
{
    if (k > R_EMAX) {
        x *= FN(c2d_pow2)(R_EMAX);
        k -= R_EMAX;
        if (k > R_EMAX) {
            x *= FN(c2d_pow2)(R_EMAX);
            k -= R_EMAX;
            if (k > R_EMAX) k = R_EMAX;
        }
    } else if (k < R_EMIN) {
        /* Step down while staying normal, so the final multiply rounds once. */
        x *= FN(c2d_pow2)(R_EMIN + R_MANT + 1);
        k -= R_EMIN + R_MANT + 1;
        if (k < R_EMIN) {
            x *= FN(c2d_pow2)(R_EMIN + R_MANT + 1);
            k -= R_EMIN + R_MANT + 1;
            if (k < R_EMIN) k = R_EMIN;
        }
    }
    return x * FN(c2d_pow2)(k);
}

/* floor(log2 |x|) for finite x != 0, subnormals included. */
static int FN(c2d_ilogb)(R x)
{
    int adjust = 0;
    int e = (int)((FN(c2d_bits)(x) >> R_MANT) & (U)(2 * R_EBIAS + 1));
    if (e == 0) { /* subnormal: scale into the normal range (exact) */
        adjust = R_MANT + 2;
        e = (int)((FN(c2d_bits)(x * FN(c2d_pow2)(adjust)) >> R_MANT) & (U)(2 * R_EBIAS + 1));
    }
    return e - R_EBIAS - adjust;
}

/* An extended-exponent number m * 2^e, |m| in [1, 2) or m == 0: nothing
 * a collision can produce over- or underflows in this form. */
typedef struct FN(c2d_xf) { R m; int e; } FN(c2d_xf);

static FN(c2d_xf) FN(c2d_xf_make)(R m, int e)
{
    FN(c2d_xf) r;
    if (m == 0) {
        r.m = 0;
        r.e = 0;
    } else {
        int k = FN(c2d_ilogb)(m);
        r.m = FN(c2d_scale2)(m, -k);
        r.e = e + k;
    }
    return r;
}

static R FN(c2d_xf_value)(FN(c2d_xf) x) { return FN(c2d_scale2)(x.m, x.e); }

/* *dst = src field by field: a struct assignment compiles to a memcpy call
 * at -Os on small cores, and the library must need no C library. */
static void FN(c2d_xf_copy)(FN(c2d_xf) *dst, const FN(c2d_xf) *src)
{
    dst->m = src->m;
    dst->e = src->e;
}

/* ------------------------------------------------ error-free transforms */

/* s + err == a + b exactly (Knuth's TwoSum; no overflow assumed). */
static R FN(c2d_two_sum)(R a, R b, R *err)
{
    R s = a + b;
    R bv = s - a;
    R av = s - bv;
    *err = (a - av) + (b - bv);
    return s;
}

/* p + err == a * b exactly, barring underflow of err (Dekker/Veltkamp, or a
 * fused multiply-add where the hardware has one: identical results). */
static R FN(c2d_two_prod)(R a, R b, R *err)
{
    R p = a * b;
#if R_HAS_FMA
    *err = R_FMA(a, b, -p);
#else
    R ca = R_SPLIT * a, cb = R_SPLIT * b;
    R ah = ca - (ca - a), bh = cb - (cb - b);
    R al = a - ah, bl = b - bh;
    *err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
    return p;
}

/* ---------------------------------------------------------- validation */

/* x - x is 0 for finite x and NaN for Inf/NaN, so a sum of such differences
 * is 0 exactly when every term is finite. */
static inline int FN(c2d_finite4)(R a, R b, R c, R d) { return ((a - a) + (b - b)) + ((c - c) + (d - d)) == 0; }

static int FN(c2d_mass_valid)(R m) { return m > 0; } /* NaN fails; INFINITY passes */

static c2d_status FN(c2d_validate)(const BODY *a, const BODY *b, R e)
{
    if (a == NULL || b == NULL) return C2D_INVALID;
    if (!FN(c2d_finite4)(a->pos.x, a->pos.y, b->pos.x, b->pos.y)) return C2D_INVALID;
    if (!FN(c2d_finite4)(a->vel.x, a->vel.y, b->vel.x, b->vel.y)) return C2D_INVALID;
    if (!FN(c2d_mass_valid)(a->mass) || !FN(c2d_mass_valid)(b->mass)) return C2D_INVALID;
    if (!(e >= 0 && e <= 1)) return C2D_INVALID;
    if (a->mass > R_MAX && b->mass > R_MAX) return C2D_DEGENERATE;
    return C2D_OK;
}

/* ----------------------------------------------------------- fast path */

/* x where keep is all ones, else 0, else 1.0 where one is all ones: a select
 * by bit masks.  Written with ?: on doubles, gcc threads the selects into
 * branches around the division below and the batch loop stops vectorising. */
C2D_HOT R FN(c2d_pick)(R x, U keep, U one)
{
    return FN(c2d_from_bits)((FN(c2d_bits)(x) & keep) | (FN(c2d_bits)(RC(1.0)) & one));
}

/* From an accurate d = (vb - va).n to the new velocities, in plain
 * arithmetic with one division: wa = mb/(ma+mb) is folded into
 * c = (1+e) d / (|n|^2 (ma+mb)), la = c mb, lb = c ma.  An INFINITY mass
 * becomes the pair (1, 0), which gives it weight 0 and the other weight 1.
 * out = {va'x, va'y, vb'x, vb'y}.  Returns nonzero when every intermediate
 * stayed in the range where it is accurate to its rounding (no overflow, no
 * underflow that a later step would magnify); the caller falls back otherwise. */
C2D_HOT U FN(c2d_finish)(R d, R nx, R ny, R ma, R mb, R e1, R vax, R vay, R vbx, R vby, R *out)
{
    const R lo = FN(c2d_pow2)(R_EMIN + 2), lo_nn = FN(c2d_pow2)(R_EMIN + R_MANT + 2);
    /* Truth values as U, the floating type's width: the vectoriser cannot
     * narrow a double comparison's 64-bit mask to an int. */
    const U ia = (U)(ma > R_MAX), ib = (U)(mb > R_MAX);
    /* a's mass as b feels it: 0 against an immovable b, 1 when a is immovable */
    const R fa = FN(c2d_pick)(ma, (U)0 - ((ia | ib) ^ 1u), (U)0 - (ia & (ib ^ 1u)));
    const R fb = FN(c2d_pick)(mb, (U)0 - ((ia | ib) ^ 1u), (U)0 - (ib & (ia ^ 1u)));
    const R nn = nx * nx + ny * ny;
    const R den = nn * (fa + fb);
    const R c = e1 * d / den;
    const R la = c * fb, lb = c * fa;
    const R ac = FN(c2d_abs)(c);
    out[0] = vax + la * nx;
    out[1] = vay + la * ny;
    out[2] = vbx - lb * nx;
    out[3] = vby - lb * ny;
    /* & rather than &&: one flag, no branches to mispredict.  A lambda may
     * be 0 only for an immovable body, never by underflow; two immovable
     * bodies and NaN masses (ma > 0 fails) are refused. */
    return (U)(ma > 0) & (U)(mb > 0) & ((ia & ib) ^ 1u) & (U)(nn >= lo_nn) & (U)(den >= lo) &
           (U)(den <= R_MAX) & (U)(ac >= lo) & (U)(ac <= R_MAX) & ((U)(FN(c2d_abs)(la) >= lo) | ia) &
           ((U)(FN(c2d_abs)(lb) >= lo) | ib) & (U)(FN(c2d_abs)(la) <= R_MAX) & (U)(FN(c2d_abs)(lb) <= R_MAX);
}

/* Flags of the fast path's verdict. */
#define C2D_F_WINDOW 1   /* every intermediate in its safe range */
#define C2D_F_CALM 2     /* little cancellation in d */
#define C2D_F_APPROACH 4 /* d < 0 */
#define C2D_F_FINITE 8   /* results finite */
#define C2D_F_ALL (C2D_F_WINDOW | C2D_F_CALM | C2D_F_APPROACH | C2D_F_FINITE)

/* Branch-free plain-arithmetic resolution for the common case: little
 * cancellation in d (|p_x| + |p_y| <= 4 |d| for p_i = (vb - va)_i n_i, so every
 * rounding in d is within a few ulp of d itself) and the products within
 * [2^-EXP_K, 2^EXP_K].  Returns C2D_F_* flags; `out` holds the answer when
 * all are set.  NaN, Inf, masses <= 0, a zero normal and two immovable
 * bodies all fail the window, so a set window flag implies valid inputs.
 * The batch kernel inlines exactly this function, so its results are
 * bit-identical to the scalar call; comparisons are combined with & and |
 * so that loop stays free of branches and vectorises. */
C2D_HOT U FN(c2d_fast_flags)(R nx, R ny, R vax, R vay, R vbx, R vby, R ma, R mb, R e1, R *out)
{
    const R k_lo = FN(c2d_pow2)(-R_EXP_K), k_hi = FN(c2d_pow2)(R_EXP_K);
    const R px = (vbx - vax) * nx, py = (vby - vay) * ny;
    const R d = px + py;
    const R k = FN(c2d_abs)(px) + FN(c2d_abs)(py);
    const U window = FN(c2d_finish)(d, nx, ny, ma, mb, e1, vax, vay, vbx, vby, out) & (U)(k >= k_lo) & (U)(k <= k_hi);
    const U calm = (U)(k <= 4 * FN(c2d_abs)(d));
    const U finite = (U)FN(c2d_finite4)(out[0], out[1], out[2], out[3]);
    return window | calm << 1 | (U)(d < 0) << 2 | finite << 3;
}

/* Flags to C2D_OK, C2D_SEPARATING, C2D_RANGE, C2D_NEED_ACCURATE (only the
 * cancellation test failed) or C2D_NEED_GENERAL. */
static inline int FN(c2d_fast_verdict)(U f)
{
    if (!(f & C2D_F_WINDOW)) return C2D_NEED_GENERAL;
    if (!(f & C2D_F_CALM)) return C2D_NEED_ACCURATE;
    if (!(f & C2D_F_APPROACH)) return C2D_SEPARATING;
    return (f & C2D_F_FINITE) ? C2D_OK : C2D_RANGE;
}

C2D_HOT int FN(c2d_fast)(R nx, R ny, R vax, R vay, R vbx, R vby, R ma, R mb, R e1, R *out)
{
    const U f = FN(c2d_fast_flags)(nx, ny, vax, vay, vbx, vby, ma, mb, e1, out);
    return f == C2D_F_ALL ? C2D_OK : FN(c2d_fast_verdict)(f);
}

/* ---------------------------------------------- exact sums (general path) */

/* Add b to the nonoverlapping expansion e[0..n) (increasing magnitude),
 * keeping it exact and nonoverlapping (Shewchuk's GROW-EXPANSION with zero
 * elimination).  Returns the new length (<= n + 1). */
static int FN(c2d_grow)(R *e, int n, R b)
{
    R q = b, h;
    int i, k = 0;
    for (i = 0; i < n; i++) {
        q = FN(c2d_two_sum)(q, e[i], &h);
        if (h != 0) e[k++] = h;
    }
    if (q != 0) e[k++] = q;
    return k;
}

#define C2D_ATOMS 40

/* Exact sum of up to C2D_ATOMS/2 extended numbers, returned rounded to an
 * extended number (error below 2^-R_MANT relative; the sign is exact).
 * Terms within R_WINDOW binades of the largest are summed exactly in one
 * scaled window; if that sum is too small to dominate the rest, its
 * components rejoin the rest and the next window starts lower. */
static FN(c2d_xf) FN(c2d_exact_sum)(FN(c2d_xf) *atom, int n)
{
    R ex[C2D_ATOMS];
    for (;;) {
        int i, k = 0, rest = 0, emax = C2D_NO_EXP;
        R approx = 0;
        for (i = 0; i < n; i++)
            if (atom[i].m != 0 && atom[i].e > emax) emax = atom[i].e;
        if (emax == C2D_NO_EXP) return FN(c2d_xf_make)(0, 0);
        for (i = 0; i < n; i++) {
            if (atom[i].m == 0) continue;
            if (atom[i].e >= emax - R_WINDOW) {
                k = FN(c2d_grow)(ex, k, FN(c2d_scale2)(atom[i].m, atom[i].e - emax));
            } else {
                FN(c2d_xf_copy)(&atom[rest++], &atom[i]);
            }
        }
        for (i = 0; i < k; i++) approx += ex[i];
        if (rest == 0 || (approx != 0 && FN(c2d_ilogb)(approx) > R_MARGIN - R_WINDOW))
            return FN(c2d_xf_make)(approx, emax);
        for (i = 0; i < k; i++) atom[rest++] = FN(c2d_xf_make)(ex[i], emax);
        n = rest;
    }
}

/* Append the exact product x * y of two extended numbers as two atoms. */
static int FN(c2d_push_product)(FN(c2d_xf) *atom, int n, FN(c2d_xf) x, FN(c2d_xf) y)
{
    R lo, hi = FN(c2d_two_prod)(x.m, y.m, &lo);
    atom[n++] = FN(c2d_xf_make)(hi, x.e + y.e);
    atom[n++] = FN(c2d_xf_make)(lo, x.e + y.e);
    return n;
}

/* ------------------------------------------------------- general path */

/* The exact difference x1 - x0 as (hi + lo) * 2^e, hi and lo as extended
 * numbers: halving first when the difference could overflow (exact for the
 * large operand, and what the small one loses is far below hi). */
static void FN(c2d_exact_diff)(R x1, R x0, FN(c2d_xf) *hi, FN(c2d_xf) *lo)
{
    int e = 0;
    R h, l;
    if (FN(c2d_abs)(x1) >= FN(c2d_pow2)(R_EMAX - 1) || FN(c2d_abs)(x0) >= FN(c2d_pow2)(R_EMAX - 1)) {
        x1 *= RC(0.5);
        x0 *= RC(0.5);
        e = 1;
    }
    h = FN(c2d_two_sum)(x1, -x0, &l);
    *hi = FN(c2d_xf_make)(h, e);
    *lo = FN(c2d_xf_make)(l, e);
}

/* Weights as extended numbers: r = m_light / m_heavy <= 1 (as extended, so
 * a ratio of 1e-600 is fine), w_heavy = r / (1 + r), w_light = 1 / (1 + r). */
static void FN(c2d_weights_x)(R ma, R mb, FN(c2d_xf) *wa, FN(c2d_xf) *wb)
{
    FN(c2d_xf) xa, xb, r, w_heavy, w_light;
    R onep;
    int a_heavy;
    if (ma > R_MAX || mb > R_MAX) {
        *wa = FN(c2d_xf_make)(ma > R_MAX ? RC(0.0) : RC(1.0), 0);
        *wb = FN(c2d_xf_make)(mb > R_MAX ? RC(0.0) : RC(1.0), 0);
        return;
    }
    xa = FN(c2d_xf_make)(ma, 0);
    xb = FN(c2d_xf_make)(mb, 0);
    a_heavy = xa.e > xb.e || (xa.e == xb.e && xa.m >= xb.m);
    r = a_heavy ? FN(c2d_xf_make)(xb.m / xa.m, xb.e - xa.e) : FN(c2d_xf_make)(xa.m / xb.m, xa.e - xb.e);
    onep = 1 + FN(c2d_xf_value)(r);
    w_heavy = FN(c2d_xf_make)(r.m / onep, r.e);
    w_light = FN(c2d_xf_make)(1 / onep, 0);
    FN(c2d_xf_copy)(wa, a_heavy ? &w_heavy : &w_light);
    FN(c2d_xf_copy)(wb, a_heavy ? &w_light : &w_heavy);
}

/* The general path: any finite inputs, the normal given exactly as
 * (nh + nl) per component in extended form.  Computes d exactly (sign exact,
 * value to < 1 ulp), everything else as extended numbers, and scales each
 * velocity change to its body once at the end. */
static c2d_status FN(c2d_general)(BODY *a, BODY *b, FN(c2d_xf) nh[2], FN(c2d_xf) nl[2], R e)
{
    FN(c2d_xf) atom[C2D_ATOMS], v[4], d, wa, wb, w[2];
    R nval[2], lval[2], nn, out[4];
    int i, j, n = 0, top;
    BODY *body[2];
    body[0] = a;
    body[1] = b;
    /* Only the normal's direction matters: shift its exponents so its
     * largest component is in [1, 2). */
    top = nh[0].m == 0 ? nh[1].e : (nh[1].m == 0 ? nh[0].e : (nh[0].e > nh[1].e ? nh[0].e : nh[1].e));
    for (i = 0; i < 2; i++) {
        nh[i].e -= top;
        nl[i].e -= top;
        nval[i] = FN(c2d_xf_value)(nh[i]);
        lval[i] = FN(c2d_xf_value)(nl[i]);
    }
    v[0] = FN(c2d_xf_make)(-a->vel.x, 0);
    v[1] = FN(c2d_xf_make)(-a->vel.y, 0);
    v[2] = FN(c2d_xf_make)(b->vel.x, 0);
    v[3] = FN(c2d_xf_make)(b->vel.y, 0);
    /* d = vb.n - va.n = sum over bodies and components of v_i (nh_i + nl_i). */
    for (j = 0; j < 4; j++) {
        n = FN(c2d_push_product)(atom, n, v[j], nh[j & 1]);
        n = FN(c2d_push_product)(atom, n, v[j], nl[j & 1]);
    }
    d = FN(c2d_exact_sum)(atom, n);
    if (d.m >= 0) return C2D_SEPARATING;
    nn = (nval[0] * nval[0] + nval[1] * nval[1]) + 2 * (nval[0] * lval[0] + nval[1] * lval[1]);
    FN(c2d_weights_x)(a->mass, b->mass, &wa, &wb);
    FN(c2d_xf_copy)(&w[0], &wa);
    FN(c2d_xf_copy)(&w[1], &wb);
    for (j = 0; j < 2; j++) {
        /* lambda = (1 + e) w d / |n|^2; dv = +-lambda n, scaled once. */
        R lm = ((1 + e) * d.m / nn) * w[j].m;
        int le = d.e + w[j].e;
        R sign = j == 0 ? RC(1.0) : RC(-1.0);
        R vel[2];
        vel[0] = body[j]->vel.x;
        vel[1] = body[j]->vel.y;
        for (i = 0; i < 2; i++) {
            R dv = w[j].m == 0 ? RC(0.0) : FN(c2d_scale2)(lm * nh[i].m, le + nh[i].e);
            out[2 * j + i] = vel[i] + sign * dv;
            if (!FN(c2d_finite4)(dv, out[2 * j + i], 0, 0)) return C2D_RANGE;
        }
    }
    a->vel.x = out[0];
    a->vel.y = out[1];
    b->vel.x = out[2];
    b->vel.y = out[3];
    return C2D_OK;
}

/* ----------------------------------------------------- accurate d (tier 2) */

/* d = (vb - va).(nh + nl) as a double-double: exact differences and exact
 * products, so the error is ~1 ulp of d plus ~u^2 of the terms. */
static R FN(c2d_dot2)(R nhx, R nhy, R nlx, R nly, R vax, R vay, R vbx, R vby)
{
    R rlx, rly, ex, ey, t;
    R rhx = FN(c2d_two_sum)(vbx, -vax, &rlx);
    R rhy = FN(c2d_two_sum)(vby, -vay, &rly);
    R px = FN(c2d_two_prod)(rhx, nhx, &ex);
    R py = FN(c2d_two_prod)(rhy, nhy, &ey);
    R s = FN(c2d_two_sum)(px, py, &t);
    R small = ((rhx * nlx + rlx * nhx) + (rhy * nly + rly * nhy)) + (rlx * nlx + rly * nly);
    return s + (t + ((ex + ey) + small));
}

/* Tier 2 for valid inputs with the normal given exactly as nh + nl (nl = 0
 * for a given normal): d in double-double, trusted if it kept R_EXP_KAPPA2
 * bits through the cancellation.  Same statuses as c2d_fast. */
static int FN(c2d_accurate)(BODY *a, BODY *b, R nhx, R nhy, R nlx, R nly, R e, R *out)
{
    const R k_lo = FN(c2d_pow2)(-R_EXP_K), k_hi = FN(c2d_pow2)(R_EXP_K);
    R rx = b->vel.x - a->vel.x, ry = b->vel.y - a->vel.y;
    R k = FN(c2d_abs)(rx * nhx) + FN(c2d_abs)(ry * nhy);
    R split = FN(c2d_abs)(rx) + FN(c2d_abs)(ry) + FN(c2d_abs)(nhx) + FN(c2d_abs)(nhy);
    R d;
    if (!(k >= k_lo && k <= k_hi && split <= FN(c2d_pow2)(R_EMAX / 2))) return C2D_NEED_GENERAL;
    d = FN(c2d_dot2)(nhx, nhy, nlx, nly, a->vel.x, a->vel.y, b->vel.x, b->vel.y);
    if (!(FN(c2d_abs)(d) * FN(c2d_pow2)(R_EXP_KAPPA2) >= k)) return C2D_NEED_GENERAL;
    if (!FN(c2d_finish)(d, nhx + nlx, nhy + nly, a->mass, b->mass, 1 + e,
                        a->vel.x, a->vel.y, b->vel.x, b->vel.y, out))
        return C2D_NEED_GENERAL;
    if (d >= 0) return C2D_SEPARATING;
    return FN(c2d_finite4)(out[0], out[1], out[2], out[3]) ? C2D_OK : C2D_RANGE;
}

/* The general path for valid inputs, the normal exact as nh + nl. */
static c2d_status FN(c2d_general_dd)(BODY *a, BODY *b, R nhx, R nhy, R nlx, R nly, R e)
{
    FN(c2d_xf) nh[2], nl[2];
    nh[0] = FN(c2d_xf_make)(nhx, 0);
    nh[1] = FN(c2d_xf_make)(nhy, 0);
    nl[0] = FN(c2d_xf_make)(nlx, 0);
    nl[1] = FN(c2d_xf_make)(nly, 0);
    return FN(c2d_general)(a, b, nh, nl, e);
}

static void FN(c2d_store)(BODY *a, BODY *b, const R *out)
{
    a->vel.x = out[0];
    a->vel.y = out[1];
    b->vel.x = out[2];
    b->vel.y = out[3];
}

/* ---------------------------------------------------------- public API */

/* Tiers 2 and 3 with the exact normal, for valid non-degenerate inputs. */
static c2d_status FN(c2d_resolve)(BODY *a, BODY *b, R nhx, R nhy, R nlx, R nly, R e)
{
    R out[4];
    int s = FN(c2d_accurate)(a, b, nhx, nhy, nlx, nly, e, out);
    if (s == C2D_NEED_GENERAL) return FN(c2d_general_dd)(a, b, nhx, nhy, nlx, nly, e);
    if (s == C2D_OK) FN(c2d_store)(a, b, out);
    return (c2d_status)s;
}

/* Everything the fast path declined: full validation in status priority,
 * then the exact normal. */
C2D_COLD c2d_status FN(c2d_collide_slow)(BODY *a, BODY *b, R restitution)
{
    R nhx, nhy, nlx, nly;
    c2d_status s = FN(c2d_validate)(a, b, restitution);
    if (s != C2D_OK) return s;
    if (a->pos.x == b->pos.x && a->pos.y == b->pos.y) return C2D_DEGENERATE;
    if (FN(c2d_abs)(a->pos.x) + FN(c2d_abs)(a->pos.y) + FN(c2d_abs)(b->pos.x) + FN(c2d_abs)(b->pos.y) >=
        FN(c2d_pow2)(R_EMAX - 2)) {
        /* Near the top of the range the difference may overflow: go general
         * with the exact difference carried in extended form. */
        FN(c2d_xf) nh[2], nl[2];
        FN(c2d_exact_diff)(b->pos.x, a->pos.x, &nh[0], &nl[0]);
        FN(c2d_exact_diff)(b->pos.y, a->pos.y, &nh[1], &nl[1]);
        return FN(c2d_general)(a, b, nh, nl, restitution);
    }
    nhx = FN(c2d_two_sum)(b->pos.x, -a->pos.x, &nlx);
    nhy = FN(c2d_two_sum)(b->pos.y, -a->pos.y, &nly);
    return FN(c2d_resolve)(a, b, nhx, nhy, nlx, nly, restitution);
}

/* Valid inputs (the fast window held) whose d cancels: only d needs the
 * exact normal.  Out of line, so the fast path keeps its registers. */
C2D_COLD c2d_status FN(c2d_collide_accurate)(BODY *a, BODY *b, R restitution)
{
    R nlx, nly;
    R nhx = FN(c2d_two_sum)(b->pos.x, -a->pos.x, &nlx);
    R nhy = FN(c2d_two_sum)(b->pos.y, -a->pos.y, &nly);
    return FN(c2d_resolve)(a, b, nhx, nhy, nlx, nly, restitution);
}

c2d_status FN(c2d_collide)(BODY *a, BODY *b, R restitution)
{
    R out[4];
    int s;
    if (a == NULL || b == NULL || !(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    s = FN(c2d_fast)(b->pos.x - a->pos.x, b->pos.y - a->pos.y, a->vel.x, a->vel.y, b->vel.x,
                     b->vel.y, a->mass, b->mass, 1 + restitution, out);
    if (s == C2D_NEED_ACCURATE) return FN(c2d_collide_accurate)(a, b, restitution);
    if (s == C2D_NEED_GENERAL) return FN(c2d_collide_slow)(a, b, restitution);
    if (s == C2D_OK) FN(c2d_store)(a, b, out);
    return (c2d_status)s;
}

/* What c2d_collide_normal's fast path declined, out of line. */
C2D_COLD c2d_status FN(c2d_collide_normal_slow)(BODY *a, BODY *b, R nx, R ny, R restitution, int verdict)
{
    c2d_status s;
    if (verdict == C2D_NEED_ACCURATE) return FN(c2d_resolve)(a, b, nx, ny, 0, 0, restitution);
    s = FN(c2d_validate)(a, b, restitution);
    if (s != C2D_OK) return s;
    if (!FN(c2d_finite4)(nx, ny, 0, 0)) return C2D_INVALID;
    if (nx == 0 && ny == 0) return C2D_DEGENERATE;
    return FN(c2d_resolve)(a, b, nx, ny, 0, 0, restitution);
}

c2d_status FN(c2d_collide_normal)(BODY *a, BODY *b, VEC normal, R restitution)
{
    R out[4];
    int s;
    if (a == NULL || b == NULL || !(restitution >= 0 && restitution <= 1)) return C2D_INVALID;
    if (!FN(c2d_finite4)(a->pos.x, a->pos.y, b->pos.x, b->pos.y)) return C2D_INVALID;
    s = FN(c2d_fast)(normal.x, normal.y, a->vel.x, a->vel.y, b->vel.x, b->vel.y, a->mass,
                     b->mass, 1 + restitution, out);
    if (s == C2D_NEED_ACCURATE || s == C2D_NEED_GENERAL)
        return FN(c2d_collide_normal_slow)(a, b, normal.x, normal.y, restitution, s);
    if (s == C2D_OK) FN(c2d_store)(a, b, out);
    return (c2d_status)s;
}

/* ------------------------------------------------------- batch kernel */

#define C2D_BLOCK 16

size_t FN(c2d_collide_batch)(const PAIRS *p, size_t count, R restitution, c2d_status *status)
{
    size_t base, done = 0;
    const int e_ok = restitution >= 0 && restitution <= 1;
    const R e1 = 1 + restitution;
    if (p == NULL) return 0;
    for (base = 0; base < count; base += C2D_BLOCK) {
        const R *pax = p->pos_ax + base, *pay = p->pos_ay + base;
        const R *pbx = p->pos_bx + base, *pby = p->pos_by + base;
        const R *vax = p->vel_ax + base, *vay = p->vel_ay + base;
        const R *vbx = p->vel_bx + base, *vby = p->vel_by + base;
        const R *ma = p->mass_a + base, *mb = p->mass_b + base;
        R out[4][C2D_BLOCK];
        U flags[C2D_BLOCK];
        size_t j, width = count - base < C2D_BLOCK ? count - base : C2D_BLOCK;
        const int kernel_ran = width == C2D_BLOCK && e_ok;
        if (kernel_ran != 0) {
            /* Fixed trip count, no branches: vectorised at -O2 by clang, and
             * by gcc 12 for float on baseline x86-64 and for double from
             * x86-64-v2 on (SSE2 has no 64-bit compare for the flag masks). */
            for (j = 0; j < C2D_BLOCK; j++) {
                R o[4];
                flags[j] = FN(c2d_fast_flags)(pbx[j] - pax[j], pby[j] - pay[j], vax[j], vay[j], vbx[j], vby[j],
                                              ma[j], mb[j], e1, o);
                out[0][j] = o[0];
                out[1][j] = o[1];
                out[2][j] = o[2];
                out[3][j] = o[3];
            }
        } else {
            for (j = 0; j < width; j++) flags[j] = 0; /* all to the scalar call */
        }
        for (j = 0; j < width; j++) {
            size_t i = base + j;
            int v = FN(c2d_fast_verdict)(flags[j]);
            c2d_status s = C2D_OK;
            if (v == C2D_SEPARATING || v == C2D_RANGE) {
                s = (c2d_status)v;
            } else if (v == C2D_OK) {
                p->vel_ax[i] = out[0][j];
                p->vel_ay[i] = out[1][j];
                p->vel_bx[i] = out[2][j];
                p->vel_by[i] = out[3][j];
            } else {
                /* The rest, exactly as the scalar call decides it: where the
                 * kernel ran, straight to the tier its verdict names (the
                 * scalar call would recompute the same fast path first). */
                BODY a, b;
                a.pos.x = pax[j], a.pos.y = pay[j], a.vel.x = vax[j], a.vel.y = vay[j], a.mass = ma[j];
                b.pos.x = pbx[j], b.pos.y = pby[j], b.vel.x = vbx[j], b.vel.y = vby[j], b.mass = mb[j];
                if (kernel_ran == 0)
                    s = FN(c2d_collide)(&a, &b, restitution);
                else if (v == C2D_NEED_ACCURATE)
                    s = FN(c2d_collide_accurate)(&a, &b, restitution);
                else
                    s = FN(c2d_collide_slow)(&a, &b, restitution);
                if (s == C2D_OK) {
                    p->vel_ax[i] = a.vel.x;
                    p->vel_ay[i] = a.vel.y;
                    p->vel_bx[i] = b.vel.x;
                    p->vel_by[i] = b.vel.y;
                }
            }
            if (s == C2D_OK) done++;
            if (status != NULL) status[i] = s;
        }
    }
    return done;
}

/* ----------------------------------------------------- time of impact */

/* The exact difference x1 - x0 as a double-double scaled by 2^-k, where k is
 * chosen from the larger of the two components so both fit in [0, 4). */
static int FN(c2d_scaled_diff2)(R x1, R x0, R y1, R y0, R *h, R *l)
{
    FN(c2d_xf) hx, lx, hy, ly;
    int k;
    FN(c2d_exact_diff)(x1, x0, &hx, &lx);
    FN(c2d_exact_diff)(y1, y0, &hy, &ly);
    if (hx.m == 0 && hy.m == 0) return C2D_NO_EXP;
    k = hx.m == 0 ? hy.e : (hy.m == 0 ? hx.e : (hx.e > hy.e ? hx.e : hy.e));
    h[0] = FN(c2d_scale2)(hx.m, hx.e - k);
    l[0] = FN(c2d_scale2)(lx.m, lx.e - k);
    h[1] = FN(c2d_scale2)(hy.m, hy.e - k);
    l[1] = FN(c2d_scale2)(ly.m, ly.e - k);
    return k;
}

/* x.y for double-double vectors, to about 2 ulp even under cancellation. */
static R FN(c2d_dot_dd)(const R *xh, const R *xl, const R *yh, const R *yl)
{
    R e0, e1, t;
    R p0 = FN(c2d_two_prod)(xh[0], yh[0], &e0);
    R p1 = FN(c2d_two_prod)(xh[1], yh[1], &e1);
    R s = FN(c2d_two_sum)(p0, p1, &t);
    return s + (t + (e0 + e1) + ((xh[0] * yl[0] + xl[0] * yh[0]) + (xh[1] * yl[1] + xl[1] * yh[1])));
}

c2d_status FN(c2d_time_of_impact)(const BODY *a, const BODY *b, R radius_sum, R *t)
{
    R dh[2], dl[2], vh[2], vl[2], crossh[2], crossl[2];
    R rad, dist, speed, dv, cross, h, c, disc, tt;
    int kd, kv;
    if (a == NULL || b == NULL || t == NULL) return C2D_INVALID;
    if (!FN(c2d_finite4)(a->pos.x, a->pos.y, b->pos.x, b->pos.y) ||
        !FN(c2d_finite4)(a->vel.x, a->vel.y, b->vel.x, b->vel.y) ||
        !(radius_sum >= 0 && radius_sum <= R_MAX))
        return C2D_INVALID;
    kv = FN(c2d_scaled_diff2)(b->vel.x, a->vel.x, b->vel.y, a->vel.y, vh, vl);
    if (kv == C2D_NO_EXP) return C2D_SEPARATING; /* no relative motion */
    kd = FN(c2d_scaled_diff2)(b->pos.x, a->pos.x, b->pos.y, a->pos.y, dh, dl);
    if (kd == C2D_NO_EXP) return C2D_SEPARATING; /* coincident: not approaching */
    /* In units of 2^kd for lengths and 2^kv for speeds, both vectors have
     * their largest component in [1, 4): squares and products are safe. */
    dv = FN(c2d_dot_dd)(dh, dl, vh, vl);
    rad = FN(c2d_scale2)(radius_sum, -kd); /* Inf when far larger than |d|: overlapping */
    dist = R_SQRT(dh[0] * dh[0] + dh[1] * dh[1] + 2 * (dh[0] * dl[0] + dh[1] * dl[1]));
    if (dist <= rad) {
        if (dv >= 0) return C2D_SEPARATING;
        *t = 0;
        return C2D_OK;
    }
    if (dv >= 0) return C2D_SEPARATING;
    speed = R_SQRT(vh[0] * vh[0] + vh[1] * vh[1] + 2 * (vh[0] * vl[0] + vh[1] * vl[1]));
    /* d x v = dx vy - dy vx, as a dot product of (dx, -dy) with (vy, vx). */
    crossh[0] = -dh[1];
    crossh[1] = dh[0];
    crossl[0] = -dl[1];
    crossl[1] = dl[0];
    cross = FN(c2d_abs)(FN(c2d_dot_dd)(crossh, crossl, vh, vl));
    h = cross / speed;
    if (h > rad) return C2D_SEPARATING; /* misses */
    c = (dist - rad) * (dist + rad);
    disc = speed * R_SQRT((rad - h) * (rad + h));
    tt = c / (disc - dv);
    tt = FN(c2d_scale2)(tt, kd - kv);
    if (!(tt <= R_MAX)) return C2D_RANGE;
    *t = tt;
    return C2D_OK;
}

#endif /* C2D_TEMPLATE */
