/* SPDX-License-Identifier: MIT */
/* c2d_time_of_impact_accel(f): statuses and times against the exact referee
 * (referee/ref_toi_accel.c: Sturm sequences over the rationals, MPFR for the
 * time), family by family: billiard balls on cloth, random accelerations,
 * zero acceleration, one body at rest, scaled and extreme magnitudes,
 * grazes, touching inside and at t = 0, the horizon at a root, leaving and
 * re-entering, contacts shorter than an ulp of t, turns while overlapping,
 * huge and zero horizons.  Outside the contract's tie band every status is
 * exact and every time within 1 unit (ulp(t) + ulp(|d|)/s); inside it,
 * wrong statuses are counted and reported.  With equal accelerations it is
 * c2d_time_of_impact(f), status and bits, within that one's bound (4 units)
 * and at every magnitude, the horizon only cutting.  Plus the closed cases
 * and the refusals. */
#include "check.h"
#include "cases_toi_accel.h"

#define CASES_PER_FAMILY 250
#define BOUND_UNITS 1.0
/* Equal accelerations: c2d_time_of_impact's own bound (its header). */
#define STRAIGHT_BOUND_UNITS 4.0

typedef struct toia_tally {
    long n, ok, wrong, band, band_wrong, linear, linear_differ;
    double worst;
} toia_tally;

static void print_case(const char *why, const ref_toia_in *in, int got, double t, const ref_toia_out *o)
{
    print_error("%s: got %d t=%a, exact %d t=%a\n  pa=(%a,%a) va=(%a,%a) aa=(%a,%a) pb=(%a,%a) vb=(%a,%a) ab=(%a,%a) "
                "R=%a H=%a\n",
                why, got, t, o->status, o->td, in->pa[0], in->pa[1], in->va[0], in->va[1], in->aa[0], in->aa[1],
                in->pb[0], in->pb[1], in->vb[0], in->vb[1], in->ab[0], in->ab[1], in->r, in->h);
}

/* The library's answer (and the constant-velocity one) for a case. */
static c2d_status call(const ref_toia_in *in, int is_float, int linear, double *t)
{
    c2d_status s;
    if (is_float) {
        c2d_bodyf a = {{(float)in->pa[0], (float)in->pa[1]}, {(float)in->va[0], (float)in->va[1]}, 1};
        c2d_bodyf b = {{(float)in->pb[0], (float)in->pb[1]}, {(float)in->vb[0], (float)in->vb[1]}, 1};
        c2d_vec2f aa = {(float)in->aa[0], (float)in->aa[1]}, ab = {(float)in->ab[0], (float)in->ab[1]};
        float tf = -1;
        s = linear ? c2d_time_of_impactf(&a, &b, (float)in->r, &tf)
                   : c2d_time_of_impact_accelf(&a, aa, &b, ab, (float)in->r, (float)in->h, &tf);
        *t = tf;
    } else {
        c2d_body a = {{in->pa[0], in->pa[1]}, {in->va[0], in->va[1]}, 1};
        c2d_body b = {{in->pb[0], in->pb[1]}, {in->vb[0], in->vb[1]}, 1};
        c2d_vec2 aa = {in->aa[0], in->aa[1]}, ab = {in->ab[0], in->ab[1]};
        *t = -1;
        s = linear ? c2d_time_of_impact(&a, &b, in->r, t)
                   : c2d_time_of_impact_accel(&a, aa, &b, ab, in->r, in->h, t);
    }
    return s;
}

static void check_case(ref_toia_in *in, int is_float, toia_tally *k, ref_toia_out *o)
{
    double t, tl;
    c2d_status got;
    int band;
    if (is_float) toia_case_to_float(in);
    got = call(in, is_float, 0, &t);
    ref_toia(in, is_float ? 24 : 53, is_float ? -126 : -1022, o);
    band = toia_in_band(o, is_float, in);
    k->n++;
    k->band += band;
    if (got != o->status) {
        if (band) {
            k->band_wrong++;
        } else {
            k->wrong++;
            print_case("wrong status", in, got, t, o);
        }
        return;
    }
    if (got == C2D_OK && !band) {
        const double e = ref_toia_err(o, t);
        k->ok++;
        const double bound = toia_accel_differs(in) ? BOUND_UNITS : STRAIGHT_BOUND_UNITS;
        if (!(e <= bound)) print_case("beyond the accuracy bound", in, got, t, o);
        assert_true(e <= bound);
        if (e > k->worst) k->worst = e;
    }
    if (!toia_accel_differs(in) && isinf(in->h)) {
        k->linear++;
        if ((call(in, is_float, 1, &tl) != got || (got == C2D_OK && tl != t)) && !band) {
            k->linear_differ++;
            print_case("differs from c2d_time_of_impact", in, got, t, o);
        }
    }
}

