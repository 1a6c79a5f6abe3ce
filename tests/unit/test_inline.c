/* SPDX-License-Identifier: MIT */
/* The opt-in inline front ends (C2D_INLINE) give the library call's
 * statuses and bits, double and float, c2d_collide and c2d_collide_normal,
 * over every input family the other suites use plus walls and axes. */
#define C2D_INLINE
#include "check.h"

#define CASES 200000

static void test_this_build_really_inlines(void **state)
{
    (void)state;
    assert_int_equal(C2D_INLINE_AS_WRITTEN, 1); /* -std=c99: contraction off */
}

/* The accept test's window, written as decimals in the header (C++ before
 * 17 has no hexadecimal floating constants), is exactly 2^+-200, 2^+-20. */
static void test_accept_window_is_exact(void **state)
{
    (void)state;
    assert_true(C2D_ACCEPT_HI == ldexp(1.0, 200) && C2D_ACCEPT_LO == ldexp(1.0, -200));
    assert_true(C2D_ACCEPT_HIF == ldexpf(1.0f, 20) && C2D_ACCEPT_LOF == ldexpf(1.0f, -20));
}

/* A case of family k: unit scale, whole range, a wall, on an axis, bad input. */
static void gen_family(c2d_rng *r, ref_case *c, int k, int prec, int emin, int emax)
{
    if (k % 2 == 0) gen_plain(r, c); else gen_extreme(r, c, prec, emin, emax);
    if (k == 2) c->mb = INFINITY;
    if (k == 3) c->pb[0] = c->pa[0], c->n[0] = 0;
    if (k == 4) c->e = (c2d_rng_next(r) & 1) ? 1.5 : NAN;
    if (k == 5) c->va[1] = NAN;
}

static void test_inline_double_is_the_library_call(void **state)
{
    c2d_rng r = {601};
    int i;
    (void)state;
    for (i = 0; i < CASES; i++) {
        ref_case c;
        c2d_body a1, b1, a2, b2;
        c2d_vec2 n;
        gen_family(&r, &c, i % 6, 53, -1022, 1023);
        n.x = c.n[0], n.y = c.n[1];
        case_to_bodies(&c, &a1, &b1);
        case_to_bodies(&c, &a2, &b2);
        assert_status(c2d_collide_inline(&a1, &b1, c.e), c2d_collide(&a2, &b2, c.e));
        assert_bits_equal(a1, a2);
        assert_bits_equal(b1, b2);
        case_to_bodies(&c, &a1, &b1);
        case_to_bodies(&c, &a2, &b2);
        assert_status(c2d_collide_normal_inline(&a1, &b1, n, c.e), c2d_collide_normal(&a2, &b2, n, c.e));
        assert_bits_equal(a1, a2);
        assert_bits_equal(b1, b2);
    }
}

static void test_inline_float_is_the_library_call(void **state)
{
    c2d_rng r = {602};
    int i;
    (void)state;
    for (i = 0; i < CASES; i++) {
        ref_case c;
        c2d_bodyf a1, b1, a2, b2;
        c2d_vec2f n;
        gen_family(&r, &c, i % 6, 24, -126, 127);
        case_to_float(&c);
        n.x = (float)c.n[0], n.y = (float)c.n[1];
        case_to_bodiesf(&c, &a1, &b1);
        case_to_bodiesf(&c, &a2, &b2);
        assert_status(c2d_collidef_inline(&a1, &b1, (float)c.e), c2d_collidef(&a2, &b2, (float)c.e));
        assert_bits_equal(a1, a2);
        assert_bits_equal(b1, b2);
        case_to_bodiesf(&c, &a1, &b1);
        case_to_bodiesf(&c, &a2, &b2);
        assert_status(c2d_collide_normalf_inline(&a1, &b1, n, (float)c.e), c2d_collide_normalf(&a2, &b2, n, (float)c.e));
        assert_bits_equal(a1, a2);
        assert_bits_equal(b1, b2);
    }
}

static void test_inline_refuses_like_the_library(void **state)
{
    c2d_body a = {{0, 0}, {1, 0}, 1}, b = {{1, 0.5}, {0, 0}, 1};
    c2d_vec2 n = {1, 0.5};
    (void)state;
    assert_status(c2d_collide_inline(NULL, &b, 1), C2D_INVALID);
    assert_status(c2d_collide_inline(&a, &a, 1), C2D_DEGENERATE);
    assert_status(c2d_collide_normal_inline(&a, &a, n, 1), C2D_DEGENERATE);
    a.pos.x = INFINITY;
    assert_status(c2d_collide_normal_inline(&a, &b, n, 1), C2D_INVALID);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_this_build_really_inlines),
        cmocka_unit_test(test_accept_window_is_exact),
        cmocka_unit_test(test_inline_double_is_the_library_call),
        cmocka_unit_test(test_inline_float_is_the_library_call),
        cmocka_unit_test(test_inline_refuses_like_the_library),
    };
    return c2d_run_tests("inline", tests);
}
