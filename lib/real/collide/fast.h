/* SPDX-License-Identifier: MIT */
/* real/collide/fast.h - template: the branch-free fast path of a collision, shared
 * by the scalar calls and the batch kernel.  Needs real/arith/bits.h first.
 *
 * THE FORMULA (docs/METHOD.md derives it)
 *   With n any vector from a towards b, d = (vb - va).n, weights
 *   wa = mb/(ma + mb), wb = ma/(ma + mb) and e1 = 1 + e:
 *       va' = va + e1 wa (d / n.n) n,    vb' = vb - e1 wb (d / n.n) n.
 *   One division: c = e1 d / (n.n (ma + mb)), then la = c mb, lb = c ma, and
 *   va' = va + la n, vb' = vb - lb n.  An immovable body (mass INFINITY)
 *   takes the mass pair (1, 0): weight 0 for itself, 1 for the other.
 *
 * WHEN PLAIN ARITHMETIC IS ACCURATE
 *   d = px + py with p_i = (vb - va)_i n_i.  Each p_i carries a few
 *   roundings relative to |p_i|, so d is accurate to a few ulp of itself
 *   when kappa = (|px| + |py|) / |d| is small; the path accepts kappa <= 4
 *   (the test k <= 4 |d| with k = |px| + |py|).  Every later step is one
 *   multiplication or division, accurate to its rounding as long as nothing
 *   overflows or underflows: the path checks that k lies in
 *   [2^-C2D_R_EXP_K, 2^C2D_R_EXP_K], that n.n, n.n (ma + mb), c, la and lb
 *   are normal, and that the results are finite.  NaN fails every
 *   comparison, so NaN and Inf inputs, masses <= 0, a zero normal and two
 *   immovable bodies all fall outside the window: a set window flag implies
 *   valid inputs.  Each condition is a flag combined with & and |, so the
 *   code has no branches and the batch loop vectorises.
 */
#ifndef C2D_REAL_FAST_H
#define C2D_REAL_FAST_H

/* One pair as the fast path reads it. */
typedef struct c2d_pair {
    c2d_real_vec n;      /* normal from a towards b, any length */
    c2d_real_vec va, vb; /* velocities */
    c2d_real ma, mb;     /* masses; INFINITY is immovable */
} c2d_pair;

/* The fast path's findings, one bit each; all four set means resolved. */
enum c2d_fast_flag {
    C2D_F_WINDOW = 1,   /* every intermediate in its safe range */
    C2D_F_CALM = 2,     /* little cancellation in d */
    C2D_F_APPROACH = 4, /* d < 0 */
    C2D_F_FINITE = 8,   /* results finite */
    C2D_F_ALL = 15
};

/* x where keep is all ones, else 0, else 1.0 where one is all ones: a select
 * by bit masks.  Written with ?: on floating values, gcc threads the selects
 * into branches around the division and the batch loop stops vectorising. */
C2D_HOT c2d_real c2d_pick(c2d_real x, c2d_real_bits keep, c2d_real_bits one)
{
    return c2d_from_bits((c2d_bits(x) & keep) | (c2d_bits((c2d_real)1.0) & one));
}

/* x, or `old` where `immovable` is 1: a bit-mask select, branch-free for
 * the vectoriser (an immovable body keeps its velocity's bits: -0 stays
 * -0, which x = old + 0 would not keep). */
C2D_HOT c2d_real c2d_keep(c2d_real x, c2d_real old, c2d_real_bits immovable)
{
    const c2d_real_bits keep = (c2d_real_bits)0 - immovable;
    return c2d_from_bits((c2d_bits(x) & ~keep) | (c2d_bits(old) & keep));
}

/* From an accurate d to the new velocities, out = {va'x, va'y, vb'x, vb'y}.
 * Returns nonzero when every intermediate stayed where it is accurate to its
 * rounding; the caller falls back otherwise. */
