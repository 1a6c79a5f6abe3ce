/* SPDX-License-Identifier: MIT */
/* real/toia/newton.h - template, accelerated time of impact: the comparison
 * of bounds with slack, plain Newton in a local frame, the double-length
 * polish, and the root finders (bisection and Newton on certified signs).
 * See real/toia/README.md. */
#ifndef C2D_REAL_TOIA_NEWTON_H
#define C2D_REAL_TOIA_NEWTON_H
/* ===================================================================== */
/* Comparing bounds; time differences                                    */
/* ===================================================================== */

/* sign(a - b) of two extended numbers, with a relative slack of
 * 2^(4 - MANT) counted against the claim (returns 0 when closer).  b may
 * have been rounded up out of [1, 2) by 1 + 2^(4 - MANT)
 * (c2d_toia_split_sign): c2d_ext_add's difference may then be off in its
 * last bit, which neither its sign nor the slack test can see
 * (tests/unit/test_ext_add.c). */
static int c2d_toia_ext_cmp(const c2d_ext *a, const c2d_ext *b)
{
    c2d_ext d;
    c2d_ext_add(&d, a, b, -1);
    if (d.m == 0) return 0;
    {
        int top = a->m == 0 ? b->e : (b->m == 0 ? a->e : c2d_toia_max_int(a->e, b->e));
        if (d.e < top + 5 - C2D_R_MANT) return 0;
    }
    return c2d_toia_sign_of(d.m);
}

/* The time difference a - b as an extended number. */
static void c2d_toia_time_diff(c2d_ext *d, const c2d_dd *a, const c2d_dd *b)
{
    c2d_dd w;
    c2d_dd_copy(&w, a);
    c2d_toia_time_add(&w, -b->h, b->e);
    c2d_toia_time_add(&w, -b->l, b->e);
    c2d_ext_set(d, w.h + w.l, w.e);
}

/* ===================================================================== */
/* Plain-arithmetic Newton in a local frame                              */
/* ===================================================================== */

/* The frame for times in [0, 2^kt): lengths in units of 2^kl chosen so
 * every term is below 1/2 there.  Returns 0 when some nonzero input falls
 * so far below the frame's scale (2^(EMIN/2 + MANT)) that squares lose it:
 * the caller then searches with certified evaluations instead. */
static int c2d_toia_frame_set(c2d_toia_frame *fr, c2d_toia_ctx *c, int kt)
{
    int kl = 0, have = 0, k, i, ok = 1;
    const int lim = C2D_R_EMIN / 2 + C2D_R_MANT;
    int ek[3];
    ek[0] = c->exp[0];
    ek[1] = c->exp[1] + kt;
    ek[2] = c->exp[2] + 2 * kt - 1;
    for (k = 0; k < 3; k++) {
        if (c->nonzero[k] != 0 && (have == 0 || ek[k] > kl)) {
            kl = ek[k];
            have = 1;
        }
    }
    kl += 3;
    for (k = 0; k < 3; k++)
        if (c->nonzero[k] != 0 && ek[k] - kl < lim) ok = 0;
    for (i = 0; i < 2; i++) {
        fr->pos[i] = c->nonzero[0] != 0 ? c->hi[0][i] * c2d_toia_pow2_clamped(ek[0] - kl) : 0;
        fr->vel[i] = c->nonzero[1] != 0 ? c->hi[1][i] * c2d_toia_pow2_clamped(ek[1] - kl) : 0;
        fr->acc[i] = c->nonzero[2] != 0 ? c->hi[2][i] * c2d_toia_pow2_clamped(ek[2] + 1 - kl) : 0;
        fr->half_acc[i] = fr->acc[i] * (c2d_real)0.5;
    }
    if (c->radius.e - kl > C2D_R_EMAX / 2 - 4) {
        fr->radius2 = c2d_pow2(C2D_R_EMAX - 8);
    } else {
        c2d_real r = c->radius.m * c2d_toia_pow2_clamped(c->radius.e - kl);
        if (c->radius.e - kl < lim) ok = 0;
        fr->radius2 = r * r;
    }
    fr->time_exp = kt;
    return ok;
}

/* phi = f (which 0) or g (1) at the local time x, its derivative (2g, or
 * h) and *noise, a bound on phi's rounding error in this plain arithmetic
 * (u times the magnitudes of the terms, constants rounded up): where
 * |phi| <= *noise its sign is not known. */
