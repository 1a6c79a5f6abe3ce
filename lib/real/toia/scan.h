/* SPDX-License-Identifier: MIT */
/* real/toia/scan.h - template, accelerated time of impact: the certified
 * fast paths, the pieces of (0, T) on which g is monotone, the decisions at
 * maxima and minima of f, and the scan over the pieces.  See
 * real/toia/README.md. */
#ifndef C2D_REAL_TOIA_SCAN_H
#define C2D_REAL_TOIA_SCAN_H
/* Fast paths: certified shortcuts for the common cases                  */
/* ===================================================================== */

/* Lower bound of the squared distance from the origin to segment [A, B]:
 * the squared distance to the line through them when the origin projects
 * within (or near) the segment, else the nearer endpoint's. */
static c2d_real c2d_toia_segment_dist2(const c2d_real *A, const c2d_real *B)
{
    c2d_real ex = B[0] - A[0], ey = B[1] - A[1], e2 = ex * ex + ey * ey;
    c2d_real a2 = A[0] * A[0] + A[1] * A[1], b2 = B[0] * B[0] + B[1] * B[1];
    c2d_real ta = -(A[0] * ex + A[1] * ey), tb = B[0] * ex + B[1] * ey, m = a2 < b2 ? a2 : b2;
    if (ta > -e2 * c2d_pow2(-20) && tb > -e2 * c2d_pow2(-20) && e2 > 0) {
        c2d_real cr = A[0] * B[1] - A[1] * B[0];
        cr = cr * cr / e2;
        if (cr < m) m = cr;
    }
    return m;
}

/* The hull test of one piece [t0, t0 + w]: the path is a quadratic Bezier
 * curve there, inside the triangle of its control points d(t0),
 * d(t0) + d'(t0) w/2, d(t0 + w); first the triangle's bounding box, then
 * the triangle itself must keep a squared distance > lim from the origin. */
static int c2d_toia_piece_clear(const c2d_toia_frame *fr, c2d_real t0, c2d_real w, c2d_real lim)
{
    c2d_real P[3][2], lo[2], hi[2], bx, by;
    int i;
    for (i = 0; i < 2; i++) {
        c2d_real d0 = fr->pos[i] + (fr->vel[i] + fr->half_acc[i] * t0) * t0;
        c2d_real d1 = fr->vel[i] + fr->acc[i] * t0, t1 = t0 + w;
        P[0][i] = d0;
        P[1][i] = d0 + d1 * (w * (c2d_real)0.5);
        P[2][i] = fr->pos[i] + (fr->vel[i] + fr->half_acc[i] * t1) * t1;
        lo[i] = P[0][i] < P[1][i] ? P[0][i] : P[1][i];
        lo[i] = lo[i] < P[2][i] ? lo[i] : P[2][i];
        hi[i] = P[0][i] > P[1][i] ? P[0][i] : P[1][i];
        hi[i] = hi[i] > P[2][i] ? hi[i] : P[2][i];
    }
    /* distance from the origin to the box */
    bx = lo[0] > 0 ? lo[0] : (hi[0] < 0 ? -hi[0] : 0);
    by = lo[1] > 0 ? lo[1] : (hi[1] < 0 ? -hi[1] : 0);
    if (bx * bx + by * by > lim) return 1;
    {
        c2d_real c0 = P[0][0] * P[1][1] - P[0][1] * P[1][0], c1 = P[1][0] * P[2][1] - P[1][1] * P[2][0],
                 c2 = P[2][0] * P[0][1] - P[2][1] * P[0][0];
        if (!((c0 > 0 || c1 > 0 || c2 > 0) && (c0 < 0 || c1 < 0 || c2 < 0))) return 0; /* origin inside */
    }
    return c2d_toia_segment_dist2(P[0], P[1]) > lim && c2d_toia_segment_dist2(P[1], P[2]) > lim &&
           c2d_toia_segment_dist2(P[2], P[0]) > lim;
}

/* f > 0 on [0, T] certified by the curve's control polygons: on each piece
 * the relative position is a quadratic Bezier curve inside the triangle of
 * its control points; if every triangle keeps a distance > R from the
 * origin, so does the path.  [0, T] is tried whole, then halved where a
 * piece fails (up to 16 pieces).  Plain arithmetic in the frame: the
 * control points are within delta = 6u (|d0| + |v| T + |a| T^2) of the
 * exact ones, R is enlarged by delta, and the squared test keeps a
 * relative margin of 2^(6 - MANT) for its own roundings.  Returns 1 when
 * certain, 0 otherwise (then nothing is concluded). */
