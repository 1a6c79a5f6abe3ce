/* SPDX-License-Identifier: MIT */
/* Q16.16: against the exact referee (and the double path) within the
 * documented bound, |error| <= 3 steps + 2^-24 S per component (S: largest
 * |velocity component| of either body, before or after); statuses;
 * saturation to C2D_RANGE instead of wrapping; time of impact. */
#include "check.h"

#define CASES 30000

static double q2d(c2d_fixed x) { return x / 65536.0; }
static c2d_fixed d2q(double x) { return (c2d_fixed)lrint(x * 65536.0); }

static void gen_fixed(c2d_rng *r, c2d_bodyx *a, c2d_bodyx *b, c2d_fixed *e, double scale)
{
    double ang = c2d_rng_range(r, 0, 6.283185307179586), dist = c2d_rng_range(r, 0.05, 2) * scale;
    a->pos.x = d2q(c2d_rng_range(r, -100, 100));
    a->pos.y = d2q(c2d_rng_range(r, -100, 100));
    b->pos.x = a->pos.x + d2q(dist * cos(ang));
    b->pos.y = a->pos.y + d2q(dist * sin(ang));
    a->vel.x = d2q(c2d_rng_range(r, -1, 1) * scale), a->vel.y = d2q(c2d_rng_range(r, -1, 1) * scale);
    b->vel.x = d2q(c2d_rng_range(r, -1, 1) * scale), b->vel.y = d2q(c2d_rng_range(r, -1, 1) * scale);
    a->mass = c2d_rng_next(r) % 16 == 0 ? C2D_FIXED_INFINITE_MASS : d2q(exp(c2d_rng_range(r, log(0.01), log(1000))));
    b->mass = a->mass == C2D_FIXED_INFINITE_MASS || c2d_rng_next(r) % 16 ? d2q(exp(c2d_rng_range(r, log(0.01), log(1000))))
                                                                     : C2D_FIXED_INFINITE_MASS;
    *e = c2d_rng_next(r) % 3 == 0 ? C2D_FIXED_ONE : (c2d_fixed)(c2d_rng_next(r) % 65537);
}

static void to_case(const c2d_bodyx *a, const c2d_bodyx *b, c2d_fixed e, ref_case *c)
{
    c->pa[0] = q2d(a->pos.x), c->pa[1] = q2d(a->pos.y), c->pb[0] = q2d(b->pos.x), c->pb[1] = q2d(b->pos.y);
    c->va[0] = q2d(a->vel.x), c->va[1] = q2d(a->vel.y), c->vb[0] = q2d(b->vel.x), c->vb[1] = q2d(b->vel.y);
    c->ma = a->mass == C2D_FIXED_INFINITE_MASS ? INFINITY : q2d(a->mass);
    c->mb = b->mass == C2D_FIXED_INFINITE_MASS ? INFINITY : q2d(b->mass);
    c->has_normal = 0;
    c->e = q2d(e);
}

/* want_checked: how many of the CASES reach the bound's check, resolved by
 * the Q16.16 call, the referee and the double call alike (not RANGE, nor an
 * approach slower than half a step): the exact count of the seeded stream,
 * about 3/4 (in the calls below).  A different count means the generator or
 * the statuses changed. */
static void run(double scale, uint64_t seed, const char *what, int want_checked)
{
    c2d_rng r;
    ref_answer ans;
    int i, n_ok = 0;
    double worst = 0, worst_vs_double = 0;
    r.s = seed;
    ref_answer_init(&ans);
    for (i = 0; i < CASES; i++) {
        c2d_bodyx a, b, a0, b0;
        c2d_body da, db;
        c2d_fixed e;
        ref_case c;
        c2d_status s, sd;
        int k;
        gen_fixed(&r, &a, &b, &e, scale);
        a0 = a, b0 = b;
        to_case(&a, &b, e, &c);
        s = c2d_collidex(&a, &b, e);
        ref_collide(&c, 32768.0, &ans);
        case_to_bodies(&c, &da, &db);
        sd = c2d_collide(&da, &db, c.e);
        if (s != C2D_OK) {
            assert_bits_equal(a, a0);
            assert_bits_equal(b, b0);
        }
        if (ans.status == C2D_OK && ans.range_required) {
            assert_status(s, C2D_RANGE);
            continue;
        }
        if (ans.status == C2D_OK && s == C2D_SEPARATING) {
            /* documented: an approach slower than half a step counts as separating */
            double n[2] = {c.pb[0] - c.pa[0], c.pb[1] - c.pa[1]};
            double vn = ((c.vb[0] - c.va[0]) * n[0] + (c.vb[1] - c.va[1]) * n[1]) / hypot(n[0], n[1]);
            assert_true(fabs(vn) * 65536.0 < 0.5 + 1e-6);
            continue;
        }
        assert_status(s, ans.status);
        assert_status(sd, ans.status);
        if (s != C2D_OK) continue;
        n_ok++;
        double vscale = 0;
        for (k = 0; k < 4; k++) {
            const c2d_fixed before = k == 0 ? a0.vel.x : k == 1 ? a0.vel.y : k == 2 ? b0.vel.x : b0.vel.y;
            vscale = fmax(vscale, fmax(fabs((double)before), fabs(mpq_get_d(ans.v[k]) * 65536.0)));
        }
        for (k = 0; k < 4; k++) {
            const c2d_fixed got = k == 0 ? a.vel.x : k == 1 ? a.vel.y : k == 2 ? b.vel.x : b.vel.y;
            const c2d_fixed before = k == 0 ? a0.vel.x : k == 1 ? a0.vel.y : k == 2 ? b0.vel.x : b0.vel.y;
            const double dbl = k == 0 ? da.vel.x : k == 1 ? da.vel.y : k == 2 ? db.vel.x : db.vel.y;
            double exact = mpq_get_d(ans.v[k]) * 65536.0;
            double err = fabs(got - exact), bound = 3 + vscale * 0x1p-24;
            (void)before;
            if (!(err <= bound)) {
                print_error("component %d: got %d, exact %.3f, bound %.3f steps\n", k, got, exact, bound);
                fail();
            }
            if (err / bound > worst) worst = err / bound;
            if (fabs(got - dbl * 65536.0) > worst_vs_double) worst_vs_double = fabs(got - dbl * 65536.0);
        }
    }
    ref_answer_clear(&ans);
    assert_cases_checked(n_ok, want_checked);
    print_message("Q16.16 %s: %d impacts, worst %.2f of the bound, worst %.2f steps from the double path\n", what, n_ok,
                  worst, worst_vs_double);
}

