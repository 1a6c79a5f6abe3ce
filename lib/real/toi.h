/* SPDX-License-Identifier: MIT */
/* real/toi.h - template: c2d_time_of_impact, two disks moving with constant
 * velocities.  Needs real/arith/bits.h, real/arith/exact.h and real/arith/sign.h first.
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
 *   the intrinsic one of a grazing miss (h ~ R).  The smaller root in the
 *   stable form (no subtraction of near-equal terms, since b < 0):
 *       t = c / (-b + sqrt(b^2 - ac)),   c = (|d| - R)(|d| + R),
 *   is accurate to a few ulp plus the time one rounding of |d| is worth at
 *   the approach speed at contact.
 *
 * THE STATUS, EXACTLY
 *   OK at t = 0 when c <= 0 (touching or overlapping) and b < 0; otherwise
 *   OK when c > 0, b < 0 and a R^2 - (d x v)^2 > 0 (the pair passes closer
 *   than R); SEPARATING in every other case, including a graze (h = R
 *   exactly: the disks touch with no approach speed, as c2d_collide would
 *   say).  The three signs are polynomials in the inputs of degree 2, 2
 *   and 4.  The fast path decides each from its floating value when the
 *   value clears a bound on its rounding error (FILTERS below); otherwise
 *   the exact path (c2d_toi_exact) evaluates them as exact sums of
 *   products (real/arith/sign.h), so the status is exact over the whole range.
 *
 * RANGE
 *   The fast path takes d and v exactly (TwoSum, as double-doubles) and
 *   scales each by a power of two so its largest component lies in [1, 4);
 *   R scales with d.  It runs only if that scaling was exact (no part of d,
 *   v or R fell below the normal range): the inputs' magnitudes may differ
 *   by more than the exponent range, and then a miss distance, a radius and
 *   d.v underflow or round together.  The exact path works in extended
 *   numbers and cannot over- or underflow; t scales back with one rounding.
 *
 * FILTERS (u = 2^-(MANT+1), the unit roundoff; scaled values are O(1))
 *   d.v by c2d_dot_dd: error <= u |d.v| + 14 u^2 k, k = sum |dh_i vh_i|.
 *   |d| = sqrt(q): relative error <= 3u.  h = |d x v| / |v|: relative error
 *   <= 5u plus 14 u^2 k' / |v| from the cross product's cancellation.
 *   Each decision is taken when its margin exceeds 4 to 16 times these
 *   bounds, plus a floor of a few 2^EMIN for underflowing products.
 */
#ifndef C2D_REAL_TOI_H
#define C2D_REAL_TOI_H

/* The exact difference (x1 - x0, y1 - y0) as a double-double vector h + l
 * scaled by 2^-k, where k is chosen from the larger component so both lie
 * in [0, 4).  Returns k, or C2D_NO_EXP for a zero difference; *exact is
 * cleared when a low part fell below the normal range in the scaling. */
static int c2d_scaled_diff2(c2d_real x1, c2d_real x0, c2d_real y1, c2d_real y0, c2d_real *h, c2d_real *l, int *exact)
{
    c2d_ext hx, lx, hy, ly;
    int k;
    c2d_exact_diff(x1, x0, &hx, &lx);
    c2d_exact_diff(y1, y0, &hy, &ly);
    if (hx.m == 0 && hy.m == 0) return C2D_NO_EXP;
    k = hx.m == 0 ? hy.e : (hy.m == 0 ? hx.e : (hx.e > hy.e ? hx.e : hy.e));
    h[0] = c2d_scale2(hx.m, hx.e - k);
    l[0] = c2d_scale2(lx.m, lx.e - k);
    h[1] = c2d_scale2(hy.m, hy.e - k);
    l[1] = c2d_scale2(ly.m, ly.e - k);
    if ((hx.m != 0 && hx.e - k < C2D_R_EMIN) || (lx.m != 0 && lx.e - k < C2D_R_EMIN) ||
        (hy.m != 0 && hy.e - k < C2D_R_EMIN) || (ly.m != 0 && ly.e - k < C2D_R_EMIN))
        *exact = 0;
    return k;
}

/* ------------------------------------------------------------ exact path */

/* d = pb - pa and v = vb - va exactly as hi + lo per component, and R, all
 * as extended numbers: [axis][0] hi, [axis][1] lo. */
typedef struct c2d_toi_pair {
    c2d_ext d[2][2], v[2][2];
    c2d_ext r;
} c2d_toi_pair;

static void c2d_toi_pair_load(c2d_toi_pair *p, const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum)
{
    c2d_exact_diff(b->pos.x, a->pos.x, &p->d[0][0], &p->d[0][1]);
    c2d_exact_diff(b->pos.y, a->pos.y, &p->d[1][0], &p->d[1][1]);
    c2d_exact_diff(b->vel.x, a->vel.x, &p->v[0][0], &p->v[0][1]);
    c2d_exact_diff(b->vel.y, a->vel.y, &p->v[1][0], &p->v[1][1]);
    c2d_ext_set(&p->r, radius_sum, 0);
}

