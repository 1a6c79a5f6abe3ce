/* SPDX-License-Identifier: MIT */
/* real/toia/num.h - template, accelerated time of impact: the types (the
 * problem, certified values, evaluations, the local frame, brackets), the
 * double-length time helpers, and exact sums of products in a sliding
 * exponent window rounded to double length.  Numbers m 2^e are
 * real/arith/bits.h's c2d_ext, times (h + l) 2^e real/arith/dd.h's c2d_dd
 * (double length, unbounded exponent).  The method and the files:
 * real/toia/README.md; the derivation: real/toia/solve.h.  Needs
 * real/arith/bits.h, real/arith/exact.h, real/arith/sign.h and
 * real/arith/dd.h first. */
#ifndef C2D_REAL_TOIA_NUM_H
#define C2D_REAL_TOIA_NUM_H
/* ===================================================================== */
/* Types and internal constants                                          */
/* ===================================================================== */

enum { C2D_TOIA_ATOMS = 32 }; /* atoms of an exact sum, at most (the signs at 0: h(0) = |v|^2 + d0.a) */
enum { C2D_TOIA_DATOMS = 14 }; /* atoms of d(t) at a working-precision time */
/* Exact-sum window: atoms scaled by at least 2^-C2D_TOIA_WIN of the largest
 * stay normal, so their TwoSum chain is exact; the window's sum is accepted
 * when it exceeds the (at most 2^5) atoms below the window by 2^DOM, far
 * below u^2. */
enum { C2D_TOIA_WIN = -C2D_R_EMIN - 4, C2D_TOIA_DOM = 2 * C2D_R_MANT + 12 };
/* Newton / bisection iteration caps (never reached in tests; a safety net). */
enum { C2D_TOIA_ITER = 200, C2D_TOIA_POLISH = 16 };

/* Which quantity: f = |d|^2 - R^2, g = d.d' = f'/2, h = g' = |d'|^2 + d.a,
 * hp = h' = 3 d'.a. */
enum { C2D_TOIA_QF = 0, C2D_TOIA_QG = 1, C2D_TOIA_QH = 2, C2D_TOIA_QHP = 3 };
enum { C2D_TOIA_MF = 1, C2D_TOIA_MG = 2, C2D_TOIA_MH = 4, C2D_TOIA_MHP = 8 };

/* Internal verdict of the scan; never mixed with c2d_status. */
typedef enum c2d_toia_verdict {
    C2D_TOIA_NONE, /* no contact in [0, horizon] */
    C2D_TOIA_HIT   /* contact at the time returned */
} c2d_toia_verdict;

/* A certified value: the exact quantity lies in
 * [value - bound, value + bound] 2^exp. */
typedef struct c2d_toia_bounded {
    c2d_real value, bound;
    int exp;
} c2d_toia_bounded;

/* One evaluation at a time: f, g, h, hp (indexed by C2D_TOIA_Q*) with
 * bounds, the signs certified so far (+1, -1, or 0 = not certified) and the
 * tier that produced qty. */
typedef struct c2d_toia_values {
    c2d_toia_bounded qty[4];
    c2d_real fmag, gmag, hmag; /* |d|^2 + R^2, sum |d_i d'_i|, |d'|^2 + sum |d_i a_i| (their units) */
    int sign[4];
    int tier;
} c2d_toia_values;

/* The problem: d0 = pb - pa, v = vb - va, a = ab - aa (k = 0, 1, 2) as
 * vectors of their exact differences' hi and lo parts on one scale
 * 2^exp[k] (largest hi component in [1, 2); a part far below may round or
 * vanish there, which the error floors cover), nonzero[k] = the vector is
 * not zero, and the radius R.  The exact paths take the parts as extended
 * numbers straight from the inputs kept here (c2d_toia_part), each vector's
 * formed once, on first use, in *parts (an ordinary pair never asks), as
 * are the four exact sums of products the splits ask for again and again. */