static void run_families(int is_float)
{
    ref_toia_out o;
    long wrong = 0, band = 0, band_wrong = 0, linear = 0;
    int f;
    ref_toia_init(&o);
    for (f = 0; f < toia_n_families; f++) {
        toia_tally k;
        c2d_rng r;
        long i;
        memset(&k, 0, sizeof k);
        r.s = 1000003u + (unsigned)f * 7919u + (unsigned)is_float;
        for (i = 0; i < CASES_PER_FAMILY; i++) {
            ref_toia_in in;
            toia_families[f].gen(&r, is_float ? 24 : 53, &in);
            check_case(&in, is_float, &k, &o);
        }
        print_message("%s %-20s %4ld cases, %4ld impacts, worst %.2f units; band %ld (%ld wrong there)\n",
                      is_float ? "float " : "double", toia_families[f].name, k.n, k.ok, k.worst, k.band, k.band_wrong);
        wrong += k.wrong + k.linear_differ;
        band += k.band;
        band_wrong += k.band_wrong;
        linear += k.linear;
    }
    ref_toia_clear(&o);
    print_message("%s: 0 wrong statuses outside the band required; %ld in the band (%ld wrong); "
                  "%ld compared with c2d_time_of_impact\n",
                  is_float ? "float " : "double", band, band_wrong, linear);
    assert_int_equal(wrong, 0);
}

static void test_double_matches_the_exact_referee_in_every_family(void **state)
{
    (void)state;
    run_families(0);
}

static void test_float_matches_the_exact_referee_in_every_family(void **state)
{
    (void)state;
    run_families(1);
}

static c2d_body at(double px, double py, double vx, double vy)
{
    c2d_body b;
    b.pos.x = px, b.pos.y = py, b.vel.x = vx, b.vel.y = vy, b.mass = 1;
    return b;
}

/* A ball rolling at 2 m/s towards one at rest 1 m away, decelerating at
 * 0.1 m/s^2: contact when 1 - R = 2t - 0.05 t^2. */
static void test_a_decelerating_ball_reaches_the_other_on_time(void **state)
{
    const double r = 0.05715, gap = 1 - r, want = 2 * gap / (2 + sqrt(4 - 4 * 0.05 * gap)); /* the stable root */
    c2d_body a = at(0, 0, 2, 0), b = at(1, 0, 0, 0);
    c2d_vec2 decel = {-0.1, 0}, none = {0, 0};
    double t = -1;
    (void)state;
    assert_status(c2d_time_of_impact_accel(&a, decel, &b, none, r, INFINITY, &t), C2D_OK);
    assert_close(t, want, 4e-16 * want);
    /* It stops first if the deceleration is strong enough (with the horizon
     * at its stop, as a caller with piecewise motion passes it). */
    decel.x = -2.5;
    assert_status(c2d_time_of_impact_accel(&a, decel, &b, none, r, 0.8, &t), C2D_SEPARATING);
    /* The horizon ending just before the contact. */
    decel.x = -0.1;
    assert_status(c2d_time_of_impact_accel(&a, decel, &b, none, r, nextafter(want, 0) * (1 - 1e-12), &t),
                  C2D_SEPARATING);
}

