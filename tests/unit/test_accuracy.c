/* SPDX-License-Identifier: MIT */
/* Accuracy against the exact referee (GMP rationals), over unit-scale scenes
 * and over the whole floating-point range: statuses must match exactly
 * (C2D_RANGE only where the contract allows it) and every output must be
 * within 16 ulp of its body's velocity scale.  The worst error is printed. */
#include "check.h"

#define PLAIN_CASES 30000
#define EXTREME_CASES 60000
#define BOUND_ULP 16.0

typedef struct tally { int n_ok, n_range; double worst, sum; } tally;

static c2d_status run_double(const ref_case *c, double got[4])
{
    c2d_body a, b;
    c2d_status s;
    case_to_bodies(c, &a, &b);
    if (c->has_normal) {
        c2d_vec2 n = {c->n[0], c->n[1]};
        s = c2d_collide_normal(&a, &b, n, c->e);
    } else {
        s = c2d_collide(&a, &b, c->e);
    }
    got[0] = a.vel.x, got[1] = a.vel.y, got[2] = b.vel.x, got[3] = b.vel.y;
    return s;
}

static c2d_status run_float(const ref_case *c, double got[4])
{
    c2d_bodyf a, b;
    c2d_status s;
    case_to_bodiesf(c, &a, &b);
    if (c->has_normal) {
        c2d_vec2f n = {(float)c->n[0], (float)c->n[1]};
        s = c2d_collide_normalf(&a, &b, n, (float)c->e);
    } else {
        s = c2d_collidef(&a, &b, (float)c->e);
    }
    got[0] = a.vel.x, got[1] = a.vel.y, got[2] = b.vel.x, got[3] = b.vel.y;
    return s;
}

static void check_one(const ref_case *c, int is_float, ref_answer *ans, tally *t)
{
    double got[4], err;
    int prec = is_float ? 24 : 53, emin = is_float ? -126 : -1022;
    c2d_status s = is_float ? run_float(c, got) : run_double(c, got);
    ref_collide(c, is_float ? FLT_MAX : DBL_MAX, ans);
    if (ans->status == C2D_OK && ans->range_required) {
        assert_status(s, C2D_RANGE);
        return;
    }
    if (s == C2D_RANGE && ans->status == C2D_OK && ans->range_allowed) {
        t->n_range++;
        return;
    }
    if (s != ans->status) {
        print_error("va=(%a,%a) vb=(%a,%a) pa=(%a,%a) pb=(%a,%a) n=%d:(%a,%a) m=%a,%a e=%a\n", c->va[0], c->va[1],
                    c->vb[0], c->vb[1], c->pa[0], c->pa[1], c->pb[0], c->pb[1], c->has_normal, c->n[0], c->n[1],
                    c->ma, c->mb, c->e);
        assert_status(s, ans->status);
    }
    if (s != C2D_OK) return;
    err = ref_collide_err(c, ans, got, prec, emin);
    if (!(err <= BOUND_ULP)) {
        print_error("error %.2f ulp: va=(%a,%a) vb=(%a,%a) pa=(%a,%a) pb=(%a,%a) n=%d:(%a,%a) m=%a,%a e=%a\n", err,
                    c->va[0], c->va[1], c->vb[0], c->vb[1], c->pa[0], c->pa[1], c->pb[0], c->pb[1], c->has_normal,
                    c->n[0], c->n[1], c->ma, c->mb, c->e);
        fail();
    }
    t->n_ok++;
    t->sum += err;
    if (err > t->worst) t->worst = err;
}

