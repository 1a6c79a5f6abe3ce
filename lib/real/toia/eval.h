/* SPDX-License-Identifier: MIT */
/* real/toia/eval.h - template, accelerated time of impact: f, g, h, h' at a
 * time with certified error bounds in three tiers (plain, double length,
 * exact) and the probe that escalates until a sign is certified.  See
 * real/toia/README.md. */
#ifndef C2D_REAL_TOIA_EVAL_H
#define C2D_REAL_TOIA_EVAL_H
/* Evaluation with certified error bounds, three tiers                   */
/* ===================================================================== */

/* Scales for evaluating at t = (th + tl) 2^te: d = d0 + v t + a t^2/2 is
 * computed in units of 2^E and d' = v + a t in units of 2^E1, E and E1
 * chosen from the terms' exponents so that every scaled term is below 1/2
 * (so nothing overflows whatever t and the inputs are).  The factors are
 * powers of two (exact multipliers, clamped at 2^EMIN: a term that small
 * relative to the largest is covered by the floor): sc[0] for d0, sc[1]
 * for v t / th, sc[2] for a t^2 / th^2 (the 1/2 included), sc[3] for v,
 * sc[4] for a t / th.  Zero vectors and t = 0 give factor 0. */
static void c2d_toia_scales(c2d_toia_ctx *c, const c2d_dd *t, int *E, int *E1, c2d_real *sc)
{
    int have = 0, e = 0, e1 = 0, have1 = 0, k;
    const int ht = t->h != 0, te = t->e;
    if (c->nonzero[0] != 0) {
        e = c->exp[0];
        have = 1;
    }
    if (c->nonzero[1] != 0 && ht != 0) {
        k = c->exp[1] + te;
        e = (have == 0 || k > e) ? k : e;
        have = 1;
    }
    if (c->nonzero[2] != 0 && ht != 0) {
        k = c->exp[2] + 2 * te - 1;
        e = (have == 0 || k > e) ? k : e;
    }
    e += 4;
    if (c->nonzero[1] != 0) {
        e1 = c->exp[1];
        have1 = 1;
    }
    if (c->nonzero[2] != 0 && ht != 0) {
        k = c->exp[2] + te;
        e1 = (have1 == 0 || k > e1) ? k : e1;
    }
    e1 += 3;
    sc[0] = c->nonzero[0] != 0 ? c2d_toia_pow2_clamped(c->exp[0] - e) : 0;
    sc[1] = (c->nonzero[1] != 0 && ht != 0) ? c2d_toia_pow2_clamped(c->exp[1] + te - e) : 0;
    sc[2] = (c->nonzero[2] != 0 && ht != 0) ? c2d_toia_pow2_clamped(c->exp[2] + 2 * te - 1 - e) : 0;
    sc[3] = c->nonzero[1] != 0 ? c2d_toia_pow2_clamped(c->exp[1] - e1) : 0;
    sc[4] = (c->nonzero[2] != 0 && ht != 0) ? c2d_toia_pow2_clamped(c->exp[2] + te - e1) : 0;
    *E = e;
    *E1 = e1;
}

static void c2d_toia_bounded_set(c2d_toia_bounded *q, c2d_real v, c2d_real r, int e)
{
    q->value = v;
    q->bound = r;
    q->exp = e;
}

/* R in units of 2^E, or -1 when R exceeds every scaled |d| (< 2) so much
 * that f < 0 is certain and R^2 could overflow. */
static c2d_real c2d_toia_radius_scaled(c2d_toia_ctx *c, int E)
{
    if (c->radius.e - E > C2D_R_EMAX / 2 - 4) return -1;
    return c->radius.m * c2d_toia_pow2_clamped(c->radius.e - E);
}

