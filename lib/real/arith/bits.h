/* SPDX-License-Identifier: MIT */
/* real/arith/bits.h - template: the floating type's bits, exact powers of two, and
 * extended-exponent numbers.  Included once by double.c and by float.c after
 * they define the type's parameters:
 *   C2D_R_TYPE, C2D_R_BITS_TYPE   the type and an unsigned integer as wide
 *   C2D_R_BODY, C2D_R_VEC, C2D_R_PAIRS   its public body, vector, batch types
 *   C2D_R_DISK, C2D_R_SURFACE     its public rough disk and surface types
 *   C2D_R_MANT, C2D_R_EBIAS, C2D_R_EMAX, C2D_R_EMIN, C2D_R_MAX   the format
 *   C2D_R_SQRT(x)                 square root (__builtin_ on gcc)
 *   C2D_R_FABS(x)                 |x|, optional (__builtin_fabs on gcc)
 *   C2D_R_SPLIT, C2D_R_FMA        for TwoProduct (real/arith/exact.h); FMA optional
 *   C2D_R_EXP_K, C2D_R_EXP_KAPPA2, C2D_R_WINDOW, C2D_R_MARGIN   window sizes
 * The other real/ headers use the names declared here.
 *
 * WHY
 *   Robustness over the whole range needs exact powers of two (scaling is
 *   then error-free), the exponent of any finite value (subnormals included),
 *   and numbers whose exponent cannot overflow: m * 2^e with |m| in [1, 2)
 *   and an int e, so a mass ratio of 1e-600 or a product of two 1e300
 *   values is representable until the final result is scaled to its body
 *   with a single rounding.  All of it reads and writes the IEEE-754 bits
 *   directly: no libm (frexp/ldexp), so the library stays freestanding.
 */
#ifndef C2D_REAL_BITS_H
#define C2D_REAL_BITS_H

typedef C2D_R_TYPE c2d_real;
typedef C2D_R_BITS_TYPE c2d_real_bits;
typedef C2D_R_BODY c2d_real_body;
typedef C2D_R_VEC c2d_real_vec;
typedef C2D_R_PAIRS c2d_real_pairs;
typedef C2D_R_DISK c2d_real_disk;
typedef C2D_R_SURFACE c2d_real_surface;

typedef union c2d_pun { c2d_real f; c2d_real_bits u; } c2d_pun;

static inline c2d_real_bits c2d_bits(c2d_real x)
{
    c2d_pun p;
    p.f = x;
    return p.u;
}

static inline c2d_real c2d_from_bits(c2d_real_bits u)
{
    c2d_pun p;
    p.u = u;
    return p.f;
}

#ifdef C2D_R_FABS
static inline c2d_real c2d_abs(c2d_real x) { return C2D_R_FABS(x); } /* andpd, not a branch */
#else
static inline c2d_real c2d_abs(c2d_real x) { return x < 0 ? -x : x; }
#endif

/* 2^k for C2D_R_EMIN <= k <= C2D_R_EMAX, exactly. */
static inline c2d_real c2d_pow2(int k) { return c2d_from_bits((c2d_real_bits)(k + C2D_R_EBIAS) << C2D_R_MANT); }

/* x * 2^k with a single rounding (only the last multiply can be inexact). */
static c2d_real c2d_scale2(c2d_real x, int k)
{
    if (k > C2D_R_EMAX) {
        x *= c2d_pow2(C2D_R_EMAX);
        k -= C2D_R_EMAX;
        if (k > C2D_R_EMAX) {
            x *= c2d_pow2(C2D_R_EMAX);
            k -= C2D_R_EMAX;
            if (k > C2D_R_EMAX) k = C2D_R_EMAX;
        }
    } else if (k < C2D_R_EMIN) {
        /* Step down while staying normal, so the final multiply rounds once. */
        x *= c2d_pow2(C2D_R_EMIN + C2D_R_MANT + 1);
        k -= C2D_R_EMIN + C2D_R_MANT + 1;
        if (k < C2D_R_EMIN) {
            x *= c2d_pow2(C2D_R_EMIN + C2D_R_MANT + 1);
            k -= C2D_R_EMIN + C2D_R_MANT + 1;
            if (k < C2D_R_EMIN) k = C2D_R_EMIN;
        }
    }
    return x * c2d_pow2(k);
}

/* floor(log2 |x|) for finite x != 0, subnormals included. */
static int c2d_ilogb(c2d_real x)
{
    int adjust = 0;
    int e = (int)((c2d_bits(x) >> C2D_R_MANT) & (c2d_real_bits)(2 * C2D_R_EBIAS + 1));
    if (e == 0) { /* subnormal: scale into the normal range (exact) */
        adjust = C2D_R_MANT + 2;
        e = (int)((c2d_bits(x * c2d_pow2(adjust)) >> C2D_R_MANT) & (c2d_real_bits)(2 * C2D_R_EBIAS + 1));
    }
    return e - C2D_R_EBIAS - adjust;
}

/* x - x is 0 for finite x and NaN for Inf/NaN, so a sum of such differences
 * is 0 exactly when every term is finite. */
static inline int c2d_finite4(c2d_real a, c2d_real b, c2d_real c, c2d_real d)
{
    return ((a - a) + (b - b)) + ((c - c) + (d - d)) == 0;
}

/* An extended-exponent number m * 2^e, |m| in [1, 2) or m == 0: nothing
 * a collision can produce over- or underflows in this form. */
typedef struct c2d_ext { c2d_real m; int e; } c2d_ext;

static c2d_ext c2d_ext_make(c2d_real m, int e)
{
    c2d_ext r;
    if (m == 0) {
        r.m = 0;
        r.e = 0;
    } else {
        int k = c2d_ilogb(m);
        r.m = c2d_scale2(m, -k);
        r.e = e + k;
    }
    return r;
}

static c2d_real c2d_ext_value(c2d_ext x) { return c2d_scale2(x.m, x.e); }

/* *dst = src field by field: a struct assignment compiles to a memcpy call
 * at -Os on small cores, and the library must need no C library. */
static void c2d_ext_copy(c2d_ext *dst, const c2d_ext *src)
{
    dst->m = src->m;
    dst->e = src->e;
}

#endif /* C2D_REAL_BITS_H */
