/* SPDX-License-Identifier: MIT */
/* c2d_time_of_impact(f): closed cases, then random cases against a 256-bit
 * MPFR referee, unit-scale and scaled over the whole range.  Bound: 4 units
 * of (ulp(t) + ulp(|d|) / closing speed), the documented accuracy. */
#include "check.h"

#define CASES 30000
#define BOUND_UNITS 4.0

static c2d_body body(double px, double py, double vx, double vy)
{
    c2d_body b;
    b.pos.x = px, b.pos.y = py, b.vel.x = vx, b.vel.y = vy, b.mass = 1;
    return b;
}

static void test_head_on_time_is_gap_over_closing_speed(void **state)
{
    c2d_body a = body(0, 0, 1, 0), b = body(10, 0, -1, 0);
    double t = -1;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, 2, &t), C2D_OK);
    assert_close(t, 4, 0);
}

static void test_miss_receding_and_no_motion_are_separating(void **state)
{
    c2d_body a = body(0, 0, 1, 0), b = body(10, 5, 0, 0), still = body(10, 0, 1, 0);
    double t = 123;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, 2, &t), C2D_SEPARATING);
    b = body(10, 0, 2, 0);
    assert_status(c2d_time_of_impact(&a, &b, 2, &t), C2D_SEPARATING);
    assert_status(c2d_time_of_impact(&a, &still, 2, &t), C2D_SEPARATING);
    assert_close(t, 123, 0); /* untouched */
}

static void test_overlapping_pair_impacts_now_only_when_approaching(void **state)
{
    c2d_body a = body(0, 0, 1, 0), b = body(1, 0, 0, 0);
    double t = 5;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, 2, &t), C2D_OK);
    assert_close(t, 0, 0);
    a.vel.x = -1;
    assert_status(c2d_time_of_impact(&a, &b, 2, &t), C2D_SEPARATING);
}

static void test_bad_arguments_are_invalid(void **state)
{
    c2d_body a = body(0, 0, 1, 0), b = body(10, 0, 0, 0);
    double t = 7;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, -1, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact(&a, &b, NAN, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact(&a, &b, INFINITY, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact(&a, &b, 1, NULL), C2D_INVALID);
    a.vel.y = NAN;
    assert_status(c2d_time_of_impact(&a, &b, 1, &t), C2D_INVALID);
    assert_close(t, 7, 0);
}

/* Disks 1e6 radii apart: the textbook b^2 - ac cancels to nothing here. */
static void test_far_apart_small_disks_keep_full_accuracy(void **state)
{
    ref_case c = {{0, 0}, {1e6, 0.75}, {1, 0}, {0, 0}, 1, 1, {0, 0}, 0, 1};
    c2d_body a = body(0, 0, 1, 0), b = body(1e6, 0.75, 0, 0);
    double t, want, unit;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, 1, &t), C2D_OK);
    assert_status(ref_time_of_impact(&c, 1, &want, &unit, 53, -1022), C2D_OK);
    assert_close(t, want, BOUND_UNITS * unit);
}

static void test_time_overflowing_double_is_range(void **state)
{
    c2d_body a = body(-1e300, 0, 1e-300, 0), b = body(1e300, 0, 0, 0);
    double t = 1;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, 1, &t), C2D_RANGE);
    assert_close(t, 1, 0);
}

/* The cases the audit of the statuses found (before the time of impact's
 * exact statuses): magnitudes that differ by more than the exponent range
 * used to underflow together after the scaling. */