/* f when R dominates: -R^2 (the bound covers |d|^2 < 4 in units of 2^E). */
static void c2d_toia_f_radius_dominates(c2d_toia_ctx *c, int E, c2d_toia_bounded *q, c2d_real *mag)
{
    *mag = c->radius.m * c->radius.m;
    c2d_toia_bounded_set(q, -(c->radius.m * c->radius.m),
                         c2d_toia_pow2_clamped(2 * (E - c->radius.e) + 4) + c2d_pow2(-C2D_R_MANT), 2 * c->radius.e);
}

/* h = |d'|^2 + d.a and hp = 3 d'.a from d (units 2^E), d' (2^E1) and
 * their error bounds dl, dl1; shared by the three tiers (each passes its
 * own rounding constant k u for the few operations here and the relative
 * error of the a it uses). */
static void c2d_toia_h_from_d(c2d_toia_ctx *c, const c2d_real *d, const c2d_real *dl, const c2d_real *d1,
                           const c2d_real *dl1, int E, int E1, c2d_real ku, c2d_real arel, c2d_toia_values *o)
{
    const c2d_real fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real h1, h2, r1, r2, ca, cb, x;
    int Eh;
    h1 = d1[0] * d1[0] + d1[1] * d1[1];
    r1 = (2 * c2d_abs(d1[0]) + dl1[0]) * dl1[0] + (2 * c2d_abs(d1[1]) + dl1[1]) * dl1[1] + ku * h1 + fl;
    if (c->nonzero[2] == 0) {
        c2d_toia_bounded_set(&o->qty[C2D_TOIA_QH], h1, r1, 2 * E1);
        c2d_toia_bounded_set(&o->qty[C2D_TOIA_QHP], 0, 0, 0);
        o->hmag = h1;
        return;
    }
    h2 = d[0] * c->hi[2][0] + d[1] * c->hi[2][1];
    x = c2d_abs(d[0] * c->hi[2][0]) + c2d_abs(d[1] * c->hi[2][1]);
    r2 = c2d_abs(c->hi[2][0]) * dl[0] + c2d_abs(c->hi[2][1]) * dl[1] + (ku + arel) * x + fl;
    Eh = c2d_toia_max_int(2 * E1, E + c->exp[2]);
    ca = c2d_toia_pow2_clamped(2 * E1 - Eh);
    cb = c2d_toia_pow2_clamped(E + c->exp[2] - Eh);
    x = h1 * ca + h2 * cb;
    c2d_toia_bounded_set(&o->qty[C2D_TOIA_QH], x, r1 * ca + r2 * cb + ku * c2d_abs(x) + fl, Eh);
    o->hmag = h1 * ca + (c2d_abs(d[0] * c->hi[2][0]) + c2d_abs(d[1] * c->hi[2][1])) * cb;
    x = d1[0] * c->hi[2][0] + d1[1] * c->hi[2][1];
    r2 = c2d_abs(c->hi[2][0]) * dl1[0] + c2d_abs(c->hi[2][1]) * dl1[1] +
         (ku + arel) * (c2d_abs(d1[0] * c->hi[2][0]) + c2d_abs(d1[1] * c->hi[2][1])) + fl;
    c2d_toia_bounded_set(&o->qty[C2D_TOIA_QHP], 3 * x, 3 * r2 * (1 + ku), E1 + c->exp[2]);
}

/* f and g from d, d' and their bounds (as c2d_toia_h_from_d). */
static void c2d_toia_fg_from_d(c2d_toia_ctx *c, const c2d_real *d, const c2d_real *dl, const c2d_real *d1,
                            const c2d_real *dl1, int E, int E1, c2d_real ku, c2d_toia_values *o)
{
    const c2d_real fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real x, y, rr = c2d_toia_radius_scaled(c, E);
    if (rr < 0) {
        c2d_toia_f_radius_dominates(c, E, &o->qty[C2D_TOIA_QF], &o->fmag);
    } else {
        x = d[0] * d[0] + d[1] * d[1];
        y = rr * rr;
        c2d_toia_bounded_set(&o->qty[C2D_TOIA_QF], x - y,
                       (2 * c2d_abs(d[0]) + dl[0]) * dl[0] + (2 * c2d_abs(d[1]) + dl[1]) * dl[1] + ku * (x + y) + fl,
                       2 * E);
        o->fmag = x + y;
    }
    x = d[0] * d1[0] + d[1] * d1[1];
    y = (c2d_abs(d1[0]) + dl1[0]) * dl[0] + c2d_abs(d[0]) * dl1[0] + (c2d_abs(d1[1]) + dl1[1]) * dl[1] +
        c2d_abs(d[1]) * dl1[1] + ku * (c2d_abs(d[0] * d1[0]) + c2d_abs(d[1] * d1[1])) + fl;
    c2d_toia_bounded_set(&o->qty[C2D_TOIA_QG], x, y, E + E1);
    o->gmag = c2d_abs(d[0] * d1[0]) + c2d_abs(d[1] * d1[1]);
}