static c2d_real c2d_toia_frame_eval(const c2d_toia_frame *fr, int which, c2d_real x, c2d_real *dphi, c2d_real *noise)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1);
    c2d_real d0 = fr->pos[0] + (fr->vel[0] + fr->half_acc[0] * x) * x;
    c2d_real d1 = fr->pos[1] + (fr->vel[1] + fr->half_acc[1] * x) * x;
    c2d_real e0 = fr->vel[0] + fr->acc[0] * x, e1 = fr->vel[1] + fr->acc[1] * x;
    c2d_real ax = c2d_abs(x);
    c2d_real n0 = 5 * u * (c2d_abs(fr->pos[0]) + (c2d_abs(fr->vel[0]) + c2d_abs(fr->half_acc[0]) * ax) * ax);
    c2d_real n1 = 5 * u * (c2d_abs(fr->pos[1]) + (c2d_abs(fr->vel[1]) + c2d_abs(fr->half_acc[1]) * ax) * ax);
    c2d_real m0 = 3 * u * (c2d_abs(fr->vel[0]) + c2d_abs(fr->acc[0]) * ax);
    c2d_real m1 = 3 * u * (c2d_abs(fr->vel[1]) + c2d_abs(fr->acc[1]) * ax);
    c2d_real g = d0 * e0 + d1 * e1;
    if (which == C2D_TOIA_QF) {
        c2d_real q = d0 * d0 + d1 * d1;
        *dphi = 2 * g;
        *noise = (2 * c2d_abs(d0) + n0) * n0 + (2 * c2d_abs(d1) + n1) * n1 + 4 * u * (q + fr->radius2);
        return q - fr->radius2;
    }
    *dphi = (e0 * e0 + e1 * e1) + (d0 * fr->acc[0] + d1 * fr->acc[1]);
    *noise = (c2d_abs(e0) + m0) * n0 + c2d_abs(d0) * m0 + (c2d_abs(e1) + m1) * n1 + c2d_abs(d1) * m1 +
             3 * u * (c2d_abs(d0 * e0) + c2d_abs(d1 * e1));
    return g;
}

/* Safeguarded Newton on [a, b] (local times) for a root of phi, which has
 * sign sa at a and -sa at b (as the caller certified).  Newton steps while
 * they stay in the bracket and shrink; else bisection (geometric when the
 * bracket spans more than a factor 16).  A value inside its noise does not
 * move the bracket.  Returns the estimate; *ok = 1 when the estimate is
 * trustworthy: the iteration converged and phi's noise there spans at most
 * 2^(8 - MANT) of it (so double-length Newton can finish from it), 0 when
 * cancellation swamps the plain values (the caller then searches with
 * certified double-length values); *width = the last step or the noise's
 * width there, whichever is larger (local units). */
static c2d_real c2d_toia_frame_newton(const c2d_toia_frame *fr, int which, c2d_real a, c2d_real b, int sa, int *ok,
                                 c2d_real *width)
{
    const c2d_real tol = c2d_pow2(-C2D_R_MANT);
    c2d_real x, dphi, prev = b - a, noise;
    int it;
    c2d_real fa = c2d_toia_frame_eval(fr, which, a, &dphi, &noise), fb;
    if (!((c2d_real)sa * fa > noise)) fa = 0;
    fb = c2d_toia_frame_eval(fr, which, b, &dphi, &noise);
    if (!((c2d_real)sa * fb < -noise)) fb = 0;
    *ok = 0;
    *width = b - a;
    /* secant start where the plain values agree with the bracket */
    if (fa != 0 && fb != 0) {
        x = a + (b - a) * (fa / (fa - fb));
    } else {
        x = a + (b - a) * (c2d_real)0.5;
    }
    if (!(x > a && x < b)) x = a + (b - a) * (c2d_real)0.5;
    for (it = 0; it < C2D_TOIA_ITER; it++) {
        c2d_real xn, d, phi = c2d_toia_frame_eval(fr, which, x, &dphi, &noise);
        if (c2d_abs(phi) <= noise) {
            /* in the noise: fine if that region is narrow here */
            *ok = dphi != 0 && noise <= c2d_abs(dphi) * c2d_pow2(8 - C2D_R_MANT) * x;
            *width = dphi != 0 ? noise / c2d_abs(dphi) : b - a;
            return x;
        }
        if ((c2d_real)sa * phi > 0) a = x;
        else b = x;
        xn = x - phi / dphi;
        d = c2d_abs(xn - x);
        if (!(xn > a && xn < b) || !(d <= prev * (c2d_real)0.5)) {
            if (a * 16 < b) xn = a == 0 ? b * (c2d_real)0.0625 : C2D_R_SQRT(a) * C2D_R_SQRT(b);
            else xn = a + (b - a) * (c2d_real)0.5;
            d = c2d_abs(xn - x);
        }
        prev = d;
        if (d <= tol * c2d_abs(xn) || b - a <= tol * b || !(xn > a && xn < b)) {
            *ok = xn > a && xn < b;
            *width = d + noise / (dphi != 0 ? c2d_abs(dphi) : 1);
            return *ok != 0 ? xn : x;
        }
        x = xn;
    }
    return x;
}

