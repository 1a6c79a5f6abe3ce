/* SPDX-License-Identifier: MIT */
/* real/toia/turns.h - template, accelerated time of impact: the turning
 * points of f (roots of g, bracketed, with f's value there; a = 0 and
 * collinear motion decided exactly) and of g (the roots of the quadratic h,
 * with g's sign certified on the slivers).  See real/toia/README.md. */
#ifndef C2D_REAL_TOIA_TURNS_H
#define C2D_REAL_TOIA_TURNS_H
/* Turning points of f: brackets of the roots of g and f's value there   */
/* ===================================================================== */

/* val > 0 with a margin of 2^(4 - MANT) of scale (>= 0): a decision that
 * survives the few roundings the bound arithmetic made. */
static int c2d_toia_ext_clearly_positive(const c2d_ext *val, const c2d_ext *scale)
{
    if (!(val->m > 0)) return 0;
    if (scale->m == 0) return 1;
    return val->e > scale->e + 4 - C2D_R_MANT;
}

/* Where c is the root of g in the bracket br (g monotone on it, with sign
 * -dir at br->lo and dir at br->hi), bound f(c):
 *   local minimum of f (dir = +1): f(c) <= f(end) for both ends, and
 *     f(c) >= f(end) - 2 max|g| w (|f'| = 2|g| <= 2|g(end)| between end
 *     and c, w the bracket's width);
 *   local maximum (dir = -1): the same with the roles exchanged;
 * and the optional center evaluation (a point of the bracket) tightens
 * the one-sided bound.  Returns -1 if f(c) < 0 is certain, +1 if f(c) > 0,
 * 0 if neither. */
C2D_COLD int c2d_toia_f_at_turn(const c2d_toia_bracket *br, int dir, const c2d_toia_fg *center)
{
    c2d_ext w, x, z;
    int i, res = 0;
    c2d_toia_time_diff(&w, &br->hi, &br->lo);
    w.m = c2d_abs(w.m);
    for (i = 0; i < 3; i++) {
        const c2d_toia_fg *ev = i == 0 ? &br->at_lo : (i == 1 ? &br->at_hi : center);
        c2d_ext f, r, tg, lo, hi;
        if (ev == NULL) continue;
        c2d_ext_set(&f, ev->f.value, ev->f.exp);
        c2d_ext_set(&r, ev->f.bound, ev->f.exp);
        tg.m = 0;
        tg.e = 0;
        if (i < 2) {
            c2d_ext_set(&x, c2d_abs(ev->g.value) + ev->g.bound, ev->g.exp + 1);
            c2d_ext_mul(&tg, &x, &w);
        }
        /* lo = f - r - (dir > 0 ? tg : 0), hi = f + r + (dir < 0 ? tg : 0);
         * each candidate judged against its own rounding scale |f| + r + tg */
        c2d_ext_add(&lo, &f, &r, -1);
        c2d_ext_add(&hi, &f, &r, 1);
        if (dir > 0) c2d_ext_add(&lo, &lo, &tg, -1);
        else c2d_ext_add(&hi, &hi, &tg, 1);
        z.m = c2d_abs(f.m);
        z.e = f.e;
        c2d_ext_add(&z, &z, &r, 1);
        c2d_ext_add(&z, &z, &tg, 1);
        /* a point value bounds a minimum from above only, a maximum from below */
        if (!(i == 2 && dir > 0) && c2d_toia_ext_clearly_positive(&lo, &z) != 0) res = 1;
        x.m = -hi.m;
        x.e = hi.e;
        if (!(i == 2 && dir < 0) && c2d_toia_ext_clearly_positive(&x, &z) != 0) res = -1;
    }
    return res;
}

/* The plain estimate of g's root in (x, y) (Newton in a local frame): 1 with
 * *r and the exponent *dw of 4 of its uncertainties, 0 if the frame's
 * values are not trustworthy there. */