typedef struct c2d_toia_parts {
    c2d_ext x[3][2][2]; /* [vector][axis][hi, lo] */
    c2d_dd dot[4];      /* the exact sums of c2d_toia_dot_inputs, likewise */
    unsigned ready;     /* bit k: x[k] formed; bit 3 + s: dot[s] formed */
} c2d_toia_parts;

typedef struct c2d_toia_ctx {
    c2d_real hi[3][2], lo[3][2];
    int exp[3], nonzero[3];
    c2d_ext radius;
    const c2d_real_body *body_a, *body_b;
    const c2d_real_vec *acc_a, *acc_b;
    c2d_toia_parts *parts;
} c2d_toia_ctx;

/* A local frame for plain-arithmetic Newton iterations on an interval
 * [0, 2^time_exp): lengths in units of 2^kl (c2d_toia_frame_set), times in
 * units of 2^time_exp; rounded copies of d0, v, a, a/2 and R^2 there. */
typedef struct c2d_toia_frame {
    c2d_real pos[2], vel[2], acc[2], half_acc[2], radius2;
    int time_exp;
} c2d_toia_frame;

/* f and g at a time, certified (as in c2d_toia_values): what a bracket keeps. */
typedef struct c2d_toia_fg {
    c2d_toia_bounded f, g;
    int sign_f, sign_g;
} c2d_toia_fg;

/* A g-root bracket: g changes sign on [lo, hi]; f and g at both ends. */
typedef struct c2d_toia_bracket {
    c2d_dd lo, hi;
    c2d_toia_fg at_lo, at_hi;
} c2d_toia_bracket;

/* ===================================================================== */
/* Extended numbers and times: helpers                                   */
/* ===================================================================== */

/* 2^k clamped into the normal range.  Below it the result is 2^EMIN,
 * larger than the true factor by at most that: callers' error floors
 * (a few 2^EMIN in scaled units) cover it. */
static c2d_real c2d_toia_pow2_clamped(int k)
{
    if (k < C2D_R_EMIN) return c2d_pow2(C2D_R_EMIN);
    if (k > C2D_R_EMAX) return c2d_pow2(C2D_R_EMAX);
    return c2d_pow2(k);
}

static int c2d_toia_sign_of(c2d_real x) { return (x > 0) - (x < 0); }

static int c2d_toia_max_int(int a, int b) { return a > b ? a : b; }

/* floor(a / b) for b > 0 (C's / truncates toward zero). */
static int c2d_toia_floor_div(int a, int b)
{
    int q = a / b;
    return (q * b > a) ? q - 1 : q;
}

/* sign(a - b). */
static int c2d_toia_time_cmp(const c2d_dd *a, const c2d_dd *b)
{
    c2d_real ah, al, bh, bl, s, err;
    int k;
    if (a->h == 0) return -c2d_toia_sign_of(b->h);
    if (b->h == 0) return c2d_toia_sign_of(a->h);
    k = a->e - b->e;
    if (k > 3) return c2d_toia_sign_of(a->h);
    if (k < -3) return -c2d_toia_sign_of(b->h);
    ah = a->h;
    al = a->l;
    bh = b->h;
    bl = b->l;
    if (k > 0) { /* |k| <= 3: scaling by 2^-k is exact unless subnormal */
        bh = c2d_scale2(bh, -k);
        bl = c2d_scale2(bl, -k);
    } else if (k < 0) {
        ah = c2d_scale2(ah, k);
        al = c2d_scale2(al, k);
    }
    s = c2d_two_sum(ah, -bh, &err);
    err += al - bl;
    return c2d_toia_sign_of(s + err);
}

