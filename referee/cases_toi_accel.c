/* SPDX-License-Identifier: MIT */
/* cases.c - see cases.h.  Constructions use few-bit dyadic values so that
 * the intended exact property (a graze, a touch, a root at a float time)
 * holds exactly in float as in double. */
#include "cases_toi_accel.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* An integer in [lo, hi]. */
static int rng_int(c2d_rng *r, int lo, int hi) { return lo + (int)(c2d_rng_next(r) % (uint64_t)(hi - lo + 1)); }

/* a dyadic with `bits` significant bits in [-2^e, 2^e] */
static double dy(c2d_rng *r, int bits, int e)
{
    int64_t m = (int64_t)(c2d_rng_next(r) >> (64 - bits)) - ((int64_t)1 << (bits - 1));
    return ldexp((double)m, e - bits + 1);
}

/* x rounded to float.  Through a volatile: gcc 12.2 -O2's SLP vectorizer
 * drops the last two of these stores when written as plain (float) casts in
 * a row after a loop (found here; -fno-tree-slp-vectorize or clang are fine). */
static double rf(double x)
{
    volatile float f = (float)x;
    return (double)f;
}

void toia_case_to_float(ref_toia_in *in)
{
    int i;
    for (i = 0; i < 2; i++) {
        in->pa[i] = rf(in->pa[i]);
        in->pb[i] = rf(in->pb[i]);
        in->va[i] = rf(in->va[i]);
        in->vb[i] = rf(in->vb[i]);
        in->aa[i] = rf(in->aa[i]);
        in->ab[i] = rf(in->ab[i]);
    }
    in->r = rf(in->r);
    in->h = rf(in->h);
}

static void zero_in(ref_toia_in *in) { memset(in, 0, sizeof *in); }

/* relative (p, v, a) given; split into bodies: a at pa (random), b = pa + p */
static void set_rel(c2d_rng *r, ref_toia_in *in, const double *p, const double *v, const double *a, int exact)
{
    int i;
    for (i = 0; i < 2; i++) {
        if (exact) {
            in->pa[i] = 0;
            in->va[i] = 0;
            in->aa[i] = 0;
        } else {
            in->pa[i] = c2d_rng_range(r, -2, 2);
            in->va[i] = c2d_rng_range(r, -1, 1);
            in->aa[i] = c2d_rng_range(r, -0.5, 0.5);
        }
        in->pb[i] = in->pa[i] + p[i];
        in->vb[i] = in->va[i] + v[i];
        in->ab[i] = in->aa[i] + a[i];
    }
}

/* --------------------------------------------------------------- billiards */
static void gen_billiard(c2d_rng *r, int prec, ref_toia_in *in)
{
    const double W = 2.54, Ht = 1.27, rad = 0.028575;
    double ha = INFINITY, hb = INFINITY, sa, sb, ang;
    int i;
    (void)prec;
    zero_in(in);
    in->r = 2 * rad;
    in->pa[0] = c2d_rng_range(r, rad, W - rad);
    in->pa[1] = c2d_rng_range(r, rad, Ht - rad);
    in->pb[0] = c2d_rng_range(r, rad, W - rad);
    in->pb[1] = c2d_rng_range(r, rad, Ht - rad);
    sa = c2d_rng_unit(r) < 0.85 ? c2d_rng_range(r, 0.05, 5) : 0;
    sb = c2d_rng_unit(r) < 0.4 ? c2d_rng_range(r, 0.05, 3) : 0;
    if (c2d_rng_unit(r) < 0.5) { /* aim a at b, roughly */
        ang = atan2(in->pb[1] - in->pa[1], in->pb[0] - in->pa[0]) + c2d_rng_range(r, -0.06, 0.06);
    } else {
        ang = c2d_rng_range(r, 0, 6.283185307179586);
    }
    in->va[0] = sa * cos(ang);
    in->va[1] = sa * sin(ang);
    ang = c2d_rng_range(r, 0, 6.283185307179586);
    in->vb[0] = sb * cos(ang);
    in->vb[1] = sb * sin(ang);
    for (i = 0; i < 2; i++) {
        double *v = i == 0 ? in->va : in->vb, *a = i == 0 ? in->aa : in->ab, s = i == 0 ? sa : sb;
        double mug = c2d_rng_range(r, 0.1, 10); /* sliding ~ 2, rolling ~ 0.1 m/s^2 */
        if (s > 0) {
            a[0] = -mug * v[0] / s;
            a[1] = -mug * v[1] / s;
            if (i == 0) ha = s / mug;
            else hb = s / mug;
        }
    }
    in->h = ha < hb ? ha : hb; /* until either ball stops */
    if (c2d_rng_unit(r) < 0.1) in->h = INFINITY;
}

