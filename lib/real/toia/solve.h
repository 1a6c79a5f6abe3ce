/* SPDX-License-Identifier: MIT */
/* real/toia/solve.h - template, accelerated time of impact: the derivation
 * (below), the signs at t = 0, the bound on the roots of g, and the entry
 * c2d_toia_solve behind c2d_time_of_impact_accel.  The other files (num.h,
 * problem.h, eval.h, newton.h, turns.h, scan.h) are included before it in
 * that order (real/instance.h); what each holds and the method in short:
 * real/toia/README.md.  The including translation unit provides the
 * format's parameters (C2D_R_*), c2d_status and C2D_COLD (internal.h); the
 * arithmetic is real/arith/'s (bits.h, exact.h, sign.h, dd.h), included
 * before.  Everything the toia files define is static and named
 * c2d_toia_*; no macros.  The entry point is c2d_toia_solve (at the end);
 * nothing else is meant to be called.
 *
 * ======================================================================
 * THE PROBLEM
 *   With d0 = pb - pa, v = vb - va, a = acc_b - acc_a (each difference is
 *   exact as hi + lo, TwoSum), the relative position is the parabola
 *       d(t) = d0 + v t + a t^2 / 2,          d'(t) = v + a t.
 *   Let f(t) = |d|^2 - R^2 (the disks overlap iff f < 0) and
 *       g(t) = d.d' = f'/2   (they approach iff g < 0),
 *       h(t) = g' = |d'|^2 + d.a,    h' = 3 d'.a,    h'' = 3|a|^2 >= 0.
 *   f is a quartic, g a cubic, h a quadratic: all with rational (dyadic)
 *   coefficients, but we never form those coefficients (the textbook
 *   quartic c0 + ... + c4 t^4 cancels catastrophically: c0 ~ |d0|^2 for
 *   far-apart disks while f ~ R^2 near contact).  We only evaluate d(t) and
 *   d'(t) as vectors.
 *
 * THE CONTACT, DEFINED
 *   The contact is the earliest t in [0, H] at which the disks touch or
 *   overlap (f(t) <= 0) and approach just after t (g < 0 on (t, t + e)).
 *   Such t form the set S; let O = {t : f(t) < 0 and g(t) < 0} (open).  Any
 *   t in S has a right neighbourhood in O, and the left end of O's first
 *   component (or 0) is in S, so
 *       t* = inf (O intersect [0, inf)),   contact iff t* <= H.
 *   Consequences: a graze (f touches 0 with g = 0 and grows again) is not a
 *   contact (O is empty near it: c2d_collide says SEPARATING at zero normal
 *   speed); a pair that overlaps and recedes is not in contact until g turns
 *   negative while f < 0 (then t* is that turn, a root of g); constant
 *   distance (v = a = 0) and R = 0 (f >= 0) never give a contact.
 *
 * THE STRUCTURE (why the search below cannot miss a contact)
 *   h' is linear, so h is monotone on each side of its vertex m = -v.a/|a|^2:
 *   h has at most two roots r- <= r+, g increases where h > 0 and decreases
 *   where h < 0.  Hence g is monotone on each of the (at most three) pieces
 *   of (0, T) cut by r-, r+, and changes sign at most once in a piece: the
 *   signs of g at the piece ends tell exactly where f turns (a minimum where
 *   g goes - to +, a maximum where + to -).  Between turns f is monotone, so
 *   O's first component is found by one walk over the pieces (c2d_toia_scan):
 *     - in a decreasing stretch of f starting at l with f(l) > 0, the entry
 *       is the stretch's unique root of f if f reaches < 0 by the stretch's
 *       end (a minimum of f, or the horizon), else there is none (a minimum
 *       with f = 0 exactly is a graze);
 *     - at a maximum c of f with f(c) < 0 the pair overlaps and turns from
 *       receding to approaching: t* = c (a root of g);
 *     - at t = 0: f(0) <= 0 with g < 0 just after 0 (the first nonzero of
 *       g(0), h(0), h'(0), h'') gives t* = 0 exactly.
 *   T = min(H, B) where B = 2^eb bounds the real roots of g (Fujiwara's
 *   bound on the monic cubic): beyond B, g > 0, f increases, nothing enters.
 *   A contact beyond the format's largest value is C2D_RANGE.
 *
 * CERTIFIED SIGNS, THREE TIERS
 *   Every decision above is the sign of f, g, h or h' at a point, and each
 *   is taken only when certified (c2d_toia_probe): an evaluation returns the
 *   value with a rigorous bound on its error, tier by tier until the sign
 *   clears its bound:
 *     tier 1  plain arithmetic (error ~6u of the terms |d0|, |v t|, |a t^2|),
 *     tier 2  double length (~16u^2 of the terms),
 *     tier 3  d(t), d'(t) EXACT (sums of exact products of the exact input
 *             differences, Shewchuk expansions in a sliding exponent window,
 *             c2d_toia_exact_sum) rounded to double length: the error is then
 *             ~(2k + 4)u^2 of |d| itself, not of the terms that cancel in it.
 *   (u = 2^-(MANT+1).)  Each tier computes in units of powers of two chosen
 *   per evaluation from the terms' exponents, so nothing over- or
 *   underflows whatever the inputs' magnitudes; times are (h + l) 2^e with an
 *   int exponent.  Signs at t = 0 are degree-2 polynomials in the inputs and
 *   are decided EXACTLY (c2d_toia_exact_sign_at0): touching pairs that stay
 *   in contact, separate, or are pushed together get the exact answer.
 *
 * WHAT CANNOT BE DECIDED: THE BAND
 *   A sign that even tier 3 cannot certify means the exact quantity is
 *   within ~2^-(2p-6) (p = MANT + 1) of zero relative to its natural scale.
 *   Deciding it would need exact algebraic numbers (a graze at an
 *   irrational time is a root of a degree-12 resultant in the inputs): out of
 *   reach of a fixed-size, allocation-free routine.  Such a tie is broken as
 *   if the quantity were exactly zero, which is right for constructed exact
 *   ties:
 *     graze      (f at a minimum of f within its bound of 0)  -> no contact;
 *     horizon    (f(H) within its bound, f decreasing)        -> contact ~H;
 *     turn       (f at a maximum within its bound)            -> contact at it;
 *     g extremum (g at a root of h within its bound)          -> no sign change.
 *   The minimum of f is located to double-length precision (a bracket
 *   [lo, hi] of the root of g with certified signs; f(c) lies in
 *   [max f(end) - 2 max|g(end)| (hi - lo), min f(end)], c2d_toia_f_at_turn), so
 *   besides the relative band a minimum whose dip is smaller than what one
 *   unit of the double-length time resolution (2^-2p c) is worth remains
 *   undecided: |f(c)| <~ (|d'|^2 + |d||a|)(2^-2p c)^2.  That needs a pass
 *   ~2^2p times longer than the disk (a contact lasting 2^-2p of the time
 *   elapsed); it is decided anyway for a = 0 (the minimum distance is
 *   |d0 x v|/|v| by Lagrange's identity: no time enters, c2d_toia_lin_min)
 *   and for motion along one line through the origin (c2d_toia_crosses).
 *   real/toia/README.md ("The band") states the band precisely, as the
 *   tests check it, and what they measure of it.
 *
 * THE TIME
 *   The root is found by Newton in a local frame (plain arithmetic, with a
 *   noise estimate that tells when cancellation makes the plain values
 *   meaningless), then polished by Newton with tier-2 values (tier 3 under
 *   heavy cancellation) until the step is below 2^-(MANT+3) t or the value
 *   is within its error bound; where the plain frame cannot represent the
 *   problem, a certified bisection/Newton in extended time takes over
 *   (c2d_toia_root_ext).  The result is within ~0.5 ulp(t) plus the time one
 *   rounding of |d| is worth at the approach speed (the contract in
 *   include/collide2d.h; measured in real/toia/README.md).
 *
 * FAST PATHS (certified shortcuts for common cases, c2d_toia_fast)
 *   - g < 0 on all of [0, T] (its Bernstein coefficients on [0, T] are all
 *     negative): f decreases throughout; contact iff f(T) < 0;
 *   - the path's control polygons keep clear of the disk: no contact;
 *   - plain Newton from 0 finds x1, f(x1(1+e)) < 0 is certified and g < 0 on
 *     [0, x1(1+e)]: the unique root there is the contact.
 * ======================================================================
 */