/* Local time of t in the frame 2^kt. */
static c2d_real c2d_toia_time_local(const c2d_dd *t, int kt)
{
    if (t->h == 0) return 0;
    return c2d_scale2(t->h + t->l, t->e - kt);
}

/* ===================================================================== */
/* Newton in double length (polish), bisection on certified signs        */
/* ===================================================================== */

/* Newton steps on phi = f (which 0: t -= f / 2g), g (1: t -= g / h) or h
 * (2: t -= h / hp) with
 * tier-2 values (tier 3 when tier 2's bound is a sizeable fraction of what
 * a working-precision rounding of |d| costs), kept inside [lo, hi].
 * Returns 1 when the last step fell below 2^-bits t or the value
 * reached its noise level (the root is then within the evaluation's
 * resolution), 0 when it did not converge. */
C2D_COLD int c2d_toia_polish(c2d_toia_ctx *c, c2d_dd *t, int which, const c2d_dd *lo, const c2d_dd *hi,
                           int bits)
{
    c2d_toia_values ev;
    int it, tier = 2;
    for (it = 0; it < C2D_TOIA_POLISH; it++) {
        const c2d_toia_bounded *q, *dq;
        c2d_real num;
        int de;
        if (tier == 2) c2d_toia_eval_double(c, t, &ev);
        else c2d_toia_eval_exact(c, t, &ev);
        q = &ev.qty[which];
        dq = &ev.qty[which + 1];
        if (tier == 2 && (which == C2D_TOIA_QH ? q->bound > c2d_pow2(-8) * ev.hmag
                                                : q->bound > c2d_pow2(-C2D_R_MANT - 5) *
                                                             (which == C2D_TOIA_QF ? ev.fmag : ev.gmag))) {
            /* heavy cancellation: tier 2's error is not far below one
             * rounding of the scale (for h, computed in plain arithmetic
             * from tier 2's d and d': when it lost even that); continue
             * with exact d, d' */
            tier = 3;
            c2d_toia_eval_exact(c, t, &ev);
        }
        if (q->value == 0 || c2d_abs(q->value) <= q->bound) return 1;
        if (dq->value == 0) return 0;
        num = -q->value / (which == C2D_TOIA_QF ? 2 * dq->value : dq->value);
        de = q->exp - dq->exp;
        {
            c2d_ext st, nx;
            c2d_ext_set(&st, num, de);
            c2d_toia_time_add(t, num, de);
            if (c2d_toia_time_cmp(t, lo) < 0) c2d_dd_copy(t, lo);
            if (c2d_toia_time_cmp(t, hi) > 0) c2d_dd_copy(t, hi);
            if (st.m == 0 || st.e < t->e - bits) return 1;
            /* Newton's error after this step is at most (max|phi''| /
             * 2 min|phi'|) step^2; with phi''/phi' estimated here (x 4 for
             * their variation over the step) it already lies below 2^-bits
             * t when the step was small: no second evaluation needed */
            if (which != C2D_TOIA_QH && st.e < t->e - C2D_R_MANT / 2 && ev.qty[which + 2].value != 0) {
                /* |phi''/phi'| = |h / g| for f (f'' = 2h, f' = 2g), |hp / h| for g */
                c2d_ext_set(&nx, 4 * c2d_abs(ev.qty[which + 2].value / dq->value) * st.m * st.m,
                               ev.qty[which + 2].exp - dq->exp + 2 * st.e);
                if (nx.m == 0 || nx.e < t->e - bits) return 1;
            }
        }
    }
    return 0;
}