C2D_COLD int c2d_toia_hull_clear(const c2d_toia_frame *fr, c2d_real T)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1);
    c2d_real S, r, lim;
    if (!(fr->radius2 > 0) || fr->radius2 >= c2d_pow2(C2D_R_EMAX - 8)) return 0;
    S = (c2d_abs(fr->pos[0]) + c2d_abs(fr->pos[1])) + (c2d_abs(fr->vel[0]) + c2d_abs(fr->vel[1])) * T +
        (c2d_abs(fr->acc[0]) + c2d_abs(fr->acc[1])) * T * T;
    r = C2D_R_SQRT(fr->radius2) * (1 + c2d_pow2(4 - C2D_R_MANT)) + 6 * u * S + c2d_pow2(C2D_R_EMIN / 2);
    lim = r * r * (1 + c2d_pow2(6 - C2D_R_MANT));
    /* depth-first over the binary subdivision (pieces of [0, T] down to T/16) */
    {
        c2d_real st0[8], sw[8];
        int sd[8], n = 1;
        st0[0] = 0;
        sw[0] = T;
        sd[0] = 0;
        while (n > 0) {
            c2d_real t0, w;
            int d;
            n--;
            t0 = st0[n];
            w = sw[n];
            d = sd[n];
            if (c2d_toia_piece_clear(fr, t0, w, lim) != 0) continue;
            if (d == 4) return 0;
            w *= (c2d_real)0.5;
            st0[n] = t0 + w;
            sw[n] = w;
            sd[n] = d + 1;
            st0[n + 1] = t0;
            sw[n + 1] = w;
            sd[n + 1] = d + 1;
            n += 2;
        }
    }
    return 1;
}

/* g < 0 on [0, T] certified by its Bernstein coefficients: g = g0 + g1 t +
 * g2 t^2 + g3 t^3 (g0 = d0.v, g1 = |v|^2 + d0.a, g2 = 3/2 v.a, g3 = |a|^2/2)
 * lies within the convex hull of its control values b0 = e0, b1 = e0 +
 * e1/3, b2 = e0 + 2e1/3 + e2/3, b3 = e0 + e1 + e2 + e3 (e_i = g_i T^i).  All
 * < 0 with a margin of 16u times the magnitudes involved (the frame's
 * rounded inputs and these few operations) means g < 0 throughout. */
static int c2d_toia_g_negative(const c2d_toia_frame *fr, c2d_real T)
{
    const c2d_real u = c2d_pow2(-C2D_R_MANT - 1);
    c2d_real e0, e1, e2, e3, m0, m1, m2, m3, b, mb;
    e0 = fr->pos[0] * fr->vel[0] + fr->pos[1] * fr->vel[1];
    m0 = c2d_abs(fr->pos[0] * fr->vel[0]) + c2d_abs(fr->pos[1] * fr->vel[1]);
    e1 = ((fr->vel[0] * fr->vel[0] + fr->vel[1] * fr->vel[1]) + (fr->pos[0] * fr->acc[0] + fr->pos[1] * fr->acc[1])) *
         T;
    m1 = ((fr->vel[0] * fr->vel[0] + fr->vel[1] * fr->vel[1]) +
          (c2d_abs(fr->pos[0] * fr->acc[0]) + c2d_abs(fr->pos[1] * fr->acc[1]))) *
         T;
    e2 = (fr->vel[0] * fr->acc[0] + fr->vel[1] * fr->acc[1]) * (c2d_real)1.5 * T * T;
    m2 = (c2d_abs(fr->vel[0] * fr->acc[0]) + c2d_abs(fr->vel[1] * fr->acc[1])) * (c2d_real)1.5 * T * T;
    e3 = (fr->acc[0] * fr->acc[0] + fr->acc[1] * fr->acc[1]) * (c2d_real)0.5 * T * T * T;
    m3 = e3;
    mb = 16 * u * (m0 + m1 + m2 + m3) + c2d_pow2(C2D_R_EMIN + 8);
    if (!(e0 < -mb)) return 0;
    b = e0 + e1 / 3;
    if (!(b < -mb)) return 0;
    b = e0 + (2 * e1 + e2) / 3;
    if (!(b < -mb)) return 0;
    b = e0 + e1 + e2 + e3;
    return b < -mb;
}