/* r = d.v, correctly rounded, sign exact. */
static void c2d_toi_dot(c2d_ext *r, c2d_acc *acc, const c2d_toi_pair *p)
{
    c2d_acc_clear(acc);
    c2d_acc_pair_product(acc, p->d[0], p->v[0], 1);
    c2d_acc_pair_product(acc, p->d[1], p->v[1], 1);
    c2d_acc_value(r, acc);
}

/* d x v = dx vy - dy vx, left in acc (not yet rounded). */
static void c2d_toi_cross(c2d_acc *acc, const c2d_toi_pair *p)
{
    c2d_acc_clear(acc);
    c2d_acc_pair_product(acc, p->d[0], p->v[1], 1);
    c2d_acc_pair_product(acc, p->d[1], p->v[0], -1);
}

/* r = |d|^2 - R^2, correctly rounded, sign exact. */
static void c2d_toi_gap(c2d_ext *r, c2d_acc *acc, const c2d_toi_pair *p)
{
    c2d_acc_clear(acc);
    c2d_acc_pair_product(acc, p->d[0], p->d[0], 1);
    c2d_acc_pair_product(acc, p->d[1], p->d[1], 1);
    c2d_acc_product(acc, &p->r, &p->r, -1);
    c2d_acc_value(r, acc);
}

enum { C2D_TOI_PARTS = 16 }; /* exact components of |v|^2 or d x v, at most */

/* Compress acc's exact sum and copy its components to parts; their count. */
static int c2d_toi_parts(c2d_ext *parts, c2d_acc *acc)
{
    int i, n = c2d_compress(acc->atom, acc->n);
    for (i = 0; i < n; i++) c2d_ext_copy(&parts[i], &acc->atom[i]);
    return n;
}

/* When the exact components of R^2 |v|^2 - (d x v)^2 do not fit the
 * accumulator (inputs whose exact differences scatter over many exponent
 * ranges: two thirds of the exact path's cases in the magnitude-ratio
 * tests), the same windowed exact sum (real/arith/exact.h) is taken with
 * the terms generated again on each pass instead of stored, in bounded
 * memory.  (The value formed from the rounded factors that stood here kept
 * the sign of those cases but lost a near graze's, 1 + 2^-367 against
 * speeds of 73 and 2^-62 + 2^-911: found by the fuzzer.)
 *   - a pass finds the largest atom not yet summed, at 2^emax, and sums
 *     exactly every atom within C2D_R_WINDOW binades of it, scaled by
 *     2^-emax, in bins (below); if that sum dominates the atoms left by
 *     2^C2D_R_MARGIN, it is the value, as in c2d_exact_sum; otherwise its
 *     exact components are carried into the next pass;
 *   - a carried sum has cancelled by at least 2^(WINDOW - MARGIN), so its
 *     components lie within MARGIN + MANT + 11 binades of the window's
 *     foot, all inside the next window (WINDOW > MARGIN + MANT + 11 in both
 *     formats): at most one window's components are carried at a time.
 * BINS.  A scaled atom is a multiple of q = 2^-(WINDOW + MANT) below 2
 * (its exponent within WINDOW of emax, its significand MANT + 1 bits).
 * Bin j holds multiples of q 2^(jB), B = MANT / 2: an atom is split from
 * the top bin down by x_j = fl(fl(s_j + x) - s_j), s_j = 1.5 2^(jB - WINDOW)
 * (x rounded to a multiple of bin j's quantum, exact since |x| < 2^(jB -
 * WINDOW + MANT - 1)), the remainder going lower.  At most 2 C2D_TOI_TERMS
 * atoms and one window's carry (25 components), under 2^9 numbers each
 * below 2, are added: each bin holds under 2^(10 + B) of its quanta and the
 * top one under 2^(MANT + 1), so every addition is exact.  The bins, exact floating numbers, are then grown
 * into one nonoverlapping expansion (real/arith/exact.h). */
enum { C2D_TOI_TERMS = 2 * C2D_TOI_PARTS + C2D_TOI_PARTS * (C2D_TOI_PARTS + 1) / 2 }; /* products, at most */

/* The products summed: R^2 (two parts) times each component of |v|^2, then
 * minus each square and twice each cross product of d x v's components. */
typedef struct c2d_toi_terms {
    const c2d_ext *r2, *vv, *cr;
    int nv, nc;
} c2d_toi_terms;

/* Term t's exact product as two atoms (hi and lo, signed, normalised). */
static void c2d_toi_term(const c2d_toi_terms *q, int t, c2d_ext atom[2])
{
    c2d_ext x, y;
    c2d_real hi, lo;
    int j = t - 2 * q->nv;
    if (j < 0) {
        int row = 0, col = t; /* no division: a helper call on small cores */
        if (col >= q->nv) {
            row = 1;
            col -= q->nv;
        }
        c2d_ext_copy(&x, &q->r2[row]);
        c2d_ext_copy(&y, &q->vv[col]);
    } else {
        int i = 0;
        while (j > i) { /* row i of the triangle holds j = 0..i */
            j -= i + 1;
            i++;
        }
        c2d_ext_set(&x, -q->cr[i].m, q->cr[i].e + (j < i ? 1 : 0));
        c2d_ext_copy(&y, &q->cr[j]);
    }
    hi = c2d_two_prod(x.m, y.m, &lo);
    c2d_ext_set(&atom[0], hi, x.e + y.e);
    c2d_ext_set(&atom[1], lo, x.e + y.e);
}