#ifndef C2D_REAL_TOIA_H
#define C2D_REAL_TOIA_H
/* Entry                                                                 */
/* ===================================================================== */

/* sign of x 2^ex + y 2^ey (a term is absent when its flag is 0), certified
 * against the bound u8 (mx 2^ex + my 2^ey) (mx, my: the magnitudes the
 * terms' errors scale with) plus a floor for the alignment; 0 if not. */
static int c2d_toia_sign_two_terms(c2d_real x, c2d_real mx, int hx, int ex, c2d_real y, c2d_real my, int hy, int ey)
{
    const c2d_real u8 = c2d_pow2(-C2D_R_MANT + 2);
    int E = hx == 0 ? ey : (hy == 0 ? ex : c2d_toia_max_int(ex, ey));
    c2d_real sx = hx != 0 ? c2d_toia_pow2_clamped(ex - E) : 0, sy = hy != 0 ? c2d_toia_pow2_clamped(ey - E) : 0;
    c2d_real v = x * sx + y * sy, r = u8 * (mx * sx + my * sy) + c2d_pow2(C2D_R_EMIN + 6);
    if (v > r) return 1;
    if (v < -r) return -1;
    return 0;
}

/* The exact signs at t = 0 of f = |d0|^2 - R^2, g = d0.v, h = |v|^2 + d0.a
 * and hp = 3 v.a: from the hi parts in plain arithmetic where that is
 * certain (the lo parts are below u of the hi parts, the products and sums
 * add a few u: 8u of the terms' magnitudes bounds it all), the exact sums
 * otherwise. */