/* Fast path for a pair separated and approaching at 0 (f(0) > 0, g(0) < 0):
 *   - g < 0 on all of [0, T]: f decreases throughout; contact iff f(T) < 0
 *     (the root in [0, T]) or a tie at the horizon;
 *   - the path's hull keeps clear of the disk on [0, T]: none;
 *   - plain Newton on f from 0 gives x1; if f(x2) < 0 certified just past
 *     it and g < 0 on [0, x2], f decreases to a unique root in (0, x2):
 *     that is the contact.
 * Returns 1 (contact in *out), 0 (none), -1 (not decided here). */
C2D_COLD int c2d_toia_fast(c2d_toia_ctx *c, const c2d_dd *T, int t_is_h, c2d_dd *out)
{
    c2d_toia_frame fr;
    c2d_toia_values ev;
    c2d_dd z, x2;
    c2d_real tl, x, dphi, noise;
    int kt = T->e + 1, it, settled = 0;
    if (c2d_toia_frame_set(&fr, c, kt) == 0) return -1;
    tl = c2d_toia_time_local(T, kt);
    c2d_dd_set(&z, 0, 0, 0);
    if (c2d_toia_g_negative(&fr, tl) != 0) {
        c2d_toia_probe(c, T, C2D_TOIA_MF, 1, &ev);
        if (ev.sign[C2D_TOIA_QF] > 0) return 0;
        if (ev.sign[C2D_TOIA_QF] < 0 || t_is_h != 0) {
            c2d_toia_root(c, &z, T, C2D_TOIA_QF, 1, out);
            return 1;
        }
        return -1;
    }
    if (c2d_toia_hull_clear(&fr, tl) != 0) return 0;
    /* Newton from 0 */
    x = 0;
    for (it = 0; it < 40 && settled == 0; it++) {
        c2d_real phi = c2d_toia_frame_eval(&fr, C2D_TOIA_QF, x, &dphi, &noise);
        if (!(dphi < 0)) return -1;
        if (c2d_abs(phi) <= noise) {
            settled = 1;
        } else {
            c2d_real step = phi / dphi;
            x -= step;
            if (!(x < tl)) return -1;
            if (c2d_abs(step) <= c2d_pow2(-C2D_R_MANT) * x) settled = 1;
        }
    }
    if (!(x > 0)) return -1;
    /* a point just past the root: 2^-20 relative, or 16 noise widths */
    {
        c2d_real w = x * c2d_pow2(-20);
        (void)c2d_toia_frame_eval(&fr, C2D_TOIA_QF, x, &dphi, &noise);
        if (dphi < 0 && 16 * noise / -dphi > w) w = 16 * noise / -dphi;
        if (!(x + w <= tl)) return -1;
        c2d_dd_set(&x2, x + w, 0, kt);
    }
    c2d_toia_probe(c, &x2, C2D_TOIA_MF, 1, &ev);
    if (ev.sign[C2D_TOIA_QF] >= 0) return -1;
    if (c2d_toia_g_negative(&fr, c2d_toia_time_local(&x2, kt)) == 0) return -1;
    c2d_dd_set(out, x, 0, kt);
    if (c2d_toia_polish(c, out, C2D_TOIA_QF, &z, &x2, C2D_R_MANT + 3) == 0)
        c2d_toia_root(c, &z, &x2, C2D_TOIA_QF, 1, out);
    return 1;
}

/* ===================================================================== */
/* The pieces of (0, T) on which g is monotone                           */
/* ===================================================================== */

/* The vertex -v.a / |a|^2 of h (where h' = 3 d'.a vanishes), in double
 * length (from exact sums if exact, else from the hi parts); returns an
 * exponent dm with |*mt - m| <= 2^dm. */