/* Add x (a multiple of q, |x| < 2) to the bins exactly. */
static void c2d_toi_bin_add(c2d_real *bin, int nbins, c2d_real x)
{
    const int width = C2D_R_MANT / 2;
    c2d_real rest = x;
    int j;
    for (j = nbins - 1; j > 0; j--) {
        const c2d_real s = c2d_pow2(j * width - C2D_R_WINDOW) + c2d_pow2(j * width - C2D_R_WINDOW - 1);
        const c2d_real part = (s + rest) - s;
        bin[j] += part;
        rest -= part;
    }
    bin[0] += rest;
}

/* Whether atom a is still to be summed (below the last window's foot). */
static int c2d_toi_pending(const c2d_ext *a, int below, int foot) { return a->m != 0 && (below == 0 || a->e < foot); }

/* r = the exact sum of q's terms, as c2d_exact_sum rounds it; carry is
 * scratch for C2D_ATOMS extended numbers (the spent accumulator's). */
static void c2d_toi_disc_streamed(c2d_ext *r, const c2d_toi_terms *q, c2d_ext *carry)
{
    enum { C2D_BINS = (C2D_R_WINDOW + 9) / (C2D_R_MANT / 2) + 2 }; /* 25 double, 9 float */
    const int nbins = C2D_BINS, nt = 2 * q->nv + q->nc * (q->nc + 1) / 2;
    c2d_real bin[C2D_BINS];
    c2d_ext atom[2];
    int ncarry = 0, foot = 0, below = 0;
    for (;;) {
        int emax = C2D_NO_EXP, rest = 0, left = 0, k = 0, i, t;
        c2d_real approx;
        for (i = 0; i < ncarry; i++)
            if (carry[i].m != 0 && carry[i].e > emax) emax = carry[i].e;
        for (t = 0; t < nt; t++) {
            c2d_toi_term(q, t, atom);
            for (i = 0; i < 2; i++)
                if (c2d_toi_pending(&atom[i], below, foot) != 0 && atom[i].e > emax) emax = atom[i].e;
        }
        if (emax == C2D_NO_EXP) break;
        for (i = 0; i < nbins; i++) bin[i] = 0;
        for (i = 0; i < ncarry; i++) {
            if (carry[i].e >= emax - C2D_R_WINDOW) {
                c2d_toi_bin_add(bin, nbins, c2d_scale2(carry[i].m, carry[i].e - emax));
            } else {
                c2d_ext_copy(&carry[rest], &carry[i]);
                if (carry[i].m != 0) rest++;
            }
        }
        for (t = 0; t < nt; t++) {
            c2d_toi_term(q, t, atom);
            for (i = 0; i < 2; i++) {
                if (c2d_toi_pending(&atom[i], below, foot) == 0) continue;
                if (atom[i].e >= emax - C2D_R_WINDOW) {
                    c2d_toi_bin_add(bin, nbins, c2d_scale2(atom[i].m, atom[i].e - emax));
                } else {
                    left = 1;
                }
            }
        }
        /* In place: the expansion's k <= i components never reach bin i. */
        for (i = 0; i < nbins; i++) k = c2d_grow(bin, k, bin[i]);
        approx = k > 0 ? bin[0] : (c2d_real)0;
        for (i = 1; i < k; i++) approx += bin[i];
        if ((rest == 0 && left == 0) || (approx != 0 && c2d_ilogb(approx) > C2D_R_MARGIN - C2D_R_WINDOW)) {
            c2d_ext_set(r, approx, emax);
            return;
        }
        for (i = 0; i < k && rest < C2D_ATOMS; i++) c2d_ext_set(&carry[rest++], bin[i], emax);
        ncarry = rest;
        foot = emax - C2D_R_WINDOW;
        below = 1;
    }
    c2d_ext_set(r, 0, 0);
}

/* r = R^2 |v|^2 - (d x v)^2 = b^2 - ac, correctly rounded, sign exact:
 * |v|^2 and d x v are compressed to their exact components first and
 * multiplied component by component.  If those products overflow the
 * accumulator even after compression, they are summed again in bounded
 * memory by c2d_toi_disc_streamed (same value, same exact sign). */
static void c2d_toi_disc(c2d_ext *r, c2d_acc *acc, const c2d_toi_pair *p)
{
    c2d_ext vv[C2D_TOI_PARTS], cr[C2D_TOI_PARTS], r2[2], twice;
    c2d_real lo;
    int i, j, nv, nc;
    c2d_acc_clear(acc);
    c2d_acc_pair_product(acc, p->v[0], p->v[0], 1);
    c2d_acc_pair_product(acc, p->v[1], p->v[1], 1);
    nv = c2d_toi_parts(vv, acc);
    c2d_toi_cross(acc, p);
    nc = c2d_toi_parts(cr, acc);
    c2d_ext_set(&r2[0], c2d_two_prod(p->r.m, p->r.m, &lo), 2 * p->r.e);
    c2d_ext_set(&r2[1], lo, 2 * p->r.e);
    c2d_acc_clear(acc);
    for (i = 0; i < 2; i++)
        for (j = 0; j < nv; j++) c2d_acc_product(acc, &r2[i], &vv[j], 1);
    for (i = 0; i < nc; i++) {
        for (j = 0; j < i; j++) {
            c2d_ext_set(&twice, cr[j].m, cr[j].e + 1);
            c2d_acc_product(acc, &cr[i], &twice, -1);
        }
        c2d_acc_product(acc, &cr[i], &cr[i], -1);
    }
    if (acc->full == 0) {
        c2d_acc_value(r, acc);
    } else {
        c2d_toi_terms q;
        q.r2 = r2;
        q.vv = vv;
        q.cr = cr;
        q.nv = nv;
        q.nc = nc;
        c2d_toi_disc_streamed(r, &q, acc->atom);
    }
}