/* Tier 1: plain arithmetic at the time t.h 2^t.e (t.l ignored).
 * ERROR (u = 2^-(MANT+1); s = the sum of the three terms' magnitudes):
 * each scaled term is an exact power-of-two multiple of the hi parts
 * (their lo parts, <= u of them, are dropped), then at most two roundings
 * for the products (t^2, then a t^2) and two for the sums: |d - d~| <=
 * u (3|d0| + 4|vt| + 5|at^2/2|) + O(u^2) <= 6u s, plus the floor 2^(EMIN+4)
 * (underflow of the scaled products and the clamped factors).  d' likewise
 * with 4u.  Then f = |d|^2 - R^2 is off by sum (2|d_i| + dl_i) dl_i plus
 * its own four roundings (4u (|d|^2 + R^2)); g, h, hp likewise.  The
 * constants are rounded up generously (bounds are themselves computed in
 * floating point). */
static void c2d_toia_eval_plain(c2d_toia_ctx *c, const c2d_dd *t, c2d_toia_values *o)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1), fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real sc[5], d[2], d1[2], dl[2], dl1[2], tm = t->h;
    int E, E1, i;
    c2d_toia_scales(c, t, &E, &E1, sc);
    sc[1] *= tm;
    sc[2] *= tm * tm;
    sc[4] *= tm;
    for (i = 0; i < 2; i++) {
        c2d_real a0 = c->hi[0][i] * sc[0], a1 = c->hi[1][i] * sc[1], a2 = c->hi[2][i] * sc[2];
        c2d_real b1 = c->hi[1][i] * sc[3], b2 = c->hi[2][i] * sc[4];
        d[i] = (a0 + a1) + a2;
        dl[i] = 7 * u * ((c2d_abs(a0) + c2d_abs(a1)) + c2d_abs(a2)) + fl;
        d1[i] = b1 + b2;
        dl1[i] = 5 * u * (c2d_abs(b1) + c2d_abs(b2)) + fl;
    }
    c2d_toia_fg_from_d(c, d, dl, d1, dl1, E, E1, 5 * u, o);
    c2d_toia_h_from_d(c, d, dl, d1, dl1, E, E1, 5 * u, 2 * u, o);
    o->tier = 1;
}

/* (ah + al) + (bh + bl) on bare parts: one TwoSum of the high parts, the
 * low parts added to its error, one TwoSum to renormalise; within 4 u^2 of
 * the operands' magnitudes.  Cheaper than c2d_dd_add (real/arith/dd.h),
 * which also sums the low parts exactly and renormalises twice, and not the
 * same bits: the bounds below take 4 u^2 per operation for it and for
 * c2d_dd_mul_parts. */
static c2d_real c2d_toia_add_parts(c2d_real ah, c2d_real al, c2d_real bh, c2d_real bl, c2d_real *l)
{
    c2d_real err, s = c2d_two_sum(ah, bh, &err);
    err += al + bl;
    return c2d_two_sum(s, err, l);
}

/* From double-length d, d' (units 2^E, 2^E1) with bounds dl, dl1 to f, g,
 * h, hp in double length (tiers 2 and 3).  Rounding to one working value
 * adds u of it to each bound. */