C2D_HOT c2d_real_bits c2d_finish(c2d_real d, const c2d_pair *p, c2d_real e1, c2d_real *out)
{
    const c2d_real lo = c2d_pow2(C2D_R_EMIN + 2), lo_nn = c2d_pow2(C2D_R_EMIN + C2D_R_MANT + 2);
    /* Truth values in the floating type's width: the vectoriser cannot
     * narrow a double comparison's 64-bit mask to an int. */
    const c2d_real_bits ia = (c2d_real_bits)(p->ma > C2D_R_MAX), ib = (c2d_real_bits)(p->mb > C2D_R_MAX);
    const c2d_real_bits both_finite = (ia | ib) ^ 1u;
    /* a's mass as b feels it: 0 against an immovable b, 1 when a is immovable */
    const c2d_real fa = c2d_pick(p->ma, (c2d_real_bits)0 - both_finite, (c2d_real_bits)0 - (ia & (ib ^ 1u)));
    const c2d_real fb = c2d_pick(p->mb, (c2d_real_bits)0 - both_finite, (c2d_real_bits)0 - (ib & (ia ^ 1u)));
    const c2d_real nn = p->n.x * p->n.x + p->n.y * p->n.y;
    const c2d_real den = nn * (fa + fb);
    const c2d_real c = e1 * d / den;
    const c2d_real la = c * fb, lb = c * fa;
    const c2d_real ac = c2d_abs(c);
    /* An immovable body's velocity is returned as given, bits included: its
     * change la n or lb n is a zero whose sign follows c and n, and
     * -0 + +0 is +0. */
    out[0] = c2d_keep(p->va.x + la * p->n.x, p->va.x, ia);
    out[1] = c2d_keep(p->va.y + la * p->n.y, p->va.y, ia);
    out[2] = c2d_keep(p->vb.x - lb * p->n.x, p->vb.x, ib);
    out[3] = c2d_keep(p->vb.y - lb * p->n.y, p->vb.y, ib);
    /* A lambda may be 0 only for an immovable body, never by underflow; two
     * immovable bodies and NaN masses (m > 0 fails) are refused. */
    return (c2d_real_bits)(p->ma > 0) & (c2d_real_bits)(p->mb > 0) & ((ia & ib) ^ 1u) &
           (c2d_real_bits)(nn >= lo_nn) & (c2d_real_bits)(den >= lo) & (c2d_real_bits)(den <= C2D_R_MAX) &
           (c2d_real_bits)(ac >= lo) & (c2d_real_bits)(ac <= C2D_R_MAX) &
           ((c2d_real_bits)(c2d_abs(la) >= lo) | ia) & ((c2d_real_bits)(c2d_abs(lb) >= lo) | ib) &
           (c2d_real_bits)(c2d_abs(la) <= C2D_R_MAX) & (c2d_real_bits)(c2d_abs(lb) <= C2D_R_MAX);
}

/* The fast path proper: c2d_fast_flag bits; `out` holds the answer when all
 * are set.  The batch kernel inlines exactly this function, so its results
 * are bit-identical to the scalar call. */
C2D_HOT c2d_real_bits c2d_fast_flags(const c2d_pair *p, c2d_real e1, c2d_real *out)
{
    const c2d_real k_lo = c2d_pow2(-C2D_R_EXP_K), k_hi = c2d_pow2(C2D_R_EXP_K);
    const c2d_real px = (p->vb.x - p->va.x) * p->n.x, py = (p->vb.y - p->va.y) * p->n.y;
    const c2d_real d = px + py;
    const c2d_real k = c2d_abs(px) + c2d_abs(py);
    const c2d_real_bits window = c2d_finish(d, p, e1, out) & (c2d_real_bits)(k >= k_lo) & (c2d_real_bits)(k <= k_hi);
    const c2d_real_bits calm = (c2d_real_bits)(k <= 4 * c2d_abs(d));
    const c2d_real_bits finite = (c2d_real_bits)c2d_finite4(out[0], out[1], out[2], out[3]);
    return window | calm << 1 | (c2d_real_bits)(d < 0) << 2 | finite << 3;
}

/* What the flags mean, in the order the tiers must be tried. */
static inline c2d_verdict c2d_fast_verdict(c2d_real_bits f)
{
    if (!(f & C2D_F_WINDOW)) return C2D_VERDICT_GENERAL;
    if (!(f & C2D_F_CALM)) return C2D_VERDICT_ACCURATE;
    if (!(f & C2D_F_APPROACH)) return C2D_VERDICT_SEPARATING;
    return (f & C2D_F_FINITE) ? C2D_VERDICT_OK : C2D_VERDICT_RANGE;
}

/* The public status of a final verdict (OK, SEPARATING or RANGE). */
static inline c2d_status c2d_verdict_status(c2d_verdict v)
{
    if (v == C2D_VERDICT_SEPARATING) return C2D_SEPARATING;
    return v == C2D_VERDICT_RANGE ? C2D_RANGE : C2D_OK;
}

C2D_HOT c2d_verdict c2d_fast(const c2d_pair *p, c2d_real e1, c2d_real *out)
{
    const c2d_real_bits f = c2d_fast_flags(p, e1, out);
    return f == C2D_F_ALL ? C2D_VERDICT_OK : c2d_fast_verdict(f);
}