/* Two pool balls touching to rounding, as in a rack or after a contact
 * (b = a + 2R (cos, sin) in the working format): a pushed into b (within
 * +-2 rad of the line of centres, so some slide off or part), b at rest or
 * moving, each slowed by the cloth along its own velocity.  Not one of the
 * unit test's families: the benchmark's touching set (issue 22's goal of
 * at most 2,500 instructions a call here). */
void toia_gen_touching(c2d_rng *r, int prec, ref_toia_in *in)
{
    const double rad = 0.028575;
    double ang, aim, s[2], *v[2], *a[2], h = INFINITY;
    int i;
    (void)prec;
    zero_in(in);
    in->r = 2 * rad;
    in->pa[0] = c2d_rng_range(r, 0.1, 2.4);
    in->pa[1] = c2d_rng_range(r, 0.1, 1.17);
    ang = c2d_rng_range(r, 0, 6.283185307179586);
    in->pb[0] = in->pa[0] + 2 * rad * cos(ang);
    in->pb[1] = in->pa[1] + 2 * rad * sin(ang);
    s[0] = c2d_rng_range(r, 0.01, 8);
    aim = ang + c2d_rng_range(r, -2.0, 2.0);
    in->va[0] = s[0] * cos(aim);
    in->va[1] = s[0] * sin(aim);
    s[1] = c2d_rng_unit(r) < 0.3 ? c2d_rng_range(r, 0.01, 3) : 0;
    aim = c2d_rng_range(r, 0, 6.283185307179586);
    in->vb[0] = s[1] * cos(aim);
    in->vb[1] = s[1] * sin(aim);
    v[0] = in->va, v[1] = in->vb, a[0] = in->aa, a[1] = in->ab;
    for (i = 0; i < 2; i++) {
        const double mug = c2d_rng_range(r, 0.1, 10); /* sliding ~ 2, rolling ~ 0.1 m/s^2 */
        if (s[i] > 0) {
            a[i][0] = -mug * v[i][0] / s[i];
            a[i][1] = -mug * v[i][1] / s[i];
            if (s[i] / mug < h) h = s[i] / mug;
        }
    }
    in->h = h; /* until either ball stops */
}

/* ---------------------------------------------------------- random accel */
static void gen_random(c2d_rng *r, int prec, ref_toia_in *in)
{
    double p[2], v[2], a[2], sp = exp(c2d_rng_range(r, -3, 5)), sv = exp(c2d_rng_range(r, -2, 2)),
                            sa = exp(c2d_rng_range(r, -4, 2)), ang = c2d_rng_range(r, 0, 6.283185307179586);
    int i;
    (void)prec;
    zero_in(in);
    p[0] = sp * cos(ang);
    p[1] = sp * sin(ang);
    /* velocity roughly toward a (often a hit), else random */
    if (c2d_rng_unit(r) < 0.6) {
        double off = c2d_rng_range(r, -1.5, 1.5) * (c2d_rng_unit(r) < 0.5 ? 0.05 : 0.5);
        v[0] = -sv * cos(ang + off);
        v[1] = -sv * sin(ang + off);
    } else {
        for (i = 0; i < 2; i++) v[i] = c2d_rng_range(r, -sv, sv);
    }
    for (i = 0; i < 2; i++) a[i] = c2d_rng_range(r, -sa, sa);
    set_rel(r, in, p, v, a, 0);
    in->r = c2d_rng_range(r, 0.05, 2) * (c2d_rng_unit(r) < 0.2 ? sp : 1);
    in->h = c2d_rng_unit(r) < 0.4 ? INFINITY : c2d_rng_range(r, 0, 3 * sp / sv + 1);
}