/* Every decision from exact signs, t from correctly rounded b, c and
 * b^2 - ac in extended arithmetic: t = c / (sqrt(b^2 - ac) - b). */
C2D_COLD c2d_status c2d_toi_exact(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum, c2d_real *t)
{
    c2d_toi_pair p;
    c2d_acc acc;
    c2d_ext dv, gap, disc, tt;
    c2d_real value;
    c2d_toi_pair_load(&p, a, b, radius_sum);
    if (p.v[0][0].m == 0 && p.v[1][0].m == 0) return C2D_SEPARATING; /* no relative motion */
    if (p.d[0][0].m == 0 && p.d[1][0].m == 0) return C2D_SEPARATING; /* coincident: not approaching */
    c2d_toi_dot(&dv, &acc, &p);
    c2d_toi_gap(&gap, &acc, &p);
    if (c2d_ext_sign(&gap) <= 0) {
        if (c2d_ext_sign(&dv) >= 0) return C2D_SEPARATING;
        *t = 0;
        return C2D_OK;
    }
    if (c2d_ext_sign(&dv) >= 0) return C2D_SEPARATING;
    c2d_toi_disc(&disc, &acc, &p);
    if (c2d_ext_sign(&disc) <= 0) return C2D_SEPARATING; /* misses, or grazes */
    c2d_ext_sqrt(&tt, &disc);
    c2d_ext_add(&tt, &tt, &dv, -1);
    c2d_ext_div(&tt, &gap, &tt);
    value = c2d_scale2(tt.m, tt.e);
    if (!(value <= C2D_R_MAX)) return C2D_RANGE;
    *t = value;
    return C2D_OK;
}

/* ------------------------------------------------------------- fast path */

/* A decision the fast path can take: |x - y| clears the error bound. */
static int c2d_clear_of(c2d_real x, c2d_real y, c2d_real bound) { return c2d_abs(x - y) > bound; }

/* Every input 0 or of magnitude within [2^-w, 2^w].  With w = W =
 * C2D_R_TOI_WINDOW (100 double, 12 float):  Then the power-of-two scaling cannot matter: d's
 * and v's parts, their products and every later quantity stay far inside
 * the normal range with or without it (the smallest nonzero part is an ulp
 * of an input, 2^-(W + MANT); products of two such are still normal, and
 * the filters' 2^(EMIN + 4) floor stays below half an ulp of the bounds it
 * is added to), so each operation rounds the same scaled or not: the
 * scaling is skipped, with the same bits. */
static int c2d_toi_in_window(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum, int w)
{
    const c2d_real lo = c2d_pow2(-w), hi = c2d_pow2(w);
    c2d_real x[9];
    int i, in = 1;
    x[0] = a->pos.x, x[1] = a->pos.y, x[2] = b->pos.x, x[3] = b->pos.y;
    x[4] = a->vel.x, x[5] = a->vel.y, x[6] = b->vel.x, x[7] = b->vel.y, x[8] = radius_sum;
    for (i = 0; i < 9; i++) {
        const c2d_real m = c2d_abs(x[i]);
        in &= (int)(m == 0) | ((int)(m >= lo) & (int)(m <= hi));
    }
    return in;
}

/* The exact sign of |d|^2 - R^2 for d = h + l given exactly (a TwoSum per
 * component).  Expanded, (hx + lx)^2 + (hy + ly)^2 - R^2 is a sum of seven
 * products, h^2, 2hl and l^2 per axis and -R^2, each split by TwoProduct
 * into two floating numbers; the fourteen are summed exactly by
 * GROW-EXPANSION (real/arith/exact.h), whose largest component carries the
 * sign.  Exact when every product and its rounding error is normal: inputs
 * in the window (below) make every part a multiple of 2^-(W + MANT), so
 * every nonzero product error is at least 2^-2(W + MANT), far above the
 * normal range's floor, and no product exceeds 2^(2W + 4). */