C2D_COLD int c2d_toia_groot_plain(c2d_toia_ctx *c, const c2d_dd *x, const c2d_dd *y, int dir,
                                         c2d_dd *r, int *dw)
{
    c2d_toia_frame fr;
    c2d_real width = 0, xr;
    int ok = 0, kt = y->e + 1;
    if (c2d_toia_frame_set(&fr, c, kt) == 0) return 0;
    xr = c2d_toia_frame_newton(&fr, C2D_TOIA_QG, c2d_toia_time_local(x, kt), c2d_toia_time_local(y, kt), -dir, &ok,
                               &width);
    if (ok == 0) return 0;
    c2d_dd_set(r, xr, 0, kt);
    *dw = r->e - C2D_R_MANT + 4;
    if (width > 0 && c2d_ilogb(width) + kt + 3 > *dw) *dw = c2d_ilogb(width) + kt + 3;
    return 1;
}

/* The exponent of 4 times the double-length Newton step on g at r plus
 * its noise, at least dw. */
C2D_COLD int c2d_toia_groot_step_exp(c2d_toia_ctx *c, const c2d_dd *r, int dw)
{
    c2d_toia_values ev;
    c2d_toia_eval_double(c, r, &ev);
    if (ev.qty[C2D_TOIA_QH].value != 0) {
        c2d_ext st;
        c2d_ext_set(&st, (c2d_abs(ev.qty[C2D_TOIA_QG].value) + ev.qty[C2D_TOIA_QG].bound) / c2d_abs(ev.qty[C2D_TOIA_QH].value),
                       ev.qty[C2D_TOIA_QG].exp - ev.qty[C2D_TOIA_QH].exp);
        if (st.m != 0 && st.e + 3 > dw) dw = st.e + 3;
    }
    return dw;
}

/* The double-length estimate of g's root in (x, y) (certified search and
 * Newton), with the exponent *dw of its uncertainty (at least 16 ulp of the
 * working format). */
C2D_COLD void c2d_toia_groot_double(c2d_toia_ctx *c, const c2d_dd *x, const c2d_dd *y, int dir,
                                       c2d_dd *r, int *dw)
{
    c2d_toia_root(c, x, y, C2D_TOIA_QG, -dir, r);
    *dw = c2d_toia_groot_step_exp(c, r, r->e - C2D_R_MANT + 4);
}

/* Bracket the root of g in the piece (x, y), where g has sign -dir at x
 * and dir at y: the plain estimate first (Newton in a local frame), else or
 * if it cannot be certified the double-length one; then certified signs of
 * g at the estimate +- 4 uncertainties (widening 64-fold: up to twice for
 * the plain estimate, three times for the other); at worst the piece
 * itself.  f and g are evaluated at both ends. */
C2D_COLD void c2d_toia_groot_bracket(c2d_toia_ctx *c, const c2d_dd *x, const c2d_dd *y, int dir,
                                            c2d_toia_bracket *br)
{
    c2d_dd r;
    int k, dw = 0, pass = 1;
    if (c2d_toia_groot_plain(c, x, y, dir, &r, &dw) != 0) pass = 0;
    for (; pass < 2; pass++) {
        int widenings = 4;
        if (pass == 1) c2d_toia_groot_double(c, x, y, dir, &r, &dw);
        if (pass == 0) widenings = 2;
        for (k = 0; k < widenings; k++) {
            c2d_dd_copy(&br->lo, &r);
            c2d_toia_time_add(&br->lo, -1, dw);
            if (c2d_toia_time_cmp(&br->lo, x) < 0) c2d_dd_copy(&br->lo, x);
            c2d_dd_copy(&br->hi, &r);
            c2d_toia_time_add(&br->hi, 1, dw);
            if (c2d_toia_time_cmp(&br->hi, y) > 0) c2d_dd_copy(&br->hi, y);
            c2d_toia_probe_fg(c, &br->lo, 1, &br->at_lo);
            if (br->at_lo.sign_g == -dir) {
                c2d_toia_probe_fg(c, &br->hi, 1, &br->at_hi);
                if (br->at_hi.sign_g == dir) return;
            }
            dw += 6;
        }
    }
    c2d_dd_copy(&br->lo, x);
    c2d_dd_copy(&br->hi, y);
    c2d_toia_probe_fg(c, &br->lo, 1, &br->at_lo);
    c2d_toia_probe_fg(c, &br->hi, 1, &br->at_hi);
}