static void c2d_toia_finish_double(c2d_toia_ctx *c, const c2d_real *dh, const c2d_real *dlo, const c2d_real *dl,
                             const c2d_real *d1h, const c2d_real *d1lo, const c2d_real *dl1, int E, int E1,
                             c2d_toia_values *o)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1), u2 = 16 * u * u, fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real xh, xl, yh, yl, sh, sl, v, mag, rr = c2d_toia_radius_scaled(c, E);
    /* f = d0^2 + d1^2 - R^2 */
    if (rr < 0) {
        c2d_toia_f_radius_dominates(c, E, &o->qty[C2D_TOIA_QF], &o->fmag);
    } else {
        xh = c2d_dd_mul_parts(dh[0], dlo[0], dh[0], dlo[0], &xl);
        yh = c2d_dd_mul_parts(dh[1], dlo[1], dh[1], dlo[1], &yl);
        sh = c2d_toia_add_parts(xh, xl, yh, yl, &sl);
        yh = c2d_two_prod(rr, rr, &yl);
        mag = sh + yh;
        sh = c2d_toia_add_parts(sh, sl, -yh, -yl, &sl);
        v = sh + sl;
        c2d_toia_bounded_set(&o->qty[C2D_TOIA_QF], v,
                       (2 * c2d_abs(dh[0]) + dl[0]) * dl[0] + (2 * c2d_abs(dh[1]) + dl[1]) * dl[1] + u2 * mag +
                           u * c2d_abs(v) + fl,
                       2 * E);
        o->fmag = mag;
    }
    /* g = d . d' */
    xh = c2d_dd_mul_parts(dh[0], dlo[0], d1h[0], d1lo[0], &xl);
    yh = c2d_dd_mul_parts(dh[1], dlo[1], d1h[1], d1lo[1], &yl);
    mag = c2d_abs(xh) + c2d_abs(yh);
    sh = c2d_toia_add_parts(xh, xl, yh, yl, &sl);
    v = sh + sl;
    c2d_toia_bounded_set(&o->qty[C2D_TOIA_QG], v,
                   (c2d_abs(d1h[0]) + dl1[0]) * dl[0] + c2d_abs(dh[0]) * dl1[0] + (c2d_abs(d1h[1]) + dl1[1]) * dl[1] +
                       c2d_abs(dh[1]) * dl1[1] + u2 * mag + u * c2d_abs(v) + fl,
                   E + E1);
    o->gmag = mag;
    /* h and hp only steer the search: plain arithmetic on the rounded
     * values suffices (bounds as tier 1, with the lo parts' bounds). */
    {
        c2d_real d[2], d1[2], e[2], e1[2];
        int i;
        for (i = 0; i < 2; i++) {
            d[i] = dh[i] + dlo[i];
            d1[i] = d1h[i] + d1lo[i];
            e[i] = dl[i] + u * c2d_abs(d[i]);
            e1[i] = dl1[i] + u * c2d_abs(d1[i]);
        }
        c2d_toia_h_from_d(c, d, e, d1, e1, E, E1, 5 * u, 2 * u, o);
    }
}

/* Tier 2: double-length arithmetic at t = (th + tl) 2^te, with the lo parts
 * of d0, v, a.  ERROR: each term of d is formed by one or two double-length
 * products (t^2, a t^2) and the three are added twice: |d - d~| <=
 * 16 u^2 s + floor (u^2 s for the lo parts below the common scale, 4 u^2 per
 * operation, rounded up); d' with 12 u^2. */
