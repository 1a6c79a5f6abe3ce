/* SPDX-License-Identifier: MIT */
/* The body of test_exp_neg.c and test_exp_negf.c: c2d_exp_neg of the
 * instance the includer built (real/double.h or real/float.h, white box)
 * against mpfr_exp.  Needs EXP_PREC (53 or 24) and EXP_NAME. */
#include "ref_sphere.h"

#define EXP_BOUND_ULP 2.0 /* the template's "a few u"; the measured worst is printed */

/* Uniform over [0, C2D_R_EXP_NEG_MAX], dense over [0, 4] (pool's slip
 * speeds times Alciatore's decay), and just above the reduction's ties
 * x = (k + 1/2) ln 2; exactly 0 beyond the flush. */
static void test_exp_neg_is_within_two_ulp_of_mpfr(void **state)
{
    double worst = 0;
    int i, n = 0;
    c2d_rng r;
    (void)state;
    r.s = 71;
    for (i = 0; i < 200000; i++) {
        double x = i % 3 == 0   ? c2d_rng_range(&r, 0, C2D_R_EXP_NEG_MAX)
                   : i % 3 == 1 ? c2d_rng_range(&r, 0, 4)
                                : (floor(c2d_rng_range(&r, 0, C2D_R_EXP_NEG_MAX / 0.7)) + 0.5) * 0.6931471805599453 *
                                      (1 + 1e-6);
        c2d_real xr = (c2d_real)x;
        double err;
        if (xr > C2D_R_EXP_NEG_MAX) continue;
        err = ref_exp_neg_err(xr, c2d_exp_neg(xr), EXP_PREC);
        if (!(err <= EXP_BOUND_ULP)) print_error("exp(-%a): %.3f ulp\n", (double)xr, err);
        assert_true(err <= EXP_BOUND_ULP);
        worst = fmax(worst, err);
        n++;
    }
    assert_true(n > 190000); /* only the ties past the flush are skipped: about 1 in 300 of a third */
    assert_true(c2d_exp_neg(0) == 1);
    assert_true(c2d_exp_neg((c2d_real)(C2D_R_EXP_NEG_MAX + 1)) == 0 && c2d_exp_neg(C2D_R_MAX) == 0);
    print_message("exp(-x), %s: worst %.3f ulp\n", EXP_NAME, worst);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exp_neg_is_within_two_ulp_of_mpfr),
    };
    return c2d_run_tests(EXP_NAME, tests);
}