static void gen_zero_accel(c2d_rng *r, int prec, ref_toia_in *in)
{
    gen_random(r, prec, in);
    in->aa[0] = in->aa[1] = in->ab[0] = in->ab[1] = 0;
    if (c2d_rng_unit(r) < 0.7) in->h = INFINITY;
}

static void gen_one_at_rest(c2d_rng *r, int prec, ref_toia_in *in)
{
    gen_random(r, prec, in);
    in->vb[0] = in->vb[1] = in->ab[0] = in->ab[1] = 0;
    if (c2d_rng_unit(r) < 0.5) { /* a decelerates along its velocity */
        double s = hypot(in->va[0], in->va[1]), mug = c2d_rng_range(r, 0.05, 5);
        if (s > 0) {
            in->aa[0] = -mug * in->va[0] / s;
            in->aa[1] = -mug * in->va[1] / s;
            in->h = s / mug;
        }
    }
}

/* lengths x 2^k, times x 2^j over the format's range */
static void gen_scaled(c2d_rng *r, int prec, ref_toia_in *in)
{
    int emax = prec == 24 ? 120 : 1000, k, j, i;
    gen_random(r, prec, in);
    for (;;) {
        k = rng_int(r, -emax + 10, emax - 10);
        j = rng_int(r, -emax / 2 + 5, emax / 2 - 5);
        if (abs(k - j) < emax - 10 && abs(k - 2 * j) < emax - 10) break;
    }
    for (i = 0; i < 2; i++) {
        in->pa[i] = ldexp(in->pa[i], k);
        in->pb[i] = ldexp(in->pb[i], k);
        in->va[i] = ldexp(in->va[i], k - j);
        in->vb[i] = ldexp(in->vb[i], k - j);
        in->aa[i] = ldexp(in->aa[i], k - 2 * j);
        in->ab[i] = ldexp(in->ab[i], k - 2 * j);
    }
    in->r = ldexp(in->r, k);
    in->h = ldexp(in->h, j);
}

/* every quantity with its own exponent anywhere in the range */
static void gen_extreme(c2d_rng *r, int prec, ref_toia_in *in)
{
    int emax = prec == 24 ? 126 : 1020, ep = rng_int(r, -emax, emax), ev = rng_int(r, -emax, emax),
        ea = rng_int(r, -emax, emax), i;
    double p[2], v[2], a[2];
    zero_in(in);
    for (i = 0; i < 2; i++) {
        p[i] = ldexp(c2d_rng_range(r, -1, 1), ep);
        v[i] = ldexp(c2d_rng_range(r, -1, 1), ev);
        a[i] = c2d_rng_unit(r) < 0.2 ? 0 : ldexp(c2d_rng_range(r, -1, 1), ea);
    }
    switch (rng_int(r, 0, 3)) {
    case 0: /* exact head-on along an axis */
        p[1] = v[1] = a[1] = 0;
        if (p[0] * v[0] > 0) v[0] = -v[0];
        break;
    case 1: /* aimed: v = -p scaled by a power of two (exactly collinear) */
        v[0] = -ldexp(p[0], ev - ep);
        v[1] = -ldexp(p[1], ev - ep);
        break;
    default:
        break;
    }
    for (i = 0; i < 2; i++) {
        in->pa[i] = 0;
        in->va[i] = 0;
        in->aa[i] = 0;
        in->pb[i] = p[i];
        in->vb[i] = v[i];
        in->ab[i] = a[i];
        if (c2d_rng_unit(r) < 0.3) { /* split with a far smaller body a */
            in->pa[i] = ldexp(c2d_rng_range(r, -1, 1), rng_int(r, -emax, ep));
            in->pb[i] = p[i] + in->pa[i];
        }
    }
    in->r = ldexp(c2d_rng_range(r, 0.5, 1), rng_int(r, -emax, emax));
    if (c2d_rng_unit(r) < 0.5) in->r = ldexp(c2d_rng_range(r, 0.5, 1), ep + rng_int(r, -60, 2));
    in->h = c2d_rng_unit(r) < 0.5 ? INFINITY : ldexp(c2d_rng_range(r, 0.5, 1), rng_int(r, -emax, emax));
    if (!isfinite(in->pb[0]) || !isfinite(in->pb[1])) in->pb[0] = in->pb[1] = 1;
}

/* ------------------------------------------------------------ adversarial */