C2D_COLD void c2d_toia_eval_double(c2d_toia_ctx *c, const c2d_dd *t, c2d_toia_values *o)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1), fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real sc[5], dh[2], dlo[2], dl[2], d1h[2], d1lo[2], dl1[2], t2h, t2l, th = t->h, tl = t->l;
    int E, E1, i;
    c2d_toia_scales(c, t, &E, &E1, sc);
    t2h = c2d_dd_mul_parts(th, tl, th, tl, &t2l);
    for (i = 0; i < 2; i++) {
        c2d_real ph, pl, vh, vl, ah, al, s, l;
        ph = c->hi[0][i] * sc[0];
        pl = c->lo[0][i] * sc[0];
        vh = c2d_dd_mul_parts(c->hi[1][i], c->lo[1][i], th, tl, &vl);
        vh *= sc[1];
        vl *= sc[1];
        ah = c2d_dd_mul_parts(c->hi[2][i], c->lo[2][i], t2h, t2l, &al);
        ah *= sc[2];
        al *= sc[2];
        s = c2d_abs(ph) + c2d_abs(vh) + c2d_abs(ah);
        dh[i] = c2d_toia_add_parts(ph, pl, vh, vl, &l);
        dh[i] = c2d_toia_add_parts(dh[i], l, ah, al, &dlo[i]);
        dl[i] = 20 * u * u * s + fl;
        vh = c->hi[1][i] * sc[3];
        vl = c->lo[1][i] * sc[3];
        ah = c2d_dd_mul_parts(c->hi[2][i], c->lo[2][i], th, tl, &al);
        ah *= sc[4];
        al *= sc[4];
        s = c2d_abs(vh) + c2d_abs(ah);
        d1h[i] = c2d_toia_add_parts(vh, vl, ah, al, &d1lo[i]);
        dl1[i] = 12 * u * u * s + fl;
    }
    c2d_toia_finish_double(c, dh, dlo, dl, d1h, d1lo, dl1, E, E1, o);
    o->tier = 2;
}

/* Tier 3: d and d' at the working-precision time th 2^te EXACTLY (sums of
 * exact products of the exact differences, c2d_toia_exact_sum), rounded to
 * double length with relative error (k + 3) u^2; then the double-length
 * correction d += d'(th) tl + a tl^2 / 2, d' += a tl for the low part of t.
 * The bound on d is therefore relative to |d| itself (plus the correction's
 * terms), not to the terms that cancel in it: f is certified unless
 * |f| <= ~ 2 (k + 3) u^2 (|d|^2 + R^2), i.e. unless |d| is within a relative
 * ~ 20 u^2 of R. */
/* One component, exactly: d_i(th) (which 0: 2 + 4 + 8 atoms at most) or
 * d'_i(th) (1: 2 + 4), rounded to double length: (*h + *l) 2^return,
 * relative error (2k + 2) u^2 with k returned in *k. */
C2D_COLD int c2d_toia_d_component_exact(c2d_toia_ctx *c, const c2d_dd *t, int i, int which, c2d_real *h,
                                        c2d_real *l, int *k)
{
    c2d_real m[C2D_TOIA_DATOMS], lo, hi;
    int e[C2D_TOIA_DATOMS], j, n = 0;
    c2d_ext T, T2[2], q;
    c2d_ext_set(&T, t->h, t->e);
    hi = c2d_two_prod(t->h, t->h, &lo);
    c2d_ext_set(&T2[0], hi, 2 * t->e);
    c2d_ext_set(&T2[1], lo, 2 * t->e);
    for (j = 0; j < 2; j++) {
        if (which == 0) {
            c2d_toia_part(c, 0, i, j, &q);
            n = c2d_toia_push_atom(m, e, n, &q, 1);
            c2d_toia_part(c, 1, i, j, &q);
            n = c2d_toia_push_product(m, e, n, &q, &T, 0, 1);
            c2d_toia_part(c, 2, i, j, &q);
            n = c2d_toia_push_product(m, e, n, &q, &T2[0], -1, 1);
            n = c2d_toia_push_product(m, e, n, &q, &T2[1], -1, 1);
        } else {
            c2d_toia_part(c, 1, i, j, &q);
            n = c2d_toia_push_atom(m, e, n, &q, 1);
            c2d_toia_part(c, 2, i, j, &q);
            n = c2d_toia_push_product(m, e, n, &q, &T, 0, 1);
        }
    }
    return c2d_toia_exact_sum(m, e, n, h, l, k);
}