static void run_suite(const char *what, int is_float, int extreme, int count, uint64_t seed)
{
    c2d_rng r;
    ref_answer ans;
    tally t = {0, 0, 0, 0};
    int i;
    r.s = seed;
    ref_answer_init(&ans);
    for (i = 0; i < count; i++) {
        ref_case c;
        if (extreme) {
            gen_extreme(&r, &c, is_float ? 24 : 53, is_float ? -126 : -1022, is_float ? 127 : 1023);
        } else {
            gen_plain(&r, &c);
            if (is_float) case_to_float(&c);
        }
        check_one(&c, is_float, &ans, &t);
    }
    ref_answer_clear(&ans);
    assert_true(t.n_ok > count / 2);
    print_message("%-16s %6d impacts: worst %.2f ulp, mean %.3f ulp (%d allowed RANGE)\n", what, t.n_ok, t.worst,
                  t.sum / t.n_ok, t.n_range);
}

static void test_double_within_16_ulp_on_unit_scale_scenes(void **state)
{
    (void)state;
    run_suite("double plain", 0, 0, PLAIN_CASES, 101);
}

static void test_double_within_16_ulp_over_the_whole_range(void **state)
{
    (void)state;
    run_suite("double extreme", 0, 1, EXTREME_CASES, 102);
}

static void test_float_within_16_ulp_on_unit_scale_scenes(void **state)
{
    (void)state;
    run_suite("float plain", 1, 0, PLAIN_CASES, 103);
}

static void test_float_within_16_ulp_over_the_whole_range(void **state)
{
    (void)state;
    run_suite("float extreme", 1, 1, EXTREME_CASES, 104);
}

/* Mass ratios of 1e+-300 and beyond the double range: the heavy body's tiny
 * velocity change must be accurate on its own scale. */
static void test_heavy_body_tiny_change_is_accurate_on_its_own_scale(void **state)
{
    static const double ratios[] = {1e300, 1e-300, 0x1p-1074, 1e308};
    ref_answer ans;
    size_t i;
    (void)state;
    ref_answer_init(&ans);
    for (i = 0; i < sizeof ratios / sizeof ratios[0]; i++) {
        ref_case c = {{0, 0}, {1, 0.25}, {0, 0}, {-1, 0.5}, 1, 1, {0, 0}, 0, 1};
        double got[4], err;
        c.ma = ratios[i];
        c.mb = ratios[i] < 1 ? 1e300 : 1;
        assert_status(run_double(&c, got), C2D_OK);
        ref_collide(&c, DBL_MAX, &ans);
        err = ref_collide_err(&c, &ans, got, 53, -1022);
        assert_true(err <= BOUND_ULP);
        assert_true(got[0] != 0 || c.ma < c.mb); /* the heavy body really moved */
    }
    ref_answer_clear(&ans);
}

/* A fast heavy body sliding tangentially past a slow light one: the light
 * body's change depends on a component 600 binades below the heavy body's
 * speed, which a common scaling of all velocities would flush to zero. */
static void test_grazing_contact_is_resolved_on_the_light_bodys_scale(void **state)
{
    ref_case c = {{0, 0}, {0, 1}, {1e300, 0}, {0, -1e-300}, 1e10, 1, {0, 0}, 0, 1};
    ref_answer ans;
    double got[4];
    (void)state;
    ref_answer_init(&ans);
    assert_status(run_double(&c, got), C2D_OK);
    ref_collide(&c, DBL_MAX, &ans);
    assert_true(ref_collide_err(&c, &ans, got, 53, -1022) <= BOUND_ULP);
    assert_true(got[3] > 0);
    ref_answer_clear(&ans);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_double_within_16_ulp_on_unit_scale_scenes),
        cmocka_unit_test(test_double_within_16_ulp_over_the_whole_range),
        cmocka_unit_test(test_float_within_16_ulp_on_unit_scale_scenes),
        cmocka_unit_test(test_float_within_16_ulp_over_the_whole_range),
        cmocka_unit_test(test_heavy_body_tiny_change_is_accurate_on_its_own_scale),
        cmocka_unit_test(test_grazing_contact_is_resolved_on_the_light_bodys_scale),
    };
    return c2d_run_tests("accuracy", tests);
}