/* A graze: d(tc) = (0, R (1 + delta)) perpendicular to d'(tc) = (w, 0), so
 * the distance has a stationary point of value exactly R (1 + delta) at tc
 * (a minimum if w^2 + R a_y > 0, else a maximum); delta == 0 is an exact
 * graze.  The relative vectors are split over the two bodies so every input
 * is an exact few-bit value: p = pb - pa, v = vb - va.  big != 0: tc large
 * (the pair travels far before the graze), delta >= 2^-(MANT-2) then. */
void case_graze(c2d_rng *r, int prec, ref_toia_in *in, double delta, int want_min, int big)
{
    int bits = prec == 24 ? 5 : 12, k, j, i;
    double R = ldexp(1, rng_int(r, -2, 2)), w, tc, a[2];
    zero_in(in);
    if (big) tc = ldexp(1, prec == 24 ? rng_int(r, 12, 24) : rng_int(r, 20, 50));
    else tc = ldexp((double)rng_int(r, 1, prec == 24 ? 15 : 63), rng_int(r, -6, prec == 24 ? 0 : 2));
    w = dy(r, bits, 2);
    if (w == 0) w = 1;
    a[0] = dy(r, bits, big ? -rng_int(r, 0, 20) : 0);
    a[1] = dy(r, bits, big ? -rng_int(r, 0, 20) : 0);
    if (want_min && w * w + R * a[1] <= 0) a[1] = -a[1] + 0.25;
    if (!want_min && w * w + R * a[1] >= 0) a[1] = -(w * w + 1) / R;
    in->pa[0] = w * tc;
    in->pb[0] = a[0] * tc * tc / 2;
    if (big) {
        in->pa[1] = -(R + R * delta);
        in->pb[1] = a[1] * tc * tc / 2;
    } else {
        in->pa[1] = -R * delta;
        in->pb[1] = R + a[1] * tc * tc / 2;
    }
    in->va[0] = -w;
    in->vb[0] = -a[0] * tc;
    in->vb[1] = -a[1] * tc;
    in->ab[0] = a[0];
    in->ab[1] = a[1];
    in->r = R;
    in->h = c2d_rng_unit(r) < 0.7 ? INFINITY : tc * c2d_rng_range(r, 1, 3);
    k = 0;
    j = 0;
    if (c2d_rng_unit(r) < 0.3) { /* over the range */
        int em = prec == 24 ? 40 : 400;
        k = rng_int(r, -em, em);
        j = rng_int(r, -em / 2, em / 2);
    }
    for (i = 0; i < 2; i++) {
        in->pa[i] = ldexp(in->pa[i], k);
        in->pb[i] = ldexp(in->pb[i], k);
        in->va[i] = ldexp(in->va[i], k - j);
        in->vb[i] = ldexp(in->vb[i], k - j);
        in->ab[i] = ldexp(in->ab[i], k - 2 * j);
    }
    in->r = ldexp(in->r, k);
    in->h = ldexp(in->h, j);
}

static double band_delta(c2d_rng *r, int prec)
{
    /* relative offsets from the tie, spanning the band's edge */
    static const int ed[] = {8, 20, 30, 40, 50, 60, 70, 80, 86, 90, 93, 96, 98, 100, 104, 110, 140, 0};
    static const int ef[] = {4, 8, 12, 16, 20, 24, 28, 30, 32, 34, 36, 38, 40, 42, 44, 48, 60, 0};
    const int *e = prec == 24 ? ef : ed;
    int n = 0, i;
    while (e[n] != 0) n++;
    i = rng_int(r, -1, n - 1);
    if (i < 0) return 0;
    return (c2d_rng_unit(r) < 0.5 ? -1 : 1) * ldexp(1 + c2d_rng_unit(r), -e[i]);
}

static void gen_graze(c2d_rng *r, int prec, ref_toia_in *in) { case_graze(r, prec, in, band_delta(r, prec), 1, 0); }

/* touch from inside (a maximum of the distance at exactly R) and near it */
static void gen_inner_touch(c2d_rng *r, int prec, ref_toia_in *in)
{
    case_graze(r, prec, in, c2d_rng_unit(r) < 0.3 ? 0 : band_delta(r, prec), 0, 0);
}

/* touching at t = 0 (|d0| = R exactly: a Pythagorean triple) with every
 * kind of start: separating, tangential, staying (same v and a), pushed */