/* t += dm 2^de, in double length. */
static void c2d_toia_time_add(c2d_dd *t, c2d_real dm, int de)
{
    c2d_ext d;
    c2d_real s, err, dv;
    int k;
    c2d_ext_set(&d, dm, de);
    if (d.m == 0) return;
    if (t->h == 0) {
        c2d_dd_set(t, d.m, 0, d.e);
        return;
    }
    k = d.e - t->e;
    if (k < -(2 * C2D_R_MANT + 8)) return; /* below t's low part */
    if (k > 2 * C2D_R_MANT + 8) {          /* t below d's low part */
        c2d_dd_set(t, d.m, 0, d.e);
        return;
    }
    dv = c2d_scale2(d.m, k);
    s = c2d_two_sum(t->h, dv, &err);
    c2d_dd_set(t, s, err + t->l, t->e);
}

/* The time rounded to the working format, or C2D_R_MAX * 2 (Inf) beyond it. */
static c2d_real c2d_toia_time_value(const c2d_dd *t)
{
    if (t->h == 0) return 0;
    if (t->e > C2D_R_EMAX) return C2D_R_MAX * 2;
    return c2d_dd_value(t);
}

/* Double-length arithmetic on (h + l) 2^e (the classical double-double
 * algorithms with an exponent; each within a few u^2). */
static void c2d_toia_time_sum(c2d_dd *r, const c2d_dd *a, const c2d_dd *b)
{
    const c2d_real pa[2] = {a->h, a->l}, pb[2] = {b->h, b->l};
    const int k = a->e - b->e;
    if (b->h != 0 && (a->h == 0 || k < -(2 * C2D_R_MANT + 8))) {
        c2d_dd_copy(r, b);
    } else if (b->h == 0 || k > 2 * C2D_R_MANT + 8) {
        c2d_dd_copy(r, a);
    } else {
        c2d_dd_sum_aligned(r, pa, a->e, pb, b->e);
    }
}

/* Geometric or arithmetic midpoint of a < b (both >= 0), for bisection:
 * arithmetic when b < 4a, else 2^((ea + eb) / 2), with a == 0 taken as
 * the smallest positive time 2^(eb - 3 MANT) below which nothing is
 * resolved (bisection of [0, b] then reaches every scale in a few dozen
 * steps; the Newton phase does the rest). */
static void c2d_toia_time_mid(c2d_dd *m, const c2d_dd *a, const c2d_dd *b)
{
    int ea = a->h == 0 ? b->e - 4 * C2D_R_MANT : a->e;
    if (a->h != 0 && b->e - a->e <= 1) {
        c2d_real h, l;
        int k = b->e - a->e; /* 0 or 1 */
        h = c2d_two_sum(c2d_scale2(a->h, -k), b->h, &l);
        l += c2d_scale2(a->l, -k) + b->l;
        c2d_dd_set(m, h, l, b->e - 1);
        return;
    }
    c2d_dd_set(m, (c2d_real)1.5, 0, c2d_toia_floor_div(ea + b->e, 2));
}
/* ===================================================================== */
/* Exact sums of products (Shewchuk expansions in a sliding window)      */
/* ===================================================================== */

/* Append sgn * x * y * 2^shift as (at most) two atoms, exactly: the
 * significands' product is hi + lo by TwoProduct (both in [1, 4) or
 * a multiple of 2^-2MANT: neither over- nor underflows). */
static int c2d_toia_push_product(c2d_real *m, int *e, int n, const c2d_ext *x, const c2d_ext *y, int shift, int sgn)
{
    c2d_real lo, hi;
    c2d_ext z;
    if (x->m == 0 || y->m == 0) return n;
    hi = c2d_two_prod(x->m, y->m, &lo);
    if (sgn < 0) {
        hi = -hi;
        lo = -lo;
    }
    c2d_ext_set(&z, hi, x->e + y->e + shift);
    m[n] = z.m;
    e[n] = z.e;
    n++;
    if (lo != 0) {
        c2d_ext_set(&z, lo, x->e + y->e + shift);
        m[n] = z.m;
        e[n] = z.e;
        n++;
    }
    return n;
}

