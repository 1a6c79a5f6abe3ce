/* SPDX-License-Identifier: MIT */
/* The sum of two extended numbers (c2d_ext_add, lib/real/arith/sign.h), double:
 * the library's templates instantiated here with lib/double.c's parameters
 * (lib/real/double.h), checked against MPFR.
 *
 * The accelerated time of impact used to carry its own copy of this sum,
 * which differed in one place: the operand far below the other was dropped
 * when the exponents differ by more than MANT + 3 (`>`), where c2d_ext_add
 * drops it from MANT + 3 on (`>=`).  At a difference of exactly MANT + 3 the
 * copy adds the small operand and rounds; c2d_ext_add returns the large one
 * unchanged.  Both are right for normalised operands (|m| in [1, 2)): the
 * small one is then below a quarter of an ulp of the large, so the rounded
 * sum is the large one.  `>=` is the tight cut: at MANT + 2 the rounded sum
 * can differ from the large operand (1 - 1.5 2^-(MANT+2) rounds below 1).
 * The one caller that passes an operand outside [1, 2) (a bound rounded up by
 * 1 + 2^(4 - MANT), real/toia/turns.h) only asks for the sign of a
 * difference against a relative slack (c2d_toia_ext_cmp), which the two cuts
 * decide alike: shown below with the old copy kept here as the witness. */
#include "../../lib/internal.h" /* first: it asks the header for the library's internals */
#include "check.h"

#pragma GCC diagnostic ignored "-Wunused-function" /* the templates hold more than the sum */

#include "../../lib/real/double.h"

#include <mpfr.h>
#include <stdio.h>

/* The copy the accelerated time of impact carried (real/toia/newton.h
 * before it was built on c2d_ext_add), verbatim but for the names. */
static void old_toia_ext_add(c2d_ext *r, const c2d_ext *a, const c2d_ext *b)
{
    int k;
    if (a->m == 0) {
        c2d_ext_copy(r, b);
        return;
    }
    if (b->m == 0) {
        c2d_ext_copy(r, a);
        return;
    }
    k = a->e - b->e;
    if (k > C2D_R_MANT + 3) {
        c2d_ext_copy(r, a);
    } else if (k < -(C2D_R_MANT + 3)) {
        c2d_ext_copy(r, b);
    } else if (k >= 0) {
        c2d_ext_set(r, a->m + c2d_scale2(b->m, -k), a->e);
    } else {
        c2d_ext_set(r, c2d_scale2(a->m, k) + b->m, b->e);
    }
}

/* c2d_toia_ext_cmp as it was, on the old sum. */
static int old_toia_ext_cmp(const c2d_ext *a, const c2d_ext *b)
{
    c2d_ext nb, d;
    nb.m = -b->m;
    nb.e = b->e;
    old_toia_ext_add(&d, a, &nb);
    if (d.m == 0) return 0;
    {
        int top = a->m == 0 ? b->e : (b->m == 0 ? a->e : c2d_toia_max_int(a->e, b->e));
        if (d.e < top + 5 - C2D_R_MANT) return 0;
    }
    return c2d_toia_sign_of(d.m);
}

/* x == m 2^e exactly (MPFR, exponents far inside its range). */
static int equals(const mpfr_t x, const c2d_ext *r)
{
    mpfr_t y;
    int same;
    mpfr_init2(y, 64);
    mpfr_set_d(y, r->m, MPFR_RNDN);
    mpfr_mul_2si(y, y, r->e, MPFR_RNDN);
    same = mpfr_equal_p(x, y) != 0 || (mpfr_zero_p(x) != 0 && r->m == 0);
    mpfr_clear(y);
    return same;
}

/* a + b rounded once to MANT + 1 bits: the right answer. */
static void rounded_sum(mpfr_t s, const c2d_ext *a, const c2d_ext *b)
{
    mpfr_t x, y;
    mpfr_inits2(64, x, y, (mpfr_ptr)0);
    mpfr_set_d(x, a->m, MPFR_RNDN);
    mpfr_mul_2si(x, x, a->e, MPFR_RNDN);
    mpfr_set_d(y, b->m, MPFR_RNDN);
    mpfr_mul_2si(y, y, b->e, MPFR_RNDN);
    mpfr_set_prec(s, C2D_R_MANT + 1);
    mpfr_add(s, x, y, MPFR_RNDN);
    mpfr_clears(x, y, (mpfr_ptr)0);
}

/* Significands at the edges of [1, 2) and inside, both signs. */
static const double sig[] = {1.0, 1.0 + 0x1p-52, 1.0 + 0x1p-51, 1.25, 1.5, 1.5 + 0x1p-52, 1.75, 2.0 - 0x1p-52,
                             2.0 - 0x1p-51};
enum { NSIG = sizeof sig / sizeof sig[0] };

/* Normalised operands, exponent differences around both cuts: c2d_ext_add
 * and the old copy both return the correctly rounded sum, bit for bit the
 * same extended number. */