static void gen_touch0(c2d_rng *r, int prec, ref_toia_in *in)
{
    static const int tri[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {1, 0, 1}, {0, 1, 1}, {7, 24, 25}};
    int t = rng_int(r, 0, 5), k = rng_int(r, -8, 8), kind = rng_int(r, 0, 5), i;
    double p[2], v[2], a[2], s = ldexp(1, k);
    (void)prec;
    zero_in(in);
    p[0] = tri[t][0] * s * (c2d_rng_unit(r) < 0.5 ? -1 : 1);
    p[1] = tri[t][1] * s * (c2d_rng_unit(r) < 0.5 ? -1 : 1);
    in->r = tri[t][2] * s;
    for (i = 0; i < 2; i++) {
        v[i] = dy(r, 8, 1);
        a[i] = dy(r, 8, 1);
    }
    switch (kind) {
    case 0: /* tangential velocity, acceleration decides */
        v[0] = -p[1] / s;
        v[1] = p[0] / s;
        break;
    case 1: /* same velocity and acceleration: stays in contact */
        v[0] = v[1] = a[0] = a[1] = 0;
        break;
    case 2: /* at rest relative, accelerating apart or together */
        v[0] = v[1] = 0;
        a[0] = p[0] / s * (c2d_rng_unit(r) < 0.5 ? 1 : -1);
        a[1] = p[1] / s * (a[0] * p[0] >= 0 ? 1 : -1);
        if (p[0] == 0) a[1] = p[1] / s * (c2d_rng_unit(r) < 0.5 ? 1 : -1);
        break;
    case 3: /* tangential v, centripetal a matched: |v|^2 = -d0.a */
        v[0] = -p[1] / s;
        v[1] = p[0] / s;
        a[0] = -p[0] / (s * s);
        a[1] = -p[1] / (s * s);
        break;
    default:
        break;
    }
    set_rel(r, in, p, v, a, 1);
    in->h = c2d_rng_unit(r) < 0.5 ? INFINITY : ldexp(1, rng_int(r, -4, 6));
}

/* horizon just below, at, above a crossing at an exactly representable time
 * (d(tc) = (R, 0) approaching head-on) and around a general root */
static void gen_horizon(c2d_rng *r, int prec, ref_toia_in *in)
{
    int bits = prec == 24 ? 6 : 12, i, which = rng_int(r, 0, 2);
    double R = 1 + fabs(dy(r, bits, 0)), tc = ldexp((double)rng_int(r, 1, 63), rng_int(r, -4, 3)), w, a[2], p[2],
           v[2], d1y;
    zero_in(in);
    w = -(1 + fabs(dy(r, bits, 1)));
    d1y = dy(r, bits, 0);
    a[0] = dy(r, bits, 0);
    a[1] = dy(r, bits, 0);
    p[0] = R - w * tc + a[0] * tc * tc / 2;
    p[1] = 0 - d1y * tc + a[1] * tc * tc / 2;
    v[0] = w - a[0] * tc;
    v[1] = d1y - a[1] * tc;
    for (i = 0; i < 2; i++) {
        in->pb[i] = p[i];
        in->vb[i] = v[i];
        in->ab[i] = a[i];
    }
    in->r = R;
    if (prec == 24) tc = (float)tc;
    in->h = which == 0 ? nextafter(tc, 0) : (which == 1 ? tc : nextafter(tc, INFINITY));
    if (prec == 24) in->h = which == 0 ? nextafterf((float)tc, 0) : (which == 1 ? tc : nextafterf((float)tc, INFINITY));
}

/* the first pass goes through (or misses), acceleration brings it back */
static void gen_reenter(c2d_rng *r, int prec, ref_toia_in *in)
{
    double X = c2d_rng_range(r, 5, 50), V = c2d_rng_range(r, 1, 10), A = c2d_rng_range(r, 0.05, 2), off = c2d_rng_range(r, -3, 3);
    double p[2], v[2], a[2];
    (void)prec;
    zero_in(in);
    p[0] = X;
    p[1] = off;
    v[0] = -V;
    v[1] = c2d_rng_range(r, -0.2, 0.2);
    a[0] = A;
    a[1] = c2d_rng_range(r, -0.1, 0.1);
    set_rel(r, in, p, v, a, 0);
    in->r = c2d_rng_range(r, 0.5, 2);
    /* horizon anywhere from before the first entry to after the return */
    in->h = c2d_rng_unit(r) < 0.3 ? INFINITY : c2d_rng_range(r, 0, 4 * V / A);
}

