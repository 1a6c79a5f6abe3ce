/* SPDX-License-Identifier: MIT */
/* c2d_time_of_impact_accel(f): statuses and times against the exact referee
 * (referee/ref_toi_accel.c: Sturm sequences over the rationals, MPFR for the
 * time), family by family: billiard balls on cloth, random accelerations,
 * zero acceleration, one body at rest, scaled and extreme magnitudes,
 * grazes, touching inside and at t = 0, the horizon at a root, leaving and
 * re-entering, contacts shorter than an ulp of t, turns while overlapping,
 * huge and zero horizons.  Outside the contract's tie band every status is
 * exact and every time within 1 unit (ulp(t) + ulp(|d|)/s); inside it,
 * wrong statuses are counted and reported.  With zero acceleration and no
 * horizon it agrees with c2d_time_of_impact(f).  Plus the closed cases and
 * the refusals. */
#include "check.h"
#include "cases_toi_accel.h"

#define CASES_PER_FAMILY 250
#define BOUND_UNITS 1.0

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
        if (!(e <= BOUND_UNITS)) print_case("beyond the accuracy bound", in, got, t, o);
        assert_true(e <= BOUND_UNITS);
        if (e > k->worst) k->worst = e;
    }
    if (!toia_accel_differs(in) && isinf(in->h)) {
        k->linear++;
        if (call(in, is_float, 1, &tl) != got && !band) {
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_decelerating_ball_reaches_the_other_on_time),
        cmocka_unit_test(test_bad_arguments_are_invalid_and_leave_t_alone),
        cmocka_unit_test(test_touching_pairs_impact_only_when_pushed_together),
        cmocka_unit_test(test_double_matches_the_exact_referee_in_every_family),
        cmocka_unit_test(test_float_matches_the_exact_referee_in_every_family),
    };
    return c2d_run_tests("time_of_impact_accel", tests);
}