/* Tighten a bracket whose f-decision was a tie: double-length Newton on g
 * from its middle, certified signs (tiers 2-3) at +- 4 steps, and a tier-3
 * value of f at the center (*ct). */
C2D_COLD void c2d_toia_tighten(c2d_toia_ctx *c, c2d_toia_bracket *br, int dir, c2d_dd *ct,
                                           c2d_toia_fg *center)
{
    c2d_dd lo, hi;
    c2d_toia_fg elo, ehi;
    int dw;
    c2d_toia_time_mid(ct, &br->lo, &br->hi);
    (void)c2d_toia_polish(c, ct, C2D_TOIA_QG, &br->lo, &br->hi, 2 * C2D_R_MANT + 2);
    dw = c2d_toia_groot_step_exp(c, ct, ct->e - 2 * C2D_R_MANT + 2);
    c2d_dd_copy(&lo, ct);
    c2d_toia_time_add(&lo, -1, dw);
    c2d_dd_copy(&hi, ct);
    c2d_toia_time_add(&hi, 1, dw);
    if (c2d_toia_time_cmp(&lo, &br->lo) > 0 && c2d_toia_time_cmp(&hi, &br->hi) < 0) {
        c2d_toia_probe_fg(c, &lo, 2, &elo);
        c2d_toia_probe_fg(c, &hi, 2, &ehi);
        if (elo.sign_g == -dir && ehi.sign_g == dir) {
            c2d_dd_copy(&br->lo, &lo);
            c2d_dd_copy(&br->hi, &hi);
            c2d_toia_fg_copy(&br->at_lo, &elo);
            c2d_toia_fg_copy(&br->at_hi, &ehi);
        }
    }
    c2d_toia_probe_fg(c, ct, 3, center);
}

/* Append the atoms of x cross y = x0 y1 - x1 y0 for input differences kx, ky. */
static int c2d_toia_push_cross(const c2d_toia_ctx *c, c2d_real *m, int *e, int n, int kx, int ky)
{
    int j, k;
    for (j = 0; j < 2; j++)
        for (k = 0; k < 2; k++) {
            c2d_ext x, y;
            c2d_toia_part(c, kx, 0, j, &x);
            c2d_toia_part(c, ky, 1, k, &y);
            n = c2d_toia_push_product(m, e, n, &x, &y, 0, 1);
            c2d_toia_part(c, kx, 1, j, &x);
            c2d_toia_part(c, ky, 0, k, &y);
            n = c2d_toia_push_product(m, e, n, &x, &y, 0, -1);
        }
    return n;
}

/* a = 0: g = d0.v + |v|^2 t has its root at c = -d0.v / |v|^2, and by
 * Lagrange's identity f(c) |v|^2 = (d0 x v)^2 - R^2 |v|^2: no time enters,
 * so even a contact far shorter than any resolution of t is decided.
 * X = d0 x v and V = |v|^2 are exact sums rounded to double length
 * (relative errors (2k + 2) u^2), then X^2 - R^2 V in double length.
 * Returns the sign of f(c) (-1 contact, +1 miss), 0 if within its bound. */
C2D_COLD int c2d_toia_lin_min(c2d_toia_ctx *c)
{
    const c2d_real u2 = c2d_pow2(-2 * C2D_R_MANT - 2), fl = c2d_pow2(C2D_R_EMIN + 4);
    c2d_real m[C2D_TOIA_ATOMS], xh, xl, vh, vl, ah = 0, al = 0, bh, bl, rh, rl, qh, ql, sa, sb, bound;
    int e[C2D_TOIA_ATOMS], n, kx, kv, ex, ev, ea, eb, E;
    n = c2d_toia_push_cross(c, m, e, 0, 0, 1);
    ex = c2d_toia_exact_sum(m, e, n, &xh, &xl, &kx);
    n = c2d_toia_push_dot(c, m, e, 0, 1, 1, 1);
    ev = c2d_toia_exact_sum(m, e, n, &vh, &vl, &kv);
    if (xh != 0) ah = c2d_dd_mul_parts(xh, xl, xh, xl, &al);
    ea = 2 * ex;
    rh = c2d_two_prod(c->radius.m, c->radius.m, &rl);
    bh = c2d_dd_mul_parts(rh, rl, vh, vl, &bl);
    eb = 2 * c->radius.e + ev;
    E = (xh != 0 && ea > eb) ? ea : eb;
    sa = c2d_toia_pow2_clamped(ea - E);
    sb = c2d_toia_pow2_clamped(eb - E);
    qh = c2d_toia_add_parts(ah * sa, al * sa, -bh * sb, -bl * sb, &ql);
    bound = ((c2d_real)(4 * kx + 12) * c2d_abs(ah * sa) + (c2d_real)(2 * kv + 12) * c2d_abs(bh * sb)) * u2 + fl;
    if (qh + ql > bound) return 1;
    if (qh + ql < -bound) return -1;
    return 0;
}