C2D_COLD void c2d_toia_d_exact(c2d_toia_ctx *c, const c2d_dd *t, c2d_real *dh, c2d_real *dlo,
                                          c2d_real *dl, c2d_real *d1h, c2d_real *d1lo, c2d_real *dl1, int *Eout,
                                          int *E1out)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1), fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real h[4], l[4], rel[4];
    int ex[4], i, k, E, E1;
    for (i = 0; i < 4; i++) {
        ex[i] = c2d_toia_d_component_exact(c, t, i & 1, i >> 1, &h[i], &l[i], &k);
        rel[i] = (c2d_real)(2 * k + 4) * u * u;
    }
    /* Common scales: E for d, E1 for d' (the largest term's exponent + 3,
     * so the components and the tl corrections stay below 1): d(th) and
     * d'(th) (components below 2^(ex+1)), and when t has a low part the
     * corrections d'(th) tl, a tl^2 / 2 and a tl. */
    {
        int have = 0, have1 = 0, el = t->l != 0 ? c2d_ilogb(t->l) + t->e + 1 : 0;
        E = 0;
        E1 = 0;
        for (i = 0; i < 2; i++) {
            if (h[i] != 0 && (have == 0 || ex[i] > E)) {
                E = ex[i];
                have = 1;
            }
            if (h[2 + i] != 0 && (have1 == 0 || ex[2 + i] > E1)) {
                E1 = ex[2 + i];
                have1 = 1;
            }
        }
        if (t->l != 0) {
            if (have1 != 0 && (have == 0 || E1 + el > E)) {
                E = E1 + el;
                have = 1;
            }
            if (c->nonzero[2] != 0) {
                if (have == 0 || c->exp[2] + 2 * el > E) E = c->exp[2] + 2 * el;
                if (have1 == 0 || c->exp[2] + 1 + el > E1) E1 = c->exp[2] + 1 + el;
                have = 1;
                have1 = 1;
            }
        }
        if (have1 == 0) E1 = E;
        if (have == 0) E = E1;
        E += 3;
        E1 += 3;
    }
    for (i = 0; i < 2; i++) {
        c2d_real s = c2d_toia_pow2_clamped(ex[i] - E), s1 = c2d_toia_pow2_clamped(ex[2 + i] - E1);
        dh[i] = h[i] * s;
        dlo[i] = l[i] * s;
        dl[i] = rel[i] * c2d_abs(dh[i]) + fl;
        d1h[i] = h[2 + i] * s1;
        d1lo[i] = l[2 + i] * s1;
        dl1[i] = rel[2 + i] * c2d_abs(d1h[i]) + fl;
    }
    if (t->l != 0) {
        /* d += d'(th) tl + a tl^2 / 2 and d' += a tl in double length, tl =
         * t.l 2^te expressed in d's units through d' (exponents folded into
         * one scale2 each, so nothing over- or underflows on the way).
         * |tl| <= ulp(th): small corrections; their rounding is bounded by
         * 8 u^2 of their size, plus 4 u of the plain a tl^2 / 2 term. */
        c2d_real tls = c2d_scale2(t->l, t->e + E1 - E);
        for (i = 0; i < 2; i++) {
            c2d_real ch, cl, ah = 0, al = 0, s2;
            ch = c2d_dd_mul_parts(d1h[i], d1lo[i], tls, 0, &cl);
            if (c->nonzero[2] != 0) ah = c2d_scale2(c->hi[2][i] * (t->l * t->l), c->exp[2] + 2 * t->e - 1 - E);
            s2 = c2d_abs(ch) + c2d_abs(ah);
            dh[i] = c2d_toia_add_parts(dh[i], dlo[i], ch, cl + ah, &dlo[i]);
            dl[i] += (rel[2 + i] + 8 * u * u) * s2 + 4 * u * c2d_abs(ah) + fl;
            if (c->nonzero[2] != 0) {
                ah = c2d_dd_mul_parts(c->hi[2][i], c->lo[2][i], t->l, 0, &al);
                ah = c2d_scale2(ah, c->exp[2] + t->e - E1);
                al = c2d_scale2(al, c->exp[2] + t->e - E1);
                d1h[i] = c2d_toia_add_parts(d1h[i], d1lo[i], ah, al, &d1lo[i]);
                dl1[i] += 8 * u * u * c2d_abs(ah) + fl;
            }
        }
    }
    *Eout = E;
    *E1out = E1;
}