C2D_COLD int c2d_toia_vertex(c2d_toia_ctx *c, int exact, c2d_dd *mt)
{
    c2d_dd a2, va;
    c2d_real rel;
    c2d_toia_dot_inputs(c, 2, 2, -1, -1, 1, exact, &a2);
    c2d_toia_dot_inputs(c, 1, 2, -1, -1, -1, exact, &va);
    c2d_dd_div(mt, &va, &a2);
    if (mt->h == 0) return C2D_R_EMIN - C2D_R_MANT;
    if (exact != 0) return mt->e - 2 * C2D_R_MANT + 3; /* 8 u^2 relative */
    /* from the hi parts: 4u of sum |v_i a_i| / |v.a| (cancellation) + 4u */
    rel = (c2d_abs(c->hi[1][0] * c->hi[2][0]) + c2d_abs(c->hi[1][1] * c->hi[2][1])) /
          c2d_abs(c->hi[1][0] * c->hi[2][0] + c->hi[1][1] * c->hi[2][1]);
    if (!(rel < c2d_pow2(C2D_R_MANT))) return mt->e + 1; /* no information */
    return mt->e + c2d_ilogb(rel + 1) + 4 - C2D_R_MANT;
}

/* The turning points of g in (0, T) (roots of h = g', at most two, in
 * order) as boundaries bt[] with g's sign on each one's sliver bs[] and
 * f's sign there bf[] when tier 1 gave it.  h is quadratic with leading
 * coefficient (3/2)|a|^2 > 0 and vertex m = -v.a / |a|^2; the exact signs
 * of h and h' just after 0 (c2d_toia_signs_at0) and, when m lies in (0, T), the
 * certified sign of h(m) decide how many roots there are: h'(0+) >= 0 means
 * h increases on (0, inf) (one root, a minimum of g, iff h(0+) < 0);
 * otherwise h decreases until m, so h(0+) <= 0 gives one root beyond m
 * (a minimum of g) and h(0+) > 0 gives two (a maximum, then a minimum)
 * iff h(m) < 0 (or one, a maximum, when m >= T and h(T) < 0).  An
 * uncertain h(m) is a near-double root of h: g then has an inflection
 * with g' ~ 0 and no usable split (the wiggle of g there is at most
 * (2/3)|h(m)| sqrt(2|h(m)|/h''), inside the band). */
C2D_COLD int c2d_toia_splits_try(c2d_toia_ctx *c, const c2d_dd *T, const int *s0, c2d_dd *bt,
                                            int *bs, int *bf, int exact, int *tied)
{
    const int sh = s0[2] != 0 ? s0[2] : (s0[3] != 0 ? s0[3] : 1);
    const int shp = s0[3] != 0 ? s0[3] : 1;
    c2d_dd rr[2];
    c2d_toia_values ev;
    int n = 0, want_m = 0, want_p = 0, k, ok, t1;
    *tied = 0;
    if (c->nonzero[2] == 0) return 0;
    if (shp > 0 || sh < 0) {
        if (sh > 0) return 0;
        want_p = 1; /* h < 0 just after 0: one root, a minimum of g */
        ok = c2d_toia_h_roots(c, NULL, exact, &rr[0], &rr[1]);
    } else {
        /* the vertex m = -v.a / |a|^2 > 0, in double length, within 2^dm:
         * h(m~) >= min h = h(m) >= h(m~) - (h''/2) 2^2dm, so only a margin
         * of (3/2)|a|^2 2^2dm above 0 proves h > 0 everywhere; the cheap
         * vertex is retried exactly (*tied) when it cannot decide */
        c2d_dd mt, mlo, mhi;
        int dm = c2d_toia_vertex(c, exact, &mt);
        if (!(mt.h > 0)) return 0;
        c2d_dd_copy(&mlo, &mt);
        c2d_toia_time_add(&mlo, -1, dm);
        c2d_dd_copy(&mhi, &mt);
        c2d_toia_time_add(&mhi, 1, dm);
        if (exact == 0 && c2d_toia_time_cmp(&mlo, T) < 0 && c2d_toia_time_cmp(&mhi, T) >= 0) {
            *tied = 1; /* is the vertex before T?  not from the hints */
            return 0;
        }
        if (c2d_toia_time_cmp(&mt, T) >= 0) {
            c2d_toia_probe(c, T, C2D_TOIA_MH, 1, &ev);
            if (ev.sign[C2D_TOIA_QH] >= 0) return 0;
            want_m = 1;
            ok = c2d_toia_h_roots(c, NULL, exact, &rr[0], &rr[1]);
        } else {
            c2d_ext hm, mg;
            c2d_toia_probe(c, &mt, C2D_TOIA_MH, 2, &ev);
            c2d_ext_set(&hm, ev.qty[C2D_TOIA_QH].value - ev.qty[C2D_TOIA_QH].bound, ev.qty[C2D_TOIA_QH].exp);
            c2d_ext_set(&mg, (c2d_real)1.5 * (c->hi[2][0] * c->hi[2][0] + c->hi[2][1] * c->hi[2][1]) * 2,
                           2 * c->exp[2] + 2 * dm);
            if (ev.sign[C2D_TOIA_QH] > 0 && c2d_toia_ext_cmp(&hm, &mg) > 0) return 0; /* h > 0 throughout */
            if (ev.sign[C2D_TOIA_QH] >= 0) {
                /* not proven: a near-double root of h (a tie) with the exact
                 * vertex, or the hints were not good enough */
                *tied = exact == 0;
                return 0;
            }
            want_m = 1;
            want_p = 1;
            ok = c2d_toia_h_roots(c, &ev, exact, &rr[0], &rr[1]);
        }
    }
    if (ok == 0) return 0;
    for (k = 0; k < 2; k++) {
        c2d_dd lo, hi;
        if ((k == 0 ? want_m : want_p) == 0 || !(rr[k].h > 0)) continue;
        c2d_dd_copy(&bt[n], &rr[k]);
        c2d_dd_set(&lo, bt[n].h, bt[n].l, bt[n].e - 1);
        c2d_dd_set(&hi, bt[n].h, bt[n].l, bt[n].e + 1);
        (void)c2d_toia_polish(c, &bt[n], C2D_TOIA_QH, &lo, &hi, 2 * C2D_R_MANT);
        if (!(bt[n].h > 0) || c2d_toia_time_cmp(&bt[n], T) >= 0) continue;
        if (n > 0 && c2d_toia_time_cmp(&bt[n], &bt[n - 1]) <= 0) continue;
        bs[n] = c2d_toia_split_sign(c, &bt[n], k == 0 ? -1 : 1, &bf[n], &t1);
        *tied |= t1;
        n++;
    }
    return n;
}