static double bits_d(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

static float bits_f(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static void test_float_miss_beyond_the_exponent_range_is_separating(void **state)
{
    c2d_bodyf a = {{0, 0}, {0, 0}, 1}, b = {{0, 0}, {0, 0}, 1};
    float t = 5;
    (void)state;
    a.vel.x = bits_f(0x3f800000u);
    b.pos.x = bits_f(0x71800000u);
    b.pos.y = bits_f(0x21800000u);
    assert_status(c2d_time_of_impactf(&a, &b, bits_f(0x1c800000u), &t), C2D_SEPARATING);
    assert_close(t, 5, 0);
}

static void test_double_miss_beyond_the_exponent_range_is_separating(void **state)
{
    c2d_body a = body(0, 0, 0, 0), b = body(0, 0, 0, 0);
    double t = 5;
    (void)state;
    a.vel.x = bits_d(0x3ff0000000000000ull);
    b.pos.x = bits_d(0x7e70000000000000ull);
    b.pos.y = bits_d(0x39b0000000000000ull);
    assert_status(c2d_time_of_impact(&a, &b, bits_d(0x3910000000000000ull), &t), C2D_SEPARATING);
    assert_close(t, 5, 0);
}

static void test_overlapping_approach_decided_by_a_tiny_component_is_a_hit_now(void **state)
{
    c2d_body a = body(0, 0, 0, 0), b = body(0, 0, 0, 0);
    double t = 5;
    (void)state;
    a.vel.x = bits_d(0x5f30000000000000ull);
    b.pos.x = bits_d(0x1a70000000000000ull);
    b.pos.y = bits_d(0x5f30000000000000ull);
    assert_status(c2d_time_of_impact(&a, &b, bits_d(0x5f40000000000000ull), &t), C2D_OK);
    assert_close(t, 0, 0);
}

/* Rows of balls on parallel lines exactly R apart touch with no approach
 * speed: a graze, SEPARATING (as c2d_collide says), at every scale; a hair
 * closer is a hit, a hair further a miss. */
static void test_exact_grazes_are_separating_and_near_grazes_exact(void **state)
{
    int k;
    (void)state;
    for (k = -1000; k <= 1000; k += 50) {
        double s = ldexp(1.0, k), t = -1;
        c2d_body a = body(0, 0, 1, 0), b = body(10 * s, 2 * s, 0, 0);
        assert_status(c2d_time_of_impact(&a, &b, 2 * s, &t), C2D_SEPARATING);
        assert_status(c2d_time_of_impact(&a, &b, nextafter(2 * s, INFINITY), &t), C2D_OK);
        assert_status(c2d_time_of_impact(&a, &b, nextafter(2 * s, 0), &t), C2D_SEPARATING);
    }
    for (k = -120; k <= 120; k += 10) {
        float s = ldexpf(1.0f, k), t = -1;
        c2d_bodyf a = {{0, 0}, {1, 0}, 1}, b = {{0, 0}, {0, 0}, 1};
        b.pos.x = 10 * s, b.pos.y = 2 * s;
        assert_status(c2d_time_of_impactf(&a, &b, 2 * s, &t), C2D_SEPARATING);
        assert_status(c2d_time_of_impactf(&a, &b, nextafterf(2 * s, INFINITY), &t), C2D_OK);
        assert_status(c2d_time_of_impactf(&a, &b, nextafterf(2 * s, 0), &t), C2D_SEPARATING);
    }
}

/* |d| = R exactly (a 3-4-5 triangle): touching now, a hit only when approaching. */
static void test_exactly_touching_pairs_hit_now_only_when_approaching(void **state)
{
    int k;
    (void)state;
    for (k = -1000; k <= 1000; k += 100) {
        double s = ldexp(1.0, k), t = -1;
        c2d_body a = body(0, 0, 1, 0), b = body(3 * s, 4 * s, 0, 0);
        assert_status(c2d_time_of_impact(&a, &b, 5 * s, &t), C2D_OK);
        assert_close(t, 0, 0);
        a.vel.x = -1;
        assert_status(c2d_time_of_impact(&a, &b, 5 * s, &t), C2D_SEPARATING);
        a.vel.x = 0, a.vel.y = 0, b.vel.x = 4, b.vel.y = -3; /* sliding along the contact */
        assert_status(c2d_time_of_impact(&a, &b, 5 * s, &t), C2D_SEPARATING);
    }
}

/* c2d_time_of_impact, or c2d_time_of_impactf on c rounded to float (out
 * of line, case_to_float: gcc 12.2's -O2 SLP vectoriser dropped the
 * velocities' rounding when it was written inline), *t widened to double;
 * radius already what the float call gets. */
static c2d_status call_toi(int is_float, ref_case *c, double radius, double *t)
{
    c2d_status got;
    if (is_float) {
        c2d_bodyf a, b;
        float tf = -1;
        case_to_float(c);
        case_to_bodiesf(c, &a, &b);
        got = c2d_time_of_impactf(&a, &b, (float)radius, &tf);
        *t = tf;
    } else {
        c2d_body a, b;
        case_to_bodies(c, &a, &b);
        got = c2d_time_of_impact(&a, &b, radius, t);
    }
    return got;
}

/* The library's status is the referee's, the case printed if not. */
static void assert_status_as_referee(c2d_status got, c2d_status want, const ref_case *c, double radius)
{
    if (got != want)
        print_error("pa=(%a,%a) pb=(%a,%a) va=(%a,%a) vb=(%a,%a) R=%a\n", c->pa[0], c->pa[1], c->pb[0], c->pb[1],
                    c->va[0], c->va[1], c->vb[0], c->vb[1], radius);
    assert_status(got, want);
}

/* Near grazes whose exact differences scatter over the whole exponent
 * range, like the fuzzer's 1 + 2^-367 against speeds of 73 and
 * 2^-62 + 2^-911: the exact discriminant then has more components than the
 * accumulator holds and is summed again window by window (real/toi.h,
 * c2d_toi_disc_streamed).  Centres about (1, 1) apart, b sweeping past a
 * along x at a unit-ish speed while the y gap drifts by a tiny speed, R = 1:
 * the miss distance differs from R by far less than an ulp, every tiny part
 * at its own random exponent.  Statuses and times against the referee.  In
 * double about 2,300 of the 3,000 cases take the streamed sum (the rounded
 * value that stood there before fails this test); float's narrower range
 * keeps its cases in the accumulator (the ratio tests above reach its
 * streamed sum about 480 times). */
static double scattered(c2d_rng *r, int lo, int hi)
{
    double m = c2d_rng_range(r, 1, 2) * (c2d_rng_next(r) % 2 == 0 ? 1 : -1);
    return ldexp(m, lo + (int)(c2d_rng_next(r) % (uint64_t)(hi - lo + 1)));
}

static void gen_scattered_graze(c2d_rng *r, ref_case *c, int is_float)
{
    const int lo = is_float ? -149 : -1074, hi = is_float ? -20 : -40;
    double drift = ldexp(c2d_rng_range(r, 1, 2), is_float ? -(int)(c2d_rng_next(r) % 20) - 30
                                                           : -(int)(c2d_rng_next(r) % 80) - 50);
    c->pa[0] = scattered(r, lo, hi), c->pa[1] = scattered(r, lo, hi);
    c->pb[0] = 1, c->pb[1] = 1;
    c->va[0] = scattered(r, lo, hi), c->va[1] = drift * (c2d_rng_next(r) % 2 == 0 ? 1 : -1);
    c->vb[0] = -c2d_rng_range(r, 1, 100), c->vb[1] = scattered(r, lo, hi);
    if (is_float) case_to_float(c);
    c->ma = c->mb = 1, c->n[0] = c->n[1] = 0, c->has_normal = 0, c->e = 0;
}

static void run_scattered_grazes(int is_float, uint64_t seed, int want_hits)
{
    c2d_rng r;
    int i, hits = 0, prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022;
    double worst = 0;
    r.s = seed;
    for (i = 0; i < CASES / 10; i++) {
        ref_case c;
        double want = 0, unit = 0, t = -1, err;
        c2d_status got, exp_st;
        gen_scattered_graze(&r, &c, is_float);
        got = call_toi(is_float, &c, 1.0, &t);
        exp_st = ref_time_of_impact(&c, 1.0, &want, &unit, prec, emin);
        assert_status_as_referee(got, exp_st, &c, 1.0);
        if (got != C2D_OK) continue;
        hits++;
        err = fabs(t - want) / unit;
        if (!(err <= BOUND_UNITS)) {
            print_error("t=%a want %a err %.2f units\n", t, want, err);
            fail();
        }
        if (err > worst) worst = err;
    }
    assert_cases_checked(hits, want_hits);
    print_message("%s scattered near grazes: %d of %d hit, worst %.2f units\n", is_float ? "float " : "double", hits,
                  CASES / 10, worst);
}

static void test_double_near_grazes_scattered_over_the_range_are_exact(void **state)
{
    (void)state;
    run_scattered_grazes(0, 207, 1492);
}

static void test_float_near_grazes_scattered_over_the_range_are_exact(void **state)
{
    (void)state;
    run_scattered_grazes(1, 208, 1510);
}

static void gen_toi(c2d_rng *r, ref_case *c, double *radius, int scale_pos, int scale_vel)
{
    double ang = c2d_rng_range(r, 0, 6.283185307179586), dist = exp(c2d_rng_range(r, 0, log(1e6)));
    double aim = c2d_rng_range(r, -1.5, 1.5), speed = c2d_rng_range(r, 0.1, 10);
    c->pa[0] = c2d_rng_range(r, -10, 10);
    c->pa[1] = c2d_rng_range(r, -10, 10);
    c->pb[0] = c->pa[0] + dist * cos(ang);
    c->pb[1] = c->pa[1] + dist * sin(ang);
    /* relative velocity pointed roughly at a, so many hit, some miss */
    c->va[0] = c2d_rng_range(r, -1, 1), c->va[1] = c2d_rng_range(r, -1, 1);
    c->vb[0] = c->va[0] - speed * cos(ang + aim * 0.01 * (c2d_rng_next(r) % 4 == 0 ? 100 : 1));
    c->vb[1] = c->va[1] - speed * sin(ang + aim * 0.01 * (c2d_rng_next(r) % 4 == 0 ? 100 : 1));
    *radius = c2d_rng_range(r, 0.1, 3) * (c2d_rng_next(r) % 3 == 0 ? dist * 0.5 : 1);
    c->pa[0] = ldexp(c->pa[0], scale_pos), c->pa[1] = ldexp(c->pa[1], scale_pos);
    c->pb[0] = ldexp(c->pb[0], scale_pos), c->pb[1] = ldexp(c->pb[1], scale_pos);
    *radius = ldexp(*radius, scale_pos);
    c->va[0] = ldexp(c->va[0], scale_vel), c->va[1] = ldexp(c->va[1], scale_vel);
    c->vb[0] = ldexp(c->vb[0], scale_vel), c->vb[1] = ldexp(c->vb[1], scale_vel);
    /* Not used by the time of impact; set so that every field is defined. */
    c->ma = c->mb = 1, c->n[0] = c->n[1] = 0, c->has_normal = 0, c->e = 0;
}

/* extreme: 0 unit scale, 1 scaled over the range, 2 magnitude ratios.
 * want_checked: how many of the CASES have a time of impact (OK, so the
 * bound is checked), the exact count of the seeded stream (in the calls
 * below: about 70% at unit scale, 2/3 scaled, 40% of the ratio cases, the
 * rest are misses, receding pairs or RANGE).  A different count means the
 * generator or the statuses changed. */
static void run_random(int is_float, int extreme, uint64_t seed, int want_checked)
{
    c2d_rng r;
    int i, hits = 0, prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022, emax = is_float ? 100 : 1000;
    double worst = 0;
    r.s = seed;
    for (i = 0; i < CASES; i++) {
        ref_case c;
        double radius, want = 0, unit = 0, t = -1, err;
        c2d_status got, exp_st;
        int sp = extreme == 1 ? (int)(c2d_rng_next(&r) % (uint64_t)(2 * emax)) - emax : 0;
        int sv = extreme == 1 ? (int)(c2d_rng_next(&r) % (uint64_t)(2 * emax)) - emax : 0;
        if (extreme == 2)
            gen_toi_ratios(&r, &c, &radius, prec, emin, is_float ? 127 : 1023);
        else
            gen_toi(&r, &c, &radius, sp, sv);
        if (is_float) radius = (float)radius;
        got = call_toi(is_float, &c, radius, &t);
        exp_st = ref_time_of_impact(&c, radius, &want, &unit, prec, emin);
        if (exp_st == C2D_OK && want > (is_float ? FLT_MAX : DBL_MAX)) exp_st = C2D_RANGE;
        assert_status_as_referee(got, exp_st, &c, radius);
        if (got != C2D_OK) continue;
        hits++;
        err = fabs(t - want) / unit;
        if (!(err <= BOUND_UNITS)) {
            print_error("t=%a want %a err %.2f units: pa=(%a,%a) pb=(%a,%a) va=(%a,%a) vb=(%a,%a) R=%a\n", t, want,
                        err, c.pa[0], c.pa[1], c.pb[0], c.pb[1], c.va[0], c.va[1], c.vb[0], c.vb[1], radius);
            fail();
        }
        if (err > worst) worst = err;
    }
    assert_cases_checked(hits, want_checked);
    print_message("%s %s: %d impacts, worst %.2f units of (ulp(t) + ulp(|d|)/closing speed)\n",
                  is_float ? "float " : "double",
                  extreme == 2 ? "magnitude ratios" : (extreme ? "scaled over the range" : "unit scale"), hits, worst);
}

static void test_double_time_of_impact_matches_referee(void **state)
{
    (void)state;
    run_random(0, 0, 201, 14566);
}

static void test_double_time_of_impact_matches_referee_at_extreme_scales(void **state)
{
    (void)state;
    run_random(0, 1, 202, 13278);
}

static void test_float_time_of_impact_matches_referee(void **state)
{
    (void)state;
    run_random(1, 0, 203, 14568);
}

static void test_float_time_of_impact_matches_referee_at_extreme_scales(void **state)
{
    (void)state;
    run_random(1, 1, 204, 13967);
}

static void test_double_statuses_exact_at_any_magnitude_ratio(void **state)
{
    (void)state;
    run_random(0, 2, 205, 8290);
}

static void test_float_statuses_exact_at_any_magnitude_ratio(void **state)
{
    (void)state;
    run_random(1, 2, 206, 8281);
}

/* Pool balls resting in contact, as a game places them: b.pos = a.pos +
 * R (cos t, sin t) rounded, so |d| = R to rounding and |d|^2 - R^2 has
 * either sign; a at rest or rolling, b rolling at 0.01-3 m/s in any
 * direction (into a, away from it, along it).  The plain path's filter on
 * |d|^2 - R^2 cannot decide these; approaching ones are taken by
 * c2d_toi_touching (real/toi.h): |d| <= R exactly (from that sign's exact
 * TwoProduct expansion) is a hit now, |d| > R a hit later whose time is
 * c2d_toi_exact's (computed by c2d_toi_mirror in double where its window
 * allows and the careful path would call the exact one) or the careful
 * path's; receding ones by the plain path's sign of d.v.  Part of
 * the cases are scaled by 2^k so that some leave the window where the
 * expansion is exact (they must take the careful path).  Statuses and
 * times against the referee; the counts (hits now, later, separating) are
 * those of the seeded stream. */
static void run_touching(int is_float, uint64_t seed, int want_now, int want_later, int want_sep)
{
    c2d_rng r;
    int i, now = 0, later = 0, sep = 0, prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022;
    const int span = is_float ? 16 : 120; /* beyond the window (12, 100) either side */
    double worst = 0;
    r.s = seed;
    for (i = 0; i < CASES / 10; i++) {
        ref_case c;
        double ang = c2d_rng_range(&r, 0, 6.283185307179586), aim, speed, radius = 2 * 0.028575, want = 0, unit = 0;
        double t = -1, err, s;
        int k = c2d_rng_next(&r) % 4 == 0 ? (int)(c2d_rng_next(&r) % (uint64_t)(2 * span + 1)) - span : 0;
        c2d_status got, exp_st;
        s = ldexp(1.0, k);
        if (is_float) radius = ref_to_float(radius);
        c.pa[0] = c2d_rng_range(&r, 0.03, 2.5), c.pa[1] = c2d_rng_range(&r, 0.03, 1.24);
        if (is_float) c.pa[0] = ref_to_float(c.pa[0]), c.pa[1] = ref_to_float(c.pa[1]);
        c.pb[0] = c.pa[0] + radius * cos(ang), c.pb[1] = c.pa[1] + radius * sin(ang);
        c.va[0] = c.va[1] = 0;
        if (c2d_rng_next(&r) % 3 == 0) {
            speed = c2d_rng_range(&r, 0.01, 3), aim = c2d_rng_range(&r, 0, 6.283185307179586);
            c.va[0] = speed * cos(aim), c.va[1] = speed * sin(aim);
        }
        speed = c2d_rng_range(&r, 0.01, 3), aim = ang + 3.141592653589793 + c2d_rng_range(&r, -2.0, 2.0);
        c.vb[0] = speed * cos(aim), c.vb[1] = speed * sin(aim);
        c.pa[0] *= s, c.pa[1] *= s, c.pb[0] *= s, c.pb[1] *= s, radius *= s;
        c.ma = c.mb = 1, c.n[0] = c.n[1] = 0, c.has_normal = 0, c.e = 0;
        got = call_toi(is_float, &c, radius, &t);
        exp_st = ref_time_of_impact(&c, radius, &want, &unit, prec, emin);
        assert_status_as_referee(got, exp_st, &c, radius);
        if (got != C2D_OK) {
            sep++;
            continue;
        }
        if (t == 0) now++;
        else later++;
        err = fabs(t - want) / unit;
        if (!(err <= BOUND_UNITS)) {
            print_error("t=%a want %a err %.2f units\n", t, want, err);
            fail();
        }
        if (err > worst) worst = err;
    }
    print_message("%s touching pairs: %d hit now, %d later, %d separating, worst %.2f units\n",
                  is_float ? "float " : "double", now, later, sep, worst);
    assert_cases_checked(now, want_now);
    assert_cases_checked(later, want_later);
    assert_cases_checked(sep, want_sep);
}

static void test_double_touching_pairs_match_referee(void **state)
{
    (void)state;
    run_touching(0, 209, 1093, 1113, 794);
}

static void test_float_touching_pairs_match_referee(void **state)
{
    (void)state;
    run_touching(1, 210, 1089, 1132, 779);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_head_on_time_is_gap_over_closing_speed),
        cmocka_unit_test(test_miss_receding_and_no_motion_are_separating),
        cmocka_unit_test(test_overlapping_pair_impacts_now_only_when_approaching),
        cmocka_unit_test(test_bad_arguments_are_invalid),
        cmocka_unit_test(test_far_apart_small_disks_keep_full_accuracy),
        cmocka_unit_test(test_time_overflowing_double_is_range),
        cmocka_unit_test(test_double_time_of_impact_matches_referee),
        cmocka_unit_test(test_double_time_of_impact_matches_referee_at_extreme_scales),
        cmocka_unit_test(test_float_time_of_impact_matches_referee),
        cmocka_unit_test(test_float_time_of_impact_matches_referee_at_extreme_scales),
        cmocka_unit_test(test_float_miss_beyond_the_exponent_range_is_separating),
        cmocka_unit_test(test_double_miss_beyond_the_exponent_range_is_separating),
        cmocka_unit_test(test_overlapping_approach_decided_by_a_tiny_component_is_a_hit_now),
        cmocka_unit_test(test_exact_grazes_are_separating_and_near_grazes_exact),
        cmocka_unit_test(test_exactly_touching_pairs_hit_now_only_when_approaching),
        cmocka_unit_test(test_double_statuses_exact_at_any_magnitude_ratio),
        cmocka_unit_test(test_float_statuses_exact_at_any_magnitude_ratio),
        cmocka_unit_test(test_double_near_grazes_scattered_over_the_range_are_exact),
        cmocka_unit_test(test_float_near_grazes_scattered_over_the_range_are_exact),
        cmocka_unit_test(test_double_touching_pairs_match_referee),
        cmocka_unit_test(test_float_touching_pairs_match_referee),
    };
    return c2d_run_tests("time_of_impact", tests);
}