/* ------------------------------------------------------------ front end
 * THE INPUT-ONLY ACCEPT TEST
 *   c2d_finish checks its intermediates after computing them, so the
 *   verdict waits for the division.  Inside a window of the inputs those
 *   checks cannot fail, and the verdict depends only on quantities formed
 *   before the division.  With W = C2D_R_QUICK_HI (2^200 double, 2^20 float):
 *   k = |px| + |py|, n.n and both masses in [1/W, W] (a sum <= W rejects
 *   NaN and Inf too: a NaN or Inf velocity or normal makes k NaN or Inf; a
 *   minimum >= 1/W the rest).  Then, if 4d + k <= 0 (an approach with
 *   kappa <= 4, the fast path's own test, exact in sign since 4d is), |d|
 *   is in [k/4, k], den = n.n (ma + mb) in [W^-2, 2 W^2], |c| = (1+e)|d|/den
 *   in [W^-3/4, 4 W^3], |la|, |lb| in [W^-4/4, 4 W^4] and |la n_i| below
 *   4 W^4.5: normal, and below half an ulp of the largest finite value
 *   (2^901 < 2^970 double, 2^91 < 2^103 float), so va + la n_i is finite
 *   for any finite va.  The fast path would accept every such pair, and the
 *   same operations in the same order give its bits.  4d - k >= 0 is a
 *   separation it would report.  Everything else goes to the fast path
 *   unchanged.  A wall (one mass INFINITY, the other in the window) takes
 *   the same test with the fast path's mass pair (0, 1).
 *   The code is written once, in the public header (C2D_ACCEPT_DEFINE_,
 *   include/collide2d.h), for this front end and the header's inline ones.
 */

/* The front end's masses for a wall (one mass INFINITY, the other finite,
 * at least 1/W, C2D_R_QUICK_LO): c2d_finish's pair (0, 1) or (1, 0).  Returns 0
 * for anything else. */
static inline int c2d_quick_wall(const c2d_pair *p, c2d_real *fa, c2d_real *fb)
{
    const c2d_real lo = C2D_R_QUICK_LO;
    if (p->mb > C2D_R_MAX && p->ma >= lo && p->ma <= C2D_R_MAX) {
        *fa = 0;
        *fb = 1;
        return 1;
    }
    if (p->ma > C2D_R_MAX && p->mb >= lo && p->mb <= C2D_R_MAX) {
        *fa = 1;
        *fb = 0;
        return 1;
    }
    return 0;
}

/* OK (out written) or SEPARATING when the accept test decides; AXIS when
 * the normal has a zero component (real/collide/axis.h); ACCURATE for a valid pair
 * inside the window whose d cancels (the double-double tier's case); else
 * GENERAL: the caller then asks the fast path (c2d_fast) as before.  The
 * test is the public header's C2D_R_ACCEPT (c2d_accept, c2d_acceptf), the
 * code the inline front ends run, with the masses themselves or, for a
 * wall (their sum beyond the largest finite value), with c2d_quick_wall's
 * pair and the masses out of the window (their sum 0, their least 1: the
 * window is then k + nn <= W and geometry >= 1/W, as it was).  Choosing the
 * masses first costs one comparison and keeps one copy of the test here. */
C2D_HOT c2d_verdict c2d_quick(const c2d_pair *p, c2d_real e1, c2d_real *out)
{
    c2d_real fa = p->ma, fb = p->mb, msum = p->ma + p->mb, lighter = p->ma < p->mb ? p->ma : p->mb;
    int r, wall = 0;
    if (p->n.x == 0 || p->n.y == 0) return C2D_VERDICT_AXIS;
    if (!(msum <= C2D_R_MAX) && c2d_quick_wall(p, &fa, &fb)) {
        msum = 0;
        lighter = 1;
        wall = 1;
    }
    r = C2D_R_ACCEPT(p->n.x, p->n.y, p->va.x, p->va.y, p->vb.x, p->vb.y, fa, fb, msum, lighter, e1, out);
    if (r == C2D_ACCEPT_OK && wall) {
        /* The wall's own velocity as given (its change is a signed zero). */
        if (fa == 0) {
            out[2] = p->vb.x;
            out[3] = p->vb.y;
        } else {
            out[0] = p->va.x;
            out[1] = p->va.y;
        }
    }
    if (r == C2D_ACCEPT_OK) return C2D_VERDICT_OK;
    if (r == C2D_ACCEPT_SEPARATING) return C2D_VERDICT_SEPARATING;
    return r == C2D_ACCEPT_UNDECIDED ? C2D_VERDICT_ACCURATE : C2D_VERDICT_GENERAL;
}

#endif /* C2D_REAL_FAST_H */
