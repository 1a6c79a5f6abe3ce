/* SPDX-License-Identifier: MIT */
/* The shared vector tables (tests/vectors/vectors.c, also run on emulated
 * MCUs), checked by the code the MCU harness runs (check_template.h,
 * check_models.h): every entry's status, outputs within its tolerance,
 * nothing written that may not be, and the batch lanes against the scalar
 * call; the models' tables (rough contact, time of impact under
 * acceleration) the same way.  `make test` also
 * regenerates the table from the exact referee and requires it unchanged. */
#include "check.h"
#include "check_vectors.h"

/* Every entry of a table passes; failures were printed as they happened. */
static void assert_table_passes(void (*check)(c2d_tally *), int count)
{
    c2d_tally tally = {0, 0};
    check(&tally);
    assert_int_equal(tally.failed, 0);
    assert_int_equal(tally.passed, count);
}

static void test_double_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_vector_count_d > 30);
    assert_table_passes(c2d_check_vectors_d, c2d_vector_count_d);
}

static void test_float_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_vector_count_f > 20);
    assert_table_passes(c2d_check_vectors_f, c2d_vector_count_f);
}

static void test_double_rough_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_rough_vector_count_d > 20);
    assert_table_passes(c2d_check_rough_vectors_d, c2d_rough_vector_count_d);
}

static void test_float_rough_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_rough_vector_count_f > 20);
    assert_table_passes(c2d_check_rough_vectors_f, c2d_rough_vector_count_f);
}

static void test_double_accel_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_accel_vector_count_d > 20);
    assert_table_passes(c2d_check_accel_vectors_d, c2d_accel_vector_count_d);
}

static void test_float_accel_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_accel_vector_count_f > 20);
    assert_table_passes(c2d_check_accel_vectors_f, c2d_accel_vector_count_f);
}

static void test_fixed_vectors_pass(void **state)
{
    (void)state;
    assert_true(c2d_vector_count_x > 20);
    assert_table_passes(c2d_check_vectors_x, c2d_vector_count_x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_double_vectors_pass),
        cmocka_unit_test(test_float_vectors_pass),
        cmocka_unit_test(test_double_rough_vectors_pass),
        cmocka_unit_test(test_float_rough_vectors_pass),
        cmocka_unit_test(test_double_accel_vectors_pass),
        cmocka_unit_test(test_float_accel_vectors_pass),
        cmocka_unit_test(test_fixed_vectors_pass),
    };
    return c2d_run_tests("vectors", tests);
}