/* d0, v and a all parallel (exactly: their three cross products vanish):
 * the relative motion runs along one line through the origin. */
C2D_COLD int c2d_toia_collinear(c2d_toia_ctx *c)
{
    c2d_real m[C2D_TOIA_ATOMS], hi, lo;
    int e[C2D_TOIA_ATOMS], n, k, i, j;
    for (i = 0; i < 3; i++)
        for (j = i + 1; j < 3; j++) {
            n = c2d_toia_push_cross(c, m, e, 0, i, j);
            (void)c2d_toia_exact_sum(m, e, n, &hi, &lo, &k);
            if (hi != 0) return 0;
        }
    return 1;
}

/* For collinear motion: d(lo) and d(hi) point in opposite directions, so
 * the path passes through the origin between them (distance 0 < R).  d is
 * parallel to the nonzero input vector w, so d.w has no cancellation and
 * its double-length value has the exact sign. */
C2D_COLD int c2d_toia_crosses(c2d_toia_ctx *c, const c2d_toia_bracket *br)
{
    c2d_real dh[2], dlo[2], dl[2], d1h[2], d1lo[2], dl1[2], s0, s1;
    const c2d_real *w = c->nonzero[0] != 0 ? c->hi[0] : (c->nonzero[1] != 0 ? c->hi[1] : c->hi[2]);
    int E, E1;
    c2d_toia_d_exact(c, &br->lo, dh, dlo, dl, d1h, d1lo, dl1, &E, &E1);
    s0 = dh[0] * w[0] + dh[1] * w[1];
    c2d_toia_d_exact(c, &br->hi, dh, dlo, dl, d1h, d1lo, dl1, &E, &E1);
    s1 = dh[0] * w[0] + dh[1] * w[1];
    return (s0 > 0 && s1 < 0) || (s0 < 0 && s1 > 0);
}

/* The decision at a minimum of f, the root of g in the piece (x, y) where
 * g goes from - to +: -1 contact (f(c) < 0), +1 no contact, 0 a graze tie
 * (no contact).  On -1, *neg = a time in the piece's bracket where f < 0 is
 * certified, or NULL when no representable time has f < 0 (a contact
 * shorter than the time resolution): then *ct is the minimum's location. */
C2D_COLD int c2d_toia_f_min_sign(c2d_toia_ctx *c, const c2d_dd *x, const c2d_dd *y, c2d_toia_bracket *br,
                                       c2d_dd *ct, c2d_toia_fg *center, const c2d_dd **neg)
{
    int d, tight = 0;
    *neg = NULL;
    center->sign_f = 0;
    if (c->nonzero[2] == 0) {
        d = c2d_toia_lin_min(c);
        if (d >= 0) return d;
        c2d_toia_groot_bracket(c, x, y, 1, br);
    } else {
        c2d_toia_groot_bracket(c, x, y, 1, br);
        d = c2d_toia_f_at_turn(br, 1, NULL);
        if (d == 0) {
            c2d_toia_tighten(c, br, 1, ct, center);
            tight = 1;
            d = c2d_toia_f_at_turn(br, 1, center);
            if (d == 0 && c2d_toia_collinear(c) != 0 && c2d_toia_crosses(c, br) != 0) d = -1;
        }
        if (d >= 0) return d;
    }
    if (br->at_lo.sign_f < 0) {
        *neg = &br->lo;
    } else if (br->at_hi.sign_f < 0) {
        *neg = &br->hi;
    } else {
        if (tight == 0) c2d_toia_tighten(c, br, 1, ct, center);
        if (br->at_lo.sign_f < 0) *neg = &br->lo;
        else if (br->at_hi.sign_f < 0) *neg = &br->hi;
        else if (center->sign_f < 0) *neg = ct;
    }
    return -1;
}

