/* SPDX-License-Identifier: MIT */
/* c2d_exp_neg (lib/real/sphere.h), the freestanding exp(-x) behind the
 * speed-dependent ball-ball friction, against mpfr_exp: the double instance
 * here (white box), the float one through test_exp_negf.c's twin. */
#include "../../lib/internal.h" /* first: it asks the header for the library's internals */
#include "check.h"

#pragma GCC diagnostic ignored "-Wunused-function" /* the templates hold more than exp */

#include "../../lib/real/double.h"

#include "ref_sphere.h"

#define EXP_BOUND_ULP 2.0 /* the header comment's "a few u": measured worst printed */

/* Uniform over [0, 708] and dense near 0 and near the reduction's ties
 * (x = (k + 1/2) ln 2); exactly 0 beyond the flush. */
static void test_exp_neg_is_within_two_ulp_of_mpfr(void **state)
{
    double worst = 0;
    int i;
    c2d_rng r;
    (void)state;
    r.s = 71;
    for (i = 0; i < 200000; i++) {
        double x = i % 3 == 0   ? c2d_rng_range(&r, 0, C2D_R_EXP_NEG_MAX)
                   : i % 3 == 1 ? c2d_rng_range(&r, 0, 4)
                                : (floor(c2d_rng_range(&r, 0, 1000)) + 0.5) * 0.6931471805599453 * (1 + 1e-15);
        double err;
        if (x > C2D_R_EXP_NEG_MAX) continue;
        err = ref_exp_neg_err(x, c2d_exp_neg(x), 53);
        if (!(err <= EXP_BOUND_ULP)) print_error("exp(-%a): %.3f ulp\n", x, err);
        assert_true(err <= EXP_BOUND_ULP);
        worst = fmax(worst, err);
    }
    assert_true(c2d_exp_neg(0) == 1);
    assert_true(c2d_exp_neg(709) == 0 && c2d_exp_neg(1e300) == 0);
    print_message("exp(-x), double: worst %.3f ulp\n", worst);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exp_neg_is_within_two_ulp_of_mpfr),
    };
    return c2d_run_tests("test_exp_neg", tests);
}