static void test_both_cuts_round_correctly_for_normalised_operands(void **state)
{
    c2d_tally t = {0, 0};
    int same = 0, at_cut = 0;
    int i, j, sa, sb, k;
    mpfr_t s;
    (void)state;
    mpfr_init2(s, C2D_R_MANT + 1);
    for (i = 0; i < NSIG; i++)
        for (j = 0; j < NSIG; j++)
            for (sa = -1; sa <= 1; sa += 2)
                for (sb = -1; sb <= 1; sb += 2)
                    for (k = -(C2D_R_MANT + 8); k <= C2D_R_MANT + 8; k++) {
                        c2d_ext a, b, shared, old;
                        a.m = sa * sig[i];
                        a.e = 7;
                        b.m = sb * sig[j];
                        b.e = 7 - k;
                        c2d_ext_add(&shared, &a, &b, 1);
                        old_toia_ext_add(&old, &a, &b);
                        rounded_sum(s, &a, &b);
                        (void)c2d_tally_add(&t, equals(s, &shared));
                        (void)c2d_tally_add(&t, equals(s, &old));
                        if (shared.m == old.m && shared.e == old.e) same++;
                        if (k == C2D_R_MANT + 3 || k == -(C2D_R_MANT + 3)) {
                            /* where the cuts differ, the rounded sum is the larger operand */
                            const c2d_ext *big = k > 0 ? &a : &b;
                            (void)c2d_tally_add(&t, shared.m == big->m && shared.e == big->e);
                            at_cut++;
                        }
                    }
    mpfr_clear(s);
    c2d_put_tally("ext_add vs MPFR, both cuts", &t);
    assert_int_equal(t.failed, 0);
    assert_int_equal(same, NSIG * NSIG * 4 * (2 * (C2D_R_MANT + 8) + 1));
    assert_int_equal(at_cut, NSIG * NSIG * 4 * 2);
}

/* The cut cannot move one lower: at MANT + 2 the rounded sum is not always
 * the larger operand, and c2d_ext_add still adds there. */
static void test_the_cut_at_mant_plus_3_is_tight(void **state)
{
    c2d_ext a, b, r;
    mpfr_t s;
    (void)state;
    a.m = 1.0;
    a.e = 0;
    b.m = -1.5;
    b.e = -(C2D_R_MANT + 2); /* b = -1.5 2^-(MANT+2): more than half the ulp below 1 */
    mpfr_init2(s, C2D_R_MANT + 1);
    rounded_sum(s, &a, &b);
    assert_true(mpfr_cmp_d(s, 1.0) < 0);       /* the rounded sum is below 1 ... */
    c2d_ext_add(&r, &a, &b, 1);
    assert_true(equals(s, &r));                /* ... and c2d_ext_add returns it */
    assert_true(r.m == 2.0 - 0x1p-52 && r.e == -1);
    mpfr_clear(s);
}

/* Zeros: the old copy returned the other operand as it was (a zero with its
 * exponent, or -0), c2d_ext_add a canonical zero; no caller reads either. */
static void test_zeros_differ_only_in_representation(void **state)
{
    c2d_ext a, z, r1, r2;
    (void)state;
    a.m = 0;
    a.e = 0;
    z.m = -0.0;
    z.e = 0;
    c2d_ext_add(&r1, &a, &z, 1);
    old_toia_ext_add(&r2, &a, &z);
    assert_true(r1.m == 0 && r2.m == 0 && r1.e == 0);
}

/* c2d_toia_ext_cmp (now on c2d_ext_add) and the old one agree, also for the
 * bound rounded up out of [1, 2) (S.m *= 1 + 2^(4 - MANT) in
 * c2d_toia_split_sign), where the two sums can differ in the last bit. */
static void test_toia_comparison_decides_as_before(void **state)
{
    static const double up[] = {1.0, 1.0 + 0x1p-48};
    c2d_tally t = {0, 0};
    int differ = 0, i, j, u, sa, sb, k;
    (void)state;
    for (i = 0; i < NSIG; i++)
        for (j = 0; j < NSIG; j++)
            for (u = 0; u < 2; u++)
                for (sa = -1; sa <= 1; sa += 2)
                    for (sb = -1; sb <= 1; sb += 2)
                        for (k = -(C2D_R_MANT + 8); k <= C2D_R_MANT + 8; k++) {
                            c2d_ext a, b, d1, d2, nb;
                            a.m = sa * sig[i];
                            a.e = -3;
                            b.m = sb * sig[j] * up[u];
                            b.e = -3 - k;
                            nb.m = -b.m;
                            nb.e = b.e;
                            c2d_ext_add(&d1, &a, &b, -1);
                            old_toia_ext_add(&d2, &a, &nb);
                            if (d1.m != d2.m || d1.e != d2.e) differ++;
                            (void)c2d_tally_add(&t, c2d_toia_ext_cmp(&a, &b) == old_toia_ext_cmp(&a, &b));
                            (void)c2d_tally_add(&t, c2d_toia_ext_cmp(&b, &a) == old_toia_ext_cmp(&b, &a));
                        }
    c2d_put_tally("toia ext_cmp, old vs shared sum", &t);
    printf("  sums that differ (operand outside [1, 2) at the cut): %d\n", differ);
    assert_int_equal(t.failed, 0);
    assert_true(differ > 0); /* the differences exist, and do not reach the decision */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_both_cuts_round_correctly_for_normalised_operands),
        cmocka_unit_test(test_the_cut_at_mant_plus_3_is_tight),
        cmocka_unit_test(test_zeros_differ_only_in_representation),
        cmocka_unit_test(test_toia_comparison_decides_as_before),
    };
    return c2d_run_tests("ext_add", tests);
}