static int c2d_toi_gap_sign(const c2d_real *h, const c2d_real *l, c2d_real r)
{
    const c2d_real u16 = c2d_pow2(-C2D_R_MANT + 3); /* 16u */
    c2d_real ex[14], p[7], e[7], s1, t1, s2, t2, x0, x1, v, m;
    int i, k = 0;
    /* The filter: the large terms' cancellation exactly (hx^2 + hy^2 - R^2
     * by TwoProduct and TwoSum: s2 + t1 + t2 + e0 + e1 + e6), the small
     * rest in plain arithmetic.  Ten terms summed in order (error 9u (1 +
     * 9u) of their magnitudes), four of them rounded products (u each): a
     * value beyond 16u of the magnitudes has the exact sign. */
    p[0] = c2d_two_prod(h[0], h[0], &e[0]);
    p[3] = c2d_two_prod(h[1], h[1], &e[3]);
    p[6] = c2d_two_prod(-r, r, &e[6]);
    s1 = c2d_two_sum(p[0], p[3], &t1);
    s2 = c2d_two_sum(s1, p[6], &t2);
    x0 = 2 * h[0] * l[0];
    x1 = 2 * h[1] * l[1];
    v = s2 + t1 + t2 + e[0] + e[3] + e[6] + x0 + x1 + l[0] * l[0] + l[1] * l[1];
    m = c2d_abs(s2) + c2d_abs(t1) + c2d_abs(t2) + c2d_abs(e[0]) + c2d_abs(e[3]) + c2d_abs(e[6]) + c2d_abs(x0) +
        c2d_abs(x1) + l[0] * l[0] + l[1] * l[1];
    if (c2d_abs(v) > u16 * m) return v > 0 ? 1 : -1;
    /* Else the exact sum. */
    p[1] = c2d_two_prod(2 * h[0], l[0], &e[1]);
    p[2] = c2d_two_prod(l[0], l[0], &e[2]);
    p[4] = c2d_two_prod(2 * h[1], l[1], &e[4]);
    p[5] = c2d_two_prod(l[1], l[1], &e[5]);
    for (i = 0; i < 7; i++) {
        k = c2d_grow(ex, k, e[i]);
        k = c2d_grow(ex, k, p[i]);
    }
    return k == 0 ? 0 : (ex[k - 1] > 0 ? 1 : -1);
}

/* c2d_toi_exact's arithmetic, step for step, in plain floating point, for
 * inputs 0 or within [2^-N, 2^N], N = (C2D_R_WINDOW - 4 MANT - 9) / 8 (47
 * in double; float's
 * exact-sum window is too narrow for any N, so it always takes the exact
 * path).  There every part of d and v, R and every exact component is a
 * multiple of 2^-(N + MANT) (degree 1), 2^-2(N + MANT) (degree 2) or
 * 2^-4(N + MANT) (degree 4, the discriminant's products), and none exceeds
 * 2^(4N + 9): every atom is normal and all of a sum's lie within
 * 8N + 4 MANT + 9 <= C2D_R_WINDOW binades of the largest, so each of
 * c2d_exact_sum's and c2d_compress's sums is one window, whose scaling by
 * 2^-emax changes no rounding.  The same atoms in the same order (zeros
 * kept in the count, skipped in the sums, as there) give the same
 * expansions, the same rounded sums and, with c2d_ext_sqrt, c2d_ext_add and
 * c2d_ext_div correctly rounded like the operations here, the same t. */
#if (C2D_R_WINDOW - 4 * C2D_R_MANT - 9) / 8 > 0

typedef struct c2d_toi_macc {
    c2d_real atom[C2D_ATOMS];
    int n, full;
} c2d_toi_macc;

/* The expansion of atom[0..n)'s nonzero atoms, grown in order; its length. */
static int c2d_toi_mgrow(c2d_real *ex, const c2d_real *atom, int n)
{
    int i, k = 0;
    for (i = 0; i < n; i++)
        if (atom[i] != 0) k = c2d_grow(ex, k, atom[i]);
    return k;
}

/* c2d_compress in one window: the components, largest first. */
static int c2d_toi_mcompress(c2d_real *atom, int n)
{
    c2d_real ex[C2D_ATOMS];
    int i, k = c2d_toi_mgrow(ex, atom, n);
    for (i = 0; i < k; i++) atom[i] = ex[k - 1 - i];
    return k;
}

/* c2d_exact_sum in one window: the components added smallest first. */
static c2d_real c2d_toi_mvalue(const c2d_toi_macc *acc)
{
    c2d_real ex[C2D_ATOMS], approx = (c2d_real)0;
    int i, k = c2d_toi_mgrow(ex, acc->atom, acc->n);
    for (i = 0; i < k; i++) approx += ex[i];
    return approx;
}

/* c2d_acc_product: sign x y as two atoms, compressing when full. */
static void c2d_toi_mproduct(c2d_toi_macc *acc, c2d_real x, c2d_real y, int sign)
{
    c2d_real lo, hi;
    if (acc->n + 2 > C2D_ATOMS) acc->n = c2d_toi_mcompress(acc->atom, acc->n);
    if (acc->n + 2 > C2D_ATOMS) {
        acc->full = 1;
        return;
    }
    hi = c2d_two_prod(sign < 0 ? -x : x, y, &lo);
    acc->atom[acc->n] = hi;
    acc->atom[acc->n + 1] = lo;
    acc->n += 2;
}

/* c2d_acc_pair_product: (x[0] + x[1]) (y[0] + y[1]), four products. */
static void c2d_toi_mpair(c2d_toi_macc *acc, const c2d_real *x, const c2d_real *y, int sign)
{
    int i, j;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) c2d_toi_mproduct(acc, x[i], y[j], sign);
}