static void c2d_toia_signs_at0(c2d_toia_ctx *c, int *s)
{
    c2d_real p2 = c->hi[0][0] * c->hi[0][0] + c->hi[0][1] * c->hi[0][1];
    c2d_real v2 = c->hi[1][0] * c->hi[1][0] + c->hi[1][1] * c->hi[1][1];
    c2d_real pv = c->hi[0][0] * c->hi[1][0] + c->hi[0][1] * c->hi[1][1];
    c2d_real pa = c->hi[0][0] * c->hi[2][0] + c->hi[0][1] * c->hi[2][1];
    c2d_real va = c->hi[1][0] * c->hi[2][0] + c->hi[1][1] * c->hi[2][1];
    c2d_real mpv = c2d_abs(c->hi[0][0] * c->hi[1][0]) + c2d_abs(c->hi[0][1] * c->hi[1][1]);
    c2d_real mpa = c2d_abs(c->hi[0][0] * c->hi[2][0]) + c2d_abs(c->hi[0][1] * c->hi[2][1]);
    c2d_real mva = c2d_abs(c->hi[1][0] * c->hi[2][0]) + c2d_abs(c->hi[1][1] * c->hi[2][1]);
    c2d_real r2 = c->radius.m * c->radius.m;
    int k;
    s[0] = c2d_toia_sign_two_terms(p2, p2, c->nonzero[0], 2 * c->exp[0], -r2, r2, 1, 2 * c->radius.e);
    s[1] = c2d_toia_sign_two_terms(pv, mpv, c->nonzero[0] * c->nonzero[1], c->exp[0] + c->exp[1], 0, 0, 0, 0);
    s[2] = c2d_toia_sign_two_terms(v2, v2, c->nonzero[1], 2 * c->exp[1], pa, mpa, c->nonzero[0] * c->nonzero[2],
                                   c->exp[0] + c->exp[2]);
    s[3] = c2d_toia_sign_two_terms(va, mva, c->nonzero[1] * c->nonzero[2], c->exp[1] + c->exp[2], 0, 0, 0, 0);
    for (k = 0; k < 4; k++)
        if (s[k] == 0) s[k] = c2d_toia_exact_sign_at0(c, k);
}

/* ceil(a / b), b > 0 */
static int c2d_toia_ceil_div(int a, int b) { return -c2d_toia_floor_div(-a, b); }

/* An exponent eb with every real root of g below 2^eb.  g / (|a|^2 / 2) =
 * t^3 + c2 t^2 + c1 t + c0 with |c2| <= 3|v|/|a|, |c1| <= 2(|v|^2 +
 * |d0||a|)/|a|^2, |c0| <= 2|d0||v|/|a|^2; Fujiwara's bound 2 max(|c2|,
 * |c1|^(1/2), |c0/2|^(1/3)), with |x| < 2^(ex + 1.5) for a vector whose
 * largest component is below 2^(ex + 1).  With a = 0, g = d0.v + |v|^2 t
 * has its root below |d0|/|v|. */
static int c2d_toia_bound(c2d_toia_ctx *c)
{
    const int e0 = c->exp[0], e1 = c->exp[1], e2 = c->exp[2];
    int eb = 0, have = 0, k;
    if (c->nonzero[2] == 0) return c->nonzero[0] != 0 ? e0 - e1 + 3 : 0;
    if (c->nonzero[1] != 0) {
        eb = e1 - e2 + 4;
        have = 1;
    }
    if (c->nonzero[1] != 0 || c->nonzero[0] != 0) {
        k = c->nonzero[1] != 0 ? 2 * e1 : e0 + e2;
        if (c->nonzero[0] != 0 && e0 + e2 > k) k = e0 + e2;
        k = c2d_toia_ceil_div(k + 5 - 2 * e2, 2);
        eb = (have == 0 || k > eb) ? k : eb;
        have = 1;
    }
    if (c->nonzero[1] != 0 && c->nonzero[0] != 0) {
        k = c2d_toia_ceil_div(e0 + e1 + 3 - 2 * e2, 3);
        eb = k > eb ? k : eb;
    }
    return have != 0 ? eb + 1 : 0;
}