C2D_COLD void c2d_toia_eval_exact(c2d_toia_ctx *c, const c2d_dd *t, c2d_toia_values *o)
{
    c2d_real dh[2], dlo[2], dl[2], d1h[2], d1lo[2], dl1[2];
    int E, E1;
    c2d_toia_d_exact(c, t, dh, dlo, dl, d1h, d1lo, dl1, &E, &E1);
    c2d_toia_finish_double(c, dh, dlo, dl, d1h, d1lo, dl1, E, E1, o);
    o->tier = 3;
}


/* Evaluate at t with the tier `from` first and escalate while a sign in
 * `need` (mask of C2D_TOIA_M*) is uncertain; o->sign[] gets each needed
 * quantity's certified sign (0 only if tier 3 could not certify it: the
 * tie cases of the contract), o->qty[] the values of the last tier used. */
C2D_COLD void c2d_toia_probe(c2d_toia_ctx *c, const c2d_dd *t, int need, int from, c2d_toia_values *o)
{
    int tier, k, sg[4];
    for (k = 0; k < 4; k++) sg[k] = 0;
    if (from < 2 && t->l != 0) from = 2;
    for (tier = from; tier <= 3; tier++) {
        int open = 0;
        if (tier == 1) {
            c2d_toia_eval_plain(c, t, o);
        } else if (tier == 2) {
            c2d_toia_eval_double(c, t, o);
        } else {
            c2d_toia_eval_exact(c, t, o);
        }
        for (k = 0; k < 4; k++) {
            if (sg[k] == 0) {
                if (o->qty[k].value > o->qty[k].bound) sg[k] = 1;
                else if (o->qty[k].value < -o->qty[k].bound) sg[k] = -1;
            }
            if ((need & (1 << k)) != 0 && sg[k] == 0) open = 1;
        }
        if (open == 0) break;
    }
    for (k = 0; k < 4; k++) o->sign[k] = sg[k];
}

/* probe, keeping f and g and their signs (a bracket end).  Records are
 * copied field by field: a struct assignment may become a memcpy call, and
 * the library must need no C library. */
C2D_COLD void c2d_toia_probe_fg(c2d_toia_ctx *c, const c2d_dd *t, int from, c2d_toia_fg *o)
{
    c2d_toia_values ev;
    c2d_toia_probe(c, t, C2D_TOIA_MF | C2D_TOIA_MG, from, &ev);
    c2d_toia_bounded_set(&o->f, ev.qty[C2D_TOIA_QF].value, ev.qty[C2D_TOIA_QF].bound, ev.qty[C2D_TOIA_QF].exp);
    c2d_toia_bounded_set(&o->g, ev.qty[C2D_TOIA_QG].value, ev.qty[C2D_TOIA_QG].bound, ev.qty[C2D_TOIA_QG].exp);
    o->sign_f = ev.sign[C2D_TOIA_QF];
    o->sign_g = ev.sign[C2D_TOIA_QG];
}

static void c2d_toia_fg_copy(c2d_toia_fg *d, const c2d_toia_fg *s)
{
    c2d_toia_bounded_set(&d->f, s->f.value, s->f.bound, s->f.exp);
    c2d_toia_bounded_set(&d->g, s->g.value, s->g.bound, s->g.exp);
    d->sign_f = s->sign_f;
    d->sign_g = s->sign_g;
}
/* ===================================================================== */

#endif /* C2D_REAL_TOIA_EVAL_H */