/* The rest of c2d_toi_exact for an approaching pair (d.v < 0) with
 * |d|^2 > R^2, both decided; d and v as hi + lo pairs per axis (x hi, x lo,
 * y hi, y lo).  Returns 0 when the discriminant's products fill the
 * accumulator (c2d_toi_exact then sums them in bounded memory). */
static int c2d_toi_mirror(const c2d_real *d, const c2d_real *v, c2d_real r, c2d_real *t, c2d_status *status)
{
    c2d_toi_macc acc;
    c2d_real vv[C2D_ATOMS], cr[C2D_ATOMS], r2[2], dv, gap, disc, tt;
    int i, j, nv, nc;
    acc.n = 0, acc.full = 0;
    c2d_toi_mpair(&acc, &d[0], &v[0], 1);
    c2d_toi_mpair(&acc, &d[2], &v[2], 1);
    dv = c2d_toi_mvalue(&acc);
    acc.n = 0;
    c2d_toi_mpair(&acc, &d[0], &d[0], 1);
    c2d_toi_mpair(&acc, &d[2], &d[2], 1);
    c2d_toi_mproduct(&acc, r, r, -1);
    gap = c2d_toi_mvalue(&acc);
    acc.n = 0;
    c2d_toi_mpair(&acc, &v[0], &v[0], 1);
    c2d_toi_mpair(&acc, &v[2], &v[2], 1);
    nv = c2d_toi_mcompress(acc.atom, acc.n);
    for (i = 0; i < nv; i++) vv[i] = acc.atom[i];
    acc.n = 0;
    c2d_toi_mpair(&acc, &d[0], &v[2], 1);
    c2d_toi_mpair(&acc, &d[2], &v[0], -1);
    nc = c2d_toi_mcompress(acc.atom, acc.n);
    for (i = 0; i < nc; i++) cr[i] = acc.atom[i];
    r2[0] = c2d_two_prod(r, r, &r2[1]);
    acc.n = 0;
    for (i = 0; i < 2; i++)
        for (j = 0; j < nv; j++) c2d_toi_mproduct(&acc, r2[i], vv[j], 1);
    for (i = 0; i < nc; i++) {
        for (j = 0; j < i; j++) c2d_toi_mproduct(&acc, cr[i], 2 * cr[j], -1);
        c2d_toi_mproduct(&acc, cr[i], cr[i], -1);
    }
    if (acc.full != 0) return 0;
    disc = c2d_toi_mvalue(&acc);
    if (!(disc > 0)) {
        *status = C2D_SEPARATING; /* misses, or grazes */
        return 1;
    }
    tt = gap / (C2D_R_SQRT(disc) - dv);
    if (!(tt <= C2D_R_MAX)) {
        *status = C2D_RANGE;
        return 1;
    }
    *t = tt;
    *status = C2D_OK;
    return 1;
}
#endif

/* A touching pair (|d| = R to rounding, so the plain filter on |d|^2 - R^2
 * cannot decide), approaching (d.v < 0, decided): two pool balls resting in
 * contact, one rolling into the other.  The exact sign of |d|^2 - R^2
 * decides, as it does in c2d_toi_exact: at most 0 is a hit now, t = 0;
 * above 0 the time is c2d_toi_exact's and this returns 0 for the careful
 * path.  Only for inputs in the window, where c2d_toi_gap_sign is exact. */
C2D_COLD int c2d_toi_touching(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum, c2d_real *t,
                            c2d_status *status)
{
    c2d_real h[2], l[2];
    if (c2d_toi_in_window(a, b, radius_sum, C2D_R_TOI_WINDOW) == 0) return 0;
    h[0] = c2d_two_sum(b->pos.x, -a->pos.x, &l[0]);
    h[1] = c2d_two_sum(b->pos.y, -a->pos.y, &l[1]);
    if (c2d_toi_gap_sign(h, l, radius_sum) > 0) {
#if (C2D_R_WINDOW - 4 * C2D_R_MANT - 9) / 8 > 0
        /* Only where c2d_toi_careful would call c2d_toi_exact (its first
         * two filters, the same expressions): where they pass, its own
         * double-length time stands. */
        const c2d_real rel = c2d_pow2(-C2D_R_MANT + 2), rel2 = c2d_pow2(-2 * C2D_R_MANT + 4);
        const c2d_real tiny = c2d_pow2(C2D_R_EMIN + 4);
        c2d_real d[4], v[4], vh[2], vl[2], dv, k, dist;
        if (c2d_toi_in_window(a, b, radius_sum, (C2D_R_WINDOW - 4 * C2D_R_MANT - 9) / 8) == 0) return 0;
        vh[0] = c2d_two_sum(b->vel.x, -a->vel.x, &vl[0]);
        vh[1] = c2d_two_sum(b->vel.y, -a->vel.y, &vl[1]);
        dv = c2d_dot_dd(h, l, vh, vl);
        k = c2d_abs(h[0] * vh[0]) + c2d_abs(h[1] * vh[1]);
        dist = C2D_R_SQRT(h[0] * h[0] + h[1] * h[1] + 2 * (h[0] * l[0] + h[1] * l[1]));
        if (c2d_abs(dv) > rel2 * k + tiny &&
            c2d_clear_of(dist, radius_sum, rel * (dist > radius_sum ? dist : radius_sum)))
            return 0;
        d[0] = h[0], d[1] = l[0], d[2] = h[1], d[3] = l[1];
        v[0] = vh[0], v[1] = vl[0], v[2] = vh[1], v[3] = vl[1];
        return c2d_toi_mirror(d, v, radius_sum, t, status);
#else
        return 0;
#endif
    }
    *t = 0;
    *status = C2D_OK;
    return 1;
}