/* The path keeps clear of the disk on [0, T] (hull test in a frame). */
C2D_COLD int c2d_toia_path_clear(c2d_toia_ctx *c, const c2d_dd *T)
{
    c2d_toia_frame fr;
    return c2d_toia_frame_set(&fr, c, T->e + 1) != 0 && c2d_toia_hull_clear(&fr, c2d_toia_time_local(T, T->e + 1)) != 0;
}

/* The contact time to the working format: RANGE beyond it; within [0, H]. */
static c2d_status c2d_toia_result(const c2d_dd *out, c2d_real horizon, c2d_real *t)
{
    c2d_real v = c2d_toia_time_value(out);
    if (!(v <= C2D_R_MAX)) return C2D_RANGE;
    if (v > horizon) v = horizon;
    if (v < 0) v = 0;
    *t = v;
    return C2D_OK;
}

/* Equal accelerations (zero ones included) cancel in the difference: the
 * relative path is a straight line, d(t) = d0 + v t, and the plain time of
 * impact is the answer, to its own accuracy and at every magnitude.  The
 * curved solver's time scale comes from bounds on the acceleration term,
 * which is zero here, so it must not see such a pair (it put a contact at
 * 2^-101 at 0x1.8p+195).  The horizon only cuts: a contact beyond it, or
 * beyond DBL_MAX under a finite horizon, is none.  Called after the exact
 * decision at t = 0 and the zero horizon, so a contact at a time that
 * underflows to 0 is none within a zero horizon. */
static c2d_status c2d_toia_straight(const c2d_real_body *a, const c2d_real_body *b, c2d_real radius_sum,
                                    c2d_real horizon, c2d_real *t)
{
    c2d_real tt;
    c2d_status s = c2d_real_time_of_impact(a, b, radius_sum, &tt);
    if (s == C2D_RANGE) return horizon <= C2D_R_MAX ? C2D_SEPARATING : C2D_RANGE;
    if (s != C2D_OK) return s;
    if (tt > horizon) return C2D_SEPARATING;
    *t = tt;
    return C2D_OK;
}

static c2d_status c2d_toia_solve(const c2d_real_body *a, const c2d_real_vec *acc_a, const c2d_real_body *b,
                                 const c2d_real_vec *acc_b, c2d_real radius_sum, c2d_real horizon, c2d_real *t)
{
    c2d_toia_ctx c;
    c2d_toia_parts parts;
    c2d_dd T, out;
    int s0[4], sg0, eb, t_is_h;
    if (a == NULL || b == NULL || acc_a == NULL || acc_b == NULL || t == NULL) return C2D_INVALID;
    if (!c2d_finite4(a->pos.x, a->pos.y, b->pos.x, b->pos.y) || !c2d_finite4(a->vel.x, a->vel.y, b->vel.x, b->vel.y) ||
        !c2d_finite4(acc_a->x, acc_a->y, acc_b->x, acc_b->y) || !(radius_sum >= 0 && radius_sum <= C2D_R_MAX) ||
        !(horizon >= 0))
        return C2D_INVALID;
    c2d_toia_load(&c, a, acc_a, b, acc_b, radius_sum, &parts);
    if (c.nonzero[1] == 0 && c.nonzero[2] == 0) return C2D_SEPARATING; /* constant distance: never approaching */
    if (radius_sum == 0) return C2D_SEPARATING;              /* f >= 0: never overlapping */
    c2d_toia_signs_at0(&c, s0);
    /* the sign of g just after 0: first nonzero of g, g', g'', g''' > 0 */
    sg0 = s0[1] != 0 ? s0[1] : (s0[2] != 0 ? s0[2] : (s0[3] != 0 ? s0[3] : 1));
    if (s0[0] <= 0 && sg0 < 0) {
        *t = 0;
        return C2D_OK;
    }
    if (horizon == 0) return C2D_SEPARATING;
    if (c.nonzero[2] == 0) return c2d_toia_straight(a, b, radius_sum, horizon, t);
    eb = c2d_toia_bound(&c);
    t_is_h = horizon <= C2D_R_MAX && c2d_ilogb(horizon) < eb;
    if (t_is_h != 0) c2d_dd_set(&T, horizon, 0, 0);
    else c2d_dd_set(&T, 1, 0, eb);
    if (s0[0] > 0 && sg0 < 0) { /* separated and approaching: the common case */
        int fast = c2d_toia_fast(&c, &T, t_is_h, &out);
        if (fast == 0) return C2D_SEPARATING;
        if (fast > 0) return c2d_toia_result(&out, horizon, t);
    } else if (s0[0] > 0 && c2d_toia_path_clear(&c, &T) != 0) { /* separated and receding: clear for good? */
        return C2D_SEPARATING;
    }
    if (c2d_toia_scan(&c, &T, t_is_h, s0, sg0, &out) == C2D_TOIA_HIT) return c2d_toia_result(&out, horizon, t);
    return C2D_SEPARATING;
}

#endif /* C2D_REAL_TOIA_H */