/* The root of phi (f: which 0, g: 1) in [lo, hi], where phi has sign sa at
 * lo and -sa at hi, with certified double-length values (tier 2, tier 3
 * where its sign is uncertain) in extended time: Newton steps from the
 * certified values while they stay in the bracket and shrink, bisection
 * otherwise; stops at the root's resolution (a sign tier 3 cannot certify,
 * or a bracket or step below 2^-2MANT of t).  For the cases the plain
 * frame cannot represent (heavy cancellation, extreme magnitudes). */
C2D_COLD void c2d_toia_root_ext(c2d_toia_ctx *c, c2d_dd *lo, c2d_dd *hi, int which, int sa, c2d_dd *out)
{
    c2d_toia_values ev;
    c2d_dd t, tn;
    c2d_ext w, prev;
    int it, done = 0;
    prev.m = 0;
    prev.e = 0;
    c2d_toia_time_mid(&t, lo, hi);
    for (it = 0; it < C2D_TOIA_ITER && done == 0; it++) {
        const c2d_toia_bounded *q, *dq;
        int s, newton = 0;
        c2d_toia_probe(c, &t, 1 << which, 2, &ev);
        s = ev.sign[which];
        if (s == 0) {
            done = 1; /* at the root, to the evaluation's resolution */
        } else {
            if (s == sa) c2d_dd_copy(lo, &t);
            else c2d_dd_copy(hi, &t);
            c2d_toia_time_diff(&w, hi, lo);
            if (w.m == 0 || w.e < hi->e - 2 * C2D_R_MANT) done = 1;
        }
        q = &ev.qty[which];
        dq = &ev.qty[which + 1];
        if (done == 0 && dq->value != 0) {
            c2d_ext st;
            c2d_ext_set(&st, -q->value / (which == C2D_TOIA_QF ? 2 * dq->value : dq->value), q->exp - dq->exp);
            c2d_dd_copy(&tn, &t);
            c2d_toia_time_add(&tn, st.m, st.e);
            if (c2d_toia_time_cmp(&tn, lo) > 0 && c2d_toia_time_cmp(&tn, hi) < 0 &&
                (prev.m == 0 || st.e < prev.e || (st.e == prev.e && c2d_abs(st.m) < c2d_abs(prev.m)))) {
                newton = 1;
                c2d_ext_copy(&prev, &st);
                c2d_dd_copy(&t, &tn);
                if (st.e < t.e - 2 * C2D_R_MANT) done = 1;
            }
        }
        if (done == 0 && newton == 0) {
            prev.m = 0;
            c2d_toia_time_mid(&t, lo, hi);
        }
    }
    c2d_dd_copy(out, &t);
}

/* The root of phi (f: which 0, g: 1) in [lo, hi], where phi has sign sa at
 * lo and -sa at hi (certified, or a tie at hi): plain Newton in a local
 * frame, then double-length polish; the certified search (rootx) when the
 * frame cannot represent the problem or its values drown in cancellation
 * or the polish does not converge. */
C2D_COLD void c2d_toia_root(c2d_toia_ctx *c, const c2d_dd *lo, const c2d_dd *hi, int which, int sa,
                          c2d_dd *out)
{
    c2d_toia_frame fr;
    c2d_dd a, b;
    int kt = hi->e + 1, ok = 0;
    c2d_real width;
    c2d_dd_copy(&a, lo);
    c2d_dd_copy(&b, hi);
    if (c2d_toia_frame_set(&fr, c, kt) != 0) {
        c2d_real x =
            c2d_toia_frame_newton(&fr, which, c2d_toia_time_local(lo, kt), c2d_toia_time_local(hi, kt), sa, &ok,
                                  &width);
        if (ok != 0) {
            c2d_dd_set(out, x, 0, kt);
            if (c2d_toia_time_cmp(out, lo) < 0) c2d_dd_copy(out, lo);
            if (c2d_toia_time_cmp(out, hi) > 0) c2d_dd_copy(out, hi);
            if (c2d_toia_polish(c, out, which, lo, hi, C2D_R_MANT + 3) != 0) return;
        }
    }
    c2d_toia_root_ext(c, &a, &b, which, sa, out);
    (void)c2d_toia_polish(c, out, which, &a, &b, C2D_R_MANT + 3);
}
/* ===================================================================== */

#endif /* C2D_REAL_TOIA_NEWTON_H */