/* ------------------------------------------------------------ plain path
 * In plain arithmetic, for pairs whose differences are moderate.  With d, v
 * the rounded differences (each component within u of its exact value,
 * u = 2^-(MANT+1)) and every nonzero |d_i|, |v_i| and R within
 * [2^-W, 2^W] (W = C2D_R_TOI_WINDOW), no product under- or overflows, and
 *   b = d.v is within 4u k of its exact value, k = |dx vx| + |dy vy| (the
 *     inputs' rounding 2u k, the products' and the sum's 2u k);
 *   |d|^2 - R^2 within 6u of the larger of |d|^2, R^2 (4u and u, and the
 *     subtraction's u);
 *   (d x v)^2 - R^2 |v|^2 within 8u (|d x v| k' + R^2 |v|^2), k' =
 *     |dx vy| + |dy vx| (d x v within 4u k', R^2 |v|^2 within 6u).
 * Each sign is taken only when its value clears twice its bound (8u k,
 * 16u max(|d|^2, R^2), 16u (|d x v| k' + R^2 |v|^2)); every other pair goes
 * to the careful path below, so the status stays exact.  A miss is found on
 * squares, with no square root.  For a hit, t = c / (sqrt(disc) - b) with
 * c = (|d| - R)(|d| + R), disc = |v|^2 (R - h)(R + h), h = |d x v| / |v|:
 * b < 0 and sqrt(disc) >= 0 in the denominator, so their relative errors
 * (a few u) pass to t unamplified; c's absolute error, about u |d|^2, is the
 * time one rounding of |d| is worth at the approach speed; the cross
 * product's error moves sqrt(disc) by at most 2h/R of that unit
 * (docs/METHOD.md).  Measured worst: docs/ACCURACY.md.  Returns 1 when it
 * decided, 0 when it cannot, 2 when it cannot because |d| = R to rounding
 * with d.v < 0 decided (for c2d_toi_touching: returned rather than called
 * from here, which costs the ordinary pair registers). */
static inline int c2d_toi_plain(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum, c2d_real *t,
                                c2d_status *status)
{
    const c2d_real lo = c2d_pow2(-C2D_R_TOI_WINDOW), hi = c2d_pow2(C2D_R_TOI_WINDOW);
    const c2d_real u8 = c2d_pow2(-C2D_R_MANT + 2), u16 = c2d_pow2(-C2D_R_MANT + 3); /* 8u, 16u */
    const c2d_real dx = b->pos.x - a->pos.x, dy = b->pos.y - a->pos.y;
    const c2d_real vx = b->vel.x - a->vel.x, vy = b->vel.y - a->vel.y;
    const c2d_real r = radius_sum;
    /* The window: zeros count as hi for the minimum; NaN and Inf (from any
     * non-finite input) fail the sum; a negative radius fails r >= 0. */
    const c2d_real mx = c2d_abs(dx) == 0 ? hi : c2d_abs(dx), my = c2d_abs(dy) == 0 ? hi : c2d_abs(dy);
    const c2d_real nx = c2d_abs(vx) == 0 ? hi : c2d_abs(vx), ny = c2d_abs(vy) == 0 ? hi : c2d_abs(vy);
    const c2d_real mr = r == 0 ? hi : r;
    const c2d_real least = (mx < my ? mx : my) < (nx < ny ? nx : ny) ? (mx < my ? mx : my) : (nx < ny ? nx : ny);
    c2d_real dv, k, q, r2, a2, dist, speed, cross, h, kc;
    if (!((c2d_abs(dx) + c2d_abs(dy)) + (c2d_abs(vx) + c2d_abs(vy)) + r <= hi && (least < mr ? least : mr) >= lo))
        return 0;
    if ((vx == 0 && vy == 0) || (dx == 0 && dy == 0)) { /* exact: moderate values subtract to 0 only if equal */
        *status = C2D_SEPARATING;
        return 1;
    }
    dv = dx * vx + dy * vy;
    k = c2d_abs(dx * vx) + c2d_abs(dy * vy);
    if (!(c2d_abs(dv) > u8 * k)) return 0;
    if (dv > 0) {
        *status = C2D_SEPARATING;
        return 1;
    }
    /* Overlap and miss decided on squares, so a miss costs no square root:
     * |d|^2 - R^2 (relative errors 4u and u) and (d x v)^2 - R^2 |v|^2
     * (cross's error 4u k', so its square's 8u |d x v| k' + ...). */
    q = dx * dx + dy * dy;
    r2 = r * r;
    if (!c2d_clear_of(q, r2, u16 * (q > r2 ? q : r2))) return 2; /* touching: c2d_toi_touching */
    if (q < r2) {
        *t = 0;
        *status = C2D_OK;
        return 1;
    }
    a2 = vx * vx + vy * vy;
    cross = dx * vy - dy * vx;
    kc = c2d_abs(dx * vy) + c2d_abs(dy * vx);
    if (!c2d_clear_of(cross * cross, r2 * a2, u16 * (c2d_abs(cross) * kc + r2 * a2))) return 0;
    if (cross * cross > r2 * a2) {
        *status = C2D_SEPARATING;
        return 1;
    }
    dist = C2D_R_SQRT(q);
    speed = C2D_R_SQRT(a2);
    h = c2d_abs(cross) / speed;
    *t = (dist - r) * (dist + r) / (speed * C2D_R_SQRT((r - h) * (r + h)) - dv);
    *status = C2D_OK;
    return 1;
}