/* ===================================================================== */
/* Turning points of g: the roots of h = g' (a quadratic)                */
/* ===================================================================== */

/* Certify the sign of g on the "sliver" between s, an approximation of a
 * root q of h with h' of sign kind at s, and q itself.  h is exactly
 * quadratic: h(s + x) = h(s) + h'(s) x + (h''/2) x^2, h'' = 3|a|^2 > 0; if
 * h(s) < 0, or h'(s)^2 >= 2 h'' h(s), the root nearest s is at
 * 2|h(s)| / (|h'(s)| + sqrt(h'(s)^2 - 2 h'' h(s))), within D = 2|h(s)|/|h'(s)|
 * (and it is q: the nearer root lies on s's side of the vertex, which
 * h'(s)'s sign tells), |h| <= |h(s)| between, and g varies there by at
 * most S = |h(s)| D.  So sign(g(s)) holds on the whole sliver if
 * |g(s)| > S.  With bounds: |h(s)| <= H, |h'(s)| >= P.  Tried with tier 1,
 * then after two double-length Newton steps on h with tiers 2 and 3; if it
 * never holds, g is within S of 0 at its extremum: the tie value kind (g
 * touching 0 from below at a maximum, from above at a minimum: no sign
 * change) is returned.  *sf = f's sign at s if tier 1 certified it. */
C2D_COLD int c2d_toia_split_sign(c2d_toia_ctx *c, c2d_dd *s, int kind, int *sf, int *tied)
{
    c2d_toia_values ev;
    c2d_ext h2, H, P, D, S, G, x, y;
    int tier;
    *sf = 0;
    *tied = 0;
    /* h'' = 3 |a|^2, rounded up */
    c2d_ext_set(&h2,
                   3 * (c->hi[2][0] * c->hi[2][0] + c->hi[2][1] * c->hi[2][1]) * (1 + c2d_pow2(3 - C2D_R_MANT)),
                   2 * c->exp[2]);
    for (tier = 1; tier <= 3; tier++) {
        if (tier == 1) {
            c2d_toia_eval_plain(c, s, &ev);
            if (c2d_abs(ev.qty[C2D_TOIA_QF].value) > ev.qty[C2D_TOIA_QF].bound)
                *sf = c2d_toia_sign_of(ev.qty[C2D_TOIA_QF].value);
        } else {
            if (tier == 2) {
                c2d_dd lo, hi;
                c2d_dd_copy(&lo, s);
                c2d_dd_copy(&hi, s);
                c2d_toia_time_add(&lo, -1, s->e - 8);
                c2d_toia_time_add(&hi, 1, s->e - 8);
                (void)c2d_toia_polish(c, s, C2D_TOIA_QH, &lo, &hi, 2 * C2D_R_MANT);
                c2d_toia_eval_double(c, s, &ev);
            } else {
                c2d_toia_eval_exact(c, s, &ev);
            }
        }
        if (!(c2d_abs(ev.qty[C2D_TOIA_QHP].value) > ev.qty[C2D_TOIA_QHP].bound) ||
            c2d_toia_sign_of(ev.qty[C2D_TOIA_QHP].value) != kind)
            continue;
        c2d_ext_set(&H, c2d_abs(ev.qty[C2D_TOIA_QH].value) + ev.qty[C2D_TOIA_QH].bound, ev.qty[C2D_TOIA_QH].exp);
        c2d_ext_set(&P, c2d_abs(ev.qty[C2D_TOIA_QHP].value) - ev.qty[C2D_TOIA_QHP].bound, ev.qty[C2D_TOIA_QHP].exp);
        /* the root exists within D unless h(s) may be positive (same sign as
         * h''): then P^2 >= 2 h'' H is needed (with slack) */
        if (!(ev.qty[C2D_TOIA_QH].value + ev.qty[C2D_TOIA_QH].bound < 0)) {
            c2d_ext_mul(&x, &P, &P);
            c2d_ext_mul(&y, &h2, &H);
            y.e += 1;
            if (H.m != 0 && c2d_toia_ext_cmp(&x, &y) <= 0) continue;
        }
        /* D = 2 H / P, S = H D (rounded up by the slack in the test) */
        c2d_ext_set(&D, 2 * H.m / P.m, H.e - P.e);
        c2d_ext_mul(&S, &H, &D);
        S.m *= 1 + c2d_pow2(4 - C2D_R_MANT);
        c2d_ext_set(&G, c2d_abs(ev.qty[C2D_TOIA_QG].value) - ev.qty[C2D_TOIA_QG].bound, ev.qty[C2D_TOIA_QG].exp);
        if (G.m > 0 && c2d_toia_ext_cmp(&G, &S) > 0) return c2d_toia_sign_of(ev.qty[C2D_TOIA_QG].value);
    }
    *tied = 1;
    return kind;
}