static void test_bad_arguments_are_invalid_and_leave_t_alone(void **state)
{
    c2d_body a = at(0, 0, 1, 0), b = at(3, 0, 0, 0);
    c2d_vec2 z = {0, 0}, nan_a = {NAN, 0}, inf_a = {0, INFINITY};
    double t = 7;
    (void)state;
    assert_status(c2d_time_of_impact_accel(&a, nan_a, &b, z, 1, 10, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact_accel(&a, z, &b, inf_a, 1, 10, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact_accel(&a, z, &b, z, -1, 10, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact_accel(&a, z, &b, z, 1, -1, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact_accel(&a, z, &b, z, 1, NAN, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact_accel(NULL, z, &b, z, 1, 10, &t), C2D_INVALID);
    assert_status(c2d_time_of_impact_accel(&a, z, &b, z, 1, 10, NULL), C2D_INVALID);
    a.pos.y = NAN;
    assert_status(c2d_time_of_impact_accel(&a, z, &b, z, 1, 10, &t), C2D_INVALID);
    assert_close(t, 7, 0);
    a.pos.y = 0;
    assert_status(c2d_time_of_impact_accel(&a, z, &b, z, 1, INFINITY, &t), C2D_OK);
    assert_close(t, 2, 0);
}

/* Two disks side by side with the same velocity and acceleration stay in
 * contact without approaching: never an impact.  Pushed together they are
 * one at once. */
static void test_touching_pairs_impact_only_when_pushed_together(void **state)
{
    c2d_body a = at(0, 0, 1, 0.5), b = at(1, 0, 1, 0.5);
    c2d_vec2 g = {0.25, -3}, push = {-0.5, 0};
    double t = -1;
    (void)state;
    assert_status(c2d_time_of_impact_accel(&a, g, &b, g, 1, INFINITY, &t), C2D_SEPARATING);
    assert_status(c2d_time_of_impact_accel(&a, g, &b, push, 1, INFINITY, &t), C2D_OK);
    assert_close(t, 0, 0);
}

/* A straight relative path at scale 2^k: b at distance 2^k (1 + u) along a
 * random direction, radius sum 2^k, closing at 2^j with a random miss. */
static void straight_pair(c2d_rng *r, int k, int j, c2d_body *a, c2d_body *b, double *rs)
{
    const double th = 6.283185307179586 * c2d_rng_unit(r), u = c2d_rng_unit(r), miss = 1.5 * c2d_rng_unit(r) - 0.75;
    const double d = ldexp(1 + u, k), s = ldexp(1, j);
    *a = at(ldexp(c2d_rng_unit(r), k), 0, ldexp(c2d_rng_unit(r) - 0.5, j), 0);
    *b = at(a->pos.x + d * cos(th), d * sin(th), a->vel.x - s * (cos(th) - miss * sin(th)),
            -s * (sin(th) + miss * cos(th)));
    *rs = ldexp(1, k);
}

/* The cases: closing at 2^-300 the contact is at 2^-k-ish tiny or
 * huge times, where the curved solver's time scale (from the acceleration,
 * zero here) once put it at 2^195 or called it RANGE. */
static void test_with_equal_accelerations_it_is_the_plain_time_of_impact_at_every_magnitude(void **state)
{
    const c2d_vec2 zero = {0, 0}, g = {0.25, -9.81};
    c2d_rng r;
    long n = 0, hits = 0, ranges = 0, cut = 0;
    int k, j, i;
    (void)state;
    r.s = 20261202u;
    for (k = -1000; k <= 1000; k += 50) {
        for (j = -1000; j <= 1000; j += 50) {
            for (i = 0; i < 4; i++) {
                c2d_body a, b;
                double rs, tp = -1, ta = -1, tg = -1, th = -1, h;
                c2d_status sp, sa, sg, sh;
                straight_pair(&r, k, j, &a, &b, &rs);
                sp = c2d_time_of_impact(&a, &b, rs, &tp);
                sa = c2d_time_of_impact_accel(&a, zero, &b, zero, rs, INFINITY, &ta);
                sg = c2d_time_of_impact_accel(&a, g, &b, g, rs, INFINITY, &tg);
                assert_int_equal(sa, sp);
                assert_int_equal(sg, sp);
                n++;
                if (sp == C2D_RANGE) ranges++;
                if (sp != C2D_OK) continue;
                hits++;
                assert_true(ta == tp && tg == tp);
                /* A finite horizon cuts: just before the contact, none; at
                 * it, the contact.  (A contact time that underflows to 0 is
                 * at no time within a zero horizon: the exact decision at 0.) */
                if (tp == 0) continue;
                h = nextafter(tp, 0);
                sh = c2d_time_of_impact_accel(&a, zero, &b, zero, rs, h, &th);
                assert_int_equal(sh, C2D_SEPARATING);
                cut++;
                assert_int_equal(c2d_time_of_impact_accel(&a, zero, &b, zero, rs, tp, &th), C2D_OK);
                assert_true(th == tp);
            }
        }
    }
    print_message("straight paths: %ld cases, %ld impacts (%ld cut by a horizon), %ld beyond DBL_MAX\n", n, hits, cut,
                  ranges);
    assert_int_equal(n, 41 * 41 * 4);
    assert_true(hits > n / 4 && cut > hits / 2 && ranges > 0);
}

/* Beyond DBL_MAX: RANGE only without a horizon, none within a finite one. */
static void test_a_straight_contact_beyond_the_range_is_range_only_without_a_horizon(void **state)
{
    const c2d_vec2 zero = {0, 0};
    c2d_body a = at(0, 0, 0, 0), b = at(1e300, 0, -1e-300, 0);
    double t = -1;
    (void)state;
    assert_status(c2d_time_of_impact(&a, &b, 1, &t), C2D_RANGE);
    assert_status(c2d_time_of_impact_accel(&a, zero, &b, zero, 1, INFINITY, &t), C2D_RANGE);
    assert_status(c2d_time_of_impact_accel(&a, zero, &b, zero, 1, DBL_MAX, &t), C2D_SEPARATING);
    b = at(1.38e223, 0, -1, 0);
    assert_status(c2d_time_of_impact_accel(&a, zero, &b, zero, 1, INFINITY, &t), C2D_OK);
    assert_close(t, 1.38e223, 1e-15 * 1.38e223);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_decelerating_ball_reaches_the_other_on_time),
        cmocka_unit_test(test_bad_arguments_are_invalid_and_leave_t_alone),
        cmocka_unit_test(test_touching_pairs_impact_only_when_pushed_together),
        cmocka_unit_test(test_with_equal_accelerations_it_is_the_plain_time_of_impact_at_every_magnitude),
        cmocka_unit_test(test_a_straight_contact_beyond_the_range_is_range_only_without_a_horizon),
        cmocka_unit_test(test_double_matches_the_exact_referee_in_every_family),
        cmocka_unit_test(test_float_matches_the_exact_referee_in_every_family),
    };
    return c2d_run_tests("time_of_impact_accel", tests);
}