/* Everything the plain path left: validation, then the double-double path
 * (scaled unless inside the window), then the exact path. */
C2D_COLD c2d_status c2d_toi_careful(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum, c2d_real *t)
{
    const c2d_real rel = c2d_pow2(-C2D_R_MANT + 2), rel2 = c2d_pow2(-2 * C2D_R_MANT + 4);
    const c2d_real tiny = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real dh[2], dl[2], vh[2], vl[2], crossh[2], crossl[2];
    c2d_real rad, dist, speed, dv, cross, h, c, disc, tt, k;
    int kd = 0, kv = 0, exact = 1;
    if (!c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y) || !c2d_finite4(a->vel.x, a->vel.y, b->vel.x, b->vel.y) ||
        !(radius_sum >= 0 && radius_sum <= C2D_R_MAX))
        return C2D_INVALID;
    if (c2d_toi_in_window(a, b, radius_sum, C2D_R_TOI_WINDOW) != 0) {
        vh[0] = c2d_two_sum(b->vel.x, -a->vel.x, &vl[0]);
        vh[1] = c2d_two_sum(b->vel.y, -a->vel.y, &vl[1]);
        dh[0] = c2d_two_sum(b->pos.x, -a->pos.x, &dl[0]);
        dh[1] = c2d_two_sum(b->pos.y, -a->pos.y, &dl[1]);
        if (vh[0] == 0 && vh[1] == 0) return C2D_SEPARATING; /* no relative motion */
        if (dh[0] == 0 && dh[1] == 0) return C2D_SEPARATING; /* coincident: not approaching */
        rad = radius_sum;
    } else {
        kv = c2d_scaled_diff2(b->vel.x, a->vel.x, b->vel.y, a->vel.y, vh, vl, &exact);
        if (kv == C2D_NO_EXP) return C2D_SEPARATING;
        kd = c2d_scaled_diff2(b->pos.x, a->pos.x, b->pos.y, a->pos.y, dh, dl, &exact);
        if (kd == C2D_NO_EXP) return C2D_SEPARATING;
        rad = c2d_scale2(radius_sum, -kd); /* Inf when far larger than |d|: overlapping */
        if (exact == 0 || (rad != 0 && rad < c2d_pow2(C2D_R_EMIN))) return c2d_toi_exact(a, b, radius_sum, t);
    }
    /* In units of 2^kd for lengths and 2^kv for speeds (or as they are, in
     * the window), squares and products are safe. */
    dv = c2d_dot_dd(dh, dl, vh, vl);
    k = c2d_abs(dh[0] * vh[0]) + c2d_abs(dh[1] * vh[1]);
    if (!(c2d_abs(dv) > rel2 * k + tiny)) return c2d_toi_exact(a, b, radius_sum, t);
    dist = C2D_R_SQRT(dh[0] * dh[0] + dh[1] * dh[1] + 2 * (dh[0] * dl[0] + dh[1] * dl[1]));
    if (!c2d_clear_of(dist, rad, rel * (dist > rad ? dist : rad))) return c2d_toi_exact(a, b, radius_sum, t);
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
    k = c2d_abs(dh[1] * vh[0]) + c2d_abs(dh[0] * vh[1]);
    if (!c2d_clear_of(h, rad, rel * h + (rel2 * k + tiny) / speed)) return c2d_toi_exact(a, b, radius_sum, t);
    if (h > rad) return C2D_SEPARATING; /* misses */
    c = (dist - rad) * (dist + rad);
    disc = speed * C2D_R_SQRT((rad - h) * (rad + h));
    tt = c / (disc - dv);
    if (kd != kv) tt = c2d_scale2(tt, kd - kv);
    if (!(tt <= C2D_R_MAX)) return C2D_RANGE;
    *t = tt;
    return C2D_OK;
}

/* c2d_time_of_impact: the plain path, else the careful one.  The plain path
 * needs no validation of its own: a NaN or Inf input makes a difference NaN
 * or Inf, which its window refuses. */
static c2d_status c2d_real_time_of_impact(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum,
                                          c2d_real *t)
{
    c2d_status plain;
    if (a == NULL || b == NULL || t == NULL) return C2D_INVALID;
    switch (c2d_toi_plain(a, b, radius_sum, t, &plain)) {
    case 1:
        return plain;
    case 2:
        if (c2d_toi_touching(a, b, radius_sum, t, &plain) != 0) return plain;
        break;
    default:
        break;
    }
    return c2d_toi_careful(a, b, radius_sum, t);
}

#endif /* C2D_REAL_TOI_H */