/* Append sgn * x as one atom. */
static int c2d_toia_push_atom(c2d_real *m, int *e, int n, const c2d_ext *x, int sgn)
{
    if (x->m == 0) return n;
    m[n] = sgn < 0 ? -x->m : x->m;
    e[n] = x->e;
    return n + 1;
}

/* The exact sum of the n atoms m[i] 2^e[i] (normalised: |m| in [1, 2)),
 * rounded to double length: returns E with (*hi + *lo) 2^E equal to the sum
 * within a relative (2 *k + 2) u^2, u = 2^-(MANT+1) (*k = the number of
 * exact components rounded), *hi in [1, 2); *hi == 0 exactly when the sum
 * is 0, and sign(*hi) is the exact sign.  Atoms within C2D_TOIA_WIN binades
 * of the largest are scaled into one window (exactly: they stay normal) and
 * summed exactly; if that sum exceeds 2^(DOM - WIN) of the window's top, the
 * atoms below the window (each < 2^-WIN of the top, fewer than 2^5) change
 * it by less than 2^(5 - DOM) relative, far below u^2, and it is returned;
 * otherwise its components rejoin the rest and the next window starts at
 * the new largest atom (at least WIN - DOM binades lower, so this ends).
 * Works in place: the window's atoms are moved to the front and the
 * expansion grows over them (after reading atom j it has at most j + 1
 * components), the others behind.  The atoms are overwritten. */
C2D_COLD int c2d_toia_exact_sum(c2d_real *m, int *e, int n, c2d_real *hi, c2d_real *lo, int *k_out)
{
    for (;;) {
        int i, j, k = 0, nw = 0, top = 0, found = 0;
        c2d_real h = 0, l = 0;
        for (i = 0; i < n; i++) {
            if (m[i] != 0 && (found == 0 || e[i] > top)) {
                top = e[i];
                found = 1;
            }
        }
        if (found == 0) {
            *hi = 0;
            *lo = 0;
            *k_out = 0;
            return 0;
        }
        /* partition: window atoms (scaled) to the front, the rest behind */
        for (i = 0; i < n; i++) {
            if (m[i] != 0 && e[i] >= top - C2D_TOIA_WIN) {
                c2d_real x = m[i];
                int ei = e[i];
                m[i] = m[nw];
                e[i] = e[nw];
                m[nw] = c2d_scale2(x, ei - top);
                e[nw] = 0;
                nw++;
            }
        }
        for (j = 0; j < nw; j++) k = c2d_grow(m, k, m[j]);
        /* Round the exact components (increasing, nonoverlapping) to
         * double length: all but the largest sum to less than an ulp of the
         * largest, so adding them in plain arithmetic errs by at most
         * 2 (k - 1) u^2 of the total, and one TwoSum renormalises. */
        if (k > 0) {
            for (i = 0; i + 1 < k; i++) l += m[i];
            h = c2d_two_sum(m[k - 1], l, &l);
        }
        if (nw == n || (h != 0 && c2d_ilogb(h) >= C2D_TOIA_DOM - C2D_TOIA_WIN)) {
            if (h == 0) {
                *hi = 0;
                *lo = 0;
                *k_out = 0;
                return 0;
            }
            i = c2d_ilogb(h); /* normalise: *hi in [1, 2) */
            *hi = c2d_scale2(h, -i);
            *lo = c2d_scale2(l, -i);
            *k_out = k;
            return top + i;
        }
        /* the window's components become atoms again, the rest follow */
        for (i = 0; i < k; i++) {
            c2d_ext z;
            c2d_ext_set(&z, m[i], top);
            m[i] = z.m;
            e[i] = z.e;
        }
        for (i = nw; i < n; i++) {
            m[k] = m[i];
            e[k] = e[i];
            k++;
        }
        n = k;
    }
}

#endif /* C2D_REAL_TOIA_NUM_H */