/* The splits from cheap hints, again from exact ones if a sliver could not
 * be certified (the hints may have missed the roots under cancellation). */
C2D_COLD int c2d_toia_splits(c2d_toia_ctx *c, const c2d_dd *T, const int *s0, c2d_dd *bt, int *bs,
                                         int *bf)
{
    int tied = 0, n = c2d_toia_splits_try(c, T, s0, bt, bs, bf, 0, &tied);
    if (tied != 0) n = c2d_toia_splits_try(c, T, s0, bt, bs, bf, 1, &tied);
    return n;
}

/* ===================================================================== */
/* The scan                                                              */
/* ===================================================================== */

/* At a maximum of f, the root of g in (x, y) where g goes from + to -:
 * returns 1 when the pair enters there (f(c) < 0: overlapping and turning
 * from receding to approaching; or a tie: f touches 0 from below, and
 * enters at once either way) with *out = c; else 0 with *l = a point of
 * the bracket where f > 0 is certified, the new decreasing stretch's start. */
C2D_COLD int c2d_toia_at_f_max(c2d_toia_ctx *c, const c2d_dd *x, const c2d_dd *y, c2d_dd *l,
                                       c2d_dd *out)
{
    c2d_toia_bracket br;
    c2d_toia_groot_bracket(c, x, y, -1, &br);
    if (c2d_toia_f_at_turn(&br, -1, NULL) <= 0) {
        c2d_toia_time_mid(out, &br.lo, &br.hi);
        (void)c2d_toia_polish(c, out, C2D_TOIA_QG, &br.lo, &br.hi, C2D_R_MANT + 3);
        return 1;
    }
    c2d_dd_copy(l, br.at_hi.sign_f > 0 ? &br.hi : &br.lo);
    return 0;
}

/* At a minimum of f in (x, y): 1 with *out = the contact time (the root of
 * f in [l, c]), 0 when f(c) > 0 or a graze tie. */
C2D_COLD int c2d_toia_at_f_min(c2d_toia_ctx *c, const c2d_dd *x, const c2d_dd *y,
                                        const c2d_dd *l, c2d_dd *out)
{
    c2d_toia_bracket br;
    c2d_toia_fg center;
    c2d_dd ct;
    const c2d_dd *neg;
    c2d_dd_set(&ct, 0, 0, 0);
    if (c2d_toia_f_min_sign(c, x, y, &br, &ct, &center, &neg) >= 0) return 0;
    if (neg != NULL) {
        c2d_toia_root(c, l, neg, C2D_TOIA_QF, 1, out);
    } else { /* shorter than the time resolution: at the minimum */
        c2d_dd_copy(out, &ct);
    }
    return 1;
}