static void test_fixed_within_bound_at_game_speeds(void **state)
{
    (void)state;
    run(10, 301, "speeds ~10", 15087);
}

static void test_fixed_within_bound_at_large_values(void **state)
{
    (void)state;
    run(8000, 302, "speeds ~8000", 14809);
}

static void test_fixed_within_bound_at_tiny_values(void **state)
{
    (void)state;
    run(0.01, 303, "speeds ~0.01", 15025);
}

static void test_fixed_overflow_is_range_not_wraparound(void **state)
{
    c2d_bodyx a = {{0, 0}, {0, 0}, 65536}, b = {{65536, 0}, {-30000 * 65536, 0}, 1000 * 65536}, a0, b0;
    (void)state;
    a0 = a, b0 = b;
    assert_status(c2d_collidex(&a, &b, C2D_FIXED_ONE), C2D_RANGE); /* a would reach ~ -60000 */
    assert_bits_equal(a, a0);
    assert_bits_equal(b, b0);
}

static void test_fixed_refusals_match_double_semantics(void **state)
{
    c2d_bodyx a = {{0, 0}, {65536, 0}, 65536}, b = {{65536, 0}, {0, 0}, 65536};
    c2d_vec2x zero = {0, 0};
    c2d_bodyx x;
    (void)state;
    x = a, x.mass = 0;
    assert_status(c2d_collidex(&x, &b, C2D_FIXED_ONE), C2D_INVALID);
    assert_status(c2d_collidex(&a, &b, C2D_FIXED_ONE + 1), C2D_INVALID);
    assert_status(c2d_collidex(&a, &b, -1), C2D_INVALID);
    assert_status(c2d_collide_normalx(&a, &b, zero, C2D_FIXED_ONE), C2D_DEGENERATE);
    x = b, x.pos = a.pos;
    assert_status(c2d_collidex(&a, &x, C2D_FIXED_ONE), C2D_DEGENERATE);
    x = a, x.vel.x = -65536;
    assert_status(c2d_collidex(&x, &b, C2D_FIXED_ONE), C2D_SEPARATING);
    assert_status(c2d_collidex(NULL, &b, C2D_FIXED_ONE), C2D_INVALID);
    assert_status(c2d_collidex(&a, &b, C2D_FIXED_ONE), C2D_OK);
    assert_int_equal(a.vel.x, 0);
    assert_int_equal(b.vel.x, 65536);
}

static void test_fixed_time_of_impact_within_bound(void **state)
{
    c2d_rng r = {304};
    int i, hits = 0;
    (void)state;
    for (i = 0; i < CASES; i++) {
        c2d_bodyx a, b;
        c2d_fixed e, t = -1, rad = d2q(c2d_rng_range(&r, 0.05, 3));
        ref_case c;
        double want = 0, unit = 0;
        c2d_status s, ws;
        gen_fixed(&r, &a, &b, &e, c2d_rng_next(&r) % 2 ? 10 : 1000);
        b.pos.x = a.pos.x + (b.pos.x - a.pos.x) * 8;
        to_case(&a, &b, e, &c);
        s = c2d_time_of_impactx(&a, &b, rad, &t);
        ws = ref_time_of_impact(&c, q2d(rad), &want, &unit, 53, -1022);
        if (ws == C2D_OK && want * 65536.0 > INT32_MAX) ws = C2D_RANGE;
        assert_status(s, ws);
        if (s != C2D_OK) continue;
        hits++;
        {
            /* 2 steps of t + the time one step (2^-16) of distance is worth at contact */
            /* 2 steps + the time to close 2^-16 + |d| 2^-27 of distance at contact */
            double dist = hypot(c.pb[0] - c.pa[0], c.pb[1] - c.pa[1]);
            double per_dist_ulp = (unit - ref_ulp(want, 53, -1022)) / ref_ulp(dist, 53, -1022);
            double bound = 2 + per_dist_ulp * (1 + dist * 65536.0 * 0x1p-27);
            if (!(fabs(t - want * 65536.0) <= bound)) {
                print_error("t=%d want %.3f steps, bound %.3f\n", t, want * 65536.0, bound);
                fail();
            }
        }
    }
    /* The pairs are spread 8 times wider along x than gen_fixed makes them,
     * so few come within the radius: seed 304's exact count of times found
     * (OK); a different count means the generator or the statuses changed. */
    assert_cases_checked(hits, 408);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fixed_within_bound_at_game_speeds),
        cmocka_unit_test(test_fixed_within_bound_at_large_values),
        cmocka_unit_test(test_fixed_within_bound_at_tiny_values),
        cmocka_unit_test(test_fixed_overflow_is_range_not_wraparound),
        cmocka_unit_test(test_fixed_refusals_match_double_semantics),
        cmocka_unit_test(test_fixed_time_of_impact_within_bound),
    };
    return c2d_run_tests("fixed", tests);
}