/* x.y (+ z.w) for input differences, as a double-length number: the exact
 * sum of the exact products when exact != 0, else from the hi parts in
 * plain arithmetic (a hint; relative error a few u unless it cancels). */
static void c2d_toia_dot_inputs(c2d_toia_ctx *c, int kx, int ky, int kz, int kw, int sgn, int exact, c2d_dd *r);

/* An exact sum of products (atoms) as a double-length number. */
static void c2d_toia_exact_sum_dd(c2d_dd *r, c2d_real *m, int *e, int n)
{
    c2d_real hi, lo;
    int k, ex = c2d_toia_exact_sum(m, e, n, &hi, &lo, &k);
    c2d_dd_set(r, hi, lo, ex);
}

/* x.y (+ z.w) as the exact sum of the exact products, to double length. */
static void c2d_toia_dot_exact(const c2d_toia_ctx *c, int kx, int ky, int kz, int kw, int sgn, c2d_dd *r)
{
    c2d_real m[C2D_TOIA_ATOMS];
    int e[C2D_TOIA_ATOMS], n = c2d_toia_push_dot(c, m, e, 0, kx, ky, sgn);
    if (kz >= 0) n = c2d_toia_push_dot(c, m, e, n, kz, kw, sgn);
    c2d_toia_exact_sum_dd(r, m, e, n);
}

static void c2d_toia_dot_inputs(c2d_toia_ctx *c, int kx, int ky, int kz, int kw, int sgn, int exact, c2d_dd *r)
{
    if (exact != 0) {
        /* |a|^2, -v.a, v.a and |v|^2 + d0.a (the sums the splits ask for,
         * again and again) are kept; any other is formed each time */
        c2d_toia_parts *p = c->parts;
        int slot = -1;
        if (kz < 0 && kx == 2 && ky == 2 && sgn > 0) slot = 0;
        if (kz < 0 && kx == 1 && ky == 2) {
            slot = 2;
            if (sgn < 0) slot = 1;
        }
        if (kz == 0 && kw == 2 && kx == 1 && ky == 1 && sgn > 0) slot = 3;
        if (slot < 0) {
            c2d_toia_dot_exact(c, kx, ky, kz, kw, sgn, r);
        } else {
            const unsigned bit = 1U << (unsigned)(3 + slot);
            if ((p->ready & bit) == 0U) {
                c2d_toia_dot_exact(c, kx, ky, kz, kw, sgn, &p->dot[slot]);
                p->ready |= bit;
            }
            c2d_dd_copy(r, &p->dot[slot]);
        }
    } else {
        c2d_dd p, q;
        c2d_dd_set(&p, c->nonzero[kx] * c->nonzero[ky] != 0 ? (c2d_real)sgn * (c->hi[kx][0] * c->hi[ky][0] + c->hi[kx][1] * c->hi[ky][1]) : 0,
                       0, c->exp[kx] + c->exp[ky]);
        if (kz >= 0) {
            c2d_dd_set(&q, c->nonzero[kz] * c->nonzero[kw] != 0 ? (c2d_real)sgn * (c->hi[kz][0] * c->hi[kw][0] + c->hi[kz][1] * c->hi[kw][1]) : 0,
                           0, c->exp[kz] + c->exp[kw]);
            c2d_toia_time_sum(r, &p, &q);
        } else {
            c2d_dd_copy(r, &p);
        }
    }
}