/* The signs of f, g and h at T (certified as needed for f and g). */
C2D_COLD void c2d_toia_signs_at(c2d_toia_ctx *c, const c2d_dd *T, int *sf, int *sg, int *sh)
{
    c2d_toia_values ev;
    c2d_toia_probe(c, T, C2D_TOIA_MF | C2D_TOIA_MG, 1, &ev);
    *sf = ev.sign[C2D_TOIA_QF];
    *sg = ev.sign[C2D_TOIA_QG];
    *sh = ev.sign[C2D_TOIA_QH];
}

/* The first entry into {f < 0, g < 0} in (0, T], given no entry at 0.
 * The boundaries 0 = b0 < ... < T cut (0, T) into pieces on which g is
 * monotone, so g changes sign at most once in a piece; where it does, f
 * turns (a minimum when g goes from - to +, a maximum otherwise).  Walking
 * the pieces in order with "dec" = f is decreasing and l = the start of
 * the current decreasing stretch (f(l) > 0 certified):
 *   - a decreasing stretch that reaches a point with f < 0 contains the
 *     entry: the root of f between l and that point (one sign change);
 *   - at a minimum c of f: f(c) < 0 means entry (same rule), f(c) > 0 none,
 *     a tie (f(c) within its bound of 0: a graze) none;
 *   - at a maximum c: f(c) < 0 (overlapping, turning from receding to
 *     approaching) or a tie means entry at c itself; f(c) > 0 starts a new
 *     decreasing stretch;
 *   - at T = horizon while decreasing: f(T) < 0 entry, a tie entry at ~T.
 * T is the horizon or a bound on the roots of g (beyond it g > 0: f
 * increases and nothing can enter). */
C2D_COLD c2d_toia_verdict c2d_toia_scan(c2d_toia_ctx *c, const c2d_dd *T, int t_is_h, const int *s0,
                                                    int sg0, c2d_dd *out)
{
    c2d_dd bt[4], l;
    int bs[4], bf[4], nb, i, dec, sg, sh;
    c2d_dd_set(&bt[0], 0, 0, 0);
    bs[0] = sg0;
    bf[0] = s0[0];
    nb = 1 + c2d_toia_splits(c, T, s0, &bt[1], &bs[1], &bf[1]);
    c2d_dd_copy(&bt[nb], T);
    c2d_toia_signs_at(c, T, &bf[nb], &sg, &sh);
    /* a tie of g at T: the sign g takes just after T if g(T) = 0 */
    bs[nb] = sg != 0 ? sg : (sh != 0 ? sh : 1);
    nb++;
    dec = bs[0] < 0;
    c2d_dd_set(&l, 0, 0, 0);
    for (i = 0; i + 1 < nb; i++) {
        const c2d_dd *x = &bt[i], *y = &bt[i + 1];
        if (bs[i] == bs[i + 1]) {
            if (dec != 0 && bf[i + 1] < 0) {
                c2d_toia_root(c, &l, y, C2D_TOIA_QF, 1, out);
                return C2D_TOIA_HIT;
            }
            continue;
        }
        if (bs[i] < 0) { /* a minimum of f in (x, y) */
            if (bf[i + 1] < 0) { /* f(c) <= f(y) < 0 */
                c2d_toia_root(c, &l, y, C2D_TOIA_QF, 1, out);
                return C2D_TOIA_HIT;
            }
            if (c2d_toia_at_f_min(c, x, y, &l, out) != 0) return C2D_TOIA_HIT;
            dec = 0; /* f(c) > 0, or a graze */
        } else { /* a maximum of f in (x, y) */
            if (c2d_toia_at_f_max(c, x, y, &l, out) != 0) return C2D_TOIA_HIT;
            dec = 1;
            if (bf[i + 1] < 0) {
                c2d_toia_root(c, &l, y, C2D_TOIA_QF, 1, out);
                return C2D_TOIA_HIT;
            }
        }
    }
    if (dec != 0 && t_is_h != 0 && bf[nb - 1] <= 0) { /* a tie at the horizon */
        c2d_toia_root(c, &l, &bt[nb - 1], C2D_TOIA_QF, 1, out);
        return C2D_TOIA_HIT;
    }
    return C2D_TOIA_NONE;
}

/* ===================================================================== */

#endif /* C2D_REAL_TOIA_SCAN_H */
