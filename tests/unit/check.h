/* SPDX-License-Identifier: MIT */
/* cmocka glue shared by the test programs: includes in the order cmocka
 * needs, plus the comparisons cmocka 1.1.5 lacks. */
#ifndef C2D_CHECK_H
#define C2D_CHECK_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "collide2d.h"
#include "cases.h"
#include "harness.h"
#include "referee.h"

/* |got - want| <= tol, printing both on failure (cmocka has no double compare). */
#define assert_close(got, want, tol)                                                          \
    do {                                                                                      \
        double got_ = (got), want_ = (want), tol_ = (tol);                                   \
        if (!(fabs(got_ - want_) <= tol_)) {                                                  \
            print_error("%s = %.17g, want %.17g (tolerance %.3g)\n", #got, got_, want_, tol_); \
            fail();                                                                           \
        }                                                                                     \
    } while (0)

#define assert_status(got, want)                                                            \
    do {                                                                                    \
        c2d_status g_ = (got), w_ = (want);                                                 \
        if (g_ != w_) {                                                                     \
            print_error("status %s, want %s\n", c2d_status_string(g_), c2d_status_string(w_)); \
            fail();                                                                         \
        }                                                                                   \
    } while (0)

#define assert_bits_equal(a, b) assert_memory_equal(&(a), &(b), sizeof(a))

/* A loop that skips cases (`continue`) states how many it checked: `got`,
 * the cases that reached its checks, against `want`, what its seeded
 * generator gives (the comment at each use says where `want` comes from). */
#define assert_cases_checked(got, want)                                       \
    do {                                                                      \
        long got_ = (long)(got), want_ = (long)(want);                        \
        if (got_ != want_) {                                                  \
            print_error("%ld cases checked, want %ld\n", got_, want_);       \
            fail();                                                           \
        }                                                                     \
    } while (0)

/* Runs a test program's group and ends with the closing line every test
 * program prints, "NAME: N passed, N failed" (harness.h), N counting tests,
 * after cmocka's own summary; returns the exit status.  main ends with
 * return c2d_run_tests("NAME", tests), tests the array of the group. */
static inline int c2d_cmocka_tally(const char *name, size_t count, int failed)
{
    c2d_tally t;
    /* cmocka returns how many tests failed, or a negative number when the
     * group could not run: then none passed. */
    t.failed = failed < 0 || (size_t)failed > count ? (int)count : failed;
    t.passed = (int)count - t.failed;
    c2d_put_tally(name, &t);
    return c2d_tally_status(&t);
}
#define c2d_run_tests(name, tests) \
    c2d_cmocka_tally(name, sizeof(tests) / sizeof((tests)[0]), cmocka_run_group_tests_name(name, tests, NULL, NULL))

#endif