/* near-grazes (either side) far along the path: the overlap (depth
 * |delta| R, well outside the band) lasts far less than an ulp of t */
static void gen_subulp(c2d_rng *r, int prec, ref_toia_in *in)
{
    double delta = (c2d_rng_unit(r) < 0.5 ? -1 : 1) * ldexp(1, prec == 24 ? -rng_int(r, 4, 20) : -rng_int(r, 8, 50));
    case_graze(r, prec, in, delta, 1, 1);
}

/* overlapping, receding, turning back while still overlapping (entry at a
 * maximum of f), including near-ties of the radial velocity */
static void gen_turn(c2d_rng *r, int prec, ref_toia_in *in)
{
    double p[2], v[2], a[2], R = c2d_rng_range(r, 1, 2);
    (void)prec;
    zero_in(in);
    p[0] = c2d_rng_range(r, 0.1, 0.9) * R;
    p[1] = c2d_rng_range(r, -0.3, 0.3) * R;
    v[0] = c2d_rng_range(r, 0, 1);
    v[1] = c2d_rng_range(r, -1, 1);
    a[0] = -c2d_rng_range(r, 0.1, 4);
    a[1] = c2d_rng_range(r, -1, 1);
    if (c2d_rng_unit(r) < 0.3) { /* circular-ish: |v|^2 ~ -d0.a, small radial velocity */
        v[0] = ldexp(c2d_rng_range(r, -1, 1), -rng_int(r, 5, 40));
        v[1] = c2d_rng_range(r, 0.5, 1);
        a[0] = -(v[1] * v[1]) / p[0] * (1 + ldexp(c2d_rng_range(r, -1, 1), -rng_int(r, 2, 40)));
        a[1] = 0;
        p[1] = 0;
    }
    set_rel(r, in, p, v, a, 0);
    in->r = R;
    in->h = c2d_rng_unit(r) < 0.5 ? INFINITY : c2d_rng_range(r, 0, 10);
}

/* huge or zero horizon, far roots, RANGE */
static void gen_huge(c2d_rng *r, int prec, ref_toia_in *in)
{
    int emax = prec == 24 ? 127 : 1023;
    gen_extreme(r, prec, in);
    switch (rng_int(r, 0, 3)) {
    case 0:
        in->h = 0;
        break;
    case 1:
        in->h = prec == 24 ? 3.4028234663852886e38 : 1.7976931348623157e308;
        break;
    case 2:
        in->h = ldexp(1, emax - rng_int(r, 0, 20));
        break;
    default:
        in->h = INFINITY;
        break;
    }
}

const family toia_families[] = {
    {"billiards", gen_billiard},   {"random accel", gen_random}, {"zero accel", gen_zero_accel},
    {"one at rest", gen_one_at_rest}, {"scaled 2^k,2^j", gen_scaled}, {"extreme ratios", gen_extreme},
    {"graze +-delta", gen_graze},  {"inner touch", gen_inner_touch}, {"touch at 0", gen_touch0},
    {"horizon at root", gen_horizon}, {"enter-leave-reenter", gen_reenter}, {"sub-ulp contact", gen_subulp},
    {"turn (overlap)", gen_turn},  {"huge/zero horizon", gen_huge},
};
const int toia_n_families = (int)(sizeof toia_families / sizeof toia_families[0]);

int toia_accel_differs(const ref_toia_in *in) { return in->aa[0] != in->ab[0] || in->aa[1] != in->ab[1]; }

int toia_in_band(const ref_toia_out *o, int is_float, const ref_toia_in *in)
{
    const double ef = is_float ? TOIA_EPS_F_FLOAT : TOIA_EPS_F_DOUBLE, eg = is_float ? TOIA_EPS_G_FLOAT : TOIA_EPS_G_DOUBLE;
    if (o->tie_f <= ef || o->tie_g <= eg) return 1;
    return toia_accel_differs(in) && (o->tie_fs <= TOIA_K_RES || o->tie_gs <= TOIA_K_RES);
}