/* The roots of the quadratic h(t) = (3/2)|a|^2 t^2 + 3 (v.a) t + h(0), as
 * double-length hints (then polished and certified by the caller).  Its
 * coefficients are exact sums rounded to double length; with beta =
 * v.a / |a|^2 and gamma = (2/3) h(0) / |a|^2 the roots are -beta +-
 * sqrt(beta^2 - gamma).  The forms used avoid every subtraction of
 * near-equal numbers: the root of larger magnitude is -beta - sgn(beta)
 * sqrt(...), the other gamma over it; and when gamma > 0 with beta < 0 (two
 * positive roots, where beta^2 - gamma cancels), the vertex form m +- w,
 * m = -beta, w^2 = -2 h(m) / h'' with h(m) evaluated at m (at_m, certified
 * negative by the caller): h is exactly quadratic, so h(m) is its minimum
 * and w is accurate to its own precision.  Returns 0 if there is no real
 * root to report.  exact = 0: the coefficients from the hi parts (cheap
 * hints); 1: from exact sums (when the cheap ones did not certify). */
C2D_COLD int c2d_toia_h_roots(c2d_toia_ctx *c, const c2d_toia_values *at_m, int exact, c2d_dd *rm,
                                         c2d_dd *rp)
{
    c2d_dd a2, beta, gamma, x, y, sq;
    c2d_toia_dot_inputs(c, 2, 2, -1, -1, 1, exact, &a2);
    c2d_toia_dot_inputs(c, 1, 2, -1, -1, 1, exact, &x);
    c2d_dd_div(&beta, &x, &a2);
    c2d_toia_dot_inputs(c, 1, 1, 0, 2, 1, exact, &x);
    c2d_dd_div(&gamma, &x, &a2);
    c2d_dd_set(&y, (c2d_real)2 / (c2d_real)3, 0, 0); /* 2/3 to double length is enough for a hint */
    c2d_dd_mul(&gamma, &gamma, &y);
    if (at_m != NULL && beta.h < 0 && gamma.h > 0) {
        /* vertex form: w^2 = -2 h(m) / (3 |a|^2) */
        c2d_dd_set(&x, -2 * at_m->qty[C2D_TOIA_QH].value, 0, at_m->qty[C2D_TOIA_QH].exp);
        c2d_dd_set(&y, 3, 0, 0);
        c2d_dd_mul(&y, &y, &a2);
        c2d_dd_div(&x, &x, &y);
        if (!(x.h > 0)) return 0;
        c2d_dd_sqrt(&sq, &x);
        c2d_dd_copy(&x, &beta);
        c2d_dd_negate(&x);
        c2d_toia_time_sum(rp, &x, &sq); /* m + w */
        /* m - w may cancel: the product of the roots is gamma */
        c2d_dd_div(rm, &gamma, rp);
        return 1;
    }
    c2d_dd_mul(&x, &beta, &beta);
    c2d_dd_copy(&y, &gamma);
    c2d_dd_negate(&y);
    c2d_toia_time_sum(&x, &x, &y);
    if (!(x.h > 0)) return 0;
    c2d_dd_sqrt(&sq, &x);
    if (beta.h > 0) c2d_dd_negate(&sq);
    c2d_dd_copy(&x, &beta);
    c2d_dd_negate(&x);
    c2d_toia_time_sum(&x, &x, &sq); /* -beta - sgn(beta) sqrt: no cancellation */
    if (x.h == 0) return 0;
    c2d_dd_div(&y, &gamma, &x);
    if (beta.h > 0) {
        c2d_dd_copy(rm, &x);
        c2d_dd_copy(rp, &y);
    } else {
        c2d_dd_copy(rp, &x);
        c2d_dd_copy(rm, &y);
    }
    return 1;
}
/* ===================================================================== */

#endif /* C2D_REAL_TOIA_TURNS_H */
